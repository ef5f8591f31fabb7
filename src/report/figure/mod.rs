//! One figure description — plain data: points, segments, arrows, polygons,
//! labels and their styles — and the small writers that turn it into SVG
//! ([`svg`]) and TikZ ([`tikz`]). The builders ([`builders`]) make the
//! description from the same results the worked steps show.
//!
//! 3D points are put on the page by one stated projection, the cabinet
//! oblique projection: x_page = x − k·z, y_page = y − k·z with
//! k = 1/(2√2) (the z axis drawn at 45°, shortened to half). Side views
//! and planes are drawn in their own two coordinates, as each panel's
//! description says.
//!
//! A command's drawing is one or more panels ([`Drawing`]): for example the
//! projection in 3D, then its side view. Each panel is a [`Figure`] with
//! its own page coordinates.

pub mod builders;
mod camera;
pub mod drawings;
pub mod layout;
mod project;
mod shade;
pub mod svg;
pub mod tikz;
mod window;

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
    /// A given vector or plane (Vup, L, the view plane): sky blue, solid.
    Given,
    /// A derived direction (R, H) or an angle's arc: reddish purple, dash-dot.
    Other,
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
            Pen::Given => "#56B4E9",
            Pen::Other => "#CC79A7",
        }
    }
    /// Every pen, in a fixed order (the writers define one colour and one
    /// arrow head each).
    pub const ALL: [Pen; 7] = [
        Pen::Frame,
        Pen::Kept,
        Pen::Cut,
        Pen::Tried,
        Pen::Vector,
        Pen::Given,
        Pen::Other,
    ];
    /// The pen's name in the writers (`gfKept`).
    pub fn name(self) -> &'static str {
        match self {
            Pen::Frame => "gfFrame",
            Pen::Kept => "gfKept",
            Pen::Cut => "gfCut",
            Pen::Tried => "gfTried",
            Pen::Vector => "gfVector",
            Pen::Given => "gfGiven",
            Pen::Other => "gfOther",
        }
    }
    /// Whether the line is dashed (cut-off parts).
    pub fn dashed(self) -> bool {
        self == Pen::Cut
    }
    /// Whether the line is dash-dotted (derived directions).
    pub fn dash_dotted(self) -> bool {
        self == Pen::Other
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
    /// An open polyline (an angle's arc).
    Path { pts: Vec<[f64; 2]>, pen: Pen },
    /// A dot.
    Dot { at: [f64; 2], pen: Pen },
    /// A text label beside a point (text stays text), on the side `place`
    /// (the writers move it further along when it would overlap another).
    Label {
        at: [f64; 2],
        text: String,
        place: Place,
    },
    /// A line of text under the panel (a legend: what a short label near
    /// a mark stands for).
    Note { text: String },
}

/// Where a label sits from its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Place {
    /// Above and to the right (the default).
    #[default]
    AboveRight,
    /// Above, centred.
    Above,
    /// Above and to the left.
    AboveLeft,
    /// To the left.
    Left,
    /// Below and to the left.
    BelowLeft,
    /// Below, centred.
    Below,
    /// Below and to the right.
    BelowRight,
    /// To the right.
    Right,
}

/// The eight sides of a point, counter-clockwise from the right (the
/// directions 0°, 45°, …, 315° on the page).
pub const RING: [Place; 8] = [
    Place::Right,
    Place::AboveRight,
    Place::Above,
    Place::AboveLeft,
    Place::Left,
    Place::BelowLeft,
    Place::Below,
    Place::BelowRight,
];

impl Place {
    /// The side a label goes on beyond the tip of an arrow pointing along
    /// `d` (page direction, y up): the eight compass sides.
    pub fn beyond(d: [f64; 2]) -> Place {
        if d[0] == 0.0 && d[1] == 0.0 {
            return Place::AboveRight;
        }
        let a = d[1].atan2(d[0]).to_degrees();
        let k = (((a + 360.0 + 22.5) % 360.0) / 45.0) as usize;
        RING[k.min(7)]
    }
}

/// A label item at `at` with the default place.
pub fn label(at: [f64; 2], text: impl Into<String>) -> Item {
    label_at(at, text, Place::AboveRight)
}

/// A label item on a chosen side; `x = ≈ 0.1` is written `x ≈ 0.1`.
pub fn label_at(at: [f64; 2], text: impl Into<String>, place: Place) -> Item {
    Item::Label {
        at,
        text: text.into().replace("= ≈ ", "≈ "),
        place,
    }
}

/// A drawing: the panels of one command or one part of a problem (for
/// `solve`), named by the part (`view`, `project`, …).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Drawing {
    /// The part (`view`, `project`, `window`, `clip`, `shade`).
    pub part: String,
    /// The panels, drawn one below the other.
    pub panels: Vec<Figure>,
}

impl Drawing {
    /// The title of the whole drawing: its panels' titles.
    pub fn title(&self) -> String {
        let t: Vec<&str> = self.panels.iter().map(|f| f.title.as_str()).collect();
        t.join("; ")
    }
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
                Item::Polygon { pts, .. } | Item::Path { pts, .. } => pts.iter().for_each(&mut add),
                Item::Dot { at, .. } | Item::Label { at, .. } => add(at),
                Item::Note { .. } => {}
            }
        }
        if b[0] > b[2] {
            return [0.0, 0.0, 1.0, 1.0];
        }
        b
    }
}

/// Escapes text for XML (SVG, XHTML): [`crate::report::escape::xml`].
pub fn xml_escape(s: &str) -> String {
    crate::report::escape::xml(s)
}

/// `name = value` as a label, or `name ≈ value` when the value is an
/// approximation (`A ≈ (0, −1, −4.243)`, not `A = ≈ …`).
pub fn labelled(st: &crate::report::Style, name: &str, v: &crate::stages::trace::Val) -> String {
    let s = short(st, v);
    match s.strip_prefix("≈ ") {
        Some(rest) => format!("{name} ≈ {rest}"),
        None => format!("{name} = {s}"),
    }
}

/// A value as a figure's label writes it: the worked steps' own form
/// (`(4/5, 3/5, 0) = (0.8, 0.6, 0)`) when short, else the exact form when
/// that is short, else the decimals.
pub fn short(st: &crate::report::Style, v: &crate::stages::trace::Val) -> String {
    let full = st.val_inline(v);
    if full.chars().count() <= 26 {
        return full;
    }
    for sep in [" ≈ ", " = "] {
        if let Some((exact, dec)) = full.split_once(sep) {
            return if exact.chars().count() <= 22 && !exact.is_empty() {
                exact.to_string()
            } else if sep == " ≈ " {
                format!("≈ {dec}")
            } else {
                dec.to_string()
            };
        }
    }
    full
}
