//! The camera figure of `basis`, `view` and `solve`'s view part: the world
//! axes, Peye and Pref with the line of sight, Vup (drawn at Pref), the
//! camera axes u, v, n at Peye and the named points with their eye
//! coordinates, in an axonometric view chosen so that u, v and n (and the
//! world axes) read: at least 15° apart on the page, none shorter than
//! 40 % of the longest.

use super::axo::Axo;
use super::builders::{
    arrow3, axes3, minus, num_val, panel3, result, say, unit, vec_of, vec_val, Part,
};
use super::{label, label_toward, labelled, mark, Figure, Item, Kind, Pen, Shape};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::camera::Camera;
use crate::stages::trace::Val;
use crate::tutor::key::{Axis, Field, Node};
use crate::tutor::solution::P3;

/// The length Vup is drawn with: 1 for a scene within 8 of the origin,
/// else an eighth of the scene's size (so it stays visible).
pub fn arrow_length(extent: f64) -> f64 {
    if extent <= 8.0 {
        1.0
    } else {
        extent / 8.0
    }
}

/// The pens of u, v, n: bluish green solid, reddish purple dash-dot,
/// vermillion dashed (Okabe–Ito, one pattern each).
pub const AXIS_PENS: [(Axis, Pen); 3] = [
    (Axis::U, Pen::Vector),
    (Axis::V, Pen::Other),
    (Axis::N, Pen::Cut),
];

/// u, v, n are drawn this many times [`arrow_length`] (Vup once).
pub const AXIS_SCALE: f64 = 2.0;

/// The world axes' directions.
const XYZ: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// The view of the camera figure: u, v, n and the world axes readable.
pub fn camera_view(uvn: &[[f64; 3]; 3]) -> Axo {
    Axo::choose(super::axo::USUAL, |a| a.readable(uvn).min(a.readable(&XYZ)))
}

/// The camera panel of camera `c` and the world points `named`.
pub fn figure(
    p: &Part,
    st: &Style,
    c: &Camera<f64>,
    named: &[(String, P3)],
) -> Option<Vec<Figure>> {
    let (pe, pr, up): (P3, P3, P3) = (c.pe.into(), c.pr.into(), c.vup.into());
    let mut uvn = [[0.0; 3]; 3];
    for (k, (axis, _)) in AXIS_PENS.iter().enumerate() {
        uvn[k] = vec_of(p.field(Field::Axis(*axis))?)?;
    }
    let axo = camera_view(&uvn);
    let extent = [pe, pr]
        .iter()
        .chain(named.iter().map(|(_, q)| q))
        .flat_map(|q| q.iter().map(|c| c.abs()))
        .fold(1.0, f64::max);
    let len = arrow_length(extent);
    let mut items = axes3(&axo, extent * 1.15, 0.0);
    items.push(mark(
        "line of sight",
        Kind::Segment,
        Pen::Tried,
        Shape::Line {
            a: axo.page(pe),
            b: axo.page(pr),
            head: false,
        },
    ));
    let sight = axo.page(minus(pr, pe));
    for (at, name, dir) in [(pe, "Peye", [-sight[0], -sight[1]]), (pr, "Pref", sight)] {
        items.push(mark(name, Kind::Point, Pen::Kept, Shape::Dot(axo.page(at))));
        let text = format!("{name} {}", st.val_inline(&vec_val(&at)));
        items.push(label_toward(name, text, Some(dir)));
    }
    let text = format!("Vup = {}", st.val_inline(&vec_val(&up)));
    items.extend(arrow3(
        &axo,
        ("Vup", Kind::Arrow),
        pr,
        unit(up),
        len,
        Pen::Given,
        text,
    ));
    // u, v, n: each its own colour and pattern, twice the length (the
    // note says so).
    for (k, (axis, pen)) in AXIS_PENS.iter().enumerate() {
        let key = Field::Axis(*axis).key();
        let text = labelled(st, &key, p.field(Field::Axis(*axis))?);
        let at = (key.as_str(), Kind::Arrow);
        items.extend(arrow3(&axo, at, pe, uvn[k], AXIS_SCALE * len, *pen, text));
    }
    let n = st.val_inline(&num_val(AXIS_SCALE * len));
    let legend = say(st, FigureMsg::Word(FigWord::CameraAxes));
    items.push(Item::Note(format!("{legend} {n}")));
    points(p, st, &axo, named, &mut items);
    Some(vec![panel3(st, Panel::Camera, &axo, items)])
}

/// Each named point: a dot with its name (unless a mark of that name is
/// drawn already: Peye, Pref), and a note under the drawing with its
/// world coordinates and its eye coordinates `A' = …` from the results.
fn points(p: &Part, st: &Style, axo: &Axo, named: &[(String, [f64; 3])], items: &mut Vec<Item>) {
    let eye = match p.field(Field::Points) {
        Some(Val::Map(m)) => m.clone(),
        _ => vec![],
    };
    for (name, q) in named {
        let taken = items
            .iter()
            .any(|it| matches!(it, Item::Mark(m) if m.name == *name));
        if !taken {
            items.push(mark(
                name,
                Kind::Point,
                Pen::Frame,
                Shape::Dot(axo.page(*q)),
            ));
            items.push(label(name, name.clone()));
        }
        let mut text = format!("{name} {}", st.val_inline(&vec_val(q)));
        if let Some(e) = result(&eye, Node::Point(name.clone())) {
            text = format!("{text}: {}", labelled(st, &format!("{name}'"), e));
        }
        items.push(Item::Note(text));
    }
}
