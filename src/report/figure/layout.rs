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
//! even that cannot, left out (its text in the note).

pub use super::metrics::{text_width, Anchor, Placed, ASCENT, DESCENT, FONT, WIDTH};
use super::place::{place, Bx, Geom, Obstacles, Pt};
use super::{Figure, Item, Mark, Shape};

/// Space kept around a panel, px.
const PAD: f64 = 14.0;
/// One line of notes, px.
const LINE: f64 = 20.0;
/// The tallest a panel is drawn, px (a tall drawing is scaled down).
const MAX_HEIGHT: f64 = 420.0;

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

/// The marks' lines, dots and arrow heads in px.
fn obstacles(f: &Figure, at: &dyn Fn(&[f64; 2]) -> Pt) -> Obstacles {
    let mut o = Obstacles::default();
    for m in f.marks() {
        let half = m.pen.width() / 2.0;
        match &m.shape {
            Shape::Line { a, b, head } => {
                let (p, q) = (at(a), at(b));
                o.lines.push((p, q));
                if *head {
                    // The head: 7 line widths long, ending at the tip.
                    let l = (q.0 - p.0).hypot(q.1 - p.1).max(1e-9);
                    let back = 5.0 * half;
                    let c = (q.0 - (q.0 - p.0) / l * back, q.1 - (q.1 - p.1) / l * back);
                    o.blobs.push((c, 8.0 * half));
                }
            }
            Shape::Polygon(_) | Shape::Path(_) | Shape::Edges(_) => {
                if let Geom::Lines(ls) = geom(m, at) {
                    o.lines.extend(ls);
                }
            }
            Shape::Dot(p) => o.blobs.push((at(p), 5.5)),
            Shape::Face(_) => {}
        }
    }
    o
}

/// The horizontal extent in px of the marks and, roughly, their labels at
/// scale s: a label takes its width on the side it asks for, else half its
/// width each side of the middle of its mark.
fn width_at(f: &Figure, s: f64) -> (f64, f64) {
    let mut lo = f64::MAX;
    let mut hi = f64::MIN;
    for p in f.marks().flat_map(Mark::points) {
        lo = lo.min(p[0] * s - 5.0);
        hi = hi.max(p[0] * s + 5.0);
    }
    for l in f.labels() {
        let Some(m) = f.mark(&l.of) else { continue };
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
fn fit_scale(f: &Figure) -> f64 {
    let [x0, y0, x1, y1] = f.bounds();
    let room = WIDTH - 2.0 * PAD;
    let mut hi = room / (x1 - x0).max(1e-9);
    hi = hi.min(f.height.unwrap_or(MAX_HEIGHT) / (y1 - y0).max(1e-9));
    let fits = |s: f64| {
        let (l, r) = width_at(f, s);
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

/// The side and the point a label asks for, in px.
fn wish(l: &super::Label, at: &dyn Fn(&[f64; 2]) -> Pt) -> (Option<[f64; 2]>, Option<Pt>) {
    (l.toward, l.near.as_ref().map(at))
}

/// The short form of a label: the one it was given, else, for a label
/// `NAME = value` (or `NAME ≈ …`, `NAME: …`) of the mark NAME, its name.
fn brief(l: &super::Label) -> Option<&str> {
    if let Some(s) = &l.short {
        return Some(s);
    }
    [" = ", " ≈ ", ": "]
        .iter()
        .filter_map(|sep| l.text.split_once(sep).map(|(name, _)| name))
        .find(|name| *name == l.of)
}

/// Places the labels of a panel (px, y from page y = 0): greedily in the
/// figure's order, then each again among the others, twice; a label that
/// still crosses a line or another label and has a short form
/// ([`brief`]) is written short, its whole text going to a note, and left
/// out when even that cannot stand clear (with a note, unless its short
/// form is empty: the figure says it elsewhere). Returns the labels and
/// those notes.
fn place_all(f: &Figure, at: &dyn Fn(&[f64; 2]) -> Pt) -> (Vec<Option<Placed>>, Vec<String>) {
    let mut obs = obstacles(f, at);
    let jobs: Vec<(Geom, &super::Label)> = f
        .labels()
        .map(|l| {
            let g = f
                .mark(&l.of)
                .map_or(Geom::Point(at(&[0.0, 0.0])), |m| geom(m, at));
            (g, l)
        })
        .collect();
    let mut placed: Vec<(Placed, f64)> = Vec::new();
    for (g, l) in &jobs {
        let (p, c) = place(&l.text, text_width(&l.text), g, wish(l, at), &obs);
        obs.boxes.push(bx(&p));
        placed.push((p, c));
    }
    let mut short = vec![false; jobs.len()];
    for round in 0..3 {
        for (i, (g, l)) in jobs.iter().enumerate() {
            if placed[i].1 < 60.0 {
                continue;
            }
            let text = match (round, brief(l)) {
                (0 | 1, _) => &l.text,
                (_, Some(b)) if !b.is_empty() => b,
                _ => continue,
            };
            let mut others = obs.clone();
            others.boxes.remove(i);
            let (p, c) = place(text, text_width(text), g, wish(l, at), &others);
            if c < placed[i].1 - 1e-9 || round == 2 {
                obs.boxes[i] = bx(&p);
                placed[i] = (p, c);
                short[i] = round == 2;
            }
        }
    }
    // A label written short, or left out because even short it cannot
    // stand clear, has its whole text in a note.
    let mut notes = Vec::new();
    let mut labels = Vec::new();
    for (i, (p, c)) in placed.into_iter().enumerate() {
        let said_elsewhere = jobs[i].1.short.as_deref() == Some("");
        if short[i] || (c >= 60.0 && !said_elsewhere) {
            notes.push(jobs[i].1.text.clone());
        }
        labels.push((c < 60.0).then_some(p));
    }
    (labels, notes)
}

/// Lays out one panel.
pub fn lay_out(f: &Figure) -> Laid {
    let s = fit_scale(f);
    let (lo, _) = width_at(f, s);
    let tx = PAD - lo;
    let at = |p: &[f64; 2]| (tx + p[0] * s, -p[1] * s);
    let (placed, overflow) = place_all(f, &at);
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
    for text in overflow.iter().chain(texts) {
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
}
