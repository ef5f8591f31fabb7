//! The JSON of a report's inputs (docs/spec.md §3's `input`): a calculator
//! command's one part as the stages took it, a problem file's tables (the
//! f64 values of the numbers written; names for named segment ends), a
//! render's scene and settings, and the render's `stats`; a refusal.

use super::lang::Lang;
use super::{words, Style};
use crate::input::fields::{Num, Vec3In};
use crate::input::problem::{PointRef, ProblemIn};
use crate::msg::{Msg, Shown};
use crate::stages::projection::Projection;
use crate::stages::trace::{Name, Step, Val};
use crate::tutor::solution::{Asked, Compared, Given, RenderRun, Report, P3};
use serde_json::{json, Map, Value};

/// A refusal as JSON (`--json`, docs/spec.md): the field at fault as it
/// is spelled and the reason in the chosen language.
pub fn error(field: &str, message: &str) -> Value {
    json!({ "error": { "field": field, "message": message } })
}

/// The `input` object of a report.
pub fn input(r: &Report) -> Value {
    match &r.asked {
        Asked::Command => r.parts.first().map(given).unwrap_or(Value::Null),
        Asked::File(p) => problem(p),
        Asked::Render(run) => render_input(run),
    }
}

/// Named points as an object.
fn named(points: &[(String, P3)]) -> Value {
    Value::Object(points.iter().map(|(n, p)| (n.clone(), json!(p))).collect())
}

/// A calculator command's part.
fn given(g: &Given) -> Value {
    let cam = |c: &crate::stages::camera::Camera<f64>| {
        let [eye, look, up]: [P3; 3] = [c.pe.into(), c.pr.into(), c.vup.into()];
        json!({ "eye": eye, "look": look, "up": up })
    };
    match g {
        Given::Basis(c) => cam(c),
        Given::View(c, points) => {
            let mut o = cam(c);
            o["points"] = named(points);
            o
        }
        Given::Project {
            projection, points, ..
        } => {
            let kind = match projection {
                Projection::Plane { d } => json!({ "d": d }),
                Projection::General { zprp, zvp } => json!({ "cop": zprp, "plane": zvp }),
                Projection::Ortho => json!({ "ortho": true }),
            };
            let pts: Map<String, Value> = points
                .iter()
                .map(|(n, v)| (n.clone(), value_json(v)))
                .collect();
            json!({ "projection": kind, "points": pts })
        }
        Given::Window(w) => {
            let pts: Map<String, Value> = w
                .points
                .iter()
                .map(|(n, v)| (n.clone(), value_json(v)))
                .collect();
            json!({
                "fovy": w.fovy, "aspect": w.aspect, "near": w.near, "far": w.far,
                "viewport": w.viewport.map(|(a, b)| [a, b]), "points": pts,
            })
        }
        Given::Clip(c) => {
            json!({ "min": c.min, "max": c.max, "from": c.ends[0], "to": c.ends[1] })
        }
        Given::Shade(s) => json!({
            "model": s.model, "normal": s.normal, "view": s.view, "position": s.position,
            "camera": s.camera, "color": s.color,
            "ka": s.k[0], "kd": s.k[1], "ks": s.k[2], "shininess": s.k[3],
            "specular": s.specular, "specular_requires_lit": s.specular_requires_lit,
            "lights": s.lights,
        }),
    }
}

/// A problem file's inputs as JSON numbers (f64 values of the written
/// numbers; names for named segment ends).
fn problem(p: &ProblemIn) -> Value {
    let n = |x: &Num| x.0.eval::<f64>().map(|v| json!(v)).unwrap_or(Value::Null);
    let v3 = |v: &Vec3In| json!([n(&v[0]), n(&v[1]), n(&v[2])]);
    let pref = |r: &PointRef| match r {
        PointRef::At(v) => v3(v),
        PointRef::Named(name) => json!(name),
    };
    let ask: Option<Vec<&str>> = (p.ask.as_ref()).map(|a| a.iter().map(|x| x.name()).collect());
    let mut o = json!({
        "title": p.title, "statement": p.statement, "source": p.source, "ask": ask,
    });
    if let Some(c) = &p.camera {
        o["camera"] = json!({ "eye": v3(&c.eye), "look": v3(&c.look), "up": v3(&c.up) });
    }
    if let Ok(points) = p.points() {
        o["points"] = Value::Object(points.iter().map(|(k, v)| (k.clone(), v3(v))).collect());
    }
    if let Some(per) = &p.perspective {
        o["perspective"] = json!({
            "near": per.near.as_ref().map(n),
            "far": per.far.as_ref().map(n),
            "fovy": per.fovy.as_ref().and_then(|a| a.0.degrees::<f64>().ok()),
            "aspect": per.aspect.as_ref().map(n),
            "viewport": per.viewport.as_ref().map(|v| json!([n(&v[0]), n(&v[1])])),
            "d": per.d.as_ref().map(n),
        });
    }
    if let Some(c) = &p.clip {
        let segs: Vec<Value> = c
            .segment
            .iter()
            .map(|s| json!({ "from": pref(&s.from), "to": pref(&s.to) }))
            .collect();
        o["clip"] = json!({ "min": v3(&c.min), "max": v3(&c.max), "segment": segs });
    }
    if let Some(sh) = &p.shade {
        let ov = |v: &Option<Vec3In>| v.as_ref().map(v3);
        o["shade"] = json!({
            "model": sh.model.unwrap_or_default().name(),
            "light": ov(&sh.light), "normal": ov(&sh.normal), "view": ov(&sh.view),
            "color": ov(&sh.color), "camera": ov(&sh.camera), "position": ov(&sh.position),
            "ka": sh.ka.as_ref().map(n), "kd": sh.kd.as_ref().map(n),
            "ks": sh.ks.as_ref().map(n), "shininess": sh.shininess.as_ref().map(n),
        });
        if !p.light.is_empty() {
            o["light"] =
                json!(p.light.iter().map(|l| json!({
                "type": l.kind.name(),
                "direction": ov(&l.direction), "position": ov(&l.position), "axis": ov(&l.axis),
            })).collect::<Vec<_>>());
        }
    }
    o
}

/// A render's scene and settings.
fn render_input(run: &RenderRun) -> Value {
    json!({
        "scene": run.scene, "output": run.output,
        "width": run.size.0, "height": run.size.1, "shading": super::render::shading_names(run),
        "normals": run.normals,
        "explain_pixel": run.explain_pixel.map(|(x, y)| [x, y]),
    })
}

impl Report {
    /// The docs/spec.md §3 JSON object; only its human-readable strings (titles,
    /// notes, warnings) depend on `lang`.
    pub fn to_json(&self, lang: Lang) -> Value {
        let style = Style::new(4, true, lang);
        let answer = self.answer();
        let result = Value::Object(
            answer
                .iter()
                .map(|(k, v)| (k.clone(), value_json(v)))
                .collect(),
        );
        let exact = Value::Object(
            answer
                .iter()
                .map(|(k, v)| (k.clone(), exact_json(v)))
                .collect(),
        );
        let steps: Vec<Value> = self.steps.iter().map(|s| step_json(s, lang)).collect();
        let warnings: Vec<String> = self.warnings.iter().map(|w| style.w(w)).collect();
        let mut obj = json!({
            "command": self.command(),
            "precision": self.precision,
            "input": input(self),
            "result": result,
            "exact": exact,
            "steps": steps,
            "warnings": warnings,
        });
        let notes = self.all_notes(&style);
        if !notes.is_empty() {
            obj["notes"] = json!(notes);
        }
        if let Asked::Render(run) = &self.asked {
            obj["stats"] = super::render::stats_json(run);
        }
        if !self.source_notes.is_empty() {
            obj["source_notes"] = json!(self.source_notes);
        }
        if let Some(c) = &self.comparison {
            obj["comparison"] = c.rows.iter().map(|r| compared_json(r, lang)).collect();
        }
        obj
    }
}

/// One compared answer as JSON (`kind`: the erratum's, a code).
fn compared_json(r: &Compared, lang: Lang) -> Value {
    json!({
        "key": r.key,
        "printed": r.printed,
        "computed": r.computed.as_ref().map(value_json),
        "agrees": r.agrees,
        "kind": r.kind,
        "why": r.why.as_ref().map(|w| crate::report::words::words(w, lang)),
    })
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

/// A step as JSON (docs/spec.md §3); its title, formula, section and note in `lang`.
pub fn step_json(s: &Step, lang: Lang) -> Value {
    let w = |m: &Msg| words::words(m, lang);
    let obj = |kv: &[(Name, Val)], f: fn(&Val) -> Value| {
        Value::Object(kv.iter().map(|(k, v)| (k.to_string(), f(v))).collect())
    };
    let mut o = json!({
        "title": w(&s.title),
        "formula": w(&s.formula),
        "values": obj(&s.values, value_json),
        "result": obj(&s.result, value_json),
        "exact": { "values": obj(&s.values, exact_json), "result": obj(&s.result, exact_json) },
    });
    if !s.subs.is_empty() {
        // notation with the numbers written the English way, like `exact`
        let en = Style::new(4, true, Lang::En);
        let subs = s
            .subs
            .iter()
            .map(|(k, x)| (k.to_string(), json!(en.subst(x))));
        o["substituted"] = Value::Object(subs.collect());
    }
    if let Some(sec) = &s.section {
        o["section"] = json!(w(sec));
    }
    if let Some(n) = &s.note {
        o["note"] = json!(w(n));
    }
    o
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::part::{PartIn, Problem, Shared, Table};
    use crate::input::problem::PerspectiveIn;
    use crate::input::{angle, num, size};
    use crate::tutor::solve::solve_problem;

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
        assert_eq!(input(&r), want);
    }

    /// A problem file's input is its tables as written, at f64, with the
    /// title and statement: near 1/10 is 0.1 whatever the precision.
    #[test]
    fn a_problem_file_gives_its_tables() {
        let text = "title = 't'\nstatement = 's'\nask = ['window']\n\
                    [perspective]\nnear = '1/10'\nfovy = 90\naspect = 2\n";
        let p = ProblemIn::parse(text, "t.toml").unwrap();
        let r = crate::tutor::solve::solve::<f32>(&p).unwrap();
        let i = input(&r);
        assert_eq!(i["title"], "t");
        assert_eq!(i["statement"], "s");
        assert_eq!(i["perspective"]["near"], json!(0.1));
        assert_eq!(i["perspective"]["fovy"], json!(90.0));
        assert_eq!(i["perspective"]["far"], Value::Null);
    }
}
