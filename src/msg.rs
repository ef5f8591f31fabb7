//! Message keys: what the stages, the tutor and the commands want to say to
//! a person, as data with its parameters. They never hold words of any
//! language; `report::words` turns each key into English or Bahasa Indonesia
//! with one exhaustive match per language, so a key without its words in
//! every language does not compile. Only [`Msg::Math`] carries text, and that text is notation
//! (`n = (Pe − Pr) / |Pe − Pr|`), the same in every language.
//!
//! This file sits at the base beside `error.rs`, so every layer can name a
//! message; only `report/` knows the words.

mod drawn;
mod errors;
mod figure;
pub mod lang;
mod number;
mod pixel;
mod render;
mod report;
mod said;
pub use drawn::{DrawnTitle, NamedPoint, Number, ShadeAsked, StatedCamera, Statement, Triple};
pub use errors::{
    Bound, Channel, ClapErr, ErrMsg, FileKind, IoWhy, ListWhy, NumErr, ObjWhy, Thing, TomlErr,
    Twice, Want,
};
pub use figure::{FigWord, FigureMsg, Panel};
pub use lang::Lang;
pub use number::{Compared, Expect, Fixed, Given, Shown};
pub use pixel::PixelMsg;
pub use render::{PerPixel, Summary};
pub use report::{
    BenchWord, CheckWord, ClassWord, CliWord, Decimal, DocWord, PlanWord, PracticeWord, QuizWord,
    StatWord,
};
pub use said::Said;

/// A term of the lighting sum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Term {
    /// The ambient term.
    #[cfg_attr(test, default)]
    Ambient,
    /// The diffuse term.
    Diffuse,
    /// The specular term.
    Specular,
}

/// A part of one light's contribution (a step title, numbered per light when
/// there is more than one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum LightPart {
    /// d > range: the light is not evaluated.
    #[cfg_attr(test, default)]
    OutOfRange,
    /// L and d.
    Direction,
    /// Att.
    Attenuation,
    /// cos α = L·N.
    Incidence,
    /// R and cos β.
    Reflection,
    /// H and N·H.
    HalfVector,
    /// The highlight factor.
    Highlight,
    /// The spot factor.
    Spot,
}

/// Where a point lies against a spot light's cones.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum SpotZone {
    /// ρ ≥ cos(θ/2).
    #[cfg_attr(test, default)]
    Inner,
    /// ρ ≤ cos(φ/2).
    Outer,
    /// Between the cones.
    Penumbra,
}

/// What the trivial tests of outcode clipping decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Trivial {
    /// Both codes 000000.
    #[cfg_attr(test, default)]
    Accept,
    /// The codes share a bit.
    Reject,
    /// Neither: intersect.
    Clip,
}

/// What kind of difference an erratum records (a problem file's
/// `[[errata]] kind`, docs/spec.md §5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Erratum {
    /// A wrong number in print (the text's 20/6 for 16/6).
    Misprint,
    /// A different but consistent definition (the text's h is the half
    /// height of the window).
    Convention,
    /// A value rounded before it was used again (h = 0.041 doubled).
    Rounding,
}

/// How an answer printed in a source compares with the computed one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Printed {
    /// It agrees to the digits printed.
    #[cfg_attr(test, default)]
    Agrees,
    /// It differs: of what kind, where the problem file says.
    Differs(Option<Erratum>),
    /// Not computed in this run (not asked for).
    NotAsked,
    /// Computed, but not comparable with what was printed.
    NotComparable,
}

/// Why a student's earlier value cannot start follow-through: it is not
/// what its step could give (`tutor::check::plausible`).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Implausible {
    /// Not a unit vector (a camera axis, L, N, H, R).
    #[cfg_attr(test, default)]
    NotUnit,
    /// Not perpendicular to the axis before it (that axis's key).
    NotPerpendicular(String),
    /// An intersection point off the segment (or off its plane).
    OffSegment,
    /// A cosine outside [−1, 1].
    NotACosine,
    /// A colour outside [0, 1].
    NotAColour,
    /// A term of the lighting below 0.
    Negative,
    /// A window edge that must be positive.
    NotPositive,
    /// A window edge that must be negative.
    NotNegative,
}

/// One message for a person.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Msg {
    /// Mathematical notation, the same in every language (empty: none).
    Math(String),
    /// Words a lecturer wrote in a problem file (an erratum's `why`), in
    /// English and, when the file gives `why_id`, in Indonesian.
    Written(String, Option<String>),
    /// An erratum's reason (`Written`) after the words for its kind.
    Erratum(Option<Erratum>, Box<Msg>),
    /// How a printed answer compares with the computed one.
    Printed(Printed),

    /// What a problem asks: its parts (`view`, `project`, `window`,
    /// `viewport`, `clip`, `shade`), in order.
    Asked(Vec<String>),

    // ---- section headings ----
    /// solve, part 1.
    SecModeling,
    /// solve, part 2.
    SecViewing,
    /// solve, part 3.
    SecProjection,
    /// solve, part 4: the window, and which points are inside its view
    /// volume.
    SecWindowClip,
    /// solve, part 4, when there are no points to test: the window alone.
    SecWindow,
    /// solve: the viewport.
    SecViewport,
    /// Line clipping (segment number when there are several).
    SecLineClip(Option<usize>),
    /// solve: the lighting.
    SecLighting,
    /// render --explain-pixel: the pixel.
    SecPixel(u32, u32),
    /// render --explain-pixel: lighting of the face.
    SecLightFace,
    /// render --explain-pixel: lighting of vertex n.
    SecLightVertex(usize),
    /// render --explain-pixel: lighting of the pixel.
    SecLightPixel,

    // ---- step titles ----
    /// Camera axis n.
    CamAxisN,
    /// Camera axis u.
    CamAxisU,
    /// Camera axis v.
    CamAxisV,
    /// Orthonormality check.
    CamCheck,
    /// Mcam.
    CamMatrix,
    /// V = Mcam⁻¹.
    ViewMatrix,
    /// Eye coordinates of a point.
    EyeCoords(String),
    /// Orthographic projection of a point.
    OrthoProj(String),
    /// Perspective projection of a point.
    PerspProj(String),
    /// Window half-height on the plane at the named distance.
    WindowTop(String),
    /// Window edges and size on the named plane.
    WindowEdges(String),
    /// Viewport coordinates of a point.
    ViewportOf(String),
    /// Outcode of a point.
    OutcodeOf(String),
    /// The trivial tests.
    TrivialTests,
    /// Intersection with a plane: its index in `clip::PLANES`, its equation.
    Intersection(usize, String),
    /// The clipped segment.
    ClippedSegment,
    /// Liang–Barsky cross-check.
    LiangBarsky,
    /// Do both clipping methods agree?
    MethodsAgree,
    /// Nothing to do (modeling).
    NothingToDo,
    /// The projection plane.
    ProjPlane,
    /// Is the projected point inside the view volume?
    InsideVolume(String),
    /// Unit vector of a named vector.
    UnitVector(String),
    /// Viewer direction (local viewer).
    ViewerLocal,
    /// Material and model.
    Material,
    /// One light's part: (light index, number of lights), which part.
    Light((usize, usize), LightPart),
    /// A term of the sum, per channel.
    TermStep(Term),
    /// The sum of the terms.
    SumOfTerms,
    /// Clamping to [0, 1].
    Clamp,
    /// Which triangle covers the pixel.
    WhichTriangle,
    /// Depth at the pixel.
    Depth,
    /// Barycentric coordinates.
    Barycentric,
    /// Flat shading.
    FlatShading,
    /// Gouraud shading.
    Gouraud,
    /// Phong shading.
    PhongShading,
    /// The pixel's 8-bit colour.
    PixelColour,

    // ---- formula captions with words ----
    /// The out-of-range test.
    FOutOfRange,
    /// cos α and its clamp.
    FIncidence,
    /// Mcam's columns.
    FCamMatrix,
    /// V = R·T(−Pe).
    FViewMatrix,
    /// The trivial tests' rules.
    FTrivial,
    /// The outcode's bits.
    FOutcode,
    /// How the segment is taken from the kept points.
    FSegment,
    /// Outcodes vs Liang–Barsky.
    FMethods,
    /// The projection plane z = d.
    FProjPlane,
    /// Pixel centre inside a triangle.
    FPixelCentre,
    /// Edge functions.
    FEdges,
    /// The z-buffer depth.
    FDepth,
    /// Barycentric weights.
    FBarycentric,
    /// Flat colour.
    FFlat,
    /// 8-bit value.
    FByte,
    /// Liang–Barsky's t0 and t1.
    FLiangBarsky,
    /// Inside the window and between the near and far planes.
    FInside,
    /// Direct3D's spot factor by the cones.
    FSpot,
    /// The clamp of the colour.
    FClamp,
    /// The window's other edges and its size from top and the aspect.
    FWindowEdges,

    // ---- notes ----
    /// Already a unit vector.
    AlreadyUnit,
    /// Clamping changed a channel.
    Saturates,
    /// Every channel in [0, 1].
    InRange,
    /// The model (named) has no such term.
    NoTermInModel(String, Term),
    /// The text's single white light.
    TextSetting,
    /// The text's own formula of a term (Iₐ = Is·ka, …), with Is = 1.
    TextTerm(Term),
    /// Summed over the lights in range.
    SummedInRange,
    /// The specular term is skipped.
    SpecularSkipped,
    /// Beyond its range a light adds nothing.
    BeyondRange,
    /// Within range.
    WithinRange,
    /// No range limit.
    NoRange,
    /// cos α < 0 (whether --specular-requires-lit).
    Behind(bool),
    /// Local viewer.
    LocalViewer,
    /// No local viewer (Direct3D's (0,0,1)).
    NoLocalViewer,
    /// n = 0.
    ShininessZero,
    /// Specular off.
    SpecularOff,
    /// No highlight from a light behind.
    NoHighlightBehind,
    /// The spot zone.
    SpotIn(SpotZone),
    /// Behind the centre of projection (note).
    BehindCentre,
    /// The text's h.
    TextH,
    /// Whether u, v, n are orthonormal.
    Orthonormal(bool),
    /// The trivial tests' decision.
    TrivialNote(Trivial),
    /// Whether the intersection is kept.
    Kept(bool),
    /// The segment touches in a point.
    TouchesPoint,
    /// The part inside the box.
    InsidePart,
    /// The segment misses the box.
    Misses,
    /// The text's default view vector.
    DefaultView,
    /// Direct3D material.
    MaterialD3d,
    /// The text's constants.
    MaterialText,
    /// No triangle covers the pixel.
    NoTriangle,
    /// The nearest triangle.
    Nearest,
    /// Whether both methods agree.
    Agree(bool),
    /// Already in world coordinates.
    AlreadyWorld,
    /// Inside the view volume: (in the window, in depth).
    Inside(bool, bool),

    // ---- check: how one answer was judged ----
    /// Expected one number.
    ExpectOne,
    /// Expected a list of n values.
    ExpectList(usize),
    /// Expected n values, got m.
    CountMismatch(usize, usize),
    /// Expected this value (a number, words or a list).
    Expected(Expect),
    /// Expected none.
    ExpectedNone,
    /// Expected yes/no.
    ExpectedBool(bool),
    /// The key holds several answers.
    SeveralAnswers,
    /// Empty answer.
    EmptyAnswer,
    /// No answer given.
    NoAnswer,
    /// An answer longer than the most read: its length, the most.
    AnswerTooLong(usize, usize),
    /// The answer cannot be read (the reader's reason).
    Unreadable(NumErr),
    /// Exactly equal.
    Exact,
    /// Rounded to n significant figures.
    Rounded(u32),
    /// Rounded to n significant figures, at least m required.
    RoundedCoarse(u32, u32),
    /// Within this percentage (written with 3 significant digits).
    WithinPct(f64),
    /// Within half a pixel (a pixel position).
    WithinPixel,
    /// Not an outcode (the text as written).
    NotAnOutcode(String),
    /// Not a clipping status (the text as written).
    NotAStatus(String),
    /// Not yes or no (the text as written).
    NotYesOrNo(String),
    /// Commas both as decimal marks and as separators: ambiguous.
    AmbiguousCommas,
    /// Right given the student's earlier answers (follow-through).
    FollowThrough,
    /// Would follow from an earlier answer that cannot be (no
    /// follow-through): that answer's key, why it cannot be, this key.
    NoFollowFrom(String, Implausible, String),
    /// Notes of components: (label, note), joined.
    Parts(Vec<(String, Msg)>),

    // ---- errors ----
    /// A location (`file:line:col`) before a message.
    At(String, Box<Msg>),
    /// Why an input was refused (`msg::errors`).
    Err(ErrMsg),
    /// Words given as a value (`msg::said`).
    Said(Said),
    /// Pe and Pr are the same point (its coordinates).
    ErrSamePoint([f64; 3]),
    /// Vup is the zero vector.
    ErrUpZero,
    /// Vup (shown) parallel to Pe − Pr (shown).
    ErrUpParallel([f64; 3], [f64; 3]),
    /// fovy out of (0°, 180°) (the value given).
    ErrFovy(f64),
    /// aspect not positive (the value given).
    ErrAspect(Given),
    /// near not positive (the value given).
    ErrNear(Given),
    /// A point (name) on the plane of the centre of projection (zprp when general).
    ErrCopPlane(String, Option<f64>),
    /// An unknown point (name); the known ones, if any.
    ErrUnknownPoint(String, Option<String>),
    /// axis min > max: axis, min, max.
    ErrBoxInverted(String, f64, f64),
    /// A file that cannot be read: path, the system's reason.
    ErrCannotRead(String, IoWhy),
    /// A zero vector that should be made a unit vector (name).
    ErrZeroUnit(String),
    /// Text that is not NAME=X,Y,Z.
    ErrNamedPoint(String),
    /// Not a point name.
    ErrPointName(String),
    /// A point given twice.
    ErrPointTwice(String),
    /// Text that is not NAME=X,Y.
    ErrNamedPair(String),
    /// Text that is not WIDTHxHEIGHT.
    ErrSize(String),
    /// --cop without --plane.
    ErrCopNeedsPlane,
    /// --plane without --cop.
    ErrPlaneNeedsCop,
    /// No projection chosen.
    ErrChooseProjection,
    /// --point without --viewport.
    ErrPointNeedsViewport,

    // ---- generated problems ----
    /// The title of a generated problem.
    DrawnTitle(DrawnTitle),
    /// A geometry step of `render --explain-pixel`.
    Pixel(PixelMsg),
    /// The statement of a generated problem.
    Statement(Box<Statement>),
    /// `generate`: a problem position has fewer different variants than
    /// asked.
    ErrFewDistinct {
        /// The topic's name.
        topic: String,
        /// The difficulty's name.
        level: String,
        /// The problem's number (1-based).
        problem: usize,
        /// How many different variants it has (new to the exam).
        found: usize,
        /// How many were asked.
        asked: usize,
        /// Whether every problem of its form was tried (else the search
        /// stopped at its limit).
        all: bool,
    },
    /// `--html` given to a command that writes no worked solution.
    ErrHtmlCommand,
    /// A figure's words, or an error of a `--figure`/`--html` file.
    Figure(FigureMsg),

    // ---- warnings ----
    /// Up nearly parallel to the view direction (angle in radians).
    UpParallel(f64),
    /// A point behind the centre of projection.
    BehindWarn(String),
    /// Exact values that grew past this many terms were left approximate.
    ExactTooLarge(usize),
    /// Exact values whose numerators or denominators grew past this many
    /// bits were left approximate.
    ExactTooLong(u64),
    /// A temporary file or folder left by a grafika process that no longer
    /// runs was removed: its path, the process.
    StaleTempRemoved(String, u32),
    /// `--figure` was asked, but no part asked has a figure of its own
    /// (a problem file asking `viewport` alone).
    NoFigure,
}

impl Default for Msg {
    fn default() -> Msg {
        Msg::Math(String::new())
    }
}

impl Msg {
    /// Whether this is empty notation (nothing to print).
    pub fn is_empty(&self) -> bool {
        matches!(self, Msg::Math(s) if s.is_empty())
    }

    /// The text of notation (with its location), else
    /// the key's name and parameters: for `Display` of errors in tests and
    /// logs; people read `report::words`.
    pub fn plain(&self) -> String {
        match self {
            Msg::Math(s) => s.clone(),
            Msg::At(place, m) => format!("{place}: {}", m.plain()),
            other => format!("{other:?}"),
        }
    }
}

/// Notation is the same in every language.
impl From<&str> for Msg {
    fn from(s: &str) -> Msg {
        Msg::Math(s.to_string())
    }
}

/// Notation is the same in every language.
impl From<String> for Msg {
    fn from(s: String) -> Msg {
        Msg::Math(s)
    }
}
