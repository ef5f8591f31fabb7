//! Dot products of a camera's axes with a point: a fast certified path from
//! error-free transformations, and an exact rational fallback.
//!
//! The view matrix's last column is −(u·Pe, v·Pe, n·Pe). When |Pe| is large
//! and the camera looks along Pe, u·Pe and v·Pe are small differences of
//! large products, and any rounding inside them is magnified by |Pe|/|u·Pe|
//! (issue 18: 7e5 ulps at f64 for an eye near 2^19). With d = Pe − Pr and
//! up = Vup (each times a power of two, which changes no direction), P = Pe:
//!
//! u·P = (up × d)·P / |up × d| = det[up; d; P] / √Su,   Su = |up × d|²,
//! v·P = (d × (up × d))·P / |d × (up × d)| = (d × up)·(d × P) / √(Sn·Su),
//! n·P = d·P / √Sn,   Sn = d·d
//!
//! (Lagrange's identity: (d × up)·(d × P) = (d·d)(up·P) − (d·up)(d·P), and
//! |d × (up × d)|² = |d|²|up × d|² because d ⊥ up × d).
//!
//! **Fast path** ([`frame_dots_fast`]). Every numerator N and every S above
//! is a sum of products of two, three or four input floats. TwoProduct
//! (h = fl(ab), l = fma(a, b, −h), h + l = ab exactly while |h| ≥ 2^−900)
//! turns each product into a few floats whose sum is exactly the product, so
//! N = Σ pᵢ exactly. Error-free VecSum passes (TwoSum along the vector,
//! Ogita–Rump–Oishi) leave Σ pᵢ unchanged and move it into the last
//! element; after a pass, res = fl(p_last + fl(Σ_{i<last} pᵢ)) satisfies
//! |res − N| ≤ u|res| + γ_m E, E = Σ_{i<last}|pᵢ|, u = 2^−53, γ_m = mu/(1 − mu).
//! Passes repeat (at most [`MAX_PASSES`]) until the running bound certifies
//! γ_m E (1 + 2mu) ≤ u|res|/8, i.e. |res − N| ≤ (9/8)u|res|: relative error
//! δ ≤ 1.13u for each of N and S (Sn·Su is then kept as an exact two-float
//! product, δ ≤ 2.26u for v). Finally q = N/√S is evaluated in double-double
//! (the square root and the quotient each corrected by one fma residual,
//! relative error O(u²)), so q = (N/√S)(1 + η), |η| ≤ δ_N + δ_S/2 + 2⁻¹⁰⁰
//! ≤ 2.3u, and rounding it once to f64 gives an error of at most
//! 0.5 ulp + η|q| ≤ 0.5 + 2.3 = 2.8 ulps (an ulp of q is at least u|q|).
//! At f32 the caller rounds this f64 once more: ≤ 0.5 + 2.8·2^−29 ulps of
//! f32. So every entry is within 4 ulps at f64 and at f32.
//!
//! **Fallback** ([`frame_dots_exact`]): when a product would lose digits to
//! underflow or overflow, or the bound is not met after [`MAX_PASSES`]
//! (extreme cancellation), the numerators and norms are computed with no
//! rounding at all (every f64 is a dyadic rational), then rounded once
//! each; one square root and one division follow, within 2 ulps.

use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

/// VecSum passes tried before the exact fallback.
pub const MAX_PASSES: usize = 4;

/// (u·p, v·p, n·p) for the camera axes u ∥ up × d, v ∥ d × (up × d),
/// n ∥ d, in f64, each within 2.8 ulps of the exact value: the certified fast
/// path, or the exact fallback when it cannot certify. NaN when an input is
/// not finite or an axis is undefined.
pub fn frame_dots(up: [f64; 3], d: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    frame_dots_fast(up, d, p).unwrap_or_else(|| frame_dots_exact(up, d, p))
}

/// The fast path of [`frame_dots`] (see the module's proof): `None` when
/// its error bound cannot certify the result (the caller then takes
/// [`frame_dots_exact`]).
pub fn frame_dots_fast(up: [f64; 3], d: [f64; 3], p: [f64; 3]) -> Option<[f64; 3]> {
    let mut t = Terms::default();
    // Sn = d·d
    for x in d {
        t.prod2(x, x);
    }
    let sn = t.sum()?;
    // Su = |up × d|², each component an exact 2×2 determinant expansion
    let su = cross_exp(up, d)?;
    for c in &su {
        t.prod_exp(c, c);
    }
    let s_u = t.sum()?;
    // Nn = d·P
    for (x, y) in d.into_iter().zip(p) {
        t.prod2(x, y);
    }
    let nn = t.sum()?;
    // Nu = (up × d)·P
    for (c, &pk) in su.iter().zip(&p) {
        t.prod_exp(c, &[pk]);
    }
    let nu = t.sum()?;
    // Nv = (d × up)·(d × P)
    let (dxu, dxp) = (cross_exp(d, up)?, cross_exp(d, p)?);
    for (a, b) in dxu.iter().zip(&dxp) {
        t.prod_exp(a, b);
    }
    let nv = t.sum()?;
    if sn <= 0.0 || s_u <= 0.0 {
        return None;
    }
    let (svh, svl) = two_prod(sn, s_u);
    let r = [
        div_sqrt(nu, s_u, 0.0),
        div_sqrt(nv, svh, svl),
        div_sqrt(nn, sn, 0.0),
    ];
    // A quotient below 2^−900 may have lost digits to underflow.
    let fine = |x: &f64| x.is_finite() && (*x == 0.0 || x.abs() >= SMALL);
    r.iter().all(fine).then_some(r)
}

/// The exact path of [`frame_dots`]: rational numerators and squared norms,
/// each rounded once.
pub fn frame_dots_exact(up: [f64; 3], d: [f64; 3], p: [f64; 3]) -> [f64; 3] {
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

/// u = 2^−53, the unit roundoff of f64.
const U: f64 = f64::EPSILON / 2.0;
/// Products are exact (TwoProduct) while factors and |ab| are within
/// [2^−900, 2^900] (no overflow in the splitting, no underflow in the tail).
const BIG: f64 = 8.452712498170644e270; // 2^900
const SMALL: f64 = 1.1830521861667747e-271; // 2^−900
/// The most terms a numerator expands to: 3 components × 4 × 4 products × 2.
const MAX_TERMS: usize = 96;

/// The floats whose exact sum is one numerator or squared norm.
struct Terms {
    p: [f64; MAX_TERMS],
    n: usize,
    bad: bool,
}

impl Default for Terms {
    fn default() -> Self {
        Terms {
            p: [0.0; MAX_TERMS],
            n: 0,
            bad: false,
        }
    }
}

impl Terms {
    /// Appends ab as h + l exactly.
    fn prod2(&mut self, a: f64, b: f64) {
        match checked_prod(a, b) {
            Some((h, l)) => {
                self.p[self.n] = h;
                self.p[self.n + 1] = l;
                self.n += 2;
            }
            None => self.bad = true,
        }
    }

    /// Appends (Σ aᵢ)(Σ bⱼ) exactly.
    fn prod_exp(&mut self, a: &[f64], b: &[f64]) {
        for &x in a {
            for &y in b {
                self.prod2(x, y);
            }
        }
    }

    /// The sum of the terms, certified to |res − Σ| ≤ (9/8)u|res| by VecSum
    /// passes and the running bound of the module's proof; `None` when not
    /// certified (or a product was not exact). Empties the terms.
    fn sum(&mut self) -> Option<f64> {
        let n = std::mem::take(&mut self.n);
        if self.bad || n == 0 {
            return (!self.bad).then_some(0.0);
        }
        let p = &mut self.p[..n];
        let m = n as f64;
        let gamma = m * U / (1.0 - m * U);
        for _ in 0..MAX_PASSES {
            for i in 1..n {
                (p[i], p[i - 1]) = two_sum(p[i], p[i - 1]);
            }
            let (mut e, mut big) = (0.0, 0.0);
            for &x in &p[..n - 1] {
                e += x;
                big += x.abs();
            }
            let res = p[n - 1] + e;
            if !res.is_finite() {
                return None;
            }
            if gamma * big * (1.0 + 2.0 * m * U) <= U * res.abs() / 8.0 {
                return Some(res);
            }
        }
        None
    }
}

/// TwoSum (Knuth): s + e = a + b exactly, s = fl(a + b).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Veltkamp's split: a = hi + lo with each half 26 bits (|a| < 2^996).
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// TwoProduct (Dekker): h + l = ab exactly, h = fl(ab), with plain
/// arithmetic (no fma call), exact when nothing overflows or underflows.
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let h = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (h, ((ah * bh - h) + ah * bl + al * bh) + al * bl)
}

/// [`two_prod`] where it is known exact: factors and product within
/// [2^−900, 2^900] or a zero factor.
#[inline(always)]
fn checked_prod(a: f64, b: f64) -> Option<(f64, f64)> {
    if a == 0.0 || b == 0.0 {
        return Some((0.0, 0.0));
    }
    let ok = |x: f64| (SMALL..=BIG).contains(&x.abs());
    (ok(a) && ok(b) && ok(a * b)).then(|| two_prod(a, b))
}

/// a × b with each component aᵢbⱼ − aⱼbᵢ kept exactly as four floats.
fn cross_exp(a: [f64; 3], b: [f64; 3]) -> Option<[[f64; 4]; 3]> {
    let det = |i: usize, j: usize| {
        let (h1, l1) = checked_prod(a[i], b[j])?;
        let (h2, l2) = checked_prod(a[j], b[i])?;
        Some([h1, l1, -h2, -l2])
    };
    Some([det(1, 2)?, det(2, 0)?, det(0, 1)?])
}

/// n/√(sh + sl) in double-double, rounded once: √ corrected by its
/// residual, r + rl = √(sh + sl)(1 + O(u²)); the quotient q corrected by
/// its residual, n − q(r + rl).
fn div_sqrt(n: f64, sh: f64, sl: f64) -> f64 {
    let r = sh.sqrt();
    let (rr, rrl) = two_prod(r, r);
    let rl = ((sh - rr) - rrl + sl) / (2.0 * r);
    let q = n / r;
    let (qr, qrl) = two_prod(q, r);
    let rem = ((n - qr) - qrl) - q * rl;
    q + rem / r
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
    /// Whether x = N/√S lies within 4 ulps of q, decided exactly:
    /// q − 4·ulp(q) ≤ x ≤ q + 4·ulp(q), each side by signs and squares
    /// (for r > 0: x ≥ r ⇔ N² ≥ r²S; for r < 0 and N < 0: x ≥ r ⇔ N² ≤ r²S).
    fn within_4_ulps(q: f64, num: &BigRational, norm2: &BigRational) -> bool {
        let e = ((q.abs().to_bits() >> 52) as i32 - 1023).max(-1022);
        let w = 4.0 * 2f64.powi(e - 52).max(f64::from_bits(1));
        let zero = BigRational::zero();
        let sq = |r: f64| {
            let r = BigRational::from_float(r).unwrap();
            (num * num).cmp(&(&r * &r * norm2))
        };
        let ge = |r: f64| match (num >= &zero, r <= 0.0) {
            (true, true) => true,
            (false, false) => false,
            (true, false) => sq(r).is_ge(),
            (false, true) => sq(r).is_le(),
        };
        let le = |r: f64| match (num <= &zero, r >= 0.0) {
            (true, true) => true,
            (false, false) => false,
            (true, false) => sq(r).is_ge(),
            (false, true) => sq(r).is_le(),
        };
        ge(q - w) && le(q + w)
    }

    /// The exact (numerator, squared norm) of u·p, v·p, n·p.
    fn exact_parts(up: [f64; 3], d: [f64; 3], p: [f64; 3]) -> [(BigRational, BigRational); 3] {
        let q = |a: [f64; 3]| flat(a.map(BigRational::from_float)).unwrap();
        let (up, d, p) = (q(up), q(d), q(p));
        let su = cross(&up, &d);
        let sv = cross(&d, &su);
        [
            (dot(&su, &p), dot(&su, &su)),
            (dot(&sv, &p), dot(&sv, &sv)),
            (dot(&d, &p), dot(&d, &d)),
        ]
    }

    fn check(up: [f64; 3], d: [f64; 3], p: [f64; 3]) -> Option<bool> {
        let fast = frame_dots_fast(up, d, p)?;
        let parts = exact_parts(up, d, p);
        Some(
            fast.iter()
                .zip(&parts)
                .all(|(q, (n, s))| within_4_ulps(*q, n, s)),
        )
    }

    #[test]
    fn issue_18_camera_is_certified_by_the_fast_path() {
        // Eye (524286, 524286, 524287), look-at −2^19(1, 1, 1), up
        // (1048573, 1048573, 1048574): d = Pe − Pr = (1048574, 1048574,
        // 1048575), up × d = (−1, 1, 0) (so u·Pe = (−524286 + 524286)/√2 = 0),
        // and v·Pe cancels 2^61-fold. Two VecSum passes certify it, so no
        // fallback is needed; the result is checked exactly against N/√S.
        let (up, d, p) = (
            [1048573.0, 1048573.0, 1048574.0],
            [1048574.0, 1048574.0, 1048575.0],
            [524286.0, 524286.0, 524287.0],
        );
        assert_eq!(check(up, d, p), Some(true));
        assert_eq!(frame_dots_fast(up, d, p).unwrap()[0], 0.0);
    }

    #[test]
    fn the_fallback_is_taken_and_exact_where_products_would_underflow() {
        // Components of 2^−1000: ab would underflow, so TwoProduct is not
        // exact and the fast path must refuse; frame_dots then equals the
        // exact path. d = (1, 0, 0), up = (0, 1, 0), p = (3, 2^−1000, 5):
        // u ∥ up × d = (0, 0, −1) → u·p = −5; v ∥ d × (0,0,−1) = (0, 1, 0)
        // → v·p = 2^−1000; n·p = 3.
        let tiny = 2f64.powi(-1000);
        let (up, d, p) = ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [3.0, tiny, 5.0]);
        assert_eq!(frame_dots_fast([0.0, 1.0, tiny], d, p), None);
        assert_eq!(frame_dots(up, d, p), [-5.0, tiny, 3.0]);
        assert_eq!(
            frame_dots([0.0, 1.0, tiny], d, p),
            frame_dots_exact([0.0, 1.0, tiny], d, p)
        );
    }

    use proptest::prelude::*;

    /// A far-eye camera with integer coordinates up to 2^bits: Pr ≈ −Pe and
    /// up ≈ 2Pe, so u·Pe and v·Pe cancel.
    fn far_int(bits: u32) -> impl Strategy<Value = ([f64; 3], [f64; 3], [f64; 3])> {
        let m = 1i64 << bits;
        let s = 8i64;
        (
            prop::array::uniform3(-m..=m),
            prop::array::uniform3(-s..=s),
            prop::array::uniform3(-s..=s),
        )
            .prop_map(|(pe, a, b)| {
                let f = |x: i64| x as f64;
                let d = [0, 1, 2].map(|i| f(2 * pe[i] + a[i]));
                let up = [0, 1, 2].map(|i| f(2 * pe[i] + b[i]));
                (up, d, pe.map(f))
            })
    }

    /// A float 1e-30..1e30 in magnitude, either sign.
    fn wide() -> impl Strategy<Value = f64> {
        (-30.0f64..30.0, 1.0f64..10.0, any::<bool>()).prop_map(|(e, m, neg)| {
            if neg {
                -m * 10f64.powf(e)
            } else {
                m * 10f64.powf(e)
            }
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        #[test]
        fn fast_path_within_4_ulps_of_exact_for_far_integer_eyes(
            (up, d, p) in prop::sample::select(vec![10u32, 20, 26, 30, 40]).prop_flat_map(far_int),
        ) {
            if let Some(ok) = check(up, d, p) { prop_assert!(ok, "{up:?} {d:?} {p:?}"); }
            let got = frame_dots(up, d, p);
            if got.iter().all(|x| x.is_finite()) {
                let parts = exact_parts(up, d, p);
                for (q, (n, s)) in got.iter().zip(&parts) {
                    prop_assert!(within_4_ulps(*q, n, s));
                }
            }
        }

        #[test]
        fn fast_path_within_4_ulps_of_exact_for_wide_floats(
            pe in prop::array::uniform3(wide()),
            pr in prop::array::uniform3(wide()),
            up in prop::array::uniform3(wide()),
            far in any::<bool>(),
        ) {
            // far: Pr = −Pe(1 + tiny) and up near Pe, the cancelling case.
            let pr = if far { pe.map(|x| -x * (1.0 + 1e-9)) } else { pr };
            let up = if far { [pe[0], pe[1] * (1.0 + 1e-12), pe[2]] } else { up };
            let d = [0, 1, 2].map(|i| pe[i] - pr[i]);
            if let Some(ok) = check(up, d, pe) { prop_assert!(ok, "{up:?} {d:?} {pe:?}"); }
        }
    }
}
