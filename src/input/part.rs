//! The typed problem: a problem file ([`ProblemIn`]) or a calculator
//! command's one part ([`PartIn`]), its flags read into expressions, names
//! and choices (the projection, the points) and not yet evaluated; the
//! solver evaluates them at the precision asked and runs the stages.
//! The parts a problem file can ask ([`Part`]) are named here, once.

use crate::input::fields::{AngleIn, Num, Vec3In};
use crate::input::lights::{LightsFileIn, ShadeIn};
use crate::input::problem::{CameraIn, ProblemIn};
use std::fmt;

/// A part of a problem: what a problem file's `ask` names, and the first
/// name of a `solve` key (`tutor::key` re-exports it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// `view`: the camera basis, the view matrix, the eye coordinates.
    View,
    /// `project`: the points projected onto the near plane.
    Project,
    /// `window`: the viewing window's edges and size.
    Window,
    /// `viewport`: the pixels of the projected points.
    Viewport,
    /// `clip`: the outcodes, intersections and clipped segment.
    Clip,
    /// `shade`: the lighting of one point.
    Shade,
}

impl Part {
    /// Every part, in the order of the text's solution (the order solve
    /// runs them).
    pub fn all() -> Vec<Part> {
        std::iter::successors(Some(Part::View), |p| p.next()).collect()
    }

    /// The part after this one: an exhaustive match, so a new part is
    /// listed (asked, solved and read from a key) as soon as it compiles.
    fn next(self) -> Option<Part> {
        match self {
            Part::View => Some(Part::Project),
            Part::Project => Some(Part::Window),
            Part::Window => Some(Part::Viewport),
            Part::Viewport => Some(Part::Clip),
            Part::Clip => Some(Part::Shade),
            Part::Shade => None,
        }
    }

    /// Its name (in `ask`, and first in its answers' keys): the one place
    /// it is spelled.
    pub fn name(self) -> &'static str {
        match self {
            Part::View => "view",
            Part::Project => "project",
            Part::Window => "window",
            Part::Viewport => "viewport",
            Part::Clip => "clip",
            Part::Shade => "shade",
        }
    }

    /// The part of that name, if any.
    pub fn named(name: &str) -> Option<Part> {
        Part::all().into_iter().find(|p| p.name() == name)
    }
}

impl fmt::Display for Part {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A problem to solve.
#[derive(Clone, Debug)]
pub enum Problem {
    /// A calculator command: one part.
    Part(Box<PartIn>),
    /// A problem file: the parts it asks.
    File(Box<ProblemIn>),
}

/// The projection chosen: `--d`, `--cop` with `--plane`, or `--ortho`.
#[derive(Clone, Debug)]
pub enum ProjectionIn {
    /// COP at the origin, plane z = d.
    Plane(Num),
    /// COP at z = zprp, plane z = zvp.
    General(Num, Num),
    /// Orthographic.
    Ortho,
}

/// The window part: fovy, aspect, near, far, the viewport W × H and
/// points (x, y) on the window.
#[derive(Clone, Debug)]
pub struct WindowIn {
    /// fovy.
    pub fovy: AngleIn,
    /// The aspect ratio.
    pub aspect: Num,
    /// near.
    pub near: Num,
    /// far.
    pub far: Option<Num>,
    /// W × H.
    pub viewport: Option<[Num; 2]>,
    /// Named points (x, y) on the window.
    pub points: Vec<(String, [Num; 2])>,
}

/// One part with its inputs, each named by the flag it came from.
#[derive(Clone, Debug)]
pub enum PartIn {
    /// `basis`: the camera.
    Basis(CameraIn),
    /// `view`: the camera and the world points.
    View(CameraIn, Vec<(String, Vec3In)>),
    /// `project`: the projection and the eye-coordinate points.
    Project(ProjectionIn, Vec<(String, Vec3In)>),
    /// `window`.
    Window(WindowIn),
    /// `clip`: the box (min, max) and the segment (from, to).
    Clip([Vec3In; 4]),
    /// `shade`: the `[shade]` set-up, the lights file and its name.
    Shade(Box<ShadeIn>, LightsFileIn, Option<String>),
}
