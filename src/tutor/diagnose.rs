//! The catalog of known mistakes, in one place. Each mistake recomputes a
//! problem the wrong way — by running the real stages on altered inputs
//! (`altered`), or with one stage result altered between stages
//! ([`run::Hooks`](crate::tutor::run::Hooks)), or with one documented change to the results —
//! so that `grafika check` can say which mistake reproduces a wrong answer.
//! No pipeline math is repeated here, and no words: a mistake is said by
//! its [`Code`] in each language's words (`ReportWords::mistake`).
//!
//! Adding a mistake is a [`Code`]: the compiler then asks for its
//! spelling, its place in the order ([`Code::all`], the catalog's order),
//! its words, and how the problem is recomputed with it ([`Code::apply`],
//! one function per mistake below).

use crate::input::answer;
use crate::input::fields::{Num, Vec3In};
use crate::input::lights::LightType;
use crate::input::lights::Setup;
use crate::input::problem::ProblemIn;
use crate::num::vec;
use crate::num::{AngleUnit, Expr, Real, Scalar};
use crate::stages::camera::{self, Basis};
use crate::stages::clip::{self, Status};
use crate::stages::lighting::{LightKind, Rules};
use crate::stages::trace::Val;
use crate::stages::window::Window;
use crate::tutor::key::{Cut, Edge, Field, Key, Part, Shading, Value};
use crate::tutor::parts::clip::ClipResult;
use crate::tutor::run::Hooks;
use crate::tutor::solution::PartResult;
use crate::tutor::solve;

pub use crate::tutor::solution::Results;

/// A mistake of the catalog: what `check` and `practice` name, and what
/// the words say in each language (`ReportWords::mistake`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Code {
    /// `cross_order`: u = n × Vup instead of Vup × n.
    CrossOrder,
    /// `n_reversed`: n from Pr − Pe instead of Pe − Pr.
    NReversed,
    /// `n_not_normalized`: n = Pe − Pr not divided by |Pe − Pr|.
    NNotNormalized,
    /// `u_not_normalized`: u = Vup × n not divided by |Vup × n|.
    UNotNormalized,
    /// `uv_swapped`: u and v swapped (the camera's x axis written as y).
    UvSwapped,
    /// `fovy_not_halved`: tan(fovy) instead of tan(fovy/2).
    FovyNotHalved,
    /// `degrees_as_radians`: The angle in degrees given to tan as radians.
    DegreesAsRadians,
    /// `height_is_half_extent`: h = near·tan(fovy/2) written as the height.
    HeightIsHalfExtent,
    /// `height_as_half_extent`: near·tan(fovy/2) taken as the full height.
    HeightAsHalfExtent,
    /// `d_sign`: The projection plane at z = +near instead of z = −near.
    DSign,
    /// `matrix_transposed`: The view matrix transposed (P·M).
    MatrixTransposed,
    /// `mcam_as_view`: Mcam (camera to world) handed in as the view matrix.
    McamAsView,
    /// `outcode_reversed`: The outcode bits in reverse order.
    OutcodeReversed,
    /// `endpoint_kept`: An endpoint outside the box kept instead of its intersection.
    EndpointKept,
    /// `t_from_p1`: t measured from P1 instead of P0.
    TFromP1,
    /// `reflect_plus_l`: R = 2N(L·N) + L instead of 2N(L·N) − L.
    ReflectPlusL,
    /// `specular_no_max`: The specular term without max(·, 0).
    SpecularNoMax,
    /// `pixel_y_from_top`: py counted from the top edge, H − py.
    PixelYFromTop,
    /// `eye_no_translation`: The eye coordinates (u·P, v·P, n·P), Peye not subtracted.
    EyeNoTranslation,
    /// `aspect_inverted`: right = top / aspect instead of aspect·top.
    AspectInverted,
    /// `light_not_normalized`: L not divided by |L|.
    LightNotNormalized,
    /// `normal_not_normalized`: N not divided by |N|.
    NormalNotNormalized,
    /// `cos_in_radians`: cos of an angle in degrees taken in radian mode.
    CosInRadians,
    /// `copied_misprint`: The value the source printed, wrong by its errata.
    CopiedMisprint,
}

impl Code {
    /// The code's spelling, the only place it is written: stable, as
    /// autograders count it (JSON, CSV, the class report, docs).
    pub fn as_str(self) -> &'static str {
        match self {
            Code::CrossOrder => "cross_order",
            Code::NReversed => "n_reversed",
            Code::NNotNormalized => "n_not_normalized",
            Code::UNotNormalized => "u_not_normalized",
            Code::UvSwapped => "uv_swapped",
            Code::FovyNotHalved => "fovy_not_halved",
            Code::DegreesAsRadians => "degrees_as_radians",
            Code::HeightIsHalfExtent => "height_is_half_extent",
            Code::HeightAsHalfExtent => "height_as_half_extent",
            Code::DSign => "d_sign",
            Code::MatrixTransposed => "matrix_transposed",
            Code::McamAsView => "mcam_as_view",
            Code::OutcodeReversed => "outcode_reversed",
            Code::EndpointKept => "endpoint_kept",
            Code::TFromP1 => "t_from_p1",
            Code::ReflectPlusL => "reflect_plus_l",
            Code::SpecularNoMax => "specular_no_max",
            Code::PixelYFromTop => "pixel_y_from_top",
            Code::EyeNoTranslation => "eye_no_translation",
            Code::AspectInverted => "aspect_inverted",
            Code::LightNotNormalized => "light_not_normalized",
            Code::NormalNotNormalized => "normal_not_normalized",
            Code::CosInRadians => "cos_in_radians",
            Code::CopiedMisprint => "copied_misprint",
        }
    }

    /// Every code, in the catalog's order.
    pub fn all() -> Vec<Code> {
        std::iter::successors(Some(Code::CrossOrder), |c| c.next()).collect()
    }

    /// The code after this one: an exhaustive match, so a new code is
    /// listed (in the catalog's order) as soon as it compiles.
    fn next(self) -> Option<Code> {
        use Code::*;
        match self {
            CrossOrder => Some(NReversed),
            NReversed => Some(NNotNormalized),
            NNotNormalized => Some(UNotNormalized),
            UNotNormalized => Some(UvSwapped),
            UvSwapped => Some(FovyNotHalved),
            FovyNotHalved => Some(DegreesAsRadians),
            DegreesAsRadians => Some(HeightIsHalfExtent),
            HeightIsHalfExtent => Some(HeightAsHalfExtent),
            HeightAsHalfExtent => Some(DSign),
            DSign => Some(MatrixTransposed),
            MatrixTransposed => Some(McamAsView),
            McamAsView => Some(OutcodeReversed),
            OutcodeReversed => Some(EndpointKept),
            EndpointKept => Some(TFromP1),
            TFromP1 => Some(ReflectPlusL),
            ReflectPlusL => Some(SpecularNoMax),
            SpecularNoMax => Some(PixelYFromTop),
            PixelYFromTop => Some(EyeNoTranslation),
            EyeNoTranslation => Some(AspectInverted),
            AspectInverted => Some(LightNotNormalized),
            LightNotNormalized => Some(NormalNotNormalized),
            NormalNotNormalized => Some(CosInRadians),
            CosInRadians => Some(CopiedMisprint),
            CopiedMisprint => None,
        }
    }
}

impl std::fmt::Display for Code {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A code in JSON is its spelling ([`Code::as_str`]).
impl serde::Serialize for Code {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

impl Code {
    /// The problem's results computed with this mistake (several variants
    /// when the mistake can be made in more than one place), or None when
    /// the mistake does not apply to the problem. One arm per code and no
    /// other: a new code stops the build here until it says how the
    /// problem is recomputed with it.
    pub fn apply(self, p: &ProblemIn) -> Option<Vec<Results>> {
        match self {
            Code::CrossOrder => cross_order(p),
            Code::NReversed => n_reversed(p),
            Code::NNotNormalized => n_not_normalized(p),
            Code::UNotNormalized => u_not_normalized(p),
            Code::UvSwapped => uv_swapped(p),
            Code::FovyNotHalved => fovy_not_halved(p),
            Code::DegreesAsRadians => degrees_as_radians(p),
            Code::HeightIsHalfExtent => height_is_half_extent(p),
            Code::HeightAsHalfExtent => height_as_half_extent(p),
            Code::DSign => d_sign(p),
            Code::MatrixTransposed => matrix_transposed(p),
            Code::McamAsView => mcam_as_view(p),
            Code::OutcodeReversed => outcode_reversed(p),
            Code::EndpointKept => endpoint_kept(p),
            Code::TFromP1 => t_from_p1(p),
            Code::ReflectPlusL => reflect_plus_l(p),
            Code::SpecularNoMax => specular_no_max(p),
            Code::PixelYFromTop => pixel_y_from_top(p),
            Code::EyeNoTranslation => eye_no_translation(p),
            Code::AspectInverted => aspect_inverted(p),
            Code::LightNotNormalized => unnormalized(p, Unit::L),
            Code::NormalNotNormalized => unnormalized(p, Unit::N),
            Code::CosInRadians => cos_in_radians(p),
            Code::CopiedMisprint => copied_misprint(p),
        }
    }
}

/// u = n × Vup instead of Vup × n: the view-up vector negated.
fn cross_order(p: &ProblemIn) -> Option<Vec<Results>> {
    altered(p, |q| map_camera(q, |c| c.up = neg3(&c.up)))
}

/// n from Pr − Pe instead of Pe − Pr: Pe − (2Pe − Pr) = Pr − Pe, the
/// look-at point reflected through the eye.
fn n_reversed(p: &ProblemIn) -> Option<Vec<Results>> {
    altered(p, |q| {
        map_camera(q, |c| {
            let look = std::array::from_fn(|k| {
                Num(Expr::Sub(
                    Box::new(Expr::Mul(
                        Box::new(Expr::Lit("2".into())),
                        Box::new(c.eye[k].0.clone()),
                    )),
                    Box::new(c.look[k].0.clone()),
                ))
            });
            c.look = Vec3In(look);
        })
    })
}

/// n = Pe − Pr not divided by |Pe − Pr|: n (and v = n × u with it)
/// scaled by |Pe − Pr|.
fn n_not_normalized(p: &ProblemIn) -> Option<Vec<Results>> {
    hooked_exact(
        p,
        Hooks {
            basis: |b| {
                let s = b.dist.clone();
                scale_axes(b, [Real::from_i64(1), s.clone(), s]);
            },
            ..Hooks::default()
        },
    )
}

/// u = Vup × n not divided by |Vup × n|: Vup × n = (Vup × d)/|d|, of
/// length |Vup × d|/|d|, scales u (and v = n × u with it).
fn u_not_normalized(p: &ProblemIn) -> Option<Vec<Results>> {
    hooked_exact(
        p,
        Hooks {
            basis: |b| {
                let s = b.vxn_norm.clone();
                scale_axes(b, [s.clone(), s, Real::from_i64(1)]);
            },
            ..Hooks::default()
        },
    )
}

/// u and v swapped: the camera's x axis written where its y axis goes,
/// and the other way round; the view matrix's first two rows and the eye
/// coordinates' x and y follow (and the projection and pixels after them).
fn uv_swapped(p: &ProblemIn) -> Option<Vec<Results>> {
    hooked_exact(
        p,
        Hooks {
            basis: |b| {
                std::mem::swap(&mut b.u, &mut b.v);
                std::mem::swap(&mut b.su, &mut b.sv);
                b.norms.swap(1, 2);
            },
            ..Hooks::default()
        },
    )
}

/// tan(fovy) instead of tan(fovy/2): the window scaled by
/// tan(fovy)/tan(fovy/2), not fovy doubled as an input (over 90° the
/// doubled angle is refused, yet the mistake gives a window, top =
/// near·tan(fovy) < 0, a student can write).
fn fovy_not_halved(p: &ProblemIn) -> Option<Vec<Results>> {
    hooked(
        p,
        Hooks {
            window: |w, fovy| {
                let half = (fovy / 2.0).to_radians();
                scale_window(w, fovy.to_radians().tan() / half.tan());
            },
            ..Hooks::default()
        },
    )
}

/// The angle in degrees given to tan as radians: as an input this would
/// be an angle of thousands of degrees, which the window rejects, so the
/// window is scaled by the ratio of the tangents, tan(fovy/2 rad) /
/// tan(fovy/2 °). Only for a fovy given in degrees.
fn degrees_as_radians(p: &ProblemIn) -> Option<Vec<Results>> {
    let deg = p
        .perspective
        .as_ref()
        .and_then(|x| x.fovy.as_ref())
        .is_some_and(|f| f.0.unit == AngleUnit::Deg);
    if !deg {
        return None;
    }
    hooked(
        p,
        Hooks {
            window: |w, fovy| {
                let half = fovy / 2.0;
                scale_window(w, half.tan() / half.to_radians().tan());
            },
            ..Hooks::default()
        },
    )
}

/// h = near·tan(fovy/2) written as the height (and right as the width):
/// written, not used, so the window's edges and the pixels stay right
/// (the text's own h and W).
fn height_is_half_extent(p: &ProblemIn) -> Option<Vec<Results>> {
    let mut t = solved(p)?;
    for (size, half) in [(Edge::Height, Edge::Top), (Edge::Width, Edge::Right)] {
        let edge = |e| Key::new(Part::Window, Value::Field(Field::Edge(e, false)));
        let h = t.get_mut(&edge(half))?.clone();
        *t.get_mut(&edge(size))? = h;
    }
    Some(vec![t])
}

/// near·tan(fovy/2) taken as the full height: the window of half the top
/// (right/top is the aspect).
fn height_as_half_extent(p: &ProblemIn) -> Option<Vec<Results>> {
    hooked(
        p,
        Hooks {
            window: |w, _| {
                let aspect = w.right / w.top;
                *w = crate::stages::window::edges(w.top / 2.0, &aspect);
            },
            ..Hooks::default()
        },
    )
}

/// The projection plane at z = +near instead of z = −near: d negated (or
/// d = near where only near is given).
fn d_sign(p: &ProblemIn) -> Option<Vec<Results>> {
    let per = p.perspective.as_ref()?;
    let d = match (&per.d, &per.near) {
        (Some(d), _) => Expr::Neg(Box::new(d.0.clone())),
        (None, Some(n)) => n.0.clone(),
        _ => return None,
    };
    altered(p, |q| {
        if let Some(x) = q.perspective.as_mut() {
            x.d = Some(Num(d.clone()));
        }
    })
}

/// The view matrix transposed (P·M): one documented change to the
/// results, the matrix's rows written as its columns.
fn matrix_transposed(p: &ProblemIn) -> Option<Vec<Results>> {
    let mut t = solved(p)?;
    let m = t.get_mut(&Key::new(Part::View, Value::Field(Field::Matrix)))?;
    if let Val::List(rows) = m {
        let cells: Vec<Vec<Val>> = rows
            .iter()
            .map(|r| match r {
                Val::List(c) => c.clone(),
                _ => vec![],
            })
            .collect();
        let n = cells.len();
        *rows = (0..n)
            .map(|c| Val::List((0..n).map(|r| cells[r][c].clone()).collect()))
            .collect();
    }
    Some(vec![t])
}

/// Mcam = T(Pe)·[u v n], the camera-to-world matrix, handed in as the view
/// matrix V = Mcam⁻¹ ([`camera::camera_matrix`], the stage's own): variant
/// 0 writes it and takes the eye coordinates right, variant 1 also takes
/// the eye coordinates as Mcam·P (and the projection and pixels after
/// them).
fn mcam_as_view(p: &ProblemIn) -> Option<Vec<Results>> {
    p.camera.as_ref()?;
    let with = |points| Hooks {
        view: Some((camera::camera_matrix, points)),
        ..Hooks::default()
    };
    let written = hooked(p, with(false))?;
    let mut variants = written;
    if let Some(mut used) = hooked(p, with(true)) {
        variants.append(&mut used);
    }
    Some(variants)
}

/// The outcode bits in reverse order: every outcode, the ends' (code0,
/// code1) and each intersection's (code), read backwards.
fn outcode_reversed(p: &ProblemIn) -> Option<Vec<Results>> {
    let code = Cut::Code.key();
    let reverse = |v: &mut Val| {
        if let Val::Text(s) = v {
            *s = s.chars().rev().collect();
        }
    };
    let mut t = solved(p)?;
    for_each_clip(&mut t, |r| {
        reverse(&mut r.code0);
        reverse(&mut r.code1);
        if let Val::Map(planes) = &mut r.intersections {
            for (_, cut) in planes.iter_mut() {
                if let Val::Map(kv) = cut {
                    kv.iter_mut()
                        .filter(|(k, _)| *k == code)
                        .for_each(|(_, v)| reverse(v));
                }
            }
        }
    });
    Some(vec![t])
}

/// An endpoint outside the box kept instead of its intersection: variant
/// 0 keeps P0, variant 1 keeps P1, in every clipped segment.
fn endpoint_kept(p: &ProblemIn) -> Option<Vec<Results>> {
    let base = solved(p)?;
    let ends = segment_ends(p)?;
    let clipped = Val::text(Status::Clipped.as_str());
    let variants = (0..2)
        .map(|which| {
            let mut t = base.clone();
            let mut i = 0;
            for_each_clip(&mut t, |r| {
                let cut = r.status == clipped;
                if let (true, Some(kept), Val::List(pts)) = (cut, ends.get(i), &mut r.segment) {
                    if pts.len() == 2 {
                        pts[which] = kept[which].clone();
                    }
                }
                i += 1;
            });
            t
        })
        .collect();
    Some(variants)
}

/// t measured from P1 instead of P0: each intersection's t is 1 − t.
/// Variant 0 puts it into the text's P(t) = P0 + t·(P1 − P0), so each
/// intersection lands at its mirror image about the segment's midpoint,
/// with the codes, the kept points and the clipped segment that follow;
/// variant 1 writes the t only (its points from P1, P(t) = P1 + t·(P0 −
/// P1), are right).
fn t_from_p1(p: &ProblemIn) -> Option<Vec<Results>> {
    p.clip.as_ref()?;
    let through = hooked(
        p,
        Hooks {
            clip: |r, b, ends| {
                for i in &mut r.intersections {
                    i.t = 1.0 - i.t;
                    i.point = clip::point_at(ends.0, ends.1, &i.t);
                    i.code = clip::outcode(b, &i.point);
                }
                if !r.intersections.is_empty() {
                    r.segment =
                        clip::kept_part(&r.intersections, (ends.0, r.code0), (ends.1, r.code1));
                    r.status = if r.segment.is_some() {
                        Status::Clipped
                    } else {
                        Status::Rejected
                    };
                }
            },
            ..Hooks::default()
        },
    )?;
    let written = hooked(
        p,
        Hooks {
            clip: |r, _, _| {
                for i in &mut r.intersections {
                    i.t = 1.0 - i.t;
                }
            },
            ..Hooks::default()
        },
    )?;
    Some([through, written].concat())
}

/// Each segment's ends [P0, P1] as results, in the problem's order.
fn segment_ends(p: &ProblemIn) -> Option<Vec<[Val; 2]>> {
    let c = p.clip.as_ref()?;
    let points: Vec<(String, vec::V3<f64>)> = p
        .points()
        .ok()?
        .iter()
        .map(|(n, v)| {
            let e: Option<Vec<f64>> = v.iter().map(|x| x.0.eval::<f64>().ok()).collect();
            e.map(|e| (n.clone(), vec::v3(e[0], e[1], e[2])))
        })
        .collect::<Option<_>>()?;
    let field = Part::Clip.key();
    let end = |r| {
        crate::tutor::parts::clip::point_ref(&field, r, &points)
            .ok()
            .map(|q| Val::vec3(&q))
    };
    c.segment
        .iter()
        .map(|s| Some([end(&s.from)?, end(&s.to)?]))
        .collect()
}

/// R = 2N(L·N) + L instead of 2N(L·N) − L: the reflection rule replaced.
fn reflect_plus_l(p: &ProblemIn) -> Option<Vec<Results>> {
    p.shade.as_ref()?;
    hooked(
        p,
        Hooks {
            shade: Rules {
                reflect: |n, l, two_ln| vec::add(&vec::scale(n, two_ln), l),
                ..Rules::default()
            },
            ..Hooks::default()
        },
    )
}

/// The specular term without max(·, 0): the highlight's base as it is.
fn specular_no_max(p: &ProblemIn) -> Option<Vec<Results>> {
    p.shade.as_ref()?;
    hooked(
        p,
        Hooks {
            shade: Rules {
                highlight_base: |c| *c,
                ..Rules::default()
            },
            ..Hooks::default()
        },
    )
}

/// py counted from the top edge: one documented change to the results,
/// each pixel's py becomes H − py.
fn pixel_y_from_top(p: &ProblemIn) -> Option<Vec<Results>> {
    let h = p.perspective.as_ref()?.viewport.as_ref()?[1]
        .0
        .eval::<f64>()
        .ok()?;
    let mut t = solved(p)?;
    let pixels = Key::new(Part::Viewport, Value::Field(Field::Pixels));
    let Val::Map(pixels) = t.get_mut(&pixels)? else {
        return None;
    };
    for (_, px) in pixels.iter_mut() {
        if let Val::List(xy) = px {
            if let Some(Val::Num(y)) = xy.get(1) {
                xy[1] = Val::num(&(h - y.value));
            }
        }
    }
    Some(vec![t])
}

/// The eye coordinates (u·P, v·P, n·P), Peye not subtracted: the same
/// camera axes with the eye at the origin, Pe' = 0 and Pr' = Pr − Pe keep
/// n, u, v and drop the translation by −Pe.
fn eye_no_translation(p: &ProblemIn) -> Option<Vec<Results>> {
    let c = p.camera.as_ref()?;
    let look = Vec3In(std::array::from_fn(|k| {
        Num(Expr::Sub(
            Box::new(c.look[k].0.clone()),
            Box::new(c.eye[k].0.clone()),
        ))
    }));
    let zero = Vec3In(std::array::from_fn(|_| Num(Expr::Lit("0".into()))));
    altered_points(p, |q| {
        map_camera(q, |c| {
            c.look = look;
            c.eye = zero;
        })
    })
}

/// right = top / aspect instead of aspect·top: the aspect inverted.
fn aspect_inverted(p: &ProblemIn) -> Option<Vec<Results>> {
    let aspect = p.perspective.as_ref()?.aspect.as_ref()?.0.clone();
    altered(p, |q| {
        if let Some(x) = q.perspective.as_mut() {
            let one = Box::new(Expr::Lit("1".into()));
            x.aspect = Some(Num(Expr::Div(one, Box::new(aspect))));
        }
    })
}

/// The value the source printed, wrong by its errata: one variant per
/// erratum, since a student who copies one printed answer has not copied
/// the others (a right answer to another erratum's key must not rule this
/// one out).
fn copied_misprint(p: &ProblemIn) -> Option<Vec<Results>> {
    let base = solved(p)?;
    let variants: Vec<Results> = p
        .errata
        .iter()
        .filter_map(|e| {
            let mut t = base.clone();
            let v = t.get_mut(&e.key.parse().ok()?)?;
            *v = printed_value(printed(p, &e.key)?, v)?;
            Some(t)
        })
        .collect();
    (!variants.is_empty()).then_some(variants)
}

/// The problem's results (f64; a mistaken value needs no exact form).
fn solved(p: &ProblemIn) -> Option<Results> {
    solve::solve::<f64>(p).ok().map(|r| r.result)
}

/// The results of the problem with its input altered by `f`.
fn altered(p: &ProblemIn, f: impl FnOnce(&mut ProblemIn)) -> Option<Vec<Results>> {
    let mut q = p.clone();
    f(&mut q);
    Some(vec![solved(&q)?])
}

/// The results of the problem altered by `f`, for the points that can
/// go through the altered steps: a point whose image the mistake leaves
/// undefined (in the plane of the centre of projection) is left out.
fn altered_points(p: &ProblemIn, f: impl FnOnce(&mut ProblemIn)) -> Option<Vec<Results>> {
    let mut q = p.clone();
    f(&mut q);
    if let Some(t) = solved(&q) {
        return Some(vec![t]);
    }
    let mut kept = q.clone();
    for name in q.points.keys() {
        let mut one = q.clone();
        one.points.retain(|k, _| k == name);
        if solved(&one).is_none() {
            kept.points.remove(name);
        }
    }
    let mut t = solved(&kept)?;
    // the eye coordinates of every point (the view part alone projects none)
    q.ask = Some(vec![Part::View]);
    let points = Key::new(Part::View, Value::Field(Field::Points));
    if let (Some(all), Some(Val::Map(eye))) = (solved(&q), t.get_mut(&points)) {
        if let Some(Val::Map(every)) = all.get(&points).as_deref() {
            for (name, e) in every {
                if !eye.iter().any(|(k, _)| k == name) {
                    eye.push((name.clone(), e.clone()));
                }
            }
        }
    }
    Some(vec![t])
}

/// The results with a stage result altered between stages.
fn hooked(p: &ProblemIn, hooks: Hooks<f64>) -> Option<Vec<Results>> {
    Some(vec![solve::solve_with::<f64>(p, &hooks).ok()?.result])
}

/// [`hooked`] in exact arithmetic, for an altered camera basis: there the
/// view matrix's translation and the eye coordinates are the text's
/// formulas on the axes as they are (in floats both come from the
/// unrounded directions, which scaling an axis does not change).
fn hooked_exact(p: &ProblemIn, hooks: Hooks<Real>) -> Option<Vec<Results>> {
    Some(vec![solve::solve_with::<Real>(p, &hooks).ok()?.result])
}

/// A vector of a lighting problem that the text divides by its length.
#[derive(Clone, Copy)]
enum Unit {
    /// L, the direction to the light.
    L,
    /// N, the normal.
    N,
}

impl Unit {
    /// The vector as the problem gives it.
    fn given(self, p: &ProblemIn) -> Option<&Vec3In> {
        let s = p.shade.as_ref()?;
        match self {
            Unit::L => s.light.as_ref(),
            Unit::N => s.normal.as_ref(),
        }
    }

    /// Its value in the results (`shade.L`, `shade.N`).
    fn shading(self) -> Shading {
        match self {
            Unit::L => Shading::L,
            Unit::N => Shading::N,
        }
    }
}

/// L or N not divided by its length: the lighting with the vector `raw`
/// the problem gives used as it is, the unit vector the set-up holds
/// scaled back by |raw|. The results gain the vector itself (`shade.L`,
/// `shade.N`), which `practice` asks for.
fn unnormalized(p: &ProblemIn, which: Unit) -> Option<Vec<Results>> {
    let v: Vec<f64> = (which.given(p)?.iter())
        .map(|x| x.0.eval::<f64>().ok())
        .collect::<Option<_>>()?;
    let len = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if len.is_nan() || len <= 0.0 || (len - 1.0).abs() < 1e-12 || !p.light.is_empty() {
        return None;
    }
    let scale = move |s: &mut Setup<f64>| match which {
        Unit::N => s.surface.normal *= len,
        Unit::L => {
            if let [l] = &mut s.lights[..] {
                if let LightKind::Directional { dir } = &mut l.kind {
                    *dir *= len;
                }
            }
        }
    };
    let hooks = Hooks {
        setup: Some(&scale),
        ..Hooks::default()
    };
    let mut t = solve::solve_with::<f64>(p, &hooks).ok()?.result;
    if let Some(PartResult::Shade(shade)) = t.of_mut(Part::Shade) {
        let raw = Val::List(v.iter().map(Val::num).collect());
        *shade.value_mut(which.shading()) = Some(raw);
    }
    Some(vec![t])
}

/// cos of an angle in degrees taken in radian mode (cos 45 read as 45
/// rad): a spot light's cone angles, whose halves the spot factor takes
/// the cosines of, given to the stage as θ·180/π degrees, so that
/// cos(θ/2 ·180/π °) = cos(θ/2 rad). Only for a problem with a spot light.
fn cos_in_radians(p: &ProblemIn) -> Option<Vec<Results>> {
    if !p.light.iter().any(|l| l.kind == LightType::Spot) {
        return None;
    }
    let radians = |s: &mut Setup<f64>| {
        for l in &mut s.lights {
            if let LightKind::Spot { theta, phi, .. } = &mut l.kind {
                *theta = theta.to_degrees();
                *phi = phi.to_degrees();
            }
        }
    };
    let hooks = Hooks {
        setup: Some(&radians),
        ..Hooks::default()
    };
    hooked(p, hooks)
}

/// The value the source printed for a result key (`[printed]`, keyed as
/// one dotted string or as nested tables).
fn printed<'a>(p: &'a ProblemIn, key: &str) -> Option<&'a toml::Value> {
    if let Some(v) = p.printed.get(key) {
        return Some(v);
    }
    let mut parts = key.split('.');
    let mut cur = p.printed.get(parts.next()?)?;
    for part in parts {
        cur = cur.as_table()?.get(part)?;
    }
    Some(cur)
}

/// A printed answer as a value shaped like `like` (a projected point
/// printed as (xp, yp) takes its zp from `like`).
fn printed_value(printed: &toml::Value, like: &Val) -> Option<Val> {
    let mut v = answer::read(printed, like).ok()?.value();
    if let (Val::List(got), Val::List(want)) = (&mut v, like) {
        if got.len() + 1 == want.len() {
            got.push(want.last()?.clone());
        }
    }
    Some(v)
}

/// Multiplies the axes u, v, n by the factors given, keeping the basis
/// consistent: the eye coordinates are computed from the unnormalized axes s
/// and divided by |s| (`norms`), so each |s| is divided by the factor.
fn scale_axes<T: Scalar>(b: &mut Basis<T>, [fu, fv, fn_]: [T; 3]) {
    b.u = vec::scale(&b.u, &fu);
    b.v = vec::scale(&b.v, &fv);
    b.n = vec::scale(&b.n, &fn_);
    b.norms[1] = b.norms[1].clone() / fu;
    b.norms[2] = b.norms[2].clone() / fv;
    b.norms[0] = b.norms[0].clone() / fn_;
}

/// Multiplies every edge and size of the window by k.
fn scale_window(w: &mut Window<f64>, k: f64) {
    for x in [
        &mut w.top,
        &mut w.bottom,
        &mut w.left,
        &mut w.right,
        &mut w.height,
        &mut w.width,
    ] {
        *x *= k;
    }
}

fn neg3(v: &Vec3In) -> Vec3In {
    Vec3In(std::array::from_fn(|k| {
        Num(Expr::Neg(Box::new(v[k].0.clone())))
    }))
}

fn map_camera(q: &mut ProblemIn, f: impl FnOnce(&mut crate::input::problem::CameraIn)) {
    if let Some(c) = q.camera.as_mut() {
        f(c);
    }
}

/// Calls `f` on each segment's clip results.
fn for_each_clip(t: &mut Results, f: impl FnMut(&mut ClipResult)) {
    if let Some(PartResult::Clip(runs)) = t.of_mut(Part::Clip) {
        runs.iter_mut().for_each(f);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spellings_are_the_snake_case_of_the_names_and_distinct() {
        // CrossOrder is written cross_order: derived by hand here, from the
        // Debug name, so a typo in `as_str` shows.
        let mut seen = std::collections::HashSet::new();
        for c in Code::all() {
            let mut snake = String::new();
            for (i, ch) in format!("{c:?}").chars().enumerate() {
                if ch.is_ascii_uppercase() && i > 0 {
                    snake.push('_');
                }
                snake.push(ch.to_ascii_lowercase());
            }
            assert_eq!(c.as_str(), snake);
            assert_eq!(c.to_string(), snake);
            assert!(seen.insert(c.as_str()), "{c}");
        }
    }

    /// The window's top in the results computed with a mistake.
    fn top_with(code: Code, p: &ProblemIn) -> f64 {
        let t = &code.apply(p).expect("the mistake applies")[0];
        let top = Key::new(Part::Window, Value::Field(Field::Edge(Edge::Top, false)));
        match t.get(&top).as_deref() {
            Some(Val::Num(top)) => top.value,
            v => panic!("window.top is {v:?}"),
        }
    }

    #[test]
    fn fovy_not_halved_is_diagnosed_over_90_degrees_too() {
        // fovy = 60°, near = 1: the right top is tan 30° = 0.57735; with
        // tan(fovy) it is tan 60° = 1.73205.
        let p = ProblemIn::parse(
            "title = 't'\nask = ['window']\n[perspective]\nnear = 1\nfovy = 60\naspect = 1\n",
            "t",
        )
        .unwrap();
        let top = top_with(Code::FovyNotHalved, &p);
        assert!((top - 3f64.sqrt()).abs() < 1e-12, "{top}");
        // Over 90°: fovy = 120°, tan 120° = −√3, so top = −√3 (near = 1).
        let p120 = ProblemIn::parse(
            "title = 't'\nask = ['window']\n[perspective]\nnear = 1\nfovy = 120\naspect = 1\n",
            "t",
        )
        .unwrap();
        let top = top_with(Code::FovyNotHalved, &p120);
        assert!((top + 3f64.sqrt()).abs() < 1e-12, "{top}");
        // degrees as radians: tan(30 rad) = −6.405331196646276
        let top = top_with(Code::DegreesAsRadians, &p);
        assert!((top - 30f64.tan()).abs() < 1e-9, "{top}");
    }

    /// A shipped problem.
    fn shipped(name: &str) -> ProblemIn {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("problems")
            .join(name);
        ProblemIn::read(&path).expect("a shipped problem")
    }

    /// The numbers of `key` in variant `i` of a mistake's results.
    fn nums(code: Code, p: &ProblemIn, i: usize, key: &str) -> Vec<f64> {
        let trees = code.apply(p).expect("the mistake applies");
        let v = trees[i].lookup(key).expect(key);
        v.numbers()
    }

    fn close(got: &[f64], want: &[f64]) -> bool {
        got.len() == want.len() && got.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-9)
    }

    #[test]
    fn u_and_v_swapped() {
        // eye (3, 4, 12) at the origin: u = (4, 0, −1)/√17, v = (−4, 51,
        // −16)/(13√17), A' = (4/√17, −4/(13√17), −166/13) for A = (1, 0, 0);
        // swapped, u and v trade places and so do A′'s x and y
        let p = shipped("view-surds.toml");
        let r17 = 17f64.sqrt();
        let u = nums(Code::UvSwapped, &p, 0, "view.u");
        assert!(
            close(
                &u,
                &[
                    -4.0 / (13.0 * r17),
                    51.0 / (13.0 * r17),
                    -16.0 / (13.0 * r17)
                ]
            ),
            "{u:?}"
        );
        let v = nums(Code::UvSwapped, &p, 0, "view.v");
        assert!(close(&v, &[4.0 / r17, 0.0, -1.0 / r17]), "{v:?}");
        let a = nums(Code::UvSwapped, &p, 0, "view.points.A");
        assert!(
            close(&a, &[-4.0 / (13.0 * r17), 4.0 / r17, -166.0 / 13.0]),
            "{a:?}"
        );
    }

    #[test]
    fn mcam_handed_in_as_the_view_matrix() {
        // the text's example 6.1: u = (0, 0, −1), v = (−3/5, 4/5, 0),
        // n = (4/5, 3/5, 0), Pe = (4, 4, 4); Mcam has them as columns
        let p = shipped("text-camera.toml");
        let mcam = [
            0.0, -0.6, 0.8, 4.0, //
            0.0, 0.8, 0.6, 4.0, //
            -1.0, 0.0, 0.0, 4.0, //
            0.0, 0.0, 0.0, 1.0,
        ];
        for variant in [0, 1] {
            let m = nums(Code::McamAsView, &p, variant, "view.matrix");
            assert!(close(&m, &mcam), "{variant}: {m:?}");
        }
        // variant 0 keeps the eye coordinates: Pref' = (0, 0, −5)
        assert!(close(
            &nums(Code::McamAsView, &p, 0, "view.points.Pref"),
            &[0.0, 0.0, -5.0]
        ));
        // variant 1 takes Mcam·Pref, Pref = (0, 1, 4): (−3/5 + 16/5 + 4,
        // 4/5 + 12/5 + 4, 4) = (6.6, 7.2, 4)
        let e = nums(Code::McamAsView, &p, 1, "view.points.Pref");
        assert!(close(&e, &[6.6, 7.2, 4.0]), "{e:?}");
    }

    #[test]
    fn t_measured_from_p1() {
        // P(t) = (4 − 6t, 2 + 4t, 2 − t): x = 3 at t = 1/6, x = 0 at 2/3,
        // y = 4 at 1/2. From P1 these are 5/6, 1/3, 1/2; put into P(t),
        // x = 3's lands at (−1, 16/3, 7/6) (code 001001), x = 0's at
        // (2, 10/3, 5/3) (inside), y = 4's where it was, (1, 4, 3/2); the
        // segment runs from t = 1/3 to t = 1/2
        let p = shipped("text-clip.toml");
        let t = |i, plane: &str| {
            nums(
                Code::TFromP1,
                &p,
                i,
                &format!("clip.intersections.{plane}.t"),
            )
        };
        for i in [0, 1] {
            assert!(close(&t(i, "right"), &[5.0 / 6.0]));
            assert!(close(&t(i, "left"), &[1.0 / 3.0]));
        }
        let right = nums(Code::TFromP1, &p, 0, "clip.intersections.right.point");
        assert!(close(&right, &[-1.0, 16.0 / 3.0, 7.0 / 6.0]), "{right:?}");
        let seg = nums(Code::TFromP1, &p, 0, "clip.segment");
        assert!(
            close(&seg, &[2.0, 10.0 / 3.0, 5.0 / 3.0, 1.0, 4.0, 1.5]),
            "{seg:?}"
        );
        let trees = Code::TFromP1.apply(&p).unwrap();
        let code = trees[0].lookup("clip.intersections.right.code");
        assert_eq!(code.as_deref(), Some(&Val::text("001001")));
        // variant 1: the t only, the points right
        let right = nums(Code::TFromP1, &p, 1, "clip.intersections.right.point");
        assert!(close(&right, &[3.0, 8.0 / 3.0, 11.0 / 6.0]), "{right:?}");
    }

    #[test]
    fn cos_of_a_spot_cone_in_radians() {
        // the spot at (3, 0, 4) shines down: ρ = 4/5, inside φ/2 = 45°
        // (cos 0.707) but not θ/2 = 30° (cos 0.866): a penumbra. In
        // radian mode cos(30 rad) = 0.1543 and cos(45 rad) = 0.5253, so
        // ρ is inside the inner cone: spot 1, the diffuse colour kd·cos α =
        // 0.6·4/5 = 0.48 on each channel
        let p = shipped("shade-spot-penumbra.toml");
        assert!(close(
            &nums(Code::CosInRadians, &p, 0, "shade.lights.0.spot"),
            &[1.0]
        ));
        let c = nums(Code::CosInRadians, &p, 0, "shade.color");
        assert!(close(&c, &[0.48, 0.48, 0.48]), "{c:?}");
        // no spot light, no such mistake
        assert!(Code::CosInRadians
            .apply(&shipped("shade-phong.toml"))
            .is_none());
    }
}
