//! `grafika check EXAM --moodle-responses FILE`: a Moodle quiz made from
//! the exam (`generate --format moodle`, same seed and options), re-marked
//! from its Responses report. The attempts become the class's sheets
//! (`tutor::class::moodle`), marked and reported as a folder of answer
//! files is (`--csv`, `--report`, the rows); besides, the grades for
//! Moodle's gradebook (`--grades`), each student's marked sheet
//! (`--sheets DIR`) and, on standard error, what was not marked or read.

use crate::cli::args::CheckArgs;
use crate::cli::check::class_out;
use crate::cli::write::Outputs;
use crate::error::{Error, Result};
use crate::input::moodle_responses;
use crate::msg::ErrMsg;
use crate::report::moodle_grades;
use crate::report::writer::{self, MarkingWriter};
use crate::report::Style;
use crate::tutor::check::Settings;
use crate::tutor::class::{moodle, Class, Paper, Sheet};
use std::path::{Path, PathBuf};

/// Re-marks the report's attempts; returns the class's rows and the exit
/// status (2 when an attempt could not be marked).
pub fn run(
    paper: &Paper,
    file: &Path,
    settings: Settings,
    a: &CheckArgs,
    json: bool,
    style: &Style,
    outputs: &Outputs,
) -> Result<(String, i32)> {
    if !paper.exam {
        return Err(Error::why(
            "moodle-responses",
            ErrMsg::NoExam(a.file.display().to_string()),
        ));
    }
    let r = moodle_responses::read(file)?;
    let (drawn, given, mut findings) = moodle::given(paper, settings, &r)?;
    let sheets = moodle::sheets(&drawn, &r, &given, &mut findings);
    let paper = &drawn.paper;
    if let Some(g) = &a.grades {
        let grades = moodle_grades::grades(&r, &given, &sheets);
        outputs.write(g, "grades", moodle_grades::csv(&grades).as_bytes())?;
    }
    if let Some(dir) = &a.sheets {
        write_sheets(dir, &sheets, style, outputs)?;
    }
    let notes = moodle_grades::notes(given.len(), r.attempts.len(), &findings, style.lang);
    notes.iter().for_each(|n| crate::cli::print::stderr_line(n));
    let class = Class {
        title: paper.title.clone(),
        exam: true,
        sheets,
        skipped: Vec::new(),
        roster: None,
    };
    class_out(paper, &class, settings, a, json, style, outputs)
}

/// Each marked sheet as `check` prints it, to `DIR/NNN-name.txt` (NNN the
/// attempt's order in the report; the name kept to letters, digits, `-`
/// and `_`), all written or none.
fn write_sheets(dir: &Path, sheets: &[Sheet], style: &Style, outputs: &Outputs) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| crate::cli::write::cannot_write("sheets", dir, &e))?;
    let files: Vec<(PathBuf, String)> = sheets
        .iter()
        .enumerate()
        .filter_map(|(i, s)| {
            let parts = s.outcome.as_ref().ok()?;
            let text = format!("{}\n\n{}", s.who, writer::Text.marking(parts, style));
            Some((dir.join(format!("{:03}-{}.txt", i + 1, safe(&s.who))), text))
        })
        .collect();
    outputs.write_all(&files, "sheets")
}

/// A name as a file name: letters and digits kept, anything else `_`, at
/// most 40 characters.
fn safe(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .take(40)
        .collect()
}
