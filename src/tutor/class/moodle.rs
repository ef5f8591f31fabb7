//! A Moodle quiz's attempts as a class's sheets: each finished attempt
//! becomes the answers an exam's answer file would hold (`variant = N`,
//! each problem's keys), so it is marked by the same judge, scheme,
//! follow-through and diagnosis as a folder of answer files.
//!
//! Which problem and variant a slot holds: the Responses report names no
//! question (a random slot draws one of the category's variants), but it
//! gives each slot's question text, which begins with the problem's
//! statement as `generate` writes it; a slot whose text begins with no
//! statement of the exam is a foreign question, listed and skipped. When
//! the report does not show the question text, slot i is problem i, which
//! only tells the variant when the exam has one.
//!
//! Which key a blank answers: a Cloze question's blanks are the scheme's
//! keys in order, each key's value's leaves depth first (the quiz's
//! `blanks`), so a key of k leaves takes the next k parts; a one-leaf key
//! is answered by its part's text, a vector or matrix by the list of its
//! parts, shaped as the key's value.

use super::{Markers, Paper, Sheet};
use crate::error::{Error, Result};
use crate::input::answer::number;
use crate::input::moodle_responses::{parts, Attempt, Responses};
use crate::msg::ErrMsg;
use crate::stages::trace::Val;
use crate::tutor::check::{Answers, Name, Settings};
use crate::tutor::class::same::Same;
use crate::tutor::generate::quiz::{typed_leaves, Typed};
use crate::tutor::key::Key;
use std::path::PathBuf;

/// What the marking of a Responses report found besides the marks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Findings {
    /// Attempts not finished (not marked): the student and the state.
    pub unfinished: Vec<(String, String)>,
    /// Slots holding a question that is not the exam's: the slot (1-based)
    /// and the beginning of its text, once per different question.
    pub foreign: Vec<(usize, String)>,
    /// Parts grafika cannot read: the student, the answer
    /// (`problem-01.view.u`) and what was typed (empty for an empty part);
    /// found by the marking ([`sheets`]).
    pub unreadable: Vec<(String, String, String)>,
}

/// One key's blanks as an attempt typed them.
#[derive(Clone, Debug)]
pub struct Blanks {
    /// The problem of the attempt's draw (0-based).
    pub problem: usize,
    /// The answer's name (`problem-01.view.u`).
    pub name: Name,
    /// The key.
    pub key: Key,
    /// Each blank's text, and whether a number is asked there.
    pub typed: Vec<(String, bool)>,
}

/// One finished attempt as an answer file would hold it.
#[derive(Clone, Debug)]
pub struct Given {
    /// The attempt (its index in the report).
    pub attempt: usize,
    /// How the sheet is named: `row 12` of the report.
    pub label: PathBuf,
    /// The student.
    pub who: String,
    /// The answers, as an exam's answer file gives them.
    pub answers: Answers,
    /// The exam's variant (1-based) of each problem the attempt drew.
    pub drawn: Vec<usize>,
    /// Each key's blanks as typed, in the order of the slots.
    pub blanks: Vec<Blanks>,
}

/// The paper a report's attempts answer, one variant per different draw
/// ([`given`]), with its markers: the exam's own, each problem solved and
/// its mistakes run once, whatever the draws.
pub struct Drawn {
    /// The paper.
    pub paper: Paper,
    markers: Markers,
}

/// The blanks of each problem of each variant: every key with its value.
type Shapes = Vec<Vec<Vec<(Key, Val)>>>;

fn shapes(markers: &Markers) -> Result<Shapes> {
    (markers.iter())
        .map(|v| {
            v.iter()
                .map(|marker| {
                    let m = marker.as_ref().map_err(Clone::clone)?;
                    let keys = m.scheme.keys();
                    Ok(keys
                        .filter_map(|k| Some((k.clone(), m.result.get(k)?.into_owned())))
                        .collect())
                })
                .collect()
        })
        .collect()
}

/// The finished attempts of a report as answers, and what was found
/// besides; with the paper they answer: a random slot draws each
/// problem's variant by itself, so an attempt answers a draw (problem 1 of
/// variant 2, problem 2 of variant 1, …), and each different draw is one
/// variant of the paper returned, in the order first met.
pub fn given(
    paper: &Paper,
    settings: Settings,
    r: &Responses,
) -> Result<(Drawn, Vec<Given>, Findings)> {
    let markers = super::markers(paper, settings);
    let shapes = shapes(&markers)?;
    let statements = statements(paper);
    let shown = r
        .attempts
        .iter()
        .any(|a| a.slots.iter().any(|s| !s.question.is_empty()));
    if !shown && paper.variants.len() > 1 {
        return Err(Error::why("moodle-responses", ErrMsg::NoQuestionText));
    }
    let mut f = Findings::default();
    let mut out = Vec::new();
    let mut draws: Vec<Vec<usize>> = Vec::new();
    for (i, a) in r.attempts.iter().enumerate() {
        if !a.finished {
            f.unfinished.push((who(a), a.state.clone()));
            continue;
        }
        let mut draw: Vec<usize> = vec![0; shapes[0].len()];
        let mut any = false;
        let mut answers: Answers = Vec::new();
        let mut blanks: Vec<Blanks> = Vec::new();
        for (s, slot) in a.slots.iter().enumerate() {
            let found = match shown {
                true => find(&statements, &slot.question, s),
                false => (s < shapes[0].len()).then_some((0, s)),
            };
            let Some((v, p)) = found else {
                let head: String = slot.question.chars().take(60).collect();
                if !f.foreign.iter().any(|(n, h)| *n == s + 1 && *h == head) {
                    f.foreign.push((s + 1, head));
                }
                continue;
            };
            draw[p] = v;
            any = true;
            let typed = slot.response.as_deref().and_then(parts).unwrap_or_default();
            let name = &paper.variants[v][p].name;
            answers.extend(answers_of(&shapes[v][p], &typed, (p, name), &mut blanks));
        }
        if !any {
            continue;
        }
        let v = match draws.iter().position(|d| *d == draw) {
            Some(v) => v,
            None => {
                draws.push(draw);
                draws.len() - 1
            }
        };
        let variant = toml::Value::Integer(v as i64 + 1);
        answers.insert(0, (Name::parse("variant"), variant));
        out.push(Given {
            attempt: i,
            label: PathBuf::from(format!("row {}", a.row)),
            who: who(a),
            answers,
            drawn: draws[v].iter().map(|d| d + 1).collect(),
            blanks,
        });
    }
    if draws.is_empty() {
        draws.push(vec![0; shapes[0].len()]); // no attempt marked: the first variant
    }
    Ok((drawn_paper(paper, &markers, &draws), out, f))
}

/// The paper returned: one variant per different draw, in the order first
/// met, each problem p of the variant its draw names, with its marker.
fn drawn_paper(paper: &Paper, markers: &Markers, draws: &[Vec<usize>]) -> Drawn {
    // each problem p of a draw with its variant v
    fn each(d: &[usize]) -> impl Iterator<Item = (usize, usize)> + '_ {
        d.iter().enumerate().map(|(p, &v)| (v, p))
    }
    Drawn {
        paper: Paper {
            title: paper.title.clone(),
            variants: (draws.iter())
                .map(|d| each(d).map(|(v, p)| paper.variants[v][p].clone()).collect())
                .collect(),
            exam: true,
        },
        markers: (draws.iter())
            .map(|d| each(d).map(|(v, p)| markers[v][p].clone()).collect())
            .collect(),
    }
}

/// How a student is named: the name, else the email, else the ID number.
pub fn who(a: &Attempt) -> String {
    [&a.name, &a.email, &a.id_number]
        .into_iter()
        .find(|s| !s.is_empty())
        .cloned()
        .unwrap_or_else(|| format!("row {}", a.row))
}

/// Each problem's statement, whitespace collapsed, by variant.
fn statements(paper: &Paper) -> Vec<Vec<String>> {
    (paper.variants.iter())
        .map(|v| {
            v.iter()
                .map(|p| collapse(p.problem.statement.as_deref().unwrap_or("")))
                .collect()
        })
        .collect()
}

fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The variant and problem (0-based) whose statement begins the question
/// text; of several, the one whose problem is the slot's.
fn find(statements: &[Vec<String>], question: &str, slot: usize) -> Option<(usize, usize)> {
    let q = collapse(question);
    let all: Vec<(usize, usize)> = (statements.iter().enumerate())
        .flat_map(|(v, ps)| ps.iter().enumerate().map(move |(p, s)| (v, p, s)))
        .filter(|(_, _, s)| !s.is_empty() && q.starts_with(s.as_str()))
        .map(|(v, p, _)| (v, p))
        .collect();
    all.iter()
        .find(|(_, p)| *p == slot)
        .or(all.first())
        .copied()
}

/// The answers of one problem from its parts in order: `problem-01.view.u`
/// and its value (a part's text, or a list shaped as the key's value);
/// each key's blanks as typed are added to `blanks`.
fn answers_of(
    keys: &[(Key, Val)],
    typed: &[String],
    (problem, name): (usize, &str),
    blanks: &mut Vec<Blanks>,
) -> Answers {
    let mut next = typed.iter().map(|s| s.trim());
    let mut out = Vec::new();
    for (key, val) in keys {
        let leaves = typed_leaves(key, val, 1e-3);
        let texts: Vec<&str> = leaves.iter().map(|_| next.next().unwrap_or("")).collect();
        let name = Name::keyed(name, key.clone());
        blanks.push(Blanks {
            problem,
            name: name.clone(),
            key: key.clone(),
            typed: (texts.iter().zip(&leaves))
                .map(|(t, (leaf, _))| (t.to_string(), matches!(leaf, Typed::Num(_))))
                .collect(),
        });
        if texts.iter().all(|t| t.is_empty()) {
            continue; // not answered: marked as missing
        }
        let mut it = texts.into_iter();
        out.push((name, shaped(val, &mut it)));
    }
    out
}

/// The blanks of the attempts that cannot be read: left empty, or not a
/// number where one is asked. Each number is parsed once, by the marking:
/// where it read a key's answer, every number of it was read (a one-blank
/// answer written after a name, `n = 5`, is the one read otherwise, and
/// its text is read again here); the blanks of a key it could not read
/// are read one by one to name the bad ones (and those of a problem an
/// attempt answers twice, where the marking read the first answer).
fn unreadable(given: &[Given], sheets: &[Sheet]) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    for (g, s) in given.iter().zip(sheets) {
        let mut seen = std::collections::HashSet::new();
        for b in &g.blanks {
            let read = seen.insert((b.problem, &b.key))
                && (s.outcome.as_ref().ok())
                    .and_then(|parts| parts.get(b.problem))
                    .and_then(|(_, m)| m.answers.iter().find(|a| a.key == b.key))
                    .is_some_and(|a| a.read.is_some());
            for (t, asked) in &b.typed {
                let again = *asked && (!read || t.contains('='));
                if t.is_empty() || (again && number(t).is_err()) {
                    out.push((g.who.clone(), b.name.to_string(), t.clone()));
                }
            }
        }
    }
    out
}

/// The parts' texts shaped as the key's value: a leaf is its text, a list
/// the list of its items.
fn shaped<'a>(like: &Val, texts: &mut impl Iterator<Item = &'a str>) -> toml::Value {
    match like {
        Val::List(items) => toml::Value::Array(items.iter().map(|x| shaped(x, texts)).collect()),
        Val::Map(kv) => toml::Value::Array(kv.iter().map(|(_, x)| shaped(x, texts)).collect()),
        Val::Said(_) => toml::Value::Array(Vec::new()),
        _ => toml::Value::String(texts.next().unwrap_or("").to_string()),
    }
}

/// Marks the given attempts as a class (see [`super::mark_given`]), each
/// sheet with the exam's variant of each problem it drew; a student with
/// several attempts is counted once, by the attempt of the highest share
/// of the marks (the first of equals), the others marked as
/// [`Same::Attempt`] of it. The blanks that cannot be read are added to
/// `found`'s unreadable ones.
pub fn sheets(drawn: &Drawn, r: &Responses, given: &[Given], found: &mut Findings) -> Vec<Sheet> {
    let mut sheets = super::mark_given(
        &drawn.paper,
        &drawn.markers,
        given
            .iter()
            .map(|g| (g.label.clone(), g.who.clone(), g.answers.clone())),
    );
    for (s, g) in sheets.iter_mut().zip(given) {
        s.drawn.clone_from(&g.drawn);
    }
    one_attempt_each(r, given, &mut sheets);
    found.unreadable.extend(unreadable(given, &sheets));
    sheets
}

/// Marks every attempt but the best of each student as another attempt.
/// A student is their email, else their ID number, else their name.
fn one_attempt_each(r: &Responses, given: &[Given], sheets: &mut [Sheet]) {
    let student = |g: &Given| {
        let a = &r.attempts[g.attempt];
        [&a.email, &a.id_number]
            .into_iter()
            .find(|s| !s.is_empty())
            .map_or_else(|| g.who.to_lowercase(), |s| s.to_lowercase())
    };
    let share = |s: &Sheet| {
        s.score()
            .zip(s.total())
            .map(|(e, t)| e / f64::from(t.max(1)))
    };
    // each student's best sheet, in one pass (the first of equals)
    let mut best: std::collections::HashMap<String, usize> = Default::default();
    for (i, g) in given.iter().enumerate() {
        let Some(mine) = sheets.get(i).and_then(share) else {
            continue;
        };
        let b = best.entry(student(g)).or_insert(i);
        if share(&sheets[*b]).is_some_and(|theirs| mine > theirs) {
            *b = i;
        }
    }
    for (i, g) in given.iter().enumerate() {
        let kept = best.get(&student(g)).copied().filter(|&b| b != i);
        if let Some(b) = kept.filter(|_| i < sheets.len()) {
            sheets[i].duplicate = Some((sheets[b].file.clone(), Same::Attempt));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;
    use crate::tutor::class::Part;

    /// The variants of the draws are marked by the exam's markers: each
    /// problem of the exam is solved and its mistakes run once, not once
    /// more for every draw that holds it.
    #[test]
    fn the_draws_share_the_exams_markers() {
        let text = "title = 't'\nask = ['view']\n\
            [camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n";
        let problem = ProblemIn::parse(text, "t.toml").expect("parses");
        let part = |name: &str| Part {
            name: name.into(),
            problem: problem.clone(),
        };
        let variant = || vec![part("problem-01"), part("problem-02")];
        let paper = Paper {
            title: "t".into(),
            variants: vec![variant(), variant()],
            exam: true,
        };
        let markers = super::super::markers(&paper, Settings::default());
        // three draws: (1, 2), (2, 1), (2, 2), 0-based
        let draws = [vec![0, 1], vec![1, 0], vec![1, 1]];
        let drawn = drawn_paper(&paper, &markers, &draws);
        for (d, draw) in draws.iter().enumerate() {
            for (p, &v) in draw.iter().enumerate() {
                let (Ok(mine), Ok(exams)) = (&drawn.markers[d][p], &markers[v][p]) else {
                    panic!("solves");
                };
                assert!(std::rc::Rc::ptr_eq(mine, exams), "draw {d}, problem {p}");
            }
        }
    }

    /// Each number an attempt types is parsed once, by the marking: the
    /// blanks are taken as typed, the marking reads them, and only the
    /// blanks of an answer it could not read are read again, to name the
    /// bad one; an empty blank is named without reading.
    #[test]
    fn a_blank_is_parsed_once_and_the_unreadable_are_named() {
        // the text's example 6.1: Pe − Pr = (4, 3, 0), |Pe − Pr| = 5, so
        // n = (4/5, 3/5, 0); Vup × n = (0, 0, −4/5), so u = (0, 0, −1)
        let text = "title = 't'\nask = ['view']\n\
            [camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n";
        let problem = ProblemIn::parse(text, "t.toml").expect("parses");
        let name = "problem-01".to_string();
        let paper = Paper {
            title: "t".into(),
            variants: vec![vec![Part { name, problem }]],
            exam: true,
        };
        let settings = Settings::default();
        let markers = super::super::markers(&paper, settings);
        let keys = &shapes(&markers).expect("solves")[0][0];
        // n right (a decimal comma), u with a blank that is no number, every
        // other key left empty
        let mut typed: Vec<String> = Vec::new();
        let mut empty = Vec::new();
        for (key, val) in keys {
            let n = typed_leaves(key, val, 1e-3).len();
            match key.to_string().as_str() {
                "view.n" => typed.extend(["0,8", " 0.6", "0"].map(String::from)),
                "view.u" => typed.extend(["0", "x", "−1"].map(String::from)),
                k => {
                    typed.extend(vec![String::new(); n]);
                    empty.extend(vec![format!("problem-01.{k}"); n]);
                }
            }
        }
        let parsed = || crate::num::expr::PARSED.with(std::cell::Cell::get);
        let before = parsed();
        let mut blanks = Vec::new();
        let mut answers = answers_of(keys, &typed, (0, "problem-01"), &mut blanks);
        assert_eq!(parsed() - before, 0, "the blanks are taken as typed");
        answers.insert(0, (Name::parse("variant"), toml::Value::Integer(1)));
        let given = Given {
            attempt: 0,
            label: PathBuf::from("row 1"),
            who: "S".into(),
            answers: answers.clone(),
            drawn: vec![1],
            blanks,
        };
        let sheets = super::super::mark_given(
            &paper,
            &markers,
            std::iter::once((given.label.clone(), given.who.clone(), answers)),
        );
        let before = parsed();
        let bad = unreadable(std::slice::from_ref(&given), &sheets);
        // the three blanks of u, read again; none of n
        assert_eq!(parsed() - before, 3);
        let mut want = vec![("problem-01.view.u".to_string(), "x".to_string())];
        want.extend(empty.into_iter().map(|k| (k, String::new())));
        let got: Vec<(String, String)> = bad.into_iter().map(|(_, k, t)| (k, t)).collect();
        assert_eq!(got, want);
    }
}
