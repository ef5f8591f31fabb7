//! The number class of a solved problem: how its answers are written
//! exactly. A difficulty names a class ([`wanted`]), and every variant of a
//! problem position is screened into it by [`classify`], so "medium" is a
//! measured property of each variant, not a hope about the numbers drawn.
//!
//! The classes, from the exact forms of the answers asked (a radicand is
//! the k of a `sqrt(k)`; the exact forms are reduced, so √8 is written
//! 2√2 and counts as the radicand 2):
//!
//! - **rational**: no square root in any answer;
//! - **one surd**: square roots of one radicand only (√2 and 3√2/4 alike);
//! - **several surds**: square roots of two or more radicands;
//! - **no closed form**: some answer has no exact form in square roots,
//!   the tangent of half a field of view other than those of 30°, 45°, 60°,
//!   90° and 120° (tan 20°, tan 25°, …): its answers are decimals.

use super::{Difficulty, Topic};
use crate::num::Shown;
use crate::stages::trace::Val;
use crate::tutor::key::{Key, Part};
use crate::tutor::solution::Results;
use std::collections::BTreeSet;

/// How the answers of a problem (or of one of its parts) are written
/// exactly; ordered from the plainest.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum NumberClass {
    /// Every answer rational.
    Rational,
    /// Square roots of one radicand.
    OneSurd,
    /// Square roots of two or more radicands.
    SeveralSurds,
    /// An answer with no exact form in square roots.
    NoClosedForm,
}

impl NumberClass {
    /// Its name in JSON (`one_surd`); the words people read are the
    /// report's.
    pub fn name(self) -> &'static str {
        match self {
            NumberClass::Rational => "rational",
            NumberClass::OneSurd => "one_surd",
            NumberClass::SeveralSurds => "several_surds",
            NumberClass::NoClosedForm => "no_closed_form",
        }
    }
}

/// The class a difficulty names for a part of a topic's problem. Easy:
/// rational. Medium: one surd, but a pipeline's camera is rational and
/// its surd is the window's (the view and the projection stay rational).
/// Hard: several surds, and a window (a pipeline's window and pixels)
/// with no closed form. Clipping is rational at every level (its
/// intersections are quotients of the integers stated): its difficulty
/// is the case, how many planes are cut (`form`).
pub fn wanted(topic: Topic, diff: Difficulty, part: Part) -> NumberClass {
    use NumberClass::*;
    let window = matches!(part, Part::Window | Part::Viewport);
    match (diff, topic) {
        (_, Topic::Clip) | (Difficulty::Easy, _) => Rational,
        (Difficulty::Medium, Topic::Pipeline) if !window => Rational,
        (Difficulty::Medium, _) => OneSurd,
        (Difficulty::Hard, Topic::Window | Topic::Pipeline) if window => NoClosedForm,
        (Difficulty::Hard, _) => SeveralSurds,
    }
}

/// The class of the answers `keys` of a solved problem's results.
pub fn classify(result: &Results, keys: &[Key]) -> NumberClass {
    let mut radicands = BTreeSet::new();
    let mut closed = true;
    for v in keys.iter().filter_map(|k| result.get(k)) {
        for_each_num(&v, &mut |n| match &n.exact {
            Some(e) => radicands.extend(radicands_of(e)),
            None => closed = false,
        });
    }
    match (closed, radicands.len()) {
        (false, _) => NumberClass::NoClosedForm,
        (true, 0) => NumberClass::Rational,
        (true, 1) => NumberClass::OneSurd,
        (true, _) => NumberClass::SeveralSurds,
    }
}

/// The class of each part of a problem the keys ask, in the order the
/// parts are first asked: `[(view, one surd), (window, rational)]`.
pub fn classes(result: &Results, keys: &[Key]) -> Vec<(Part, NumberClass)> {
    let mut parts: Vec<Part> = Vec::new();
    for p in keys.iter().filter_map(|k| k.part) {
        if !parts.contains(&p) {
            parts.push(p);
        }
    }
    parts
        .into_iter()
        .map(|p| {
            let of_part: Vec<Key> = keys.iter().filter(|k| k.part == Some(p)).cloned().collect();
            (p, classify(result, &of_part))
        })
        .collect()
}

/// Calls `f` on every number of a value.
pub(super) fn for_each_num(v: &Val, f: &mut impl FnMut(&Shown)) {
    match v {
        Val::Num(n) => f(n),
        Val::List(items) => items.iter().for_each(|x| for_each_num(x, f)),
        Val::Map(kv) => kv.iter().for_each(|(_, x)| for_each_num(x, f)),
        _ => {}
    }
}

/// The radicands of an ASCII exact form: `(300+50*sqrt(2))/3` → {"2"}.
pub fn radicands_of(exact: &str) -> BTreeSet<String> {
    exact
        .split("sqrt(")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .map(str::to_string)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;
    use crate::num::Real;
    use crate::tutor::keys::ordered_keys;
    use crate::tutor::solve;

    /// The classes of each part of a problem file's every answer.
    fn of(toml: &str) -> Vec<(Part, NumberClass)> {
        let p = ProblemIn::parse(toml, "test").expect("parses");
        let r = solve::solve::<Real>(&p).expect("solves").result;
        let keys = ordered_keys(&r);
        classes(&r, &keys)
    }

    #[test]
    fn the_classes_follow_the_radicands_of_the_exact_answers() {
        use NumberClass::*;
        // Pe − Pr = (4, 3, 0): |.| = 5 and |Vup × (4, 3, 0)| = |(0, 0, −4)|
        // = 4, so n = (4/5, 3/5, 0), u = (0, 0, −1), v = (−3/5, 4/5, 0):
        // rational.
        let camera = "title = 't'\nask = ['view']\n[camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n";
        assert_eq!(of(camera), [(Part::View, Rational)]);
        // Pe − Pr = (1, 0, 1): n = (√2/2, 0, √2/2), u = (√2/2, 0, −√2/2),
        // v = (0, 1, 0): one radicand, 2.
        let one = "title = 't'\nask = ['view']\n[camera]\neye = [1, 0, 1]\nlook = [0, 0, 0]\nup = [0, 1, 0]\n";
        assert_eq!(of(one), [(Part::View, OneSurd)]);
        // Pe − Pr = (1, 1, 1): n = (1, 1, 1)/√3, Vup × n = (1, 0, −1)/√3,
        // |.| = √2/√3, u = (1, 0, −1)/√2, v = n × u = (−1, 2, −1)/√6:
        // radicands 3, 2 and 6.
        let several = "title = 't'\nask = ['view']\n[camera]\neye = [1, 1, 1]\nlook = [0, 0, 0]\nup = [0, 1, 0]\n";
        assert_eq!(of(several), [(Part::View, SeveralSurds)]);
        // fovy 90°: top = near·tan 45° = 1 (rational); fovy 60°: top =
        // tan 30° = √3/3 (one surd); fovy 40°: tan 20° has no form in
        // square roots (no closed form).
        let window = |fovy| {
            format!("title = 't'\nask = ['window']\n[perspective]\nnear = 1\nfovy = {fovy}\naspect = 2\n")
        };
        assert_eq!(of(&window(90)), [(Part::Window, Rational)]);
        assert_eq!(of(&window(60)), [(Part::Window, OneSurd)]);
        assert_eq!(of(&window(40)), [(Part::Window, NoClosedForm)]);
    }

    #[test]
    fn the_difficulties_name_their_classes() {
        use NumberClass::*;
        assert_eq!(wanted(Topic::View, Difficulty::Easy, Part::View), Rational);
        assert_eq!(wanted(Topic::View, Difficulty::Medium, Part::View), OneSurd);
        assert_eq!(
            wanted(Topic::Shade, Difficulty::Hard, Part::Shade),
            SeveralSurds
        );
        assert_eq!(wanted(Topic::Clip, Difficulty::Hard, Part::Clip), Rational);
        assert_eq!(
            wanted(Topic::Window, Difficulty::Hard, Part::Window),
            NoClosedForm
        );
        let p = Topic::Pipeline;
        assert_eq!(wanted(p, Difficulty::Medium, Part::View), Rational);
        assert_eq!(wanted(p, Difficulty::Medium, Part::Viewport), OneSurd);
        assert_eq!(wanted(p, Difficulty::Hard, Part::Project), SeveralSurds);
        assert_eq!(wanted(p, Difficulty::Hard, Part::Viewport), NoClosedForm);
    }
}
