//! The `grafika check` command line: one answer file, a directory of them
//! (one row per student, and a CSV summary), or the answers printed in the
//! source (`--answers-from-text`).

use crate::cli::args::CheckArgs;
use crate::cli::cut_message;
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::{Bound, ErrMsg, IoWhy, Msg, Twice};
use crate::report::check::{to_json, to_text};
use crate::report::lang::{tr, Lang};
use crate::report::Style;
use crate::tutor::check::{self, Marking, Verdict};
use serde_json::json;
use std::path::{Path, PathBuf};

/// Runs `grafika check`; returns what to print on stdout and the exit
/// status (2 when a file of a class could not be marked).
pub fn run(a: &CheckArgs, json: bool, style: &Style) -> Result<(String, i32)> {
    valid_tolerance(a.tolerance)?;
    let stdin = Path::new("-");
    // `--csv -` prints only the CSV: there is no room for the JSON.
    if json && a.csv.as_deref() == Some(stdin) {
        return Err(Error::why("csv", ErrMsg::CsvAndJson));
    }
    if a.file == stdin && a.answers.as_deref() == Some(stdin) {
        return Err(Error::why("answers", ErrMsg::BothStdin));
    }
    let p = ProblemIn::read(&a.file)?.localized(style.lang == Lang::Id);
    let settings = check::Settings {
        follow_through: a.follow_through,
        ..check::settings_for(&p, a.tolerance, a.sig_figs)
    };
    let style = &Style {
        exact_mode: true,
        ..*style
    };
    match (&a.answers, a.answers_from_text) {
        (Some(_), true) | (None, false) => Err(Error::why("answers", Twice::Answers)),
        (None, true) => {
            if p.printed.is_empty() {
                return Err(Error::why(
                    "answers-from-text",
                    ErrMsg::NoPrinted(a.file.display().to_string()),
                ));
            }
            let (_, answers) = check::answers_from_table(&p.printed);
            let who =
                (p.source.clone()).unwrap_or_else(|| tr(style.lang, "the text", "teks").into());
            let m = check::mark(&p, &who, &answers, settings, true)?;
            Ok((output(&m, json, style), 0))
        }
        (Some(path), false) if path.is_dir() => class(&p, path, settings, a, json, style),
        (Some(path), false) => {
            let (student, answers) = check::read_answers(path)?;
            let who = student.unwrap_or_else(|| path.display().to_string());
            let m = check::mark(&p, &who, &answers, settings, false)?;
            if let Some(c) = &a.csv {
                let row = Row {
                    file: path.clone(),
                    who: m.who.clone(),
                    outcome: Ok(m.clone()),
                    note: None,
                };
                let csv = summary_csv(std::slice::from_ref(&row), style.lang);
                write_csv(c, &csv)?;
                if c.as_os_str() == "-" {
                    return Ok((csv, 0));
                }
            }
            Ok((output(&m, json, style), 0))
        }
    }
}

/// One answer file of a class: its marking, or why it could not be marked,
/// and a note on what was done with it.
struct Row {
    file: PathBuf,
    who: String,
    outcome: Result<Marking>,
    note: Option<String>,
}

/// Marks every answer file of a directory: a file that cannot be read or
/// marked is a row with its error (the others are marked all the same), and
/// the exit status is then 2.
fn class(
    p: &ProblemIn,
    dir: &Path,
    settings: check::Settings,
    a: &CheckArgs,
    json: bool,
    style: &Style,
) -> Result<(String, i32)> {
    let to_stdout = a.csv.as_deref() == Some(Path::new("-"));
    let (files, skipped) = answer_files(dir, style.lang)?;
    // the problem solved, and its mistakes run, once for the whole class
    let marker = check::Marker::new(p, settings)?;
    let rows: Vec<Row> = files.iter().map(|f| row(&marker, f, style.lang)).collect();
    let status = if rows.iter().any(|r| r.outcome.is_err()) {
        2
    } else {
        0
    };
    let csv = summary_csv(&rows, style.lang);
    if let Some(c) = &a.csv {
        if to_stdout {
            return Ok((csv, status));
        }
        write_csv(c, &csv)?;
    }
    let out = if json {
        serde_json::to_string_pretty(&json!({
            "command": "check",
            "title": p.title,
            "students": rows.iter().map(|r| row_json(r, style.lang)).collect::<Vec<_>>(),
            "skipped": skipped.iter().map(|(f, why)| json!({ "file": f.display().to_string(), "reason": why })).collect::<Vec<_>>(),
        }))
        .unwrap_or_default()
            + "\n"
    } else {
        let mut t = summary_table(&p.title, &rows, style.lang);
        for r in &rows {
            if let Some(n) = &r.note {
                t.push_str(&format!("{}: {n}\n", r.file.display()));
            }
        }
        for (f, why) in &skipped {
            t.push_str(&format!("{}: {why}\n", f.display()));
        }
        t
    };
    Ok((out, status))
}

/// Reads and marks one student's file.
fn row(marker: &check::Marker, f: &Path, lang: Lang) -> Row {
    let read = check::read_answers(f);
    let who = match &read {
        Ok((Some(s), _)) => s.clone(),
        _ => stem(f),
    };
    let note = match &read {
        Ok((_, answers)) if answers.is_empty() => Some(
            tr(
                lang,
                "holds no answers: marked with every answer missing",
                "tidak berisi jawaban: dinilai dengan semua jawaban kosong",
            )
            .to_string(),
        ),
        Err(_) => Some(
            tr(
                lang,
                "not marked: the file is not a valid answer file (see the error in its row)",
                "tidak dinilai: berkas ini bukan berkas jawaban yang sah (lihat galat di barisnya)",
            )
            .to_string(),
        ),
        _ => None,
    };
    let outcome = read.map(|(_, answers)| marker.mark(&who, &answers, false));
    Row {
        file: f.to_path_buf(),
        who,
        outcome,
        note,
    }
}

fn row_json(r: &Row, lang: Lang) -> serde_json::Value {
    match &r.outcome {
        Ok(m) => {
            let mut j = to_json(m, lang);
            j["file"] = json!(r.file.display().to_string());
            j
        }
        Err(e) => json!({
            "student": r.who,
            "file": r.file.display().to_string(),
            "error": { "field": e.field, "message": crate::report::words::words(&e.message, lang) },
        }),
    }
}

/// Writes the CSV to a file (`-`: nothing here, the caller prints it).
fn write_csv(c: &Path, csv: &str) -> Result<()> {
    if c.as_os_str() == "-" {
        return Ok(());
    }
    std::fs::write(c, csv).map_err(|e| {
        Error::why(
            "csv",
            ErrMsg::CannotWrite(c.display().to_string(), IoWhy::of(&e)),
        )
    })
}

/// `--tolerance` must be a finite number ≥ 0.
pub(crate) fn valid_tolerance(t: Option<f64>) -> Result<()> {
    match t {
        Some(t) if !(t.is_finite() && t >= 0.0) => Err(Error::why(
            "tolerance",
            ErrMsg::MustBe(Bound::FiniteAtLeastZero, t.to_string()),
        )),
        _ => Ok(()),
    }
}

fn output(m: &Marking, json: bool, style: &Style) -> String {
    if json {
        serde_json::to_string_pretty(&to_json(m, style.lang)).unwrap_or_default() + "\n"
    } else {
        to_text(m, style)
    }
}

fn stem(f: &Path) -> String {
    f.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// The `*.toml` files of a directory, sorted by name, and every other
/// entry with the reason it is not read (a subdirectory, another kind of file).
type Skipped = Vec<(PathBuf, String)>;

fn answer_files(dir: &Path, lang: Lang) -> Result<(Vec<PathBuf>, Skipped)> {
    let rd = std::fs::read_dir(dir).map_err(|e| {
        Error::said(
            "answers",
            Msg::ErrCannotRead(dir.display().to_string(), IoWhy::of(&e)),
        )
    })?;
    let mut all: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
    all.sort();
    let (files, others): (Vec<PathBuf>, Vec<PathBuf>) = all
        .into_iter()
        .partition(|p| p.is_file() && p.extension().is_some_and(|x| x == "toml"));
    let skipped = others
        .into_iter()
        .map(|p| {
            let why = if p.is_dir() {
                tr(
                    lang,
                    "skipped: a subdirectory (its files are not read)",
                    "dilewati: subdirektori (berkas di dalamnya tidak dibaca)",
                )
            } else {
                tr(
                    lang,
                    "skipped: not a .toml file",
                    "dilewati: bukan berkas .toml",
                )
            };
            (p, why.to_string())
        })
        .collect();
    if files.is_empty() {
        return Err(Error::why(
            "answers",
            ErrMsg::NoAnswerFiles(dir.display().to_string()),
        ));
    }
    Ok((files, skipped))
}

fn mistakes(m: &Marking) -> String {
    m.diagnoses
        .iter()
        .map(|d| d.mistake.code)
        .collect::<Vec<_>>()
        .join(" ")
}

/// An error as a person reads it: `field: words`, cut when long.
fn said(e: &Error, lang: Lang) -> String {
    let words = crate::report::words::words(&e.message, lang);
    cut_message(&format!("{}: {words}", e.field), lang)
}

/// One row per student.
fn summary_table(title: &str, rows: &[Row], lang: Lang) -> String {
    use comfy_table::{presets, Table};
    let mut t = Table::new();
    t.load_preset(presets::UTF8_FULL_CONDENSED)
        .set_header(crate::report::check::class_header(lang));
    for r in rows {
        let m = match &r.outcome {
            Ok(m) => m,
            Err(e) => {
                let mut cells = vec![r.who.clone(), "—".to_string()];
                cells.extend(std::iter::repeat_n(String::new(), 6));
                cells.push(format!(
                    "{}: {}",
                    tr(lang, "error", "kesalahan"),
                    said(e, lang)
                ));
                t.add_row(cells);
                continue;
            }
        };
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

/// `student,file,score,total,correct,too_coarse,wrong,missing,unparseable,follow_through,mistakes,error`
/// (follow_through: how many of the correct were credited by follow-through;
/// a file that could not be marked: empty counts and its error).
fn summary_csv(rows: &[Row], lang: Lang) -> String {
    let q = |s: &str| {
        if s.contains([',', '"', '\n']) {
            format!("\"{}\"", s.replace('"', "\"\""))
        } else {
            s.to_string()
        }
    };
    let mut out = String::from(
        "student,file,score,total,correct,too_coarse,wrong,missing,unparseable,follow_through,mistakes,error\n",
    );
    for r in rows {
        let (who, file) = (q(&r.who), q(&r.file.display().to_string()));
        match &r.outcome {
            Ok(m) => out.push_str(&format!(
                "{who},{file},{},{},{},{},{},{},{},{},{},\n",
                m.score(),
                m.total(),
                m.count(Verdict::Correct),
                m.count(Verdict::TooCoarse),
                m.count(Verdict::Wrong),
                m.count(Verdict::Missing),
                m.count(Verdict::Unparseable),
                m.follow_through(),
                q(&mistakes(m)),
            )),
            Err(e) => out.push_str(&format!("{who},{file},,,,,,,,,,{}\n", q(&said(e, lang)))),
        }
    }
    out
}
