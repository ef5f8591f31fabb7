//! Every word in English: one type, [`En`], implementing each family's
//! trait of [`super::Words`] in its own file.

mod errors;
mod keys;
mod msg;
mod names;
mod report;

/// English.
pub struct En;

impl super::Words for En {}
