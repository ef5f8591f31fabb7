//! The calculator commands: flags → validated values → stage functions →
//! a report. No math here; that is in the stage modules.

use crate::cli::args::{CameraArgs, ClipArgs, OnOff, ProjectArgs, ShadeArgs, WindowArgs};
use crate::error::{Error, Result};
use crate::input;
use crate::input::fields::{Num, Vec3In};
use crate::input::lights::ShadeIn;
use crate::msg::Msg;
use crate::num::Expr;
use crate::num::Scalar;
use crate::stages::camera::{self, Camera};
use crate::stages::clip::ClipBox;
use crate::stages::projection::{self, Projection};
use crate::stages::trace::{Recorder, Val};
use crate::stages::window;
use crate::tutor::keys::{basis_result, clip_run, shade_run, window_result};
use crate::tutor::solution::{at, p3, Asked, CameraAt, Given, Report, ShadeAt, WindowAt};

/// The camera from its flags.
pub fn camera_from<T: Scalar>(c: &CameraArgs) -> Result<Camera<T>> {
    Ok(Camera {
        pe: input::vec3("eye", &c.eye)?,
        pr: input::vec3("look", &c.look)?,
        vup: input::vec3("up", &c.up)?,
    })
}

/// `grafika basis`.
pub fn basis<T: Scalar>(c: &CameraArgs) -> Result<Report> {
    let cam = camera_from::<T>(c)?;
    let mut rec = Recorder::new();
    let b = camera::basis(&cam, &mut rec)?;
    let given = Given::Basis(CameraAt::of(&cam));
    Ok(one_part::<T>(given, basis_result(&b), rec))
}

/// `grafika view`.
pub fn view<T: Scalar>(c: &CameraArgs, points: &[String]) -> Result<Report> {
    let cam = camera_from::<T>(c)?;
    let pts = input::points3::<T>("point", points)?;
    let mut rec = Recorder::new();
    let b = camera::basis(&cam, &mut rec)?;
    let m = camera::view_matrix(&b, &cam.pe, &mut rec)?;
    let eye: Vec<(String, Val)> = pts
        .iter()
        .map(|(n, p)| {
            Ok((
                n.clone(),
                Val::vec3(&camera::to_eye(&b, &cam.pe, n, p, &mut rec)?),
            ))
        })
        .collect::<Result<_>>()?;
    let mut result = basis_result(&b);
    result.push(("matrix".into(), Val::mat4(&m)));
    result.push(("points".into(), Val::Map(eye)));
    let world = pts.iter().map(|(n, p)| (n.clone(), p3(p))).collect();
    let given = Given::View(CameraAt::of(&cam), world);
    Ok(one_part::<T>(given, result, rec))
}

/// The report of a calculator command: one part.
fn one_part<T: Scalar>(given: Given, result: Vec<(String, Val)>, rec: Recorder) -> Report {
    Report::from_recorder::<T>(Asked::Command, vec![given], result, rec)
}

/// `grafika project`.
pub fn project<T: Scalar>(a: &ProjectArgs) -> Result<Report> {
    let proj = match (&a.d, &a.cop, &a.plane, a.ortho) {
        (Some(d), None, None, false) => Projection::Plane {
            d: input::num::<T>("d", d)?,
        },
        (None, Some(c), Some(p), false) => Projection::General {
            zprp: input::num("cop", c)?,
            zvp: input::num("plane", p)?,
        },
        (None, None, None, true) => Projection::Ortho,
        (None, Some(_), None, false) => return Err(Error::said("plane", Msg::ErrCopNeedsPlane)),
        (None, None, Some(_), false) => return Err(Error::said("cop", Msg::ErrPlaneNeedsCop)),
        _ => return Err(Error::said("d", Msg::ErrChooseProjection)),
    };
    proj.validate()?;
    let pts = input::points3::<T>("point", &a.points)?;
    let mut rec = Recorder::new();
    let mut out = Vec::new();
    for (n, p) in &pts {
        let q = projection::project(&proj, n, p, &mut rec)?;
        out.push((n.clone(), Val::vec3(&q)));
    }
    let given = Given::Project {
        projection: Given::projection(&proj),
        points: pts.iter().map(|(n, p)| (n.clone(), Val::vec3(p))).collect(),
        chained: false,
    };
    Ok(one_part::<T>(
        given,
        vec![("points".into(), Val::Map(out))],
        rec,
    ))
}

/// `grafika window`.
pub fn window<T: Scalar>(a: &WindowArgs) -> Result<Report> {
    let fovy: T = input::angle_deg("fovy", &a.fovy)?;
    let aspect: T = input::num("aspect", &a.aspect)?;
    let near: T = input::num("near", &a.near)?;
    let far: Option<T> = a.far.as_deref().map(|f| input::num("far", f)).transpose()?;
    let vp: Option<(T, T)> = a
        .viewport
        .as_deref()
        .map(|v| input::size("viewport", v))
        .transpose()?;
    let pts = input::points2::<T>("point", &a.points)?;
    if !pts.is_empty() && vp.is_none() {
        return Err(Error::said("viewport", Msg::ErrPointNeedsViewport));
    }
    if let Some(f) = &far {
        if *f <= near {
            return Err(Error::said(
                "far",
                Msg::ErrFar(near.to_f64().to_string(), f.to_f64().to_string()),
            ));
        }
    }
    let mut rec = Recorder::new();
    let w = window::window(&fovy, &aspect, &near, "near", &mut rec)?;
    let mut result = window_result(&w, "");
    if let Some(f) = &far {
        let fw = window::window(&fovy, &aspect, f, "far", &mut rec)?;
        result.extend(
            window_result(&fw, "far_")
                .into_iter()
                .filter(|(k, _)| !k.ends_with("height") && !k.ends_with("width")),
        );
    }
    if let Some((vw, vh)) = &vp {
        window::validate_viewport(vw, vh)?;
        let mut px = Vec::new();
        for (n, (x, y)) in &pts {
            let (a, b) = window::to_viewport(&w, (vw, vh), n, (x, y), &mut rec);
            px.push((n.clone(), Val::vec2(&a, &b)));
        }
        if !px.is_empty() {
            result.push(("pixels".into(), Val::Map(px)));
        }
    }
    let given = Given::Window(WindowAt {
        fovy: at(&fovy),
        aspect: at(&aspect),
        near: at(&near),
        far: far.as_ref().map(at),
        viewport: vp.as_ref().map(|(w, h)| (at(w), at(h))),
        points: pts
            .iter()
            .map(|(n, (x, y))| (n.clone(), Val::vec2(x, y)))
            .collect(),
        projected: false,
    });
    Ok(one_part::<T>(given, result, rec))
}

/// `grafika clip`.
pub fn clip<T: Scalar>(a: &ClipArgs) -> Result<Report> {
    let b = ClipBox {
        min: input::vec3::<T>("min", &a.min)?,
        max: input::vec3("max", &a.max)?,
    };
    b.validate()?;
    let (p0, p1) = (
        input::vec3::<T>("from", &a.from)?,
        input::vec3::<T>("to", &a.to)?,
    );
    let mut rec = Recorder::new();
    let result = clip_run(&b, &p0, &p1, &mut rec);
    let given = Given::clip(&b, (&p0, &p1), None);
    Ok(one_part::<T>(given, result, rec))
}

/// `grafika shade`.
pub fn shade<T: Scalar>(a: &ShadeArgs) -> Result<Report> {
    use crate::input::lights::{build, LightsFileIn};
    let sh = shade_in(a)?;
    let file = match &a.lights {
        Some(path) => LightsFileIn::read(path)?,
        None => LightsFileIn::default(),
    };
    let mut rec = Recorder::new();
    let setup = build::<T>(&sh, &file, "", "light", &mut rec)?;
    let result = shade_run(&setup, &crate::stages::lighting::Rules::default(), &mut rec);
    let lights = a.lights.as_ref().map(|p| p.display().to_string());
    let given = Given::Shade(ShadeAt::of(&setup, lights));
    Ok(one_part::<T>(given, result, rec))
}

/// The flags' expressions as a `[shade]` table.
fn shade_in(a: &ShadeArgs) -> Result<ShadeIn> {
    let v = |field: &str, s: &Option<String>| -> Result<Option<Vec3In>> {
        s.as_deref()
            .map(|t| {
                input::vec3_expr(field, t).map(|[x, y, z]: [Expr; 3]| [Num(x), Num(y), Num(z)])
            })
            .transpose()
    };
    let n = |field: &str, s: &Option<String>| -> Result<Option<Num>> {
        s.as_deref()
            .map(|t| input::expr(field, t).map(Num))
            .transpose()
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
