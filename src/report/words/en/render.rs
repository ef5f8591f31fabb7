//! `render`'s report words in English: a summary name is its JSON key.

use super::En;
use crate::msg::{PerPixel, Summary};
use crate::report::words::RenderWords;

impl RenderWords for En {
    fn render_heading(&self) -> &'static str {
        "Render"
    }

    fn summary(&self, k: Summary) -> String {
        k.key()
    }

    fn per_pixel(&self, p: &PerPixel) -> String {
        match p {
            PerPixel::Everywhere => "yes (Phong)".into(),
            PerPixel::PhongObjectsOnly => "Phong objects only".into(),
            PerPixel::Nowhere(s) => format!("none ({} shading)", s.join(" and ")),
        }
    }
}
