//! The family of `render --explain-pixel`'s geometry steps' words
//! (`crate::msg::PixelMsg`), each language's in en/pixel.rs and
//! id/pixel.rs.

use crate::msg::PixelMsg;

/// The words of `render --explain-pixel`'s geometry steps.
pub trait PixelWords {
    /// The words of a section title, a step or a note under a step.
    fn pixel(&self, m: &PixelMsg) -> String;
}

/// Every message, for the test that each has words in both languages.
#[cfg(test)]
pub fn every() -> Vec<PixelMsg> {
    let n = || "V0".to_string();
    let mut v = vec![
        PixelMsg::SecVertex(0),
        PixelMsg::SecClip,
        PixelMsg::SecMatrices,
        PixelMsg::SecScreen(1),
        PixelMsg::Matrices(n()),
        PixelMsg::World(n()),
        PixelMsg::Eye(n()),
        PixelMsg::ProjMatrix,
        PixelMsg::Clip(n()),
        PixelMsg::Outcode(n()),
        PixelMsg::Divide(n()),
        PixelMsg::WindowPoint(n()),
        PixelMsg::Row(n()),
        PixelMsg::Snap(n()),
        PixelMsg::SetUp,
        PixelMsg::FOutcode,
        PixelMsg::Composed,
        PixelMsg::BoxInside,
        PixelMsg::Outside,
        PixelMsg::SameAsRaster(true),
        PixelMsg::SameAsRaster(false),
    ];
    v.extend((0..6).map(PixelMsg::ClipPlane));
    v
}
