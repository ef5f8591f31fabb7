//! The clip figure of `clip` and `solve`'s clip parts, in two panels.
//!
//! In 3D (an axonometric view chosen so that the box, the ends and the
//! intersections read): the axes x, y, z; the box, its hidden edges
//! dashed; each of its six planes named by its equation and the text's
//! word (x = 0 kiri … z = 3 belakang); P0 and P1 with their region codes;
//! the segment, its kept part solid and the cut-off parts dashed; each
//! intersection tried, and the kept part's ends with their coordinates.
//!
//! Along the segment, P(t) = P0 + t·(P1 − P0) from t = 0 (P0, at the top)
//! to t = 1 (P1): each intersection tried at its t with its plane, its
//! point and its code, so the kept part between them reads as the steps
//! find it.

use super::axo::{diameter, Axo};
use super::builders::{dot, minus, num_val, panel, panel3, result, say, vec_of, vec_val, Part};
use super::{exact, label_near, label_short, label_toward, mark, Figure, Item, Kind, Pen, Shape};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::clip::{PLANES, PLANE_KEYS};
use crate::stages::trace::Val;
use crate::tutor::key::{Cut, Field};
use crate::tutor::solution::ClipAt;

/// One intersection tried, as the results give it.
struct Tried {
    /// The plane's bit (0 = left … 5 = back) and key (`left`).
    bit: usize,
    /// t.
    t: f64,
    /// t as the steps show it.
    t_val: Val,
    /// The point P(t).
    point: [f64; 3],
    /// The point as the steps show it.
    point_val: Val,
    /// Its region code as text.
    code: String,
    /// Whether it bounds the kept part.
    kept: bool,
}

/// The clip problem: the box, the ends, their codes, the intersections
/// tried and the kept part (if any).
struct Clip {
    lo: [f64; 3],
    hi: [f64; 3],
    ends: [[f64; 3]; 2],
    codes: [String; 2],
    tried: Vec<Tried>,
    kept: Option<[[f64; 3]; 2]>,
}

fn read(p: &Part, st: &Style, g: &ClipAt) -> Option<Clip> {
    let code = |k: Field| p.field(k).map(|v| st.val_inline(v)).unwrap_or_default();
    let mut tried = Vec::new();
    if let Some(Val::Map(m)) = p.field(Field::Intersections) {
        for (key, v) in m {
            let Val::Map(f) = v else { continue };
            let (Some(bit), Some(t_val), Some(point_val), Some(c)) = (
                PLANE_KEYS.iter().position(|k| k == key),
                result(f, Cut::T),
                result(f, Cut::Point),
                result(f, Cut::Code),
            ) else {
                continue;
            };
            let Val::Num(t) = t_val else { continue };
            tried.push(Tried {
                bit,
                t: t.value,
                t_val: t_val.clone(),
                point: vec_of(point_val)?,
                point_val: point_val.clone(),
                code: st.val_inline(c),
                kept: matches!(result(f, Cut::Kept), Some(Val::Bool(true))),
            });
        }
    }
    let kept = match p.field(Field::Segment) {
        Some(Val::List(e)) if e.len() == 2 => Some([vec_of(&e[0])?, vec_of(&e[1])?]),
        _ => None,
    };
    Some(Clip {
        lo: g.min,
        hi: g.max,
        ends: g.ends,
        codes: [code(Field::Code0), code(Field::Code1)],
        tried,
        kept,
    })
}

/// The clip panels of the clipping `g`: in 3D, and along the segment.
pub(super) fn figures(p: &Part, st: &Style, g: &ClipAt) -> Option<Vec<Figure>> {
    let c = read(p, st, g)?;
    let axo = view(&c);
    Some(vec![three_d(&c, &axo, st), along(&c, st)])
}

/// The view of the box, mirrored in z as the text's planes read (x to the
/// right, y up, z away from the reader: the front face z = zmin toward
/// the reader, [`Axo::mirrored`]): the axes readable, no face seen
/// edge-on (|w_k| ≥ 0.15), and the ends and intersections apart (each
/// distance drawn at no less than 40 % of its length).
fn view(c: &Clip) -> Axo {
    let mut pts: Vec<[f64; 3]> = c.ends.to_vec();
    pts.extend(c.tried.iter().map(|t| t.point));
    let xyz = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    Axo::choose_in(super::axo::USUAL, true, |a| {
        let w = a.toward();
        let mut q = a.readable(&xyz);
        q = q.min(w.iter().fold(f64::MAX, |m, x| m.min(x.abs())) / 0.15);
        // The reader on the front's side (z < zmin), so x runs right.
        q = q.min(-w[2] / 0.15);
        for (i, p) in pts.iter().enumerate() {
            for r in &pts[..i] {
                let d = minus(*p, *r);
                let len = dot(d, d).sqrt();
                if len > 1e-9 {
                    let pd = a.page(d);
                    q = q.min(pd[0].hypot(pd[1]) / len / 0.4);
                }
            }
        }
        q
    })
}

/// The box's corner i (bit 0: x at max, bit 1: y, bit 2: z).
fn corner(c: &Clip, i: usize) -> [f64; 3] {
    [0, 1, 2].map(|k| if i >> k & 1 == 0 { c.lo[k] } else { c.hi[k] })
}

/// The twelve edges, each with its pen: those at the corner farthest from
/// the viewer are hidden (dashed).
fn edges(c: &Clip, axo: &Axo) -> Shape {
    let back = (0..8)
        .min_by(|i, j| {
            axo.depth(corner(c, *i))
                .total_cmp(&axo.depth(corner(c, *j)))
        })
        .unwrap_or(0);
    let mut out = Vec::new();
    for i in 0..8usize {
        for bit in [1usize, 2, 4] {
            if i & bit == 0 {
                let hidden = i == back || i | bit == back;
                let pen = if hidden { Pen::Hidden } else { Pen::Frame };
                out.push((axo.page(corner(c, i)), axo.page(corner(c, i | bit)), pen));
            }
        }
    }
    Shape::Edges(out)
}

/// The face of plane `bit` (its four corners).
fn face(c: &Clip, bit: usize) -> [[f64; 3]; 4] {
    let (axis, is_max) = (PLANES[bit].0, PLANES[bit].1);
    let (j, k) = ((axis + 1) % 3, (axis + 2) % 3);
    let at = |a: bool, b: bool| {
        let mut p = if is_max { c.hi } else { c.lo };
        p[j] = if a { c.hi[j] } else { c.lo[j] };
        p[k] = if b { c.hi[k] } else { c.lo[k] };
        p
    };
    [
        at(false, false),
        at(true, false),
        at(true, true),
        at(false, true),
    ]
}

/// The middle of the box.
fn mid3(c: &Clip) -> [f64; 3] {
    [0, 1, 2].map(|k| (c.lo[k] + c.hi[k]) / 2.0)
}

/// Where a plane's label goes first: beyond its face on its outer side
/// (where the points whose bit it sets lie), just outside the box as drawn.
fn outside(c: &Clip, axo: &Axo, bit: usize, size: f64) -> [f64; 2] {
    let hull: Vec<[f64; 2]> = (0..8).map(|i| axo.page(corner(c, i))).collect();
    let corners = face(c, bit);
    let mid = [0, 1, 2].map(|k| corners.iter().map(|p| p[k]).sum::<f64>() / 4.0);
    let (axis, sign) = (PLANES[bit].0, if PLANES[bit].1 { 1.0 } else { -1.0 });
    let mut p = axo.page(mid);
    for step in 1..=15 {
        let mut q = mid;
        q[axis] += sign * 0.1 * f64::from(step) * size;
        p = axo.page(q);
        if !inside_hull(p, &hull, 0.04 * diameter(&hull)) {
            break;
        }
    }
    p
}

/// Whether p is inside the convex hull of `pts` or within `margin` of it.
fn inside_hull(p: [f64; 2], pts: &[[f64; 2]], margin: f64) -> bool {
    // p is outside when some direction separates it from every point.
    (0..72).all(|k| {
        let a = f64::from(k) * 5f64.to_radians();
        let d = [a.cos(), a.sin()];
        let s = p[0] * d[0] + p[1] * d[1];
        pts.iter().any(|q| q[0] * d[0] + q[1] * d[1] >= s - margin)
    })
}

/// A number as a label writes it.
fn num(st: &Style, x: f64) -> String {
    st.val_inline(&num_val(x))
}

/// A plane's words: `x = 3 kanan` (`x = 3 (right)` in English).
fn plane_words(c: &Clip, st: &Style, bit: usize) -> String {
    let (axis, is_max) = (PLANES[bit].0, PLANES[bit].1);
    let v = if is_max { c.hi[axis] } else { c.lo[axis] };
    let eq = format!("{} = {}", ["x", "y", "z"][axis], num(st, v));
    say(st, FigureMsg::Plane(bit, Some(eq)))
}

/// The axes x, y, z from the origin (or, for a box far from it, from a
/// corner beyond the box's least corner) to beyond the box; an axis along
/// an edge of the box from where it leaves the box.
fn axes(c: &Clip, axo: &Axo) -> Vec<Item> {
    let size = (0..3)
        .map(|k| c.hi[k] - c.lo[k])
        .fold(0.0, f64::max)
        .max(1e-9);
    let far = (0..3).any(|k| c.lo[k] > 2.0 * size || c.hi[k] < -2.0 * size);
    let o = if far {
        c.lo.map(|x| x - 0.2 * size)
    } else {
        [0.0; 3]
    };
    let mut out = Vec::new();
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        // Along an edge of the box, the axis is that edge (dashed when
        // hidden): it is drawn from where it leaves the box.
        let on_edge = (0..3).all(|j| j == k || o[j] == c.lo[j] || o[j] == c.hi[j]);
        let mut from = o;
        if on_edge && (c.lo[k]..=c.hi[k]).contains(&o[k]) {
            from[k] = c.hi[k];
        }
        let mut tip = o;
        tip[k] = c.hi[k].max(o[k]) + 0.3 * size;
        let (a, b) = (axo.page(from), axo.page(tip));
        out.push(mark(
            *name,
            Kind::Axis,
            Pen::Frame,
            Shape::Line { a, b, head: true },
        ));
        out.push(label_toward(*name, *name, Some([b[0] - a[0], b[1] - a[1]])));
    }
    out
}

/// The segment's pieces: the kept part solid, the cut-off parts dashed.
fn pieces(c: &Clip, at: &dyn Fn([f64; 3]) -> [f64; 2]) -> Vec<Item> {
    let line = |a, b| Shape::Line {
        a: at(a),
        b: at(b),
        head: false,
    };
    let [p0, p1] = c.ends;
    let Some([a, b]) = c.kept else {
        return vec![mark("P0P1", Kind::Segment, Pen::Cut, line(p0, p1))];
    };
    let mut out = Vec::new();
    for (name, from, to) in [("cut part P0", p0, a), ("cut part P1", b, p1)] {
        if from != to {
            out.push(mark(name, Kind::Segment, Pen::Cut, line(from, to)));
        }
    }
    out.push(mark("kept part", Kind::Segment, Pen::Kept, line(a, b)));
    out
}

/// The 3D panel.
fn three_d(c: &Clip, axo: &Axo, st: &Style) -> Figure {
    let mut items = axes(c, axo);
    items.push(mark("box", Kind::Box, Pen::Frame, edges(c, axo)));
    let size = (0..3).map(|k| c.hi[k] - c.lo[k]).fold(0.0, f64::max);
    for (bit, plane) in PLANES.iter().enumerate() {
        let corners = face(c, bit);
        let pts = corners.iter().map(|p| axo.page(*p)).collect();
        let name = plane.2;
        items.push(mark(name, Kind::Plane, Pen::Frame, Shape::Face(pts)));
        let near = outside(c, axo, bit, size);
        let mid = axo.page(mid3(c));
        let away = [near[0] - mid[0], near[1] - mid[1]];
        items.push(label_near(name, plane_words(c, st, bit), near, away));
    }
    items.extend(pieces(c, &|p| axo.page(p)));
    for t in &c.tried {
        let (key, pen) = (
            PLANE_KEYS[t.bit],
            if t.kept { Pen::Kept } else { Pen::Tried },
        );
        items.push(mark(key, Kind::Point, pen, Shape::Dot(axo.page(t.point))));
        let word = say(st, FigureMsg::Plane(t.bit, None));
        // The panel along t says all of it: left out when it cannot stand
        // clear.
        let away = axo.page(minus(t.point, mid3(c)));
        items.push(label_short(key, word, "", away));
    }
    for (k, name) in ["P0", "P1"].iter().enumerate() {
        let p = c.ends[k];
        items.push(mark(
            *name,
            Kind::Point,
            Pen::Frame,
            Shape::Dot(axo.page(p)),
        ));
        let away = axo.page(minus(p, c.ends[1 - k]));
        let text = format!("{name}: {}", c.codes[k]);
        items.push(label_toward(*name, text, Some(away)));
    }
    panel3(st, Panel::Clip, axo, items)
}

/// What the figure says of a segment decided without a kept
/// intersection: accepted whole, rejected by the AND of its codes, or
/// missing the box.
fn verdict(c: &Clip) -> Option<FigureMsg> {
    let code = |s: &str| u8::from_str_radix(s, 2).ok();
    let (a, b) = (code(&c.codes[0])?, code(&c.codes[1])?);
    if a | b == 0 {
        Some(FigureMsg::Word(FigWord::Accepted))
    } else if a & b != 0 {
        Some(FigureMsg::Rejected(format!("{:06b}", a & b)))
    } else if c.kept.is_none() {
        Some(FigureMsg::Word(FigWord::Missed))
    } else {
        None
    }
}

/// The panel along the segment: t from 0 (top) to 1 (bottom).
fn along(c: &Clip, st: &Style) -> Figure {
    let [p0, p1] = c.ends;
    // The point at parameter t on the page: (0, −t).
    let d = minus(p1, p0);
    let t_of = |p: [f64; 3]| {
        let l2 = dot(d, d);
        if l2 == 0.0 {
            0.0
        } else {
            dot(minus(p, p0), d) / l2
        }
    };
    let mut items = pieces(c, &|p| [0.0, -t_of(p)]);
    let code_word = say(st, FigureMsg::Word(FigWord::Outcode));
    for (k, name) in ["P0", "P1"].iter().enumerate() {
        let at = [0.0, -(k as f64)];
        items.push(mark(*name, Kind::Point, Pen::Frame, Shape::Dot(at)));
        let p = st.val_inline(&vec_val(&c.ends[k]));
        let text = format!("t = {k}: {name} {p}, {code_word} {}", c.codes[k]);
        items.push(label_toward(*name, text, Some([1.0, 0.0])));
    }
    for t in &c.tried {
        let key = PLANE_KEYS[t.bit];
        let pen = if t.kept { Pen::Kept } else { Pen::Tried };
        items.push(mark(key, Kind::Point, pen, Shape::Dot([0.0, -t.t])));
        let verdict = say(
            st,
            FigureMsg::Word(if t.kept {
                FigWord::Kept
            } else {
                FigWord::CutOff
            }),
        );
        let head = format!("t = {}: {}", exact(st, &t.t_val), plane_words(c, st, t.bit));
        let p = exact(st, &t.point_val);
        let text = format!("{head} → {p}, {}, {verdict}", t.code);
        items.push(label_short(key, text, head, [1.0, 0.0]));
    }
    items.push(Item::Note("P(t) = P0 + t·(P1 − P0)".into()));
    items.extend(verdict(c).map(|m| Item::Note(say(st, m))));
    let mut f = panel(st, Panel::ClipAlong, items);
    // Tall enough that the labels of two near t stand apart (24 px), from
    // 260 px up to 520.
    let mut ts: Vec<f64> = c.tried.iter().map(|t| t.t).chain([0.0, 1.0]).collect();
    ts.sort_by(f64::total_cmp);
    let gap = ts
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|g| *g > 1e-9)
        .fold(1.0, f64::min);
    f.height = Some((24.0 / gap).clamp(260.0, 520.0));
    f
}
