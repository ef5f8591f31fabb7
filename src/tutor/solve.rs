//! The solver: a problem ([`solve_problem`]) is a calculator command's one
//! part ([`crate::tutor::part`]) or a whole problem file, solved here
//! through the text's steps — modeling, viewing transformation, projection
//! onto the near plane, window and clipping, viewport — with a comparison
//! with the answers the source printed. Both run their parts by the same
//! functions ([`crate::tutor::run`]).

use crate::error::{Error, Result};
use crate::input::part::Problem;
use crate::input::problem::{PointRef, ProblemIn};
use crate::input::{eval, eval3};
use crate::msg::{ErrMsg, Msg};
use crate::num::format::fmt_dec;
use crate::num::vec::V3;
use crate::num::{Expr, Scalar};
use crate::stages::camera::Camera;
use crate::stages::clip::ClipBox;
use crate::stages::projection::Projection;
use crate::stages::trace::{Name, Recorder, Step, Subst, Trace, Val};
use crate::stages::window;
use crate::tutor::key::{Field, Part};
use crate::tutor::run::{
    basis_run, clip_run, eye_run, light_run, pixels, points_val, project_run, view_result,
    window_run, Hooks, Named,
};
use crate::tutor::solution::{
    at, lookup, p3, Asked, CameraAt, Compared, Comparison, Given, Report, ShadeAt, Tree, WindowAt,
};

/// Solves a problem at precision `T`: a calculator command's one part or
/// a problem file's parts.
pub fn solve_problem<T: Scalar>(p: &Problem) -> Result<Report> {
    match p {
        Problem::Part(part) => crate::tutor::part::solve_part::<T>(part),
        Problem::File(file) => solve::<T>(file),
    }
}

/// Solves a parsed problem at precision `T`.
pub fn solve<T: Scalar>(p: &ProblemIn) -> Result<Report> {
    solve_with::<T>(p, &Hooks::default())
}

/// Solves a parsed problem at precision `T`, with stage results altered by `hooks`.
pub fn solve_with<T: Scalar>(p: &ProblemIn, hooks: &Hooks<T>) -> Result<Report> {
    let mut out = Out::default();
    let out = &mut out;
    let points: Vec<(String, V3<T>)> = p
        .points()?
        .iter()
        .map(|(n, v)| Ok((n.clone(), eval3(&format!("points.{n}"), v)?)))
        .collect::<Result<_>>()?;
    let eye_pts = view_part(p, hooks, &points, out)?;
    let near: Option<T> = p
        .perspective
        .as_ref()
        .and_then(|x| x.near.as_ref())
        .map(|n| eval("perspective.near", n))
        .transpose()?;
    let projected = project_part(p, hooks, &eye_pts, near.as_ref(), out)?;
    let eyes = (&eye_pts[..], &projected[..]);
    let win = window_part(p, hooks, eyes, near.as_ref(), out)?;
    viewport_part(p, win.as_ref(), &projected, out)?;
    clip_part(p, hooks, &points, out)?;
    shade_part(p, hooks, out)?;
    let Out { rec, result, parts } = std::mem::take(out);
    if result.is_empty() {
        return Err(Error::why("ask", ErrMsg::NothingToSolve));
    }

    // Exact printed forms are compared to 1e-9 relative, or to what the
    // precision itself can hold (f32 rounds at about 1e-7).
    let rel = match T::PRECISION {
        crate::num::Precision::F32 => 64.0 * f64::from(f32::EPSILON),
        _ => 1e-9,
    };
    let comparison = compare_printed(p, &result, rel);
    let asked = Asked::File(Box::new(p.clone()));
    let mut report = Report::from_recorder::<T>(asked, parts, result, rec);
    report.comparison = comparison;
    report.source_notes = p.source_notes.clone();
    Ok(report)
}

/// Where the parts write: the steps, the named results, what each part was given.
#[derive(Default)]
struct Out {
    rec: Recorder,
    result: Tree,
    parts: Vec<Given>,
}

/// Steps 1 and 2, modeling and viewing transformation: the basis, the view
/// matrix and the eye coordinates of the points (empty when not needed).
fn view_part<T: Scalar>(
    p: &ProblemIn,
    hooks: &Hooks<T>,
    points: &[(String, V3<T>)],
    out: &mut Out,
) -> Result<Vec<(String, V3<T>)>> {
    let Out { rec, result, parts } = out;
    let want_view = p.asks("view") || p.asks("project") || p.asks("viewport");
    let c = match (want_view, &p.camera) {
        (true, Some(c)) => c,
        (true, None) if !points.is_empty() && p.ask.is_some() => {
            return Err(Error::why("camera", ErrMsg::NoCameraTable))
        }
        _ => return Ok(vec![]),
    };
    let cam = Camera {
        pe: eval3("camera.eye", &c.eye)?,
        pr: eval3("camera.look", &c.look)?,
        vup: eval3("camera.up", &c.up)?,
    };
    rec.section(Msg::SecModeling);
    rec.step(|| Step::new(Msg::NothingToDo, "").note(Msg::AlreadyWorld));
    rec.section(Msg::SecViewing);
    let b = basis_run(&cam, hooks, rec).map_err(camera_field)?;
    let (m, eye_pts) = eye_run(&b, &cam, points, (hooks, camera_field), rec)?;
    if p.asks("view") {
        result.push((Part::View.key(), Val::Map(view_result(&b, &m, &eye_pts))));
        let world = points.iter().map(|(n, q)| (n.clone(), p3(q))).collect();
        parts.push(Given::View(CameraAt::of(&cam), world));
    }
    Ok(eye_pts)
}

/// Step 3, projection onto the near plane (d = −near unless given): the
/// projected points (empty when not needed).
fn project_part<T: Scalar>(
    p: &ProblemIn,
    hooks: &Hooks<T>,
    eye_pts: &[(String, V3<T>)],
    near: Option<&T>,
    out: &mut Out,
) -> Result<Vec<(String, V3<T>)>> {
    let Out { rec, result, parts } = out;
    if !(p.asks("project") || p.asks("viewport")) || eye_pts.is_empty() {
        return Ok(vec![]);
    }
    let given = p.perspective.as_ref().and_then(|x| x.d.as_ref());
    let d: T = match (given, near) {
        (Some(d), _) => eval("perspective.d", d)?,
        (None, Some(n)) => -n.clone(),
        (None, None) => return Err(Error::why("perspective.near", ErrMsg::ProjectionNeedsNear)),
    };
    rec.section(Msg::SecProjection);
    rec.step(|| match (given, near) {
        (None, Some(n)) => Step::new(Msg::ProjPlane, Msg::FProjPlane)
            .val(Name::math("near"), Val::num(n))
            .res(Name::math("d"), Val::num(&d))
            .sub(Name::math("d"), Subst::new("−{}", vec![Val::num(n)])),
        _ => Step::new(Msg::ProjPlane, "z = d").val(Name::math("d"), Val::num(&d)),
    });
    let proj = Projection::Plane { d };
    proj.validate().map_err(|e| e.in_field("perspective.d"))?;
    let projected = project_run(&proj, eye_pts, hooks, rec)?;
    if p.asks("project") {
        let r = vec![(Field::Points.key(), points_val(&projected))];
        result.push((Part::Project.key(), Val::Map(r)));
        parts.push(Given::Project {
            projection: Given::projection(&proj),
            points: eye_pts
                .iter()
                .map(|(n, e)| (n.clone(), Val::vec3(e)))
                .collect(),
            chained: true,
        });
    }
    Ok(projected)
}

/// Step 4, the window on the near plane (and the far one), and which
/// projected points it contains; `eyes` = (eye points, projected points).
fn window_part<T: Scalar>(
    p: &ProblemIn,
    hooks: &Hooks<T>,
    eyes: (&[Named<T>], &[Named<T>]),
    near: Option<&T>,
    out: &mut Out,
) -> Result<Option<window::Window<T>>> {
    let Out { rec, result, parts } = out;
    let per = match &p.perspective {
        Some(per) if p.asks("window") || p.asks("viewport") => per,
        _ => return Ok(None),
    };
    let (Some(fovy), Some(aspect), Some(near)) = (&per.fovy, &per.aspect, near) else {
        return match &p.ask {
            Some(a) if a.iter().any(|x| x == "window" || x == "viewport") => {
                Err(Error::why("perspective", ErrMsg::WindowNeeds))
            }
            _ => Ok(None),
        };
    };
    let fovy: T = fovy
        .0
        .degrees()
        .map_err(|m| Error::why("perspective.fovy", m))?;
    let aspect: T = eval("perspective.aspect", aspect)?;
    let far: Option<T> = per
        .far
        .as_ref()
        .map(|f| eval("perspective.far", f))
        .transpose()?;
    rec.section(Msg::SecWindowClip);
    let set_up = (&fovy, &aspect, near, far.as_ref());
    let (w, r) = window_run(set_up, hooks, rec).map_err(perspective_field)?;
    for ((n, q), (_, e)) in eyes.1.iter().zip(eyes.0) {
        point_inside_step(rec, n, q, e, &w, near, far.as_ref());
    }
    if p.asks("window") {
        result.push((Part::Window.key(), Val::Map(r)));
        parts.push(Given::Window(WindowAt {
            fovy: at(&fovy),
            aspect: at(&aspect),
            near: at(near),
            far: far.as_ref().map(at),
            viewport: None,
            points: match p.asks("project") {
                true => eyes
                    .1
                    .iter()
                    .map(|(n, q)| (n.clone(), Val::vec3(q)))
                    .collect(),
                false => vec![],
            },
            projected: true,
        }));
    }
    Ok(Some(w))
}

/// The viewport mapping of the projected points (window → pixels).
fn viewport_part<T: Scalar>(
    p: &ProblemIn,
    win: Option<&window::Window<T>>,
    projected: &[(String, V3<T>)],
    out: &mut Out,
) -> Result<()> {
    let Out { rec, result, parts } = out;
    let vp = p.perspective.as_ref().and_then(|x| x.viewport.as_ref());
    let (true, Some(w), Some(vp)) = (p.asks("viewport"), win, vp) else {
        return Ok(());
    };
    let (vw, vh): (T, T) = (
        eval("perspective.viewport", &vp[0])?,
        eval("perspective.viewport", &vp[1])?,
    );
    window::validate_viewport(&vw, &vh).map_err(|e| e.in_field("perspective.viewport"))?;
    rec.section(Msg::SecViewport);
    if let Some(Given::Window(w)) = parts.last_mut() {
        w.viewport = Some((at(&vw), at(&vh)));
    }
    let on_window = projected.iter().map(|(n, q)| (n, (&q[0], &q[1])));
    let px = pixels(w, (&vw, &vh), on_window, rec);
    result.push((
        Part::Viewport.key(),
        Val::Map(vec![(Field::Pixels.key(), Val::Map(px))]),
    ));
    Ok(())
}

/// Clipping of the segments against the box.
fn clip_part<T: Scalar>(
    p: &ProblemIn,
    hooks: &Hooks<T>,
    points: &[(String, V3<T>)],
    out: &mut Out,
) -> Result<()> {
    let Out { rec, result, parts } = out;
    let (true, Some(c)) = (p.asks("clip"), &p.clip) else {
        return Ok(());
    };
    let b = ClipBox {
        min: eval3("clip.min", &c.min)?,
        max: eval3("clip.max", &c.max)?,
    };
    b.validate().map_err(|e| e.in_field("clip.min"))?;
    let mut all = Vec::new();
    for (i, s) in c.segment.iter().enumerate() {
        let f = format!("clip.segment[{i}]");
        let p0: V3<T> = point_ref(&format!("{f}.from"), &s.from, points)?;
        let p1: V3<T> = point_ref(&format!("{f}.to"), &s.to, points)?;
        rec.section(Msg::SecLineClip((c.segment.len() > 1).then_some(i + 1)));
        let segment = (c.segment.len() > 1).then_some(i);
        let given = Given::clip(&b, (&p0, &p1), segment);
        all.push(Val::Map(clip_run(&b, (&p0, &p1), (hooks, segment), rec)));
        parts.push(given);
    }
    match all.len() {
        0 => {}
        1 => result.push((Part::Clip.key(), all.remove(0))),
        _ => result.push((Part::Clip.key(), Val::List(all))),
    }
    Ok(())
}

/// Lighting at the `[shade]` point.
fn shade_part<T: Scalar>(p: &ProblemIn, hooks: &Hooks<T>, out: &mut Out) -> Result<()> {
    let Out { rec, result, parts } = out;
    match (p.asks("shade"), &p.shade) {
        (true, Some(sh)) => {
            rec.section(Msg::SecLighting);
            let file = crate::input::lights::LightsFileIn {
                global_ambient: p.global_ambient.clone(),
                material: None,
                light: p.light.clone(),
            };
            let (setup, r) = light_run((sh, &file, "shade."), hooks, rec)?;
            result.push((Part::Shade.key(), Val::Map(r)));
            parts.push(Given::Shade(ShadeAt::of(&setup, None)));
            Ok(())
        }
        _ if !p.light.is_empty() && p.shade.is_none() => {
            Err(Error::why("shade", ErrMsg::LightsNeedShade))
        }
        _ => Ok(()),
    }
}

/// A segment end: its coordinates, or the named point's.
pub fn point_ref<T: Scalar>(
    field: &str,
    r: &PointRef,
    points: &[(String, V3<T>)],
) -> Result<V3<T>> {
    match r {
        PointRef::At(v) => eval3(field, v),
        PointRef::Named(name) => points
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| p.clone())
            .ok_or_else(|| {
                let known: Vec<&str> = points.iter().map(|(n, _)| n.as_str()).collect();
                Error::said(
                    field,
                    Msg::ErrUnknownPoint(
                        name.to_string(),
                        (!known.is_empty()).then(|| known.join(", ")),
                    ),
                )
            }),
    }
}

fn camera_field(e: Error) -> Error {
    let f = format!("camera.{}", e.field);
    e.in_field(f)
}

fn perspective_field(e: Error) -> Error {
    let f = format!("perspective.{}", e.field);
    e.in_field(f)
}

/// The text's point-clipping test after projection: inside the window and
/// between the near and far planes (−far ≤ z' ≤ −near).
fn point_inside_step<T: Scalar>(
    rec: &mut Recorder,
    name: &str,
    q: &V3<T>,
    e: &V3<T>,
    w: &window::Window<T>,
    near: &T,
    far: Option<&T>,
) {
    let in_window = window::inside(w, &q[0], &q[1]);
    let in_depth = e[2] <= -near.clone() && far.is_none_or(|f| e[2] >= -f.clone());
    rec.step(|| {
        Step::new(Msg::InsideVolume(name.to_string()), Msg::FInside)
            .val(Name::Image(name.to_string()), Val::vec2(&q[0], &q[1]))
            .val(Name::EyeZ(name.to_string()), Val::num(&e[2]))
            .res(Name::Inside, Val::Bool(in_window && in_depth))
            .note(match (in_window, in_depth) {
                (true, true) => Msg::Inside(true, true),
                (false, w) => Msg::Inside(false, w),
                (true, false) => Msg::Inside(true, false),
            })
    });
}

/// Flattens a nested TOML table into dotted keys.
fn flatten(prefix: &str, t: &toml::Table, out: &mut Vec<(String, toml::Value)>) {
    for (k, v) in t {
        let key = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        match v {
            toml::Value::Table(inner) => flatten(&key, inner, out),
            other => out.push((key, other.clone())),
        }
    }
}

/// Whether a printed value agrees with a computed one: texts equal; numbers
/// equal to the digits the text wrote (a printed 0.041 agrees with 0.04142),
/// or to `rel` (relative, at least absolute near zero) when the printed form
/// is exact (−6/sqrt(2)); lists element by element (a printed (x, y) is
/// compared with the first two of (x, y, z)).
pub fn agrees(printed: &toml::Value, computed: &Val, rel: f64) -> Option<bool> {
    match (printed, computed) {
        (toml::Value::Array(ps), Val::List(cs)) => {
            if ps.len() > cs.len() {
                return Some(false);
            }
            let mut all = true;
            for (p, c) in ps.iter().zip(cs) {
                all &= agrees(p, c, rel)?;
            }
            Some(all)
        }
        (toml::Value::String(s), Val::Text(t)) => Some(s == t),
        (p, Val::Num(c)) => {
            let text = match p {
                toml::Value::String(s) => s.clone(),
                toml::Value::Integer(i) => i.to_string(),
                toml::Value::Float(f) => format!("{f}"),
                _ => return None,
            };
            let e: Expr = crate::num::parse_expr(&text.replace(',', ".")).ok()?;
            let v: f64 = e.eval::<f64>().ok()?;
            Some((v - c.value).abs() <= written_tolerance(&text).max(rel * c.value.abs().max(1.0)))
        }
        (toml::Value::String(s), Val::Null) => Some(s == "none" || s == "null"),
        _ => None,
    }
}

/// Half a unit in the last decimal place written (0 for exact forms).
fn written_tolerance(text: &str) -> f64 {
    let mut best: f64 = 0.0;
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if chars[i] == '.' || chars[i] == ',' {
            let mut k = 0;
            while i + 1 + k < chars.len() && chars[i + 1 + k].is_ascii_digit() {
                k += 1;
            }
            best = best.max(0.5 * 10f64.powi(-(k as i32)));
            i += k;
        }
        i += 1;
    }
    best * 1.000001
}

/// Compares every `[printed]` answer with the computed results.
fn compare_printed(p: &ProblemIn, result: &[(String, Val)], rel: f64) -> Option<Comparison> {
    let mut flat = Vec::new();
    flatten("", &p.printed, &mut flat);
    if flat.is_empty() {
        return None;
    }
    let rows = flat
        .iter()
        .map(|(key, printed)| {
            let computed = lookup(result, key).cloned();
            let erratum = p.errata.iter().find(|e| &e.key == key);
            Compared {
                key: key.clone(),
                printed: printed_text(printed),
                agrees: computed.as_ref().and_then(|v| agrees(printed, v, rel)),
                computed,
                kind: erratum.and_then(|e| e.kind),
                why: erratum.map(|e| e.why()),
            }
        })
        .collect();
    Some(Comparison {
        source: p.source.clone(),
        rows,
    })
}

/// A printed value as the text wrote it.
fn printed_text(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Array(a) => format!(
            "({})",
            a.iter().map(printed_text).collect::<Vec<_>>().join(", ")
        ),
        toml::Value::Float(f) => fmt_dec(*f, 17),
        other => other.to_string(),
    }
}
