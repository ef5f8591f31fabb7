//! Follow-through marking (error carried forward): the value a later answer
//! should have when it is computed, correctly, from the student's own
//! earlier answers. `practice` and `check --follow-through` credit an answer
//! that is wrong against grafika's value but right against this one as
//! `correct.follow_through`.
//!
//! Each rule is the text's formula for one key, fed with the earlier values
//! through `own` (the student's value of a key when it was wrong, grafika's
//! otherwise: a right but rounded answer carries no rounding forward). The problem's inputs (Pe, Vup, the points, d, the
//! viewport, the segment ends, the lighting constants) are never the
//! student's. Values are f64: a follow-through value has no exact form.

use crate::input::fields::{Num, Vec3In};
use crate::input::lights::{self, LightsFileIn};
use crate::input::problem::{PointRef, ProblemIn};
use crate::num::vec::{self, V3};
use crate::stages::trace::{NoTrace, Val};
use crate::stages::window::{viewport_xy, Window};
use crate::tutor::solve::lookup;

/// The student's value of an earlier key when it was wrong, or grafika's
/// (for a right answer, one not given, or one that cannot be read).
pub type Own<'a> = dyn Fn(&str) -> Option<Val> + 'a;

/// The problem's inputs, as f64 (a part is empty when the problem lacks it).
#[derive(Clone, Debug, Default)]
pub struct Inputs {
    /// The eye Pe and up vector Vup.
    camera: Option<(V3<f64>, V3<f64>)>,
    /// The world points, by name.
    points: Vec<(String, V3<f64>)>,
    /// The projection plane z = d (d = −near unless given).
    d: Option<f64>,
    /// The aspect ratio width/height.
    aspect: Option<f64>,
    /// The viewport size W × H in pixels.
    viewport: Option<(f64, f64)>,
    /// Each clipped segment's ends P0, P1.
    segments: Vec<(V3<f64>, V3<f64>)>,
    /// The lighting constants, when one white light of the text lights the point.
    shade: Option<Lighting>,
}

/// The constants of the text's lighting at one point with one white light.
#[derive(Clone, Debug)]
struct Lighting {
    /// V, toward the viewer.
    view: V3<f64>,
    kd: f64,
    ks: f64,
    shininess: f64,
    /// Cs and the specular colour.
    color: [f64; 3],
    specular: [f64; 3],
    /// Which terms the model adds: ambient, diffuse, specular.
    terms: (bool, bool, bool),
    /// Whether the text's one white directional light is the only light
    /// (then Ld = Ls = 1 and the terms follow from cos α and cos β).
    text_light: bool,
}

fn num(n: &Num) -> Option<f64> {
    n.0.eval::<f64>().ok()
}

fn vec3(v: &Vec3In) -> Option<V3<f64>> {
    Some(vec::v3(num(&v[0])?, num(&v[1])?, num(&v[2])?))
}

/// The problem's inputs at f64; parts that cannot be read are left out.
pub fn inputs(p: &ProblemIn) -> Inputs {
    let points: Vec<(String, V3<f64>)> = p
        .points()
        .unwrap_or_default()
        .iter()
        .filter_map(|(n, v)| Some((n.clone(), vec3(v)?)))
        .collect();
    let per = p.perspective.as_ref();
    let end = |r: &PointRef| match r {
        PointRef::At(v) => vec3(v),
        PointRef::Named(n) => points.iter().find(|(k, _)| k == n).map(|(_, q)| *q),
    };
    let segments = p
        .clip
        .iter()
        .flat_map(|c| c.segment.iter())
        .filter_map(|s| Some((end(&s.from)?, end(&s.to)?)))
        .collect();
    Inputs {
        camera: p
            .camera
            .as_ref()
            .and_then(|c| Some((vec3(&c.eye)?, vec3(&c.up)?))),
        d: per.and_then(|x| match (&x.d, &x.near) {
            (Some(d), _) => num(d),
            (None, Some(n)) => num(n).map(|n| -n),
            _ => None,
        }),
        aspect: per.and_then(|x| x.aspect.as_ref()).and_then(num),
        viewport: per
            .and_then(|x| x.viewport.as_ref())
            .and_then(|v| Some((num(&v[0])?, num(&v[1])?))),
        segments,
        shade: lighting(p),
        points,
    }
}

/// The lighting constants of the problem, if it has a lighting part.
fn lighting(p: &ProblemIn) -> Option<Lighting> {
    let sh = p.shade.as_ref()?;
    let file = LightsFileIn {
        global_ambient: p.global_ambient.clone(),
        material: None,
        light: p.light.clone(),
    };
    let s = lights::build::<f64>(sh, &file, "shade.", "light", &mut NoTrace).ok()?;
    let m = &s.material;
    let view = match &s.surface.camera {
        Some(c) => vec::normalize(&vec::sub(c, &s.surface.position))?.0,
        None => s.surface.view,
    };
    Some(Lighting {
        view,
        kd: m.kd,
        ks: m.ks,
        shininess: m.shininess,
        color: m.color,
        specular: m.specular,
        terms: m.model.terms(),
        text_light: s.text_light && s.lights.len() == 1 && m.specular_on,
    })
}

/// The numbers of a value, flattened (a point's coordinates, a matrix by rows).
pub fn numbers(v: &Val) -> Vec<f64> {
    match v {
        Val::Num(s) => vec![s.value],
        Val::List(items) => items.iter().flat_map(numbers).collect(),
        _ => vec![],
    }
}

fn get3(own: &Own, key: &str) -> Option<V3<f64>> {
    match numbers(&own(key)?)[..] {
        [x, y, z] => Some(vec::v3(x, y, z)),
        _ => None,
    }
}

fn get1(own: &Own, key: &str) -> Option<f64> {
    match numbers(&own(key)?)[..] {
        [x] => Some(x),
        _ => None,
    }
}

fn text(own: &Own, key: &str) -> Option<String> {
    match own(key)? {
        Val::Text(t) => Some(t),
        _ => None,
    }
}

/// The value of `key` computed from the earlier values `own`, or None when
/// the key does not follow from earlier answers (an input-only step such as
/// n or the window's top, or a part the problem lacks). `right` is
/// grafika's result tree (which ends of the segment are intersections).
pub fn recompute(inp: &Inputs, key: &str, own: &Own, right: &[(String, Val)]) -> Option<Val> {
    let parts: Vec<&str> = key.split('.').collect();
    match parts[..] {
        ["view", k] => view_axis(inp, k, own),
        ["view", "points", name] => eye_point(inp, name, own),
        ["project", "points", name] => projected(inp, name, own),
        ["window", k] => window_edge(inp, k, own),
        ["viewport", "pixels", name] => pixel(name, inp, own),
        ["shade", k] => shade(inp, k, own),
        ["clip", ..] => clip(inp, &parts, own, right),
        _ => None,
    }
}

/// u = (Vup × n)/|Vup × n|;  v = n × u;  the view matrix with rows
/// (u, −u·Pe), (v, −v·Pe), (n, −n·Pe), (0, 0, 0, 1).
fn view_axis(inp: &Inputs, k: &str, own: &Own) -> Option<Val> {
    let (pe, up) = inp.camera?;
    match k {
        "u" => Some(Val::vec3(
            &vec::normalize(&vec::cross(&up, &get3(own, "view.n")?))?.0,
        )),
        "v" => Some(Val::vec3(&vec::cross(
            &get3(own, "view.n")?,
            &get3(own, "view.u")?,
        ))),
        "matrix" => {
            let axes = [
                get3(own, "view.u")?,
                get3(own, "view.v")?,
                get3(own, "view.n")?,
            ];
            let mut rows: Vec<Val> = axes
                .iter()
                .map(|a| {
                    let t = -vec::dot(a, &pe);
                    Val::List([a[0], a[1], a[2], t].iter().map(Val::num).collect())
                })
                .collect();
            rows.push(Val::List(
                [0.0, 0.0, 0.0, 1.0].iter().map(Val::num).collect(),
            ));
            Some(Val::List(rows))
        }
        _ => None,
    }
}

/// P' = (u·(P − Pe), v·(P − Pe), n·(P − Pe)).
fn eye_point(inp: &Inputs, name: &str, own: &Own) -> Option<Val> {
    let (pe, _) = inp.camera?;
    let p = inp.points.iter().find(|(n, _)| n == name)?.1;
    let rel = vec::sub(&p, &pe);
    let [u, v, n] = ["view.u", "view.v", "view.n"].map(|k| get3(own, k));
    Some(Val::vec3(&vec::v3(
        vec::dot(&u?, &rel),
        vec::dot(&v?, &rel),
        vec::dot(&n?, &rel),
    )))
}

/// xp = d·x/z,  yp = d·y/z,  zp = d.
fn projected(inp: &Inputs, name: &str, own: &Own) -> Option<Val> {
    let d = inp.d?;
    let e = get3(own, &format!("view.points.{name}"))?;
    if e[2] == 0.0 {
        return None;
    }
    Some(Val::vec3(&vec::v3(d * e[0] / e[2], d * e[1] / e[2], d)))
}

/// bottom = −top,  left = −aspect·top,  right = aspect·top,
/// height = top − bottom,  width = right − left (in the order asked: top,
/// bottom, left, right, height, width).
fn window_edge(inp: &Inputs, k: &str, own: &Own) -> Option<Val> {
    let g = |k: &str| get1(own, &format!("window.{k}"));
    let x = match k {
        "bottom" => -g("top")?,
        "right" => inp.aspect? * g("top")?,
        "left" => -(inp.aspect? * g("top")?),
        "height" => g("top")? - g("bottom")?,
        "width" => g("right")? - g("left")?,
        _ => return None,
    };
    Some(Val::num(&x))
}

/// px = (xp − left)/(right − left)·W,  py = (yp − bottom)/(top − bottom)·H,
/// from the student's window and projected point.
fn pixel(name: &str, inp: &Inputs, own: &Own) -> Option<Val> {
    let (vw, vh) = inp.viewport?;
    let g = |k: &str| get1(own, &format!("window.{k}"));
    let w = Window {
        top: g("top")?,
        bottom: g("bottom")?,
        left: g("left")?,
        right: g("right")?,
        height: g("height")?,
        width: g("width")?,
    };
    let q = numbers(&own(&format!("project.points.{name}"))?);
    if q.len() < 2 || w.width == 0.0 || w.height == 0.0 {
        return None;
    }
    let (px, py) = viewport_xy(&w, (&vw, &vh), (&q[0], &q[1]));
    Some(Val::vec2(&px, &py))
}

/// cos α = L·N;  R = 2N(L·N) − L;  cos β = R·V;
/// diffuse = kd·max(cos α, 0)·Cs;  specular = ks·max(cos β, 0)ⁿ·Cspecular;
/// color = min(max(ambient + diffuse + specular, 0), 1), per channel.
fn shade(inp: &Inputs, k: &str, own: &Own) -> Option<Val> {
    let s = inp.shade.as_ref()?;
    let rgb = |f: &dyn Fn(usize) -> f64| Val::List((0..3).map(|i| Val::num(&f(i))).collect());
    match k {
        "cos_alpha" => Some(Val::num(&vec::dot(
            &get3(own, "shade.L")?,
            &get3(own, "shade.N")?,
        ))),
        "R" => {
            let (l, n) = (get3(own, "shade.L")?, get3(own, "shade.N")?);
            let two_ln = 2.0 * get1(own, "shade.cos_alpha")?;
            Some(Val::vec3(&vec::sub(&vec::scale(&n, &two_ln), &l)))
        }
        "cos_beta" => Some(Val::num(&vec::dot(&get3(own, "shade.R")?, &s.view))),
        "diffuse" if s.text_light && s.terms.1 => {
            let c = get1(own, "shade.cos_alpha")?.max(0.0);
            Some(rgb(&|i| s.kd * c * s.color[i]))
        }
        "specular" if s.text_light && s.terms.2 => {
            let h = get1(own, "shade.cos_beta")?.max(0.0).powf(s.shininess);
            Some(rgb(&|i| s.ks * h * s.specular[i]))
        }
        "color" if s.text_light => {
            let terms =
                ["ambient", "diffuse", "specular"].map(|t| get3(own, &format!("shade.{t}")));
            let sum = vec::add(&vec::add(&terms[0]?, &terms[1]?), &terms[2]?);
            Some(rgb(&|i| sum[i].clamp(0.0, 1.0)))
        }
        _ => None,
    }
}

/// For segment i (key `clip.K` or `clip.i.K`): an intersection point
/// P(t) = P0 + t·(P1 − P0) from the student's t; the status from the
/// student's outcodes (both 000000: accepted; code0 AND code1 ≠ 0: rejected;
/// else clipped); the segment with the student's intersection points in
/// place of grafika's.
fn clip(inp: &Inputs, parts: &[&str], own: &Own, right: &[(String, Val)]) -> Option<Val> {
    let (prefix, rest) = match parts.get(1)?.parse::<usize>() {
        Ok(i) => (format!("clip.{i}"), (i, &parts[2..])),
        Err(_) => ("clip".to_string(), (0, &parts[1..])),
    };
    let (p0, p1) = *inp.segments.get(rest.0)?;
    match rest.1 {
        ["intersections", plane, "point"] => {
            let t = get1(own, &format!("{prefix}.intersections.{plane}.t"))?;
            Some(Val::vec3(&vec::add(
                &p0,
                &vec::scale(&vec::sub(&p1, &p0), &t),
            )))
        }
        ["status"] => {
            let code = |k: &str| u8::from_str_radix(&text(own, &format!("{prefix}.{k}"))?, 2).ok();
            let (c0, c1) = (code("code0")?, code("code1")?);
            let s = match (c0 | c1, c0 & c1) {
                (0, _) => "accepted",
                (_, 0) => "clipped",
                _ => "rejected",
            };
            Some(Val::text(s))
        }
        ["segment"] => {
            let Some(Val::List(ends)) = lookup(right, &format!("{prefix}.segment")) else {
                return None;
            };
            let Some(Val::Map(planes)) = lookup(right, &format!("{prefix}.intersections")) else {
                return None;
            };
            // an end that is one of grafika's intersection points becomes the student's
            let swap = |end: &Val| -> Option<Val> {
                let e = numbers(end);
                let point_is_end = |x: &Val| match x {
                    Val::Map(kv) => kv.iter().any(|(k, q)| k == "point" && numbers(q) == e),
                    _ => false,
                };
                match planes.iter().find(|(_, x)| point_is_end(x)) {
                    Some((pl, _)) => own(&format!("{prefix}.intersections.{pl}.point")),
                    None => Some(end.clone()),
                }
            };
            Some(Val::List(ends.iter().map(swap).collect::<Option<_>>()?))
        }
        _ => None,
    }
}
