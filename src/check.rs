//! `grafika check`: marks a student's answers against grafika's exact
//! solution of a problem, and diagnoses wrong answers with the mistake
//! catalog ([`crate::diagnose`]).
//!
//! An answer is correct when it equals the exact value (any equivalent
//! form), when it is within the relative tolerance (0.1% by default;
//! absolute 1e-12 near zero), or when it is the exact value correctly
//! rounded to the decimal places the student wrote. A rounded decimal with
//! fewer significant figures than required is "too coarse".
//!
//! Verdicts and their stable codes (for autograders):
//!
//! | verdict | code | meaning | marks |
//! |---|---|---|---|
//! | correct | `correct.exact` | equal to the exact value (any equivalent form) | 1 |
//! | correct | `correct.tolerance` | within the relative tolerance | 1 |
//! | correct | `correct.rounded` | the exact value rounded to the digits written | 1 |
//! | too_coarse | `too_coarse` | right, but fewer significant figures than required | ½ |
//! | wrong | `wrong` | none of the above (diagnosed where a known mistake reproduces it) | 0 |
//! | missing | `missing` | no answer | 0 |
//! | unparseable | `unparseable` | not a number, list or code grafika can read | 0 |
//!
//! A list (a point, a segment) takes its worst component's verdict.

use crate::diagnose::{self, Mistake};
use crate::error::{Error, Result};
use crate::num::{parse_expr, Real, Shown};
use crate::problem::ProblemIn;
use crate::report::{exact_json, value_json, Style};
use crate::solve::{self, lookup};
use crate::trace::Val;
use serde_json::{json, Value};

/// A result tree: named values, as `solve` returns them.
pub type Tree = Vec<(String, Val)>;

/// Default relative tolerance (the usual default of online homework systems).
pub const DEFAULT_TOLERANCE: f64 = 1e-3;
/// Absolute tolerance used when the expected value is (near) zero.
pub const ZERO_TOLERANCE: f64 = 1e-12;
/// Default minimum significant figures of a rounded decimal answer.
pub const DEFAULT_SIG_FIGS: u32 = 2;

/// How answers are marked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Relative tolerance.
    pub tolerance: f64,
    /// Minimum significant figures of a decimal answer.
    pub sig_figs: u32,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            tolerance: DEFAULT_TOLERANCE,
            sig_figs: DEFAULT_SIG_FIGS,
        }
    }
}

/// The verdict on one answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Verdict {
    /// Right.
    Correct,
    /// Right, but rounded to fewer significant figures than required.
    TooCoarse,
    /// Could not be read as a number (or a list of them).
    Unparseable,
    /// Not the expected value.
    Wrong,
    /// Not answered.
    Missing,
}

impl Verdict {
    /// The verdict's word in output and JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Correct => "correct",
            Verdict::TooCoarse => "too_coarse",
            Verdict::Unparseable => "unparseable",
            Verdict::Wrong => "wrong",
            Verdict::Missing => "missing",
        }
    }
    /// Marks for the verdict: 1 correct, ½ too coarse, 0 otherwise.
    pub fn points(self) -> f64 {
        match self {
            Verdict::Correct => 1.0,
            Verdict::TooCoarse => 0.5,
            _ => 0.0,
        }
    }
}

/// A judged value (a number, or a list judged element by element).
#[derive(Clone, Debug, PartialEq)]
struct Judged {
    verdict: Verdict,
    /// The stable code: `correct.exact`, `correct.tolerance`,
    /// `correct.rounded`, `too_coarse`, `wrong`, `unparseable`, `missing`.
    code: &'static str,
    note: String,
}

impl Judged {
    fn new(verdict: Verdict, code: &'static str, note: impl Into<String>) -> Judged {
        Judged {
            verdict,
            code,
            note: note.into(),
        }
    }
}

/// The marking of one answer.
#[derive(Clone, Debug)]
pub struct Marked {
    /// The answer key (`view.points.A`).
    pub key: String,
    /// The verdict.
    pub verdict: Verdict,
    /// The stable code (see the module docs and README).
    pub code: &'static str,
    /// The answer as written, on one line (None when missing).
    pub given: Option<String>,
    /// The answer as given in the file.
    pub given_value: Option<toml::Value>,
    /// The expected value (None when grafika has no such answer).
    pub expected: Option<Val>,
    /// A short note: how it was judged, or what was expected.
    pub note: String,
    /// Codes of the mistakes that reproduce this (wrong) answer.
    pub diagnosis: Vec<&'static str>,
    /// Why the source's printed answer is wrong (its `[[errata]]`), when
    /// checking the source's own answers.
    pub why: Option<String>,
}

/// One mistake that explains some wrong answers.
#[derive(Clone, Debug)]
pub struct Diagnosis {
    /// The mistake.
    pub mistake: &'static Mistake,
    /// The answers it reproduces.
    pub keys: Vec<String>,
    /// Other mistakes that reproduce only some of these answers, with the
    /// same values (the answers given cannot tell them apart).
    pub also: Vec<&'static Mistake>,
}

/// The marking of a whole answer file.
#[derive(Clone, Debug)]
pub struct Marking {
    /// The problem's title.
    pub title: String,
    /// Whose answers (a file name, or "the text").
    pub who: String,
    /// Every answer, in key order: the expected ones, then extra ones given.
    pub answers: Vec<Marked>,
    /// The mistakes found, each once, with the answers they explain.
    pub diagnoses: Vec<Diagnosis>,
    /// Keys given that grafika does not compute (typos, unasked parts).
    pub unknown: Vec<String>,
    /// The settings used.
    pub settings: Settings,
}

impl Marking {
    /// Points earned.
    pub fn score(&self) -> f64 {
        self.answers.iter().map(|a| a.verdict.points()).sum()
    }
    /// Points possible.
    pub fn total(&self) -> usize {
        self.answers.len()
    }
    /// How many answers got the verdict.
    pub fn count(&self, v: Verdict) -> usize {
        self.answers.iter().filter(|a| a.verdict == v).count()
    }
}

/// The answer keys a problem expects by default: every answer of the parts
/// it solves, except the view matrix, the far-plane window and the clipping
/// intersections tried (checked when
/// given, not required).
pub fn default_keys(result: &Tree) -> Vec<String> {
    let mut keys = Vec::new();
    for (part, v) in result {
        match (part.as_str(), v) {
            ("clip", Val::List(items)) => {
                for (i, it) in items.iter().enumerate() {
                    if let Val::Map(kv) = it {
                        keys.extend(kv.iter().map(|(k, _)| format!("clip.{i}.{k}")));
                    }
                }
            }
            (_, Val::Map(kv)) => {
                for (k, x) in kv {
                    if k == "matrix" || k == "intersections" || k.starts_with("far_") {
                        continue;
                    }
                    match x {
                        Val::Map(inner) if k == "points" || k == "pixels" => {
                            keys.extend(inner.iter().map(|(n, _)| format!("{part}.{k}.{n}")))
                        }
                        _ => keys.push(format!("{part}.{k}")),
                    }
                }
            }
            _ => keys.push(part.clone()),
        }
    }
    keys
}

/// Answers keyed by dotted result keys, in the order given.
pub type Answers = Vec<(String, toml::Value)>;

/// Answers from a TOML table, flattened to dotted keys (`view.points.A`).
/// A top-level `student` string names the student and is not an answer.
pub fn answers_from_table(t: &toml::Table) -> (Option<String>, Answers) {
    let mut out = Vec::new();
    let mut student = None;
    for (k, v) in t {
        match (k.as_str(), v) {
            ("student", toml::Value::String(s)) => student = Some(s.clone()),
            _ => flatten(k, v, &mut out),
        }
    }
    (student, out)
}

fn flatten(key: &str, v: &toml::Value, out: &mut Vec<(String, toml::Value)>) {
    match v {
        toml::Value::Table(t) => {
            for (k, x) in t {
                flatten(&format!("{key}.{k}"), x, out);
            }
        }
        other => out.push((key.to_string(), other.clone())),
    }
}

/// Reads an answer file.
pub fn read_answers(path: &std::path::Path) -> Result<(Option<String>, Answers)> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::new("answers", format!("cannot read {}: {e}", path.display())))?;
    let t: toml::Table = toml::from_str(&text)
        .map_err(|e| crate::problem::toml_error(&path.display().to_string(), &text, &e))?;
    Ok(answers_from_table(&t))
}

/// The settings for a problem: the command line over the problem's `[check]`
/// over the defaults.
pub fn settings_for(p: &ProblemIn, tolerance: Option<f64>, sig_figs: Option<u32>) -> Settings {
    let c = p.check.clone().unwrap_or_default();
    Settings {
        tolerance: tolerance.or(c.tolerance).unwrap_or(DEFAULT_TOLERANCE).abs(),
        sig_figs: sig_figs.or(c.sig_figs).unwrap_or(DEFAULT_SIG_FIGS),
    }
}

/// Solves the problem exactly and marks the answers. With `from_text` the
/// answers are the source's printed ones: only those keys are marked, and a
/// wrong one gets the reason from the file's `[[errata]]`; otherwise the keys
/// expected are the problem's `[check] keys` (default: [`default_keys`]) plus
/// any other key given.
pub fn mark(
    p: &ProblemIn,
    who: &str,
    answers: &[(String, toml::Value)],
    settings: Settings,
    from_text: bool,
) -> Result<Marking> {
    let report = solve::solve::<Real>(p)?;
    let result = report.result;
    let keys: Vec<String> = if from_text {
        answers.iter().map(|(k, _)| k.clone()).collect()
    } else {
        let mut k = p
            .check
            .as_ref()
            .and_then(|c| c.keys.clone())
            .unwrap_or_else(|| default_keys(&result));
        for (given, _) in answers {
            if !k.contains(given) {
                k.push(given.clone());
            }
        }
        k
    };
    let mut marked = Vec::new();
    let mut unknown = Vec::new();
    for key in &keys {
        let given = answers.iter().find(|(k, _)| k == key).map(|(_, v)| v);
        let Some(expected) = lookup(&result, key) else {
            if given.is_some() {
                unknown.push(key.clone());
            }
            continue;
        };
        let j = match given {
            None => Judged::new(Verdict::Missing, "missing", "no answer given"),
            Some(g) => judge(g, expected, &settings, key, false),
        };
        let note = j.note;
        let why = match (from_text, p.errata.iter().find(|e| &e.key == key)) {
            (true, Some(e)) if j.verdict == Verdict::Wrong => Some(e.why.clone()),
            _ => None,
        };
        marked.push(Marked {
            key: key.clone(),
            verdict: j.verdict,
            code: j.code,
            given: given.map(written),
            given_value: given.cloned(),
            expected: Some(expected.clone()),
            note,
            diagnosis: vec![],
            why,
        });
    }
    let diagnoses = diagnose_all(p, answers, &mut marked, &settings);
    Ok(Marking {
        title: p.title.clone(),
        who: who.to_string(),
        answers: marked,
        diagnoses,
        unknown,
        settings,
    })
}

/// Runs every mistake of the catalog once and names, for each wrong
/// answer, the mistakes that reproduce it; a mistake is listed once with
/// all the answers it explains.
fn diagnose_all(
    p: &ProblemIn,
    answers: &[(String, toml::Value)],
    marked: &mut [Marked],
    settings: &Settings,
) -> Vec<Diagnosis> {
    let wrong: Vec<usize> = (0..marked.len())
        .filter(|&i| marked[i].verdict == Verdict::Wrong)
        .collect();
    if wrong.is_empty() {
        return vec![];
    }
    let mut out: Vec<Diagnosis> = Vec::new();
    for m in diagnose::CATALOG {
        let Some(variants) = (m.apply)(p) else {
            continue;
        };
        let mut explained: Vec<String> = Vec::new();
        for &i in &wrong {
            let key = &marked[i].key;
            let Some((_, given)) = answers.iter().find(|(k, _)| k == key) else {
                continue;
            };
            let Some(right) = &marked[i].expected else {
                continue;
            };
            // The mistake must change this answer, and the answer must then
            // be what the mistake gives.
            let hit = variants.iter().any(|tree| {
                lookup(tree, key).is_some_and(|mv| {
                    differs(mv, right)
                        && matches!(
                            judge(given, mv, settings, key, true).verdict,
                            Verdict::Correct | Verdict::TooCoarse
                        )
                })
            });
            if hit {
                marked[i].diagnosis.push(m.code);
                explained.push(key.clone());
            }
        }
        if !explained.is_empty() {
            out.push(Diagnosis {
                mistake: m,
                keys: explained,
                also: vec![],
            });
        }
    }
    // The mistakes that explain the most answers first; one whose answers
    // are all explained by an earlier one is named with it, not again.
    out.sort_by_key(|d| std::cmp::Reverse(d.keys.len()));
    let mut folded: Vec<Diagnosis> = Vec::new();
    for d in out {
        match folded
            .iter_mut()
            .find(|f| d.keys.iter().all(|k| f.keys.contains(k)))
        {
            Some(f) => f.also.push(d.mistake),
            None => folded.push(d),
        }
    }
    folded
}

/// Whether two values differ (numbers by more than a relative 1e-9).
fn differs(a: &Val, b: &Val) -> bool {
    match (a, b) {
        (Val::Num(x), Val::Num(y)) => {
            (x.value - y.value).abs() > 1e-9 * x.value.abs().max(y.value.abs()).max(1e-300)
        }
        (Val::List(xs), Val::List(ys)) => {
            xs.len() != ys.len() || xs.iter().zip(ys).any(|(x, y)| differs(x, y))
        }
        (Val::Map(xs), Val::Map(ys)) => {
            xs.len() != ys.len() || xs.iter().zip(ys).any(|((_, x), (_, y))| differs(x, y))
        }
        _ => a != b,
    }
}

/// A TOML answer as the student wrote it.
pub fn written(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Array(a) => {
            format!("({})", a.iter().map(written).collect::<Vec<_>>().join(", "))
        }
        other => other.to_string(),
    }
}

/// Judges a given answer against an expected value.
/// `carry`: also accept a decimal within one unit of its last written digit
/// (used when matching mistaken values: students carry rounded intermediate
/// values forward, as the text does with 2 × 0.041 = 0.082).
fn judge(given: &toml::Value, expected: &Val, s: &Settings, key: &str, carry: bool) -> Judged {
    match expected {
        Val::Num(e) => match scalar_text(given) {
            Some(t) => judge_number(&t, e, s, carry),
            None => Judged::new(Verdict::Unparseable, "unparseable", "expected one number"),
        },
        Val::List(items) => {
            let parts: Vec<toml::Value> = match given {
                toml::Value::Array(a) => a.clone(),
                toml::Value::String(t) => {
                    let inner = t
                        .trim()
                        .trim_start_matches(['(', '['])
                        .trim_end_matches([')', ']']);
                    crate::num::expr::split_top_level(inner)
                        .into_iter()
                        .map(|x| toml::Value::String(x.trim().to_string()))
                        .collect()
                }
                _ => {
                    return Judged::new(
                        Verdict::Unparseable,
                        "unparseable",
                        format!("expected a list of {} values", items.len()),
                    )
                }
            };
            // A projected point may be given as (xp, yp): zp = d is the plane.
            let prefix_ok = key.starts_with("project.") && parts.len() == items.len() - 1;
            if parts.len() != items.len() && !prefix_ok {
                return Judged::new(
                    Verdict::Wrong,
                    "wrong",
                    format!("expected {} values, got {}", items.len(), parts.len()),
                );
            }
            let nested = items.iter().any(|x| matches!(x, Val::List(_)));
            let label = |i: usize| {
                if nested {
                    format!("point {}", i + 1)
                } else if items.len() <= 3 {
                    ["x", "y", "z"][i].to_string()
                } else {
                    format!("component {}", i + 1)
                }
            };
            combine(
                parts
                    .iter()
                    .zip(items)
                    .map(|(g, e)| judge(g, e, s, key, carry))
                    .collect(),
                label,
            )
        }
        Val::Text(t) => {
            let g = scalar_text(given).unwrap_or_default();
            let g = g.trim();
            let same = if t.len() == 6 && t.chars().all(|c| c == '0' || c == '1') {
                // an outcode; a short binary number is padded on the left
                g.len() <= 6 && g.chars().all(|c| c == '0' || c == '1') && format!("{g:0>6}") == *t
            } else {
                g.eq_ignore_ascii_case(t)
            };
            if same {
                Judged::new(Verdict::Correct, "correct.exact", "")
            } else {
                Judged::new(Verdict::Wrong, "wrong", format!("expected {t}"))
            }
        }
        Val::Null => {
            let empty = match given {
                toml::Value::Array(a) => a.is_empty(),
                toml::Value::String(s) => {
                    matches!(
                        s.trim().to_lowercase().as_str(),
                        "" | "none" | "null" | "rejected"
                    )
                }
                _ => false,
            };
            if empty {
                Judged::new(Verdict::Correct, "correct.exact", "")
            } else {
                Judged::new(Verdict::Wrong, "wrong", "expected none (nothing is left)")
            }
        }
        Val::Bool(b) => {
            let g = scalar_text(given).unwrap_or_default().to_lowercase();
            let gb = matches!(g.as_str(), "true" | "yes" | "1");
            if gb == *b {
                Judged::new(Verdict::Correct, "correct.exact", "")
            } else {
                Judged::new(Verdict::Wrong, "wrong", format!("expected {b}"))
            }
        }
        Val::Map(_) => Judged::new(
            Verdict::Unparseable,
            "unparseable",
            "this key holds several answers: give them one by one",
        ),
    }
}

/// The text of a scalar TOML value.
fn scalar_text(v: &toml::Value) -> Option<String> {
    match v {
        toml::Value::String(s) => Some(s.clone()),
        toml::Value::Integer(i) => Some(i.to_string()),
        toml::Value::Float(f) => Some(format!("{f}")),
        toml::Value::Boolean(b) => Some(b.to_string()),
        _ => None,
    }
}

/// The verdict on a list: its worst element; the weakest kind of correct.
fn combine(parts: Vec<Judged>, label: impl Fn(usize) -> String) -> Judged {
    let worst = parts
        .iter()
        .map(|j| j.verdict)
        .max()
        .unwrap_or(Verdict::Correct);
    let rank = |c: &str| match c {
        "correct.exact" => 0,
        "correct.tolerance" => 1,
        _ => 2,
    };
    let code = if worst == Verdict::Correct {
        parts
            .iter()
            .map(|j| j.code)
            .max_by_key(|c| rank(c))
            .unwrap_or("correct.exact")
    } else {
        parts
            .iter()
            .find(|j| j.verdict == worst)
            .map(|j| j.code)
            .unwrap_or("wrong")
    };
    // The notes of the components that decided the verdict.
    let notes: Vec<String> = parts
        .iter()
        .enumerate()
        .filter(|(_, j)| {
            !j.note.is_empty()
                && if worst == Verdict::Correct {
                    j.code == code
                } else {
                    j.verdict == worst
                }
        })
        .map(|(i, j)| format!("{}: {}", label(i), j.note))
        .collect();
    // One note when every component says the same.
    let note = if !notes.is_empty()
        && parts.iter().all(|j| j.note == parts[0].note)
        && !parts[0].note.is_empty()
    {
        parts[0].note.clone()
    } else {
        notes.join("; ")
    };
    Judged::new(worst, code, note)
}

/// A plain decimal as written: (significant figures, exponent of the last
/// written digit), e.g. "0.041" → (2, −3), "-1.50e2" → (3, 0). None for
/// integers (taken as exact) and for expressions.
pub fn decimal_places(text: &str) -> Option<(u32, i32)> {
    let t = text.trim().trim_start_matches(['-', '−', '+']);
    let (mant, exp) = match t.find(['e', 'E']) {
        Some(i) => (&t[..i], t[i + 1..].parse::<i32>().ok()?),
        None => (t, 0),
    };
    let (int, frac) = mant.split_once('.')?;
    if !(int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit())) || int.len() + frac.len() == 0
    {
        return None;
    }
    let digits: String = format!("{int}{frac}");
    let sig = digits.trim_start_matches('0').len() as u32;
    Some((sig.max(1), exp - frac.len() as i32))
}

/// Judges one number written by the student against an expected number.
fn judge_number(text: &str, e: &Shown, s: &Settings, carry: bool) -> Judged {
    let t = text.trim();
    if t.is_empty() {
        return Judged::new(Verdict::Missing, "missing", "empty answer");
    }
    // A decimal comma (0,041) is a decimal point.
    let t = t.replace(',', ".");
    let expr = match parse_expr(&t) {
        Ok(x) => x,
        Err(m) => return Judged::new(Verdict::Unparseable, "unparseable", m),
    };
    let g = match expr.eval::<f64>() {
        Ok(v) => v,
        Err(m) => return Judged::new(Verdict::Unparseable, "unparseable", m),
    };
    let ev = e.value;
    let places = decimal_places(&t);
    let expected_txt = || {
        let st = Style {
            digits: 6,
            exact_mode: true,
        };
        format!("expected {}", st.num(e))
    };

    // 1. Exact equality, when both sides are exact.
    if let Some(ex) = &e.exact {
        if let (Ok(er), Ok(gr)) = (
            parse_expr(ex).and_then(|x| x.eval::<Real>()),
            expr.eval::<Real>(),
        ) {
            if er.is_exact() && gr.is_exact() {
                if er == gr {
                    return Judged::new(Verdict::Correct, "correct.exact", "exact");
                }
                if places.is_none() {
                    // an exact form that is not equal: only tolerance can save it
                    return within_tolerance(g, ev, s, places)
                        .unwrap_or_else(|| Judged::new(Verdict::Wrong, "wrong", expected_txt()));
                }
            }
        }
    }
    // Equal to 1e-12 (relative): exact, when exact arithmetic cannot decide
    // (a terminating decimal such as 0.6 = 3/5 is exact, however few digits).
    if (g - ev).abs() <= ZERO_TOLERANCE * ev.abs().max(1.0) {
        return Judged::new(Verdict::Correct, "correct.exact", "exact");
    }
    if let Some(j) = within_tolerance(g, ev, s, places) {
        return j;
    }
    // 3. Correctly rounded to the places written.
    if let Some((sig, last)) = places {
        let unit = if carry { 1.0 } else { 0.5 };
        let half = unit * 10f64.powi(last) * (1.0 + 1e-9);
        if (g - ev).abs() <= half {
            return if sig < s.sig_figs {
                Judged::new(
                    Verdict::TooCoarse,
                    "too_coarse",
                    format!(
                        "rounded to {sig} significant figure{}, at least {} required",
                        if sig == 1 { "" } else { "s" },
                        s.sig_figs
                    ),
                )
            } else {
                Judged::new(
                    Verdict::Correct,
                    "correct.rounded",
                    format!("rounded to {sig} significant figures"),
                )
            };
        }
    }
    Judged::new(Verdict::Wrong, "wrong", expected_txt())
}

/// The tolerance test: relative `s.tolerance` (absolute 1e-12 near zero).
fn within_tolerance(g: f64, ev: f64, s: &Settings, places: Option<(u32, i32)>) -> Option<Judged> {
    let tol = (s.tolerance * ev.abs()).max(ZERO_TOLERANCE);
    if (g - ev).abs() > tol {
        return None;
    }
    Some(match places {
        Some((sig, _)) if sig < s.sig_figs => Judged::new(
            Verdict::TooCoarse,
            "too_coarse",
            format!(
                "{sig} significant figure(s), at least {} required",
                s.sig_figs
            ),
        ),
        _ => Judged::new(
            Verdict::Correct,
            "correct.tolerance",
            format!("within {}%", fmt_pct(s.tolerance)),
        ),
    })
}

fn fmt_pct(t: f64) -> String {
    crate::report::fmt_dec(t * 100.0, 3)
}

/// The marking as JSON for autograders.
pub fn to_json(m: &Marking) -> Value {
    let answers: Vec<Value> = m
        .answers
        .iter()
        .map(|a| {
            json!({
                "key": a.key,
                "verdict": a.verdict.as_str(),
                "code": a.code,
                "given": a.given_value.as_ref().and_then(|g| serde_json::to_value(g).ok()),
                "expected": a.expected.as_ref().map(|e| json!({ "decimal": value_json(e), "exact": exact_json(e) })),
                "note": a.note,
                "diagnosis": a.diagnosis,
                "why": a.why,
            })
        })
        .collect();
    json!({
        "command": "check",
        "title": m.title,
        "who": m.who,
        "settings": { "tolerance": m.settings.tolerance, "sig_figs": m.settings.sig_figs },
        "score": { "points": m.score(), "total": m.total(),
                   "fraction": if m.total() == 0 { 1.0 } else { m.score() / m.total() as f64 } },
        "counts": {
            "correct": m.count(Verdict::Correct), "too_coarse": m.count(Verdict::TooCoarse),
            "wrong": m.count(Verdict::Wrong), "missing": m.count(Verdict::Missing),
            "unparseable": m.count(Verdict::Unparseable),
        },
        "answers": answers,
        "diagnosis": m.diagnoses.iter().map(|d| json!({
            "code": d.mistake.code, "mistake": d.mistake.description, "keys": d.keys,
            "also": d.also.iter().map(|a| a.code).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "unknown_keys": m.unknown,
    })
}

/// The marking as text: a table of answers, the mistakes found, the score.
pub fn to_text(m: &Marking, style: &Style) -> String {
    use comfy_table::{presets, ContentArrangement, Table};
    let mut t = Table::new();
    t.load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_width(120)
        .set_header(vec!["answer", "verdict", "given", "expected", "note"]);
    for a in &m.answers {
        t.add_row(vec![
            a.key.clone(),
            a.verdict.as_str().replace('_', " "),
            a.given.clone().unwrap_or_else(|| "—".into()),
            a.expected
                .as_ref()
                .map(|e| style.val_inline(e))
                .unwrap_or_default(),
            a.note.clone(),
        ]);
    }
    let mut out = format!("{} — answers of {}\n{t}\n", m.title, m.who);
    let whys: Vec<String> = m
        .answers
        .iter()
        .filter_map(|a| a.why.as_ref().map(|w| format!("  • {}: {w}\n", a.key)))
        .collect();
    if !whys.is_empty() {
        out.push_str("\nWhy the printed answers are wrong (the problem file's errata):\n");
        out.push_str(&whys.concat());
    }
    if !m.diagnoses.is_empty() {
        out.push_str("\nDiagnosis:\n");
        for d in &m.diagnoses {
            out.push_str(&format!(
                "  • {} [{}]\n    reproduces: {}\n",
                d.mistake.description,
                d.mistake.code,
                d.keys.join(", ")
            ));
            for a in &d.also {
                out.push_str(&format!(
                    "    (some of these also follow from: {} [{}])\n",
                    a.description, a.code
                ));
            }
        }
    }
    let undiagnosed: Vec<&str> = m
        .answers
        .iter()
        .filter(|a| a.verdict == Verdict::Wrong && a.diagnosis.is_empty())
        .map(|a| a.key.as_str())
        .collect();
    if !undiagnosed.is_empty() {
        out.push_str(&format!(
            "\nNo known mistake reproduces: {} (an arithmetic slip?)\n",
            undiagnosed.join(", ")
        ));
    }
    if !m.unknown.is_empty() {
        out.push_str(&format!(
            "\nNot answers to this problem (ignored): {}\n",
            m.unknown.join(", ")
        ));
    }
    out.push_str(&format!(
        "\nScore: {}/{} ({} correct, {} too coarse, {} wrong, {} missing, {} unparseable)\n",
        crate::report::fmt_dec(m.score(), 4),
        m.total(),
        m.count(Verdict::Correct),
        m.count(Verdict::TooCoarse),
        m.count(Verdict::Wrong),
        m.count(Verdict::Missing),
        m.count(Verdict::Unparseable)
    ));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(v: f64) -> Shown {
        Shown {
            value: v,
            exact: None,
            pretty: None,
        }
    }
    fn j(text: &str, v: f64) -> Judged {
        judge_number(text, &num(v), &Settings::default(), false)
    }

    #[test]
    fn places_written() {
        assert_eq!(decimal_places("0.041"), Some((2, -3)));
        assert_eq!(decimal_places("-0.0283"), Some((3, -4)));
        assert_eq!(decimal_places("1.50e2"), Some((3, 0)));
        assert_eq!(decimal_places("12"), None);
        assert_eq!(decimal_places("-6/sqrt(2)"), None);
    }

    #[test]
    fn verdicts_on_numbers() {
        // tan 22.5° = √2 − 1, so 0.1·tan 22.5° = 0.0414213562...
        let top = 0.1 * (2f64.sqrt() - 1.0);
        assert_eq!(j("0.041", top).code, "correct.rounded"); // |0.041 − top| = 0.00042 ≤ 0.0005
        assert_eq!(j("0.0414", top).code, "correct.tolerance"); // 0.05% off
        assert_eq!(j("0.04", top).verdict, Verdict::TooCoarse); // 1 significant figure
        assert_eq!(j("0.042", top).verdict, Verdict::Wrong); // 1.4% off, not the rounding
        assert_eq!(j("0,041", top).code, "correct.rounded"); // decimal comma
                                                             // −6/√2 = −3√2, written either way
        let a = -6.0 / 2f64.sqrt();
        assert_eq!(j("-3*sqrt(2)", a).code, "correct.exact");
        assert_eq!(j("-3√2", a).code, "correct.exact");
        assert_eq!(j("-4.24", a).code, "correct.tolerance"); // 0.06% off
        assert_eq!(j("-4.2", a).code, "correct.rounded");
        assert_eq!(j("1/(", a).verdict, Verdict::Unparseable);
        assert_eq!(j("", a).verdict, Verdict::Missing);
        // near zero: absolute 1e-12
        assert_eq!(j("0", 1e-15).verdict, Verdict::Correct);
        assert_eq!(j("0.001", 0.0).verdict, Verdict::Wrong);
    }

    #[test]
    fn lists_and_codes() {
        let s = Settings::default();
        let e = Val::List(vec![Val::Num(num(0.02)), Val::Num(num(-0.0282842712))]);
        let g: toml::Value = toml::Value::Array(vec!["0.0067".into(), "-0.0283".into()]);
        let r = judge(&g, &e, &s, "project.points.B", false);
        assert_eq!(r.verdict, Verdict::Wrong);
        let ok: toml::Value = "(1/50, -sqrt(2)/50)".into();
        assert_eq!(
            judge(&ok, &e, &s, "project.points.B", false).verdict,
            Verdict::Correct
        );
        let code = Val::text("000010");
        assert_eq!(
            judge(&"10".into(), &code, &s, "clip.code0", false).verdict,
            Verdict::Correct
        );
        assert_eq!(
            judge(&"010000".into(), &code, &s, "clip.code0", false).verdict,
            Verdict::Wrong
        );
    }
}
