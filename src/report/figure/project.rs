//! The projection figure of `project` and `solve`'s project part: the
//! centre of projection, the view plane and each projector from the centre
//! through the point to its image, in 3D (an axonometric view with the
//! centre of projection outside the view plane); the side view (y–z) with
//! the similar triangles; the images on the view plane.

use super::axo::{apex_outside, Axo};
use super::builders::{axes3, num_val, nums_of, panel, panel3, result, say, Part};
use super::{label, label_toward, labelled, mark, short, Figure, Item, Kind, Pen, Shape};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::projection::Projection;
use crate::stages::trace::Val;
use crate::tutor::key::{Field, Node};

/// The projection asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Proj {
    /// Centre at the origin, plane z = d.
    Plane(f64),
    /// Centre at (0, 0, zprp), plane z = zvp.
    General(f64, f64),
    /// Orthographic onto z = 0.
    Ortho,
}

impl Proj {
    /// The centre of projection (none for the orthographic projection).
    pub fn cop(self) -> Option<[f64; 3]> {
        match self {
            Proj::Plane(_) => Some([0.0; 3]),
            Proj::General(c, _) => Some([0.0, 0.0, c]),
            Proj::Ortho => None,
        }
    }
    /// The view plane's z.
    pub fn plane(self) -> f64 {
        match self {
            Proj::Plane(d) => d,
            Proj::General(_, z) => z,
            Proj::Ortho => 0.0,
        }
    }
    /// The similar triangles' relation, in the text's notation.
    fn relation(self) -> &'static str {
        match self {
            Proj::Plane(_) => "yp/d = y/z  ⇒  yp = d·y/z",
            Proj::General(..) => "yp/(zprp − zvp) = y/(zprp − z)",
            Proj::Ortho => "yp = y",
        }
    }
    /// The plane's label.
    fn plane_label(self, st: &Style) -> String {
        let n = |x: f64| st.val_inline(&num_val(x));
        match self {
            Proj::Plane(d) => format!("z = d = {}", n(d)),
            Proj::General(_, z) => format!("z = zvp = {}", n(z)),
            Proj::Ortho => "z = 0".into(),
        }
    }
}

impl From<&Projection<f64>> for Proj {
    fn from(p: &Projection<f64>) -> Proj {
        match p {
            Projection::Plane { d } => Proj::Plane(*d),
            Projection::General { zprp, zvp } => Proj::General(*zprp, *zvp),
            Projection::Ortho => Proj::Ortho,
        }
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

/// The points: eye coordinates as given (the view part's results when
/// `chained`), images from the results.
fn projected(p: &Part, eyes: &[(String, Val)], chained: bool) -> Vec<Projected> {
    let Some(Val::Map(images)) = p.field(Field::Points) else {
        return vec![];
    };
    images
        .iter()
        .filter_map(|(name, img_val)| {
            let eye_val = result(eyes, Node::Point(name.clone()))?.clone();
            let (e, i) = (nums_of(&eye_val)?, nums_of(img_val)?);
            Some(Projected {
                name: if chained {
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

/// The projection panels: 3D, side view, view plane, of the `eyes`
/// (eye-coordinate points) projected by `proj`.
pub fn figures(
    p: &Part,
    st: &Style,
    proj: &Projection<f64>,
    (eyes, chained): (&[(String, Val)], bool),
) -> Option<Vec<Figure>> {
    let k = Proj::from(proj);
    let pts = projected(p, eyes, chained);
    let (d3, side) = (three_d(k, &pts, st), side_view(k, &pts, st));
    let mut out = vec![d3, side];
    if !pts.is_empty() {
        out.push(view_plane(&pts, st));
    }
    Some(out)
}

/// The largest |coordinate| of the points, their images, the centre and
/// the plane (at least `floor`).
fn extent(k: Proj, pts: &[Projected], floor: f64) -> f64 {
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
fn projector(k: Proj, q: &Projected) -> ([f64; 3], [f64; 3]) {
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
/// least a sixth of the scene, or, when the plane is near the centre of
/// projection (the images then drawn in an inset), 0.8 times its distance
/// (so the centre stays outside it in the view).
fn plane_half(k: Proj, pts: &[Projected], ext: f64) -> f64 {
    let m = 1.4 * image_reach(pts, 0.0);
    match zoomed(k, pts, ext) {
        Some(s) => m.max(0.8 * s.abs()),
        None => m.max(ext / 6.0),
    }
}

/// A round enlargement for an inset: the largest 1, 2 or 5 × 10^k not
/// above x (at least 1).
pub fn round_factor(x: f64) -> f64 {
    if !x.is_finite() || x <= 1.0 {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * p)
        .find(|m| *m <= x)
        .unwrap_or(p)
}

/// The signed distance (along −z) from the centre of projection to the
/// view plane when it is under an eighth of the scene (the images then
/// crowd the centre and are drawn again, enlarged, in an inset); none for
/// the orthographic projection or a plane far enough away.
fn zoomed(k: Proj, pts: &[Projected], ext: f64) -> Option<f64> {
    let c = k.cop()?;
    let s = c[2] - k.plane();
    (!pts.is_empty() && s != 0.0 && 8.0 * s.abs() < ext).then_some(s)
}

/// The largest |xp|, |yp| of the images (at least `floor`).
fn image_reach(pts: &[Projected], floor: f64) -> f64 {
    pts.iter()
        .map(|q| q.img[0].abs().max(q.img[1].abs()))
        .fold(floor, f64::max)
}

/// A line from a to b (no head).
fn seg(a: [f64; 2], b: [f64; 2]) -> Shape {
    Shape::Line { a, b, head: false }
}

/// The square of half size h about c on the page.
fn square(c: [f64; 2], h: f64) -> Vec<[f64; 2]> {
    [[-h, -h], [h, -h], [h, h], [-h, h]]
        .iter()
        .map(|d| [c[0] + d[0], c[1] + d[1]])
        .collect()
}

/// The inset of the 3D panel: the view plane seen from the front (xp to
/// the right, yp up), enlarged m times, to the right of the drawing, with
/// each image on it, joined to the plane by a line.
fn plane_inset(k: Proj, pts: &[Projected], ext: f64, axo: &Axo, st: &Style, items: &mut Vec<Item>) {
    let b = Figure {
        items: items.clone(),
        ..Figure::default()
    }
    .bounds();
    let hi = 0.3 * ext;
    let m = round_factor(0.8 * hi / image_reach(pts, 1e-12));
    let (cx, cy) = (b[2] + 1.5 * hi, 0.5 * (b[1] + b[3]));
    let times = st.val_inline(&num_val(m));
    let name = format!("view plane (×{times})");
    items.push(mark(
        &name,
        Kind::Plane,
        Pen::Given,
        Shape::Polygon(square([cx, cy], hi)),
    ));
    let h = plane_half(k, pts, ext);
    let edge = axo.page([h, 0.0, k.plane()]);
    items.push(mark(
        "inset link",
        Kind::Segment,
        Pen::Given,
        seg(edge, [cx - hi, cy]),
    ));
    for (a, b, axis) in [([-hi, 0.0], [hi, 0.0], "xp"), ([0.0, -hi], [0.0, hi], "yp")] {
        let (a, b) = ([cx + a[0], cy + a[1]], [cx + b[0], cy + b[1]]);
        items.push(mark(axis, Kind::Axis, Pen::Frame, seg(a, b)));
    }
    let text = format!("{} (×{times})", k.plane_label(st));
    items.push(label_toward(&name, text, Some([0.0, 1.0])));
    for q in pts {
        let at = [cx + m * q.img[0], cy + m * q.img[1]];
        let img = image_names(&q.name);
        items.push(mark(&img, Kind::Point, Pen::Kept, Shape::Dot(at)));
        items.push(label(&img, img.clone()));
    }
    let word = say(st, FigureMsg::Word(FigWord::Zoomed));
    items.push(Item::Note(format!("{word} ×{times}")));
}

/// The centre of projection's label, `COP` as the text abbreviates it,
/// and a note with its name.
fn cop_label(st: &Style) -> [Item; 2] {
    let name = say(st, FigureMsg::Word(FigWord::Cop));
    [label("COP", "COP"), Item::Note(format!("COP: {name}"))]
}

/// The view plane's corners in 3D.
fn plane_corners(k: Proj, h: f64) -> Vec<[f64; 3]> {
    [[-h, -h], [h, -h], [h, h], [-h, h]]
        .iter()
        .map(|c| [c[0], c[1], k.plane()])
        .collect()
}

/// The 3D panel.
fn three_d(k: Proj, pts: &[Projected], st: &Style) -> Figure {
    let ext = extent(k, pts, 1.0);
    let h = plane_half(k, pts, ext);
    let axo = apex_outside(k.cop(), &[plane_corners(k, h)]);
    let zlo = pts
        .iter()
        .map(|q| q.eye[2])
        .fold(k.plane(), f64::min)
        .min(0.0);
    let mut items = axes3(&axo, ext * 0.3, zlo - 0.1 * ext);
    let corners = plane_corners(k, h).iter().map(|c| axo.page(*c)).collect();
    items.push(mark(
        "view plane",
        Kind::Plane,
        Pen::Given,
        Shape::Polygon(corners),
    ));
    items.push(label("view plane", k.plane_label(st)));
    if let Some(c) = k.cop() {
        items.push(mark(
            "COP",
            Kind::Point,
            Pen::Frame,
            Shape::Dot(axo.page(c)),
        ));
        items.extend(cop_label(st));
    }
    let zoom = zoomed(k, pts, ext).is_some();
    for q in pts {
        let (a, b) = projector(k, q);
        let name = format!("projector {}", q.name);
        items.push(mark(
            name,
            Kind::Segment,
            Pen::Tried,
            seg(axo.page(a), axo.page(b)),
        ));
        items.push(mark(
            &q.name,
            Kind::Point,
            Pen::Frame,
            Shape::Dot(axo.page(q.eye)),
        ));
        items.push(label(&q.name, labelled(st, &q.name, &q.eye_val)));
        if !zoom {
            let img = image_names(&q.name);
            items.push(mark(
                &img,
                Kind::Point,
                Pen::Kept,
                Shape::Dot(axo.page(q.img)),
            ));
            items.push(label(&img, img.clone()));
        }
    }
    if zoom {
        plane_inset(k, pts, ext, &axo, st, &mut items);
    }
    panel3(st, Panel::Projection, &axo, items)
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
fn side_view(k: Proj, pts: &[Projected], st: &Style) -> Figure {
    let ext = extent(k, pts, 0.0).max(1e-9);
    let zv = k.plane();
    let xs = pts.iter().map(|q| -q.eye[2]).chain([-zv, 0.0]);
    let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    let m = 0.08 * (hi - lo).max(ext * 0.1);
    let axis = Shape::Line {
        a: [lo - m, 0.0],
        b: [hi + m, 0.0],
        head: true,
    };
    let mut items = vec![mark("−z", Kind::Axis, Pen::Frame, axis)];
    items.push(label_toward("−z", "−z", Some([1.0, 0.0])));
    let h = pts
        .iter()
        .map(|q| q.eye[1].abs().max(q.img[1].abs()))
        .fold(0.0, f64::max)
        .max(ext * 0.05);
    let plane = seg([-zv, -1.2 * h], [-zv, 1.2 * h]);
    items.push(mark("view plane", Kind::Plane, Pen::Given, plane));
    items.push(label("view plane", k.plane_label(st)));
    if let Some(c) = k.cop() {
        items.push(mark("COP", Kind::Point, Pen::Frame, Shape::Dot(side(c))));
        items.extend(cop_label(st));
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
    let groups: Vec<(&Projected, String)> =
        shared.iter().map(|(q, n)| (*q, n.join(", "))).collect();
    let zoom = zoomed(k, pts, ext);
    for (q, names) in &groups {
        items.extend(triangle_marks(k, q, names, st));
        if zoom.is_none() {
            let (pi, foot) = (side(q.img), [-q.img[2], 0.0]);
            items.extend(image_marks([pi, foot], q, names, st));
        }
    }
    items.push(Item::Note(k.relation().to_string()));
    if let Some(s) = zoom {
        let at = [lo - m, -1.2 * h - 0.25 * h];
        side_inset(k, &groups, s, (at, 0.9 * (hi - lo)), st, &mut items);
    }
    panel(st, Panel::ProjectionSide, items)
}

/// Component i of a value as a label writes it.
fn val_at(st: &Style, v: &Val, i: usize) -> String {
    comp(v, i).map(|c| short(st, c)).unwrap_or_default()
}

/// One point (or several with the same y and z, `names`) in the side
/// view: its projector, its leg y from the axis, its dot and its label
/// `A': y = …, z = …`.
fn triangle_marks(k: Proj, q: &Projected, names: &str, st: &Style) -> Vec<Item> {
    let (a, b) = projector(k, q);
    let pe = side(q.eye);
    let (y, z) = (val_at(st, &q.eye_val, 1), val_at(st, &q.eye_val, 2));
    vec![
        mark(
            format!("projector {names}"),
            Kind::Segment,
            Pen::Tried,
            seg(side(a), side(b)),
        ),
        mark(
            format!("y {names}"),
            Kind::Segment,
            Pen::Frame,
            seg([pe[0], 0.0], pe),
        ),
        mark(names, Kind::Point, Pen::Frame, Shape::Dot(pe)),
        label(names, format!("{names}: y = {y}, z = {z}")),
    ]
}

/// An image in a side view at `at[0]`: the leg yp from its foot `at[1]`
/// on the axis, the dot, the label `A'': yp = …`.
fn image_marks(at: [[f64; 2]; 2], q: &Projected, names: &str, st: &Style) -> [Item; 3] {
    let img = image_names(names);
    let text = format!("{img}: yp = {}", val_at(st, &q.img_val, 1));
    [
        mark(
            format!("yp {img}"),
            Kind::Segment,
            Pen::Kept,
            seg(at[1], at[0]),
        ),
        mark(&img, Kind::Point, Pen::Kept, Shape::Dot(at[0])),
        label(&img, text),
    ]
}

/// The inset of the side view, under it with its left end at `at.0`: the
/// part near the centre of projection, from the centre to 1.5 times the
/// plane's distance `s`, enlarged m times (uniformly, so each small
/// triangle keeps its shape: yp/d = y/z), about `at.1` wide. In it: the
/// axis, the plane, the centre, each projector and each image with its
/// leg yp and label.
fn side_inset(
    k: Proj,
    groups: &[(&Projected, String)],
    s: f64,
    at: ([f64; 2], f64),
    st: &Style,
    items: &mut Vec<Item>,
) {
    let c = side(k.cop().unwrap_or_default());
    let w = 1.5 * s;
    let yr = 1.5
        * groups
            .iter()
            .map(|(q, _)| q.img[1].abs())
            .fold(0.1 * s.abs(), f64::max);
    let m = round_factor(at.1 / w.abs());
    // Page point of a side-view point (−z, y) in the inset.
    let x0 = at.0[0] + (-w * m).max(0.0);
    let y0 = at.0[1] - yr * m;
    let f = |p: [f64; 2]| [x0 + (p[0] - c[0]) * m, y0 + p[1] * m];
    let times = st.val_inline(&num_val(m));
    let frame = [[c[0], -yr], [c[0] + w, -yr], [c[0] + w, yr], [c[0], yr]];
    let inset = format!("inset (×{times})");
    let outline = Shape::Polygon(frame.iter().map(|p| f(*p)).collect());
    items.push(mark(&inset, Kind::Window, Pen::Frame, outline));
    let axis = seg(f(c), f([c[0] + w, 0.0]));
    items.push(mark(format!("−z (×{times})"), Kind::Axis, Pen::Frame, axis));
    let zv = -k.plane();
    let name = format!("view plane (×{times})");
    let plane = seg(f([zv, -yr]), f([zv, yr]));
    items.push(mark(&name, Kind::Plane, Pen::Given, plane));
    items.push(label(&name, format!("{} (×{times})", k.plane_label(st))));
    items.push(mark(
        format!("COP (×{times})"),
        Kind::Point,
        Pen::Frame,
        Shape::Dot(f(c)),
    ));
    for (q, names) in groups {
        let pe = side(q.eye);
        let t = w / (pe[0] - c[0]);
        let end = [c[0] + t * (pe[0] - c[0]), c[1] + t * (pe[1] - c[1])];
        let proj = format!("projector {names} (×{times})");
        items.push(mark(proj, Kind::Segment, Pen::Tried, seg(f(c), f(end))));
        let pi = side(q.img);
        items.extend(image_marks([f(pi), f([pi[0], 0.0])], q, names, st));
    }
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
        items.push(mark(
            name,
            Kind::Axis,
            Pen::Frame,
            Shape::Line { a, b, head: true },
        ));
        items.push(label_toward(name, name, Some([b[0] - a[0], b[1] - a[1]])));
    }
    for q in pts {
        let at = [q.img[0], q.img[1]];
        let xy = match &q.img_val {
            Val::List(c) => Val::List(c.iter().take(2).cloned().collect()),
            v => v.clone(),
        };
        let name = image_names(&q.name);
        items.push(mark(&name, Kind::Point, Pen::Kept, Shape::Dot(at)));
        items.push(label(&name, labelled(st, &name, &xy)));
    }
    let mut f = panel(st, Panel::ViewPlane, items);
    f.height = Some(300.0);
    f
}
