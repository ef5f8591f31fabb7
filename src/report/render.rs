//! The words of `render`: the summary's labels and the `--stats` table, in
//! English and in Bahasa Indonesia. The summary's JSON keys stay English
//! (they are the same in every language); only the text shows these labels.

use super::lang::{decimal, Lang};
use crate::input::scene::Shading;
use crate::render::Stats;

/// The median times of a frame's stages, in milliseconds, over `runs` runs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Times {
    /// How many frames were rendered (`--repeat`).
    pub runs: usize,
    /// Transforms, culling, clipping, set-up.
    pub geometry: f64,
    /// Gathering the triangles of each band.
    pub binning: f64,
    /// The band pass (raster and shading, in parallel).
    pub bands: f64,
    /// Thread time: raster.
    pub raster: f64,
    /// Thread time: shading.
    pub shading: f64,
    /// The whole frame.
    pub frame: f64,
    /// PNG encoding.
    pub png: f64,
}

/// The text label of a render summary key (its JSON key) in `lang`.
pub fn label(key: &str, lang: Lang) -> String {
    if lang == Lang::En {
        return key.to_string();
    }
    if let Some(n) = key
        .strip_prefix("frame time (median of ")
        .and_then(|r| r.strip_suffix(')'))
    {
        return format!("waktu per bingkai (median dari {n})");
    }
    match key {
        "image" => "gambar",
        "size" => "ukuran",
        "shading" => "shading",
        "triangles drawn" => "segitiga digambar",
        "pixels shaded" => "piksel diwarnai",
        "frame time" => "waktu per bingkai",
        other => other,
    }
    .to_string()
}

/// `--stats`: counts of the pipeline's work and the median time of each
/// stage, one line each.
pub fn stats_text(st: &Stats, t: &Times, shading: Shading, lang: Lang) -> String {
    let id = lang == Lang::Id;
    let w = |en: &'static str, ind: &'static str| if id { ind } else { en };
    let ms = |x: f64| decimal(&format!("{x:.2} ms"), lang);
    let mut s = format!("{}\n", w("Stats", "Statistik"));
    let width = if id { 42 } else { 34 };
    let mut line = |k: &str, v: String| s.push_str(&format!("  {k:<width$} {v}\n"));
    line(w("triangles in", "segitiga masuk"), st.tris_in.to_string());
    line(
        w(
            "  back faces culled (closed meshes)",
            "  sisi belakang dibuang (mesh tertutup)",
        ),
        st.culled.to_string(),
    );
    line(
        w("  rejected by outcodes", "  ditolak oleh region code"),
        st.rejected.to_string(),
    );
    line(
        w(
            "  clipped (crossing a plane)",
            "  di-clip (memotong bidang)",
        ),
        st.clipped.to_string(),
    );
    line(
        w("  set up and rasterized", "  disiapkan dan dirasterisasi"),
        st.drawn.to_string(),
    );
    line(
        w(
            "  covering no pixel centre",
            "  tidak menutupi pusat piksel",
        ),
        st.no_pixels.to_string(),
    );
    line(
        w(
            "objects rejected whole (bounding box)",
            "objek ditolak utuh (kotak pembatas)",
        ),
        st.objects_rejected.to_string(),
    );
    line(
        w(
            "objects inside whole (no clip tests)",
            "objek di dalam utuh (tanpa uji clip)",
        ),
        st.objects_inside.to_string(),
    );
    line(
        w("pixels shaded", "piksel diwarnai"),
        st.pixels_shaded.to_string(),
    );
    line(
        w("lighting evaluations", "evaluasi pencahayaan"),
        st.lighting_evals.to_string(),
    );
    let name = format!("{shading:?}").to_lowercase();
    let per_pixel = match (shading == Shading::Phong, id) {
        (true, false) => "yes (Phong)".to_string(),
        (true, true) => "ya (Phong)".to_string(),
        (false, false) => format!("none ({name} shading)"),
        (false, true) => format!("tidak ada ({name} shading)"),
    };
    line(w("per-pixel lighting", "pencahayaan per piksel"), per_pixel);
    line(
        w(
            "lights skipped (out of range)",
            "sumber cahaya dilewati (di luar jangkauan)",
        ),
        st.lights_skipped.to_string(),
    );
    line(
        w(
            "objects without specular work",
            "objek tanpa perhitungan specular",
        ),
        st.specular_skipped.to_string(),
    );
    let median = match (t.runs > 1, id) {
        (false, _) => String::new(),
        (true, false) => format!(" (median of {})", t.runs),
        (true, true) => format!(" (median dari {})", t.runs),
    };
    let geometry = format!("{}{median}", w("time: geometry", "waktu: geometri"));
    line(&geometry, ms(t.geometry));
    line(w("time: binning", "waktu: binning"), ms(t.binning));
    line(
        w(
            "time: bands (raster + shading)",
            "waktu: pita (raster + shading)",
        ),
        ms(t.bands),
    );
    line(
        w("  thread time: raster", "  waktu thread: raster"),
        ms(t.raster),
    );
    line(
        w("  thread time: shading", "  waktu thread: shading"),
        ms(t.shading),
    );
    line(w("time: frame", "waktu: bingkai"), ms(t.frame));
    line(w("time: PNG encoding", "waktu: encoding PNG"), ms(t.png));
    s
}
