//! `grafika generate`: draws the exams (tutor), has them written as sheets
//! and keys (report), and writes the files.

use crate::cli::args::{Format, GenerateArgs};
use crate::cli::stage::Stage;
use crate::error::{Error, Result};
use crate::msg::QuizWord;
use crate::msg::{Bound, ErrMsg};
use crate::report::doc::Doc;
use crate::report::gift::{gift_units, GIFT};
use crate::report::moodle::{moodle_units, Written, XML};
use crate::report::quizfile::pack;
use crate::report::sheets::{
    exam_json, exam_title, key_file, key_title, problem_file, sheet_title, sheets, written_json,
    written_summary,
};
use crate::report::Style;
use crate::tutor::check::DEFAULT_TOLERANCE;
use crate::tutor::generate::blueprint::blueprint;
use crate::tutor::generate::quiz::Quiz;
use crate::tutor::generate::{exams, problem_name, variant_name, Exams, Generated, Spec};
use std::path::PathBuf;

/// Runs `grafika generate`; returns what to print. `force`: `--force`.
pub fn run(a: &GenerateArgs, force: bool, json: bool, style: &Style) -> Result<String> {
    let (files, plan) = write_exams(a, force, style)?;
    Ok(if json {
        written_json(&files, a.seed, plan.json)
    } else {
        let mut s = written_summary(
            &files,
            a.variants,
            a.count,
            &a.topic,
            a.seed,
            (&a.out, style.lang),
        );
        if a.format == Format::Gift {
            // said to the lecturer here, never to students in a question
            let note = crate::report::words::of(style.lang).quiz(&QuizWord::FiguresInMoodle);
            s.push_str(&note);
            s.push('\n');
        }
        s.push('\n');
        s.push_str(&plan.table);
        s
    })
}

/// An exam's blueprint as `generate` prints it (the table) and writes it
/// (blueprint.md, blueprint.json).
pub struct Plan {
    /// The Markdown table printed.
    pub table: String,
    /// blueprint.json's value.
    pub json: serde_json::Value,
    /// blueprint.md.
    pub markdown: String,
}

/// The blueprint of a drawn exam in the user's language.
fn plan(drawn: &Exams, style: &Style) -> Plan {
    let bp = blueprint(drawn);
    let first = drawn.variants.first();
    let titles: Vec<String> = (first.iter().flat_map(|v| v.iter()))
        .map(|g| style.w(&g.title))
        .collect();
    let topics: Vec<&str> = drawn.forms.iter().map(|f| f.topic.name()).collect();
    let table = crate::report::blueprint::table(&bp, &titles, style.lang);
    Plan {
        json: crate::report::blueprint::json(&bp, &topics),
        markdown: crate::report::blueprint::markdown(&bp, &table, style),
        table,
    }
}

/// The blueprint's files, (name, text), written beside the exam.
fn plan_files(plan: &Plan) -> [(String, String); 2] {
    [
        (BLUEPRINT_MD.to_string(), plan.markdown.clone()),
        (
            BLUEPRINT_JSON.to_string(),
            serde_json::to_string_pretty(&plan.json).unwrap_or_default() + "\n",
        ),
    ]
}

/// The blueprint's file names.
pub const BLUEPRINT_MD: &str = "blueprint.md";
/// See [`BLUEPRINT_MD`].
pub const BLUEPRINT_JSON: &str = "blueprint.json";

/// More problems than this (count × variants) are written only with `--force`.
pub const MAX_PROBLEMS: u64 = 2_000;

/// About how many bytes one problem takes on disk (its problem file, key
/// and worked solution), for the size given when refusing.
const BYTES_PER_PROBLEM: u64 = 16_000;

/// Refuses, unless `--force`, more than [`MAX_PROBLEMS`] problems.
fn check_size(a: &GenerateArgs, force: bool) -> Result<()> {
    let n = a.count as u64 * a.variants as u64;
    if n > MAX_PROBLEMS && !force {
        return Err(Error::why(
            "count",
            ErrMsg::TooManyProblems(
                n,
                a.count as u64,
                a.variants as u64,
                n * BYTES_PER_PROBLEM / 1_000_000,
                MAX_PROBLEMS,
            ),
        ));
    }
    Ok(())
}

/// The names the output has in `--out`: `quiz.xml`, `variant-01` …, or one
/// exam's files (a quiz split by `--split-mb`: [`quiz_name`]).
fn entries(a: &GenerateArgs) -> Vec<String> {
    let mut names = match a.format {
        Format::Moodle | Format::Gift => vec![quiz_name(a.format, None)],
        _ if a.variants == 1 => exam_files(a.count, a.format),
        _ => (1..=a.variants).map(|v| variant_name(v as usize)).collect(),
    };
    names.extend([BLUEPRINT_MD, BLUEPRINT_JSON].map(String::from));
    names
}

/// The files of one exam: problem and key files, then the sheets.
fn exam_files(count: u32, format: Format) -> Vec<String> {
    let mut names: Vec<String> = (1..=count)
        .flat_map(|i| {
            [
                format!("{}.toml", problem_name(i as usize)),
                format!("{}.key.toml", problem_name(i as usize)),
            ]
        })
        .collect();
    names.extend(sheet_ext(format).map_or_else(
        || {
            (format == Format::Json)
                .then(|| "exam.json".to_string())
                .into_iter()
                .collect()
        },
        |ext| vec![format!("questions.{ext}"), format!("key.{ext}")],
    ));
    names
}

/// The extension of the question sheet and key, for the formats that have them.
fn sheet_ext(format: Format) -> Option<&'static str> {
    match format {
        Format::Md => Some("md"),
        Format::Latex => Some("tex"),
        Format::Html => Some("html"),
        Format::Toml | Format::Json | Format::Moodle | Format::Gift => None,
    }
}

/// Generates and writes every variant, the whole output or nothing (see
/// [`Stage`], the blueprint beside it); returns the files written and the
/// blueprint.
pub fn write_exams(a: &GenerateArgs, force: bool, style: &Style) -> Result<(Vec<PathBuf>, Plan)> {
    check_size(a, force)?;
    let limit = split_limit(a)?;
    if matches!(a.format, Format::Moodle | Format::Gift) {
        let rel = quiz_tolerance(a)?;
        // drawn before anything is written: an exam that cannot be made
        // leaves the output directory as it was
        let drawn = draw(a, style)?;
        let plan = plan(&drawn, style);
        let files = write_quiz(a, (rel, limit), (drawn, plan_files(&plan)), force, style)?;
        return Ok((files, plan));
    }
    let drawn = draw(a, style)?;
    let plan = plan(&drawn, style);
    let mut stage = Stage::begin(&a.out, entries(a), force, run_of(a))?;
    let mut files = Vec::new();
    for (v, exam) in drawn.variants.iter().enumerate() {
        let dir = if a.variants == 1 {
            String::new()
        } else {
            format!("{}/", variant_name(v + 1))
        };
        files.extend(write_exam(&mut stage, &dir, a, v as u32 + 1, exam, style)?);
    }
    for (name, text) in plan_files(&plan) {
        files.push(stage.write(&name, &text)?);
    }
    stage.commit()?;
    Ok((files, plan))
}

/// The run, as the list of generate's own files says it: what it was
/// asked, so that the same command writes the same list.
fn run_of(a: &GenerateArgs) -> String {
    use clap::ValueEnum;
    let topics: Vec<&str> = a.topic.iter().map(|t| t.name()).collect();
    let format = a.format.to_possible_value();
    format!(
        "(seed {}, topic {}, difficulty {}, count {}, variants {}, format {})",
        a.seed,
        topics.join(","),
        a.difficulty.name(),
        a.count,
        a.variants,
        format.as_ref().map_or("", |v| v.get_name()),
    )
}

/// The exam the arguments ask for.
fn spec(a: &GenerateArgs) -> Spec {
    Spec {
        topics: a.topic.clone(),
        difficulty: a.difficulty,
        count: a.count,
        variants: a.variants,
        seed: a.seed,
        clip: a.clip,
    }
}

/// Draws every variant of the exam, with a progress bar over its problems
/// on a terminal when there are more than 100 (smaller exams are drawn in
/// well under a second).
fn draw(a: &GenerateArgs, style: &Style) -> Result<Exams> {
    let n = a.count as u64 * a.variants as u64;
    let msg = crate::report::words::of(style.lang).cli(crate::msg::CliWord::Problems);
    let bar = (n > 100).then(|| super::terminal_bar(n, msg)).flatten();
    let drawn = exams(&spec(a), &mut |k| bar.iter().for_each(|b| b.inc(k)));
    bar.iter().for_each(|b| b.finish_and_clear());
    drawn
}

/// Writes one exam's files (into `dir`, `` or `variant-NN/`): the problem
/// and key files, then the sheets in the chosen format.
fn write_exam(
    stage: &mut Stage,
    dir: &str,
    a: &GenerateArgs,
    variant: u32,
    exam: &[Generated],
    style: &Style,
) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let mut put = |name: String, text: String| -> Result<()> {
        files.push(stage.write(&format!("{dir}{name}"), &text)?);
        Ok(())
    };
    for (i, g) in exam.iter().enumerate() {
        put(
            format!("{}.toml", problem_name(i + 1)),
            problem_file(g, style.lang),
        )?;
        put(
            format!("{}.key.toml", problem_name(i + 1)),
            key_file(g, style.lang),
        )?;
    }
    let numbered = (a.variants > 1).then_some(variant);
    // The question sheet does not show the seed (anyone could regenerate the key).
    let title = |seed| exam_title(&a.topic, a.difficulty, seed, numbered, style.lang);
    if a.format == Format::Json {
        let j = exam_json(&title(Some(a.seed)), a.seed, variant, exam, style.lang);
        put(
            "exam.json".into(),
            serde_json::to_string_pretty(&j).unwrap_or_default() + "\n",
        )?;
    }
    let (Some(ext), Some(doc)) = (sheet_ext(a.format), doc_of(a.format)) else {
        return Ok(files);
    };
    let (q, k) = sheets(doc, exam, style);
    let sheet = sheet_title(a.difficulty, numbered, style.lang);
    put(
        format!("questions.{ext}"),
        doc.document(&sheet, &q, style.lang),
    )?;
    let key = key_title(&title(Some(a.seed)), style.lang);
    put(format!("key.{ext}"), doc.document(&key, &k, style.lang))?;
    Ok(files)
}

/// The document kind of a format's sheets.
fn doc_of(format: Format) -> Option<Doc> {
    match format {
        Format::Md => Some(Doc::Markdown),
        Format::Latex => Some(Doc::Latex),
        Format::Html => Some(Doc::Html),
        Format::Toml | Format::Json | Format::Moodle | Format::Gift => None,
    }
}

/// The relative tolerance of a quiz: `--tolerance`, else 0.1 %; it must be
/// a number in (0, 1), so that no nonzero key gets a zero tolerance.
fn quiz_tolerance(a: &GenerateArgs) -> Result<f64> {
    let r = a.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    if r.is_finite() && r > 0.0 && r < 1.0 {
        Ok(r)
    } else {
        Err(Error::why("tolerance", ErrMsg::MustBe(Bound::Fraction, r)))
    }
}

/// The bytes a quiz file may have, from `--split-mb` (megabytes of 10⁶
/// bytes, a number above 0), given only with a quiz's format.
fn split_limit(a: &GenerateArgs) -> Result<Option<usize>> {
    let Some(mb) = a.split_mb else {
        return Ok(None);
    };
    if !matches!(a.format, Format::Moodle | Format::Gift) {
        return Err(Error::why("split-mb", ErrMsg::SplitNotQuiz));
    }
    if !(mb.is_finite() && mb > 0.0) {
        return Err(Error::why("split-mb", ErrMsg::MustBe(Bound::AboveZero, mb)));
    }
    Ok(Some((mb * 1e6).floor().min(usize::MAX as f64) as usize))
}

/// A quiz file's name: `quiz.xml` (`quiz.gift`), or file k (from 1) of a
/// split quiz, `quiz-01.xml`.
pub fn quiz_name(format: Format, k: Option<usize>) -> String {
    let ext = if format == Format::Gift {
        "gift"
    } else {
        "xml"
    };
    match k {
        None => format!("quiz.{ext}"),
        Some(k) => format!("quiz-{k:02}.{ext}"),
    }
}

/// Writes every variant into one Moodle XML or GIFT file in the output
/// directory (quiz.xml or quiz.gift), or, with a `limit` in bytes, into
/// as many files as it takes, none larger (quiz-01.xml, …). An existing
/// entry is refused before the work (the names of a split quiz are known
/// once it is written: any quiz file is refused then, without `--force`).
fn write_quiz(
    a: &GenerateArgs,
    (rel, limit): (f64, Option<usize>),
    (drawn, beside): (Exams, [(String, String); 2]),
    force: bool,
    style: &Style,
) -> Result<Vec<PathBuf>> {
    let early = match limit {
        None => Some(Stage::begin(&a.out, entries(a), force, run_of(a))?),
        Some(_) => {
            refuse_quiz_files(a, force)?;
            None
        }
    };
    let mut texts = quiz_files(a, (rel, limit), drawn, style)?;
    texts.extend(beside);
    let mut stage = match early {
        Some(stage) => stage,
        None => Stage::begin(
            &a.out,
            texts.iter().map(|(n, _)| n.clone()).collect(),
            force,
            run_of(a),
        )?,
    };
    let files = (texts.iter())
        .map(|(name, text)| stage.write(name, text))
        .collect::<Result<Vec<_>>>()?;
    stage.commit()?;
    Ok(files)
}

/// Without `--force`, an error naming a quiz file already in `--out`
/// (`quiz.xml` or `quiz-NN.xml`; `.gift`): a split quiz's names are known
/// only once it is written, so any of them is refused before the work.
fn refuse_quiz_files(a: &GenerateArgs, force: bool) -> Result<()> {
    if force {
        return Ok(());
    }
    let ext = quiz_name(a.format, None).replace("quiz.", ".");
    let Ok(dir) = std::fs::read_dir(&a.out) else {
        return Ok(());
    };
    let quiz = |name: &String| {
        let numbered = (name.strip_prefix("quiz-"))
            .and_then(|r| r.strip_suffix(&ext))
            .is_some_and(|k| !k.is_empty() && k.chars().all(|c| c.is_ascii_digit()));
        numbered || *name == quiz_name(a.format, None)
    };
    let first = (dir.flatten())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(quiz)
        .min();
    match first {
        Some(name) => {
            let shown = a.out.join(&name).display().to_string();
            Err(Error::why("out", ErrMsg::ExistsForce(shown)))
        }
        None => Ok(()),
    }
}

/// The quiz's files, (name, text): one, or split under `limit` bytes.
fn quiz_files(
    a: &GenerateArgs,
    (rel, limit): (f64, Option<usize>),
    drawn: Exams,
    style: &Style,
) -> Result<Vec<(String, String)>> {
    let quiz = Quiz::new(drawn.variants, &a.topic, rel);
    let w = Written::new(style, a.decimal);
    let (units, frame) = match a.format {
        Format::Gift => (gift_units(&quiz, &w), GIFT),
        _ => (moodle_units(&quiz, &w), XML),
    };
    let texts = pack(&units, frame, limit).map_err(|i| {
        let mb = |bytes: usize| crate::msg::Fixed(bytes as f64 / 1e6, 3);
        let size =
            units[i].text.len() + units[i].category.len() + frame.head.len() + frame.foot.len();
        let limit = mb(limit.unwrap_or(0));
        Error::why(
            "split-mb",
            ErrMsg::QuestionTooLarge(units[i].name.clone(), mb(size), limit),
        )
    })?;
    Ok(match limit {
        None => texts
            .into_iter()
            .map(|t| (quiz_name(a.format, None), t))
            .collect(),
        Some(_) => (texts.into_iter().enumerate())
            .map(|(k, t)| (quiz_name(a.format, Some(k + 1)), t))
            .collect(),
    })
}
