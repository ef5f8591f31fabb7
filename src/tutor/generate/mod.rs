//! `grafika generate`: exams with answer keys. Each problem is a problem file
//! (docs/spec.md §5) drawn from a seeded [`SplitMix64`] with nice numbers for its
//! difficulty, checked to be non-degenerate and solvable, and solved exactly
//! for its key; the question sheet and the key (with the full worked
//! solution) are rendered as Markdown, LaTeX or JSON.
//!
//! Nice numbers: at easy level |Pe − Pr| is an integer (Pythagorean triples,
//! also for |Vup × (Pe − Pr)|, so u, v, n are rational), fovy = 90°, clipping
//! boxes at the origin; at medium level the answers have a single surd (one
//! of the two norms is an integer), fovy ∈ {30°, 45°, 60°, 120°}; at hard
//! level anything goes. Never degenerate: the up vector is not parallel to
//! the view direction, points lie beyond the near plane (so not on the
//! projection plane), clipping endpoints are off the box planes and no
//! segment lies in a box plane. Clipping problems cycle through partial
//! (clipped), accepted and rejected segments at every level.

mod draw;
pub mod quiz;

pub use draw::problem;

use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::num::format::fmt_dec;
use crate::num::rng::SplitMix64;
use crate::stages::trace::Report;
use crate::stages::trace::Val;
use crate::tutor::solve::lookup;

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

/// One generated problem.
pub struct Generated {
    /// The problem file's text.
    pub toml: String,
    /// The parsed problem.
    pub problem: ProblemIn,
    /// The exact solution.
    pub report: Report,
    /// The answers asked for.
    pub keys: Vec<String>,
}

/// The seed of variant v (variant 0 of seed S is S itself).
pub fn variant_seed(seed: u64, v: u32) -> u64 {
    if v == 0 {
        seed
    } else {
        SplitMix64::fork(seed, 0x5641_5249_0000_0000 | v as u64).next_u64()
    }
}

/// The problems of one exam: problem i is on topic i mod (number of topics).
pub fn exam(topics: &[Topic], diff: Difficulty, count: u32, seed: u64) -> Result<Vec<Generated>> {
    if topics.is_empty() {
        return Err(Error::new("topic", "give at least one topic"));
    }
    (0..count as usize)
        .map(|i| {
            let mut rng = SplitMix64::fork(seed, i as u64);
            // k: the problem's index among those of its topic
            problem(topics[i % topics.len()], diff, i / topics.len(), &mut rng)
        })
        .collect()
}

/// `view,clip` for the titles.
pub fn topics_name(t: &[Topic]) -> String {
    t.iter()
        .map(|x| format!("{x:?}").to_lowercase())
        .collect::<Vec<_>>()
        .join(",")
}

/// The answer-key file: `key = value` lines in `grafika check` format, each
/// value exact where it has an exact form.
pub fn key_toml(g: &Generated) -> String {
    let mut s = format!("# Answer key: {}\n", g.problem.title);
    for k in &g.keys {
        if let Some(v) = lookup(&g.report.result, k) {
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
        Val::Null => T::String("none".into()),
        Val::Bool(b) => T::Boolean(*b),
        Val::Map(kv) => T::Table(
            kv.iter()
                .map(|(k, x)| (k.clone(), answer_toml(x)))
                .collect(),
        ),
    }
}
