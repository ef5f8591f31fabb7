//! The names of a step's values (`crate::stages::trace`), in words.

/// The names of a step's values (`crate::stages::trace`), in words.
pub trait NameWords {}
