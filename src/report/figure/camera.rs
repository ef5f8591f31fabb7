//! The camera figure of `basis`, `view` and `solve`'s view part: the world
//! axes, Peye and Pref with the line of sight, Vup (drawn at Pref), the
//! camera axes u, v, n at Peye and the named points with their eye
//! coordinates, all under the cabinet projection.

use super::builders::say;
use super::builders::{
    arrow3, axes3, input3, minus, page_dir, panel, result, vec_of, vec_val, Part,
};
use super::{cabinet, label_at, labelled, Figure, Item, Pen, Place};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::trace::Val;

/// The length u, v, n and Vup are drawn with: 1 for a scene within 8 of
/// the origin, else an eighth of the scene's size (so they stay visible).
pub fn arrow_length(extent: f64) -> f64 {
    if extent <= 8.0 {
        1.0
    } else {
        extent / 8.0
    }
}

/// The pens of u, v, n: bluish green solid, reddish purple dash-dot,
/// vermillion dashed (Okabe–Ito, one pattern each).
pub const AXIS_PENS: [(&str, Pen); 3] = [("u", Pen::Vector), ("v", Pen::Other), ("n", Pen::Cut)];

/// u, v, n are drawn this many times [`arrow_length`] (Vup once).
pub const AXIS_SCALE: f64 = 2.0;

/// The camera panel.
pub fn figure(p: &Part, st: &Style) -> Option<Vec<Figure>> {
    let (pe, pr, up) = (
        input3(p.inp, "eye")?,
        input3(p.inp, "look")?,
        input3(p.inp, "up")?,
    );
    let named = world_points(p);
    let extent = [pe, pr]
        .iter()
        .chain(named.iter().map(|(_, q)| q))
        .flat_map(|q| q.iter().map(|c| c.abs()))
        .fold(1.0, f64::max);
    let len = arrow_length(extent);
    let mut items = axes3(extent * 1.15, ["x", "y", "z"]);
    items.push(Item::Segment {
        a: cabinet(pe),
        b: cabinet(pr),
        pen: Pen::Tried,
    });
    let sight = page_dir(minus(pr, pe));
    let back = [-sight[0], -sight[1]];
    for (at, name, dir) in [(pe, "Peye", back), (pr, "Pref", sight)] {
        items.push(Item::Dot {
            at: cabinet(at),
            pen: Pen::Kept,
        });
        let text = format!("{name} {}", st.val_inline(&vec_val(&at)));
        items.push(label_at(cabinet(at), text, Place::beyond(dir)));
    }
    let norm = up.iter().map(|c| c * c).sum::<f64>().sqrt().max(1e-300);
    let text = format!("Vup = {}", st.val_inline(&vec_val(&up)));
    items.extend(arrow3(pr, up, len / norm, Pen::Given, text));
    // u, v, n: each its own colour and pattern, twice the length (the
    // note says so), so that two axes in nearly one page direction (u and
    // n of the text's example) stay apart.
    for (key, pen) in AXIS_PENS {
        let v = result(p.res, key)?;
        let text = labelled(st, key, v);
        items.extend(arrow3(pe, vec_of(v)?, AXIS_SCALE * len, pen, text));
    }
    let n = st.val_inline(&super::builders::num_val(AXIS_SCALE * len));
    let legend = say(st, FigureMsg::Word(FigWord::CameraAxes));
    items.push(Item::Note {
        text: format!("{legend} {n}"),
    });
    points(p, st, &named, [pe, pr], &mut items);
    Some(vec![panel(st, Panel::Camera, items)])
}

/// The world points of the inputs (`points`: name → [x, y, z]).
fn world_points(p: &Part) -> Vec<(String, [f64; 3])> {
    let Some(o) = p.inp.get("points").and_then(|o| o.as_object()) else {
        return vec![];
    };
    o.keys()
        .filter_map(|k| Some((k.clone(), input3(p.inp.get("points")?, k)?)))
        .collect()
}

/// Each named point: a dot with its name, and a note under the drawing
/// with its world coordinates and its eye coordinates `A' = …` from the
/// results.
fn points(
    p: &Part,
    st: &Style,
    named: &[(String, [f64; 3])],
    given: [[f64; 3]; 2],
    items: &mut Vec<Item>,
) {
    let eye = match result(p.res, "points") {
        Some(Val::Map(m)) => m.clone(),
        _ => vec![],
    };
    for (name, q) in named {
        items.push(Item::Dot {
            at: cabinet(*q),
            pen: Pen::Frame,
        });
        // The name beside the dot (unless the point is Peye or Pref, which
        // are labelled already), the values in a note under the drawing.
        if !given.contains(q) {
            items.push(label_at(cabinet(*q), name.clone(), Place::BelowRight));
        }
        let mut text = format!("{name} {}", st.val_inline(&vec_val(q)));
        if let Some(e) = result(&eye, name) {
            text = format!("{text}: {}", labelled(st, &format!("{name}'"), e));
        }
        items.push(Item::Note { text });
    }
}
