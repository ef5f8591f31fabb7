//! The words of `render`'s report: the heading of its summary, the
//! summary's names and the per-pixel line of `--stats`. One exhaustive
//! match per language: a name without its words does not compile.

use crate::msg::{PerPixel, Summary};
use crate::report::lang::Lang;

/// The heading of the summary: a render has no answer, it has a picture.
pub fn heading(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "Render",
        Lang::Id => "Hasil render",
    }
}

/// The words of a summary name in `lang`: English shows the JSON key
/// itself (its words, `Summary::key`).
pub fn summary(k: Summary, lang: Lang) -> String {
    match lang {
        Lang::En => k.key(),
        Lang::Id => summary_id(k),
    }
}

fn summary_id(k: Summary) -> String {
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

/// The per-pixel lighting line of `--stats` in `lang`: `yes (Phong)`,
/// `Phong objects only`, `none (flat and gouraud shading)`.
pub fn per_pixel(p: &PerPixel, lang: Lang) -> String {
    let names = |s: &[&str], and: &str| s.join(and);
    match lang {
        Lang::En => match p {
            PerPixel::Everywhere => "yes (Phong)".into(),
            PerPixel::PhongObjectsOnly => "Phong objects only".into(),
            PerPixel::Nowhere(s) => format!("none ({} shading)", names(s, " and ")),
        },
        Lang::Id => match p {
            PerPixel::Everywhere => "ya (Phong)".into(),
            PerPixel::PhongObjectsOnly => "hanya objek Phong".into(),
            PerPixel::Nowhere(s) => format!("tidak ada ({} shading)", names(s, " dan ")),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_per_pixel_line_names_every_shading_drawn() {
        let en = |p: PerPixel| per_pixel(&p, Lang::En);
        let id = |p: PerPixel| per_pixel(&p, Lang::Id);
        assert_eq!(en(PerPixel::Nowhere(vec!["flat"])), "none (flat shading)");
        let both = || PerPixel::Nowhere(vec!["gouraud", "flat"]);
        assert_eq!(en(both()), "none (gouraud and flat shading)");
        assert_eq!(id(both()), "tidak ada (gouraud dan flat shading)");
        assert_eq!(en(PerPixel::Everywhere), "yes (Phong)");
        assert_eq!(en(PerPixel::PhongObjectsOnly), "Phong objects only");
        assert_eq!(id(PerPixel::PhongObjectsOnly), "hanya objek Phong");
    }

    #[test]
    fn a_summary_name_has_its_words_and_its_json_key_in_every_language() {
        let median = Summary::FrameTime { runs: 5 };
        assert_eq!(median.key(), "frame time (median of 5)");
        assert_eq!(
            summary(median, Lang::Id),
            "waktu per bingkai (median dari 5)"
        );
        assert_eq!(Summary::FrameTime { runs: 1 }.key(), "frame time");
        assert_eq!(
            summary(Summary::TrianglesDrawn, Lang::Id),
            "segitiga digambar"
        );
        assert_eq!(Summary::TrianglesDrawn.key(), "triangles drawn");
    }
}
