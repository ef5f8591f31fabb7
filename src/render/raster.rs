//! Rasterization: triangle setup in fixed point, edge functions with the
//! top-left fill rule, a depth test, binning into horizontal bands and the
//! visibility pass of one band (the renderer runs the bands in parallel).
//!
//! Screen coordinates here are pixels with the origin at the *top* left
//! (rows as the PNG stores them), snapped to 1/256 pixel. A pixel (i, j) is
//! covered when its centre (i + ½, j + ½) is inside the triangle or on a top
//! or left edge: two triangles sharing an edge never both cover a pixel on
//! it and never both miss it, because the edge functions are exact integers.

use crate::stages::window::snap;
use multiversion::multiversion;

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
    /// Which of the object's triangles (its number in the object's
    /// triangle list; several set-up triangles share it when it was
    /// clipped).
    pub src: u32,
}

/// A triangle's vertices snapped to 1/256 pixel, wound positively, with the
/// pixel box of the centres it may cover (the cheap first half of [`setup`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Snapped {
    /// Snapped columns (vertices 1 and 2 exchanged when `swap`).
    x: [i64; 3],
    /// Snapped rows.
    y: [i64; 3],
    /// Twice the area, > 0: E_01 at vertex 2.
    area: i64,
    /// Whether vertices 1 and 2 were exchanged to make the winding positive.
    swap: bool,
    /// Covered pixels lie in columns x0..=x1 and rows y0..=y1.
    pub bbox: [u32; 4],
}

/// A triangle's vertices snapped by [`snap`] (x, y each) for an image of
/// `w` × `h` pixels, wound positively, with its pixel box: `None` exactly
/// when [`setup`] returns `None` (zero area, or a box with no pixel centre
/// in it or on the image).
#[inline]
pub fn snap_box_of(s: [[i64; 2]; 3], w: u32, h: u32) -> Option<Snapped> {
    let mut x = s.map(|p| p[0]);
    let mut y = s.map(|p| p[1]);
    // Twice the signed area: E_01 at vertex 2.
    let mut area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if area == 0 {
        return None;
    }
    let swap = area < 0;
    if swap {
        x.swap(1, 2);
        y.swap(1, 2);
        area = -area;
    }
    // Pixel box: centres X = 256·i + 128 within [min, max].
    let (minx, maxx) = (x[0].min(x[1]).min(x[2]), x[0].max(x[1]).max(x[2]));
    let (miny, maxy) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
    let lo = |m: i64| (m - HALF + ONE - 1).div_euclid(ONE).max(0);
    let hi = |m: i64, n: u32| (m - HALF).div_euclid(ONE).min(n as i64 - 1);
    let (x0, x1, y0, y1) = (lo(minx), hi(maxx, w), lo(miny), hi(maxy, h));
    if x0 > x1 || y0 > y1 {
        return None;
    }
    Some(Snapped {
        x,
        y,
        area,
        swap,
        bbox: [x0 as u32, x1 as u32, y0 as u32, y1 as u32],
    })
}

impl Snapped {
    /// Whether vertices 1 and 2 were exchanged to make the winding positive.
    pub fn swap(&self) -> bool {
        self.swap
    }
}

/// Sets up a triangle for an image of `w` × `h` pixels. Returns `None` when
/// it covers no pixel centre (degenerate, or between centres, or off
/// screen). `swap` reports whether vertices 1 and 2 were exchanged to make
/// the winding positive (the caller swaps their attributes too).
pub fn setup(v: [ScreenVert; 3], w: u32, h: u32) -> Option<(Tri, bool)> {
    setup_of(v.map(|p| (p, [snap(p.x), snap(p.y)])), w, h)
}

/// [`setup`] of vertices each given with its position snapped by
/// [`snap`] (x, y).
pub fn setup_of(v: [(ScreenVert, [i64; 2]); 3], w: u32, h: u32) -> Option<(Tri, bool)> {
    let s = snap_box_of(v.map(|p| p.1), w, h)?;
    let mut t = Tri::default();
    setup_into(&v.map(|p| [p.0.z, p.0.inv_w]), &s, &mut t);
    Some((t, s.swap))
}

/// The second half of [`setup`], written straight into `t` (every field
/// but `obj` and `src`), so that the geometry stage sets up a triangle in
/// its place in the frame's array without a copy: from a triangle that
/// [`snap_box_of`] accepted and its vertices' depth z/w and 1/w (`v`, in
/// the order given to it, not yet swapped). Edge k runs from vertex k+1 to vertex
/// k+2: a_k = −dy, b_k = dx, c_k = dy·x_i − dx·y_i (less 1 off the
/// top-left edges); the barycentric plane of vertex k over pixel indices
/// from (x0, y0) is (E_k(x0, y0), 256·a_k, 256·b_k)/area in f64 (E_k
/// without the fill-rule bias), and the depth plane Σ_k plane_k·z_k.
#[inline(always)]
pub fn setup_into(v: &[[f32; 2]; 3], s: &Snapped, t: &mut Tri) {
    let mut v = *v;
    if s.swap {
        v.swap(1, 2);
    }
    let (x, y, area) = (s.x, s.y, s.area);
    let [x0, _, y0, _] = s.bbox.map(i64::from);
    // Edge k runs from vertex k+1 to vertex k+2; E_k(P) = dx·(Py − ay) − dy·(Px − ax).
    let mut a = [0i64; 3];
    let mut b = [0i64; 3];
    let mut c = [0i64; 3];
    let mut biased = [false; 3];
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let (dx, dy) = (x[j] - x[i], y[j] - y[i]);
        a[k] = -dy;
        b[k] = dx;
        c[k] = dy * x[i] - dx * y[i];
        // Top-left rule (y down, interior where E ≥ 0): a top edge is
        // horizontal running right, a left edge runs up. Others need E > 0.
        let top_left = (dy == 0 && dx > 0) || dy < 0;
        biased[k] = !top_left;
        if !top_left {
            c[k] -= 1;
        }
    }
    // Depth and barycentric planes over pixel indices, relative to (x0, y0).
    let (ox, oy) = (x0 * ONE + HALF, y0 * ONE + HALF);
    let areaf = area as f64;
    let p: [[f64; 3]; 3] = std::array::from_fn(|k| {
        let e0 = (a[k] * ox + b[k] * oy + c[k] + i64::from(biased[k])) as f64;
        [
            e0 / areaf,
            (a[k] * ONE) as f64 / areaf,
            (b[k] * ONE) as f64 / areaf,
        ]
    });
    let z = v.map(|p| p[0] as f64);
    t.a = a.map(|a| a as i32);
    t.b = b.map(|b| b as i32);
    t.c = c;
    t.bbox = s.bbox;
    t.z = std::array::from_fn(|i| (p[0][i] * z[0] + p[1][i] * z[1] + p[2][i] * z[2]) as f32);
    t.l1 = p[1].map(|t| t as f32);
    t.l2 = p[2].map(|t| t as f32);
    t.inv_w = v.map(|p| p[1]);
}

impl Tri {
    /// Whether the pixel (i, j) is covered (exact, with the fill rule).
    pub fn covers(&self, i: u32, j: u32) -> bool {
        let (px, py) = (i as i64 * ONE + HALF, j as i64 * ONE + HALF);
        (0..3).all(|k| i64::from(self.a[k]) * px + i64::from(self.b[k]) * py + self.c[k] >= 0)
    }

    /// Screen barycentrics (λ0, λ1, λ2) at pixel (i, j).
    #[inline]
    pub fn lambda(&self, i: u32, j: u32) -> [f32; 3] {
        let (di, dj) = (
            i as f32 - self.bbox[0] as f32,
            j as f32 - self.bbox[2] as f32,
        );
        let l1 = self.l1[0] + self.l1[1] * di + self.l1[2] * dj;
        let l2 = self.l2[0] + self.l2[1] * di + self.l2[2] * dj;
        [1.0 - l1 - l2, l1, l2]
    }

    /// Perspective-correct weights at pixel (i, j): μk = (λk/wk) / Σ λm/wm
    /// (an attribute that is linear in eye space is Σ μk·ak).
    #[inline]
    pub fn mu(&self, i: u32, j: u32) -> [f32; 3] {
        let l = self.lambda(i, j);
        let q = [
            l[0] * self.inv_w[0],
            l[1] * self.inv_w[1],
            l[2] * self.inv_w[2],
        ];
        let s = q[0] + q[1] + q[2];
        if s != 0.0 {
            let r = 1.0 / s;
            [q[0] * r, q[1] * r, q[2] * r]
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
        let (di, dj) = (
            i as f32 - self.bbox[0] as f32,
            j as f32 - self.bbox[2] as f32,
        );
        let row = self.z[0] + self.z[2] * dj;
        row + self.z[1] * di
    }
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

/// Columns per block of the blocked raster loop.
const LANES: usize = 8;

/// Rasterizes one triangle into rows r0..=r1 of a band. The depth at
/// pixel (i, j) is [`Tri::depth`]: (z₀ + z_y·(j − y0)) + z_x·(i − x0), on
/// either path.
#[inline(always)]
fn raster_one(t: &Tri, id: u32, r0: u32, r1: u32, w: usize, dz: &mut [f32], ids: &mut [u32]) {
    let [x0, x1, y0, y1] = t.bbox;
    let (ya, yb) = (y0.max(r0), y1.min(r1));
    if ya > yb {
        return;
    }
    let blocks = ((x1 - x0 + 1) as usize).div_ceil(LANES);
    let reach = x0 as usize + blocks * LANES;
    let narrow = match Narrow::small(t, ya, blocks) {
        _ if reach > w => None,
        Some(n) => Some(n),
        None => Narrow::of_large(t, ya, yb, reach - 1),
    };
    match narrow {
        Some(n) => n.raster(t, id, (ya, yb), r0, w, dz, ids),
        None => raster_wide(t, id, ya..=yb, r0, w, dz, ids),
    }
}

/// Edges shorter than this in x and in y (1/256 pixel: 64 pixels) make a
/// triangle [`Narrow::small`].
const SMALL: u64 = 1 << 14;

/// The edge functions of a triangle whose every value over the pixels it
/// is drawn on (its rows, columns x0 up to whole blocks) fits in an i32,
/// kept in wrapping 32-bit arithmetic: a wrapped sum or product is exact
/// modulo 2³², so it is the true value whenever that fits.
#[derive(Debug, PartialEq)]
struct Narrow {
    /// E_k at the centre of pixel (x0, ya).
    e0: [i32; 3],
    /// E_k's step per row: 256·b_k.
    row: [i32; 3],
    /// E_k's step per column: 256·a_k.
    col: [i32; 3],
    /// Blocks per row.
    blocks: usize,
}

impl Narrow {
    /// `None` when some E_k leaves the i32 range on rows ya..=yb, columns
    /// x0..=xe. E_k is affine, so its extremes over that box are at the
    /// corners: E_k(x0, ya) plus none, one or both of 256·a_k·(xe − x0)
    /// and 256·b_k·(yb − ya).
    #[inline(always)]
    fn of(t: &Tri, ya: u32, yb: u32, xe: usize) -> Option<Narrow> {
        let x0 = t.bbox[0] as i64;
        let (di, dj) = (xe as i64 - x0, (yb - ya) as i64);
        let e0: [i64; 3] = std::array::from_fn(|k| edge(t, k, x0, ya as i64));
        // v fits in an i32 exactly when it equals its low 32 bits sign-extended.
        let mut outside = 0;
        for (k, &e) in e0.iter().enumerate() {
            let (s, r) = (i64::from(t.a[k]) * ONE * di, i64::from(t.b[k]) * ONE * dj);
            for v in [e, e + s, e + r, e + s + r] {
                outside |= v ^ i64::from(v as i32);
            }
        }
        if outside != 0 {
            return None;
        }
        Some(Narrow {
            e0: e0.map(|e| e as i32),
            row: t.b.map(|b| (i64::from(b) * ONE) as i32),
            col: t.a.map(|a| (i64::from(a) * ONE) as i32),
            blocks: (di as usize + 1) / LANES,
        })
    }

    /// [`Narrow::of`] kept out of line: the rare triangle that is not
    /// [`Narrow::small`].
    #[cold]
    #[inline(never)]
    fn of_large(t: &Tri, ya: u32, yb: u32, xe: usize) -> Option<Narrow> {
        Narrow::of(t, ya, yb, xe)
    }

    /// [`Narrow::of`] without its range test, for a triangle drawn from
    /// row ya in `blocks` blocks whose edges span less than 2¹⁴ (64 pixels)
    /// in x and in y: every |a_k|, |b_k| < 2¹⁴; `None` for any other.
    ///
    /// Why every E_k fits in an i32: the triangle's vertices span X < 2¹⁴
    /// in x and Y < 2¹⁴ in y, and the box's first and last pixel centres
    /// lie within that span (the box holds only centres between the
    /// vertices' extremes), so a drawn centre P (columns up to 7 past the
    /// box, rows inside it) is within X + 7·256 in x and Y in y of any
    /// vertex V. With V on edge k, E_k(P) = a_k·(Px − Vx) + b_k·(Py − Vy)
    /// (− 1 for the fill rule), |a_k| ≤ Y and |b_k| ≤ X, so |E_k| ≤
    /// Y·(X + 1792) + X·Y + 1 < 2²⁸ + 2²⁵ + 2²⁸ + 1 < 2³¹. Then E_k(x0, ya)
    /// computed in wrapping i32 (exact modulo 2³²) is the true value.
    #[inline(always)]
    fn small(t: &Tri, ya: u32, blocks: usize) -> Option<Narrow> {
        let span = (0..3).fold(0, |m, k| {
            m | u64::from(t.a[k].unsigned_abs() | t.b[k].unsigned_abs())
        });
        if span >= SMALL {
            return None;
        }
        // Pixel centres in 1/256 pixel: below 2²² (the image is at most
        // 8192 pixels a side).
        let (px, py) = (
            (t.bbox[0] as i32) * ONE as i32 + HALF as i32,
            (ya as i32) * ONE as i32 + HALF as i32,
        );
        let e0 = std::array::from_fn(|k| {
            let (a, b, c) = (t.a[k], t.b[k], t.c[k] as i32);
            a.wrapping_mul(px)
                .wrapping_add(b.wrapping_mul(py))
                .wrapping_add(c)
        });
        Some(Narrow {
            e0,
            row: t.b.map(|b| (i64::from(b) * ONE) as i32),
            col: t.a.map(|a| (i64::from(a) * ONE) as i32),
            blocks,
        })
    }

    /// Draws rows ya..=yb in blocks of `LANES` columns without branches per
    /// pixel: every column of a block is tested (coverage, strictly
    /// nearer) and the drawn ones written. A covered column is inside the
    /// box (the triangle is), and the caller keeps the blocks inside the
    /// image, so coverage needs no column test.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn raster(
        &self,
        t: &Tri,
        id: u32,
        (ya, yb): (u32, u32),
        r0: u32,
        w: usize,
        dz: &mut [f32],
        ids: &mut [u32],
    ) {
        // The common widths get their own copy of the loop, the blocks
        // unrolled.
        match self.blocks {
            1 => self.rows(t, id, (ya, yb), r0, w, dz, ids, 1),
            2 => self.rows(t, id, (ya, yb), r0, w, dz, ids, 2),
            n => self.rows(t, id, (ya, yb), r0, w, dz, ids, n),
        }
    }

    /// [`Narrow::raster`] with `blocks` blocks per row. At column
    /// i = x0 + q and row j: E_k = E_k(x0, ya) + 256·a_k·q + 256·b_k·(j − ya)
    /// and z = (z₀ + z_y·(j − y0)) + z_x·q.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn rows(
        &self,
        t: &Tri,
        id: u32,
        (ya, yb): (u32, u32),
        r0: u32,
        w: usize,
        dz: &mut [f32],
        ids: &mut [u32],
        blocks: usize,
    ) {
        const COLUMN: [i32; LANES] = [0, 1, 2, 3, 4, 5, 6, 7];
        let [x0, _, y0, _] = t.bbox;
        let [z0, zx, zy] = t.z;
        let n = blocks * LANES;
        // E_k at the columns of the row's first block, starting at row ya.
        let mut er = [[0i32; LANES]; 3];
        for (er, (e0, s)) in er.iter_mut().zip(self.e0.into_iter().zip(self.col)) {
            // (`black_box`: multiplied by an opaque vector, the lanes take
            // one vector multiply; by the known constants, LLVM emits a
            // longer mix of shifts, multiplies and permutes.)
            for (e, c) in er.iter_mut().zip(std::hint::black_box(COLUMN)) {
                *e = e0.wrapping_add(s.wrapping_mul(c));
            }
        }
        let block = self.col.map(|s| s.wrapping_mul(LANES as i32));
        // Rows ya..=yb from column x0: one row is w pixels on, row r of
        // the span starts at r·w and needs n pixels.
        let start = (ya - r0) as usize * w + x0 as usize;
        let end = (yb - r0) as usize * w + x0 as usize + n;
        let (dspan, ispan) = (&mut dz[start..end], &mut ids[start..end]);
        // j − y0 counted in f32: exact (image sizes are far below 2²⁴).
        let mut dj = (ya - y0) as f32;
        for r in 0..(yb - ya + 1) as usize {
            let zr = z0 + zy * dj;
            let o = r * w;
            let (drow, irow) = (&mut dspan[o..o + n], &mut ispan[o..o + n]);
            let mut e = er;
            for (b, (d, ib)) in drow
                .chunks_exact_mut(LANES)
                .zip(irow.chunks_exact_mut(LANES))
                .enumerate()
            {
                let d: &mut [f32; LANES] = d.try_into().expect("a block of LANES");
                let ib: &mut [u32; LANES] = ib.try_into().expect("a block of LANES");
                // Negative where the pixel is drawn: every E_k ≥ 0 (sign
                // bits clear) and strictly nearer. Masks and selects, not
                // branches, so the block vectorizes (into masked stores)
                // and overdraw costs no mispredictions.
                let mut m = [0i32; LANES];
                let mut z = [0.0f32; LANES];
                for c in 0..LANES {
                    z[c] = zr + zx * (b * LANES + c) as f32;
                    m[c] = !(e[0][c] | e[1][c] | e[2][c]) & -i32::from(z[c] < d[c]);
                }
                for c in 0..LANES {
                    let s = (m[c] >> 31) as u32;
                    d[c] = f32::from_bits((z[c].to_bits() & s) | (d[c].to_bits() & !s));
                    ib[c] = (id & s) | (ib[c] & !s);
                }
                step(&mut e, block);
            }
            step(&mut er, self.row);
            dj += 1.0;
        }
    }
}

/// Adds s_k to every lane of E_k (wrapping).
#[inline(always)]
fn step(e: &mut [[i32; LANES]; 3], s: [i32; 3]) {
    for (e, s) in e.iter_mut().zip(s) {
        for e in e {
            *e = e.wrapping_add(s);
        }
    }
}

/// E_k at the centre of pixel (i, j): a_k·(256·i + 128) + b_k·(256·j + 128) + c_k.
#[inline]
fn edge(t: &Tri, k: usize, i: i64, j: i64) -> i64 {
    i64::from(t.a[k]) * (i * ONE + HALF) + i64::from(t.b[k]) * (j * ONE + HALF) + t.c[k]
}

/// The general path: every pixel of the box, edge functions in i64.
#[allow(clippy::too_many_arguments)]
fn raster_wide(
    t: &Tri,
    id: u32,
    rows: std::ops::RangeInclusive<u32>,
    r0: u32,
    w: usize,
    dz: &mut [f32],
    ids: &mut [u32],
) {
    let [x0, x1, y0, _] = t.bbox;
    let step = t.a.map(|a| i64::from(a) * ONE);
    for j in rows {
        let mut e = [0, 1, 2].map(|k| edge(t, k, x0 as i64, j as i64));
        let zr = t.z[0] + t.z[2] * (j - y0) as f32;
        let row = (j - r0) as usize * w;
        let (drow, irow) = (&mut dz[row..row + w], &mut ids[row..row + w]);
        for i in x0 as usize..=x1 as usize {
            let z = zr + t.z[1] * (i - x0 as usize) as f32;
            if (e[0] | e[1] | e[2]) >= 0 && z < drow[i] {
                drow[i] = z;
                irow[i] = id;
            }
            e[0] += step[0];
            e[1] += step[1];
            e[2] += step[2];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        // triangle is touched.
        let (w, h) = (301u32, 70u32);
        let tris = random_tris(7, 600, w, h);
        // Triangles drawn by the general path, and by the blocked one with
        // 1, 2 and more blocks per row; of the blocked, how many small.
        let mut kinds = [0usize; 5];
        for (n, t) in tris.iter().enumerate() {
            let blocks = (t.bbox[1] - t.bbox[0]) as usize / LANES + 1;
            let reach = t.bbox[0] as usize + blocks * LANES;
            let narrow =
                reach <= w as usize && Narrow::of(t, t.bbox[2], t.bbox[3], reach - 1).is_some();
            kinds[if narrow { blocks.min(3) } else { 0 }] += 1;
            kinds[4] += usize::from(narrow && Narrow::small(t, t.bbox[2], blocks).is_some());
            for pass in PASSES {
                for r0 in (0..h).step_by(BAND) {
                    let rows = (BAND as u32).min(h - r0);
                    let mut dz = vec![0.0f32; (rows * w) as usize];
                    let mut id = vec![0u32; (rows * w) as usize];
                    pass(
                        std::slice::from_ref(t),
                        &[0],
                        r0,
                        w as usize,
                        &mut dz,
                        &mut id,
                    );
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
        assert!(kinds.iter().all(|&k| k > 20), "{kinds:?}");
        assert!(kinds[1] + kinds[2] + kinds[3] - kinds[4] > 20, "{kinds:?}");
    }

    #[test]
    fn a_small_triangle_gets_the_checked_edge_functions() {
        // `Narrow::small` skips the range test of `Narrow::of` on the
        // strength of the triangle's size: wherever it accepts a triangle,
        // from any of its rows, `of` must accept it too and give the same
        // edge values and steps.
        let (w, h) = (301u32, 70u32);
        let mut small = 0;
        for t in random_tris(5, 3000, w, h) {
            let blocks = (t.bbox[1] - t.bbox[0]) as usize / LANES + 1;
            let reach = t.bbox[0] as usize + blocks * LANES;
            for ya in t.bbox[2]..=t.bbox[3] {
                if let Some(n) = Narrow::small(&t, ya, blocks) {
                    assert_eq!(Some(n), Narrow::of(&t, ya, t.bbox[3], reach - 1), "{t:?}");
                    small += 1;
                }
            }
        }
        assert!(small > 1000, "{small}");
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
