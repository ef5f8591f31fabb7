//! What `check --moodle-responses` writes besides the class's outputs: the
//! grades CSV for Moodle's gradebook import, and the notes on the report
//! (attempts marked, not finished, foreign questions, parts not read).
//!
//! The gradebook's CSV import (Grades → Import → CSV file) maps one column
//! to a user field (here "Email address", or "ID number") and any other
//! column to a grade item; the others are left unmapped. One row per
//! student: grafika's grade g = s / t · G (s the marks earned, t the marks
//! possible over the attempt's problems, G the quiz's maximum grade, the
//! report's `Grade/G` column), two decimals with a point, the form Moodle's
//! import reads; Moodle's own grade beside it for comparison. A student
//! with several finished attempts gets the highest, as the quiz's default
//! grading method does. Every cell goes through the CSV rules of
//! [`super::csv`] (a name that begins with `=` holds no formula).

use crate::input::moodle_responses::Responses;
use crate::msg::DocWord;
use crate::report::lang::Lang;
use crate::report::words;
use crate::tutor::class::moodle::{Findings, Given};
use crate::tutor::class::Sheet;

/// The columns of the grades CSV: Moodle's names of its identity fields,
/// then the grade item's column and Moodle's grade.
pub const HEADER: [&str; 5] = ["Email address", "ID number", "Name", "grafika", "Moodle"];

/// One student's grades: grafika's (out of `out_of`) and Moodle's.
#[derive(Clone, Debug, PartialEq)]
pub struct Grade {
    /// The email address.
    pub email: String,
    /// The ID number.
    pub id_number: String,
    /// The student's name.
    pub name: String,
    /// grafika's grade, out of the quiz's maximum grade.
    pub grafika: f64,
    /// Moodle's grade of the same attempt.
    pub moodle: Option<f64>,
}

/// Each student's grade, by the highest of their marked attempts (the
/// others are marked as another attempt of it: `class::moodle::sheets`).
pub fn grades(r: &Responses, given: &[Given], sheets: &[Sheet]) -> Vec<Grade> {
    let out_of = r.out_of.unwrap_or(100.0);
    (given.iter().zip(sheets))
        .filter(|(_, s)| s.duplicate.is_none())
        .filter_map(|(g, s)| {
            let (score, total) = (s.score()?, s.total()?);
            let a = &r.attempts[g.attempt];
            Some(Grade {
                email: a.email.clone(),
                id_number: a.id_number.clone(),
                name: g.who.clone(),
                grafika: score / f64::from(total.max(1)) * out_of,
                moodle: a.grade,
            })
        })
        .collect()
}

/// The grades CSV (RFC 4180, CRLF, formulas neutralised).
pub fn csv(grades: &[Grade]) -> String {
    let rows: Vec<Vec<String>> = grades
        .iter()
        .map(|g| {
            vec![
                g.email.clone(),
                g.id_number.clone(),
                g.name.clone(),
                format!("{:.2}", g.grafika),
                g.moodle.map(|m| format!("{m:.2}")).unwrap_or_default(),
            ]
        })
        .collect();
    super::csv::write(&HEADER, &rows)
}

/// The notes on a report, one line each, in the user's language.
pub fn notes(marked: usize, attempts: usize, f: &Findings, lang: Lang) -> Vec<String> {
    let w = |d: DocWord| words::of(lang).doc(&d);
    let mut out = vec![w(DocWord::MoodleMarked(marked, attempts))];
    out.extend(
        f.unfinished
            .iter()
            .map(|(who, st)| w(DocWord::MoodleUnfinished(who.clone(), st.clone()))),
    );
    out.extend(
        f.foreign
            .iter()
            .map(|(n, h)| w(DocWord::MoodleForeign(*n, h.clone()))),
    );
    out.extend(
        f.unreadable
            .iter()
            .map(|(who, k, t)| w(DocWord::MoodleUnreadable(who.clone(), k.clone(), t.clone()))),
    );
    out
}
