//! Numbers: the scalar trait every stage is generic over, its float
//! implementations (with the error-free transformations the stable formulas
//! need), the exact number type [`Real`], and the input-expression parser.
//!
//! The stages are written once, over `T: Scalar`, and run at three precisions:
//! `f32`, `f64` and [`Real`] (exact sums of surds, falling back to a marked
//! approximation where no exact form exists).

pub mod exact_dot;
pub mod expr;
pub mod fast;
mod float;
pub mod format;
pub mod lanes;
pub mod real;
pub mod rng;
pub mod vec;

pub use expr::{parse_expr, parse_vec3, Angle, AngleUnit, Expr};
pub use fast::Fast32;
pub use lanes::F32x8;
pub use real::Real;

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::ops::{BitAnd, Not};

/// The precision a calculation runs at (`--precision`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, Default)]
#[serde(rename_all = "lowercase")]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Precision {
    /// Exact sums of surds where the mathematics is exact, marked `≈` otherwise.
    #[default]
    Exact,
    /// IEEE double precision with stable formulas.
    F64,
    /// IEEE single precision with stable formulas.
    F32,
}

impl Precision {
    /// Its name as `--precision` and the JSON spell it (`exact`, `f64`).
    pub fn name(self) -> &'static str {
        match self {
            Precision::Exact => "exact",
            Precision::F64 => "f64",
            Precision::F32 => "f32",
        }
    }
}

/// A number shown to the user (defined with the messages that carry it).
pub use crate::msg::Shown;

/// The truth value of a comparison, one per lane: `bool` for a number of
/// one value, whose `any` and `all` are the value itself.
pub trait Mask: Copy + Debug + From<bool> + BitAnd<Output = Self> + Not<Output = Self> {
    /// Whether some lane holds.
    fn any(self) -> bool;
    /// Whether every lane holds.
    fn all(self) -> bool;
}

impl Mask for bool {
    #[inline(always)]
    fn any(self) -> bool {
        self
    }
    #[inline(always)]
    fn all(self) -> bool {
        self
    }
}

/// The scalar the stages compute with.
///
/// Implemented for `f32`, `f64` and [`Real`]. The arithmetic operators are the
/// field operations; the methods below are the few things a stage needs that
/// the operators do not give, each with a float version that is numerically
/// stable and an exact version where one exists.
pub trait Scalar:
    Clone
    + PartialEq
    + PartialOrd
    + Debug
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + num_traits::Zero
    + num_traits::One
{
    /// The name of the precision, as `--precision` spells it.
    const PRECISION: Precision;
    /// The truth value of a comparison of two such numbers: `bool` for a
    /// number of one value, one truth value per lane for the renderer's
    /// lane type [`F32x8`] (whose lanes may fall on both sides).
    type Mask: Mask;

    /// The value of an exact number at this precision (nearest float).
    fn from_real(x: &Real) -> Self;
    /// The value of a float at this precision (exact for `Real`, since every
    /// finite float is a rational).
    fn from_f64(x: f64) -> Self;
    /// A small integer.
    fn from_i64(x: i64) -> Self;
    /// This number as the nearest f64.
    fn to_f64(&self) -> f64;
    /// This number as an exact [`Real`] (every float is rational), or the
    /// approximation it is for an approximate `Real`.
    fn to_real(&self) -> Real;

    /// √x for x ≥ 0 (exact where the root has a closed form in `Real`).
    fn sqrt(&self) -> Self;
    /// |x|.
    fn abs(&self) -> Self {
        if *self < Self::zero() {
            -self.clone()
        } else {
            self.clone()
        }
    }
    /// xⁿ for an integer n ≥ 0 (exact in `Real`).
    fn powi(&self, n: u32) -> Self {
        let mut acc = Self::one();
        let mut base = self.clone();
        let mut e = n;
        while e > 0 {
            if e & 1 == 1 {
                acc *= base.clone();
            }
            base = base.clone() * base;
            e >>= 1;
        }
        acc
    }
    /// xⁿ for any n (an approximation through f64, marked `≈` in `Real`).
    fn powf(&self, n: &Self) -> Self {
        Self::from_real(&Real::Approx(self.to_f64().powf(n.to_f64())))
    }
    /// n, when this number is a whole number 0 ≤ n ≤ u32::MAX.
    fn as_whole(&self) -> Option<u32> {
        let x = self.to_f64();
        // The cast round-trips exactly for a whole x in range (no libm trunc).
        (x >= 0.0 && x <= f64::from(u32::MAX) && f64::from(x as u32) == x).then_some(x as u32)
    }
    /// self > o, lane by lane (for one value, the plain comparison; a lane
    /// type overrides this).
    #[inline(always)]
    fn gt_mask(&self, o: &Self) -> Self::Mask {
        Self::Mask::from(self > o)
    }
    /// `a` where `m` holds, `b` elsewhere, lane by lane (for one value,
    /// `if m { a } else { b }`; a lane type overrides this).
    #[inline(always)]
    fn select(m: Self::Mask, a: Self, b: Self) -> Self {
        if m.all() {
            a
        } else {
            b
        }
    }
    /// `a()` where self > o, `b()` elsewhere, lane by lane: each branch
    /// runs only if some lane takes it (for one value, exactly one runs).
    #[inline(always)]
    fn if_gt(&self, o: &Self, a: impl FnOnce() -> Self, b: impl FnOnce() -> Self) -> Self {
        let m = self.gt_mask(o);
        if m.all() {
            a()
        } else if !m.any() {
            b()
        } else {
            Self::select(m, a(), b())
        }
    }
    /// max(self, o) as `if self > o { self } else { o }`, lane by lane.
    #[inline(always)]
    fn max_of(&self, o: &Self) -> Self {
        self.if_gt(o, || self.clone(), || o.clone())
    }
    /// min(self, o) as `if self > o { o } else { self }`, lane by lane.
    #[inline(always)]
    fn min_of(&self, o: &Self) -> Self {
        self.if_gt(o, || o.clone(), || self.clone())
    }
    /// π (an approximation in every precision, marked `≈` in `Real`).
    fn pi() -> Self;
    /// tan of an angle in degrees (exact in `Real` for multiples of 15° and 22.5°).
    fn tan_deg(&self) -> Self;
    /// sin of an angle in degrees (exact in `Real` for multiples of 15° and 22.5°).
    fn sin_deg(&self) -> Self;
    /// cos of an angle in degrees (exact in `Real` for multiples of 15° and 22.5°).
    fn cos_deg(&self) -> Self;

    /// (a₀/s, a₁/s, a₂/s): three correctly rounded divisions. The
    /// renderer's plain types ([`Fast32`], [`F32x8`]) multiply by 1/s
    /// instead (one division, each quotient within an ulp or so).
    #[inline(always)]
    fn div3(a: [&Self; 3], s: &Self) -> [Self; 3] {
        [
            a[0].clone() / s.clone(),
            a[1].clone() / s.clone(),
            a[2].clone() / s.clone(),
        ]
    }
    /// `a*b - c*d` with one rounding where it matters (Kahan's algorithm with
    /// FMA for floats), so that cross products and 2×2 determinants do not
    /// lose all their digits to cancellation.
    fn diff_of_products(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        a.clone() * b.clone() - c.clone() * d.clone()
    }
    /// `a*b + c*d` with the same care as [`Scalar::diff_of_products`].
    fn sum_of_products(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        a.clone() * b.clone() + c.clone() * d.clone()
    }
    /// `a₀b₀ + a₁b₁ + a₂b₂` (compensated for floats).
    fn dot3(a: [&Self; 3], b: [&Self; 3]) -> Self {
        a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
    }

    /// The triple product a·(b × c) = det[a; b; c], as accurately as the
    /// type allows: exact in `Real`; in f64 from exactly rounded cross
    /// products (Kahan) and a compensated dot; in f32 evaluated the same way
    /// in f64 and rounded once, so that a result much smaller than its terms
    /// (a point near a camera plane) keeps its digits.
    fn triple_product(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3]) -> Self {
        let x = Self::diff_of_products(b[1], c[2], b[2], c[1]);
        let y = Self::diff_of_products(b[2], c[0], b[0], c[2]);
        let z = Self::diff_of_products(b[0], c[1], b[1], c[0]);
        Self::dot3(a, [&x, &y, &z])
    }

    /// (a × (b × a))·c = (a·a)(b·c) − (a·b)(a·c), with the same care as
    /// [`Scalar::triple_product`].
    fn double_cross_dot(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3]) -> Self {
        let aa = Self::dot3(a, a);
        let bc = Self::dot3(b, c);
        let ab = Self::dot3(a, b);
        let ac = Self::dot3(a, c);
        Self::diff_of_products(&aa, &bc, &ab, &ac)
    }

    /// A power of two 2^-e that brings the largest magnitude among `xs` near
    /// 1 (multiplying by it is exact in floats, barring underflow); one for
    /// exact numbers, which need no scaling.
    fn pow2_scale(xs: &[&Self]) -> Self {
        let _ = xs;
        Self::one()
    }

    /// |(a, b, c)| = √(a² + b² + c²), without overflow or underflow in
    /// floats (scaled by a power of two near the largest component).
    fn hypot3(a: &Self, b: &Self, c: &Self) -> Self {
        Self::dot3([a, b, c], [a, b, c]).sqrt()
    }

    /// Whether the value is a finite number.
    fn is_finite(&self) -> bool;
    /// Whether the value is exact (always true for floats: they are exactly
    /// what they are, even if rounded from something else).
    fn is_exact(&self) -> bool {
        true
    }
    /// Whether the value is exactly zero (in every lane, for a lane type).
    fn is_zero_value(&self) -> bool {
        *self == Self::zero()
    }
    /// The number for display and JSON.
    fn shown(&self) -> Shown;
    /// √self for display: [`shown`](Scalar::shown) of the root, and, where
    /// the root has no exact form but self has (an exact run), `√(s)` as
    /// its form for people beside the decimal (|V + L| = √(2+√2) ≈ 1.848;
    /// `exact` stays `None`: the JSON's forms take `sqrt` of integers only).
    fn root_shown(&self) -> Shown {
        self.sqrt().shown()
    }
}

#[cfg(test)]
mod tests {
    use super::Precision;
    use strum::IntoEnumIterator;

    /// `--precision`, the errors and the JSON spell a precision one way:
    /// `name`, which is also serde's spelling.
    #[test]
    fn a_precision_is_spelled_by_its_name_everywhere() {
        for p in Precision::iter() {
            assert_eq!(serde_json::to_value(p).ok(), Some(p.name().into()));
        }
        let names: Vec<&str> = Precision::iter().map(Precision::name).collect();
        assert_eq!(names, ["exact", "f64", "f32"]);
    }
}
