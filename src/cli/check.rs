//! The `grafika check` command line: one answer file, a directory of them
//! (one row per student, and a CSV summary), or the answers printed in the
//! source (`--answers-from-text`).

use crate::cli::args::CheckArgs;
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::report::check::{to_json, to_text};
use crate::report::Style;
use crate::tutor::check::{self, Marking, Verdict};
use serde_json::json;
use std::path::{Path, PathBuf};

/// Runs `grafika check`; returns what to print on stdout.
pub fn run(a: &CheckArgs, json: bool, style: &Style) -> Result<String> {
    valid_tolerance(a.tolerance)?;
    let p = ProblemIn::read(&a.file)?;
    let settings = check::Settings {
        follow_through: a.follow_through,
        ..check::settings_for(&p, a.tolerance, a.sig_figs)
    };
    let style = &Style {
        exact_mode: true,
        ..*style
    };
    match (&a.answers, a.answers_from_text) {
        (Some(_), true) | (None, false) => Err(Error::new(
            "answers",
            "give either --answers FILE|DIR or --answers-from-text",
        )),
        (None, true) => {
            if p.printed.is_empty() {
                return Err(Error::new(
                    "answers-from-text",
                    format!("{} has no [printed] table", a.file.display()),
                ));
            }
            let (_, answers) = check::answers_from_table(&p.printed);
            let who = p.source.clone().unwrap_or_else(|| "the text".into());
            let m = check::mark(&p, &who, &answers, settings, true)?;
            Ok(output(&m, json, style))
        }
        (Some(path), false) if path.is_dir() => {
            let files = answer_files(path)?;
            let mut marks = Vec::new();
            for f in &files {
                let (student, answers) = check::read_answers(f)?;
                let who = student.unwrap_or_else(|| stem(f));
                marks.push((f.clone(), check::mark(&p, &who, &answers, settings, false)?));
            }
            let csv = summary_csv(&marks);
            if let Some(c) = &a.csv {
                if c.as_os_str() != "-" {
                    std::fs::write(c, &csv).map_err(|e| {
                        Error::new("csv", format!("cannot write {}: {e}", c.display()))
                    })?;
                }
            }
            let mut out = if json {
                serde_json::to_string_pretty(&json!({
                    "command": "check",
                    "title": p.title,
                    "students": marks.iter().map(|(_, m)| to_json(m)).collect::<Vec<_>>(),
                }))
                .unwrap_or_default()
                    + "\n"
            } else {
                summary_table(&p.title, &marks)
            };
            if a.csv.as_deref() == Some(Path::new("-")) {
                out.push_str(&csv);
            }
            Ok(out)
        }
        (Some(path), false) => {
            let (student, answers) = check::read_answers(path)?;
            let who = student.unwrap_or_else(|| path.display().to_string());
            let m = check::mark(&p, &who, &answers, settings, false)?;
            Ok(output(&m, json, style))
        }
    }
}

/// `--tolerance` must be a finite number ≥ 0.
pub(crate) fn valid_tolerance(t: Option<f64>) -> Result<()> {
    match t {
        Some(t) if !(t.is_finite() && t >= 0.0) => Err(Error::new(
            "tolerance",
            format!("must be a finite number ≥ 0, got {t}"),
        )),
        _ => Ok(()),
    }
}

fn output(m: &Marking, json: bool, style: &Style) -> String {
    if json {
        serde_json::to_string_pretty(&to_json(m)).unwrap_or_default() + "\n"
    } else {
        to_text(m, style)
    }
}

fn stem(f: &Path) -> String {
    f.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// The `*.toml` files of a directory, sorted by name.
fn answer_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let rd = std::fs::read_dir(dir)
        .map_err(|e| Error::new("answers", format!("cannot read {}: {e}", dir.display())))?;
    let mut files: Vec<PathBuf> = rd
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(Error::new(
            "answers",
            format!("{} holds no .toml answer files", dir.display()),
        ));
    }
    Ok(files)
}

fn mistakes(m: &Marking) -> String {
    m.diagnoses
        .iter()
        .map(|d| d.mistake.code)
        .collect::<Vec<_>>()
        .join(" ")
}

/// One row per student.
fn summary_table(title: &str, marks: &[(PathBuf, Marking)]) -> String {
    use comfy_table::{presets, Table};
    let mut t = Table::new();
    t.load_preset(presets::UTF8_FULL_CONDENSED).set_header(vec![
        "student",
        "score",
        "correct",
        "too coarse",
        "wrong",
        "missing",
        "unparseable",
        "follow-through",
        "mistakes",
    ]);
    for (_, m) in marks {
        t.add_row(vec![
            m.who.clone(),
            format!("{}/{}", crate::report::fmt_dec(m.score(), 4), m.total()),
            m.count(Verdict::Correct).to_string(),
            m.count(Verdict::TooCoarse).to_string(),
            m.count(Verdict::Wrong).to_string(),
            m.count(Verdict::Missing).to_string(),
            m.count(Verdict::Unparseable).to_string(),
            m.follow_through().to_string(),
            mistakes(m),
        ]);
    }
    format!("{title}\n{t}\n")
}

/// `student,file,score,total,correct,too_coarse,wrong,missing,unparseable,follow_through,mistakes`
/// (follow_through: how many of the correct were credited by follow-through).
fn summary_csv(marks: &[(PathBuf, Marking)]) -> String {
    let q = |s: &str| {
        if s.contains([',', '"', '\n']) {
            format!("\"{}\"", s.replace('"', "\"\""))
        } else {
            s.to_string()
        }
    };
    let mut out = String::from(
        "student,file,score,total,correct,too_coarse,wrong,missing,unparseable,follow_through,mistakes\n",
    );
    for (f, m) in marks {
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{}\n",
            q(&m.who),
            q(&f.display().to_string()),
            m.score(),
            m.total(),
            m.count(Verdict::Correct),
            m.count(Verdict::TooCoarse),
            m.count(Verdict::Wrong),
            m.count(Verdict::Missing),
            m.count(Verdict::Unparseable),
            m.follow_through(),
            q(&mistakes(m)),
        ));
    }
    out
}
