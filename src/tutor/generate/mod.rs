//! `grafika generate`: exams with answer keys, whose variants are
//! parallel forms. Each problem is a problem file (docs/spec.md §5),
//! solved exactly for its key; the question sheet and the key (with the
//! full worked solution) are rendered as Markdown, LaTeX or JSON. Titles
//! and statements are message keys, written in the user's language by
//! `report`.
//!
//! An exam is drawn position by position. A position's form ([`form`]) is
//! drawn once from the seed: the number of points, the lighting model, the
//! clipping case (`--clip`). Every variant of the position then draws its
//! numbers within that form from a numbered space ([`space`]), visited in
//! an order drawn from the seed, and is kept only when it solves, its
//! case is the form's, nothing in it is trivial (a point not beyond the
//! near plane, a light along the normal, a specular term of 0), each
//! part's answers are of the number class the difficulty names
//! ([`numbers`]: rational, one surd, several surds, no closed form), and
//! its statement is new to the exam. So the variants of a position ask the
//! same keys with the same marks, of the same case and class. When a
//! position's space has fewer new problems than variants asked, that is an
//! error saying how many it could make.

pub mod blueprint;
mod draw;
pub mod form;
pub mod numbers;
pub mod quiz;
mod screen;
pub mod space;

pub use form::Form;

use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::Msg;
use crate::num::format::fmt_dec;
use crate::num::rng::SplitMix64;
use crate::stages::trace::Val;
use crate::tutor::key::Key;
use crate::tutor::solution::Report;

use std::collections::HashSet;
use std::fmt::Write as _;

pub use crate::tutor::topic::Topic;

/// How nice the numbers are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Difficulty {
    /// Integer norms, rational answers.
    Easy,
    /// One surd in the answers.
    Medium,
    /// General.
    Hard,
}

impl Difficulty {
    /// Every level, from the nicest numbers to the most general.
    pub const ALL: [Difficulty; 3] = [Difficulty::Easy, Difficulty::Medium, Difficulty::Hard];

    /// Its name as `--difficulty` and the exam titles spell it (`easy`).
    pub fn name(self) -> &'static str {
        match self {
            Difficulty::Easy => "easy",
            Difficulty::Medium => "medium",
            Difficulty::Hard => "hard",
        }
    }
}

/// One generated problem.
pub struct Generated {
    /// The title, said in the user's language when written.
    pub title: Msg,
    /// The statement, said in the user's language when written.
    pub statement: Msg,
    /// The problem file after its `title` and `statement` lines: what is
    /// asked and the data (the same in every language).
    pub body: String,
    /// The parsed problem; its title and statement are filled in the
    /// user's language by `report::sheets::localize`.
    pub problem: ProblemIn,
    /// The exact solution.
    pub report: Report,
    /// The answers asked for (the scheme's keys, in order).
    pub keys: Vec<Key>,
    /// What each answer is worth (`check`'s marking scheme).
    pub scheme: crate::tutor::check::scheme::Scheme,
}

/// The name of problem i (1-based) of an exam, as its files are named
/// (`problem-01.toml`, `problem-01.key.toml`) and as a class's answer files
/// name its table (`[problem-01]`).
pub fn problem_name(i: usize) -> String {
    format!("problem-{i:02}")
}

/// The number of the problem named `name` (`problem-01` → 1): the inverse
/// of [`problem_name`], so `problem-1` is no problem's name.
pub fn problem_number(name: &str) -> Option<usize> {
    let n = name.rsplit('-').next()?.parse().ok()?;
    (problem_name(n) == name).then_some(n)
}

/// The folder of variant v (1-based) of an exam: `variant-01`.
pub fn variant_name(v: usize) -> String {
    format!("variant-{v:02}")
}

/// The clipping case an exam asks (`--clip`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ClipCase {
    /// A segment cut by the box: at least one intersection computed and
    /// kept (the default: a real clipping problem).
    #[default]
    Clipped,
    /// A segment inside the box: accepted whole.
    Accepted,
    /// A segment beyond one plane of the box at both ends: rejected by
    /// the AND test.
    Rejected,
    /// The exam's clipping problems take clipped, accepted and rejected
    /// in turn, in an order drawn from the seed (each problem's variants
    /// all the same case).
    Mixed,
}

impl ClipCase {
    /// Its name as `--clip` and the blueprint spell it (`clipped`).
    pub fn name(self) -> &'static str {
        match self {
            ClipCase::Clipped => "clipped",
            ClipCase::Accepted => "accepted",
            ClipCase::Rejected => "rejected",
            ClipCase::Mixed => "mixed",
        }
    }
}

/// What an exam is asked to be.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// The topics, in turn through the exam.
    pub topics: Vec<Topic>,
    /// The difficulty.
    pub difficulty: Difficulty,
    /// Problems per exam.
    pub count: u32,
    /// Variants of each problem (one per student).
    pub variants: u32,
    /// The seed.
    pub seed: u64,
    /// The clipping case.
    pub clip: ClipCase,
}

/// An exam drawn: each position's form, and its variants.
pub struct Exams {
    /// The form of each problem position.
    pub forms: Vec<Form>,
    /// The variants, each its problems in order (`variants[v][i]`).
    pub variants: Vec<Vec<Generated>>,
}

/// Draws every variant of an exam: problem i on topic i mod (number of
/// topics), its form drawn from the seed, its variants from the form's
/// space, no statement twice in the whole exam.
/// `tick` is told how many problems each position adds, as it is drawn.
pub fn exams(spec: &Spec, tick: &mut dyn FnMut(u64)) -> Result<Exams> {
    if spec.topics.is_empty() {
        return Err(Error::why("topic", crate::msg::ErrMsg::NoTopic));
    }
    let mut seen = HashSet::new();
    let mut forms = Vec::new();
    let mut by_position = Vec::new();
    let mut clips = 0;
    for i in 0..spec.count as usize {
        let topic = spec.topics[i % spec.topics.len()];
        let f = form::form(topic, spec.difficulty, spec.clip, (i, clips), spec.seed);
        clips += usize::from(topic == Topic::Clip);
        let key = SplitMix64::fork(spec.seed, i as u64).next_u64();
        by_position.push(screen::variants(
            &f,
            (i, spec.variants as usize),
            &mut seen,
            key,
        )?);
        forms.push(f);
        tick(u64::from(spec.variants));
    }
    let mut variants: Vec<Vec<Generated>> = (0..spec.variants).map(|_| Vec::new()).collect();
    for position in by_position {
        for (v, g) in position.into_iter().enumerate() {
            variants[v].push(g);
        }
    }
    Ok(Exams { forms, variants })
}

/// One exam of one variant (a real clipping case, `--clip clipped`): the
/// problems `generate` writes for these topics, difficulty, count and seed.
pub fn exam(topics: &[Topic], diff: Difficulty, count: u32, seed: u64) -> Result<Vec<Generated>> {
    let spec = Spec {
        topics: topics.to_vec(),
        difficulty: diff,
        count,
        variants: 1,
        seed,
        clip: ClipCase::Clipped,
    };
    Ok(exams(&spec, &mut |_| {})?.variants.swap_remove(0))
}

/// The order of the clipping statuses of `--clip mixed` (0 clipped, 1
/// accepted, 2 rejected): one of the six permutations, drawn from the seed.
pub fn clip_order(seed: u64) -> [usize; 3] {
    let mut rng = SplitMix64::fork(seed, 0x434c_4950); // "CLIP"
    *rng.pick(&crate::num::rng::PERMUTATIONS_OF_3)
}

/// `view,clip` for the titles.
pub fn topics_name(t: &[Topic]) -> String {
    t.iter().map(|x| x.name()).collect::<Vec<_>>().join(",")
}

/// The answers of the answer-key file: `key = value` lines in `grafika
/// check` format, each value exact where it has an exact form.
pub fn key_lines(g: &Generated) -> String {
    let mut s = String::new();
    for k in &g.keys {
        if let Some(v) = g.report.result.get(k) {
            let _ = writeln!(s, "{k} = {}", answer_toml(&v));
        }
    }
    s
}

/// A value as a check answer: numbers as strings, exact where they have an
/// exact form; a rejected segment as "none".
pub fn answer_toml(v: &Val) -> toml::Value {
    use toml::Value as T;
    match v {
        Val::Num(n) => T::String(n.exact.clone().unwrap_or_else(|| {
            // 12 significant digits: far inside the 0.1% tolerance, and the
            // same on every platform even where libm's tan differs by an ulp.
            fmt_dec(n.value, 12)
        })),
        Val::List(items) => T::Array(items.iter().map(answer_toml).collect()),
        Val::Text(t) => T::String(t.clone()),
        Val::Null | Val::Said(_) => T::String("none".into()),
        Val::Bool(b) => T::Boolean(*b),
        Val::Map(kv) => T::Table(
            kv.iter()
                .map(|(k, x)| (k.clone(), answer_toml(x)))
                .collect(),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    /// `ALL` lists every variant once (the tests and the exams loop over
    /// it): a topic or level added to the type and not to its list fails.
    #[test]
    fn every_topic_and_level_is_listed_once() {
        assert_eq!(Topic::ALL.to_vec(), Topic::iter().collect::<Vec<_>>());
        assert_eq!(
            Difficulty::ALL.to_vec(),
            Difficulty::iter().collect::<Vec<_>>()
        );
    }
}
