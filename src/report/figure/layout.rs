//! Where a panel goes on a 600 px wide page, and where its labels go: the
//! one layout both writers use, so that the SVG and the TikZ picture put
//! every mark and every label at the same place (TikZ at 0.025 cm per px,
//! 15 cm wide).
//!
//! The scale is the largest that fits the marks and the labels' text in the
//! width. A label that would overlap one placed before it is moved by a
//! line at a time, down or up, to the nearest free place.

use super::{Figure, Item, Place, RING};

/// The page width in px.
pub const WIDTH: f64 = 600.0;
/// The label font size in px.
pub const FONT: f64 = 15.0;
/// Space kept around a panel, px.
const PAD: f64 = 14.0;
/// The average advance of one character of the 15 px sans-serif font
/// (digits are 8.3 px, most lower-case letters 7–8 px), px.
const CHAR: f64 = 8.0;
/// One line of labels, px.
const LINE: f64 = 18.0;
/// The tallest a panel is drawn, px (a tall drawing is scaled down).
const MAX_HEIGHT: f64 = 420.0;

/// How a label's text is anchored at its x.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at x.
    Start,
    /// The text is centred on x.
    Middle,
    /// The text ends at x.
    End,
}

/// A label placed on the page: its baseline's anchor point in px (y down).
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// x in px.
    pub x: f64,
    /// The baseline's y in px.
    pub y: f64,
    /// How the text is anchored at x.
    pub anchor: Anchor,
    /// The text.
    pub text: String,
}

impl Placed {
    /// The box the label's text takes, px: left, right, top, bottom (the
    /// width estimated from the characters).
    pub fn bounds(&self) -> (f64, f64, f64, f64) {
        let (l, r) = span(self.x, text_width(&self.text), self.anchor);
        (l, r, self.y - 12.0, self.y + 4.0)
    }
}

/// A panel laid out: page units to px, its height, its labels.
#[derive(Clone, Debug, PartialEq)]
pub struct Laid {
    /// px per page unit.
    pub scale: f64,
    /// px x of page x = 0.
    pub tx: f64,
    /// px y of page y = 0.
    pub ty: f64,
    /// The panel's height in px.
    pub height: f64,
    /// The labels and notes, in the order of the figure's items.
    pub labels: Vec<Placed>,
}

impl Laid {
    /// A page point in px (y down).
    pub fn map(&self, p: &[f64; 2]) -> (f64, f64) {
        (self.tx + p[0] * self.scale, self.ty - p[1] * self.scale)
    }
}

/// The offset of a label's anchor from its point, px (y down), and how it
/// is anchored.
fn offset(place: Place) -> (f64, f64, Anchor) {
    match place {
        Place::AboveRight => (6.0, -7.0, Anchor::Start),
        Place::Above => (0.0, -9.0, Anchor::Middle),
        Place::AboveLeft => (-6.0, -7.0, Anchor::End),
        Place::Left => (-9.0, 5.0, Anchor::End),
        Place::BelowLeft => (-6.0, 19.0, Anchor::End),
        Place::Below => (0.0, 21.0, Anchor::Middle),
        Place::BelowRight => (6.0, 19.0, Anchor::Start),
        Place::Right => (9.0, 5.0, Anchor::Start),
    }
}

/// The estimated width of a label's text, px.
fn text_width(t: &str) -> f64 {
    t.chars().count() as f64 * CHAR
}

/// The horizontal extent of a text anchored at x: (left, right).
fn span(x: f64, w: f64, a: Anchor) -> (f64, f64) {
    match a {
        Anchor::Start => (x, x + w),
        Anchor::Middle => (x - w / 2.0, x + w / 2.0),
        Anchor::End => (x - w, x),
    }
}

/// Each mark's points, and each label's point, offset, anchor and width.
type Extents = (Vec<[f64; 2]>, Vec<([f64; 2], f64, f64, Anchor, f64)>);

fn extents(f: &Figure) -> Extents {
    let mut pts = Vec::new();
    let mut labels = Vec::new();
    for it in &f.items {
        match it {
            Item::Segment { a, b, .. } | Item::Arrow { a, b, .. } => pts.extend([*a, *b]),
            Item::Polygon { pts: p, .. } | Item::Path { pts: p, .. } => pts.extend(p),
            Item::Dot { at, .. } => pts.push(*at),
            Item::Label { at, text, place } => {
                let (dx, dy, a) = offset(*place);
                labels.push((*at, dx, dy, a, text_width(text)));
            }
            Item::Note { .. } => {}
        }
    }
    (pts, labels)
}

/// The horizontal extent in px of everything drawn at scale s.
fn width_at(s: f64, e: &Extents) -> (f64, f64) {
    let mut lo = f64::MAX;
    let mut hi = f64::MIN;
    for p in &e.0 {
        lo = lo.min(p[0] * s - 5.0);
        hi = hi.max(p[0] * s + 5.0);
    }
    // A label needs about half its width on each side of its point (it
    // moves to the side where it fits when placed); one wider than half
    // the page counts as half the page.
    for (p, _, _, _, w) in &e.1 {
        let (l, r) = span(p[0] * s, w.min(WIDTH / 2.0), Anchor::Middle);
        lo = lo.min(l);
        hi = hi.max(r);
    }
    (lo, hi)
}

/// The largest scale at which the panel fits the page width (and at most
/// [`MAX_HEIGHT`] tall).
fn fit_scale(f: &Figure, e: &Extents) -> f64 {
    let [x0, y0, x1, y1] = f.bounds();
    let room = WIDTH - 2.0 * PAD;
    let mut hi = room / (x1 - x0).max(1e-9);
    hi = hi.min(MAX_HEIGHT / (y1 - y0).max(1e-9));
    let mut lo = 0.0;
    let (l, r) = width_at(hi, e);
    if r - l <= room {
        return hi;
    }
    for _ in 0..60 {
        let mid = (lo + hi) / 2.0;
        let (l, r) = width_at(mid, e);
        if r - l <= room {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo.max(1e-9)
}

/// A box in px: left, right, top, bottom.
type Bx = (f64, f64, f64, f64);

/// A line in px: from, to.
type Line = ((f64, f64), (f64, f64));

/// Whether the segment a–b crosses the box (or lies in it).
fn crosses(a: (f64, f64), b: (f64, f64), r: Bx) -> bool {
    // Liang–Barsky: clip the segment's parameter range to the box.
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0: f64 = 0.0;
    let mut t1: f64 = 1.0;
    for (p, q) in [
        (-dx, a.0 - r.0),
        (dx, r.1 - a.0),
        (-dy, a.1 - r.2),
        (dy, r.3 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    t0 <= t1
}

/// The order in which a label tries the eight sides: its own, then the
/// neighbours alternately.
fn sides(first: Place) -> Vec<Place> {
    let k = RING.iter().position(|p| *p == first).unwrap_or(1);
    let mut out = vec![first];
    for step in 1..=4usize {
        out.push(RING[(k + step) % 8]);
        if step < 4 {
            out.push(RING[(k + 8 - step) % 8]);
        }
    }
    out
}

/// The marks' lines and dots in px (y measured from page y = 0).
fn obstacles(f: &Figure, s: f64, tx: f64) -> Vec<Line> {
    let m = |p: &[f64; 2]| (tx + p[0] * s, -p[1] * s);
    let mut out = Vec::new();
    for it in &f.items {
        match it {
            Item::Segment { a, b, .. } | Item::Arrow { a, b, .. } => out.push((m(a), m(b))),
            Item::Polygon { pts, .. } | Item::Path { pts, .. } => {
                for w in pts.windows(2) {
                    out.push((m(&w[0]), m(&w[1])));
                }
                if let (true, Some(a), Some(b)) =
                    (matches!(it, Item::Polygon { .. }), pts.last(), pts.first())
                {
                    out.push((m(a), m(b)));
                }
            }
            Item::Dot { at, .. } => {
                let (x, y) = m(at);
                out.push(((x - 4.0, y), (x + 4.0, y)));
                out.push(((x, y - 4.0), (x, y + 4.0)));
            }
            Item::Label { .. } | Item::Note { .. } => {}
        }
    }
    out
}

/// Places one label: of its candidate places (its own side, the other
/// sides, then each side moved by whole lines), the first of the least
/// cost: leaving the page counts 100, overlapping another label 10,
/// crossing a line 5 (so a label rather moves up to four lines away than
/// sits across a box edge), each line moved away 1.
fn place_label(
    at: (f64, f64),
    text: &str,
    place: Place,
    boxes: &[Bx],
    lines: &[Line],
) -> (Placed, Bx) {
    let w = text_width(text);
    let mut candidates: Vec<(Place, f64)> = Vec::new();
    for k in [0.0, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0] {
        candidates.extend(sides(place).into_iter().map(|p| (p, k * LINE)));
    }
    let mut best: Option<(usize, Placed, Bx)> = None;
    for (p, shift) in candidates {
        let (dx, dy, anchor) = offset(p);
        let (x, y) = (at.0 + dx, at.1 + dy + shift);
        let (l, r) = span(x, w, anchor);
        let b = (l - 1.0, r + 1.0, y - 12.0, y + 4.0);
        let on_labels = boxes
            .iter()
            .filter(|o| !(b.1 < o.0 || b.0 > o.1 || b.3 < o.2 || b.2 > o.3))
            .count();
        let on_lines = lines.iter().filter(|(a, c)| crosses(*a, *c, b)).count();
        let outside = usize::from(b.0 < 1.0 || b.1 > WIDTH - 1.0);
        let away = (shift / LINE).abs() as usize;
        let cost = 100 * outside + 10 * on_labels + 5 * on_lines + away;
        if best.as_ref().is_none_or(|(c, ..)| cost < *c) {
            let text = text.to_string();
            best = Some((cost, Placed { x, y, anchor, text }, b));
            if cost == 0 {
                break;
            }
        }
    }
    let (_, placed, b) = best.expect("at least one candidate");
    (placed, b)
}

/// Lays out one panel.
pub fn lay_out(f: &Figure) -> Laid {
    let e = extents(f);
    let s = fit_scale(f, &e);
    let (lo, _) = width_at(s, &e);
    let tx = PAD - lo;
    let lines = obstacles(f, s, tx);
    // Labels at y measured from page y = 0 (ty added below).
    let mut boxes: Vec<Bx> = Vec::new();
    let mut labels = Vec::new();
    for it in &f.items {
        let Item::Label { at, text, place } = it else {
            continue;
        };
        let (p, b) = place_label((tx + at[0] * s, -at[1] * s), text, *place, &boxes, &lines);
        boxes.push(b);
        labels.push(p);
    }
    let mut top = f64::MAX;
    let mut bottom = f64::MIN;
    for p in &e.0 {
        top = top.min(-p[1] * s - 5.0);
        bottom = bottom.max(-p[1] * s + 5.0);
    }
    for b in &boxes {
        top = top.min(b.2);
        bottom = bottom.max(b.3);
    }
    if top > bottom {
        (top, bottom) = (0.0, 1.0);
    }
    // The notes, one line each under the drawing, in the labels' order.
    for (i, it) in f.items.iter().enumerate() {
        let Item::Note { text } = it else { continue };
        bottom += LINE;
        let before = f.items[..i]
            .iter()
            .filter(|x| matches!(x, Item::Label { .. } | Item::Note { .. }))
            .count();
        let placed = Placed {
            x: PAD,
            y: bottom - 2.0,
            anchor: Anchor::Start,
            text: text.clone(),
        };
        labels.insert(before.min(labels.len()), placed);
    }
    let ty = PAD - top;
    for l in &mut labels {
        l.y += ty;
    }
    Laid {
        scale: s,
        tx,
        ty,
        height: (bottom - top + 2.0 * PAD).ceil(),
        labels,
    }
}
