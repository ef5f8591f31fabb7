//! The synthetic camera: the basis u, v, n from Pe, Pr, Vup, the camera
//! matrix Mcam (camera to world) and the view matrix V = Mcam⁻¹ (world to
//! eye coordinates), and eye coordinates of points.

use crate::error::{Error, Result};
use crate::msg::{Msg, PixelMsg};
use crate::num::vec::{self, V3};
use crate::num::Scalar;
use crate::stages::trace::{Name, Step, Subst, Trace, Val};
use nalgebra::{Matrix4, Vector4};

/// An up vector closer than this to the view direction (radians) gets a warning.
pub const NEAR_PARALLEL_RAD: f64 = 1e-6;

/// A camera: eye Pe, look-at (reference) point Pr and up vector Vup, in world
/// coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera<T> {
    /// Pe, the eye.
    pub pe: V3<T>,
    /// Pr, the point looked at.
    pub pr: V3<T>,
    /// Vup, the up direction.
    pub vup: V3<T>,
}

/// The camera's orthonormal basis, with the unnormalized vectors it came
/// from (kept so that eye coordinates can be computed from unrounded
/// directions).
#[derive(Clone, Debug, PartialEq)]
pub struct Basis<T> {
    /// u, the camera's x axis (right).
    pub u: V3<T>,
    /// v, the camera's y axis (up).
    pub v: V3<T>,
    /// n, the camera's z axis (the camera looks along −n).
    pub n: V3<T>,
    /// Pe − Pr times a power of two (one in exact arithmetic) that brings
    /// its largest component near 1: parallel to n.
    pub d: V3<T>,
    /// Vup times a power of two, likewise.
    pub up: V3<T>,
    /// up × d, parallel to u.
    pub su: V3<T>,
    /// d × (up × d), parallel to v.
    pub sv: V3<T>,
    /// |d|, |su|, |sv| (of the scaled vectors above: what eye coordinates
    /// divide by).
    pub norms: [T; 3],
    /// |Pe − Pr|, unscaled.
    pub dist: T,
    /// |Vup × n| = |Vup × (Pe − Pr)|/|Pe − Pr|, unscaled.
    pub vxn_norm: T,
    /// u, v, n were given in place of the computed ones (follow-through):
    /// eye coordinates and the view matrix use them as they are, not the
    /// unnormalized d and Vup they no longer follow from.
    pub given: bool,
}

/// The camera basis:
///
/// n = (Pe − Pr)/|Pe − Pr|,  u = (Vup × n)/|Vup × n|,  v = n × u.
///
/// Computed from the unrounded direction d = Pe − Pr: u ∥ Vup × d and
/// v ∥ d × (Vup × d), each normalized once, which is the same vector in exact
/// arithmetic and loses no accuracy to a rounded n in floats. In floats, d
/// and Vup are first scaled by powers of two (exactly) so that their largest
/// components are near 1: the cross products can then neither overflow nor
/// underflow for coordinates from 1e-30 to 1e30, even in f32.
///
/// Errors: Pe = Pr (no view direction), Vup = 0 or parallel to Pe − Pr.
/// Warns when Vup is within [`NEAR_PARALLEL_RAD`] of the view direction.
pub fn basis<T: Scalar>(cam: &Camera<T>, tr: &mut impl Trace) -> Result<Basis<T>> {
    let Camera { pe, pr, vup } = cam;
    // n from the view direction
    let d = vec::sub(pe, pr);
    let (n, dn) = view_direction(pe, &d)?;
    tr.step(|| n_step(cam, &d, &dn, &n));

    // u from Vup × d
    if vec::normalize(vup).is_none() {
        return Err(Error::said("up", Msg::ErrUpZero));
    }
    // Exact power-of-two scaling (one for Real): directions are unchanged.
    let (kd, ku) = (
        T::pow2_scale(&[&d[0], &d[1], &d[2]]),
        T::pow2_scale(&[&vup[0], &vup[1], &vup[2]]),
    );
    let ds = vec::scale(&d, &kd);
    let ups = vec::scale(vup, &ku);
    let su = vec::cross(&ups, &ds);
    let (u, sun) = vec::normalize(&su)
        .ok_or_else(|| Error::said("up", Msg::ErrUpParallel(f64s(vup), f64s(&d))))?;
    warn_near_parallel(&sun, &ups, &ds, tr);
    tr.step(|| u_step(vup, &n, &u));

    // v completes the right-handed frame: exactly n × u, in floats from
    // the unrounded d × (Vup × d)
    let sv = vec::cross(&ds, &su);
    let (v, svn) =
        vec::normalize(&sv).ok_or_else(|| Error::why("up", crate::msg::ErrMsg::VVanished))?;
    let v = if T::PRECISION == crate::num::Precision::Exact {
        v_axis(&n, &u)
    } else {
        v
    };
    tr.step(|| {
        Step::new(Msg::CamAxisV, "v = n × u")
            .val(Name::math("n"), Val::vec3(&n))
            .val(Name::math("u"), Val::vec3(&u))
            .res(Name::math("v"), Val::vec3(&v))
            .sub(Name::math("v"), Subst::cross(&n, &u))
    });
    let b = Basis {
        u,
        v,
        n,
        vxn_norm: sun.clone() / (ku * kd) / dn.clone(),
        dist: dn,
        norms: [vec::norm(&ds), sun, svn],
        d: ds,
        up: ups,
        su,
        sv,
        given: false,
    };
    tr.step(|| check_step(&b));
    Ok(b)
}

/// The text's v = n × u: what [`basis`] computes in exact arithmetic (in
/// floats it takes the same direction from the unrounded d × (Vup × d)).
/// From a non-unit n or u it is as long as their product, as a student
/// computes it from their own n and u.
pub fn v_axis<T: Scalar>(n: &V3<T>, u: &V3<T>) -> V3<T> {
    vec::cross(n, u)
}

/// n = (Pe − Pr)/|Pe − Pr| and |Pe − Pr|, for d = Pe − Pr: an error when
/// d overflows the precision or is zero (Pe = Pr).
fn view_direction<T: Scalar>(pe: &V3<T>, d: &V3<T>) -> Result<(V3<T>, T)> {
    if !vec::is_finite(d) {
        return Err(Error::why(
            "look",
            crate::msg::ErrMsg::EyeLookTooLarge(f64s(d), T::PRECISION.name().into()),
        ));
    }
    vec::normalize(d).ok_or_else(|| Error::said("look", Msg::ErrSamePoint(f64s(pe))))
}

/// The step of the axis n.
fn n_step<T: Scalar>(cam: &Camera<T>, d: &V3<T>, dn: &T, n: &V3<T>) -> Step {
    Step::new(Msg::CamAxisN, "n = (Pe − Pr) / |Pe − Pr|")
        .val(Name::math("Pe"), Val::vec3(&cam.pe))
        .val(Name::math("Pr"), Val::vec3(&cam.pr))
        .val(Name::math("Pe − Pr"), Val::vec3(d))
        .sub(Name::math("Pe − Pr"), Subst::difference(&cam.pe, &cam.pr))
        .val(Name::math("|Pe − Pr|"), Val::length(d, dn))
        .sub(Name::math("|Pe − Pr|"), Subst::norm(d))
        .res(Name::math("n"), Val::vec3(n))
        .sub(
            Name::math("n"),
            Subst::quotient(Val::vec3(d), Val::length(d, dn)),
        )
}

/// Warns when Vup is nearly parallel to d: sin of the angle between them =
/// |Vup × d| / (|Vup| |d|) (on the scaled vectors `ups`, `ds`).
fn warn_near_parallel<T: Scalar>(sun: &T, ups: &V3<T>, ds: &V3<T>, tr: &mut impl Trace) {
    let sin_angle = sun.to_f64() / (vec::norm(ups).to_f64() * vec::norm(ds).to_f64());
    let angle = sin_angle.clamp(-1.0, 1.0).asin();
    if angle < NEAR_PARALLEL_RAD {
        tr.warn(|| Msg::UpParallel(angle));
    }
}

/// The step of the axis u.
fn u_step<T: Scalar>(vup: &V3<T>, n: &V3<T>, u: &V3<T>) -> Step {
    let vxn = vec::cross(vup, n);
    let len = vec::norm(&vxn);
    Step::new(Msg::CamAxisU, "u = (Vup × n) / |Vup × n|")
        .val(Name::math("Vup"), Val::vec3(vup))
        .val(Name::math("Vup × n"), Val::vec3(&vxn))
        .sub(Name::math("Vup × n"), Subst::cross(vup, n))
        .val(Name::math("|Vup × n|"), Val::length(&vxn, &len))
        .sub(Name::math("|Vup × n|"), Subst::norm(&vxn))
        .res(Name::math("u"), Val::vec3(u))
        .sub(
            Name::math("u"),
            match len == T::one() {
                true => Subst::default(),
                false => Subst::quotient(Val::vec3(&vxn), Val::length(&vxn, &len)),
            },
        )
}

/// The orthonormality check shown after the basis: u·v, v·n, n·u, |u|, |v|,
/// |n| and (u × v)·n (+1 for a right-handed frame).
fn check_step<T: Scalar>(b: &Basis<T>) -> Step {
    let Basis { u, v, n, .. } = b;
    let uxv = vec::cross(u, v);
    let handed = vec::dot(&uxv, n);
    let ok = |x: &T, want: f64| (x.to_f64() - want).abs() < 1e-6;
    let dots = [vec::dot(u, v), vec::dot(v, n), vec::dot(n, u)];
    let lens = [vec::dot(u, u), vec::dot(v, v), vec::dot(n, n)];
    let good =
        dots.iter().all(|x| ok(x, 0.0)) && lens.iter().all(|x| ok(x, 1.0)) && ok(&handed, 1.0);
    Step::new(
        Msg::CamCheck,
        "u·v = v·n = n·u = 0,  |u| = |v| = |n| = 1,  (u × v)·n = 1",
    )
    .val(Name::math("u·v"), Val::num(&dots[0]))
    .sub(Name::math("u·v"), Subst::dot(u, v))
    .val(Name::math("v·n"), Val::num(&dots[1]))
    .sub(Name::math("v·n"), Subst::dot(v, n))
    .val(Name::math("n·u"), Val::num(&dots[2]))
    .sub(Name::math("n·u"), Subst::dot(n, u))
    .val(Name::math("u·u"), Val::num(&lens[0]))
    .sub(Name::math("u·u"), Subst::dot(u, u))
    .val(Name::math("v·v"), Val::num(&lens[1]))
    .sub(Name::math("v·v"), Subst::dot(v, v))
    .val(Name::math("n·n"), Val::num(&lens[2]))
    .sub(Name::math("n·n"), Subst::dot(n, n))
    .val(Name::math("u × v"), Val::vec3(&uxv))
    .sub(Name::math("u × v"), Subst::cross(u, v))
    .res(Name::math("(u × v)·n"), Val::num(&handed))
    .sub(Name::math("(u × v)·n"), Subst::dot(&uxv, n))
    .note(if good {
        Msg::Orthonormal(true)
    } else {
        Msg::Orthonormal(false)
    })
}

/// Mcam = T(Pe)·[u v n]: the camera-to-world matrix (its columns are u, v, n
/// and Pe).
pub fn camera_matrix<T: Scalar>(b: &Basis<T>, pe: &V3<T>) -> Matrix4<T> {
    let mut m = Matrix4::<T>::identity();
    for r in 0..3 {
        m[(r, 0)] = b.u[r].clone();
        m[(r, 1)] = b.v[r].clone();
        m[(r, 2)] = b.n[r].clone();
        m[(r, 3)] = pe[r].clone();
    }
    m
}

/// The view matrix V = Mcam⁻¹ (world to eye coordinates): rows u, v, n times
/// the translation by −Pe, so its last column is (−u·Pe, −v·Pe, −n·Pe, 1).
///
/// Errors when the translation column is too large for the precision (f32
/// with coordinates near 1e38).
pub fn view_matrix<T: Scalar>(b: &Basis<T>, pe: &V3<T>, tr: &mut impl Trace) -> Result<Matrix4<T>> {
    let rot = rows(&b.u, &b.v, &b.n);
    let mut trans = Matrix4::<T>::identity();
    for r in 0..3 {
        trans[(r, 3)] = -pe[r].clone();
    }
    let mut view = rot.clone();
    let col = translation(b, pe);
    for (r, x) in col.into_iter().enumerate() {
        view[(r, 3)] = -x;
    }
    if !(0..3).all(|r| view[(r, 3)].is_finite()) {
        return Err(Error::why(
            "eye",
            crate::msg::ErrMsg::TranslationTooLarge(T::PRECISION.name().into()),
        ));
    }
    tr.step(|| {
        Step::new(Msg::CamMatrix, Msg::FCamMatrix)
            .val(Name::math("u"), Val::vec3(&b.u))
            .val(Name::math("v"), Val::vec3(&b.v))
            .val(Name::math("n"), Val::vec3(&b.n))
            .val(Name::math("Pe"), Val::vec3(pe))
            .res(Name::math("Mcam"), Val::mat4(&camera_matrix(b, pe)))
    });
    tr.step(|| {
        let last = |name: &str, axis: &V3<T>, r: usize| {
            (
                Name::math(format!("−{name}·Pe")),
                Val::num(&view[(r, 3)]),
                Subst::dot(axis, pe).within("−(", ")"),
            )
        };
        let column = [last("u", &b.u, 0), last("v", &b.v, 1), last("n", &b.n, 2)];
        let s = Step::new(Msg::ViewMatrix, Msg::FViewMatrix)
            .val(Name::math("R"), Val::mat4(&rot))
            .val(Name::math("T(−Pe)"), Val::mat4(&trans));
        column
            .into_iter()
            .fold(s, |s, (name, v, sub)| s.val(name.clone(), v).sub(name, sub))
            .res(Name::math("V"), Val::mat4(&view))
    });
    Ok(view)
}

/// (u·Pe, v·Pe, n·Pe): exactly with [`Real`](crate::num::Real); in floats
/// from the unnormalized axes by error-free transformations with a
/// certified error bound, falling back to exact rationals only when the
/// bound is not met ([`frame_dots`](crate::num::exact_dot::frame_dots)), so
/// each is within 2.8 ulps at f64 (0.5 + 2^−26 at f32) even when it is a
/// small difference of products of size |Pe|.
fn translation<T: Scalar>(b: &Basis<T>, pe: &V3<T>) -> [T; 3] {
    if T::PRECISION == crate::num::Precision::Exact || b.given {
        return [vec::dot(&b.u, pe), vec::dot(&b.v, pe), vec::dot(&b.n, pe)];
    }
    let f = |a: &V3<T>| [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()];
    crate::num::exact_dot::frame_dots(f(&b.up), f(&b.d), f(pe)).map(T::from_f64)
}

/// The matrix with rows a, b, c (and 0 0 0 1).
fn rows<T: Scalar>(a: &V3<T>, b: &V3<T>, c: &V3<T>) -> Matrix4<T> {
    let mut m = Matrix4::<T>::identity();
    for (r, row) in [a, b, c].into_iter().enumerate() {
        for k in 0..3 {
            m[(r, k)] = row[k].clone();
        }
    }
    m
}

/// Eye coordinates of a world point: P' = V·P = (u·(P − Pe), v·(P − Pe), n·(P − Pe)).
///
/// Errors when they are too large for the precision (f32 near 1e38).
///
/// Computed from the unnormalized axes of [`Basis`] so that no rounded unit
/// vector enters the result, each numerator from the camera's own inputs
/// (up, d) and w = P − Pe rather than from rounded cross products:
///
/// u·w = (up × d)·w / |up × d| = det[up; d; w] / |su|,
/// v·w = (d × (up × d))·w / |sv| = ((d·d)(up·w) − (d·up)(d·w)) / |sv|,
/// n·w = d·w / |d|,
///
/// with [`Scalar::triple_product`] and [`Scalar::double_cross_dot`], which
/// keep the digits of a coordinate much smaller than |w| (a point near a
/// camera plane). In exact arithmetic the formula itself, from the axes
/// u, v, n as they are (the same value; and a basis whose axes are a
/// student's own gives the student's eye coordinates).
pub fn to_eye<T: Scalar>(
    b: &Basis<T>,
    pe: &V3<T>,
    name: &str,
    p: &V3<T>,
    tr: &mut impl Trace,
) -> Result<V3<T>> {
    let rel = vec::sub(p, pe);
    let (up, d, w) = (refs(&b.up), refs(&b.d), refs(&rel));
    let e = if T::PRECISION == crate::num::Precision::Exact || b.given {
        vec::v3(
            vec::dot(&b.u, &rel),
            vec::dot(&b.v, &rel),
            vec::dot(&b.n, &rel),
        )
    } else {
        vec::v3(
            T::triple_product(up, d, w) / b.norms[1].clone(),
            T::double_cross_dot(d, up, w) / b.norms[2].clone(),
            vec::dot(&b.d, &rel) / b.norms[0].clone(),
        )
    };
    tr.step(|| {
        Step::new(
            Msg::EyeCoords(name.to_string()),
            format!("{name}' = V·{name} = (u·({name} − Pe), v·({name} − Pe), n·({name} − Pe))"),
        )
        .val(Name::math(name), Val::vec3(p))
        .val(Name::math(format!("{name} − Pe")), Val::vec3(&rel))
        .sub(Name::math(format!("{name} − Pe")), Subst::difference(p, pe))
        .val(Name::math(format!("u·({name} − Pe)")), Val::num(&e[0]))
        .sub(
            Name::math(format!("u·({name} − Pe)")),
            Subst::dot(&b.u, &rel),
        )
        .val(Name::math(format!("v·({name} − Pe)")), Val::num(&e[1]))
        .sub(
            Name::math(format!("v·({name} − Pe)")),
            Subst::dot(&b.v, &rel),
        )
        .val(Name::math(format!("n·({name} − Pe)")), Val::num(&e[2]))
        .sub(
            Name::math(format!("n·({name} − Pe)")),
            Subst::dot(&b.n, &rel),
        )
        .res(Name::Eye(name.to_string()), Val::vec3(&e))
    });
    if !vec::is_finite(&e) {
        return Err(Error::why(
            format!("points.{name}"),
            crate::msg::ErrMsg::EyeCoordsTooLarge(name.to_string(), T::PRECISION.name().into()),
        ));
    }
    Ok(e)
}

/// (x, y, z, w) = M·(P, 1): a 4×4 matrix applied to a point in
/// homogeneous coordinates, row r summed as ((m_r0·x + m_r1·y) + m_r2·z)
/// + m_r3 (nalgebra's product; the renderer's every vertex goes through it).
#[inline(always)]
pub fn apply<T: Scalar>(m: &Matrix4<T>, p: &V3<T>) -> Vector4<T> {
    m * Vector4::new(p[0].clone(), p[1].clone(), p[2].clone(), T::one())
}

/// World coordinates of an object point: Pw = M·P, M the object's
/// modeling matrix.
pub fn to_world<T: Scalar>(m: &Matrix4<T>, name: &str, p: &V3<T>, tr: &mut impl Trace) -> V3<T> {
    let w = apply(m, p).xyz();
    tr.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::World(name.to_string())),
            format!("{name}w = M·{name}"),
        )
        .val(Name::math(name), Val::vec3(p))
        .res(Name::math(format!("{name}w")), Val::vec3(&w))
    });
    w
}

/// Eye coordinates of an object point by the view matrix:
/// P' = V·Pw = (V·M)·P, with `vm` the product V·M (one matrix per object,
/// as the renderer applies it).
pub fn eye_by_matrix<T: Scalar>(
    vm: &Matrix4<T>,
    name: &str,
    p: &V3<T>,
    tr: &mut impl Trace,
) -> V3<T> {
    let e = apply(vm, p).xyz();
    tr.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::Eye(name.to_string())),
            format!("{name}' = V·{name}w = (V·M)·{name}"),
        )
        .val(Name::math(name), Val::vec3(p))
        .res(Name::Eye(name.to_string()), Val::vec3(&e))
        .note(Msg::Pixel(PixelMsg::Composed))
    });
    e
}

/// The components of a vector by reference.
fn refs<T>(a: &V3<T>) -> [&T; 3] {
    [&a[0], &a[1], &a[2]]
}

/// A vector's components as doubles, for an error message.
pub fn f64s<T: Scalar>(a: &V3<T>) -> [f64; 3] {
    [0, 1, 2].map(|k| a[k].to_f64())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stages::trace::NoTrace;

    fn cam(pe: [f64; 3], pr: [f64; 3], up: [f64; 3]) -> Camera<f64> {
        Camera {
            pe: pe.into(),
            pr: pr.into(),
            vup: up.into(),
        }
    }

    #[test]
    fn text_example_6_1_by_hand() {
        // Pe = (4,4,4), Pr = (0,1,4): Pe − Pr = (4,3,0), |.| = 5, n = (4/5, 3/5, 0);
        // Vup × n = (0,1,0) × (4/5,3/5,0) = (0, 0, −4/5), u = (0,0,−1);
        // v = n × u = (3/5·(−1) − 0, 0 − 4/5·(−1), 0) = (−3/5, 4/5, 0).
        let c = cam([4.0, 4.0, 4.0], [0.0, 1.0, 4.0], [0.0, 1.0, 0.0]);
        let b = basis(&c, &mut NoTrace).unwrap();
        approx::assert_relative_eq!(b.n, V3::new(0.8, 0.6, 0.0), epsilon = 1e-15);
        approx::assert_relative_eq!(b.u, V3::new(0.0, 0.0, -1.0), epsilon = 1e-15);
        approx::assert_relative_eq!(b.v, V3::new(-0.6, 0.8, 0.0), epsilon = 1e-15);
        // Pr − Pe = (−4,−3,0): u· = 0, v· = 12/5 − 12/5 = 0, n· = −16/5 − 9/5 = −5.
        let e = to_eye(&b, &c.pe, "P", &c.pr, &mut NoTrace).unwrap();
        approx::assert_relative_eq!(e, V3::new(0.0, 0.0, -5.0), epsilon = 1e-14);
    }

    #[test]
    fn view_matrix_agrees_with_eye_coordinates() {
        let c = cam([3.0, 1.0, 3.0], [2.0, 1.0, 2.0], [0.0, 1.0, 0.0]);
        let b = basis(&c, &mut NoTrace).unwrap();
        let v = view_matrix(&b, &c.pe, &mut NoTrace).unwrap();
        let p = V3::new(1.0, 0.0, 0.0);
        let e = to_eye(&b, &c.pe, "B", &p, &mut NoTrace).unwrap();
        let h = v * nalgebra::Vector4::new(1.0, 0.0, 0.0, 1.0);
        approx::assert_relative_eq!(h.xyz(), e, epsilon = 1e-14);
        // B' = (1/√2, −1, −5/√2) by hand.
        let r = std::f64::consts::FRAC_1_SQRT_2;
        approx::assert_relative_eq!(e, V3::new(r, -1.0, -5.0 * r), epsilon = 1e-14);
        // V is the inverse of Mcam.
        let m = camera_matrix(&b, &c.pe);
        approx::assert_relative_eq!(v * m, Matrix4::identity(), epsilon = 1e-14);
    }

    #[test]
    fn degenerate_cameras_are_errors() {
        let same = cam([1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [0.0, 1.0, 0.0]);
        assert_eq!(basis(&same, &mut NoTrace).unwrap_err().field, "look");
        let parallel = cam([0.0, 5.0, 0.0], [0.0, 0.0, 0.0], [0.0, 2.0, 0.0]);
        assert_eq!(basis(&parallel, &mut NoTrace).unwrap_err().field, "up");
        let zero = cam([0.0, 0.0, 5.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]);
        assert_eq!(basis(&zero, &mut NoTrace).unwrap_err().field, "up");
    }
}
