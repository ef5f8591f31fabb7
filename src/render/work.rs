//! The work of a frame, estimated before it is drawn (issue 37), so that a
//! render that would run for minutes or hours is refused at once: the time
//! of a frame follows the pixels its triangles cover, not their number (100
//! full-image quads at 8192² are 200 triangles and took 29 s).
//!
//! The estimate is in steps of about one pixel test of the rasterizer
//! (2 ns of wall time on 2 cores):
//!
//! - raster: per triangle, the pixels of its box on the image (the
//!   rasterizer tests each, in blocks of 8 columns), from its vertices
//!   through the view (the whole image for a triangle with a vertex behind
//!   the eye: clipped, it may cover all of it); none for a back face of a
//!   closed mesh when faces are culled, nor for an object whose box lies
//!   outside one plane of the view volume;
//! - geometry: [`TRIANGLE`] steps per triangle;
//! - shading: per pixel of the image, [`PIXEL`] steps, and [`PHONG_LIGHT`]
//!   more per light when an object is shaded by Phong (each visible pixel
//!   is lit once, whatever the overlap).
//!
//! The boxes count more than the pixels drawn (a triangle covers about half
//! of its box), so a render takes about its estimate's time or less.

use super::geometry::shading_of;
use super::Options;
use crate::error::Result;
use crate::input::scene::{Scene, Shading};
use crate::stages::clip;
use crate::stages::trace::NoTrace;
use crate::stages::view;
use nalgebra::{Matrix4, Vector3, Vector4};

/// Steps of the geometry stage per triangle (transforms, tests, set-up:
/// about 50 ns of thread time).
pub const TRIANGLE: u64 = 16;

/// Steps per pixel of the image for its shading (flat, Gouraud).
pub const PIXEL: u64 = 2;

/// Steps per pixel and light for Phong's per-pixel lighting.
pub const PHONG_LIGHT: u64 = 8;

/// The estimated work of one frame, in steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Pixel tests of the rasterizer: Σ over triangles of their boxes.
    pub raster: u64,
    /// The geometry stage: [`TRIANGLE`] per triangle.
    pub geometry: u64,
    /// Shading: [`PIXEL`] per pixel, [`PHONG_LIGHT`] per pixel and light
    /// with Phong.
    pub shading: u64,
}

impl Work {
    /// All the steps of one frame.
    pub fn total(&self) -> u64 {
        self.raster
            .saturating_add(self.geometry)
            .saturating_add(self.shading)
    }
}

/// The work of one frame of `scene` at `opt` (see the module).
pub fn estimate(scene: &Scene, opt: &Options) -> Result<Work> {
    let vs = view::setup(&scene.view, opt.width, opt.height, &mut NoTrace)?;
    let size = (opt.width, opt.height);
    let mut work = Work::default();
    for obj in &scene.objects {
        let ntris = obj.tris.tris.len() as u64;
        work.geometry = work.geometry.saturating_add(ntris.saturating_mul(TRIANGLE));
        let eye = vs.eye_from_world * obj.model;
        let clip = vs.clip_from_eye * eye;
        if outside(obj.bounds, &clip) {
            continue;
        }
        let cull = scene.cull && obj.closed;
        let verts: Vec<Vert> = (obj.mesh.positions.iter())
            .map(|p| Vert::of(p, &eye, &clip, size))
            .collect();
        let boxes = (obj.tris.tris.iter())
            .map(|t| t.map(|i| &verts[i as usize]))
            .filter(|v| !(cull && back(v, vs.ortho)))
            .map(|v| box_pixels(v, size))
            .fold(0u64, u64::saturating_add);
        work.raster = work.raster.saturating_add(boxes);
    }
    let phong = (scene.objects.iter()).any(|o| shading_of(o, opt) == Shading::Phong);
    let per_pixel = PIXEL
        + if phong {
            PHONG_LIGHT * scene.lights.len() as u64
        } else {
            0
        };
    work.shading = u64::from(opt.width) * u64::from(opt.height) * per_pixel;
    Ok(work)
}

/// A vertex: eye coordinates and its pixel position (`None` behind the
/// eye, w ≤ 0).
struct Vert {
    eye: Vector3<f64>,
    pixel: Option<[f64; 2]>,
}

impl Vert {
    fn of(p: &[f32; 3], eye: &Matrix4<f64>, clip: &Matrix4<f64>, (w, h): (u32, u32)) -> Vert {
        let p = Vector4::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]), 1.0);
        let (e, c) = (eye * p, clip * p);
        let pixel = (c.w > 0.0).then(|| {
            let (x, y) = (c.x / c.w, c.y / c.w);
            [
                (x + 1.0) / 2.0 * f64::from(w),
                (1.0 - y) / 2.0 * f64::from(h),
            ]
        });
        Vert {
            eye: e.xyz(),
            pixel,
        }
    }
}

/// Whether the object's bounding box lies outside one plane of the view
/// volume (the renderer then draws none of it).
fn outside(bounds: [[f32; 3]; 2], clip: &Matrix4<f64>) -> bool {
    let [lo, hi] = bounds;
    let mut and = 0x3f;
    for k in 0..8 {
        let q = Vector3::from_fn(|a, _| f64::from(if k & (1 << a) == 0 { lo[a] } else { hi[a] }));
        and &= clip::outcode_clip_space(&crate::stages::camera::apply(clip, &q));
    }
    and != 0
}

/// Whether a triangle faces away from the viewer: the renderer's test,
/// N·(toward the viewer) ≤ 0 with N = (v1 − v0) × (v2 − v0).
fn back(v: &[&Vert; 3], ortho: bool) -> bool {
    let n = (v[1].eye - v[0].eye).cross(&(v[2].eye - v[0].eye));
    let toward = if ortho { n.z } else { -n.dot(&v[0].eye) };
    toward <= 0.0
}

/// The pixels the rasterizer tests for a triangle: its box on the image,
/// columns in whole blocks of 8; the whole image when a vertex is behind
/// the eye.
fn box_pixels(v: [&Vert; 3], (w, h): (u32, u32)) -> u64 {
    let whole = u64::from(w) * u64::from(h);
    let Some(p) = v.iter().map(|v| v.pixel).collect::<Option<Vec<[f64; 2]>>>() else {
        return whole;
    };
    let span = |k: usize, n: u32| {
        let lo = p.iter().map(|q| q[k]).fold(f64::INFINITY, f64::min).floor();
        let hi = p
            .iter()
            .map(|q| q[k])
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil();
        let (lo, hi) = (lo.max(0.0), hi.min(f64::from(n)));
        if hi > lo {
            (hi - lo) as u64
        } else {
            0
        }
    };
    let (cols, rows) = (span(0, w), span(1, h));
    if cols == 0 || rows == 0 {
        return 0;
    }
    // columns in whole blocks of 8
    let cols = cols.next_multiple_of(8).min(u64::from(w));
    (cols * rows).min(whole)
}
