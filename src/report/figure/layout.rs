//! Where a panel goes on a 600 px wide page, and where its labels go: the
//! one layout both writers use, so that the SVG and the TikZ picture put
//! every mark and every label at the same place (TikZ at 0.025 cm per px,
//! 15 cm wide).
//!
//! The scale is the largest that fits the marks and the labels' text in the
//! width. Each label is then put beside its own mark by `place`'s search,
//! in the order of the figure, and placed again once the others stand
//! (twice), where that costs less; one that still cannot stand clear is
//! written short (its mark's name) with its whole text in a note, or, when
//! even that cannot, left out (its text in the note). A panel places at
//! most [`MAX_LABELS`] labels: those beyond (400 points projected, say)
//! are listed in its notes instead, where they can be read.

pub use super::index::Work;
use super::index::{Obstacles, Scene};
pub use super::metrics::{text_width, Anchor, Placed, ASCENT, DESCENT, FONT, WIDTH};
use super::place::{place, Bx, Geom, Job, Pt};
use super::{Figure, Item, Mark, Shape};
use std::collections::HashMap;

/// Space kept around a panel, px.
const PAD: f64 = 14.0;
/// One line of notes, px.
const LINE: f64 = 20.0;
/// The tallest a panel is drawn, px (a tall drawing is scaled down).
const MAX_HEIGHT: f64 = 420.0;
/// The most labels a panel places (more would not be readable on a
/// 600 px panel): the figure's first labels are placed, the texts of the
/// others listed in its notes.
pub const MAX_LABELS: usize = 40;
/// Space between the drawing and its notes, px.
const NOTE_GAP: f64 = 4.0;

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
    /// The labels, in the order of the figure's labels (none for a label
    /// left out: its text is in the notes).
    pub labels: Vec<Option<Placed>>,
    /// The notes' lines, in order (a note wider than the page is broken
    /// into lines between words).
    pub notes: Vec<Placed>,
    /// The work of placing the labels.
    pub work: Work,
}

impl Laid {
    /// A page point in px (y down).
    pub fn map(&self, p: &[f64; 2]) -> (f64, f64) {
        (self.tx + p[0] * self.scale, self.ty - p[1] * self.scale)
    }
}

/// What a label names, in px: an arrow or an axis by its tip, a dot by its
/// centre, a face by its region, anything else by its lines.
fn geom(m: &Mark, at: &dyn Fn(&[f64; 2]) -> Pt) -> Geom {
    let lines = |p: &[[f64; 2]], closed: bool| -> Geom {
        let mut ls: Vec<(Pt, Pt)> = p.windows(2).map(|w| (at(&w[0]), at(&w[1]))).collect();
        if let (true, Some(a), Some(b)) = (closed && p.len() > 2, p.last(), p.first()) {
            ls.push((at(a), at(b)));
        }
        Geom::Lines(ls)
    };
    match &m.shape {
        Shape::Line { b, head: true, .. } => Geom::Point(at(b)),
        Shape::Line { a, b, .. } => lines(&[*a, *b], false),
        Shape::Dot(p) => Geom::Point(at(p)),
        Shape::Polygon(p) => lines(p, true),
        Shape::Path(p) => lines(p, false),
        Shape::Face(p) => Geom::Region(p.iter().map(at).collect()),
        Shape::Edges(e) => Geom::Lines(e.iter().map(|(a, b, _)| (at(a), at(b))).collect()),
    }
}

/// The marks in px: their lines, dots and arrow heads, their points (a
/// dot's centre, an arrow's or an axis's tip, with the mark's number in
/// the figure's order of marks) and the ends of their lines, arcs and
/// outlines.
fn scene(f: &Figure, at: &dyn Fn(&[f64; 2]) -> Pt) -> Scene {
    let mut o = Scene::default();
    for (k, m) in f.marks().enumerate() {
        let half = m.pen.width() / 2.0;
        match &m.shape {
            Shape::Line { a, b, head } => {
                let (p, q) = (at(a), at(b));
                o.lines.push((p, q));
                o.ends.extend([p, q]);
                if *head {
                    // The head: 7 line widths long, ending at the tip.
                    let l = (q.0 - p.0).hypot(q.1 - p.1).max(1e-9);
                    let back = 5.0 * half;
                    let c = (q.0 - (q.0 - p.0) / l * back, q.1 - (q.1 - p.1) / l * back);
                    o.blobs.push((c, 8.0 * half));
                    o.spots.push((q, k));
                }
            }
            Shape::Polygon(p) | Shape::Path(p) => {
                if let Geom::Lines(ls) = geom(m, at) {
                    o.lines.extend(ls);
                }
                match &m.shape {
                    Shape::Path(_) => o.ends.extend(p.first().into_iter().chain(p.last()).map(at)),
                    _ => o.ends.extend(p.iter().map(at)),
                }
            }
            Shape::Edges(e) => {
                for (a, b, _) in e {
                    o.lines.push((at(a), at(b)));
                    o.ends.extend([at(a), at(b)]);
                }
            }
            Shape::Dot(p) => {
                o.blobs.push((at(p), 5.5));
                o.spots.push((at(p), k));
            }
            Shape::Face(_) => {}
        }
    }
    o
}

/// The horizontal extent in px of the marks and, roughly, their labels at
/// scale s: a label takes its width on the side it asks for, else half its
/// width each side of the middle of its mark.
fn width_at(f: &Figure, by_name: &HashMap<&str, usize>, s: f64) -> (f64, f64) {
    let mut lo = f64::MAX;
    let mut hi = f64::MIN;
    for p in f.marks().flat_map(Mark::points) {
        lo = lo.min(p[0] * s - 5.0);
        hi = hi.max(p[0] * s + 5.0);
    }
    let marks: Vec<&Mark> = f.marks().collect();
    for l in f.labels().take(MAX_LABELS) {
        let Some(m) = by_name.get(l.of.as_str()).map(|k| marks[*k]) else {
            continue;
        };
        let pts = match (l.near, &m.shape) {
            (Some(p), _) => vec![p],
            (None, Shape::Line { b, head: true, .. }) => vec![*b],
            _ => m.points(),
        };
        let x = pts.iter().map(|p| p[0]).sum::<f64>() / pts.len().max(1) as f64 * s;
        let w = text_width(&l.text).min(WIDTH / 2.0);
        let (l, r) = match l.toward.map(|t| t[0] / t[0].hypot(t[1]).max(1e-300)) {
            Some(c) if c > 0.38 => (x, x + w + 8.0),
            Some(c) if c < -0.38 => (x - w - 8.0, x),
            _ => (x - w / 2.0, x + w / 2.0),
        };
        lo = lo.min(l);
        hi = hi.max(r);
    }
    (lo, hi)
}

/// The largest scale at which the panel fits the page width (and at most
/// [`MAX_HEIGHT`] tall).
fn fit_scale(f: &Figure, by_name: &HashMap<&str, usize>) -> f64 {
    let [x0, y0, x1, y1] = f.bounds();
    let room = WIDTH - 2.0 * PAD;
    let mut hi = room / (x1 - x0).max(1e-9);
    hi = hi.min(f.height.unwrap_or(MAX_HEIGHT) / (y1 - y0).max(1e-9));
    let fits = |s: f64| {
        let (l, r) = width_at(f, by_name, s);
        r - l <= room
    };
    if fits(hi) {
        return hi;
    }
    let mut lo = 0.0;
    for _ in 0..60 {
        let mid = (lo + hi) / 2.0;
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo.max(1e-9)
}

/// The box of a placed label.
fn bx(p: &Placed) -> Bx {
    let (l, r, t, b) = p.bounds();
    Bx { l, r, t, b }
}

/// The short form of a label: the one it was given, else, for a label
/// `NAME = value` (or `NAME ≈ …`, `NAME: …`, `NAME (x, y, z)` as Peye and
/// Pref are labelled) of the mark NAME, its name.
fn brief(l: &super::Label) -> Option<&str> {
    if let Some(s) = &l.short {
        return Some(s);
    }
    [" = ", " ≈ ", ": ", " ("]
        .iter()
        .filter_map(|sep| l.text.split_once(sep).map(|(name, _)| name))
        .find(|name| *name == l.of)
}

/// The marks a label may stand near besides other marks' points: its own
/// and those its text names (`N = V = (0, 0, 1)` names V too: the pieces
/// of the text between ` = ` and ` ≈ `, but the last, that are marks'
/// names), by number.
fn named(l: &super::Label, by_name: &HashMap<&str, usize>) -> Vec<usize> {
    let mut pieces: Vec<&str> = l.text.split(" = ").flat_map(|p| p.split(" ≈ ")).collect();
    pieces.pop();
    let mut own: Vec<usize> = by_name.get(l.of.as_str()).copied().into_iter().collect();
    own.extend(pieces.iter().filter_map(|p| by_name.get(p)).copied());
    own
}

/// The marks a label may stand near, `own`, with every mark whose dot or
/// tip lies on the label's own point (within 1 px): two marks drawn at one
/// place (Pref and a point Q both at the origin, a segment's two
/// intersections at a corner of the box) are one place on the page, and
/// each label stands beside it, as near the other mark as its own.
fn with_coincident(g: &Geom, mut own: Vec<usize>, sc: &Scene) -> Vec<usize> {
    if let Geom::Point(p) = g {
        for (q, k) in &sc.spots {
            if (q.0 - p.0).hypot(q.1 - p.1) <= 1.0 && !own.contains(k) {
                own.push(*k);
            }
        }
    }
    own
}

/// The px box that the marks take, grown by the reach of a label (what
/// lies beyond is indexed in the border cells).
fn area(sc: &Scene) -> Bx {
    let pts = sc.lines.iter().flat_map(|(a, b)| [*a, *b]);
    let pts = pts.chain(sc.blobs.iter().map(|b| b.0));
    let mut b = Bx {
        l: f64::MAX,
        r: f64::MIN,
        t: f64::MAX,
        b: f64::MIN,
    };
    for p in pts {
        b = Bx {
            l: b.l.min(p.0),
            r: b.r.max(p.0),
            t: b.t.min(p.1),
            b: b.b.max(p.1),
        };
    }
    if b.l > b.r {
        return Bx {
            l: 0.0,
            r: WIDTH,
            t: 0.0,
            b: 1.0,
        };
    }
    b.grown(40.0, 40.0)
}

/// Places the labels of a panel (px, y from page y = 0): greedily in the
/// figure's order, then each again among the others, twice; a label that
/// still meets an obstacle and has a short form ([`brief`]) is written
/// short, its whole text going to a note, and left out when even that
/// cannot stand clear (with a note, unless its short form is empty: the
/// figure says it elsewhere, or its text is only its mark's name: such a
/// note says nothing); one with no short form is tried whole once more
/// in the last round, among the others written short. A label stands as
/// near a mark drawn on its own point as its own ([`with_coincident`]).
/// Only the first [`MAX_LABELS`] are placed;
/// the texts of the others are listed in the notes ([`pack`]). Returns
/// the labels, those notes and the work done.
fn place_all(
    f: &Figure,
    by_name: &HashMap<&str, usize>,
    at: &dyn Fn(&[f64; 2]) -> Pt,
) -> (Vec<Option<Placed>>, Vec<String>, Work) {
    let labels: Vec<&super::Label> = f.labels().collect();
    let shown = labels.len().min(MAX_LABELS);
    let marks: Vec<&Mark> = f.marks().collect();
    let jobs: Vec<(Geom, Vec<usize>, Option<Pt>)> = labels[..shown]
        .iter()
        .map(|l| {
            let g = by_name
                .get(l.of.as_str())
                .map_or(Geom::Point(at(&[0.0, 0.0])), |k| geom(marks[*k], at));
            (g, named(l, by_name), l.near.as_ref().map(at))
        })
        .collect();
    let sc = scene(f, at);
    let jobs: Vec<(Geom, Vec<usize>, Option<Pt>)> = jobs
        .into_iter()
        .map(|(g, own, near)| (g.clone(), with_coincident(&g, own, &sc), near))
        .collect();
    let job = |k: usize| Job {
        geom: &jobs[k].0,
        toward: labels[k].toward,
        near: jobs[k].2,
        own: &jobs[k].1,
    };
    let room = area(&sc);
    let mut obs = Obstacles::new(sc, shown, room);
    let mut placed: Vec<(Placed, f64)> = Vec::new();
    for (k, l) in labels[..shown].iter().enumerate() {
        let (p, c) = place(&l.text, text_width(&l.text), &job(k), &mut obs);
        obs.set_box(k, Some(bx(&p)));
        placed.push((p, c));
    }
    let mut short = vec![false; shown];
    for round in 0..3 {
        for (i, l) in labels[..shown].iter().enumerate() {
            if placed[i].1 < 60.0 {
                continue;
            }
            // The last round writes a label short; one with no short
            // form (a bare name: the inset's C″) is tried once more
            // whole, now that the others stand where they end.
            let text = match (round, brief(l)) {
                (0 | 1, _) | (_, None) => &l.text,
                (_, Some(b)) if !b.is_empty() => b,
                _ => {
                    obs.set_box(i, None);
                    continue;
                }
            };
            obs.set_box(i, None);
            let (p, c) = place(text, text_width(text), &job(i), &mut obs);
            if c < placed[i].1 - 1e-9 || round == 2 {
                placed[i] = (p, c);
                short[i] = round == 2 && *text != l.text;
            }
            let stays = round < 2 || placed[i].1 < 60.0;
            obs.set_box(i, stays.then(|| bx(&placed[i].0)));
        }
    }
    // A label written short, or left out because even short it cannot
    // stand clear, has its whole text in a note, unless that text is only
    // its mark's name (it says nothing the panel does not). In a panel of
    // more than MAX_LABELS labels these notes and the texts of the labels
    // beyond are listed together, packed, likewise.
    let crowded = labels.len() > MAX_LABELS;
    let mut notes = Vec::new();
    let mut out = Vec::new();
    for (i, (p, c)) in placed.into_iter().enumerate() {
        let said_elsewhere = labels[i].short.as_deref() == Some("");
        let bare = labels[i].text == labels[i].of;
        if !bare && (short[i] || (c >= 60.0 && !said_elsewhere)) {
            notes.push(labels[i].text.clone());
        }
        out.push((c < 60.0).then_some(p));
    }
    if crowded {
        notes.extend(
            labels[shown..]
                .iter()
                .filter(|l| l.text != l.of && l.short.as_deref() != Some(""))
                .map(|l| l.text.clone()),
        );
        notes = pack(&notes, WIDTH - 2.0 * PAD);
    }
    out.extend(labels[shown..].iter().map(|_| None));
    (out, notes, obs.work)
}

/// Texts listed on as few lines as fit `room` px, ` · ` between them (a
/// text wider than that stands alone, to be broken between words).
fn pack(texts: &[String], room: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for t in texts {
        match lines.last_mut() {
            Some(l) if text_width(&format!("{l} · {t}")) <= room => {
                l.push_str(" · ");
                l.push_str(t);
            }
            _ => lines.push(t.clone()),
        }
    }
    lines
}

/// Lays out one panel.
pub fn lay_out(f: &Figure) -> Laid {
    let mut by_name: HashMap<&str, usize> = HashMap::new();
    for (k, m) in f.marks().enumerate() {
        by_name.entry(m.name.as_str()).or_insert(k);
    }
    let s = fit_scale(f, &by_name);
    let (lo, _) = width_at(f, &by_name, s);
    let tx = PAD - lo;
    let at = |p: &[f64; 2]| (tx + p[0] * s, -p[1] * s);
    let (placed, overflow, work) = place_all(f, &by_name, &at);
    let mut top = f64::MAX;
    let mut bottom = f64::MIN;
    for p in f.marks().flat_map(Mark::points) {
        top = top.min(-p[1] * s - 5.0);
        bottom = bottom.max(-p[1] * s + 5.0);
    }
    for p in placed.iter().flatten() {
        let (_, _, t, b) = p.bounds();
        top = top.min(t);
        bottom = bottom.max(b);
    }
    if top > bottom {
        (top, bottom) = (0.0, 1.0);
    }
    // The notes, one line each (or more) under the drawing.
    let mut notes = Vec::new();
    let texts = f.items.iter().filter_map(|it| match it {
        Item::Note(text) => Some(text),
        _ => None,
    });
    let mut texts = overflow.iter().chain(texts).peekable();
    if texts.peek().is_some() {
        bottom += NOTE_GAP;
    }
    for text in texts {
        for line in wrap(text, WIDTH - 2.0 * PAD) {
            bottom += LINE;
            notes.push(Placed {
                x: PAD,
                y: bottom - DESCENT,
                anchor: Anchor::Start,
                text: line,
            });
        }
    }
    let mut labels = placed;
    let ty = PAD - top;
    for l in labels.iter_mut().flatten().chain(&mut notes) {
        l.y += ty;
    }
    Laid {
        scale: s,
        tx,
        ty,
        height: (bottom - top + 2.0 * PAD).ceil(),
        labels,
        notes,
        work,
    }
}

/// A text broken into lines of at most `room` px between words (a word
/// wider than that stands alone).
fn wrap(text: &str, room: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(l) if text_width(&format!("{l} {word}")) <= room => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Widths of DejaVu Sans at 15 px: a digit 0.636 em = 9.54 px, `x`
    /// 0.592 em = 8.88 px, `−` 0.838 em.
    #[test]
    fn text_widths() {
        assert!((text_width("0") - 9.54).abs() < 1e-9);
        assert!((text_width("x −") - (8.88 + 4.77 + 12.57)).abs() < 1e-9);
    }

    /// A panel of n dots P1 … Pn scattered over a 6 × 4 page area (a
    /// fixed pseudo-random sequence), each labelled `Pk = (x, y)`.
    fn dots(n: usize) -> Figure {
        dots_labelled(n, |name, x, y| format!("{name} = ({x:.2}, {y:.2})"))
    }

    /// As [`dots`], each labelled `text(name, x, y)`.
    fn dots_labelled(n: usize, text: impl Fn(&str, f64, f64) -> String) -> Figure {
        let mut seed: u64 = 12345;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut items = Vec::new();
        for k in 1..=n {
            let (x, y) = (6.0 * next(), 4.0 * next());
            let name = format!("P{k}");
            items.push(super::super::mark(
                &name,
                super::super::Kind::Point,
                super::super::Pen::Given,
                Shape::Dot([x, y]),
            ));
            items.push(super::super::label(&name, text(&name, x, y)));
        }
        Figure {
            items,
            ..Figure::default()
        }
    }

    /// Beyond MAX_LABELS labels a panel places at most the first 40 (those
    /// that stand clear among 400 dots) and lists the
    /// others' texts in its notes; the work stays bounded: a dot's label
    /// is tried at 4 gaps × 20 boxes = 80 candidates, placed once and
    /// again at most 3 times (two rounds and its short form), so at most
    /// 40 × 4 × 80 = 12,800 candidates are costed however many points
    /// there are; the obstacles tested grow with the points near the
    /// labels, not with the square of the points (5 × the points: less
    /// than 8 × the tests; testing every label against every mark would
    /// be 25 ×).
    #[test]
    fn labels_beyond_forty_are_listed_and_the_work_is_bounded() {
        let small = lay_out(&dots(400));
        let big = lay_out(&dots(2000));
        for laid in [&small, &big] {
            assert!(laid.labels[MAX_LABELS..].iter().all(Option::is_none));
            let placed = laid.labels.iter().flatten().count();
            assert!((1..=MAX_LABELS).contains(&placed), "{placed} placed");
            assert!(laid.work.candidates <= 12_800, "{:?}", laid.work);
        }
        let notes: Vec<&str> = big.notes.iter().map(|n| n.text.as_str()).collect();
        let notes = notes.join(" ");
        for k in [41, 1000, 2000] {
            assert!(notes.contains(&format!("P{k} = (")), "P{k} listed");
        }
        // The notes are packed, two or more texts to a line.
        assert!(big.notes.len() <= 2000 / 2, "{} lines", big.notes.len());
        // Labels that are only their dots' names are not listed: a list
        // of names would say nothing the panel does not.
        let bare = lay_out(&dots_labelled(400, |name, _, _| name.to_string()));
        assert!(bare.notes.is_empty(), "{:?}", bare.notes);
        assert!(
            big.work.tests < 8 * small.work.tests,
            "{:?} {:?}",
            small.work,
            big.work
        );
    }
}
