//! [`F32x8`]: eight f32 lanes, the renderer's batch scalar, with which
//! the Phong band pass calls the calculator's own `lighting::shade_color`.
//!
//! Every operation is a loop over the lanes doing the plain f32 operation
//! of [`super::Fast32`], which the compiler turns into vector instructions
//! of the width the caller is compiled for (two SSE registers in the
//! baseline build, one AVX register in the band pass's AVX2 copy chosen at
//! run time by `multiversion`). IEEE add, subtract, multiply, divide and
//! square root are correctly rounded at any width, and Rust never fuses a
//! multiply and an add on its own, so lane k is bit for bit what `Fast32`
//! gives for lane k's inputs, whichever copy runs.
//!
//! [`Scalar::gt_mask`] and [`Scalar::select`] compare and pick lane by lane
//! (the lighting is written with them); the operators `==`, `<`, `>` that
//! [`Scalar`] also requires mean "in every lane". Reading a number out
//! (`to_f64`, `shown`) gives lane 0: a batch is only turned into pixels.

use super::{Mask, Precision, Real, Scalar, Shown};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, BitAnd, Div, DivAssign, Mul, MulAssign, Neg, Not, Sub, SubAssign};

/// Eight f32 lanes with plain, lane-wise arithmetic.
#[derive(Clone, Copy, Debug)]
pub struct F32x8(Store);

/// How eight lanes are held: on x86-64 in the 256-bit vector type, so that
/// the compiler keeps a value in vector registers from one operation to
/// the next (an array is split into eight scalars, which the compiler then
/// regroups into vectors only in part); elsewhere as an array. Either way
/// every operation is written on the lanes as an array
/// ([`F32x8::to_array`], [`F32x8::from_array`]: a reinterpretation of the
/// same 32 bytes, no instruction), never with intrinsics.
#[cfg(target_arch = "x86_64")]
type Store = std::arch::x86_64::__m256;
/// How eight lanes are held (see the x86-64 definition).
#[cfg(not(target_arch = "x86_64"))]
type Store = [f32; 8];

/// Eight truth values, one per lane (what a lane-wise comparison gives):
/// all 32 bits of a lane set when it is true, none when false, held as
/// [`F32x8`] is.
#[derive(Clone, Copy, Debug)]
pub struct Mask8(Store);

/// Lane k of the result is `$e` with `$k` = k.
macro_rules! lanes {
    ($k:ident => $e:expr) => {{
        let mut out = [Default::default(); 8];
        for ($k, o) in out.iter_mut().enumerate() {
            *o = $e;
        }
        out
    }};
}

impl Mask8 {
    /// Lane k true when `b[k]` is.
    #[inline(always)]
    pub fn from_bools(b: [bool; 8]) -> Mask8 {
        Mask8(bytemuck::cast(lanes!(k => u32::from(b[k]).wrapping_neg())))
    }
    /// Lane k true when bit k of `bits` is set.
    #[inline(always)]
    pub fn from_bits(bits: u32) -> Mask8 {
        Mask8::from_bools(lanes!(k => bits >> k & 1 == 1))
    }
    /// Each lane's 32 bits (all set or none).
    #[inline(always)]
    fn words(self) -> [u32; 8] {
        bytemuck::cast(self.0)
    }
    /// The mask of the given 32-bit lanes.
    #[inline(always)]
    fn words_from(w: [u32; 8]) -> Mask8 {
        Mask8(bytemuck::cast(w))
    }
}

impl From<bool> for Mask8 {
    #[inline(always)]
    fn from(b: bool) -> Mask8 {
        Mask8::from_bools([b; 8])
    }
}

impl BitAnd for Mask8 {
    type Output = Mask8;
    #[inline(always)]
    fn bitand(self, o: Mask8) -> Mask8 {
        let (a, b) = (self.words(), o.words());
        Mask8::words_from(lanes!(k => a[k] & b[k]))
    }
}

impl Not for Mask8 {
    type Output = Mask8;
    #[inline(always)]
    fn not(self) -> Mask8 {
        let a = self.words();
        Mask8::words_from(lanes!(k => !a[k]))
    }
}

impl Mask for Mask8 {
    #[inline(always)]
    fn any(self) -> bool {
        self.words().iter().fold(0, |a, &b| a | b) != 0
    }
    #[inline(always)]
    fn all(self) -> bool {
        self.words().iter().fold(u32::MAX, |a, &b| a & b) == u32::MAX
    }
}

impl F32x8 {
    /// Every lane `x`.
    #[inline(always)]
    pub fn splat(x: f32) -> F32x8 {
        F32x8::from_array([x; 8])
    }
    /// The lanes from an array (lane k = `a[k]`).
    #[inline(always)]
    pub fn from_array(a: [f32; 8]) -> F32x8 {
        F32x8(bytemuck::cast(a))
    }
    /// The lanes as an array.
    #[inline(always)]
    pub fn to_array(self) -> [f32; 8] {
        bytemuck::cast(self.0)
    }
    /// `f` applied to each lane (for the rare operations without a vector
    /// instruction).
    #[inline(always)]
    pub fn map(self, f: impl Fn(f32) -> f32) -> F32x8 {
        F32x8::from_array(self.to_array().map(f))
    }
    /// Column a of eight rows of twelve values as lanes, a = 0…N − 1: lane k
    /// of result a is `q[k][a]` (the lanes of a batch from its pixels' rows).
    #[inline(always)]
    pub fn from_rows<const N: usize>(q: &[[f32; 12]; 8]) -> [F32x8; N] {
        let mut out = [F32x8::default(); N];
        for (a, o) in out.iter_mut().enumerate() {
            *o = F32x8::from_array(lanes!(k => q[k][a]));
        }
        out
    }
    /// Each lane truncated to a byte, `x as u8` (toward zero, saturating;
    /// NaN gives 0), in lane operations only: c = min(max(x, 0), 255)
    /// (max(x, 0) is 0 for NaN); r = c + 2²³ is 2²³ + n for n = c rounded
    /// to a whole number (exact: the f32s from 2²³ to 2²⁴ are the whole
    /// numbers), so n is the low byte of r's bits; where r − 2²³ > c (c
    /// was rounded up), trunc(c) = n − 1. Each byte is held in a 32-bit
    /// lane, so the caller packs pixels with lane operations too. (A cast
    /// per lane would be eight scalar conversions.)
    #[inline(always)]
    pub fn to_bytes(self) -> [u32; 8] {
        let m = F32x8::splat(8_388_608.0);
        let c = self.max_of(&F32x8::splat(0.0)).min_of(&F32x8::splat(255.0));
        let r = c + m;
        // All bits set (−1) in the lanes rounded up.
        let up = (r - m).gt_mask(&c).words();
        let bits = r.to_array();
        lanes!(k => bits[k].to_bits().wrapping_add(up[k]) & 0xff)
    }
}

/// The lane-wise arithmetic operators, each with its assigning form.
macro_rules! lane_op {
    ($tr:ident, $f:ident, $tra:ident, $fa:ident, $op:tt) => {
        impl $tr for F32x8 {
            type Output = F32x8;
            #[inline(always)]
            fn $f(self, o: F32x8) -> F32x8 {
                let (a, b) = (self.to_array(), o.to_array());
                F32x8::from_array(lanes!(k => a[k] $op b[k]))
            }
        }
        impl $tra for F32x8 {
            #[inline(always)]
            fn $fa(&mut self, o: F32x8) {
                *self = *self $op o;
            }
        }
    };
}
lane_op!(Add, add, AddAssign, add_assign, +);
lane_op!(Sub, sub, SubAssign, sub_assign, -);
lane_op!(Mul, mul, MulAssign, mul_assign, *);
lane_op!(Div, div, DivAssign, div_assign, /);

impl Neg for F32x8 {
    type Output = F32x8;
    #[inline(always)]
    fn neg(self) -> F32x8 {
        let a = self.to_array();
        F32x8::from_array(lanes!(k => -a[k]))
    }
}

impl Default for F32x8 {
    #[inline(always)]
    fn default() -> F32x8 {
        F32x8::splat(0.0)
    }
}

/// Equal in every lane.
impl PartialEq for F32x8 {
    #[inline(always)]
    fn eq(&self, o: &F32x8) -> bool {
        let (a, b) = (self.to_array(), o.to_array());
        Mask8::from_bools(lanes!(k => a[k] == b[k])).all()
    }
}

/// The order every lane agrees on, `None` when they disagree (or a lane is
/// NaN): so `a > b` is "a > b in every lane".
impl PartialOrd for F32x8 {
    #[inline(always)]
    fn partial_cmp(&self, o: &F32x8) -> Option<Ordering> {
        if self == o {
            Some(Ordering::Equal)
        } else if o.gt_mask(self).all() {
            Some(Ordering::Less)
        } else if self.gt_mask(o).all() {
            Some(Ordering::Greater)
        } else {
            None
        }
    }
}

impl num_traits::Zero for F32x8 {
    #[inline(always)]
    fn zero() -> F32x8 {
        F32x8::splat(0.0)
    }
    #[inline(always)]
    fn is_zero(&self) -> bool {
        *self == F32x8::splat(0.0)
    }
}

impl num_traits::One for F32x8 {
    #[inline(always)]
    fn one() -> F32x8 {
        F32x8::splat(1.0)
    }
}

/// Each method lane by lane with the same f32 operations as [`super::Fast32`]
/// (always inlined, so that the band pass's AVX2 copy compiles them for AVX2).
impl Scalar for F32x8 {
    const PRECISION: Precision = Precision::F32;
    type Mask = Mask8;
    fn from_real(x: &Real) -> Self {
        F32x8::splat(x.to_f64() as f32)
    }
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        F32x8::splat(x as f32)
    }
    #[inline(always)]
    fn from_i64(x: i64) -> Self {
        F32x8::splat(x as f32)
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
        let a = self.to_array();
        F32x8::from_array(lanes!(k => a[k].sqrt()))
    }
    #[inline(always)]
    fn abs(&self) -> Self {
        let a = self.to_array();
        F32x8::from_array(lanes!(k => a[k].abs()))
    }
    #[inline(always)]
    fn gt_mask(&self, o: &Self) -> Mask8 {
        let (a, b) = (self.to_array(), o.to_array());
        Mask8::from_bools(lanes!(k => a[k] > b[k]))
    }
    /// The bits of `a` where `m` is set, else of `b`.
    #[inline(always)]
    fn select(m: Mask8, a: Self, b: Self) -> Self {
        let (m, a, b): ([u32; 8], [u32; 8], [u32; 8]) =
            (m.words(), bytemuck::cast(a.0), bytemuck::cast(b.0));
        F32x8(bytemuck::cast(lanes!(k => (a[k] & m[k]) | (b[k] & !m[k]))))
    }
    /// a > b ? a : b per lane (one vector max instruction where there is one).
    #[inline(always)]
    fn max_of(&self, o: &Self) -> Self {
        let (a, b) = (self.to_array(), o.to_array());
        F32x8::from_array(lanes!(k => if a[k] > b[k] { a[k] } else { b[k] }))
    }
    /// a > b ? b : a per lane.
    #[inline(always)]
    fn min_of(&self, o: &Self) -> Self {
        let (a, b) = (self.to_array(), o.to_array());
        F32x8::from_array(lanes!(k => if a[k] > b[k] { b[k] } else { a[k] }))
    }
    /// xⁿ with the same products as `Fast32::powi`: the squarings for n's
    /// trailing zero bits, then repeated squaring.
    #[inline(always)]
    fn powi(&self, n: u32) -> Self {
        if n == 0 {
            return F32x8::splat(1.0);
        }
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
    /// xⁿ lane by lane, through f64 as `Fast32` does (the default method).
    fn powf(&self, n: &Self) -> Self {
        let (x, n) = (self.to_array(), n.to_array());
        F32x8::from_array(lanes!(k => f64::from(x[k]).powf(f64::from(n[k])) as f32))
    }
    /// n when every lane holds the same whole number n.
    #[inline(always)]
    fn as_whole(&self) -> Option<u32> {
        let x = self.to_array()[0];
        // x as u32 saturates (and gives 0 for NaN): it is x exactly when x
        // is a whole number from 0 to u32::MAX.
        let k = x as u32;
        (*self == F32x8::splat(x) && k as f64 == f64::from(x)).then_some(k)
    }
    #[inline(always)]
    fn hypot3(a: &Self, b: &Self, c: &Self) -> Self {
        Self::dot3([a, b, c], [a, b, c]).sqrt()
    }
    /// a·(1/s), as `Fast32::div3`.
    #[inline(always)]
    fn div3(a: [&Self; 3], s: &Self) -> [Self; 3] {
        let r = F32x8::splat(1.0) / *s;
        [*a[0] * r, *a[1] * r, *a[2] * r]
    }
    fn pi() -> Self {
        F32x8::splat(std::f32::consts::PI)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Fast32;

    fn lanes(f: impl Fn(usize) -> f32) -> F32x8 {
        F32x8::from_array(std::array::from_fn(f))
    }

    /// The values where float rules differ: ±0, ±∞, NaN, subnormals, the
    /// largest f32, and a few ordinary numbers.
    const SPECIAL: [f32; 12] = [
        0.0,
        -0.0,
        1.0,
        -1.5,
        3.25,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        1e-40,
        -1e-40,
        f32::MAX,
        -7.0,
    ];

    /// Each lane operation gives, lane by lane, the bits of the same
    /// operation at `Fast32` (plain f32), on every pair of special values.
    #[test]
    fn lane_operations_are_the_scalar_ones_on_special_values() {
        let n = SPECIAL.len();
        for shift in 0..n {
            for base in [0, 8] {
                let (x, y) = (
                    lanes(|k| SPECIAL[(base + k) % n]),
                    lanes(|k| SPECIAL[(base + k + shift) % n]),
                );
                let got = [
                    x + y,
                    x - y,
                    x * y,
                    x / y,
                    x.sqrt(),
                    -x,
                    x.abs(),
                    x.max_of(&y),
                    x.min_of(&y),
                    x.if_gt(&y, || x, || y * y),
                    F32x8::select(x.gt_mask(&y), y, x),
                ];
                for k in 0..8 {
                    let (a, b) = (Fast32(x.to_array()[k]), Fast32(y.to_array()[k]));
                    let want = [
                        a + b,
                        a - b,
                        a * b,
                        a / b,
                        a.sqrt(),
                        -a,
                        a.abs(),
                        a.max_of(&b),
                        a.min_of(&b),
                        a.if_gt(&b, || a, || b * b),
                        if a.0 > b.0 { b } else { a },
                    ];
                    for (op, (g, w)) in got.iter().zip(want).enumerate() {
                        assert_eq!(
                            g.to_array()[k].to_bits(),
                            w.0.to_bits(),
                            "op {op}: {a:?}, {b:?}"
                        );
                    }
                }
            }
        }
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
    }

    #[test]
    fn comparisons_hold_in_every_lane_or_not_at_all() {
        let a = lanes(|k| k as f32);
        let zero = F32x8::splat(0.0);
        // Lane 0 is 0, the others positive: not > 0 everywhere, not ≤ 0
        // everywhere either; > 0 lane by lane in lanes 1…7.
        let (all_gt, all_le) = (a > zero, a <= zero);
        assert!(!all_gt && !all_le);
        assert_eq!(a.gt_mask(&zero).words(), Mask8::from_bits(0xfe).words());
        assert!(a.gt_mask(&zero).any() && !zero.gt_mask(&a).any());
        assert_eq!(a.partial_cmp(&zero), None);
        assert!(a + F32x8::splat(1.0) > zero);
        // Lanes mixing = and > are not ≥ as a whole (partial_cmp is None).
        let ge = a >= zero;
        assert!(!ge);
        assert!(F32x8::splat(1.0) >= zero && zero >= zero);
        assert!(F32x8::splat(2.0) == F32x8::splat(2.0));
        assert!(a != zero);
        // Masks combine lane by lane.
        let (m, o) = (Mask8::from_bits(0b1100), Mask8::from_bits(0b1010));
        assert_eq!((m & o).words(), Mask8::from_bits(0b1000).words());
        assert_eq!((!m).words(), Mask8::from_bits(0xf3).words());
        assert!(Mask8::from(true).all() && !Mask8::from(false).any());
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
        let x = lanes(|k| 0.3 + 0.09 * k as f32);
        for n in [0, 1, 2, 3, 4, 5, 7, 12, 32, 33, 100, 128, 1000] {
            let want: [f32; 8] = std::array::from_fn(|k| Fast32(x.to_array()[k]).powi(n).0);
            assert_eq!(x.powi(n).to_array(), want, "n = {n}");
        }
    }

    /// A batch's rows become lanes: lane k of column a is row k's entry a.
    #[test]
    fn rows_become_lanes() {
        let q: [[f32; 12]; 8] =
            std::array::from_fn(|k| std::array::from_fn(|a| (100 * k + a) as f32));
        let all: [F32x8; 12] = F32x8::from_rows(&q);
        let first8: [F32x8; 8] = F32x8::from_rows(&q);
        for a in 0..12 {
            let want: [f32; 8] = std::array::from_fn(|k| (100 * k + a) as f32);
            assert_eq!(all[a].to_array(), want, "column {a}");
            if a < 8 {
                assert_eq!(first8[a].to_array(), want, "column {a}");
            }
        }
    }
}
