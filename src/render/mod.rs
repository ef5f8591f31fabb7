//! The renderer: the calculator's stages at scale. Per vertex, eye and
//! clip coordinates (`camera::eye_by_matrix`, `projection::to_clip`, over
//! the view of `stages::view`) and the outcode (`clip::outcode_clip`);
//! per triangle, rejection, culling, clipping (`clip::clip_polygon`), the
//! perspective division, viewport and snapping (`projection::divide`,
//! `window::to_pixel`, `window::snap_pixel`); then raster (fill rule,
//! z-buffer) and shading (`lighting::shade` at f32): flat per face,
//! Gouraud per vertex, Phong per pixel.
//!
//! The frame is drawn in bands of 32 rows, in parallel: a band's
//! visibility (the nearest triangle per pixel), then its shading (each
//! visible pixel lit once), so the lighting work does not depend on how
//! many triangles overlap a pixel, nor the output on the number of threads
//! (each band draws its triangles in submission order).

use crate::error::Result;
use crate::input::scene::{Normals, Scene, Shading};
use crate::num::Fast32;
use crate::stages::lighting::{Light, Material};
use crate::stages::trace::NoTrace;
use crate::stages::view;
pub use crate::stages::view::ViewSetup;
use raster::{Tri, BAND};
use rayon::prelude::*;
use std::sync::Mutex;
use std::time::{Duration, Instant};

pub(crate) mod geometry;
pub mod raster;
mod shade;
pub mod work;

use geometry::{prepare, triangles};
use shade::Planes;
pub use shade::{light_at, phong_attributes, pixel_color, to_u8};

/// Per-corner data of a triangle: lit colour (flat, Gouraud), eye-space
/// normal, eye-space position, surface colour.
pub type Corner = [f32; 12];

/// What to render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Shading mode.
    pub shading: Shading,
    /// Vertex-normal source.
    pub normals: Normals,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Use `shading` for every object, even those that name their own.
    pub force_shading: bool,
}

impl Options {
    /// The scene's own settings.
    pub fn of(scene: &Scene) -> Options {
        Options {
            shading: scene.shading,
            normals: scene.normals,
            width: scene.width,
            height: scene.height,
            force_shading: false,
        }
    }
}

/// What was done and what was skipped (its counters are the render
/// JSON's `stats`, docs/spec.md; the times are written from the medians).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Stats {
    /// Triangles in the scene.
    #[serde(rename = "triangles_in")]
    pub tris_in: u64,
    /// Back faces of closed meshes, culled.
    pub culled: u64,
    /// Triangles wholly outside one plane of the view volume (outcodes).
    pub rejected: u64,
    /// Objects whose bounding box is wholly outside one plane.
    pub objects_rejected: u64,
    /// Objects whose bounding box is wholly inside (no per-triangle tests).
    pub objects_inside: u64,
    /// Triangles that crossed a plane and were clipped.
    pub clipped: u64,
    /// Triangles set up for rasterization (after clipping).
    pub drawn: u64,
    /// Triangles that cover no pixel centre.
    pub no_pixels: u64,
    /// Pixels that got a colour from a triangle.
    pub pixels_shaded: u64,
    /// Calls of `lighting::shade`.
    #[serde(rename = "lighting_evaluations")]
    pub lighting_evals: u64,
    /// (object, light) pairs skipped because the object is out of range.
    pub lights_skipped: u64,
    /// Objects drawn without specular work (ks = 0 or specular off).
    pub specular_skipped: u64,
    /// Time: transforms, culling, clipping, setup, per-face/vertex lighting,
    /// Phong's attribute planes and the index of its objects' triangles.
    #[serde(skip)]
    pub geometry: Duration,
    /// Time: gathering the triangles of each band (made per chunk in the
    /// geometry stage) in submission order.
    #[serde(skip)]
    pub binning: Duration,
    /// Thread time (summed over bands): visibility.
    #[serde(skip)]
    pub raster: Duration,
    /// Thread time (summed over bands): shading.
    #[serde(skip)]
    pub shading: Duration,
    /// Wall time of the band pass (visibility and shading, in parallel).
    #[serde(skip)]
    pub pass: Duration,
}

impl Stats {
    /// Raster + shading time of the frame (everything but file output).
    pub fn frame(&self) -> Duration {
        self.geometry + self.binning + self.pass
    }

    fn add(&mut self, o: &Stats) {
        self.tris_in += o.tris_in;
        self.culled += o.culled;
        self.rejected += o.rejected;
        self.clipped += o.clipped;
        self.drawn += o.drawn;
        self.no_pixels += o.no_pixels;
        self.lighting_evals += o.lighting_evals;
    }
}

/// A rendered frame.
#[derive(Debug)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGB, 8 bits each, rows from the top.
    pub rgb: Vec<u8>,
    /// The visible triangle per pixel (`NONE` for background).
    pub ids: Vec<u32>,
    /// The set-up triangles.
    pub tris: Vec<Tri>,
    /// Their corners (empty when every object is shaded by Phong, which
    /// lights each pixel from its attribute planes instead; the explainer
    /// makes a triangle's corners again).
    pub corners: Vec<[Corner; 3]>,
    /// Per object: how it is shaded.
    pub looks: Vec<Look>,
    /// Whether the view was orthographic (the viewer along +z).
    pub ortho: bool,
    /// Counters and times.
    pub stats: Stats,
    /// Buffers kept for the next frame.
    scratch: Scratch,
}

/// Working buffers a frame hands on to the next (so a repeated render
/// touches no fresh memory pages).
#[derive(Debug, Default)]
struct Scratch {
    /// Phong's attribute planes per triangle.
    planes: Vec<Planes>,
    /// The geometry stage's per-chunk working data.
    chunks: Vec<geometry::ChunkBuf>,
    /// The geometry stage's per-vertex arrays.
    verts: geometry::VertBufs,
    /// Per worker thread, the z-buffer of the band it is drawing.
    depth: DepthBufs,
}

/// One band's z-buffer per worker thread of the pool (entry k for thread
/// k), reused band after band so it stays in the thread's cache; no
/// frame-sized depth buffer is written.
#[derive(Debug, Default)]
struct DepthBufs(Vec<Mutex<Vec<f32>>>);

impl DepthBufs {
    /// Runs `f` on a z-buffer of `n` entries (contents unspecified): the
    /// current worker thread's own, or a fresh one when the thread has no
    /// entry (not a worker, or of a larger pool) or its entry is in use.
    fn with<R>(&self, n: usize, f: impl FnOnce(&mut [f32]) -> R) -> R {
        let own = rayon::current_thread_index().and_then(|k| self.0.get(k));
        match own.and_then(|m| m.try_lock().ok()) {
            Some(mut dz) => {
                dz.resize(n, 0.0);
                f(&mut dz[..n])
            }
            None => f(&mut vec![0.0; n]),
        }
    }
}

/// How one object is shaded: its material, the lights that reach it and
/// the shading mode.
#[derive(Clone, Debug)]
pub struct Look {
    /// Material (specular switched off when ks = 0).
    pub material: Material<Fast32>,
    /// The lights within range of the object.
    pub lights: Vec<Light<Fast32>>,
    /// Flat, Gouraud or Phong.
    pub shading: Shading,
    /// The object has one colour, which `material.color` holds: every
    /// pixel's surface colour is that one (Phong need not interpolate it).
    pub one_colour: bool,
}

/// Frees what no step of a render with `opt` reads: the polygon lists
/// (`mesh.faces`) of the objects not shaded flat. Only flat shading reads
/// a face's polygon (Newell's normal); the triangles, their face numbers
/// and the vertex normals were made from the polygons when the scene was
/// read. (A 1,048,576-triangle sphere has 524,288 such small lists, about
/// 29 MB with the allocator's overhead.)
pub fn release_unused(scene: &mut Scene, opt: &Options) {
    for o in &mut scene.objects {
        if geometry::shading_of(o, opt) != Shading::Flat {
            o.mesh.faces = Vec::new();
        }
    }
}

/// Renders a scene.
pub fn render(scene: &Scene, opt: &Options) -> Result<Frame> {
    render_observed(scene, opt, None, &|| {})
}

/// Renders a scene into the buffers of a previous frame when it has the
/// same size (as a real-time loop would: no fresh allocation per frame),
/// calling `band_done` as each band of [`BAND`] rows is finished (from the
/// worker threads): for a progress bar.
pub fn render_observed(
    scene: &Scene,
    opt: &Options,
    prev: Option<Frame>,
    band_done: &(dyn Fn() + Sync),
) -> Result<Frame> {
    crate::input::scene::check_size(opt.width, opt.height)?;
    let t0 = Instant::now();
    let vs = view::setup(&scene.view, opt.width, opt.height, &mut NoTrace)?;
    let n = (opt.width * opt.height) as usize;
    let mut f = match prev {
        Some(f) if f.rgb.len() == 3 * n => f,
        _ => Frame {
            width: opt.width,
            height: opt.height,
            rgb: vec![0u8; 3 * n],
            ids: vec![0u32; n],
            tris: Vec::new(),
            corners: Vec::new(),
            looks: Vec::new(),
            ortho: vs.ortho,
            stats: Stats::default(),
            scratch: Scratch::default(),
        },
    };
    (f.width, f.height, f.ortho) = (opt.width, opt.height, vs.ortho);
    f.stats = Stats::default();
    let (bins, ranges) = geometry_stage(scene, opt, &vs, &mut f);
    let phong = shade::PhongIndex::new(f.tris.len(), &ranges, &f.looks);
    f.stats.geometry = t0.elapsed().saturating_sub(f.stats.binning);
    band_pass(&mut f, to_u8(scene.background), &bins, &phong, band_done);
    Ok(f)
}

/// The geometry stage of every object, in submission order, into the
/// frame's triangles, corners, Phong planes and looks: returns the bins
/// (per band, its triangles in order) and per object the numbers lo..hi
/// of its set-up triangles. Corners are kept when some object is shaded
/// flat or Gouraud, planes when some object is shaded by Phong.
fn geometry_stage(
    scene: &Scene,
    opt: &Options,
    vs: &ViewSetup,
    f: &mut Frame,
) -> (Vec<Vec<u32>>, Vec<[u32; 2]>) {
    let phong = |o| geometry::shading_of(o, opt) == Shading::Phong;
    let keep = [
        !scene.objects.iter().all(phong),
        scene.objects.iter().any(phong),
    ];
    // The triangle arrays keep their length from the previous frame (only
    // new entries are filled before being written) and are cut at the end.
    let mut planes = std::mem::take(&mut f.scratch.planes);
    if !keep[0] {
        f.corners.clear();
    }
    if !keep[1] {
        planes.clear();
    }
    let mut bins: Vec<Vec<u32>> = Vec::new();
    let mut out = geometry::Output {
        tris: &mut f.tris,
        corners: &mut f.corners,
        planes: &mut planes,
        bins: &mut bins,
        keep,
    };
    let (mut count, mut ranges) = (0, Vec::new());
    f.looks.clear();
    for (oi, obj) in scene.objects.iter().enumerate() {
        let (stats, verts) = (&mut f.stats, &mut f.scratch.verts);
        let Some(p) = prepare(obj, vs, &scene.lights, opt, stats, verts) else {
            f.looks.push(Look {
                material: obj.material.cast(),
                lights: Vec::new(),
                shading: opt.shading,
                one_colour: false,
            });
            ranges.push([count as u32; 2]);
            continue;
        };
        let chunks = &mut f.scratch.chunks;
        let (n, s) = triangles(&p, oi as u32, vs, scene, opt, count, &mut out, chunks);
        ranges.push([count as u32, (count + n) as u32]);
        count += n;
        f.stats.add(&s);
        f.stats.binning += s.binning;
        f.looks.push(Look {
            material: p.material,
            lights: p.lights,
            shading: p.shading,
            one_colour: matches!(obj.colors, crate::input::scene::Colors::One(_)),
        });
    }
    f.tris.truncate(count);
    f.corners.truncate(if keep[0] { count } else { 0 });
    planes.truncate(if keep[1] { count } else { 0 });
    f.scratch.planes = planes;
    bins.resize_with((opt.height as usize).div_ceil(BAND), Vec::new);
    (bins, ranges)
}

/// The band pass: over bands in parallel, a band's visibility (nearest
/// triangle per pixel), then its shading while the band is in cache, with
/// the counters and times into the frame's stats.
fn band_pass(
    f: &mut Frame,
    bg: [u8; 3],
    bins: &[Vec<u32>],
    phong: &shade::PhongIndex,
    band_done: &(dyn Fn() + Sync),
) {
    let Frame {
        width,
        rgb,
        ids,
        tris,
        corners,
        looks,
        ortho,
        stats,
        scratch,
        ..
    } = f;
    let w = *width as usize;
    let band_in = shade::BandInput {
        tris,
        corners,
        planes: &scratch.planes,
        looks,
        phong,
        ortho: *ortho,
        bg,
        width: w,
    };
    let t2 = Instant::now();
    let depth = &mut scratch.depth.0;
    depth.resize_with(rayon::current_num_threads(), Mutex::default);
    let depth = &scratch.depth;
    let (shaded, evals, raster_t, shade_t) = rgb
        .par_chunks_mut(3 * w * BAND)
        .zip(ids.par_chunks_mut(w * BAND))
        .zip(bins.par_iter())
        .enumerate()
        .map(|(band, ((out, id), bin))| {
            let t = Instant::now();
            depth.with(id.len(), |dz| {
                raster::visibility_band(tris, bin, (band * BAND) as u32, w, dz, id)
            });
            let raster_t = t.elapsed();
            let t = Instant::now();
            let (count, evals) = shade::shade_band(&band_in, (band * BAND) as u32, out, id);
            band_done();
            (count, evals, raster_t, t.elapsed())
        })
        .reduce(
            || (0, 0, Duration::ZERO, Duration::ZERO),
            |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2, a.3 + b.3),
        );
    stats.pixels_shaded = shaded;
    stats.lighting_evals += evals;
    stats.raster = raster_t;
    stats.shading = shade_t;
    stats.pass = t2.elapsed();
}

impl Frame {
    /// The depth z/w per pixel that the z-buffer held at the end of the
    /// frame (rows from the top): the visible triangle's [`Tri::depth`],
    /// ∞ for background. Rebuilt from `ids` on request: the renderer keeps
    /// a z-buffer only for the band being drawn.
    pub fn depth(&self) -> Vec<f32> {
        let w = self.width as usize;
        let at = |(k, &id): (usize, &u32)| match self.tris.get(id as usize) {
            Some(t) => t.depth((k % w) as u32, (k / w) as u32),
            None => f32::INFINITY,
        };
        self.ids.iter().enumerate().map(at).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_band_gets_its_threads_z_buffer_or_a_fresh_one() {
        // A worker thread draws into its own entry (kept for the next
        // band); a thread without one, or whose entry is in use, gets a
        // fresh buffer. Either way `n` entries.
        let bufs = DepthBufs(vec![Mutex::default()]);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        pool.install(|| bufs.with(7, |dz| dz.fill(1.0)));
        assert_eq!(*bufs.0[0].lock().unwrap(), vec![1.0; 7]);
        // Not a worker of a pool: a fresh buffer, the entry untouched.
        let fresh = |dz: &mut [f32]| {
            dz.fill(3.0);
            dz.len()
        };
        assert_eq!(bufs.with(9, fresh), 9);
        // The entry in use: a fresh one.
        let held = bufs.0[0].lock().unwrap();
        assert_eq!(pool.install(|| bufs.with(9, fresh)), 9);
        assert_eq!(*held, vec![1.0; 7]);
        drop(held);
        // Reused, and grown to the size asked for.
        pool.install(|| bufs.with(9, |dz| dz.fill(2.0)));
        assert_eq!(*bufs.0[0].lock().unwrap(), vec![2.0; 9]);
    }
}
