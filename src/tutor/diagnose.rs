//! The catalog of known mistakes, in one place. Each entry recomputes a
//! problem the wrong way — by running the real stages on altered inputs
//! (`altered`), or with one stage result altered between stages
//! ([`run::Hooks`](crate::tutor::run::Hooks)), or with one documented change to the result tree —
//! so that `grafika check` can say which mistake reproduces a wrong answer.
//! No pipeline math is repeated here, and no words: a mistake is said by
//! its [`Code`] in each language's words (`ReportWords::mistake`).
//!
//! Adding a mistake is a [`Code`] (the compiler then asks for its
//! spelling, its place in the order and its words) and one entry in
//! [`CATALOG`] (a test asks for it).

use crate::input::answer;
use crate::input::fields::{Num, Vec3In};
use crate::input::lights::Setup;
use crate::input::problem::ProblemIn;
use crate::num::vec;
use crate::num::{AngleUnit, Expr, Real, Scalar};
use crate::stages::camera::Basis;
use crate::stages::lighting::{LightKind, Rules};
use crate::stages::trace::Val;
use crate::stages::window::Window;
use crate::tutor::run::Hooks;
use crate::tutor::solution::lookup;
use crate::tutor::solve;

pub use crate::tutor::solution::Tree;

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
    /// `outcode_reversed`: The outcode bits in reverse order.
    OutcodeReversed,
    /// `endpoint_kept`: An endpoint outside the box kept instead of its intersection.
    EndpointKept,
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
            Code::FovyNotHalved => "fovy_not_halved",
            Code::DegreesAsRadians => "degrees_as_radians",
            Code::HeightIsHalfExtent => "height_is_half_extent",
            Code::HeightAsHalfExtent => "height_as_half_extent",
            Code::DSign => "d_sign",
            Code::MatrixTransposed => "matrix_transposed",
            Code::OutcodeReversed => "outcode_reversed",
            Code::EndpointKept => "endpoint_kept",
            Code::ReflectPlusL => "reflect_plus_l",
            Code::SpecularNoMax => "specular_no_max",
            Code::PixelYFromTop => "pixel_y_from_top",
            Code::EyeNoTranslation => "eye_no_translation",
            Code::AspectInverted => "aspect_inverted",
            Code::LightNotNormalized => "light_not_normalized",
            Code::NormalNotNormalized => "normal_not_normalized",
            Code::CopiedMisprint => "copied_misprint",
        }
    }

    /// Every code, in the catalog's order.
    pub fn all() -> Vec<Code> {
        std::iter::successors(Some(Code::CrossOrder), |c| c.next()).collect()
    }

    /// The code after this one: an exhaustive match, so a new code is
    /// listed (and its place in [`CATALOG`] tested) as soon as it compiles.
    fn next(self) -> Option<Code> {
        use Code::*;
        match self {
            CrossOrder => Some(NReversed),
            NReversed => Some(NNotNormalized),
            NNotNormalized => Some(UNotNormalized),
            UNotNormalized => Some(FovyNotHalved),
            FovyNotHalved => Some(DegreesAsRadians),
            DegreesAsRadians => Some(HeightIsHalfExtent),
            HeightIsHalfExtent => Some(HeightAsHalfExtent),
            HeightAsHalfExtent => Some(DSign),
            DSign => Some(MatrixTransposed),
            MatrixTransposed => Some(OutcodeReversed),
            OutcodeReversed => Some(EndpointKept),
            EndpointKept => Some(ReflectPlusL),
            ReflectPlusL => Some(SpecularNoMax),
            SpecularNoMax => Some(PixelYFromTop),
            PixelYFromTop => Some(EyeNoTranslation),
            EyeNoTranslation => Some(AspectInverted),
            AspectInverted => Some(LightNotNormalized),
            LightNotNormalized => Some(NormalNotNormalized),
            NormalNotNormalized => Some(CopiedMisprint),
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

/// One known mistake.
pub struct Mistake {
    /// Which mistake (its words are the report's, by this code).
    pub code: Code,
    /// The problem's results computed with this mistake (several variants
    /// when the mistake can be made in more than one place), or None when
    /// the mistake does not apply to the problem.
    pub apply: fn(&ProblemIn) -> Option<Vec<Tree>>,
}

impl std::fmt::Debug for Mistake {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Mistake({})", self.code)
    }
}

/// Every known mistake.
pub static CATALOG: &[Mistake] = &[
    Mistake {
        code: Code::CrossOrder,
        apply: |p| altered(p, |q| map_camera(q, |c| c.up = neg3(&c.up))),
    },
    Mistake {
        code: Code::NReversed,
        // Pe − (2Pe − Pr) = Pr − Pe: the look-at point reflected through the eye.
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::NNotNormalized,
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::UNotNormalized,
        apply: |p| {
            hooked_exact(
                p,
                Hooks {
                    // Vup × n = (Vup × d)/|d|, of length |Vup × d|/|d|.
                    basis: |b| {
                        let s = b.vxn_norm.clone();
                        scale_axes(b, [s.clone(), s, Real::from_i64(1)]);
                    },
                    ..Hooks::default()
                },
            )
        },
    },
    Mistake {
        code: Code::FovyNotHalved,
        // The window scaled by tan(fovy)/tan(fovy/2), not fovy doubled as an
        // input: over 90° the doubled angle is refused, yet the mistake gives
        // a window (top = near·tan(fovy) < 0) a student can write.
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::DegreesAsRadians,
        // As an input this would be an angle of thousands of degrees, which
        // the window rejects; so the window is scaled by the ratio of the tangents.
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::HeightIsHalfExtent,
        // Written as the height and width, not used as them: the window's
        // edges and the pixels stay right (the text's own h and W).
        apply: |p| {
            let mut t = solved(p)?;
            for (size, half) in [("height", "top"), ("width", "right")] {
                let h = find_key(&mut t, &format!("window.{half}"))?.clone();
                *find_key(&mut t, &format!("window.{size}"))? = h;
            }
            Some(vec![t])
        },
    },
    Mistake {
        code: Code::HeightAsHalfExtent,
        apply: |p| {
            hooked(
                p,
                Hooks {
                    // the window of half the top (right/top is the aspect)
                    window: |w, _| {
                        let aspect = w.right / w.top;
                        *w = crate::stages::window::edges(w.top / 2.0, &aspect);
                    },
                    ..Hooks::default()
                },
            )
        },
    },
    Mistake {
        code: Code::DSign,
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::MatrixTransposed,
        apply: |p| {
            let mut t = solved(p)?;
            let m = find_mut(&mut t, &["view", "matrix"])?;
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
        },
    },
    Mistake {
        code: Code::OutcodeReversed,
        // every outcode: the ends' and each intersection's
        apply: |p| {
            fn reverse(kv: &mut [(String, Val)]) {
                for (k, v) in kv.iter_mut() {
                    match (k.starts_with("code"), &mut *v) {
                        (true, Val::Text(s)) => *s = s.chars().rev().collect(),
                        (_, Val::Map(inner)) => reverse(inner),
                        _ => {}
                    }
                }
            }
            let mut t = solved(p)?;
            for_each_clip(&mut t, |kv| reverse(kv));
            Some(vec![t])
        },
    },
    Mistake {
        code: Code::EndpointKept,
        apply: |p| {
            let base = solved(p)?;
            let c = p.clip.as_ref()?;
            let points: Vec<(String, crate::num::vec::V3<f64>)> = p
                .points()
                .ok()?
                .iter()
                .map(|(n, v)| {
                    let e: Option<Vec<f64>> = v.iter().map(|x| x.0.eval::<f64>().ok()).collect();
                    e.map(|e| (n.clone(), crate::num::vec::v3(e[0], e[1], e[2])))
                })
                .collect::<Option<_>>()?;
            let end = |r| {
                solve::point_ref("clip", r, &points)
                    .ok()
                    .map(|q| Val::vec3(&q))
            };
            let ends: Vec<(Val, Val)> = c
                .segment
                .iter()
                .map(|s| Some((end(&s.from)?, end(&s.to)?)))
                .collect::<Option<_>>()?;
            // Variant 0 keeps P0, variant 1 keeps P1, in every clipped segment.
            let variants = (0..2)
                .map(|which| {
                    let mut t = base.clone();
                    let mut i = 0;
                    for_each_clip(&mut t, |kv| {
                        let clipped = kv
                            .iter()
                            .any(|(k, v)| k == "status" && *v == Val::text("clipped"));
                        if let (true, Some((p0, p1))) = (clipped, ends.get(i)) {
                            for (k, v) in kv.iter_mut() {
                                if let (true, Val::List(pts)) = (k == "segment", &mut *v) {
                                    if pts.len() == 2 {
                                        pts[which] =
                                            if which == 0 { p0.clone() } else { p1.clone() };
                                    }
                                }
                            }
                        }
                        i += 1;
                    });
                    t
                })
                .collect();
            Some(variants)
        },
    },
    Mistake {
        code: Code::ReflectPlusL,
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::SpecularNoMax,
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::PixelYFromTop,
        // One documented change to the results: each pixel's py becomes H − py.
        apply: |p| {
            let h = p.perspective.as_ref()?.viewport.as_ref()?[1]
                .0
                .eval::<f64>()
                .ok()?;
            let mut t = solved(p)?;
            let Val::Map(pixels) = find_mut(&mut t, &["viewport", "pixels"])? else {
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
        },
    },
    Mistake {
        code: Code::EyeNoTranslation,
        // The same camera axes with the eye at the origin: Pe' = 0 and
        // Pr' = Pr − Pe keep n, u, v, and drop the translation by −Pe.
        apply: |p| {
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
        },
    },
    Mistake {
        code: Code::AspectInverted,
        apply: |p| {
            let aspect = p.perspective.as_ref()?.aspect.as_ref()?.0.clone();
            altered(p, |q| {
                if let Some(x) = q.perspective.as_mut() {
                    let one = Box::new(Expr::Lit("1".into()));
                    x.aspect = Some(Num(Expr::Div(one, Box::new(aspect))));
                }
            })
        },
    },
    Mistake {
        code: Code::LightNotNormalized,
        apply: |p| unnormalized(p, p.shade.as_ref()?.light.as_ref()?, "L"),
    },
    Mistake {
        code: Code::NormalNotNormalized,
        apply: |p| unnormalized(p, p.shade.as_ref()?.normal.as_ref()?, "N"),
    },
    Mistake {
        code: Code::CopiedMisprint,
        // One variant per erratum: a student who copies one printed answer
        // has not copied the others, so a right answer to another erratum's
        // key must not rule this one out.
        apply: |p| {
            let base = solved(p)?;
            let variants: Vec<Tree> = p
                .errata
                .iter()
                .filter_map(|e| {
                    let mut t = base.clone();
                    let v = find_key(&mut t, &e.key)?;
                    *v = printed_value(printed(p, &e.key)?, v)?;
                    Some(t)
                })
                .collect();
            (!variants.is_empty()).then_some(variants)
        },
    },
];

/// The catalog's entry of a code.
pub fn find(code: Code) -> Option<&'static Mistake> {
    CATALOG.iter().find(|m| m.code == code)
}

/// The problem's results (f64; a mistaken value needs no exact form).
fn solved(p: &ProblemIn) -> Option<Tree> {
    solve::solve::<f64>(p).ok().map(|r| r.result)
}

/// The results of the problem with its input altered by `f`.
fn altered(p: &ProblemIn, f: impl FnOnce(&mut ProblemIn)) -> Option<Vec<Tree>> {
    let mut q = p.clone();
    f(&mut q);
    Some(vec![solved(&q)?])
}

/// The results of the problem altered by `f`, for the points that can
/// go through the altered steps: a point whose image the mistake leaves
/// undefined (in the plane of the centre of projection) is left out.
fn altered_points(p: &ProblemIn, f: impl FnOnce(&mut ProblemIn)) -> Option<Vec<Tree>> {
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
    q.ask = Some(vec![crate::tutor::key::Part::View]);
    if let (Some(all), Some(Val::Map(eye))) = (solved(&q), find_key(&mut t, "view.points")) {
        if let Some(Val::Map(every)) = lookup(&all, "view.points") {
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
fn hooked(p: &ProblemIn, hooks: Hooks<f64>) -> Option<Vec<Tree>> {
    Some(vec![solve::solve_with::<f64>(p, &hooks).ok()?.result])
}

/// [`hooked`] in exact arithmetic, for an altered camera basis: there the
/// view matrix's translation and the eye coordinates are the text's
/// formulas on the axes as they are (in floats both come from the
/// unrounded directions, which scaling an axis does not change).
fn hooked_exact(p: &ProblemIn, hooks: Hooks<Real>) -> Option<Vec<Tree>> {
    Some(vec![solve::solve_with::<Real>(p, &hooks).ok()?.result])
}

/// The lighting with the vector `raw` (the light L or the normal N as the
/// problem gives it) used without dividing it by its length: the unit
/// vector the set-up holds is scaled back by |raw|. The results gain the
/// vector itself (`shade.L`, `shade.N`), which `practice` asks for.
fn unnormalized(p: &ProblemIn, raw: &Vec3In, name: &'static str) -> Option<Vec<Tree>> {
    let v: Vec<f64> = raw
        .iter()
        .map(|x| x.0.eval::<f64>().ok())
        .collect::<Option<_>>()?;
    let len = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if len.is_nan() || len <= 0.0 || (len - 1.0).abs() < 1e-12 || !p.light.is_empty() {
        return None;
    }
    let scale = move |s: &mut Setup<f64>| match name {
        "N" => s.surface.normal *= len,
        _ => {
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
    if let Some(Val::Map(kv)) = find_mut(&mut t, &["shade"]) {
        kv.insert(
            0,
            (
                name.to_string(),
                Val::List(v.iter().map(Val::num).collect()),
            ),
        );
    }
    Some(vec![t])
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

/// The value at a dotted result key (a list index may be a number).
fn find_key<'a>(t: &'a mut Tree, key: &str) -> Option<&'a mut Val> {
    let mut parts = key.split('.');
    let first = parts.next()?;
    let mut cur = &mut t.iter_mut().find(|(k, _)| k == first)?.1;
    for part in parts {
        cur = match cur {
            Val::Map(kv) => &mut kv.iter_mut().find(|(k, _)| k == part)?.1,
            Val::List(items) => items.get_mut(part.parse::<usize>().ok()?)?,
            _ => return None,
        };
    }
    Some(cur)
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

/// The value at a path of map keys.
fn find_mut<'a>(t: &'a mut Tree, path: &[&str]) -> Option<&'a mut Val> {
    find_key(t, &path.join("."))
}

/// Calls `f` on each clip result (one, or each of a list).
fn for_each_clip(t: &mut Tree, mut f: impl FnMut(&mut Vec<(String, Val)>)) {
    if let Some((_, v)) = t.iter_mut().find(|(k, _)| k == "clip") {
        match v {
            Val::Map(kv) => f(kv),
            Val::List(items) => {
                for it in items {
                    if let Val::Map(kv) = it {
                        f(kv);
                    }
                }
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalog_has_every_code_once_in_order() {
        let codes: Vec<Code> = CATALOG.iter().map(|m| m.code).collect();
        assert_eq!(codes, Code::all());
        for c in Code::all() {
            assert_eq!(find(c).map(|x| x.code), Some(c));
        }
    }

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

    #[test]
    fn fovy_not_halved_is_diagnosed_over_90_degrees_too() {
        // fovy = 60°, near = 1: the right top is tan 30° = 0.57735; with
        // tan(fovy) it is tan 60° = 1.73205.
        let p = ProblemIn::parse(
            "title = 't'\nask = ['window']\n[perspective]\nnear = 1\nfovy = 60\naspect = 1\n",
            "t",
        )
        .unwrap();
        let m = find(Code::FovyNotHalved).unwrap();
        let t = &(m.apply)(&p).unwrap()[0];
        let Some(Val::Num(top)) = lookup(t, "window.top") else {
            panic!()
        };
        assert!((top.value - 3f64.sqrt()).abs() < 1e-12);
        // Over 90°: fovy = 120°, tan 120° = −√3, so top = −√3 (near = 1).
        let p120 = ProblemIn::parse(
            "title = 't'\nask = ['window']\n[perspective]\nnear = 1\nfovy = 120\naspect = 1\n",
            "t",
        )
        .unwrap();
        let t = &(m.apply)(&p120).expect("fovy_not_halved applies over 90°")[0];
        let Some(Val::Num(top)) = lookup(t, "window.top") else {
            panic!()
        };
        assert!((top.value + 3f64.sqrt()).abs() < 1e-12, "{}", top.value);
        // degrees as radians: tan(30 rad) = −6.405331196646276
        let m = find(Code::DegreesAsRadians).unwrap();
        let t = &(m.apply)(&p).unwrap()[0];
        let Some(Val::Num(top)) = lookup(t, "window.top") else {
            panic!()
        };
        assert!((top.value - 30f64.tan()).abs() < 1e-9, "{}", top.value);
    }
}
