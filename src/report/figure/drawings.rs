//! The drawings of a report: a calculator command gives one drawing,
//! `solve` one per part of the problem (view, project, window, clip,
//! shade), each built by its figure kind from the report's input and
//! results.

use super::builders::{result, vec_of, Part};
use super::{camera, clip, project, shade, window, Drawing, Figure};
use crate::report::Style;
use crate::stages::trace::{Report, Val};
use serde_json::{json, Value};

/// The drawings of a report: one for a calculator command, one per part
/// for `solve`, none for a command without figures.
pub fn drawings(r: &Report, st: &Style) -> Vec<Drawing> {
    let p = Part {
        inp: &r.input,
        res: &r.result,
        steps: &r.steps,
    };
    let one = |part: &str, panels: Option<Vec<Figure>>| {
        panels
            .map(|panels| Drawing {
                part: part.into(),
                panels,
            })
            .into_iter()
            .collect()
    };
    match r.command.as_str() {
        "basis" | "view" => one("view", camera::figure(&p, st)),
        "project" => one("project", project::figures(&p, st)),
        "window" => one("window", window::figures(&p, st)),
        "clip" => one("clip", clip::figures(&p, st)),
        "shade" => one("shade", shade::figures(&p, st)),
        "solve" => solve_drawings(r, st),
        _ => vec![],
    }
}

/// The drawings of `solve`, in the order of its parts.
fn solve_drawings(r: &Report, st: &Style) -> Vec<Drawing> {
    let mut out = Vec::new();
    let mut add = |part: String, panels: Option<Vec<Figure>>| {
        if let Some(panels) = panels {
            out.push(Drawing { part, panels });
        }
    };
    let inp = &r.input;
    let steps = &r.steps[..];
    if let Some(Val::Map(view)) = result(&r.result, "view") {
        let mut i = inp.get("camera").cloned().unwrap_or(Value::Null);
        i["points"] = inp.get("points").cloned().unwrap_or(Value::Null);
        let p = Part {
            inp: &i,
            res: view,
            steps,
        };
        add("view".into(), camera::figure(&p, st));
    }
    if let Some(Val::Map(proj)) = result(&r.result, "project") {
        let i = json!({ "projection": { "d": plane_d(r) } });
        let eyes = eye_points(r);
        let mut res = proj.clone();
        res.push(("eye".into(), Val::Map(eyes)));
        let p = Part {
            inp: &i,
            res: &res,
            steps,
        };
        add("project".into(), project::figures(&p, st));
    }
    if let Some(Val::Map(win)) = result(&r.result, "window") {
        add("window".into(), solve_window(r, win, st));
    }
    match result(&r.result, "clip") {
        Some(Val::Map(c)) => add("clip".into(), solve_clip(inp, 0, c, st)),
        Some(Val::List(cs)) => {
            for (k, c) in cs.iter().enumerate() {
                if let Val::Map(c) = c {
                    add(format!("clip-{}", k + 1), solve_clip(inp, k, c, st));
                }
            }
        }
        _ => {}
    }
    if let Some(Val::Map(sh)) = result(&r.result, "shade") {
        let p = Part {
            inp,
            res: sh,
            steps,
        };
        add("shade".into(), shade::figures(&p, st));
    }
    out
}

/// The window part of `solve`: the perspective inputs, the window results,
/// the pixels of the viewport part and the projected points.
fn solve_window(r: &Report, win: &[(String, Val)], st: &Style) -> Option<Vec<Figure>> {
    let per = r.input.get("perspective")?;
    let mut res = win.to_vec();
    if let Some(Val::Map(vp)) = result(&r.result, "viewport") {
        res.extend(vp.iter().cloned());
    }
    let mut i = per.clone();
    if let Some(Val::Map(proj)) = result(&r.result, "project") {
        if let Some(pts) = result(proj, "points") {
            res.push(("window_points".into(), pts.clone()));
        }
    }
    if result(&r.result, "viewport").is_none() {
        i["viewport"] = Value::Null;
    }
    let p = Part {
        inp: &i,
        res: &res,
        steps: &r.steps,
    };
    window::figures(&p, st)
}

/// Segment k of `solve`'s clip part, its ends resolved from named points.
fn solve_clip(inp: &Value, k: usize, c: &[(String, Val)], st: &Style) -> Option<Vec<Figure>> {
    let clip = inp.get("clip")?;
    let seg = clip.get("segment")?.get(k)?;
    let end = |key: &str| match seg.get(key)? {
        Value::String(name) => inp.get("points")?.get(name).cloned(),
        v => Some(v.clone()),
    };
    let i = json!({ "min": clip.get("min")?, "max": clip.get("max")?, "from": end("from")?, "to": end("to")? });
    let p = Part {
        inp: &i,
        res: c,
        steps: &[],
    };
    clip::figures(&p, st)
}

/// d of `solve`'s projection: the step that states it.
fn plane_d(r: &Report) -> Value {
    r.steps
        .iter()
        .flat_map(|s| &s.result)
        .find(|(k, _)| k == "d")
        .and_then(|(_, v)| match v {
            Val::Num(s) => Some(json!(s.value)),
            _ => None,
        })
        .unwrap_or(Value::Null)
}

/// The eye coordinates of `solve`'s points: the results of the steps
/// `A' = …` (also when the view is not asked for).
fn eye_points(r: &Report) -> Vec<(String, Val)> {
    let mut out: Vec<(String, Val)> = Vec::new();
    for (k, v) in r.steps.iter().flat_map(|s| &s.result) {
        if let Some(name) = k.strip_suffix('\'') {
            if !name.ends_with('\'') && vec_of(v).is_some() && !out.iter().any(|(n, _)| n == name) {
                out.push((name.to_string(), v.clone()));
            }
        }
    }
    out
}
