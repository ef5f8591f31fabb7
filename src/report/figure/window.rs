//! The window figure of `window` and `solve`'s window part: the view
//! volume from the eye with the near (and far) window in 3D (cabinet
//! projection), the side view with fovy and top, the window on the near
//! plane with the projected points, and the viewport with their pixels.

use super::builders::{input_num, num_val, nums_of, panel, result, say, vec_val, Part};
use super::{cabinet, label, label_at, labelled, short, Figure, Item, Pen, Place};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::trace::Val;

/// The window's numbers: (left, right, bottom, top) at z = −near.
type Win = [f64; 4];

/// The window results with this prefix (`` or `far_`).
fn win(p: &Part, prefix: &str) -> Option<Win> {
    let n = |k: &str| match result(p.res, &format!("{prefix}{k}"))? {
        Val::Num(s) => Some(s.value),
        _ => None,
    };
    Some([n("left")?, n("right")?, n("bottom")?, n("top")?])
}

/// A result's value as a label writes it.
fn shown(p: &Part, st: &Style, key: &str) -> String {
    result(p.res, key).map(|v| short(st, v)).unwrap_or_default()
}

/// A result as a label in a crowded panel: its exact form when that is
/// at most 12 characters, else its decimal.
fn tiny(p: &Part, st: &Style, key: &str) -> String {
    let Some(Val::Num(s)) = result(p.res, key) else {
        return String::new();
    };
    match &s.pretty {
        Some(e) if e.chars().count() <= 12 => e.replace('-', "−"),
        _ => {
            let plain = crate::stages::trace::Val::Num(crate::num::Shown {
                exact: None,
                pretty: None,
                ..s.clone()
            });
            st.val_inline(&plain)
        }
    }
}

/// The window panels.
pub fn figures(p: &Part, st: &Style) -> Option<Vec<Figure>> {
    let near = input_num(p.inp, "near")?;
    let fovy = input_num(p.inp, "fovy")?;
    let w = win(p, "")?;
    let mut out = vec![frustum(p, st, near, w), side_view(p, st, near, fovy, w)];
    let pts = window_points(p);
    if !pts.is_empty() {
        out.push(near_window(p, st, w, &pts));
    }
    if let Some(f) = viewport(p, st) {
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

/// The view volume in 3D: the eye, the near window, the far window (when
/// given, and within [`FAR_TO_SCALE`]) and the edges from the eye to the
/// farthest window's corners.
fn frustum(p: &Part, st: &Style, near: f64, w: Win) -> Figure {
    let far = input_num(p.inp, "far").zip(win(p, "far_"));
    let to_scale = far.filter(|(f, _)| *f <= FAR_TO_SCALE * near);
    let mut items = Vec::new();
    let (end, end_w) = to_scale.unwrap_or((near, w));
    for c in rect(end_w, -end) {
        items.push(Item::Segment {
            a: [0.0, 0.0],
            b: cabinet(c),
            pen: Pen::Frame,
        });
    }
    items.push(Item::Polygon {
        pts: rect(w, -near).iter().map(|c| cabinet(*c)).collect(),
        pen: Pen::Kept,
    });
    if to_scale.is_none() {
        // The edges run on, dashed, to twice near.
        for c in rect(w, -near) {
            items.push(Item::Segment {
                a: cabinet(c),
                b: cabinet([2.0 * c[0], 2.0 * c[1], 2.0 * c[2]]),
                pen: Pen::Cut,
            });
        }
    }
    if let Some((f, fw)) = far {
        let text = format!(
            "far = {}, far_top = {}",
            st.val_inline(&num_val(f)),
            shown(p, st, "far_top")
        );
        let corner = match to_scale {
            Some(_) => {
                items.push(Item::Polygon {
                    pts: rect(fw, -f).iter().map(|c| cabinet(*c)).collect(),
                    pen: Pen::Given,
                });
                cabinet([fw[1], fw[3], -f])
            }
            None => {
                let note = format!("({})", say(st, FigureMsg::Word(FigWord::NotToScale)));
                let at = cabinet([2.0 * w[1], 2.0 * w[3], -2.0 * near]);
                items.push(label_at(at, note, Place::AboveLeft));
                at
            }
        };
        items.push(label_at(corner, text, Place::AboveLeft));
    }
    eye_at_origin(st, &mut items);
    let top = format!("top = {}", shown(p, st, "top"));
    items.push(label_at(cabinet([0.0, w[3], -near]), top, Place::Above));
    let right = format!("right = {}", shown(p, st, "right"));
    items.push(label_at(cabinet([w[1], 0.0, -near]), right, Place::Right));
    panel(st, Panel::Frustum, items)
}

/// The side view (−z, y): the eye, the lines through bottom and top of the
/// near window, the angle fovy, top and near.
fn side_view(p: &Part, st: &Style, near: f64, fovy: f64, w: Win) -> Figure {
    let mut items = vec![Item::Arrow {
        a: [-0.1 * near, 0.0],
        b: [1.5 * near, 0.0],
        pen: Pen::Frame,
    }];
    items.push(label_at([1.5 * near, 0.0], "−z", Place::Right));
    for y in [w[2], w[3]] {
        items.push(Item::Segment {
            a: [0.0, 0.0],
            b: [1.3 * near, 1.3 * y],
            pen: Pen::Frame,
        });
    }
    items.push(Item::Segment {
        a: [near, w[2]],
        b: [near, w[3]],
        pen: Pen::Kept,
    });
    let half = (fovy / 2.0).to_radians();
    let r = 0.35 * near;
    let arc: Vec<[f64; 2]> = (0..=24)
        .map(|i| {
            let a = -half + 2.0 * half * i as f64 / 24.0;
            [r * a.cos(), r * a.sin()]
        })
        .collect();
    items.push(Item::Path {
        pts: arc,
        pen: Pen::Other,
    });
    let fov = format!("fovy = {}°", st.val_inline(&num_val(fovy)));
    items.push(label_at([r, 0.0], fov, Place::AboveRight));
    eye_at_origin(st, &mut items);
    let top = format!("top = near·tan(fovy/2) = {}", shown(p, st, "top"));
    items.push(label_at([near, w[3]], top, Place::AboveRight));
    let n = format!("near = {}", st.val_inline(&num_val(near)));
    items.push(label_at([near, 0.0], n, Place::BelowRight));
    panel(st, Panel::WindowSide, items)
}

/// The points on the near plane: the command's `points` (x, y), or
/// `solve`'s projected points (`window_points`), with their values.
fn window_points(p: &Part) -> Vec<(String, [f64; 2], Val)> {
    let from = |name: &str, v: &Val| -> Option<(String, [f64; 2], Val)> {
        let n = nums_of(v)?;
        let xy = Val::List(match v {
            Val::List(c) => c.iter().take(2).cloned().collect(),
            _ => return None,
        });
        Some((name.to_string(), [*n.first()?, *n.get(1)?], xy))
    };
    if let Some(Val::Map(m)) = result(p.res, "window_points") {
        return m
            .iter()
            .filter_map(|(k, v)| from(&format!("{k}''"), v))
            .collect();
    }
    let Some(o) = p.inp.get("points").and_then(|o| o.as_object()) else {
        return vec![];
    };
    o.iter()
        .filter_map(|(k, v)| {
            let xs: Option<Vec<f64>> = v.as_array()?.iter().map(|x| x.as_f64()).collect();
            from(k, &super::builders::vec_val(&xs?))
        })
        .collect()
}

/// The near window left..right × bottom..top with the points in it.
fn near_window(p: &Part, st: &Style, w: Win, pts: &[(String, [f64; 2], Val)]) -> Figure {
    let mut items = vec![Item::Polygon {
        pts: vec![[w[0], w[2]], [w[1], w[2]], [w[1], w[3]], [w[0], w[3]]],
        pen: Pen::Kept,
    }];
    for (a, b) in [([w[0], 0.0], [w[1], 0.0]), ([0.0, w[2]], [0.0, w[3]])] {
        items.push(Item::Segment {
            a,
            b,
            pen: Pen::Tried,
        });
    }
    for (at, key, place) in [
        ([w[1], 0.0], "right", Place::Right),
        ([0.0, w[3]], "top", Place::Above),
        ([w[0], 0.0], "left", Place::Left),
        ([0.0, w[2]], "bottom", Place::Below),
    ] {
        items.push(label_at(at, format!("{key} = {}", tiny(p, st, key)), place));
    }
    for (name, at, v) in pts {
        items.push(Item::Dot {
            at: *at,
            pen: Pen::Frame,
        });
        items.push(label(*at, labelled(st, name, v)));
    }
    panel(st, Panel::NearWindow, items)
}

/// The viewport W × H with each point at its pixel position.
fn viewport(p: &Part, st: &Style) -> Option<Figure> {
    let vp = p.inp.get("viewport")?.as_array()?;
    let (vw, vh) = (vp.first()?.as_f64()?, vp.get(1)?.as_f64()?);
    let Some(Val::Map(px)) = result(p.res, "pixels") else {
        return None;
    };
    let mut items = vec![Item::Polygon {
        pts: vec![[0.0, 0.0], [vw, 0.0], [vw, vh], [0.0, vh]],
        pen: Pen::Frame,
    }];
    let origin = st.val_inline(&vec_val(&[0.0, 0.0]));
    items.push(label_at([0.0, 0.0], origin, Place::BelowLeft));
    let size = st.val_inline(&vec_val(&[vw, vh]));
    items.push(label_at([vw, vh], size, Place::AboveRight));
    for (name, v) in px {
        let n = nums_of(v)?;
        let at = [*n.first()?, *n.get(1)?];
        items.push(Item::Dot { at, pen: Pen::Kept });
        items.push(label(at, labelled(st, name, v)));
    }
    Some(panel(st, Panel::Viewport, items))
}

/// The eye: a dot at the origin of the panel, labelled on its left.
fn eye_at_origin(st: &Style, items: &mut Vec<Item>) {
    items.push(Item::Dot {
        at: [0.0, 0.0],
        pen: Pen::Frame,
    });
    let eye = say(st, FigureMsg::Word(FigWord::Eye));
    items.push(label_at([0.0, 0.0], eye, Place::Left));
}
