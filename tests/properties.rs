//! Invariants of the viewing pipeline (issue 2), checked with exact
//! equalities at exact precision on small integer inputs, and within a
//! small tolerance in f64 on larger ones.

use grafika::num::vec::{self, V3};
use grafika::num::{Real, Scalar};
use grafika::stages::camera::{self, Camera};
use grafika::stages::clip::{self, ClipBox};
use grafika::stages::projection::{self, Projection};
use grafika::stages::trace::NoTrace;
use nalgebra::Vector4;
use num_traits::{One, Zero};
use proptest::prelude::*;

fn v<T: Scalar>(a: [i64; 3]) -> V3<T> {
    V3::new(T::from_i64(a[0]), T::from_i64(a[1]), T::from_i64(a[2]))
}

fn small() -> impl Strategy<Value = [i64; 3]> {
    [-6i64..=6, -6i64..=6, -6i64..=6]
}

fn large() -> impl Strategy<Value = [i64; 3]> {
    let m = 1i64 << 20;
    [-m..=m, -m..=m, -m..=m]
}

/// A camera with Pe ≠ Pr and Vup not parallel to Pe − Pr.
fn camera_ok(pe: [i64; 3], pr: [i64; 3], up: [i64; 3]) -> bool {
    let d = [pe[0] - pr[0], pe[1] - pr[1], pe[2] - pr[2]];
    let c = [
        up[1] * d[2] - up[2] * d[1],
        up[2] * d[0] - up[0] * d[2],
        up[0] * d[1] - up[1] * d[0],
    ];
    c != [0, 0, 0]
}

fn zero<T: Scalar>() -> T {
    T::zero()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// u, v, n are orthonormal and right-handed (u × v = n), exactly.
    #[test]
    fn basis_orthonormal_right_handed_exact(pe in small(), pr in small(), up in small()) {
        prop_assume!(camera_ok(pe, pr, up));
        let cam = Camera { pe: v::<Real>(pe), pr: v(pr), vup: v(up) };
        let b = camera::basis(&cam, &mut NoTrace).unwrap();
        let one = Real::one();
        prop_assert_eq!(vec::dot(&b.u, &b.v), zero::<Real>());
        prop_assert_eq!(vec::dot(&b.v, &b.n), zero::<Real>());
        prop_assert_eq!(vec::dot(&b.n, &b.u), zero::<Real>());
        prop_assert_eq!(vec::dot(&b.u, &b.u), one.clone());
        prop_assert_eq!(vec::dot(&b.v, &b.v), one.clone());
        prop_assert_eq!(vec::dot(&b.n, &b.n), one);
        prop_assert_eq!(vec::cross(&b.u, &b.v), b.n.clone());
        // n points from Pr to Pe: n·(Pe − Pr) = |Pe − Pr| > 0; u has no
        // component along Vup × ... beyond the plane: u ⟂ Vup.
        prop_assert!(vec::dot(&b.n, &vec::sub(&cam.pe, &cam.pr)) > Real::zero());
        prop_assert_eq!(vec::dot(&b.u, &cam.vup), zero::<Real>());
    }

    /// The view transformation maps the eye to the origin and the look-at
    /// point to (0, 0, −|Pe − Pr|), exactly, by `to_eye` and by the matrix V.
    #[test]
    fn view_maps_eye_and_look_at_exact(pe in small(), pr in small(), up in small()) {
        prop_assume!(camera_ok(pe, pr, up));
        let cam = Camera { pe: v::<Real>(pe), pr: v(pr), vup: v(up) };
        let b = camera::basis(&cam, &mut NoTrace).unwrap();
        let dist = vec::norm(&vec::sub(&cam.pe, &cam.pr));
        let origin = V3::new(Real::zero(), Real::zero(), Real::zero());
        prop_assert_eq!(camera::to_eye(&b, &cam.pe, "Pe", &cam.pe, &mut NoTrace).unwrap(), origin);
        let look = camera::to_eye(&b, &cam.pe, "Pr", &cam.pr, &mut NoTrace).unwrap();
        prop_assert_eq!(look.clone(), V3::new(Real::zero(), Real::zero(), -dist.clone()));
        let m = camera::view_matrix(&b, &cam.pe, &mut NoTrace).unwrap();
        let h = |p: &V3<Real>| m.clone() * Vector4::new(p[0].clone(), p[1].clone(), p[2].clone(), Real::one());
        let he = h(&cam.pe);
        let hr = h(&cam.pr);
        for k in 0..3 {
            prop_assert_eq!(he[k].clone(), Real::zero());
            prop_assert_eq!(hr[k].clone(), look[k].clone());
        }
    }

    /// The same in f64 for coordinates up to 2^20, within a few ulps of the
    /// vectors' scale.
    #[test]
    fn basis_and_view_f64(pe in large(), pr in large(), up in large(), p in large()) {
        prop_assume!(camera_ok(pe, pr, up));
        let cam = Camera { pe: v::<f64>(pe), pr: v(pr), vup: v(up) };
        let b = camera::basis(&cam, &mut NoTrace).unwrap();
        let tol = 8.0 * f64::EPSILON;
        prop_assert!(vec::dot(&b.u, &b.v).abs() <= tol);
        prop_assert!(vec::dot(&b.v, &b.n).abs() <= tol);
        prop_assert!(vec::dot(&b.n, &b.u).abs() <= tol);
        for a in [&b.u, &b.v, &b.n] {
            prop_assert!((vec::dot(a, a) - 1.0).abs() <= tol);
        }
        prop_assert!((vec::cross(&b.u, &b.v) - b.n).norm() <= tol);
        let e = camera::to_eye(&b, &cam.pe, "Pe", &cam.pe, &mut NoTrace).unwrap();
        prop_assert_eq!(e, V3::zeros());
        let dist = vec::norm(&vec::sub(&cam.pe, &cam.pr));
        let look = camera::to_eye(&b, &cam.pe, "Pr", &cam.pr, &mut NoTrace).unwrap();
        prop_assert!(look[0].abs() <= tol * dist && look[1].abs() <= tol * dist);
        prop_assert!((look[2] + dist).abs() <= tol * dist);
        // Distances are kept: |P' | = |P − Pe|.
        let q = v::<f64>(p);
        let pq = camera::to_eye(&b, &cam.pe, "P", &q, &mut NoTrace).unwrap();
        let r = vec::norm(&vec::sub(&q, &cam.pe));
        prop_assert!((pq.norm() - r).abs() <= tol * r.max(1.0));
    }

    /// A projected point lies on the line from the centre of projection
    /// through the point, and on the view plane: exactly.
    #[test]
    fn projection_on_projector_exact(
        p in small(), d in -6i64..=6, zprp in -6i64..=6, zvp in -6i64..=6, general in any::<bool>()
    ) {
        let (proj, cop, plane) = if general {
            prop_assume!(zprp != zvp && p[2] != zprp);
            (
                Projection::General { zprp: Real::from_i64(zprp), zvp: Real::from_i64(zvp) },
                v::<Real>([0, 0, zprp]),
                Real::from_i64(zvp),
            )
        } else {
            prop_assume!(d != 0 && p[2] != 0);
            (Projection::Plane { d: Real::from_i64(d) }, v::<Real>([0, 0, 0]), Real::from_i64(d))
        };
        let pt = v::<Real>(p);
        let img = projection::project(&proj, "P", &pt, &mut NoTrace).unwrap();
        prop_assert_eq!(img[2].clone(), plane);
        let c = vec::cross(&vec::sub(&img, &cop), &vec::sub(&pt, &cop));
        prop_assert_eq!(c, V3::new(Real::zero(), Real::zero(), Real::zero()));
    }

    /// The clipped segment lies in the box and on the original segment, and
    /// outcode clipping agrees with Liang–Barsky: exactly.
    #[test]
    fn clip_inside_on_segment_and_agrees_with_liang_barsky_exact(
        a in small(), b in small(), p0 in small(), p1 in small()
    ) {
        let bx = ClipBox {
            min: v::<Real>([a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])]),
            max: v::<Real>([a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])]),
        };
        let (q0, q1) = (v::<Real>(p0), v::<Real>(p1));
        let r = clip::clip_segment(&bx, &q0, &q1, &mut NoTrace);
        let lb = clip::liang_barsky(&bx, &q0, &q1, &mut NoTrace);
        prop_assert_eq!(r.segment.clone(), lb);
        if let Some((s, e)) = r.segment {
            let delta = vec::sub(&q1, &q0);
            let mut ts = Vec::new();
            for q in [&s, &e] {
                prop_assert_eq!(clip::outcode(&bx, q), 0);
                let w = vec::sub(q, &q0);
                prop_assert_eq!(vec::cross(&w, &delta), V3::new(Real::zero(), Real::zero(), Real::zero()));
                // t = w·Δ/Δ·Δ ∈ [0, 1] (Δ ≠ 0 here, or both ends are P0).
                let dd = vec::dot(&delta, &delta);
                let t = if dd == Real::zero() { Real::zero() } else { vec::dot(&w, &delta) / dd };
                prop_assert!(t >= Real::zero() && t <= Real::one());
                ts.push(t);
            }
            // The direction P0 → P1 is kept.
            prop_assert!(ts[0] <= ts[1]);
        }
    }

    /// The same agreement in f64 for coordinates up to 2^20, to rounding.
    #[test]
    fn clip_agrees_with_liang_barsky_f64(a in large(), b in large(), p0 in large(), p1 in large()) {
        let bx = ClipBox {
            min: v::<f64>([a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])]),
            max: v::<f64>([a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])]),
        };
        let (q0, q1) = (v::<f64>(p0), v::<f64>(p1));
        let r = clip::clip_segment(&bx, &q0, &q1, &mut NoTrace);
        let lb = clip::liang_barsky(&bx, &q0, &q1, &mut NoTrace);
        match (r.segment, lb) {
            (Some((s, e)), Some((ls, le))) => {
                let scale = 1e-9 * (1u64 << 21) as f64;
                prop_assert!((s - ls).norm() <= scale && (e - le).norm() <= scale);
                for q in [s, e] {
                    for k in 0..3 {
                        prop_assert!(q[k] >= bx.min[k] && q[k] <= bx.max[k]);
                    }
                }
            }
            (None, None) => {}
            // A segment touching the box in (nearly) one point may be kept
            // by one method and missed by the other after rounding.
            (x, y) => {
                let (s, e) = x.or(y).unwrap();
                prop_assert!((s - e).norm() <= 1e-6, "{:?} vs {:?}", s, e);
            }
        }
    }
}
