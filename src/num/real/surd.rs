//! The exact field arithmetic behind [`Real`](super::Real): canonical sums
//! Σ qᵣ·√r of rationals times square roots of square-free integers, with
//! rationalizing division, exact sign determination and the square roots that
//! have a closed form (rationals, and `a + b√r` when it denests).
//!
//! Division and sign work over a *coprime basis* of the radicands instead of
//! their prime factors: the radicands are split into pairwise coprime
//! square-free factors g₁ … gₘ (e.g. {6, 10} → {2, 3, 5}, but {6} stays {6}).
//! The square roots of those factors are multiplicatively independent, so
//! √gⱼ ↦ −√gⱼ is a field automorphism of Q(√g₁, …, √gₘ) exactly as for a
//! prime, and no radicand ever has to be factored for `/` or `<`.

use std::cmp::Ordering;
use std::collections::btree_map::Entry;
use std::collections::BTreeMap;
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Trial division stops (and the square root is left approximate) once the
/// divisor passes this bound while the cofactor still exceeds its cube.
const TRIAL_DIVISION_CAP: u64 = 20_000_000;

/// While the cofactor is wider than 128 bits its cube root is far beyond
/// [`TRIAL_DIVISION_CAP`]; only small factors are stripped (2^200·3 still
/// works) before giving up.
const BIG_TRIAL_DIVISION_CAP: u64 = 100_000;

/// A bound on rationalization / sign steps; each step removes one basis
/// element, so this is never reached for radicands of practical size.
const MAX_FIELD_STEPS: usize = 64;

/// The largest exact value kept: a sum of at most this many terms (exact
/// sign determination, too, narrows an interval instead beyond it). A
/// result that would have more (the exact forms of values with many
/// different square roots grow exponentially with them: 2^k terms for a
/// quotient by a sum of k roots) is left approximate by [`super::Real`].
pub const MAX_EXACT_TERMS: usize = 64;

/// The longest exact value kept: no numerator, denominator or radicand of
/// more than this many bits (2466 decimal digits; as the input reader's
/// powers, 2^±8192). Beyond it the arithmetic itself grows costly (the
/// gcds of a product are quadratic in its length: (√5/5)^100000 took
/// 11 s), and no decimal shown needs it; [`super::Real`] leaves such a
/// value approximate.
pub const MAX_EXACT_BITS: u64 = 8192;

/// The most term products one multiplication may form (the product of two
/// sums of [`MAX_EXACT_TERMS`] terms); a larger product is not formed.
pub const MAX_PRODUCTS: usize = MAX_EXACT_TERMS * MAX_EXACT_TERMS;

/// An exact number Σ qᵣ·√r in canonical form: every key r ≥ 1 is square-free
/// (r = 1 is the rational part) and every coefficient qᵣ is nonzero, so two
/// `Surd`s are equal exactly when their values are.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Surd {
    terms: BTreeMap<BigUint, BigRational>,
}

impl Surd {
    /// Zero (no terms).
    pub fn zero() -> Self {
        Surd::default()
    }

    /// One.
    pub fn one() -> Self {
        Surd::from_rational(BigRational::one())
    }

    /// A rational number.
    pub fn from_rational(q: BigRational) -> Self {
        let mut s = Surd::zero();
        s.add_term(BigUint::one(), q);
        s
    }

    /// An integer.
    pub fn from_integer(n: BigInt) -> Self {
        Surd::from_rational(BigRational::from_integer(n))
    }

    /// q·√r for a radicand the caller knows to be square-free (constants).
    pub(crate) fn term_unchecked(q: BigRational, r: u64) -> Self {
        let mut s = Surd::zero();
        s.add_term(BigUint::from(r), q);
        s
    }

    /// The terms (radicand, coefficient), rational part first, radicands
    /// ascending.
    pub fn terms(&self) -> impl Iterator<Item = (&BigUint, &BigRational)> {
        self.terms.iter()
    }

    /// The length in bits of its longest number: numerator, denominator
    /// or radicand of any term.
    pub fn bits(&self) -> u64 {
        (self.terms.iter())
            .map(|(r, q)| r.bits().max(q.numer().bits()).max(q.denom().bits()))
            .max()
            .unwrap_or(0)
    }

    /// A lower bound on [`Surd::bits`] of the n-th power, without forming
    /// it: each factor multiplies the largest term's numerator or
    /// denominator by at least 2^(bits − 1), and its radicand's root by
    /// 2^((bits − 1)/2) more (for one term; a sum of terms grows faster).
    pub fn power_bits(&self, n: u32) -> u64 {
        let floor_log2 = |b: u64| b.saturating_sub(1);
        let per = (self.terms.iter())
            .map(|(r, q)| {
                let q_bits = floor_log2(q.numer().bits()).max(floor_log2(q.denom().bits()));
                2 * q_bits + floor_log2(r.bits())
            })
            .max()
            .unwrap_or(0);
        (per * u64::from(n)) / 2
    }

    /// The number of nonzero terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether this is zero (has no terms).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Whether the value is rational.
    pub fn is_rational(&self) -> bool {
        self.terms.keys().all(One::is_one)
    }

    /// The value as a rational, if it is one.
    pub fn as_rational(&self) -> Option<BigRational> {
        match self.terms.len() {
            0 => Some(BigRational::zero()),
            1 => self.terms.get(&BigUint::one()).cloned(),
            _ => None,
        }
    }

    fn rational_part(&self) -> Option<&BigRational> {
        self.terms.get(&BigUint::one())
    }

    fn add_term(&mut self, r: BigUint, q: BigRational) {
        if q.is_zero() {
            return;
        }
        match self.terms.entry(r) {
            Entry::Occupied(mut e) => {
                *e.get_mut() += q;
                if e.get().is_zero() {
                    e.remove();
                }
            }
            Entry::Vacant(e) => {
                e.insert(q);
            }
        }
    }

    /// This number times a rational.
    pub fn scale(&self, q: &BigRational) -> Surd {
        if q.is_zero() {
            return Surd::zero();
        }
        Surd {
            terms: self.terms.iter().map(|(r, c)| (r.clone(), c * q)).collect(),
        }
    }

    /// The image under √g ↦ −√g (g an element of a coprime basis of the
    /// radicands): every term whose radicand contains g changes sign.
    fn conjugate(&self, g: &BigUint) -> Surd {
        Surd {
            terms: self
                .terms
                .iter()
                .map(|(r, c)| {
                    if (r % g).is_zero() {
                        (r.clone(), -c)
                    } else {
                        (r.clone(), c.clone())
                    }
                })
                .collect(),
        }
    }

    /// Splits self = X + Y·√g with X, Y free of √g (g from a coprime basis).
    fn split(&self, g: &BigUint) -> (Surd, Surd) {
        let mut x = Surd::zero();
        let mut y = Surd::zero();
        for (r, c) in &self.terms {
            let (quot, rem) = r.div_rem(g);
            if rem.is_zero() {
                y.terms.insert(quot, c.clone());
            } else {
                x.terms.insert(r.clone(), c.clone());
            }
        }
        (x, y)
    }

    /// An element of a coprime basis of the radicands > 1, if there are any.
    fn generator(&self) -> Option<BigUint> {
        let basis = coprime_basis(self.terms.keys().filter(|r| !r.is_one()));
        basis.into_iter().max()
    }

    /// The exact sign: −1, 0 or 1.
    ///
    /// A 64-bit interval enclosure settles most cases at once; otherwise
    /// sign(X + Y√g) is found from the signs of X, Y and X² − g·Y², each in a
    /// field with one generator fewer.
    pub fn signum(&self) -> i8 {
        self.sign_with(0, true)
    }

    fn sign_with(&self, depth: usize, filter: bool) -> i8 {
        if self.terms.len() <= 1 {
            return self.terms.values().next().map_or(0, rational_sign);
        }
        if filter {
            if let Some(s) = self.interval_sign(64) {
                return s;
            }
        }
        let g = match self.generator() {
            Some(g) if depth <= MAX_FIELD_STEPS && self.terms.len() <= MAX_EXACT_TERMS => g,
            // Far beyond practical sizes: narrow the enclosure instead (a
            // nonzero value is eventually separated from zero).
            _ => return self.refined_interval_sign(),
        };
        let (x, y) = self.split(&g);
        let sx = x.sign_with(depth + 1, filter);
        let sy = y.sign_with(depth + 1, filter);
        if sy == 0 || sx == sy {
            return sx;
        }
        if sx == 0 {
            return sy;
        }
        // Signs differ: sign(X + Y√g) = sign(X)·sign(X² − g·Y²).
        let gq = BigRational::from_integer(BigInt::from(g));
        let t = &(&x * &x) - &(&y * &y).scale(&gq);
        sx * t.sign_with(depth + 1, filter)
    }

    fn refined_interval_sign(&self) -> i8 {
        let mut k = 256;
        while k <= 1 << 16 {
            if let Some(s) = self.interval_sign(k) {
                return s;
            }
            k *= 4;
        }
        let v = self.to_f64();
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    }

    /// self / d with a rational denominator, or `None` when d is zero (or
    /// too large to rationalize, thousands of terms).
    pub fn checked_div(&self, d: &Surd) -> Option<Surd> {
        if d.is_empty() {
            return None;
        }
        let mut num = self.clone();
        let mut den = d.clone();
        let mut steps = 0;
        while let Some(g) = den.generator() {
            steps += 1;
            let products = den.len() * (num.len() + den.len());
            if steps > MAX_FIELD_STEPS || products > MAX_PRODUCTS {
                return None;
            }
            let conj = den.conjugate(&g);
            num = &num * &conj;
            den = &den * &conj;
        }
        let q = den.as_rational()?;
        if q.is_zero() {
            return None;
        }
        Some(num.scale(&q.recip()))
    }

    /// 1 / self, or `None` for zero.
    pub fn recip(&self) -> Option<Surd> {
        Surd::one().checked_div(self)
    }

    /// √q for a rational q ≥ 0 with square factors pulled out
    /// (√(1/2) = √2/2). `None` for q < 0 or when the radicand is too large
    /// to find its square factors in reasonable time.
    pub fn sqrt_rational(q: &BigRational) -> Option<Surd> {
        if q.is_negative() {
            return None;
        }
        if q.is_zero() {
            return Some(Surd::zero());
        }
        // q = a/b in lowest terms; a = sa²·fa, b = sb²·fb with fa, fb
        // square-free and coprime, so √q = sa/(sb·fb) · √(fa·fb).
        let (sa, fa) = split_square(q.numer().magnitude())?;
        let (sb, fb) = split_square(q.denom().magnitude())?;
        let coef = BigRational::new(BigInt::from(sa), BigInt::from(sb * &fb));
        let mut s = Surd::zero();
        s.add_term(fa * fb, coef);
        Some(s)
    }

    /// √self where it lies in the field: rationals, and `a + b√r` when
    /// a² − b²r is a rational square (denesting). `None` otherwise and for
    /// negative values.
    pub fn sqrt(&self) -> Option<Surd> {
        if let Some(q) = self.as_rational() {
            return Surd::sqrt_rational(&q);
        }
        if self.signum() < 0 || self.terms.len() != 2 {
            return None;
        }
        let a = self.rational_part()?.clone();
        let (r, b) = self.terms.iter().find(|(r, _)| !r.is_one())?;
        let rq = BigRational::from_integer(BigInt::from(r.clone()));
        let disc = &a * &a - b * b * rq;
        let c = rational_square_root(&disc)?;
        let two = BigRational::from_integer(BigInt::from(2));
        let u = Surd::sqrt_rational(&((&a + &c) / &two))?;
        let v = Surd::sqrt_rational(&((&a - &c) / &two))?;
        let root = if b.is_positive() { &u + &v } else { &u - &v };
        // Never return a wrong exact value: check it squares back.
        if &(&root * &root) == self && root.signum() >= 0 {
            Some(root)
        } else {
            None
        }
    }
}

fn rational_sign(q: &BigRational) -> i8 {
    if q.is_positive() {
        1
    } else if q.is_negative() {
        -1
    } else {
        0
    }
}

/// The nonnegative rational c with c² = q, if there is one.
fn rational_square_root(q: &BigRational) -> Option<BigRational> {
    if q.is_negative() {
        return None;
    }
    let n = q.numer().magnitude();
    let d = q.denom().magnitude();
    let sn = n.sqrt();
    let sd = d.sqrt();
    if &(&sn * &sn) == n && &(&sd * &sd) == d {
        Some(BigRational::new(BigInt::from(sn), BigInt::from(sd)))
    } else {
        None
    }
}

/// Refines square-free integers > 1 into a pairwise coprime set whose
/// products give back each input.
fn coprime_basis<'a>(nums: impl Iterator<Item = &'a BigUint>) -> Vec<BigUint> {
    let mut basis: Vec<BigUint> = Vec::new();
    for n in nums {
        let mut x = n.clone();
        let mut i = 0;
        while i < basis.len() && !x.is_one() {
            let g = x.gcd(&basis[i]);
            if g.is_one() {
                i += 1;
                continue;
            }
            // basis[i] = g·(b/g) and x = g·(x/g), all three pairwise coprime
            // (square-free inputs) and g, b/g coprime to the rest of the basis.
            let b = basis.swap_remove(i);
            let rest = &b / &g;
            x /= &g;
            if !rest.is_one() {
                basis.push(rest);
            }
            basis.push(g);
            // swap_remove moved an unchecked element to i: look at it next.
        }
        if !x.is_one() {
            basis.push(x);
        }
    }
    basis
}

/// n = s²·f with f square-free, or `None` when n has a large cofactor that
/// trial division up to [`TRIAL_DIVISION_CAP`] cannot settle.
pub(crate) fn split_square(n: &BigUint) -> Option<(BigUint, BigUint)> {
    let mut m = n.clone();
    let mut s = BigUint::one();
    let mut f = BigUint::one();
    if m.is_zero() {
        return Some((BigUint::zero(), BigUint::one()));
    }
    // Divisors 2, 3, then 6k ± 1.
    let mut d: u64 = 2;
    let mut step: u64 = 2;
    loop {
        if let Some(small) = m.to_u128() {
            let (ss, sf) = split_square_u128(small, d, step)?;
            return Some((s * ss, f * sf));
        }
        if d > BIG_TRIAL_DIVISION_CAP {
            return None;
        }
        let mut e = 0u32;
        while (&m % d).is_zero() {
            m /= d;
            e += 1;
        }
        if e > 0 {
            s *= BigUint::from(d).pow(e / 2);
            if e % 2 == 1 {
                f *= d;
            }
        }
        (d, step) = next_divisor(d, step);
    }
}

fn next_divisor(d: u64, step: u64) -> (u64, u64) {
    match d {
        2 => (3, 2),
        3 => (5, 2),
        _ => (d + step, 6 - step),
    }
}

/// [`split_square`] for a cofactor that fits in a u128, continuing the trial
/// division at divisor `d`.
fn split_square_u128(mut m: u128, mut d: u64, mut step: u64) -> Option<(BigUint, BigUint)> {
    let mut s = BigUint::one();
    let mut f = BigUint::one();
    loop {
        let dd = u128::from(d);
        if dd * dd * dd > m {
            break;
        }
        if d > TRIAL_DIVISION_CAP {
            return None;
        }
        if m.is_multiple_of(dd) {
            let mut e = 0u32;
            while m.is_multiple_of(dd) {
                m /= dd;
                e += 1;
            }
            s *= BigUint::from(d).pow(e / 2);
            if e % 2 == 1 {
                f *= d;
            }
        }
        (d, step) = next_divisor(d, step);
    }
    // Every prime factor of m exceeds ∛m, so m is 1, p, p·q or p².
    if m > 1 {
        let r = BigUint::from(m).sqrt();
        if &r * &r == BigUint::from(m) {
            s *= r;
        } else {
            f *= m;
        }
    }
    Some((s, f))
}

impl PartialOrd for Surd {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Numeric order (exact).
impl Ord for Surd {
    fn cmp(&self, other: &Self) -> Ordering {
        if self == other {
            return Ordering::Equal;
        }
        if let (Some(a), Some(b)) = (self.as_rational(), other.as_rational()) {
            return a.cmp(&b);
        }
        (self - other).signum().cmp(&0)
    }
}

impl AddAssign<&Surd> for Surd {
    fn add_assign(&mut self, rhs: &Surd) {
        for (r, c) in &rhs.terms {
            self.add_term(r.clone(), c.clone());
        }
    }
}

impl SubAssign<&Surd> for Surd {
    fn sub_assign(&mut self, rhs: &Surd) {
        for (r, c) in &rhs.terms {
            self.add_term(r.clone(), -c);
        }
    }
}

impl Add for &Surd {
    type Output = Surd;
    fn add(self, rhs: &Surd) -> Surd {
        let mut out = self.clone();
        out += rhs;
        out
    }
}

impl Sub for &Surd {
    type Output = Surd;
    fn sub(self, rhs: &Surd) -> Surd {
        let mut out = self.clone();
        out -= rhs;
        out
    }
}

impl Mul for &Surd {
    type Output = Surd;
    fn mul(self, rhs: &Surd) -> Surd {
        let mut out = Surd::zero();
        for (r1, q1) in &self.terms {
            for (r2, q2) in &rhs.terms {
                let q = q1 * q2;
                if r1.is_one() {
                    out.add_term(r2.clone(), q);
                } else if r2.is_one() {
                    out.add_term(r1.clone(), q);
                } else if r1 == r2 {
                    out.add_term(BigUint::one(), q * BigInt::from(r1.clone()));
                } else {
                    // √r1·√r2 = g·√((r1/g)(r2/g)), the product square-free.
                    let g = r1.gcd(r2);
                    let r = (r1 / &g) * (r2 / &g);
                    out.add_term(r, q * BigInt::from(g));
                }
            }
        }
        out
    }
}

impl MulAssign<&Surd> for Surd {
    fn mul_assign(&mut self, rhs: &Surd) {
        *self = &*self * rhs;
    }
}

impl Neg for &Surd {
    type Output = Surd;
    fn neg(self) -> Surd {
        Surd {
            terms: self.terms.iter().map(|(r, c)| (r.clone(), -c)).collect(),
        }
    }
}

impl Neg for Surd {
    type Output = Surd;
    fn neg(mut self) -> Surd {
        for c in self.terms.values_mut() {
            *c = -std::mem::take(c);
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn int(n: i64) -> BigRational {
        BigRational::from_integer(BigInt::from(n))
    }

    fn root(n: i64) -> Surd {
        Surd::sqrt_rational(&int(n)).unwrap()
    }

    #[test]
    fn split_square_small_and_large() {
        let check = |n: u128, s: u64, f: u64| {
            let (gs, gf) = split_square(&BigUint::from(n)).unwrap();
            assert_eq!((gs, gf), (BigUint::from(s), BigUint::from(f)), "n = {n}");
        };
        check(1, 1, 1);
        check(8, 2, 2);
        check(72, 6, 2); // 72 = 36·2
        check(49, 7, 1);
        check(30, 1, 30);
        // 1000003 is prime: 1000003² has no factor below its cube root.
        check(1_000_003u128 * 1_000_003, 1_000_003, 1);
        // 2²·999983·1000003 (two large primes) is square-free after the 4.
        check(4 * 999_983u128 * 1_000_003, 2, 999_983 * 1_000_003);
        // A radicand beyond u128: 2^200·3 = (2^100)²·3.
        let big = BigUint::from(3u32) << 200;
        let (s, f) = split_square(&big).unwrap();
        assert_eq!(s, BigUint::one() << 100);
        assert_eq!(f, BigUint::from(3u32));
    }

    #[test]
    fn coprime_basis_refines() {
        let nums = [BigUint::from(6u32), BigUint::from(10u32)];
        let mut b = coprime_basis(nums.iter());
        b.sort();
        assert_eq!(
            b,
            vec![2u32, 3, 5]
                .into_iter()
                .map(BigUint::from)
                .collect::<Vec<_>>()
        );
        let nums = [BigUint::from(6u32), BigUint::from(35u32)];
        let mut b = coprime_basis(nums.iter());
        b.sort();
        assert_eq!(b, vec![BigUint::from(6u32), BigUint::from(35u32)]);
    }

    #[test]
    fn composite_generator_division() {
        // Only √6 appears: the basis is {6} and 1/(1+√6) = (√6−1)/5.
        let d = &Surd::one() + &root(6);
        let inv = d.recip().unwrap();
        let expect = (&root(6) - &Surd::one()).scale(&BigRational::new(1.into(), 5.into()));
        assert_eq!(inv, expect);
    }

    fn exact_sign(s: &Surd) -> i8 {
        s.sign_with(0, false)
    }

    #[test]
    fn exact_sign_without_filter() {
        let one = Surd::one();
        // (√2+√3)² = 5+2√6 < 10: √2+√3−√10 < 0.
        let a = &(&root(2) + &root(3)) - &root(10);
        assert_eq!(exact_sign(&a), -1);
        assert_eq!(exact_sign(&-&a), 1);
        // 3−2√2 > 0 (9 > 8); 1−√2 < 0.
        assert_eq!(
            exact_sign(&(&Surd::from_integer(3.into()) - &(&root(2) + &root(2)))),
            1
        );
        assert_eq!(exact_sign(&(&one - &root(2))), -1);
        // (√10+√11)² = 21+2√110 > (√5+√18)² = 23+2√90 ⇔ √110 − √90 > 1
        // ⇔ 200 − 2√9900 > 1 ⇔ 199² = 39601 > 4·9900 = 39600.
        let b = &(&(&root(10) + &root(11)) - &root(5)) - &root(18);
        assert_eq!(exact_sign(&b), 1);
        // Nested: √2+√3+√5 − √(10+2√6+…) style value with four generators.
        let c = &(&(&root(2) + &root(3)) + &root(5)) - &root(7);
        // √2+√3+√5 ≈ 5.382 > √7 ≈ 2.646.
        assert_eq!(exact_sign(&c), 1);
        assert_eq!(exact_sign(&Surd::zero()), 0);
    }

    #[test]
    fn big_coefficient_sign() {
        // √2 = 1.41421356237309504880168…, so √2·10^20 lies between
        // 141421356237309504880 and the next integer.
        let t = BigInt::parse_bytes(b"141421356237309504880", 10).unwrap();
        let scaled = root(2).scale(&BigRational::from_integer(BigInt::from(10u32).pow(20)));
        let lo = Surd::from_integer(t.clone());
        let hi = Surd::from_integer(t + 1);
        assert_eq!((&scaled - &lo).signum(), 1);
        assert_eq!((&scaled - &hi).signum(), -1);
        assert!(lo < scaled && scaled < hi);
    }

    fn random_surd() -> impl proptest::strategy::Strategy<Value = Surd> {
        use proptest::prelude::*;
        let radicands = [1i64, 2, 3, 5, 6, 7, 10, 14, 15, 21, 30];
        prop::collection::vec((0..radicands.len(), -9i64..=9, 1i64..=5), 0..=5).prop_map(
            move |ts| {
                ts.into_iter().fold(Surd::zero(), |acc, (i, n, d)| {
                    let q = BigRational::new(n.into(), d.into());
                    &acc + &root(radicands[i]).scale(&q)
                })
            },
        )
    }

    proptest::proptest! {
        #[test]
        fn exact_sign_agrees_with_filtered(a in random_surd(), b in random_surd()) {
            proptest::prop_assert_eq!(exact_sign(&a), a.signum());
            // a² − b² has the sign of |a| − |b|: exercises near-cancellation.
            let d = &(&a * &a) - &(&b * &b);
            let abs = |x: &Surd| if x.signum() < 0 { -x } else { x.clone() };
            let e = &abs(&a) - &abs(&b);
            proptest::prop_assert_eq!(exact_sign(&d), e.signum());
            proptest::prop_assert_eq!(d.signum(), exact_sign(&e));
        }
    }
}
