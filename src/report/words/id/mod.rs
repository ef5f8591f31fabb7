//! Every word in Bahasa Indonesia: one type, [`Id`], implementing each family's
//! trait of [`super::Words`] in its own file.

mod drawn;
mod errors;
mod figure;
mod keys;
mod mistakes;
mod msg;
mod names;
mod pixel;
mod render;
mod report;
mod said;

/// Bahasa Indonesia.
pub struct Id;

impl super::Words for Id {}
