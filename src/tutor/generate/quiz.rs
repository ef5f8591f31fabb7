//! An exam as a quiz: every value a student types (each number of a
//! vector, matrix or segment, each outcode and status) is a blank, with the
//! key's value as the quiz writes it, its absolute tolerance, and the
//! mistaken values the catalog predicts with the mistakes that give them.
//! Everything is computed here; the Moodle XML and GIFT writers
//! (`report::moodle`, `report::gift`) only put it into words.
//!
//! Tolerance: a quiz system marks a number right when it lies within an
//! absolute tolerance of the value written; t is the one rule `check` uses
//! ([`crate::tutor::check::tolerance`]: r·|x|, a zero by its answer's
//! largest magnitude, a pixel position at least half a pixel).
//!
//! What a student is shown as the correct answer is the value written, so
//! the key is written to the significant figures the question asks for
//! plus one ([`sig_figs`] + 1: 5 at 0.1 %), a rounding a of the exact x, and
//! its tolerance widened by |a − x| so that the quiz accepts every number
//! `check` accepts: [x − t, x + t] ⊆ [a − t', a + t'] with t' = t + |a − x|
//! (at 0.1 %, |a − x| ≤ 5·10⁻⁵·|x|, a twentieth of t). Mistaken values are
//! written the same way.
//!
//! A number below what a student computes by hand is asked as 0: working
//! to the significant figures asked, a student resolves an answer to r·S,
//! S its scale ([`scale`]: the largest magnitude among the answer's
//! numbers; for a colour, at least 1, full intensity, whatever its
//! channels), so a number |x| < r·S (a zero included) is written 0 with the
//! tolerance r·S, which holds x too: 0 and x are both right. A specular
//! term of 1.6·10⁻¹⁰ (cos β⁸ of a far highlight) is asked as 0 ± 0.001;
//! `check`'s rule, r·|x|, would take nothing but 1.587·10⁻¹⁰ itself, so
//! the quiz accepts every number `check` accepts, and 0 besides.
//!
//! A mistaken value a student could not reasonably type is left out of its
//! blank: one that is not finite, or more than [`ABSURD`] times the larger
//! of the key's magnitude and its answer's scale: `tan 90°` for a window at
//! fovy = 90° gives 1.6·10¹⁶; a normal not divided by |N| raises a cos β
//! of 4 to the 8th, a colour channel of 58,465.

use super::{Generated, Topic};
use crate::input::problem::ProblemIn;
use crate::stages::trace::Val;
use crate::tutor::check::tolerance;
use crate::tutor::diagnose::{Code, Results};
use crate::tutor::key::{Field, Key, Part, Value};

/// A mistaken value more than this many times the larger of the key's
/// magnitude and its answer's scale is left out of its blank.
pub const ABSURD: f64 = 1e3;

/// A quiz: the problems of every variant with their blanks.
pub struct Quiz {
    /// `variants[v][i]`: problem i of variant v; problem i is on
    /// `topics[i % topics.len()]`.
    pub variants: Vec<Vec<Question>>,
    /// The topics, in the order the problems cycle through them.
    pub topics: Vec<Topic>,
    /// The relative tolerance r (> 0).
    pub rel: f64,
    /// The significant figures a student is asked to type ([`sig_figs`]).
    pub figures: u32,
}

/// One question: a generated problem and its blanks.
pub struct Question {
    /// The problem, its solution and the keys asked.
    pub problem: Generated,
    /// The answers asked, each with its blanks.
    pub asked: Vec<Asked>,
    /// What kinds of blanks it has (for the instruction line).
    pub typing: Typing,
}

impl Question {
    /// The question's marks: the scheme's total over the answers asked (a
    /// Moodle question's default mark).
    pub fn marks(&self) -> u32 {
        self.asked.iter().map(|a| a.marks).sum()
    }

    /// The weight of each answer's every blank, so that an answer weighs
    /// its marks whatever its number of blanks: an answer of m marks and k
    /// blanks needs a multiple of k/gcd(m, k) for m·L/k to be whole; with L
    /// the least common multiple of these over the answers, each of its
    /// blanks weighs m·L/k (n = (0.8, 0.6, 0) worth 1 and a status worth 1:
    /// L = 3, each of n's blanks 1, the status 3; n worth 3: L = 1). Moodle
    /// grades a Cloze question as Σ weight·fraction / Σ weight, so a right
    /// answer earns its share of the marks exactly.
    pub fn weights(&self) -> Vec<u32> {
        let count = |a: &Asked| a.blanks.len().max(1) as u32;
        let l = (self.asked.iter())
            .map(|a| count(a) / gcd(a.marks.max(1), count(a)))
            .fold(1, lcm);
        self.asked.iter().map(|a| a.marks * l / count(a)).collect()
    }
}

/// The greatest common divisor of two numbers.
fn gcd(mut x: u32, mut y: u32) -> u32 {
    while y != 0 {
        (x, y) = (y, x % y);
    }
    x
}

/// The least common multiple of two positive numbers.
fn lcm(a: u32, b: u32) -> u32 {
    a / gcd(a, b) * b
}

/// What kinds of blanks a question has, for its instruction line: the
/// rules of typing a pixel, an outcode or a status are stated only where
/// they are asked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Typing {
    /// Pixel positions.
    pub pixels: bool,
    /// Outcodes.
    pub outcodes: bool,
    /// A clipping status (and a segment that may be none).
    pub status: bool,
}

impl Typing {
    /// The kinds of the blanks asked.
    pub fn of(asked: &[Asked]) -> Typing {
        let any = |f: &dyn Fn(&Asked) -> bool| asked.iter().any(f);
        Typing {
            pixels: any(&|a| a.blanks.iter().any(|b| b.pixel)),
            outcodes: any(&|a| a.asks(&[Field::Code0, Field::Code1])),
            status: any(&|a| a.asks(&[Field::Status])),
        }
    }
}

impl Quiz {
    /// The quiz of the variants' exams (`exams[v][i]`) with relative
    /// tolerance `rel` (> 0).
    pub fn new(exams: Vec<Vec<Generated>>, topics: &[Topic], rel: f64) -> Quiz {
        let figures = sig_figs(rel);
        let variants = exams
            .into_iter()
            .map(|exam| {
                exam.into_iter()
                    .map(|g| {
                        let asked = blanks(&g, rel, figures + 1);
                        Question {
                            typing: Typing::of(&asked),
                            asked,
                            problem: g,
                        }
                    })
                    .collect()
            })
            .collect();
        Quiz {
            variants,
            topics: topics.to_vec(),
            rel,
            figures,
        }
    }

    /// The number of problems of each variant.
    pub fn count(&self) -> usize {
        self.variants.first().map_or(0, Vec::len)
    }

    /// The topic of problem i (from 0).
    pub fn topic(&self, i: usize) -> Topic {
        self.topics[i % self.topics.len().max(1)]
    }
}

/// The significant figures that keep a rounded decimal within the relative
/// tolerance r: n figures err by at most 5·10⁻ⁿ relatively, so n = ⌈log₁₀(5/r)⌉.
pub fn sig_figs(rel: f64) -> u32 {
    (5.0 / rel).log10().ceil().clamp(1.0, 15.0) as u32
}

/// What a student types into one blank.
#[derive(Clone, Debug, PartialEq)]
pub enum Typed {
    /// A number.
    Num(f64),
    /// A code or word (an outcode `000010`, a status `clipped`, `none`).
    Text(String),
}

/// A wrong value and the known mistakes that give it.
#[derive(Clone, Debug)]
pub struct Wrong {
    /// The mistaken value, as written (see the module docs).
    pub value: Typed,
    /// Its absolute tolerance (0 for text).
    pub tolerance: f64,
    /// The mistakes that give this value (they cannot be told apart by it).
    pub mistakes: Vec<Code>,
}

/// One blank: the key's value, its tolerance, the known wrong values.
#[derive(Clone, Debug)]
pub struct Blank {
    /// The key's value, as written (see the module docs).
    pub value: Typed,
    /// Its absolute tolerance (0 for text).
    pub tolerance: f64,
    /// Whether it is a pixel position (half a pixel is within tolerance).
    pub pixel: bool,
    /// The mistaken values, each apart from the key's and from each other.
    pub wrong: Vec<Wrong>,
}

/// One answer asked for (`view.u`): its value (for its shape) and its
/// blanks, in the order of the value's leaves (depth first).
#[derive(Clone, Debug)]
pub struct Asked {
    /// The answer key (`grafika check` spells it by its `Display`).
    pub key: Key,
    /// The exact value.
    pub value: Val,
    /// The blanks, one per leaf.
    pub blanks: Vec<Blank>,
    /// Its marks in the scheme ([`Generated::scheme`]).
    pub marks: u32,
}

impl Asked {
    /// Whether it asks one of the clip's `fields` (of any segment).
    fn asks(&self, fields: &[Field]) -> bool {
        self.key.part == Some(Part::Clip)
            && matches!(self.key.value, Value::Field(f) if fields.contains(&f))
    }
}

/// The blanks of a generated problem with relative tolerance `rel` (> 0),
/// numbers written to `figs` significant figures.
pub fn blanks(g: &Generated, rel: f64, figs: u32) -> Vec<Asked> {
    let trees = mistaken_trees(&g.problem);
    g.keys
        .iter()
        .filter_map(|key| {
            let value = g.report.result.get(key)?.into_owned();
            let blanks = key_blanks(key, &value, &trees, rel, figs);
            Some(Asked {
                key: key.clone(),
                value,
                blanks,
                marks: g.scheme.item(key).map_or(1, |i| i.marks),
            })
        })
        .collect()
}

/// The results of every catalog mistake that applies to the problem.
fn mistaken_trees(p: &ProblemIn) -> Vec<(Code, Results)> {
    Code::all()
        .into_iter()
        .filter_map(|m| m.apply(p).map(|ts| (m, ts)))
        .flat_map(|(m, ts)| ts.into_iter().map(move |t| (m, t)))
        .collect()
}

/// The blanks of one answer: the key's leaves with their tolerances, and at
/// each leaf the mistaken values that differ from it (beyond both
/// tolerances: the intervals do not overlap) and are not absurd, merged
/// when two mistakes give the same value.
fn key_blanks(
    key: &Key,
    value: &Val,
    trees: &[(Code, Results)],
    rel: f64,
    figs: u32,
) -> Vec<Blank> {
    let right = typed_leaves(key, value, rel);
    let scale = scale(key, value);
    let mut blanks: Vec<Blank> = right
        .into_iter()
        .map(|(value, tolerance)| {
            let (value, tolerance) = by_hand(value, tolerance, scale * rel);
            let (value, tolerance) = written(value, tolerance, figs);
            Blank {
                value,
                tolerance,
                pixel: tolerance::is_pixel(key),
                wrong: Vec::new(),
            }
        })
        .collect();
    for (m, t) in trees {
        let Some(v) = t.get(key) else { continue };
        let leaves = typed_leaves(key, &v, rel);
        if leaves.len() != blanks.len() {
            continue; // another shape (a rejected segment): not comparable
        }
        for (b, (w, wt)) in blanks.iter_mut().zip(leaves) {
            if absurd(&b.value, &w, scale) {
                continue;
            }
            let (w, wt) = written(w, wt, figs);
            if apart(&b.value, b.tolerance, &w, wt) {
                add_wrong(b, w, wt, *m);
            }
        }
    }
    blanks
}

/// The scale S of an answer: the largest magnitude among its finite
/// numbers ([`tolerance::scale`]); for a colour (a lighting term, the
/// colour before and after clamping) at least 1, the full intensity of a
/// channel; 1 when the whole answer is zero.
pub fn scale(key: &Key, v: &Val) -> f64 {
    let largest = tolerance::scale(v);
    let colour = matches!(key.value, Value::Field(Field::Shading(s)) if s.is_colour());
    match (colour, largest > 0.0) {
        (true, _) => largest.max(1.0),
        (false, true) => largest,
        (false, false) => 1.0,
    }
}

/// A number as a student computes it by hand (see the module docs): below
/// `resolution` (r·S) it is 0, with that tolerance; otherwise as it is.
fn by_hand(v: Typed, t: f64, resolution: f64) -> (Typed, f64) {
    match v {
        Typed::Num(x) if x.abs() < resolution => (Typed::Num(0.0), t.max(resolution)),
        other => (other, t),
    }
}

/// Whether a mistaken value is no number a student would type: not finite,
/// or more than [`ABSURD`] times the larger of the key's magnitude and its
/// answer's scale.
fn absurd(key: &Typed, w: &Typed, scale: f64) -> bool {
    match (key, w) {
        (Typed::Num(x), Typed::Num(y)) => !y.is_finite() || y.abs() > ABSURD * x.abs().max(scale),
        _ => false,
    }
}

/// A value as the quiz writes it: a number rounded to `figs` significant
/// figures, its tolerance widened by the rounding (see the module docs).
fn written(v: Typed, t: f64, figs: u32) -> (Typed, f64) {
    match v {
        Typed::Num(x) => {
            let a = round_sig(x, figs);
            (Typed::Num(a), t + (a - x).abs())
        }
        text => (text, t),
    }
}

/// x rounded to n significant figures (through its decimal form, so the
/// same on every platform).
pub fn round_sig(x: f64, n: u32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let digits = n.saturating_sub(1) as usize;
    format!("{x:.digits$e}").parse().unwrap_or(x)
}

/// Adds a mistaken value to a blank, or the mistake to the wrong value it
/// falls within.
fn add_wrong(b: &mut Blank, value: Typed, tolerance: f64, m: Code) {
    match b
        .wrong
        .iter_mut()
        .find(|w| within(&value, &w.value, w.tolerance))
    {
        Some(w) => {
            if !w.mistakes.contains(&m) {
                w.mistakes.push(m);
            }
        }
        None => b.wrong.push(Wrong {
            value,
            tolerance,
            mistakes: vec![m],
        }),
    }
}

/// Whether a mistaken value is read by an answer already written (the
/// answer's own interval [x − t, x + t] holds it, or the same text): only
/// then does the answer's feedback name its mistake too, as a student who
/// makes that mistake and types its value gets that answer's feedback.
fn within(value: &Typed, written: &Typed, t: f64) -> bool {
    match (value, written) {
        (Typed::Num(y), Typed::Num(x)) => (y - x).abs() <= t,
        (Typed::Text(y), Typed::Text(x)) => x == y,
        _ => false,
    }
}

/// Whether two values can be told apart: numbers by the one tolerance rule
/// ([`tolerance::apart`]: their intervals [x − t, x + t] do not meet), or
/// different texts.
fn apart(a: &Typed, ta: f64, b: &Typed, tb: f64) -> bool {
    match (a, b) {
        (Typed::Num(x), Typed::Num(y)) => tolerance::apart(*x, ta, *y, tb),
        (Typed::Text(x), Typed::Text(y)) => x != y,
        _ => true,
    }
}

/// The leaves of a value, depth first, each with its absolute tolerance
/// (see the module docs); a non-finite number keeps a tolerance of 0 (it is
/// left out as absurd).
pub fn typed_leaves(key: &Key, v: &Val, rel: f64) -> Vec<(Typed, f64)> {
    let mut leaves = Vec::new();
    collect(v, &mut leaves);
    let scale = tolerance::scale(v);
    leaves
        .into_iter()
        .map(|l| {
            let t = match &l {
                Typed::Num(x) if x.is_finite() => tolerance::for_key(key, *x, scale, rel),
                _ => 0.0,
            };
            (l, t)
        })
        .collect()
}

fn collect(v: &Val, out: &mut Vec<Typed>) {
    match v {
        Val::Num(s) => out.push(Typed::Num(s.value)),
        Val::List(items) => items.iter().for_each(|x| collect(x, out)),
        Val::Map(kv) => kv.iter().for_each(|(_, x)| collect(x, out)),
        Val::Text(t) => out.push(Typed::Text(t.clone())),
        Val::Bool(b) => out.push(Typed::Text(b.to_string())),
        Val::Null => out.push(Typed::Text("none".into())),
        // Words beside the numbers are not asked.
        Val::Said(_) => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_within_both_tolerances_are_not_apart() {
        assert!(!apart(&Typed::Num(1.0), 0.001, &Typed::Num(1.0015), 0.001));
        assert!(apart(&Typed::Num(1.0), 0.001, &Typed::Num(1.0025), 0.001));
        assert!(apart(
            &Typed::Text("a".into()),
            0.0,
            &Typed::Text("b".into()),
            0.0
        ));
    }

    #[test]
    fn four_figures_for_a_tenth_of_a_percent() {
        assert_eq!(sig_figs(1e-3), 4);
        assert_eq!(sig_figs(1e-2), 3);
        assert_eq!(sig_figs(5e-3), 3);
    }

    #[test]
    fn a_written_key_covers_the_check_interval() {
        // (√2 − 1)/2 = 0.20710678…: 5 figures 0.20711, off by 3.2e-6
        let x = (2f64.sqrt() - 1.0) / 2.0;
        let (a, t) = written(Typed::Num(x), 1e-3 * x, 5);
        assert_eq!(a, Typed::Num(0.20711));
        assert!(0.20711 - t <= x - 1e-3 * x && 0.20711 + t >= x + 1e-3 * x);
        assert!(t < 1.02e-3 * x);
        assert_eq!(round_sig(-133.3249, 5), -133.32);
        assert_eq!(round_sig(0.0, 5), 0.0);
    }

    #[test]
    fn absurd_values_are_those_no_student_types() {
        let k = Typed::Num(0.5);
        // tan 90° in floating point: 1.633e16
        assert!(absurd(&k, &Typed::Num(0.5 * 1.633e16), 0.5));
        assert!(absurd(&k, &Typed::Num(f64::INFINITY), 0.5));
        assert!(absurd(&k, &Typed::Num(f64::NAN), 0.5));
        // 1,000 times the key, 500, is the last value kept
        assert!(!absurd(&k, &Typed::Num(-500.0), 0.5));
        assert!(absurd(&k, &Typed::Num(-501.0), 0.5));
        // a zero key goes by its answer's scale: a colour channel's is 1,
        // so 58,465 (a normal of length 3 not divided by |N|: cos β = 4,
        // 4⁸ = 65,536, times ks) is out, and 324.9 stays
        assert!(absurd(&Typed::Num(0.0), &Typed::Num(58465.0), 1.0));
        assert!(!absurd(&Typed::Num(0.0), &Typed::Num(324.94), 1.0));
        // a small component of a large vector goes by the vector
        assert!(!absurd(&Typed::Num(0.001), &Typed::Num(-2.0), 13.0));
    }

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn a_colour_has_the_scale_of_full_intensity() {
        let n = |x: f64| Val::num(&x);
        let l = |xs: &[Val]| Val::List(xs.to_vec());
        // specular = cos β⁸·ks ≈ 1.6·10⁻¹⁰ in each channel: scale 1
        let tiny = [n(1.6e-10), n(1.6e-10), n(1.6e-10)];
        assert_eq!(scale(&key("shade.specular"), &l(&tiny)), 1.0);
        // a vector keeps its own largest component
        let v = [n(0.0), n(-13.0), n(0.5)];
        assert_eq!(scale(&key("view.points.A"), &l(&v)), 13.0);
        // a colour brighter than 1 (before clamping) keeps its own
        assert_eq!(scale(&key("shade.unclamped"), &l(&[n(1.4), n(0.2)])), 1.4);
        // all zero: 1
        assert_eq!(scale(&key("view.u"), &l(&[n(0.0), n(0.0)])), 1.0);
    }

    #[test]
    fn a_number_below_the_resolution_asked_is_asked_as_zero() {
        // r·S = 0.001·1 for a colour: 1.5873·10⁻¹⁰ is 0 ± 0.001, and
        // both 0 and the value itself lie within it
        let (v, t) = by_hand(Typed::Num(1.5873e-10), 1.5873e-13, 1e-3);
        assert_eq!((v, t), (Typed::Num(0.0), 1e-3));
        assert!(1.5873e-10 <= t);
        // at the resolution and above: as it is
        assert_eq!(
            by_hand(Typed::Num(0.001), 1e-6, 1e-3),
            (Typed::Num(0.001), 1e-6)
        );
        // a zero takes the resolution as its tolerance (check's rule: r·S)
        assert_eq!(by_hand(Typed::Num(0.0), 0.0, 2e-4), (Typed::Num(0.0), 2e-4));
        // a word is no number
        let w = Typed::Text("clipped".into());
        assert_eq!(by_hand(w.clone(), 0.0, 1e-3), (w, 0.0));
    }
}
