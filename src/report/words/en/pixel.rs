//! The words of `render --explain-pixel`'s geometry steps in English.

use super::En;
use crate::msg::PixelMsg;
use crate::report::words::{PixelWords, PLANE_NAMES};

impl PixelWords for En {
    /// A word table: long on purpose.
    fn pixel(&self, m: &PixelMsg) -> String {
        match m {
            PixelMsg::SecVertex(k) => format!("Vertex {k} of the triangle: object → world → eye → clip coordinates"),
            PixelMsg::SecClip => "Clipping the triangle against the view volume (Sutherland–Hodgman in clip space)".into(),
            PixelMsg::SecMatrices => "The view and projection matrices".into(),
            PixelMsg::SecScreen(k) => format!("Vertex {k} of the set-up triangle: clip coordinates → pixel"),
            PixelMsg::Matrices(n) => format!("The matrices of {n}: modeling M, V·M and P·V·M"),
            PixelMsg::World(n) => format!("World coordinates of {n}"),
            PixelMsg::Eye(n) => format!("Eye coordinates of {n} (view matrix)"),
            PixelMsg::ProjMatrix => "Projection matrix".into(),
            PixelMsg::Clip(n) => format!("Clip coordinates of {n}"),
            PixelMsg::Outcode(n) => format!("Outcode of {n} in clip space"),
            PixelMsg::ClipPlane(b) => format!(
                "Clipping against the {} plane (bit {})",
                PLANE_NAMES[(*b).min(5)].0,
                b + 1
            ),
            PixelMsg::Divide(n) => format!("Perspective division of {n}"),
            PixelMsg::WindowPoint(n) => format!("Window point of {n}"),
            PixelMsg::Row(n) => format!("Pixel row of {n}, counted from the top"),
            PixelMsg::Snap(n) => format!("Snapping {n} to 1/256 pixel"),
            PixelMsg::SetUp => "The triangle set up for the rasterizer".into(),
            PixelMsg::FOutcode => "bit 1: x < −w, bit 2: x > w, bit 3: y < −w, bit 4: y > w, bit 5: z < −w, bit 6: z > w".into(),
            PixelMsg::Composed => "the renderer multiplies the object point by the product V·M once (the same matrix for every vertex of the object)".into(),
            PixelMsg::BoxInside => "the object's bounding box is inside the view volume (all eight corners have code 000000), so the renderer takes every vertex's code as 000000 without this test".into(),
            PixelMsg::Outside => "outside a plane: this vertex gets no pixel of its own; the clipped polygon's vertices do".into(),
            PixelMsg::SameAsRaster(true) => "these are the vertices the rasterizer used for the pixel's triangle".into(),
            PixelMsg::SameAsRaster(false) => "these vertices differ from the rasterizer's (a bug: please report it)".into(),
        }
    }
}
