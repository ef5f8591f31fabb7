//! What each part was given, as the stages took it (numbers at the
//! precision's value): what its figure is drawn from and a calculator's
//! JSON `input` is written from.

use crate::input::lights::Setup;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera::Camera;
use crate::stages::clip::ClipBox;
use crate::stages::projection::Projection;
use crate::stages::trace::Val;
use crate::tutor::key::{self, Part};

/// A point or vector of the inputs, as the stages took it (f64 of the
/// precision's value).
pub type P3 = [f64; 3];

/// A vector at f64 (the value the precision holds).
pub fn p3<T: Scalar>(v: &V3<T>) -> P3 {
    [at(&v[0]), at(&v[1]), at(&v[2])]
}

/// The camera at precision `T` as the stages took it (Pe, Pr, Vup), at
/// f64 (the values the precision holds).
pub fn camera<T: Scalar>(c: &Camera<T>) -> Camera<f64> {
    let at = |v: &V3<T>| V3::from(p3(v));
    Camera {
        pe: at(&c.pe),
        pr: at(&c.pr),
        vup: at(&c.vup),
    }
}

/// A number at f64 (the value the precision holds).
pub fn at<T: Scalar>(x: &T) -> f64 {
    x.shown().value
}

/// The window part's inputs: fovy (degrees), aspect, near, far, the
/// viewport W × H (when the viewport is asked) and the window points.
#[derive(Clone, Debug, PartialEq)]
pub struct WindowAt {
    /// fovy in degrees.
    pub fovy: f64,
    /// The aspect ratio.
    pub aspect: f64,
    /// near.
    pub near: f64,
    /// far, when given.
    pub far: Option<f64>,
    /// The viewport W × H, when the pixels are asked.
    pub viewport: Option<(f64, f64)>,
    /// The points on the window (x, y), as the steps show them.
    pub points: Vec<(String, Val)>,
    /// Whether the points are the projection's images (a problem file:
    /// named A''), not given.
    pub projected: bool,
}

/// The lighting part's inputs: the model, the surface, the material and
/// the lights file, as the stages took them.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadeAt {
    /// The model's name (`phong`, `blinn`, …).
    pub model: &'static str,
    /// N.
    pub normal: P3,
    /// V.
    pub view: P3,
    /// The surface point.
    pub position: P3,
    /// The camera (a local viewer), if given.
    pub camera: Option<P3>,
    /// Cs (at the precision's f64).
    pub color: P3,
    /// ka, kd, ks, n.
    pub k: [f64; 4],
    /// Whether the specular term is on.
    pub specular: bool,
    /// Whether the specular term needs L·N > 0.
    pub specular_requires_lit: bool,
    /// The lights file, if any (as the user named it).
    pub lights: Option<String>,
}

impl ShadeAt {
    /// The lighting set-up at f64, with the lights file's name.
    pub fn of<T: Scalar>(s: &Setup<T>, lights: Option<String>) -> ShadeAt {
        let (m, f) = (&s.material, |x: &T| x.to_f64());
        ShadeAt {
            model: m.model.name(),
            normal: p3(&s.surface.normal),
            view: p3(&s.surface.view),
            position: p3(&s.surface.position),
            camera: s.surface.camera.as_ref().map(p3),
            color: [f(&m.color[0]), f(&m.color[1]), f(&m.color[2])],
            k: [f(&m.ka), f(&m.kd), f(&m.ks), f(&m.shininess)],
            specular: m.specular_on,
            specular_requires_lit: m.specular_requires_lit,
            lights,
        }
    }
}

/// The clipping part's inputs: the box and one segment.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipAt {
    /// (xmin, ymin, zmin).
    pub min: P3,
    /// (xmax, ymax, zmax).
    pub max: P3,
    /// P0 and P1.
    pub ends: [P3; 2],
    /// The segment's index when the problem has several.
    pub segment: Option<usize>,
}

/// What one part was given, as the stages took it (numbers at the
/// precision's value): what its figure is drawn from and a calculator's
/// JSON `input` is written from.
#[derive(Clone, Debug, PartialEq)]
pub enum Given {
    /// The camera basis.
    Basis(Camera<f64>),
    /// The view: the camera and the world points.
    View(Camera<f64>, Vec<(String, P3)>),
    /// The projection and the eye-coordinate points it projects, as the
    /// steps show them; `chained` when they come from the view part (a
    /// problem file: the figure names them A').
    Project {
        /// The projection.
        projection: Projection<f64>,
        /// The eye-coordinate points.
        points: Vec<(String, Val)>,
        /// Whether they are the view part's results.
        chained: bool,
    },
    /// The window (and the viewport).
    Window(WindowAt),
    /// Clipping one segment.
    Clip(ClipAt),
    /// Lighting one point.
    Shade(ShadeAt),
}

impl Given {
    /// The calculator command of a one-part problem.
    pub fn command(&self) -> &'static str {
        match self {
            Given::Basis(_) => "basis",
            Given::View(..) => "view",
            Given::Project { .. } => "project",
            Given::Window(_) => "window",
            Given::Clip(_) => "clip",
            Given::Shade(_) => "shade",
        }
    }

    /// The part of a problem file it is.
    pub fn part(&self) -> Part {
        match self {
            Given::Basis(_) | Given::View(..) => Part::View,
            Given::Project { .. } => Part::Project,
            Given::Window(_) => Part::Window,
            Given::Clip(_) => Part::Clip,
            Given::Shade(_) => Part::Shade,
        }
    }

    /// The part's key in a problem file's results (`view`, `clip`, or
    /// `clip.1` for the second of several segments).
    pub fn key(&self) -> String {
        key::prefix(self.part(), self.segment())
    }

    /// The segment of a clip problem with several.
    pub fn segment(&self) -> Option<usize> {
        match self {
            Given::Clip(c) => c.segment,
            _ => None,
        }
    }

    /// The part's name in figure files (`view`, `clip-2`).
    pub fn name(&self) -> String {
        match self {
            Given::Clip(ClipAt {
                segment: Some(i), ..
            }) => format!("clip-{}", i + 1),
            other => other.key(),
        }
    }

    /// The clipping of `segment` in box `b`.
    pub fn clip<T: Scalar>(
        b: &ClipBox<T>,
        ends: (&V3<T>, &V3<T>),
        segment: Option<usize>,
    ) -> Given {
        Given::Clip(ClipAt {
            min: p3(&b.min),
            max: p3(&b.max),
            ends: [p3(ends.0), p3(ends.1)],
            segment,
        })
    }

    /// The projection at f64.
    pub fn projection<T: Scalar>(p: &Projection<T>) -> Projection<f64> {
        match p {
            Projection::Plane { d } => Projection::Plane { d: at(d) },
            Projection::General { zprp, zvp } => Projection::General {
                zprp: at(zprp),
                zvp: at(zvp),
            },
            Projection::Ortho => Projection::Ortho,
        }
    }
}
