//! Figure descriptions built from a report: its input and the named results
//! the worked steps show (so every label's value is a result's value).

use super::{cabinet, Figure, Item, Pen};
use crate::report::lang::tr;
use crate::report::Style;
use crate::stages::trace::{Report, Val};
use serde_json::Value;

/// The figure of a report, when its command draws one (`clip` so far).
pub fn figure_of(r: &Report, style: &Style) -> Option<Figure> {
    match r.command.as_str() {
        "clip" => clip_figure(r, style),
        _ => None,
    }
}

/// A result by key.
fn result<'a>(r: &'a Report, key: &str) -> Option<&'a Val> {
    r.result.iter().find(|(k, _)| k == key).map(|(_, v)| v)
}

/// Numbers of a vector value.
fn vec_of(v: &Val) -> Option<[f64; 3]> {
    match v {
        Val::List(xs) if xs.len() == 3 => {
            let mut o = [0.0; 3];
            for (k, x) in xs.iter().enumerate() {
                match x {
                    Val::Num(s) => o[k] = s.value,
                    _ => return None,
                }
            }
            Some(o)
        }
        _ => None,
    }
}

/// Numbers of an input vector.
fn input3(v: &Value, key: &str) -> Option<[f64; 3]> {
    let a = v.get(key)?.as_array()?;
    Some([
        a.first()?.as_f64()?,
        a.get(1)?.as_f64()?,
        a.get(2)?.as_f64()?,
    ])
}

/// The 12 edges of the box [min, max] under the cabinet projection.
fn box_edges(lo: [f64; 3], hi: [f64; 3], items: &mut Vec<Item>) {
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
                    pen: Pen::Frame,
                });
            }
        }
    }
}

/// The clip figure: the box, the segment P0P1, each intersection tried
/// (a dot labelled with its plane, t and outcode), the kept part solid and
/// the cut-off parts dashed. Points are drawn by the cabinet projection.
pub fn clip_figure(r: &Report, style: &Style) -> Option<Figure> {
    let lang = style.lang;
    let (lo, hi) = (input3(&r.input, "min")?, input3(&r.input, "max")?);
    let (p0, p1) = (input3(&r.input, "from")?, input3(&r.input, "to")?);
    let mut items = Vec::new();
    box_edges(lo, hi, &mut items);
    match result(r, "segment") {
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
    if let Some(Val::Map(tried)) = result(r, "intersections") {
        for (plane, v) in tried {
            items.extend(tried_marks(plane, v, style));
        }
    }
    items.push(Item::Label {
        at: cabinet(p0),
        text: format!("P0 {}", style.val_inline(&vec_val(p0))),
    });
    items.push(Item::Label {
        at: cabinet(p1),
        text: format!("P1 {}", style.val_inline(&vec_val(p1))),
    });
    Some(Figure {
        title: tr(lang, "Clipping P0P1 against the box", "Klipping P0P1 terhadap kotak").into(),
        desc: tr(
            lang,
            "Cabinet oblique projection (x − z/(2√2), y − z/(2√2)). The kept part is solid blue, the cut-off parts dashed vermillion; each intersection tried is a dot labelled with its plane, t and outcode.",
            "Proyeksi oblik kabinet (x − z/(2√2), y − z/(2√2)). Bagian yang disimpan biru tegas, bagian yang dibuang putus-putus merah jingga; tiap titik potong yang dicoba diberi label bidang, t dan outcode-nya.",
        )
        .into(),
        items,
    })
}

/// A cut-off piece from a to b.
fn cut(a: [f64; 3], b: [f64; 3]) -> Item {
    Item::Segment {
        a: cabinet(a),
        b: cabinet(b),
        pen: Pen::Cut,
    }
}

/// An input point as a value for a label.
fn vec_val(p: [f64; 3]) -> Val {
    Val::List(
        p.iter()
            .map(|x| {
                Val::Num(crate::num::Shown {
                    value: *x,
                    exact: None,
                    pretty: None,
                })
            })
            .collect(),
    )
}

/// One intersection tried: a dot and a label "plane: t = …, code".
fn tried_marks(plane: &str, v: &Val, style: &Style) -> Vec<Item> {
    let Val::Map(fields) = v else { return vec![] };
    let get = |k: &str| fields.iter().find(|(n, _)| n == k).map(|(_, v)| v);
    let (Some(point), Some(t), Some(code)) = (get("point").and_then(vec_of), get("t"), get("code"))
    else {
        return vec![];
    };
    let kept = matches!(get("kept"), Some(Val::Bool(true)));
    let at = cabinet(point);
    vec![
        Item::Dot {
            at,
            pen: if kept { Pen::Kept } else { Pen::Tried },
        },
        Item::Label {
            at,
            text: format!(
                "{plane}: t = {}, outcode {}",
                style.val_inline(t),
                style.val_inline(code)
            ),
        },
    ]
}
