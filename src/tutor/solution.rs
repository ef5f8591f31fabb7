//! A worked solution as data: what was asked (a calculator command's one
//! part, a problem file, a render), what each part was given as the stages
//! took it, the named results (docs/spec.md §3's keys), the steps and the
//! warnings, and for a problem file the comparison with the printed
//! answers. `report/` writes it as text, JSON, HTML and figures; nothing
//! here is words or JSON.

use crate::input::lights::Setup;
use crate::input::problem::ProblemIn;
use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::{Precision, Scalar};
use crate::stages::camera::Camera;
use crate::stages::clip::ClipBox;
use crate::stages::projection::Projection;
use crate::stages::trace::{Recorder, Step, Val};
use crate::tutor::key::{self, Field, Key, Node, Part, Value};

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

/// Named results, in order (docs/spec.md §3's keys; a part's results
/// nest under its key in a problem file's).
pub type Tree = Vec<(String, Val)>;

/// The value of an answer key in the results, found by walking its typed
/// names: the part, the segment (an index into a clip's list of
/// segments), then the names and the light's index inside the part, then
/// the component's indices (a whole part stops at the part).
pub fn value_of<'a>(result: &'a [(String, Val)], key: &Key) -> Option<&'a Val> {
    let hops = hops(key);
    let (Hop::Name(first), rest) = hops.split_first()? else {
        return None;
    };
    let mut cur = named(result, first)?;
    for hop in rest {
        cur = match (hop, cur) {
            (Hop::Name(n), Val::Map(kv)) => named(kv, n)?,
            (Hop::Nth(i), Val::List(items)) => items.get(*i)?,
            _ => return None,
        };
    }
    Some(cur)
}

/// The value of an answer key in the results, to change it (a mistake's
/// results are the right ones with one value changed).
pub fn value_of_mut<'a>(result: &'a mut [(String, Val)], key: &Key) -> Option<&'a mut Val> {
    let hops = hops(key);
    let (Hop::Name(first), rest) = hops.split_first()? else {
        return None;
    };
    let mut cur = named_mut(result, first)?;
    for hop in rest {
        cur = match (hop, cur) {
            (Hop::Name(n), Val::Map(kv)) => named_mut(kv, n)?,
            (Hop::Nth(i), Val::List(items)) => items.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(cur)
}

/// The results of a part in a problem file's results (of one segment of
/// a clip with several: an index into its list).
pub fn part_value(result: &[(String, Val)], part: Part, segment: Option<usize>) -> Option<&Val> {
    let v = named(result, &Node::Part(part))?;
    match (segment, v) {
        (Some(i), Val::List(items)) => items.get(i),
        (Some(_), _) => None,
        (None, v) => Some(v),
    }
}

/// One step of the walk from the results to a key's value: a name in a
/// map, or an item of a list.
enum Hop {
    Name(Node),
    Nth(usize),
}

/// The walk to a key's value: its part (and segment), then what it names
/// inside; an exhaustive match, so a new kind of value is walked as soon as
/// it compiles.
fn hops(key: &Key) -> Vec<Hop> {
    let mut h = Vec::new();
    if let Some(p) = key.part {
        h.push(Hop::Name(Node::Part(p)));
        h.extend(key.segment.map(Hop::Nth));
    }
    let field = |f: Field| Hop::Name(Node::Field(f));
    let name = |n: Node| Hop::Name(n);
    match &key.value {
        Value::Whole => {}
        Value::Field(f) => h.push(field(*f)),
        Value::Point(n) => h.extend([field(Field::Points), name(Node::Point(n.clone()))]),
        Value::Pixel(n) => h.extend([field(Field::Pixels), name(Node::Point(n.clone()))]),
        Value::Plane(p) => h.extend([field(Field::Intersections), name(Node::Plane(*p))]),
        Value::Cut(p, c) => h.extend([
            field(Field::Intersections),
            name(Node::Plane(*p)),
            name(Node::Cut(*c)),
        ]),
        Value::Light(i) => h.extend([field(Field::Lights), Hop::Nth(*i)]),
        Value::Factor(i, x) => {
            h.extend([field(Field::Lights), Hop::Nth(*i), name(Node::Factor(*x))])
        }
    }
    h.extend(key.component.iter().map(|i| Hop::Nth(*i)));
    h
}

/// The value named `name` in a map of results (its spelling is `Node`'s).
fn named<'a>(kv: &'a [(String, Val)], name: &Node) -> Option<&'a Val> {
    let name = name.to_string();
    kv.iter().find(|(k, _)| *k == name).map(|(_, v)| v)
}

/// [`named`], to change it.
fn named_mut<'a>(kv: &'a mut [(String, Val)], name: &Node) -> Option<&'a mut Val> {
    let name = name.to_string();
    kv.iter_mut().find(|(k, _)| *k == name).map(|(_, v)| v)
}

/// The value of a key a file spells (a problem file's `[printed]` table):
/// read as a [`Key`] (`clip[1].status` as `clip.1.status`), found by
/// [`value_of`]; None for a name that is no key.
pub fn lookup<'a>(result: &'a [(String, Val)], key: &str) -> Option<&'a Val> {
    value_of(result, &key.parse().ok()?)
}

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
    fn segment(&self) -> Option<usize> {
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
    pub result: Vec<(String, Val)>,
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
        result: Vec<(String, Val)>,
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

    /// The results of one part: a calculator's all, a problem file's under
    /// the part's key.
    pub fn part_result(&self, g: &Given) -> &[(String, Val)] {
        match &self.asked {
            Asked::File(_) => match part_value(&self.result, g.part(), g.segment()) {
                Some(Val::Map(kv)) => kv,
                _ => &[],
            },
            _ => &self.result,
        }
    }

    /// The key of the first result that is not a finite number (NaN or ±∞,
    /// from an overflow or underflow of the floats): such a result is never
    /// printed as an answer.
    pub fn non_finite_result(&self) -> Option<String> {
        self.result
            .iter()
            .find_map(|(k, v)| first_not_finite(k, v, false))
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

#[cfg(test)]
mod tests {
    use super::*;

    fn text(s: &str) -> Val {
        Val::Text(s.to_string())
    }

    fn map(kv: &[(&str, Val)]) -> Val {
        Val::Map(kv.iter().map(|(k, v)| (k.to_string(), v.clone())).collect())
    }

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn a_typed_key_walks_to_its_value() {
        let seg = |status: &str| {
            map(&[
                ("status", text(status)),
                (
                    "intersections",
                    map(&[("left", map(&[("code", text("000000"))]))]),
                ),
            ])
        };
        let tree: Tree = vec![
            ("view".into(), map(&[("points", map(&[("A", text("a"))]))])),
            (
                "clip".into(),
                Val::List(vec![seg("accepted"), seg("clipped")]),
            ),
            (
                "shade".into(),
                map(&[(
                    "lights",
                    Val::List(vec![text("l0"), map(&[("spot", text("s1"))])]),
                )]),
            ),
            ("top".into(), text("h")),
        ];
        let at = |k: &str| value_of(&tree, &key(k)).cloned();
        assert_eq!(at("view.points.A"), Some(text("a")));
        assert_eq!(at("clip.1.status"), Some(text("clipped")));
        assert_eq!(at("clip[0].status"), Some(text("accepted")));
        assert_eq!(at("clip.0.intersections.left.code"), Some(text("000000")));
        assert_eq!(at("shade.lights.0"), Some(text("l0")));
        assert_eq!(at("shade.lights[1].spot"), Some(text("s1")));
        assert_eq!(at("top"), Some(text("h")));
        // not in the results: no segment 2, no point B, a clip of several
        // segments asked without one, a light's factor not computed
        for k in [
            "clip.2.status",
            "view.points.B",
            "clip.status",
            "shade.lights.0.spot",
            "window.top",
        ] {
            assert_eq!(at(k), None, "{k}");
        }
    }

    /// Every name and index of a shipped problem's results, spelled as a
    /// dotted key (`view.points.A.1`, `clip.0`, `view`), is a `Key`, and
    /// `value_of` walks it to that very value: an answer file can name
    /// nothing in the results that no `Key` names.
    #[test]
    fn every_place_in_the_results_is_a_key() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .expect("problems/")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        let mut n = 0;
        for f in &files {
            let p = ProblemIn::read(f).expect("a shipped problem reads");
            let tree = crate::tutor::solve::solve::<crate::num::Real>(&p)
                .expect("a shipped problem solves")
                .result;
            let mut all = Vec::new();
            let index = |at: &str, i: usize| format!("{at}.{i}");
            for (k, v) in &tree {
                v.walk(k, &index, &mut |at, x| {
                    all.push((at.to_string(), x));
                    true
                });
            }
            for (at, v) in all {
                let found = value_of(&tree, &key(&at));
                assert!(found.is_some_and(|x| std::ptr::eq(x, v)), "{at} in {f:?}");
                n += 1;
            }
        }
        assert!(n > 500, "{n}");
    }
}
