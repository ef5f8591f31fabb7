//! Where a label goes: a small search over candidate places around its
//! mark, as map labelling does. Each candidate is a box beside a point of
//! the mark (the dot, the arrow's tip, points along a segment, an arc or a
//! face's outline): to its right or left, above or below, or at a corner,
//! at one of four gaps ([`candidates`]); its cost counts what it would
//! spoil, and the cheapest wins:
//!
//! | what | cost |
//! |---|---|
//! | over another label (or nearer it than 10 px side by side, 2 px above or below), or off the page | 1000 each |
//! | a line crossing it, over a dot or an arrow head, or within 2 px of a line's end | 60 each |
//! | another mark's dot or tip as near as its own mark (or less than 3 px farther) | 60 each |
//! | each px from its mark | 1 |
//! | away from the side asked for (beyond an arrow's tip) | up to 12 |
//! | each px along the mark from the point asked for (or its middle) | 0.08 |
//!
//! Only places within [`REACH`] px of the mark are tried, so every label
//! stands beside its own mark, and nearer it than any other mark's dot or
//! tip (the marks its text names too, `N = V = …`, excepted). The
//! obstacles are found through a spatial index ([`super::index`]).

use super::index::Obstacles;
use super::metrics::{Anchor, Placed, ASCENT, DESCENT};

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

/// The length of (x, y) (px, far from overflow: a plain square root,
/// cheaper than `hypot` in the placer's inner loop).
fn len(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

impl Bx {
    /// The box of the point c grown by r each way.
    pub fn around(c: Pt, r: f64) -> Bx {
        Bx {
            l: c.0 - r,
            r: c.0 + r,
            t: c.1 - r,
            b: c.1 + r,
        }
    }
    /// The box grown by dx left and right, dy up and down.
    pub fn grown(&self, dx: f64, dy: f64) -> Bx {
        Bx {
            l: self.l - dx,
            r: self.r + dx,
            t: self.t - dy,
            b: self.b + dy,
        }
    }
    /// Whether two boxes overlap.
    pub fn overlaps(&self, o: &Bx) -> bool {
        self.l < o.r && o.l < self.r && self.t < o.b && o.t < self.b
    }
    /// The distance from the box to a point (0 inside).
    pub fn dist_point(&self, p: Pt) -> f64 {
        let dx = (self.l - p.0).max(p.0 - self.r).max(0.0);
        let dy = (self.t - p.1).max(p.1 - self.b).max(0.0);
        len(dx, dy)
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
            d = d.min(to_segment(c, a, b));
        }
        d
    }
}

/// The distance from p to the segment a–b.
fn to_segment(p: Pt, a: Pt, b: Pt) -> f64 {
    let (ux, uy) = (b.0 - a.0, b.1 - a.1);
    let l2 = ux * ux + uy * uy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * ux + (p.1 - a.1) * uy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    len(p.0 - a.0 - t * ux, p.1 - a.1 - t * uy)
}

/// Whether p lies in the convex polygon `pts` (or on its outline).
fn inside(p: Pt, pts: &[Pt]) -> bool {
    let n = pts.len();
    let mut sign = 0.0;
    for i in 0..n {
        let (a, b) = (pts[i], pts[(i + 1) % n]);
        let c = (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0);
        if c != 0.0 {
            if sign != 0.0 && c.signum() != sign {
                return false;
            }
            sign = c.signum();
        }
    }
    n >= 3
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
                if inside(c, pts) {
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
    len(a.0 - b.0, a.1 - b.1)
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

/// What a label is placed for: its mark's shape, the side `toward` it
/// asks for (a page direction, y up) and the point `near` (px) it asks
/// to stand beside, if any, and the marks it may stand near (its own, and
/// those its text names), by number.
pub struct Job<'a> {
    /// The mark's shape.
    pub geom: &'a Geom,
    /// The side asked for.
    pub toward: Option<[f64; 2]>,
    /// The point asked for.
    pub near: Option<Pt>,
    /// Its mark and the marks its text names.
    pub own: &'a [usize],
}

/// The best place for a text of width w beside the mark of `job`,
/// preferring the side asked for and the point asked for, else the
/// middle of the mark: each px of the anchor from that point costs 0.08.
/// Returns the label and its cost.
pub fn place(text: &str, w: f64, job: &Job, obs: &mut Obstacles) -> (Placed, f64) {
    let (g, toward, near) = (job.geom, job.toward, job.near);
    let gaps: [f64; 4] = match g {
        Geom::Point(_) => [6.0, 12.0, 20.0, 30.0],
        _ => [3.0, 8.0, 16.0, 26.0],
    };
    let want = toward.map(|t| {
        let n = len(t[0], t[1]).max(1e-300);
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
                let off = ((bx.l + bx.r) / 2.0 - at.0, (bx.t + bx.b) / 2.0 - at.1);
                let n = len(off.0, off.1).max(1e-300);
                let d = (off.0 / n, off.1 / n);
                let side = want.map_or(0.0, |t| 6.0 * (1.0 - (t.0 * d.0 + t.1 * d.1)));
                // What it costs at least; the distance to the mark and the
                // obstacles only add to it.
                let beaten = |least: f64| best.as_ref().is_some_and(|(b, ..)| least >= *b - 1e-9);
                if beaten(side + along) {
                    continue;
                }
                let near_mark = g.distance(&bx);
                let least = near_mark + side + along;
                if near_mark > REACH || beaten(least) {
                    continue;
                }
                let c = least + obs.cost(&bx, job.own, near_mark);
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
    use crate::report::figure::index::Scene;

    fn area() -> Bx {
        Bx {
            l: 0.0,
            r: 600.0,
            t: 0.0,
            b: 400.0,
        }
    }

    fn job<'a>(g: &'a Geom, own: &'a [usize]) -> Job<'a> {
        Job {
            geom: g,
            toward: Some([1.0, 0.0]),
            near: None,
            own,
        }
    }

    /// Nothing in the way: the label stands on the side asked for, at the
    /// least gap (6 px from a dot), and costs that distance.
    #[test]
    fn a_free_label_stands_on_its_side() {
        let g = Geom::Point((100.0, 100.0));
        let mut obs = Obstacles::new(Scene::default(), 1, area());
        let (p, c) = place("A", 10.0, &job(&g, &[0]), &mut obs);
        assert_eq!((p.x, p.anchor), (106.0, Anchor::Start));
        assert!((c - 6.0).abs() < 1e-9, "{c}");
    }

    /// A line just right of the dot: the label goes elsewhere, clear of it
    /// and within reach.
    #[test]
    fn a_label_steps_around_a_line() {
        let g = Geom::Point((100.0, 100.0));
        let scene = Scene {
            lines: vec![((110.0, 0.0), (110.0, 200.0))],
            ..Scene::default()
        };
        let mut obs = Obstacles::new(scene, 1, area());
        let w = crate::report::figure::layout::text_width("A = (1, 2)");
        let (p, c) = place("A = (1, 2)", w, &job(&g, &[0]), &mut obs);
        let (l, r, t, b) = p.bounds();
        let bx = Bx { l, r, t, b };
        assert!(!bx.crossed_by((110.0, 0.0), (110.0, 200.0)), "{p:?}");
        assert!(c < 60.0 && g.distance(&bx) <= REACH, "{c}");
    }

    /// Another mark's dot 14 px to the right of A's (mark 1 at (114,
    /// 100)): the label of A may not stand to the right, where it would be
    /// as near B's dot as A's (at the least gap, 6 px from A's centre, it
    /// would reach over B's dot); it stands on the other side, nearer its
    /// own dot than B's by at least 3 px.
    #[test]
    fn a_label_stands_nearer_its_own_dot_than_another() {
        let (a, b) = ((100.0, 100.0), (114.0, 100.0));
        let g = Geom::Point(a);
        let scene = Scene {
            spots: vec![(a, 0), (b, 1)],
            ..Scene::default()
        };
        let mut obs = Obstacles::new(scene, 1, area());
        let (p, c) = place("A", 10.0, &job(&g, &[0]), &mut obs);
        let (l, r, t, bt) = p.bounds();
        let bx = Bx { l, r, t, b: bt };
        assert!(c < 60.0, "{c}");
        assert!(bx.dist_point(b) >= bx.dist_point(a) + 3.0, "{p:?}");
        // the same dot named by the label's text (`A = B = …`) is no
        // obstacle: the label stands on the side asked for.
        let mut obs = Obstacles::new(
            Scene {
                spots: vec![(a, 0), (b, 1)],
                ..Scene::default()
            },
            1,
            area(),
        );
        let (p, _) = place("A = B", 40.0, &job(&g, &[0, 1]), &mut obs);
        assert_eq!(p.anchor, Anchor::Start);
    }

    /// The work of placing a label does not grow with the marks away from
    /// it: a dot at (100, 100) alone, then with 500 vertical lines and 500
    /// dots from x = 300 to 550 (more than REACH + a label's width away):
    /// the same candidates are costed and the same obstacles tested
    /// (before the index, each candidate was tested against all 1,000).
    #[test]
    fn far_marks_add_no_work() {
        let a = (100.0, 100.0);
        let g = Geom::Point(a);
        let work = |far: usize| {
            let mut scene = Scene {
                spots: vec![(a, 0)],
                blobs: vec![(a, 5.5)],
                ..Scene::default()
            };
            for k in 0..far {
                let x = 300.0 + 0.5 * k as f64;
                scene.lines.push(((x, 0.0), (x, 400.0)));
                scene.blobs.push(((x, 200.0), 5.5));
                scene.spots.push(((x, 200.0), k + 1));
            }
            let mut obs = Obstacles::new(scene, 1, area());
            let (p, c) = place("A = (1, 2)", 75.0, &job(&g, &[0]), &mut obs);
            (p, c, obs.work)
        };
        let (alone, with) = (work(0), work(500));
        assert_eq!(alone, with);
        assert!(alone.2.candidates > 0 && alone.2.tests > 0, "{:?}", alone.2);
    }
}
