//! `grafika generate`: exams with answer keys. Each problem is a problem file
//! (SPEC §5) drawn from a seeded [`SplitMix64`] with nice numbers for its
//! difficulty, checked to be non-degenerate and solvable, and solved exactly
//! for its key; the question sheet and the key (with the full worked
//! solution) are rendered as Markdown, LaTeX or JSON.
//!
//! Nice numbers: at easy level |Pe − Pr| is an integer (Pythagorean triples,
//! also for |Vup × (Pe − Pr)|, so u, v, n are rational), fovy = 90°, clipping
//! boxes at the origin; at medium level the answers have a single surd (one
//! of the two norms is an integer), fovy ∈ {30°, 45°, 60°, 120°}; at hard
//! level anything goes. Never degenerate: the up vector is not parallel to
//! the view direction, points lie beyond the near plane (so not on the
//! projection plane), clipping endpoints are off the box planes and no
//! segment lies in a box plane. Clipping problems cycle through partial
//! (clipped), accepted and rejected segments at every level.

mod draw;

pub use draw::problem;

use crate::error::{Error, Result};
use crate::problem::ProblemIn;
use crate::report::{fmt_dec, Report, Style};
use crate::report_doc::Doc;
use crate::rng::SplitMix64;
use crate::solve::lookup;
use crate::trace::Val;
use clap::{Args, ValueEnum};
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What the problems are about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Topic {
    /// The camera basis u, v, n.
    Basis,
    /// The basis and eye coordinates of points.
    View,
    /// Projection onto the near plane.
    Project,
    /// The viewing window from fovy, aspect and near.
    Window,
    /// Line clipping with outcodes.
    Clip,
    /// Lighting at one point.
    Shade,
    /// The whole chain: view, projection, window, viewport.
    Pipeline,
}

/// How nice the numbers are.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Difficulty {
    /// Integer norms, rational answers.
    Easy,
    /// One surd in the answers.
    Medium,
    /// General.
    Hard,
}

/// The format of the question sheet and the key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Only the problem files and the answer-key files (TOML).
    Toml,
    /// questions.md and key.md.
    Md,
    /// questions.tex and key.tex (plain pdflatex).
    Latex,
    /// exam.json (statements, answers, worked steps).
    Json,
}

/// The `generate` flags.
#[derive(Args, Debug, Clone)]
pub struct GenerateArgs {
    /// The topic; several, comma-separated, alternate through the exam.
    #[arg(long, value_enum, value_delimiter = ',', required = true)]
    pub topic: Vec<Topic>,
    /// Problems per exam.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=500))]
    pub count: u32,
    /// The seed: the same seed gives the same files, byte for byte.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// How nice the numbers are.
    #[arg(long, value_enum, default_value_t = Difficulty::Medium)]
    pub difficulty: Difficulty,
    /// The format of the question sheet and key.
    #[arg(long, value_enum, default_value_t = Format::Md)]
    pub format: Format,
    /// The output directory (created if needed).
    #[arg(long)]
    pub out: PathBuf,
    /// Versions of the exam (one per student), each with its own key.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=500))]
    pub variants: u32,
}

/// One generated problem.
pub struct Generated {
    /// The problem file's text.
    pub toml: String,
    /// The parsed problem.
    pub problem: ProblemIn,
    /// The exact solution.
    pub report: Report,
    /// The answers asked for.
    pub keys: Vec<String>,
}

/// Runs `grafika generate`; returns what to print.
pub fn run(a: &GenerateArgs, json: bool, digits: usize) -> Result<String> {
    let files = write_exams(a, digits)?;
    Ok(if json {
        serde_json::to_string_pretty(&json!({
            "command": "generate",
            "seed": a.seed,
            "files": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        }))
        .unwrap_or_default()
            + "\n"
    } else {
        let mut s = format!(
            "wrote {} files ({} variant{} of {} {} problem{}, seed {}) to {}\n",
            files.len(),
            a.variants,
            if a.variants == 1 { "" } else { "s" },
            a.count,
            topics_name(&a.topic),
            if a.count == 1 { "" } else { "s" },
            a.seed,
            a.out.display()
        );
        for f in files.iter().take(12) {
            let _ = writeln!(s, "  {}", f.display());
        }
        if files.len() > 12 {
            let _ = writeln!(s, "  … and {} more", files.len() - 12);
        }
        s
    })
}

/// Generates and writes every variant; returns the files written.
/// `digits`: significant digits of the decimals in the sheets and keys.
pub fn write_exams(a: &GenerateArgs, digits: usize) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for v in 0..a.variants {
        let dir = if a.variants == 1 {
            a.out.clone()
        } else {
            a.out.join(format!("variant-{:02}", v + 1))
        };
        std::fs::create_dir_all(&dir)
            .map_err(|e| Error::new("out", format!("cannot create {}: {e}", dir.display())))?;
        let exam = exam(&a.topic, a.difficulty, a.count, variant_seed(a.seed, v))?;
        files.extend(write_exam(&dir, a, v + 1, &exam, digits)?);
    }
    Ok(files)
}

/// The seed of variant v (variant 0 of seed S is S itself).
fn variant_seed(seed: u64, v: u32) -> u64 {
    if v == 0 {
        seed
    } else {
        SplitMix64::fork(seed, 0x5641_5249_0000_0000 | v as u64).next_u64()
    }
}

/// The problems of one exam: problem i is on topic i mod (number of topics).
pub fn exam(topics: &[Topic], diff: Difficulty, count: u32, seed: u64) -> Result<Vec<Generated>> {
    if topics.is_empty() {
        return Err(Error::new("topic", "give at least one topic"));
    }
    (0..count as usize)
        .map(|i| {
            let mut rng = SplitMix64::fork(seed, i as u64);
            // k: the problem's index among those of its topic
            problem(topics[i % topics.len()], diff, i / topics.len(), &mut rng)
        })
        .collect()
}

/// `view,clip` for the titles.
fn topics_name(t: &[Topic]) -> String {
    t.iter()
        .map(|x| format!("{x:?}").to_lowercase())
        .collect::<Vec<_>>()
        .join(",")
}

/// The answer-key file: `key = value` lines in `grafika check` format, each
/// value exact where it has an exact form.
pub fn key_toml(g: &Generated) -> String {
    let mut s = format!("# Answer key: {}\n", g.problem.title);
    for k in &g.keys {
        if let Some(v) = lookup(&g.report.result, k) {
            let _ = writeln!(s, "{k} = {}", answer_toml(v));
        }
    }
    s
}

/// A value as a check answer: numbers as strings, exact where they have an
/// exact form; a rejected segment as "none".
pub fn answer_toml(v: &Val) -> toml::Value {
    use toml::Value as T;
    match v {
        Val::Num(n) => T::String(n.exact.clone().unwrap_or_else(|| {
            // 12 significant digits: far inside the 0.1% tolerance, and the
            // same on every platform even where libm's tan differs by an ulp.
            fmt_dec(n.value, 12)
        })),
        Val::List(items) => T::Array(items.iter().map(answer_toml).collect()),
        Val::Text(t) => T::String(t.clone()),
        Val::Null => T::String("none".into()),
        Val::Bool(b) => T::Boolean(*b),
        Val::Map(kv) => T::Table(
            kv.iter()
                .map(|(k, x)| (k.clone(), answer_toml(x)))
                .collect(),
        ),
    }
}

/// Writes one exam's files.
fn write_exam(
    dir: &Path,
    a: &GenerateArgs,
    variant: u32,
    exam: &[Generated],
    digits: usize,
) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let mut put = |name: String, text: String| -> Result<()> {
        let path = dir.join(name);
        std::fs::write(&path, text)
            .map_err(|e| Error::new("out", format!("cannot write {}: {e}", path.display())))?;
        files.push(path);
        Ok(())
    };
    for (i, g) in exam.iter().enumerate() {
        put(format!("problem-{:02}.toml", i + 1), g.toml.clone())?;
        put(format!("problem-{:02}.key.toml", i + 1), key_toml(g))?;
    }
    let title = format!(
        "grafika exam: {} ({}), seed {}{}",
        topics_name(&a.topic),
        format!("{:?}", a.difficulty).to_lowercase(),
        a.seed,
        if a.variants > 1 {
            format!(", variant {variant}")
        } else {
            String::new()
        }
    );
    let style = Style {
        digits,
        exact_mode: true,
    };
    match a.format {
        Format::Toml => {}
        Format::Md | Format::Latex => {
            let doc = if a.format == Format::Md {
                Doc::Markdown
            } else {
                Doc::Latex
            };
            let ext = if doc == Doc::Markdown { "md" } else { "tex" };
            let (q, k) = sheets(doc, exam, &style);
            put(format!("questions.{ext}"), doc.document(&title, &q))?;
            put(
                format!("key.{ext}"),
                doc.document(&format!("{title} — answer key"), &k),
            )?;
        }
        Format::Json => {
            let problems: Vec<Value> = exam
                .iter()
                .enumerate()
                .map(|(i, g)| {
                    json!({
                        "file": format!("problem-{:02}.toml", i + 1),
                        "title": g.problem.title,
                        "statement": g.problem.statement,
                        "keys": g.keys,
                        "answers": g.keys.iter().filter_map(|k| lookup(&g.report.result, k).map(|v| (k.clone(), json!({
                            "decimal": crate::report::value_json(v), "exact": crate::report::exact_json(v) })))).collect::<serde_json::Map<_, _>>(),
                        "solution": g.report.to_json(),
                    })
                })
                .collect();
            let j =
                json!({ "title": title, "seed": a.seed, "variant": variant, "problems": problems });
            put(
                "exam.json".into(),
                serde_json::to_string_pretty(&j).unwrap_or_default() + "\n",
            )?;
        }
    }
    Ok(files)
}

/// The question sheet and the key bodies.
fn sheets(doc: Doc, exam: &[Generated], st: &Style) -> (String, String) {
    let mut q = String::new();
    let mut k = String::new();
    for (i, g) in exam.iter().enumerate() {
        let title = &format!("Problem {}: {}", i + 1, g.problem.title);
        let statement = g.problem.statement.clone().unwrap_or_default();
        q.push_str(&doc.heading(1, title));
        q.push_str(&doc.text(&statement));
        q.push_str("\n\n");
        k.push_str(&doc.heading(1, title));
        k.push_str(&doc.text(&statement));
        k.push_str("\n\n");
        k.push_str(&doc.heading(2, "Answers"));
        let items: Vec<(String, Val)> = g
            .keys
            .iter()
            .filter_map(|key| lookup(&g.report.result, key).map(|v| (key.clone(), v.clone())))
            .collect();
        k.push_str(&doc.answers(st, &items));
        k.push_str(&doc.heading(2, "Worked solution"));
        k.push_str(&doc.steps(&g.report, st));
    }
    (q, k)
}
