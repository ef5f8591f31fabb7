//! The exact number type [`Real`]: a canonical sum of rationals times square
//! roots of square-free integers ([`Surd`]), or, where no exact form exists
//! here (π, tan 50°, a square root that does not denest, anything computed
//! from an approximation), an `f64` marked as approximate.
//!
//! Field arithmetic is exact (division rationalizes its denominator), order is
//! decided by exact sign determination, and nothing panics: division by an
//! exact zero gives an approximate ±∞ or NaN, as IEEE division would.

mod convert;
mod format;
mod surd;
mod trig;

pub use surd::{Surd, MAX_EXACT_BITS, MAX_EXACT_TERMS};

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

use super::{Precision, Scalar, Shown};

/// An exact sum of surds, or a marked approximation.
#[derive(Clone)]
pub enum Real {
    /// Σ qᵣ·√r exactly.
    Exact(Surd),
    /// A value with no exact form here.
    Approx(f64),
}

impl Real {
    /// A rational number.
    pub fn from_rational(q: BigRational) -> Real {
        Real::Exact(Surd::from_rational(q))
    }

    /// An integer.
    pub fn from_bigint(n: BigInt) -> Real {
        Real::Exact(Surd::from_integer(n))
    }

    /// The rational n/d; d = 0 gives the IEEE quotient (±∞ or NaN), approximate.
    pub fn from_ratio(n: i64, d: i64) -> Real {
        if d == 0 {
            return Real::Approx(n as f64 / 0.0);
        }
        Real::from_rational(BigRational::new(BigInt::from(n), BigInt::from(d)))
    }

    /// A small integer.
    pub fn from_i64(n: i64) -> Real {
        Real::from_bigint(BigInt::from(n))
    }

    /// The exact value of a finite float; ±∞ and NaN stay approximate.
    pub fn from_f64(x: f64) -> Real {
        match convert::f64_to_rational(x) {
            Some(q) => Real::from_rational(q),
            None => Real::Approx(x),
        }
    }

    /// Parses a decimal literal exactly: `123`, `-1.25`, `.5`, `2.5e-7`,
    /// `1E30` (so 0.1 is 1/10). `None` if it is not one, or its exponent
    /// exceeds 100000 in magnitude.
    pub fn from_decimal(s: &str) -> Option<Real> {
        convert::parse_decimal(s).map(Real::from_rational)
    }

    /// The exact surd, if the value is exact.
    pub fn as_surd(&self) -> Option<&Surd> {
        match self {
            Real::Exact(s) => Some(s),
            Real::Approx(_) => None,
        }
    }

    /// Whether the value is exact.
    pub fn is_exact(&self) -> bool {
        matches!(self, Real::Exact(_))
    }

    /// Whether the value is an exact rational.
    pub fn is_rational(&self) -> bool {
        self.as_surd().is_some_and(Surd::is_rational)
    }

    /// The value as a rational, if it is an exact one.
    pub fn as_rational(&self) -> Option<BigRational> {
        self.as_surd().and_then(Surd::as_rational)
    }

    /// The sign: −1, 0 or 1, exact for exact values (0 for NaN).
    pub fn signum(&self) -> i8 {
        match self {
            Real::Exact(s) => s.signum(),
            Real::Approx(x) if *x > 0.0 => 1,
            Real::Approx(x) if *x < 0.0 => -1,
            Real::Approx(_) => 0,
        }
    }

    /// The f64 nearest the value (correctly rounded for exact values).
    pub fn to_f64(&self) -> f64 {
        match self {
            Real::Exact(s) => s.to_f64(),
            Real::Approx(x) => *x,
        }
    }

    /// √x: exact for rationals and denestable `a + b√r`, approximate
    /// otherwise, NaN for x < 0.
    pub fn sqrt(&self) -> Real {
        match self {
            Real::Exact(s) => match s.sqrt() {
                Some(r) => Real::Exact(r),
                None if s.signum() < 0 => Real::Approx(f64::NAN),
                None => Real::Approx(scaled_sqrt(s)),
            },
            Real::Approx(x) => Real::Approx(x.sqrt()),
        }
    }

    /// |x|.
    pub fn abs(&self) -> Real {
        match self {
            Real::Exact(s) if s.signum() < 0 => Real::Exact(-s),
            Real::Exact(_) => self.clone(),
            Real::Approx(x) => Real::Approx(x.abs()),
        }
    }

    /// sin of an angle in degrees (exact for multiples of 15°).
    pub fn sin_deg(&self) -> Real {
        trig::sin_deg(self)
    }

    /// cos of an angle in degrees (exact for multiples of 15°).
    pub fn cos_deg(&self) -> Real {
        trig::cos_deg(self)
    }

    /// tan of an angle in degrees (exact for multiples of 15° and 22.5°;
    /// ±∞ at 90° + k·180°).
    pub fn tan_deg(&self) -> Real {
        trig::tan_deg(self)
    }

    /// The ASCII exact form (`(sqrt(2)-1)/10`), `None` if approximate.
    pub fn exact_ascii(&self) -> Option<String> {
        self.as_surd().map(|s| format::format_surd(s, false))
    }

    /// The Unicode exact form (`(√2−1)/10`), `None` if approximate.
    pub fn exact_pretty(&self) -> Option<String> {
        self.as_surd().map(|s| format::format_surd(s, true))
    }
}

impl From<Surd> for Real {
    fn from(s: Surd) -> Real {
        Real::Exact(s)
    }
}

impl From<BigRational> for Real {
    fn from(q: BigRational) -> Real {
        Real::from_rational(q)
    }
}

impl From<i64> for Real {
    fn from(n: i64) -> Real {
        Real::from_i64(n)
    }
}

thread_local! {
    /// Why exact results were left approximate since [`take_grew_too_large`]
    /// last looked (on this thread): bit 0, too many terms; bit 1, numbers
    /// too long.
    static GREW: std::cell::Cell<u8> = const { std::cell::Cell::new(0) };
}

/// Why exact values were left approximate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Grew {
    /// A value grew past [`surd::MAX_EXACT_TERMS`] terms.
    pub terms: bool,
    /// A value's numbers grew past [`surd::MAX_EXACT_BITS`] bits.
    pub bits: bool,
}

const TERMS: u8 = 1;
const BITS: u8 = 2;

fn grew(why: u8) {
    GREW.with(|g| g.set(g.get() | why));
}

/// Whether, since the last call, an exact value grew past
/// [`surd::MAX_EXACT_TERMS`] terms or [`surd::MAX_EXACT_BITS`] bits and
/// was left approximate (so the caller can say so); clears the marks.
pub fn take_grew_too_large() -> Grew {
    let g = GREW.with(|g| g.replace(0));
    Grew {
        terms: g & TERMS != 0,
        bits: g & BITS != 0,
    }
}

/// An exact result kept exact while it has at most
/// [`surd::MAX_EXACT_TERMS`] terms and no number longer than
/// [`surd::MAX_EXACT_BITS`] bits; beyond that its f64 value, marked
/// approximate (the precision ladder's step down, noted by [`GREW`]).
fn bounded(s: Surd) -> Real {
    if s.len() > surd::MAX_EXACT_TERMS {
        grew(TERMS);
        Real::Approx(s.to_f64())
    } else if s.bits() > surd::MAX_EXACT_BITS {
        grew(BITS);
        Real::Approx(s.to_f64())
    } else {
        Real::Exact(s)
    }
}

fn add_ref(a: &Real, b: &Real) -> Real {
    match (a, b) {
        (Real::Exact(x), Real::Exact(y)) => bounded(x + y),
        _ => Real::Approx(a.to_f64() + b.to_f64()),
    }
}

fn sub_ref(a: &Real, b: &Real) -> Real {
    match (a, b) {
        (Real::Exact(x), Real::Exact(y)) => bounded(x - y),
        _ => Real::Approx(a.to_f64() - b.to_f64()),
    }
}

fn mul_ref(a: &Real, b: &Real) -> Real {
    match (a, b) {
        (Real::Exact(x), Real::Exact(y)) if x.len() * y.len() <= surd::MAX_PRODUCTS => {
            bounded(x * y)
        }
        (Real::Exact(_), Real::Exact(_)) => {
            grew(TERMS);
            Real::Approx(a.to_f64() * b.to_f64())
        }
        _ => Real::Approx(a.to_f64() * b.to_f64()),
    }
}

fn div_ref(a: &Real, b: &Real) -> Real {
    match (a, b) {
        (Real::Exact(x), Real::Exact(y)) => match x.checked_div(y) {
            Some(q) => bounded(q),
            // Exact zero divisor: ±∞ or NaN, as x / +0.0 is in IEEE.
            None if y.is_empty() => Real::Approx(a.to_f64() / b.to_f64()),
            // Too large to rationalize within the bound.
            None => {
                grew(TERMS);
                Real::Approx(a.to_f64() / b.to_f64())
            }
        },
        _ => Real::Approx(a.to_f64() / b.to_f64()),
    }
}

macro_rules! binop {
    ($tr:ident, $method:ident, $f:ident, $atr:ident, $amethod:ident) => {
        impl $tr<&Real> for &Real {
            type Output = Real;
            fn $method(self, rhs: &Real) -> Real {
                $f(self, rhs)
            }
        }
        impl $tr<Real> for &Real {
            type Output = Real;
            fn $method(self, rhs: Real) -> Real {
                $f(self, &rhs)
            }
        }
        impl $tr<&Real> for Real {
            type Output = Real;
            fn $method(self, rhs: &Real) -> Real {
                $f(&self, rhs)
            }
        }
        impl $tr<Real> for Real {
            type Output = Real;
            fn $method(self, rhs: Real) -> Real {
                $f(&self, &rhs)
            }
        }
        impl $atr<&Real> for Real {
            fn $amethod(&mut self, rhs: &Real) {
                *self = $f(self, rhs);
            }
        }
        impl $atr<Real> for Real {
            fn $amethod(&mut self, rhs: Real) {
                *self = $f(self, &rhs);
            }
        }
    };
}

binop!(Add, add, add_ref, AddAssign, add_assign);
binop!(Sub, sub, sub_ref, SubAssign, sub_assign);
binop!(Mul, mul, mul_ref, MulAssign, mul_assign);
binop!(Div, div, div_ref, DivAssign, div_assign);

impl Neg for Real {
    type Output = Real;
    fn neg(self) -> Real {
        match self {
            Real::Exact(s) => Real::Exact(-s),
            Real::Approx(x) => Real::Approx(-x),
        }
    }
}

impl Neg for &Real {
    type Output = Real;
    fn neg(self) -> Real {
        match self {
            Real::Exact(s) => Real::Exact(-s),
            Real::Approx(x) => Real::Approx(-x),
        }
    }
}

impl Zero for Real {
    fn zero() -> Real {
        Real::Exact(Surd::zero())
    }
    fn is_zero(&self) -> bool {
        match self {
            Real::Exact(s) => s.is_empty(),
            Real::Approx(x) => *x == 0.0,
        }
    }
}

impl One for Real {
    fn one() -> Real {
        Real::Exact(Surd::one())
    }
}

/// Exact values compare structurally (which is numerically, the form being
/// canonical); anything involving an approximation compares as f64.
impl PartialEq for Real {
    fn eq(&self, other: &Real) -> bool {
        match (self, other) {
            (Real::Exact(a), Real::Exact(b)) => a == b,
            _ => self.to_f64() == other.to_f64(),
        }
    }
}

/// Exact values are ordered by exact sign determination of their difference.
impl PartialOrd for Real {
    fn partial_cmp(&self, other: &Real) -> Option<Ordering> {
        match (self, other) {
            (Real::Exact(a), Real::Exact(b)) => Some(a.cmp(b)),
            _ => self.to_f64().partial_cmp(&other.to_f64()),
        }
    }
}

impl fmt::Display for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Real::Exact(s) => f.write_str(&format::format_surd(s, true)),
            Real::Approx(x) => write!(f, "≈{x}"),
        }
    }
}

impl fmt::Debug for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Real::Exact(s) => write!(f, "Exact({})", format::format_surd(s, false)),
            Real::Approx(x) => write!(f, "Approx({x:?})"),
        }
    }
}

impl Scalar for Real {
    const PRECISION: Precision = Precision::Exact;
    type Mask = bool;

    fn from_real(x: &Real) -> Self {
        x.clone()
    }
    fn from_f64(x: f64) -> Self {
        Real::from_f64(x)
    }
    fn from_i64(x: i64) -> Self {
        Real::from_i64(x)
    }
    fn to_f64(&self) -> f64 {
        Real::to_f64(self)
    }
    fn to_real(&self) -> Real {
        self.clone()
    }
    fn sqrt(&self) -> Self {
        Real::sqrt(self)
    }
    fn abs(&self) -> Self {
        Real::abs(self)
    }
    /// xⁿ by repeated squaring (as the other precisions), each product
    /// [`bounded`]; a power whose numbers would pass
    /// [`surd::MAX_EXACT_BITS`] bits even in the best case
    /// ([`Surd::power_bits`]) is not formed at all: its f64 value,
    /// approximate (`shade --shininess 1e9` is no slower than 4).
    fn powi(&self, n: u32) -> Self {
        if let Real::Exact(s) = self {
            if s.power_bits(n) > surd::MAX_EXACT_BITS {
                grew(BITS);
                return Real::Approx(s.to_f64().powi(n.min(i32::MAX as u32) as i32));
            }
        }
        let (mut acc, mut base, mut e) = (Real::from_i64(1), self.clone(), n);
        while e > 0 {
            if e & 1 == 1 {
                acc *= base.clone();
            }
            e >>= 1;
            if e > 0 {
                base = &base * &base;
            }
        }
        acc
    }
    fn pi() -> Self {
        Real::Approx(std::f64::consts::PI)
    }
    fn tan_deg(&self) -> Self {
        Real::tan_deg(self)
    }
    fn sin_deg(&self) -> Self {
        Real::sin_deg(self)
    }
    fn cos_deg(&self) -> Self {
        Real::cos_deg(self)
    }
    fn is_finite(&self) -> bool {
        match self {
            Real::Exact(_) => true,
            Real::Approx(x) => x.is_finite(),
        }
    }
    fn is_exact(&self) -> bool {
        Real::is_exact(self)
    }
    fn is_zero_value(&self) -> bool {
        Zero::is_zero(self)
    }
    fn shown(&self) -> Shown {
        let value = Real::to_f64(self);
        let beyond = match self {
            Real::Exact(s) if !s.is_empty() && (value == 0.0 || !value.is_finite()) => {
                scientific(s)
            }
            _ => None,
        };
        Shown {
            value,
            exact: self.exact_ascii(),
            pretty: self.exact_pretty().filter(|p| super::format::helps(p)),
            beyond,
        }
    }
    fn root_shown(&self) -> Shown {
        let root = Real::sqrt(self);
        let mut s = Scalar::shown(&root);
        if !root.is_exact() && Real::to_f64(self) > 0.0 {
            s.pretty = Scalar::shown(self).pretty.map(|p| format!("√({p})"));
        }
        s
    }
}

#[cfg(test)]
mod tests;

/// A nonzero surd beyond the doubles as m·10^e, 1 ≤ |m| < 10: s scaled
/// exactly by a power of ten into the doubles' range, its exponent first
/// estimated from the largest term's bit lengths, q·√r ≈ 2^(bits(numerator)
/// − bits(denominator) + bits(r)/2), and corrected when the scaled value is
/// still out of range (a sum whose terms cancel is smaller than its largest).
fn scientific(s: &Surd) -> Option<(f64, i64)> {
    let log2 = (s.terms())
        .map(|(r, q)| q.numer().bits() as f64 - q.denom().bits() as f64 + r.bits() as f64 / 2.0)
        .fold(f64::NEG_INFINITY, f64::max);
    let mut e10 = (log2 * std::f64::consts::LOG10_2).floor() as i64;
    for _ in 0..8 {
        let ten = BigRational::from_integer(BigInt::from(10)).pow(i32::try_from(-e10).ok()?);
        let y = s.scale(&ten).to_f64();
        if y == 0.0 {
            e10 -= 300;
        } else if !y.is_finite() {
            e10 += 300;
        } else {
            let k = y.abs().log10().floor();
            return Some((y / 10f64.powi(k as i32), e10 + k as i64));
        }
    }
    None
}

/// √s of a positive surd as the nearest double, also when s itself is
/// outside the range of doubles (|v|² of v = (1e308, 1e308, 1) is 2e616):
/// √s = 2^m · √(s / 4^m), with m chosen so that s / 4^m is a normal double.
fn scaled_sqrt(s: &Surd) -> f64 {
    let x = s.to_f64();
    if x.is_normal() || (x == 0.0 && s.signum() == 0) {
        return x.sqrt();
    }
    let step: i32 = if x.is_infinite() { 256 } else { -256 };
    let mut m: i32 = 0;
    while m.abs() < 1 << 16 {
        m += step;
        // s / 4^m, exactly
        let four_m = BigRational::from_integer(BigInt::from(4)).pow(-m);
        let y = s.scale(&four_m).to_f64();
        if y.is_normal() {
            return y.sqrt() * 2f64.powi(m);
        }
    }
    if step > 0 {
        f64::INFINITY
    } else {
        0.0
    }
}
