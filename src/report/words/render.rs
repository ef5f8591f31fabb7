//! The family of `render`'s report words: the heading of its summary, the
//! summary's names and the per-pixel line of `--stats`; each language's in
//! en/render.rs and id/render.rs.

use crate::msg::{PerPixel, Summary};

/// The words of `render`'s report.
pub trait RenderWords {
    /// The heading of the summary: a render has no answer, it has a picture.
    fn render_heading(&self) -> &'static str;
    /// The words of a summary name (its JSON key is `Summary::key`).
    fn summary(&self, k: Summary) -> String;
    /// The per-pixel lighting line of `--stats`: `yes (Phong)`, `Phong
    /// objects only`, `none (flat and gouraud shading)`.
    fn per_pixel(&self, p: &PerPixel) -> String;
}
