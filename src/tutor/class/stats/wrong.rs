//! What the class got wrong: each catalog mistake with its students, keys
//! and step, and the wrong answers no mistake explains, grouped when equal
//! within `check`'s tolerance.

use super::{answer, MistakeStats, Solved, StepRef, WrongAnswers, WrongValue};
use crate::input::answer::Read;
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
            let read = a.read.as_ref().map(Read::value);
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
            let same = |v: &WrongValue| same_value(v, (&read, given), a, settings.tolerance);
            match w.values.iter_mut().find(|v| same(v)) {
                Some(v) => v.students.push(s.who.clone()),
                None => w.values.push(WrongValue {
                    value: written(given),
                    read,
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

/// Whether a wrong answer (`read` by marking, and as given) equals a
/// group's value within the tolerance of `check` ([`tolerance::for_key`],
/// componentwise), or, where either could not be read, as written.
fn same_value(
    group: &WrongValue,
    (read, given): (&Option<Val>, &toml::Value),
    a: &Marked,
    rel: f64,
) -> bool {
    match (&group.read, read) {
        (Some(x), Some(y)) => close(x, y, &a.key, rel),
        _ => group
            .value
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;
    use crate::tutor::check::{Answers, Name};
    use crate::tutor::class::{mark_given, markers};
    use std::path::PathBuf;

    /// The groups of wrong answers to `key` of a class whose students
    /// answer it `given`: each group's value as first written and its
    /// students; and how many texts grouping them parsed.
    fn groups(
        p: ProblemIn,
        key: &str,
        given: &[(&str, toml::Value)],
    ) -> (Vec<(String, Vec<String>)>, usize) {
        let paper = Paper::one(p);
        let settings = Settings::default();
        let sheets = mark_given(
            &paper,
            &markers(&paper, settings),
            given.iter().map(|(who, v)| {
                let answers: Answers = vec![(Name::parse(key), v.clone())];
                (PathBuf::from(who), who.to_string(), answers)
            }),
        );
        let sheets: Vec<&Sheet> = sheets.iter().collect();
        let keys = [ClassKey {
            problem: None,
            key: key.parse().expect("a key"),
        }];
        let parsed = || crate::num::expr::PARSED.with(std::cell::Cell::get);
        let before = parsed();
        let wrong = wrong_answers(&sheets, &keys, &paper, &settings);
        let parses = parsed() - before;
        let groups = (wrong[0].values.iter())
            .map(|v| (v.value.clone(), v.students.clone()))
            .collect();
        (groups, parses)
    }

    fn text(s: &str) -> toml::Value {
        toml::Value::String(s.into())
    }

    /// The wrong answers of a class are grouped by the values marking
    /// read: no answer is read again, and equal values group whatever
    /// their form.
    #[test]
    fn wrong_answers_group_what_marking_read_without_reading_again() {
        // Pe − Pr = (4, 3, 0), |Pe − Pr| = 5: n = (4/5, 3/5, 0); the wrong
        // (0.9, 0.6, 0) written three ways is one value, (0.5, 0.5, 0.5)
        // another; no mistake of the catalog gives either
        let p = "title = 't'\nask = ['view']\n\
            [camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n";
        let p = ProblemIn::parse(p, "t.toml").expect("parses");
        let list = |xs: [&str; 3]| toml::Value::Array(xs.iter().map(|x| text(x)).collect());
        let given = [
            ("A", text("(0.9, 0.6, 0)")),
            ("B", text("0,9; 0,6; 0")),
            ("C", list(["9/10", "3/5", "0"])),
            ("D", text("n = (0.5, 0.5, 0.5)")),
            ("E", text("(4/5, 3/5, 0)")),
        ];
        let (groups, parses) = groups(p, "view.n", &given);
        assert_eq!(parses, 0, "no answer is parsed again");
        let abc = ["A", "B", "C"].map(String::from).to_vec();
        assert_eq!(
            groups,
            [
                ("(0.9, 0.6, 0)".to_string(), abc),
                ("n = (0.5, 0.5, 0.5)".to_string(), vec!["D".to_string()])
            ]
        );
    }

    /// A projected point written (xp, yp) is the point (xp, yp, d) as
    /// marking reads it, so it groups with the same point written whole.
    #[test]
    fn a_projected_point_without_its_zp_groups_with_the_whole_point() {
        // the text's triangle: A in eye coordinates is (0, −1, −3√2) and
        // the near plane is z = −0.1, so d = −0.1, yp = d·y/z = −√2/60; the
        // wrong xp = 0.5 with and without zp = −0.1 is one value
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("problems")
            .join("text-triangle.toml");
        let p = ProblemIn::read(&path).expect("a shipped problem");
        let given = [
            ("A", text("(0.5, −√2/60)")),
            ("B", text("(0.5, −√2/60, −0.1)")),
        ];
        let (groups, _) = groups(p, "project.points.A", &given);
        let ab = ["A", "B"].map(String::from).to_vec();
        assert_eq!(groups, [("(0.5, −√2/60)".to_string(), ab)]);
    }
}
