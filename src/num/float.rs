//! `Scalar` for `f32` and `f64`: the IEEE types with the error-free
//! transformations that keep the stages accurate near cancellation.

use super::{Precision, Real, Scalar, Shown};

/// Implements `Scalar` for one float type; `$bits` names its to-bits method,
/// `$prec` its precision.
macro_rules! float_scalar {
    ($t:ty, $prec:expr) => {
        impl Scalar for $t {
            const PRECISION: Precision = $prec;
            type Mask = bool;

            fn from_real(x: &Real) -> Self {
                x.to_f64() as $t
            }
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            fn from_i64(x: i64) -> Self {
                x as $t
            }
            fn to_f64(&self) -> f64 {
                *self as f64
            }
            fn to_real(&self) -> Real {
                Real::from_f64(*self as f64)
            }
            fn sqrt(&self) -> Self {
                <$t>::sqrt(*self)
            }
            fn abs(&self) -> Self {
                <$t>::abs(*self)
            }
            fn powi(&self, n: u32) -> Self {
                <$t>::powi(*self, n.min(i32::MAX as u32) as i32)
            }
            fn pi() -> Self {
                std::f64::consts::PI as $t
            }
            /// Through the exact type, so that standard angles (multiples of
            /// 15° and 22.5°) give the correctly rounded value: tan 45° = 1.
            fn tan_deg(&self) -> Self {
                match table_index(*self as f64) {
                    Some(k) => trig_table()[k][2] as $t,
                    None => Real::from_f64(*self as f64).tan_deg().to_f64() as $t,
                }
            }
            /// Through the exact type, so that standard angles (multiples of
            /// 15° and 22.5°) give the correctly rounded value: tan 45° = 1.
            fn sin_deg(&self) -> Self {
                match table_index(*self as f64) {
                    Some(k) => trig_table()[k][0] as $t,
                    None => Real::from_f64(*self as f64).sin_deg().to_f64() as $t,
                }
            }
            /// Through the exact type, so that standard angles (multiples of
            /// 15° and 22.5°) give the correctly rounded value: tan 45° = 1.
            fn cos_deg(&self) -> Self {
                match table_index(*self as f64) {
                    Some(k) => trig_table()[k][1] as $t,
                    None => Real::from_f64(*self as f64).cos_deg().to_f64() as $t,
                }
            }
            /// Kahan: w = c·d; e = fma(−c, d, w) (the rounding error of w);
            /// f = fma(a, b, −w); result f + e. Error ≤ 1.5 ulp of the result.
            #[inline]
            fn diff_of_products(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
                let w = c * d;
                let e = (-c).mul_add(*d, w);
                let f = a.mul_add(*b, -w);
                f + e
            }
            #[inline]
            fn sum_of_products(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
                Self::diff_of_products(a, b, &-c, d)
            }
            /// Compensated dot product (Ogita–Rump–Oishi Dot2 with FMA):
            /// as accurate as if computed in twice the precision, then rounded.
            #[inline]
            fn dot3(a: [&Self; 3], b: [&Self; 3]) -> Self {
                let mut s: $t = 0.0;
                let mut c: $t = 0.0;
                for i in 0..3 {
                    let p = a[i] * b[i];
                    let pe = a[i].mul_add(*b[i], -p); // exact error of the product
                    let t = s + p;
                    let z = t - s;
                    let se = (s - (t - z)) + (p - z); // exact error of the sum (TwoSum)
                    s = t;
                    c += pe + se;
                }
                s + c
            }
            fn hypot3(a: &Self, b: &Self, c: &Self) -> Self {
                let m = a.abs().max(b.abs()).max(c.abs());
                if m == 0.0 || !m.is_finite() {
                    return m;
                }
                // 2^-e with e the exponent of m: scaling by a power of two is exact.
                let e = m.log2().floor();
                let k = (2.0 as $t).powi(-(e as i32));
                let (x, y, z) = (a * k, b * k, c * k);
                Self::dot3([&x, &y, &z], [&x, &y, &z]).sqrt() / k
            }
            fn triple_product(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3]) -> Self {
                let w = |x: [&Self; 3]| [*x[0] as f64, *x[1] as f64, *x[2] as f64];
                let (a, b, c) = (w(a), w(b), w(c));
                let x = f64::diff_of_products(&b[1], &c[2], &b[2], &c[1]);
                let y = f64::diff_of_products(&b[2], &c[0], &b[0], &c[2]);
                let z = f64::diff_of_products(&b[0], &c[1], &b[1], &c[0]);
                f64::dot3([&a[0], &a[1], &a[2]], [&x, &y, &z]) as $t
            }
            fn double_cross_dot(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3]) -> Self {
                let w = |x: [&Self; 3]| [*x[0] as f64, *x[1] as f64, *x[2] as f64];
                let (a, b, c) = (w(a), w(b), w(c));
                let aa = f64::dot3(r(&a), r(&a));
                let bc = f64::dot3(r(&b), r(&c));
                let ab = f64::dot3(r(&a), r(&b));
                let ac = f64::dot3(r(&a), r(&c));
                f64::diff_of_products(&aa, &bc, &ab, &ac) as $t
            }
            fn pow2_scale(xs: &[&Self]) -> Self {
                let m = xs.iter().fold(0.0 as $t, |m, x| m.max(x.abs()));
                if m == 0.0 || !m.is_finite() {
                    return 1.0;
                }
                // e = floor(log2 m) from the f64 exponent bits (m is normal
                // in f64 even when it is a subnormal f32), clamped so that
                // 2^-e is a normal number of this type.
                let bits = (m as f64).to_bits();
                let be = ((bits >> 52) & 0x7ff) as i32;
                let e = if be == 0 { -1023 } else { be - 1023 };
                let e = e.clamp(<$t>::MIN_EXP, <$t>::MAX_EXP - 2);
                f64::from_bits(((1023 - e) as u64) << 52) as $t
            }
            fn is_finite(&self) -> bool {
                <$t>::is_finite(*self)
            }
            fn shown(&self) -> Shown {
                // Shortest decimal that reads back to this value at its own
                // precision, carried in an f64 that prints the same digits.
                let value = format!("{}", self).parse::<f64>().unwrap_or(*self as f64);
                Shown {
                    value,
                    exact: None,
                    pretty: None,
                    beyond: None,
                }
            }
        }
    };
}

/// k mod 48 when x = k·7.5° exactly (the angles whose trig values the table
/// holds), else `None`.
fn table_index(x: f64) -> Option<usize> {
    let k = (x / 7.5).round();
    (k.abs() < 1e12 && k * 7.5 == x).then(|| k.rem_euclid(48.0) as usize)
}

/// sin, cos and tan of k·7.5° for k = 0 … 47, from the exact type once (so
/// the same values as going through `Real` each time, correctly rounded
/// where the value is exact, without its cost on every call).
fn trig_table() -> &'static [[f64; 3]; 48] {
    static TABLE: std::sync::OnceLock<[[f64; 3]; 48]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        std::array::from_fn(|k| {
            let a = Real::from_f64(k as f64 * 7.5);
            [
                a.sin_deg().to_f64(),
                a.cos_deg().to_f64(),
                a.tan_deg().to_f64(),
            ]
        })
    })
}

/// The components of an array by reference.
fn r(x: &[f64; 3]) -> [&f64; 3] {
    [&x[0], &x[1], &x[2]]
}

float_scalar!(f64, Precision::F64);
float_scalar!(f32, Precision::F32);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kahan_difference_of_products_survives_cancellation() {
        // a*b - c*d with a*b and c*d equal to the last bit of their product in
        // f64: (2^27+1)(2^27-1) - 2^54 = -1 exactly, while naive evaluation
        // rounds 2^54 - 1 to 2^54 and returns 0.
        let a = 134_217_729.0_f64;
        let b = 134_217_727.0_f64;
        let c = 134_217_728.0_f64;
        assert_eq!(f64::diff_of_products(&a, &b, &c, &c), -1.0);
    }

    #[test]
    fn compensated_dot_recovers_small_result() {
        // (1e16, 1, -1e16)·(1, 1, 1) = 1, which plain summation loses.
        let x = [1e16, 1.0, -1e16];
        let y = [1.0, 1.0, 1.0];
        assert_eq!(f64::dot3([&x[0], &x[1], &x[2]], [&y[0], &y[1], &y[2]]), 1.0);
    }

    #[test]
    fn trig_table_agrees_with_the_exact_type() {
        // Every multiple of 7.5° from −720° to 720°, and its neighbours
        // (which miss the table), give what the exact type gives.
        for k in -96..=96 {
            let x = k as f64 * 7.5;
            for y in [x, x + 0.25, f64::from_bits(x.to_bits() + 1)] {
                let r = Real::from_f64(y);
                assert_eq!(
                    y.tan_deg().to_bits(),
                    r.tan_deg().to_f64().to_bits(),
                    "tan {y}"
                );
                assert_eq!(
                    y.sin_deg().to_bits(),
                    r.sin_deg().to_f64().to_bits(),
                    "sin {y}"
                );
                assert_eq!(
                    y.cos_deg().to_bits(),
                    r.cos_deg().to_f64().to_bits(),
                    "cos {y}"
                );
            }
        }
        // By hand: tan 45° = 1, sin 30° = 1/2, cos 60° = 1/2 exactly.
        assert_eq!(45.0f64.tan_deg(), 1.0);
        assert_eq!(30.0f64.sin_deg(), 0.5);
        assert_eq!(60.0f32.cos_deg(), 0.5);
    }

    #[test]
    fn f32_shown_prints_short() {
        let s = 0.1f32.shown();
        assert_eq!(format!("{}", s.value), "0.1");
        assert_eq!(s.value as f32, 0.1f32);
    }
}
