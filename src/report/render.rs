//! The report of `render`: the summary (its JSON keys stay English, the
//! same in every language; only the text shows the labels in Bahasa
//! Indonesia), the `--stats` table and the JSON's `stats`.

use super::lang::Lang;
use super::words;
use crate::input::scene::Shading;
use crate::msg::Fixed;
use crate::msg::StatWord;
pub use crate::msg::{PerPixel, Summary};
use crate::render::Stats;
use crate::stages::trace::Val;
use crate::tutor::solution::{RenderRun, Times};

/// The summary: image, size, shading, counts and the frame time (frame,
/// PNG encoding, Mpixels/s).
pub fn summary(run: &RenderRun) -> Vec<(Summary, Val)> {
    let count = |n: u64| Val::Num(crate::num::Scalar::shown(&(n as f64)));
    let t = &run.times;
    let time = Val::said(crate::msg::Said::FrameTime(
        Fixed(t.frame, 2),
        Fixed(run.mpixels_per_s, 1),
        Fixed(t.png, 2),
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

/// The JSON's `stats`: the counters, then the median times.
#[derive(serde::Serialize)]
pub struct StatsJson<'a> {
    #[serde(flatten)]
    counts: &'a Stats,
    frame_ms: f64,
    geometry_ms: f64,
    binning_ms: f64,
    raster_ms: f64,
    shading_ms: f64,
    bands_ms: f64,
    png_ms: f64,
    repeat: usize,
    mpixels_per_s: f64,
}

/// The JSON's `stats` of a render.
pub fn stats_json(run: &RenderRun) -> StatsJson<'_> {
    let t = &run.times;
    StatsJson {
        counts: &run.stats,
        frame_ms: t.frame,
        geometry_ms: t.geometry,
        binning_ms: t.binning,
        raster_ms: t.raster,
        shading_ms: t.shading,
        bands_ms: t.bands,
        png_ms: t.png,
        repeat: t.runs,
        mpixels_per_s: run.mpixels_per_s,
    }
}

/// `--stats`: counts of the pipeline's work and the median time of each
/// stage, one line each.
pub fn stats_text(run: &RenderRun, lang: Lang) -> String {
    let (st, t) = (&run.stats, &run.times);
    let said = words::of(lang);
    let per_pixel = words::of(lang).per_pixel(&per_pixel_of(&run.shadings));
    let rows: Vec<(String, String)> = counts(st, per_pixel)
        .into_iter()
        .chain(times(t, lang))
        .map(|(depth, k, v)| ("  ".repeat(depth) + &said.stat(k), v))
        .collect();
    // Every value starts in one column: after the longest label.
    let width = rows.iter().map(|(k, _)| k.chars().count()).max();
    let width = width.unwrap_or(0);
    let mut s = format!("{}\n", said.stat(StatWord::Heading));
    for (k, v) in rows {
        s.push_str(&format!("  {k:<width$} {v}\n"));
    }
    s
}

/// A line of the table: its depth (a part of the line above is indented
/// under it), its name, the value.
type Row = (usize, StatWord, String);

/// The counts of `--stats`, with the per-pixel line's words.
fn counts(st: &Stats, per_pixel: String) -> Vec<Row> {
    use StatWord as S;
    let r = |depth: usize, k: S, v: u64| (depth, k, v.to_string());
    vec![
        r(0, S::TrianglesIn, st.tris_in),
        r(1, S::Culled, st.culled),
        r(1, S::Rejected, st.rejected),
        r(1, S::Clipped, st.clipped),
        r(1, S::Drawn, st.drawn),
        r(1, S::NoPixels, st.no_pixels),
        r(0, S::ObjectsRejected, st.objects_rejected),
        r(0, S::ObjectsInside, st.objects_inside),
        r(0, S::PixelsShaded, st.pixels_shaded),
        r(0, S::LightingEvals, st.lighting_evals),
        (0, S::PerPixel, per_pixel),
        r(0, S::LightsSkipped, st.lights_skipped),
        r(0, S::SpecularSkipped, st.specular_skipped),
    ]
}

/// The median times of `--stats`, in milliseconds.
fn times(t: &Times, lang: Lang) -> Vec<Row> {
    use StatWord as S;
    let r = |depth: usize, k: S, ms: f64| {
        (
            depth,
            k,
            format!("{} ms", words::of(lang).nums().fixed(ms, 2)),
        )
    };
    vec![
        r(0, S::Geometry { runs: t.runs }, t.geometry),
        r(0, S::Binning, t.binning),
        r(0, S::Bands, t.bands),
        r(1, S::Raster, t.raster),
        r(1, S::Shading, t.shading),
        r(0, S::Frame, t.frame),
        r(0, S::Png, t.png),
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
