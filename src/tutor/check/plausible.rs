//! Which of a student's earlier values can start follow-through: only a
//! value that could be what its step gives, allowing for the rounding of
//! the digits written (one unit of the last digit, as rounded values are
//! carried forward) and the tolerance:
//!
//! - a camera axis u, v, n, and the unit vectors L, N, H, R of the
//!   lighting, are of length 1: |x| = √(x² + y² + z²) = 1;
//! - u is perpendicular to n, and v to n and u (the student's own where
//!   given, else grafika's): u·n = 0, v·n = 0, v·u = 0;
//! - an intersection of the segment P(t) = P0 + t·(P1 − P0) with a box's
//!   plane lies on that plane and on the segment (0 ≤ t ≤ 1): on a line
//!   the plane meets once, that is the intersection grafika found;
//! - a cosine (cos α, cos β, N·H) lies in [−1, 1]; the terms of the
//!   lighting and their sum are not negative, and the colour is in [0, 1];
//! - the window's top, right, height and width are positive, its bottom
//!   and left negative.
//!
//! Any other value is plausible.

use crate::input::answer::{Number, Read};
use crate::msg::Implausible;
use crate::stages::trace::Val;
use crate::tutor::key::{Axis, Cut, Edge, Field, Key, Shading, Value};

/// A number as written, with the slack of its writing: one unit of its
/// last digit (none for an exact form) and the tolerance `rel`.
#[derive(Clone, Copy, Debug)]
struct Loose {
    x: f64,
    e: f64,
}

fn loose(n: &Number, rel: f64) -> Loose {
    let unit = n.last_digit.map_or(0.0, |d| 10f64.powi(d));
    Loose {
        x: n.value,
        e: unit + rel * n.value.abs(),
    }
}

/// The numbers of an answer, depth first (None for a word).
fn numbers(r: &Read, rel: f64) -> Option<Vec<Loose>> {
    match r {
        Read::Num(n) => Some(vec![loose(n, rel)]),
        Read::List(items) => {
            let mut out = Vec::new();
            for x in items {
                out.extend(numbers(x, rel)?);
            }
            Some(out)
        }
        Read::Word(_) | Read::None => None,
    }
}

/// A value's numbers, exact (no slack).
fn exact(v: &Val) -> Vec<Loose> {
    match v {
        Val::Num(s) => vec![Loose { x: s.value, e: 0.0 }],
        Val::List(items) => items.iter().flat_map(exact).collect(),
        _ => vec![],
    }
}

/// Whether some vector within the slack of `v` has length 1 (within the
/// tolerance `rel`).
fn can_be_unit(v: &[Loose], rel: f64) -> bool {
    let lo: f64 = v.iter().map(|c| (c.x.abs() - c.e).max(0.0).powi(2)).sum();
    let hi: f64 = v.iter().map(|c| (c.x.abs() + c.e).powi(2)).sum();
    lo.sqrt() <= 1.0 + rel && hi.sqrt() >= 1.0 - rel
}

/// Whether two vectors within their slack can be perpendicular: |a·b| is
/// at most what the slack can move it by.
fn can_be_perpendicular(a: &[Loose], b: &[Loose], rel: f64) -> bool {
    if a.len() != b.len() {
        return true;
    }
    let dot: f64 = a.iter().zip(b).map(|(p, q)| p.x * q.x).sum();
    let slack: f64 = (a.iter().zip(b))
        .map(|(p, q)| p.x.abs() * q.e + q.x.abs() * p.e + p.e * q.e)
        .sum();
    dot.abs() <= slack + rel
}

/// Whether every number lies within [lo, hi], allowing its slack.
fn within(v: &[Loose], lo: f64, hi: f64) -> bool {
    v.iter().all(|c| c.x + c.e >= lo && c.x - c.e <= hi)
}

/// Whether the written point can be `at` (grafika's), component by
/// component within its slack and the tolerance of the point's scale.
fn can_be(v: &[Loose], at: &[Loose], rel: f64) -> bool {
    let scale = at.iter().map(|c| c.x.abs()).fold(1.0, f64::max);
    v.len() == at.len() && (v.iter().zip(at)).all(|(p, q)| (p.x - q.x).abs() <= p.e + rel * scale)
}

/// What the checks need besides the value: grafika's results, and the
/// student's own earlier values where given.
pub(crate) struct Context<'a> {
    /// The tolerance.
    pub rel: f64,
    /// grafika's value of a key.
    pub right: &'a dyn Fn(&Key) -> Option<Val>,
    /// The student's own value of a key, where given (wrong).
    pub own: &'a dyn Fn(&Key) -> Option<Read>,
}

impl Context<'_> {
    /// The value in use for `key`: the student's own where given, else
    /// grafika's.
    fn in_use(&self, key: &Key) -> Option<Vec<Loose>> {
        match (self.own)(key) {
            Some(r) => numbers(&r, self.rel),
            None => Some(exact(&(self.right)(key)?)),
        }
    }
}

/// Why the student's value `read` of `key` cannot start follow-through,
/// or None when it can.
pub(crate) fn why_not(key: &Key, read: &Read, cx: &Context) -> Option<Implausible> {
    let v = numbers(read, cx.rel)?;
    let rel = cx.rel;
    let field = match &key.value {
        Value::Field(f) => *f,
        Value::Cut(plane, Cut::Point) => {
            let at = Key {
                value: Value::Cut(*plane, Cut::T),
                ..key.clone()
            };
            let t = (cx.right)(&at).map(|t| exact(&t));
            let on_segment = matches!(t.as_deref(), Some([t]) if (0.0..=1.0).contains(&t.x));
            let point = (cx.right)(key).map(|p| exact(&p));
            return match point {
                Some(p) if on_segment && can_be(&v, &p, rel) => None,
                _ => Some(Implausible::OffSegment),
            };
        }
        _ => return None,
    };
    let axis = |a: Axis| Key {
        value: Value::Field(Field::Axis(a)),
        ..key.clone()
    };
    match field {
        Field::Axis(a) => {
            if !can_be_unit(&v, rel) {
                return Some(Implausible::NotUnit);
            }
            let others: &[Axis] = match a {
                Axis::N => &[],
                Axis::U => &[Axis::N],
                Axis::V => &[Axis::N, Axis::U],
            };
            others.iter().find_map(|o| {
                let w = cx.in_use(&axis(*o))?;
                (!can_be_perpendicular(&v, &w, rel))
                    .then(|| Implausible::NotPerpendicular(axis(*o).to_string()))
            })
        }
        Field::Shading(s) => match s {
            Shading::L | Shading::N | Shading::H | Shading::R => {
                (!can_be_unit(&v, rel)).then_some(Implausible::NotUnit)
            }
            Shading::CosAlpha | Shading::CosBeta | Shading::NDotH => {
                (!within(&v, -1.0, 1.0)).then_some(Implausible::NotACosine)
            }
            Shading::Color => (!within(&v, 0.0, 1.0)).then_some(Implausible::NotAColour),
            Shading::Ambient
            | Shading::Diffuse
            | Shading::Specular
            | Shading::Emissive
            | Shading::Unclamped => {
                (!within(&v, 0.0, f64::INFINITY)).then_some(Implausible::Negative)
            }
        },
        Field::Edge(e, _) => match e {
            Edge::Top | Edge::Right | Edge::Height | Edge::Width => {
                (!within(&v, f64::MIN_POSITIVE, f64::INFINITY)).then_some(Implausible::NotPositive)
            }
            Edge::Bottom | Edge::Left => (!within(&v, f64::NEG_INFINITY, -f64::MIN_POSITIVE))
                .then_some(Implausible::NotNegative),
        },
        Field::Matrix
        | Field::Points
        | Field::Pixels
        | Field::Code0
        | Field::Code1
        | Field::Status
        | Field::Segment
        | Field::Intersections
        | Field::Lights => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::answer;

    fn read(text: &str, like: &Val) -> Read {
        answer::read(&toml::Value::String(text.into()), like).expect("reads")
    }
    fn v3(x: f64, y: f64, z: f64) -> Val {
        Val::List([x, y, z].map(|c| Val::num(&c)).to_vec())
    }
    fn key(s: &str) -> Key {
        s.parse().expect("a key")
    }

    /// With n = (√2/2, 0, √2/2): u = (1, 2, 3) is no unit vector (|u| =
    /// √14); (0.71, 0, −0.71) is (√2/2, 0, −√2/2) rounded to two figures
    /// (|u| = 1.0041, within the rounding of its digits; u·n = 0); n itself
    /// is of length 1 but no axis beside n (u·n = 1 ≠ 0); (0, −1, 0) is.
    #[test]
    fn a_camera_axis_is_a_unit_vector_perpendicular_to_the_axes_before_it() {
        let like = v3(0.0, 0.0, 0.0);
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let n = v3(r, 0.0, r);
        let right = |k: &Key| (k.to_string() == "view.n").then(|| n.clone());
        let own = |_: &Key| None;
        let cx = Context {
            rel: 1e-3,
            right: &right,
            own: &own,
        };
        let u = key("view.u");
        assert_eq!(
            why_not(&u, &read("1, 2, 3", &like), &cx),
            Some(Implausible::NotUnit)
        );
        assert_eq!(why_not(&u, &read("(0,71; 0; −0,71)", &like), &cx), None);
        assert_eq!(
            why_not(&u, &read("(1/√2, 0, 1/√2)", &like), &cx),
            Some(Implausible::NotPerpendicular("view.n".into()))
        );
        assert_eq!(why_not(&u, &read("(0, -1, 0)", &like), &cx), None);
    }

    /// The segment P0(4, 2, 2)–P1(−2, 6, 1) meets x = 3 at t = 1/6, in
    /// (3, 8/3, 11/6); the text's (3, 20/6, 11/6) is on the plane but not
    /// on the segment; 2.67 is 8/3 to three figures.
    #[test]
    fn an_intersection_lies_on_the_segment() {
        let like = v3(0.0, 0.0, 0.0);
        let point = v3(3.0, 8.0 / 3.0, 11.0 / 6.0);
        let right = |k: &Key| match k.to_string().as_str() {
            "clip.intersections.right.t" => Some(Val::num(&(1.0f64 / 6.0))),
            "clip.intersections.right.point" => Some(point.clone()),
            _ => None,
        };
        let own = |_: &Key| None;
        let cx = Context {
            rel: 1e-3,
            right: &right,
            own: &own,
        };
        let k = key("clip.intersections.right.point");
        assert_eq!(
            why_not(&k, &read("(3, 20/6, 11/6)", &like), &cx),
            Some(Implausible::OffSegment)
        );
        assert_eq!(why_not(&k, &read("3; 2,67; 1,83", &like), &cx), None);
    }

    #[test]
    fn a_cosine_lies_in_minus_one_to_one_and_a_colour_in_zero_to_one() {
        let num = Val::num(&0.0f64);
        let none = |_: &Key| None;
        let no_own = |_: &Key| None;
        let cx = Context {
            rel: 1e-3,
            right: &none,
            own: &no_own,
        };
        let cos = key("shade.cos_alpha");
        assert_eq!(
            why_not(&cos, &read("1.2", &num), &cx),
            Some(Implausible::NotACosine)
        );
        assert_eq!(why_not(&cos, &read("-0.5", &num), &cx), None);
        let colour = key("shade.color");
        assert_eq!(
            why_not(&colour, &read("1.2, 0, 0", &v3(0.0, 0.0, 0.0)), &cx),
            Some(Implausible::NotAColour)
        );
    }
}
