//! `grafika check`: marks a student's answers against grafika's exact
//! solution of a problem, and diagnoses wrong answers with the mistake
//! catalog ([`crate::tutor::diagnose`]). `practice` marks with the same
//! judge ([`Marker`]: one reader, [`crate::input::answer`], and one order of
//! judgment); the quiz exports give Moodle the same tolerance
//! ([`tolerance`]) and the same catalog's values.
//!
//! An answer is correct when it equals the exact value (any equivalent
//! form), when it is within the tolerance ([`tolerance::for_key`]: 0.1% by
//! default, a zero by its answer's largest magnitude, a pixel within half a
//! pixel) whatever figures it is written with, or when it is the exact
//! value correctly rounded to the digits written. A rounding outside the
//! tolerance with fewer significant figures than required is "too
//! coarse"; figures are counted from the value's leading digit. An answer
//! that is a catalog mistake's value is wrong and names the mistake.
//!
//! Verdicts ([`Verdict`]) and their stable codes (`Verdict::name`, for
//! autograders):
//!
//! | verdict | code | meaning | marks |
//! |---|---|---|---|
//! | correct | `correct.exact` | equal to the exact value (any equivalent form) | 1 |
//! | correct | `correct.tolerance` | within the tolerance | 1 |
//! | correct | `correct.rounded` | the exact value rounded to the digits written | 1 |
//! | correct | `correct.follow_through` | wrong, but right given the student's own earlier answers (`--follow-through`) | 1 |
//! | too_coarse | `too_coarse` | a rounding of the value, outside the tolerance, with fewer significant figures than required | ½ |
//! | wrong | `wrong` | none of the above (diagnosed where a known mistake reproduces it) | 0 |
//! | missing | `missing` | no answer | 0 |
//! | unparseable | `unparseable` | not a number, list or code grafika can read | 0 |
//!
//! A list (a point, a segment) takes its worst component's verdict.

mod judge;
mod marker;
mod plausible;
pub mod scheme;
mod sheet;
pub mod tolerance;
mod verdict;

pub(crate) use judge::printed_agrees;
pub use marker::{Follow, Judgement, Marker};
pub use verdict::Verdict;

use crate::error::Result;
use crate::input::answer::Read;
use crate::input::problem::ProblemIn;
use crate::stages::trace::Val;
use crate::tutor::diagnose::Code;
use crate::tutor::key::{Field, Key, Part, Shading, Value};
use crate::tutor::solution::One;

pub use crate::tutor::solution::Results;

/// Default relative tolerance (the usual default of online homework systems).
pub const DEFAULT_TOLERANCE: f64 = 1e-3;
/// Default minimum significant figures of a rounded decimal answer.
pub const DEFAULT_SIG_FIGS: u32 = 2;

/// How answers are marked.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Settings {
    /// Relative tolerance.
    pub tolerance: f64,
    /// Minimum significant figures of a decimal answer.
    pub sig_figs: u32,
    /// Credit a wrong answer that is right given the student's own earlier
    /// answers (`correct.follow_through`).
    pub follow_through: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            tolerance: DEFAULT_TOLERANCE,
            sig_figs: DEFAULT_SIG_FIGS,
            follow_through: false,
        }
    }
}

/// The marking of one answer.
#[derive(Clone, Debug)]
pub struct Marked {
    /// The answer key (`view.points.A`).
    pub key: Key,
    /// The verdict, with its stable code (see the module docs and README).
    pub verdict: Verdict,
    /// The answer as written, on one line (None when missing).
    pub given: Option<String>,
    /// The answer as given in the file.
    pub given_value: Option<toml::Value>,
    /// The expected value (None when grafika has no such answer).
    pub expected: Option<Val>,
    /// A short note: how it was judged, or what was expected.
    pub note: crate::msg::Msg,
    /// Codes of the mistakes that reproduce this (wrong) answer.
    pub diagnosis: Vec<Code>,
    /// Why the source's printed answer is wrong (its `[[errata]]`), when
    /// checking the source's own answers, or when the answer is the
    /// source's misprint (`copied_misprint`).
    pub why: Option<crate::msg::Msg>,
    /// The answer as read (None when missing or unreadable).
    pub read: Option<Read>,
    /// The marks the scheme gives this answer; None for working (an
    /// answer to a key the scheme does not ask: marked, never counted).
    pub worth: Option<u32>,
    /// The marks earned (method marks included); 0 for working.
    pub earned: f64,
    /// The working that earned method marks for this answer (when they
    /// are more than its own verdict's share).
    pub method: Vec<Key>,
}

impl Marked {
    /// Whether the scheme asks this answer (it counts in the total).
    pub fn asked(&self) -> bool {
        self.worth.is_some()
    }
}

/// One mistake that explains some wrong answers.
#[derive(Clone, Debug)]
pub struct Diagnosis {
    /// The mistake.
    pub mistake: Code,
    /// The answers it reproduces.
    pub keys: Vec<Key>,
    /// Other mistakes that reproduce only some of these answers, with the
    /// same values (the answers given cannot tell them apart).
    pub also: Vec<Code>,
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
    /// Keys given that grafika does not compute (typos, unasked parts): a
    /// key in its one spelling, a name that is no key as written.
    pub unknown: Vec<String>,
    /// The settings used.
    pub settings: Settings,
}

impl Marking {
    /// Marks earned: the scheme's answers' marks, method marks included.
    pub fn score(&self) -> f64 {
        self.asked().fold(0.0, |s, a| s + a.earned)
    }
    /// Marks possible: the scheme's total (of the answers marked: every
    /// key asked, or with the source's printed answers those printed).
    pub fn total(&self) -> u32 {
        self.asked().filter_map(|a| a.worth).sum()
    }
    /// The score as a share of the total (1 when nothing is worth marks).
    pub fn fraction(&self) -> f64 {
        match self.total() {
            0 => 1.0,
            t => self.score() / f64::from(t),
        }
    }
    /// The answers the scheme asks.
    pub fn asked(&self) -> impl Iterator<Item = &Marked> {
        self.answers.iter().filter(|a| a.asked())
    }
    /// The working: answers to keys the scheme does not ask.
    pub fn working(&self) -> impl Iterator<Item = &Marked> {
        self.answers.iter().filter(|a| !a.asked())
    }
    /// How many answers asked got the verdict's word (every correct one
    /// for a correct verdict).
    pub fn count(&self, v: Verdict) -> usize {
        self.asked().filter(|a| a.verdict.alike(v)).count()
    }
    /// How many answers asked were credited by follow-through (counted
    /// among the correct ones too).
    pub fn follow_through(&self) -> usize {
        self.asked()
            .filter(|a| a.verdict == Verdict::FollowThrough)
            .count()
    }
    /// The marks earned by working (method marks) beyond the answers' own.
    pub fn method_marks(&self) -> f64 {
        self.asked()
            .filter(|a| !a.method.is_empty())
            .fold(0.0, |s, a| {
                s + a.earned - scheme::share(a.verdict, a.worth.unwrap_or(0))
            })
    }
}

/// The answer keys a problem expects by default: every answer of the parts
/// it solves, except those `asked_by_default` leaves out, for each segment
/// of a clip with several as for a lone one.
pub fn default_keys(result: &Results) -> Vec<Key> {
    let mut keys = Vec::new();
    for p in &result.parts {
        let part = p.part();
        if !result.nested {
            let fields = p.one(None).map(One::entries).unwrap_or_default();
            keys.extend(fields.into_iter().map(|(f, _)| Key {
                part: None,
                segment: None,
                value: Value::Field(f),
                component: Vec::new(),
            }));
            continue;
        }
        for (segment, one) in p.segments() {
            for (f, x) in asked(one) {
                let of = |k: Key| k.of_segment(segment);
                keys.extend(field_keys(part, f, x).into_iter().map(of));
            }
        }
    }
    keys
}

/// The fields of a part (or a segment) asked by default.
fn asked(o: One<'_>) -> Vec<(Field, &Val)> {
    let fields = o.entries().into_iter();
    fields.filter(|(f, _)| asked_by_default(*f)).collect()
}

/// The keys of field `f` of a part: one per point or pixel of a map of
/// them, else the field's.
fn field_keys(part: Part, f: Field, x: &Val) -> Vec<Key> {
    let names = || crate::tutor::parts::names(Some(x));
    match (f, x) {
        (Field::Points, Val::Map(_)) => names().map(|n| Key::new(part, Value::Point(n))).collect(),
        (Field::Pixels, Val::Map(_)) => names().map(|n| Key::new(part, Value::Pixel(n))).collect(),
        _ => vec![Key::new(part, Value::Field(f))],
    }
}

/// Whether a part's field is asked by default (a final value of the
/// scheme): the view matrix, the far-plane window, the clipping
/// intersections tried, and a lighting problem's working (the unit
/// vectors, cos α, R, cos β, each term, their unclamped sum, a light's
/// factors) are marked when given, never counted; of a lighting problem
/// the colour is asked. An exhaustive match, so a new field is decided.
fn asked_by_default(f: Field) -> bool {
    match f {
        Field::Matrix | Field::Intersections | Field::Edge(_, true) | Field::Lights => false,
        Field::Shading(s) => s == Shading::Color,
        Field::Axis(_)
        | Field::Points
        | Field::Pixels
        | Field::Edge(_, false)
        | Field::Code0
        | Field::Code1
        | Field::Status
        | Field::Segment => true,
    }
}

/// The longest answer read, in characters (the longest expression the
/// number syntax takes, docs/spec.md §2): a longer one is `unparseable`
/// with the reason, and shown cut.
pub const MAX_ANSWER: usize = 4_000;

/// The length in characters of an answer's text (every part of a list).
pub(crate) fn answer_len(v: &toml::Value) -> usize {
    match v {
        toml::Value::String(s) => s.chars().count(),
        toml::Value::Array(a) => a.iter().map(answer_len).sum(),
        other => other.to_string().len(),
    }
}

/// A `[check] keys`' key read as a [`Key`]:
/// `clip[2].status` and `clip.2.status` alike, a whole part (`view`), one
/// component (`view.points.A.1`); a name that is no key is refused with
/// the name as written (`check` reports it unknown).
pub fn answer_key(name: &str) -> std::result::Result<Key, String> {
    name.parse().map_err(|_| name.to_string())
}

/// Answers by their names as given ([`Name`]), in the order given.
pub type Answers = Vec<(Name, toml::Value)>;

/// An answer's name as its file gives it: the names of the TOML tables
/// down to the answer (`view.points.A = …`, or `A = …` under
/// `[view.points]`, is `view`, `points`, `A`), read into a [`Key`] name by
/// name ([`Name::key`]); spelled with dots where it is shown. A name
/// grafika builds from a key it has (a Moodle blank's, [`Name::keyed`])
/// keeps the key typed, never spelled to be read back.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Name {
    /// The names as written; of a name grafika builds, those before its
    /// key (`problem-01`).
    names: Vec<String>,
    /// The answer key after the names, when grafika builds the name from
    /// a key it has in hand.
    key: Option<Key>,
}

impl Name {
    /// A name written on one line (`problem-01.view.u`): its names
    /// between the dots.
    pub fn parse(s: &str) -> Name {
        Name {
            names: s.split('.').map(str::to_string).collect(),
            key: None,
        }
    }

    /// The key `key` of the problem named `problem` (`problem-01` and
    /// `view.u`), as typed as it is.
    pub fn keyed(problem: &str, key: Key) -> Name {
        Name {
            names: vec![problem.to_string()],
            key: Some(key),
        }
    }

    /// This name with the TOML key `k` under it: a quoted key with dots
    /// (`"view.u"`) is its names as `view.u` is; an empty key at the top
    /// adds none.
    fn under(&self, k: &str) -> Name {
        let mut names = self.names.clone();
        if !(names.is_empty() && k.is_empty()) {
            names.extend(k.split('.').map(str::to_string));
        }
        Name {
            names,
            key: self.key.clone(),
        }
    }

    /// Whether it is the one name `s` (`nim`, `variant`).
    pub fn is(&self, s: &str) -> bool {
        self.key.is_none() && matches!(&self.names[..], [one] if one == s)
    }

    /// Its first name and the rest (`problem-01` and `view.u`); None for a
    /// lone name.
    pub fn split_first(&self) -> Option<(&str, Name)> {
        match &self.names[..] {
            [first, rest @ ..] if !rest.is_empty() || self.key.is_some() => {
                let rest = Name {
                    names: rest.to_vec(),
                    key: self.key.clone(),
                };
                Some((first, rest))
            }
            _ => None,
        }
    }

    /// The answer key it names; a name that is no key is refused as it is
    /// spelled (`check` reports it unknown).
    pub fn key(&self) -> std::result::Result<Key, String> {
        match &self.key {
            Some(key) if self.names.is_empty() => Ok(key.clone()),
            Some(_) => Err(self.to_string()),
            None => {
                Key::from_names(self.names.iter().map(String::as_str)).map_err(|_| self.to_string())
            }
        }
    }
}

impl std::fmt::Display for Name {
    /// The names joined by dots (`view.points.A`), the key after them.
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(&self.names.join("."))?;
        match (&self.key, self.names.is_empty()) {
            (Some(key), true) => write!(f, "{key}"),
            (Some(key), false) => write!(f, ".{key}"),
            (None, _) => Ok(()),
        }
    }
}

/// The longest student's name shown, in characters: a longer one (a
/// `student` of 1 MB in a class of 10,000 made a table of 658 MB) is cut to
/// its first 79 characters and `…` wherever it is shown: tables, CSV,
/// JSON and the class report.
pub const MAX_NAME: usize = 80;

/// A student's name as it is shown: at most [`MAX_NAME`] characters.
pub fn shown_name(name: &str) -> String {
    match name.char_indices().nth(MAX_NAME) {
        None => name.to_string(),
        Some(_) => {
            let cut = name.char_indices().nth(MAX_NAME - 1).map_or(0, |(i, _)| i);
            format!("{}…", &name[..cut])
        }
    }
}

/// Answers from a TOML table: each value that is no table, by its
/// [`Name`] (`view.points.A`). A top-level `student` string names the
/// student (as [`shown_name`] shows it) and is not an answer.
pub fn answers_from_table(t: &toml::Table) -> (Option<String>, Answers) {
    let mut out = Vec::new();
    let mut student = None;
    for (k, v) in t {
        match (k.as_str(), v) {
            ("student", toml::Value::String(s)) => student = Some(shown_name(s)),
            _ => leaves(Name::default().under(k), v, &mut out),
        }
    }
    (student, out)
}

/// A TOML table's values that are no tables, each by its [`Name`], in
/// order (an answer file's answers, a problem's `[printed]` answers).
pub fn named_leaves(t: &toml::Table) -> Answers {
    let mut out = Vec::new();
    for (k, v) in t {
        leaves(Name::default().under(k), v, &mut out);
    }
    out
}

/// The values under `name` that are no tables, each by its name, a
/// table's entries in order.
fn leaves(name: Name, v: &toml::Value, out: &mut Answers) {
    match v {
        toml::Value::Table(t) => t.iter().for_each(|(k, x)| leaves(name.under(k), x, out)),
        // a value at an empty name is named by the empty word
        other if name.names.is_empty() => out.push((Name::parse(""), other.clone())),
        other => out.push((name, other.clone())),
    }
}

/// Reads an answer file (at most [`crate::input::MAX_FILE`] bytes, refused
/// before it is read as TOML).
pub fn read_answers(path: &std::path::Path) -> Result<(Option<String>, Answers)> {
    let text = crate::input::read_text("answers", path)?;
    let origin = path.display().to_string();
    let t: toml::Table = crate::input::fields::parse_toml(&text, &origin)?;
    Ok(answers_from_table(&t))
}

/// The settings for a problem: the command line over the problem's `[check]`
/// over the defaults.
pub fn settings_for(p: &ProblemIn, tolerance: Option<f64>, sig_figs: Option<u32>) -> Settings {
    let c = p.check.clone().unwrap_or_default();
    Settings {
        tolerance: tolerance.or(c.tolerance).unwrap_or(DEFAULT_TOLERANCE).abs(),
        sig_figs: sig_figs.or(c.sig_figs).unwrap_or(DEFAULT_SIG_FIGS),
        follow_through: false,
    }
}

/// Solves the problem exactly and marks one answer sheet ([`Marker::mark`]);
/// a class is marked with one [`Marker`].
pub fn mark(
    p: &ProblemIn,
    who: &str,
    answers: &[(Name, toml::Value)],
    settings: Settings,
    from_text: bool,
) -> Result<Marking> {
    Ok(Marker::new(p, settings)?.mark(who, answers, from_text))
}

/// An answer's text as shown: a long one cut in the middle (at most 200
/// characters, the middle replaced by `…`).
pub(crate) fn shown_cut(s: &str) -> String {
    let n = s.chars().count();
    if n <= 200 {
        return s.to_string();
    }
    let head: String = s.chars().take(100).collect();
    let tail: String = s.chars().skip(n - 99).collect();
    format!("{head}…{tail}")
}

/// A TOML answer as it was written: a student's, or a source's printed
/// one (a list in brackets, a number or a word as TOML spells it).
pub fn written(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Array(a) => {
            format!("({})", a.iter().map(written).collect::<Vec<_>>().join(", "))
        }
        other => other.to_string(),
    }
}
