//! One module per part of a problem, each holding what the part is: its
//! solve (its own inputs evaluated, the stages run through the functions
//! of its module, its results and what it was given written), the order
//! of its answer keys and the topic they practise, behind one trait,
//! [`Solves`]. What the parts share is here:
//! the [`Solver`] they write through ([`Out`]), what earlier stages
//! produced, each worked once when a part first needs it ([`Earlier`]),
//! and the list of parts: the one match from a typed part ([`PartIn`]) to
//! its solve (`Solver::part`) and the one from a part ([`Part`]) to its
//! definition ([`of`]). A new part is a module here, an arm in each of
//! the two, and its words.

pub mod clip;
pub mod fields;
pub mod project;
pub mod result;
pub mod shade;
pub mod view;
pub mod viewport;
pub mod window;

use crate::error::Result;
use crate::input::eval;
use crate::input::part::{PartIn, Problem};
use crate::msg::Msg;
use crate::num::Scalar;
use crate::stages::camera::{Basis, Camera};
use crate::stages::projection::Projection;
use crate::stages::trace::{Recorder, Val};
use crate::tutor::key::{Key, Part, Value};
use crate::tutor::run::{Hooks, Named};
use crate::tutor::solution::{Given, WindowAt};
use crate::tutor::topic::Topic;
use clip::ClipPart;
use fields::Fields;
use nalgebra::Matrix4;
use project::ProjectPart;
use result::{PartResult, Results};
use shade::ShadePart;
use view::{Extent, ViewPart};
use viewport::ViewportPart;
use window::WindowPart;

/// A part of a problem, as its module defines it: how it is solved from
/// its own inputs and what earlier parts produced, and how its answers
/// are asked (their order, their topic).
pub(crate) trait Solves {
    /// The part it is: its results' key, its name in `ask`.
    const PART: Part;
    /// Its own inputs (its [`PartIn`] variant's; the inputs it shares with
    /// other parts are the problem's `shared`).
    type In;
    /// Solves it: evaluates its inputs, takes what it needs of earlier
    /// parts from [`Earlier`] (`based`, `viewed`, `near`, `projected`,
    /// `windowed`: each worked once, when first needed), runs its stage
    /// and writes its results (`Solver::put`) and what it was given.
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, input: &Self::In) -> Result<()>;
    /// Its results (of a clip: one segment's).
    type Result: Fields;
    /// Its answer keys in the order of the text's solution, from its
    /// results `r` (the order practice asks and check follows through).
    fn keys(r: &Self::Result) -> Vec<Key>;
    /// The topic a value of its results practises.
    fn topic(value: &Value) -> Topic;
}

/// A part's definition, as functions: what the tutor asks of a part
/// whatever its inputs.
#[derive(Clone, Copy)]
pub(crate) struct Def {
    /// [`Solves::topic`].
    pub topic: fn(&Value) -> Topic,
}

/// The definition of part `P`.
fn def<P: Solves>() -> Def {
    Def { topic: P::topic }
}

/// The list of parts: each part's definition. An exhaustive match, so a
/// new part stops the build here.
pub(crate) fn of(part: Part) -> Def {
    match part {
        Part::View => def::<ViewPart>(),
        Part::Project => def::<ProjectPart>(),
        Part::Window => def::<WindowPart>(),
        Part::Viewport => def::<ViewportPart>(),
        Part::Clip => def::<ClipPart>(),
        Part::Shade => def::<ShadePart>(),
    }
}

/// Where the parts write: the steps, the named results, what each part
/// was given; whether section headers are written (a problem file's).
#[derive(Default)]
pub(crate) struct Out {
    pub(crate) rec: Recorder,
    pub(crate) result: Results,
    pub(crate) parts: Vec<Given>,
    pub(crate) sections: bool,
}

impl Out {
    /// A section header, for a problem file.
    pub(crate) fn section(&mut self, m: Msg) {
        if self.sections {
            self.rec.section(m);
        }
    }
}

/// What the stages produced for the parts after them, each worked (its
/// steps written) once, when a part first needs it; `None`: not yet.
pub(crate) struct Earlier<T> {
    /// The shared points, in order (read for every problem).
    pub(crate) points: Vec<Named<T>>,
    /// The camera and its basis (inside, `None`: no camera).
    pub(crate) based: Option<Option<(Camera<T>, Basis<T>)>>,
    /// The camera's view (inside, `None`: no camera to view with).
    pub(crate) viewed: Option<Option<Viewed<T>>>,
    /// near, when given.
    pub(crate) near: Option<Option<T>>,
    /// The projection and the projected points (inside, `None`: no eye
    /// points to project).
    pub(crate) projected: Option<Option<Projected<T>>>,
    /// The window (inside, `None`: the perspective does not set one up).
    pub(crate) window: Option<Option<Windowed<T>>>,
}

/// Steps 1 and 2 done: the camera, its basis, the view matrix, the eye
/// coordinates of the points.
#[derive(Clone)]
pub(crate) struct Viewed<T> {
    pub(crate) cam: Camera<T>,
    pub(crate) basis: Basis<T>,
    pub(crate) matrix: Matrix4<T>,
    pub(crate) eye: Vec<Named<T>>,
}

/// Step 3 done: the projection and the projected points.
pub(crate) type Projected<T> = (Projection<T>, Vec<Named<T>>);

/// Step 4 done: the window, its result keys, what it was given, and the
/// points given on it (a `window` command's), evaluated.
#[derive(Clone)]
pub(crate) struct Windowed<T> {
    pub(crate) w: crate::stages::window::Window<T>,
    pub(crate) result: window::WindowResult,
    pub(crate) given: WindowAt,
    pub(crate) on_window: Option<Vec<(String, (T, T))>>,
}

/// A problem being solved: the problem, the hooks, what is written and
/// what earlier stages produced.
pub(crate) struct Solver<'a, 'h, T> {
    pub(crate) p: &'a Problem,
    pub(crate) hooks: &'a Hooks<'h, T>,
    pub(crate) out: Out,
    pub(crate) earlier: Earlier<T>,
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// One part, by the one exhaustive match over the typed part: the
    /// list of parts' solves.
    pub(crate) fn part(&mut self, part: &PartIn) -> Result<()> {
        match part {
            PartIn::Basis => ViewPart::solve(self, &Extent::Basis),
            PartIn::View => ViewPart::solve(self, &Extent::Whole),
            PartIn::Project(how) => ProjectPart::solve(self, how),
            PartIn::Window => WindowPart::solve(self, &()),
            PartIn::Viewport => ViewportPart::solve(self, &()),
            PartIn::Clip(c) => ClipPart::solve(self, c),
            PartIn::Shade(s) => ShadePart::solve(self, s),
        }
    }

    /// A part's results, after the parts solved before it.
    pub(crate) fn put(&mut self, r: impl Into<PartResult>) {
        self.out.result.parts.push(r.into());
    }

    /// Whether a part asked takes the projected points (a problem file's
    /// project or viewport).
    pub(crate) fn projects(&self) -> bool {
        let shared = &self.p.shared;
        self.p.parts.iter().any(|t| t.takes_projected(shared))
    }

    /// near, when given (read once).
    pub(crate) fn near(&mut self) -> Result<Option<T>> {
        if let Some(near) = &self.earlier.near {
            return Ok(near.clone());
        }
        let near = (self.p.shared.perspective.as_ref())
            .and_then(|x| x.table.near.as_ref().map(|n| eval(&x.field("near"), n)))
            .transpose()?;
        self.earlier.near = Some(near.clone());
        Ok(near)
    }
}

/// The names of a map of results (a part's points, its pixels), in order.
pub(crate) fn names(v: Option<&Val>) -> impl Iterator<Item = String> + '_ {
    let map = match v {
        Some(Val::Map(m)) => &m[..],
        _ => &[],
    };
    map.iter().map(|(n, _)| n.clone())
}
