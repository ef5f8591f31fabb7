//! An exam as quiz blanks: every value a student types (each number of a
//! vector, matrix or segment, each outcode and status), with the key's value,
//! its absolute tolerance, and the mistaken values the catalog predicts with
//! the mistakes that give them. The Moodle XML and GIFT writers
//! (`report::moodle`, `report::gift`) only put these into words.
//!
//! Tolerance: a quiz system marks a number right when it lies within an
//! absolute tolerance t of the key's value x; t is the one rule `check` uses
//! ([`crate::tutor::check::tolerance`]).

use super::Generated;
use crate::input::problem::ProblemIn;
use crate::stages::trace::Val;
use crate::tutor::check::tolerance;
use crate::tutor::diagnose::{Mistake, Tree, CATALOG};
use crate::tutor::solve::lookup;

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
    /// The mistaken value.
    pub value: Typed,
    /// Its absolute tolerance (0 for text).
    pub tolerance: f64,
    /// The mistakes that give this value (they cannot be told apart by it).
    pub mistakes: Vec<&'static Mistake>,
}

/// One blank: the key's value, its tolerance, the known wrong values.
#[derive(Clone, Debug)]
pub struct Blank {
    /// The key's value.
    pub value: Typed,
    /// Its absolute tolerance (0 for text).
    pub tolerance: f64,
    /// The mistaken values, each apart from the key's and from each other.
    pub wrong: Vec<Wrong>,
}

/// One answer asked for (`view.u`): its value (for its shape) and its
/// blanks, in the order of the value's leaves (depth first).
#[derive(Clone, Debug)]
pub struct Asked {
    /// The answer key, as `grafika check` spells it.
    pub key: String,
    /// The exact value.
    pub value: Val,
    /// The blanks, one per leaf.
    pub blanks: Vec<Blank>,
}

/// The blanks of a generated problem with relative tolerance `rel` (> 0).
pub fn blanks(g: &Generated, rel: f64) -> Vec<Asked> {
    let trees = mistaken_trees(&g.problem);
    g.keys
        .iter()
        .filter_map(|key| {
            let value = lookup(&g.report.result, key)?.clone();
            let blanks = key_blanks(key, &value, &trees, rel);
            Some(Asked {
                key: key.clone(),
                value,
                blanks,
            })
        })
        .collect()
}

/// The results of every catalog mistake that applies to the problem.
fn mistaken_trees(p: &ProblemIn) -> Vec<(&'static Mistake, Tree)> {
    CATALOG
        .iter()
        .filter_map(|m| (m.apply)(p).map(|ts| (m, ts)))
        .flat_map(|(m, ts)| ts.into_iter().map(move |t| (m, t)))
        .collect()
}

/// The blanks of one answer: the key's leaves with their tolerances, and at
/// each leaf the mistaken values that differ from it (beyond both
/// tolerances: the intervals do not overlap), merged when two mistakes give
/// the same value.
fn key_blanks(key: &str, value: &Val, trees: &[(&'static Mistake, Tree)], rel: f64) -> Vec<Blank> {
    let right = typed_leaves(key, value, rel);
    let mut blanks: Vec<Blank> = right
        .into_iter()
        .map(|(value, tolerance)| Blank {
            value,
            tolerance,
            wrong: Vec::new(),
        })
        .collect();
    for (m, t) in trees {
        let Some(v) = lookup(t, key) else { continue };
        let leaves = typed_leaves(key, v, rel);
        if leaves.len() != blanks.len() {
            continue; // another shape (a rejected segment): not comparable
        }
        for (b, (w, wt)) in blanks.iter_mut().zip(leaves) {
            if apart(&b.value, b.tolerance, &w, wt) {
                add_wrong(b, w, wt, m);
            }
        }
    }
    blanks
}

/// Adds a mistaken value to a blank, or the mistake to the wrong value it
/// falls within.
fn add_wrong(b: &mut Blank, value: Typed, tolerance: f64, m: &'static Mistake) {
    match b
        .wrong
        .iter_mut()
        .find(|w| !apart(&w.value, w.tolerance, &value, tolerance))
    {
        Some(w) => {
            if !w.mistakes.iter().any(|x| x.code == m.code) {
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

/// Whether two values can be told apart: numbers whose tolerance intervals
/// [x − t, x + t] do not meet, or different texts.
fn apart(a: &Typed, ta: f64, b: &Typed, tb: f64) -> bool {
    match (a, b) {
        (Typed::Num(x), Typed::Num(y)) => (x - y).abs() > ta + tb,
        (Typed::Text(x), Typed::Text(y)) => x != y,
        _ => true,
    }
}

/// The leaves of a value, depth first, each with its absolute tolerance (see
/// the module docs); a non-finite number is no leaf a student could type, so
/// a value with one has no leaves.
pub fn typed_leaves(key: &str, v: &Val, rel: f64) -> Vec<(Typed, f64)> {
    let mut leaves = Vec::new();
    collect(v, &mut leaves);
    if leaves
        .iter()
        .any(|l| matches!(l, Typed::Num(x) if !x.is_finite()))
    {
        return Vec::new();
    }
    let scale = leaves
        .iter()
        .filter_map(|l| match l {
            Typed::Num(x) => Some(x.abs()),
            Typed::Text(_) => None,
        })
        .fold(0.0, f64::max);
    leaves
        .into_iter()
        .map(|l| {
            let t = match &l {
                Typed::Num(x) => tolerance::for_key(key, *x, scale, rel),
                Typed::Text(_) => 0.0,
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
}
