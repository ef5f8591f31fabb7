//! A worked solution as data: what was asked (a calculator command's one
//! part, a problem file, a render), what each part was given as the stages
//! took it, the named results (docs/spec.md §3's keys), the steps and the
//! warnings, and for a problem file the comparison with the printed
//! answers. `report/` writes it as text, JSON, HTML and figures; nothing
//! here is words or JSON.

use crate::input::problem::ProblemIn;
use crate::msg::Msg;
use crate::num::{Precision, Scalar};
use crate::stages::trace::{Recorder, Step, Val};
pub use crate::tutor::given::{at, camera, p3, ClipAt, Given, ShadeAt, WindowAt, P3};
use crate::tutor::key::Field;
pub use crate::tutor::parts::result::{One, PartResult, Results};

/// What was asked.
#[derive(Clone, Debug)]
pub enum Asked {
    /// A calculator command (`basis`, `view`, …): one part, the report's
    /// only [`Given`].
    Command,
    /// A problem file (`solve`), its parts in the report's [`Given`]s.
    File(Box<ProblemIn>),
    /// A rendered scene.
    Render(Box<RenderRun>),
}

/// A render: the scene, the image, the settings, and the counters and
/// median times of the frames.
#[derive(Clone, Debug)]
pub struct RenderRun {
    /// The scene file, as named.
    pub scene: String,
    /// The PNG, as named.
    pub output: String,
    /// The image size.
    pub size: (u32, u32),
    /// The shadings drawn, each once, in object order (`flat, gouraud`).
    pub shadings: Vec<crate::input::scene::Shading>,
    /// The vertex normals (`average`, `position`).
    pub normals: String,
    /// The pixel explained, if any.
    pub explain_pixel: Option<(u32, u32)>,
    /// `--stats`.
    pub stats_asked: bool,
    /// The last frame's counters.
    pub stats: crate::render::Stats,
    /// The median times, in milliseconds.
    pub times: Times,
    /// Mpixels per second of the median frame.
    pub mpixels_per_s: f64,
}

/// The median times of a frame's stages, in milliseconds, over `runs` runs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Times {
    /// How many frames were rendered (`--repeat`).
    pub runs: usize,
    /// Transforms, culling, clipping, set-up.
    pub geometry: f64,
    /// Gathering the triangles of each band.
    pub binning: f64,
    /// The band pass (raster and shading, in parallel).
    pub bands: f64,
    /// Thread time: raster.
    pub raster: f64,
    /// Thread time: shading.
    pub shading: f64,
    /// The whole frame.
    pub frame: f64,
    /// PNG encoding.
    pub png: f64,
}

/// Everything a command produced.
#[derive(Clone, Debug)]
pub struct Report {
    /// What was asked.
    pub asked: Asked,
    /// What each part was given, in the order of the parts.
    pub parts: Vec<Given>,
    /// The named results.
    pub result: Results,
    /// The worked steps.
    pub steps: Vec<Step>,
    /// Warnings (also on stderr).
    pub warnings: Vec<Msg>,
    /// The precision used.
    pub precision: Precision,
    /// The answers printed in the source, compared with the results (`solve`).
    pub comparison: Option<Comparison>,
    /// Notes on the source (`solve`: the problem file's `source_notes`).
    pub source_notes: Vec<String>,
}

/// The answers a source printed, compared with the computed ones.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The source, as the problem file names it.
    pub source: Option<String>,
    /// One row per printed answer, in the file's order.
    pub rows: Vec<Compared>,
}

/// One printed answer against the computed value.
#[derive(Clone, Debug, PartialEq)]
pub struct Compared {
    /// The result key (`project.points.B`).
    pub key: String,
    /// The printed value, as the source wrote it.
    pub printed: String,
    /// The computed value (`None`: not computed in this run).
    pub computed: Option<Val>,
    /// Whether they agree (`None`: not comparable, or not computed).
    pub agrees: Option<bool>,
    /// What kind of difference it is, where the problem file says.
    pub kind: Option<crate::msg::Erratum>,
    /// Why the source differs, where the problem file says.
    pub why: Option<crate::msg::Msg>,
}

/// The key (`window.pixels.A`) of the first number under `v` that is NaN
/// or infinite, if any; with `exact_ok`, a value with an exact form
/// passes even beyond the doubles.
fn first_not_finite(key: &str, v: &Val, exact_ok: bool) -> Option<String> {
    match v {
        Val::Num(n) if !(n.value.is_finite() || exact_ok && n.pretty.is_some()) => {
            Some(key.to_string())
        }
        Val::List(items) => items
            .iter()
            .find_map(|x| first_not_finite(key, x, exact_ok)),
        Val::Map(m) => m
            .iter()
            .find_map(|(k, x)| first_not_finite(&format!("{key}.{k}"), x, exact_ok)),
        _ => None,
    }
}

impl Report {
    /// The report of a finished recorder: what was asked, what each part
    /// was given, the named results, its steps and warnings, at the
    /// precision `T` ran.
    pub fn from_recorder<T: Scalar>(
        asked: Asked,
        parts: Vec<Given>,
        result: Results,
        rec: Recorder,
    ) -> Report {
        Report {
            asked,
            parts,
            result,
            steps: rec.steps,
            warnings: rec.warnings,
            precision: T::PRECISION,
            comparison: None,
            source_notes: vec![],
        }
    }

    /// The command that ran (docs/spec.md §3's `command`).
    pub fn command(&self) -> &'static str {
        match &self.asked {
            Asked::Command => self.parts.first().map_or("", Given::command),
            Asked::File(_) => "solve",
            Asked::Render(_) => "render",
        }
    }

    /// The problem's title, for a problem file.
    pub fn title(&self) -> Option<&str> {
        match &self.asked {
            Asked::File(p) => Some(p.title.as_str()),
            _ => None,
        }
    }

    /// The results of the part `g` was given to (of its segment, of a
    /// clip with several).
    pub fn part_result(&self, g: &Given) -> Option<One<'_>> {
        self.result.of(g.part())?.one(g.segment())
    }

    /// The key of the first result that is not a finite number (NaN or ±∞,
    /// from an overflow or underflow of the floats): such a result is never
    /// printed as an answer.
    pub fn non_finite_result(&self) -> Option<String> {
        let r = &self.result;
        r.parts.iter().find_map(|p| {
            let at = |f: Field| match r.nested {
                true => format!("{}.{}", p.part().key(), f.key()),
                false => f.key(),
            };
            (p.segments().into_iter())
                .flat_map(|(_, o)| o.entries())
                .find_map(|(f, v)| first_not_finite(&at(f), v, false))
        })
    }

    /// The name of the first value shown in a step that is not a finite
    /// number and not exact either (an exact value beyond the doubles is
    /// shown by its exact form): NaN or ±∞ from the floats.
    pub fn non_finite_step_value(&self) -> Option<String> {
        self.steps
            .iter()
            .flat_map(|s| s.values.iter().chain(&s.result))
            .find_map(|(k, v)| first_not_finite(&k.to_string(), v, true))
    }
}
