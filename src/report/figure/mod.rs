//! One figure description — plain data: points, segments, arrows, polygons,
//! labels and their styles — and the small writers that turn it into SVG
//! ([`svg`]) and TikZ ([`tikz`]). The builders ([`builders`]) make the
//! description from the same results the worked steps show.
//!
//! 3D points are put on the page by one stated projection, the cabinet
//! oblique projection: x_page = x − k·z, y_page = y − k·z with
//! k = 1/(2√2) (the z axis drawn at 45°, shortened to half).

pub mod builders;
pub mod svg;
pub mod tikz;

/// k of the cabinet projection: half length at 45°, 1/(2√2).
pub const CABINET_K: f64 = 0.353_553_390_593_273_8;

/// A 3D point on the page under the cabinet projection
/// (x − k·z, y − k·z), k = 1/(2√2).
pub fn cabinet(p: [f64; 3]) -> [f64; 2] {
    [p[0] - CABINET_K * p[2], p[1] - CABINET_K * p[2]]
}

/// How a mark is drawn; each has one colour of the Okabe–Ito palette
/// (safe for the common colour-vision deficiencies) and a line pattern,
/// so no meaning rests on colour alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pen {
    /// Outlines of given things (the box): black, thin.
    Frame,
    /// The kept part of a segment: blue, thick, solid.
    Kept,
    /// A part cut off: vermillion, dashed.
    Cut,
    /// A tried point or a helper line: orange, dotted.
    Tried,
    /// A computed vector: bluish green, with an arrow head.
    Vector,
}

impl Pen {
    /// Okabe–Ito colour as #rrggbb.
    pub fn colour(self) -> &'static str {
        match self {
            Pen::Frame => "#000000",
            Pen::Kept => "#0072B2",
            Pen::Cut => "#D55E00",
            Pen::Tried => "#E69F00",
            Pen::Vector => "#009E73",
        }
    }
    /// Whether the line is dashed (cut-off parts).
    pub fn dashed(self) -> bool {
        self == Pen::Cut
    }
    /// Whether the line is dotted (helpers).
    pub fn dotted(self) -> bool {
        self == Pen::Tried
    }
    /// Line width in page points.
    pub fn width(self) -> f64 {
        match self {
            Pen::Kept => 3.0,
            Pen::Frame => 1.2,
            _ => 2.0,
        }
    }
}

/// One mark of a figure, in page coordinates (y up).
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A line from a to b.
    Segment { a: [f64; 2], b: [f64; 2], pen: Pen },
    /// An arrow from a to b (head at b).
    Arrow { a: [f64; 2], b: [f64; 2], pen: Pen },
    /// A closed polygon outline.
    Polygon { pts: Vec<[f64; 2]>, pen: Pen },
    /// A dot.
    Dot { at: [f64; 2], pen: Pen },
    /// A text label at a point (text stays text).
    Label { at: [f64; 2], text: String },
}

/// A figure: what it shows in words (for screen readers) and its marks.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Figure {
    /// Short title (`<title>`).
    pub title: String,
    /// Longer description (`<desc>`), naming the projection.
    pub desc: String,
    /// The marks, drawn in order.
    pub items: Vec<Item>,
}

impl Figure {
    /// The page-coordinate bounding box (min x, min y, max x, max y).
    pub fn bounds(&self) -> [f64; 4] {
        let mut b = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
        let mut add = |p: &[f64; 2]| {
            b[0] = b[0].min(p[0]);
            b[1] = b[1].min(p[1]);
            b[2] = b[2].max(p[0]);
            b[3] = b[3].max(p[1]);
        };
        for it in &self.items {
            match it {
                Item::Segment { a, b, .. } | Item::Arrow { a, b, .. } => {
                    add(a);
                    add(b);
                }
                Item::Polygon { pts, .. } => pts.iter().for_each(&mut add),
                Item::Dot { at, .. } | Item::Label { at, .. } => add(at),
            }
        }
        if b[0] > b[2] {
            return [0.0, 0.0, 1.0, 1.0];
        }
        b
    }
}

/// Escapes text for XML (SVG, XHTML).
pub fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
