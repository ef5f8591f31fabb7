//! Dot products of a camera's axes with a point, from exact products.
//!
//! The view matrix's last column is (−u·Pe, −v·Pe, −n·Pe). When |Pe| is
//! large and the camera looks along Pe, u·Pe and v·Pe are small differences
//! of large products, and any rounding inside them is magnified by
//! |Pe|/|u·Pe| (issue 18: 7e5 ulps at f64 for an eye near 2^19). Every f64 is
//! a dyadic rational, so the numerators
//!
//! u·P = (Vup × d)·P / |Vup × d|,
//! v·P = (d × (Vup × d))·P / |d × (Vup × d)| = ((d·d)(Vup·P) − (d·Vup)(d·P)) / |…|,
//! n·P = d·P / |d|
//!
//! and the squared norms are computed here with no rounding at all (big
//! integers over powers of two), then rounded once each; one square root
//! and one division follow, so each result is within 2 ulps of the exact
//! value.

use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

/// (u·p, v·p, n·p) for the camera axes u ∥ up × d, v ∥ d × (up × d),
/// n ∥ d, in f64. NaN when an input is not finite or an axis is undefined.
pub fn frame_dots(up: [f64; 3], d: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let q = |a: [f64; 3]| a.map(BigRational::from_float);
    let (Some(up), Some(d), Some(p)) = (flat(q(up)), flat(q(d)), flat(q(p))) else {
        return [f64::NAN; 3];
    };
    let su = cross(&up, &d);
    let sv = cross(&d, &su);
    [
        ratio(&dot(&su, &p), &dot(&su, &su)),
        ratio(&dot(&sv, &p), &dot(&sv, &sv)),
        ratio(&dot(&d, &p), &dot(&d, &d)),
    ]
}

type Q3 = [BigRational; 3];

fn flat(a: [Option<BigRational>; 3]) -> Option<Q3> {
    let [x, y, z] = a;
    Some([x?, y?, z?])
}

fn cross(a: &Q3, b: &Q3) -> Q3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &Q3, b: &Q3) -> BigRational {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// num / √(norm2), each rounded once to f64 (NaN for a zero norm).
fn ratio(num: &BigRational, norm2: &BigRational) -> f64 {
    if norm2.is_zero() {
        return f64::NAN;
    }
    let n = num.to_f64().unwrap_or(f64::NAN);
    let s = norm2.to_f64().unwrap_or(f64::NAN);
    n / s.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_dots_by_hand() {
        // The text's example 6.1: d = Pe − Pr = (4, 3, 0), up = (0, 1, 0):
        // up × d = (0, 0, −4) → u = (0, 0, −1); v = (−3/5, 4/5, 0);
        // n = (4/5, 3/5, 0). With P = Pe = (4, 4, 4): u·P = −4,
        // v·P = −12/5 + 16/5 = 4/5, n·P = 16/5 + 12/5 = 28/5.
        let r = frame_dots([0.0, 1.0, 0.0], [4.0, 3.0, 0.0], [4.0, 4.0, 4.0]);
        assert_eq!(r, [-4.0, 0.8, 5.6]);
    }

    #[test]
    fn an_undefined_axis_or_an_infinite_input_gives_nan() {
        assert!(frame_dots([1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [1.0; 3])[0].is_nan());
        assert!(frame_dots([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [f64::INFINITY; 3])[0].is_nan());
    }
}
