//! Every word in English: one type, [`En`], implementing each family's
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

/// English.
pub struct En;

impl super::Words for En {}
