//! What every figure kind is built from: a report's input and the named
//! results the worked steps show (so every label's value is a result's
//! value), read by small helpers shared by the kinds; and the clip figure.

use super::{cabinet, label, label_at, short, Figure, Item, Pen, Place};
use crate::msg::{FigureMsg, Msg, Panel};
use crate::report::Style;
use crate::stages::trace::{Step, Val};
use serde_json::Value;

/// What one part's drawing is made from: the inputs (in the calculator's
/// JSON layout), the named results and the steps.
pub(super) struct Part<'a> {
    /// The inputs.
    pub inp: &'a Value,
    /// The named results.
    pub res: &'a [(String, Val)],
    /// The worked steps (vectors that are not results: N, L, V).
    pub steps: &'a [Step],
}

/// A result by key.
pub(super) fn result<'a>(res: &'a [(String, Val)], key: &str) -> Option<&'a Val> {
    res.iter().find(|(k, _)| k == key).map(|(_, v)| v)
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

/// A number of the inputs.
pub(super) fn input_num(v: &Value, key: &str) -> Option<f64> {
    v.get(key)?.as_f64()
}

/// Numbers of an input vector.
pub(super) fn input3(v: &Value, key: &str) -> Option<[f64; 3]> {
    let a = v.get(key)?.as_array()?;
    Some([
        a.first()?.as_f64()?,
        a.get(1)?.as_f64()?,
        a.get(2)?.as_f64()?,
    ])
}

/// An input number as a value for a label.
pub(super) fn num_val(x: f64) -> Val {
    Val::Num(crate::num::Shown {
        value: x,
        exact: None,
        pretty: None,
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
    }
}

/// `a + k·b`.
pub(super) fn along(a: [f64; 3], b: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

/// `b − a`.
pub(super) fn minus(b: [f64; 3], a: [f64; 3]) -> [f64; 3] {
    [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
}

/// The page direction of a 3D direction under the cabinet projection.
pub(super) fn page_dir(d: [f64; 3]) -> [f64; 2] {
    cabinet(d)
}

/// An arrow from `at` along `d` (scaled by k) with a label beyond its tip.
pub(super) fn arrow3(at: [f64; 3], d: [f64; 3], k: f64, pen: Pen, text: String) -> [Item; 2] {
    let tip = along(at, d, k);
    [
        Item::Arrow {
            a: cabinet(at),
            b: cabinet(tip),
            pen,
        },
        label_at(cabinet(tip), text, Place::beyond(page_dir(d))),
    ]
}

/// The world (or eye) axes x, y, z from the origin, length `a`.
pub(super) fn axes3(a: f64, names: [&str; 3]) -> Vec<Item> {
    let mut out = Vec::new();
    for (k, name) in names.iter().enumerate() {
        let mut d = [0.0; 3];
        d[k] = 1.0;
        out.extend(arrow3([0.0; 3], d, a, Pen::Frame, name.to_string()));
    }
    out
}

/// The 12 edges of the box [min, max] under the cabinet projection.
pub(super) fn box_edges(lo: [f64; 3], hi: [f64; 3], pen: Pen, items: &mut Vec<Item>) {
    let corner = |i: usize| {
        cabinet([
            if i & 1 == 0 { lo[0] } else { hi[0] },
            if i & 2 == 0 { lo[1] } else { hi[1] },
            if i & 4 == 0 { lo[2] } else { hi[2] },
        ])
    };
    for i in 0..8usize {
        for bit in [1usize, 2, 4] {
            if i & bit == 0 {
                items.push(Item::Segment {
                    a: corner(i),
                    b: corner(i | bit),
                    pen,
                });
            }
        }
    }
}

/// The clip figure: the box, the segment P0P1, each intersection tried
/// (a dot labelled with its plane, t and outcode), the kept part solid and
/// the cut-off parts dashed. Points are drawn by the cabinet projection.
pub(super) fn clip_figure(p: &Part, st: &Style) -> Option<Figure> {
    let (lo, hi) = (input3(p.inp, "min")?, input3(p.inp, "max")?);
    let (p0, p1) = (input3(p.inp, "from")?, input3(p.inp, "to")?);
    let mut items = Vec::new();
    box_edges(lo, hi, Pen::Frame, &mut items);
    match result(p.res, "segment") {
        Some(Val::List(ends)) if ends.len() == 2 => {
            let (a, b) = (vec_of(&ends[0])?, vec_of(&ends[1])?);
            for (from, to) in [(p0, a), (b, p1)] {
                if from != to {
                    items.push(cut(from, to));
                }
            }
            items.push(Item::Segment {
                a: cabinet(a),
                b: cabinet(b),
                pen: Pen::Kept,
            });
        }
        _ => items.push(cut(p0, p1)),
    }
    if let Some(Val::Map(tried)) = result(p.res, "intersections") {
        for (plane, v) in tried {
            items.extend(tried_marks(plane, v, st));
        }
    }
    let back = Place::beyond(page_dir(minus(p0, p1)));
    let fwd = Place::beyond(page_dir(minus(p1, p0)));
    items.push(label_at(
        cabinet(p0),
        format!("P0 {}", st.val_inline(&vec_val(&p0))),
        back,
    ));
    items.push(label_at(
        cabinet(p1),
        format!("P1 {}", st.val_inline(&vec_val(&p1))),
        fwd,
    ));
    Some(panel(st, Panel::Clip, items))
}

/// A cut-off piece from a to b.
fn cut(a: [f64; 3], b: [f64; 3]) -> Item {
    Item::Segment {
        a: cabinet(a),
        b: cabinet(b),
        pen: Pen::Cut,
    }
}

/// One intersection tried: a dot labelled with its plane (`right`), short
/// enough to sit off the box's edges, and a note under the drawing
/// "plane: t = …, outcode …".
fn tried_marks(plane: &str, v: &Val, st: &Style) -> Vec<Item> {
    let Val::Map(fields) = v else { return vec![] };
    let (Some(point), Some(t), Some(code)) = (
        result(fields, "point").and_then(vec_of),
        result(fields, "t"),
        result(fields, "code"),
    ) else {
        return vec![];
    };
    let kept = matches!(result(fields, "kept"), Some(Val::Bool(true)));
    let at = cabinet(point);
    vec![
        Item::Dot {
            at,
            pen: if kept { Pen::Kept } else { Pen::Tried },
        },
        label(at, plane),
        Item::Note {
            text: format!(
                "{plane}: t = {}, outcode {}",
                short(st, t),
                st.val_inline(code)
            ),
        },
    ]
}
