//! [`Avx16`]: sixteen f32 lanes in one 512-bit AVX-512 register, the lane
//! type of the band pass compiled for AVX-512 (`shade_band_avx512`).
//!
//! It is [`super::avx::Avx8`] twice as wide: the same lane operations (IEEE
//! add, multiply, divide and square root, correctly rounded in every lane;
//! the same min/max/compare/select rules), so a batch lit at `Avx16` gives
//! the same bits as at `Avx8`, `F32x8` and `Fast32`, lane by lane (tested in
//! `shade::tests`). Sixteen pixels per lighting call halve the lighting's
//! instructions per pixel; division and square root cost the same per lane
//! as in 256-bit registers, though, so the shading of the reference sphere
//! gains about 8 % of its time, not half.
//!
//! **Why this is sound.** Every operation of `Avx16` executes AVX-512F
//! instructions (and the byte shuffles SSSE3 ones), which a CPU without
//! them cannot run. The type is visible only to its parent module,
//! `render::shade`, and that module uses it in one place:
//! `shade_band_avx512`, a function compiled for AVX-512F and AVX2 and
//! called only after `is_x86_feature_detected!` said yes to both (and the
//! tests, which call it the same way). So every `Avx16` value is made, and
//! every operation on one runs, on a CPU with AVX-512F. Keep it that way:
//! never make this type more visible, and never use it outside
//! `shade_band_avx512`.

crate::num::lanes::lane_type!(
    /// Sixteen f32 lanes in an AVX-512 register (see the module
    /// documentation: only for code reached through `shade_band_avx512`).
    pub Avx16,
    Avx16Mask,
    imp,
    16
);

/// The lane operations over AVX-512F.
mod imp {
    use std::arch::x86_64::*;

    /// Calls AVX-512F (and AVX, SSSE3) intrinsics.
    macro_rules! avx512 {
        ($e:expr) => {
            // SAFETY: only code reached through `shade_band_avx512`
            // operates on `Avx16` (see the module documentation), and that
            // code runs only on a CPU with AVX-512F and AVX2 (which implies
            // AVX and SSSE3); the intrinsics take and return plain values.
            unsafe { $e }
        };
    }

    /// Sixteen f32.
    #[derive(Clone, Copy, Debug)]
    pub struct V(__m512);
    /// Sixteen lane masks, bit k for lane k.
    #[derive(Clone, Copy, Debug)]
    pub struct M(__mmask16);

    #[inline(always)]
    pub fn from_array(a: [f32; 16]) -> V {
        // The load reads sixteen f32 from an array of sixteen (unaligned
        // loads need no alignment).
        avx512!(V(_mm512_loadu_ps(a.as_ptr())))
    }
    #[inline(always)]
    pub fn to_array(v: V) -> [f32; 16] {
        let mut a = [0.0f32; 16];
        // The store writes sixteen f32 into an array of sixteen.
        avx512!(_mm512_storeu_ps(a.as_mut_ptr(), v.0));
        a
    }
    #[inline(always)]
    pub fn splat(x: f32) -> V {
        avx512!(V(_mm512_set1_ps(x)))
    }
    #[inline(always)]
    pub fn add(a: V, b: V) -> V {
        avx512!(V(_mm512_add_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn sub(a: V, b: V) -> V {
        avx512!(V(_mm512_sub_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn mul(a: V, b: V) -> V {
        avx512!(V(_mm512_mul_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn div(a: V, b: V) -> V {
        avx512!(V(_mm512_div_ps(a.0, b.0)))
    }
    #[inline(always)]
    pub fn sqrt(a: V) -> V {
        avx512!(V(_mm512_sqrt_ps(a.0)))
    }
    /// −a (the sign bit flipped, as f32 negation does).
    #[inline(always)]
    pub fn neg(a: V) -> V {
        avx512!(V(_mm512_castsi512_ps(_mm512_xor_si512(
            _mm512_castps_si512(a.0),
            _mm512_set1_epi32(i32::MIN),
        ))))
    }
    /// |a| (the sign bit cleared).
    #[inline(always)]
    pub fn abs(a: V) -> V {
        avx512!(V(_mm512_abs_ps(a.0)))
    }
    /// a > b ? a : b per lane (VMAXPS, as MAXPS: b when either is NaN or
    /// both are zeros).
    #[inline(always)]
    pub fn max(a: V, b: V) -> V {
        avx512!(V(_mm512_max_ps(a.0, b.0)))
    }
    /// a > b ? b : a per lane, that is b < a ? b : a (VMINPS of b, a).
    #[inline(always)]
    pub fn min(a: V, b: V) -> V {
        avx512!(V(_mm512_min_ps(b.0, a.0)))
    }
    /// a > b, ordered (false for NaN).
    #[inline(always)]
    pub fn gt(a: V, b: V) -> M {
        avx512!(M(_mm512_cmp_ps_mask::<_CMP_GT_OS>(a.0, b.0)))
    }
    /// a < b, ordered.
    #[inline(always)]
    pub fn lt(a: V, b: V) -> M {
        avx512!(M(_mm512_cmp_ps_mask::<_CMP_LT_OS>(a.0, b.0)))
    }
    /// a == b, ordered.
    #[inline(always)]
    pub fn eq(a: V, b: V) -> M {
        avx512!(M(_mm512_cmp_ps_mask::<_CMP_EQ_OQ>(a.0, b.0)))
    }
    /// a where m, else b.
    #[inline(always)]
    pub fn select(m: M, a: V, b: V) -> V {
        // The blend takes its second operand where the mask bit is set.
        avx512!(V(_mm512_mask_blend_ps(m.0, b.0, a.0)))
    }
    /// Byte k of output chunk `chunk` (of three 16-byte chunks of r g b
    /// interleaved) when it belongs to channel `ch`: the pixel's index in
    /// that channel's bytes; else −128 (a shuffle writes zero there).
    const fn order(chunk: usize, ch: usize) -> [i8; 16] {
        let mut t = [-128i8; 16];
        let mut k = 0;
        while k < 16 {
            let o = 16 * chunk + k;
            if o % 3 == ch {
                t[k] = (o / 3) as i8;
            }
            k += 1;
        }
        t
    }
    /// The shuffles of [`rgb_bytes`]: per output chunk, per channel.
    const ORDER: [[[i8; 16]; 3]; 3] = {
        let mut t = [[[0i8; 16]; 3]; 3];
        let mut m = 0;
        while m < 3 {
            let mut c = 0;
            while c < 3 {
                t[m][c] = order(m, c);
                c += 1;
            }
            m += 1;
        }
        t
    };
    /// Three channels' bytes interleaved, r0 g0 b0 r1 …, each lane `x as
    /// u8`: clamped to [0, 255] first (max(x, 0) is 0 for NaN, as the cast
    /// gives), so that truncation to i32 is the cast, then the low byte of
    /// each (VPMOVDB), and the three channels' sixteen bytes shuffled into
    /// pixel order.
    #[inline(always)]
    pub fn rgb_bytes(r: V, g: V, b: V) -> [u8; 48] {
        let mut out = [0u8; 48];
        avx512!({
            let bytes = |v: V| {
                let v = max(v, splat(0.0));
                let v = _mm512_min_ps(v.0, _mm512_set1_ps(255.0));
                _mm512_cvtepi32_epi8(_mm512_cvttps_epi32(v))
            };
            let ch = [bytes(r), bytes(g), bytes(b)];
            for (m, chunk) in out.chunks_exact_mut(16).enumerate() {
                // The loads read sixteen i8 from a table of sixteen.
                let pick = |c: usize| {
                    _mm_shuffle_epi8(ch[c], _mm_loadu_si128(ORDER[m][c].as_ptr().cast()))
                };
                let px = _mm_or_si128(_mm_or_si128(pick(0), pick(1)), pick(2));
                // The store writes sixteen bytes into a chunk of sixteen.
                _mm_storeu_si128(chunk.as_mut_ptr().cast(), px);
            }
        });
        out
    }
    /// Bit k set when lane k is true.
    #[inline(always)]
    pub fn bits(m: M) -> u32 {
        u32::from(m.0)
    }
    #[inline(always)]
    pub fn mask_from(b: [bool; 16]) -> M {
        M((0..16).fold(0, |m, k| m | u16::from(b[k]) << k))
    }
    /// Columns 0–7 of sixteen rows of twelve as lanes (lane k of result a
    /// is `q[k][a]`): the 8 × 8 transposes of rows 0–7 and of rows 8–15 in
    /// 256-bit registers, then each pair of halves joined. (Each row is read
    /// by a load of the 32 bytes that `fill8` stored, which the CPU forwards
    /// from the store; one 64-byte load across two such stores would wait
    /// for them to reach the cache.)
    #[inline(always)]
    pub fn transpose8(q: &[[f32; 12]; 16]) -> [V; 8] {
        // The loads read eight f32 from a row of twelve.
        let rows = |k0: usize| -> [__m256; 8] {
            std::array::from_fn(|k| avx512!(_mm256_loadu_ps(q[k0 + k].as_ptr())))
        };
        // SAFETY: as for `avx512!`: this runs only on a CPU with AVX-512F
        // and AVX2.
        let (lo, hi) = unsafe {
            (
                super::super::avx::transpose8x8(rows(0)),
                super::super::avx::transpose8x8(rows(8)),
            )
        };
        std::array::from_fn(|a| {
            avx512!(V(_mm512_castpd_ps(_mm512_insertf64x4::<1>(
                _mm512_castpd256_pd512(_mm256_castps_pd(lo[a])),
                _mm256_castps_pd(hi[a]),
            ))))
        })
    }
    /// Columns 8–11 of sixteen rows of twelve as lanes, entry by entry (the
    /// colour planes, read only for objects whose colour varies).
    #[inline(always)]
    pub fn transpose_tail(q: &[[f32; 12]; 16]) -> [V; 4] {
        std::array::from_fn(|a| from_array(std::array::from_fn(|k| q[k][8 + a])))
    }
}
