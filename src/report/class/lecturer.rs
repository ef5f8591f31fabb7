//! The lecturer's report of a class (`grafika check … --answers DIR
//! --report FILE`): which keys the class gets wrong and which keys are
//! suspect, which mistakes explain it and who made them, the wrong answers
//! no mistake explains, and the score distribution; for an exam, per
//! problem and per variant. The numbers are the tutor's
//! ([`crate::tutor::class::stats`]); here they are only written, as one
//! HTML page (the histogram as SVG), Markdown, JSON or CSV (one row per
//! key), in either language. JSON and CSV keys never depend on the
//! language.

use crate::report::json::{exact_json, value_json};
use crate::report::lang::Lang;
use crate::report::mistakes::mistake_text;
use crate::report::writer::{self, ClassWriter};
use crate::tutor::check::{Settings, Verdict};
use crate::tutor::class::stats::{compare, Flag, Gap, Stats, StepRef};
use crate::tutor::class::Class;
use crate::tutor::class::ClassKey;
use serde_json::{json, Value};

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

/// A number rounded to 4 decimals for JSON (no float noise in a report).
fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

fn flag_code(f: Flag) -> &'static str {
    match f {
        Flag::VeryEasy => "very_easy",
        Flag::VeryHard => "very_hard",
        Flag::Negative => "negative",
    }
}

fn step_json(s: &Option<StepRef>, lang: Lang) -> Value {
    s.as_ref().map_or(Value::Null, |s| {
        json!({ "problem": s.part, "number": s.number, "title": crate::report::words::words(&s.title, lang) })
    })
}

/// The report as JSON (docs/spec.md §5): `students`, `keys`, `mistakes`,
/// `wrong_answers`, `histogram`, and `problems`, `variants`, `not_marked`.
pub fn to_json(class: &Class, s: &Stats, settings: &Settings, lang: Lang) -> Value {
    let keys: Vec<Value> = s.keys.iter().map(|k| {
        let counts: serde_json::Map<String, Value> = k.counts.iter().map(|(v, n)| (v.name().to_string(), json!(n))).collect();
        json!({
            "key": k.key, "students": k.students, "facility": round4(k.facility),
            "discrimination": k.discrimination.map(round4), "point_biserial": k.point_biserial.map(round4),
            "counts": counts, "flags": k.flags.iter().map(|f| flag_code(*f)).collect::<Vec<_>>(),
        })
    }).collect();
    let mistakes: Vec<Value> = s
        .mistakes
        .iter()
        .map(|m| {
            json!({
                "code": m.mistake, "description": mistake_text(m.mistake, lang),
                "students": m.students, "keys": m.keys,
                "also": m.also, "step": step_json(&m.step, lang),
            })
        })
        .collect();
    let wrong: Vec<Value> = s.wrong_answers.iter().map(|w| json!({
        "key": w.key, "variant": w.variant,
        "expected": w.expected.as_ref().map(|e| json!({ "decimal": value_json(e), "exact": exact_json(e) })),
        "values": w.values.iter().map(|v| json!({ "value": v.value, "count": v.students.len(), "students": v.students })).collect::<Vec<_>>(),
    })).collect();
    let variants: Vec<Value> = s.variants.iter().map(|v| json!({
        "variant": v.variant, "students": v.students, "facility": v.facility.map(round4),
        "problems": v.problems.iter().map(|c| json!({
            "problem": c.problem, "facility": c.facility.map(round4), "p_value": c.p_value.map(sig4),
            "flag": c.gap.map(|g| match g { Gap::Harder => "harder", Gap::Easier => "easier" }),
        })).collect::<Vec<_>>(),
    })).collect();
    json!({
        "command": "check",
        "report": "class",
        "title": class.title,
        "settings": { "tolerance": settings.tolerance, "sig_figs": settings.sig_figs, "follow_through": settings.follow_through },
        "students": s.students,
        "keys": keys,
        "mistakes": mistakes,
        "wrong_answers": wrong,
        "histogram": s.histogram.iter().map(|b| json!({ "from": b.from, "to": b.to, "count": b.count })).collect::<Vec<_>>(),
        "problems": s.problems.iter().map(|p| json!({ "problem": p.name, "title": p.title, "students": p.students, "facility": p.facility.map(round4) })).collect::<Vec<_>>(),
        "variants": variants,
        "variant_test": { "min_students": compare::MIN_STUDENTS, "level": compare::LEVEL },
        "roster": super::roster_json(class),
        "duplicates": class.sheets.iter().filter_map(|sh| sh.duplicate.as_ref().map(|(kept, why)| json!({
            "student": sh.who, "file": sh.file.display().to_string(), "kept": kept.display().to_string(), "same": why.code(),
        }))).collect::<Vec<_>>(),
        "fits": class.marked().filter_map(|sh| sh.fits.map(|f| json!({
            "student": sh.who, "file": sh.file.display().to_string(), "variant": super::variant_json(sh),
            "fits_variant": f.variant, "there": round4(f.there), "own": round4(f.own),
        }))).collect::<Vec<_>>(),
        "not_marked": class.sheets.iter().filter_map(|sh| sh.outcome.as_ref().err().map(|e| json!({
            "student": sh.who, "file": sh.file.display().to_string(),
            "error": { "field": e.field, "message": crate::report::words::words(&e.message, lang) },
        }))).collect::<Vec<_>>(),
    })
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
