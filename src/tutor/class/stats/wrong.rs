//! What the class got wrong: each catalog mistake with its students, keys
//! and step, and the wrong answers no mistake explains, grouped when equal
//! within `check`'s tolerance.

use super::{answer, MistakeStats, Solved, StepRef, WrongAnswers, WrongValue};
use crate::input::answer::read as read_answer;
use crate::stages::trace::Val;
use crate::tutor::check::tolerance;
use crate::tutor::check::{written, Marked, Settings, Verdict};
use crate::tutor::class::{ClassKey, Paper, Sheet};
use crate::tutor::diagnose::Code;
use crate::tutor::key::Key;
use crate::tutor::practice::step_for;

/// Each catalog mistake named in the class with its students and keys, the
/// most students first (ties in the catalog's order).
pub(super) fn mistakes(
    sheets: &[&Sheet],
    keys: &[ClassKey],
    paper: &Paper,
    solved: &[Vec<Solved>],
) -> Vec<MistakeStats> {
    // each mistake with the variant of its first student and its last sheet
    let mut out: Vec<(MistakeStats, usize, usize)> = Vec::new();
    for (i, s) in sheets.iter().enumerate() {
        let v = s.variant.unwrap_or(1);
        for (problem, (_, m)) in s.outcome.iter().flatten().enumerate() {
            for d in &m.diagnoses {
                let at = out.iter().position(|(x, _, _)| x.mistake == d.mistake);
                let at = at.unwrap_or_else(|| {
                    let stats = MistakeStats {
                        mistake: d.mistake,
                        students: vec![],
                        keys: vec![],
                        also: vec![],
                        step: None,
                    };
                    out.push((stats, v, usize::MAX));
                    out.len() - 1
                });
                let (x, _, last) = &mut out[at];
                if *last != i {
                    x.students.push(s.who.clone());
                    *last = i;
                }
                for key in &d.keys {
                    let k = ClassKey {
                        problem: paper.problem(problem),
                        key: key.clone(),
                    };
                    if !x.keys.contains(&k) {
                        x.keys.push(k);
                    }
                }
                for a in &d.also {
                    if !x.also.contains(a) {
                        x.also.push(*a);
                    }
                }
            }
        }
    }
    let rank = |k: &ClassKey| keys.iter().position(|x| x == k).unwrap_or(usize::MAX);
    let catalog = |m: Code| Code::all().iter().position(|c| *c == m);
    for (x, v, _) in &mut out {
        x.keys.sort_by_key(|k| rank(k));
        x.step = x.keys.first().and_then(|k| {
            let parts = solved.get(*v - 1)?;
            made_step(x.mistake, k, parts).or_else(|| step_of(k, parts))
        });
    }
    let mut out: Vec<MistakeStats> = out.into_iter().map(|(x, _, _)| x).collect();
    out.sort_by_key(|x| (std::cmp::Reverse(x.students.len()), catalog(x.mistake)));
    out
}

/// The step of the worked solution where a mistake is made
/// ([`super::made`]), in the problem of the first key it spoils.
fn made_step(code: Code, key: &ClassKey, parts: &[Solved]) -> Option<StepRef> {
    let steps = &parts.get(key.problem.unwrap_or(0))?.steps;
    let i = super::made::step_made(code, steps)?;
    Some(StepRef {
        part: key.problem_name(),
        number: i + 1,
        title: steps[i].title.clone(),
    })
}

/// The step of the worked solution that computes a class key.
fn step_of(key: &ClassKey, parts: &[Solved]) -> Option<StepRef> {
    let steps = &parts.get(key.problem.unwrap_or(0))?.steps;
    let step = step_for(&key.key, steps)?;
    let number = steps.iter().position(|s| *s == step)? + 1;
    Some(StepRef {
        part: key.problem_name(),
        number,
        title: step.title,
    })
}

/// The wrong answers no mistake explains, per key (and variant), grouped
/// when equal within the tolerance, the most common first; the keys with
/// the most such answers first.
pub(super) fn wrong_answers(
    sheets: &[&Sheet],
    keys: &[ClassKey],
    paper: &Paper,
    settings: &Settings,
) -> Vec<WrongAnswers> {
    let several = paper.exam && paper.variants.len() > 1;
    let mut out: Vec<WrongAnswers> = Vec::new();
    for key in keys {
        for s in sheets {
            let Some(a) =
                answer(s, key).filter(|a| a.verdict == Verdict::Wrong && a.diagnosis.is_empty())
            else {
                continue;
            };
            let variant = s.variant_of(key.problem.unwrap_or(0)).filter(|_| several);
            let Some(given) = &a.given_value else {
                continue;
            };
            let at = out
                .iter()
                .position(|w| &w.key == key && w.variant == variant);
            let i = at.unwrap_or_else(|| {
                out.push(WrongAnswers {
                    key: key.clone(),
                    variant,
                    expected: a.expected.clone(),
                    values: vec![],
                });
                out.len() - 1
            });
            let w = &mut out[i];
            let same = |v: &WrongValue| same_value(&v.given, given, a, settings.tolerance);
            match w.values.iter_mut().find(|v| same(v)) {
                Some(v) => v.students.push(s.who.clone()),
                None => w.values.push(WrongValue {
                    value: written(given),
                    given: given.clone(),
                    students: vec![s.who.clone()],
                }),
            }
        }
    }
    for w in &mut out {
        w.values
            .sort_by_key(|v| std::cmp::Reverse(v.students.len()));
    }
    let most = |w: &WrongAnswers| w.values.iter().map(|v| v.students.len()).max().unwrap_or(0);
    out.sort_by_key(|w| std::cmp::Reverse(most(w)));
    out
}

/// Whether a wrong answer equals a group's value within the tolerance of
/// `check` ([`tolerance::for_key`], componentwise), or, for text, as written.
fn same_value(first: &toml::Value, given: &toml::Value, a: &Marked, rel: f64) -> bool {
    let like = a.expected.as_ref();
    let read = |v: &toml::Value| like.and_then(|e| read_answer(v, e).ok()).map(|r| r.value());
    match (read(first), read(given)) {
        (Some(x), Some(y)) => close(&x, &y, &a.key, rel),
        _ => written(first)
            .trim()
            .eq_ignore_ascii_case(written(given).trim()),
    }
}

fn close(x: &Val, y: &Val, key: &Key, rel: f64) -> bool {
    let (xs, ys) = (tolerance::numbers(key, x, rel), y.numbers());
    if xs.is_empty() || xs.len() != ys.len() {
        return x == y;
    }
    xs.iter().zip(&ys).all(|((a, t), b)| (a - b).abs() <= *t)
}
