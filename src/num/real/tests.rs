//! Tests of [`Real`](super::Real); expected values are derived by hand in the
//! comments.

use super::*;
use proptest::prelude::*;

fn int(n: i64) -> Real {
    Real::from_i64(n)
}

fn rat(n: i64, d: i64) -> Real {
    Real::from_ratio(n, d)
}

fn root(n: i64) -> Real {
    int(n).sqrt()
}

fn ascii(x: &Real) -> String {
    x.exact_ascii().unwrap()
}

fn pretty(x: &Real) -> String {
    x.exact_pretty().unwrap()
}

fn dec(s: &str) -> Real {
    Real::from_decimal(s).unwrap()
}

#[test]
fn canonical_square_roots() {
    // √8 = √(4·2) = 2√2.
    assert_eq!(root(8), int(2) * root(2));
    assert_eq!(ascii(&root(8)), "2*sqrt(2)");
    assert_eq!(pretty(&root(8)), "2√2");
    // √(1/2) = √2/2.
    assert_eq!(rat(1, 2).sqrt(), root(2) / int(2));
    assert_eq!(ascii(&rat(1, 2).sqrt()), "sqrt(2)/2");
    // √(18/50) = √(9/25) = 3/5 is rational.
    assert_eq!(rat(18, 50).sqrt(), rat(3, 5));
    // √0.1 = √(1/10) = √10/10.
    assert_eq!(ascii(&dec("0.1").sqrt()), "sqrt(10)/10");
    assert_eq!(ascii(&root(1)), "1");
    assert_eq!(ascii(&root(0)), "0");
}

#[test]
fn rationalized_division() {
    // 6/√2 = 6√2/2 = 3√2, and the negative forms agree.
    assert_eq!(int(6) / root(2), int(3) * root(2));
    assert_eq!(ascii(&(int(6) / root(2))), "3*sqrt(2)");
    assert_eq!(int(-6) / root(2), -(int(3) * root(2)));
    assert_eq!(int(6) / -root(2), int(-3) * root(2));
    // 1/(√2−1) = (√2+1)/((√2)²−1) = √2+1.
    let x = int(1) / (root(2) - int(1));
    assert_eq!(x, root(2) + int(1));
    // Rational part first (the stated term order).
    assert_eq!(ascii(&x), "1+sqrt(2)");
    // 1/(√2+√3) = (√3−√2)/(3−2) = √3−√2.
    let x = int(1) / (root(2) + root(3));
    assert_eq!(x, root(3) - root(2));
    assert_eq!(ascii(&x), "sqrt(3)-sqrt(2)");
    assert_eq!(pretty(&x), "√3−√2");
    // (1+√2+√3)(1+√2−√3) = (1+√2)²−3 = 2√2, so
    // 1/(1+√2+√3) = (1+√2−√3)/(2√2) = (√2+2−√6)/4.
    let x = int(1) / (int(1) + root(2) + root(3));
    assert_eq!(x, (int(2) + root(2) - root(6)) / int(4));
    assert_eq!(ascii(&x), "(2+sqrt(2)-sqrt(6))/4");
    // 1/(√6+√10+√15): basis {2,3,5} reached only through gcds.
    // (√6+√10+√15)·(√6+√10−√15) = (√6+√10)² − 15 = 1 + 2√60 = 1 + 4√15,
    // and (1+4√15)(1−4√15) = 1 − 240 = −239, so the inverse is
    // (√6+√10−√15)(1−4√15)/(−239); check by multiplying back instead.
    let d = root(6) + root(10) + root(15);
    assert_eq!((int(1) / &d) * &d, int(1));
    // (1+√2)(1−√2) = 1−2 = −1.
    assert_eq!((int(1) + root(2)) * (int(1) - root(2)), int(-1));
}

#[test]
fn denesting() {
    // (1+√2)² = 3+2√2.
    let x = (int(3) + int(2) * root(2)).sqrt();
    assert_eq!(x, int(1) + root(2));
    assert!(x.is_exact());
    // (√2+√3)² = 5+2√6.
    assert_eq!((int(5) + int(2) * root(6)).sqrt(), root(2) + root(3));
    // (√3−1)² = 4−2√3.
    assert_eq!((int(4) - int(2) * root(3)).sqrt(), root(3) - int(1));
    // 2+√2: 4−2 = 2 is not a square, no denesting; √(2+√2) = 2cos 22.5°.
    let y = (int(2) + root(2)).sqrt();
    assert!(!y.is_exact());
    assert!((y.to_f64() - 1.847_759_065_022_573_5).abs() < 1e-15);
    // Negative radicands are NaN, never a panic.
    assert!(int(-2).sqrt().to_f64().is_nan());
    assert!((int(1) - root(2)).sqrt().to_f64().is_nan());
    assert!(!(int(1) - root(2)).sqrt().is_exact());
}

#[test]
fn course_numbers() {
    let d = rat(-1, 10);
    let z = int(-6) / root(2);
    let y = int(-1);
    // d·y/z = (1/10)·(−√2/6) = −√2/60.
    let v = &d * &y / &z;
    assert_eq!(v, -(root(2) / int(60)));
    assert_eq!(ascii(&v), "-sqrt(2)/60");
    assert_eq!(pretty(&v), "−√2/60");
    // d·(1/√2)/(−5/√2) = d·(−1/5) = 1/50.
    let w = &d * (int(1) / root(2)) / (int(-5) / root(2));
    assert_eq!(w, rat(1, 50));
    assert_eq!(ascii(&w), "1/50");
    // 0.1·tan 22.5° = (√2−1)/10.
    let t = dec("0.1") * rat(45, 2).tan_deg();
    assert_eq!(ascii(&t), "(sqrt(2)-1)/10");
    assert_eq!(pretty(&t), "(√2−1)/10");
    assert_eq!(t.to_string(), "(√2−1)/10");
}

#[test]
fn trig_table() {
    assert_eq!(int(15).tan_deg(), int(2) - root(3));
    assert_eq!(ascii(&int(15).tan_deg()), "2-sqrt(3)");
    assert_eq!(int(75).tan_deg(), int(2) + root(3));
    assert_eq!(int(45).tan_deg(), int(1));
    assert_eq!(rat(45, 2).tan_deg(), root(2) - int(1));
    assert_eq!(rat(135, 2).tan_deg(), root(2) + int(1));
    assert_eq!(rat(225, 2).tan_deg(), -(root(2) + int(1)));
    assert_eq!(ascii(&rat(225, 2).tan_deg()), "-1-sqrt(2)");
    assert_eq!(rat(-45, 2).tan_deg(), int(1) - root(2));
    assert_eq!(ascii(&rat(-45, 2).tan_deg()), "1-sqrt(2)");
    assert_eq!(int(60).sin_deg(), root(3) / int(2));
    assert_eq!(int(135).cos_deg(), -(root(2) / int(2)));
    assert_eq!(ascii(&int(135).cos_deg()), "-sqrt(2)/2");
    assert_eq!(int(-30).sin_deg(), rat(-1, 2));
    assert_eq!(int(390).sin_deg(), rat(1, 2));
    assert_eq!(int(210).sin_deg(), rat(-1, 2));
    assert_eq!(int(300).cos_deg(), rat(1, 2));
    assert_eq!(int(-45).cos_deg(), root(2) / int(2));
    assert_eq!(int(720).sin_deg(), int(0));
    assert_eq!(int(180).cos_deg(), int(-1));
    assert_eq!(int(135).tan_deg(), int(-1));
    assert_eq!(int(30).tan_deg(), root(3) / int(3));
    assert_eq!(ascii(&int(30).tan_deg()), "sqrt(3)/3");
    assert_eq!(int(60).tan_deg(), root(3));
    // sin 15° = (√6−√2)/4, cos 15° = (√6+√2)/4.
    assert_eq!(ascii(&int(15).sin_deg()), "(sqrt(6)-sqrt(2))/4");
    assert_eq!(ascii(&int(15).cos_deg()), "(sqrt(2)+sqrt(6))/4");
    assert_eq!(int(105).sin_deg(), int(15).cos_deg());
    // tan 90° is undefined: not finite, no panic.
    assert!(!int(90).tan_deg().is_finite());
    assert!(!int(-90).tan_deg().is_finite());
    assert!(!int(270).tan_deg().is_finite());
    // tan 50° has no exact form here.
    let t = int(50).tan_deg();
    assert!(!t.is_exact());
    assert!((t.to_f64() - 1.191_753_592_594_209_8).abs() < 1e-14);
    // sin 22.5° = √(2−√2)/2 does not denest.
    let s = rat(45, 2).sin_deg();
    assert!(!s.is_exact());
    assert!((s.to_f64() - 0.382_683_432_365_089_8).abs() < 1e-15);
    assert!(!rat(45, 2).cos_deg().is_exact());
    // A non-standard rational angle and an approximate angle.
    assert!(!int(1).sin_deg().is_exact());
    assert!(!Real::Approx(45.0).tan_deg().is_exact());
    assert!((int(1).sin_deg().to_f64() - 0.017_452_406_437_283_51).abs() < 1e-16);
}

#[test]
fn exact_signs() {
    // (√2+√3)² = 5+2√6 ≈ 9.899 < 10, so √2+√3−√10 < 0.
    let a = root(2) + root(3) - root(10);
    assert_eq!(a.signum(), -1);
    assert!(a < int(0));
    // √2 = 1.41421356237… > 1.41421356.
    assert_eq!((root(2) - dec("1.41421356")).signum(), 1);
    assert_eq!((root(2) - dec("1.41421357")).signum(), -1);
    // 3−2√2 = 3−√8, 9 > 8.
    assert_eq!((int(3) - int(2) * root(2)).signum(), 1);
    // (√5+√7)² = 12+2√35 ≈ 23.83 < (√3+√11)² = 14+2√33 ≈ 25.49.
    assert!(root(5) + root(7) < root(3) + root(11));
    assert!(root(3) + root(11) > root(5) + root(7));
    // (√10+√11)² = 21+2√110 ≈ 41.97618 > (√5+3√2)² = 23+6√10 ≈ 41.97367:
    // a difference of only 1.9e-4.
    assert!(root(10) + root(11) > root(5) + int(3) * root(2));
    // Equal values in different forms compare equal.
    let p = int(1) / (root(2) - int(1));
    assert_eq!(p.partial_cmp(&(root(2) + int(1))), Some(Ordering::Equal));
    // abs through the trait.
    assert_eq!(Scalar::abs(&(int(1) - root(2))), root(2) - int(1));
    assert_eq!(int(0).signum(), 0);
}

#[test]
fn float_conversion() {
    assert_eq!(rat(1, 3).to_f64(), 1.0 / 3.0);
    assert_eq!(rat(1, 10).to_f64(), "0.1".parse::<f64>().unwrap());
    let big = Real::from_bigint(BigInt::from(10u32).pow(300)) / int(7);
    assert_eq!(
        big.to_f64(),
        "1.4285714285714285714285714285714285714e299"
            .parse::<f64>()
            .unwrap()
    );
    let tiny = Real::from_f64(f64::from_bits(1)) * rat(3, 4);
    assert_eq!(tiny.to_f64(), f64::from_bits(1));
    // √2·10^20 − 141421356237309504880 = 0.16887242096980785696718753769…
    // (digits of √2): the terms cancel to 21 digits.
    let c = root(2) * Real::from_bigint(BigInt::from(10u32).pow(20))
        - Real::from_decimal("141421356237309504880").unwrap();
    assert_eq!(
        c.to_f64(),
        "0.16887242096980785696718753769".parse::<f64>().unwrap()
    );
    // …and to 41 digits: √2·10^40 − 14142135623730950488016887242096980785696
    // = 0.71875376948073176679737990732…
    let c = root(2) * Real::from_bigint(BigInt::from(10u32).pow(40))
        - Real::from_decimal("14142135623730950488016887242096980785696").unwrap();
    assert_eq!(
        c.to_f64(),
        "0.71875376948073176679737990732".parse::<f64>().unwrap()
    );
    // √2/2 = √0.5, which f64::sqrt rounds correctly.
    assert_eq!((root(2) / int(2)).to_f64(), 0.5f64.sqrt());
    assert_eq!(Real::from_f64(0.1), Real::from_rational(convert_exact(0.1)));
    assert_ne!(Real::from_f64(0.1), dec("0.1"));
    assert!(!Real::from_f64(f64::NAN).is_finite());
}

fn convert_exact(x: f64) -> BigRational {
    // 0.1 = 0x3FB999999999999A: exponent 0x3FB − 1075 = −56, significand
    // 0x1999999999999A, so 0.1 = 0x1999999999999A·2^-56.
    assert_eq!(x, 0.1);
    BigRational::new(
        BigInt::from(0x0019_9999_9999_999a_u64),
        BigInt::from(1u64 << 56),
    )
}

#[test]
fn formatting() {
    assert_eq!(ascii(&int(0)), "0");
    assert_eq!(ascii(&rat(-1, 2)), "-1/2");
    assert_eq!(pretty(&rat(-1, 2)), "−1/2");
    assert_eq!(ascii(&(int(3) * root(2) / int(2))), "3*sqrt(2)/2");
    assert_eq!(pretty(&(int(3) * root(2) / int(2))), "3√2/2");
    assert_eq!(ascii(&(root(6) / int(3))), "sqrt(6)/3");
    assert_eq!(ascii(&((int(1) + root(5)) / int(4))), "(1+sqrt(5))/4");
    // 1/2 + √2/3 = (3 + 2√2)/6.
    assert_eq!(ascii(&(rat(1, 2) + root(2) / int(3))), "(3+2*sqrt(2))/6");
    // All terms negative: minus in front of the fraction.
    let n = -(int(1) + root(2)) / int(10);
    assert_eq!(ascii(&n), "-(1+sqrt(2))/10");
    assert_eq!(pretty(&n), "−(1+√2)/10");
    assert_eq!(ascii(&-(int(1) + root(2))), "-1-sqrt(2)");
    // Leading negative term moves behind the first positive one.
    assert_eq!(ascii(&(root(3) - int(1) - root(5))), "sqrt(3)-1-sqrt(5)");
    assert_eq!(ascii(&(int(-2) * root(7))), "-2*sqrt(7)");
    assert_eq!(pretty(&(int(-2) * root(7))), "−2√7");
    assert_eq!(Real::Approx(0.5).to_string(), "≈0.5");
    assert_eq!(Real::Approx(0.5).exact_ascii(), None);
    assert_eq!(format!("{:?}", root(2) + int(1)), "Exact(1+sqrt(2))");
}

#[test]
fn shown_and_scalar() {
    let s = Scalar::shown(&(root(2) / int(2)));
    assert_eq!(s.value, 0.5f64.sqrt());
    assert_eq!(s.exact.as_deref(), Some("sqrt(2)/2"));
    assert_eq!(s.pretty.as_deref(), Some("√2/2"));
    let s = Scalar::shown(&Real::pi());
    assert_eq!(s.value, std::f64::consts::PI);
    assert_eq!((s.exact, s.pretty), (None, None));
    assert_eq!(Real::PRECISION, Precision::Exact);
    assert!(!Scalar::is_exact(&Real::pi()));
    assert!(Scalar::is_exact(&root(2)));
    // (√2)^5 = 4√2.
    assert_eq!(Scalar::powi(&root(2), 5), int(4) * root(2));
    assert!(Scalar::is_zero_value(&(root(2) * root(2) - int(2))));
    assert_eq!(<Real as Scalar>::from_real(&root(3)), root(3));
    assert_eq!(<Real as Scalar>::from_f64(0.25), rat(1, 4));
    fn needs_scalar<T: Scalar>(x: T) -> T {
        T::diff_of_products(&x, &x, &T::one(), &T::one())
    }
    // (√3)² − 1 = 2.
    assert_eq!(needs_scalar(root(3)), int(2));
}

#[test]
fn zero_division_and_approx() {
    let inf = int(1) / int(0);
    assert!(!Scalar::is_finite(&inf) && inf.to_f64() > 0.0);
    assert_eq!((int(-1) / int(0)).to_f64(), f64::NEG_INFINITY);
    assert!((int(0) / int(0)).to_f64().is_nan());
    assert!(!Scalar::is_finite(&(root(2) / (root(2) - root(2)))));
    let mut x = int(1);
    x /= Real::zero();
    assert!(!Scalar::is_finite(&x));
    assert!(!Scalar::is_finite(&Real::from_ratio(1, 0)));
    // Approximations contaminate: the result is never falsely exact.
    let a = Real::Approx(0.5) + rat(1, 2);
    assert!(!a.is_exact());
    assert_eq!(a.to_f64(), 1.0);
    assert!(!(Real::pi() * int(0)).is_exact());
    assert_eq!(rat(1, 2), Real::Approx(0.5));
    assert!(Real::Approx(f64::NAN) != Real::Approx(f64::NAN));
    assert_eq!(Real::Approx(f64::NAN).partial_cmp(&int(0)), None);
}

#[test]
fn send_sync_static() {
    fn check<T: Send + Sync + 'static>() {}
    check::<Real>();
}

/// A random sum of `len` terms (n/d)·√r with small radicands.
fn surd_with(len: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Real> {
    let radicands = [1i64, 2, 3, 5, 6, 7, 10, 12, 15];
    prop::collection::vec((0..radicands.len(), -12i64..=12, 1i64..=9), len).prop_map(move |ts| {
        ts.into_iter().fold(Real::zero(), |acc, (i, n, d)| {
            acc + rat(n, d) * root(radicands[i])
        })
    })
}

/// Up to three terms, zero included.
fn surd() -> impl Strategy<Value = Real> {
    surd_with(0..=3)
}

/// One to three terms, filtered to be nonzero.
fn nonzero_surd() -> impl Strategy<Value = Real> {
    surd_with(1..=3).prop_filter("nonzero", |x| !x.is_zero())
}

/// Σ (n/d)·√r in plain f64, as an independent reference.
fn naive(ts: &[(i64, i64, i64)]) -> f64 {
    ts.iter()
        .map(|&(r, n, d)| n as f64 / d as f64 * (r as f64).sqrt())
        .sum()
}

proptest! {
    #[test]
    fn add_then_sub(a in surd(), b in surd()) {
        prop_assert_eq!((&a + &b) - &b, a);
    }

    #[test]
    fn mul_then_div(a in surd(), b in nonzero_surd()) {
        prop_assert_eq!((&a * &b) / &b, a);
    }

    #[test]
    fn reciprocal(a in nonzero_surd()) {
        let inv = Real::one() / &a;
        prop_assert!(inv.is_exact());
        prop_assert_eq!(&a * &inv, Real::one());
    }

    #[test]
    fn distributive(a in surd(), b in surd(), c in surd()) {
        prop_assert_eq!(&a * (&b + &c), &a * &b + &a * &c);
    }

    #[test]
    fn rational_square_roots(n in 0i64..100_000, d in 1i64..1000) {
        let x = rat(n, d);
        let r = x.sqrt();
        prop_assert!(r.is_exact());
        prop_assert_eq!(&r * &r, x.clone());
        prop_assert_eq!((&x * &x).sqrt(), x);
    }

    #[test]
    fn squares_denest(a in -20i64..=20, b in -20i64..=20, ri in 0usize..6) {
        let r = [2i64, 3, 5, 6, 7, 10][ri];
        let y = int(a) + int(b) * root(r);
        prop_assert_eq!((&y * &y).sqrt(), Scalar::abs(&y));
    }

    #[test]
    fn sign_matches_float(
        ts in prop::collection::vec((0usize..9, -12i64..=12, 1i64..=9), 1..=4)
    ) {
        let radicands = [1i64, 2, 3, 5, 6, 7, 10, 11, 15];
        let ts: Vec<(i64, i64, i64)> =
            ts.into_iter().map(|(i, n, d)| (radicands[i], n, d)).collect();
        let x = ts.iter().fold(Real::zero(), |acc, &(r, n, d)| acc + rat(n, d) * root(r));
        let f = naive(&ts);
        prop_assume!(f.abs() > 1e-9);
        prop_assert_eq!(x.signum(), if f > 0.0 { 1 } else { -1 });
        prop_assert_eq!(x > Real::zero(), f > 0.0);
        let v = x.to_f64();
        prop_assert!((v - f).abs() <= 1e-13 * (1.0 + f.abs()), "{} vs {}", v, f);
    }

    #[test]
    fn ratio_rounds_like_ieee_division(
        n in -(1i64 << 53)..(1i64 << 53),
        d in -(1i64 << 53)..(1i64 << 53),
    ) {
        prop_assume!(d != 0);
        // n, d are exact doubles, so IEEE n/d is the correctly rounded quotient.
        prop_assert_eq!(rat(n, d).to_f64(), n as f64 / d as f64);
    }

    #[test]
    fn root_rounds_like_ieee_sqrt(n in 0i64..(1i64 << 53), k in 0u32..40) {
        // √(n/4^k) = √n/2^k, and f64::sqrt is correctly rounded.
        let x = rat(n, 1) / Real::from_bigint(BigInt::from(4u64).pow(k));
        let expect = (n as f64).sqrt() / f64::powi(2.0, k as i32);
        prop_assert_eq!(x.sqrt().to_f64(), expect);
    }

    #[test]
    fn float_round_trip(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let r = Real::from_f64(x);
        prop_assert!(r.is_rational());
        prop_assert_eq!(r.to_f64().to_bits(), x.to_bits() & if x == 0.0 { 0 } else { u64::MAX });
    }

    #[test]
    fn decimal_matches_float_parse(m in 1u64..10_000_000_000, e in -330i32..300) {
        let s = format!("{m}e{e}");
        prop_assert_eq!(dec(&s).to_f64(), s.parse::<f64>().unwrap());
    }
}

#[test]
fn the_square_root_of_a_surd_beyond_the_doubles_is_scaled_not_infinite() {
    let ten = |k: u32| BigInt::from(10).pow(k);
    // 2·10^616 + 1 (|v|² of v = (1e308, 1e308, 1)) is no double, but its
    // root √2·10^308 ≈ 1.414e308 is one (below 1.797e308).
    let big = Real::from_rational(BigRational::from_integer(ten(616) * 2 + 1));
    let want = std::f64::consts::SQRT_2 * 1e308;
    let r = big.sqrt();
    assert!(
        (r.to_f64() - want).abs() <= 4.0 * f64::EPSILON * want,
        "{r}"
    );
    // 3·10^-600 + 10^-900 underflows as a double; its root √3·10^-300 does not.
    let small = BigRational::new(BigInt::from(3), ten(600)) + BigRational::new(1.into(), ten(900));
    let want = 3f64.sqrt() * 1e-300;
    let t = Real::from_rational(small).sqrt();
    assert!(
        (t.to_f64() - want).abs() <= 4.0 * f64::EPSILON * want,
        "{t}"
    );
}

#[test]
fn an_exact_value_past_64_terms_is_left_approximate_and_marked() {
    // 1/(√2 + √3 + … + √p8) rationalized has 2^7 = 128 terms: past the
    // bound, so it is the f64 quotient, and the mark is set once.
    let primes = [2, 3, 5, 7, 11, 13, 17, 19];
    let sum = primes
        .iter()
        .fold(Real::from_i64(0), |acc, &p| acc + Real::from_i64(p).sqrt());
    take_grew_too_large();
    let q = Real::from_i64(1) / &sum;
    assert!(!q.is_exact());
    let want: f64 = 1.0 / primes.iter().map(|&p| (p as f64).sqrt()).sum::<f64>();
    assert!((q.to_f64() - want).abs() <= 4.0 * f64::EPSILON * want);
    assert!(take_grew_too_large().terms);
    assert_eq!(
        take_grew_too_large(),
        Grew::default(),
        "the mark is cleared when read"
    );
    // Three roots stay exact: 1/(√2 + √3 + √5) has 4 terms.
    let small = Real::from_i64(1)
        / (Real::from_i64(2).sqrt() + Real::from_i64(3).sqrt() + Real::from_i64(5).sqrt());
    assert!(small.is_exact());
    assert_eq!(take_grew_too_large(), Grew::default());
}

#[test]
fn a_power_past_8192_bits_is_left_approximate_without_forming_it() {
    take_grew_too_large();
    // (2/3)^5000 = 2^5000/3^5000: 3^5000 has ⌊5000·log2 3⌋ + 1 = 7925 bits,
    // within the bound: exact, and its decimal is found from it although
    // the double is 0: log10 = 5000·log10(2/3) = 5000·(−0.1760912…) =
    // −880.4563…, so 10^(1 − 0.4563) = 10^0.5437 = 3.4971 times 10^−881.
    let two_thirds = Real::from_ratio(2, 3);
    let p = Scalar::powi(&two_thirds, 5000);
    assert!(p.is_exact(), "{p}");
    assert_eq!(p.to_f64(), 0.0);
    let shown = Scalar::shown(&p);
    let (m, e) = shown.beyond.expect("beyond the doubles");
    assert_eq!(e, -881);
    assert!((m - 3.4971).abs() < 1e-3, "{m}");
    assert_eq!(take_grew_too_large(), Grew::default());
    // (2/3)^30000: 3^30000 has 47,549 bits. Not formed: the f64 power.
    let p = Scalar::powi(&two_thirds, 30_000);
    assert!(!p.is_exact());
    assert!(take_grew_too_large().bits);
    // (√5/5)^100000 and ^10^9 likewise (the exponent costs nothing).
    let b = Real::from_i64(5).sqrt() / Real::from_i64(5);
    for n in [100_000, 1_000_000_000] {
        assert!(!Scalar::powi(&b, n).is_exact());
        assert!(take_grew_too_large().bits, "(√5/5)^{n}");
    }
    // 1ⁿ, 0ⁿ and (−1)ⁿ stay exact for any n; 2^8000 too (8001 bits).
    for (x, n, want) in [(1, 1_000_000_000u32, 1.0), (0, 7, 0.0), (-1, 999_999, -1.0)] {
        let p = Scalar::powi(&Real::from_i64(x), n);
        assert!(p.is_exact() && p.to_f64() == want, "{x}^{n}");
    }
    assert!(Scalar::powi(&Real::from_i64(2), 8000).is_exact());
    assert_eq!(take_grew_too_large(), Grew::default());
    // A sum that grows past the bound is left approximate too.
    let big = Real::from_bigint(BigInt::from(1) << 8191usize);
    assert!((&big * &big).to_f64().is_infinite());
    assert!(take_grew_too_large().bits);
}
