//! The variants of one problem position: the indices of its form's space
//! visited in an order drawn from the seed, each drawing screened (it
//! solves exactly, without warnings; its case is the form's; nothing in
//! it is trivial; each part's answers are of the class the difficulty
//! names) and kept when its statement is new to the exam. A variant whose
//! answers repeat an earlier variant's is kept back, and used only when
//! the space has no other.

use super::draw::{draft, shade, space_size, Draft};
use super::form::{ClipShape, Form};
use super::numbers::{classes, wanted};
use super::space::{permuted, Digits};
use super::{key_lines, Generated, Topic};
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::Msg;
use crate::num::Real;
use crate::stages::trace::Val;
use crate::tutor::check::scheme::Scheme;
use crate::tutor::key::{Field, Key, Part, Shading};
use crate::tutor::keys::ordered_keys;
use crate::tutor::solution::Results;
use crate::tutor::solve;
use std::collections::HashSet;

/// The most drawings screened for one position before `generate` gives
/// up: far more than any form needs (the sparsest, a medium Blinn–Phong
/// problem, keeps about one drawing in twenty).
const MAX_TRIES: u64 = 200_000;

/// `count` variants of the position `position` (0-based) of the form,
/// none stating a problem in `seen` (the exam's so far, which they join);
/// `key` orders the visit of the form's space.
pub(super) fn variants(
    form: &Form,
    (position, count): (usize, usize),
    seen: &mut HashSet<String>,
    key: u64,
) -> Result<Vec<Generated>> {
    let n = space_size(form);
    let mut out: Vec<Generated> = Vec::with_capacity(count.min(1000));
    let mut held_back: Vec<Generated> = Vec::new();
    let mut answers: HashSet<String> = HashSet::new();
    let mut visited = 0;
    while out.len() < count && visited < n.min(MAX_TRIES) {
        let i = permuted(visited, n, key);
        visited += 1;
        let Some(d) = draft(form, &mut Digits::of(i)) else {
            continue;
        };
        if seen.contains(&d.body) {
            continue;
        }
        let Some(g) = accept(d, form) else { continue };
        seen.insert(g.body.clone());
        if answers.insert(key_lines(&g)) {
            out.push(g);
        } else {
            held_back.push(g);
        }
    }
    let short = count - out.len().min(count);
    out.extend(held_back.into_iter().take(short));
    if out.len() < count {
        return Err(Error::said(
            if count > 1 { "variants" } else { "count" },
            Msg::ErrFewDistinct {
                topic: form.topic.name().to_string(),
                level: form.difficulty.name().to_string(),
                problem: position + 1,
                found: out.len(),
                asked: count,
                all: visited >= n,
            },
        ));
    }
    Ok(out)
}

/// Parses, solves and screens a drawn problem.
pub(super) fn accept(d: Draft, form: &Form) -> Option<Generated> {
    // The title is written in the user's language later (report::sheets).
    let problem = ProblemIn::parse(&format!("title = \"\"\n{}", d.body), "generated").ok()?;
    let f64_result = solve::solve::<f64>(&problem).ok()?.result;
    if !screen(form, &problem, &f64_result) {
        return None;
    }
    let report = solve::solve::<Real>(&problem).ok()?;
    if !report.warnings.is_empty() {
        return None;
    }
    // the marking scheme `check` marks it by: its `[check] keys` (written
    // by the generator from typed keys, so each reads back), weighted by
    // its `[marks]`
    let order = ordered_keys(&report.result);
    let scheme = Scheme::of(&problem, &report.result, &order).ok()?;
    let keys: Vec<Key> = scheme.keys().cloned().collect();
    let measured = classes(&report.result, &keys);
    if measured
        .iter()
        .any(|(part, c)| *c != wanted(form.topic, form.difficulty, *part))
    {
        return None;
    }
    Some(Generated {
        title: Msg::DrawnTitle(d.title),
        statement: Msg::Statement(Box::new(d.statement)),
        body: d.body,
        problem,
        report,
        keys,
        scheme,
    })
}

/// The numbers of a value.
fn nums(v: Option<&Val>) -> Vec<f64> {
    match v {
        Some(Val::Num(s)) => vec![s.value],
        Some(Val::List(items)) => items.iter().flat_map(|x| nums(Some(x))).collect(),
        _ => vec![],
    }
}

/// The form's case, and nothing trivial: a pipeline's pixels inside its
/// viewport; a lighting problem lit at a slant (0.1 ≤ cos α ≤ 0.99: the
/// light neither grazing nor along the normal) with a specular term that
/// shows (at least 0.01, where the model has one); a clipping problem of
/// the form's clipping case.
fn screen(form: &Form, p: &ProblemIn, r: &Results) -> bool {
    match form.topic {
        Topic::Pipeline => inside_viewport(p, r),
        Topic::Shade => {
            let cos_alpha = nums(r.get(&shade(Shading::CosAlpha)).as_deref());
            let slant = matches!(cos_alpha[..], [c] if (0.1..=0.99).contains(&c));
            let specular = nums(r.get(&shade(Shading::Specular)).as_deref());
            let shows = specular.iter().any(|s| *s >= 0.01);
            let has_specular = form.model.is_some_and(|m| m.terms().2);
            slant && (shows || !has_specular)
        }
        Topic::Clip => form.clip.is_some_and(|c| clip_case(&c, r)),
        Topic::Basis | Topic::View | Topic::Project | Topic::Window => true,
    }
}

/// Every pixel of a pipeline strictly inside its viewport.
fn inside_viewport(p: &ProblemIn, r: &Results) -> bool {
    let vp: Vec<f64> = p
        .perspective
        .as_ref()
        .and_then(|x| x.viewport.as_ref())
        .map(|v| v.iter().filter_map(|n| n.0.eval::<f64>().ok()).collect())
        .unwrap_or_default();
    let Some(Val::Map(px)) = field_of(r, Part::Viewport, Field::Pixels) else {
        return false;
    };
    px.iter().all(|(_, q)| match (&nums(Some(q))[..], &vp[..]) {
        ([x, y, ..], [w, h]) => *x > 0.0 && x < w && *y > 0.0 && y < h,
        _ => false,
    })
}

/// Whether a solved clipping problem is of the case: its status, the
/// bits set in each outcode, the intersections tried and kept; a clipped
/// segment is more than a point.
fn clip_case(c: &ClipShape, r: &Results) -> bool {
    let field = |f| field_of(r, Part::Clip, f);
    let bits = |f| match field(f) {
        Some(Val::Text(code)) => code.chars().filter(|b| *b == '1').count() as u32,
        _ => u32::MAX,
    };
    let status = matches!(field(Field::Status), Some(Val::Text(s)) if s == c.status.as_str());
    let (tried, kept) = match field(Field::Intersections) {
        Some(Val::Map(cuts)) => (
            cuts.len() as u32,
            (cuts.iter())
                .filter(|(_, i)| match i {
                    Val::Map(kv) => kv.iter().any(|(_, x)| *x == Val::Bool(true)),
                    _ => false,
                })
                .count() as u32,
        ),
        _ => (0, 0),
    };
    let piece = match field(Field::Segment) {
        Some(Val::List(seg)) => seg.first() != seg.get(1),
        _ => true,
    };
    status
        && [bits(Field::Code0), bits(Field::Code1)] == c.bits
        && tried == c.tried
        && kept == c.kept
        && piece
}

/// Field `f` of the results of `part` (of a clip's one segment).
fn field_of(r: &Results, part: Part, f: Field) -> Option<&Val> {
    r.of(part)?.one(None)?.field(f)
}

#[cfg(test)]
mod tests {
    use super::super::draw::shade_draft;
    use super::super::Difficulty;
    use super::*;
    use crate::msg::Number;
    use crate::stages::lighting::Model;

    #[test]
    fn an_exam_can_ask_about_every_model() {
        // N = (0, 3, 4)/5, L = (0, 0, 1): cos α = 4/5, R = 2N(L·N) − L =
        // (0, 24, 7)/25, and V = (0, 24, 7)/25 sees it: cos β = 1, the
        // specular term ks = 0.7; with Blinn–Phong H = (0, 0, 1) and N·H =
        // 4/5. Every answer rational. Each model's problem is accepted as
        // a drawn one is, and each answer it checks is in its results.
        for m in Model::all() {
            let draw = ([0, 3, 4], [0, 0, 1], [0, 24, 7], None);
            let d = shade_draft([Number::int(1), Number::int(1), Number::int(0)], m, draw);
            let form = Form {
                topic: Topic::Shade,
                difficulty: Difficulty::Easy,
                points: 0,
                model: Some(m),
                clip: None,
            };
            let g =
                accept(d, &form).unwrap_or_else(|| panic!("{m:?}: the drawn problem is refused"));
            assert!(!g.keys.is_empty(), "{m:?}");
            for k in &g.keys {
                let v = g.report.result.get(k);
                assert!(v.is_some_and(|v| *v != Val::Null), "{m:?}: no {k}");
            }
        }
    }
}
