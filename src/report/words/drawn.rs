//! The family of a generated problem's words: its title and its statement
//! (`crate::msg::Statement`), each language's in en/drawn.rs and
//! id/drawn.rs.

use crate::msg::{DrawnTitle, Statement};
use crate::report::lang::NumStyle;

/// The words of a generated problem.
pub trait DrawnWords {
    /// A generated problem's title.
    fn drawn_title(&self, t: DrawnTitle) -> &'static str;
    /// A generated problem's statement, its numbers written in `nums` (the
    /// language's own, or a quiz's `--decimal`).
    fn statement(&self, s: &Statement, nums: NumStyle) -> String;
}
