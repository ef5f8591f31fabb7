//! `grafika generate`: exams with answer keys. Each problem is a problem file
//! (docs/spec.md §5) drawn from a seeded [`SplitMix64`] with nice numbers for its
//! difficulty, checked to be non-degenerate and solvable, and solved exactly
//! for its key; the question sheet and the key (with the full worked
//! solution) are rendered as Markdown, LaTeX or JSON. Titles and statements
//! are message keys, written in the user's language by `report`.
//!
//! Nice numbers, screened on the exact key: at easy level every answer is
//! rational (Pythagorean directions, fovy = 90°, boxes at the origin); at
//! medium level the answers have at most one square root between them; at
//! hard level anything goes, but every answer has its exact form except a
//! window resting on tan(fovy/2) for an angle with no form in square roots.
//! Never degenerate: the up vector is not parallel to the view direction,
//! points are different and lie beyond the near plane, clipping endpoints
//! are off the box planes. No problem repeats within an exam. The clipping
//! problems of an exam take the statuses clipped, accepted and rejected in
//! an order drawn from the seed.

mod draw;
pub mod quiz;

pub use draw::problem;

use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::Msg;
use crate::num::format::fmt_dec;
use crate::num::rng::SplitMix64;
use crate::stages::trace::Val;
use crate::tutor::key::Key;
use crate::tutor::solution::{value_of, Report};

use std::collections::HashSet;
use std::fmt::Write as _;

/// What the problems are about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Topic {
    /// The camera basis u, v, n.
    Basis,
    /// The basis and eye coordinates of points.
    View,
    /// Projection onto the near plane.
    Project,
    /// The viewing window from fovy, aspect and near.
    Window,
    /// Line clipping with outcodes.
    Clip,
    /// Lighting at one point.
    Shade,
    /// The whole chain: view, projection, window, viewport.
    Pipeline,
}

impl Topic {
    /// Its name as `--topic` and the exam titles spell it (`basis`).
    pub fn name(self) -> &'static str {
        match self {
            Topic::Basis => "basis",
            Topic::View => "view",
            Topic::Project => "project",
            Topic::Window => "window",
            Topic::Clip => "clip",
            Topic::Shade => "shade",
            Topic::Pipeline => "pipeline",
        }
    }
}

/// How nice the numbers are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Difficulty {
    /// Integer norms, rational answers.
    Easy,
    /// One surd in the answers.
    Medium,
    /// General.
    Hard,
}

impl Difficulty {
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

/// The seed of variant v (variant 0 of seed S is S itself).
pub fn variant_seed(seed: u64, v: u32) -> u64 {
    if v == 0 {
        seed
    } else {
        SplitMix64::fork(seed, 0x5641_5249_0000_0000 | v as u64).next_u64()
    }
}

/// The problems of one exam: problem i is on topic i mod (number of
/// topics), drawn from its own fork of the seed, and unlike every earlier
/// problem of the exam. The k-th clipping problem wants status
/// `order[k mod 3]`, `order` a permutation of (clipped, accepted, rejected)
/// drawn from the seed: three clipping problems show all three, and two
/// may show any two.
pub fn exam(topics: &[Topic], diff: Difficulty, count: u32, seed: u64) -> Result<Vec<Generated>> {
    if topics.is_empty() {
        return Err(Error::why("topic", crate::msg::ErrMsg::NoTopic));
    }
    let order = clip_order(seed);
    let mut seen = HashSet::new();
    let mut out = Vec::with_capacity(count.min(10_000) as usize);
    for i in 0..count as usize {
        let mut rng = SplitMix64::fork(seed, i as u64);
        // k: the problem's index among those of its topic
        let k = i / topics.len();
        let g = problem(
            topics[i % topics.len()],
            diff,
            order[k % 3],
            &seen,
            &mut rng,
        )?;
        seen.insert(g.body.clone());
        out.push(g);
    }
    Ok(out)
}

/// The order of the clipping statuses in an exam (0 clipped, 1 accepted,
/// 2 rejected): one of the six permutations, drawn from the seed.
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
        if let Some(v) = value_of(&g.report.result, k) {
            let _ = writeln!(s, "{k} = {}", answer_toml(v));
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
