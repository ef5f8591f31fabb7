//! Every word in Bahasa Indonesia: one type, [`Id`], implementing each family's
//! trait of [`super::Words`] in its own file.

mod errors;
mod keys;
mod mistakes;
mod msg;
mod names;
mod report;

/// Bahasa Indonesia.
pub struct Id;

impl super::Words for Id {}
