//! The family of values given as words (`crate::msg::Said`): an outcode
//! bit's test, the render time, a clipping status; each language's in
//! en/said.rs and id/said.rs.

use crate::msg::{Compared, Said};
use crate::report::lang::NumStyle;
use crate::stages::clip::Status;

/// The words of values given as words.
pub trait SaidWords {
    /// The words of `s`, its numbers in the style `nums` (the language's
    /// own, or a quiz's `--decimal`).
    fn said(&self, s: &Said, nums: NumStyle) -> String;
}

/// An outcode bit's comparison with its values, each as short as it
/// reads (its exact form, else 6 digits) in the style `nums`: `4 > 3`,
/// `0,5 < −1`.
pub fn compared(c: &Compared, nums: NumStyle) -> String {
    let Compared(a, op, b) = c;
    format!("{} {op} {}", nums.short(a), nums.short(b))
}

/// The clipping status whose code (docs/spec.md's word, `clipped`) is
/// `code`, if it is one.
pub fn status(code: &str) -> Option<Status> {
    [Status::Accepted, Status::Rejected, Status::Clipped]
        .into_iter()
        .find(|s| s.as_str() == code)
}
