//! Drawing one problem per topic with nice numbers for its difficulty, and
//! screening it: solvable, non-degenerate, the clipping status wanted.

use super::{Difficulty, Generated, Topic};
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::{DrawnTitle, Msg, NamedPoint, Number, ShadeAsked, StatedCamera, Statement};
use crate::num::rng::SplitMix64;
use crate::num::Real;
use crate::stages::lighting::Model;
use crate::stages::trace::Val;
use crate::tutor::check::scheme::Scheme;
use crate::tutor::key::{Axis, Field, Key, Part, Shading, Value};
use crate::tutor::keys::ordered_keys;
use crate::tutor::solution::value_of;
use crate::tutor::solve;
use std::collections::{BTreeSet, HashSet};
use std::fmt::Write as _;

/// A drawn problem before it is screened: its title and statement as
/// message keys, and the rest of its problem file.
struct Draft {
    title: DrawnTitle,
    statement: Statement,
    /// The problem file after its `title` and `statement` lines.
    body: String,
}

/// One problem: drawn until it is non-degenerate, solves, and is not one
/// of the problems `seen` earlier in the exam (their bodies). `status` is
/// the clipping status wanted (0 clipped, 1 accepted, 2 rejected).
pub fn problem(
    topic: Topic,
    diff: Difficulty,
    status: usize,
    seen: &HashSet<String>,
    rng: &mut SplitMix64,
) -> Result<Generated> {
    let mut repeats = 0;
    for _ in 0..500 {
        let d = match topic {
            Topic::Basis | Topic::View | Topic::Project | Topic::Pipeline => {
                camera_problem(topic, diff, rng)
            }
            Topic::Window => window_problem(diff, rng),
            Topic::Clip => clip_problem(diff, status, rng),
            Topic::Shade => shade_problem(diff, rng),
        };
        let Some(d) = d else { continue };
        if seen.contains(&d.body) {
            repeats += 1;
            continue;
        }
        if let Some(g) = accept(d, topic, diff, status) {
            return Ok(g);
        }
    }
    if repeats > 0 {
        return Err(Error::said(
            "count",
            Msg::ErrFewDistinct(
                super::topics_name(&[topic]),
                diff.name().to_string(),
                seen.len(),
            ),
        ));
    }
    Err(Error::why("seed", crate::msg::ErrMsg::NoDrawing))
}

/// Parses, solves and screens a drawn problem.
fn accept(d: Draft, topic: Topic, diff: Difficulty, status: usize) -> Option<Generated> {
    // The title is written in the user's language later (report::sheets).
    let problem = ProblemIn::parse(&format!("title = \"\"\n{}", d.body), "generated").ok()?;
    let f64_result = solve::solve::<f64>(&problem).ok()?.result;
    if !screen(&problem, &f64_result, topic, status) {
        return None;
    }
    let report = solve::solve::<Real>(&problem).ok()?;
    if !report.warnings.is_empty() {
        return None;
    }
    // the marking scheme `check` marks it by: its `[check] keys` (written
    // by the generator from typed keys, `toml_keys`, so each reads back),
    // weighted by its `[marks]`
    let order = ordered_keys(&report.result);
    let scheme = Scheme::of(&problem, &report.result, &order).ok()?;
    let keys: Vec<Key> = scheme.keys().cloned().collect();
    if !nice_enough(&report.result, &keys, diff) {
        return None;
    }
    Some(Generated {
        title: Msg::DrawnTitle(d.title),
        statement: Msg::Statement(Box::new(d.statement)),
        body: d.body,
        problem,
        report,
        keys,
        scheme,
    })
}

/// The exact forms the difficulty promises: easy answers are rational (no
/// square root), medium ones have at most one square root (one radicand
/// across the problem's answers), and at every level an answer has an exact
/// form unless it rests on the tangent of an angle that has none in square
/// roots (the hard window's fovy/2 of 20°, 25°, 35° or 40°: not of the form 3°·m/2^k).
fn nice_enough(result: &[(String, Val)], keys: &[Key], diff: Difficulty) -> bool {
    let mut radicands = BTreeSet::new();
    for k in keys {
        let Some(v) = value_of(result, k) else {
            continue;
        };
        let mut ok = true;
        for_each_num(v, &mut |n| match &n.exact {
            Some(e) => radicands.extend(radicands_of(e)),
            None => ok &= matches!(k.part, Some(Part::Window | Part::Viewport)),
        });
        if !ok {
            return false;
        }
    }
    match diff {
        Difficulty::Easy => radicands.is_empty(),
        Difficulty::Medium => radicands.len() <= 1,
        Difficulty::Hard => true,
    }
}

/// Calls `f` on every number of a value.
fn for_each_num(v: &Val, f: &mut impl FnMut(&crate::num::Shown)) {
    match v {
        Val::Num(n) => f(n),
        Val::List(items) => items.iter().for_each(|x| for_each_num(x, f)),
        Val::Map(kv) => kv.iter().for_each(|(_, x)| for_each_num(x, f)),
        _ => {}
    }
}

/// The radicands of an ASCII exact form: `(300+50*sqrt(2))/3` → {"2"}.
pub fn radicands_of(exact: &str) -> BTreeSet<String> {
    exact
        .split("sqrt(")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .map(str::to_string)
        .collect()
}

/// Non-degeneracy and the clipping status wanted.
fn screen(p: &ProblemIn, r: &[(String, Val)], topic: Topic, status: usize) -> bool {
    let num = |v: &Val| match v {
        Val::Num(s) => Some(s.value),
        _ => None,
    };
    // Points strictly beyond the near plane (never on the projection plane
    // z' = −near, never behind the eye), and not grazing it.
    if let Some(Val::Map(pts)) = value_of(r, &Key::new(Part::View, Value::Field(Field::Points))) {
        let near = p
            .perspective
            .as_ref()
            .and_then(|x| x.near.as_ref())
            .and_then(|n| n.0.eval::<f64>().ok())
            .unwrap_or(0.0);
        for (_, e) in pts {
            if let Val::List(c) = e {
                match c.get(2).and_then(num) {
                    Some(z) if z < -(near + 0.5) => {}
                    _ => return false,
                }
            }
        }
    }
    // Projected points inside the window for the pipeline (a clean exam).
    if topic == Topic::Pipeline {
        if let Some(Val::Map(px)) =
            value_of(r, &Key::new(Part::Viewport, Value::Field(Field::Pixels)))
        {
            let vp: Vec<f64> = p
                .perspective
                .as_ref()
                .and_then(|x| x.viewport.as_ref())
                .map(|v| v.iter().filter_map(|n| n.0.eval::<f64>().ok()).collect())
                .unwrap_or_default();
            for (_, q) in px {
                if let Val::List(c) = q {
                    let (x, y) = (c.first().and_then(num), c.get(1).and_then(num));
                    match (x, y, vp.first(), vp.get(1)) {
                        (Some(x), Some(y), Some(w), Some(h))
                            if x > 0.0 && x < *w && y > 0.0 && y < *h => {}
                        _ => return false,
                    }
                }
            }
        }
    }
    // Lighting: the light clearly in front of the surface.
    if topic == Topic::Shade {
        match value_of(r, &shade(Shading::CosAlpha)).and_then(num) {
            Some(c) if c > 0.05 => {}
            _ => return false,
        }
    }
    if topic == Topic::Clip {
        let want = ["clipped", "accepted", "rejected"][status % 3];
        let ok = matches!(value_of(r, &Key::new(Part::Clip, Value::Field(Field::Status))), Some(Val::Text(s)) if s == want);
        if !ok {
            return false;
        }
        if want == "clipped" {
            // a real piece, not a single point
            if let Some(Val::List(seg)) =
                value_of(r, &Key::new(Part::Clip, Value::Field(Field::Segment)))
            {
                if seg.first() == seg.get(1) {
                    return false;
                }
            }
        }
    }
    true
}

/// The key of a value of the lighting: `shade.cos_alpha`, …
fn shade(x: Shading) -> Key {
    Key::new(Part::Shade, Value::Field(Field::Shading(x)))
}

/// A `[check]` table's keys for a TOML file: `["view.n", "view.u"]`.
fn toml_keys(keys: impl IntoIterator<Item = Key>) -> String {
    let quoted: Vec<String> = keys.into_iter().map(|k| format!("\"{k}\"")).collect();
    arr(&quoted)
}

/// `[a, b, c]` for a TOML file.
fn arr(v: &[String]) -> String {
    format!("[{}]", v.join(", "))
}

fn ints(v: [i64; 3]) -> String {
    arr(&v.iter().map(|x| x.to_string()).collect::<Vec<_>>())
}

/// A TOML string literal.
fn tstr(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// The integer `n`, the decimal `units · 10^−places` and the fraction
/// `p/q` as a statement states them.
const fn int(n: i64) -> Number {
    Number::int(n)
}
const fn dec(units: i64, places: u32) -> Number {
    Number::dec(units, places)
}
const fn frac(p: i64, q: i64) -> Number {
    Number::Fraction(p, q)
}

const TRIPLES: [(i64, i64); 6] = [(3, 4), (4, 3), (5, 12), (12, 5), (6, 8), (8, 6)];

/// Pe − Pr and Vup for the difficulty.
fn direction(diff: Difficulty, rng: &mut SplitMix64) -> ([i64; 3], [i64; 3]) {
    let sign = |r: &mut SplitMix64| if r.coin() { 1 } else { -1 };
    match diff {
        Difficulty::Easy => {
            // (a, 0, c) with a² + c² a square, or (3, 12, 4)-like: |d| = 13
            // and |Vup × d| = 5 are both integers.
            if rng.below(3) == 0 {
                let (a, c) = *rng.pick(&[(3, 4), (4, 3)]);
                ([sign(rng) * a, sign(rng) * 12, sign(rng) * c], [0, 1, 0])
            } else {
                let (a, c) = *rng.pick(&TRIPLES[..4]);
                ([sign(rng) * a, 0, sign(rng) * c], [0, 1, 0])
            }
        }
        Difficulty::Medium => {
            if rng.coin() {
                // (a, 0, c): |d| = |Vup × d| = √(a² + c²), one surd
                let a = rng.range(-3, 3);
                let c = rng.range(1, 3) * sign(rng);
                ([a, 0, c], [0, 1, 0])
            } else {
                // a² + c² square, b ≠ 0: u rational, |d| = √(25 + b²)
                let (a, c) = *rng.pick(&TRIPLES[..2]);
                let b = rng.range(1, 3) * sign(rng);
                ([sign(rng) * a, b, sign(rng) * c], [0, 1, 0])
            }
        }
        Difficulty::Hard => {
            let d = [rng.range(-5, 5), rng.range(-5, 5), rng.range(-5, 5)];
            let up = *rng.pick(&[[0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]);
            (d, up)
        }
    }
}

fn camera_problem(topic: Topic, diff: Difficulty, rng: &mut SplitMix64) -> Option<Draft> {
    let (d, up) = direction(diff, rng);
    let look = [rng.range(-2, 2), rng.range(-2, 2), rng.range(-2, 2)];
    let eye = [look[0] + d[0], look[1] + d[1], look[2] + d[2]];
    let pts = camera_points(topic, diff, look, rng);
    let nears: &[Number] = match diff {
        Difficulty::Easy => &[int(1), int(2)],
        Difficulty::Medium => &[dec(5, 1), int(1), int(2)],
        Difficulty::Hard => &[dec(1, 1), dec(25, 2), dec(5, 1)],
    };
    let near = *rng.pick(nears);
    let points = pts.clone();
    let camera = StatedCamera { eye, look, up };
    let (title, ask, statement, per) = match topic {
        Topic::Basis => (
            DrawnTitle::Basis,
            "view",
            Statement::Basis(camera),
            String::new(),
        ),
        Topic::View => (
            DrawnTitle::EyeCoordinates,
            "view",
            Statement::View(camera, points),
            String::new(),
        ),
        Topic::Project => (
            DrawnTitle::Projection,
            "project",
            Statement::Project(camera, points, near),
            format!("[perspective]\nnear = {near}\n\n"),
        ),
        _ => {
            let (statement, per) = pipeline_setup(diff, near, camera, points, rng);
            (DrawnTitle::Pipeline, "pipeline", statement, per)
        }
    };
    let ask = match ask {
        "pipeline" => r#"["view", "project", "window", "viewport"]"#.to_string(),
        one => format!("[\"{one}\"]"),
    };
    let mut t = format!("ask = {ask}\n\n");
    let _ = writeln!(
        t,
        "[camera]\neye = {}\nlook = {}\nup = {}\n",
        ints(eye),
        ints(look),
        ints(up)
    );
    t.push_str(&per);
    if !pts.is_empty() {
        t.push_str("[points]\n");
        for (n, p) in &pts {
            let _ = writeln!(t, "{n} = {}", ints(*p));
        }
        t.push('\n');
    }
    if topic == Topic::Basis {
        let axis = |a| Key::new(Part::View, Value::Field(Field::Axis(a)));
        let keys = toml_keys([Axis::N, Axis::U, Axis::V].map(axis));
        let _ = writeln!(t, "[check]\nkeys = {keys}");
    }
    Some(Draft {
        title,
        statement,
        body: t,
    })
}

/// The named points of a camera problem, near the look-at point and all
/// different: none for the basis, three for the pipeline, else two or three.
fn camera_points(
    topic: Topic,
    diff: Difficulty,
    look: [i64; 3],
    rng: &mut SplitMix64,
) -> Vec<(String, [i64; 3])> {
    let npts = match topic {
        Topic::Basis => 0,
        Topic::Pipeline => 3,
        _ => 2 + rng.below(2) as usize,
    };
    let spread = if diff == Difficulty::Hard { 3 } else { 2 };
    let mut pts: Vec<(String, [i64; 3])> = Vec::new();
    for n in &["A", "B", "C"][..npts] {
        let p = loop {
            let p = [
                look[0] + rng.range(-spread, spread),
                look[1] + rng.range(-spread, spread),
                look[2] + rng.range(-spread, spread),
            ];
            if pts.iter().all(|(_, q)| *q != p) {
                break p;
            }
        };
        pts.push((n.to_string(), p));
    }
    pts
}

/// A pipeline problem's perspective set-up (fovy, aspect, viewport drawn
/// for the difficulty): its statement and its `[perspective]` table.
fn pipeline_setup(
    diff: Difficulty,
    near: Number,
    camera: StatedCamera,
    points: Vec<NamedPoint>,
    rng: &mut SplitMix64,
) -> (Statement, String) {
    let fovy: i64 = *rng.pick(match diff {
        Difficulty::Easy => &[90][..],
        Difficulty::Medium => &[45, 60, 90][..],
        Difficulty::Hard => &[40, 50, 70][..],
    });
    let aspect = *rng.pick(&[int(1), int(2), dec(15, 1)]);
    let (w, h) = *rng.pick(&[(200, 100), (400, 200), (300, 200)]);
    let statement = Statement::Pipeline {
        camera,
        points,
        near,
        fovy,
        aspect,
        viewport: (w, h),
    };
    let per = format!(
        "[perspective]\nnear = {near}\nfovy = {fovy}\naspect = {aspect}\nviewport = [{w}, {h}]\n\n"
    );
    (statement, per)
}

/// The window from fovy, aspect and near. Easy: fovy = 90° (top = near),
/// 20 different problems; medium: a fovy whose tangent has one surd; hard:
/// a fovy whose half has no tangent in square roots (20°, 25°, 35°, 40°).
fn window_problem(diff: Difficulty, rng: &mut SplitMix64) -> Option<Draft> {
    let (fovy, aspect, near): (i64, Number, Number) = match diff {
        Difficulty::Easy => (
            90,
            *rng.pick(&[int(1), int(2), dec(15, 1), dec(5, 1)]),
            *rng.pick(&[int(1), int(2), int(3), int(4), int(5)]),
        ),
        Difficulty::Medium => (
            *rng.pick(&[30, 45, 60, 120]),
            *rng.pick(&[dec(15, 1), int(2), frac(4, 3)]),
            *rng.pick(&[dec(5, 1), int(1), dec(1, 1)]),
        ),
        Difficulty::Hard => (
            *rng.pick(&[40, 50, 70, 80]),
            *rng.pick(&[frac(16, 9), dec(16, 1), dec(125, 2)]),
            *rng.pick(&[dec(1, 1), dec(25, 2), dec(3, 1)]),
        ),
    };
    // a fraction is a string of the file (an expression), a decimal a number
    let aspect_toml = match aspect {
        Number::Fraction(..) => tstr(&aspect.to_string()),
        Number::Decimal(..) => aspect.to_string(),
    };
    Some(Draft {
        title: DrawnTitle::Window,
        statement: Statement::Window(fovy, aspect, near),
        body: format!(
            "ask = [\"window\"]\n\n[perspective]\nnear = {near}\nfovy = {fovy}\naspect = {aspect_toml}\n"
        ),
    })
}

/// The clipping box (corners) for the difficulty, and how far outside it
/// segment ends may lie.
fn clip_box(diff: Difficulty, rng: &mut SplitMix64) -> ([i64; 3], [i64; 3], i64) {
    match diff {
        Difficulty::Easy => (
            [0, 0, 0],
            [rng.range(2, 4), rng.range(2, 4), rng.range(2, 4)],
            2,
        ),
        Difficulty::Medium => {
            let min = [rng.range(-3, 0), rng.range(-3, 0), rng.range(-3, 0)];
            (
                min,
                [
                    min[0] + rng.range(2, 5),
                    min[1] + rng.range(2, 5),
                    min[2] + rng.range(2, 5),
                ],
                3,
            )
        }
        Difficulty::Hard => {
            let min = [rng.range(-5, 0), rng.range(-5, 0), rng.range(-5, 0)];
            (
                min,
                [
                    min[0] + rng.range(3, 8),
                    min[1] + rng.range(3, 8),
                    min[2] + rng.range(3, 8),
                ],
                4,
            )
        }
    }
}

/// Segment ends off the box planes for the wanted status: 0 clipped (one
/// end inside and the other anywhere, or both anywhere), 1 accepted, 2
/// rejected.
fn clip_ends(
    status: usize,
    (min, max, pad): ([i64; 3], [i64; 3], i64),
    rng: &mut SplitMix64,
) -> ([i64; 3], [i64; 3]) {
    // A coordinate off the box planes: inside (strictly) or outside.
    let inside = |r: &mut SplitMix64, k: usize| r.range(min[k] + 1, max[k] - 1);
    let any = |r: &mut SplitMix64, k: usize| loop {
        let x = r.range(min[k] - pad, max[k] + pad);
        if x != min[k] && x != max[k] {
            return x;
        }
    };
    match status {
        // clipped: one end inside and the other anywhere, or both anywhere
        0 => {
            let a: [i64; 3] = if rng.coin() {
                std::array::from_fn(|k| inside(rng, k))
            } else {
                std::array::from_fn(|k| any(rng, k))
            };
            let b: [i64; 3] = std::array::from_fn(|k| any(rng, k));
            if rng.coin() {
                (a, b)
            } else {
                (b, a)
            }
        }
        // accepted: both ends strictly inside
        1 => (
            std::array::from_fn(|k| inside(rng, k)),
            std::array::from_fn(|k| inside(rng, k)),
        ),
        // rejected: both ends beyond one plane, or anywhere (a segment
        // that passes the box by is rejected only after clipping)
        _ => {
            let mut a: [i64; 3] = std::array::from_fn(|k| any(rng, k));
            let mut b: [i64; 3] = std::array::from_fn(|k| any(rng, k));
            if rng.below(3) != 0 {
                let k = rng.below(3) as usize;
                let (lo, hi) = if rng.coin() {
                    (min[k] - pad, min[k] - 1)
                } else {
                    (max[k] + 1, max[k] + pad)
                };
                a[k] = rng.range(lo, hi);
                b[k] = rng.range(lo, hi);
            }
            (a, b)
        }
    }
}

fn clip_problem(diff: Difficulty, status: usize, rng: &mut SplitMix64) -> Option<Draft> {
    let (min, max, pad) = clip_box(diff, rng);
    let (p0, p1) = clip_ends(status, (min, max, pad), rng);
    if p0 == p1 {
        return None;
    }
    Some(Draft {
        title: DrawnTitle::Clipping,
        statement: Statement::Clip(min, max, p0, p1),
        body: format!(
            "ask = [\"clip\"]\n\n[clip]\nmin = {}\nmax = {}\n\n[[clip.segment]]\nfrom = {}\nto = {}\n",
            ints(min),
            ints(max),
            ints(p0),
            ints(p1)
        ),
    })
}

/// A lighting problem's vectors, model and constants for the difficulty:
/// (N, L, V, model, [ka, kd, ks, n] unless the text's).
type Draw = ([i64; 3], [i64; 3], [i64; 3], Model, Option<[Number; 4]>);

/// Draws N, L, V, the model and (hard) the constants.
fn shade_draw(diff: Difficulty, rng: &mut SplitMix64) -> Draw {
    match diff {
        Difficulty::Easy => (
            *rng.pick(&[
                [0, 3, 4],
                [3, 0, 4],
                [0, 4, 3],
                [4, 0, 3],
                [0, -3, 4],
                [-3, 0, 4],
            ]),
            [0, 0, 1],
            [0, 0, 1],
            Model::Phong,
            None,
        ),
        Difficulty::Medium => (
            *rng.pick(&[
                [0, 1, 1],
                [1, 0, 1],
                [0, -1, 1],
                [-1, 0, 1],
                [0, 1, 2],
                [1, 0, 2],
            ]),
            [0, 0, 1],
            *rng.pick(&[[0, 0, 1], [0, 1, 1], [1, 0, 1]]),
            *rng.pick(&[Model::Phong, Model::Lambert, Model::Blinn]),
            None,
        ),
        Difficulty::Hard => {
            let vec = |r: &mut SplitMix64| [r.range(-2, 3), r.range(-2, 3), r.range(1, 3)];
            let k = [
                *rng.pick(&[dec(2, 1), dec(3, 1), dec(4, 1)]),
                *rng.pick(&[dec(5, 1), dec(6, 1), dec(7, 1)]),
                *rng.pick(&[dec(5, 1), dec(7, 1), dec(9, 1)]),
                *rng.pick(&[int(3), int(5), int(8), int(10)]),
            ];
            (
                vec(rng),
                vec(rng),
                vec(rng),
                *rng.pick(&[Model::Phong, Model::Blinn, Model::Lambert]),
                Some(k),
            )
        }
    }
}

/// What a lighting problem asks for, and the answers checked, follow the
/// model: (the constants as stated, what is asked, the check keys). One
/// arm per model, so an exam can draw any model and a new one is asked
/// here what its problem asks.
fn shade_asked(
    model: Model,
    [ka, kd, ks, sh]: [Number; 4],
) -> (Vec<(&'static str, Number)>, ShadeAsked, String) {
    use Shading::*;
    let keys = |v: &[Shading]| toml_keys(v.iter().map(|x| shade(*x)));
    let all = || vec![("ka", ka), ("kd", kd), ("ks", ks), ("n", sh)];
    match model {
        Model::Ambient => (
            vec![("ka", ka)],
            ShadeAsked::Ambient,
            keys(&[Ambient, Color]),
        ),
        Model::Diffuse => (
            vec![("kd", kd)],
            ShadeAsked::Diffuse,
            keys(&[CosAlpha, Diffuse, Color]),
        ),
        Model::Specular => (
            vec![("ks", ks), ("n", sh)],
            ShadeAsked::Specular,
            keys(&[CosAlpha, R, CosBeta, Specular, Color]),
        ),
        Model::Lambert => (
            vec![("ka", ka), ("kd", kd)],
            ShadeAsked::Lambert,
            keys(&[CosAlpha, Ambient, Diffuse, Color]),
        ),
        Model::Blinn => (
            all(),
            ShadeAsked::Blinn,
            keys(&[CosAlpha, H, NDotH, Ambient, Diffuse, Specular, Color]),
        ),
        Model::Phong => (
            all(),
            ShadeAsked::Phong,
            keys(&[CosAlpha, R, CosBeta, Ambient, Diffuse, Specular, Color]),
        ),
    }
}

/// A lighting problem at one point: white directional light L, viewer V,
/// normal N, surface color Cs. Easy: L = V = (0, 0, 1) (the text's) and a
/// normal with a rational length (3-4-5), so every answer is rational;
/// medium: normals like (0, 1, 1) with one surd, the models phong, lambert
/// and blinn; hard: any small vectors and coefficients. Always lit (N·L > 0).
fn shade_problem(diff: Difficulty, rng: &mut SplitMix64) -> Option<Draft> {
    let half = dec(5, 1);
    let colors: [[Number; 3]; 5] = [
        [int(1), int(1), int(0)],
        [int(1), int(0), int(0)],
        [int(0), half, int(1)],
        [int(1), half, int(0)],
        [half, half, half],
    ];
    let color = *rng.pick(&colors);
    Some(shade_draft(color, shade_draw(diff, rng)))
}

/// The lighting problem of a surface colour and what was drawn.
fn shade_draft(color: [Number; 3], (n, l, v, model, k): Draw) -> Draft {
    let coeffs = k.map_or(String::new(), |k| {
        format!(
            "ka = {}\nkd = {}\nks = {}\nshininess = {}\n",
            k[0], k[1], k[2], k[3]
        )
    });
    // the text's constants unless drawn
    let text = [dec(4, 1), dec(6, 1), dec(7, 1), int(4)];
    let (constants, asked, keys) = shade_asked(model, k.unwrap_or(text));
    let statement = Statement::Shade {
        normal: n,
        color,
        light: l,
        view: v,
        model: model.name().to_string(),
        constants,
        asked,
    };
    let body = format!(
        "ask = [\"shade\"]\n\n[shade]\nmodel = \"{}\"\nlight = {}\nnormal = {}\nview = {}\ncolor = {}\n{coeffs}\n[check]\nkeys = {keys}\n",
        model.name(),
        ints(l),
        ints(n),
        ints(v),
        arr(&color.iter().map(|c| c.to_string()).collect::<Vec<_>>()),
    );
    Draft {
        title: DrawnTitle::Lighting,
        statement,
        body,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_exam_can_ask_about_every_model() {
        // N = (0, 3, 4)/5, L = V = (0, 0, 1): cos α = 4/5, lit, every
        // answer rational. Each model's problem is accepted as a drawn one
        // is, and each answer it checks is in its results.
        for m in Model::all() {
            let draw = ([0, 3, 4], [0, 0, 1], [0, 0, 1], m, None);
            let d = shade_draft([int(1), int(1), int(0)], draw);
            let g = accept(d, Topic::Shade, Difficulty::Easy, 0)
                .unwrap_or_else(|| panic!("{m:?}: the drawn problem is refused"));
            assert!(!g.keys.is_empty(), "{m:?}");
            for k in &g.keys {
                let v = value_of(&g.report.result, k);
                assert!(v.is_some_and(|v| *v != Val::Null), "{m:?}: no {k}");
            }
        }
    }
}
