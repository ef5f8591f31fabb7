//! The `grafika check` command line: one answer file, a directory of them
//! (one row per student, a CSV summary, the lecturer's report), or the
//! answers printed in the source (`--answers-from-text`); the problem may
//! be an exam folder written by `generate`. The marking and the statistics
//! are the tutor's (`tutor::check`, `tutor::class`), the tables, CSV, JSON
//! and reports the report layer's (`report::check`, `report::class`); this
//! module parses, dispatches and writes.

use crate::cli::args::CheckArgs;
use crate::cli::write::Outputs;
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::{Bound, CliWord, DocWord, ErrMsg, IoWhy, Twice};
use crate::report::class::lecturer::Format;
use crate::report::lang::Lang;
use crate::report::words;
use crate::report::writer::{self, MarkingWriter, MarksWriter};
use crate::report::Style;
use crate::tutor::check::{self, Marking};
use crate::tutor::class::{self, exam, stats, Paper, Sheet};
use std::path::{Path, PathBuf};

/// Runs `grafika check`; returns what to print on stdout and the exit
/// status (2 when a file of a class could not be marked).
pub fn run(a: &CheckArgs, json: bool, style: &Style, outputs: &Outputs) -> Result<(String, i32)> {
    valid_tolerance(a.tolerance)?;
    let stdin = Path::new("-");
    // `--csv -` prints only the CSV: there is no room for the JSON.
    if json && a.csv.as_deref() == Some(stdin) {
        return Err(Error::why("csv", ErrMsg::CsvAndJson));
    }
    if a.file == stdin && a.answers.as_deref() == Some(stdin) {
        return Err(Error::why("answers", ErrMsg::BothStdin));
    }
    // a report's format, and the class list, are known before any marking
    a.report.as_deref().map(report_format).transpose()?;
    let listed = a.roster.as_deref().map(class::roster::read).transpose()?;
    if listed.is_some() && !a.answers.as_deref().is_some_and(Path::is_dir) {
        return Err(match &a.answers {
            Some(path) if std::fs::metadata(path).is_err() => not_a_class(path),
            _ => Error::why("roster", ErrMsg::RosterNeedsClass),
        });
    }
    let paper = if a.file.is_dir() {
        exam::read(&a.file, style.lang)?
    } else {
        Paper::one(ProblemIn::read(&a.file)?.localized(style.lang))
    };
    let settings = check::Settings {
        follow_through: a.follow_through,
        ..check::settings_for(&paper.variants[0][0].problem, a.tolerance, a.sig_figs)
    };
    let style = &Style {
        exact_mode: true,
        ..*style
    };
    if let Some(file) = &a.moodle_responses {
        return crate::cli::moodle::run(&paper, file, settings, a, json, style, outputs);
    }
    match (&a.answers, a.answers_from_text) {
        (Some(_), true) | (None, false) => Err(Error::why("answers", Twice::Answers)),
        (None, true) if a.report.is_some() => Err(Error::why("report", ErrMsg::ReportNeedsClass)),
        (None, true) => from_text(&paper, a, settings, json, style, outputs),
        (Some(path), false) if path.is_dir() => {
            class(&paper, (path, listed), settings, a, json, style, outputs)
        }
        (Some(path), false) if a.report.is_some() => Err(not_a_class(path)),
        (Some(path), false) => {
            let sheet = if paper.exam {
                class::mark_file(&paper, path, settings)
            } else {
                let (student, mut answers) = check::read_answers(path)?;
                // a file's `nim` says who, as its `student` does
                answers.retain(|(k, _)| !k.is("nim"));
                let who = student.unwrap_or_else(|| check::shown_name(&path.display().to_string()));
                let m = check::mark(
                    &paper.variants[0][0].problem,
                    &who,
                    &answers,
                    settings,
                    false,
                )?;
                lone_sheet(path, who, m)
            };
            one_sheet(sheet, paper.exam, a, json, style, outputs)
        }
    }
}

/// Marks a folder of answer files: the rows (text or JSON), the CSV, the
/// lecturer's report; exit status 2 when a file could not be marked.
fn class(
    paper: &Paper,
    (dir, listed): (&Path, Option<Vec<class::roster::Listed>>),
    settings: check::Settings,
    a: &CheckArgs,
    json: bool,
    style: &Style,
    outputs: &Outputs,
) -> Result<(String, i32)> {
    let mut class = class::mark_dir(paper, dir, settings)?;
    class.roster = listed.map(|l| class::roster::against(l, &class.sheets));
    class_out(paper, &class, settings, a, json, style, outputs)
}

/// A class's outputs: the lecturer's report, the CSV, the rows (text or
/// JSON); exit status 2 when a sheet could not be marked.
pub(crate) fn class_out(
    paper: &Paper,
    class: &class::Class,
    settings: check::Settings,
    a: &CheckArgs,
    json: bool,
    style: &Style,
    outputs: &Outputs,
) -> Result<(String, i32)> {
    if let Some(file) = &a.report {
        let format = report_format(file)?;
        let stats = stats::of(class, paper, &settings);
        let text = format
            .writer()
            .class_report(class, &stats, &settings, style);
        outputs.write(file, "report", text.as_bytes())?;
    }
    let status = if class.sheets.iter().any(|s| s.outcome.is_err()) {
        2
    } else {
        0
    };
    not_marked(&class.sheets, style.lang);
    if let Some(out) = csv_out(a, class, style.lang, outputs)? {
        return Ok((out, status));
    }
    let rows: &dyn MarksWriter = if json { &writer::Json } else { &writer::Text };
    Ok((rows.marks(class, style.lang), status))
}

/// Marks the answers the source printed (its `[printed]` table): the
/// rows, or the CSV of its one sheet.
fn from_text(
    paper: &Paper,
    a: &CheckArgs,
    settings: check::Settings,
    json: bool,
    style: &Style,
    outputs: &Outputs,
) -> Result<(String, i32)> {
    let p = &paper.variants[0][0].problem;
    if paper.exam || p.printed.is_empty() {
        return Err(Error::why(
            "answers-from-text",
            ErrMsg::NoPrinted(a.file.display().to_string()),
        ));
    }
    let (_, answers) = check::answers_from_table(&p.printed);
    let who =
        (p.source.clone()).unwrap_or_else(|| words::of(style.lang).cli(CliWord::TheText).into());
    let m = check::mark(p, &who, &answers, settings, true)?;
    one_sheet(lone_sheet(&a.file, who, m), false, a, json, style, outputs)
}

/// The sheet of one student's answers to a lone problem.
fn lone_sheet(file: &Path, who: String, m: Marking) -> Sheet {
    Sheet {
        file: file.to_path_buf(),
        who,
        variant: Some(1),
        drawn: Vec::new(),
        outcome: Ok(vec![(String::new(), m)]),
        note: None,
        identity: Default::default(),
        duplicate: None,
        fits: None,
    }
}

/// One sheet out: its CSV (`--csv`), else its rows; exit status 2 when
/// the file could not be marked.
fn one_sheet(
    sheet: Sheet,
    exam: bool,
    a: &CheckArgs,
    json: bool,
    style: &Style,
    outputs: &Outputs,
) -> Result<(String, i32)> {
    let status = if sheet.outcome.is_err() { 2 } else { 0 };
    let mut one = class::Class::of_one(sheet, exam);
    if let Some(out) = csv_out(a, &one, style.lang, outputs)? {
        return Ok((out, status));
    }
    let Some(sheet) = one.sheets.pop() else {
        return Ok((String::new(), status)); // a class of one has its sheet
    };
    let printed: &dyn MarkingWriter = if json { &writer::Json } else { &writer::Text };
    Ok((printed.marking(&sheet.outcome?, style), 0))
}

/// Why `--answers PATH` with `--report` is no class: a path that cannot be
/// read (missing, or not allowed) is named as the folder of answers that
/// cannot be read; a file is one student, not a class.
fn not_a_class(path: &Path) -> Error {
    match std::fs::metadata(path) {
        Err(e) => Error::why(
            "answers",
            ErrMsg::AnswersFolder(path.display().to_string(), IoWhy::of(&e)),
        ),
        Ok(_) => Error::why("report", ErrMsg::ReportNeedsClass),
    }
}

/// The report's format by the file's extension.
fn report_format(path: &Path) -> Result<Format> {
    let ext = path.extension().map(|e| e.to_string_lossy().to_lowercase());
    Format::from_extension(ext.as_deref().unwrap_or(""))
        .ok_or_else(|| Error::why("report", ErrMsg::ReportFormat(path.display().to_string())))
}

/// Writes the `--csv` summary to its file; returns it when it goes to
/// standard output (`--csv -`), which then prints nothing else.
fn csv_out(
    a: &CheckArgs,
    class: &class::Class,
    lang: Lang,
    outputs: &Outputs,
) -> Result<Option<String>> {
    let Some(c) = &a.csv else {
        return Ok(None);
    };
    let csv = writer::Csv.marks(class, lang);
    if c.as_os_str() == "-" {
        return Ok(Some(csv));
    }
    outputs.write(c, "csv", csv.as_bytes())?;
    Ok(None)
}

/// Says on standard error which files of a class could not be marked (the
/// exit status is then 2; their rows give each reason).
fn not_marked(sheets: &[Sheet], lang: Lang) {
    let bad: Vec<String> = sheets
        .iter()
        .filter(|s| s.outcome.is_err())
        .map(|s| s.file.display().to_string())
        .collect();
    if !bad.is_empty() {
        let e = Error::why(
            "answers",
            ErrMsg::NotMarked(bad.len(), sheets.len(), bad.join(", ")),
        );
        crate::cli::print::stderr_line(&format!(
            "{}: {}",
            words::of(lang).doc(&DocWord::Error),
            crate::report::class::said(&e, lang)
        ));
    }
}

/// The files a path names: the file, or a folder's entries and those of its
/// subfolders (an exam's `variant-NN/`): the command's inputs, which
/// `--csv` and `--report` must not overwrite.
pub(crate) fn input_paths(path: &PathBuf) -> Vec<PathBuf> {
    match std::fs::read_dir(path) {
        Ok(rd) => rd
            .filter_map(|e| e.ok().map(|e| e.path()))
            .flat_map(|p| match p.is_dir() {
                true => std::fs::read_dir(&p)
                    .map(|rd| rd.filter_map(|e| e.ok().map(|e| e.path())).collect())
                    .unwrap_or_default(),
                false => vec![p],
            })
            .collect(),
        Err(_) => vec![path.clone()],
    }
}

/// `--tolerance` must be a finite number ≥ 0.
pub(crate) fn valid_tolerance(t: Option<f64>) -> Result<()> {
    match t {
        Some(t) if !(t.is_finite() && t >= 0.0) => Err(Error::why(
            "tolerance",
            ErrMsg::MustBe(Bound::FiniteAtLeastZero, t),
        )),
        _ => Ok(()),
    }
}
