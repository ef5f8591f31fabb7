//! [`F32x8`]: eight f32 lanes, the renderer's batch scalar.
//!
//! The Phong renderer lights eight pixels at once by calling the
//! calculator's own `lighting::shade_color` with this type: every operator
//! and method works lane by lane with the same plain f32 operation as
//! [`super::Fast32`], so lane k of a result is bit for bit what `Fast32`
//! gives for lane k's inputs (IEEE add, multiply, divide and square root
//! are correctly rounded in vector registers too). On x86-64 the lanes
//! live in two SSE registers (the operations are `core::arch` intrinsics,
//! so the compiler keeps them packed instead of splitting them into eight
//! scalars); elsewhere they are an array processed lane by lane.
//!
//! **Comparisons mean "in every lane".** `a > b` is true when every lane of
//! `a` is greater; `partial_cmp` is `None` when the lanes disagree. The
//! lighting code uses comparisons only as shortcuts that are right when
//! every lane agrees (a light out of range of the whole batch is skipped);
//! where lanes may differ it uses [`Scalar::if_gt`], which this type
//! evaluates per lane, running each branch only when some lane takes it.
//!
//! **One definition, several backends.** The type is written once, as the
//! macro `lane_type!` over a module of lane operations and a lane count.
//! `F32x8` is it over SSE (or the array); the renderer's band pass defines
//! two more instances for the copies of the pass it compiles for newer
//! CPUs: over AVX (`render::shade::avx::Avx8`, eight lanes in one 256-bit
//! register) for AVX2, and over AVX-512 (`render::shade::avx512::Avx16`,
//! sixteen lanes in one 512-bit register). The [`Wide`] trait is what that
//! pass asks of any of them.
//!
//! **Reading a number out** (`to_f64`, `to_real`, `shown`) gives lane 0: a
//! batch is never reported, only turned into pixels.

/// The lane operations on x86-64: two SSE registers (SSE and SSE2 are part
/// of the x86-64 baseline, so the intrinsics are safe to call).
#[cfg(target_arch = "x86_64")]
mod imp {
    use std::arch::x86_64::*;

    /// Calls SSE/SSE2 intrinsics.
    macro_rules! sse {
        ($e:expr) => {
            // SAFETY: SSE and SSE2 are part of the x86-64 baseline, so
            // every CPU this code runs on has them (the only requirement of
            // these intrinsics, which take and return plain values).
            unsafe { $e }
        };
    }

    /// Eight f32.
    #[derive(Clone, Copy, Debug)]
    pub struct V(__m128, __m128);
    /// Eight lane masks (all ones or zero), as f32 bit patterns.
    #[derive(Clone, Copy, Debug)]
    pub struct M(__m128, __m128);

    macro_rules! two {
        ($f:ident, $a:expr, $b:expr) => {
            sse!(V($f($a.0, $b.0), $f($a.1, $b.1)))
        };
    }

    #[inline(always)]
    pub fn from_array(a: [f32; 8]) -> V {
        sse!(V(
            _mm_set_ps(a[3], a[2], a[1], a[0]),
            _mm_set_ps(a[7], a[6], a[5], a[4]),
        ))
    }
    #[inline(always)]
    pub fn to_array(v: V) -> [f32; 8] {
        let mut a = [0.0f32; 8];
        let (lo, hi) = a.split_at_mut(4);
        // SAFETY: each store writes four f32 into a slice of four f32
        // (unaligned stores need no alignment), and SSE is baseline.
        unsafe {
            _mm_storeu_ps(lo.as_mut_ptr(), v.0);
            _mm_storeu_ps(hi.as_mut_ptr(), v.1);
        }
        a
    }
    #[inline(always)]
    pub fn splat(x: f32) -> V {
        sse!(V(_mm_set1_ps(x), _mm_set1_ps(x)))
    }
    #[inline(always)]
    pub fn add(a: V, b: V) -> V {
        two!(_mm_add_ps, a, b)
    }
    #[inline(always)]
    pub fn sub(a: V, b: V) -> V {
        two!(_mm_sub_ps, a, b)
    }
    #[inline(always)]
    pub fn mul(a: V, b: V) -> V {
        two!(_mm_mul_ps, a, b)
    }
    #[inline(always)]
    pub fn div(a: V, b: V) -> V {
        two!(_mm_div_ps, a, b)
    }
    #[inline(always)]
    pub fn sqrt(a: V) -> V {
        sse!(V(_mm_sqrt_ps(a.0), _mm_sqrt_ps(a.1)))
    }
    /// −a (the sign bit flipped, as f32 negation does).
    #[inline(always)]
    pub fn neg(a: V) -> V {
        sse!({
            let s = _mm_set1_ps(-0.0);
            V(_mm_xor_ps(a.0, s), _mm_xor_ps(a.1, s))
        })
    }
    /// |a| (the sign bit cleared).
    #[inline(always)]
    pub fn abs(a: V) -> V {
        sse!({
            let s = _mm_set1_ps(-0.0);
            V(_mm_andnot_ps(s, a.0), _mm_andnot_ps(s, a.1))
        })
    }
    /// a > b ? a : b per lane (MAXPS is exactly this).
    #[inline(always)]
    pub fn max(a: V, b: V) -> V {
        two!(_mm_max_ps, a, b)
    }
    /// a > b ? b : a per lane, that is b < a ? b : a (MINPS of b, a).
    #[inline(always)]
    pub fn min(a: V, b: V) -> V {
        two!(_mm_min_ps, b, a)
    }
    #[inline(always)]
    pub fn gt(a: V, b: V) -> M {
        sse!(M(_mm_cmpgt_ps(a.0, b.0), _mm_cmpgt_ps(a.1, b.1)))
    }
    #[inline(always)]
    pub fn lt(a: V, b: V) -> M {
        sse!(M(_mm_cmplt_ps(a.0, b.0), _mm_cmplt_ps(a.1, b.1)))
    }
    #[inline(always)]
    pub fn eq(a: V, b: V) -> M {
        sse!(M(_mm_cmpeq_ps(a.0, b.0), _mm_cmpeq_ps(a.1, b.1)))
    }
    /// a where m, else b.
    #[inline(always)]
    pub fn select(m: M, a: V, b: V) -> V {
        let pick = |m, a, b| sse!(_mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b)));
        V(pick(m.0, a.0, b.0), pick(m.1, a.1, b.1))
    }
    /// `x as u8` per lane for 0 ≤ x < 256 (what the renderer converts):
    /// truncation to i32, then the low byte; NaN and values outside that
    /// range go through the scalar cast.
    #[inline(always)]
    pub fn to_bytes(v: V) -> [u8; 8] {
        let a = to_array(v);
        let ok = sse!(
            _mm_movemask_ps(_mm_and_ps(
                _mm_cmpge_ps(v.0, _mm_setzero_ps()),
                _mm_cmplt_ps(v.0, _mm_set1_ps(256.0))
            )) & _mm_movemask_ps(_mm_and_ps(
                _mm_cmpge_ps(v.1, _mm_setzero_ps()),
                _mm_cmplt_ps(v.1, _mm_set1_ps(256.0))
            ))
        );
        if ok != 0xf {
            return a.map(|x| x as u8);
        }
        let mut i = [0i32; 8];
        let (lo, hi) = i.split_at_mut(4);
        // SAFETY: each store writes four i32 into a slice of four i32
        // (unaligned stores need no alignment), and SSE2 is baseline.
        unsafe {
            _mm_storeu_si128(lo.as_mut_ptr().cast(), _mm_cvttps_epi32(v.0));
            _mm_storeu_si128(hi.as_mut_ptr().cast(), _mm_cvttps_epi32(v.1));
        }
        i.map(|x| x as u8)
    }
    /// The bytes of three channels interleaved, r0 g0 b0 r1 …: each lane
    /// as [`to_bytes`] converts it.
    #[inline(always)]
    pub fn rgb_bytes(r: V, g: V, b: V) -> [u8; 24] {
        super::interleave(to_bytes(r), to_bytes(g), to_bytes(b))
    }
    /// Bit k set when lane k is true.
    #[inline(always)]
    pub fn bits(m: M) -> u32 {
        sse!(_mm_movemask_ps(m.0) | (_mm_movemask_ps(m.1) << 4)) as u32
    }
    #[inline(always)]
    pub fn mask_from(b: [bool; 8]) -> M {
        let t = |x: bool| f32::from_bits((x as u32).wrapping_neg());
        let v = from_array(b.map(t));
        M(v.0, v.1)
    }
    /// Columns 0…7 of eight rows of twelve as lanes (the lanes of a batch
    /// from its pixels' rows), entry by entry.
    #[inline(always)]
    pub fn transpose8(q: &[[f32; 12]; 8]) -> [V; 8] {
        super::columns(q, 0, from_array)
    }
    /// Columns 8…11 of eight rows of twelve as lanes, entry by entry.
    #[inline(always)]
    pub fn transpose_tail(q: &[[f32; 12]; 8]) -> [V; 4] {
        super::columns(q, 8, from_array)
    }
}

/// The lane operations elsewhere: an array, lane by lane.
#[cfg(not(target_arch = "x86_64"))]
mod imp {
    /// Eight f32.
    #[derive(Clone, Copy, Debug)]
    pub struct V([f32; 8]);
    /// Eight lane masks.
    #[derive(Clone, Copy, Debug)]
    pub struct M([bool; 8]);

    #[inline(always)]
    fn zip(a: V, b: V, f: impl Fn(f32, f32) -> f32) -> V {
        V(std::array::from_fn(|k| f(a.0[k], b.0[k])))
    }
    #[inline(always)]
    fn cmp(a: V, b: V, f: impl Fn(f32, f32) -> bool) -> M {
        M(std::array::from_fn(|k| f(a.0[k], b.0[k])))
    }
    #[inline(always)]
    pub fn from_array(a: [f32; 8]) -> V {
        V(a)
    }
    #[inline(always)]
    pub fn to_array(v: V) -> [f32; 8] {
        v.0
    }
    #[inline(always)]
    pub fn splat(x: f32) -> V {
        V([x; 8])
    }
    #[inline(always)]
    pub fn add(a: V, b: V) -> V {
        zip(a, b, |x, y| x + y)
    }
    #[inline(always)]
    pub fn sub(a: V, b: V) -> V {
        zip(a, b, |x, y| x - y)
    }
    #[inline(always)]
    pub fn mul(a: V, b: V) -> V {
        zip(a, b, |x, y| x * y)
    }
    #[inline(always)]
    pub fn div(a: V, b: V) -> V {
        zip(a, b, |x, y| x / y)
    }
    #[inline(always)]
    pub fn sqrt(a: V) -> V {
        V(a.0.map(f32::sqrt))
    }
    #[inline(always)]
    pub fn neg(a: V) -> V {
        V(a.0.map(|x| -x))
    }
    #[inline(always)]
    pub fn abs(a: V) -> V {
        V(a.0.map(f32::abs))
    }
    #[inline(always)]
    pub fn max(a: V, b: V) -> V {
        zip(a, b, |x, y| if x > y { x } else { y })
    }
    #[inline(always)]
    pub fn min(a: V, b: V) -> V {
        zip(a, b, |x, y| if x > y { y } else { x })
    }
    #[inline(always)]
    pub fn gt(a: V, b: V) -> M {
        cmp(a, b, |x, y| x > y)
    }
    #[inline(always)]
    pub fn lt(a: V, b: V) -> M {
        cmp(a, b, |x, y| x < y)
    }
    #[inline(always)]
    pub fn eq(a: V, b: V) -> M {
        cmp(a, b, |x, y| x == y)
    }
    #[inline(always)]
    pub fn select(m: M, a: V, b: V) -> V {
        V(std::array::from_fn(
            |k| if m.0[k] { a.0[k] } else { b.0[k] },
        ))
    }
    #[inline(always)]
    pub fn to_bytes(v: V) -> [u8; 8] {
        v.0.map(|x| x as u8)
    }
    #[inline(always)]
    pub fn rgb_bytes(r: V, g: V, b: V) -> [u8; 24] {
        super::interleave(to_bytes(r), to_bytes(g), to_bytes(b))
    }
    #[inline(always)]
    pub fn bits(m: M) -> u32 {
        (0..8).fold(0, |acc, k| acc | (m.0[k] as u32) << k)
    }
    #[inline(always)]
    pub fn mask_from(b: [bool; 8]) -> M {
        M(b)
    }
    /// Columns 0…7 of eight rows of twelve as lanes (the lanes of a batch
    /// from its pixels' rows), entry by entry.
    #[inline(always)]
    pub fn transpose8(q: &[[f32; 12]; 8]) -> [V; 8] {
        super::columns(q, 0, from_array)
    }
    /// Columns 8…11 of eight rows of twelve as lanes, entry by entry.
    #[inline(always)]
    pub fn transpose_tail(q: &[[f32; 12]; 8]) -> [V; 4] {
        super::columns(q, 8, from_array)
    }
}

/// Columns a0 … a0 + N − 1 of eight rows of twelve, each made into lanes
/// by `lanes` (lane k of result c is `q[k][a0 + c]`): the transposes of the
/// lane types without a shuffle of their own.
#[inline(always)]
fn columns<V, const N: usize>(q: &[[f32; 12]; 8], a0: usize, lanes: fn([f32; 8]) -> V) -> [V; N] {
    std::array::from_fn(|c| lanes(std::array::from_fn(|k| q[k][a0 + c])))
}

/// Three channels' bytes interleaved pixel by pixel: r0 g0 b0 r1 g1 b1 ….
#[inline(always)]
pub fn interleave(r: [u8; 8], g: [u8; 8], b: [u8; 8]) -> [u8; 24] {
    std::array::from_fn(|i| [r, g, b][i % 3][i / 3])
}

/// What the renderer's Phong batches need of a lane type besides
/// [`Scalar`](super::Scalar): lanes in and bytes out. `LANES` (8 or 16)
/// pixels per batch; the associated arrays have that many entries.
pub trait Wide: super::Scalar + Copy {
    /// How many lanes.
    const LANES: usize;
    /// One f32 per lane: `[f32; LANES]`.
    type Array: Copy + Default + AsRef<[f32]> + AsMut<[f32]>;
    /// One row of twelve attribute values per lane: `[[f32; 12]; LANES]`.
    type Rows: Copy + Default + AsRef<[[f32; 12]]> + AsMut<[[f32; 12]]>;
    /// Three bytes per lane: `[u8; 3 · LANES]`.
    type Bytes: Copy + AsRef<[u8]>;
    /// Lane k = `a[k]`.
    fn from_array(a: Self::Array) -> Self;
    /// The lanes as an array.
    fn to_array(self) -> Self::Array;
    /// The pixels' 8-bit RGB, r0 g0 b0 r1 g1 b1 …: lane k of each channel
    /// truncated to a byte (`x as u8`: toward zero, saturating; NaN gives 0).
    fn rgb_bytes(r: Self, g: Self, b: Self) -> Self::Bytes;
    /// Column a of the rows as lanes, a = 0…11: lane k of result a is
    /// `q[k][a]`.
    fn from_rows(q: &Self::Rows) -> [Self; 12];
    /// Columns 0…7 of the rows as lanes (the first eight of
    /// [`Wide::from_rows`]).
    fn from_rows8(q: &Self::Rows) -> [Self; 8];
    /// Lane k of `self` where bit k of `bits` is set, else lane k of
    /// `other`.
    fn select_bits(self, bits: u32, other: Self) -> Self;
}

/// Defines an f32 type `$name` of `$lanes` lanes (with its mask type
/// `$mask`) over a module `$imp` of lane operations: `V`, `M`, `from_array`,
/// `to_array`, `splat`, `add`, `sub`, `mul`, `div`, `sqrt`, `neg`, `abs`,
/// `max`, `min`, `gt`, `lt`, `eq`, `select`, `rgb_bytes`, `bits`,
/// `mask_from`, `transpose8`, `transpose_tail`, each lane by lane with the
/// plain f32 operation, for arrays of `$lanes` lanes. [`F32x8`] is this over
/// SSE (or an array); the renderer defines two more, over AVX and AVX-512,
/// for the code it compiles for those features.
macro_rules! lane_type {
    ($(#[$meta:meta])* $vis:vis $name:ident, $mask:ident, $imp:ident, $lanes:literal) => {
        #[allow(unused_imports)]
        use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
        #[allow(unused_imports)]
        use std::cmp::Ordering;
        #[allow(unused_imports)]
        use $crate::num::{Precision, Real, Scalar, Shown};

        $(#[$meta])*
        #[derive(Clone, Copy, Debug)]
        $vis struct $name($imp::V);

        /// A mask over the lanes (the result of a lane-wise comparison).
        #[derive(Clone, Copy, Debug)]
        $vis struct $mask($imp::M);

        impl $mask {
            /// Lane k true when bit k of `bits` is set.
            #[inline(always)]
            pub fn from_bits(bits: u32) -> $mask {
                $mask($imp::mask_from(std::array::from_fn(|k| bits >> k & 1 == 1)))
            }
            /// Bit k set when lane k is true.
            #[inline(always)]
            pub fn bits(self) -> u32 {
                $imp::bits(self.0)
            }
            /// Whether some lane is true.
            #[inline(always)]
            pub fn any(self) -> bool {
                self.bits() != 0
            }
            /// Whether every lane is true.
            #[inline(always)]
            pub fn all(self) -> bool {
                self.bits() == u32::MAX >> (32 - $lanes)
            }
        }

        impl From<bool> for $mask {
            #[inline(always)]
            fn from(b: bool) -> $mask {
                $mask::from_bits(if b { u32::MAX } else { 0 })
            }
        }
        impl std::ops::BitAnd for $mask {
            type Output = $mask;
            #[inline(always)]
            fn bitand(self, o: $mask) -> $mask {
                $mask::from_bits(self.bits() & o.bits())
            }
        }
        impl std::ops::Not for $mask {
            type Output = $mask;
            #[inline(always)]
            fn not(self) -> $mask {
                $mask::from_bits(!self.bits())
            }
        }
        impl $crate::num::Mask for $mask {
            #[inline(always)]
            fn any(self) -> bool {
                $mask::any(self)
            }
            #[inline(always)]
            fn all(self) -> bool {
                $mask::all(self)
            }
        }

        impl Default for $name {
            fn default() -> $name {
                $name::splat(0.0)
            }
        }

        impl $name {
            /// Every lane `x`.
            #[inline(always)]
            pub fn splat(x: f32) -> $name {
                $name($imp::splat(x))
            }
            /// The lanes from an array (lane k = `a[k]`).
            #[inline(always)]
            pub fn from_array(a: [f32; $lanes]) -> $name {
                $name($imp::from_array(a))
            }
            /// The lanes as an array.
            #[inline(always)]
            pub fn to_array(self) -> [f32; $lanes] {
                $imp::to_array(self.0)
            }
            /// `f` applied to each lane (lane by lane, for the rare operations
            /// without a vector instruction).
            #[inline(always)]
            pub fn map(self, f: impl Fn(f32) -> f32) -> $name {
                $name::from_array(self.to_array().map(f))
            }
            /// Lane k of `self` where lane k of `take` is true, else lane k of
            /// `other`.
            #[inline(always)]
            pub fn select(self, take: $mask, other: $name) -> $name {
                $name($imp::select(take.0, self.0, other.0))
            }
            /// True in the lanes where `self` > `o`.
            #[inline(always)]
            pub fn gt_mask(self, o: $name) -> $mask {
                $mask($imp::gt(self.0, o.0))
            }
        }

        impl Add for $name {
            type Output = $name;
            #[inline(always)]
            fn add(self, o: $name) -> $name {
                $name($imp::add(self.0, o.0))
            }
        }
        impl AddAssign for $name {
            #[inline(always)]
            fn add_assign(&mut self, o: $name) {
                self.0 = $imp::add(self.0, o.0);
            }
        }
        impl Sub for $name {
            type Output = $name;
            #[inline(always)]
            fn sub(self, o: $name) -> $name {
                $name($imp::sub(self.0, o.0))
            }
        }
        impl SubAssign for $name {
            #[inline(always)]
            fn sub_assign(&mut self, o: $name) {
                self.0 = $imp::sub(self.0, o.0);
            }
        }
        impl Mul for $name {
            type Output = $name;
            #[inline(always)]
            fn mul(self, o: $name) -> $name {
                $name($imp::mul(self.0, o.0))
            }
        }
        impl MulAssign for $name {
            #[inline(always)]
            fn mul_assign(&mut self, o: $name) {
                self.0 = $imp::mul(self.0, o.0);
            }
        }
        impl Div for $name {
            type Output = $name;
            #[inline(always)]
            fn div(self, o: $name) -> $name {
                $name($imp::div(self.0, o.0))
            }
        }
        impl DivAssign for $name {
            #[inline(always)]
            fn div_assign(&mut self, o: $name) {
                self.0 = $imp::div(self.0, o.0);
            }
        }

        impl Neg for $name {
            type Output = $name;
            #[inline(always)]
            fn neg(self) -> $name {
                $name($imp::neg(self.0))
            }
        }

        /// Equal in every lane.
        impl PartialEq for $name {
            #[inline(always)]
            fn eq(&self, o: &$name) -> bool {
                $mask($imp::eq(self.0, o.0)).all()
            }
        }

        /// The order every lane agrees on, `None` when they disagree (or a lane is
        /// NaN): so `a > b` is "a > b in every lane", and `!(a <= b)` is "a > b in
        /// some lane".
        impl PartialOrd for $name {
            #[inline(always)]
            fn partial_cmp(&self, o: &$name) -> Option<Ordering> {
                if self == o {
                    Some(Ordering::Equal)
                } else if self < o {
                    Some(Ordering::Less)
                } else if self > o {
                    Some(Ordering::Greater)
                } else {
                    None
                }
            }
            #[inline(always)]
            fn lt(&self, o: &$name) -> bool {
                $mask($imp::lt(self.0, o.0)).all()
            }
            #[inline(always)]
            fn gt(&self, o: &$name) -> bool {
                $mask($imp::gt(self.0, o.0)).all()
            }
            // ≤ and ≥ keep the defaults (Less/Greater or Equal in every lane as a
            // whole), consistent with partial_cmp: lanes mixing < and = give false.
        }

        impl ::num_traits::Zero for $name {
            #[inline(always)]
            fn zero() -> $name {
                $name::splat(0.0)
            }
            #[inline(always)]
            fn is_zero(&self) -> bool {
                *self == $name::splat(0.0)
            }
        }

        impl $crate::num::lanes::Wide for $name {
            const LANES: usize = $lanes;
            type Array = [f32; $lanes];
            type Rows = [[f32; 12]; $lanes];
            type Bytes = [u8; 3 * $lanes];
            #[inline(always)]
            fn from_array(a: [f32; $lanes]) -> $name {
                $name::from_array(a)
            }
            #[inline(always)]
            fn to_array(self) -> [f32; $lanes] {
                $name::to_array(self)
            }
            #[inline(always)]
            fn rgb_bytes(r: $name, g: $name, b: $name) -> [u8; 3 * $lanes] {
                $imp::rgb_bytes(r.0, g.0, b.0)
            }
            #[inline(always)]
            fn from_rows(q: &[[f32; 12]; $lanes]) -> [$name; 12] {
                let [a, b, c, d, e, f, g, h] = $imp::transpose8(q);
                let [i, j, k, l] = $imp::transpose_tail(q);
                [a, b, c, d, e, f, g, h, i, j, k, l].map($name)
            }
            #[inline(always)]
            fn from_rows8(q: &[[f32; 12]; $lanes]) -> [$name; 8] {
                $imp::transpose8(q).map($name)
            }
            #[inline(always)]
            fn select_bits(self, bits: u32, other: $name) -> $name {
                self.select($mask::from_bits(bits), other)
            }
        }

        impl ::num_traits::One for $name {
            #[inline(always)]
            fn one() -> $name {
                $name::splat(1.0)
            }
        }

        impl $crate::num::Scalar for $name {
            const PRECISION: Precision = Precision::F32;
            type Mask = $mask;
            fn from_real(x: &Real) -> Self {
                $name::splat(x.to_f64() as f32)
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                $name::splat(x as f32)
            }
            #[inline(always)]
            fn from_i64(x: i64) -> Self {
                $name::splat(x as f32)
            }
            /// Lane 0 (see the module documentation).
            fn to_f64(&self) -> f64 {
                f64::from(self.to_array()[0])
            }
            /// Lane 0 (see the module documentation).
            fn to_real(&self) -> Real {
                Real::from_f64(self.to_f64())
            }
            #[inline(always)]
            fn sqrt(&self) -> Self {
                $name($imp::sqrt(self.0))
            }
            #[inline(always)]
            fn abs(&self) -> Self {
                $name($imp::abs(self.0))
            }
            /// xⁿ lane by lane, with the same products as `Fast32::powi`.
            #[inline(always)]
            fn powi(&self, n: u32) -> Self {
                if n == 0 {
                    return $name::splat(1.0);
                }
                // The squarings for n's trailing zero bits, as a counted loop.
                let mut base = *self;
                for _ in 0..n.trailing_zeros() {
                    base = base * base;
                }
                let mut acc = base;
                let mut e = n >> n.trailing_zeros() >> 1;
                while e > 0 {
                    base = base * base;
                    if e & 1 == 1 {
                        acc *= base;
                    }
                    e >>= 1;
                }
                acc
            }
            #[inline(always)]
            fn dot3(a: [&Self; 3], b: [&Self; 3]) -> Self {
                *a[0] * *b[0] + *a[1] * *b[1] + *a[2] * *b[2]
            }
            #[inline(always)]
            fn hypot3(a: &Self, b: &Self, c: &Self) -> Self {
                Self::dot3([a, b, c], [a, b, c]).sqrt()
            }
            #[inline(always)]
            fn diff_of_products(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
                *a * *b - *c * *d
            }
            #[inline(always)]
            fn sum_of_products(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
                *a * *b + *c * *d
            }
            /// a·(1/s), as `Fast32::div3`.
            #[inline(always)]
            fn div3(a: [&Self; 3], s: &Self) -> [Self; 3] {
                let r = $name::splat(1.0) / *s;
                [*a[0] * r, *a[1] * r, *a[2] * r]
            }
            /// xⁿ lane by lane, through f64 as `Fast32` does (the default method).
            fn powf(&self, n: &Self) -> Self {
                let (x, n) = (self.to_array(), n.to_array());
                $name::from_array(std::array::from_fn(|k| {
                    f64::from(x[k]).powf(f64::from(n[k])) as f32
                }))
            }
            /// n when every lane holds the same whole number n (the test of the
            /// default method, on that one value).
            #[inline(always)]
            fn as_whole(&self) -> Option<u32> {
                let x = self.to_array()[0];
                // x as u32 saturates (and gives 0 for NaN): it is x exactly
                // when x is a whole number from 0 to u32::MAX.
                let k = x as u32;
                (*self == $name::splat(x) && k as f64 == f64::from(x)).then_some(k)
            }
            #[inline(always)]
            fn gt_mask(&self, o: &Self) -> $mask {
                $name::gt_mask(*self, *o)
            }
            #[inline(always)]
            fn select(m: $mask, a: Self, b: Self) -> Self {
                a.select(m, b)
            }
            #[inline(always)]
            fn max_of(&self, o: &Self) -> Self {
                $name($imp::max(self.0, o.0))
            }
            #[inline(always)]
            fn min_of(&self, o: &Self) -> Self {
                $name($imp::min(self.0, o.0))
            }
            fn pi() -> Self {
                $name::splat(std::f32::consts::PI)
            }
            fn tan_deg(&self) -> Self {
                self.map(|a| <f32 as Scalar>::tan_deg(&a))
            }
            /// As `Fast32::sin_deg`, lane by lane.
            fn sin_deg(&self) -> Self {
                self.map(|a| a.to_radians().sin())
            }
            /// As `Fast32::cos_deg`, lane by lane.
            fn cos_deg(&self) -> Self {
                self.map(|a| a.to_radians().cos())
            }
            /// Finite in every lane.
            #[inline(always)]
            fn is_finite(&self) -> bool {
                self.to_array().iter().all(|a| a.is_finite())
            }
            /// Lane 0 (see the module documentation).
            fn shown(&self) -> Shown {
                self.to_array()[0].shown()
            }
        }

    };
}
#[cfg_attr(not(target_arch = "x86_64"), allow(unused_imports))]
pub(crate) use lane_type;

lane_type!(
    /// Eight f32 lanes with plain, lane-wise arithmetic.
    pub F32x8,
    Mask,
    imp,
    8
);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Fast32;

    fn lanes(f: impl Fn(usize) -> f32) -> F32x8 {
        F32x8::from_array(std::array::from_fn(f))
    }

    #[test]
    fn each_lane_is_the_plain_f32_result() {
        let a = lanes(|k| 0.1 + k as f32 * 0.37);
        let b = lanes(|k| 1.9 - k as f32 * 0.61);
        let r = (a * b + a / b - -a).sqrt();
        for k in 0..8 {
            let (x, y) = (a.to_array()[k], b.to_array()[k]);
            assert_eq!(
                r.to_array()[k].to_bits(),
                (x * y + x / y + x).sqrt().to_bits()
            );
        }
        // Powers: the same products as Fast32's, lane by lane.
        for n in [0, 1, 2, 3, 5, 32, 33] {
            let p = a.powi(n);
            for k in 0..8 {
                assert_eq!(
                    p.to_array()[k].to_bits(),
                    Fast32(a.to_array()[k]).powi(n).0.to_bits()
                );
            }
        }
    }

    #[test]
    fn comparisons_hold_in_every_lane_or_not_at_all() {
        let a = lanes(|k| k as f32);
        let zero = F32x8::splat(0.0);
        // Lane 0 is 0, the others positive: not > 0 everywhere, not ≤ 0
        // everywhere either.
        let (all_gt, all_le) = (a > zero, a <= zero);
        assert!(!all_gt && !all_le);
        assert!(a.gt_mask(zero).any() && !zero.gt_mask(a).any());
        assert_eq!(a.partial_cmp(&zero), None);
        assert!(a + F32x8::splat(1.0) > zero);
        // Lanes mixing = and > are not ≥ as a whole (partial_cmp is None).
        let ge = a >= zero;
        assert!(!ge);
        assert!(F32x8::splat(1.0) >= zero && zero >= zero);
        assert!(F32x8::splat(2.0) == F32x8::splat(2.0));
        assert!(a != zero);
    }

    #[test]
    fn if_gt_picks_per_lane_and_runs_only_the_branches_needed() {
        let x = lanes(|k| k as f32 - 3.5);
        let zero = F32x8::splat(0.0);
        // max(x, 0) per lane.
        let m = x.if_gt(&zero, || x, || zero);
        for k in 0..8 {
            assert_eq!(m.to_array()[k], (k as f32 - 3.5).max(0.0));
        }
        // All lanes on one side: the other branch is not evaluated.
        let pos = F32x8::splat(1.0);
        let r = pos.if_gt(&zero, || pos, || unreachable!("no lane is ≤ 0"));
        assert_eq!(r, pos);
    }

    #[test]
    fn whole_exponents_only_when_every_lane_agrees() {
        assert_eq!(F32x8::splat(32.0).as_whole(), Some(32));
        assert_eq!(F32x8::splat(0.0).as_whole(), Some(0));
        assert_eq!(F32x8::splat(2.5).as_whole(), None);
        assert_eq!(F32x8::splat(-1.0).as_whole(), None);
        assert_eq!(lanes(|k| k as f32).as_whole(), None);
        // The ends of u32 and what lies past them.
        assert_eq!(F32x8::splat(4294967040.0).as_whole(), Some(4294967040));
        assert_eq!(F32x8::splat(4294967296.0).as_whole(), None);
        assert_eq!(F32x8::splat(f32::INFINITY).as_whole(), None);
        assert_eq!(F32x8::splat(f32::NAN).as_whole(), None);
    }

    /// xⁿ lane by lane takes the same products as `Fast32::powi`: the same
    /// bits, for exponents with and without trailing zero bits.
    #[test]
    fn whole_powers_are_the_scalar_products_lane_by_lane() {
        use crate::num::Fast32;
        let x = lanes(|k| 0.3 + 0.09 * k as f32);
        for n in [0, 1, 2, 3, 4, 5, 7, 12, 32, 33, 100, 128, 1000] {
            let want: [f32; 8] = std::array::from_fn(|k| Fast32(x.to_array()[k]).powi(n).0);
            assert_eq!(x.powi(n).to_array(), want, "n = {n}");
        }
    }
}
