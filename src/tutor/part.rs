//! A calculator command's one part solved: its flags' expressions
//! evaluated at the precision asked (errors named by the flag), the part
//! run by the same functions as a problem file's parts ([`run`]), and a
//! report with the part's results unnested (docs/spec.md §3's keys of
//! `basis`, `view`, …).

use crate::error::{Error, Result};
use crate::input::fields::Vec3In;
use crate::input::part::{PartIn, ProjectionIn, WindowIn};
use crate::input::problem::CameraIn;
use crate::input::{eval, eval3, point_field};
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera::Camera;
use crate::stages::clip::ClipBox;
use crate::stages::projection::Projection;
use crate::stages::trace::{Recorder, Val};
use crate::stages::window;
use crate::tutor::key::Field;
use crate::tutor::keys::basis_result;
use crate::tutor::run::{self, Hooks, Named};
use crate::tutor::solution::{at, p3, Asked, CameraAt, Given, Report, ShadeAt, WindowAt};

/// Solves one part at precision `T`.
pub fn solve_part<T: Scalar>(part: &PartIn) -> Result<Report> {
    let mut rec = Recorder::new();
    let (given, result) = match part {
        PartIn::Basis(c) => {
            let cam = camera::<T>(c)?;
            let b = run::basis_run(&cam, &Hooks::default(), &mut rec)?;
            (Given::Basis(CameraAt::of(&cam)), basis_result(&b))
        }
        PartIn::View(c, points) => view::<T>(c, points, &mut rec)?,
        PartIn::Project(proj, points) => project::<T>(proj, points, &mut rec)?,
        PartIn::Window(w) => window_part::<T>(w, &mut rec)?,
        PartIn::Clip([min, max, from, to]) => {
            let b = ClipBox {
                min: eval3::<T>("min", min)?,
                max: eval3("max", max)?,
            };
            b.validate()?;
            let ends: (V3<T>, V3<T>) = (eval3("from", from)?, eval3("to", to)?);
            let given = Given::clip(&b, (&ends.0, &ends.1), None);
            let hooks = (&Hooks::default(), None);
            let r = run::clip_run(&b, (&ends.0, &ends.1), hooks, &mut rec);
            (given, r)
        }
        PartIn::Shade(sh, file, name) => {
            let hooks = Hooks::<T>::default();
            let (setup, r) = run::light_run((sh.as_ref(), file, ""), &hooks, &mut rec)?;
            (Given::Shade(ShadeAt::of(&setup, name.clone())), r)
        }
    };
    Ok(Report::from_recorder::<T>(
        Asked::Command,
        vec![given],
        result,
        rec,
    ))
}

/// The camera of the flags.
fn camera<T: Scalar>(c: &CameraIn) -> Result<Camera<T>> {
    Ok(Camera {
        pe: eval3("eye", &c.eye)?,
        pr: eval3("look", &c.look)?,
        vup: eval3("up", &c.up)?,
    })
}

/// The points of `--point`.
fn points<T: Scalar>(points: &[(String, Vec3In)]) -> Result<Vec<Named<T>>> {
    (points.iter())
        .map(|(n, v)| Ok((n.clone(), eval3(&point_field("point", n), v)?)))
        .collect()
}

/// A part's inputs and results.
type Solved = (Given, Vec<(String, Val)>);

/// `view`: the basis, the view matrix, the eye coordinates.
fn view<T: Scalar>(c: &CameraIn, pts: &[(String, Vec3In)], rec: &mut Recorder) -> Result<Solved> {
    let cam = camera::<T>(c)?;
    let pts = points::<T>(pts)?;
    let hooks = Hooks::default();
    let b = run::basis_run(&cam, &hooks, rec)?;
    let (m, eye) = run::eye_run(&b, &cam, &pts, (&hooks, |e| e), rec)?;
    let world = pts.iter().map(|(n, p)| (n.clone(), p3(p))).collect();
    let given = Given::View(CameraAt::of(&cam), world);
    Ok((given, run::view_result(&b, &m, &eye)))
}

/// `project`: the images of the points.
fn project<T: Scalar>(
    proj: &ProjectionIn,
    pts: &[(String, Vec3In)],
    rec: &mut Recorder,
) -> Result<Solved> {
    let proj: Projection<T> = match proj {
        ProjectionIn::Plane(d) => Projection::Plane { d: eval("d", d)? },
        ProjectionIn::General(c, p) => Projection::General {
            zprp: eval("cop", c)?,
            zvp: eval("plane", p)?,
        },
        ProjectionIn::Ortho => Projection::Ortho,
    };
    proj.validate()?;
    let pts = points::<T>(pts)?;
    let images = run::project_run(&proj, &pts, &Hooks::default(), rec)?;
    let given = Given::Project {
        projection: Given::projection(&proj),
        points: pts.iter().map(|(n, p)| (n.clone(), Val::vec3(p))).collect(),
        chained: false,
    };
    Ok((given, vec![(Field::Points.key(), run::points_val(&images))]))
}

/// `window`: the window (and the far one), and the pixels of the points.
fn window_part<T: Scalar>(w: &WindowIn, rec: &mut Recorder) -> Result<Solved> {
    let fovy: T = w.fovy.0.degrees().map_err(|m| Error::why("fovy", m))?;
    let aspect: T = eval("aspect", &w.aspect)?;
    let near: T = eval("near", &w.near)?;
    let far: Option<T> = w.far.as_ref().map(|f| eval("far", f)).transpose()?;
    let vp: Option<(T, T)> = (w.viewport.as_ref())
        .map(|[a, b]| Ok::<_, Error>((eval("viewport", a)?, eval("viewport", b)?)))
        .transpose()?;
    let pts: Vec<(String, (T, T))> = (w.points.iter())
        .map(|(n, [x, y])| {
            let f = point_field("point", n);
            Ok((n.clone(), (eval(&f, x)?, eval(&f, y)?)))
        })
        .collect::<Result<_>>()?;
    let set_up = (&fovy, &aspect, &near, far.as_ref());
    let (win, mut result) = run::window_run(set_up, &Hooks::default(), rec)?;
    if let Some((vw, vh)) = &vp {
        window::validate_viewport(vw, vh)?;
        let on_window = pts.iter().map(|(n, (x, y))| (n, (x, y)));
        let px = run::pixels(&win, (vw, vh), on_window, rec);
        if !px.is_empty() {
            result.push((Field::Pixels.key(), Val::Map(px)));
        }
    }
    let given = Given::Window(WindowAt {
        fovy: at(&fovy),
        aspect: at(&aspect),
        near: at(&near),
        far: far.as_ref().map(at),
        viewport: vp.as_ref().map(|(w, h)| (at(w), at(h))),
        points: (pts.iter())
            .map(|(n, (x, y))| (n.clone(), Val::vec2(x, y)))
            .collect(),
        projected: false,
    });
    Ok((given, result))
}
