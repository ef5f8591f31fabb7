//! The family of a generated problem's words: its title and its statement
//! (`crate::msg::Statement`), each language's in en/drawn.rs and
//! id/drawn.rs; the statement's numbers, points and constants written in a
//! number style, once for every language.

use crate::msg::{DrawnTitle, NamedPoint, Number, Statement, Triple};
use crate::report::lang::NumStyle;

/// The words of a generated problem.
pub trait DrawnWords {
    /// A generated problem's title.
    fn drawn_title(&self, t: DrawnTitle) -> &'static str;
    /// A generated problem's statement, its numbers written in `nums` (the
    /// language's own, or a quiz's `--decimal`).
    fn statement(&self, s: &Statement, nums: NumStyle) -> String;
}

/// A stated number in `nums` (`0.5`, `0,5`, `4/3`).
pub fn number(n: Number, nums: NumStyle) -> String {
    n.written(nums.mark)
}

/// A point's coordinates, `(1, -2, 3)` or `(1; -2; 3)`.
pub fn triple(v: Triple, nums: NumStyle) -> String {
    let s = nums.sep;
    format!("({}{s}{}{s}{})", v[0], v[1], v[2])
}

/// Three stated numbers (a colour), `(1, 0.5, 0)` or `(1; 0,5; 0)`.
pub fn numbers(v: [Number; 3], nums: NumStyle) -> String {
    let [a, b, c] = v.map(|x| number(x, nums));
    let s = nums.sep;
    format!("({a}{s}{b}{s}{c})")
}

/// Named points, `A(1, 0, 2), B(…)` or `A(1; 0; 2); B(…)`.
pub fn points(pts: &[NamedPoint], nums: NumStyle) -> String {
    pts.iter()
        .map(|(name, p)| format!("{name}{}", triple(*p, nums)))
        .collect::<Vec<_>>()
        .join(nums.sep)
}

/// The constants stated, `ka = 0.4, kd = 0.6` or `ka = 0,4; kd = 0,6`.
pub fn constants(k: &[(&str, Number)], nums: NumStyle) -> String {
    k.iter()
        .map(|(name, v)| format!("{name} = {}", number(*v, nums)))
        .collect::<Vec<_>>()
        .join(nums.sep)
}
