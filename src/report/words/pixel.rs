//! The family of `render --explain-pixel`'s geometry steps' words
//! (`crate::msg::PixelMsg`), each language's in en/pixel.rs and
//! id/pixel.rs.

use crate::msg::PixelMsg;

/// The words of `render --explain-pixel`'s geometry steps.
pub trait PixelWords {
    /// The words of a section title, a step or a note under a step.
    fn pixel(&self, m: &PixelMsg) -> String;
}

/// Every message, for the test that each has words in both languages:
/// every variant (`EnumIter`, its fields at their defaults), each plane
/// of `clip::PLANES` by its index, and both answers of the raster check.
#[cfg(test)]
pub fn every() -> Vec<PixelMsg> {
    use strum::IntoEnumIterator;
    let mut v: Vec<PixelMsg> = PixelMsg::iter().collect();
    v.extend((1..6).map(PixelMsg::ClipPlane));
    v.push(PixelMsg::SameAsRaster(true));
    v
}
