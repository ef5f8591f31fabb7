//! The words of `render`: the summary's labels and the `--stats` table, in
//! English and in Bahasa Indonesia. The summary's JSON keys stay English
//! (they are the same in every language); only the text shows these labels.

use super::lang::{Lang, NumStyle};
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
    let width = if id { 42 } else { 34 };
    let mut s = format!("{}\n", if id { "Statistik" } else { "Stats" });
    for (en, ind, v) in counts(st, shading, lang).into_iter().chain(times(t, lang)) {
        let k = if id { ind } else { en };
        s.push_str(&format!("  {k:<width$} {v}\n"));
    }
    s
}

/// A line of the table: its English label, its Indonesian label, the value.
type Row = (String, String, String);

/// The counts of `--stats`.
fn counts(st: &Stats, shading: Shading, lang: Lang) -> Vec<Row> {
    let r = |en: &str, ind: &str, v: u64| (en.to_string(), ind.to_string(), v.to_string());
    let name = format!("{shading:?}").to_lowercase();
    let per_pixel = match (shading == Shading::Phong, lang) {
        (true, Lang::En) => "yes (Phong)".to_string(),
        (true, Lang::Id) => "ya (Phong)".to_string(),
        (false, Lang::En) => format!("none ({name} shading)"),
        (false, Lang::Id) => format!("tidak ada ({name} shading)"),
    };
    vec![
        r("triangles in", "segitiga masuk", st.tris_in),
        r(
            "  back faces culled (closed meshes)",
            "  sisi belakang dibuang (mesh tertutup)",
            st.culled,
        ),
        r(
            "  rejected by outcodes",
            "  ditolak oleh region code",
            st.rejected,
        ),
        r(
            "  clipped (crossing a plane)",
            "  di-clip (memotong bidang)",
            st.clipped,
        ),
        r(
            "  set up and rasterized",
            "  disiapkan dan dirasterisasi",
            st.drawn,
        ),
        r(
            "  covering no pixel centre",
            "  tidak menutupi pusat piksel",
            st.no_pixels,
        ),
        r(
            "objects rejected whole (bounding box)",
            "objek ditolak utuh (kotak pembatas)",
            st.objects_rejected,
        ),
        r(
            "objects inside whole (no clip tests)",
            "objek di dalam utuh (tanpa uji clip)",
            st.objects_inside,
        ),
        r("pixels shaded", "piksel diwarnai", st.pixels_shaded),
        r(
            "lighting evaluations",
            "evaluasi pencahayaan",
            st.lighting_evals,
        ),
        (
            "per-pixel lighting".into(),
            "pencahayaan per piksel".into(),
            per_pixel,
        ),
        r(
            "lights skipped (out of range)",
            "sumber cahaya dilewati (di luar jangkauan)",
            st.lights_skipped,
        ),
        r(
            "objects without specular work",
            "objek tanpa perhitungan specular",
            st.specular_skipped,
        ),
    ]
}

/// The median times of `--stats`, in milliseconds.
fn times(t: &Times, lang: Lang) -> Vec<Row> {
    let r = |en: &str, ind: &str, ms: f64| {
        let v = NumStyle::of(lang).number(&format!("{ms:.2} ms"));
        (en.to_string(), ind.to_string(), v)
    };
    let (en, ind) = match t.runs {
        0 | 1 => (String::new(), String::new()),
        n => (format!(" (median of {n})"), format!(" (median dari {n})")),
    };
    let mut geometry = r("time: geometry", "waktu: geometri", t.geometry);
    geometry.0.push_str(&en);
    geometry.1.push_str(&ind);
    vec![
        geometry,
        r("time: binning", "waktu: binning", t.binning),
        r(
            "time: bands (raster + shading)",
            "waktu: pita (raster + shading)",
            t.bands,
        ),
        r("  thread time: raster", "  waktu thread: raster", t.raster),
        r(
            "  thread time: shading",
            "  waktu thread: shading",
            t.shading,
        ),
        r("time: frame", "waktu: bingkai", t.frame),
        r("time: PNG encoding", "waktu: encoding PNG", t.png),
    ]
}
