//! The results of the calculator's stages as named values (the result keys
//! of the JSON contract: `u`, `v`, `n`, `top`, `code0`, `segment`, ...),
//! shared by the calculator commands and `solve`.

use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera;
use crate::stages::clip::{self, ClipBox};
use crate::stages::trace::{Recorder, Step, Trace, Val};
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

/// Clips one segment by outcodes and by Liang–Barsky, records whether they
/// agree, and returns docs/spec.md's clip result keys.
pub fn clip_run<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
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
            .val("outcodes", segment(&r.segment))
            .val("Liang–Barsky", segment(&lb))
            .res("agree", Val::Bool(agree))
            .note(if agree {
                Msg::Agree(true)
            } else {
                Msg::Agree(false)
            })
    });
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
