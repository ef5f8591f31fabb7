//! The lighting figure of `shade` and `solve`'s shade part, drawn as the
//! text draws it: a flat diagram in the plane of incidence (the plane of
//! N and L), the surface a line with N straight up, L to the left and R
//! mirrored to the right of N, V (and H for Blinn) where they lie in that
//! plane, every vector at its true angle and the arcs of α (L to N) and β
//! (R to V) at true size. A vector that leaves the plane (V, H) is not
//! bent into it: a note says by how much it leaves it, and a further panel
//! draws it in its own plane (R and V for β, N and H for Blinn's N·H).
//! With several lights each light has its own plane of incidence and
//! panel (L2, R2, α2, β2, …).
//!
//! A vector v is drawn at (s·(v·t), v·N), where t is the unit direction
//! of L's part along the surface (or of V's, when L lies along N) and
//! s = −1 puts L on the left.

use super::builders::{cross, dot, num_val, panel, result, say, unit, vec_of, Part};
use super::{label_short, label_toward, labelled, mark, Figure, Item, Kind, Pen, Shape};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::trace::{Name, Val};
use crate::tutor::key::{Factor, Field, Shading};

/// The length every unit vector is drawn with (page units).
pub const LENGTH: f64 = 1.5;

/// How far a vector that coincides with one drawn before is moved
/// sideways on the page (page units; a twentieth of [`LENGTH`]).
pub const BESIDE: f64 = 0.075;

/// A vector lies in a plane when its part out of the plane is under this.
const IN_PLANE: f64 = 1e-9;

/// The vectors of the steps with this name that are 3-vectors (N, V, and
/// each light's L), in order.
fn step_vectors<'a>(p: &'a Part, name: &str) -> Vec<&'a Val> {
    p.steps
        .iter()
        .flat_map(|s| &s.result)
        .filter(|(k, v)| *k == Name::math(name) && vec_of(v).is_some())
        .map(|(_, v)| v)
        .collect()
}

/// Light i's value of a result that is one value for one light (a number
/// or a 3-vector) and a list (one per light) for several.
fn per_light(v: Option<&Val>, i: usize) -> Option<&Val> {
    let v = v?;
    match v {
        Val::Num(_) => (i == 0).then_some(v),
        _ if vec_of(v).is_some() => (i == 0).then_some(v),
        Val::List(xs) => xs.get(i).filter(|x| !matches!(x, Val::Null)),
        _ => None,
    }
}

/// The numbers (from 0) of the lights in range, in order: each has an L
/// step (a light out of range has none).
fn lit(p: &Part, count: usize) -> Vec<usize> {
    match p.field(Field::Lights) {
        Some(Val::List(ls)) => (0..ls.len())
            .filter(|i| match &ls[*i] {
                Val::Map(m) => matches!(result(m, Factor::InRange), Some(Val::Bool(true))),
                _ => false,
            })
            .collect(),
        _ => (0..count).collect(),
    }
}

/// A plane through the surface point: its up direction `n` and the
/// direction `x` drawn to the right (page x of v = v·x, page y = v·n).
#[derive(Clone, Copy)]
struct Plane {
    n: [f64; 3],
    x: [f64; 3],
}

impl Plane {
    /// The plane of `up` and `a` (or `b` when a lies along up), a on the
    /// left when `a_left`.
    fn of(up: [f64; 3], a: [f64; 3], b: Option<[f64; 3]>, a_left: bool) -> Plane {
        let n = unit(up);
        let along = |v: [f64; 3]| {
            let t = [0, 1, 2].map(|k| v[k] - dot(v, n) * n[k]);
            (dot(t, t).sqrt() > 1e-9).then(|| unit(t))
        };
        let (t, sign) = match (along(a), b.and_then(along)) {
            (Some(t), _) => (t, if a_left { -1.0 } else { 1.0 }),
            (None, Some(t)) => (t, 1.0),
            (None, None) => {
                let k = (0..3).min_by(|i, j| n[*i].abs().total_cmp(&n[*j].abs()));
                let mut e = [0.0; 3];
                e[k.unwrap_or(0)] = 1.0;
                (unit(cross(n, e)), 1.0)
            }
        };
        Plane {
            n,
            x: t.map(|c| sign * c),
        }
    }
    /// A vector on the page.
    fn page(&self, v: [f64; 3]) -> [f64; 2] {
        [dot(v, self.x), dot(v, self.n)]
    }
    /// The angle by which a vector leaves the plane, degrees.
    fn off(&self, v: [f64; 3]) -> f64 {
        let b = cross(self.n, self.x);
        dot(unit(v), b).clamp(-1.0, 1.0).asin().abs().to_degrees()
    }
    fn holds(&self, v: [f64; 3]) -> bool {
        dot(unit(v), cross(self.n, self.x)).abs() < IN_PLANE
    }
}

/// A vector to draw: its name, its value, its pen.
struct Vector<'a> {
    name: String,
    val: &'a Val,
    pen: Pen,
}

impl<'a> Vector<'a> {
    fn new(name: &str, val: &'a Val, pen: Pen) -> Vector<'a> {
        Vector {
            name: name.to_string(),
            val,
            pen,
        }
    }
}

/// Where each vector's arrow starts on the page, by name.
type Tails = Vec<(String, [f64; 2])>;

/// The tail of the arrow of `name` (the surface point if not drawn).
fn tail(tails: &Tails, name: &str) -> [f64; 2] {
    tails
        .iter()
        .find(|(n, _)| n == name)
        .map_or([0.0, 0.0], |(_, t)| *t)
}

/// The arrows of the vectors in a plane, each from the surface point,
/// [`LENGTH`] long: vectors along one direction are drawn side by side
/// ([`BESIDE`] apart) under one label `L = V = (…)`, and a note says
/// they coincide. Returns where each arrow starts.
fn arrows(plane: &Plane, vs: &[Vector], st: &Style, items: &mut Vec<Item>) -> Tails {
    let mut tails = Vec::new();
    let mut groups: Vec<(String, [f64; 2], Vec<&Vector>)> = Vec::new();
    for v in vs {
        let Some(d) = vec_of(v.val) else { continue };
        let d = plane.page(unit(d));
        let key = format!("{:.9},{:.9}", d[0], d[1]);
        match groups.iter_mut().find(|g| g.0 == key) {
            Some(g) => g.2.push(v),
            None => groups.push((key, d, vec![v])),
        }
    }
    for (_, d, members) in groups {
        let len = d[0].hypot(d[1]).max(1e-300);
        let side = [-d[1] / len, d[0] / len];
        for (k, v) in members.iter().enumerate() {
            let s = k as f64 * BESIDE;
            let a = [side[0] * s, side[1] * s];
            tails.push((v.name.clone(), a));
            let b = [a[0] + LENGTH * d[0], a[1] + LENGTH * d[1]];
            items.push(mark(
                &v.name,
                Kind::Arrow,
                v.pen,
                Shape::Line { a, b, head: true },
            ));
        }
        let names: Vec<&str> = members.iter().map(|v| v.name.as_str()).collect();
        let text = labelled(st, &names.join(" = "), members[0].val);
        items.push(label_toward(names[0], text, Some(d)));
        if names.len() > 1 {
            let word = say(st, FigureMsg::Word(FigWord::Coincide));
            items.push(Item::Note(format!("{}: {word}", names.join(", "))));
        }
    }
    tails
}

/// The arc of the angle `name` from direction a to direction b at radius
/// `r`·[`LENGTH`], labelled `α = 45°`, and a note with its cosine
/// (`cos α = √2/2 ≈ 0.7071`; Blinn's `N·H = …` for the angle of N and H).
/// An angle under 1° (vectors that coincide, drawn side by side) is
/// marked where it would be: a short arc across, at radius r, from a's
/// arrow to b's, drawn from their tails; and by the note alone
/// when the two arrows are drawn one over the other.
fn angle(
    plane: &Plane,
    (a, b): ([f64; 3], [f64; 3]),
    (tail_a, tail_b): ([f64; 2], [f64; 2]),
    (name, r): (&str, f64),
    cos: &Val,
    st: &Style,
) -> Vec<Item> {
    let (pa, pb) = (plane.page(unit(a)), plane.page(unit(b)));
    let (ta, tb) = (pa[1].atan2(pa[0]), pb[1].atan2(pb[0]));
    let turn = 2.0 * std::f64::consts::PI;
    let sweep = (tb - ta + turn / 2.0).rem_euclid(turn) - turn / 2.0;
    let deg = match cos {
        Val::Num(s) => s.value.clamp(-1.0, 1.0).acos().to_degrees(),
        _ => sweep.abs().to_degrees(),
    };
    let shown_deg = st.val_inline(&num_val((deg * 100.0).round() / 100.0));
    // The label, its short form (when it cannot stand clear) and the note.
    let (text, brief, note) = match name {
        "N·H" => (
            format!(
                "{} = {shown_deg}°",
                say(st, FigureMsg::Word(FigWord::AngleNH))
            ),
            format!("{shown_deg}°"),
            labelled(st, "N·H", cos),
        ),
        _ => (
            format!("{name} = {shown_deg}°"),
            name.to_string(),
            labelled(st, &format!("cos {name}"), cos),
        ),
    };
    let r = r * LENGTH;
    let pts: Vec<[f64; 2]> = if sweep.abs().to_degrees() < 1.0 {
        // Across the arrows drawn side by side, at radius r along them.
        let at = |t: [f64; 2], d: [f64; 2]| [t[0] + r * d[0], t[1] + r * d[1]];
        let (p, q) = (at(tail_a, pa), at(tail_b, pb));
        if (p[0] - q[0]).hypot(p[1] - q[1]) < 1e-9 {
            return vec![Item::Note(format!("{text}: {note}"))];
        }
        (0..=32)
            .map(|i| {
                let t = f64::from(i) / 32.0;
                [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
            })
            .collect()
    } else {
        (0..=32)
            .map(|i| {
                let t = ta + sweep * f64::from(i) / 32.0;
                [r * t.cos(), r * t.sin()]
            })
            .collect()
    };
    let mid = pts[16];
    vec![
        mark(name, Kind::Arc, Pen::Other, Shape::Path(pts)),
        label_short(name, text, brief, mid),
        Item::Note(note),
    ]
}

/// The surface: a line through the point along the plane, hatched below
/// (the side inside the object), and the point itself.
fn surface(st: &Style, items: &mut Vec<Item>) {
    let w = 1.25 * LENGTH;
    let mut lines = vec![([-w, 0.0], [w, 0.0], Pen::Frame)];
    for k in 0..14 {
        let x = -w + 0.2 + 0.26 * f64::from(k);
        lines.push(([x, 0.0], [x - 0.15, -0.15], Pen::Frame));
    }
    items.push(mark(
        "surface",
        Kind::Plane,
        Pen::Frame,
        Shape::Edges(lines),
    ));
    let text = say(st, FigureMsg::Word(FigWord::Surface));
    items.push(label_toward("surface", text, Some([1.0, -1.0])));
    items.push(mark(
        "surface point",
        Kind::Point,
        Pen::Frame,
        Shape::Dot([0.0, 0.0]),
    ));
}

/// Everything about one light that the figure draws.
struct Light<'a> {
    /// `""` for the only or first light, else `2`, `3`, …
    tag: String,
    /// Its number, from 1.
    number: usize,
    l: &'a Val,
    r: Option<&'a Val>,
    cos_a: Option<&'a Val>,
    cos_b: Option<&'a Val>,
}

/// The lighting panels.
pub fn figures(p: &Part, st: &Style) -> Option<Vec<Figure>> {
    let nv = *step_vectors(p, "N").first()?;
    let n = vec_of(nv)?;
    let v = step_vectors(p, "V").first().copied();
    let ls = step_vectors(p, "L");
    let single = !matches!(p.field(Field::Lights), Some(Val::List(x)) if x.len() > 1);
    let lights: Vec<Light> = ls
        .iter()
        .zip(lit(p, ls.len()))
        .map(|(l, i)| Light {
            tag: if i == 0 {
                String::new()
            } else {
                (i + 1).to_string()
            },
            number: i + 1,
            l,
            r: per_light(p.field(Field::Shading(Shading::R)), i),
            cos_a: per_light(p.field(Field::Shading(Shading::CosAlpha)), i),
            cos_b: per_light(p.field(Field::Shading(Shading::CosBeta)), i),
        })
        .collect();
    let h = p
        .field(Field::Shading(Shading::H))
        .filter(|h| vec_of(h).is_some());
    let mut out = Vec::new();
    for light in &lights {
        let first = light.number == 1;
        let blinn = if first {
            h.zip(p.field(Field::Shading(Shading::NDotH)))
        } else {
            None
        };
        let which = if single {
            Panel::Shade
        } else {
            Panel::ShadeLight(light.number)
        };
        out.extend(incidence(st, which, (nv, n), v, light, blinn));
    }
    // The lights out of range: a note on the first panel.
    let count = match p.field(Field::Lights) {
        Some(Val::List(x)) => x.len(),
        _ => 0,
    };
    let drawn: Vec<usize> = lights.iter().map(|l| l.number).collect();
    let dark = (1..=count).filter(|k| !drawn.contains(k));
    let notes: Vec<Item> = dark
        .map(|k| Item::Note(say(st, FigureMsg::OutOfRange(k))))
        .collect();
    if let Some(first) = out.first_mut() {
        first.items.extend(notes);
    }
    (!out.is_empty()).then_some(out)
}

/// The panels of one light: its plane of incidence, then (when V or H
/// leaves it) the plane of R and V, and the plane of N and H.
fn incidence(
    st: &Style,
    which: Panel,
    (nv, n): (&Val, [f64; 3]),
    v: Option<&Val>,
    light: &Light,
    blinn: Option<(&Val, &Val)>,
) -> Vec<Figure> {
    let l = vec_of(light.l).unwrap_or(n);
    let vd = v.and_then(vec_of);
    let plane = Plane::of(n, l, vd, true);
    let mut items = Vec::new();
    surface(st, &mut items);
    let named = |name: &str| format!("{name}{}", light.tag);
    let mut vs = vec![
        Vector::new("N", nv, Pen::Frame),
        Vector::new(&named("L"), light.l, Pen::Given),
    ];
    vs.extend(light.r.map(|val| Vector::new(&named("R"), val, Pen::Other)));
    // V and H in this plane, or a note and a panel of their own.
    let mut leave = Vec::new();
    for (name, val, pen) in [("V", v, Pen::Vector), ("H", blinn.map(|b| b.0), Pen::Tried)] {
        let Some((val, d)) = val.and_then(|x| Some((x, vec_of(x)?))) else {
            continue;
        };
        if plane.holds(d) {
            vs.push(Vector::new(name, val, pen));
        } else {
            let deg = st.val_inline(&num_val((plane.off(d) * 10.0).round() / 10.0));
            items.push(Item::Note(say(st, FigureMsg::OffPlane(name.into(), deg))));
            leave.push(name);
        }
    }
    let tails = arrows(&plane, &vs, st, &mut items);
    let at = |a: &str, b: &str| (tail(&tails, a), tail(&tails, b));
    if let Some(c) = light.cos_a {
        let ends = at(&named("L"), "N");
        items.extend(angle(&plane, (l, n), ends, (&named("α"), 0.3), c, st));
    }
    let r = light.r.and_then(vec_of);
    if let (Some(r), Some(vd), Some(c), false) = (r, vd, light.cos_b, leave.contains(&"V")) {
        let ends = at(&named("R"), "V");
        items.extend(angle(&plane, (r, vd), ends, (&named("β"), 0.45), c, st));
    }
    if let (Some((hv, nh)), false) = (blinn, leave.contains(&"H")) {
        let h = vec_of(hv).unwrap_or(n);
        let ends = at("N", "H");
        items.extend(angle(&plane, (n, h), ends, ("N·H", 0.6), nh, st));
    }
    let mut out = vec![panel(st, which, items)];
    if let (true, Some(rv), Some(vv), Some(c)) = (leave.contains(&"V"), light.r, v, light.cos_b) {
        let vs = [
            Vector::new(&named("R"), rv, Pen::Other),
            Vector::new("V", vv, Pen::Vector),
        ];
        out.push(pair(st, Panel::ShadeRV, vs, (&named("β"), c)));
    }
    if let (true, Some((hv, nh))) = (leave.contains(&"H"), blinn) {
        let vs = [
            Vector::new("N", nv, Pen::Frame),
            Vector::new("H", hv, Pen::Tried),
        ];
        out.push(pair(st, Panel::ShadeNH, vs, ("N·H", nh)));
    }
    out
}

/// A panel of two vectors in their own plane, the first straight up, with
/// the angle between them.
fn pair(st: &Style, which: Panel, vs: [Vector; 2], (name, cos): (&str, &Val)) -> Figure {
    let [a, b] = [&vs[0], &vs[1]].map(|v| vec_of(v.val).unwrap_or([0.0, 0.0, 1.0]));
    let plane = Plane::of(a, b, None, false);
    let dot = Shape::Dot([0.0, 0.0]);
    let mut items = vec![mark("surface point", Kind::Point, Pen::Frame, dot)];
    let tails = arrows(&plane, &vs, st, &mut items);
    let ends = (tail(&tails, &vs[0].name), tail(&tails, &vs[1].name));
    items.extend(angle(&plane, (a, b), ends, (name, 0.45), cos, st));
    panel(st, which, items)
}
