//! What a label must keep clear of, kept in a spatial index: a grid of
//! cells about [`CELL`] px square, each listing the lines that pass
//! through it, the dots and arrow heads, the marks' points (dots and
//! tips), the lines' ends and the labels placed that touch it. A candidate
//! place is tested only against what the cells under it hold, so the work
//! of placing one label does not grow with the marks elsewhere in the
//! panel (before, every candidate was tested against every line, dot and
//! label: placing n labels took about n² tests).
//!
//! The cost of a candidate box (see `place`'s table) counts:
//!
//! | what | cost |
//! |---|---|
//! | over another label, or nearer it than [`GAP_X`] px side by side or [`GAP_Y`] px above or below; off the page | 1000 each |
//! | a line crossing it; over a dot or an arrow head; within [`END`] px of a line's end | 60 each |
//! | another mark's dot or tip no farther than its own mark plus [`NEARER`] px | 60 each |

use super::metrics::WIDTH;
use super::place::{Bx, Pt};

/// The side of a cell, px (a label is about 19 px tall and 30 to 200 px
/// wide).
pub const CELL: f64 = 32.0;
/// The most cells along one side (a larger panel gets larger cells).
const MAX_CELLS: f64 = 64.0;
/// Labels side by side stand at least this far apart, px (two word
/// spaces: closer, `fovy = 60°` and `near = 1` read as one phrase).
pub const GAP_X: f64 = 10.0;
/// Labels one above the other stand at least this far apart, px.
pub const GAP_Y: f64 = 2.0;
/// A label keeps this far from a line's end, px (so it is never read as
/// naming that end).
pub const END: f64 = 2.0;
/// Every other mark's dot or tip is at least this much farther from a
/// label than the label's own mark, px.
pub const NEARER: f64 = 3.0;

/// What is drawn in a panel, in px (y down): the lines of the marks,
/// their dots and arrow heads (centre and radius), the points that a
/// label may name (a dot's centre, an arrow's or an axis's tip) with the
/// number of their mark, and the ends of the lines.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    /// Lines.
    pub lines: Vec<(Pt, Pt)>,
    /// Dots and arrow heads: centre, radius.
    pub blobs: Vec<(Pt, f64)>,
    /// The marks' points, each with its mark's number.
    pub spots: Vec<(Pt, usize)>,
    /// The ends of lines, arcs and outlines.
    pub ends: Vec<Pt>,
}

/// The work of placing labels: candidate places whose cost was counted,
/// and the obstacles tested for them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Candidate places costed.
    pub candidates: u64,
    /// Obstacles (lines, dots, points, ends, labels) tested.
    pub tests: u64,
}

/// What one cell holds, by number.
#[derive(Clone, Debug, Default)]
struct Cell {
    lines: Vec<u32>,
    blobs: Vec<u32>,
    spots: Vec<u32>,
    ends: Vec<u32>,
    boxes: Vec<u32>,
}

/// The index of a scene and of the labels placed on it.
#[derive(Clone, Debug)]
pub struct Obstacles {
    scene: Scene,
    boxes: Vec<Option<Bx>>,
    x0: f64,
    y0: f64,
    cw: f64,
    ch: f64,
    nx: usize,
    ny: usize,
    cells: Vec<Cell>,
    /// Each item's last query, so an item in several cells is tested once.
    seen: [Vec<u32>; 5],
    query: u32,
    /// The largest radius of a dot or head.
    blob_r: f64,
    /// The items found by the last query.
    buf: Vec<u32>,
    /// The work done so far.
    pub work: Work,
}

/// Which list of a cell (and of `seen`).
const LINES: usize = 0;
const BLOBS: usize = 1;
const SPOTS: usize = 2;
const ENDS: usize = 3;
const BOXES: usize = 4;

impl Obstacles {
    /// The index of `scene`, for `labels` labels, over the px box `area`
    /// (what lies outside it is kept in the border cells).
    pub fn new(scene: Scene, labels: usize, area: Bx) -> Obstacles {
        let (w, h) = ((area.r - area.l).max(1.0), (area.b - area.t).max(1.0));
        let (cw, ch) = (CELL.max(w / MAX_CELLS), CELL.max(h / MAX_CELLS));
        let (nx, ny) = ((w / cw).ceil() as usize, (h / ch).ceil() as usize);
        let seen = [
            vec![0; scene.lines.len()],
            vec![0; scene.blobs.len()],
            vec![0; scene.spots.len()],
            vec![0; scene.ends.len()],
            vec![0; labels],
        ];
        let mut o = Obstacles {
            scene: Scene::default(),
            boxes: vec![None; labels],
            x0: area.l,
            y0: area.t,
            cw,
            ch,
            nx: nx.max(1),
            ny: ny.max(1),
            cells: vec![Cell::default(); nx.max(1) * ny.max(1)],
            seen,
            query: 0,
            blob_r: scene.blobs.iter().map(|b| b.1).fold(0.0, f64::max),
            buf: Vec::new(),
            work: Work::default(),
        };
        for (i, (a, b)) in scene.lines.iter().enumerate() {
            let span = Bx {
                l: a.0.min(b.0),
                r: a.0.max(b.0),
                t: a.1.min(b.1),
                b: a.1.max(b.1),
            };
            for k in o.cells_of(&span) {
                let (cx, cy) = (k % o.nx, k / o.nx);
                if o.cell_box(cx, cy).crossed_by(*a, *b) {
                    o.cells[k].lines.push(i as u32);
                }
            }
        }
        for (i, (c, r)) in scene.blobs.iter().enumerate() {
            for k in o.cells_of(&Bx::around(*c, *r)) {
                o.cells[k].blobs.push(i as u32);
            }
        }
        for (i, (p, _)) in scene.spots.iter().enumerate() {
            for k in o.cells_of(&Bx::around(*p, 0.0)) {
                o.cells[k].spots.push(i as u32);
            }
        }
        for (i, p) in scene.ends.iter().enumerate() {
            for k in o.cells_of(&Bx::around(*p, 0.0)) {
                o.cells[k].ends.push(i as u32);
            }
        }
        o.scene = scene;
        o
    }

    /// The cells a box touches (those of the border for what lies beyond
    /// the area), by number.
    fn cells_of(&self, b: &Bx) -> impl Iterator<Item = usize> {
        let col = |x: f64| (((x - self.x0) / self.cw).floor().max(0.0) as usize).min(self.nx - 1);
        let row = |y: f64| (((y - self.y0) / self.ch).floor().max(0.0) as usize).min(self.ny - 1);
        let (c0, c1, r0, r1) = (col(b.l), col(b.r), row(b.t), row(b.b));
        let nx = self.nx;
        (r0..=r1).flat_map(move |r| (c0..=c1).map(move |c| r * nx + c))
    }

    /// Cell (cx, cy) as a box; a border cell reaches to infinity outward.
    fn cell_box(&self, cx: usize, cy: usize) -> Bx {
        let edge = |i: usize, n: usize, o: f64, s: f64| {
            let lo = if i == 0 { f64::MIN } else { o + i as f64 * s };
            let hi = if i + 1 == n {
                f64::MAX
            } else {
                o + (i + 1) as f64 * s
            };
            (lo - 0.01, hi + 0.01)
        };
        let (l, r) = edge(cx, self.nx, self.x0, self.cw);
        let (t, b) = edge(cy, self.ny, self.y0, self.ch);
        Bx { l, r, t, b }
    }

    /// Puts label i's box (or takes it away, `None`).
    pub fn set_box(&mut self, i: usize, bx: Option<Bx>) {
        if let Some(old) = self.boxes[i] {
            let cells: Vec<usize> = self.cells_of(&old).collect();
            for k in cells {
                self.cells[k].boxes.retain(|j| *j as usize != i);
            }
        }
        if let Some(new) = bx {
            let cells: Vec<usize> = self.cells_of(&new).collect();
            for k in cells {
                self.cells[k].boxes.push(i as u32);
            }
        }
        self.boxes[i] = bx;
    }

    /// The items of list `which` in the cells under `b`, each once, into
    /// `out`.
    fn near(&mut self, which: usize, b: &Bx, out: &mut Vec<u32>) {
        self.query = self.query.wrapping_add(1);
        if self.query == 0 {
            self.seen.iter_mut().for_each(|s| s.fill(0));
            self.query = 1;
        }
        out.clear();
        let col = |x: f64| (((x - self.x0) / self.cw).floor().max(0.0) as usize).min(self.nx - 1);
        let row = |y: f64| (((y - self.y0) / self.ch).floor().max(0.0) as usize).min(self.ny - 1);
        let (c0, c1, r0, r1) = (col(b.l), col(b.r), row(b.t), row(b.b));
        let nx = self.nx;
        for k in (r0..=r1).flat_map(|r| (c0..=c1).map(move |c| r * nx + c)) {
            let c = &self.cells[k];
            let list = match which {
                LINES => &c.lines,
                BLOBS => &c.blobs,
                SPOTS => &c.spots,
                ENDS => &c.ends,
                _ => &c.boxes,
            };
            for &i in list {
                let s = &mut self.seen[which][i as usize];
                if *s != self.query {
                    *s = self.query;
                    out.push(i);
                }
            }
        }
        self.work.tests += out.len() as u64;
    }

    /// The cost of the obstacles a label's box meets (the module's
    /// table), for a label `d_own` px from its own mark that may stand
    /// near the points of the marks `own` (its mark, and the marks its
    /// text names).
    pub fn cost(&mut self, bx: &Bx, own: &[usize], d_own: f64) -> f64 {
        self.work.candidates += 1;
        let mut buf = std::mem::take(&mut self.buf);
        let apart = bx.grown(GAP_X, GAP_Y);
        let mut heavy = usize::from(bx.l < 1.0 || bx.r > WIDTH - 1.0);
        self.near(BOXES, &apart, &mut buf);
        for &i in &buf {
            heavy += usize::from(self.boxes[i as usize].is_some_and(|o| o.overlaps(&apart)));
        }
        let mut light = 0;
        self.near(LINES, bx, &mut buf);
        for &i in &buf {
            let (a, b) = self.scene.lines[i as usize];
            light += usize::from(bx.crossed_by(a, b));
        }
        self.near(BLOBS, &bx.grown(self.blob_r, self.blob_r), &mut buf);
        for &i in &buf {
            let (c, r) = self.scene.blobs[i as usize];
            light += usize::from(bx.dist_point(c) < r);
        }
        let reach = d_own + NEARER;
        self.near(SPOTS, &bx.grown(reach, reach), &mut buf);
        for &i in &buf {
            let (p, m) = self.scene.spots[i as usize];
            light += usize::from(!own.contains(&m) && bx.dist_point(p) < reach);
        }
        self.near(ENDS, &bx.grown(END, END), &mut buf);
        for &i in &buf {
            light += usize::from(bx.dist_point(self.scene.ends[i as usize]) < END);
        }
        self.buf = buf;
        1000.0 * heavy as f64 + 60.0 * light as f64
    }
}
