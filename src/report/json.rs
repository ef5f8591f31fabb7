//! The JSON of a report's inputs (docs/spec.md §3's `input`): a calculator
//! command's one part as the stages took it, a problem file's tables (the
//! f64 values of the numbers written; names for named segment ends), a
//! render's scene and settings, and the render's `stats`; a refusal.

use super::lang::Lang;
use super::render::StatsJson;
use super::{words, Style};
use crate::input::fields::{Num, Vec3In};
use crate::input::problem::{PointRef, ProblemIn};
use crate::msg::{Msg, Shown};
use crate::num::Precision;
use crate::stages::projection::Projection;
use crate::stages::trace::{exact_forms, Step, Val};
use crate::tutor::solution::{Asked, Compared, Given, RenderRun, Report, Results, P3};
use serde::{Serialize, Serializer};
use serde_json::{Map, Value};

/// A refusal as JSON (`--json`, docs/spec.md): `{"error": {…}}`.
#[derive(Serialize)]
pub struct Refusal<'a> {
    error: Fault<'a>,
}

/// The field at fault as it is spelled and the reason in the chosen
/// language (a refusal's, a class's file that could not be marked).
#[derive(Serialize)]
pub struct Fault<'a> {
    /// The field, as spelled.
    pub field: &'a str,
    /// The reason, in words.
    pub message: String,
}

/// A refusal as JSON (`--json`, docs/spec.md): the field at fault as it
/// is spelled and the reason in the chosen language.
pub fn error<'a>(field: &'a str, message: &str) -> Refusal<'a> {
    let message = message.to_string();
    Refusal {
        error: Fault { field, message },
    }
}

/// Named values (unique names: points, verdict words) as one JSON
/// object, in order.
pub fn as_map<S: Serializer, K: Serialize, V: Serialize>(
    kv: &[(K, V)],
    s: S,
) -> Result<S::Ok, S::Error> {
    s.collect_map(kv.iter().map(|(k, v)| (k, v)))
}

/// Named values as one JSON object, each value's numbers written by `f`
/// (a later value of a name written twice replaces the earlier one).
pub fn plain<K: ToString>(kv: &[(K, Val)], f: fn(&Val) -> Value) -> Map<String, Value> {
    kv.iter().map(|(k, v)| (k.to_string(), f(v))).collect()
}

/// The `input` object of a report: a calculator's part, a problem file,
/// a render (null when a calculator command has no part).
#[derive(Serialize)]
#[serde(untagged)]
pub enum Input<'a> {
    /// A calculator command's part.
    Part(GivenJson<'a>),
    /// A problem file's tables.
    File(Box<ProblemJson<'a>>),
    /// A render's scene and settings.
    Render(RenderInput<'a>),
    /// Nothing given.
    None,
}

/// The `input` object of a report.
pub fn input(r: &Report) -> Input<'_> {
    match &r.asked {
        Asked::Command => (r.parts.first()).map_or(Input::None, |g| Input::Part(given(g))),
        Asked::File(p) => Input::File(Box::new(problem(p))),
        Asked::Render(run) => Input::Render(render_input(run)),
    }
}

/// A camera: Pe, Pr, Vup.
#[derive(Serialize)]
pub struct CameraJson<T> {
    eye: T,
    look: T,
    up: T,
}

/// A projection's set-up: onto z = d, the general one, orthographic.
#[derive(Serialize)]
#[serde(untagged)]
pub enum ProjectionJson {
    /// Onto the plane z = d.
    Plane { d: f64 },
    /// The centre of projection's and the plane's z.
    General { cop: f64, plane: f64 },
    /// Orthographic.
    Ortho { ortho: bool },
}

/// A calculator command's part as the stages took it.
#[derive(Serialize)]
#[serde(untagged)]
pub enum GivenJson<'a> {
    /// The camera basis.
    Basis(CameraJson<P3>),
    /// The camera and the world points.
    View {
        #[serde(flatten)]
        camera: CameraJson<P3>,
        #[serde(serialize_with = "as_map")]
        points: &'a [(String, P3)],
    },
    /// The projection and the eye-coordinate points.
    Project {
        projection: ProjectionJson,
        points: Map<String, Value>,
    },
    /// The window, the viewport and the points on the window.
    Window {
        fovy: f64,
        aspect: f64,
        near: f64,
        far: Option<f64>,
        viewport: Option<(f64, f64)>,
        points: Map<String, Value>,
    },
    /// The clipping box and the segment.
    Clip { min: P3, max: P3, from: P3, to: P3 },
    /// The lighting set-up.
    Shade(ShadeJson<'a>),
}

/// The lighting part's inputs, its constants each by name.
#[derive(Serialize)]
pub struct ShadeJson<'a> {
    model: &'static str,
    normal: P3,
    view: P3,
    position: P3,
    camera: Option<P3>,
    color: P3,
    ka: f64,
    kd: f64,
    ks: f64,
    shininess: f64,
    specular: bool,
    specular_requires_lit: bool,
    lights: &'a Option<String>,
}

/// A calculator command's part.
fn given(g: &Given) -> GivenJson<'_> {
    let cam = |c: &crate::stages::camera::Camera<f64>| CameraJson {
        eye: c.pe.into(),
        look: c.pr.into(),
        up: c.vup.into(),
    };
    match g {
        Given::Basis(c) => GivenJson::Basis(cam(c)),
        Given::View(c, points) => GivenJson::View {
            camera: cam(c),
            points,
        },
        Given::Project {
            projection, points, ..
        } => GivenJson::Project {
            projection: match *projection {
                Projection::Plane { d } => ProjectionJson::Plane { d },
                Projection::General { zprp, zvp } => ProjectionJson::General {
                    cop: zprp,
                    plane: zvp,
                },
                Projection::Ortho => ProjectionJson::Ortho { ortho: true },
            },
            points: plain(points, value_json),
        },
        Given::Window(w) => GivenJson::Window {
            fovy: w.fovy,
            aspect: w.aspect,
            near: w.near,
            far: w.far,
            viewport: w.viewport,
            points: plain(&w.points, value_json),
        },
        Given::Clip(c) => GivenJson::Clip {
            min: c.min,
            max: c.max,
            from: c.ends[0],
            to: c.ends[1],
        },
        Given::Shade(s) => GivenJson::Shade(ShadeJson {
            model: s.model,
            normal: s.normal,
            view: s.view,
            position: s.position,
            camera: s.camera,
            color: s.color,
            ka: s.k[0],
            kd: s.k[1],
            ks: s.k[2],
            shininess: s.k[3],
            specular: s.specular,
            specular_requires_lit: s.specular_requires_lit,
            lights: &s.lights,
        }),
    }
}

/// A number of a problem file as JSON: its f64 value (null when it has none).
type N = Option<f64>;
/// A vector of a problem file.
type V3 = [N; 3];

/// A problem file's inputs: its f64 values of the numbers written.
#[derive(Serialize)]
pub struct ProblemJson<'a> {
    title: &'a str,
    statement: &'a Option<String>,
    source: &'a Option<String>,
    ask: Option<Vec<&'static str>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    camera: Option<CameraJson<V3>>,
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "some_map")]
    points: Option<Vec<(String, V3)>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    perspective: Option<PerspectiveJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    clip: Option<ClipJson<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    shade: Option<ShadeInJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    light: Option<Vec<LightJson>>,
}

/// `as_map` of a value that is there (a missing one is skipped).
fn some_map<S: Serializer>(kv: &Option<Vec<(String, V3)>>, s: S) -> Result<S::Ok, S::Error> {
    as_map(kv.as_deref().unwrap_or_default(), s)
}

/// A problem file's `[perspective]`.
#[derive(Serialize)]
pub struct PerspectiveJson {
    near: N,
    far: N,
    fovy: N,
    aspect: N,
    viewport: Option<[N; 2]>,
    d: N,
}

/// A segment's end: a vector, or a point's name.
#[derive(Serialize)]
#[serde(untagged)]
pub enum EndJson<'a> {
    /// Written as a vector.
    At(V3),
    /// A named point.
    Named(&'a str),
}

/// A segment to clip.
#[derive(Serialize)]
pub struct SegmentJson<'a> {
    from: EndJson<'a>,
    to: EndJson<'a>,
}

/// A problem file's `[clip]`.
#[derive(Serialize)]
pub struct ClipJson<'a> {
    min: V3,
    max: V3,
    segment: Vec<SegmentJson<'a>>,
}

/// A problem file's `[shade]`.
#[derive(Serialize)]
pub struct ShadeInJson {
    model: &'static str,
    light: Option<V3>,
    normal: Option<V3>,
    view: Option<V3>,
    color: Option<V3>,
    camera: Option<V3>,
    position: Option<V3>,
    ka: N,
    kd: N,
    ks: N,
    shininess: N,
}

/// One of a problem file's `[[light]]`s.
#[derive(Serialize)]
pub struct LightJson {
    #[serde(rename = "type")]
    kind: &'static str,
    direction: Option<V3>,
    position: Option<V3>,
    axis: Option<V3>,
}

fn n(x: &Num) -> N {
    x.0.eval::<f64>().ok()
}

fn v3(v: &Vec3In) -> V3 {
    [n(&v[0]), n(&v[1]), n(&v[2])]
}

fn ov(v: &Option<Vec3In>) -> Option<V3> {
    v.as_ref().map(v3)
}

/// A problem file's inputs as JSON numbers (f64 values of the written
/// numbers; names for named segment ends).
fn problem<'a>(p: &'a ProblemIn) -> ProblemJson<'a> {
    let pref = |r: &'a PointRef| match r {
        PointRef::At(v) => EndJson::At(v3(v)),
        PointRef::Named(name) => EndJson::Named(name),
    };
    let shade = p.shade.as_ref();
    ProblemJson {
        title: &p.title,
        statement: &p.statement,
        source: &p.source,
        ask: (p.ask.as_ref()).map(|a| a.iter().map(|x| x.name()).collect()),
        camera: (p.camera.as_ref()).map(|c| CameraJson {
            eye: v3(&c.eye),
            look: v3(&c.look),
            up: v3(&c.up),
        }),
        points: (p.points().ok()).map(|ps| ps.iter().map(|(k, v)| (k.clone(), v3(v))).collect()),
        perspective: p.perspective.as_ref().map(|per| PerspectiveJson {
            near: per.near.as_ref().and_then(n),
            far: per.far.as_ref().and_then(n),
            fovy: per.fovy.as_ref().and_then(|a| a.0.degrees::<f64>().ok()),
            aspect: per.aspect.as_ref().and_then(n),
            viewport: per.viewport.as_ref().map(|v| [n(&v[0]), n(&v[1])]),
            d: per.d.as_ref().and_then(n),
        }),
        clip: p.clip.as_ref().map(|c| ClipJson {
            min: v3(&c.min),
            max: v3(&c.max),
            segment: (c.segment.iter())
                .map(|s| SegmentJson {
                    from: pref(&s.from),
                    to: pref(&s.to),
                })
                .collect(),
        }),
        shade: shade.map(|sh| ShadeInJson {
            model: sh.model.unwrap_or_default().name(),
            light: ov(&sh.light),
            normal: ov(&sh.normal),
            view: ov(&sh.view),
            color: ov(&sh.color),
            camera: ov(&sh.camera),
            position: ov(&sh.position),
            ka: sh.ka.as_ref().and_then(n),
            kd: sh.kd.as_ref().and_then(n),
            ks: sh.ks.as_ref().and_then(n),
            shininess: sh.shininess.as_ref().and_then(n),
        }),
        light: (shade.is_some() && !p.light.is_empty()).then(|| lights(p)),
    }
}

/// A problem file's `[[light]]`s.
fn lights(p: &ProblemIn) -> Vec<LightJson> {
    (p.light.iter())
        .map(|l| LightJson {
            kind: l.kind.name(),
            direction: ov(&l.direction),
            position: ov(&l.position),
            axis: ov(&l.axis),
        })
        .collect()
}

/// A render's scene and settings.
#[derive(Serialize)]
pub struct RenderInput<'a> {
    scene: &'a str,
    output: &'a str,
    width: u32,
    height: u32,
    shading: String,
    normals: &'a str,
    explain_pixel: Option<(u32, u32)>,
}

/// A render's scene and settings.
fn render_input(run: &RenderRun) -> RenderInput<'_> {
    RenderInput {
        scene: &run.scene,
        output: &run.output,
        width: run.size.0,
        height: run.size.1,
        shading: super::render::shading_names(run),
        normals: &run.normals,
        explain_pixel: run.explain_pixel,
    }
}

/// A worked solution as JSON (docs/spec.md §3).
#[derive(Serialize)]
pub struct SolutionJson<'a> {
    command: &'static str,
    precision: Precision,
    input: Input<'a>,
    result: ResultJson<'a>,
    exact: ResultJson<'a>,
    steps: Vec<StepJson>,
    warnings: Vec<String>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    notes: Vec<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    stats: Option<StatsJson<'a>>,
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    source_notes: &'a [String],
    #[serde(skip_serializing_if = "Option::is_none")]
    comparison: Option<Vec<ComparedJson<'a>>>,
}

impl Report {
    /// The docs/spec.md §3 JSON object; only its human-readable strings (titles,
    /// notes, warnings) depend on `lang`.
    pub fn to_json(&self, lang: Lang) -> SolutionJson<'_> {
        let style = Style::new(4, true, lang);
        let (result, exact) = match &self.asked {
            Asked::Render(_) => {
                let answer = self.answer();
                let summary = |f| ResultJson::Summary(plain(&answer, f));
                (summary(value_json), summary(exact_json))
            }
            _ => (
                ResultJson::Results(&self.result),
                ResultJson::Exact(ExactJson(&self.result)),
            ),
        };
        SolutionJson {
            command: self.command(),
            precision: self.precision,
            input: input(self),
            result,
            exact,
            steps: self.steps.iter().map(|s| step_json(s, lang)).collect(),
            warnings: self.warnings.iter().map(|w| style.w(w)).collect(),
            notes: self.all_notes(&style),
            stats: match &self.asked {
                Asked::Render(run) => Some(super::render::stats_json(run)),
                _ => None,
            },
            source_notes: &self.source_notes,
            comparison: (self.comparison.as_ref())
                .map(|c| c.rows.iter().map(|r| compared_json(r, lang)).collect()),
        }
    }
}

/// §3's `result` or `exact`: the results' own serialization, or a
/// render's summary.
#[derive(Serialize)]
#[serde(untagged)]
pub enum ResultJson<'a> {
    /// The results, numbers as doubles.
    Results(&'a Results),
    /// The results, numbers as exact forms.
    Exact(ExactJson<'a>),
    /// A render's summary.
    Summary(Map<String, Value>),
}

/// The results with each number's exact form (null where it has none).
pub struct ExactJson<'a>(&'a Results);

impl Serialize for ExactJson<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        exact_forms(move || self.0.serialize(s))
    }
}

/// One compared answer as JSON (`kind`: the erratum's, a code).
#[derive(Serialize)]
pub struct ComparedJson<'a> {
    key: &'a str,
    printed: &'a str,
    computed: Option<Value>,
    agrees: Option<bool>,
    kind: Option<crate::msg::Erratum>,
    why: Option<String>,
}

/// One compared answer as JSON.
fn compared_json(r: &Compared, lang: Lang) -> ComparedJson<'_> {
    ComparedJson {
        key: &r.key,
        printed: &r.printed,
        computed: r.computed.as_ref().map(value_json),
        agrees: r.agrees,
        kind: r.kind,
        why: r.why.as_ref().map(|w| words::words(w, lang)),
    }
}

/// A value as `{"decimal": …, "exact": …}` (`check`'s `expected`, an
/// exam's answers, practice's).
#[derive(Serialize)]
pub struct Both {
    decimal: Value,
    exact: Value,
}

/// A value's plain numbers and exact forms.
pub fn both(v: &Val) -> Both {
    Both {
        decimal: value_json(v),
        exact: exact_json(v),
    }
}

/// A value with plain numbers.
pub fn value_json(v: &Val) -> Value {
    shaped(v, &|s| {
        serde_json::Number::from_f64(s.value)
            .map(Value::Number)
            .unwrap_or(Value::Null)
    })
}

/// The same shape with each number as its exact expression string (or null).
pub fn exact_json(v: &Val) -> Value {
    shaped(v, &|s| {
        s.exact.clone().map(Value::String).unwrap_or(Value::Null)
    })
}

/// A value as JSON, each number written by `num` (its double or its exact
/// form): §3's `result` and `exact` are the one shape.
fn shaped(v: &Val, num: &dyn Fn(&Shown) -> Value) -> Value {
    match v {
        Val::Num(s) => num(s),
        Val::List(items) => Value::Array(items.iter().map(|x| shaped(x, num)).collect()),
        Val::Map(kv) => Value::Object(
            kv.iter()
                .map(|(k, x)| (k.clone(), shaped(x, num)))
                .collect::<Map<_, _>>(),
        ),
        Val::Text(t) => Value::String(t.clone()),
        Val::Said(m) => Value::String(words::words(m, Lang::En)),
        Val::Bool(b) => Value::Bool(*b),
        Val::Null => Value::Null,
    }
}

/// A step's values and results with their exact forms.
#[derive(Serialize)]
pub struct StepExact {
    values: Map<String, Value>,
    result: Map<String, Value>,
}

/// A step as JSON (docs/spec.md §3).
#[derive(Serialize)]
pub struct StepJson {
    title: String,
    formula: String,
    values: Map<String, Value>,
    result: Map<String, Value>,
    exact: StepExact,
    /// The notation with the numbers written the English way, like `exact`.
    #[serde(skip_serializing_if = "Map::is_empty")]
    substituted: Map<String, Value>,
    #[serde(skip_serializing_if = "Option::is_none")]
    section: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<String>,
}

/// A step as JSON (docs/spec.md §3); its title, formula, section and note in `lang`.
pub fn step_json(s: &Step, lang: Lang) -> StepJson {
    let w = |m: &Msg| words::words(m, lang);
    let en = Style::new(4, true, Lang::En);
    StepJson {
        title: w(&s.title),
        formula: w(&s.formula),
        values: plain(&s.values, value_json),
        result: plain(&s.result, value_json),
        exact: StepExact {
            values: plain(&s.values, exact_json),
            result: plain(&s.result, exact_json),
        },
        substituted: (s.subs.iter())
            .map(|(k, x)| (k.to_string(), Value::String(en.subst(x))))
            .collect(),
        section: s.section.as_ref().map(w),
        note: s.note.as_ref().map(w),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::part::{PartIn, Problem, Shared, Table};
    use crate::input::problem::PerspectiveIn;
    use crate::input::{angle, num, size};
    use crate::tutor::solve::solve_problem;
    use serde_json::json;

    /// A calculator command's input is its one part as the stages took it:
    /// at f32, near typed `0,1` is the f32 nearest 1/10, written by the
    /// shortest decimal that reads back to it (0.1); no far is null.
    #[test]
    fn a_calculator_part_gives_its_inputs_at_the_precision() {
        let table = PerspectiveIn {
            fovy: Some(angle("fovy", "45").unwrap()),
            aspect: Some(num("aspect", "2").unwrap()),
            near: Some(num("near", "0,1").unwrap()),
            far: None,
            viewport: Some(size("viewport", "200x100").unwrap()),
            d: None,
        };
        let xy = [
            num("point A", "0").unwrap(),
            num("point A", "0,01").unwrap(),
        ];
        let shared = Shared {
            perspective: Some(Table { prefix: "", table }),
            on_window: Some(vec![("A".into(), "point A".into(), xy)]),
            ..Shared::default()
        };
        let problem = Problem::command(vec![PartIn::Window, PartIn::Viewport], shared);
        let r = solve_problem::<f32>(&problem).unwrap();
        assert_eq!(r.command(), "window");
        let want = json!({
            "fovy": 45.0, "aspect": 2.0, "near": 0.1, "far": null,
            "viewport": [200.0, 100.0], "points": { "A": [0.0, 0.01] },
        });
        assert_eq!(serde_json::to_value(input(&r)).unwrap(), want);
    }

    /// A problem file's input is its tables as written, at f64, with the
    /// title and statement: near 1/10 is 0.1 whatever the precision.
    #[test]
    fn a_problem_file_gives_its_tables() {
        let text = "title = 't'\nstatement = 's'\nask = ['window']\n\
                    [perspective]\nnear = '1/10'\nfovy = 90\naspect = 2\n";
        let p = ProblemIn::parse(text, "t.toml").unwrap();
        let r = crate::tutor::solve::solve::<f32>(&p).unwrap();
        let i = serde_json::to_value(input(&r)).unwrap();
        assert_eq!(i["title"], "t");
        assert_eq!(i["statement"], "s");
        assert_eq!(i["perspective"]["near"], json!(0.1));
        assert_eq!(i["perspective"]["fovy"], json!(90.0));
        assert_eq!(i["perspective"]["far"], Value::Null);
    }
}
