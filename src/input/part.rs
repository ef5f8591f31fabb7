//! The typed problem: a problem file ([`ProblemIn`]) or a calculator
//! command's one part ([`PartIn`]), its flags read into expressions, names
//! and choices (the projection, the points) and not yet evaluated; the
//! solver evaluates them at the precision asked and runs the stages.
//! The parts a problem file can ask are [`Part`] (named once, in
//! [`crate::input::ask`]).

use crate::input::fields::{AngleIn, Num, Vec3In};
use crate::input::lights::{LightsFileIn, ShadeIn};
use crate::input::problem::{CameraIn, ProblemIn};

pub use crate::input::ask::Part;

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
