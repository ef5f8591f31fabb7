//! `render`'s report words in Bahasa Indonesia.

use super::Id;
use crate::msg::{PerPixel, Summary};
use crate::report::words::RenderWords;

impl RenderWords for Id {
    fn render_heading(&self) -> &'static str {
        "Hasil render"
    }

    fn summary(&self, k: Summary) -> String {
        match k {
            Summary::Image => "gambar".into(),
            Summary::Size => "ukuran".into(),
            Summary::Shading => "shading".into(),
            Summary::TrianglesDrawn => "segitiga digambar".into(),
            Summary::PixelsShaded => "piksel diwarnai".into(),
            Summary::FrameTime { runs: 0 | 1 } => "waktu per bingkai".into(),
            Summary::FrameTime { runs } => format!("waktu per bingkai (median dari {runs})"),
        }
    }

    fn per_pixel(&self, p: &PerPixel) -> String {
        match p {
            PerPixel::Everywhere => "ya (Phong)".into(),
            PerPixel::PhongObjectsOnly => "hanya objek Phong".into(),
            PerPixel::Nowhere(s) => format!("tidak ada ({} shading)", s.join(" dan ")),
        }
    }
}
