//! The report of `render`: the summary (its JSON keys stay English, the
//! same in every language; only the text shows the labels in Bahasa
//! Indonesia), the `--stats` table and the JSON's `stats`.

use super::lang::{Lang, NumStyle};
use crate::input::scene::Shading;
use crate::render::Stats;
use crate::stages::trace::Val;
use crate::tutor::solution::{RenderRun, Times};
use serde_json::{json, Value};

/// The summary: image, size, shading, counts and the frame time (frame,
/// PNG encoding, Mpixels/s), keyed as the JSON's `result`.
pub fn summary(run: &RenderRun) -> Vec<(String, Val)> {
    let count = |n: u64| Val::Num(crate::num::Scalar::shown(&(n as f64)));
    let t = &run.times;
    let label = if t.runs > 1 {
        format!("frame time (median of {})", t.runs)
    } else {
        "frame time".to_string()
    };
    let time = Val::said(crate::msg::Said::FrameTime(
        format!("{:.2}", t.frame),
        format!("{:.1}", run.mpixels_per_s),
        format!("{:.2}", t.png),
    ));
    vec![
        ("image".to_string(), Val::text(run.output.clone())),
        (
            "size".to_string(),
            Val::text(format!("{}x{}", run.size.0, run.size.1)),
        ),
        ("shading".to_string(), Val::text(run.shading.clone())),
        ("triangles drawn".to_string(), count(run.stats.drawn)),
        ("pixels shaded".to_string(), count(run.stats.pixels_shaded)),
        (label, time),
    ]
}

/// The JSON's `stats`: the counters and the median times.
pub fn stats_json(run: &RenderRun) -> Value {
    let (st, t) = (&run.stats, &run.times);
    json!({
        "triangles_in": st.tris_in, "culled": st.culled, "rejected": st.rejected,
        "objects_rejected": st.objects_rejected, "objects_inside": st.objects_inside,
        "clipped": st.clipped, "drawn": st.drawn, "no_pixels": st.no_pixels,
        "pixels_shaded": st.pixels_shaded, "lighting_evaluations": st.lighting_evals,
        "lights_skipped": st.lights_skipped, "specular_skipped": st.specular_skipped,
        "frame_ms": t.frame, "geometry_ms": t.geometry,
        "binning_ms": t.binning, "raster_ms": t.raster,
        "shading_ms": t.shading, "bands_ms": t.bands, "png_ms": t.png,
        "repeat": t.runs, "mpixels_per_s": run.mpixels_per_s,
    })
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
pub fn stats_text(run: &RenderRun, lang: Lang) -> String {
    let (st, t, shading) = (&run.stats, &run.times, run.options_shading);
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
