//! The results of the calculator's stages as named values (the result keys
//! of the JSON contract: `u`, `v`, `n`, `top`, `code0`, `segment`, `color`,
//! ...), shared by the calculator commands and `solve`.

use crate::input::lights::Setup;
use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera;
use crate::stages::clip::{self, ClipBox};
use crate::stages::lighting::{self, rgb_val, LightTerm, Material, Model};
use crate::stages::trace::{Name, NoTrace, Recorder, Step, Trace, Val};
use crate::stages::window;

/// The basis as named results.
pub fn basis_result<T: Scalar>(b: &camera::Basis<T>) -> Vec<(String, Val)> {
    vec![
        ("u".into(), Val::vec3(&b.u)),
        ("v".into(), Val::vec3(&b.v)),
        ("n".into(), Val::vec3(&b.n)),
    ]
}

/// The window's named results, keys prefixed (`far_top`, ...).
pub fn window_result<T: Scalar>(w: &window::Window<T>, prefix: &str) -> Vec<(String, Val)> {
    [
        ("top", &w.top),
        ("bottom", &w.bottom),
        ("left", &w.left),
        ("right", &w.right),
        ("height", &w.height),
        ("width", &w.width),
    ]
    .into_iter()
    .map(|(k, v)| (format!("{prefix}{k}"), Val::num(v)))
    .collect()
}

/// Clips one segment by outcodes and by Liang–Barsky and records whether
/// they agree; the outcodes' clipping.
pub fn clip_checked<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    rec: &mut Recorder,
) -> clip::Clipped<T> {
    let r = clip::clip_segment(b, p0, p1, rec);
    let lb = clip::liang_barsky(b, p0, p1, rec);
    let agree = match (&r.segment, &lb) {
        (None, None) => true,
        (Some((a, z)), Some((c, d))) => close(a, c) && close(z, d),
        _ => false,
    };
    let segment = |s: &Option<(V3<T>, V3<T>)>| match s {
        Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
        None => Val::Null,
    };
    rec.step(|| {
        Step::new(Msg::MethodsAgree, Msg::FMethods)
            .val(Name::Outcodes, segment(&r.segment))
            .val(Name::math("Liang–Barsky"), segment(&lb))
            .res(Name::Agree, Val::Bool(agree))
            .note(if agree {
                Msg::Agree(true)
            } else {
                Msg::Agree(false)
            })
    });
    r
}

/// docs/spec.md's clip result keys of a clipping.
pub fn clip_result<T: Scalar>(r: &clip::Clipped<T>) -> Vec<(String, Val)> {
    vec![
        ("code0".into(), Val::text(clip::code_str(r.code0))),
        ("code1".into(), Val::text(clip::code_str(r.code1))),
        ("status".into(), Val::text(r.status.as_str())),
        (
            "segment".into(),
            match &r.segment {
                Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
                None => Val::Null,
            },
        ),
        (
            "intersections".into(),
            Val::Map(r.intersections.iter().map(intersection_val).collect()),
        ),
    ]
}

/// One tried intersection as a result: its plane's key and t, point, code, kept.
fn intersection_val<T: Scalar>(i: &clip::Intersection<T>) -> (String, Val) {
    (
        clip::PLANE_KEYS[i.bit].to_string(),
        Val::Map(vec![
            ("t".into(), Val::num(&i.t)),
            ("point".into(), Val::vec3(&i.point)),
            ("code".into(), Val::text(clip::code_str(i.code))),
            ("kept".into(), Val::Bool(i.code == 0)),
        ]),
    )
}

/// Equal up to rounding (exact values compare exactly).
fn close<T: Scalar>(a: &V3<T>, b: &V3<T>) -> bool {
    (0..3).all(|k| {
        let (x, y) = (a[k].to_f64(), b[k].to_f64());
        a[k] == b[k] || (x - y).abs() <= 1e-5 * (1.0 + x.abs().max(y.abs()))
    })
}

fn opt_vec<T: Scalar>(v: &Option<V3<T>>) -> Val {
    v.as_ref().map(Val::vec3).unwrap_or(Val::Null)
}

fn opt_num<T: Scalar>(v: &Option<T>) -> Val {
    v.as_ref().map(Val::num).unwrap_or(Val::Null)
}

/// Lights the set-up under `rules` (the text's, `Rules::default()`, or the
/// mistake catalog's), steps into `rec`, and returns docs/spec.md §3's shade
/// keys: `color`, `unclamped`, `ambient`, `diffuse`, `specular`, `R`, `H`
/// (Blinn), `cos_alpha`, `cos_beta` — per light (lists) when there are
/// several, with `lights` (attenuation, spot, in range) for lights from a
/// file.
pub fn shade_run<T: Scalar, R: lighting::RuleSet<T>>(
    s: &Setup<T>,
    rules: &R,
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
    let m = &s.material;
    rec.step(|| material_step(m));
    let sh = lighting::shade_with_rules(m, &s.lights, &s.global_ambient, &s.surface, rules, rec);
    let mut out: Vec<(String, Val)> = vec![
        ("color".into(), rgb_val(&sh.color)),
        ("unclamped".into(), rgb_val(&sh.unclamped)),
        ("ambient".into(), rgb_val(&sh.ambient)),
        ("diffuse".into(), rgb_val(&sh.diffuse)),
        ("specular".into(), rgb_val(&sh.specular)),
    ];
    if sh.emissive.iter().any(|x| !x.is_zero_value()) {
        out.push(("emissive".into(), rgb_val(&sh.emissive)));
    }
    let blinn = m.model == Model::Blinn;
    if s.lights.len() == 1 {
        out.push(("R".into(), opt_vec(&sh.r)));
        if blinn {
            out.push(("H".into(), opt_vec(&sh.h)));
            out.push(("N_dot_H".into(), opt_num(&sh.cos_nh)));
        }
        out.push(("cos_alpha".into(), opt_num(&sh.cos_alpha)));
        out.push(("cos_beta".into(), opt_num(&sh.cos_beta)));
    } else {
        out.extend(vectors_per_light(s, &sh.view, rules));
    }
    if !s.text_light {
        let per = (0..s.lights.len()).map(|i| light_factors(s, i, &sh.view));
        out.push(("lights".into(), Val::List(per.collect())));
    }
    out
}

/// The step that shows the material and the model.
fn material_step<T: Scalar>(m: &Material<T>) -> Step {
    Step::new(Msg::Material, format!("model = {}", m.model.name()))
        .val(Name::math("ka"), Val::num(&m.ka))
        .val(Name::math("kd"), Val::num(&m.kd))
        .val(Name::math("ks"), Val::num(&m.ks))
        .val(Name::math("n"), Val::num(&m.shininess))
        .val(Name::math("Cs"), rgb_val(&m.color))
        .val(Name::math("Cspecular"), rgb_val(&m.specular))
        .note(
            if m.ka == T::one() && m.kd == T::one() && m.ks == T::one() {
                Msg::MaterialD3d
            } else {
                Msg::MaterialText
            },
        )
}

/// With several lights: R (H, N·H), cos α and cos β as lists, one entry per
/// light (recomputed without steps: they are recorded already).
fn vectors_per_light<T: Scalar, R: lighting::RuleSet<T>>(
    s: &Setup<T>,
    view: &V3<T>,
    rules: &R,
) -> Vec<(String, Val)> {
    let m = &s.material;
    let n = s.lights.len();
    let terms: Vec<Option<LightTerm<T>>> = (s.lights.iter().enumerate())
        .map(|(i, l)| {
            let at = (i, n);
            lighting::light_term_with(m, l, at, &s.surface, view, true, rules, &mut NoTrace)
        })
        .collect();
    let list = |f: &dyn Fn(&LightTerm<T>) -> Val| {
        Val::List(
            terms
                .iter()
                .map(|t| t.as_ref().map(f).unwrap_or(Val::Null))
                .collect(),
        )
    };
    let mut out = vec![("R".to_string(), list(&|t| opt_vec(&t.r)))];
    if m.model == Model::Blinn {
        out.push(("H".into(), list(&|t| opt_vec(&t.h))));
        out.push(("N_dot_H".into(), list(&|t| opt_num(&t.cos_nh))));
    }
    out.push(("cos_alpha".into(), list(&|t| Val::num(&t.cos_alpha))));
    out.push(("cos_beta".into(), list(&|t| opt_num(&t.cos_beta))));
    out
}

/// Light i's range, distance, attenuation and spot factor.
fn light_factors<T: Scalar>(s: &Setup<T>, i: usize, view: &V3<T>) -> Val {
    let (m, l, n) = (&s.material, &s.lights[i], s.lights.len());
    let rules = &lighting::TextRules;
    let t = lighting::light_term_with(m, l, (i, n), &s.surface, view, false, rules, &mut NoTrace);
    let or_null = |f: &dyn Fn(&LightTerm<T>) -> Val| t.as_ref().map(f).unwrap_or(Val::Null);
    Val::Map(vec![
        ("in_range".into(), Val::Bool(t.is_some())),
        ("distance".into(), or_null(&|t| opt_num(&t.distance))),
        ("attenuation".into(), or_null(&|t| Val::num(&t.attenuation))),
        ("spot".into(), or_null(&|t| Val::num(&t.spot))),
    ])
}

/// The answer keys of a result tree in the order of the text's solution:
/// n, u, v, the view matrix, the eye coordinates; the projected points;
/// the window's top, bottom, left, right, height, width (not the far
/// window's); the pixels; per segment the outcodes, each plane tried (its
/// t, intersection point and that point's outcode, the text's deciding
/// step), the clipped segment and the status; the lighting's unit L and
/// N, cos α, R (H and N·H for Blinn), cos β, the terms, their sum and the
/// clamped colour.
pub fn ordered_keys(result: &[(String, Val)]) -> Vec<String> {
    let mut keys = Vec::new();
    for (part, v) in result {
        match (part.as_str(), v) {
            ("view", Val::Map(kv)) => {
                keys.extend(in_order(kv, "view", &["n", "u", "v", "matrix"]));
                keys.extend(named(kv, "view.points", "points"));
            }
            ("project", Val::Map(kv)) => keys.extend(named(kv, "project.points", "points")),
            ("viewport", Val::Map(kv)) => keys.extend(named(kv, "viewport.pixels", "pixels")),
            ("window", Val::Map(kv)) => keys.extend(
                kv.iter()
                    .filter(|(k, _)| !k.starts_with("far_"))
                    .map(|(k, _)| format!("window.{k}")),
            ),
            ("clip", Val::Map(kv)) => keys.extend(clip_keys("clip", kv)),
            ("clip", Val::List(runs)) => {
                for (i, r) in runs.iter().enumerate() {
                    if let Val::Map(kv) = r {
                        keys.extend(clip_keys(&format!("clip.{i}"), kv));
                    }
                }
            }
            ("shade", Val::Map(kv)) => keys.extend(in_order(
                kv,
                "shade",
                &[
                    "L",
                    "N",
                    "cos_alpha",
                    "R",
                    "H",
                    "N_dot_H",
                    "cos_beta",
                    "ambient",
                    "diffuse",
                    "specular",
                    "unclamped",
                    "color",
                ],
            )),
            _ => {}
        }
    }
    keys
}

/// `prefix.K` for each of `order` the map holds, in that order.
fn in_order(kv: &[(String, Val)], prefix: &str, order: &[&str]) -> Vec<String> {
    order
        .iter()
        .filter(|k| kv.iter().any(|(x, _)| x == *k))
        .map(|k| format!("{prefix}.{k}"))
        .collect()
}

/// `prefix.NAME` for each name of the map held at `inner`.
fn named(kv: &[(String, Val)], prefix: &str, inner: &str) -> Vec<String> {
    match kv.iter().find(|(k, _)| k == inner) {
        Some((_, Val::Map(m))) => m.iter().map(|(n, _)| format!("{prefix}.{n}")).collect(),
        _ => vec![],
    }
}

/// The outcodes, each plane tried (t, intersection, its outcode), the
/// clipped segment, the status.
fn clip_keys(prefix: &str, kv: &[(String, Val)]) -> Vec<String> {
    let mut keys = vec![format!("{prefix}.code0"), format!("{prefix}.code1")];
    if let Some((_, Val::Map(planes))) = kv.iter().find(|(k, _)| k == "intersections") {
        for (pl, _) in planes {
            for k in ["t", "point", "code"] {
                keys.push(format!("{prefix}.intersections.{pl}.{k}"));
            }
        }
    }
    keys.push(format!("{prefix}.segment"));
    keys.push(format!("{prefix}.status"));
    keys
}
