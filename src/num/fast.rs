//! [`Fast32`]: f32 with plain arithmetic, the renderer's scalar.
//!
//! The calculator's `f32` runs the stable formulas (compensated dot
//! products, Kahan's difference of products, scaled norms), which matter
//! when a student compares digits but cost a dozen library calls per
//! lighting evaluation. The renderer calls the *same* stage functions
//! (`lighting::shade`, …) with this type: every product and sum is one f32
//! operation, so a pixel is lit in a few dozen instructions. A vector
//! divided by a length is multiplied by its reciprocal (one division, not
//! three; each quotient within an ulp or so of the correctly rounded one).

use super::{Precision, Real, Scalar, Shown};
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// An f32 whose [`Scalar`] methods use plain arithmetic.
#[derive(Clone, Copy, Debug, Default, PartialEq, PartialOrd)]
#[repr(transparent)]
pub struct Fast32(pub f32);

macro_rules! binop {
    ($tr:ident, $f:ident, $tra:ident, $fa:ident, $op:tt) => {
        impl $tr for Fast32 {
            type Output = Fast32;
            #[inline(always)]
            fn $f(self, o: Fast32) -> Fast32 {
                Fast32(self.0 $op o.0)
            }
        }
        impl $tra for Fast32 {
            #[inline(always)]
            fn $fa(&mut self, o: Fast32) {
                self.0 = self.0 $op o.0;
            }
        }
    };
}
binop!(Add, add, AddAssign, add_assign, +);
binop!(Sub, sub, SubAssign, sub_assign, -);
binop!(Mul, mul, MulAssign, mul_assign, *);
binop!(Div, div, DivAssign, div_assign, /);

impl Neg for Fast32 {
    type Output = Fast32;
    #[inline(always)]
    fn neg(self) -> Fast32 {
        Fast32(-self.0)
    }
}

impl num_traits::Zero for Fast32 {
    #[inline(always)]
    fn zero() -> Fast32 {
        Fast32(0.0)
    }
    #[inline(always)]
    fn is_zero(&self) -> bool {
        self.0 == 0.0
    }
}

impl num_traits::One for Fast32 {
    #[inline(always)]
    fn one() -> Fast32 {
        Fast32(1.0)
    }
}

impl Scalar for Fast32 {
    const PRECISION: Precision = Precision::F32;
    type Mask = bool;
    fn from_real(x: &Real) -> Self {
        Fast32(x.to_f64() as f32)
    }
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        Fast32(x as f32)
    }
    #[inline(always)]
    fn from_i64(x: i64) -> Self {
        Fast32(x as f32)
    }
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        self.0 as f64
    }
    fn to_real(&self) -> Real {
        Real::from_f64(self.0 as f64)
    }
    #[inline(always)]
    fn sqrt(&self) -> Self {
        Fast32(self.0.sqrt())
    }
    #[inline(always)]
    fn abs(&self) -> Self {
        Fast32(self.0.abs())
    }
    /// xⁿ by repeated squaring, inline (f32::powi is a library call). The
    /// same products as the default method, less the first `1·x` and the
    /// last unused squaring: x³² is five squarings in a row.
    #[inline(always)]
    fn powi(&self, n: u32) -> Self {
        if n == 0 {
            return Fast32(1.0);
        }
        let (mut base, mut e) = (self.0, n);
        while e & 1 == 0 {
            base *= base;
            e >>= 1;
        }
        let mut acc = base;
        e >>= 1;
        while e > 0 {
            base *= base;
            if e & 1 == 1 {
                acc *= base;
            }
            e >>= 1;
        }
        Fast32(acc)
    }
    /// a·(1/s): one division for three quotients (see the module docs).
    #[inline(always)]
    fn div3(a: [&Self; 3], s: &Self) -> [Self; 3] {
        let r = Fast32(1.0) / *s;
        [*a[0] * r, *a[1] * r, *a[2] * r]
    }
    fn pi() -> Self {
        Fast32(std::f32::consts::PI)
    }
    fn tan_deg(&self) -> Self {
        Fast32(self.0.tan_deg_f32())
    }
    fn sin_deg(&self) -> Self {
        Fast32(self.0.to_radians().sin())
    }
    fn cos_deg(&self) -> Self {
        Fast32(self.0.to_radians().cos())
    }
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.0.is_finite()
    }
    fn shown(&self) -> Shown {
        self.0.shown()
    }
}

trait TanDeg {
    fn tan_deg_f32(self) -> f32;
}
impl TanDeg for f32 {
    fn tan_deg_f32(self) -> f32 {
        <f32 as Scalar>::tan_deg(&self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn powers_are_the_default_methods_products() {
        // The same multiplications as Scalar::powi's default for f32 (plain
        // f32 products there too), so the results agree bit for bit.
        for x in [0.0f32, 1.0, -1.5, 0.987_654_3, 0.3, 2.5e-3, 7.25] {
            for n in [0u32, 1, 2, 3, 5, 8, 13, 32, 33, 100, 1024] {
                let mut want = 1.0f32;
                let (mut b, mut e) = (x, n);
                while e > 0 {
                    if e & 1 == 1 {
                        want *= b;
                    }
                    b *= b;
                    e >>= 1;
                }
                assert_eq!(Fast32(x).powi(n).0.to_bits(), want.to_bits(), "{x}^{n}");
            }
        }
        // 2⁰ = 1, 2¹⁰ = 1024 (exact in f32).
        assert_eq!(Fast32(2.0).powi(0).0, 1.0);
        assert_eq!(Fast32(2.0).powi(10).0, 1024.0);
    }

    #[test]
    fn plain_arithmetic_agrees_with_f32() {
        let (a, b) = (Fast32(1.5), Fast32(-0.25));
        assert_eq!((a * b + a / b - -a).0, 1.5f32 * -0.25 + 1.5 / -0.25 + 1.5);
        // A dot product is the plain sum of products: (1, 2, 3)·(4, 5, 6) = 32.
        let x = [Fast32(1.0), Fast32(2.0), Fast32(3.0)];
        let y = [Fast32(4.0), Fast32(5.0), Fast32(6.0)];
        assert_eq!(
            Fast32::dot3([&x[0], &x[1], &x[2]], [&y[0], &y[1], &y[2]]).0,
            32.0
        );
        assert_eq!(
            Fast32::hypot3(&Fast32(3.0), &Fast32(4.0), &Fast32(12.0)).0,
            13.0
        );
    }
}
