//! The typed problem: the parts asked, each with its inputs, whether they
//! come from a calculator command's flags (one part, `cli/calc.rs`) or
//! from a problem file's tables ([`Problem::of_file`]). Inputs are
//! expressions, names and choices, not yet evaluated, each named by the
//! field its errors name (`eye` for a flag, `camera.eye` in a file); an
//! input is either given or taken from an earlier part (the view's eye
//! coordinates, the projected points). The solver (`tutor::solve`)
//! evaluates them at the precision asked and runs the stages. The parts a
//! problem file can ask are [`Part`] (named once, in [`crate::input::ask`]).

use crate::error::Result;
use crate::input::fields::{Num, Vec3In};
use crate::input::lights::{LightsFileIn, ShadeIn};
use crate::input::problem::{CameraIn, PerspectiveIn, PointRef, ProblemIn};

pub use crate::input::ask::Part;

/// A problem to solve: the parts asked, in the order they are solved; the
/// inputs they share; and, for a problem file, the file itself (its
/// title, printed answers, errata and source notes).
#[derive(Clone, Debug)]
pub struct Problem {
    /// The parts asked, in [`Part::all`]'s order.
    pub parts: Vec<PartIn>,
    /// The inputs the parts share.
    pub shared: Shared,
    /// The problem file; `None`: a calculator command (one part, its
    /// results unnested, no section headers).
    pub file: Option<Box<ProblemIn>>,
}

/// A table of inputs whose fields are named under `prefix` (`camera.` in a
/// problem file, nothing for a command's flags: `camera.eye`, `eye`).
#[derive(Clone, Debug)]
pub struct Table<X> {
    /// What a field's name starts with.
    pub prefix: &'static str,
    /// The inputs.
    pub table: X,
}

impl<X> Table<X> {
    /// The field `name` of this table (`camera.eye`).
    pub fn field(&self, name: &str) -> String {
        format!("{}{name}", self.prefix)
    }
}

/// A point's name, the field its errors name (`points.A`, `point A`) and
/// its coordinates.
pub type PointIn = (String, String, Vec3In);

/// The inputs that several parts take (the view, the projection, the
/// window and the viewport of a problem file all stand on the camera, the
/// points and the perspective).
#[derive(Clone, Debug, Default)]
pub struct Shared {
    /// The points (world coordinates for the view; a `project` command's
    /// are eye coordinates), in the order given.
    pub points: Vec<PointIn>,
    /// The camera.
    pub camera: Option<Table<CameraIn>>,
    /// The perspective set-up (near, far, fovy, aspect, viewport, d).
    pub perspective: Option<Table<PerspectiveIn>>,
    /// The points (x, y) on the window, each with its field, when given
    /// (a `window` command's `--point`); `None`: the projected points.
    pub on_window: Option<Vec<(String, String, [Num; 2])>>,
}

/// The projection a `project` part uses.
#[derive(Clone, Debug)]
pub enum ProjectIn {
    /// Given with the points' eye coordinates (the shared points).
    Given(ProjectionIn),
    /// Taken from earlier parts: the view's eye coordinates projected onto
    /// the perspective's plane z = d (d = −near unless given).
    Chained,
}

/// A projection given, each number with its field: `--d`, `--cop` with
/// `--plane`, or `--ortho`.
#[derive(Clone, Debug)]
pub enum ProjectionIn {
    /// COP at the origin, plane z = d.
    Plane((String, Num)),
    /// COP at z = zprp, plane z = zvp.
    General((String, Num), (String, Num)),
    /// Orthographic.
    Ortho,
}

/// A segment to clip: its two ends, each with its field.
pub type SegmentIn = [(String, PointRef); 2];

/// The clip part's own inputs: the box (min, max) and the segments.
#[derive(Clone, Debug)]
pub struct ClipIn {
    /// (min, max), named under its prefix.
    pub bounds: Table<[Vec3In; 2]>,
    /// The segments, in order.
    pub segments: Vec<SegmentIn>,
}

/// The shade part's own inputs.
#[derive(Clone, Debug)]
pub struct ShadePartIn {
    /// The `[shade]` set-up, its fields under the prefix (`shade.`).
    pub shade: Table<ShadeIn>,
    /// The lights (a lights file, or a problem file's `[[light]]`).
    pub lights: LightsFileIn,
    /// The lights file's name, when one was read.
    pub file: Option<String>,
}

/// One part with its own inputs (what it shares with other parts is in
/// [`Shared`]).
#[derive(Clone, Debug)]
pub enum PartIn {
    /// The camera basis (a `basis` command).
    Basis,
    /// The basis, the view matrix and the eye coordinates of the points.
    View,
    /// The points projected.
    Project(ProjectIn),
    /// The window on the near plane (and the far one).
    Window,
    /// The pixels of the points on the window.
    Viewport,
    /// The clipping of segments against a box.
    Clip(ClipIn),
    /// The lighting of a point.
    Shade(Box<ShadePartIn>),
}

impl PartIn {
    /// The part of a problem it is (its results' key in a problem file).
    pub fn part(&self) -> Part {
        match self {
            PartIn::Basis | PartIn::View => Part::View,
            PartIn::Project(_) => Part::Project,
            PartIn::Window => Part::Window,
            PartIn::Viewport => Part::Viewport,
            PartIn::Clip(_) => Part::Clip,
            PartIn::Shade(_) => Part::Shade,
        }
    }
}

impl PartIn {
    /// Whether it takes the projected points (worked from the view's eye
    /// coordinates by earlier steps).
    pub fn takes_projected(&self, shared: &Shared) -> bool {
        match self {
            PartIn::Project(ProjectIn::Chained) => true,
            PartIn::Project(ProjectIn::Given(_)) => false,
            PartIn::Viewport => shared.on_window.is_none(),
            PartIn::Basis | PartIn::View | PartIn::Window | PartIn::Clip(_) | PartIn::Shade(_) => {
                false
            }
        }
    }
}

impl Problem {
    /// A calculator command's one part (or, for `window` with a viewport,
    /// the window and the viewport parts), on the inputs `shared`.
    pub fn command(parts: Vec<PartIn>, shared: Shared) -> Problem {
        Problem {
            parts,
            shared,
            file: None,
        }
    }

    /// A problem file as the typed problem: the parts it asks (all, when
    /// `ask` is absent) in [`Part::all`]'s order, each taking its inputs
    /// from the file's tables and earlier parts; a clip or shade asked
    /// without its table is left out, as is any part whose tables are
    /// missing when the solver comes to it.
    pub fn of_file(p: ProblemIn) -> Result<Problem> {
        let points = (p.points()?.into_iter())
            .map(|(n, v)| (n.clone(), format!("points.{n}"), v))
            .collect();
        let shared = Shared {
            points,
            camera: (p.camera.clone()).map(|table| Table {
                prefix: "camera.",
                table,
            }),
            perspective: (p.perspective.clone()).map(|table| Table {
                prefix: "perspective.",
                table,
            }),
            on_window: None,
        };
        let parts = (Part::all().into_iter())
            .filter(|part| p.asks(*part))
            .filter_map(|part| part_of_file(&p, part))
            .collect();
        Ok(Problem {
            parts,
            shared,
            file: Some(Box::new(p)),
        })
    }

    /// Whether a part is asked.
    pub fn asks(&self, part: Part) -> bool {
        self.parts.iter().any(|p| p.part() == part)
    }

    /// Whether the parts are asked by name (a problem file's `ask`, or a
    /// command): a part whose tables are missing is then refused, not
    /// left out.
    pub fn by_name(&self) -> bool {
        self.file.as_ref().is_none_or(|f| f.ask.is_some())
    }
}

/// The part `part` of problem file `p`, with its inputs, if its table is there.
fn part_of_file(p: &ProblemIn, part: Part) -> Option<PartIn> {
    Some(match part {
        Part::View => PartIn::View,
        Part::Project => PartIn::Project(ProjectIn::Chained),
        Part::Window => PartIn::Window,
        Part::Viewport => PartIn::Viewport,
        Part::Clip => {
            let c = p.clip.as_ref()?;
            let segments = (c.segment.iter().enumerate())
                .map(|(i, s)| {
                    let f = format!("clip.segment[{i}]");
                    [
                        (format!("{f}.from"), s.from.clone()),
                        (format!("{f}.to"), s.to.clone()),
                    ]
                })
                .collect();
            PartIn::Clip(ClipIn {
                bounds: Table {
                    prefix: "clip.",
                    table: [c.min.clone(), c.max.clone()],
                },
                segments,
            })
        }
        Part::Shade => PartIn::Shade(Box::new(ShadePartIn {
            shade: Table {
                prefix: "shade.",
                table: p.shade.clone()?,
            },
            lights: LightsFileIn {
                global_ambient: p.global_ambient.clone(),
                material: None,
                light: p.light.clone(),
            },
            file: None,
        })),
    })
}
