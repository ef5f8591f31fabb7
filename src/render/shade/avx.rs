//! [`Avx8`]: eight f32 lanes in one 256-bit AVX register, the lane type of
//! the band pass compiled for AVX2 (`shade_band_avx2`).
//!
//! It is [`crate::num::F32x8`] over AVX instead of SSE: the same lane
//! operations (IEEE add, multiply, divide and square root, correctly
//! rounded in every lane; the same min/max/compare/select rules), so a
//! batch lit at `Avx8` gives the same bits as at `F32x8` and at `Fast32`
//! lane by lane (tested in `shade::tests`). One register per value instead
//! of two halves the instructions and lets the lighting's working set
//! (normal, position, view and light vectors) stay in registers.
//!
//! **Why this is sound.** Every operation of `Avx8` executes AVX
//! instructions, which a CPU without AVX cannot run. The type is visible
//! only to its parent module, `render::shade`, and that module uses it in
//! one place: `shade_band_avx2`, a function compiled for AVX2 and called
//! only after `is_x86_feature_detected!("avx2")` said yes. So every `Avx8`
//! value is made, and every operation on one runs, on a CPU with AVX2.
//! Keep it that way: never make this type more visible, and never use it
//! outside `shade_band_avx2`.
//!
//! The one item the module shares is [`transpose8x8`], an `unsafe fn` of
//! plain registers whose caller promises AVX: the AVX-512 band pass
//! (`super::avx512`) transposes its two halves with it.

crate::num::lanes::lane_type!(
    /// Eight f32 lanes in an AVX register (see the module documentation:
    /// only for code reached through `shade_band_avx2`).
    pub Avx8,
    AvxMask,
    imp,
    8
);

/// The 8 × 8 transpose of eight registers of eight f32 (lane k of result
/// a is lane a of `r[k]`), by shuffles: pairs of rows interleaved, then
/// quadruples, then the 128-bit halves swapped.
///
/// # Safety
///
/// The CPU must have AVX.
#[inline(always)]
pub(super) unsafe fn transpose8x8(
    r: [std::arch::x86_64::__m256; 8],
) -> [std::arch::x86_64::__m256; 8] {
    use std::arch::x86_64::*;
    let [r0, r1, r2, r3, r4, r5, r6, r7] = r;
    // SAFETY: the caller guarantees AVX; the intrinsics take and return
    // plain values.
    unsafe {
        // t: (a0 b0 a1 b1 | a4 b4 a5 b5) and (a2 b2 a3 b3 | a6 b6 a7 b7).
        let (t0, t1) = (_mm256_unpacklo_ps(r0, r1), _mm256_unpackhi_ps(r0, r1));
        let (t2, t3) = (_mm256_unpacklo_ps(r2, r3), _mm256_unpackhi_ps(r2, r3));
        let (t4, t5) = (_mm256_unpacklo_ps(r4, r5), _mm256_unpackhi_ps(r4, r5));
        let (t6, t7) = (_mm256_unpacklo_ps(r6, r7), _mm256_unpackhi_ps(r6, r7));
        // u: column c of rows 0–3 (or 4–7) | column c + 4.
        let u0 = _mm256_shuffle_ps::<0x44>(t0, t2);
        let u1 = _mm256_shuffle_ps::<0xee>(t0, t2);
        let u2 = _mm256_shuffle_ps::<0x44>(t1, t3);
        let u3 = _mm256_shuffle_ps::<0xee>(t1, t3);
        let u4 = _mm256_shuffle_ps::<0x44>(t4, t6);
        let u5 = _mm256_shuffle_ps::<0xee>(t4, t6);
        let u6 = _mm256_shuffle_ps::<0x44>(t5, t7);
        let u7 = _mm256_shuffle_ps::<0xee>(t5, t7);
        let lo = |a, b| _mm256_permute2f128_ps::<0x20>(a, b);
        let hi = |a, b| _mm256_permute2f128_ps::<0x31>(a, b);
        [
            lo(u0, u4),
            lo(u1, u5),
            lo(u2, u6),
            lo(u3, u7),
            hi(u0, u4),
            hi(u1, u5),
            hi(u2, u6),
            hi(u3, u7),
        ]
    }
}

/// The lane operations over AVX.
mod imp {
    use std::arch::x86_64::*;

    /// Calls AVX intrinsics.
    macro_rules! avx {
        ($e:expr) => {
            // SAFETY: only code reached through `shade_band_avx2` operates
            // on `Avx8` (see the module documentation), and that code runs
            // only on a CPU with AVX2, so AVX is there; the intrinsics take
            // and return plain values.
            unsafe { $e }
        };
    }

    /// Eight f32.
    #[derive(Clone, Copy, Debug)]
    pub struct V(__m256);
    /// Eight lane masks (all ones or zero), as f32 bit patterns.
    #[derive(Clone, Copy, Debug)]
    pub struct M(__m256);

    #[inline(always)]
    pub fn from_array(a: [f32; 8]) -> V {
        // The load reads eight f32 from an array of eight (unaligned loads
        // need no alignment).
        avx!(V(_mm256_loadu_ps(a.as_ptr())))
    }
    #[inline(always)]
    pub fn to_array(v: V) -> [f32; 8] {
        let mut a = [0.0f32; 8];
        // The store writes eight f32 into an array of eight.
        avx!(_mm256_storeu_ps(a.as_mut_ptr(), v.0));
        a
    }
    #[inline(always)]
    pub fn splat(x: f32) -> V {
        avx!(V(_mm256_set1_ps(x)))
    }
    #[inline(always)]
    pub fn add(a: V, b: V) -> V {
        avx!(V(_mm256_add_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn sub(a: V, b: V) -> V {
        avx!(V(_mm256_sub_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn mul(a: V, b: V) -> V {
        avx!(V(_mm256_mul_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn div(a: V, b: V) -> V {
        avx!(V(_mm256_div_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn sqrt(a: V) -> V {
        avx!(V(_mm256_sqrt_ps(a.0)))
    }
    /// −a (the sign bit flipped, as f32 negation does).
    #[inline(always)]
    pub fn neg(a: V) -> V {
        avx!(V(_mm256_xor_ps(a.0, _mm256_set1_ps(-0.0))))
    }
    /// |a| (the sign bit cleared).
    #[inline(always)]
    pub fn abs(a: V) -> V {
        avx!(V(_mm256_andnot_ps(_mm256_set1_ps(-0.0), a.0)))
    }
    /// a > b ? a : b per lane (VMAXPS is exactly this, as MAXPS).
    #[inline(always)]
    pub fn max(a: V, b: V) -> V {
        avx!(V(_mm256_max_ps(a.0, b.0)))
    }
    /// a > b ? b : a per lane, that is b < a ? b : a (VMINPS of b, a).
    #[inline(always)]
    pub fn min(a: V, b: V) -> V {
        avx!(V(_mm256_min_ps(b.0, a.0)))
    }
    /// a > b, ordered (false for NaN), as SSE's CMPGTPS.
    #[inline(always)]
    pub fn gt(a: V, b: V) -> M {
        avx!(M(_mm256_cmp_ps::<_CMP_GT_OS>(a.0, b.0)))
    }
    /// a < b, ordered.
    #[inline(always)]
    pub fn lt(a: V, b: V) -> M {
        avx!(M(_mm256_cmp_ps::<_CMP_LT_OS>(a.0, b.0)))
    }
    /// a == b, ordered.
    #[inline(always)]
    pub fn eq(a: V, b: V) -> M {
        avx!(M(_mm256_cmp_ps::<_CMP_EQ_OQ>(a.0, b.0)))
    }
    /// a where m, else b (m is all ones or zero per lane).
    #[inline(always)]
    pub fn select(m: M, a: V, b: V) -> V {
        avx!(V(_mm256_blendv_ps(b.0, a.0, m.0)))
    }
    /// Three channels' bytes interleaved, r0 g0 b0 r1 …, each lane `x as
    /// u8`: clamped to [0, 255] first (max(x, 0) is 0 for NaN, as the cast
    /// gives), so that truncation to i32 is the cast, packed to bytes (with
    /// saturation, which then changes nothing) and shuffled into pixel
    /// order.
    #[inline(always)]
    pub fn rgb_bytes(r: V, g: V, b: V) -> [u8; 24] {
        let clamp = |v: V| avx!(_mm256_min_ps(max(v, splat(0.0)).0, _mm256_set1_ps(255.0)));
        let (r, g, b) = (V(clamp(r)), V(clamp(g)), V(clamp(b)));
        let mut out = [0u8; 32];
        avx!({
            let (ri, gi, bi) = (
                _mm256_cvttps_epi32(r.0),
                _mm256_cvttps_epi32(g.0),
                _mm256_cvttps_epi32(b.0),
            );
            // Per 128-bit half h (pixels 4h … 4h + 3): r, g, b, b as bytes.
            let rg = _mm256_packs_epi32(ri, gi);
            let bb = _mm256_packs_epi32(bi, bi);
            let bytes = _mm256_packus_epi16(rg, bb);
            // Within each half: r0 g0 b0 r1 g1 b1 r2 g2 b2 r3 g3 b3, then 4 spare.
            let order = _mm256_setr_epi8(
                0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11, -1, -1, -1, -1, //
                0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11, -1, -1, -1, -1,
            );
            let px = _mm256_shuffle_epi8(bytes, order);
            // The two halves' twelve bytes side by side.
            let px = _mm256_permutevar8x32_epi32(px, _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 7));
            // The store writes 32 bytes into an array of 32.
            _mm256_storeu_si256(out.as_mut_ptr().cast(), px);
        });
        let mut rgb = [0u8; 24];
        rgb.copy_from_slice(&out[..24]);
        rgb
    }
    /// Bit k set when lane k is true.
    #[inline(always)]
    pub fn bits(m: M) -> u32 {
        avx!(_mm256_movemask_ps(m.0)) as u32
    }
    #[inline(always)]
    pub fn mask_from(b: [bool; 8]) -> M {
        let t = |x: bool| f32::from_bits((x as u32).wrapping_neg());
        M(from_array(b.map(t)).0)
    }
    /// Columns 0–7 of eight rows of twelve as lanes (lane k of result a
    /// is `q[k][a]`), by [`super::transpose8x8`].
    #[inline(always)]
    pub fn transpose8(q: &[[f32; 12]; 8]) -> [V; 8] {
        // The loads read eight f32 from a row of twelve (unaligned loads
        // need no alignment).
        let rows = q.map(|row| avx!(_mm256_loadu_ps(row.as_ptr())));
        // SAFETY: as for `avx!`: this runs only on a CPU with AVX2.
        unsafe { super::transpose8x8(rows) }.map(V)
    }
    /// Columns 8–11 of eight rows of twelve as lanes, by two 4 × 4
    /// transposes side by side (rows k and k + 4 in the two halves of one
    /// register).
    #[inline(always)]
    pub fn transpose_tail(q: &[[f32; 12]; 8]) -> [V; 4] {
        avx!({
            // The loads read four f32 from the last four of a row of twelve.
            let s = |k: usize| {
                _mm256_set_m128(
                    _mm_loadu_ps(q[k + 4][8..].as_ptr()),
                    _mm_loadu_ps(q[k][8..].as_ptr()),
                )
            };
            let (s0, s1, s2, s3) = (s(0), s(1), s(2), s(3));
            let (v0, v1) = (_mm256_unpacklo_ps(s0, s1), _mm256_unpackhi_ps(s0, s1));
            let (v2, v3) = (_mm256_unpacklo_ps(s2, s3), _mm256_unpackhi_ps(s2, s3));
            [
                V(_mm256_shuffle_ps::<0x44>(v0, v2)),
                V(_mm256_shuffle_ps::<0xee>(v0, v2)),
                V(_mm256_shuffle_ps::<0x44>(v1, v3)),
                V(_mm256_shuffle_ps::<0xee>(v1, v3)),
            ]
        })
    }
}
