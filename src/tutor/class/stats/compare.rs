//! Whether a variant of an exam is harder or easier than the rest of the
//! class on a problem, said only when the numbers can carry it: a variant
//! is compared with at least [`MIN_STUDENTS`] students on it (and as many
//! in the rest of the class), by a two-proportion z-test of its facility
//! against the rest's, the p-values of one problem's variants corrected
//! by Holm's method, and flagged when the corrected p is below [`LEVEL`].

/// The fewest students a variant (and the rest of the class) needs before
/// it is compared with the others.
pub const MIN_STUDENTS: usize = 5;

/// The level of the test: a variant is flagged when its Holm-corrected
/// p-value is below this.
pub const LEVEL: f64 = 0.05;

/// The upper tail of the standard normal distribution, Q(z) = 1 − Φ(z) =
/// ½·erfc(z/√2), for z of either sign.
pub fn normal_upper_tail(z: f64) -> f64 {
    0.5 * erfc(z / std::f64::consts::SQRT_2)
}

/// The complementary error function erfc(x) = 1 − erf(x), by the Chebyshev
/// fit of Numerical Recipes (`erfcc`; its relative error is below 1.2·10⁻⁷
/// for every x): with t = 1/(1 + |x|/2),
/// erfc(|x|) = t·exp(−x² − 1.26551223 + t·(1.00002368 + t·(…))), and
/// erfc(−x) = 2 − erfc(x).
pub fn erfc(x: f64) -> f64 {
    const C: [f64; 10] = [
        -1.265_512_23,
        1.000_023_68,
        0.374_091_96,
        0.096_784_18,
        -0.186_288_06,
        0.278_868_07,
        -1.135_203_98,
        1.488_515_87,
        -0.822_152_23,
        0.170_872_77,
    ];
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = C.iter().rev().fold(0.0, |acc, c| c + t * acc);
    let r = t * (-z * z + poly).exp();
    if x >= 0.0 {
        r
    } else {
        2.0 - r
    }
}

/// The two-sided p-value of the two-proportion z-test of p₁ (over n₁
/// students) against p₂ (over n₂): with the pooled p̄ = (n₁p₁ + n₂p₂)/(n₁ +
/// n₂), z = (p₁ − p₂) / √(p̄(1 − p̄)(1/n₁ + 1/n₂)) and p = 2·Q(|z|). A
/// facility is a mean of shares of marks in [0, 1], whose variance is at
/// most p̄(1 − p̄) (the variance of a right-or-wrong mark of the same
/// mean), so for partial marks the test is conservative. None when a
/// group is empty or p̄ is 0 or 1 (every student alike: nothing to test).
pub fn two_proportion_p(p1: f64, n1: usize, p2: f64, n2: usize) -> Option<f64> {
    if n1 == 0 || n2 == 0 {
        return None;
    }
    let (a, b) = (n1 as f64, n2 as f64);
    let pooled = (a * p1 + b * p2) / (a + b);
    let var = pooled * (1.0 - pooled) * (1.0 / a + 1.0 / b);
    if var <= 1e-15 {
        return None;
    }
    let z = (p1 - p2) / var.sqrt();
    Some((2.0 * normal_upper_tail(z.abs())).min(1.0))
}

/// Holm's step-down correction of m p-values: sorted p₍₁₎ ≤ … ≤ p₍ₘ₎,
/// the corrected p₍ᵢ₎ is maxⱼ≤ᵢ min(1, (m − j + 1)·p₍ⱼ₎); returned in the
/// order given. Flagging the corrected values below a level keeps the
/// chance of any false flag among the m at most that level.
pub fn holm(p: &[f64]) -> Vec<f64> {
    let m = p.len();
    let mut order: Vec<usize> = (0..m).collect();
    order.sort_by(|&a, &b| p[a].total_cmp(&p[b]));
    let mut out = vec![1.0; m];
    let mut running = 0.0f64;
    for (j, &i) in order.iter().enumerate() {
        running = running.max(((m - j) as f64 * p[i]).min(1.0));
        out[i] = running;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_normal_tail_matches_the_table() {
        // a table of Φ: Φ(0) = 0.5, Φ(1) = 0.841345, Φ(1.96) = 0.975002,
        // Φ(2.575829) = 0.995, Φ(3) = 0.998650
        for (z, q) in [
            (0.0, 0.5),
            (1.0, 0.158_655),
            (1.96, 0.024_998),
            (2.575_829, 0.005),
            (3.0, 0.001_350),
            (-1.0, 0.841_345),
        ] {
            let got = normal_upper_tail(z);
            assert!((got - q).abs() < 2e-6, "Q({z}) = {got}, the table {q}");
        }
        assert!((erfc(0.0) - 1.0).abs() < 1e-7);
    }

    #[test]
    fn two_proportions_by_hand() {
        // 2 of 10 against 8 of 10: p̄ = ½, √(¼·(1/10 + 1/10)) = √0.05 =
        // 0.223607, z = 0.6/0.223607 = 2.683282, p = 2·Q(2.683282); the
        // table: Φ(2.68) = 0.996319, Φ(2.69) = 0.996427, so Φ(2.6833) ≈
        // 0.996355 and p ≈ 0.00729
        let p = two_proportion_p(0.2, 10, 0.8, 10).unwrap();
        assert!((p - 0.00729).abs() < 2e-5, "{p}");
        // 5 students with nothing against 35 with 0.8: p̄ = 28/40 = 0.7,
        // √(0.21·(1/5 + 1/35)) = √0.048 = 0.219089, z = 3.651484; Φ(3.65)
        // = 0.999869, Φ(3.66) = 0.999874: p ≈ 2·0.000130 = 0.00026
        let p = two_proportion_p(0.0, 5, 0.8, 35).unwrap();
        assert!((p - 0.00026).abs() < 1e-5, "{p}");
        // equal facilities: z = 0, p = 1
        assert!((two_proportion_p(0.6, 5, 0.6, 100).unwrap() - 1.0).abs() < 1e-7);
        // one student on 0 against 39 on 0.8: z = 0.8/√(0.78·0.22·(1 +
        // 1/39)) = 0.8/0.419658 = 1.906, p ≈ 0.057: even a zero is not
        // enough to tell, which is why a variant needs 5 students
        let p = two_proportion_p(0.0, 1, 0.8, 39).unwrap();
        assert!(p > LEVEL, "{p}");
        // everyone right, or no one: nothing to test
        assert_eq!(two_proportion_p(1.0, 5, 1.0, 30), None);
        assert_eq!(two_proportion_p(0.0, 5, 0.0, 30), None);
        assert_eq!(two_proportion_p(0.5, 0, 0.5, 30), None);
    }

    #[test]
    fn holm_by_hand() {
        // sorted 0.01, 0.03, 0.04, 0.5 (m = 4): 4·0.01 = 0.04, 3·0.03 =
        // 0.09, max(0.09, 2·0.04) = 0.09, max(0.09, 0.5) = 0.5
        let got = holm(&[0.01, 0.04, 0.03, 0.5]);
        let want = [0.04, 0.09, 0.09, 0.5];
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{got:?}");
        }
        // capped at 1
        assert_eq!(holm(&[0.6, 0.7]), vec![1.0, 1.0]);
        assert!(holm(&[]).is_empty());
    }
}
