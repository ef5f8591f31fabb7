//! A problem ready to mark: grafika's exact results and every catalog
//! mistake's results, computed once for a whole class (and once per
//! `practice` session); then, per answer, the order of judgment, and per
//! sheet, a diagnosis consistent with all of it, and follow-through
//! computed by the stages.
//!
//! One answer is judged so (see [`judge`] for a number):
//!
//! 1. read ([`answer::read`]); an answer that cannot be read is
//!    `unparseable`, with the part, the column and what was expected;
//! 2. exactly grafika's value: correct;
//! 3. a catalog mistake's value, exactly or (a decimal) within the
//!    tolerance: wrong, and that mistake named — never "rounded";
//! 4. within the tolerance: correct (whatever figures are written); else
//!    rounded to the digits written: correct, or too coarse with fewer
//!    figures than asked;
//! 5. otherwise wrong, with the mistakes whose values it rounds
//!    ([`Marker::fitting`] keeps those the rest of the sheet allows).

use super::judge::{apart, judge, matches_closely, Ctx, Judged};
use super::plausible;
use super::scheme::Scheme;
use super::{Results, Settings, Verdict};
use crate::error::Result;
use crate::input::answer::{self, Read};
use crate::input::part::Problem;
use crate::input::problem::ProblemIn;
use crate::msg::Implausible;
use crate::msg::Msg;
use crate::num::{Expr, Real, Scalar};
use crate::stages::trace::{Name, Step, Val};
use crate::tutor::diagnose::Code;
use crate::tutor::follow::Given;
use crate::tutor::key::{Field, Key, Part, Shading};
use crate::tutor::keys::ordered_keys;
use crate::tutor::run::Hooks;
use crate::tutor::solution::PartResult;
use crate::tutor::solve;
use std::borrow::Cow;
use std::cell::RefCell;
use std::collections::HashMap;

/// A problem ready to mark.
pub struct Marker {
    problem: ProblemIn,
    /// The problem typed once, for follow-through's many solves.
    typed: Problem,
    /// grafika's exact results, with the unit vectors L and N of a
    /// lighting problem with one light (steps of the solution that
    /// `practice` asks for).
    pub result: Results,
    /// The worked steps of the solution.
    pub steps: Vec<Step>,
    /// The keys in the order of the text's solution.
    pub order: Vec<Key>,
    /// What the problem asks and what each answer is worth ([`Scheme`]:
    /// the problem's `[check] keys` or [`super::default_keys`], weighted by
    /// its `[marks]`).
    pub scheme: Scheme,
    /// How answers are marked.
    pub settings: Settings,
    /// Each mistake of the catalog that applies, with its results.
    variants: Vec<(Code, Vec<Results>)>,
    /// The exact forms of grafika's values (and of its mistakes') already
    /// turned into exact numbers.
    exact: RefCell<HashMap<String, Option<Real>>>,
    /// The answers' expressions, as read, already turned into exact
    /// numbers: a class writes the same forms many times.
    given: RefCell<HashMap<Expr, Option<Real>>>,
}

/// What follow-through makes of a wrong answer ([`Marker::follow`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Follow {
    /// Right given the student's own earlier answers: the value they lead to.
    Credited(Val),
    /// It would be, but only from an earlier answer that cannot be: why.
    Blocked(Msg),
    /// Neither.
    Not,
}

/// One answer judged.
#[derive(Clone, Debug)]
pub struct Judgement {
    /// The verdict, with its stable code.
    pub verdict: Verdict,
    /// How it was judged.
    pub note: Msg,
    /// The answer as read (None when it could not be).
    pub read: Option<Read>,
    /// The mistakes of the catalog whose value it is (of a wrong answer).
    pub mistakes: Vec<Code>,
}

impl Marker {
    /// Solves the problem exactly and runs every mistake of the catalog on it.
    pub fn new(p: &ProblemIn, settings: Settings) -> Result<Marker> {
        let report = solve::solve::<Real>(p)?;
        let mut result = report.result;
        if let Some(PartResult::Shade(shade)) = result.of_mut(Part::Shade) {
            // the unit vectors are steps of the solution, not results of
            // `solve`; with one light there is one of each
            for unit in [Shading::N, Shading::L] {
                let name = Field::Shading(unit).key();
                let mut found = report.steps.iter().filter_map(|s| step_result(s, &name));
                if let (Some(v), None) = (found.next(), found.next()) {
                    *shade.value_mut(unit) = Some(v);
                }
            }
        }
        let variants = Code::all()
            .into_iter()
            .filter_map(|m| Some((m, m.apply(p)?)))
            .collect();
        let order = ordered_keys(&result);
        let scheme = Scheme::of(p, &result, &order)?;
        Ok(Marker {
            typed: Problem::of_file(p.clone())?,
            problem: p.clone(),
            order,
            result,
            steps: report.steps,
            scheme,
            settings,
            variants,
            exact: RefCell::new(HashMap::new()),
            given: RefCell::new(HashMap::new()),
        })
    }

    /// The problem.
    pub fn problem(&self) -> &ProblemIn {
        &self.problem
    }

    /// A value's exact form as an exact number (cached: a class is judged
    /// against the same values many times).
    fn exact_of(&self, text: &str) -> Option<Real> {
        if let Some(x) = self.exact.borrow().get(text) {
            return x.clone();
        }
        let x = crate::num::parse_expr(text)
            .ok()
            .and_then(|e| e.eval::<Real>().ok());
        self.exact.borrow_mut().insert(text.to_string(), x.clone());
        x
    }

    /// An answer's expression as an exact number (cached).
    fn given_exact(&self, e: &Expr) -> Option<Real> {
        if let Some(x) = self.given.borrow().get(e) {
            return x.clone();
        }
        let x = e.eval::<Real>().ok();
        self.given.borrow_mut().insert(e.clone(), x.clone());
        x
    }

    /// Judges `read` against `v` for `key`.
    fn judged(&self, read: &Read, v: &Val, key: &Key, carry: bool) -> Judged {
        let exact = |t: &str| self.exact_of(t);
        let given = |e: &Expr| self.given_exact(e);
        let ctx = Ctx {
            settings: &self.settings,
            key,
            carry,
            exact: &exact,
            given: &given,
        };
        judge(read, v, &ctx)
    }

    /// The values the catalog's mistakes give for `key` where they differ
    /// from grafika's `right`.
    fn mistaken<'a>(
        &'a self,
        key: &'a Key,
        right: &'a Val,
    ) -> impl Iterator<Item = (Code, Cow<'a, Val>)> + 'a {
        self.variants.iter().flat_map(move |(m, trees)| {
            trees
                .iter()
                .filter_map(move |t| t.get(key))
                .filter(move |v| differs(v, right))
                .map(move |v| (*m, v))
        })
    }

    /// Judges one answer to `key`, whose value is `right` (grafika's, as
    /// the caller found it in [`Marker::result`]), in the order of judgment
    /// (module docs): a value of an answer file ([`answer::Given::of`]) or
    /// a line typed ([`answer::Given::Text`]), read as it is.
    pub fn judge(&self, key: &Key, right: &Val, given: answer::Given) -> Judgement {
        if given.is_blank() {
            let j = Judged::new(Verdict::Missing, Msg::EmptyAnswer);
            return judgement(j, None);
        }
        let read = match given.read(right) {
            Ok(r) => completed(key, r, right),
            Err(note) => return judgement(Judged::new(Verdict::Unparseable, note), None),
        };
        let j = self.judged(&read, right, key, false);
        if j.verdict == Verdict::Exact {
            return judgement(j, Some(read));
        }
        // a mistake's value itself is wrong, however it rounds (where the
        // tolerance can tell it from grafika's)
        let rel = self.settings.tolerance;
        let mut mistakes: Vec<Code> = Vec::new();
        for (m, v) in self.mistaken(key, right) {
            if apart(&v, right, key, rel)
                && matches_closely(&read, &v, key, rel)
                && !mistakes.contains(&m)
            {
                mistakes.push(m);
            }
        }
        let j = match (mistakes.is_empty(), j.verdict) {
            (false, _) => Judged::new(Verdict::Wrong, super::judge::expected_note(right)),
            (true, Verdict::Wrong) => j,
            (true, _) => return judgement(j, Some(read)),
        };
        // a wrong answer: every mistake whose value it rounds
        for (m, v) in self.mistaken(key, right) {
            if self.judged(&read, &v, key, true).verdict.is_correct() && !mistakes.contains(&m) {
                mistakes.push(m);
            }
        }
        Judgement {
            mistakes,
            ..judgement(j, Some(read))
        }
    }

    /// The mistakes among `candidates` of which one variant gives the
    /// answer `read` to `key` and changes none of the answers `agreed` (the
    /// student's answers that agree with grafika's values): a mistake that
    /// would have made a right answer wrong is not the one made.
    pub fn fitting(
        &self,
        key: &Key,
        read: &Read,
        candidates: &[Code],
        agreed: &[(&Key, &Read)],
    ) -> Vec<Code> {
        let Some(right) = self.result.get(key) else {
            return vec![];
        };
        let rel = self.settings.tolerance;
        let gives = |t: &Results| {
            t.get(key).is_some_and(|v| {
                differs(&v, &right)
                    && (matches_closely(read, &v, key, rel)
                        || self.judged(read, &v, key, true).verdict.is_correct())
            })
        };
        let keeps = |t: &Results, (k, r): &(&Key, &Read)| match (t.get(k), self.result.get(k)) {
            (Some(v), Some(rk)) if apart(&v, &rk, k, rel) => self.judged(r, &v, k, true).agrees(),
            _ => true,
        };
        self.variants
            .iter()
            .filter(|(m, _)| candidates.contains(m))
            .filter(|(_, trees)| {
                trees
                    .iter()
                    .any(|t| gives(t) && agreed.iter().all(|a| keeps(t, a)))
            })
            .map(|(m, _)| *m)
            .collect()
    }

    /// What follow-through makes of the wrong answer `read` to `key`: right
    /// against the value the student's own earlier answers (`own`, where
    /// they were wrong) lead to, computed by the stages; only earlier
    /// values that could be what their step gives start it
    /// ([`super::plausible`]). When the answer follows only from one that
    /// cannot be, the note says which and why.
    pub fn follow(&self, key: &Key, read: &Read, own: &dyn Fn(&Key) -> Option<Read>) -> Follow {
        // a key not of this problem's solution (a component, a whole part)
        // is in no order, so nothing is carried to it
        let Some(pos) = self.order.iter().position(|k| k == key) else {
            return Follow::Not;
        };
        let earlier: Vec<(&Key, Read)> = (self.order[..pos].iter())
            .filter_map(|k| Some((k, own(k)?)))
            .collect();
        if earlier.is_empty() {
            return Follow::Not;
        }
        let right = |k: &Key| self.result.get(k).map(Cow::into_owned);
        let cx = plausible::Context {
            rel: self.settings.tolerance,
            right: &right,
            own,
        };
        let why: Vec<Option<Implausible>> = (earlier.iter())
            .map(|(k, r)| plausible::why_not(k, r, &cx))
            .collect();
        let fine: Vec<(&Key, Read)> = (earlier.iter().zip(&why))
            .filter(|(_, w)| w.is_none())
            .map(|((k, r), _)| (*k, r.clone()))
            .collect();
        if let Some(ft) = self.carried(key, &fine) {
            if self.follows(read, &ft, key) {
                return Follow::Credited(ft);
            }
        }
        let Some(((from, _), Some(why))) = earlier.iter().zip(&why).find(|(_, w)| w.is_some())
        else {
            return Follow::Not;
        };
        match self.carried(key, &earlier) {
            Some(ft) if self.follows(read, &ft, key) => Follow::Blocked(Msg::NoFollowFrom(
                from.to_string(),
                why.clone(),
                key.to_string(),
            )),
            _ => Follow::Not,
        }
    }

    /// The value of `key` that the values `givens` lead to, computed by
    /// the stages with each given in place of grafika's; None when they do
    /// not change it. Worked in doubles without steps: follow-through
    /// judges within the tolerance, and exact sums of many surds would
    /// cost seconds a sheet.
    fn carried(&self, key: &Key, givens: &[(&Key, Read)]) -> Option<Val> {
        let givens: Vec<(&Key, Given<f64>)> = (givens.iter())
            .filter_map(|(k, r)| Some((*k, given(r)?)))
            .collect();
        if givens.is_empty() {
            return None;
        }
        let look = |k: &Key| givens.iter().find(|(g, _)| *g == k).map(|(_, v)| v.clone());
        let hooks = Hooks {
            given: Some(&look),
            quiet: true,
            ..Hooks::default()
        };
        let result = solve::solve_typed::<f64>(&self.typed, &hooks).ok()?.result;
        let v = result.get(key)?;
        let right = self.result.get(key)?;
        differs(&v, &right).then(|| v.into_owned())
    }

    /// The worked steps with the student's own values `own` in place of
    /// grafika's, exactly: what a hint after a wrong answer substitutes,
    /// so it goes on from the student's values, not the right ones.
    pub fn steps_given(&self, own: &[(Key, Read)]) -> Option<Vec<Step>> {
        let givens: Vec<(&Key, Given<Real>)> = (own.iter())
            .filter_map(|(k, r)| Some((k, given(r)?)))
            .collect();
        let look = |k: &Key| givens.iter().find(|(g, _)| *g == k).map(|(_, v)| v.clone());
        let hooks = Hooks {
            given: Some(&look),
            ..Hooks::default()
        };
        Some(solve::solve_typed::<Real>(&self.typed, &hooks).ok()?.steps)
    }

    /// Whether an answer is right against the value `ft` carried through
    /// from the student's own answers (rounded values carried forward are
    /// accepted, and too few figures are not held against it).
    pub fn follows(&self, read: &Read, ft: &Val, key: &Key) -> bool {
        self.judged(read, ft, key, true).agrees()
    }

    /// The erratum of `key`, if the problem has one (the file's key read
    /// as a key: `clip[1].status` is `clip.1.status`).
    pub fn erratum(&self, key: &Key) -> Option<Msg> {
        self.problem
            .errata
            .iter()
            .find(|e| e.key.parse::<Key>().as_ref() == Ok(key))
            .map(|e| e.reason())
    }
}

fn judgement(j: Judged, read: Option<Read>) -> Judgement {
    Judgement {
        verdict: j.verdict,
        note: j.note,
        read,
        mistakes: vec![],
    }
}

/// A projected point written as (xp, yp) takes zp = d from grafika's value.
fn completed(key: &Key, read: Read, right: &Val) -> Read {
    match (read, right) {
        (Read::List(mut xy), Val::List(want))
            if key.part == Some(Part::Project) && xy.len() + 1 == want.len() =>
        {
            if let Some(Val::Num(zp)) = want.last() {
                if let Ok(n) = answer::number(zp.exact.as_deref().unwrap_or(&zp.value.to_string()))
                {
                    xy.push(Read::Num(n));
                }
            }
            Read::List(xy)
        }
        (read, _) => read,
    }
}

/// An answer as a value given to the stages: its numbers at precision `T`.
fn given<T: Scalar>(read: &Read) -> Option<Given<T>> {
    fn nums<T: Scalar>(r: &Read, out: &mut Vec<T>) -> Option<()> {
        match r {
            Read::Num(n) => out.push(n.expr.eval::<T>().ok()?),
            Read::List(items) => items.iter().try_for_each(|x| nums(x, out))?,
            Read::Word(_) | Read::None => return None,
        }
        Some(())
    }
    match read {
        Read::Word(w) => Some(Given::Word(w.clone())),
        Read::None => None,
        _ => {
            let mut out = Vec::new();
            nums(read, &mut out)?;
            Some(Given::Nums(out))
        }
    }
}

/// The step's result of this name.
fn step_result(step: &Step, name: &str) -> Option<Val> {
    step.result
        .iter()
        .find(|(n, _)| *n == Name::math(name))
        .map(|(_, v)| v.clone())
}

/// Whether two values differ (numbers by more than a relative 1e-9).
pub(crate) fn differs(a: &Val, b: &Val) -> bool {
    match (a, b) {
        (Val::Num(x), Val::Num(y)) => {
            (x.value - y.value).abs() > 1e-9 * x.value.abs().max(y.value.abs()).max(1e-300)
        }
        (Val::List(xs), Val::List(ys)) => {
            xs.len() != ys.len() || xs.iter().zip(ys).any(|(x, y)| differs(x, y))
        }
        (Val::Map(xs), Val::Map(ys)) => {
            xs.len() != ys.len() || xs.iter().zip(ys).any(|((_, x), (_, y))| differs(x, y))
        }
        _ => a != b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An erratum is found whichever spelling of a segment the problem
    /// file and the marked key use (answers are marked by the key's one
    /// spelling, `clip.1.status`).
    #[test]
    fn an_erratum_is_found_in_either_spelling_of_a_segment() {
        let text = "title = 't'\n[clip]\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n\
            [[clip.segment]]\nfrom = [0.5, 0.5, 0.5]\nto = [0.2, 0.2, 0.2]\n\
            [[clip.segment]]\nfrom = [2, 2, 2]\nto = [3, 3, 3]\n\
            [[errata]]\nkey = 'clip[1].status'\nwhy = 'misprinted'\n";
        let p = ProblemIn::parse(text, "t.toml").expect("parses");
        let m = Marker::new(&p, Settings::default()).expect("solves");
        let key = |s: &str| s.parse::<Key>().expect("a key");
        assert!(m.erratum(&key("clip.1.status")).is_some());
        assert!(m.erratum(&key("clip[1].status")).is_some());
        assert!(m.erratum(&key("clip.0.status")).is_none());
    }
}
