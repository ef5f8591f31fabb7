//! The names of a step's values ([`Name`]), in words: one exhaustive match
//! per language (en/names.rs, id/names.rs). Notation ([`Name::Math`]) is
//! the same in every language; every other name is said by each language.

use crate::stages::trace::Name;

/// The names of a step's values (`crate::stages::trace`), in words.
pub trait NameWords {
    /// The name `n` as a reader of this language sees it before its value
    /// (`z' of A'`, `z' dari A'`).
    fn name(&self, n: &Name) -> String;
}
