//! A marking as text (a table, the diagnosis, the score) or as JSON for
//! autograders.

use crate::msg::CheckWord as K;
use crate::report::json::{as_map, both, Both};
use crate::report::lang::Lang;
use crate::report::words::{self, words};
use crate::report::{joined, Style};
use crate::tutor::check::{Marked, Marking, Settings, Verdict};
use crate::tutor::diagnose::Code;
use crate::tutor::key::Key;
use serde::Serialize;

/// A marking as JSON for autograders (docs/spec.md §5); an exam's
/// problem adds its `problem`, a class's lone sheet its `file`.
#[derive(Serialize)]
pub struct MarkingJson<'a> {
    command: &'static str,
    title: &'a str,
    who: &'a str,
    settings: &'a Settings,
    score: ScoreJson,
    #[serde(serialize_with = "as_map")]
    counts: Vec<(&'static str, usize)>,
    working: WorkingJson,
    answers: Vec<MarkedJson<'a>>,
    diagnosis: Vec<DiagnosisJson<'a>>,
    unknown_keys: &'a [String],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) problem: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) file: Option<String>,
}

/// A marking's score.
#[derive(Serialize)]
struct ScoreJson {
    points: f64,
    total: u32,
    fraction: f64,
    percent: f64,
    method: f64,
}

/// How many answers to keys not asked were given, and how many are right.
#[derive(Serialize)]
struct WorkingJson {
    answers: usize,
    correct: usize,
}

/// One answer marked.
#[derive(Serialize)]
struct MarkedJson<'a> {
    key: &'a Key,
    verdict: &'static str,
    code: &'static str,
    given: &'a Option<toml::Value>,
    expected: Option<Both>,
    note: String,
    diagnosis: &'a [Code],
    why: Option<String>,
    marks: Option<MarksJson>,
    method: &'a [Key],
}

/// The marks an answer earned of its worth.
#[derive(Serialize)]
struct MarksJson {
    earned: f64,
    of: u32,
}

/// A mistake found: its code, its words, the answers it reproduces.
#[derive(Serialize)]
pub(crate) struct DiagnosisJson<'a> {
    code: Code,
    mistake: &'static str,
    keys: &'a [Key],
    also: &'a [Code],
}

/// The marking as JSON for autograders.
pub fn to_json(m: &Marking, lang: Lang) -> MarkingJson<'_> {
    MarkingJson {
        command: "check",
        title: &m.title,
        who: &m.who,
        settings: &m.settings,
        score: ScoreJson {
            points: m.score(),
            total: m.total(),
            fraction: m.fraction(),
            percent: crate::report::words::report::percent(m.score(), m.total()),
            method: m.method_marks(),
        },
        counts: counts(m),
        working: WorkingJson {
            answers: m.working().count(),
            correct: m.working().filter(|a| a.verdict.is_correct()).count(),
        },
        answers: m.answers.iter().map(|a| answer_json(a, lang)).collect(),
        diagnosis: (m.diagnoses.iter())
            .map(|d| DiagnosisJson {
                code: d.mistake,
                mistake: crate::report::mistakes::mistake_text(d.mistake, lang),
                keys: &d.keys,
                also: &d.also,
            })
            .collect(),
        unknown_keys: &m.unknown,
        problem: None,
        file: None,
    }
}

/// One answer marked as JSON.
fn answer_json(a: &Marked, lang: Lang) -> MarkedJson<'_> {
    MarkedJson {
        key: &a.key,
        verdict: a.verdict.word(),
        code: a.verdict.name(),
        given: &a.given_value,
        expected: a.expected.as_ref().map(both),
        note: words(&a.note, lang),
        diagnosis: &a.diagnosis,
        why: a.why.as_ref().map(|w| words(w, lang)),
        marks: a.worth.map(|of| MarksJson {
            earned: a.earned,
            of,
        }),
        method: &a.method,
    }
}

/// The answers asked counted by verdict word, in the order of
/// [`Verdict::words`] (`correct`, `too_coarse`, …), then those credited by
/// follow-through (counted among the correct ones too).
fn counts(m: &Marking) -> Vec<(&'static str, usize)> {
    let mut counts: Vec<(&str, usize)> = (Verdict::words().into_iter())
        .map(|v| (v.word(), m.count(v)))
        .collect();
    counts.push(("follow_through", m.follow_through()));
    counts
}

/// One student's marking of a lone problem or an exam as text: a lone
/// problem (named "") as [`to_text`]; an exam's problems one after
/// another, each under `== problem-01 ==`.
pub fn marked_text(marked: &[(String, Marking)], style: &Style) -> String {
    match marked {
        [(name, m)] if name.is_empty() => to_text(m, style),
        _ => marked
            .iter()
            .map(|(name, m)| format!("== {name} ==\n{}", to_text(m, style)))
            .collect::<Vec<_>>()
            .join("\n"),
    }
}

/// One student's marking as JSON: a lone problem (named "") as
/// [`to_json`]; an exam's problems under `problems`, each with its
/// `problem`.
#[derive(Serialize)]
#[serde(untagged)]
pub enum MarkedFile<'a> {
    /// A lone problem's marking.
    One(MarkingJson<'a>),
    /// An exam's.
    Exam {
        command: &'static str,
        problems: Vec<MarkingJson<'a>>,
    },
}

/// One student's marking as JSON.
pub fn marked_json(marked: &[(String, Marking)], lang: Lang) -> MarkedFile<'_> {
    match marked {
        [(name, m)] if name.is_empty() => MarkedFile::One(to_json(m, lang)),
        _ => MarkedFile::Exam {
            command: "check",
            problems: problems_json(marked, lang),
        },
    }
}

/// An exam's markings, each with its `problem`.
pub(crate) fn problems_json(marked: &[(String, Marking)], lang: Lang) -> Vec<MarkingJson<'_>> {
    (marked.iter())
        .map(|(name, m)| MarkingJson {
            problem: Some(name),
            ..to_json(m, lang)
        })
        .collect()
}

/// A word of a marked answer file, in `style`'s language.
fn w(style: &Style, k: K) -> String {
    words::of(style.lang).check(&k)
}

/// The marking as text: a table of answers, the mistakes found, the score.
pub fn to_text(m: &Marking, style: &Style) -> String {
    use comfy_table::{presets, ContentArrangement, Table};
    let mut t = Table::new();
    let header = [
        K::Answer,
        K::Verdict,
        K::Marks,
        K::Given,
        K::Expected,
        K::Note,
    ];
    t.load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_width(120)
        .set_header(header.map(|k| w(style, k)));
    for a in &m.answers {
        t.add_row(vec![
            a.key.to_string(),
            words::of(style.lang).verdict(a.verdict).to_string(),
            marks_cell(a, style),
            a.given.clone().unwrap_or_else(|| "—".into()),
            a.expected
                .as_ref()
                .map(|e| expected_text(&a.key, e, style))
                .unwrap_or_default(),
            style.w(&a.note),
        ]);
    }
    let of = w(style, K::AnswersOf);
    let mut out = format!("{} — {of} {}\n{t}\n", m.title, m.who);
    let whys: Vec<String> = m
        .answers
        .iter()
        .filter_map(|a| (a.why.as_ref()).map(|why| format!("  • {}: {}\n", a.key, style.w(why))))
        .collect();
    if !whys.is_empty() {
        out.push_str(&format!("\n{}\n", w(style, K::Errata)));
        out.push_str(&whys.concat());
    }
    out.push_str(&method_text(m, style));
    out.push_str(&diagnoses_text(m, style));
    out.push_str(&score_text(m, style));
    out
}

/// An answer's marks: earned of its worth (`0.5/1`), or the word for
/// working, which the scheme does not count.
fn marks_cell(a: &Marked, style: &Style) -> String {
    match a.worth {
        Some(of) => format!("{}/{of}", marks(a.earned, style)),
        None => w(style, K::Working),
    }
}

/// Marks as shown: `2`, `0.5` (`0,5`).
fn marks(x: f64, style: &Style) -> String {
    style.nums.dec(x, 4)
}

/// The marks the working earned for values that are not right.
fn method_text(m: &Marking, style: &Style) -> String {
    let lines: Vec<String> = (m.asked())
        .filter(|a| !a.method.is_empty())
        .map(|a| {
            let earned = K::MethodEarned(marks(a.earned, style), a.worth.unwrap_or(0));
            format!(
                "  • {}: {} {}\n",
                a.key,
                w(style, earned),
                joined(&a.method)
            )
        })
        .collect();
    match lines.is_empty() {
        true => String::new(),
        false => format!("\n{}\n{}", w(style, K::MethodMarks), lines.concat()),
    }
}

/// The expected value as the text writes it: a clipping status in the
/// chosen language's word (`di-clip`), the code staying in the JSON.
fn expected_text(key: &Key, e: &crate::stages::trace::Val, style: &Style) -> String {
    use crate::stages::trace::Val;
    use crate::tutor::key::{Field, Value};
    match e {
        Val::Text(t) if key.value == Value::Field(Field::Status) => {
            style.val_inline(&Val::said(crate::msg::Said::Status(t.clone())))
        }
        _ => style.val_inline(e),
    }
}

/// The mistakes found, the wrong answers no mistake explains, the unknown keys.
fn diagnoses_text(m: &Marking, style: &Style) -> String {
    let t_ = |k| w(style, k);
    let mut out = String::new();
    if !m.diagnoses.is_empty() {
        out.push_str(&format!("\n{}\n", t_(K::Diagnosis)));
        for d in &m.diagnoses {
            out.push_str(&format!(
                "  • {} [{}]\n    {}: {}\n",
                crate::report::mistakes::mistake_text(d.mistake, style.lang),
                d.mistake,
                t_(K::Reproduces),
                joined(&d.keys)
            ));
            for a in &d.also {
                out.push_str(&format!(
                    "    ({}: {} [{}])\n",
                    t_(K::AlsoFollow),
                    crate::report::mistakes::mistake_text(*a, style.lang),
                    a
                ));
            }
        }
    }
    let undiagnosed: Vec<&Key> = m
        .answers
        .iter()
        // an erratum of the source (listed above) explains its printed answer
        .filter(|a| a.verdict == Verdict::Wrong && a.diagnosis.is_empty() && a.why.is_none())
        .map(|a| &a.key)
        .collect();
    if !undiagnosed.is_empty() {
        out.push_str(&format!(
            "\n{} {}\n",
            t_(K::NoMistakeExplains),
            joined(undiagnosed),
        ));
    }
    if !m.unknown.is_empty() {
        out.push_str(&format!(
            "\n{}: {}\n",
            t_(K::NotAnswers),
            m.unknown.join(", ")
        ));
    }
    out
}

/// The score line.
fn score_text(m: &Marking, style: &Style) -> String {
    let c = |v| m.count(v);
    let score = style.nums.dec(m.score(), 4);
    let said = words::of(style.lang);
    let counts: Vec<String> = (Verdict::words().into_iter())
        .map(|v| format!("{} {}", c(v), said.verdict(v)))
        .collect();
    let mut out = format!(
        "\n{}: {score}/{} = {} ({})\n",
        w(style, K::Score),
        m.total(),
        percent(m, style),
        counts.join(", ")
    );
    let n = m.follow_through();
    if n > 0 {
        out += &(w(style, K::FollowThroughCount(n)) + "\n");
    }
    let working: Vec<&Marked> = m.working().collect();
    if !working.is_empty() {
        let right = working.iter().filter(|a| a.verdict.is_correct()).count();
        out += &(w(style, K::WorkingCount(working.len(), right)) + "\n");
    }
    out
}

/// A share as a percentage to one decimal, without a trailing `.0`:
/// `100%`, `88.9%` (`88,9%`).
pub fn percent(m: &Marking, style: &Style) -> String {
    let p = crate::report::words::report::percent(m.score(), m.total());
    format!("{}%", style.nums.dec(p, 6))
}
