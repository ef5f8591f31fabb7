//! Conversions between exact numbers and floats/text: correctly rounded
//! rational → f64, correctly rounded surd → f64 (by interval refinement),
//! the exact rational value of an f64, and exact decimal parsing.

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::surd::Surd;

/// Decimal exponents beyond this are refused by [`parse_decimal`] (the exact
/// value of `1e999999999` would not fit in memory).
const MAX_DECIMAL_EXPONENT: i64 = 100_000;

/// Refinement rounds for an irrational value before settling for the
/// midpoint of the last interval.
const MAX_REFINEMENTS: u32 = 10;

/// n ≥ d·2^e ?
fn ge_scaled(n: &BigUint, d: &BigUint, e: i64) -> bool {
    if e >= 0 {
        *n >= d << (e as u64)
    } else {
        n << (e.unsigned_abs()) >= *d
    }
}

/// The f64 nearest n/d (ties to even), with IEEE overflow to ±∞, gradual
/// underflow, and n/0 as IEEE division by +0 gives it. The fraction need not
/// be in lowest terms.
pub(crate) fn ratio_to_f64(n: &BigInt, d: &BigInt) -> f64 {
    if d.is_zero() {
        return nonzero_over_zero(n);
    }
    let negative = (n.sign() == Sign::Minus) != (d.sign() == Sign::Minus);
    let v = magnitude_to_f64(n.magnitude(), d.magnitude());
    if negative {
        -v
    } else {
        v
    }
}

fn nonzero_over_zero(n: &BigInt) -> f64 {
    match n.sign() {
        Sign::Plus => f64::INFINITY,
        Sign::Minus => f64::NEG_INFINITY,
        Sign::NoSign => f64::NAN,
    }
}

fn magnitude_to_f64(n: &BigUint, d: &BigUint) -> f64 {
    if n.is_zero() {
        return 0.0;
    }
    // n/d ∈ [2^E, 2^(E+1)).
    let e = n.bits() as i64 - d.bits() as i64;
    let exp = if ge_scaled(n, d, e) { e } else { e - 1 };
    if exp > 1024 {
        return f64::INFINITY;
    }
    if exp < -1075 {
        return 0.0;
    }
    // The spacing of doubles at this magnitude is 2^q.
    let mut q = exp.max(-1022) - 52;
    let (num, den) = if q <= 0 {
        (n << q.unsigned_abs(), d.clone())
    } else {
        (n.clone(), d << (q as u64))
    };
    let (m, rem) = num.div_rem(&den);
    let mut m = m.to_u64().unwrap_or(u64::MAX);
    match (rem << 1u32).cmp(&den) {
        std::cmp::Ordering::Greater => m += 1,
        std::cmp::Ordering::Equal if m & 1 == 1 => m += 1,
        _ => {}
    }
    if m == 1 << 53 {
        m = 1 << 52;
        q += 1;
    }
    if m >= 1 << 52 {
        let biased = q + 52 + 1023;
        if biased >= 2047 {
            return f64::INFINITY;
        }
        f64::from_bits(((biased as u64) << 52) | (m & ((1 << 52) - 1)))
    } else {
        // Subnormal: q = −1074 and m is the raw significand.
        f64::from_bits(m)
    }
}

/// The f64 nearest a rational.
pub(crate) fn rational_to_f64(q: &BigRational) -> f64 {
    ratio_to_f64(q.numer(), q.denom())
}

/// The exact value of a finite float; `None` for ±∞ and NaN.
pub(crate) fn f64_to_rational(x: f64) -> Option<BigRational> {
    if !x.is_finite() {
        return None;
    }
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1 << 52) - 1);
    let (m, e) = if biased == 0 {
        (frac, -1074)
    } else {
        (frac | (1 << 52), biased - 1075)
    };
    let mut n = BigInt::from(m);
    if negative {
        n = -n;
    }
    Some(if e >= 0 {
        BigRational::from_integer(n << (e as u64))
    } else {
        BigRational::new(n, BigInt::one() << e.unsigned_abs())
    })
}

/// Parses `123`, `-1.25`, `.5`, `2.5e-7`, `1E30` exactly (0.1 = 1/10).
pub(crate) fn parse_decimal(s: &str) -> Option<BigRational> {
    let s = s.trim();
    let (negative, s) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    };
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], Some(&s[i + 1..])),
        None => (s, None),
    };
    let (int_part, frac_part) = match mantissa.find('.') {
        Some(i) => (&mantissa[..i], &mantissa[i + 1..]),
        None => (mantissa, ""),
    };
    let all_digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
    if int_part.len() + frac_part.len() == 0 || !all_digits(int_part) || !all_digits(frac_part) {
        return None;
    }
    let mut exp: i64 = match exponent {
        None => 0,
        Some(t) => {
            let (neg, digits) = match t.as_bytes().first() {
                Some(b'-') => (true, &t[1..]),
                Some(b'+') => (false, &t[1..]),
                _ => (false, t),
            };
            if digits.is_empty() || !all_digits(digits) {
                return None;
            }
            let trimmed = digits.trim_start_matches('0');
            if trimmed.len() > 12 {
                return None;
            }
            let v: i64 = if trimmed.is_empty() {
                0
            } else {
                trimmed.parse().ok()?
            };
            if neg {
                -v
            } else {
                v
            }
        }
    };
    exp -= frac_part.len() as i64;
    let digits = format!("{int_part}{frac_part}");
    let mut n = BigInt::parse_bytes(digits.as_bytes(), 10)?;
    if n.is_zero() {
        return Some(BigRational::zero());
    }
    if exp.abs() > MAX_DECIMAL_EXPONENT {
        return None;
    }
    if negative {
        n = -n;
    }
    let p = BigInt::from(10u32).pow(exp.unsigned_abs() as u32);
    Some(if exp >= 0 {
        BigRational::from_integer(n * p)
    } else {
        BigRational::new(n, p)
    })
}

/// A surd over a common denominator, ready to be enclosed in intervals.
struct Enclosure<'a> {
    /// Common denominator L of the coefficients.
    l: BigInt,
    /// (r, cᵣ) with the value Σ cᵣ·√r / L.
    coefs: Vec<(&'a BigUint, BigInt)>,
}

impl<'a> Enclosure<'a> {
    fn new(s: &'a Surd) -> Self {
        let mut l = BigInt::one();
        for (_, q) in s.terms() {
            l = l.lcm(q.denom());
        }
        let coefs = s
            .terms()
            .map(|(r, q)| (r, q.numer() * (&l / q.denom())))
            .collect();
        Enclosure { l, coefs }
    }

    /// (lo, hi, den) with lo/den ≤ value ≤ hi/den, den > 0: each √r is
    /// replaced by its k-bit floor and ceiling, so the width is about 2^-k
    /// of the terms' size.
    fn at(&self, k: u64) -> (BigInt, BigInt, BigInt) {
        let mut lo = BigInt::zero();
        let mut hi = BigInt::zero();
        for (r, c) in &self.coefs {
            if r.is_one() {
                let v = c << k;
                lo += &v;
                hi += v;
                continue;
            }
            // √r·2^k ∈ [s, s+1) with s = ⌊√(r·4^k)⌋.
            let s = BigInt::from((*r << (2 * k)).sqrt());
            let a = c * &s;
            let b = &a + c;
            if c.is_positive() {
                lo += a;
                hi += b;
            } else {
                lo += b;
                hi += a;
            }
        }
        (lo, hi, &self.l << k)
    }
}

impl Surd {
    /// The f64 nearest the value (correctly rounded: the value is enclosed in
    /// an interval of rationals that is narrowed until both ends round to the
    /// same double; an irrational value never sits on a rounding boundary).
    pub fn to_f64(&self) -> f64 {
        if let Some(q) = self.as_rational() {
            return rational_to_f64(&q);
        }
        let enc = Enclosure::new(self);
        // k doubles each time cancellation leaves the interval too coarse.
        let mut k: u64 = 64;
        let mut mid = 0.0;
        for _ in 0..MAX_REFINEMENTS {
            let (lo, hi, den) = enc.at(k);
            let flo = ratio_to_f64(&lo, &den);
            let fhi = ratio_to_f64(&hi, &den);
            if flo == fhi {
                return flo;
            }
            mid = ratio_to_f64(&(lo + hi), &(den << 1u32));
            k *= 2;
        }
        mid
    }

    /// The sign, if an enclosure with `k` bits per root excludes zero.
    pub(crate) fn interval_sign(&self, k: u64) -> Option<i8> {
        let (lo, hi, _) = Enclosure::new(self).at(k);
        if lo.is_positive() {
            Some(1)
        } else if hi.is_negative() {
            Some(-1)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ratio(n: &str, d: &str) -> f64 {
        ratio_to_f64(
            &BigInt::parse_bytes(n.as_bytes(), 10).unwrap(),
            &BigInt::parse_bytes(d.as_bytes(), 10).unwrap(),
        )
    }

    fn pow2(e: i64) -> BigRational {
        if e >= 0 {
            BigRational::from_integer(BigInt::one() << (e as u64))
        } else {
            BigRational::new(BigInt::one(), BigInt::one() << e.unsigned_abs())
        }
    }

    #[test]
    fn simple_ratios() {
        assert_eq!(
            ratio("1", "3"),
            "0.333333333333333333333333333333333"
                .parse::<f64>()
                .unwrap()
        );
        assert_eq!(ratio("1", "10"), 0.1);
        assert_eq!(ratio("-7", "2"), -3.5);
        assert_eq!(ratio("0", "5"), 0.0);
        assert_eq!(ratio("6", "-4"), -1.5);
        // Unreduced fractions are fine.
        assert_eq!(ratio("20", "200"), 0.1);
    }

    #[test]
    fn huge_ratio() {
        let n = format!("1{}", "0".repeat(300));
        let expect = "1.428571428571428571428571428571428571428571e299"
            .parse::<f64>()
            .unwrap();
        assert_eq!(ratio(&n, "7"), expect);
    }

    #[test]
    fn subnormals_and_ties() {
        let tiny = |q: BigRational| rational_to_f64(&q);
        assert_eq!(tiny(pow2(-1074)), f64::from_bits(1));
        // 0.75·2^-1074 rounds up to 2^-1074; exactly half rounds to even 0.
        assert_eq!(tiny(pow2(-1076) * BigInt::from(3)), f64::from_bits(1));
        assert_eq!(tiny(pow2(-1075)), 0.0);
        // A hair above half rounds up.
        let above = pow2(-1075) + pow2(-1200);
        assert_eq!(tiny(above), f64::from_bits(1));
        // 1.5·2^-1074 is a tie between 1 and 2 ulps: even is 2.
        assert_eq!(tiny(pow2(-1075) * BigInt::from(3)), f64::from_bits(2));
        assert_eq!(tiny(pow2(-1100)), 0.0);
        // Largest subnormal and smallest normal.
        let max_sub = (pow2(52) - BigRational::one()) * pow2(-1074);
        assert_eq!(tiny(max_sub), f64::from_bits((1 << 52) - 1));
        assert_eq!(tiny(pow2(-1022)), f64::MIN_POSITIVE);
        assert_eq!(
            ratio("1", &format!("1{}", "0".repeat(320))),
            "1e-320".parse::<f64>().unwrap()
        );
    }

    #[test]
    fn overflow_boundary() {
        // MAX = (2^53−1)·2^971; halfway to 2^1024 ties to even, i.e. up to ∞.
        let max = (pow2(53) - BigRational::one()) * pow2(971);
        assert_eq!(rational_to_f64(&max), f64::MAX);
        let half = pow2(1024) - pow2(970);
        assert_eq!(rational_to_f64(&half), f64::INFINITY);
        let below = &half - pow2(900);
        assert_eq!(rational_to_f64(&below), f64::MAX);
        assert_eq!(rational_to_f64(&-pow2(1100)), f64::NEG_INFINITY);
    }

    #[test]
    fn float_round_trip_values() {
        let q = f64_to_rational(0.1).unwrap();
        // 0.1 as a double is 3602879701896397/2^55.
        assert_eq!(
            q,
            BigRational::new(3602879701896397u64.into(), BigInt::one() << 55u32)
        );
        assert_eq!(
            f64_to_rational(-2.0).unwrap(),
            BigRational::from_integer((-2).into())
        );
        assert_eq!(f64_to_rational(f64::from_bits(1)).unwrap(), pow2(-1074));
        assert!(f64_to_rational(f64::NAN).is_none());
        assert!(f64_to_rational(f64::INFINITY).is_none());
    }

    #[test]
    fn decimals() {
        let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
        assert_eq!(parse_decimal("123"), Some(r(123, 1)));
        assert_eq!(parse_decimal("1.25"), Some(r(5, 4)));
        assert_eq!(parse_decimal(".5"), Some(r(1, 2)));
        assert_eq!(parse_decimal("0.1"), Some(r(1, 10)));
        assert_eq!(parse_decimal("-0.1"), Some(r(-1, 10)));
        assert_eq!(parse_decimal("2.5e-7"), Some(r(1, 4_000_000)));
        assert_eq!(
            parse_decimal("1E30"),
            Some(BigRational::from_integer(BigInt::from(10u32).pow(30)))
        );
        assert_eq!(parse_decimal("3."), Some(r(3, 1)));
        assert_eq!(parse_decimal("0e5"), Some(r(0, 1)));
        assert_eq!(parse_decimal("+7e0"), Some(r(7, 1)));
        for bad in [
            "",
            ".",
            "e5",
            "1e",
            "1e+",
            "abc",
            "1.2.3",
            "--1",
            "1e5.5",
            "1e99999999",
        ] {
            assert_eq!(parse_decimal(bad), None, "{bad:?}");
        }
    }
}
