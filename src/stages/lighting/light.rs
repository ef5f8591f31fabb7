//! One light at the point: direction and distance, range, attenuation,
//! spot factor, cos α, R and cos β, the half vector H and the highlight.
//!
//! Written once for every scalar, the renderer's lane type included: every
//! "where" of the text is a lane-wise truth value ([`Scalar::gt_mask`], a
//! plain `bool` for one value) and every "else" a [`Scalar::select`]. A light
//! is skipped when it reaches the point in no lane; in a lane it does not
//! reach, its attenuation is 0. The steps' builders describe one value (only
//! a listening recorder calls them, and lane types are never recorded).

use super::{
    label, listening, max0, pow, Highlight, Light, LightKind, LightTerm, Material, Part, RuleSet,
    Surface,
};
use crate::msg::{LightPart, Msg, SpotZone};
use crate::num::vec::{add, dot, sub, V3};
use crate::num::{Mask, Scalar};
use crate::stages::trace::{Name, Step, Subst, Trace, Val};

/// One light's geometry and factors at the point; `None` when the point is
/// beyond the light's range (the light is not evaluated at all) or at the
/// light's own position. `at` = (index, number of lights), for step titles.
///
/// Under the given rules ([`super::Rules`] or [`super::TextRules`]):
/// L (and d), Att, Spot, cos α = L·N, then the specular part
/// (`specular`); always inlined (into `shade`'s body too).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn light_term_with<T: Scalar, R: RuleSet<T>>(
    mat: &Material<T>,
    light: &Light<T>,
    at: (usize, usize),
    s: &Surface<T>,
    v: &V3<T>,
    want_spec: bool,
    rules: &R,
    tr: &mut impl Trace,
) -> Option<LightTerm<T>> {
    let (l, distance, reached) = match &light.kind {
        LightKind::Directional { dir } => (dir.clone(), None, T::Mask::from(true)),
        LightKind::Point { pos } | LightKind::Spot { pos, .. } => {
            let (l, d, reached) = toward(light, pos, s, at, tr)?;
            (l, Some(d), reached)
        }
    };
    let attenuation = match &distance {
        Some(d) => attenuation(&light.attenuation, d, reached, at, tr),
        None => T::one(),
    };
    let spot = match &light.kind {
        LightKind::Spot {
            dir,
            theta,
            phi,
            falloff,
            ..
        } => spot_factor(&l, dir, theta, phi, falloff, at, tr),
        _ => T::one(),
    };
    // cos α = L·N
    let cos_alpha = rules.given_num(Part::CosAlpha, dot(&l, &s.normal));
    let mut term = LightTerm {
        l,
        distance,
        attenuation,
        spot,
        cos_alpha,
        r: None,
        cos_beta: None,
        h: None,
        cos_nh: None,
        highlight: T::zero(),
    };
    // Att·Spot = 0 (in every lane): the light adds nothing here.
    let silent = (term.attenuation.clone() * term.spot.clone()).is_zero_value();
    if silent && !listening(tr) {
        return Some(term);
    }
    tr.step(|| incidence_step(mat, &term, &s.normal, at));
    specular(mat, &mut term, s, v, want_spec, rules, at, tr);
    Some(term)
}

/// d = |Pl − P| and L = (Pl − P)/d toward a point or spot light at `pos`,
/// and where the light reaches the point: d² ≤ range² (everywhere without
/// a range) and d > 0. `None` when it reaches no lane (after the step
/// "out of range" when that is the reason).
#[inline(always)]
fn toward<T: Scalar>(
    light: &Light<T>,
    pos: &V3<T>,
    s: &Surface<T>,
    at: (usize, usize),
    tr: &mut impl Trace,
) -> Option<(V3<T>, T, T::Mask)> {
    let to = sub(pos, &s.position);
    let d2 = dot(&to, &to);
    let mut in_range = T::Mask::from(true);
    if let Some(r) = &light.range {
        let r2 = r.clone() * r.clone();
        in_range = !d2.gt_mask(&r2);
        if !in_range.any() {
            tr.step(|| {
                Step::new(label(at, LightPart::OutOfRange), Msg::FOutOfRange)
                    .val(Name::math("Pl − P"), Val::vec3(&to))
                    .sub(Name::math("Pl − P"), Subst::difference(pos, &s.position))
                    .val(Name::math("d²"), Val::num(&d2))
                    .sub(
                        Name::math("d²"),
                        Subst::new("{}² + {}² + {}²", to.iter().map(Val::num).collect()),
                    )
                    .val(Name::math("range²"), Val::num(&r2))
                    .sub(Name::math("range²"), Subst::new("{}²", vec![Val::num(r)]))
                    .res(Name::Contributes, Val::Bool(false))
                    .sub(
                        Name::Contributes,
                        Subst::new("{} > {}", vec![Val::num(&d2), Val::num(&r2)]),
                    )
                    .note(Msg::BeyondRange)
            });
            return None;
        }
    }
    let d = d2.sqrt();
    let reached = in_range & d.gt_mask(&T::zero());
    if !reached.any() {
        return None;
    }
    let l = crate::num::vec::div(&to, &d);
    tr.step(|| {
        Step::new(
            label(at, LightPart::Direction),
            "d = |Pl − P|,  L = (Pl − P)/d",
        )
        .val(Name::math("Pl"), Val::vec3(pos))
        .val(Name::math("P"), Val::vec3(&s.position))
        .val(Name::math("Pl − P"), Val::vec3(&to))
        .sub(Name::math("Pl − P"), Subst::difference(pos, &s.position))
        .val(Name::math("d"), Val::length(&to, &d))
        .sub(Name::math("d"), Subst::norm(&to))
        .res(Name::math("L"), Val::vec3(&l))
        .sub(
            Name::math("L"),
            Subst::quotient(Val::vec3(&to), Val::length(&to, &d)),
        )
        .note(match &light.range {
            Some(_) => Msg::WithinRange,
            None => Msg::NoRange,
        })
    });
    Some((l, d, reached))
}

/// Att = 1/(a0 + a1·d + a2·d²) where the light reaches the point
/// (`reached`), 0 elsewhere.
#[inline(always)]
fn attenuation<T: Scalar>(
    a: &[T; 3],
    d: &T,
    reached: T::Mask,
    at: (usize, usize),
    tr: &mut impl Trace,
) -> T {
    let den = a[0].clone() + a[1].clone() * d.clone() + a[2].clone() * d.clone() * d.clone();
    let att = T::select(reached, T::one() / den.clone(), T::zero());
    tr.step(|| {
        Step::new(
            label(at, LightPart::Attenuation),
            "Att = 1/(a0 + a1·d + a2·d²)",
        )
        .val(
            Name::math("(a0, a1, a2)"),
            Val::List(a.iter().map(Val::num).collect()),
        )
        .val(Name::math("d"), Val::num(d))
        .val(Name::math("a0 + a1·d + a2·d²"), Val::num(&den))
        .sub(
            Name::math("a0 + a1·d + a2·d²"),
            Subst::new(
                "{} + {}·{} + {}·{}²",
                [&a[0], &a[1], d, &a[2], d].map(Val::num).to_vec(),
            ),
        )
        .res(Name::math("Att"), Val::num(&att))
        .sub(Name::math("Att"), Subst::new("1/{}", vec![Val::num(&den)]))
    });
    att
}

/// The step of cos α = L·N and max(cos α, 0), noting a light behind the
/// surface (cos α < 0).
fn incidence_step<T: Scalar>(
    mat: &Material<T>,
    term: &LightTerm<T>,
    n: &V3<T>,
    at: (usize, usize),
) -> Step {
    let cos_alpha = &term.cos_alpha;
    let s = Step::new(label(at, LightPart::Incidence), Msg::FIncidence)
        .val(Name::math("L"), Val::vec3(&term.l))
        .val(Name::math("N"), Val::vec3(n))
        .res(Name::math("cos α"), Val::num(cos_alpha))
        .sub(Name::math("cos α"), Subst::dot(&term.l, n))
        .res(Name::math("max(cos α, 0)"), Val::num(&max0(cos_alpha)))
        .sub(
            Name::math("max(cos α, 0)"),
            Subst::new("max({}{,}0)", vec![Val::num(cos_alpha)]),
        );
    if *cos_alpha < T::zero() {
        s.note(Msg::Behind(mat.specular_requires_lit))
    } else {
        s
    }
}

/// The specular part of one light: R = 2N(L·N) − L and cos β = R·V
/// (with the model's [`Highlight::NDotH`], Blinn's: H = norm(V + L) and
/// N·H), then the highlight max(cos β, 0)ⁿ (max(N·H, 0)ⁿ) where the term is added: everywhere, or only
/// where cos α > 0 when the material's specular needs a lit surface.
/// Evaluated when the term is added in some lane, or explained.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn specular<T: Scalar, R: RuleSet<T>>(
    mat: &Material<T>,
    term: &mut LightTerm<T>,
    s: &Surface<T>,
    v: &V3<T>,
    want_spec: bool,
    rules: &R,
    at: (usize, usize),
    tr: &mut impl Trace,
) {
    let n = &s.normal;
    let gate = if mat.specular_requires_lit {
        term.cos_alpha.gt_mask(&T::zero())
    } else {
        T::Mask::from(true)
    };
    let active = want_spec && gate.any();
    if !(active || listening(tr)) {
        return;
    }
    let two_ln = T::from_i64(2) * term.cos_alpha.clone();
    let r = rules.given_vec(Part::R, rules.reflect(n, &term.l, &two_ln));
    let cos_beta = rules.given_num(Part::CosBeta, dot(&r, v));
    tr.step(|| {
        Step::new(
            label(at, LightPart::Reflection),
            "R = 2N(L·N) − L,  cos β = R·V",
        )
        .val(Name::math("2(L·N)"), Val::num(&two_ln))
        .sub(
            Name::math("2(L·N)"),
            Subst::new("2·{}", vec![Val::num(&term.cos_alpha)]),
        )
        .val(Name::math("V"), Val::vec3(v))
        .res(Name::math("R"), Val::vec3(&r))
        .sub(
            Name::math("R"),
            Subst::new(
                "{}·{} − {}",
                vec![Val::num(&two_ln), Val::vec3(n), Val::vec3(&term.l)],
            ),
        )
        .res(Name::math("cos β"), Val::num(&cos_beta))
        .sub(Name::math("cos β"), Subst::dot(&r, v))
    });
    let cos_spec = match mat.model.highlight() {
        Highlight::NDotH => {
            let (h, nh) = half_vector(n, &term.l, v, s.camera.is_some(), at, tr);
            term.h = Some(h);
            term.cos_nh = Some(nh.clone());
            nh
        }
        Highlight::RDotV => cos_beta.clone(),
    };
    term.r = Some(r);
    term.cos_beta = Some(cos_beta);
    if active {
        let hv = pow(&rules.highlight_base(&cos_spec), &mat.shininess);
        term.highlight = T::select(gate, hv, T::zero());
        tr.step(|| highlight_step(mat, &cos_spec, &term.highlight, at));
    } else {
        tr.step(|| {
            Step::new(label(at, LightPart::Highlight), "")
                .res(Name::Highlight, Val::num(&T::zero()))
                .note(if !want_spec {
                    Msg::SpecularOff
                } else {
                    Msg::NoHighlightBehind
                })
        });
    }
}

/// Blinn's half vector H = norm(V + L) (V + L itself where |V + L| = 0)
/// and N·H.
#[inline(always)]
fn half_vector<T: Scalar>(
    n: &V3<T>,
    l: &V3<T>,
    v: &V3<T>,
    local: bool,
    at: (usize, usize),
    tr: &mut impl Trace,
) -> (V3<T>, T) {
    let sum = add(v, l);
    // |V + L| ≤ 2 for unit V and L: no overflow, so a plain √(s·s) will do
    let len = dot(&sum, &sum).sqrt();
    let away = len.gt_mask(&T::zero());
    let h = if away.any() {
        let q = crate::num::vec::div(&sum, &len);
        V3::from_fn(|k, _| T::select(away, q[k].clone(), sum[k].clone()))
    } else {
        sum.clone()
    };
    let nh = dot(n, &h);
    tr.step(|| {
        Step::new(
            label(at, LightPart::HalfVector),
            if local {
                "H = norm(norm(Cp − Vp) + Ldir) = norm(V + L),  cos = N·H"
            } else {
                "H = norm((0, 0, 1) + Ldir) = norm(V + L),  cos = N·H"
            },
        )
        .val(Name::math("V + L"), Val::vec3(&sum))
        .sub(
            Name::math("V + L"),
            Subst::new("{} + {}", vec![Val::vec3(v), Val::vec3(l)]),
        )
        .val(Name::math("|V + L|"), Val::length(&sum, &len))
        .sub(Name::math("|V + L|"), Subst::norm(&sum))
        .res(Name::math("H"), Val::vec3(&h))
        .sub(
            Name::math("H"),
            Subst::quotient(Val::vec3(&sum), Val::length(&sum, &len)),
        )
        .res(Name::math("N·H"), Val::num(&nh))
        .sub(Name::math("N·H"), Subst::dot(n, &h))
        .note(if local {
            Msg::LocalViewer
        } else {
            Msg::NoLocalViewer
        })
    });
    (h, nh)
}

/// The step of the highlight max(cos β, 0)ⁿ (Blinn: max(N·H, 0)ⁿ), with
/// `cos` = cos β (N·H).
fn highlight_step<T: Scalar>(
    mat: &Material<T>,
    cos: &T,
    highlight: &T,
    at: (usize, usize),
) -> Step {
    let s = Step::new(
        label(at, LightPart::Highlight),
        match mat.model.highlight() {
            Highlight::NDotH => "max(N·H, 0)ⁿ",
            Highlight::RDotV => "max(cos β, 0)ⁿ",
        },
    )
    .val(Name::math("n"), Val::num(&mat.shininess))
    .res(Name::Highlight, Val::num(highlight))
    .sub(
        Name::Highlight,
        Subst::new(
            "max({}{,}0)^{}",
            vec![Val::num(cos), Val::num(&mat.shininess)],
        ),
    );
    if mat.shininess.is_zero_value() {
        s.note(Msg::ShininessZero)
    } else {
        s
    }
}

/// Direct3D's spot factor: ρ = (−L)·axis; 1 where ρ ≥ cos(θ/2), 0 where
/// ρ ≤ cos(φ/2), else ((ρ − cos(φ/2)) / (cos(θ/2) − cos(φ/2)))^falloff.
#[inline(always)]
pub fn spot_factor<T: Scalar>(
    l: &V3<T>,
    axis: &V3<T>,
    theta: &T,
    phi: &T,
    falloff: &T,
    at: (usize, usize),
    tr: &mut impl Trace,
) -> T {
    let two = T::from_i64(2);
    let rho = -dot(l, axis);
    let cos_t = (theta.clone() / two.clone()).cos_deg();
    let cos_p = (phi.clone() / two).cos_deg();
    // Outside the inner cone: ρ < cos(θ/2); of those, in the penumbra: ρ > cos(φ/2).
    let outside = cos_t.gt_mask(&rho);
    let penumbra = outside & rho.gt_mask(&cos_p);
    let f = T::select(outside, T::zero(), T::one());
    let f = if penumbra.any() {
        let x = (rho.clone() - cos_p.clone()) / (cos_t.clone() - cos_p.clone());
        T::select(penumbra, pow(&x, falloff), f)
    } else {
        f
    };
    tr.step(|| {
        let zone = if !outside.any() {
            SpotZone::Inner
        } else if !penumbra.any() {
            SpotZone::Outer
        } else {
            SpotZone::Penumbra
        };
        let s = Step::new(label(at, LightPart::Spot), Msg::FSpot)
            .val(Name::math("ρ"), Val::num(&rho))
            .sub(Name::math("ρ"), Subst::dot(l, axis).within("−(", ")"))
            .val(Name::math("cos(θ/2)"), Val::num(&cos_t))
            .sub(
                Name::math("cos(θ/2)"),
                Subst::new(
                    "cos({}°)",
                    vec![Val::num(&(theta.clone() / T::from_i64(2)))],
                ),
            )
            .val(Name::math("cos(φ/2)"), Val::num(&cos_p))
            .sub(
                Name::math("cos(φ/2)"),
                Subst::new("cos({}°)", vec![Val::num(&(phi.clone() / T::from_i64(2)))]),
            )
            .val(Name::math("falloff"), Val::num(falloff))
            .res(Name::math("Spot"), Val::num(&f));
        let s = match zone {
            SpotZone::Penumbra => s.sub(
                Name::math("Spot"),
                Subst::new(
                    "(({} − {})/({} − {}))^{}",
                    [&rho, &cos_p, &cos_t, &cos_p, falloff]
                        .map(Val::num)
                        .to_vec(),
                ),
            ),
            _ => s,
        };
        s.note(Msg::SpotIn(zone))
    });
    f
}
