//! Accuracy of the float stages against the exact path: the error measure
//! (ulps against the exact value), a fixed set of random and adversarial
//! inputs for every stage, and the evaluation of one stage on one input at
//! any precision. `grafika bench` and the stress tests use it.
//!
//! The inputs are reproducible: they come from [`InputRng`], i.e. SplitMix64 (Steele, Lea
//! and Flood's generator, the one `java.util.SplittableRandom` uses) with a
//! fixed seed, so every run measures the same set.
//!
//! Every input value is exactly representable in f32 (integers below 2^24,
//! or a 24-bit integer times a power of two), so the f32, f64 and exact runs
//! all solve the same problem and the error measured is the error of the
//! computation alone, not of reading the inputs.
//!
//! What the measurement shows (issue 3, point 4), and why:
//!
//! - basis, view, project, clip on integers up to 2^20 (near-parallel up
//!   vectors down to 5e-13 rad, points next to the plane of the centre of
//!   projection, segment ends on box planes included): within 4 ulps at
//!   f64 and f32 (about 0.5–2.2 ulps measured). The formulas that make it
//!   so: cross products by Kahan's FMA difference of products; eye
//!   coordinates as triple products of the *inputs* (not of rounded axes),
//!   evaluated in f64 for f32; projection as one scaled x·num/den; clip
//!   intersections as one quotient of exact differences measured from the
//!   end nearer the plane.
//! - window: no target in the issue. The edges are within 1.5 ulps; the
//!   viewport mapping (xp − left)/width·W cancels when xp is near an edge,
//!   and the rounding of left (tan of the half angle, rounded once, then
//!   two products) is magnified by |left|/|xp − left|: tens of ulps
//!   measured. Removing it needs the edges to more than working precision.
//! - values from 1e-30 to 1e30 are outside the target's domain: the
//!   differences of inputs of unlike magnitude (P1 − P0, bound − P0) are
//!   themselves rounded, and no formula over the rounded differences can
//!   recover the lost digits in general; measured and reported. Where the
//!   exact square roots of such inputs are beyond `Real` (radicands it
//!   cannot factor), the case has no reference and is not counted.
//! - f32 results beyond the f32 range are errors (the projection says so),
//!   never infinities.

use crate::num::vec::V3;
use crate::num::{Precision, Real, Scalar};
use crate::stages::camera::{self, Basis, Camera};
use crate::stages::clip::{self, ClipBox};
use crate::stages::projection::{self, Projection};
use crate::stages::trace::NoTrace;
use crate::stages::window;

/// The input generator: [`crate::num::rng::SplitMix64`] (the generator behind
/// `grafika generate`) with the draws the input set needs. `below` is the
/// plain modulo reduction, fixed here because the input set depends on it.
#[derive(Clone, Debug)]
pub struct InputRng(crate::num::rng::SplitMix64);

impl InputRng {
    /// A generator starting from `seed`.
    pub fn new(seed: u64) -> InputRng {
        InputRng(crate::num::rng::SplitMix64::new(seed))
    }

    /// A number in 0..n (n ≥ 1; the modulo bias is below 2^-40 for the
    /// small n used here).
    pub fn below(&mut self, n: u64) -> u64 {
        self.0.next_u64() % n.max(1)
    }

    /// An integer in −m..=m.
    pub fn int(&mut self, m: i64) -> i64 {
        self.below(2 * m as u64 + 1) as i64 - m
    }

    /// An integer in lo..=hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }

    /// An integer of magnitude up to 2^k with k itself random in 1..=max_bits,
    /// so that small and large magnitudes are both common.
    pub fn int_bits(&mut self, max_bits: u32) -> i64 {
        let k = 1 + self.below(max_bits as u64) as u32;
        self.int(1i64 << k)
    }

    /// A value ± m·2^e with m a random 24-bit integer and the magnitude
    /// between about 1e-30 and 1e30 (exact in f32).
    pub fn wide(&mut self) -> f64 {
        let m = self.range(1 << 23, (1 << 24) - 1) as f64;
        let e = self.range(-123, 75) as i32;
        let s = if self.below(2) == 0 { 1.0 } else { -1.0 };
        s * m * pow2(e)
    }
}

/// 2^k as an f64 (k from −1074 to 1023), exact.
pub fn pow2(k: i32) -> f64 {
    if k >= -1022 {
        f64::from_bits(((k + 1023).clamp(0, 2046) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (k + 1074).clamp(0, 51))
    }
}

/// The unit in the last place of `x` at precision `prec` (the spacing of
/// the floats in x's binade; the smallest subnormal for 0). Exact uses f64.
pub fn ulp(x: f64, prec: Precision) -> f64 {
    let a = x.abs();
    let e = if a == 0.0 || !a.is_finite() {
        i32::MIN / 2
    } else {
        // floor(log2 a), exact from the bits (subnormals included).
        let bits = a.to_bits();
        let be = (bits >> 52) as i32;
        if be == 0 {
            -1011 - (bits.leading_zeros() as i32)
        } else {
            be - 1023
        }
    };
    match prec {
        Precision::F32 => pow2(e.clamp(-126, 127) - 23),
        _ => pow2((e - 52).max(-1074)),
    }
}

/// The error of `computed` against the exact value, in ulps of the exact
/// value at precision `prec` — or in ulps of 1 when `unit` (components of
/// unit vectors, whose error matters relative to the vector's length).
///
/// The difference is taken exactly (every float is a rational) and rounded
/// once; a non-finite computed value counts as an infinite error. An
/// approximate `exact` (no exact form) is compared as an f64.
pub fn ulp_error(computed: f64, exact: &Real, unit: bool, prec: Precision) -> f64 {
    if !computed.is_finite() {
        return f64::INFINITY;
    }
    let diff = if exact.is_exact() {
        (Real::from_f64(computed) - exact).abs().to_f64()
    } else {
        (computed - exact.to_f64()).abs()
    };
    let scale = if unit { 1.0 } else { exact.to_f64() };
    diff / ulp(scale, prec)
}

/// The pipeline stages measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stage {
    /// Camera basis u, v, n.
    Basis,
    /// Eye coordinates of a world point.
    View,
    /// Perspective projection of an eye-coordinate point.
    Project,
    /// Window edges and the viewport mapping.
    Window,
    /// Outcode clipping of a segment.
    Clip,
}

impl Stage {
    /// All stages in pipeline order.
    pub const ALL: [Stage; 5] = [
        Stage::Basis,
        Stage::View,
        Stage::Project,
        Stage::Window,
        Stage::Clip,
    ];

    /// The stage's name in the table.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Basis => "basis",
            Stage::View => "view",
            Stage::Project => "project",
            Stage::Window => "window",
            Stage::Clip => "clip",
        }
    }

    /// Whether issue 3's 4-ulp target applies to this stage's outputs (the
    /// window is not among the quantities the target names).
    pub fn has_target(self) -> bool {
        !matches!(self, Stage::Window)
    }
}

/// Where an input came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Random integers of magnitude up to 2^20 (the accuracy target's domain).
    Random,
    /// Integers up to about 2^20, up vector within 1e-6 … 5e-13 rad of the
    /// view direction (target domain too).
    NearParallel,
    /// Integers up to 2^20 placed on or next to a plane of the problem
    /// (projection plane, box planes): target domain.
    Grazing,
    /// Values from about 1e-30 to 1e30 (24-bit mantissas): outside the
    /// target's domain, measured and reported.
    Wide,
}

impl Kind {
    /// Whether the 4-ulp target applies to inputs of this kind.
    pub fn in_target(self) -> bool {
        !matches!(self, Kind::Wide)
    }
}

type P3 = [f64; 3];

/// A camera and a world point.
#[derive(Clone, Debug)]
pub struct CameraCase {
    /// Where the case came from.
    pub kind: Kind,
    /// Eye.
    pub pe: P3,
    /// Look-at point.
    pub pr: P3,
    /// Up vector.
    pub up: P3,
    /// A world point for eye coordinates.
    pub p: P3,
}

/// A projection and an eye-coordinate point.
#[derive(Clone, Debug)]
pub struct ProjectCase {
    /// Where the case came from.
    pub kind: Kind,
    /// `None`: plane z = d with d = `a`; `Some(zvp)`: COP at z = `a`, plane z = zvp.
    pub zvp: Option<f64>,
    /// d, or zprp.
    pub a: f64,
    /// The point (eye coordinates).
    pub p: P3,
}

/// A window set-up and a point to map to the viewport.
#[derive(Clone, Debug)]
pub struct WindowCase {
    /// Where the case came from.
    pub kind: Kind,
    /// fovy in degrees (a standard angle, so the exact path stays exact).
    pub fovy: f64,
    /// aspect (a dyadic rational).
    pub aspect: f64,
    /// near.
    pub near: f64,
    /// (xp, yp).
    pub pt: (f64, f64),
    /// Viewport W, H.
    pub size: (f64, f64),
}

/// A box and a segment.
#[derive(Clone, Debug)]
pub struct ClipCase {
    /// Where the case came from.
    pub kind: Kind,
    /// Box min.
    pub min: P3,
    /// Box max.
    pub max: P3,
    /// P0.
    pub p0: P3,
    /// P1.
    pub p1: P3,
}

/// The fixed input set.
#[derive(Clone, Debug, Default)]
pub struct Inputs {
    /// For basis and view.
    pub cameras: Vec<CameraCase>,
    /// For project.
    pub projects: Vec<ProjectCase>,
    /// For window.
    pub windows: Vec<WindowCase>,
    /// For clip.
    pub clips: Vec<ClipCase>,
}

impl Inputs {
    /// The number of cases of a stage.
    pub fn len(&self, s: Stage) -> usize {
        match s {
            Stage::Basis | Stage::View => self.cameras.len(),
            Stage::Project => self.projects.len(),
            Stage::Window => self.windows.len(),
            Stage::Clip => self.clips.len(),
        }
    }

    /// Whether a stage has no cases.
    pub fn is_empty(&self, s: Stage) -> bool {
        self.len(s) == 0
    }

    /// The kind of case `i` of stage `s`.
    pub fn kind(&self, s: Stage, i: usize) -> Kind {
        match s {
            Stage::Basis | Stage::View => self.cameras[i].kind,
            Stage::Project => self.projects[i].kind,
            Stage::Window => self.windows[i].kind,
            Stage::Clip => self.clips[i].kind,
        }
    }
}

/// The seed of the fixed input set.
pub const SEED: u64 = 0x6772_6166_696b_6133; // "grafika3"

const M20: i64 = 1 << 20;

fn f3(a: [i64; 3]) -> P3 {
    [a[0] as f64, a[1] as f64, a[2] as f64]
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

/// (x, y) with a·y − b·x = 1 for coprime a, b > 0, 0 ≤ x ≤ a, 0 ≤ y ≤ b.
fn farey_neighbour(a: i64, b: i64) -> (i64, i64) {
    // Extended Euclid: s·a + t·b = 1 → y = s (mod b), x = −t (mod a).
    let (mut r0, mut r1, mut s0, mut s1, mut t0, mut t1) = (a, b, 1i64, 0i64, 0i64, 1i64);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    let y = s0.rem_euclid(b);
    let x = (a * y - 1) / b;
    debug_assert_eq!(a * y - b * x, 1);
    let _ = t0;
    (x, y)
}

/// Permutes and sign-flips the axes of both vectors the same way (a
/// rotation or reflection: angles are kept).
fn shuffle(rng: &mut InputRng, a: &mut [i64; 3], b: &mut [i64; 3]) {
    let p = crate::num::rng::PERMUTATIONS_OF_3[rng.below(6) as usize];
    let (a0, b0) = (*a, *b);
    for k in 0..3 {
        a[k] = a0[p[k]];
        b[k] = b0[p[k]];
        if rng.below(2) == 1 {
            a[k] = -a[k];
            b[k] = -b[k];
        }
    }
}

/// The fixed input set: `n` random cases per stage plus about `n`
/// adversarial ones (half near-parallel/grazing integers, half wide-range).
/// The cases are drawn in a fixed order from one generator.
pub fn inputs(n: usize) -> Inputs {
    let mut rng = InputRng::new(SEED);
    let mut out = Inputs::default();
    random_cameras(&mut rng, n, &mut out.cameras);
    near_parallel_cameras(&mut rng, n, &mut out.cameras);
    wide_cameras(&mut rng, n, &mut out.cameras);
    random_projects(&mut rng, n, &mut out.projects);
    grazing_projects(&mut rng, n, &mut out.projects);
    wide_projects(&mut rng, n, &mut out.projects);
    windows(&mut rng, n, &mut out.windows);
    random_clips(&mut rng, n, &mut out.clips);
    grazing_clips(&mut rng, n, &mut out.clips);
    wide_clips(&mut rng, n, &mut out.clips);
    // From a generator of their own, so that the cases above stay the same.
    far_eye_cameras(&mut InputRng::new(SEED ^ 18), n, &mut out.cameras);
    out
}

/// Cameras: `n / 2` with the eye near 2^19…2^20 looking back through the
/// origin, so that u·Pe and v·Pe (the view matrix's last column) are small
/// differences of products near 2^39 (issue 18). Integers within 2^20: the
/// target domain.
fn far_eye_cameras(rng: &mut InputRng, n: usize, out: &mut Vec<CameraCase>) {
    for i in 0..n / 2 {
        let pe = [0; 3]
            .map(|_: i32| rng.range(M20 / 2, M20 - 1) * if rng.below(2) == 0 { 1 } else { -1 });
        let pr = pe.map(|x| -x + rng.int(2));
        // Up: nearly along the view direction (as in the issue), or random.
        let up = if i % 2 == 0 {
            pe.map(|x| (2 * x).clamp(-(M20 - 1), M20 - 1) + rng.int(3))
        } else {
            r20(rng)
        };
        out.push(CameraCase {
            kind: Kind::Random,
            pe: f3(pe),
            pr: f3(pr),
            up: f3(up),
            p: f3(r20(rng)),
        });
    }
}

/// Three random integers of up to 20 bits.
fn r20(rng: &mut InputRng) -> [i64; 3] {
    [rng.int_bits(20), rng.int_bits(20), rng.int_bits(20)]
}

/// A random box: the corners of two random points.
fn bx(rng: &mut InputRng) -> ([i64; 3], [i64; 3]) {
    let a = r20(rng);
    let b = r20(rng);
    (
        [a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])],
        [a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])],
    )
}

/// Cameras: `n` random ones.
fn random_cameras(rng: &mut InputRng, n: usize, out: &mut Vec<CameraCase>) {
    for _ in 0..n {
        out.push(CameraCase {
            kind: Kind::Random,
            pe: f3(r20(rng)),
            pr: f3(r20(rng)),
            up: f3(r20(rng)),
            p: f3(r20(rng)),
        });
    }
}

/// Cameras: `n / 2` with the up vector nearly parallel to the view direction.
fn near_parallel_cameras(rng: &mut InputRng, n: usize, out: &mut Vec<CameraCase>) {
    for i in 0..n / 2 {
        // Up vector (a, b, 0) and view direction (x, y, 0) with a·y − b·x = 1
        // (adding (a, b) to (x, y) keeps that, and makes |d| ≥ |up|):
        // |up × d| = 1 while |up|·|d| ≥ 2·(3·2^18)² ≈ 1.2e12, an angle below 1e-12 rad, with Pe
        // and Pr = ∓d/2 within 2^20. Every other case instead perturbs d by
        // a few units (about 1e-6 rad). Axes are then permuted and flipped.
        let a = rng.range(3 * M20 / 4, M20 - 1);
        let mut b = rng.range(3 * M20 / 4, M20 - 2);
        while gcd(a, b) != 1 {
            b += 1;
        }
        let (x, y) = farey_neighbour(a, b);
        let (x, y) = (x + a, y + b);
        let farey = i % 2 == 0;
        let (mut up, mut d) = if farey {
            ([a, b, 0], [x, y, 0])
        } else {
            ([a, b, 0], [a + rng.int(3), b + rng.int(3), rng.int(3)])
        };
        shuffle(rng, &mut up, &mut d);
        let pr = if farey {
            [-d[0] / 2, -d[1] / 2, -d[2] / 2]
        } else {
            [rng.int(1 << 10), rng.int(1 << 10), rng.int(1 << 10)]
        };
        let pe = [pr[0] + d[0], pr[1] + d[1], pr[2] + d[2]];
        // The point: on the view axis, next to it, or random.
        let p = match i % 3 {
            0 => [pr[0] - d[0] / 2, pr[1] - d[1] / 2, pr[2] - d[2] / 2],
            1 => [pr[0] + rng.int(2), pr[1] + rng.int(2), pr[2] + rng.int(2)],
            _ => r20(rng),
        };
        if d == [0, 0, 0] {
            continue;
        }
        out.push(CameraCase {
            kind: Kind::NearParallel,
            pe: f3(pe),
            pr: f3(pr),
            up: f3(up),
            p: f3(p),
        });
    }
}

/// Cameras: `n / 2` with magnitudes from 1e-30 to 1e30.
fn wide_cameras(rng: &mut InputRng, n: usize, out: &mut Vec<CameraCase>) {
    for i in 0..n / 2 {
        // Every other case mixes magnitudes from 1e-30 to 1e30 freely; the
        // others give each of Vup and the points (Pe, Pr, P share one) a
        // scale 2^e from 1e-30 to 1e30 times 10-bit integers, so that the
        // exact square roots stay within reach of `Real` (the radicands are
        // integers below 2^72 times powers of four) and these cases have a
        // reference.
        let w = |rng: &mut InputRng| [rng.wide(), rng.wide(), rng.wide()];
        let case = if i % 2 == 0 {
            CameraCase {
                kind: Kind::Wide,
                pe: w(rng),
                pr: w(rng),
                up: w(rng),
                p: w(rng),
            }
        } else {
            let ep = pow2(rng.range(-100, 90) as i32);
            let eu = pow2(rng.range(-100, 90) as i32);
            let mut s = |e: f64| [0; 3].map(|_: i32| rng.int(1 << 10) as f64 * e);
            CameraCase {
                kind: Kind::Wide,
                pe: s(ep),
                pr: s(ep),
                up: s(eu),
                p: s(ep),
            }
        };
        out.push(case);
    }
}

/// Projections: `n` random ones.
fn random_projects(rng: &mut InputRng, n: usize, out: &mut Vec<ProjectCase>) {
    for _ in 0..n {
        let z = loop {
            let z = rng.int_bits(20);
            if z != 0 {
                break z;
            }
        };
        let general = rng.below(2) == 1;
        let a = rng.int_bits(20);
        let zvp = if general {
            Some(loop {
                let v = rng.int_bits(20) as f64;
                if v != a as f64 {
                    break v;
                }
            })
        } else {
            None
        };
        let z = if general && z == a { z + 1 } else { z };
        out.push(ProjectCase {
            kind: Kind::Random,
            zvp,
            a: if general || a != 0 { a as f64 } else { 1.0 },
            p: [rng.int_bits(20) as f64, rng.int_bits(20) as f64, z as f64],
        });
    }
}

/// Projections: `n / 2` points one unit from the plane of the centre of projection.
fn grazing_projects(rng: &mut InputRng, n: usize, out: &mut Vec<ProjectCase>) {
    for i in 0..n / 2 {
        // Points one unit from the plane of the centre of projection.
        let zprp = rng.int(M20 - 1);
        let zvp = zprp
            + if rng.below(2) == 0 {
                1
            } else {
                -rng.int_bits(20).abs() - 1
            };
        let z = zprp + if i % 2 == 0 { 1 } else { -1 };
        out.push(ProjectCase {
            kind: Kind::Grazing,
            zvp: Some(zvp as f64),
            a: zprp as f64,
            p: [rng.int(M20) as f64, rng.int(M20) as f64, z as f64],
        });
    }
}

/// Projections: `n / 2` with magnitudes from 1e-30 to 1e30.
fn wide_projects(rng: &mut InputRng, n: usize, out: &mut Vec<ProjectCase>) {
    for _ in 0..n / 2 {
        let mut z = rng.wide();
        if z == 0.0 {
            z = 1.0;
        }
        out.push(ProjectCase {
            kind: Kind::Wide,
            zvp: None,
            a: rng.wide(),
            p: [rng.wide(), rng.wide(), z],
        });
    }
}

/// Windows: `2n` (random, grazing, wide).
fn windows(rng: &mut InputRng, n: usize, out: &mut Vec<WindowCase>) {
    // Windows: standard angles keep the exact path exact.
    // fovy/2 a multiple of 15° or 22.5°.
    let angles = [30.0, 45.0, 60.0, 90.0, 120.0, 135.0, 150.0];
    for i in 0..(2 * n) {
        let wide = i >= n + n / 2;
        let fovy = angles[rng.below(angles.len() as u64) as usize];
        let aspect = rng.range(1, 1 << 12) as f64 / 1024.0;
        let near = if wide {
            rng.wide().abs()
        } else {
            rng.range(1, M20) as f64
        };
        let half = (fovy / 2.0_f64).to_radians().tan() * near * aspect.max(1.0);
        // A point inside the window (in target cases: an integer multiple of
        // a small power of two, so it is exact in f32).
        let pt = if wide {
            (half * (rng.int(1 << 20) as f64 / (1 << 20) as f64), 0.0)
        } else {
            let lim = (half as i64).max(1);
            (rng.int(lim) as f64, rng.int(lim) as f64)
        };
        let pt = ((pt.0 as f32) as f64, (pt.1 as f32) as f64);
        out.push(WindowCase {
            kind: if wide {
                Kind::Wide
            } else if i >= n {
                Kind::Grazing
            } else {
                Kind::Random
            },
            fovy,
            aspect,
            near,
            pt,
            size: (rng.range(1, 4096) as f64, rng.range(1, 4096) as f64),
        });
    }
}

/// Clipping: `n` random segments and boxes.
fn random_clips(rng: &mut InputRng, n: usize, out: &mut Vec<ClipCase>) {
    for _ in 0..n {
        let (min, max) = bx(rng);
        out.push(ClipCase {
            kind: Kind::Random,
            min: f3(min),
            max: f3(max),
            p0: f3(r20(rng)),
            p1: f3(r20(rng)),
        });
    }
}

/// Clipping: `n / 2` segments touching, lying in, or passing by a box plane.
fn grazing_clips(rng: &mut InputRng, n: usize, out: &mut Vec<ClipCase>) {
    for i in 0..n / 2 {
        // Segments with an end on a box plane, lying in a plane, or passing
        // one unit from an edge.
        let (min, max) = bx(rng);
        let mut p0 = r20(rng);
        let mut p1 = r20(rng);
        let axis = rng.below(3) as usize;
        let plane = if rng.below(2) == 0 {
            min[axis]
        } else {
            max[axis]
        };
        match i % 3 {
            0 => p0[axis] = plane,
            1 => {
                p0[axis] = plane;
                p1[axis] = plane;
            }
            _ => {
                p0[axis] = plane + 1;
                p1[axis] = plane - 1;
            }
        }
        out.push(ClipCase {
            kind: Kind::Grazing,
            min: f3(min),
            max: f3(max),
            p0: f3(p0),
            p1: f3(p1),
        });
    }
}

/// Clipping: `n / 2` with magnitudes from 1e-30 to 1e30.
fn wide_clips(rng: &mut InputRng, n: usize, out: &mut Vec<ClipCase>) {
    for _ in 0..n / 2 {
        let w = |rng: &mut InputRng| [rng.wide(), rng.wide(), rng.wide()];
        let (a, b) = (w(rng), w(rng));
        let min = [a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])];
        let max = [a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])];
        out.push(ClipCase {
            kind: Kind::Wide,
            min,
            max,
            p0: w(rng),
            p1: w(rng),
        });
    }
}

fn v<T: Scalar>(a: &P3) -> V3<T> {
    V3::new(T::from_f64(a[0]), T::from_f64(a[1]), T::from_f64(a[2]))
}

/// The inputs converted to one precision (and the camera bases, which the
/// view stage takes as given).
pub struct Prepared<T: Scalar> {
    cameras: Vec<(Camera<T>, V3<T>)>,
    bases: Vec<Option<Basis<T>>>,
    projects: Vec<(Projection<T>, V3<T>)>,
    windows: Vec<[T; 7]>,
    clips: Vec<(ClipBox<T>, V3<T>, V3<T>)>,
}

impl<T: Scalar> Prepared<T> {
    /// Converts every input to `T` (exactly: inputs are f32 values).
    pub fn new(inp: &Inputs) -> Prepared<T> {
        let cameras: Vec<_> = inp
            .cameras
            .iter()
            .map(|c| {
                (
                    Camera {
                        pe: v(&c.pe),
                        pr: v(&c.pr),
                        vup: v(&c.up),
                    },
                    v(&c.p),
                )
            })
            .collect();
        let bases = cameras
            .iter()
            .map(|(c, _)| camera::basis(c, &mut NoTrace).ok())
            .collect();
        Prepared {
            cameras,
            bases,
            projects: inp
                .projects
                .iter()
                .map(|c| {
                    let proj = match c.zvp {
                        None => Projection::Plane {
                            d: T::from_f64(c.a),
                        },
                        Some(z) => Projection::General {
                            zprp: T::from_f64(c.a),
                            zvp: T::from_f64(z),
                        },
                    };
                    (proj, v(&c.p))
                })
                .collect(),
            windows: inp
                .windows
                .iter()
                .map(|w| {
                    [w.fovy, w.aspect, w.near, w.pt.0, w.pt.1, w.size.0, w.size.1].map(T::from_f64)
                })
                .collect(),
            clips: inp
                .clips
                .iter()
                .map(|c| {
                    (
                        ClipBox {
                            min: v(&c.min),
                            max: v(&c.max),
                        },
                        v(&c.p0),
                        v(&c.p1),
                    )
                })
                .collect(),
        }
    }

    /// Runs stage `s` on case `i` (with [`NoTrace`]): its outputs, each with
    /// whether it is a unit-vector component, or `None` when the stage
    /// refuses the input (an error) or, for clipping, finds nothing inside.
    pub fn eval(&self, s: Stage, i: usize) -> Option<Vec<(T, bool)>> {
        match s {
            Stage::Basis => {
                let b = camera::basis(&self.cameras[i].0, &mut NoTrace).ok()?;
                Some(
                    b.u.iter()
                        .chain(b.v.iter())
                        .chain(b.n.iter())
                        .map(|x| (x.clone(), true))
                        .collect(),
                )
            }
            Stage::View => {
                let b = self.bases[i].as_ref()?;
                let (c, p) = &self.cameras[i];
                let e = camera::to_eye(b, &c.pe, "P", p, &mut NoTrace).ok()?;
                // The view matrix's last column (−u·Pe, −v·Pe, −n·Pe) too.
                let m = camera::view_matrix(b, &c.pe, &mut NoTrace).ok()?;
                let col = (0..3).map(|r| m[(r, 3)].clone());
                Some(e.iter().cloned().chain(col).map(|x| (x, false)).collect())
            }
            Stage::Project => {
                let (proj, p) = &self.projects[i];
                let r = projection::project(proj, "P", p, &mut NoTrace).ok()?;
                Some(r.iter().map(|x| (x.clone(), false)).collect())
            }
            Stage::Window => {
                let [fovy, aspect, near, x, y, w, h] = &self.windows[i];
                let win = window::window(fovy, aspect, near, "near", &mut NoTrace).ok()?;
                let (px, py) = window::to_viewport(&win, (w, h), "P", (x, y), &mut NoTrace);
                Some(
                    [
                        win.top, win.bottom, win.left, win.right, win.height, win.width, px, py,
                    ]
                    .into_iter()
                    .map(|x| (x, false))
                    .collect(),
                )
            }
            Stage::Clip => {
                let (b, p0, p1) = &self.clips[i];
                let r = clip::clip_segment(b, p0, p1, &mut NoTrace);
                let (a, z) = r.segment?;
                Some(
                    a.iter()
                        .chain(z.iter())
                        .map(|x| (x.clone(), false))
                        .collect(),
                )
            }
        }
    }
}

/// The errors of one stage at one precision over the input set.
#[derive(Clone, Debug, Default)]
pub struct Errors {
    /// Every component's error in ulps (target-domain cases).
    pub target: Vec<f64>,
    /// Every component's error in ulps (wide-range cases).
    pub wide: Vec<f64>,
    /// Cases where the float path failed (error or no segment) but the exact
    /// path did not, or the other way round.
    pub disagreements: usize,
    /// Of those, the ones in the target domain.
    pub target_disagreements: usize,
    /// Components whose exact value is not exact (no reference).
    pub unreferenced: usize,
}

impl Errors {
    /// All errors.
    pub fn all(&self) -> Vec<f64> {
        let mut v = self.target.clone();
        v.extend_from_slice(&self.wide);
        v
    }
}

/// The maximum and the median of a list (0 for an empty one; NaN-free input).
pub fn max_median(xs: &[f64]) -> (f64, f64) {
    if xs.is_empty() {
        return (0.0, 0.0);
    }
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    (v[v.len() - 1], v[v.len() / 2])
}

/// The errors of stage `s` at precision `T` against the exact results `exact`
/// (from [`Prepared::<Real>::eval`] on the same inputs).
pub fn errors<T: Scalar>(
    inp: &Inputs,
    prep: &Prepared<T>,
    exact: &[Option<Vec<(Real, bool)>>],
    s: Stage,
) -> Errors {
    let mut e = Errors::default();
    for (i, ex) in exact.iter().enumerate() {
        let got = prep.eval(s, i);
        match (got, ex) {
            (Some(g), Some(x)) if g.len() == x.len() => {
                for ((gv, unit), (xv, _)) in g.iter().zip(x) {
                    if !xv.is_exact() {
                        e.unreferenced += 1;
                        continue;
                    }
                    let err = ulp_error(gv.to_f64(), xv, *unit, T::PRECISION);
                    if inp.kind(s, i).in_target() {
                        e.target.push(err);
                    } else {
                        e.wide.push(err);
                    }
                }
            }
            (None, None) => {}
            _ => {
                e.disagreements += 1;
                if inp.kind(s, i).in_target() {
                    e.target_disagreements += 1;
                }
            }
        }
    }
    e
}

/// The exact results of every case of stage `s`.
pub fn exact_results(
    prep: &Prepared<Real>,
    inp: &Inputs,
    s: Stage,
) -> Vec<Option<Vec<(Real, bool)>>> {
    (0..inp.len(s)).map(|i| prep.eval(s, i)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulps_by_hand() {
        // ulp(1) = 2^-52 in f64, 2^-23 in f32; ulp(3) = 2^-51 (binade [2, 4)).
        assert_eq!(ulp(1.0, Precision::F64), f64::EPSILON);
        assert_eq!(ulp(1.0, Precision::F32), f32::EPSILON as f64);
        assert_eq!(ulp(3.0, Precision::F64), 2.0 * f64::EPSILON);
        assert_eq!(ulp(0.0, Precision::F64), pow2(-1074));
        assert_eq!(ulp(pow2(-1060), Precision::F64), pow2(-1074));
        // 1/3 rounded to f64 is off by 1/3 ulp of 1/3 (2^-54): |1/3 − rn(1/3)|
        // = 1/(3·2^54), ulp(1/3) = 2^-54.
        let third = Real::from_ratio(1, 3);
        let e = ulp_error(1.0 / 3.0, &third, false, Precision::F64);
        assert!((e - 1.0 / 3.0).abs() < 1e-12, "{e}");
        // In ulps of 1 the same error is 1/12 ulp.
        let e = ulp_error(1.0 / 3.0, &third, true, Precision::F64);
        assert!((e - 1.0 / 12.0).abs() < 1e-12, "{e}");
        assert!(ulp_error(f64::NAN, &third, false, Precision::F64).is_infinite());
    }

    #[test]
    fn farey_neighbours_have_unit_determinant() {
        for (a, b) in [(5, 3), (1_048_575, 524_288), (7, 1)] {
            let (x, y) = farey_neighbour(a, b);
            assert_eq!(a * y - b * x, 1);
        }
    }

    #[test]
    fn inputs_are_f32_values() {
        let inp = inputs(8);
        let all = inp
            .cameras
            .iter()
            .flat_map(|c| c.pe.into_iter().chain(c.pr).chain(c.up).chain(c.p))
            .chain(inp.clips.iter().flat_map(|c| c.p0.into_iter().chain(c.p1)));
        for x in all {
            assert_eq!((x as f32) as f64, x);
        }
    }
}
