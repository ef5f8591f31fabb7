//! Rasterization: triangle setup in fixed point, edge functions with the
//! top-left fill rule, a depth test, binning into horizontal bands and the
//! visibility pass of one band (the renderer runs the bands in parallel).
//!
//! Screen coordinates here are pixels with the origin at the *top* left
//! (rows as the PNG stores them), snapped to 1/256 pixel. A pixel (i, j) is
//! covered when its centre (i + ½, j + ½) is inside the triangle or on a top
//! or left edge: two triangles sharing an edge never both cover a pixel on
//! it and never both miss it, because the edge functions are exact integers.

use multiversion::multiversion;
use num_traits::{AsPrimitive, PrimInt, WrappingAdd, WrappingMul};

/// Sub-pixel bits of the fixed-point screen coordinates (the stage's
/// [`crate::stages::window::SUBPIXEL_BITS`]).
pub const SUB: i64 = crate::stages::window::SUBPIXEL_BITS;
const ONE: i64 = 1 << SUB;
const HALF: i64 = ONE / 2;

/// Rows per band: the unit of binning and of parallel work.
pub const BAND: usize = 32;

/// "No triangle" in the visibility buffer.
pub const NONE: u32 = u32::MAX;

/// A screen-space vertex: pixel coordinates (origin top left, y down),
/// depth z/w (−1 near … 1 far) and 1/w.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ScreenVert {
    /// Column, pixels.
    pub x: f32,
    /// Row, pixels (down).
    pub y: f32,
    /// z/w.
    pub z: f32,
    /// 1/w.
    pub inv_w: f32,
}

/// A set-up triangle: integer edge functions, a pixel bounding box, and the
/// planes of depth and of the screen barycentrics.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tri {
    /// Edge function k (weight of vertex k): E = a·X + b·Y + c, X and Y in
    /// 1/256 pixel; c includes the fill-rule bias. a and b are differences
    /// of snapped coordinates on the image (at most 8192·256 = 2²¹ apart).
    pub a: [i32; 3],
    /// See `a`.
    pub b: [i32; 3],
    /// See `a`.
    pub c: [i64; 3],
    /// Covered pixels lie in columns x0..=x1 and rows y0..=y1.
    pub bbox: [u32; 4],
    /// Depth at pixel (x0, y0) and its steps per column and per row.
    pub z: [f32; 3],
    /// Screen barycentric λ1 at (x0, y0) and its steps.
    pub l1: [f32; 3],
    /// Screen barycentric λ2 at (x0, y0) and its steps.
    pub l2: [f32; 3],
    /// 1/w at the vertices.
    pub inv_w: [f32; 3],
    /// Which object it came from.
    pub obj: u32,
    /// Which of the object's triangles (its number in the object's triangle
    /// list; several set-up triangles share it when it was clipped).
    pub src: u32,
}

/// A triangle's vertices snapped to 1/256 pixel, wound positively (vertices
/// 1 and 2 exchanged when `swap`), with its pixel box: the cheap first half
/// of a set-up, from [`snap_box_of`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Snapped {
    x: [i64; 3],
    y: [i64; 3],
    /// Twice the area, > 0: E_01 at vertex 2.
    area: i64,
    swap: bool,
    /// Covered pixels lie in columns x0..=x1 and rows y0..=y1.
    pub bbox: [u32; 4],
}

impl Snapped {
    /// Whether vertices 1 and 2 were exchanged to make the winding positive.
    pub fn swap(&self) -> bool {
        self.swap
    }
}

/// A triangle's vertices snapped by [`crate::stages::window::snap`] (x, y
/// each) for an image of `w` × `h` pixels, wound positively, with its pixel
/// box (the centres X = 256·i + 128 within the vertices' extremes): `None`
/// when it covers no pixel centre (zero area, or no centre in the box or on
/// the image).
#[inline]
pub fn snap_box_of(s: [[i64; 2]; 3], w: u32, h: u32) -> Option<Snapped> {
    let (mut x, mut y) = (s.map(|p| p[0]), s.map(|p| p[1]));
    let area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if area < 0 {
        x.swap(1, 2);
        y.swap(1, 2);
    }
    let lo = |m: i64| (m - HALF + ONE - 1).div_euclid(ONE).max(0);
    let hi = |m: i64, n: u32| (m - HALF).div_euclid(ONE).min(n as i64 - 1);
    let (x0, x1) = (x[0].min(x[1]).min(x[2]), x[0].max(x[1]).max(x[2]));
    let (y0, y1) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
    let bbox = [lo(x0), hi(x1, w), lo(y0), hi(y1, h)];
    (area != 0 && bbox[0] <= bbox[1] && bbox[2] <= bbox[3]).then(|| Snapped {
        x,
        y,
        area: area.abs(),
        swap: area < 0,
        bbox: bbox.map(|v| v as u32),
    })
}

/// Sets up a triangle for an image of `w` × `h` pixels from its vertices,
/// each with its position snapped by [`crate::stages::window::snap`] (x, y):
/// `None` exactly when [`snap_box_of`] gives `None`. The flag says whether
/// vertices 1 and 2 were exchanged to make the winding positive (the caller
/// swaps their attributes too).
pub fn setup_of(v: [(ScreenVert, [i64; 2]); 3], w: u32, h: u32) -> Option<(Tri, bool)> {
    let s = snap_box_of(v.map(|p| p.1), w, h)?;
    let mut t = Tri::default();
    setup_into(&v.map(|p| [p.0.z, p.0.inv_w]), &s, &mut t);
    Some((t, s.swap))
}

/// The second half of a set-up, written straight into `t` (every field but
/// `obj` and `src`; the geometry stage sets up in place), from the vertices'
/// z/w and 1/w (`v`, in their order before [`snap_box_of`] swapped them).
/// Edge k runs from vertex i = k+1 to j = k+2: a_k = y_i − y_j,
/// b_k = x_j − x_i, c_k = −a_k·x_i − b_k·y_i (E_k = 0 on it), less 1 unless
/// the edge is top or left (y down, inside where E ≥ 0: a top edge runs right
/// along a row, a left edge runs up; any other needs E > 0). The plane of λ_k
/// over pixel indices from (x0, y0) is (E_k(x0, y0), 256·a_k, 256·b_k)/area
/// in f64 (E_k without the bias), the depth plane Σ_k plane_k·z_k.
#[inline(always)]
pub fn setup_into(v: &[[f32; 2]; 3], s: &Snapped, t: &mut Tri) {
    let mut v = *v;
    if s.swap {
        v.swap(1, 2);
    }
    let (x, y, area) = (s.x, s.y, s.area as f64);
    let (ox, oy) = (s.bbox[0] as i64 * ONE + HALF, s.bbox[2] as i64 * ONE + HALF);
    // A loop, not `array::from_fn`, which the compiler left as a call.
    let mut p = [[0.0f64; 3]; 3];
    for (k, p) in p.iter_mut().enumerate() {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let (a, b) = (y[i] - y[j], x[j] - x[i]);
        let c = -a * x[i] - b * y[i];
        (t.a[k], t.b[k]) = (a as i32, b as i32);
        t.c[k] = c - i64::from(a < 0 || (a == 0 && b <= 0));
        *p = [a * ox + b * oy + c, a * ONE, b * ONE].map(|e| e as f64 / area);
    }
    let z = v.map(|p| f64::from(p[0]));
    t.bbox = s.bbox;
    t.z = std::array::from_fn(|i| (p[0][i] * z[0] + p[1][i] * z[1] + p[2][i] * z[2]) as f32);
    t.l1 = p[1].map(|t| t as f32);
    t.l2 = p[2].map(|t| t as f32);
    t.inv_w = v.map(|p| p[1]);
}

impl Tri {
    /// Whether the pixel (i, j) is covered (exact, with the fill rule).
    pub fn covers(&self, i: u32, j: u32) -> bool {
        (0..3).all(|k| edge(self, k, i.into(), j.into()) >= 0)
    }

    /// Pixel (i, j) less the box's corner (x0, y0), in f32.
    fn offset(&self, i: u32, j: u32) -> (f32, f32) {
        (
            i as f32 - self.bbox[0] as f32,
            j as f32 - self.bbox[2] as f32,
        )
    }

    /// Screen barycentrics (λ0, λ1, λ2) at pixel (i, j).
    #[inline]
    pub fn lambda(&self, i: u32, j: u32) -> [f32; 3] {
        let (di, dj) = self.offset(i, j);
        let l1 = self.l1[0] + self.l1[1] * di + self.l1[2] * dj;
        let l2 = self.l2[0] + self.l2[1] * di + self.l2[2] * dj;
        [1.0 - l1 - l2, l1, l2]
    }

    /// Perspective-correct weights at pixel (i, j): μk = (λk/wk) / Σ λm/wm
    /// (an attribute that is linear in eye space is Σ μk·ak).
    #[inline]
    pub fn mu(&self, i: u32, j: u32) -> [f32; 3] {
        let l = self.lambda(i, j);
        let q: [f32; 3] = std::array::from_fn(|k| l[k] * self.inv_w[k]);
        let s = q[0] + q[1] + q[2];
        if s != 0.0 {
            let r = 1.0 / s;
            q.map(|q| q * r)
        } else {
            l
        }
    }

    /// Depth z/w at pixel (i, j): the plane's row value plus the column
    /// steps, z(i, j) = (z₀ + z_y·(j − y0)) + z_x·(i − x0) in f32, the two
    /// sums in that order (the rasterizer computes the same expression, so
    /// this is the value the z-buffer held).
    #[inline]
    pub fn depth(&self, i: u32, j: u32) -> f32 {
        let (di, dj) = self.offset(i, j);
        (self.z[0] + self.z[2] * dj) + self.z[1] * di
    }
}

/// E_k at the centre of pixel (i, j): a_k·(256·i + 128) + b_k·(256·j + 128) + c_k.
#[inline]
fn edge(t: &Tri, k: usize, i: i64, j: i64) -> i64 {
    i64::from(t.a[k]) * (i * ONE + HALF) + i64::from(t.b[k]) * (j * ONE + HALF) + t.c[k]
}

/// The visibility pass of one band (rows from `r0`): clears it, then draws
/// its triangles in order; for every pixel the nearest triangle wins
/// (strictly nearer, so the first drawn keeps a tie).
///
/// Compiled for AVX2 and FMA too (a block of eight columns in one
/// register), chosen at run time; the results are the same bits.
#[multiversion(targets("x86_64+avx2+fma"))]
pub fn visibility_band(
    tris: &[Tri],
    bin: &[u32],
    r0: u32,
    w: usize,
    dz: &mut [f32],
    id: &mut [u32],
) {
    dz.fill(f32::INFINITY);
    id.fill(NONE);
    let r1 = r0 + (dz.len() / w) as u32 - 1;
    for &t in bin {
        raster_one(&tris[t as usize], t, r0, r1, w, dz, id);
    }
}

/// Columns per block of the raster loop.
const LANES: usize = 8;

/// Rasterizes one triangle into rows r0..=r1 of a band: its rows there,
/// columns x0 up to whole blocks (cut at the image's edge), edge functions in
/// i32 lanes where they fit ([`fits_i32`]) and in i64 otherwise. The 1- and
/// 2-block widths get their own copy of the loop, the blocks unrolled.
#[inline(always)]
fn raster_one(t: &Tri, id: u32, r0: u32, r1: u32, w: usize, dz: &mut [f32], ids: &mut [u32]) {
    let [x0, x1, y0, y1] = t.bbox;
    let (ya, yb) = (y0.max(r0), y1.min(r1));
    if ya > yb {
        return;
    }
    let n = ((x1 - x0) as usize + 1)
        .next_multiple_of(LANES)
        .min(w - x0 as usize);
    match (fits_i32(t, (ya, yb), n), n) {
        (true, LANES) => rows::<i32>(t, id, (ya, yb, r0, w), LANES, dz, ids),
        (true, 16) => rows::<i32>(t, id, (ya, yb, r0, w), 2 * LANES, dz, ids),
        (true, n) => rows::<i32>(t, id, (ya, yb, r0, w), n, dz, ids),
        (false, n) => rows::<i64>(t, id, (ya, yb, r0, w), n, dz, ids),
    }
}

/// Whether every E_k drawn from row ya to yb, in `n` columns from x0 rounded
/// up to whole blocks, fits in an i32. First by a bound on the triangle:
/// Y·(2·X + 2048) < 2³¹, X and Y the largest |b_k| and |a_k| (the vertices'
/// spans in x and in y, 1/256 pixel). Why: the box's pixel centres lie within
/// those spans, so a drawn centre P (columns up to 7 past the box) is within
/// X + 7·256 in x and Y in y of any vertex V. With V on edge k,
/// E_k(P) = a_k·(Px − Vx) + b_k·(Py − Vy) (− 1 for the fill rule), so
/// |E_k| ≤ Y·(X + 1792) + X·Y + 1. Failing that, exactly: E_k is affine, so
/// its least (greatest) value is E_k(x0, ya) plus those of 256·a_k·(columns
/// − 1) and 256·b_k·(yb − ya) that are negative (positive).
#[inline(always)]
fn fits_i32(t: &Tri, (ya, yb): (u32, u32), n: usize) -> bool {
    let most = |v: [i32; 3]| u64::from(v.map(i32::unsigned_abs).into_iter().max().unwrap_or(0));
    most(t.a) * (2 * most(t.b) + 2048) < 1 << 31
        || (0..3).all(|k| {
            let (di, dj) = (n.next_multiple_of(LANES) as i64 - 1, i64::from(yb - ya));
            let e = edge(t, k, t.bbox[0].into(), ya.into());
            let (s, r) = (i64::from(t.a[k]) * ONE * di, i64::from(t.b[k]) * ONE * dj);
            let ends = [e + s.min(0) + r.min(0), e + s.max(0) + r.max(0)];
            ends.iter().all(|&v| v == i64::from(v as i32))
        })
}

/// Draws rows ya..=yb of `t` in columns x0..x0 + n, LANES at a time, with
/// the edge functions in lanes of type `L` (wrapping, so exact modulo 2^bits:
/// the true value whenever that fits). At column i = x0 + q and row j:
/// E_k = E_k(x0, ya) + 256·a_k·q + 256·b_k·(j − ya) and
/// z = (z₀ + z_y·(j − y0)) + z_x·q ([`draw`]). A last block cut short by the
/// image's edge is drawn in a copy padded with −∞ (never nearer).
#[inline(always)]
fn rows<L>(
    t: &Tri,
    id: u32,
    (ya, yb, r0, w): (u32, u32, u32, usize),
    n: usize,
    dz: &mut [f32],
    ids: &mut [u32],
) where
    L: PrimInt + WrappingAdd + WrappingMul + 'static,
    i64: AsPrimitive<L>,
{
    let [x0, _, y0, _] = t.bbox;
    let [z0, zx, zy] = t.z;
    let col = t.a.map(|a| i64::from(a) * ONE);
    let (row, block) = (
        t.b.map(|b| (i64::from(b) * ONE).as_()),
        col.map(|s| (s * LANES as i64).as_()),
    );
    // E_k at the columns of the row's first block, starting at row ya.
    // (`black_box`: multiplied by an opaque vector, the lanes take one vector
    // multiply; by the known constants, LLVM emits a longer mix of shifts,
    // multiplies and permutes.)
    let column: [L; LANES] = std::hint::black_box(std::array::from_fn(|c| (c as i64).as_()));
    let mut er: [[L; LANES]; 3] = std::array::from_fn(|k| {
        let (e, s): (L, L) = (edge(t, k, x0.into(), ya.into()).as_(), col[k].as_());
        column.map(|c| e.wrapping_add(&s.wrapping_mul(&c)))
    });
    // Rows ya..=yb from column x0: row r of the span starts at r·w and
    // needs n pixels; j − y0 counted in f32 (exact: images are far below 2²⁴).
    let at = (ya - r0) as usize * w + x0 as usize..(yb - r0) as usize * w + x0 as usize + n;
    let (dz, ids, mut dj) = (&mut dz[at.clone()], &mut ids[at], (ya - y0) as f32);
    for o in (0..(yb - ya + 1) as usize).map(|r| r * w) {
        let zr = (z0 + zy * dj, zx);
        let ((dc, dr), (ic, ir)) = (dz[o..o + n].as_chunks_mut(), ids[o..o + n].as_chunks_mut());
        let mut e = er;
        for (q, (d, ib)) in dc.iter_mut().zip(ic).enumerate() {
            draw(&e, zr, (q * LANES) as i32, id, (d, ib));
            step(&mut e, block);
        }
        if !dr.is_empty() {
            let (m, mut d, mut ib) = (dr.len(), [f32::NEG_INFINITY; LANES], [0; LANES]);
            d[..m].copy_from_slice(dr);
            ib[..m].copy_from_slice(ir);
            draw(&e, zr, (n - m) as i32, id, (&mut d, &mut ib));
            dr.copy_from_slice(&d[..m]);
            ir.copy_from_slice(&ib[..m]);
        }
        step(&mut er, row);
        dj += 1.0;
    }
}

/// Draws the block of columns x0 + q..x0 + q + LANES of a row, whose depth
/// at column x0 + p is z = z_r + z_x·p: a column is drawn where every E_k ≥ 0
/// and z is strictly nearer. Masks and selects, not branches, so the block
/// vectorizes and overdraw costs no mispredictions.
#[inline(always)]
fn draw<L: PrimInt>(
    e: &[[L; LANES]; 3],
    (zr, zx): (f32, f32),
    q: i32,
    id: u32,
    (d, ib): (&mut [f32; LANES], &mut [u32; LANES]),
) {
    for c in 0..LANES {
        let z = zr + zx * (q + c as i32) as f32;
        let inside = (e[0][c] | e[1][c] | e[2][c]) >= L::zero();
        let s = 0u32.wrapping_sub(u32::from(inside & (z < d[c])));
        d[c] = f32::from_bits((z.to_bits() & s) | (d[c].to_bits() & !s));
        ib[c] = (id & s) | (ib[c] & !s);
    }
}

/// Adds s_k to every lane of E_k (wrapping).
#[inline(always)]
fn step<L: WrappingAdd>(e: &mut [[L; LANES]; 3], s: [L; 3]) {
    for (e, s) in e.iter_mut().zip(s) {
        for e in e {
            *e = e.wrapping_add(&s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stages::window::snap;

    fn setup(v: [ScreenVert; 3], w: u32, h: u32) -> Option<(Tri, bool)> {
        setup_of(v.map(|p| (p, [snap(p.x), snap(p.y)])), w, h)
    }

    fn sv(x: f32, y: f32) -> ScreenVert {
        ScreenVert {
            x,
            y,
            z: 0.0,
            inv_w: 1.0,
        }
    }

    fn coverage(tris: &[Tri], w: u32, h: u32) -> Vec<u32> {
        let mut n = vec![0u32; (w * h) as usize];
        for t in tris {
            for j in 0..h {
                for i in 0..w {
                    if t.covers(i, j) {
                        n[(j * w + i) as usize] += 1;
                    }
                }
            }
        }
        n
    }

    #[test]
    fn quad_split_in_two_covers_each_pixel_once() {
        // A quad whose diagonal passes exactly through pixel centres
        // (x + ½ = y + ½), and whose sides lie on pixel centres: the shared
        // diagonal and the edges on centres must be decided by the fill rule.
        let (a, b, c, d) = (sv(0.5, 0.5), sv(8.5, 0.5), sv(8.5, 8.5), sv(0.5, 8.5));
        let t1 = setup([a, b, c], 10, 10).unwrap().0;
        let t2 = setup([a, c, d], 10, 10).unwrap().0;
        let n = coverage(&[t1, t2], 10, 10);
        assert!(n.iter().all(|&k| k <= 1), "a pixel drawn twice");
        // Centres (i+½, j+½) with 0.5 ≤ · < 8.5 on each axis (top-left
        // rule: left and top edges in, right and bottom out): 8 × 8 pixels.
        assert_eq!(n.iter().sum::<u32>(), 64);
    }

    #[test]
    fn fan_around_a_centre_has_no_cracks() {
        // Eight triangles around (5.3, 4.7) with irregular outer points: every
        // pixel centre inside the octagon is covered exactly once.
        let c = sv(5.3, 4.7);
        let ring = [
            sv(1.1, 1.2),
            sv(5.0, 0.3),
            sv(9.7, 1.9),
            sv(9.9, 5.0),
            sv(9.1, 9.6),
            sv(5.5, 9.9),
            sv(0.4, 9.2),
            sv(0.2, 5.1),
        ];
        let tris: Vec<Tri> = (0..8)
            .filter_map(|k| setup([c, ring[k], ring[(k + 1) % 8]], 11, 11).map(|t| t.0))
            .collect();
        let n = coverage(&tris, 11, 11);
        assert!(n.iter().all(|&k| k <= 1));
        // The pixel at the centre and its neighbours are covered.
        assert_eq!(n[4 * 11 + 5], 1);
        assert_eq!(n[5 * 11 + 4], 1);
    }

    #[test]
    fn winding_does_not_matter_and_barycentrics_sum_to_one() {
        let t = setup([sv(1.0, 1.0), sv(9.0, 2.0), sv(3.0, 8.0)], 10, 10).unwrap();
        let u = setup([sv(1.0, 1.0), sv(3.0, 8.0), sv(9.0, 2.0)], 10, 10).unwrap();
        assert!(!t.1 && u.1);
        assert_eq!(
            coverage(std::slice::from_ref(&t.0), 10, 10),
            coverage(&[u.0], 10, 10)
        );
        // At a vertex's own position λ is 1 for it (vertex 0 at (1,1) is not a
        // centre, so check the sum and a centre near vertex 2 instead).
        let l = t.0.lambda(3, 6);
        assert!((l[0] + l[1] + l[2] - 1.0).abs() < 1e-6);
        assert!(l[2] > l[0] && l[2] > l[1]);
    }

    /// The depth the raster writes at pixel (i, j): the plane at the row,
    /// z₀ + z_y·(j − y0), plus z_x times the columns from x0, in f32 (the
    /// definition, written out independently of `Tri::depth`).
    fn plane_depth(t: &Tri, i: u32, j: u32) -> f32 {
        let row = t.z[0] + t.z[2] * (j - t.bbox[2]) as f32;
        row + t.z[1] * (i - t.bbox[0]) as f32
    }

    /// A random screen vertex: anywhere around the image, on pixel centres,
    /// or on quarter pixels.
    fn random_vert(rng: &mut crate::num::rng::SplitMix64, w: u32, h: u32) -> ScreenVert {
        let mut c = |n: u32| rng.range(-40 * 4, (n as i64 + 40) * 4) as f32 / 4.0;
        let (x, y) = (c(w), c(h));
        let (x, y) = match rng.below(3) {
            0 => (x.floor() + 0.5, y.floor() + 0.5),
            _ => (x, y),
        };
        ScreenVert {
            x,
            y,
            z: rng.range(-1000, 1000) as f32 / 1000.0,
            inv_w: 1.0,
        }
    }

    /// Random triangles of every kind: large (edge functions beyond i32),
    /// small, tiny (within a pixel or two), thin (a vertex near the opposite
    /// edge's line), and off the image or across its edges.
    fn random_tris(seed: u64, n: usize, w: u32, h: u32) -> Vec<Tri> {
        let mut rng = crate::num::rng::SplitMix64::new(seed);
        let mut tris = Vec::new();
        while tris.len() < n {
            let a = random_vert(&mut rng, w, h);
            let (mut b, mut c) = (random_vert(&mut rng, w, h), random_vert(&mut rng, w, h));
            match rng.below(4) {
                0 => {}
                1 => {
                    // Small or tiny: b and c within r pixels of a.
                    let r = [1, 2, 6, 15][rng.below(4) as usize] as f32;
                    for v in [&mut b, &mut c] {
                        v.x = a.x + (v.x - a.x) / (w as f32) * r;
                        v.y = a.y + (v.y - a.y) / (h as f32) * r;
                    }
                }
                2 => {
                    // Thin: c just off the segment ab.
                    let f = rng.below(1000) as f32 / 1000.0;
                    c.x = a.x + f * (b.x - a.x) + rng.range(-2, 2) as f32 / 8.0;
                    c.y = a.y + f * (b.y - a.y) + rng.range(-2, 2) as f32 / 8.0;
                }
                _ => {
                    // Axis-aligned edge through pixel centres.
                    b.y = a.y;
                }
            }
            if let Some((t, _)) = setup([a, b, c], w, h) {
                tris.push(t);
            }
        }
        tris
    }

    /// The band pass as the renderer calls it.
    type Pass = fn(&[Tri], &[u32], u32, usize, &mut [f32], &mut [u32]);
    const PASSES: [Pass; 1] = [visibility_band];

    #[test]
    fn band_raster_covers_exactly_the_pixels_covers_accepts() {
        // Each triangle alone: the pixels the band pass draws are exactly
        // those whose centre passes the three edge tests, with the plane's
        // depth (the one `Tri::depth` explains); nothing outside the
        // triangle is touched. Images narrower than a block and not a
        // whole number of blocks wide too.
        // Triangles drawn in i64 lanes, in i32 lanes with 1, 2 and more
        // blocks per row, and with a last block cut at the image's edge.
        let mut kinds = [0usize; 5];
        for (w, h, count) in [
            (301u32, 70u32, 600),
            (1500, 40, 100),
            (13, 40, 100),
            (5, 40, 100),
        ] {
            for (n, t) in random_tris(7, count, w, h).iter().enumerate() {
                let blocks = (t.bbox[1] - t.bbox[0]) as usize / LANES + 1;
                let cols = (blocks * LANES).min((w - t.bbox[0]) as usize);
                let fits = fits_i32(t, (t.bbox[2], t.bbox[3]), cols);
                kinds[if fits { blocks.min(3) } else { 0 }] += 1;
                kinds[4] += usize::from(t.bbox[0] as usize + blocks * LANES > w as usize);
                for pass in PASSES {
                    for r0 in (0..h).step_by(BAND) {
                        let rows = (BAND as u32).min(h - r0);
                        let mut dz = vec![0.0f32; (rows * w) as usize];
                        let mut id = vec![0u32; (rows * w) as usize];
                        let one = std::slice::from_ref(t);
                        pass(one, &[0], r0, w as usize, &mut dz, &mut id);
                        for j in r0..r0 + rows {
                            for i in 0..w {
                                let k = ((j - r0) * w + i) as usize;
                                if t.covers(i, j) {
                                    assert_eq!(id[k], 0, "triangle {n} misses ({i}, {j})");
                                    assert_eq!(dz[k].to_bits(), plane_depth(t, i, j).to_bits());
                                    assert_eq!(dz[k].to_bits(), t.depth(i, j).to_bits());
                                } else {
                                    assert_eq!(id[k], NONE, "triangle {n} draws ({i}, {j})");
                                    assert_eq!(dz[k], f32::INFINITY);
                                }
                            }
                        }
                    }
                }
            }
        }
        assert!(kinds.iter().all(|&k| k > 20), "{kinds:?}");
    }

    #[test]
    fn fits_i32_bounds_every_edge_value_drawn() {
        // Wherever `fits_i32` accepts a triangle from one of its rows ya,
        // E_k at the corners of the pixels drawn (rows ya..=y1, columns x0
        // up to whole blocks; E_k is affine, so its extremes are there),
        // computed exactly, is an i32.
        let (w, h) = (301u32, 70u32);
        let (mut fit, mut wide) = (0, 0);
        for t in random_tris(5, 3000, w, h) {
            let [x0, x1, y0, y1] = t.bbox;
            let n = ((x1 - x0) as usize + 1).next_multiple_of(LANES);
            for ya in y0..=y1 {
                if !fits_i32(&t, (ya, y1), n) {
                    wide += 1;
                    continue;
                }
                fit += 1;
                for (i, j) in [(0, ya), (n - 1, ya), (0, y1), (n - 1, y1)] {
                    for k in 0..3 {
                        let e = edge(&t, k, i64::from(x0) + i as i64, j.into());
                        assert_eq!(e, i64::from(e as i32), "{t:?}");
                    }
                }
            }
        }
        assert!(fit > 10000 && wide > 1000, "{fit} {wide}");
    }

    #[test]
    fn band_raster_keeps_the_nearest_and_the_first_of_equals() {
        // Many triangles in one buffer against the rule applied pixel by
        // pixel: in submission order, a covered pixel takes the triangle when
        // its depth is strictly less than the stored one.
        let (w, h) = (301u32, 70u32);
        let mut tris = random_tris(11, 300, w, h);
        // Exact ties: copies of earlier triangles drawn again later.
        for k in 0..40 {
            tris.push(tris[k * 3].clone());
        }
        let order: Vec<u32> = (0..tris.len() as u32).collect();
        let mut want_z = vec![f32::INFINITY; (w * h) as usize];
        let mut want_id = vec![NONE; (w * h) as usize];
        for (n, t) in tris.iter().enumerate() {
            for j in 0..h {
                for i in 0..w {
                    let k = (j * w + i) as usize;
                    if t.covers(i, j) && plane_depth(t, i, j) < want_z[k] {
                        want_z[k] = plane_depth(t, i, j);
                        want_id[k] = n as u32;
                    }
                }
            }
        }
        for r0 in (0..h).step_by(BAND) {
            let rows = (BAND as u32).min(h - r0);
            let (a, b) = ((r0 * w) as usize, ((r0 + rows) * w) as usize);
            let mut dz = vec![0.0f32; b - a];
            let mut id = vec![0u32; b - a];
            for pass in PASSES {
                pass(&tris, &order, r0, w as usize, &mut dz, &mut id);
                assert_eq!(id, want_id[a..b]);
                assert!(dz
                    .iter()
                    .zip(&want_z[a..b])
                    .all(|(x, y)| x.to_bits() == y.to_bits()));
            }
        }
    }
}
