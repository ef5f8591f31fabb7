//! `grafika generate`: draws the exams (tutor), has them written as sheets
//! and keys (report), and writes the files.

use crate::cli::args::{Format, GenerateArgs};
use crate::error::{Error, Result};
use crate::msg::{Bound, ErrMsg, IoWhy};
use crate::report::doc::Doc;
use crate::report::gift::gift;
use crate::report::moodle::{moodle_xml, Written};
use crate::report::sheets::{
    exam_json, exam_title, key_file, key_title, problem_file, sheets, written_summary,
};
use crate::report::Style;
use crate::tutor::check::DEFAULT_TOLERANCE;
use crate::tutor::generate::quiz::Quiz;
use crate::tutor::generate::{exam, problem_name, variant_name, variant_seed, Generated};
use serde_json::json;
use std::path::{Path, PathBuf};

/// Runs `grafika generate`; returns what to print.
pub fn run(a: &GenerateArgs, json: bool, style: &Style) -> Result<String> {
    let files = write_exams(a, style)?;
    Ok(if json {
        let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
        let j = json!({ "command": "generate", "seed": a.seed, "files": names });
        serde_json::to_string_pretty(&j).unwrap_or_default() + "\n"
    } else {
        written_summary(
            &files,
            a.variants,
            a.count,
            &a.topic,
            a.seed,
            (&a.out, style.lang),
        )
    })
}

/// More problems than this (count × variants) are written only with `--force`.
pub const MAX_PROBLEMS: u64 = 2_000;

/// About how many bytes one problem takes on disk (its problem file, key
/// and worked solution), for the size given when refusing.
const BYTES_PER_PROBLEM: u64 = 16_000;

/// Refuses, unless `--force`: more than [`MAX_PROBLEMS`] problems, and an
/// output that would overwrite existing files. `--out` naming a file that is
/// not a directory is always an error.
fn check_out(a: &GenerateArgs) -> Result<()> {
    if a.out.exists() && !a.out.is_dir() {
        return Err(Error::why(
            "out",
            ErrMsg::NotDirectory(a.out.display().to_string()),
        ));
    }
    let n = a.count as u64 * a.variants as u64;
    if n > MAX_PROBLEMS && !a.force {
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
    let first = a.out.join(match a.format {
        Format::Moodle => "quiz.xml".to_string(),
        Format::Gift => "quiz.gift".to_string(),
        _ if a.variants == 1 => format!("{}.toml", problem_name(1)),
        _ => variant_name(1),
    });
    if first.exists() && !a.force {
        return Err(Error::why(
            "out",
            ErrMsg::ExistsForce(first.display().to_string()),
        ));
    }
    Ok(())
}

/// Generates and writes every variant; returns the files written.
pub fn write_exams(a: &GenerateArgs, style: &Style) -> Result<Vec<PathBuf>> {
    check_out(a)?;
    if matches!(a.format, Format::Moodle | Format::Gift) {
        return write_quiz(a, style).map(|f| vec![f]);
    }
    let mut files = Vec::new();
    let bar = progress(a, style);
    for v in 0..a.variants {
        let dir = if a.variants == 1 {
            a.out.clone()
        } else {
            a.out.join(variant_name(v as usize + 1))
        };
        std::fs::create_dir_all(&dir).map_err(|e| out_error(ErrMsg::CannotCreate, &dir, &e))?;
        let exam = exam(&a.topic, a.difficulty, a.count, variant_seed(a.seed, v))?;
        files.extend(write_exam(&dir, a, v + 1, &exam, style)?);
        bar.iter().for_each(|b| b.inc(1));
    }
    bar.iter().for_each(|b| b.finish_and_clear());
    Ok(files)
}

/// A progress bar over the variants, on a terminal, when there are more
/// than 100 problems in all (smaller exams are written in well under a
/// second).
fn progress(a: &GenerateArgs, style: &Style) -> Option<indicatif::ProgressBar> {
    let n = a.count as u64 * a.variants as u64;
    let msg = crate::report::lang::tr(style.lang, "variants", "varian");
    (n > 100)
        .then(|| super::terminal_bar(a.variants as u64, msg))
        .flatten()
}

/// Writes one exam's files: the problem and key files, then the sheets in
/// the chosen format.
fn write_exam(
    dir: &Path,
    a: &GenerateArgs,
    variant: u32,
    exam: &[Generated],
    style: &Style,
) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let mut put = |name: String, text: String| -> Result<()> {
        let path = dir.join(name);
        std::fs::write(&path, text).map_err(|e| out_error(ErrMsg::CannotWrite, &path, &e))?;
        files.push(path);
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
    let doc = match a.format {
        Format::Toml => return Ok(files),
        Format::Json => {
            let j = exam_json(&title(Some(a.seed)), a.seed, variant, exam, style.lang);
            put(
                "exam.json".into(),
                serde_json::to_string_pretty(&j).unwrap_or_default() + "\n",
            )?;
            return Ok(files);
        }
        Format::Md => Doc::Markdown,
        Format::Latex => Doc::Latex,
        Format::Html => Doc::Html,
        Format::Moodle | Format::Gift => return Ok(files),
    };
    let ext = match doc {
        Doc::Markdown => "md",
        Doc::Latex => "tex",
        Doc::Html => "html",
    };
    let (q, k) = sheets(doc, exam, style);
    put(
        format!("questions.{ext}"),
        doc.document(&title(None), &q, style.lang),
    )?;
    let key = key_title(&title(Some(a.seed)), style.lang);
    put(format!("key.{ext}"), doc.document(&key, &k, style.lang))?;
    Ok(files)
}

/// The relative tolerance of a quiz: `--tolerance`, else 0.1 %; it must be
/// a number in (0, 1), so that no nonzero key gets a zero tolerance.
fn quiz_tolerance(a: &GenerateArgs) -> Result<f64> {
    let r = a.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    if r.is_finite() && r > 0.0 && r < 1.0 {
        Ok(r)
    } else {
        Err(Error::why(
            "tolerance",
            ErrMsg::MustBe(Bound::Fraction, r.to_string()),
        ))
    }
}

/// Writes every variant into one Moodle XML or GIFT file in the output
/// directory: quiz.xml or quiz.gift.
fn write_quiz(a: &GenerateArgs, style: &Style) -> Result<PathBuf> {
    let rel = quiz_tolerance(a)?;
    let bar = progress(a, style);
    let exams = (0..a.variants)
        .map(|v| {
            bar.iter().for_each(|b| b.inc(1));
            exam(&a.topic, a.difficulty, a.count, variant_seed(a.seed, v))
        })
        .collect::<Result<Vec<_>>>()?;
    bar.iter().for_each(|b| b.finish_and_clear());
    let quiz = Quiz::new(exams, &a.topic, rel);
    let w = Written {
        style,
        decimal: a.decimal,
    };
    let (name, text) = match a.format {
        Format::Gift => ("quiz.gift", gift(&quiz, &w)),
        _ => ("quiz.xml", moodle_xml(&quiz, &w)),
    };
    std::fs::create_dir_all(&a.out).map_err(|e| out_error(ErrMsg::CannotCreate, &a.out, &e))?;
    let path = a.out.join(name);
    std::fs::write(&path, text).map_err(|e| out_error(ErrMsg::CannotWrite, &path, &e))?;
    Ok(path)
}

/// An error on `--out`: a directory that cannot be created or a file that
/// cannot be written (`what`), with the system's reason.
fn out_error(what: fn(String, IoWhy) -> ErrMsg, path: &Path, e: &std::io::Error) -> Error {
    Error::why("out", what(path.display().to_string(), IoWhy::of(e)))
}
