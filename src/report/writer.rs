//! One interface for every format grafika writes: a type per format (text,
//! JSON, HTML, Markdown, LaTeX, TOML, Moodle XML, GIFT, CSV), each
//! implementing the traits of the things it can write. A format that
//! cannot write a thing does not implement its trait, so asking it to is a
//! compile error, never a runtime one:
//!
//! | trait | what | formats |
//! |---|---|---|
//! | [`SolutionWriter`] | a worked solution (`solve`, the calculator) | text, JSON, HTML |
//! | [`ExamWriter`] | an exam and its key (`generate`) | TOML, Markdown, LaTeX, HTML, JSON, Moodle XML, GIFT |
//! | [`QuizWriter`] | every variant of an exam in one quiz file | Moodle XML, GIFT |
//! | [`MarkingWriter`] | one student's marking (`check`) | text, JSON |
//! | [`MarksWriter`] | a class's marks, one row per sheet (`check --answers DIR`, `--csv`) | text, JSON, CSV |
//! | [`ClassWriter`] | the lecturer's report of a class (`check --report`) | HTML, Markdown, JSON, CSV |
//!
//! The command line asks a format for its writer once
//! (`cli::args::Format::writer`, [`lecturer::Format::writer`]); what
//! differs between formats (file names, one quiz file or a folder of
//! files, the note a format needs) is a method of the writer, not a
//! `match` on the format. The writers only regroup the functions of the
//! other modules of `report/`, which do the writing.

use crate::msg::{CliWord, QuizWord};
use crate::report::check::{marked_json, marked_text};
use crate::report::class::lecturer;
use crate::report::doc::Doc;
use crate::report::gift::{gift_units, GIFT};
use crate::report::lang::Lang;
use crate::report::moodle::{moodle_units, Written, XML};
use crate::report::quizfile::{Frame, Unit};
use crate::report::sheets::{exam_json, key_title, sheets};
use crate::report::{words, Report, Style};
use crate::tutor::check::{Marking, Settings};
use crate::tutor::class::stats::Stats;
use crate::tutor::class::Class;
use crate::tutor::generate::quiz::Quiz;
use crate::tutor::generate::Generated;

/// What every format has: the extension of the files it writes.
pub trait Writer {
    /// The extension of its files, without the dot (`md`, `tex`, `xml`).
    fn extension(&self) -> &'static str;
}

/// A worked solution: `solve` or a calculator command's report.
pub trait SolutionWriter: Writer {
    /// The whole solution as the format writes it.
    fn solution(&self, r: &Report, st: &Style) -> String;
}

/// One exam (one variant) as its sheets are written: its titles, its
/// seed and number, its problems.
pub struct ExamPaper<'a> {
    /// The exam's title with the seed (the key's, the JSON's).
    pub title: String,
    /// The question sheet's title (without the seed: anyone could
    /// regenerate the key from it).
    pub sheet_title: String,
    /// `--seed`.
    pub seed: u64,
    /// The variant's number, from 1.
    pub variant: u32,
    /// The problems drawn.
    pub problems: &'a [Generated],
}

/// An exam and its key (`generate`). Every format but a quiz writes each
/// variant as a folder of files: a problem file and a key file (TOML) per
/// problem, then the format's own sheets.
pub trait ExamWriter: Writer {
    /// The quiz's writer, when the format writes every variant into one
    /// quiz file (or a few, split by size) instead of a folder of files
    /// per variant.
    fn quiz(&self) -> Option<&dyn QuizWriter> {
        None
    }

    /// The names of one exam's sheets, beside its problem and key files.
    fn sheet_names(&self) -> Vec<String> {
        Vec::new()
    }

    /// One exam's sheets, (name, text), named as [`Self::sheet_names`].
    fn sheets(&self, _exam: &ExamPaper, _st: &Style) -> Vec<(String, String)> {
        Vec::new()
    }
}

/// Every variant of an exam as the questions of one quiz file, which a
/// size limit may split into several ([`crate::report::quizfile`]).
pub trait QuizWriter: Writer {
    /// The quiz's questions, each in the category it goes in.
    fn units(&self, q: &Quiz, w: &Written) -> Vec<Unit>;

    /// What comes before the questions of a file and after them.
    fn frame(&self) -> Frame;

    /// What the lecturer is told about the quiz, if anything.
    fn note(&self) -> Option<QuizWord> {
        None
    }

    /// The quiz file's name: `quiz.xml`, or file k (from 1) of a split
    /// quiz, `quiz-01.xml`.
    fn file_name(&self, k: Option<usize>) -> String {
        let ext = self.extension();
        match k {
            None => format!("quiz.{ext}"),
            Some(k) => format!("quiz-{k:02}.{ext}"),
        }
    }
}

/// One student's marking of a lone problem (named "") or of an exam's
/// problems (each named `problem-01`, …).
pub trait MarkingWriter: Writer {
    /// The whole marking.
    fn marking(&self, marked: &[(String, Marking)], st: &Style) -> String;
}

/// A class's marks: one row per answer file, marked or with its error.
pub trait MarksWriter: Writer {
    /// Every row, with the entries skipped (text, JSON) and the class
    /// list (JSON).
    fn marks(&self, class: &Class, lang: Lang) -> String;
}

/// The lecturer's report of a class (`check --answers DIR --report FILE`).
pub trait ClassWriter: Writer {
    /// The whole report.
    fn class_report(&self, class: &Class, stats: &Stats, settings: &Settings, st: &Style)
        -> String;
}

/// The worked solution as text (what `solve` prints).
pub struct Text;
/// JSON, pretty-printed, ending with a newline (docs/spec.md).
pub struct Json;
/// One self-contained HTML page, formulas in MathML.
pub struct Html;
/// GitHub-flavoured Markdown.
pub struct Markdown;
/// LaTeX that a plain `pdflatex` compiles.
pub struct Latex;
/// Only the problem files and the answer-key files (TOML).
pub struct Toml;
/// Moodle XML: one Cloze question per problem and variant.
pub struct Moodle;
/// GIFT: one question per value asked.
pub struct Gift;
/// CSV (RFC 4180, [`crate::report::csv`]).
pub struct Csv;

/// A JSON value as the files and standard output have it.
fn pretty(v: &impl serde::Serialize) -> String {
    serde_json::to_string_pretty(v).unwrap_or_default() + "\n"
}

impl Writer for Text {
    fn extension(&self) -> &'static str {
        "txt"
    }
}

impl SolutionWriter for Text {
    fn solution(&self, r: &Report, st: &Style) -> String {
        r.to_text(st)
    }
}

impl MarkingWriter for Text {
    fn marking(&self, marked: &[(String, Marking)], st: &Style) -> String {
        marked_text(marked, st)
    }
}

impl MarksWriter for Text {
    fn marks(&self, class: &Class, lang: Lang) -> String {
        crate::report::class::table(class, lang)
    }
}

impl Writer for Json {
    fn extension(&self) -> &'static str {
        "json"
    }
}

impl SolutionWriter for Json {
    fn solution(&self, r: &Report, st: &Style) -> String {
        pretty(&r.to_json(st.lang))
    }
}

impl ExamWriter for Json {
    fn sheet_names(&self) -> Vec<String> {
        vec!["exam.json".into()]
    }

    fn sheets(&self, exam: &ExamPaper, st: &Style) -> Vec<(String, String)> {
        let (title, seed, problems) = (&exam.title, exam.seed, exam.problems);
        let j = exam_json(title, seed, exam.variant, problems, st.lang);
        vec![("exam.json".into(), pretty(&j))]
    }
}

impl MarkingWriter for Json {
    fn marking(&self, marked: &[(String, Marking)], st: &Style) -> String {
        pretty(&marked_json(marked, st.lang))
    }
}

impl MarksWriter for Json {
    fn marks(&self, class: &Class, lang: Lang) -> String {
        pretty(&crate::report::class::json(class, lang))
    }
}

impl ClassWriter for Json {
    fn class_report(
        &self,
        class: &Class,
        stats: &Stats,
        settings: &Settings,
        st: &Style,
    ) -> String {
        pretty(&lecturer::to_json(class, stats, settings, st.lang))
    }
}

impl SolutionWriter for Html {
    /// The page, each part's figure under its heading.
    fn solution(&self, r: &Report, st: &Style) -> String {
        use crate::report::figure::{drawings::drawings, svg::to_svg};
        let figures: Vec<(String, String, String)> = drawings(r, st)
            .iter()
            .map(|d| (d.part.clone(), to_svg(d), d.title()))
            .collect();
        crate::report::page::report_page(r, st, &page_title(r, st), &figures)
    }
}

/// A solution page's title: the problem's title for `solve`, else the
/// command.
fn page_title(r: &Report, st: &Style) -> String {
    match r.title() {
        Some(t) => format!("grafika {}: {t}", r.command()),
        None => format!(
            "grafika {} — {}",
            r.command(),
            words::of(st.lang).cli(CliWord::WorkedSolution)
        ),
    }
}

/// A document format's sheets: `questions.EXT` and `key.EXT`.
fn doc_sheet_names(ext: &str) -> Vec<String> {
    vec![format!("questions.{ext}"), format!("key.{ext}")]
}

/// A document format's sheets: the questions and the key, with their
/// worked solutions.
fn doc_sheets(doc: Doc, ext: &str, exam: &ExamPaper, st: &Style) -> Vec<(String, String)> {
    let (q, k) = sheets(doc, exam.problems, st);
    let key = key_title(&exam.title, st.lang);
    vec![
        (
            format!("questions.{ext}"),
            doc.document(&exam.sheet_title, &q, st.lang),
        ),
        (format!("key.{ext}"), doc.document(&key, &k, st.lang)),
    ]
}

/// The exam and class report methods of a document format (`Doc`).
macro_rules! document_format {
    ($t:ty, $doc:expr, $ext:literal) => {
        impl Writer for $t {
            fn extension(&self) -> &'static str {
                $ext
            }
        }

        impl ExamWriter for $t {
            fn sheet_names(&self) -> Vec<String> {
                doc_sheet_names($ext)
            }

            fn sheets(&self, exam: &ExamPaper, st: &Style) -> Vec<(String, String)> {
                doc_sheets($doc, $ext, exam, st)
            }
        }
    };
}

document_format!(Html, Doc::Html, "html");
document_format!(Markdown, Doc::Markdown, "md");
document_format!(Latex, Doc::Latex, "tex");

impl ClassWriter for Html {
    fn class_report(
        &self,
        class: &Class,
        stats: &Stats,
        settings: &Settings,
        st: &Style,
    ) -> String {
        crate::report::class::page::document(Doc::Html, class, stats, settings, st)
    }
}

impl ClassWriter for Markdown {
    fn class_report(
        &self,
        class: &Class,
        stats: &Stats,
        settings: &Settings,
        st: &Style,
    ) -> String {
        crate::report::class::page::document(Doc::Markdown, class, stats, settings, st)
    }
}

impl Writer for Toml {
    fn extension(&self) -> &'static str {
        "toml"
    }
}

/// Only the problem and key files, which every folder format writes.
impl ExamWriter for Toml {}

impl Writer for Moodle {
    fn extension(&self) -> &'static str {
        "xml"
    }
}

impl ExamWriter for Moodle {
    fn quiz(&self) -> Option<&dyn QuizWriter> {
        Some(self)
    }
}

impl QuizWriter for Moodle {
    fn units(&self, q: &Quiz, w: &Written) -> Vec<Unit> {
        moodle_units(q, w)
    }

    fn frame(&self) -> Frame {
        XML
    }
}

impl Writer for Gift {
    fn extension(&self) -> &'static str {
        "gift"
    }
}

impl ExamWriter for Gift {
    fn quiz(&self) -> Option<&dyn QuizWriter> {
        Some(self)
    }
}

impl QuizWriter for Gift {
    fn units(&self, q: &Quiz, w: &Written) -> Vec<Unit> {
        gift_units(q, w)
    }

    fn frame(&self) -> Frame {
        GIFT
    }

    /// GIFT carries no files: the figures are in the Moodle XML only.
    fn note(&self) -> Option<QuizWord> {
        Some(QuizWord::FiguresInMoodle)
    }
}

impl Writer for Csv {
    fn extension(&self) -> &'static str {
        "csv"
    }
}

impl MarksWriter for Csv {
    fn marks(&self, class: &Class, lang: Lang) -> String {
        crate::report::class::csv(&class.sheets, class.exam, lang)
    }
}

impl ClassWriter for Csv {
    fn class_report(&self, _: &Class, stats: &Stats, _: &Settings, _: &Style) -> String {
        lecturer::to_csv(stats)
    }
}
