//! The words of the report writers' own headings, columns and notes (class
//! report, practice, check, Moodle, GIFT, …): one method per writer's key
//! enum (`crate::msg::report`), and per tutor enum a writer names, each one
//! exhaustive match in every language. The language-neutral parts (a
//! number written in a language's style) are plain functions here.

use crate::msg::{
    BenchWord, CheckWord, ClassWord, CliWord, DocWord, PracticeWord, QuizWord, StatWord,
};
use crate::num::format::fmt_dec;
use crate::report::lang::NumStyle;
use crate::tutor::class::stats::Flag;
use crate::tutor::check::Verdict;
use crate::tutor::class::{Note, Skip};
use crate::tutor::diagnose::Mistake;
use crate::tutor::practice::Summary;

/// The words of the report writers' own headings, columns and notes.
pub trait ReportWords {
    /// A word of the class report.
    fn class(&self, w: &ClassWord) -> String;
    /// What was done with an unusual answer file.
    fn note(&self, n: Note) -> &'static str;
    /// Why an entry of the answers folder was skipped.
    fn skip(&self, s: Skip) -> &'static str;
    /// A flag on a key of the class report.
    fn flag(&self, f: Flag) -> &'static str;
    /// A verdict on an answer (also a column of the class's tables).
    fn verdict(&self, v: Verdict) -> &'static str;
    /// A word of a marked answer file.
    fn check(&self, w: &CheckWord) -> String;
    /// A word the documents share.
    fn doc(&self, w: &DocWord) -> String;
    /// A word of a quiz (Moodle XML, GIFT).
    fn quiz(&self, w: &QuizWord) -> String;
    /// A word of the command line itself.
    fn cli(&self, w: CliWord) -> &'static str;
    /// A line of `render --stats`.
    fn stat(&self, w: StatWord) -> String;
    /// A word of `grafika bench`'s table.
    fn bench(&self, w: BenchWord) -> &'static str;
    /// What the student did, by a mistake of the catalog.
    fn mistake(&self, m: &Mistake) -> &'static str;
    /// A word of `grafika practice`.
    fn practice(&self, w: &PracticeWord) -> String;
    /// A practice session's summary: the points, the counts, the second
    /// tries (each line ends with a newline).
    fn practice_summary(&self, s: &Summary) -> String;
}

/// `x` with at most `digits` decimals, in `style`: `0.5` or `0,5`.
pub fn dec(x: f64, digits: usize, style: NumStyle) -> String {
    style.number(&fmt_dec(x, digits))
}

/// An exam's title: `name: topics (difficulty), seed s, variant v`, the
/// variant with its word.
pub fn exam_title(
    name: &str,
    (topics, difficulty): (&str, &str),
    seed: Option<u64>,
    variant: Option<(String, u32)>,
) -> String {
    format!(
        "{name}: {topics} ({difficulty}){}{}",
        seed.map(|s| format!(", seed {s}")).unwrap_or_default(),
        variant
            .map(|(word, v)| format!(", {word} {v}"))
            .unwrap_or_default()
    )
}
