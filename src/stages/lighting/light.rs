//! One light at the point: direction and distance, range, attenuation,
//! spot factor, cos α, R and cos β, the half vector H and the highlight.

use super::{
    label, listening, max0, pow, Light, LightKind, LightTerm, Material, Model, RuleSet, Surface,
    TextRules,
};
use crate::msg::{LightPart, Msg, SpotZone};
use crate::num::vec::{add, dot, sub, V3};
use crate::num::Scalar;
use crate::stages::trace::{Step, Trace, Val};

/// One light's geometry and factors at the point; `None` when the point is
/// beyond the light's range (the light is not evaluated at all) or at the
/// light's own position. `at` = (index, number of lights), for step titles.
#[inline]
pub fn light_term<T: Scalar>(
    mat: &Material<T>,
    light: &Light<T>,
    at: (usize, usize),
    s: &Surface<T>,
    v: &V3<T>,
    want_spec: bool,
    tr: &mut impl Trace,
) -> Option<LightTerm<T>> {
    light_term_with(mat, light, at, s, v, want_spec, &TextRules, tr)
}

/// [`light_term`] under the given rules ([`super::Rules`] or [`TextRules`]);
/// always inlined (into `shade`'s body too).
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
    let n = &s.normal;
    // Lanes of a lane type that the light does not reach: 0 there, else 1.
    let mut keep: Option<T> = None;
    // Direction to the light, distance and range
    let (l, distance) = match &light.kind {
        LightKind::Directional { dir } => (dir.clone(), None),
        LightKind::Point { pos } | LightKind::Spot { pos, .. } => {
            let to = sub(pos, &s.position);
            let d2 = dot(&to, &to);
            if let Some(r) = &light.range {
                if d2 > r.clone() * r.clone() {
                    tr.step(|| {
                        Step::new(label(at, LightPart::OutOfRange), Msg::FOutOfRange)
                            .val("d²", Val::num(&d2))
                            .val("range²", Val::num(&(r.clone() * r.clone())))
                            .res("contributes", Val::Bool(false))
                            .note(Msg::BeyondRange)
                    });
                    return None;
                }
            }
            let d = d2.sqrt();
            if d.is_zero_value() {
                return None;
            }
            // A lane type reaches here when *some* lane is in range and away
            // from the light: the others get nothing from it, as a scalar
            // that returned above (no work for a one-lane scalar).
            if T::LANES > 1 {
                let reach = d.if_gt(&T::zero(), T::one, T::zero);
                keep = Some(match &light.range {
                    Some(r) => d2.if_gt(&(r.clone() * r.clone()), T::zero, || reach),
                    None => reach,
                });
            }
            let l = crate::num::vec::div(&to, &d);
            tr.step(|| {
                Step::new(
                    label(at, LightPart::Direction),
                    "d = |Pl − P|,  L = (Pl − P)/d",
                )
                .val("Pl", Val::vec3(pos))
                .val("P", Val::vec3(&s.position))
                .val("d", Val::num(&d))
                .res("L", Val::vec3(&l))
                .note(match &light.range {
                    Some(_) => Msg::WithinRange,
                    None => Msg::NoRange,
                })
            });
            (l, Some(d))
        }
    };

    // Attenuation 1/(a0 + a1·d + a2·d²) and the spot factor
    let attenuation = match &distance {
        Some(d) => {
            let a = &light.attenuation;
            let den =
                a[0].clone() + a[1].clone() * d.clone() + a[2].clone() * d.clone() * d.clone();
            let att = T::one() / den.clone();
            let att = match &keep {
                Some(k) => att * k.clone(),
                None => att,
            };
            tr.step(|| {
                Step::new(
                    label(at, LightPart::Attenuation),
                    "Att = 1/(a0 + a1·d + a2·d²)",
                )
                .val("(a0, a1, a2)", Val::List(a.iter().map(Val::num).collect()))
                .val("d", Val::num(d))
                .val("a0 + a1·d + a2·d²", Val::num(&den))
                .res("Att", Val::num(&att))
            });
            att
        }
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
    let listening = listening(tr);
    // cos α = L·N
    let cos_alpha = dot(&l, n);
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
    if !listening && (term.attenuation.clone() * term.spot.clone()).is_zero_value() {
        return Some(term);
    }
    tr.step(|| {
        let cos_alpha = &term.cos_alpha;
        let s = Step::new(label(at, LightPart::Incidence), Msg::FIncidence)
            .val("L", Val::vec3(&term.l))
            .val("N", Val::vec3(n))
            .res("cos α", Val::num(cos_alpha))
            .res("max(cos α, 0)", Val::num(&max0(cos_alpha)));
        if *cos_alpha < T::zero() {
            s.note(if mat.specular_requires_lit {
                Msg::Behind(true)
            } else {
                Msg::Behind(false)
            })
        } else {
            s
        }
    });

    // Specular: R and cos β (Phong), or H and N·H (Blinn)
    // cos α > 0 (in some lane, for a lane type).
    let lit = term.cos_alpha.any_gt(&T::zero());
    let active = want_spec && (lit || !mat.specular_requires_lit);
    if !(active || listening) {
        return Some(term);
    }
    let two_ln = T::from_i64(2) * term.cos_alpha.clone();
    let r = rules.reflect(n, &term.l, &two_ln);
    let cos_beta = dot(&r, v);
    tr.step(|| {
        Step::new(
            label(at, LightPart::Reflection),
            "R = 2N(L·N) − L,  cos β = R·V",
        )
        .val("2(L·N)", Val::num(&two_ln))
        .val("V", Val::vec3(v))
        .res("R", Val::vec3(&r))
        .res("cos β", Val::num(&cos_beta))
    });
    let cos_spec = if mat.model == Model::Blinn {
        let sum = add(v, &term.l);
        // |V + L| ≤ 2 for unit V and L: no overflow, so a plain √(s·s) will do
        let len = dot(&sum, &sum).sqrt();
        let h = if len.is_zero_value() {
            sum
        } else {
            crate::num::vec::div(&sum, &len)
        };
        let nh = dot(n, &h);
        tr.step(|| {
            Step::new(
                label(at, LightPart::HalfVector),
                if s.camera.is_some() {
                    "H = norm(norm(Cp − Vp) + Ldir) = norm(V + L),  cos = N·H"
                } else {
                    "H = norm((0,0,1) + Ldir) = norm(V + L),  cos = N·H"
                },
            )
            .val("V + L", Val::vec3(&add(v, &term.l)))
            .res("H", Val::vec3(&h))
            .res("N·H", Val::num(&nh))
            .note(if s.camera.is_some() {
                Msg::LocalViewer
            } else {
                Msg::NoLocalViewer
            })
        });
        term.h = Some(h);
        term.cos_nh = Some(nh.clone());
        nh
    } else {
        cos_beta.clone()
    };
    term.r = Some(r);
    term.cos_beta = Some(cos_beta);
    if active {
        // Only where cos α > 0 with --specular-requires-lit (every lane but
        // those of a lane type that are unlit); else everywhere (gate 1).
        // A lane type computes xⁿ for all lanes and keeps the gated ones:
        // no closure, so the renderer's batch code stays one inlined body
        // (an outlined closure would be compiled without the AVX2 of its
        // caller). A scalar computes it only when the gate is open.
        let gate = if mat.specular_requires_lit {
            term.cos_alpha.clone()
        } else {
            T::one()
        };
        term.highlight = if T::LANES > 1 {
            let hv = pow(&rules.highlight_base(&cos_spec), &mat.shininess);
            gate.if_gt(&T::zero(), || hv, T::zero)
        } else if gate > T::zero() {
            pow(&rules.highlight_base(&cos_spec), &mat.shininess)
        } else {
            T::zero()
        };
        tr.step(|| {
            let s = Step::new(
                label(at, LightPart::Highlight),
                if mat.model == Model::Blinn {
                    "max(N·H, 0)ⁿ"
                } else {
                    "max(cos β, 0)ⁿ"
                },
            )
            .val("n", Val::num(&mat.shininess))
            .res("highlight", Val::num(&term.highlight));
            if mat.shininess.is_zero_value() {
                s.note(Msg::ShininessZero)
            } else {
                s
            }
        });
    } else {
        tr.step(|| {
            Step::new(label(at, LightPart::Highlight), Msg::FNotAdded)
                .res("highlight", Val::num(&T::zero()))
                .note(if !want_spec {
                    Msg::SpecularOff
                } else {
                    Msg::NoHighlightBehind
                })
        });
    }
    Some(term)
}

/// Direct3D's spot factor: ρ = (−L)·axis; 1 when ρ ≥ cos(θ/2), 0 when
/// ρ ≤ cos(φ/2), else ((ρ − cos(φ/2)) / (cos(θ/2) − cos(φ/2)))^falloff.
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
    // 1 where ρ ≥ cos(θ/2), else 0 where ρ ≤ cos(φ/2), else the penumbra
    // (per lane for a lane type).
    let penumbra = || {
        let x = (rho.clone() - cos_p.clone()) / (cos_t.clone() - cos_p.clone());
        pow(&x, falloff)
    };
    let f = cos_t.if_gt(&rho, || rho.if_gt(&cos_p, penumbra, T::zero), T::one);
    tr.step(|| {
        let where_ = if rho >= cos_t {
            Msg::SpotIn(SpotZone::Inner)
        } else if rho <= cos_p {
            Msg::SpotIn(SpotZone::Outer)
        } else {
            Msg::SpotIn(SpotZone::Penumbra)
        };
        Step::new(
            label(at, LightPart::Spot),
            "ρ = (−L)·axis;  Spot = 1 if ρ ≥ cos(θ/2), 0 if ρ ≤ cos(φ/2), else ((ρ − cos(φ/2))/(cos(θ/2) − cos(φ/2)))^falloff",
        )
        .val("ρ", Val::num(&rho))
        .val("cos(θ/2)", Val::num(&cos_t))
        .val("cos(φ/2)", Val::num(&cos_p))
        .val("falloff", Val::num(falloff))
        .res("Spot", Val::num(&f))
        .note(where_)
    });
    f
}
