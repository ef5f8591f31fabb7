//! Drawing one problem of a form from the digits of its index
//! ([`super::space::Digits`]): every choice is a digit whose radix does
//! not depend on the other choices, so a form's space has a known size.
//! A drawing whose digits make no problem the text would set (points that
//! coincide, a point not beyond the near plane, a clipping end outside its
//! box's range) is `None`; the rest is screened on the solved problem
//! (`screen`).

use super::form::Form;
use super::numbers::{wanted, NumberClass};
use super::space::Digits;
use super::{Difficulty, Topic};
use crate::msg::{DrawnTitle, NamedPoint, Number, ShadeAsked, StatedCamera, Statement};
use crate::stages::lighting::Model;
use crate::tutor::key::{Axis, Field, Key, Part, Shading, Value};
use std::fmt::Write as _;
use std::sync::OnceLock;

/// A drawn problem before it is screened: its title and statement as
/// message keys, and the rest of its problem file.
pub(super) struct Draft {
    pub title: DrawnTitle,
    pub statement: Statement,
    /// The problem file after its `title` and `statement` lines.
    pub body: String,
}

/// The problem the digits draw in the form's space, if they draw one.
pub(super) fn draft(form: &Form, d: &mut Digits) -> Option<Draft> {
    match form.topic {
        Topic::Basis | Topic::View | Topic::Project | Topic::Pipeline => camera_problem(form, d),
        Topic::Window => window_problem(form.difficulty, d),
        Topic::Clip => clip_problem(form, d),
        Topic::Shade => shade_problem(form, d),
    }
}

/// How many problems the form's space numbers (the product of the radices
/// its drawing asks).
pub(super) fn space_size(form: &Form) -> u64 {
    let mut d = Digits::of(0);
    let _ = draft(form, &mut d);
    d.size()
}

/// The key of a value of the lighting: `shade.cos_alpha`, …
pub(super) fn shade(x: Shading) -> Key {
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

/// A number as a problem file writes it: a fraction as a string (an
/// expression), a decimal as a number.
fn toml_number(x: Number) -> String {
    match x {
        Number::Fraction(..) => tstr(&x.to_string()),
        Number::Decimal(..) => x.to_string(),
    }
}

/// A stated number's value.
fn value(x: Number) -> f64 {
    match x {
        Number::Decimal(units, places) => units as f64 / 10f64.powi(places as i32),
        Number::Fraction(p, q) => p as f64 / q as f64,
    }
}

fn dot(a: [i64; 3], b: [i64; 3]) -> i64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The square-free part of n > 0 (12 → 3): √n = k·√(its square-free part).
fn square_free(mut n: i64) -> i64 {
    let mut k = 2;
    while k * k <= n {
        while n % (k * k) == 0 {
            n /= k * k;
        }
        k += 1;
    }
    n
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

/// Whether a vector's components have no common factor and at least two
/// are not zero (not along an axis).
fn primitive_off_axis(v: [i64; 3]) -> bool {
    gcd(gcd(v[0], v[1]), v[2]) == 1 && v.iter().filter(|x| **x != 0).count() >= 2
}

/// The class of the camera basis of Pe − Pr = d and Vup = up, from its
/// norms: n = d/√a, u = (Vup × d)/√b and v = n × u = d × (Vup × d)/√(ab)
/// with a = |d|², b = |Vup × d|²; its radicands are the square-free parts
/// of a, b and ab that are not 1 (none, one, or three of them).
fn basis_class(d: [i64; 3], up: [i64; 3]) -> Option<NumberClass> {
    let (a, b) = (dot(d, d), dot(cross(up, d), cross(up, d)));
    if b == 0 {
        return None;
    }
    let mut r: Vec<i64> = [a, b, a * b]
        .map(square_free)
        .into_iter()
        .filter(|x| *x != 1)
        .collect();
    r.sort();
    r.dedup();
    Some(match r.len() {
        0 => NumberClass::Rational,
        1 => NumberClass::OneSurd,
        _ => NumberClass::SeveralSurds,
    })
}

/// A direction Pe − Pr and its Vup.
type Direction = ([i64; 3], [i64; 3]);

/// The directions Pe − Pr (with their Vup) whose camera basis is of the
/// class: rational ones up to 12 (|d| and |Vup × d| whole: (3, 0, 4),
/// (3, 12, 4), …), one surd and several surds up to 4; never along an
/// axis, no two of the same direction; Vup = (0, 1, 0) but for several
/// surds, which also tilt it.
fn directions(class: NumberClass) -> &'static [Direction] {
    static LISTS: OnceLock<[Vec<Direction>; 3]> = OnceLock::new();
    let lists = LISTS.get_or_init(|| {
        let list = |c: NumberClass, r: i64, ups: &[[i64; 3]]| {
            let mut out = Vec::new();
            for &up in ups {
                for x in -r..=r {
                    for y in -r..=r {
                        for z in -r..=r {
                            let d = [x, y, z];
                            if primitive_off_axis(d) && basis_class(d, up) == Some(c) {
                                out.push((d, up));
                            }
                        }
                    }
                }
            }
            out
        };
        let tilted = [[0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]];
        [
            list(NumberClass::Rational, 12, &[[0, 1, 0]]),
            list(NumberClass::OneSurd, 4, &[[0, 1, 0]]),
            list(NumberClass::SeveralSurds, 4, &tilted),
        ]
    });
    match class {
        NumberClass::Rational => &lists[0],
        NumberClass::OneSurd => &lists[1],
        NumberClass::SeveralSurds | NumberClass::NoClosedForm => &lists[2],
    }
}

/// The named points of a camera problem, near the look-at point: the
/// form's number of them, each offset from Pr by at most 2 (hard: 3) in
/// each coordinate.
fn camera_points(form: &Form, look: [i64; 3], d: &mut Digits) -> Vec<(String, [i64; 3])> {
    let spread = if form.difficulty == Difficulty::Hard {
        3
    } else {
        2
    };
    ["A", "B", "C"][..form.points.min(3)]
        .iter()
        .map(|n| {
            let p = look.map(|x| x + d.range(-spread, spread));
            (n.to_string(), p)
        })
        .collect()
}

/// Whether every point lies beyond `depth` in front of the eye: its eye
/// coordinate z' = n·(P − Pe), n = (Pe − Pr)/|Pe − Pr|, below −depth.
fn beyond(eye: [i64; 3], dir: [i64; 3], pts: &[(String, [i64; 3])], depth: f64) -> bool {
    let len = (dot(dir, dir) as f64).sqrt();
    pts.iter().all(|(_, p)| {
        let rel = [p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]];
        (dot(dir, rel) as f64) / len < -depth
    })
}

fn camera_problem(form: &Form, d: &mut Digits) -> Option<Draft> {
    let (topic, diff) = (form.topic, form.difficulty);
    let (dir, up) = d.pick(directions(wanted(topic, diff, Part::View)));
    let look = [0; 3].map(|_| d.range(-2, 2));
    let eye = [look[0] + dir[0], look[1] + dir[1], look[2] + dir[2]];
    let pts = camera_points(form, look, d);
    let nears: &[Number] = match diff {
        Difficulty::Easy => &[int(1), int(2)],
        Difficulty::Medium => &[dec(5, 1), int(1), int(2)],
        Difficulty::Hard => &[dec(1, 1), dec(25, 2), dec(5, 1)],
    };
    let near = match topic {
        Topic::Project | Topic::Pipeline => Some(d.pick(nears)),
        _ => None,
    };
    let setup = (topic == Topic::Pipeline).then(|| pipeline_draw(diff, d));
    // all digits drawn: now the problem the text would set, or none.
    let distinct = (1..pts.len()).all(|i| pts[..i].iter().all(|(_, q)| *q != pts[i].1));
    // beyond the near plane (the text projects points beyond it), with
    // room; a view problem's points in front of the eye
    let depth = near.map_or(0.5, |n| value(n) + 0.5);
    if !distinct || !beyond(eye, dir, &pts, depth) {
        return None;
    }
    let camera = StatedCamera { eye, look, up };
    let points = pts.clone();
    let (title, ask, statement, per) = match (topic, near, setup) {
        (Topic::Basis, ..) => (
            DrawnTitle::Basis,
            "view",
            Statement::Basis(camera),
            String::new(),
        ),
        (Topic::View, ..) => (
            DrawnTitle::EyeCoordinates,
            "view",
            Statement::View(camera, points),
            String::new(),
        ),
        (Topic::Pipeline, Some(near), Some(setup)) => {
            let (statement, per) = pipeline_setup(near, camera, points, setup);
            (DrawnTitle::Pipeline, "pipeline", statement, per)
        }
        (_, Some(near), _) => (
            DrawnTitle::Projection,
            "project",
            Statement::Project(camera, points, near),
            format!("[perspective]\nnear = {near}\n\n"),
        ),
        _ => return None,
    };
    Some(Draft {
        title,
        statement,
        body: camera_body(topic, ask, (eye, look, up), &per, &pts),
    })
}

/// A camera problem's file after its title and statement.
fn camera_body(
    topic: Topic,
    ask: &str,
    (eye, look, up): ([i64; 3], [i64; 3], [i64; 3]),
    per: &str,
    pts: &[(String, [i64; 3])],
) -> String {
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
    t.push_str(per);
    if !pts.is_empty() {
        t.push_str("[points]\n");
        for (n, p) in pts {
            let _ = writeln!(t, "{n} = {}", ints(*p));
        }
        t.push('\n');
    }
    if topic == Topic::Basis {
        let axis = |a| Key::new(Part::View, Value::Field(Field::Axis(a)));
        let keys = toml_keys([Axis::N, Axis::U, Axis::V].map(axis));
        let _ = writeln!(t, "[check]\nkeys = {keys}");
    }
    t
}

/// The fields of view of a class: fovy = 90° gives tan 45° = 1
/// (rational); 30°, 45°, 60°, 120° a tangent of one surd (2 − √3, √2 − 1,
/// √3/3, √3); the others a half angle whose tangent has no form in square
/// roots (10°, 20°, 25°, 35°, 40°, 50°, 55°, 70°: not 3°·m/2^k).
fn fovys(class: NumberClass) -> &'static [i64] {
    match class {
        NumberClass::Rational => &[90],
        NumberClass::OneSurd => &[30, 45, 60, 120],
        NumberClass::SeveralSurds | NumberClass::NoClosedForm => {
            &[20, 40, 50, 70, 80, 100, 110, 140]
        }
    }
}

/// A pipeline's fovy, aspect and viewport.
type Setup = (i64, Number, (i64, i64));

fn pipeline_draw(diff: Difficulty, d: &mut Digits) -> Setup {
    let fovy = d.pick(fovys(wanted(Topic::Pipeline, diff, Part::Window)));
    let aspect = d.pick(&[int(1), int(2), dec(15, 1), frac(4, 3)]);
    let viewport = d.pick(&[(200, 100), (400, 200), (300, 200), (640, 480), (800, 600)]);
    (fovy, aspect, viewport)
}

/// A pipeline problem's statement and its `[perspective]` table.
fn pipeline_setup(
    near: Number,
    camera: StatedCamera,
    points: Vec<NamedPoint>,
    (fovy, aspect, (w, h)): Setup,
) -> (Statement, String) {
    let statement = Statement::Pipeline {
        camera,
        points,
        near,
        fovy,
        aspect,
        viewport: (w, h),
    };
    let per = format!(
        "[perspective]\nnear = {near}\nfovy = {fovy}\naspect = {}\nviewport = [{w}, {h}]\n\n",
        toml_number(aspect)
    );
    (statement, per)
}

/// The window from fovy, aspect and near: fovy of the difficulty's class
/// ([`fovys`]); easy: 10 aspects × 10 nears (100 problems), medium:
/// 4 fovys × 7 × 7 (196), hard: 8 × 6 × 6 (288).
fn window_problem(diff: Difficulty, d: &mut Digits) -> Option<Draft> {
    let fovy = d.pick(fovys(wanted(Topic::Window, diff, Part::Window)));
    let (aspects, nears): (&[Number], &[Number]) = match diff {
        Difficulty::Easy => (
            &[
                int(1),
                int(2),
                dec(15, 1),
                dec(5, 1),
                int(3),
                dec(25, 1),
                dec(75, 2),
                dec(125, 2),
                frac(4, 3),
                frac(16, 9),
            ],
            &[
                int(1),
                int(2),
                int(3),
                int(4),
                int(5),
                dec(5, 1),
                dec(1, 1),
                dec(2, 1),
                dec(25, 1),
                int(10),
            ],
        ),
        Difficulty::Medium => (
            &[
                dec(15, 1),
                int(2),
                frac(4, 3),
                int(1),
                frac(16, 9),
                dec(5, 1),
                dec(125, 2),
            ],
            &[
                dec(5, 1),
                int(1),
                dec(1, 1),
                int(2),
                dec(2, 1),
                dec(25, 2),
                int(3),
            ],
        ),
        Difficulty::Hard => (
            &[
                frac(16, 9),
                dec(16, 1),
                dec(125, 2),
                dec(14, 1),
                dec(22, 1),
                frac(5, 3),
            ],
            &[
                dec(1, 1),
                dec(25, 2),
                dec(3, 1),
                dec(15, 2),
                dec(4, 1),
                dec(35, 2),
            ],
        ),
    };
    let (aspect, near) = (d.pick(aspects), d.pick(nears));
    Some(Draft {
        title: DrawnTitle::Window,
        statement: Statement::Window(fovy, aspect, near),
        body: format!(
            "ask = [\"window\"]\n\n[perspective]\nnear = {near}\nfovy = {fovy}\naspect = {}\n",
            toml_number(aspect)
        ),
    })
}

/// The clipping box for the difficulty: its corners, how far outside it an
/// end may lie, and the most coordinates strictly inside it on an axis.
/// Easy: from the origin, sides 2 to 4; medium: min −3 to 0, sides 2 to
/// 5; hard: min −5 to 0, sides 3 to 8.
fn clip_box(diff: Difficulty, d: &mut Digits) -> ([i64; 3], [i64; 3], i64) {
    let (mins, sides, pad): ((i64, i64), (i64, i64), i64) = match diff {
        Difficulty::Easy => ((0, 0), (2, 4), 2),
        Difficulty::Medium => ((-3, 0), (2, 5), 3),
        Difficulty::Hard => ((-5, 0), (3, 8), 4),
    };
    let min = [0; 3].map(|_| d.range(mins.0, mins.1));
    let side = [0; 3].map(|_| d.range(sides.0, sides.1));
    (min, [0, 1, 2].map(|k| min[k] + side[k]), pad)
}

/// The axes an end lies beyond, by how many: none; x, y or z; two of them;
/// all three.
const BEYOND: [&[&[usize]]; 4] = [
    &[&[]],
    &[&[0], &[1], &[2]],
    &[&[0, 1], &[0, 2], &[1, 2]],
    &[&[0, 1, 2]],
];

/// An end of a segment beyond `bits` planes of the box and strictly inside
/// the others (never on a box plane), or None when its digits name a
/// coordinate the box has not (an inside offset past a short side).
fn clip_end(
    bits: u32,
    (min, max, pad): ([i64; 3], [i64; 3], i64),
    longest: i64,
    d: &mut Digits,
) -> Option<[i64; 3]> {
    let axes = d.pick(BEYOND[bits.min(3) as usize]);
    let mut p = [0; 3];
    let mut ok = true;
    for k in 0..3 {
        let (high, out, inside) = (d.coin(), d.range(1, pad), d.range(1, longest - 1));
        p[k] = match (axes.contains(&k), high) {
            (true, true) => max[k] + out,
            (true, false) => min[k] - out,
            (false, _) => min[k] + inside,
        };
        ok &= axes.contains(&k) || p[k] < max[k];
    }
    ok.then_some(p)
}

fn clip_problem(form: &Form, d: &mut Digits) -> Option<Draft> {
    let shape = form.clip?;
    let longest = match form.difficulty {
        Difficulty::Easy => 4,
        Difficulty::Medium => 5,
        Difficulty::Hard => 8,
    };
    let b = clip_box(form.difficulty, d);
    let (p0, p1) = (
        clip_end(shape.bits[0], b, longest, d),
        clip_end(shape.bits[1], b, longest, d),
    );
    let (p0, p1) = (p0?, p1?);
    let (min, max, _) = b;
    (p0 != p1).then(|| Draft {
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

/// Integer vectors of whole length (their unit vectors rational) facing
/// the viewer (z ≥ 1), up to 9: (0, 0, 1), (0, 3, 4), (1, 2, 2), (2, 3, 6),
/// …; and those with one surd in their length up to 2: (0, 1, 1), (1, 1,
/// 1), (1, 0, 2), …; `off_axis`: not (0, 0, 1).
fn unit_directions(class: NumberClass, off_axis: bool) -> &'static [[i64; 3]] {
    static LISTS: OnceLock<[Vec<[i64; 3]>; 4]> = OnceLock::new();
    let lists = LISTS.get_or_init(|| {
        let list = |r: i64, whole: bool, off: bool| {
            let mut out = Vec::new();
            for x in -r..=r {
                for y in -r..=r {
                    for z in 1..=r {
                        let v = [x, y, z];
                        let n = dot(v, v);
                        // a perfect square: its square-free part is 1
                        let is_whole = square_free(n) == 1;
                        let primitive = gcd(gcd(x, y), z) == 1;
                        if primitive && is_whole == whole && (!off || v != [0, 0, 1]) {
                            out.push(v);
                        }
                    }
                }
            }
            out
        };
        [
            list(9, true, false),
            list(9, true, true),
            list(2, false, false),
            list(2, false, true),
        ]
    });
    match (class, off_axis) {
        (NumberClass::Rational, false) => &lists[0],
        (NumberClass::Rational, true) => &lists[1],
        (_, false) => &lists[2],
        (_, true) => &lists[3],
    }
}

/// A lighting problem's vectors and constants: (N, L, V, [ka, kd, ks, n]
/// unless the text's).
type Draw = ([i64; 3], [i64; 3], [i64; 3], Option<[Number; 4]>);

/// N, L, V (and, hard, the constants) of the difficulty's class: easy, N,
/// L and V of whole length (N off the z axis), so every answer is
/// rational; medium, N with one surd in its length and L, V of whole
/// length (R = 2N(L·N) − L and cos β are then rational, cos α has the
/// surd); hard, N and (Phong) V each with a surd in its length, L whole:
/// cos α has N's radicand, R is rational and cos β has V's, so the colour
/// has two (with Blinn–Phong V is whole and H brings the second,
/// [`half_vector_fits`]); each power cos^n β of one radicand stays short.
fn shade_draw(diff: Difficulty, model: Model, d: &mut Digits) -> Draw {
    let whole = unit_directions(NumberClass::Rational, false);
    let surd = unit_directions(NumberClass::OneSurd, true);
    match wanted(Topic::Shade, diff, Part::Shade) {
        NumberClass::Rational => (
            d.pick(unit_directions(NumberClass::Rational, true)),
            d.pick(whole),
            d.pick(whole),
            None,
        ),
        NumberClass::OneSurd => (d.pick(surd), d.pick(whole), d.pick(whole), None),
        NumberClass::SeveralSurds | NumberClass::NoClosedForm => {
            let n = d.pick(surd);
            let l = d.pick(whole);
            let v = d.pick(if model == Model::Blinn { whole } else { surd });
            let k = [
                d.pick(&[dec(2, 1), dec(3, 1), dec(4, 1)]),
                d.pick(&[dec(5, 1), dec(6, 1), dec(7, 1)]),
                d.pick(&[dec(5, 1), dec(7, 1), dec(9, 1)]),
                d.pick(&[int(3), int(5), int(8), int(10)]),
            ];
            (n, l, v, Some(k))
        }
    }
}

/// Whether a hard Phong problem's N and V have different radicands (so
/// its colour has two).
fn two_radicands(class: NumberClass, model: Model, n: [i64; 3], v: [i64; 3]) -> bool {
    class != NumberClass::SeveralSurds
        || model == Model::Blinn
        || square_free(dot(n, n)) != square_free(dot(v, v))
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
/// normal N, surface colour Cs, the form's model; the viewer on the lit
/// side (N·V > 0).
fn shade_problem(form: &Form, d: &mut Digits) -> Option<Draft> {
    let model = form.model?;
    let half = dec(5, 1);
    let colors: [[Number; 3]; 5] = [
        [int(1), int(1), int(0)],
        [int(1), int(0), int(0)],
        [int(0), half, int(1)],
        [int(1), half, int(0)],
        [half, half, half],
    ];
    let color = d.pick(&colors);
    let draw = shade_draw(form.difficulty, model, d);
    let (n, l, v, _) = draw;
    let class = wanted(Topic::Shade, form.difficulty, Part::Shade);
    let half_fits = model != Model::Blinn || half_vector_fits(class, n, l, v);
    let fits = half_fits && two_radicands(class, model, n, v);
    (dot(n, v) > 0 && fits).then(|| shade_draft(color, model, draw))
}

/// Whether Blinn–Phong's half vector keeps a problem in its class, told
/// from the integers before solving (the solved problem's class is still
/// measured): with |L| = m and |V| = p whole, |L/m + V/p|² = 2(mp +
/// L·V)/(mp), so H = norm(V + L) has the radicand h of 2mp(mp + L·V), and
/// N·H that times |N|²'s. Rational: h = 1; one surd: h = 1 or |N|²'s own;
/// several surds: h neither 1 nor |N|²'s.
fn half_vector_fits(class: NumberClass, n: [i64; 3], l: [i64; 3], v: [i64; 3]) -> bool {
    let whole = |x: [i64; 3]| (dot(x, x) as f64).sqrt().round() as i64;
    let (m, p) = (whole(l), whole(v));
    let sum = 2 * m * p * (m * p + dot(l, v));
    if sum <= 0 {
        return false;
    }
    let (h, own) = (square_free(sum), square_free(dot(n, n)));
    match class {
        NumberClass::Rational => h == 1,
        NumberClass::OneSurd => h == 1 || h == own,
        NumberClass::SeveralSurds => h != 1 && h != own,
        NumberClass::NoClosedForm => true,
    }
}

/// The lighting problem of a surface colour, a model and what was drawn.
pub(super) fn shade_draft(color: [Number; 3], model: Model, (n, l, v, k): Draw) -> Draft {
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
    fn the_direction_lists_have_the_class_of_their_basis() {
        // (3, 0, 4): |d| = 5, |Vup × d| = |(4, 0, −3)| = 5: rational.
        assert_eq!(
            basis_class([3, 0, 4], [0, 1, 0]),
            Some(NumberClass::Rational)
        );
        // (3, 12, 4): |d| = 13, |Vup × d| = 5: rational.
        assert_eq!(
            basis_class([3, 12, 4], [0, 1, 0]),
            Some(NumberClass::Rational)
        );
        // (1, 0, 1): |d| = |Vup × d| = √2, and √2·√2 = 2: one surd.
        assert_eq!(
            basis_class([1, 0, 1], [0, 1, 0]),
            Some(NumberClass::OneSurd)
        );
        // (1, 1, 1): √3, √2 and √6: several.
        assert_eq!(
            basis_class([1, 1, 1], [0, 1, 0]),
            Some(NumberClass::SeveralSurds)
        );
        // along Vup: no basis
        assert_eq!(basis_class([0, 2, 0], [0, 1, 0]), None);
        for class in [
            NumberClass::Rational,
            NumberClass::OneSurd,
            NumberClass::SeveralSurds,
        ] {
            let list = directions(class);
            assert!(list.len() >= 40, "{class:?}: {}", list.len());
            for (d, up) in list {
                assert_eq!(basis_class(*d, *up), Some(class));
                assert!(primitive_off_axis(*d), "{d:?}");
            }
        }
    }

    #[test]
    fn the_unit_directions_have_whole_or_surd_lengths() {
        for v in unit_directions(NumberClass::Rational, false) {
            let n = dot(*v, *v);
            let r = (n as f64).sqrt().round() as i64;
            assert_eq!(r * r, n, "{v:?}");
        }
        assert!(unit_directions(NumberClass::Rational, false).contains(&[0, 0, 1]));
        assert!(!unit_directions(NumberClass::Rational, true).contains(&[0, 0, 1]));
        assert!(unit_directions(NumberClass::Rational, true).contains(&[2, 3, 6]));
        for v in unit_directions(NumberClass::OneSurd, true) {
            let n = dot(*v, *v);
            let r = (n as f64).sqrt().round() as i64;
            assert_ne!(r * r, n, "{v:?}");
        }
    }
}
