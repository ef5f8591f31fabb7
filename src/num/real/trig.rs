//! Exact trigonometry of the standard angles, in degrees: sin, cos and tan of
//! multiples of 15°, and tan of odd multiples of 22.5° (whose sin and cos are
//! nested radicals outside the field, so those stay approximate). Every other
//! angle gives an approximation.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

use super::surd::Surd;
use super::Real;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// sin(15°·k) for k = 0 … 6.
fn sin_first_quadrant(k: u32) -> Surd {
    match k {
        0 => Surd::zero(),
        // (√6 − √2)/4
        1 => &Surd::term_unchecked(q(1, 4), 6) - &Surd::term_unchecked(q(1, 4), 2),
        2 => Surd::from_rational(q(1, 2)),
        3 => Surd::term_unchecked(q(1, 2), 2),
        4 => Surd::term_unchecked(q(1, 2), 3),
        // (√6 + √2)/4
        5 => &Surd::term_unchecked(q(1, 4), 6) + &Surd::term_unchecked(q(1, 4), 2),
        _ => Surd::one(),
    }
}

/// sin(15°·k) for k = 0 … 23.
fn sin15(k: u32) -> Surd {
    match k % 24 {
        k @ 0..=6 => sin_first_quadrant(k),
        k @ 7..=12 => sin_first_quadrant(12 - k),
        k => -sin15(k - 12),
    }
}

/// The angle reduced to [0°, period°) exactly, if it is rational.
fn reduce(x: &Real, period: i64) -> Option<BigRational> {
    let a = x.as_rational()?;
    let p = BigRational::from_integer(BigInt::from(period));
    Some(&a - (&a / &p).floor() * &p)
}

/// `r / step` as an integer, if it is one (r ∈ [0, 360)).
fn multiple_of(r: &BigRational, step: &BigRational) -> Option<u32> {
    let k = r / step;
    if k.is_integer() {
        k.to_integer().try_into().ok()
    } else {
        None
    }
}

fn approx(x: &Real, f: fn(f64) -> f64) -> Real {
    let deg = match reduce(x, 360) {
        Some(r) => super::convert::rational_to_f64(&r),
        None => x.to_f64().rem_euclid(360.0),
    };
    Real::Approx(f(deg.to_radians()))
}

pub(crate) fn sin_deg(x: &Real) -> Real {
    if let Some(r) = reduce(x, 360) {
        if let Some(k) = multiple_of(&r, &q(15, 1)) {
            return Real::Exact(sin15(k));
        }
    }
    approx(x, f64::sin)
}

pub(crate) fn cos_deg(x: &Real) -> Real {
    if let Some(r) = reduce(x, 360) {
        if let Some(k) = multiple_of(&r, &q(15, 1)) {
            return Real::Exact(sin15(k + 6));
        }
    }
    approx(x, f64::cos)
}

pub(crate) fn tan_deg(x: &Real) -> Real {
    if let Some(r) = reduce(x, 180) {
        if let Some(k) = multiple_of(&r, &q(15, 1)) {
            // sin/cos; at 90° the division by exact zero gives +∞.
            return Real::Exact(sin15(k)) / Real::Exact(sin15(k + 6));
        }
        if let Some(k) = multiple_of(&r, &q(45, 2)) {
            // Odd multiples of 22.5°: tan 22.5° = √2−1, tan 67.5° = √2+1.
            let root2 = Surd::term_unchecked(BigRational::one(), 2);
            let one = Surd::one();
            let t = match k {
                1 => &root2 - &one,
                3 => &root2 + &one,
                5 => -(&root2 + &one),
                _ => &one - &root2,
            };
            return Real::Exact(t);
        }
    }
    let deg = match reduce(x, 180) {
        Some(r) => super::convert::rational_to_f64(&r),
        None => x.to_f64().rem_euclid(180.0),
    };
    Real::Approx(deg.to_radians().tan())
}
