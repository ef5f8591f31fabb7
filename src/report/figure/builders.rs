//! What every figure kind is built from besides its part's inputs: the
//! named results the worked steps show (so every label's value is a
//! result's value) and the steps, read by small helpers shared by the
//! kinds.

pub(super) use super::axo::dot;
use super::axo::Axo;
use super::{label_toward, mark, Figure, Item, Kind, Pen, Shape};
use crate::msg::{FigureMsg, Msg, Panel};
use crate::num::vec::{self, V3};
use crate::report::Style;
use crate::stages::trace::{Step, Val};
use crate::tutor::key::{Field, Node};
use crate::tutor::solution::One;

/// What one part's drawing is made from besides its inputs: the named
/// results and the steps.
pub(super) struct Part<'a> {
    /// The part's results (none when it has none).
    pub res: Option<One<'a>>,
    /// The pixels of a problem file's viewport part, which join the
    /// window's drawing.
    pub pixels: Option<&'a Val>,
    /// The worked steps (vectors that are not results: N, L, V).
    pub steps: &'a [Step],
}

impl<'a> Part<'a> {
    /// A field of the part's results.
    pub fn field(&self, f: Field) -> Option<&'a Val> {
        match f {
            Field::Pixels if self.pixels.is_some() => self.pixels,
            _ => self.res?.field(f),
        }
    }
}

/// A result by its typed name (a field of the part, a point's name, what
/// is asked of an intersection, a light's factor), spelled as the key.
pub(super) fn result(res: &[(String, Val)], name: impl Into<Node>) -> Option<&Val> {
    let name = name.into().to_string();
    res.iter().find(|(k, _)| *k == name).map(|(_, v)| v)
}

/// The numbers of a value that is a list of numbers.
pub(super) fn nums_of(v: &Val) -> Option<Vec<f64>> {
    match v {
        Val::List(xs) => xs
            .iter()
            .map(|x| match x {
                Val::Num(s) => Some(s.value),
                _ => None,
            })
            .collect(),
        _ => None,
    }
}

/// Numbers of a 3-vector value.
pub(super) fn vec_of(v: &Val) -> Option<[f64; 3]> {
    match nums_of(v)?[..] {
        [x, y, z] => Some([x, y, z]),
        _ => None,
    }
}

/// An input number as a value for a label.
pub(super) fn num_val(x: f64) -> Val {
    // a whole number is its own exact form: a box's `x = 0` is 0, not an
    // approximation that underflowed (`≈ 0`, [`crate::num::format::is_approx`])
    let whole = x.is_finite() && x.fract() == 0.0 && x.abs() < 9e15;
    Val::Num(crate::num::Shown {
        value: x,
        exact: whole.then(|| (x as i64).to_string()),
        pretty: None,
        beyond: None,
    })
}

/// An input point as a value for a label.
pub(super) fn vec_val(p: &[f64]) -> Val {
    Val::List(p.iter().map(|x| num_val(*x)).collect())
}

/// The words of a figure message.
pub(super) fn say(st: &Style, m: FigureMsg) -> String {
    st.w(&Msg::Figure(m))
}

/// A panel: its title and description in the chosen language, its marks.
pub(super) fn panel(st: &Style, which: Panel, items: Vec<Item>) -> Figure {
    Figure {
        title: say(st, FigureMsg::Title(which)),
        desc: say(st, FigureMsg::Desc(which)),
        items,
        height: None,
    }
}

/// A 3D panel: as [`panel`], its description ending with the view it is
/// drawn in (the direction toward the viewer, azimuth and elevation).
pub(super) fn panel3(st: &Style, which: Panel, axo: &Axo, items: Vec<Item>) -> Figure {
    // The direction toward the viewer, its azimuth and elevation (for a
    // view mirrored in z, the −z side the reader stands on: azimuth
    // 180° − az).
    let t = axo.toward();
    let w = t.map(|c| (c * 100.0).round() / 100.0 + 0.0);
    let deg = |x: f64| (x.to_degrees() * 100.0).round() / 100.0 + 0.0;
    let view = FigureMsg::View {
        from: st.val_inline(&vec_val(&w)),
        az: st.val_inline(&num_val(deg(t[0].atan2(t[2])))),
        el: st.val_inline(&num_val(deg(t[1].clamp(-1.0, 1.0).asin()))),
    };
    let mut f = panel(st, which, items);
    f.desc = format!("{} {}", say(st, view), f.desc);
    f
}

/// `a + k·b`.
pub(super) fn along(a: [f64; 3], b: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

/// `b − a`.
pub(super) fn minus(b: [f64; 3], a: [f64; 3]) -> [f64; 3] {
    [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
}

/// An arrow from `at` along `d` (scaled by k) in the view `axo`, named
/// `name`, with its label `text` beyond the tip.
pub(super) fn arrow3(
    axo: &Axo,
    (name, kind): (&str, Kind),
    at: [f64; 3],
    d: [f64; 3],
    k: f64,
    pen: Pen,
    text: String,
) -> [Item; 2] {
    let (a, b) = (axo.page(at), axo.page(along(at, d, k)));
    [
        mark(name, kind, pen, Shape::Line { a, b, head: true }),
        label_toward(name, text, Some([b[0] - a[0], b[1] - a[1]])),
    ]
}

/// The axes x, y, z (named so) from the origin, length `a`, in the view
/// `axo`; the z axis starts at z = `z0` (≤ 0: eye space, where the camera
/// looks along −z).
pub(super) fn axes3(axo: &Axo, a: f64, z0: f64) -> Vec<Item> {
    let mut out = Vec::new();
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let mut d = [0.0; 3];
        d[k] = 1.0;
        let (at, len) = if k == 2 {
            ([0.0, 0.0, z0], a - z0)
        } else {
            ([0.0; 3], a)
        };
        out.extend(arrow3(
            axo,
            (name, Kind::Axis),
            at,
            d,
            len,
            Pen::Frame,
            name.to_string(),
        ));
    }
    out
}

fn v3(a: [f64; 3]) -> V3<f64> {
    V3::new(a[0], a[1], a[2])
}

/// The unit vector along a (a zero vector stays zero), by the stages' own
/// `normalize`.
pub(super) fn unit(a: [f64; 3]) -> [f64; 3] {
    vec::normalize(&v3(a)).map_or(a, |(u, _)| vec::to_f64(&u))
}

/// a × b.
pub(super) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    vec::to_f64(&vec::cross(&v3(a), &v3(b)))
}
