//! Projection of eye-coordinate points onto a view plane: perspective with
//! the centre of projection (COP) at the origin and the plane z = d, the
//! general perspective set-up (COP at z = zprp, plane z = zvp), and
//! orthographic projection.

use crate::error::{Error, Result};
use crate::msg::{Msg, PixelMsg};
use crate::num::vec::{self, V3};
use crate::num::Scalar;
use crate::stages::trace::{Name, Step, Subst, Trace, Val};

/// A projection set-up.
#[derive(Clone, Debug, PartialEq)]
pub enum Projection<T> {
    /// COP at the origin, view plane z = d: xp = d·x/z, yp = d·y/z, zp = d.
    Plane {
        /// d, the plane's z (the text's worked example uses d = −near).
        d: T,
    },
    /// COP at (0, 0, zprp), view plane z = zvp:
    /// xp = x·(zprp − zvp)/(zprp − z), yp likewise, zp = zvp.
    General {
        /// zprp, the z of the centre of projection.
        zprp: T,
        /// zvp, the z of the view plane.
        zvp: T,
    },
    /// Orthographic: xp = x, yp = y, zp = 0.
    Ortho,
}

impl<T: Scalar> Projection<T> {
    /// Checks that the plane does not pass through the centre of projection.
    pub fn validate(&self) -> Result<()> {
        match self {
            Projection::Plane { d } if d.is_zero_value() => {
                Err(Error::why("d", crate::msg::ErrMsg::PlaneThroughOrigin))
            }
            Projection::General { zprp, zvp } if zprp == zvp => Err(Error::why(
                "plane",
                crate::msg::ErrMsg::PlaneThroughCop(zvp.to_f64()),
            )),
            _ => Ok(()),
        }
    }

    /// The z of the centre of projection (None for orthographic).
    fn cop_z(&self) -> Option<T> {
        match self {
            Projection::Plane { .. } => Some(T::zero()),
            Projection::General { zprp, .. } => Some(zprp.clone()),
            Projection::Ortho => None,
        }
    }
}

/// x·a/b, with x, a and b first scaled by powers of two to magnitudes near
/// 1 (exactly; all three factors are one for exact numbers) and the result
/// scaled back one factor at a time, always by the factor that moves it
/// toward 1, so that no intermediate overflows or underflows unless the
/// result itself does.
fn mul_div<T: Scalar>(x: &T, a: &T, b: &T) -> T {
    if T::PRECISION == crate::num::Precision::Exact {
        return x.clone() * a.clone() / b.clone();
    }
    let (sx, sa, sb) = (
        T::pow2_scale(&[x]),
        T::pow2_scale(&[a]),
        T::pow2_scale(&[b]),
    );
    let mut r = (x.clone() * sx.clone()) * (a.clone() * sa.clone()) / (b.clone() * sb.clone());
    // Undo: multiply by 1/sx, 1/sa and sb (powers of two), each time by the
    // smallest remaining factor while |r| ≥ 1 and the largest otherwise.
    let mut factors = [T::one() / sx, T::one() / sa, sb];
    factors.sort_by(|p, q| p.partial_cmp(q).unwrap_or(std::cmp::Ordering::Equal));
    let (mut lo, mut hi) = (0, 3);
    while lo < hi {
        if r.abs() >= T::one() {
            r *= factors[lo].clone();
            lo += 1;
        } else {
            hi -= 1;
            r *= factors[hi].clone();
        }
    }
    r
}

/// Projects the eye-coordinate point `p` (named `name` in steps and errors).
///
/// Errors when the point lies in the plane through the centre of projection
/// parallel to the view plane (its projector never meets the view plane).
/// A point behind the centre of projection is projected (the formula still
/// applies, its image is inverted) with a warning.
pub fn project<T: Scalar>(
    proj: &Projection<T>,
    name: &str,
    p: &V3<T>,
    tr: &mut impl Trace,
) -> Result<V3<T>> {
    let (x, y, z) = (&p[0], &p[1], &p[2]);
    let Some((scale, plane_z, formula, scale_name)) = perspective_form(proj, name, z)? else {
        let r = vec::v3(x.clone(), y.clone(), T::zero());
        tr.step(|| {
            Step::new(Msg::OrthoProj(name.to_string()), "xp = x,  yp = y,  zp = 0")
                .val(Name::math(name), Val::vec3(p))
                .res(Name::Image(name.to_string()), Val::vec3(&r))
                .sub(
                    Name::Image(name.to_string()),
                    Subst::new("({}{,}{}{,}0)", vec![Val::num(x), Val::num(y)]),
                )
        });
        return Ok(r);
    };
    // x·(num/den) evaluated as a scaled x·num/den: no premature overflow or
    // underflow of the scale factor, two roundings.
    let (num, den) = scale;
    let r = vec::v3(
        mul_div(x, &num, &den),
        mul_div(y, &num, &den),
        plane_z.clone(),
    );
    if !vec::is_finite(&r) {
        return Err(Error::why(
            format!("points.{name}"),
            crate::msg::ErrMsg::ImageTooLarge(name.to_string(), T::PRECISION.name().to_string()),
        ));
    }
    // Behind: the point and the plane are on opposite sides of the COP.
    let cop = proj.cop_z().unwrap_or_else(T::zero);
    let behind = (z.clone() - cop.clone() < T::zero()) != (plane_z - cop < T::zero());
    if behind {
        tr.warn(|| Msg::BehindWarn(name.to_string()));
    }
    tr.step(|| {
        let k = num.clone() / den.clone();
        let scale_sub = match proj {
            Projection::General { zprp, zvp } => (
                "({} − {})/({} − {})",
                vec![Val::num(zprp), Val::num(zvp), Val::num(zprp), Val::num(z)],
            ),
            _ => ("{}/{}", vec![Val::num(&num), Val::num(&den)]),
        };
        let image = [x, &k, y, &k, &r[2]].map(Val::num).to_vec();
        let mut s = Step::new(Msg::PerspProj(name.to_string()), formula)
            .val(Name::math(name), Val::vec3(p))
            .val(Name::math(scale_name), Val::num(&k))
            .sub(Name::math(scale_name), Subst::new(scale_sub.0, scale_sub.1))
            .res(Name::Image(name.to_string()), Val::vec3(&r))
            .sub(
                Name::Image(name.to_string()),
                Subst::new("({}·{}{,}{}·{}{,}{})", image),
            );
        if behind {
            s = s.note(Msg::BehindCentre);
        }
        s
    });
    Ok(r)
}

/// (numerator, denominator) of the scale, the plane's z, formula, scale's name.
type Form<T> = ((T, T), T, &'static str, &'static str);

/// A perspective set-up's scale factor as (numerator, denominator), the
/// plane's z, the formula and the factor's name: d/z onto z = d, or
/// (zprp − zvp)/(zprp − z) in the general set-up; `None` for the
/// orthographic projection. A point in the plane of the centre of
/// projection (zero denominator) is an error.
fn perspective_form<T: Scalar>(proj: &Projection<T>, name: &str, z: &T) -> Result<Option<Form<T>>> {
    Ok(Some(match proj {
        Projection::Ortho => return Ok(None),
        Projection::Plane { d } => {
            if z.is_zero_value() {
                return Err(Error::said(
                    format!("points.{name}"),
                    Msg::ErrCopPlane(name.to_string(), None),
                ));
            }
            (
                (d.clone(), z.clone()),
                d.clone(),
                "xp = d·x/z,  yp = d·y/z,  zp = d",
                "d/z",
            )
        }
        Projection::General { zprp, zvp } => {
            let den = zprp.clone() - z.clone();
            if den.is_zero_value() {
                return Err(Error::said(
                    format!("points.{name}"),
                    Msg::ErrCopPlane(name.to_string(), Some(zprp.to_f64())),
                ));
            }
            (
                (zprp.clone() - zvp.clone(), den),
                zvp.clone(),
                "xp = x·(zprp − zvp)/(zprp − z),  yp = y·(zprp − zvp)/(zprp − z),  zp = zvp",
                "(zprp − zvp)/(zprp − z)",
            )
        }
    }))
}

/// The perspective projection as a 4×4 matrix (eye → homogeneous clip
/// space), built from the viewing window on the near plane
/// ([`crate::stages::window::window`]: top = near·tan(fovy/2), right = aspect·top):
///
/// ```text
/// | near/right  0         0                     0                  |
/// | 0           near/top  0                     0                  |
/// | 0           0         −(far+near)/(far−near) −2·far·near/(far−near) |
/// | 0           0         −1                    0                  |
/// ```
///
/// so w = −z and x/w = (−near·x/z)/right: the text's projection onto the
/// near plane (d = −near, xp = d·x/z) divided by the window's half width,
/// −1 … 1 across the window. z/w runs from −1 on the near plane to +1 on the
/// far plane (nearer is smaller).
pub fn perspective_matrix<T: Scalar>(
    win: &crate::stages::window::Window<T>,
    near: &T,
    far: &T,
) -> nalgebra::Matrix4<T> {
    let mut m = nalgebra::Matrix4::<T>::zeros();
    let depth = far.clone() - near.clone();
    m[(0, 0)] = near.clone() / win.right.clone();
    m[(1, 1)] = near.clone() / win.top.clone();
    m[(2, 2)] = -(far.clone() + near.clone()) / depth.clone();
    m[(2, 3)] = -(T::from_i64(2) * far.clone() * near.clone()) / depth;
    m[(3, 2)] = -T::one();
    m
}

/// The projection matrix P (eye → clip space) as a step: the
/// [`perspective_matrix`] of the window, or the tilt view's
/// [`ortho_matrix`], given as `p`.
pub fn projection_step<T: Scalar>(p: &nalgebra::Matrix4<T>, ortho: bool, tr: &mut impl Trace) {
    tr.step(|| {
        let f = if ortho {
            "P = [2/width 0 0 −(right+left)/width; 0 2/height 0 −(top+bottom)/height; 0 0 −2/(far−near) −(far+near)/(far−near); 0 0 0 1]"
        } else {
            "P = [near/right 0 0 0; 0 near/top 0 0; 0 0 −(far+near)/(far−near) −2·far·near/(far−near); 0 0 −1 0]"
        };
        Step::new(Msg::Pixel(PixelMsg::ProjMatrix), f).res(Name::math("P"), Val::mat4(p))
    });
}

/// Clip coordinates of an object point: c = (x, y, z, w) = P·V·M·(P, 1),
/// with `pvm` the product P·V·M (one matrix per object). For the
/// perspective matrix w = −z_eye.
pub fn to_clip<T: Scalar>(
    pvm: &nalgebra::Matrix4<T>,
    name: &str,
    p: &V3<T>,
    tr: &mut impl Trace,
) -> nalgebra::Vector4<T> {
    let c = crate::stages::camera::apply(pvm, p);
    tr.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::Clip(name.to_string())),
            format!("c = (x, y, z, w) = P·V·M·{name}"),
        )
        .val(Name::math(name), Val::vec3(p))
        .res(Name::math("c"), vec4(&c))
    });
    c
}

/// A 4-vector as a value.
pub fn vec4<T: Scalar>(c: &nalgebra::Vector4<T>) -> Val {
    Val::List(c.iter().map(Val::num).collect())
}

/// The perspective division of clip coordinates c = (x, y, z, w): with
/// q = 1/w, the normalized coordinates (x·q, y·q, z·q), each −1 … 1 inside
/// the view volume (z·q is the depth, nearer is smaller). Returns them and q.
pub fn divide<T: Scalar>(c: &nalgebra::Vector4<T>, name: &str, tr: &mut impl Trace) -> (V3<T>, T) {
    let q = T::one() / c[3].clone();
    let n = vec::v3(
        c[0].clone() * q.clone(),
        c[1].clone() * q.clone(),
        c[2].clone() * q.clone(),
    );
    tr.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::Divide(name.to_string())),
            "1/w,  (xn, yn, zn) = (x·(1/w), y·(1/w), z·(1/w))",
        )
        .val(Name::math("c"), vec4(c))
        .res(Name::math("1/w"), Val::num(&q))
        .res(Name::math("(xn, yn, zn)"), Val::vec3(&n))
    });
    (n, q)
}

/// The orthographic projection (xp = x, yp = y) as a 4×4 matrix onto the
/// same clip space: the window [left, right] × [bottom, top] maps to −1 … 1
/// and eye z from −near to −far maps to −1 … 1 (w = 1).
pub fn ortho_matrix<T: Scalar>(
    win: &crate::stages::window::Window<T>,
    near: &T,
    far: &T,
) -> nalgebra::Matrix4<T> {
    let two = T::from_i64(2);
    let mut m = nalgebra::Matrix4::<T>::identity();
    m[(0, 0)] = two.clone() / win.width.clone();
    m[(0, 3)] = -(win.right.clone() + win.left.clone()) / win.width.clone();
    m[(1, 1)] = two.clone() / win.height.clone();
    m[(1, 3)] = -(win.top.clone() + win.bottom.clone()) / win.height.clone();
    let depth = far.clone() - near.clone();
    m[(2, 2)] = -two / depth.clone();
    m[(2, 3)] = -(far.clone() + near.clone()) / depth;
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stages::trace::NoTrace;

    #[test]
    fn plane_projection_by_similar_triangles() {
        // d = −0.1, P = (1, 2, −4): xp = −0.1·1/−4 = 0.025, yp = 0.05.
        let p = project(
            &Projection::Plane { d: -0.1 },
            "P",
            &V3::new(1.0, 2.0, -4.0),
            &mut NoTrace,
        )
        .unwrap();
        approx::assert_relative_eq!(p, V3::new(0.025, 0.05, -0.1), epsilon = 1e-16);
    }

    #[test]
    fn cop_on_positive_z_axis() {
        // COP at z = d = 10, plane z = 0: xp = x·d/(d − z) = 4·10/(10 − (−10)) = 2.
        let g = Projection::General {
            zprp: 10.0,
            zvp: 0.0,
        };
        let p = project(&g, "P", &V3::new(4.0, -6.0, -10.0), &mut NoTrace).unwrap();
        approx::assert_relative_eq!(p, V3::new(2.0, -3.0, 0.0), epsilon = 1e-15);
    }

    #[test]
    fn perspective_matrix_is_the_near_plane_projection_over_the_window() {
        // fovy 90°, aspect 2, near 0.5: top = 0.5, right = 1.
        let w = crate::stages::window::window(&90.0, &2.0, &0.5, "near", &mut NoTrace).unwrap();
        let m = perspective_matrix(&w, &0.5, &10.0);
        let p = V3::new(1.0, 2.0, -4.0);
        let c = m * nalgebra::Vector4::new(p.x, p.y, p.z, 1.0);
        // The text's projection onto z = −near, then divided by right and top.
        let q = project(&Projection::Plane { d: -0.5 }, "P", &p, &mut NoTrace).unwrap();
        approx::assert_relative_eq!(c.x / c.w, q.x / w.right, epsilon = 1e-15);
        approx::assert_relative_eq!(c.y / c.w, q.y / w.top, epsilon = 1e-15);
        // The near plane goes to z/w = −1 and the far plane to +1.
        let n = m * nalgebra::Vector4::new(0.0, 0.0, -0.5, 1.0);
        let f = m * nalgebra::Vector4::new(0.0, 0.0, -10.0, 1.0);
        approx::assert_relative_eq!(n.z / n.w, -1.0, epsilon = 1e-15);
        approx::assert_relative_eq!(f.z / f.w, 1.0, epsilon = 1e-15);
    }

    #[test]
    fn point_in_cop_plane_is_an_error() {
        let e = project(
            &Projection::Plane { d: -1.0 },
            "Q",
            &V3::new(1.0, 1.0, 0.0),
            &mut NoTrace,
        )
        .unwrap_err();
        assert_eq!(e.field, "points.Q");
        assert!(Projection::Plane { d: 0.0 }.validate().is_err());
        assert!(Projection::General {
            zprp: 2.0,
            zvp: 2.0
        }
        .validate()
        .is_err());
    }
}
