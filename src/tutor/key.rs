//! An answer's key as a typed value: `view.points.A`, `window.far_top`,
//! `clip[2].intersections.left.t`, `shade.lights[1].attenuation`, a whole
//! part (`view`, `clip[1]`), one component of a value (`view.points.A.1`,
//! `view.matrix.2.3`), or a calculator command's own key without its part
//! (`top`, `points.A`).
//!
//! The keys are a contract (docs/spec.md §3's JSON, answer and problem
//! files), so each name is spelled in ONE place, [`Node`]'s `Display`
//! (a part's by [`Part::name`], beside the part in the input layer, where
//! a problem file's `ask` reads it);
//! a [`Key`] is written from its nodes and read back by [`Key::from_str`]
//! (`clip.2.status` and `clip[2].status` alike). The words people read for
//! a key are `report::words::keys`, one exhaustive match per language over
//! these types: a new part's keys are new variants here, and the compiler
//! then asks for their words.

pub use crate::input::part::Part;
use crate::stages::clip::PLANE_KEYS;
use std::fmt;
use std::str::FromStr;

/// The one after `x` in `all`.
fn after<T: PartialEq + Copy>(all: &[T], x: T) -> Option<T> {
    let i = all.iter().position(|y| *y == x)?;
    all.get(i + 1).copied()
}

/// `first` and each `next` after it.
fn every<T: Copy>(first: T, next: fn(T) -> Option<T>) -> Vec<T> {
    std::iter::successors(Some(first), |x| next(*x)).collect()
}

/// A camera axis: `u`, `v`, `n`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// u, to the right.
    U,
    /// v, up in the picture.
    V,
    /// n, from the look-at point back to the eye.
    N,
}

/// An edge or a size of the viewing window.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Edge {
    /// `top`, the text's h.
    Top,
    /// `bottom` = −top.
    Bottom,
    /// `left` = −right.
    Left,
    /// `right` = aspect · top.
    Right,
    /// `height` = 2 · top.
    Height,
    /// `width` = 2 · right.
    Width,
}

/// One of the six planes of the clipping box, in outcode bit order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Plane {
    /// bit 1, x = xmin.
    Left,
    /// bit 2, x = xmax.
    Right,
    /// bit 3, y = ymin.
    Bottom,
    /// bit 4, y = ymax.
    Top,
    /// bit 5, z = zmin.
    Front,
    /// bit 6, z = zmax.
    Back,
}

impl Plane {
    /// The planes in outcode bit order (bit 1 first).
    pub const ALL: [Plane; 6] = [
        Plane::Left,
        Plane::Right,
        Plane::Bottom,
        Plane::Top,
        Plane::Front,
        Plane::Back,
    ];

    /// Its 0-based outcode bit.
    pub fn bit(self) -> usize {
        self as usize
    }
}

/// What is asked of one tried intersection.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cut {
    /// `t`, the segment's parameter at the plane.
    T,
    /// `point`, P(t).
    Point,
    /// `code`, P(t)'s outcode.
    Code,
    /// `kept`, whether P(t) is inside (code 000000).
    Kept,
}

/// A value of the lighting.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shading {
    /// `L`, the unit vector to the light.
    L,
    /// `N`, the unit normal.
    N,
    /// `cos_alpha` = L·N.
    CosAlpha,
    /// `R`, the reflection of L.
    R,
    /// `H`, the half-way vector (Blinn–Phong).
    H,
    /// `N_dot_H` (Blinn–Phong).
    NDotH,
    /// `cos_beta` = R·V.
    CosBeta,
    /// `ambient`, the ambient term.
    Ambient,
    /// `diffuse`, the diffuse term.
    Diffuse,
    /// `specular`, the specular term.
    Specular,
    /// `emissive`, the material's own light.
    Emissive,
    /// `unclamped`, the sum of the terms.
    Unclamped,
    /// `color`, the sum clamped to [0, 1].
    Color,
}

impl Shading {
    /// Every value of the lighting.
    pub fn all() -> Vec<Shading> {
        every(Shading::L, Shading::next)
    }

    /// The value after this one: an exhaustive match, so a new value is
    /// listed (and read from a key) as soon as it compiles.
    fn next(self) -> Option<Shading> {
        use Shading::*;
        match self {
            L => Some(N),
            N => Some(CosAlpha),
            CosAlpha => Some(R),
            R => Some(H),
            H => Some(NDotH),
            NDotH => Some(CosBeta),
            CosBeta => Some(Ambient),
            Ambient => Some(Diffuse),
            Diffuse => Some(Specular),
            Specular => Some(Emissive),
            Emissive => Some(Unclamped),
            Unclamped => Some(Color),
            Color => None,
        }
    }
}

impl Shading {
    /// Whether the value is a colour (its components r, g, b) rather than
    /// a vector (x, y, z) or a number.
    pub fn is_colour(self) -> bool {
        use Shading::*;
        match self {
            Ambient | Diffuse | Specular | Emissive | Unclamped | Color => true,
            L | N | CosAlpha | R | H | NDotH | CosBeta => false,
        }
    }
}

/// One light's factors (a light from a file).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Factor {
    /// `in_range`: d ≤ range.
    InRange,
    /// `distance`, d.
    Distance,
    /// `attenuation`, Att.
    Attenuation,
    /// `spot`, the spot factor.
    Spot,
}

/// A name directly inside a part (a calculator command's result key).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// `u`, `v`, `n`.
    Axis(Axis),
    /// `matrix`, the view matrix V.
    Matrix,
    /// `points`, the map of named points.
    Points,
    /// `pixels`, the map of named pixels.
    Pixels,
    /// `top`, …; `far_top`, … (`true`: on the far plane).
    Edge(Edge, bool),
    /// `code0`, P0's outcode.
    Code0,
    /// `code1`, P1's outcode.
    Code1,
    /// `status`: accepted, rejected or clipped.
    Status,
    /// `segment`, the clipped segment.
    Segment,
    /// `intersections`, the planes tried.
    Intersections,
    /// A value of the lighting.
    Shading(Shading),
    /// `lights`, each light's factors.
    Lights,
}

impl Part {
    /// Its key in the results (`view`, …).
    pub fn key(self) -> String {
        Node::Part(self).to_string()
    }
}

impl Field {
    /// Its key in the results (`u`, `far_top`, `cos_alpha`, …).
    pub fn key(self) -> String {
        Node::Field(self).to_string()
    }

    /// Every field, each once (the far edges as well as the near).
    pub fn all() -> Vec<Field> {
        every(Field::Axis(Axis::U), Field::next)
    }

    /// The field after this one: an exhaustive match, so a new field is
    /// listed (and read from a key) as soon as it compiles.
    fn next(self) -> Option<Field> {
        use Field::*;
        Some(match self {
            Axis(a) => after(&AXES, a).map_or(Matrix, Axis),
            Matrix => Points,
            Points => Pixels,
            Pixels => Edge(EDGES[0], false),
            Edge(e, far) => match (after(&EDGES, e), far) {
                (Some(e), _) => Edge(e, far),
                (None, false) => Edge(EDGES[0], true),
                (None, true) => Code0,
            },
            Code0 => Code1,
            Code1 => Status,
            Status => Segment,
            Segment => Intersections,
            Intersections => Shading(self::Shading::L),
            Shading(s) => s.next().map_or(Lights, Shading),
            Lights => return None,
        })
    }

    /// The parts a field belongs to: an exhaustive match, so a new field
    /// stops the build here until it says whose results hold it (here,
    /// beneath the parts' modules, which read keys).
    pub(crate) fn in_part(self, part: Part) -> bool {
        use Field::*;
        match self {
            Axis(_) | Matrix => part == Part::View,
            Points => matches!(part, Part::View | Part::Project),
            Pixels => part == Part::Viewport,
            Edge(..) => part == Part::Window,
            Code0 | Code1 | Status | Segment | Intersections => part == Part::Clip,
            Shading(_) | Lights => part == Part::Shade,
        }
    }
}

const AXES: [Axis; 3] = [Axis::U, Axis::V, Axis::N];

const EDGES: [Edge; 6] = [
    Edge::Top,
    Edge::Bottom,
    Edge::Left,
    Edge::Right,
    Edge::Height,
    Edge::Width,
];

const CUTS: [Cut; 4] = [Cut::T, Cut::Point, Cut::Code, Cut::Kept];

const FACTORS: [Factor; 4] = [
    Factor::InRange,
    Factor::Distance,
    Factor::Attenuation,
    Factor::Spot,
];

/// One name of the results (and of their JSON), read with the name it is under: a part, a
/// field of a part, a point's own name (under `points`, `pixels`), a plane
/// (under `intersections`), what is asked of an intersection (under a
/// plane), a light's factor (under `lights`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// `view`, …
    Part(Part),
    /// `u`, `top`, `code0`, `color`, …
    Field(Field),
    /// `A`: a point's name, as its problem or flag gives it.
    Point(String),
    /// `left`, …
    Plane(Plane),
    /// `t`, `point`, `code`, `kept`.
    Cut(Cut),
    /// `in_range`, `distance`, `attenuation`, `spot`.
    Factor(Factor),
}

impl fmt::Display for Node {
    /// The spelling of every name of every key: the one place it is written.
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        use Shading as S;
        let s = match self {
            Node::Part(p) => p.name(),
            Node::Field(field) => match field {
                Field::Axis(Axis::U) => "u",
                Field::Axis(Axis::V) => "v",
                Field::Axis(Axis::N) => "n",
                Field::Matrix => "matrix",
                Field::Points => "points",
                Field::Pixels => "pixels",
                Field::Edge(e, far) => {
                    let edge = match e {
                        Edge::Top => "top",
                        Edge::Bottom => "bottom",
                        Edge::Left => "left",
                        Edge::Right => "right",
                        Edge::Height => "height",
                        Edge::Width => "width",
                    };
                    return write!(f, "{}{edge}", if *far { "far_" } else { "" });
                }
                Field::Code0 => "code0",
                Field::Code1 => "code1",
                Field::Status => "status",
                Field::Segment => "segment",
                Field::Intersections => "intersections",
                Field::Shading(s) => match s {
                    S::L => "L",
                    S::N => "N",
                    S::CosAlpha => "cos_alpha",
                    S::R => "R",
                    S::H => "H",
                    S::NDotH => "N_dot_H",
                    S::CosBeta => "cos_beta",
                    S::Ambient => "ambient",
                    S::Diffuse => "diffuse",
                    S::Specular => "specular",
                    S::Emissive => "emissive",
                    S::Unclamped => "unclamped",
                    S::Color => "color",
                },
                Field::Lights => "lights",
            },
            Node::Point(name) => name,
            Node::Plane(p) => PLANE_KEYS[p.bit()],
            Node::Cut(c) => match c {
                Cut::T => "t",
                Cut::Point => "point",
                Cut::Code => "code",
                Cut::Kept => "kept",
            },
            Node::Factor(x) => match x {
                Factor::InRange => "in_range",
                Factor::Distance => "distance",
                Factor::Attenuation => "attenuation",
                Factor::Spot => "spot",
            },
        };
        f.write_str(s)
    }
}

impl serde::Serialize for Node {
    /// JSON names a result by its one spelling ([`Node`]'s `Display`).
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl From<Field> for Node {
    fn from(f: Field) -> Node {
        Node::Field(f)
    }
}

impl From<Cut> for Node {
    fn from(c: Cut) -> Node {
        Node::Cut(c)
    }
}

impl From<Factor> for Node {
    fn from(x: Factor) -> Node {
        Node::Factor(x)
    }
}

impl Cut {
    /// Its key in the results (`t`, …).
    pub fn key(self) -> String {
        Node::Cut(self).to_string()
    }
}

impl Factor {
    /// Its key in the results (`in_range`, …).
    pub fn key(self) -> String {
        Node::Factor(self).to_string()
    }
}

impl Node {
    /// The name `s` under `under` (`None`: at the top of a result, a part
    /// or a calculator command's field); `None` if no key has it there.
    pub fn read(s: &str, under: Option<&Node>) -> Option<Node> {
        let one = |cands: Vec<Node>| cands.into_iter().find(|n| n.to_string() == s);
        match under {
            None => one(Part::all().into_iter().map(Node::Part).collect())
                .or_else(|| one(Field::all().into_iter().map(Node::Field).collect())),
            Some(Node::Part(p)) => one((Field::all().into_iter())
                .filter(|f| f.in_part(*p))
                .map(Node::Field)
                .collect()),
            Some(Node::Field(Field::Points | Field::Pixels)) => {
                (!s.is_empty()).then(|| Node::Point(s.to_string()))
            }
            Some(Node::Field(Field::Intersections)) => one(Plane::ALL.map(Node::Plane).to_vec()),
            Some(Node::Plane(_)) => one(CUTS.map(Node::Cut).to_vec()),
            Some(Node::Field(Field::Lights)) => one(FACTORS.map(Node::Factor).to_vec()),
            Some(_) => None,
        }
    }
}

/// What a key names inside its part.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Value {
    /// The whole part: `view`, `clip.1` (one segment of a clip with
    /// several).
    Whole,
    /// A field: `n`, `matrix`, `points` (the whole map), `status`, …
    Field(Field),
    /// `points.A`.
    Point(String),
    /// `pixels.A`.
    Pixel(String),
    /// `intersections.left` (all that is asked of it).
    Plane(Plane),
    /// `intersections.left.t`, …
    Cut(Plane, Cut),
    /// `lights.1`: one light's factors (the index as written).
    Light(usize),
    /// `lights.1.attenuation`, …
    Factor(usize, Factor),
}

/// An answer's key: its part (none for a calculator command's own keys),
/// the segment of a clip with several (the index as written: `clip.0` in
/// the results, `clip[1]` numbered for people), and the value.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Key {
    /// `view`, …; `None` for a calculator command's key (`top`).
    pub part: Option<Part>,
    /// The segment of a clip problem with several.
    pub segment: Option<usize>,
    /// What is named inside the part.
    pub value: Value,
    /// One component of the value: the indices into its lists, outermost
    /// first (`view.points.A.1` is A's y, `view.matrix.2` the matrix's
    /// row 2 and `view.matrix.2.3` one entry, `clip.segment.0` the clipped
    /// segment's first end, `viewport.pixels.A.0` the pixel's x); empty
    /// for the whole value.
    pub component: Vec<usize>,
}

impl Key {
    /// `part.value`, one segment or none.
    pub fn new(part: Part, value: Value) -> Key {
        Key {
            part: Some(part),
            segment: None,
            value,
            component: Vec::new(),
        }
    }

    /// This key for segment `i` of a clip problem.
    pub fn of_segment(self, i: Option<usize>) -> Key {
        Key { segment: i, ..self }
    }
}

/// A part's key with the segment of a clip with several: `view`,
/// `clip.1` (the start of its answers' keys).
pub fn prefix(part: Part, segment: Option<usize>) -> String {
    match segment {
        Some(i) => format!("{}.{i}", Node::Part(part)),
        None => part.key(),
    }
}

impl fmt::Display for Key {
    /// The key as the results spell it: `clip.2.intersections.left.t`,
    /// `shade.lights.0.attenuation`, `clip.1` (a whole part),
    /// `view.points.A.1` (a component; a whole part without its part is no
    /// key, and spelled empty).
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        if let Some(p) = self.part {
            f.write_str(&prefix(p, self.segment))?;
            if self.value != Value::Whole {
                f.write_str(".")?;
            }
        }
        self.fmt_value(f)?;
        self.component.iter().try_for_each(|i| write!(f, ".{i}"))
    }
}

impl Key {
    /// The value's names inside its part (`points.A`).
    fn fmt_value(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let field = |x| Node::Field(x);
        match &self.value {
            Value::Whole => Ok(()),
            Value::Field(x) => write!(f, "{}", field(*x)),
            Value::Point(n) => write!(f, "{}.{n}", field(Field::Points)),
            Value::Pixel(n) => write!(f, "{}.{n}", field(Field::Pixels)),
            Value::Plane(p) => write!(f, "{}.{}", field(Field::Intersections), Node::Plane(*p)),
            Value::Cut(p, c) => write!(
                f,
                "{}.{}.{}",
                field(Field::Intersections),
                Node::Plane(*p),
                Node::Cut(*c)
            ),
            Value::Light(i) => write!(f, "{}.{i}", field(Field::Lights)),
            Value::Factor(i, x) => write!(f, "{}.{i}.{}", field(Field::Lights), Node::Factor(*x)),
        }
    }
}

impl serde::Serialize for Key {
    /// JSON writes a key as its one spelling ([`Key`]'s `Display`).
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// A string that is no answer key.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NotAKey;

impl FromStr for Key {
    type Err = NotAKey;

    /// Reads `clip.2.intersections.left.t` and `clip[2].intersections.left.t`
    /// alike (an index after a name or as a name of its own), a whole part
    /// (`view`, `clip[1]`), a component (`view.points.A.1`,
    /// `view.points.A[1]`), and a calculator command's keys without their
    /// part (`top`, `points.A`). A number under `points` or `pixels` is a
    /// point's name (`view.points.1`).
    fn from_str(s: &str) -> Result<Key, NotAKey> {
        Key::from_names(s.split('.'))
    }
}

impl Key {
    /// A key from its names in order, as a TOML table's path gives them
    /// (`view.points.A` in an answer file is `view`, `points`, `A`), read
    /// as [`Key::from_str`] reads the names between its dots: an index as a
    /// name of its own (`2`) or after one (`clip[2]`).
    pub fn from_names<'a>(names: impl IntoIterator<Item = &'a str>) -> Result<Key, NotAKey> {
        let mut read = Read::default();
        for name in names {
            let (name, index) = match name.split_once('[') {
                Some((n, i)) => {
                    let i = i.strip_suffix(']').and_then(|i| i.parse().ok());
                    (n, Some(i.ok_or(NotAKey)?))
                }
                None if name.is_empty() => return Err(NotAKey),
                None => match (name.parse::<usize>(), read.nodes.last()) {
                    (Ok(_), Some(Node::Field(Field::Points | Field::Pixels))) => (name, None),
                    (Ok(i), _) => ("", Some(i)),
                    (Err(_), _) => (name, None),
                },
            };
            if !name.is_empty() {
                read.name(name)?;
            }
            if let Some(i) = index {
                read.index(i)?;
            }
        }
        read.key()
    }
}

/// A key's names and indices as read so far.
#[derive(Default)]
struct Read {
    nodes: Vec<Node>,
    segment: Option<usize>,
    light: Option<usize>,
    component: Vec<usize>,
}

impl Read {
    /// A name under the last one read (none after a component).
    fn name(&mut self, name: &str) -> Result<(), NotAKey> {
        if !self.component.is_empty() {
            return Err(NotAKey);
        }
        let node = Node::read(name, self.nodes.last()).ok_or(NotAKey)?;
        self.nodes.push(node);
        Ok(())
    }

    /// An index after the last name: a clip's segment, a light, or a
    /// component of a value that is a list (a vector, point, matrix,
    /// segment; a map of names has none).
    fn index(&mut self, i: usize) -> Result<(), NotAKey> {
        match self.nodes.last() {
            Some(Node::Part(Part::Clip)) if self.segment.is_none() => self.segment = Some(i),
            Some(Node::Field(Field::Lights)) if self.light.is_none() => self.light = Some(i),
            None
            | Some(Node::Part(_))
            | Some(Node::Plane(_))
            | Some(Node::Field(
                Field::Lights | Field::Points | Field::Pixels | Field::Intersections,
            )) => return Err(NotAKey),
            Some(Node::Field(_) | Node::Point(_) | Node::Cut(_) | Node::Factor(_)) => {
                self.component.push(i)
            }
        }
        Ok(())
    }

    /// The key of the names read, with the indices they carried.
    fn key(self) -> Result<Key, NotAKey> {
        let (part, rest) = match &self.nodes[..] {
            [Node::Part(p), rest @ ..] => (Some(*p), rest),
            rest => (None, rest),
        };
        let value = match (rest, self.light) {
            ([Node::Field(Field::Lights)], Some(i)) => Value::Light(i),
            ([Node::Field(Field::Lights), Node::Factor(x)], Some(i)) => Value::Factor(i, *x),
            (_, Some(_)) => return Err(NotAKey),
            ([], None) if part.is_some() => Value::Whole,
            ([Node::Field(f)], None) => Value::Field(*f),
            ([Node::Field(Field::Points), Node::Point(n)], None) => Value::Point(n.clone()),
            ([Node::Field(Field::Pixels), Node::Point(n)], None) => Value::Pixel(n.clone()),
            ([Node::Field(Field::Intersections), Node::Plane(p)], None) => Value::Plane(*p),
            ([_, Node::Plane(p), Node::Cut(c)], None) => Value::Cut(*p, *c),
            _ => return Err(NotAKey),
        };
        Ok(Key {
            part,
            segment: self.segment,
            value,
            component: self.component,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn keys_are_read_in_both_spellings_of_a_segment() {
        let t = Key::new(Part::Clip, Value::Cut(Plane::Left, Cut::T)).of_segment(Some(2));
        assert_eq!(key("clip.2.intersections.left.t"), t);
        assert_eq!(key("clip[2].intersections.left.t"), t);
        assert_eq!(t.to_string(), "clip.2.intersections.left.t");
        let att = key("shade.lights[1].attenuation");
        assert_eq!(
            att,
            Key::new(Part::Shade, Value::Factor(1, Factor::Attenuation))
        );
        assert_eq!(att.to_string(), "shade.lights.1.attenuation");
    }

    #[test]
    fn every_spelling_reads_back_to_its_key() {
        let spelled = [
            "view.u",
            "view.n",
            "view.matrix",
            "view.points",
            "view.points.A",
            "project.points.P0",
            "window.top",
            "window.far_width",
            "viewport.pixels.B",
            "clip.code0",
            "clip.status",
            "clip.segment",
            "clip.intersections.back",
            "clip.0.intersections.front.kept",
            "shade.N_dot_H",
            "shade.cos_alpha",
            "shade.color",
            "shade.lights.0",
            "shade.lights.2.in_range",
            "top",
            "far_bottom",
            "points.A",
            "intersections.top.point",
            "lights.0.spot",
            // a whole part, a component
            "view",
            "clip.1",
            "view.points.A.1",
            "view.points.1",
            "view.points.1.2",
            "view.matrix.2",
            "view.matrix.2.3",
            "view.n.0",
            "clip.segment.1.2",
            "clip.0.intersections.left.point.2",
            "viewport.pixels.A.0",
            "shade.color.2",
            "points.A.1",
        ];
        for s in spelled {
            assert_eq!(key(s).to_string(), s);
        }
    }

    #[test]
    fn names_that_are_no_key_are_refused() {
        for s in [
            "",
            "view.top",
            "view.2.n",
            "window.far_",
            "clip.intersections.middle.t",
            "clip.intersections.left.x",
            "clip[x].status",
            "clip[1",
            "clip.1.2.status",
            "shade.lights.attenuation",
            "shade.cos",
            "view.points.",
            "View.n",
            "view.1",
            "view.points.A.1.x",
            "view.points[1]",
            "view.matrix[1][2]",
            "clip.intersections.left.1",
            "shade.lights.0.0",
            "0",
            "[1]",
        ] {
            assert_eq!(s.parse::<Key>(), Err(NotAKey), "{s}");
        }
    }

    #[test]
    fn a_whole_part_and_a_component_are_read_in_both_spellings() {
        let whole = Key::new(Part::Clip, Value::Whole).of_segment(Some(1));
        assert_eq!(key("clip[1]"), whole);
        assert_eq!(key("clip.1"), whole);
        assert_eq!(whole.to_string(), "clip.1");
        assert_eq!(key("view"), Key::new(Part::View, Value::Whole));
        let y = Key {
            component: vec![1],
            ..Key::new(Part::View, Value::Point("A".into()))
        };
        assert_eq!(key("view.points.A.1"), y);
        assert_eq!(key("view.points.A[1]"), y);
        assert_eq!(y.to_string(), "view.points.A.1");
        // a number under `points` is a point's name, then a component
        let named = Key {
            component: vec![2],
            ..Key::new(Part::View, Value::Point("1".into()))
        };
        assert_eq!(key("view.points.1.2"), named);
        let entry = Key {
            component: vec![2, 3],
            ..Key::new(Part::View, Value::Field(Field::Matrix))
        };
        assert_eq!(key("view.matrix.2.3"), entry);
        let end = Key {
            component: vec![0, 2],
            ..Key::new(Part::Clip, Value::Cut(Plane::Left, Cut::Point)).of_segment(Some(2))
        };
        assert_eq!(key("clip[2].intersections.left.point[0].2"), end);
        assert_eq!(end.to_string(), "clip.2.intersections.left.point.0.2");
    }

    /// `Display` then `FromStr` gives the key back, for keys made of any
    /// part, segment, value and component.
    #[test]
    fn every_key_reads_back_from_its_spelling() {
        let values = || {
            let mut v = vec![
                Value::Whole,
                Value::Point("A".into()),
                Value::Point("7".into()),
                Value::Pixel("B".into()),
                Value::Light(0),
                Value::Light(3),
            ];
            v.extend(Field::all().into_iter().map(Value::Field));
            v.extend(Plane::ALL.map(Value::Plane));
            for p in Plane::ALL {
                v.extend(CUTS.map(|c| Value::Cut(p, c)));
            }
            v.extend(FACTORS.map(|x| Value::Factor(1, x)));
            v
        };
        let mut n = 0;
        for part in Part::all() {
            for value in values() {
                // only what a part has, and a component only of a value
                // that is a list (or may be)
                let fits = match &value {
                    Value::Whole => true,
                    Value::Field(f) => f.in_part(part),
                    Value::Point(_) => Field::Points.in_part(part),
                    Value::Pixel(_) => Field::Pixels.in_part(part),
                    Value::Plane(_) | Value::Cut(..) => part == Part::Clip,
                    Value::Light(_) | Value::Factor(..) => part == Part::Shade,
                };
                let lists = !matches!(
                    value,
                    Value::Whole
                        | Value::Plane(_)
                        | Value::Light(_)
                        | Value::Field(
                            Field::Points | Field::Pixels | Field::Intersections | Field::Lights
                        )
                );
                let segments: &[Option<usize>] = match part {
                    Part::Clip => &[None, Some(0), Some(12)],
                    _ => &[None],
                };
                let components: &[&[usize]] = if lists { &[&[], &[1], &[2, 0]] } else { &[&[]] };
                for (seg, comp) in segments
                    .iter()
                    .flat_map(|s| components.iter().map(move |c| (s, c)))
                {
                    if !fits {
                        continue;
                    }
                    let k = Key {
                        component: comp.to_vec(),
                        ..Key::new(part, value.clone()).of_segment(*seg)
                    };
                    assert_eq!(key(&k.to_string()), k, "{k}");
                    n += 1;
                }
            }
        }
        assert!(n > 300, "{n}");
    }

    proptest::proptest! {
        /// A point's or a pixel's name as a point may be named (letters,
        /// digits, `_`, `'`; all digits too), with any component, reads
        /// back from its spelling.
        #[test]
        fn a_named_point_and_its_component_read_back(
            name in "[A-Za-z0-9_']{1,8}",
            component in proptest::collection::vec(0usize..20, 0..3),
            pixel in proptest::bool::ANY,
        ) {
            let k = Key {
                component,
                ..match pixel {
                    true => Key::new(Part::Viewport, Value::Pixel(name)),
                    false => Key::new(Part::View, Value::Point(name)),
                }
            };
            proptest::prop_assert_eq!(key(&k.to_string()), k);
        }
    }

    #[test]
    fn every_field_is_listed_once() {
        // 3 axes, matrix, points, pixels, 6 + 6 window edges, code0, code1,
        // status, segment, intersections, 13 lighting values, lights
        let all: Vec<String> = Field::all().into_iter().map(Field::key).collect();
        assert_eq!(all.len(), 37);
        let mut once = all.clone();
        once.sort();
        once.dedup();
        assert_eq!(once.len(), all.len(), "{all:?}");
        assert_eq!(Part::all().len(), 6);
    }

    #[test]
    fn a_planes_spelling_is_its_outcode_bits_key() {
        for (bit, p) in Plane::ALL.iter().enumerate() {
            assert_eq!(p.bit(), bit);
            assert_eq!(Node::Plane(*p).to_string(), PLANE_KEYS[bit]);
        }
    }
}
