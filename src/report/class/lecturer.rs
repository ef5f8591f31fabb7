//! The lecturer's report of a class (`grafika check … --answers DIR
//! --report FILE`): which keys the class gets wrong and which keys are
//! suspect, which mistakes explain it and who made them, the wrong answers
//! no mistake explains, and the score distribution; for an exam, per
//! problem and per variant. The numbers are the tutor's
//! ([`crate::tutor::class::stats`]); here they are only written, as one
//! HTML page (the histogram as SVG), Markdown, JSON or CSV (one row per
//! key), in either language. JSON and CSV keys never depend on the
//! language.

use super::{round4, RosterJson};
use crate::report::json::{as_map, both, Both, Fault};
use crate::report::lang::Lang;
use crate::report::mistakes::mistake_text;
use crate::report::writer::{self, ClassWriter};
use crate::tutor::check::{Settings, Verdict};
use crate::tutor::class::stats::{compare, Bin, Flag, Gap, KeyStats, MistakeStats, Stats};
use crate::tutor::class::stats::{VariantStats, WrongAnswers};
use crate::tutor::class::Class;
use crate::tutor::class::ClassKey;
use crate::tutor::diagnose::Code;
use serde::Serialize;

/// The formats of a report, chosen by the file's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// `.html`: one self-contained page.
    Html,
    /// `.md`.
    Markdown,
    /// `.json`: the numbers for scripts.
    Json,
    /// `.csv`: one row per answer key.
    Csv,
}

impl Format {
    /// The format's writer: the one place a report's format is matched.
    pub fn writer(self) -> Box<dyn ClassWriter> {
        match self {
            Format::Html => Box::new(writer::Html),
            Format::Markdown => Box::new(writer::Markdown),
            Format::Json => Box::new(writer::Json),
            Format::Csv => Box::new(writer::Csv),
        }
    }

    /// The format of an extension (`html`, `htm`, `md`, `json`, `csv`).
    pub fn from_extension(ext: &str) -> Option<Format> {
        match ext {
            "html" | "htm" => Some(Format::Html),
            "md" => Some(Format::Markdown),
            "json" => Some(Format::Json),
            "csv" => Some(Format::Csv),
            _ => None,
        }
    }
}

/// A p-value to 4 significant digits (a small one is not rounded to 0).
fn sig4(x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    let scale = 10f64.powi(3 - x.log10().floor() as i32);
    (x * scale).round() / scale
}

fn flag_code(f: Flag) -> &'static str {
    match f {
        Flag::VeryEasy => "very_easy",
        Flag::VeryHard => "very_hard",
        Flag::Negative => "negative",
    }
}

/// The report as JSON (docs/spec.md §5): `students`, `keys`, `mistakes`,
/// `wrong_answers`, `histogram`, and `problems`, `variants`, `not_marked`;
/// each share rounded to 4 decimals, a p-value to 4 significant digits.
#[derive(Serialize)]
pub struct ReportJson<'a> {
    command: &'static str,
    report: &'static str,
    title: &'a str,
    settings: &'a Settings,
    students: usize,
    keys: Vec<KeyJson<'a>>,
    mistakes: Vec<MistakeJson<'a>>,
    wrong_answers: Vec<WrongJson<'a>>,
    histogram: &'a [Bin],
    problems: Vec<ProblemJson<'a>>,
    variants: Vec<VariantJson<'a>>,
    variant_test: VariantTest,
    roster: Option<RosterJson<'a>>,
    duplicates: Vec<DuplicateJson<'a>>,
    fits: Vec<FitsJson<'a>>,
    not_marked: Vec<NotMarkedJson<'a>>,
}

/// One answer key: how the class did on it.
#[derive(Serialize)]
struct KeyJson<'a> {
    key: &'a ClassKey,
    students: usize,
    facility: f64,
    discrimination: Option<f64>,
    point_biserial: Option<f64>,
    #[serde(serialize_with = "as_map")]
    counts: Vec<(&'static str, usize)>,
    flags: Vec<&'static str>,
}

/// A mistake made in the class: who made it, the keys it explains, the
/// step where it happens.
#[derive(Serialize)]
struct MistakeJson<'a> {
    code: Code,
    description: &'static str,
    students: &'a [String],
    keys: &'a [ClassKey],
    also: &'a [Code],
    step: Option<StepJson<'a>>,
}

/// The step of a worked solution where a mistake happens.
#[derive(Serialize)]
struct StepJson<'a> {
    problem: &'a str,
    number: usize,
    title: String,
}

/// The wrong answers to a key that no mistake explains.
#[derive(Serialize)]
struct WrongJson<'a> {
    key: &'a ClassKey,
    variant: Option<usize>,
    expected: Option<Both>,
    values: Vec<WrongValueJson<'a>>,
}

/// One wrong value, and who gave it.
#[derive(Serialize)]
struct WrongValueJson<'a> {
    value: &'a str,
    count: usize,
    students: &'a [String],
}

/// One problem of an exam.
#[derive(Serialize)]
struct ProblemJson<'a> {
    problem: &'a str,
    title: &'a str,
    students: usize,
    facility: Option<f64>,
}

/// One variant of an exam, and its problems against the class's.
#[derive(Serialize)]
struct VariantJson<'a> {
    variant: usize,
    students: usize,
    facility: Option<f64>,
    problems: Vec<VariantProblemJson<'a>>,
}

/// One problem of a variant.
#[derive(Serialize)]
struct VariantProblemJson<'a> {
    problem: &'a str,
    facility: Option<f64>,
    p_value: Option<f64>,
    flag: Option<Gap>,
}

/// When a variant's problem is compared with the class's.
#[derive(Serialize)]
struct VariantTest {
    min_students: usize,
    level: f64,
}

/// A sheet not counted: a copy of `kept`.
#[derive(Serialize)]
struct DuplicateJson<'a> {
    student: &'a str,
    file: String,
    kept: String,
    same: &'static str,
}

/// A sheet whose answers fit another variant's key.
#[derive(Serialize)]
struct FitsJson<'a> {
    student: &'a str,
    file: String,
    variant: super::VariantJson<'a>,
    fits_variant: usize,
    there: f64,
    own: f64,
}

/// A file that could not be marked.
#[derive(Serialize)]
struct NotMarkedJson<'a> {
    student: &'a str,
    file: String,
    error: Fault<'a>,
}

/// The report as JSON.
pub fn to_json<'a>(
    class: &'a Class,
    s: &'a Stats,
    settings: &'a Settings,
    lang: Lang,
) -> ReportJson<'a> {
    ReportJson {
        command: "check",
        report: "class",
        title: &class.title,
        settings,
        students: s.students,
        keys: s.keys.iter().map(key_json).collect(),
        mistakes: s.mistakes.iter().map(|m| mistake_json(m, lang)).collect(),
        wrong_answers: s.wrong_answers.iter().map(wrong_json).collect(),
        histogram: &s.histogram,
        problems: (s.problems.iter())
            .map(|p| ProblemJson {
                problem: &p.name,
                title: &p.title,
                students: p.students,
                facility: p.facility.map(round4),
            })
            .collect(),
        variants: s.variants.iter().map(variant_json).collect(),
        variant_test: VariantTest {
            min_students: compare::MIN_STUDENTS,
            level: compare::LEVEL,
        },
        roster: super::roster_json(class),
        duplicates: duplicates(class),
        fits: fits(class),
        not_marked: (class.sheets.iter())
            .filter_map(|sh| {
                let e = sh.outcome.as_ref().err()?;
                Some(NotMarkedJson {
                    student: &sh.who,
                    file: sh.file.display().to_string(),
                    error: super::fault(e, lang),
                })
            })
            .collect(),
    }
}

fn key_json(k: &KeyStats) -> KeyJson<'_> {
    KeyJson {
        key: &k.key,
        students: k.students,
        facility: round4(k.facility),
        discrimination: k.discrimination.map(round4),
        point_biserial: k.point_biserial.map(round4),
        counts: k.counts.iter().map(|(v, n)| (v.name(), *n)).collect(),
        flags: k.flags.iter().map(|f| flag_code(*f)).collect(),
    }
}

fn mistake_json(m: &MistakeStats, lang: Lang) -> MistakeJson<'_> {
    MistakeJson {
        code: m.mistake,
        description: mistake_text(m.mistake, lang),
        students: &m.students,
        keys: &m.keys,
        also: &m.also,
        step: m.step.as_ref().map(|s| StepJson {
            problem: &s.part,
            number: s.number,
            title: crate::report::words::words(&s.title, lang),
        }),
    }
}

fn wrong_json(w: &WrongAnswers) -> WrongJson<'_> {
    WrongJson {
        key: &w.key,
        variant: w.variant,
        expected: w.expected.as_ref().map(both),
        values: (w.values.iter())
            .map(|v| WrongValueJson {
                value: &v.value,
                count: v.students.len(),
                students: &v.students,
            })
            .collect(),
    }
}

fn variant_json(v: &VariantStats) -> VariantJson<'_> {
    VariantJson {
        variant: v.variant,
        students: v.students,
        facility: v.facility.map(round4),
        problems: (v.problems.iter())
            .map(|c| VariantProblemJson {
                problem: &c.problem,
                facility: c.facility.map(round4),
                p_value: c.p_value.map(sig4),
                flag: c.gap,
            })
            .collect(),
    }
}

/// The sheets not counted, each a copy of another.
fn duplicates(class: &Class) -> Vec<DuplicateJson<'_>> {
    (class.sheets.iter())
        .filter_map(|sh| {
            let (kept, why) = sh.duplicate.as_ref()?;
            Some(DuplicateJson {
                student: &sh.who,
                file: sh.file.display().to_string(),
                kept: kept.display().to_string(),
                same: why.code(),
            })
        })
        .collect()
}

/// The sheets marked whose answers fit another variant's key.
fn fits(class: &Class) -> Vec<FitsJson<'_>> {
    (class.marked())
        .filter_map(|sh| {
            let f = sh.fits?;
            Some(FitsJson {
                student: &sh.who,
                file: sh.file.display().to_string(),
                variant: super::variant_json(sh),
                fits_variant: f.variant,
                there: round4(f.there),
                own: round4(f.own),
            })
        })
        .collect()
}

/// The report as CSV: one row per key, with its counts by code, facility,
/// D, r, flags, the mistakes that explain it and how many wrong answers no
/// mistake explains.
pub fn to_csv(s: &Stats) -> String {
    let mut header: Vec<&str> = vec!["key", "students"];
    header.extend(Verdict::ALL.map(Verdict::name));
    header.extend([
        "facility",
        "discrimination",
        "point_biserial",
        "flags",
        "mistakes",
        "unexplained_wrong",
    ]);
    let opt = |x: Option<f64>| x.map(|x| round4(x).to_string()).unwrap_or_default();
    let rows: Vec<Vec<String>> = s
        .keys
        .iter()
        .map(|k| {
            let mut row = vec![k.key.to_string(), k.students.to_string()];
            row.extend(Verdict::ALL.map(|v| k.count(v).to_string()));
            row.extend([
                round4(k.facility).to_string(),
                opt(k.discrimination),
                opt(k.point_biserial),
                k.flags
                    .iter()
                    .map(|f| flag_code(*f))
                    .collect::<Vec<_>>()
                    .join(" "),
                explaining(s, &k.key).join(" "),
                unexplained(s, &k.key).to_string(),
            ]);
            row
        })
        .collect();
    crate::report::csv::write(&header, &rows)
}

/// The codes of the mistakes that explain a key.
fn explaining<'a>(s: &'a Stats, key: &ClassKey) -> Vec<&'a str> {
    s.mistakes
        .iter()
        .filter(|m| m.keys.iter().any(|k| k == key))
        .map(|m| m.mistake.as_str())
        .collect()
}

/// How many wrong answers to a key no mistake explains.
fn unexplained(s: &Stats, key: &ClassKey) -> usize {
    s.wrong_answers
        .iter()
        .filter(|w| w.key == *key)
        .flat_map(|w| &w.values)
        .map(|v| v.students.len())
        .sum()
}
