//! Words given as values (`Val::Said`): what a step or a summary states in
//! words beside its numbers. The numbers travel as numbers;
//! `report::words` writes them in each language's number style.

use super::{Compared, Fixed};

/// Words given as a value.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Said {
    /// An outcode bit's test: whether it holds, the comparison (`x > xmax`)
    /// and its values (`4 > 3`; boxed: two numbers with their forms).
    BitTest(bool, String, Box<Compared>),
    /// An outcode bit's test asked, not answered (a hint): the comparison
    /// and its values.
    BitQuestion(String, Box<Compared>),
    /// One frame's time: milliseconds, millions of pixels per second, and
    /// the PNG encoding's milliseconds.
    FrameTime(Fixed, Fixed, Fixed),
    /// A clipping status as a word (`clipped`, `accepted`, `rejected`).
    Status(String),
}

/// For the tests' iteration over the message keys (`strum::EnumIter`
/// fills a variant's fields with their defaults).
#[cfg(test)]
impl Default for Said {
    fn default() -> Said {
        Said::Status(String::new())
    }
}
