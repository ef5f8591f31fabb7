//! The shading stage of the renderer: `lighting::shade` at [`Fast32`] per
//! face (flat) or vertex (Gouraud), and for Phong per pixel — eight pixels
//! per call at [`F32x8`] in the band pass, one at [`Fast32`] when a pixel
//! is explained, with the same bits either way.

use crate::input::scene::Shading;
use crate::num::lanes::Mask8;
use crate::num::{F32x8, Fast32, Scalar};
use crate::render::raster::{Tri, NONE};
use crate::stages::lighting::{self, Light, Material, Surface};
use crate::stages::trace::{NoTrace, Trace};
use multiversion::multiversion;
use nalgebra::Vector3;

use super::{Corner, Look};

/// One lighting evaluation through the calculator's `lighting::shade`, at
/// [`Fast32`] (plain f32 arithmetic).
#[inline]
pub fn light_at(
    mat: &Material<Fast32>,
    lights: &[Light<Fast32>],
    color: [f32; 3],
    n: Vector3<f32>,
    p: Vector3<f32>,
    ortho: bool,
    tr: &mut impl Trace,
) -> [f32; 3] {
    // A one-colour object's material already holds its colour: no copy.
    let color = color.map(Fast32);
    let recoloured = (mat.color != color).then(|| Material {
        color,
        ..mat.clone()
    });
    let m = recoloured.as_ref().unwrap_or(mat);
    lit(m, lights, n.map(Fast32), p.map(Fast32), ortho, tr).map(|c| c.0)
}

/// `lighting::shade` of a material that already holds the surface colour,
/// at the normal `n` made a unit vector, n·(1/|n|) (an interpolated normal is
/// shorter than 1), and the eye-space point `p`: one pixel at [`Fast32`],
/// or eight at once at [`F32x8`] (lane k then is bit for bit the `Fast32`
/// result for lane k's inputs).
#[inline(always)]
fn lit<T: Scalar, Tr: Trace>(
    m: &Material<T>,
    lights: &[Light<T>],
    n: Vector3<T>,
    p: Vector3<T>,
    ortho: bool,
    tr: &mut Tr,
) -> [T; 3] {
    let len = T::hypot3(&n[0], &n[1], &n[2]);
    let inv = len.if_gt(&T::zero(), || T::one() / len.clone(), T::one);
    let n = crate::num::vec::scale(&n, &inv);
    let (o, i) = (T::zero(), T::one());
    // The tilt view's viewer is along +z; a camera is a local viewer at the
    // eye-space origin, V = norm(0 − P), which shade computes itself.
    let s = Surface {
        normal: n,
        view: Vector3::new(o.clone(), o.clone(), i),
        position: p,
        camera: (!ortho).then(|| Vector3::new(o.clone(), o.clone(), o)),
    };
    if Tr::ON {
        lighting::shade(m, lights, &s, tr).color
    } else {
        // The same computation, the color alone (nothing is recorded).
        lighting::shade_color(m, lights, &s)
    }
}

/// A triangle's Phong attributes as planes over the pixel grid: lane 0 is
/// 1/w, lanes 1–9 are (normal, eye position, colour)/w, each
/// `c0 + cx·di + cy·dj` with (di, dj) the pixel's offset from the corner
/// `origin` = (x0, y0) of the triangle's box. Quantities divided by w are
/// affine in screen space, so one division per pixel (by the 1/w lane)
/// gives the perspective-correct attributes: Σ λk·ak/wk / Σ λk/wk = Σ μk·ak.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Planes {
    c0: [f32; 12],
    cx: [f32; 12],
    cy: [f32; 12],
    origin: [f32; 2],
    /// The three corners have the same surface colour. Then it is not
    /// interpolated: lanes 7–9 hold that colour itself (c0 = C, cx = cy =
    /// 0, so every pixel's value is exactly C), not C/w.
    solid: bool,
}

/// Attribute lanes of a plane: 1/w, N/w, P/w, C/w.
const ATTRS: usize = 10;

impl Planes {
    /// The planes of triangle `t` with corners `c` (from its screen
    /// barycentric planes λ1, λ2 and its 1/w at the vertices).
    pub fn of(t: &Tri, c: &[Corner; 3]) -> Planes {
        let mut p = Planes::default();
        p.set(t, c);
        p
    }

    /// Makes `self` [`Planes::of`] `t` and `c`, in place (the geometry
    /// stage writes the frame's array without a copy): lane k of vertex v
    /// is q_v = a_k/w_v in f64 (a = 1 for lane 0), and with d1 = q1 − q0,
    /// d2 = q2 − q0: c0 = q0 + λ1₀·d1 + λ2₀·d2, cx = λ1ₓ·d1 + λ2ₓ·d2,
    /// cy = λ1ᵧ·d1 + λ2ᵧ·d2, each rounded to f32.
    #[inline(always)]
    pub fn set(&mut self, t: &Tri, c: &[Corner; 3]) {
        let iw = t.inv_w.map(f64::from);
        let (l1, l2) = (t.l1.map(f64::from), t.l2.map(f64::from));
        // Lane k of vertex v: ak/wk (a = 1 for lane 0), all lanes at once.
        let at = |v: usize| -> [f64; ATTRS] {
            let mut a = [iw[v]; ATTRS];
            for (k, a) in a.iter_mut().enumerate().skip(1) {
                *a *= f64::from(c[v][k + 2]);
            }
            a
        };
        let (q0, q1, q2) = (at(0), at(1), at(2));
        for k in 0..ATTRS {
            let (d1, d2) = (q1[k] - q0[k], q2[k] - q0[k]);
            // q = q0·λ0 + q1·λ1 + q2·λ2 with λ0 = 1 − λ1 − λ2.
            self.c0[k] = (q0[k] + l1[0] * d1 + l2[0] * d2) as f32;
            self.cx[k] = (l1[1] * d1 + l2[1] * d2) as f32;
            self.cy[k] = (l1[2] * d1 + l2[2] * d2) as f32;
        }
        for k in ATTRS..12 {
            (self.c0[k], self.cx[k], self.cy[k]) = (0.0, 0.0, 0.0);
        }
        self.origin = [t.bbox[0] as f32, t.bbox[2] as f32];
        let rgb = |v: usize| [c[v][9], c[v][10], c[v][11]];
        self.solid = rgb(0) == rgb(1) && rgb(1) == rgb(2);
        if self.solid {
            for (k, c) in (7..ATTRS).zip(rgb(0)) {
                (self.c0[k], self.cx[k], self.cy[k]) = (c, 0.0, 0.0);
            }
        }
    }

    /// The planes along row j: r = c0 + cy·dj, so that a pixel's value is
    /// r + cx·di.
    #[inline(always)]
    fn row(&self, j: u32) -> Row {
        let dj = j as f32 - self.origin[1];
        let mut r = [0.0; 12];
        for (k, r) in r.iter_mut().enumerate() {
            *r = self.c0[k] + self.cy[k] * dj;
        }
        Row {
            r,
            cx: self.cx,
            x0: self.origin[0],
            solid: self.solid,
        }
    }

    /// Normal, eye position and colour at pixel (i, j), perspective-correct
    /// (one pixel of what a [`Batch`] does for eight).
    #[inline(always)]
    fn at(&self, i: u32, j: u32) -> Attrs<Fast32> {
        let row = self.row(j);
        let di = i as f32 - row.x0;
        let q: [Fast32; ATTRS] = std::array::from_fn(|k| Fast32(row.r[k] + row.cx[k] * di));
        let (n, p, r) = attributes(&q);
        let c = if row.solid {
            [q[7], q[8], q[9]]
        } else {
            colour(&q, &r)
        };
        (n, p, c)
    }
}

/// The interpolated normal (not unit), eye position and surface colour at
/// pixel (i, j) of triangle `t` with corners `c`, exactly as Phong shading
/// computes them (from the attribute planes): Σ μₖaₖ for each attribute a.
pub fn phong_attributes(t: &Tri, c: &[Corner; 3], i: u32, j: u32) -> [[f32; 3]; 3] {
    let (n, p, s) = Planes::of(t, c).at(i, j);
    [[n.x.0, n.y.0, n.z.0], [p.x.0, p.y.0, p.z.0], s.map(|x| x.0)]
}

/// A triangle's planes along one row (from [`Planes::row`]).
struct Row {
    r: [f32; 12],
    cx: [f32; 12],
    x0: f32,
    solid: bool,
}

/// Interpolated normal (not unit), eye position and surface colour.
type Attrs<T> = (Vector3<T>, Vector3<T>, [T; 3]);

/// The normal and position from their planes' values q = (1/w, N/w, P/w,
/// …) at a pixel, each times r = 1/(1/w), and r. 1/w > 0 inside a clipped
/// triangle (0 would need w = ∞ and gives r = 0).
#[inline(always)]
fn attributes<T: Scalar>(q: &[T]) -> (Vector3<T>, Vector3<T>, T) {
    let r = q[0].if_gt(&T::zero(), || T::one() / q[0].clone(), T::zero);
    let a = |k: usize| q[k].clone() * r.clone();
    (
        Vector3::new(a(1), a(2), a(3)),
        Vector3::new(a(4), a(5), a(6)),
        r,
    )
}

/// The interpolated surface colour: (C/w)·r.
#[inline(always)]
fn colour<T: Scalar>(q: &[T], r: &T) -> [T; 3] {
    let c = |k: usize| q[k].clone() * r.clone();
    [c(7), c(8), c(9)]
}

/// What the shading of a band reads: the frame's triangles, their data and
/// each object's look.
pub struct BandInput<'a> {
    /// The set-up triangles.
    pub tris: &'a [Tri],
    /// Their corners.
    pub corners: &'a [[Corner; 3]],
    /// Their Phong attribute planes.
    pub planes: &'a [Planes],
    /// Per object: how it is shaded.
    pub looks: &'a [Look],
    /// Which triangles belong to which Phong-shaded object.
    pub phong: &'a PhongIndex,
    /// The viewer is along +z (tilt view), not at the eye-space origin.
    pub ortho: bool,
    /// The background's 8-bit colour.
    pub bg: [u8; 3],
    /// Image width.
    pub width: usize,
}

/// Which triangles belong to which Phong-shaded object. The set-up
/// triangles are numbered object by object (the geometry stage writes them
/// in submission order), so an object's triangles are one range of numbers.
#[derive(Clone, Debug, Default)]
pub struct PhongIndex {
    /// Per triangle, and one more entry last: the triangle's object when
    /// that object is shaded by Phong, else [`NONE`] (and [`NONE`] in the
    /// last entry, which [`NONE`] ids are clamped to).
    obj: Vec<u32>,
    /// Per object: its triangles' numbers lo..hi when it is shaded by
    /// Phong (else an empty range).
    range: Vec<[u32; 2]>,
}

impl PhongIndex {
    /// The index of a frame's `n` triangles, numbered object by object:
    /// object o's are `ranges[o]` = [lo, hi) (hi = lo when it has none),
    /// shaded as `looks[o]` says.
    pub fn new(n: usize, ranges: &[[u32; 2]], looks: &[Look]) -> PhongIndex {
        let phong = |(&r, l): (&[u32; 2], &Look)| (l.shading == Shading::Phong).then_some(r);
        let range: Vec<[u32; 2]> = ranges
            .iter()
            .zip(looks)
            .map(phong)
            .map(Option::unwrap_or_default)
            .collect();
        let mut obj = vec![NONE; n + 1];
        for (o, &[lo, hi]) in range.iter().enumerate() {
            obj[lo as usize..hi as usize].fill(o as u32);
        }
        PhongIndex { obj, range }
    }

    /// The Phong-shaded object that all eight triangles `ids` belong to,
    /// if there is one ([`NONE`] ids belong to none).
    #[inline(always)]
    fn one_object(&self, ids: &[u32; 8]) -> Option<usize> {
        let last = self.obj.len() - 1;
        let o = self.obj[(ids[0] as usize).min(last)];
        if o == NONE {
            return None;
        }
        let [lo, hi] = self.range[o as usize];
        // t in lo..hi, for all eight at once (NONE − lo ≥ hi − lo).
        let inside = ids
            .iter()
            .fold(true, |all, &t| all & (t.wrapping_sub(lo) < hi - lo));
        inside.then_some(o as usize)
    }
}

/// Shades the rows of one band from its visibility buffer `id` (first row
/// `r0`), writing 8-bit RGB into `out`: background where no triangle is
/// visible; flat and Gouraud colours from the corners; Phong pixels lit
/// eight at a time at [`F32x8`] (with each object's material and lights
/// made at [`F32x8`] first). Returns (pixels shaded, lighting evaluations).
///
/// `multiversion` compiles the pass for x86-64 with AVX2 and FMA (one
/// 256-bit instruction per `F32x8` operation) beside the baseline (two SSE
/// registers), chosen at the first call. The copies give the same bits: the
/// lane operations are IEEE-exact at any width, and Rust never fuses a
/// multiply and an add on its own.
#[multiversion(targets("x86_64+avx2+fma"))]
pub fn shade_band(inp: &BandInput, r0: u32, out: &mut [u8], id: &[u32]) -> (u64, u64) {
    band(inp, r0, out, id)
}

/// The body of [`shade_band`], inlined into each copy (and called as it is
/// by the test of the baseline copy).
#[inline(always)]
fn band(inp: &BandInput, r0: u32, out: &mut [u8], id: &[u32]) -> (u64, u64) {
    let w = inp.width;
    let mut objs: Vec<LitObj> = inp
        .looks
        .iter()
        .map(|l| LitObj {
            mat: l.material.cast(),
            lights: l.lights.iter().map(Light::cast).collect(),
            one_colour: l.one_colour,
        })
        .collect();
    // A row of background, copied over the runs no triangle covers.
    let bg_row: Vec<u8> = inp.bg.repeat(w);
    let (mut count, mut evals) = (0, 0);
    for (r, (orow, irow)) in out
        .chunks_exact_mut(3 * w)
        .zip(id.chunks_exact(w))
        .enumerate()
    {
        let (c, e) = shade_row(inp, &mut objs, &bg_row, r0 + r as u32, orow, irow);
        (count, evals) = (count + c, evals + e);
    }
    (count, evals)
}

/// Row j of a band, pixel ids `irow`, into `orow`: runs of pixels covered
/// by the same triangle (or none), and groups of eight Phong pixels of one
/// object. Returns (pixels shaded, lighting evaluations).
#[inline(always)]
fn shade_row(
    inp: &BandInput,
    objs: &mut [LitObj],
    bg_row: &[u8],
    j: u32,
    orow: &mut [u8],
    irow: &[u32],
) -> (u64, u64) {
    let (mut count, mut evals) = (0u64, 0u64);
    let mut batch = Batch::default();
    let mut i = 0;
    while i < inp.width {
        // Eight Phong pixels of one object side by side (inside a shaded
        // surface, the usual case): lit straight from their triangles'
        // planes, without following the runs, whose short and irregular
        // lengths cost a mispredicted branch each.
        let ids = irow
            .get(i..i + 8)
            .and_then(|s| <&[u32; 8]>::try_from(s).ok());
        if let Some((ids, o)) = ids.and_then(|ids| Some((ids, inp.phong.one_object(ids)?))) {
            batch.flush(&mut objs[batch.obj], inp.ortho, orow);
            batch.fill8(inp.planes, ids, i, j, !objs[o].one_colour);
            batch.obj = o;
            batch.flush(&mut objs[o], inp.ortho, orow);
            (count, evals, i) = (count + 8, evals + 8, i + 8);
            continue;
        }
        let t = irow[i];
        let end = i + run_length(&irow[i..], t);
        if t == NONE {
            orow[3 * i..3 * end].copy_from_slice(&bg_row[3 * i..3 * end]);
            i = end;
            continue;
        }
        count += (end - i) as u64;
        let tri = &inp.tris[t as usize];
        let obj = tri.obj as usize;
        match inp.looks[obj].shading {
            Shading::Phong => {
                evals += (end - i) as u64;
                if obj != batch.obj {
                    batch.flush(&mut objs[batch.obj], inp.ortho, orow);
                    batch.obj = obj;
                }
                let row = inp.planes[t as usize].row(j);
                let mut k = i;
                while k < end {
                    k += batch.fill(&row, k as u32, end - k);
                    if batch.len == LANES {
                        batch.flush(&mut objs[obj], inp.ortho, orow);
                    }
                }
            }
            // Corners exist only in frames with flat or Gouraud objects.
            flat => {
                let c = &inp.corners[t as usize];
                let span = &mut orow[3 * i..3 * end];
                corner_run(tri, c, flat == Shading::Flat, i, j, span);
            }
        }
        i = end;
    }
    batch.flush(&mut objs[batch.obj], inp.ortho, orow);
    (count, evals)
}

/// A run of flat or Gouraud pixels (i, j), (i + 1, j), … of triangle `tri`
/// with corners `c`: what `pixel_color` gives, the mode decided per run.
#[inline(always)]
fn corner_run(tri: &Tri, c: &[Corner; 3], flat: bool, i: usize, j: u32, out: &mut [u8]) {
    let span = out.chunks_exact_mut(3);
    if flat {
        let col = to_u8([c[0][0], c[0][1], c[0][2]]);
        span.for_each(|px| px.copy_from_slice(&col));
    } else {
        for (k, px) in span.enumerate() {
            px.copy_from_slice(&to_u8(gouraud(tri, c, (i + k) as u32, j)));
        }
    }
}

/// How many of the ids at the start of `ids` equal `t`: the first eight
/// one by one (a triangle's runs are short), then sixteen at a time (one
/// vector compare each: background runs are long), then one by one.
#[inline(always)]
fn run_length(ids: &[u32], t: u32) -> usize {
    let head = ids.len().min(8);
    if let Some(k) = ids[..head].iter().position(|&u| u != t) {
        return k;
    }
    let mut n = head;
    while let Some(c) = ids.get(n..n + 16) {
        if !c.iter().fold(true, |same, &u| same & (u == t)) {
            break;
        }
        n += 16;
    }
    n + ids[n..]
        .iter()
        .position(|&u| u != t)
        .unwrap_or(ids.len() - n)
}

/// An object's material (recoloured per batch unless it has one colour)
/// and its lights, at [`F32x8`].
struct LitObj {
    mat: Material<F32x8>,
    lights: Vec<Light<F32x8>>,
    /// See [`Look::one_colour`].
    one_colour: bool,
}

/// Pixels per batch: the lanes of [`F32x8`].
const LANES: usize = 8;

/// Up to eight Phong pixels of one object in one row: their attribute
/// planes' values q (row k for pixel k; lanes 7–9 are C/w, or the colour
/// itself for a triangle with one colour) and columns.
#[derive(Default)]
struct Batch {
    q: [[f32; 12]; LANES],
    /// Bit k set when pixel k's colour is interpolated (q's C/w planes).
    interp: u32,
    col: [u32; LANES],
    len: usize,
    obj: usize,
}

impl Batch {
    /// Puts pixels i0, i0 + 1, … of a run of `n` pixels of one triangle,
    /// with planes `row` along the row, into the free lanes: q = r + cx·di
    /// as [`Planes::at`] computes it, pixel by pixel (runs are about three
    /// pixels long). Returns how many pixels it took.
    #[inline(always)]
    fn fill(&mut self, row: &Row, i0: u32, n: usize) -> usize {
        let (base, m) = (self.len, n.min(LANES - self.len));
        for k in 0..m {
            let i = i0 + k as u32;
            let di = i as f32 - row.x0;
            let q = &mut self.q[base + k];
            for ((q, r), cx) in q.iter_mut().zip(&row.r).zip(&row.cx) {
                *q = r + cx * di;
            }
            self.col[base + k] = i;
        }
        let bits = ((1u32 << m) - 1) << base;
        if row.solid {
            self.interp &= !bits;
        } else {
            self.interp |= bits;
        }
        self.len += m;
        m
    }

    /// Fills the empty batch with the eight pixels i, i + 1, … of row j,
    /// covered by the triangles `ids`, whose planes are in `planes`:
    /// q = (c0 + cy·dj) + cx·di as [`Planes::at`] computes it, for the
    /// colour planes (lanes 7–11) too when `colours` (lane 7 is filled
    /// anyway).
    #[inline(always)]
    fn fill8(&mut self, planes: &[Planes], ids: &[u32; 8], i: usize, j: u32, colours: bool) {
        let rows = &mut self.q;
        // Columns and rows are at most 8192 (`scene::check_size`): exact
        // as f32, converted from u32 as in `Planes::at`.
        let (i, j) = (i as u32, j as f32);
        for (k, &t) in ids.iter().enumerate() {
            let p = &planes[t as usize];
            let dj = j - p.origin[1];
            let di = (i + k as u32) as f32 - p.origin[0];
            let plane = |a: usize| (p.c0[a] + p.cy[a] * dj) + p.cx[a] * di;
            let (head, tail) = rows[k].split_at_mut(8);
            for (a, q) in head.iter_mut().enumerate() {
                *q = plane(a);
            }
            if colours {
                for (a, q) in tail.iter_mut().enumerate() {
                    *q = plane(8 + a);
                }
            }
        }
        for (k, c) in self.col.iter_mut().enumerate() {
            *c = i + k as u32;
        }
        // Which colours are interpolated matters only with the colour planes.
        self.interp = if colours {
            let interp = |k: usize| u32::from(!planes[ids[k] as usize].solid) << k;
            (0..8).fold(0, |m, k| m | interp(k))
        } else {
            0
        };
        self.len = LANES;
    }

    /// Lights the pixels in the batch with one `lighting::shade` call at
    /// [`F32x8`] (the object's material, recoloured here unless it
    /// has one colour, and its lights), writes their 8-bit RGB into the row
    /// `out` and empties the batch. Lanes past `len` hold earlier pixels'
    /// values: computed, not written.
    #[inline(always)]
    fn flush(&mut self, o: &mut LitObj, ortho: bool, out: &mut [u8]) {
        if self.len == 0 {
            return;
        }
        let (n, p) = if o.one_colour {
            // Every pixel's colour is the object's, which the material
            // holds (the colour lanes would all be exactly it: c0 = C,
            // cx = cy = 0).
            let (n, p, _) = attributes(&F32x8::from_rows::<8>(&self.q));
            (n, p)
        } else {
            let q: [F32x8; 12] = F32x8::from_rows(&self.q);
            let (n, p, r) = attributes(&q);
            // The colour lanes: C/w·r where interpolated, C itself elsewhere.
            let rgb = [q[7], q[8], q[9]];
            o.mat.color = if self.interp == 0 {
                rgb
            } else {
                let c = colour(&q, &r);
                let m = Mask8::from_bits(self.interp);
                let pick = |ch: usize| F32x8::select(m, c[ch], rgb[ch]);
                [pick(0), pick(1), pick(2)]
            };
            (n, p)
        };
        let px = to_u8_lanes(lit(&o.mat, &o.lights, n, p, ortho, &mut NoTrace));
        let (n, first, full) = (self.len, self.col[0] as usize, LANES);
        if n == full && self.col[full - 1] as usize == first + full - 1 {
            // A full batch side by side (the usual case): one copy.
            out[3 * first..3 * (first + full)].copy_from_slice(&px);
        } else {
            // Pixel by pixel (a copy of a length known only at run time
            // would be a call).
            for (k, &i) in self.col[..n].iter().enumerate() {
                let i = 3 * i as usize;
                out[i..i + 3].copy_from_slice(&px[3 * k..3 * k + 3]);
            }
        }
        self.len = 0;
    }
}

/// The colour of pixel (i, j) covered by triangle `t`: flat and Gouraud
/// interpolate stored colours (no lighting here), Phong interpolates the
/// normal, position and surface colour and calls `lighting::shade`.
#[inline]
pub fn pixel_color(
    t: &Tri,
    c: &[Corner; 3],
    i: u32,
    j: u32,
    looks: &[Look],
    ortho: bool,
    tr: &mut impl Trace,
) -> [f32; 3] {
    let look = &looks[t.obj as usize];
    match look.shading {
        Shading::Flat => [c[0][0], c[0][1], c[0][2]],
        Shading::Gouraud => gouraud(t, c, i, j),
        Shading::Phong => {
            let (n, p, s) = Planes::of(t, c).at(i, j);
            let m = Material {
                color: s,
                ..look.material.clone()
            };
            lit(&m, &look.lights, n, p, ortho, tr).map(|c| c.0)
        }
    }
}

/// Gouraud's colour at pixel (i, j): the corners' lit colours weighted by
/// the perspective-correct μ, C = μ₀C₀ + μ₁C₁ + μ₂C₂.
#[inline(always)]
fn gouraud(t: &Tri, c: &[Corner; 3], i: u32, j: u32) -> [f32; 3] {
    let m = t.mu(i, j);
    let ch = |k: usize| m[0] * c[0][k] + m[1] * c[1][k] + m[2] * c[2][k];
    [ch(0), ch(1), ch(2)]
}

/// A colour 0…1 as 8-bit: `byte` of each channel, truncated.
#[inline]
pub fn to_u8(c: [f32; 3]) -> [u8; 3] {
    c.map(|x| byte(&Fast32(x)).0 as u8)
}

/// Eight colours 0…1 (channel by channel, a pixel per lane) as 8-bit RGB
/// in pixel order r0 g0 b0 r1 g1 b1 …: [`byte`] of each lane, truncated,
/// as [`to_u8`] gives for each pixel.
#[inline(always)]
fn to_u8_lanes([r, g, b]: [F32x8; 3]) -> [u8; 24] {
    let bytes = |c: F32x8| byte(&c).to_bytes();
    let (r, g, b) = (bytes(r), bytes(g), bytes(b));
    // Pixel k's bytes r, g, b, 0 as one little-endian word, then the
    // three colour bytes of each word in turn.
    let words: [u32; 8] = std::array::from_fn(|k| r[k] | g[k] << 8 | b[k] << 16);
    let bytes: [u8; 32] = bytemuck::cast(words);
    // a loop in this body, not `RGB_OF_WORDS.map(…)`: the array's generic
    // `map` was left out of line in some builds (~6 % more instructions
    // per frame), a loop here is always inlined with its caller
    let mut rgb = [0; 24];
    for (out, &i) in rgb.iter_mut().zip(&RGB_OF_WORDS) {
        *out = bytes[i];
    }
    rgb
}

/// Where byte i of eight RGB pixels is in their eight words: pixel i / 3,
/// channel i % 3.
const RGB_OF_WORDS: [usize; 24] = [
    0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 16, 17, 18, 20, 21, 22, 24, 25, 26, 28, 29, 30,
];

/// The 8-bit value of a colour channel, round(255·clamp(x, 0, 1)), as a
/// number whose integer part is the byte: 0 ≤ 255·x + ½ ≤ 255.5 after
/// the clamp (max(x, 0) is 0 for NaN), so truncation gives the rounded
/// value. One pixel at [`Fast32`] or eight at [`F32x8`].
#[inline(always)]
fn byte<T: Scalar>(x: &T) -> T {
    x.max_of(&T::zero()).min_of(&T::one()) * T::from_i64(255) + T::from_f64(0.5)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::scene::Scene;
    use crate::num::rng::SplitMix64;
    use crate::stages::lighting::{LightKind, Model};

    /// The camera scene whose Phong batches take every branch (shared with
    /// tests/render.rs).
    const MIXED: &str = include_str!("../../tests/common/mixed.toml");

    /// The Phong index of a rendered frame, its ranges found from the
    /// triangles' own objects (checking that they come object by object).
    fn index_of(f: &crate::render::Frame) -> PhongIndex {
        let mut ranges = vec![[0u32; 2]; f.looks.len()];
        for (k, t) in f.tris.iter().enumerate() {
            let r = &mut ranges[t.obj as usize];
            if r[1] == 0 {
                r[0] = k as u32;
            }
            assert!(r[1] == 0 || r[1] == k as u32, "triangles object by object");
            r[1] = k as u32 + 1;
        }
        PhongIndex::new(f.tris.len(), &ranges, &f.looks)
    }

    /// Eight ids are one Phong object's exactly when each is in its range
    /// of numbers: the mixed scene's index agrees with each triangle's own
    /// object, and runs across objects, background or non-Phong triangles
    /// are refused.
    #[test]
    fn eight_ids_are_one_objects_when_all_are_in_its_range() {
        let s = Scene::parse(MIXED, "mixed.toml", std::path::Path::new(".")).unwrap();
        let f = crate::render::render(&s, &crate::render::Options::of(&s)).unwrap();
        let ix = index_of(&f);
        let n = f.tris.len() as u32;
        let obj = |t: u32| f.tris[t as usize].obj as usize;
        // Windows of eight consecutive numbers, and of numbers far apart.
        for t0 in 0..n.saturating_sub(8) {
            for step in [1, 2, 7] {
                let ids: [u32; 8] = std::array::from_fn(|k| (t0 + step * k as u32).min(n - 1));
                let want = (ids.iter().all(|&t| obj(t) == obj(ids[0])))
                    .then(|| obj(ids[0]))
                    .filter(|&o| f.looks[o].shading == Shading::Phong);
                assert_eq!(ix.one_object(&ids), want, "ids {ids:?}");
            }
        }
        let mut ids = [0u32; 8];
        ids[5] = NONE;
        assert_eq!(ix.one_object(&ids), None, "background among them");
        assert_eq!(ix.one_object(&[NONE; 8]), None);
        // A scene of two objects: both are used.
        assert!(ix.range.iter().filter(|r| r[1] > r[0]).count() >= 2);
    }

    /// `run_length` counts what a scan one by one counts: runs shorter and
    /// longer than sixteen, ending inside or at the end of the slice.
    #[test]
    fn run_length_is_the_count_of_equal_leading_ids() {
        let mut rng = SplitMix64::new(3);
        for case in 0..2000 {
            let len = (rng.next_u64() % 70) as usize;
            let t = (rng.next_u64() % 3) as u32;
            let run = (rng.next_u64() % (len as u64 + 1)) as usize;
            let ids: Vec<u32> = (0..len)
                .map(|k| {
                    if k < run {
                        t
                    } else {
                        (rng.next_u64() % 4) as u32
                    }
                })
                .collect();
            let want = ids.iter().position(|&u| u != t).unwrap_or(len);
            assert_eq!(run_length(&ids, t), want, "case {case}: {ids:?}");
        }
    }

    /// The band pass compiled for the baseline (its body, `band`, called
    /// here without `multiversion`: two SSE registers per `F32x8` on
    /// x86-64) writes the same bytes as the copy `render` chose for this
    /// CPU (the AVX2 one where there is AVX2): on such machines this is the
    /// only run of the baseline copy, and elsewhere a copy is compared with
    /// itself. (tests/render.rs compares the frame with the one-pixel
    /// `pixel_color` path.)
    #[test]
    fn the_band_pass_gives_the_same_bytes_in_either_copy() {
        let s = Scene::parse(MIXED, "mixed.toml", std::path::Path::new(".")).unwrap();
        let f = crate::render::render(&s, &crate::render::Options::of(&s)).unwrap();
        let inp = BandInput {
            tris: &f.tris,
            corners: &f.corners,
            planes: &f.scratch.planes,
            looks: &f.looks,
            phong: &index_of(&f),
            ortho: f.ortho,
            bg: to_u8(s.background),
            width: f.width as usize,
        };
        let w = f.width as usize;
        let rows = crate::render::raster::BAND;
        let mut phong = 0;
        for (b, (want, id)) in f
            .rgb
            .chunks(3 * w * rows)
            .zip(f.ids.chunks(w * rows))
            .enumerate()
        {
            let mut got = vec![0u8; want.len()];
            let (_, evals) = band(&inp, (b * rows) as u32, &mut got, id);
            phong += evals;
            assert_eq!(got, want, "band {b}");
        }
        assert!(phong > 1500, "{phong}");
    }

    /// The lighting of eight pixels at [`F32x8`], in a function compiled by
    /// `multiversion` as the band pass is (AVX2 and FMA where the CPU has
    /// them), equals the lighting of each pixel at [`Fast32`], to the bit,
    /// over random materials, lights and surfaces of every model (tests/
    /// lanes.rs does the same for the baseline build).
    #[test]
    fn lanes_in_the_dispatched_copy_light_exactly_as_one_pixel() {
        let mut rng = SplitMix64::new(0x5eed);
        let mut u = move |lo: f32, hi: f32| {
            lo + (hi - lo) * (rng.next_u64() >> 40) as f32 / (1u64 << 24) as f32
        };
        for case in 0..400 {
            let (m, lights) = random_setting(case, &mut u);
            let lane = |u: &mut dyn FnMut(f32, f32) -> f32, lo, hi| {
                std::array::from_fn::<f32, 8, _>(|_| u(lo, hi))
            };
            let n = [0; 3].map(|_| lane(&mut u, -1.0, 1.0));
            let p = [0; 3].map(|_| lane(&mut u, -4.0, 4.0).map(|x| x - 5.0));
            let c = [0; 3].map(|_| lane(&mut u, 0.0, 1.0));
            let ortho = case % 7 == 0;
            let got = lit_lanes(&m, &lights, [n, p, c], ortho);
            for k in 0..8 {
                let one = |v: &[[f32; 8]; 3]| Vector3::new(v[0][k], v[1][k], v[2][k]);
                let want = light_at(
                    &m,
                    &lights,
                    one(&c).into(),
                    one(&n),
                    one(&p),
                    ortho,
                    &mut NoTrace,
                );
                for ch in 0..3 {
                    assert_eq!(
                        got[ch][k].to_bits(),
                        want[ch].to_bits(),
                        "case {case} channel {ch} lane {k}"
                    );
                }
            }
        }
    }

    /// A material and 1–3 lights of every kind and model, from `u`.
    fn random_setting(
        case: usize,
        u: &mut impl FnMut(f32, f32) -> f32,
    ) -> (Material<Fast32>, Vec<Light<Fast32>>) {
        let model = [Model::Phong, Model::Blinn, Model::Lambert, Model::Specular][case % 4];
        let mut m = Material::<Fast32>::text_default([Fast32(0.0); 3]);
        m.model = model;
        (m.ka, m.kd, m.ks) = (
            Fast32(u(0.0, 1.0)),
            Fast32(u(0.0, 1.0)),
            Fast32(u(0.0, 1.0)),
        );
        m.shininess = Fast32(if case.is_multiple_of(3) {
            u(0.5, 20.0)
        } else {
            (case % 40) as f32
        });
        m.specular_requires_lit = case.is_multiple_of(2);
        let mut lights = Vec::new();
        for k in 0..1 + case % 3 {
            let mut l = Light::<Fast32>::text_default();
            let mut v = || [u(-4.0, 4.0), u(-4.0, 4.0), u(-4.0, 4.0)];
            let (p, d) = (v(), v());
            let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-3);
            let (p, d) = (p.map(Fast32).into(), d.map(|x| Fast32(x / len)).into());
            l.kind = match (case + k) % 3 {
                0 => LightKind::Directional { dir: d },
                1 => LightKind::Point { pos: p },
                _ => LightKind::Spot {
                    pos: p,
                    dir: d,
                    theta: Fast32(u(5.0, 60.0)),
                    phi: Fast32(u(60.0, 100.0)),
                    falloff: Fast32(u(0.2, 3.0)),
                },
            };
            l.attenuation = [Fast32(1.0), Fast32(0.1), Fast32(0.02)];
            l.range = (case.is_multiple_of(5)).then(|| Fast32(u(0.5, 6.0)));
            lights.push(l);
        }
        (m, lights)
    }

    /// `lit` at [`F32x8`] for eight pixels given as normals, positions and
    /// colours (lane k of each), compiled as the band pass is.
    #[multiversion(targets("x86_64+avx2+fma"))]
    fn lit_lanes(
        m: &Material<Fast32>,
        lights: &[Light<Fast32>],
        [n, p, c]: [[[f32; 8]; 3]; 3],
        ortho: bool,
    ) -> [[f32; 8]; 3] {
        let mut mw: Material<F32x8> = m.cast();
        mw.color = c.map(F32x8::from_array);
        let lw: Vec<Light<F32x8>> = lights.iter().map(Light::cast).collect();
        let v = |a: [[f32; 8]; 3]| a.map(F32x8::from_array).into();
        lit(&mw, &lw, v(n), v(p), ortho, &mut NoTrace).map(F32x8::to_array)
    }

    /// Eight pixels' bytes come out in pixel order r0 g0 b0 r1 …, each
    /// what `to_u8` gives for its pixel, on colours in [0, 1], outside it,
    /// at the rounding boundaries (k ± ½)/255 and NaN; and the lane cast
    /// is `x as u8` on any f32.
    #[test]
    fn eight_pixels_bytes_are_the_one_pixel_bytes_in_pixel_order() {
        let mut rng = SplitMix64::new(11);
        let mut u = move |lo: f32, hi: f32| {
            lo + (hi - lo) * (rng.next_u64() >> 40) as f32 / (1u64 << 24) as f32
        };
        for case in 0..300 {
            let mut ch: [[f32; 8]; 3] =
                std::array::from_fn(|_| std::array::from_fn(|_| u(0.0, 1.0)));
            // One lane of one channel on a boundary or outside [0, 1].
            let k = (case % 255) as f32;
            let odd = [(k + 0.5) / 255.0, (k - 0.5) / 255.0, -0.25, 1.5, f32::NAN];
            ch[case / 3 % 3][case % 8] = odd[case % 5];
            let want: [u8; 24] =
                std::array::from_fn(|i| to_u8([ch[0][i / 3], ch[1][i / 3], ch[2][i / 3]])[i % 3]);
            assert_eq!(to_u8_lanes(ch.map(F32x8::from_array)), want, "case {case}");
            // The cast alone, on values from far below 0 to far above 255.
            let x: [f32; 8] = std::array::from_fn(|_| u(-300.0, 600.0));
            let x = if case % 7 == 0 { [f32::NAN; 8] } else { x };
            assert_eq!(
                F32x8::from_array(x).to_bytes(),
                x.map(|v| u32::from(v as u8))
            );
        }
    }

    /// Eight pixels filled straight from their triangles' planes hold, to
    /// the bit, the attributes the one-pixel path (`Planes::at`, which
    /// `--explain-pixel` shows) gives each of them.
    #[test]
    fn eight_pixels_from_planes_are_the_one_pixel_attributes() {
        let mut rng = SplitMix64::new(7);
        let mut u = move |lo: f32, hi: f32| {
            lo + (hi - lo) * (rng.next_u64() >> 40) as f32 / (1u64 << 24) as f32
        };
        let planes: Vec<Planes> = (0..5)
            .map(|t| Planes {
                c0: std::array::from_fn(|_| u(-2.0, 2.0)),
                cx: std::array::from_fn(|_| u(-0.1, 0.1)),
                cy: std::array::from_fn(|_| u(-0.1, 0.1)),
                origin: [u(0.0, 500.0).floor(), u(0.0, 500.0).floor()],
                solid: t % 2 == 0,
            })
            .collect();
        for case in 0..50u32 {
            let ids: [u32; 8] = std::array::from_fn(|k| (case + k as u32 / 3) % 5);
            let (i, j) = (3 * case as usize, 400 + case);
            // Without the colour planes, lanes 0–7 are filled and the rest
            // left as they were (NaN here); with them, all.
            let mut b = Batch {
                q: [[f32::NAN; 12]; 8],
                ..Batch::default()
            };
            b.fill8(&planes, &ids, i, j, false);
            for (k, &t) in ids.iter().enumerate() {
                let p = &planes[t as usize];
                let want: [f32; 8] = std::array::from_fn(|a| {
                    (p.c0[a] + p.cy[a] * (j as f32 - p.origin[1]))
                        + p.cx[a] * ((i + k) as f32 - p.origin[0])
                });
                assert_eq!(b.q[k][..8], want, "case {case} pixel {k}");
                assert!(b.q[k][8..].iter().all(|x| x.is_nan()));
            }
            b.len = 0;
            b.fill8(&planes, &ids, i, j, true);
            for (k, &t) in ids.iter().enumerate() {
                let p = &planes[t as usize];
                let (n, pos, c) = p.at((i + k) as u32, j);
                let q = &b.q[k];
                // at() gives N, P and (for interpolated colour) C times
                // r = 1/q0; the batch holds q itself: compare through at()'s
                // own formulas.
                let r = if q[0] > 0.0 { 1.0 / q[0] } else { 0.0 };
                assert_eq!(
                    [n.x.0, n.y.0, n.z.0],
                    [q[1] * r, q[2] * r, q[3] * r],
                    "case {case} pixel {k}"
                );
                assert_eq!([pos.x.0, pos.y.0, pos.z.0], [q[4] * r, q[5] * r, q[6] * r]);
                let want = if p.solid {
                    [q[7], q[8], q[9]]
                } else {
                    [q[7] * r, q[8] * r, q[9] * r]
                };
                assert_eq!(c.map(|x| x.0), want);
                assert_eq!(b.col[k] as usize, i + k);
                assert_eq!(b.interp >> k & 1 == 1, !p.solid);
            }
            b.len = 0;
            b.fill8(&planes, &ids, i, j, false);
            for k in 0..8 {
                assert_eq!(b.col[k] as usize, i + k);
                assert_eq!(b.interp, 0, "colours not interpolated without their planes");
            }
        }
    }
}
