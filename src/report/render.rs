//! The report of `render`: the summary (its JSON keys stay English, the
//! same in every language; only the text shows the labels in Bahasa
//! Indonesia), the `--stats` table and the JSON's `stats`.

use super::lang::Lang;
use super::words;
use crate::input::scene::Shading;
pub use crate::msg::{PerPixel, Summary};
use crate::render::Stats;
use crate::stages::trace::Val;
use crate::tutor::solution::{RenderRun, Times};
use serde_json::{json, Value};

/// The summary: image, size, shading, counts and the frame time (frame,
/// PNG encoding, Mpixels/s).
pub fn summary(run: &RenderRun) -> Vec<(Summary, Val)> {
    let count = |n: u64| Val::Num(crate::num::Scalar::shown(&(n as f64)));
    let t = &run.times;
    let time = Val::said(crate::msg::Said::FrameTime(
        format!("{:.2}", t.frame),
        format!("{:.1}", run.mpixels_per_s),
        format!("{:.2}", t.png),
    ));
    vec![
        (Summary::Image, Val::text(run.output.clone())),
        (
            Summary::Size,
            Val::text(format!("{}x{}", run.size.0, run.size.1)),
        ),
        (Summary::Shading, Val::text(shading_names(run))),
        (Summary::TrianglesDrawn, count(run.stats.drawn)),
        (Summary::PixelsShaded, count(run.stats.pixels_shaded)),
        (Summary::FrameTime { runs: t.runs }, time),
    ]
}

/// The shadings drawn as the scene file names them (`flat, gouraud`).
pub fn shading_names(run: &RenderRun) -> String {
    let names: Vec<&str> = run.shadings.iter().map(|s| s.name()).collect();
    names.join(", ")
}

/// Where the lighting is evaluated per pixel for a render whose objects
/// were drawn with `shadings`.
pub fn per_pixel_of(shadings: &[Shading]) -> PerPixel {
    let phong = shadings.iter().filter(|s| **s == Shading::Phong).count();
    match phong {
        0 => PerPixel::Nowhere(shadings.iter().map(|s| s.name()).collect()),
        n if n == shadings.len() => PerPixel::Everywhere,
        _ => PerPixel::PhongObjectsOnly,
    }
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

/// `--stats`: counts of the pipeline's work and the median time of each
/// stage, one line each.
pub fn stats_text(run: &RenderRun, lang: Lang) -> String {
    let (st, t) = (&run.stats, &run.times);
    let id = lang == Lang::Id;
    let per_pixel = words::of(lang).per_pixel(&per_pixel_of(&run.shadings));
    let rows: Vec<(String, String)> = counts(st, per_pixel)
        .into_iter()
        .chain(times(t, lang))
        .map(|(en, ind, v)| (if id { ind } else { en }, v))
        .collect();
    // Every value starts in one column: after the longest label.
    let width = rows.iter().map(|(k, _)| k.chars().count()).max();
    let width = width.unwrap_or(0);
    let mut s = format!("{}\n", if id { "Statistik" } else { "Stats" });
    for (k, v) in rows {
        s.push_str(&format!("  {k:<width$} {v}\n"));
    }
    s
}

/// A line of the table: its English label, its Indonesian label, the value.
type Row = (String, String, String);

/// The counts of `--stats`, with the per-pixel line's words.
fn counts(st: &Stats, per_pixel: String) -> Vec<Row> {
    let r = |en: &str, ind: &str, v: u64| (en.to_string(), ind.to_string(), v.to_string());
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
        let v = words::of(lang).nums().number(&format!("{ms:.2} ms"));
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

#[cfg(test)]
mod per_pixel_tests {
    use super::*;
    use crate::input::scene::Shading::{Flat, Gouraud, Phong};

    #[test]
    fn per_pixel_lighting_follows_the_shadings_drawn() {
        let names = |v: Vec<&'static str>| PerPixel::Nowhere(v);
        assert_eq!(
            per_pixel_of(&[Flat, Gouraud]),
            names(vec!["flat", "gouraud"])
        );
        assert_eq!(per_pixel_of(&[Phong, Phong]), PerPixel::Everywhere);
        assert_eq!(per_pixel_of(&[Flat, Phong]), PerPixel::PhongObjectsOnly);
    }
}
