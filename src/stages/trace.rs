//! Worked-solution steps as data, and the recorder the stages write them to.
//!
//! A stage takes `&mut impl Trace` and describes each step inside a closure;
//! [`NoTrace`] never calls the closure, so the renderer's calls compile to
//! the bare arithmetic. [`Recorder`] keeps the steps for a report.

pub use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::{Scalar, Shown};
use nalgebra::Matrix4;
use std::fmt;

/// The name of a value in a step. Notation, the same in every language,
/// is [`Name::Math`] (`u`, `|Pe − Pr|`, `cos α`, `code0 AND code1`,
/// `A − Pe`); a name made of words, or one a reader looks for, is its own
/// variant, its parts as data, so every language must say it. Its English
/// spelling ([`Display`](fmt::Display)) is the key of the step's JSON
/// `values` and `result` (docs/spec.md §3), written here once.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Name {
    /// Notation: the same in every language.
    Math(String),
    /// A point's eye coordinates: `A'`.
    Eye(String),
    /// A point's projection: `A''`.
    Image(String),
    /// A point's eye-space depth: `z' of A'`.
    EyeZ(String),
    /// A point's pixel: `A pixel`.
    Pixel(String),
    /// An outcode's bit (from 0) and its side as the clipping planes
    /// name it: `bit 1 (kiri (left))`.
    Bit(usize, &'static str),
    /// Vertex k of the set-up triangle in 1/256 pixel: `vertex 0 (X, Y)`.
    Vertex(usize),
    /// A vector in eye space (`N`, `P`): `N (eye space)`.
    InEyeSpace(&'static str),
    /// The colour before the clamp: `unclamped`.
    Unclamped,
    /// The window's full height, 2·top (the text's tinggi): `height`.
    Height,
    /// The window's full width, 2·right (the text's lebar): `width`.
    Width,
    /// The colour after the clamp: `color`.
    Color,
    /// The specular highlight factor: `highlight`.
    Highlight,
    /// Whether a light contributes (in range): `contributes`.
    Contributes,
    /// Half the field of view in degrees: `fovy/2 (degrees)`.
    HalfFovy,
    /// The segment clipped by outcodes: `outcodes`.
    Outcodes,
    /// A point's outcode (the text's region code): `code`.
    RegionCode,
    /// Whether the two clippings agree: `agree`.
    Agree,
    /// The t of the points kept: `t kept`.
    TKept,
    /// The first end of the clipped segment: `from`.
    From,
    /// The last end of the clipped segment: `to`.
    To,
    /// The clipped segment (none): `segment`.
    Segment,
    /// Whether a point is inside the view volume: `inside`.
    Inside,
    /// A polygon in clip coordinates: `polygon (x, y, z, w)`.
    Polygon,
    /// The polygon after a plane's clip: `clipped polygon`.
    ClippedPolygon,
    /// The object a pixel shows: `object`.
    Object,
    /// The face of the mesh: `polygon face`.
    PolygonFace,
    /// The triangle's number in its object: `object's triangle`.
    ObjectTriangle,
    /// The triangle a pixel shows: `triangle`.
    Triangle,
    /// The depths at a triangle's vertices: `z at the vertices`.
    ZAtVertices,
    /// The centre of a face: `face centre`.
    FaceCentre,
    /// The colour of a surface: `surface colour`.
    SurfaceColour,
    /// Whether a triangle made again is the rasterizer's:
    /// `same as the rasterizer's`.
    SameAsRasterizer,
}

impl Name {
    /// Notation (`u`, `cos α`, `A − Pe`): the same in every language.
    pub fn math(s: impl Into<String>) -> Name {
        Name::Math(s.into())
    }
}

impl fmt::Display for Name {
    /// The English spelling: the key of the step's JSON (docs/spec.md §3).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let word = match self {
            Name::Math(s) => s,
            Name::Eye(p) => return write!(f, "{p}'"),
            Name::Image(p) => return write!(f, "{p}''"),
            Name::EyeZ(p) => return write!(f, "z' of {p}'"),
            Name::Pixel(p) => return write!(f, "{p} pixel"),
            Name::Bit(bit, side) => return write!(f, "bit {} ({side})", bit + 1),
            Name::Vertex(k) => return write!(f, "vertex {k} (X, Y)"),
            Name::InEyeSpace(v) => return write!(f, "{v} (eye space)"),
            Name::Unclamped => "unclamped",
            Name::Height => "height",
            Name::Width => "width",
            Name::Color => "color",
            Name::Highlight => "highlight",
            Name::Contributes => "contributes",
            Name::HalfFovy => "fovy/2 (degrees)",
            Name::Outcodes => "outcodes",
            Name::RegionCode => "code",
            Name::Agree => "agree",
            Name::TKept => "t kept",
            Name::From => "from",
            Name::To => "to",
            Name::Segment => "segment",
            Name::Inside => "inside",
            Name::Polygon => "polygon (x, y, z, w)",
            Name::ClippedPolygon => "clipped polygon",
            Name::Object => "object",
            Name::PolygonFace => "polygon face",
            Name::ObjectTriangle => "object's triangle",
            Name::Triangle => "triangle",
            Name::ZAtVertices => "z at the vertices",
            Name::FaceCentre => "face centre",
            Name::SurfaceColour => "surface colour",
            Name::SameAsRasterizer => "same as the rasterizer's",
        };
        f.write_str(word)
    }
}

/// A value inside a step or a result.
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    /// A number.
    Num(Shown),
    /// A list of values (a vector is a list of numbers, a matrix a list of rows).
    List(Vec<Val>),
    /// Named values, in order.
    Map(Vec<(String, Val)>),
    /// Text (an outcode, a status, a verdict).
    Text(String),
    /// Words for a person as a value (an outcode bit's test, the render
    /// time): text output says them in the chosen language, JSON in
    /// English, so the JSON is the same in every language.
    Said(crate::msg::Msg),
    /// Yes or no.
    Bool(bool),
    /// Nothing (a rejected segment).
    Null,
}

impl Val {
    /// A number.
    pub fn num<T: Scalar>(x: &T) -> Val {
        Val::Num(x.shown())
    }
    /// The length `len` = |v| of a vector, with √(v·v) as its form where
    /// the length has none of its own but v·v has (an exact run: |V + L| =
    /// √(2+√2) ≈ 1.848; [`Scalar::root_shown`]).
    pub fn length<T: Scalar>(v: &V3<T>, len: &T) -> Val {
        let mut s = len.shown();
        if s.pretty.is_none() && !len.is_exact() {
            s.pretty = crate::num::vec::dot(v, v).root_shown().pretty;
        }
        Val::Num(s)
    }
    /// A 3-vector.
    pub fn vec3<T: Scalar>(a: &V3<T>) -> Val {
        Val::List(a.iter().map(Val::num).collect())
    }
    /// A 2-vector.
    pub fn vec2<T: Scalar>(x: &T, y: &T) -> Val {
        Val::List(vec![Val::num(x), Val::num(y)])
    }
    /// A 4×4 matrix as a list of rows.
    pub fn mat4<T: Scalar>(m: &Matrix4<T>) -> Val {
        Val::List(
            (0..4)
                .map(|r| Val::List((0..4).map(|c| Val::num(&m[(r, c)])).collect()))
                .collect(),
        )
    }
    /// Words for a person (a message key).
    pub fn said(m: impl Into<crate::msg::Said>) -> Val {
        Val::Said(crate::msg::Msg::Said(m.into()))
    }
    /// Text.
    pub fn text(s: impl Into<String>) -> Val {
        Val::Text(s.into())
    }
    /// The numbers of a value: a number, or the numbers of a list (of
    /// lists), in order; words, maps and nothing give none.
    pub fn numbers(&self) -> Vec<f64> {
        match self {
            Val::Num(n) => vec![n.value],
            Val::List(items) => items.iter().flat_map(Val::numbers).collect(),
            _ => vec![],
        }
    }
    /// Walks a value's places depth first, each by its dotted key from
    /// `at`: `visit(key, value)` for each, and into a map (its entries at
    /// `key.name`) or a list (its items at `index(key, i)`, i from 0) when
    /// `visit` opens it (returns true). The one walk of a value's places:
    /// a report's rows (`clip.0.status`) and every answer key
    /// (`view.points.A.1`) alike.
    pub fn walk<'a>(
        &'a self,
        at: &str,
        index: &dyn Fn(&str, usize) -> String,
        visit: &mut dyn FnMut(&str, &'a Val) -> bool,
    ) {
        if !visit(at, self) {
            return;
        }
        match self {
            Val::Map(kv) => {
                (kv.iter()).for_each(|(k, x)| x.walk(&format!("{at}.{k}"), index, visit))
            }
            Val::List(items) => {
                (items.iter().enumerate()).for_each(|(i, x)| x.walk(&index(at, i), index, visit))
            }
            _ => {}
        }
    }
    /// Whether this is a matrix (a list of lists of numbers).
    pub fn is_matrix(&self) -> bool {
        matches!(self, Val::List(rows) if !rows.is_empty() && rows.iter().all(|r| matches!(r, Val::List(_))))
    }
}

thread_local! {
    /// Whether [`Val`]'s `Serialize` writes each number's exact form
    /// (docs/spec.md §3's `exact`) rather than its double (`result`).
    static EXACT: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// `f` with every [`Val`] serialized inside it writing its numbers' exact
/// forms (the ASCII expression, or null for a number with none): §3's
/// `result` and `exact` are one derive, serialized twice. serde passes no
/// state down a derive, so the choice is the thread's while `f` runs.
pub fn exact_forms<R>(f: impl FnOnce() -> R) -> R {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            EXACT.with(|e| e.set(self.0));
        }
    }
    let _restore = Restore(EXACT.with(|e| e.replace(true)));
    f()
}

impl serde::Serialize for Val {
    /// A number as its double (null when not finite) or, inside
    /// [`exact_forms`], as its exact form (null when it has none); a list
    /// as an array, a map as an object in order, text as a string. Words
    /// ([`Val::Said`]) are written by the report in a language, never
    /// here: a result holds none.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::{Error, SerializeMap};
        match self {
            Val::Num(n) if EXACT.with(|e| e.get()) => s.serialize_some(&n.exact),
            Val::Num(n) if n.value.is_finite() => s.serialize_f64(n.value),
            Val::Num(_) | Val::Null => s.serialize_none(),
            Val::List(items) => s.collect_seq(items),
            Val::Map(kv) => {
                let mut m = s.serialize_map(Some(kv.len()))?;
                kv.iter().try_for_each(|(k, v)| m.serialize_entry(k, v))?;
                m.end()
            }
            Val::Text(t) => s.serialize_str(t),
            Val::Bool(b) => s.serialize_bool(*b),
            Val::Said(_) => Err(S::Error::custom("a result holds no words")),
        }
    }
}

/// A formula with the step's numbers put in, as a worked solution writes
/// it before the value: t = (xmin − x0)/(x1 − x0) becomes `(0 − 4)/(−2 −
/// 4)`. `form` is notation with `{}` where each value of `args` goes; the
/// report writes the values in the reader's language (exact forms where
/// they help, a negative value in parentheses after an operator).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Subst {
    /// Notation with a `{}` for each value and [`Subst::SEP`] for the
    /// separator between a vector's or a function's arguments.
    pub form: String,
    /// The values, in order.
    pub args: Vec<Val>,
}

impl Subst {
    /// The separator between the components of a vector or the arguments
    /// of a function in a form (`max({}{,}0)`), written as the number style
    /// separates them: `max(0.8, 0)`, `max(0,8; 0)`.
    pub const SEP: &'static str = "{,}";
    /// `form` with `args` put in its `{}`s.
    pub fn new(form: impl Into<String>, args: Vec<Val>) -> Subst {
        Subst {
            form: form.into(),
            args,
        }
    }
    /// a − b by components: `(a₀ − b₀, a₁ − b₁, a₂ − b₂)`.
    pub fn difference<T: Scalar>(a: &V3<T>, b: &V3<T>) -> Subst {
        Subst::new("({} − {}{,}{} − {}{,}{} − {})", pairs(a, b))
    }
    /// a·b by components: `a₀·b₀ + a₁·b₁ + a₂·b₂`.
    pub fn dot<T: Scalar>(a: &V3<T>, b: &V3<T>) -> Subst {
        Subst::new("{}·{} + {}·{} + {}·{}", pairs(a, b))
    }
    /// a × b by components: `(a₁·b₂ − a₂·b₁, a₂·b₀ − a₀·b₂, a₀·b₁ −
    /// a₁·b₀)`.
    pub fn cross<T: Scalar>(a: &V3<T>, b: &V3<T>) -> Subst {
        let args = [(1, 2), (2, 1), (2, 0), (0, 2), (0, 1), (1, 0)]
            .iter()
            .flat_map(|&(i, j)| [Val::num(&a[i]), Val::num(&b[j])])
            .collect();
        Subst::new("({}·{} − {}·{}{,}{}·{} − {}·{}{,}{}·{} − {}·{})", args)
    }
    /// a/b (a vector or a number over a number).
    pub fn quotient(a: Val, b: Val) -> Subst {
        Subst::new("{}/{}", vec![a, b])
    }
    /// The same between `before` and `after` (`−(…)`).
    pub fn within(self, before: &str, after: &str) -> Subst {
        Subst::new(format!("{before}{}{after}", self.form), self.args)
    }
    /// |a| from its components: `√(a₀² + a₁² + a₂²)`.
    pub fn norm<T: Scalar>(a: &V3<T>) -> Subst {
        Subst::new("√({}² + {}² + {}²)", a.iter().map(Val::num).collect())
    }
}

/// a₀, b₀, a₁, b₁, a₂, b₂.
fn pairs<T: Scalar>(a: &V3<T>, b: &V3<T>) -> Vec<Val> {
    (0..3)
        .flat_map(|k| [Val::num(&a[k]), Val::num(&b[k])])
        .collect()
}

/// One step of a worked solution.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Step {
    /// The part of the problem this step belongs to (`solve` groups by it).
    pub section: Option<Msg>,
    /// What is computed.
    pub title: Msg,
    /// The formula, in the text's notation.
    pub formula: Msg,
    /// The values substituted.
    pub values: Vec<(Name, Val)>,
    /// What came out.
    pub result: Vec<(Name, Val)>,
    /// A remark: a check, a warning, a note on the text.
    pub note: Option<Msg>,
    /// The substitution shown before a value or result of that name
    /// (`t = (0 − 4)/(−2 − 4) = 2/3`).
    pub subs: Vec<(Name, Subst)>,
}

impl Step {
    /// A step with a title (a message key) and formula (notation as a
    /// string, or a key when the caption has words).
    pub fn new(title: Msg, formula: impl Into<Msg>) -> Step {
        Step {
            title,
            formula: formula.into(),
            ..Step::default()
        }
    }
    /// Adds a substituted value.
    pub fn val(mut self, name: Name, v: Val) -> Step {
        self.values.push((name, v));
        self
    }
    /// Adds a result.
    pub fn res(mut self, name: Name, v: Val) -> Step {
        self.result.push((name, v));
        self
    }
    /// Adds a note.
    pub fn note(mut self, n: Msg) -> Step {
        self.note = Some(n);
        self
    }
    /// Shows how the value or result `name` was worked (`t = (0 − 4)/(−2 −
    /// 4)`); an empty form shows nothing (a term the model does not have).
    pub fn sub(mut self, name: Name, worked: Subst) -> Step {
        if !worked.form.is_empty() {
            self.subs.push((name, worked));
        }
        self
    }
    /// The substitution of the value or result `name`, if the step shows one.
    pub fn sub_of(&self, name: &Name) -> Option<&Subst> {
        self.subs.iter().find(|(n, _)| n == name).map(|(_, s)| s)
    }
}

/// Where stages write their steps and warnings.
pub trait Trace {
    /// Whether anyone is listening (lets a stage skip work done only to explain).
    const ON: bool;
    /// Records the step the closure builds (not called when `ON` is false).
    fn step(&mut self, f: impl FnOnce() -> Step);
    /// Records a warning (also printed on stderr by the calculator).
    fn warn(&mut self, f: impl FnOnce() -> Msg);
}

/// The recorder that records nothing: the renderer's, free at run time.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoTrace;

impl Trace for NoTrace {
    const ON: bool = false;
    #[inline(always)]
    fn step(&mut self, _f: impl FnOnce() -> Step) {}
    #[inline(always)]
    fn warn(&mut self, _f: impl FnOnce() -> Msg) {}
}

/// The recorder that keeps every step, under the current section.
#[derive(Clone, Debug, Default)]
pub struct Recorder {
    /// The steps, in order.
    pub steps: Vec<Step>,
    /// The warnings, in order.
    pub warnings: Vec<Msg>,
    section: Option<Msg>,
    /// Keeps no step (a solve whose results alone are wanted: the steps
    /// are never made).
    pub quiet: bool,
}

impl Recorder {
    /// A new, empty recorder.
    pub fn new() -> Recorder {
        Recorder::default()
    }
    /// A new recorder that keeps no step when `quiet`.
    pub fn quiet(quiet: bool) -> Recorder {
        Recorder {
            quiet,
            ..Recorder::default()
        }
    }
    /// Starts a section: the steps that follow belong to it.
    pub fn section(&mut self, name: Msg) {
        self.section = Some(name);
    }
}

impl Trace for Recorder {
    const ON: bool = true;
    fn step(&mut self, f: impl FnOnce() -> Step) {
        if self.quiet {
            return;
        }
        let mut s = f();
        s.section = self.section.clone();
        self.steps.push(s);
    }
    fn warn(&mut self, f: impl FnOnce() -> Msg) {
        let w = f();
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The keys of a step's JSON, as docs/spec.md §3's scripts read them.
    #[test]
    fn a_name_is_spelled_in_english_as_its_json_key() {
        let a = || "A".to_string();
        let keys = [
            (Name::math("|Pe − Pr|"), "|Pe − Pr|"),
            (Name::Eye(a()), "A'"),
            (Name::Image(a()), "A''"),
            (Name::EyeZ(a()), "z' of A'"),
            (Name::Pixel(a()), "A pixel"),
            (Name::Bit(0, "kiri (left)"), "bit 1 (kiri (left))"),
            (Name::Vertex(0), "vertex 0 (X, Y)"),
            (Name::InEyeSpace("P"), "P (eye space)"),
            (Name::TKept, "t kept"),
            (Name::RegionCode, "code"),
            (Name::SameAsRasterizer, "same as the rasterizer's"),
        ];
        for (name, key) in keys {
            assert_eq!(name.to_string(), key);
        }
    }
}
