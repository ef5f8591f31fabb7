//! The calculator commands' flags read into the typed problem: one part
//! whose inputs are the flags' expressions, names and choices, each named
//! by its flag. The solver (`tutor::solve`) evaluates and runs it, as it
//! runs a problem file's parts; no math here.

use crate::cli::args::{CameraArgs, ClipArgs, Command, OnOff, ProjectArgs, ShadeArgs, WindowArgs};
use crate::error::{Error, Result};
use crate::input;
use crate::input::fields::{Num, Vec3In};
use crate::input::lights::{LightsFileIn, ShadeIn};
use crate::input::part::{
    ClipIn, PartIn, PointIn, Problem, ProjectIn, ProjectionIn, ShadePartIn, Shared, Table,
};
use crate::input::problem::{CameraIn, PerspectiveIn, PointRef};
use crate::msg::Msg;

/// The one-part problem a calculator command asks, if `cmd` is one.
pub fn part_of(cmd: &Command) -> Option<Result<Problem>> {
    Some(match cmd {
        Command::Basis(c) => camera(c).map(|c| Problem::command(vec![PartIn::Basis], c)),
        Command::View { camera: c, points } => view(c, points),
        Command::Project(a) => project(a),
        Command::Window(a) => window(a),
        Command::Clip(a) => clip(a),
        Command::Shade(a) => shade(a),
        _ => return None,
    })
}

/// A table of flags (their fields unprefixed).
fn flags<X>(table: X) -> Table<X> {
    Table { prefix: "", table }
}

/// `--eye --look --up`.
fn camera(c: &CameraArgs) -> Result<Shared> {
    let table = CameraIn {
        eye: input::vec3("eye", &c.eye)?,
        look: input::vec3("look", &c.look)?,
        up: input::vec3("up", &c.up)?,
    };
    Ok(Shared {
        camera: Some(flags(table)),
        ..Shared::default()
    })
}

/// `--point NAME=X,Y,Z`, each named by its flag (`point A`).
fn points(items: &[String]) -> Result<Vec<PointIn>> {
    let named = input::points3("point", items)?.into_iter();
    Ok(named
        .map(|(n, v)| (n.clone(), input::point_field("point", &n), v))
        .collect())
}

/// `grafika view`.
fn view(c: &CameraArgs, pts: &[String]) -> Result<Problem> {
    let camera = camera(c)?;
    let shared = Shared {
        points: points(pts)?,
        ..camera
    };
    Ok(Problem::command(vec![PartIn::View], shared))
}

/// `grafika project`: `--d`, `--cop` with `--plane`, or `--ortho`.
fn project(a: &ProjectArgs) -> Result<Problem> {
    let flag = |f: &str, t: &str| Ok::<_, Error>((f.to_string(), input::num(f, t)?));
    let proj = match (&a.d, &a.cop, &a.plane, a.ortho) {
        (Some(d), None, None, false) => ProjectionIn::Plane(flag("d", d)?),
        (None, Some(c), Some(p), false) => {
            ProjectionIn::General(flag("cop", c)?, flag("plane", p)?)
        }
        (None, None, None, true) => ProjectionIn::Ortho,
        (None, Some(_), None, false) => return Err(Error::said("plane", Msg::ErrCopNeedsPlane)),
        (None, None, Some(_), false) => return Err(Error::said("cop", Msg::ErrPlaneNeedsCop)),
        _ => return Err(Error::said("d", Msg::ErrChooseProjection)),
    };
    let shared = Shared {
        points: points(&a.points)?,
        ..Shared::default()
    };
    let part = PartIn::Project(ProjectIn::Given(proj));
    Ok(Problem::command(vec![part], shared))
}

/// `grafika window`: the window part, and the viewport part when
/// `--viewport` is given (the points' pixels, in the same flat results).
fn window(a: &WindowArgs) -> Result<Problem> {
    let table = PerspectiveIn {
        fovy: Some(input::angle("fovy", &a.fovy)?),
        aspect: Some(input::num("aspect", &a.aspect)?),
        near: Some(input::num("near", &a.near)?),
        far: a.far.as_deref().map(|f| input::num("far", f)).transpose()?,
        viewport: (a.viewport.as_deref())
            .map(|v| input::size("viewport", v))
            .transpose()?,
        d: None,
    };
    let on_window: Vec<(String, String, [Num; 2])> = (input::points2("point", &a.points)?)
        .into_iter()
        .map(|(n, xy)| (n.clone(), input::point_field("point", &n), xy))
        .collect();
    if !on_window.is_empty() && table.viewport.is_none() {
        return Err(Error::said("viewport", Msg::ErrPointNeedsViewport));
    }
    let mut parts = vec![PartIn::Window];
    if table.viewport.is_some() {
        parts.push(PartIn::Viewport);
    }
    let shared = Shared {
        perspective: Some(flags(table)),
        on_window: Some(on_window),
        ..Shared::default()
    };
    Ok(Problem::command(parts, shared))
}

/// `grafika clip`.
fn clip(a: &ClipArgs) -> Result<Problem> {
    let bounds = flags([input::vec3("min", &a.min)?, input::vec3("max", &a.max)?]);
    let end = |f: &str, t: &str| -> Result<(String, PointRef)> {
        Ok((f.to_string(), PointRef::At(Box::new(input::vec3(f, t)?))))
    };
    let segment = [end("from", &a.from)?, end("to", &a.to)?];
    let part = PartIn::Clip(ClipIn {
        bounds,
        segments: vec![segment],
    });
    Ok(Problem::command(vec![part], Shared::default()))
}

/// `grafika shade`: the flags as a `[shade]` table, and the lights file.
fn shade(a: &ShadeArgs) -> Result<Problem> {
    let sh = shade_in(a)?;
    let lights = match &a.lights {
        Some(path) => LightsFileIn::read(path)?,
        None => LightsFileIn::default(),
    };
    let file = a.lights.as_ref().map(|p| p.display().to_string());
    let part = PartIn::Shade(Box::new(ShadePartIn {
        shade: flags(sh),
        lights,
        file,
    }));
    Ok(Problem::command(vec![part], Shared::default()))
}

/// The flags' expressions as a `[shade]` table.
fn shade_in(a: &ShadeArgs) -> Result<ShadeIn> {
    let v = |field: &str, s: &Option<String>| -> Result<Option<Vec3In>> {
        s.as_deref().map(|t| input::vec3(field, t)).transpose()
    };
    let n = |field: &str, s: &Option<String>| -> Result<Option<Num>> {
        s.as_deref().map(|t| input::num(field, t)).transpose()
    };
    Ok(ShadeIn {
        model: a.model,
        light: v("light", &a.light)?,
        normal: v("normal", &a.normal)?,
        view: v("view", &a.view)?,
        color: v("color", &a.color)?,
        ka: n("ka", &a.ka)?,
        kd: n("kd", &a.kd)?,
        ks: n("ks", &a.ks)?,
        shininess: n("shininess", &a.shininess)?,
        camera: v("camera", &a.camera)?,
        position: v("position", &a.position)?,
        specular: Some(a.specular == OnOff::On),
        specular_requires_lit: Some(a.specular_requires_lit),
        global_ambient: v("global-ambient", &a.global_ambient)?,
        material: None,
    })
}
