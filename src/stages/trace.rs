//! Worked-solution steps as data, and the recorder the stages write them to.
//!
//! A stage takes `&mut impl Trace` and describes each step inside a closure;
//! [`NoTrace`] never calls the closure, so the renderer's calls compile to
//! the bare arithmetic. [`Recorder`] keeps the steps for a report.

pub use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::{Scalar, Shown};
use nalgebra::Matrix4;

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
    /// Whether this is a matrix (a list of lists of numbers).
    pub fn is_matrix(&self) -> bool {
        matches!(self, Val::List(rows) if !rows.is_empty() && rows.iter().all(|r| matches!(r, Val::List(_))))
    }
}

/// A formula with the step's numbers put in, as a worked solution writes
/// it before the value: t = (xmin − x0)/(x1 − x0) becomes `(0 − 4)/(−2 −
/// 4)`. `form` is notation with `{}` where each value of `args` goes; the
/// report writes the values in the reader's language (exact forms where
/// they help, a negative value in parentheses after an operator).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Subst {
    /// Notation with a `{}` for each value.
    pub form: String,
    /// The values, in order.
    pub args: Vec<Val>,
}

impl Subst {
    /// `form` with `args` put in its `{}`s.
    pub fn new(form: impl Into<String>, args: Vec<Val>) -> Subst {
        Subst {
            form: form.into(),
            args,
        }
    }
    /// a − b by components: `(a₀ − b₀, a₁ − b₁, a₂ − b₂)`.
    pub fn difference<T: Scalar>(a: &V3<T>, b: &V3<T>) -> Subst {
        Subst::new("({} − {}, {} − {}, {} − {})", pairs(a, b))
    }
    /// a·b by components: `a₀·b₀ + a₁·b₁ + a₂·b₂`.
    pub fn dot<T: Scalar>(a: &V3<T>, b: &V3<T>) -> Subst {
        Subst::new("{}·{} + {}·{} + {}·{}", pairs(a, b))
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
    pub values: Vec<(String, Val)>,
    /// What came out.
    pub result: Vec<(String, Val)>,
    /// A remark: a check, a warning, a note on the text.
    pub note: Option<Msg>,
    /// The substitution shown before a value or result of that name
    /// (`t = (0 − 4)/(−2 − 4) = 2/3`).
    pub subs: Vec<(String, Subst)>,
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
    pub fn val(mut self, name: impl Into<String>, v: Val) -> Step {
        self.values.push((name.into(), v));
        self
    }
    /// Adds a result.
    pub fn res(mut self, name: impl Into<String>, v: Val) -> Step {
        self.result.push((name.into(), v));
        self
    }
    /// Adds a note.
    pub fn note(mut self, n: Msg) -> Step {
        self.note = Some(n);
        self
    }
    /// Shows how the value or result `name` was worked (`t = (0 − 4)/(−2 −
    /// 4)`); an empty form shows nothing (a term the model does not have).
    pub fn sub(mut self, name: impl Into<String>, worked: Subst) -> Step {
        if !worked.form.is_empty() {
            self.subs.push((name.into(), worked));
        }
        self
    }
    /// The substitution of the value or result `name`, if the step shows one.
    pub fn sub_of(&self, name: &str) -> Option<&Subst> {
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
}

impl Recorder {
    /// A new, empty recorder.
    pub fn new() -> Recorder {
        Recorder::default()
    }
    /// Starts a section: the steps that follow belong to it.
    pub fn section(&mut self, name: Msg) {
        self.section = Some(name);
    }
}

impl Trace for Recorder {
    const ON: bool = true;
    fn step(&mut self, f: impl FnOnce() -> Step) {
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
