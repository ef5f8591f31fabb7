//! Where a label goes: a small search over candidate places around its
//! mark, as map labelling does. Each candidate is a box beside a point of
//! the mark (the dot, the arrow's tip, points along a segment, an arc or a
//! face's outline): to its right or left, above or below, or at a corner,
//! at one of four gaps ([`candidates`]); its cost counts what it would
//! spoil, and the cheapest wins:
//!
//! | what | cost |
//! |---|---|
//! | over another label (or within 3 px of it), or off the page | 1000 each |
//! | a line crossing it, or over a dot or an arrow head | 60 each |
//! | each px from its mark | 1 |
//! | away from the side asked for (beyond an arrow's tip) | up to 12 |
//! | each px along the mark from the point asked for (or its middle) | 0.08 |
//!
//! Only places within [`REACH`] px of the mark are tried, so every label
//! stands beside its own mark.

use super::metrics::{Anchor, Placed, ASCENT, DESCENT, WIDTH};

/// A point in px (y down).
pub type Pt = (f64, f64);

/// A box in px: left, right, top, bottom.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bx {
    /// Left.
    pub l: f64,
    /// Right.
    pub r: f64,
    /// Top.
    pub t: f64,
    /// Bottom.
    pub b: f64,
}

impl Bx {
    fn overlaps(&self, o: &Bx) -> bool {
        self.l < o.r && o.l < self.r && self.t < o.b && o.t < self.b
    }
    /// The distance from the box to a point (0 inside).
    pub fn dist_point(&self, p: Pt) -> f64 {
        let dx = (self.l - p.0).max(p.0 - self.r).max(0.0);
        let dy = (self.t - p.1).max(p.1 - self.b).max(0.0);
        dx.hypot(dy)
    }
    /// Whether the segment a–b crosses the box (or lies in it).
    pub fn crossed_by(&self, a: Pt, b: Pt) -> bool {
        // Liang–Barsky: clip the segment's parameter range to the box.
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [
            (-dx, a.0 - self.l),
            (dx, self.r - a.0),
            (-dy, a.1 - self.t),
            (dy, self.b - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
        t0 <= t1
    }
    /// The distance from the box to the segment a–b.
    pub fn dist_segment(&self, a: Pt, b: Pt) -> f64 {
        if self.crossed_by(a, b) {
            return 0.0;
        }
        let corners = [
            (self.l, self.t),
            (self.r, self.t),
            (self.r, self.b),
            (self.l, self.b),
        ];
        let mut d = self.dist_point(a).min(self.dist_point(b));
        for c in corners {
            d = d.min(super::axo::to_segment([c.0, c.1], [a.0, a.1], [b.0, b.1]));
        }
        d
    }
}

/// The farthest a label stands from its mark, px (the promise is 40).
pub const REACH: f64 = 36.0;

/// What a label names, in px: a point (a dot, an arrow's tip), lines (a
/// segment, an arc, a window's outline, the box's edges) or a region (a
/// face of the box).
#[derive(Clone, Debug, PartialEq)]
pub enum Geom {
    /// A point.
    Point(Pt),
    /// Lines.
    Lines(Vec<(Pt, Pt)>),
    /// A convex region.
    Region(Vec<Pt>),
}

impl Geom {
    /// The distance from a box to the mark.
    pub fn distance(&self, bx: &Bx) -> f64 {
        match self {
            Geom::Point(p) => bx.dist_point(*p),
            Geom::Lines(ls) => ls
                .iter()
                .map(|(a, b)| bx.dist_segment(*a, *b))
                .fold(f64::MAX, f64::min),
            Geom::Region(pts) => {
                let c = ((bx.l + bx.r) / 2.0, (bx.t + bx.b) / 2.0);
                let poly: Vec<[f64; 2]> = pts.iter().map(|p| [p.0, p.1]).collect();
                if super::axo::outside_by([c.0, c.1], &poly) == 0.0 {
                    return 0.0;
                }
                let n = pts.len();
                (0..n)
                    .map(|i| bx.dist_segment(pts[i], pts[(i + 1) % n]))
                    .fold(f64::MAX, f64::min)
            }
        }
    }
    /// Points of the mark to put a label beside: the point itself, or
    /// points about every 14 px along the lines or the outline (at most
    /// 24), nearest the middle first; and that middle.
    fn anchors(&self) -> (Vec<Pt>, Pt) {
        let lines: Vec<(Pt, Pt)> = match self {
            Geom::Point(p) => return (vec![*p], *p),
            Geom::Lines(ls) => ls.clone(),
            Geom::Region(p) => (0..p.len()).map(|i| (p[i], p[(i + 1) % p.len()])).collect(),
        };
        let total: f64 = lines.iter().map(|(a, b)| dist(*a, *b)).sum();
        let step = (total / 24.0).max(14.0);
        let mut out = Vec::new();
        for (a, b) in &lines {
            let k = (dist(*a, *b) / step).ceil().max(1.0) as usize;
            for i in 0..=k {
                let t = i as f64 / k as f64;
                out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
        }
        let mid = out.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
        let mid = (mid.0 / out.len() as f64, mid.1 / out.len() as f64);
        out.sort_by(|p, q| dist(*p, mid).total_cmp(&dist(*q, mid)));
        (out, mid)
    }
}

fn dist(a: Pt, b: Pt) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// What a label must keep clear of: the marks' lines, their dots and
/// arrow heads (centre and radius), and the labels placed before it.
#[derive(Clone, Debug, Default)]
pub struct Obstacles {
    /// Lines.
    pub lines: Vec<(Pt, Pt)>,
    /// Dots and arrow heads.
    pub blobs: Vec<(Pt, f64)>,
    /// Labels placed.
    pub boxes: Vec<Bx>,
}

/// The candidate boxes of a text of width w about `at` with a gap of `g`
/// px, and how each text is anchored: to the right and to the left
/// (centred on `at`, or slid up or down by half a line or a line), above
/// and below (centred, or starting or ending at `at`), and at the four
/// corners.
fn candidates(at: Pt, g: f64, w: f64) -> Vec<(Bx, Anchor)> {
    let h = ASCENT + DESCENT;
    let (x, y) = at;
    let b = |l: f64, t: f64| Bx {
        l,
        r: l + w,
        t,
        b: t + h,
    };
    let mut out = Vec::with_capacity(20);
    for dy in [0.0, -0.5, 0.5, -1.0, 1.0] {
        let t = y - h / 2.0 + dy * (h + 2.0);
        out.push((b(x + g, t), Anchor::Start));
        out.push((b(x - g - w, t), Anchor::End));
    }
    for (l, a) in [
        (x - w / 2.0, Anchor::Middle),
        (x - 6.0, Anchor::Start),
        (x + 6.0 - w, Anchor::End),
    ] {
        out.push((b(l, y - g - h), a));
        out.push((b(l, y + g), a));
    }
    let c = 0.7 * g;
    out.push((b(x + c, y - c - h), Anchor::Start));
    out.push((b(x - c - w, y - c - h), Anchor::End));
    out.push((b(x + c, y + c), Anchor::Start));
    out.push((b(x - c - w, y + c), Anchor::End));
    out
}

/// The cost of the obstacles a box meets: see the module's table.
fn cost(bx: &Bx, obs: &Obstacles) -> f64 {
    // Labels keep 3 px apart (so two never read as one).
    let apart = Bx {
        l: bx.l - 3.0,
        r: bx.r + 3.0,
        t: bx.t - 1.0,
        b: bx.b + 1.0,
    };
    let on_labels = obs.boxes.iter().filter(|o| o.overlaps(&apart)).count();
    let off_page = usize::from(bx.l < 1.0 || bx.r > WIDTH - 1.0);
    let lines = obs
        .lines
        .iter()
        .filter(|(a, b)| bx.crossed_by(*a, *b))
        .count();
    let blobs = obs
        .blobs
        .iter()
        .filter(|(c, r)| bx.dist_point(*c) < *r)
        .count();
    1000.0 * (on_labels + off_page) as f64 + 60.0 * (lines + blobs) as f64
}

/// The best place for a text of width w beside the mark g, preferring the
/// side `toward` (a page direction, y up) and the point `near` (px) if
/// given, else the middle of the mark: each px of the anchor from that
/// point costs 0.08. Returns the label and its cost.
pub fn place(
    text: &str,
    w: f64,
    g: &Geom,
    (toward, near): (Option<[f64; 2]>, Option<Pt>),
    obs: &Obstacles,
) -> (Placed, f64) {
    let gaps: [f64; 4] = match g {
        Geom::Point(_) => [6.0, 12.0, 20.0, 30.0],
        _ => [3.0, 8.0, 16.0, 26.0],
    };
    let want = toward.map(|t| {
        let n = t[0].hypot(t[1]).max(1e-300);
        (t[0] / n, -t[1] / n)
    });
    let (found, mid) = g.anchors();
    let anchors: Vec<Pt> = near.into_iter().chain(found).collect();
    let pref = near.unwrap_or(mid);
    let mut best: Option<(f64, Bx, Anchor)> = None;
    for at in &anchors {
        let along = 0.08 * dist(*at, pref);
        for gap in gaps {
            for (bx, anchor) in candidates(*at, gap, w) {
                let near_mark = g.distance(&bx);
                if near_mark > REACH {
                    continue;
                }
                let off = ((bx.l + bx.r) / 2.0 - at.0, (bx.t + bx.b) / 2.0 - at.1);
                let n = off.0.hypot(off.1).max(1e-300);
                let d = (off.0 / n, off.1 / n);
                let side = want.map_or(0.0, |t| 6.0 * (1.0 - (t.0 * d.0 + t.1 * d.1)));
                // What it costs at least; the obstacles only add to it.
                let least = near_mark + side + along;
                if best.as_ref().is_some_and(|(b, ..)| least >= *b - 1e-9) {
                    continue;
                }
                let c = least + cost(&bx, obs);
                if best.as_ref().is_none_or(|(b, ..)| c < *b - 1e-9) {
                    best = Some((c, bx, anchor));
                }
            }
        }
    }
    let (c, bx, anchor) = best.unwrap_or_else(|| {
        let at = anchors.first().copied().unwrap_or((0.0, 0.0));
        let (bx, a) = candidates(at, gaps[0], w)[0];
        (f64::MAX, bx, a)
    });
    let x = match anchor {
        Anchor::Start => bx.l,
        Anchor::Middle => (bx.l + bx.r) / 2.0,
        Anchor::End => bx.r,
    };
    let placed = Placed {
        x,
        y: bx.b - DESCENT,
        anchor,
        text: text.to_string(),
    };
    (placed, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Nothing in the way: the label stands on the side asked for, at the
    /// least gap (6 px from a dot), and costs that distance.
    #[test]
    fn a_free_label_stands_on_its_side() {
        let g = Geom::Point((100.0, 100.0));
        let (p, c) = place(
            "A",
            10.0,
            &g,
            (Some([1.0, 0.0]), None),
            &Obstacles::default(),
        );
        assert_eq!((p.x, p.anchor), (106.0, Anchor::Start));
        assert!((c - 6.0).abs() < 1e-9, "{c}");
    }

    /// A line just right of the dot: the label goes elsewhere, clear of it
    /// and within reach.
    #[test]
    fn a_label_steps_around_a_line() {
        let g = Geom::Point((100.0, 100.0));
        let obs = Obstacles {
            lines: vec![((110.0, 0.0), (110.0, 200.0))],
            ..Obstacles::default()
        };
        let w = crate::report::figure::layout::text_width("A = (1, 2)");
        let (p, c) = place("A = (1, 2)", w, &g, (Some([1.0, 0.0]), None), &obs);
        let (l, r, t, b) = p.bounds();
        let bx = Bx { l, r, t, b };
        assert!(!bx.crossed_by((110.0, 0.0), (110.0, 200.0)), "{p:?}");
        assert!(c < 60.0 && g.distance(&bx) <= REACH, "{c}");
    }
}
