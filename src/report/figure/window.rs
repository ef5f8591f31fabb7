//! The window figure of `window` and `solve`'s window part: the view
//! volume with the near (and far) window in 3D, seen from outside (an
//! axonometric view with the eye, its apex, outside the windows), the side
//! view with fovy and top, the viewing window on the near plane with the
//! projected points, and the viewport with their pixels.

use super::axo::apex_outside;
use super::builders::{num_val, nums_of, panel, panel3, say, vec_val, Part};
use super::{label, label_toward, labelled, mark, short, Figure, Item, Kind, Pen, Shape};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::trace::Val;
use crate::tutor::key::{Edge, Field};
use crate::tutor::solution::WindowAt;

/// The window's numbers: (left, right, bottom, top) at z = −near.
type Win = [f64; 4];

/// The window's edges on the near plane, or (`far`) on the far one.
fn win(p: &Part, far: bool) -> Option<Win> {
    let n = |e: Edge| match p.field(Field::Edge(e, far))? {
        Val::Num(s) => Some(s.value),
        _ => None,
    };
    Some([
        n(Edge::Left)?,
        n(Edge::Right)?,
        n(Edge::Bottom)?,
        n(Edge::Top)?,
    ])
}

/// A result's value as a label writes it.
fn shown(p: &Part, st: &Style, key: Field) -> String {
    p.field(key).map(|v| short(st, v)).unwrap_or_default()
}

/// A result as a label in a crowded panel: its exact form when that is
/// at most 12 characters, else its decimal.
fn tiny(p: &Part, st: &Style, key: Field) -> String {
    let Some(Val::Num(s)) = p.field(key) else {
        return String::new();
    };
    match &s.pretty {
        Some(e) if e.chars().count() <= 12 => e.replace('-', "−"),
        _ => {
            let plain = crate::stages::trace::Val::Num(crate::num::Shown {
                exact: None,
                pretty: None,
                beyond: None,
                ..s.clone()
            });
            st.val_inline(&plain)
        }
    }
}

/// The window panels of the window part `g`.
pub fn figures(p: &Part, st: &Style, g: &WindowAt) -> Option<Vec<Figure>> {
    let near = g.near;
    let w = win(p, false)?;
    let mut out = vec![frustum(p, st, g, w), side_view(p, st, near, g.fovy, w)];
    let pts = window_points(g);
    if !pts.is_empty() {
        out.push(near_window(p, st, w, &pts));
    }
    if let Some(f) = viewport(p, st, g) {
        out.push(f);
    }
    Some(out)
}

/// The rectangle left..right × bottom..top at depth z.
fn rect(w: Win, z: f64) -> Vec<[f64; 3]> {
    vec![
        [w[0], w[2], z],
        [w[1], w[2], z],
        [w[1], w[3], z],
        [w[0], w[3], z],
    ]
}

/// Beyond this ratio far/near the far window is not drawn to scale (the
/// near window would be a dot): the edges run on, dashed, to twice near.
pub const FAR_TO_SCALE: f64 = 10.0;

/// A line from a to b (no head).
fn seg(a: [f64; 2], b: [f64; 2]) -> Shape {
    Shape::Line { a, b, head: false }
}

/// The view volume in 3D: the eye, the near window, the far window (when
/// given, and within [`FAR_TO_SCALE`]) and the edges from the eye to the
/// farthest window's corners, with top and right marked on the near
/// window.
fn frustum(p: &Part, st: &Style, g: &WindowAt, w: Win) -> Figure {
    let near = g.near;
    let far = g.far.zip(win(p, true));
    let to_scale = far.filter(|(f, _)| *f <= FAR_TO_SCALE * near);
    let mut windows = vec![rect(w, -near)];
    windows.extend(to_scale.map(|(f, fw)| rect(fw, -f)));
    let axo = apex_outside(Some([0.0; 3]), &windows);
    let page = |c: &[f64; 3]| axo.page(*c);
    let mut items = Vec::new();
    let (end, end_w) = to_scale.unwrap_or((near, w));
    for (k, c) in rect(end_w, -end).iter().enumerate() {
        let name = format!("edge {}", k + 1);
        items.push(mark(
            name,
            Kind::Segment,
            Pen::Frame,
            seg([0.0, 0.0], page(c)),
        ));
    }
    let near_rect = Shape::Polygon(rect(w, -near).iter().map(page).collect());
    items.push(mark("near window", Kind::Window, Pen::Kept, near_rect));
    if to_scale.is_none() {
        // The edges run on, dashed, to twice near.
        for (k, c) in rect(w, -near).iter().enumerate() {
            let name = format!("edge {} beyond", k + 1);
            let beyond = seg(page(c), page(&c.map(|x| 2.0 * x)));
            items.push(mark(name, Kind::Segment, Pen::Cut, beyond));
        }
    }
    if let Some((f, fw)) = far {
        let text = format!(
            "far = {}, far_top = {}",
            st.val_inline(&num_val(f)),
            shown(p, st, Field::Edge(Edge::Top, true))
        );
        match to_scale {
            Some(_) => {
                let far_rect = Shape::Polygon(rect(fw, -f).iter().map(page).collect());
                items.push(mark("far window", Kind::Window, Pen::Given, far_rect));
                items.push(label("far window", text));
            }
            None => {
                let note = say(st, FigureMsg::Word(FigWord::NotToScale));
                items.push(Item::Note(format!("{text}: {note}")));
            }
        }
    }
    eye_at_origin(st, &mut items);
    // top and right beside their edges, on the window's outer side.
    let r = rect(w, -near);
    let centre = page(&[(w[0] + w[1]) / 2.0, (w[2] + w[3]) / 2.0, -near]);
    for (edge, a, b) in [(Edge::Top, 2, 3), (Edge::Right, 1, 2)] {
        let key = Field::Edge(edge, false);
        let edge = key.key();
        let (pa, pb) = (page(&r[a]), page(&r[b]));
        items.push(mark(&edge, Kind::Segment, Pen::Kept, seg(pa, pb)));
        let out = [
            (pa[0] + pb[0]) / 2.0 - centre[0],
            (pa[1] + pb[1]) / 2.0 - centre[1],
        ];
        let text = format!("{edge} = {}", shown(p, st, key));
        items.push(label_toward(&edge, text, Some(out)));
    }
    panel3(st, Panel::Frustum, &axo, items)
}

/// The side view (−z, y): the eye, the lines through bottom and top of the
/// near window, the angle fovy, top and near.
fn side_view(p: &Part, st: &Style, near: f64, fovy: f64, w: Win) -> Figure {
    let axis = Shape::Line {
        a: [-0.1 * near, 0.0],
        b: [1.5 * near, 0.0],
        head: true,
    };
    let mut items = vec![mark("−z", Kind::Axis, Pen::Frame, axis)];
    items.push(label_toward("−z", "−z", Some([1.0, 0.0])));
    for (y, name) in [(w[2], "bottom edge"), (w[3], "top edge")] {
        let line = seg([0.0, 0.0], [1.3 * near, 1.3 * y]);
        items.push(mark(name, Kind::Segment, Pen::Frame, line));
    }
    let window = seg([near, w[2]], [near, w[3]]);
    items.push(mark("near window", Kind::Window, Pen::Kept, window));
    let half = (fovy / 2.0).to_radians();
    let r = 0.35 * near;
    let arc: Vec<[f64; 2]> = (0..=24)
        .map(|i| {
            let a = -half + 2.0 * half * i as f64 / 24.0;
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    items.push(mark("fovy", Kind::Arc, Pen::Other, Shape::Path(arc)));
    let fov = format!("fovy = {}°", st.val_inline(&num_val(fovy)));
    items.push(label("fovy", fov));
    eye_at_origin(st, &mut items);
    let top = seg([near, 0.0], [near, w[3]]);
    items.push(mark("top", Kind::Segment, Pen::Kept, top));
    let top = shown(p, st, Field::Edge(Edge::Top, false));
    let text = format!("top = near·tan(fovy/2) = {top}");
    items.push(label("top", text));
    let dist = seg([0.0, 0.0], [near, 0.0]);
    items.push(mark("near", Kind::Segment, Pen::Frame, dist));
    let n = format!("near = {}", st.val_inline(&num_val(near)));
    items.push(label_toward("near", n, Some([0.0, -1.0])));
    panel(st, Panel::WindowSide, items)
}

/// The points on the near plane: the command's points (x, y), labelled
/// by their decimals, or the projected points (A''), with their values.
fn window_points(g: &WindowAt) -> Vec<(String, [f64; 2], Val)> {
    let from = |name: &str, v: &Val| -> Option<(String, [f64; 2], Val)> {
        let n = nums_of(v)?;
        let xy = Val::List(match v {
            Val::List(c) => c.iter().take(2).cloned().collect(),
            _ => return None,
        });
        Some((name.to_string(), [*n.first()?, *n.get(1)?], xy))
    };
    (g.points.iter())
        .filter_map(|(k, v)| match g.projected {
            true => from(&format!("{k}''"), v),
            false => from(k, &vec_val(&nums_of(v)?)),
        })
        .collect()
}

/// The near window left..right × bottom..top with the points in it.
fn near_window(p: &Part, st: &Style, w: Win, pts: &[(String, [f64; 2], Val)]) -> Figure {
    let corners = vec![[w[0], w[2]], [w[1], w[2]], [w[1], w[3]], [w[0], w[3]]];
    let mut items = vec![mark(
        "near window",
        Kind::Window,
        Pen::Kept,
        Shape::Polygon(corners),
    )];
    for (a, b, name) in [
        ([w[0], 0.0], [w[1], 0.0], "x"),
        ([0.0, w[2]], [0.0, w[3]], "y"),
    ] {
        items.push(mark(name, Kind::Axis, Pen::Tried, seg(a, b)));
    }
    for (edge, a, b) in [
        (Edge::Right, [w[1], w[2]], [w[1], w[3]]),
        (Edge::Top, [w[0], w[3]], [w[1], w[3]]),
        (Edge::Left, [w[0], w[2]], [w[0], w[3]]),
        (Edge::Bottom, [w[0], w[2]], [w[1], w[2]]),
    ] {
        let key = Field::Edge(edge, false);
        let edge = key.key();
        items.push(mark(&edge, Kind::Segment, Pen::Kept, seg(a, b)));
        items.push(label(&edge, format!("{edge} = {}", tiny(p, st, key))));
    }
    for (name, at, v) in pts {
        items.push(mark(name, Kind::Point, Pen::Frame, Shape::Dot(*at)));
        items.push(label(name, labelled(st, name, v)));
    }
    panel(st, Panel::NearWindow, items)
}

/// The viewport W × H with each point at its pixel position.
fn viewport(p: &Part, st: &Style, g: &WindowAt) -> Option<Figure> {
    let (vw, vh) = g.viewport?;
    let Some(Val::Map(px)) = p.field(Field::Pixels) else {
        return None;
    };
    let corners = vec![[0.0, 0.0], [vw, 0.0], [vw, vh], [0.0, vh]];
    let mut items = vec![mark(
        "viewport",
        Kind::Window,
        Pen::Frame,
        Shape::Polygon(corners),
    )];
    for (name, at) in [("(0, 0)", [0.0, 0.0]), ("(W, H)", [vw, vh])] {
        items.push(mark(name, Kind::Point, Pen::Frame, Shape::Dot(at)));
        let text = st.val_inline(&vec_val(&at));
        items.push(label_toward(
            name,
            text,
            Some([at[0] - vw / 2.0, at[1] - vh / 2.0]),
        ));
    }
    for (name, v) in px {
        let n = nums_of(v)?;
        let at = [*n.first()?, *n.get(1)?];
        items.push(mark(name, Kind::Point, Pen::Kept, Shape::Dot(at)));
        // a pixel with the decimal beside its exact form, as the steps
        // write it: (100, (100−25√2)/3) ≈ (100, 21.55)
        let full = st.val_inline(v);
        let text = match full.strip_prefix("≈ ") {
            Some(rest) => format!("{name} ≈ {rest}"),
            None => format!("{name} = {full}"),
        };
        items.push(label(name, text));
    }
    Some(panel(st, Panel::Viewport, items))
}

/// The eye: a dot at the origin of the panel, labelled.
fn eye_at_origin(st: &Style, items: &mut Vec<Item>) {
    items.push(mark("eye", Kind::Point, Pen::Frame, Shape::Dot([0.0, 0.0])));
    let eye = say(st, FigureMsg::Word(FigWord::Eye));
    items.push(label_toward("eye", eye, Some([-1.0, 0.0])));
}
