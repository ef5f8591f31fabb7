//! The projection figure of `project` and `solve`'s project part: the
//! centre of projection, the view plane and each projector from the centre
//! through the point to its image, in 3D (cabinet projection); the side
//! view (y–z) with the similar triangles; the images on the view plane.

use super::builders::{axes3, input_num, num_val, nums_of, panel, result, say, vec_val, Part};
use super::{cabinet, label, label_at, labelled, short, Figure, Item, Pen, Place};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::trace::Val;

/// The projection asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// Centre at the origin, plane z = d.
    Plane(f64),
    /// Centre at (0, 0, zprp), plane z = zvp.
    General(f64, f64),
    /// Orthographic onto z = 0.
    Ortho,
}

impl Kind {
    /// The centre of projection (none for the orthographic projection).
    pub fn cop(self) -> Option<[f64; 3]> {
        match self {
            Kind::Plane(_) => Some([0.0; 3]),
            Kind::General(c, _) => Some([0.0, 0.0, c]),
            Kind::Ortho => None,
        }
    }
    /// The view plane's z.
    pub fn plane(self) -> f64 {
        match self {
            Kind::Plane(d) => d,
            Kind::General(_, z) => z,
            Kind::Ortho => 0.0,
        }
    }
    /// The similar triangles' relation, in the text's notation.
    fn relation(self) -> &'static str {
        match self {
            Kind::Plane(_) => "yp/d = y/z  ⇒  yp = d·y/z",
            Kind::General(..) => "yp/(zprp − zvp) = y/(zprp − z)",
            Kind::Ortho => "yp = y",
        }
    }
    /// The plane's label.
    fn plane_label(self, st: &Style) -> String {
        let n = |x: f64| st.val_inline(&num_val(x));
        match self {
            Kind::Plane(d) => format!("z = d = {}", n(d)),
            Kind::General(_, z) => format!("z = zvp = {}", n(z)),
            Kind::Ortho => "z = 0".into(),
        }
    }
}

/// The projection of the inputs (`projection`: `d`, `cop` and `plane`, or
/// `ortho`).
fn kind(p: &Part) -> Option<Kind> {
    let j = p.inp.get("projection")?;
    if let Some(d) = input_num(j, "d") {
        return Some(Kind::Plane(d));
    }
    match (input_num(j, "cop"), input_num(j, "plane")) {
        (Some(c), Some(z)) => Some(Kind::General(c, z)),
        _ => j.get("ortho").and(Some(Kind::Ortho)),
    }
}

/// One point: its name as drawn, its eye coordinates and its image (as
/// numbers and as the values the steps show).
struct Projected {
    name: String,
    eye: [f64; 3],
    eye_val: Val,
    img: [f64; 3],
    img_val: Val,
}

/// The points: eye coordinates from `solve`'s steps (`eye`) or the
/// inputs, images from the results.
fn projected(p: &Part) -> Vec<Projected> {
    let Some(Val::Map(images)) = result(p.res, "points") else {
        return vec![];
    };
    let from_solve = matches!(result(p.res, "eye"), Some(Val::Map(_)));
    let eye_of = |name: &str| -> Option<Val> {
        match result(p.res, "eye") {
            Some(Val::Map(m)) => result(m, name).cloned(),
            _ => {
                // The step that projects the point shows it (exact forms).
                let image = format!("{name}''");
                let step = p
                    .steps
                    .iter()
                    .find(|s| s.result.iter().any(|(k, _)| *k == image));
                if let Some(v) = step.and_then(|s| result(&s.values, name)) {
                    return Some(v.clone());
                }
                let a = p.inp.get("points")?.get(name)?.as_array()?;
                let xs: Option<Vec<f64>> = a.iter().map(|x| x.as_f64()).collect();
                Some(vec_val(&xs?))
            }
        }
    };
    images
        .iter()
        .filter_map(|(name, img_val)| {
            let eye_val = eye_of(name)?;
            let (e, i) = (nums_of(&eye_val)?, nums_of(img_val)?);
            Some(Projected {
                name: if from_solve {
                    format!("{name}'")
                } else {
                    name.clone()
                },
                eye: [*e.first()?, *e.get(1)?, *e.get(2)?],
                eye_val,
                img: [*i.first()?, *i.get(1)?, *i.get(2).unwrap_or(&0.0)],
                img_val: img_val.clone(),
            })
        })
        .collect()
}

/// The projection panels: 3D, side view, view plane.
pub fn figures(p: &Part, st: &Style) -> Option<Vec<Figure>> {
    let k = kind(p)?;
    let pts = projected(p);
    let (d3, side) = (three_d(k, &pts, st), side_view(k, &pts, st));
    let mut out = vec![d3, side];
    if !pts.is_empty() {
        out.push(view_plane(&pts, st));
    }
    Some(out)
}

/// The largest |coordinate| of the points, their images, the centre and
/// the plane (at least `floor`).
fn extent(k: Kind, pts: &[Projected], floor: f64) -> f64 {
    let mut e = k.plane().abs().max(floor);
    if let Some(c) = k.cop() {
        e = e.max(c[2].abs());
    }
    for q in pts {
        for c in q.eye.iter().chain(&q.img) {
            e = e.max(c.abs());
        }
    }
    e
}

/// Where a projector starts and ends: from the centre (or, orthographic,
/// from the point) to the farther of the point and its image.
fn projector(k: Kind, q: &Projected) -> ([f64; 3], [f64; 3]) {
    let Some(c) = k.cop() else {
        return (q.eye, q.img);
    };
    let dist = |a: [f64; 3]| (0..3).map(|i| (a[i] - c[i]).powi(2)).sum::<f64>();
    let far = if dist(q.eye) >= dist(q.img) {
        q.eye
    } else {
        q.img
    };
    (c, far)
}

/// The half size of the view plane drawn: beyond every image, and at
/// least a sixth of the scene.
fn plane_half(pts: &[Projected], ext: f64) -> f64 {
    let m = pts
        .iter()
        .map(|q| q.img[0].abs().max(q.img[1].abs()))
        .fold(0.0, f64::max);
    (1.4 * m).max(ext / 6.0)
}

/// The 3D panel.
fn three_d(k: Kind, pts: &[Projected], st: &Style) -> Figure {
    let ext = extent(k, pts, 1.0);
    let zv = k.plane();
    let mut items = axes3(ext * 0.3, ["x", "y", "z"]);
    let zlo = pts.iter().map(|q| q.eye[2]).fold(zv, f64::min).min(0.0);
    items.push(Item::Segment {
        a: cabinet([0.0; 3]),
        b: cabinet([0.0, 0.0, zlo - 0.1 * ext]),
        pen: Pen::Frame,
    });
    let h = plane_half(pts, ext);
    let corners = [[-h, -h], [h, -h], [h, h], [-h, h]];
    items.push(Item::Polygon {
        pts: corners.iter().map(|c| cabinet([c[0], c[1], zv])).collect(),
        pen: Pen::Given,
    });
    items.push(label_at(
        cabinet([h, h, zv]),
        k.plane_label(st),
        Place::Right,
    ));
    if let Some(c) = k.cop() {
        items.push(Item::Dot {
            at: cabinet(c),
            pen: Pen::Frame,
        });
        let text = say(st, FigureMsg::Word(FigWord::Cop));
        items.push(label_at(cabinet(c), text, Place::AboveLeft));
    }
    for q in pts {
        let (a, b) = projector(k, q);
        items.push(Item::Segment {
            a: cabinet(a),
            b: cabinet(b),
            pen: Pen::Tried,
        });
        items.push(Item::Dot {
            at: cabinet(q.eye),
            pen: Pen::Frame,
        });
        items.push(label_at(
            cabinet(q.eye),
            labelled(st, &q.name, &q.eye_val),
            Place::BelowRight,
        ));
        items.push(Item::Dot {
            at: cabinet(q.img),
            pen: Pen::Kept,
        });
    }
    super::builders::panel(st, Panel::Projection, items)
}

/// A point of the side view: (−z, y).
fn side(p: [f64; 3]) -> [f64; 2] {
    [-p[2], p[1]]
}

/// Component i of a vector value.
fn comp(v: &Val, i: usize) -> Option<&Val> {
    match v {
        Val::List(xs) => xs.get(i),
        _ => None,
    }
}

/// The side view: the z axis, the plane, the centre, each projector and
/// the legs y (point) and yp (image) of the similar triangles.
fn side_view(k: Kind, pts: &[Projected], st: &Style) -> Figure {
    let ext = extent(k, pts, 0.0).max(1e-9);
    let zv = k.plane();
    let xs = pts.iter().map(|q| -q.eye[2]).chain([-zv, 0.0]);
    let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    let m = 0.08 * (hi - lo).max(ext * 0.1);
    let mut items = vec![Item::Arrow {
        a: [lo - m, 0.0],
        b: [hi + m, 0.0],
        pen: Pen::Frame,
    }];
    items.push(label_at([hi + m, 0.0], "−z", Place::Right));
    let h = pts
        .iter()
        .map(|q| q.eye[1].abs().max(q.img[1].abs()))
        .fold(0.0, f64::max)
        .max(ext * 0.05);
    items.push(Item::Segment {
        a: [-zv, -1.2 * h],
        b: [-zv, 1.2 * h],
        pen: Pen::Given,
    });
    items.push(label_at([-zv, -1.2 * h], k.plane_label(st), Place::Below));
    if let Some(c) = k.cop() {
        items.push(Item::Dot {
            at: side(c),
            pen: Pen::Frame,
        });
        let text = say(st, FigureMsg::Word(FigWord::Cop));
        items.push(label_at(side(c), text, Place::AboveLeft));
    }
    // Points with the same (y, z) share one triangle: B', C': y = …
    let mut shared: Vec<(&Projected, Vec<&str>)> = Vec::new();
    for q in pts {
        let same = |o: &Projected| side(o.eye) == side(q.eye) && side(o.img) == side(q.img);
        match shared.iter_mut().find(|(o, _)| same(o)) {
            Some((_, names)) => names.push(&q.name),
            None => shared.push((q, vec![&q.name])),
        }
    }
    for (q, names) in shared {
        items.extend(triangle_marks(k, q, &names.join(", "), st));
    }
    items.push(label([lo - m, 1.2 * h], k.relation()));
    panel(st, Panel::ProjectionSide, items)
}

/// One point's marks in the side view: the projector, the legs y and yp,
/// the dots and their labels.
fn triangle_marks(k: Kind, q: &Projected, names: &str, st: &Style) -> Vec<Item> {
    let (a, b) = projector(k, q);
    let (pe, pi) = (side(q.eye), side(q.img));
    let up = |y: f64| if y >= 0.0 { Place::Above } else { Place::Below };
    let val = |v: &Val, i: usize| comp(v, i).map(|c| short(st, c)).unwrap_or_default();
    vec![
        Item::Segment {
            a: side(a),
            b: side(b),
            pen: Pen::Tried,
        },
        Item::Segment {
            a: [pe[0], 0.0],
            b: pe,
            pen: Pen::Frame,
        },
        Item::Segment {
            a: [pi[0], 0.0],
            b: pi,
            pen: Pen::Kept,
        },
        Item::Dot {
            at: pe,
            pen: Pen::Frame,
        },
        Item::Dot {
            at: pi,
            pen: Pen::Kept,
        },
        label_at(
            pe,
            format!(
                "{names}: y = {}, z = {}",
                val(&q.eye_val, 1),
                val(&q.eye_val, 2)
            ),
            up(pe[1]),
        ),
        label_at(
            pe,
            format!("{}: yp = {}", image_names(names), val(&q.img_val, 1)),
            up(pe[1]),
        ),
    ]
}

/// The names of the images of named points: `A', B'` → `A'', B''`.
fn image_names(names: &str) -> String {
    names
        .split(", ")
        .map(|n| format!("{}''", n.trim_end_matches('\'')))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The images on the view plane (xp, yp).
fn view_plane(pts: &[Projected], st: &Style) -> Figure {
    // The axes reach a little beyond the images on each side.
    let range = |i: usize| {
        let (lo, hi) = pts.iter().fold((0.0f64, 0.0f64), |(l, h), q| {
            (l.min(q.img[i]), h.max(q.img[i]))
        });
        let pad = 0.25 * (hi - lo).max(1e-9);
        (lo - pad, hi + pad)
    };
    let ((x0, x1), (y0, y1)) = (range(0), range(1));
    let mut items = Vec::new();
    for (a, b, name) in [([x0, 0.0], [x1, 0.0], "xp"), ([0.0, y0], [0.0, y1], "yp")] {
        items.push(Item::Arrow {
            a,
            b,
            pen: Pen::Frame,
        });
        items.push(label_at(b, name, Place::beyond([b[0], b[1]])));
    }
    for q in pts {
        let at = [q.img[0], q.img[1]];
        items.push(Item::Dot { at, pen: Pen::Kept });
        let xy = match &q.img_val {
            Val::List(c) => Val::List(c.iter().take(2).cloned().collect()),
            v => v.clone(),
        };
        let name = image_names(&q.name);
        items.push(label(at, labelled(st, &name, &xy)));
    }
    panel(st, Panel::ViewPlane, items)
}
