//! The calculator commands' flags read into a typed problem: one part
//! whose inputs are the flags' expressions, names and choices. The solver
//! evaluates and runs it (`tutor::part`); no math here.

use crate::cli::args::{CameraArgs, ClipArgs, Command, OnOff, ProjectArgs, ShadeArgs, WindowArgs};
use crate::error::{Error, Result};
use crate::input;
use crate::input::fields::{Num, Vec3In};
use crate::input::lights::{LightsFileIn, ShadeIn};
use crate::input::part::{PartIn, ProjectionIn, WindowIn};
use crate::input::problem::CameraIn;
use crate::msg::Msg;

/// The part a calculator command asks, if `cmd` is one.
pub fn part_of(cmd: &Command) -> Option<Result<PartIn>> {
    Some(match cmd {
        Command::Basis(c) => camera(c).map(PartIn::Basis),
        Command::View { camera: c, points } => view(c, points),
        Command::Project(a) => project(a),
        Command::Window(a) => window(a),
        Command::Clip(a) => clip(a),
        Command::Shade(a) => shade(a),
        _ => return None,
    })
}

/// `--eye --look --up`.
fn camera(c: &CameraArgs) -> Result<CameraIn> {
    Ok(CameraIn {
        eye: input::vec3("eye", &c.eye)?,
        look: input::vec3("look", &c.look)?,
        up: input::vec3("up", &c.up)?,
    })
}

/// `grafika view`.
fn view(c: &CameraArgs, points: &[String]) -> Result<PartIn> {
    Ok(PartIn::View(camera(c)?, input::points3("point", points)?))
}

/// `grafika project`: `--d`, `--cop` with `--plane`, or `--ortho`.
fn project(a: &ProjectArgs) -> Result<PartIn> {
    let proj = match (&a.d, &a.cop, &a.plane, a.ortho) {
        (Some(d), None, None, false) => ProjectionIn::Plane(input::num("d", d)?),
        (None, Some(c), Some(p), false) => {
            ProjectionIn::General(input::num("cop", c)?, input::num("plane", p)?)
        }
        (None, None, None, true) => ProjectionIn::Ortho,
        (None, Some(_), None, false) => return Err(Error::said("plane", Msg::ErrCopNeedsPlane)),
        (None, None, Some(_), false) => return Err(Error::said("cop", Msg::ErrPlaneNeedsCop)),
        _ => return Err(Error::said("d", Msg::ErrChooseProjection)),
    };
    Ok(PartIn::Project(proj, input::points3("point", &a.points)?))
}

/// `grafika window`.
fn window(a: &WindowArgs) -> Result<PartIn> {
    let w = WindowIn {
        fovy: input::angle("fovy", &a.fovy)?,
        aspect: input::num("aspect", &a.aspect)?,
        near: input::num("near", &a.near)?,
        far: a.far.as_deref().map(|f| input::num("far", f)).transpose()?,
        viewport: (a.viewport.as_deref())
            .map(|v| input::size("viewport", v))
            .transpose()?,
        points: input::points2("point", &a.points)?,
    };
    if !w.points.is_empty() && w.viewport.is_none() {
        return Err(Error::said("viewport", Msg::ErrPointNeedsViewport));
    }
    Ok(PartIn::Window(w))
}

/// `grafika clip`.
fn clip(a: &ClipArgs) -> Result<PartIn> {
    Ok(PartIn::Clip([
        input::vec3("min", &a.min)?,
        input::vec3("max", &a.max)?,
        input::vec3("from", &a.from)?,
        input::vec3("to", &a.to)?,
    ]))
}

/// `grafika shade`: the flags as a `[shade]` table, and the lights file.
fn shade(a: &ShadeArgs) -> Result<PartIn> {
    let sh = shade_in(a)?;
    let file = match &a.lights {
        Some(path) => LightsFileIn::read(path)?,
        None => LightsFileIn::default(),
    };
    let name = a.lights.as_ref().map(|p| p.display().to_string());
    Ok(PartIn::Shade(Box::new(sh), file, name))
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
