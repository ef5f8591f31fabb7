//! One figure description — plain data: named marks (arrows, points,
//! segments, planes, boxes, arcs, axes, windows), the labels that name
//! them, and notes — and the small writers that turn it into SVG
//! ([`svg`]) and TikZ ([`tikz`]). The figure kinds (`camera`,
//! `project`, `window`, `clip`, `shade`) make the description from
//! the same results the worked steps show; [`drawings`] picks them for a
//! report.
//!
//! Every mark has the name the steps use (`N`, `u`, `Peye`, `A''`,
//! `near window`, `xmax`, …) and a kind; a label says which mark it names
//! (`for`), and [`layout`] puts it beside that mark by a small search over
//! candidate places (`place`). The SVG carries them as `data-name`,
//! `data-kind` and `data-for` (docs/spec.md §4).
//!
//! 3D panels are drawn in an axonometric (orthographic) view chosen per
//! figure ([`axo`]) and stated in the panel's description; side views and
//! planes in their own two coordinates; the lighting vectors as a flat
//! diagram in the plane of incidence.

pub mod axo;
pub mod builders;
mod camera;
mod clip;
pub mod drawings;
mod index;
pub mod layout;
mod metrics;
mod place;
mod project;
mod shade;
pub mod svg;
pub mod tikz;
mod window;

/// How a mark is drawn; each has one colour of the Okabe–Ito palette
/// (safe for the common colour-vision deficiencies) and a line pattern,
/// so no meaning rests on colour alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pen {
    /// Outlines of given things (the box, the axes): black, thin.
    Frame,
    /// An edge hidden behind the box: black, thin, dashed.
    Hidden,
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
            Pen::Frame | Pen::Hidden => "#000000",
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
    pub const ALL: [Pen; 8] = [
        Pen::Frame,
        Pen::Hidden,
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
            Pen::Hidden => "gfHidden",
            Pen::Kept => "gfKept",
            Pen::Cut => "gfCut",
            Pen::Tried => "gfTried",
            Pen::Vector => "gfVector",
            Pen::Given => "gfGiven",
            Pen::Other => "gfOther",
        }
    }
    /// The line pattern: SVG dash lengths and the TikZ option, or none
    /// for a solid line.
    pub fn dashes(self) -> Option<(&'static str, &'static str)> {
        match self {
            Pen::Cut => Some(("9 6", "dashed")),
            Pen::Hidden => Some(("5 4", "dash pattern=on 2.5pt off 2pt")),
            Pen::Tried => Some(("2 4", "dotted")),
            Pen::Other => Some(("10 4 2 4", "dash pattern=on 5pt off 2pt on 1pt off 2pt")),
            _ => None,
        }
    }
    /// Line width in px.
    pub fn width(self) -> f64 {
        match self {
            Pen::Kept => 3.0,
            Pen::Frame | Pen::Hidden => 1.2,
            _ => 2.0,
        }
    }
}

/// What a mark is: its `data-kind` in the SVG.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A vector: a line from its tail to its tip, with a head.
    Arrow,
    /// A point: a dot.
    Point,
    /// A segment (a line of sight, a projector, a leg, a cut-off part).
    Segment,
    /// A plane: the view plane, or a face of the clipping box (unstroked).
    Plane,
    /// The clipping box: its twelve edges, hidden ones dashed.
    Box,
    /// An angle's arc.
    Arc,
    /// A coordinate axis: a line from the origin with a head.
    Axis,
    /// A window (near, far, viewport): a rectangle.
    Window,
}

impl Kind {
    /// The `data-kind` word.
    pub fn word(self) -> &'static str {
        match self {
            Kind::Arrow => "arrow",
            Kind::Point => "point",
            Kind::Segment => "segment",
            Kind::Plane => "plane",
            Kind::Box => "box",
            Kind::Arc => "arc",
            Kind::Axis => "axis",
            Kind::Window => "window",
        }
    }
}

/// The geometry of a mark, in page coordinates (y up).
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A line from a to b; with a head at b when `head`.
    Line {
        a: [f64; 2],
        b: [f64; 2],
        head: bool,
    },
    /// A closed outline.
    Polygon(Vec<[f64; 2]>),
    /// A closed region drawn without an outline (a face of the box: its
    /// edges are the box's).
    Face(Vec<[f64; 2]>),
    /// An open polyline (an arc).
    Path(Vec<[f64; 2]>),
    /// A dot.
    Dot([f64; 2]),
    /// Several lines, each with its own pen (the box's edges).
    Edges(Vec<([f64; 2], [f64; 2], Pen)>),
}

/// One drawn object: its name (the steps' name for it), its kind, its pen
/// and its geometry.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// The name (`data-name`), unique in its panel.
    pub name: String,
    /// The kind (`data-kind`).
    pub kind: Kind,
    /// How it is drawn.
    pub pen: Pen,
    /// Where.
    pub shape: Shape,
}

impl Mark {
    /// A mark.
    pub fn new(name: impl Into<String>, kind: Kind, pen: Pen, shape: Shape) -> Mark {
        Mark {
            name: name.into(),
            kind,
            pen,
            shape,
        }
    }
    /// Every page point of the mark.
    pub fn points(&self) -> Vec<[f64; 2]> {
        match &self.shape {
            Shape::Line { a, b, .. } => vec![*a, *b],
            Shape::Polygon(p) | Shape::Face(p) | Shape::Path(p) => p.clone(),
            Shape::Dot(p) => vec![*p],
            Shape::Edges(e) => e.iter().flat_map(|(a, b, _)| [*a, *b]).collect(),
        }
    }
}

/// A label: text beside the mark it names.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The name of the mark it names (`data-for`).
    pub of: String,
    /// The text.
    pub text: String,
    /// A page direction to try first (beyond an arrow's tip, away from
    /// the middle of the drawing), if any.
    pub toward: Option<[f64; 2]>,
    /// A page point to put it beside first (outside a face of the box),
    /// if any; else the middle of the mark.
    pub near: Option<[f64; 2]>,
    /// The short form written when the whole text cannot stand clear
    /// (the whole text then goes to a note); none: the mark's name when
    /// the text is `NAME = …`, `NAME ≈ …` or `NAME: …`; empty: the label
    /// is left out without a note (another panel says it).
    pub short: Option<String>,
}

/// One item of a figure.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A drawn object.
    Mark(Mark),
    /// A label beside a mark.
    Label(Label),
    /// A line of text under the panel (a legend: what a short label near
    /// a mark stands for).
    Note(String),
}

/// A mark item.
pub fn mark(name: impl Into<String>, kind: Kind, pen: Pen, shape: Shape) -> Item {
    Item::Mark(Mark::new(name, kind, pen, shape))
}

/// A label for the mark `of`; `x = ≈ 0.1` is written `x ≈ 0.1`.
pub fn label(of: impl Into<String>, text: impl Into<String>) -> Item {
    label_toward(of, text, None)
}

/// A label for the mark `of` that tries the side `toward` first.
pub fn label_toward(
    of: impl Into<String>,
    text: impl Into<String>,
    toward: Option<[f64; 2]>,
) -> Item {
    Item::Label(Label {
        of: of.into(),
        text: text.into().replace("= ≈ ", "≈ "),
        toward,
        near: None,
        short: None,
    })
}

/// A label for the mark `of` on the side `toward`, written `short` when
/// the whole text cannot stand clear.
pub fn label_short(
    of: impl Into<String>,
    text: impl Into<String>,
    short: impl Into<String>,
    toward: [f64; 2],
) -> Item {
    Item::Label(Label {
        of: of.into(),
        text: text.into(),
        toward: Some(toward),
        near: None,
        short: Some(short.into()),
    })
}

/// A label for the mark `of` put beside the page point `near` first, on
/// its side `toward`.
pub fn label_near(
    of: impl Into<String>,
    text: impl Into<String>,
    near: [f64; 2],
    toward: [f64; 2],
) -> Item {
    Item::Label(Label {
        of: of.into(),
        text: text.into(),
        toward: Some(toward),
        near: Some(near),
        short: None,
    })
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
    /// Longer description (`<desc>`), naming the view it is drawn in.
    pub desc: String,
    /// The marks, labels and notes, drawn in order.
    pub items: Vec<Item>,
    /// The most px the marks may take from top to bottom (none: the
    /// layout's usual 420).
    pub height: Option<f64>,
}

impl Figure {
    /// The marks, in order.
    pub fn marks(&self) -> impl Iterator<Item = &Mark> {
        self.items.iter().filter_map(|it| match it {
            Item::Mark(m) => Some(m),
            _ => None,
        })
    }
    /// The labels, in order.
    pub fn labels(&self) -> impl Iterator<Item = &Label> {
        self.items.iter().filter_map(|it| match it {
            Item::Label(l) => Some(l),
            _ => None,
        })
    }
    /// The mark of this name.
    pub fn mark(&self, name: &str) -> Option<&Mark> {
        self.marks().find(|m| m.name == name)
    }
    /// The page-coordinate bounding box of the marks (min x, min y, max x,
    /// max y).
    pub fn bounds(&self) -> [f64; 4] {
        let mut b = [f64::MAX, f64::MAX, f64::MIN, f64::MIN];
        for p in self.marks().flat_map(Mark::points) {
            b = [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ];
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

/// A value in its exact form alone when it has one (`2/3`, `(1, 4, 3/2)`),
/// else as the steps write it (`≈ 0.4142`).
pub fn exact(st: &crate::report::Style, v: &crate::stages::trace::Val) -> String {
    let full = st.val_inline(v);
    for sep in [" ≈ ", " = "] {
        if let Some((e, _)) = full.split_once(sep) {
            if !e.is_empty() {
                return e.to_string();
            }
        }
    }
    full
}
