//! The viewing window on the near plane from fovy, aspect and near (and the
//! far-plane window), and the viewport mapping from the window to pixels.

use crate::error::{Error, Result};
use crate::msg::{Given, Msg, PixelMsg};
use crate::num::Scalar;
use crate::stages::trace::{Name, Step, Subst, Trace, Val};

/// A window on a plane z = −dist: its edges and size.
#[derive(Clone, Debug, PartialEq)]
pub struct Window<T> {
    /// top = dist·tan(fovy/2).
    pub top: T,
    /// bottom = −top.
    pub bottom: T,
    /// left = −right.
    pub left: T,
    /// right = aspect·top.
    pub right: T,
    /// height = 2·top.
    pub height: T,
    /// width = 2·right.
    pub width: T,
}

impl<T> Window<T> {
    /// Each number through `f` (the same window at another precision).
    pub fn map<U>(&self, f: impl Fn(&T) -> U) -> Window<U> {
        let [top, bottom, left, right, height, width] = [
            &self.top,
            &self.bottom,
            &self.left,
            &self.right,
            &self.height,
            &self.width,
        ]
        .map(f);
        Window {
            top,
            bottom,
            left,
            right,
            height,
            width,
        }
    }
}

/// Checks fovy (degrees) ∈ (0°, 180°), aspect > 0 and near > 0.
pub fn validate<T: Scalar>(fovy_deg: &T, aspect: &T, near: &T) -> Result<()> {
    if !(*fovy_deg > T::zero() && *fovy_deg < T::from_i64(180)) {
        return Err(Error::said("fovy", Msg::ErrFovy(fovy_deg.to_f64())));
    }
    if *aspect <= T::zero() {
        return Err(Error::said("aspect", Msg::ErrAspect(got(aspect))));
    }
    if *near <= T::zero() {
        return Err(Error::said("near", Msg::ErrNear(got(near))));
    }
    Ok(())
}

/// A refused value as the message shows it: a float zero says that a tiny
/// positive number written (1e-400) is 0 at that precision too.
fn got<T: Scalar>(x: &T) -> Given {
    let v = x.to_f64();
    match T::PRECISION {
        crate::num::Precision::F64 if v == 0.0 => Given::ZeroAt("f64", "5e-324"),
        crate::num::Precision::F32 if v == 0.0 => Given::ZeroAt("f32", "1e-45"),
        _ => Given::Value(v),
    }
}

/// The window on the plane at distance `dist` (near or far):
///
/// top = dist·tan(fovy/2), bottom = −top, right = aspect·top, left = −right,
/// height = 2·top, width = 2·right.
///
/// `label` names the plane in the steps ("near", "far").
pub fn window<T: Scalar>(
    fovy_deg: &T,
    aspect: &T,
    dist: &T,
    label: &str,
    tr: &mut impl Trace,
) -> Result<Window<T>> {
    validate(fovy_deg, aspect, dist).map_err(|e| {
        if e.field == "near" {
            e.in_field(label)
        } else {
            e
        }
    })?;
    let half = fovy_deg.clone() / T::from_i64(2);
    let t = half.tan_deg();
    let w = edges(dist.clone() * t.clone(), aspect);
    tr.step(|| {
        Step::new(
            Msg::WindowTop(label.to_string()),
            format!("top = {label}·tan(fovy/2)"),
        )
        .val(Name::math(label), Val::num(dist))
        .val(Name::HalfFovy, Val::num(&half))
        .sub(Name::HalfFovy, Subst::new("{}/2", vec![Val::num(fovy_deg)]))
        .val(Name::math("tan(fovy/2)"), Val::num(&t))
        .sub(
            Name::math("tan(fovy/2)"),
            Subst::new("tan({}°)", vec![Val::num(&half)]),
        )
        .res(Name::math("top"), Val::num(&w.top))
        .sub(
            Name::math("top"),
            Subst::new("{}·{}", vec![Val::num(dist), Val::num(&t)]),
        )
        .note(Msg::TextH)
    });
    tr.step(|| {
        Step::new(Msg::WindowEdges(label.to_string()), Msg::FWindowEdges)
            .val(Name::math("aspect"), Val::num(aspect))
            .val(Name::math("top"), Val::num(&w.top))
            .res(Name::math("right"), Val::num(&w.right))
            .sub(
                Name::math("right"),
                Subst::new("{}·{}", vec![Val::num(aspect), Val::num(&w.top)]),
            )
            .res(Name::math("bottom"), Val::num(&w.bottom))
            .sub(
                Name::math("bottom"),
                Subst::new("−{}", vec![Val::num(&w.top)]),
            )
            .res(Name::math("left"), Val::num(&w.left))
            .sub(
                Name::math("left"),
                Subst::new("−{}", vec![Val::num(&w.right)]),
            )
            .res(Name::Height, Val::num(&w.height))
            .sub(Name::Height, Subst::new("2·{}", vec![Val::num(&w.top)]))
            .res(Name::Width, Val::num(&w.width))
            .sub(Name::Width, Subst::new("2·{}", vec![Val::num(&w.right)]))
    });
    Ok(w)
}

/// The window's edges and size from its top and the aspect ratio:
/// bottom = −top, right = aspect·top, left = −right, height = 2·top,
/// width = 2·right.
pub fn edges<T: Scalar>(top: T, aspect: &T) -> Window<T> {
    let right = aspect.clone() * top.clone();
    let two = T::from_i64(2);
    Window {
        bottom: -top.clone(),
        left: -right.clone(),
        height: two.clone() * top.clone(),
        width: two * right.clone(),
        top,
        right,
    }
}

/// Checks a viewport size: both positive.
pub fn validate_viewport<T: Scalar>(w: &T, h: &T) -> Result<()> {
    if *w <= T::zero() || *h <= T::zero() {
        return Err(Error::why(
            "viewport",
            crate::msg::ErrMsg::Viewport(w.to_f64(), h.to_f64()),
        ));
    }
    Ok(())
}

/// The viewport mapping of a window point (xp, yp) to pixels, origin at the
/// bottom left:
///
/// px = (xp − left)/(right − left)·W,  py = (yp − bottom)/(top − bottom)·H.
pub fn to_viewport<T: Scalar>(
    w: &Window<T>,
    size: (&T, &T),
    name: &str,
    p: (&T, &T),
    tr: &mut impl Trace,
) -> (T, T) {
    let (px, py) = viewport_xy(w, size, p);
    tr.step(|| {
        let form = "({} − {})/({} − {})·{}";
        let n = Val::num;
        Step::new(
            Msg::ViewportOf(name.to_string()),
            "px = (xp − left)/(right − left)·W,  py = (yp − bottom)/(top − bottom)·H",
        )
        .val(
            Name::math(format!("({name}x, {name}y)")),
            Val::vec2(p.0, p.1),
        )
        .val(Name::math("W × H"), Val::vec2(size.0, size.1))
        .val(Name::math("px"), n(&px))
        .sub(
            Name::math("px"),
            Subst::new(
                form,
                vec![n(p.0), n(&w.left), n(&w.right), n(&w.left), n(size.0)],
            ),
        )
        .val(Name::math("py"), n(&py))
        .sub(
            Name::math("py"),
            Subst::new(
                form,
                vec![n(p.1), n(&w.bottom), n(&w.top), n(&w.bottom), n(size.1)],
            ),
        )
        .res(Name::Pixel(name.to_string()), Val::vec2(&px, &py))
    });
    (px, py)
}

/// The viewport formula alone (what [`to_viewport`] explains and the
/// renderer calls per vertex), origin at the bottom left:
///
/// px = (xp − left)/(right − left)·W,  py = (yp − bottom)/(top − bottom)·H.
#[inline]
pub fn viewport_xy<T: Scalar>(w: &Window<T>, size: (&T, &T), p: (&T, &T)) -> (T, T) {
    let px = (p.0.clone() - w.left.clone()) / w.width.clone() * size.0.clone();
    let py = (p.1.clone() - w.bottom.clone()) / w.height.clone() * size.1.clone();
    (px, py)
}

/// The window point of normalized coordinates (xn, yn), −1 … 1 across
/// the window:
///
/// xp = left + (xn + 1)·½·width,  yp = bottom + (yn + 1)·½·height.
#[inline]
pub fn window_point<T: Scalar>(w: &Window<T>, n: (&T, &T)) -> (T, T) {
    let half = T::from_f64(0.5);
    let xp = w.left.clone() + (n.0.clone() + T::one()) * half.clone() * w.width.clone();
    let yp = w.bottom.clone() + (n.1.clone() + T::one()) * half * w.height.clone();
    (xp, yp)
}

/// Normalized coordinates (xn, yn) to a pixel position (x, row) of a
/// W × H image with rows counted from the top (as an image file stores
/// them): the [`window_point`], the viewport mapping ([`to_viewport`]),
/// then row = H − py.
pub fn to_pixel<T: Scalar>(
    w: &Window<T>,
    size: (&T, &T),
    name: &str,
    n: (&T, &T),
    tr: &mut impl Trace,
) -> (T, T) {
    let (xp, yp) = window_point(w, n);
    tr.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::WindowPoint(name.to_string())),
            "xp = left + (xn + 1)·½·width,  yp = bottom + (yn + 1)·½·height",
        )
        .val(Name::math("(xn, yn)"), Val::vec2(n.0, n.1))
        .val(Name::math("(left, bottom)"), Val::vec2(&w.left, &w.bottom))
        .val(Name::math("width × height"), Val::vec2(&w.width, &w.height))
        .res(Name::math("(xp, yp)"), Val::vec2(&xp, &yp))
    });
    let (px, py) = to_viewport(w, size, name, (&xp, &yp), tr);
    let row = size.1.clone() - py.clone();
    tr.step(|| {
        Step::new(Msg::Pixel(PixelMsg::Row(name.to_string())), "row = H − py")
            .val(Name::math("H"), Val::num(size.1))
            .val(Name::math("py"), Val::num(&py))
            .res(Name::math("(x, row)"), Val::vec2(&px, &row))
    });
    (px, row)
}

/// Sub-pixel bits of the rasterizer's fixed-point screen coordinates: a
/// position is snapped to 1/2⁸ = 1/256 pixel.
pub const SUBPIXEL_BITS: i64 = 8;

/// x snapped to 1/256 pixel: X = round(256·x), halves away from zero (in
/// f64, exact for every f32 x; casts, no libm call).
#[inline]
pub fn snap(x: f32) -> i64 {
    let t = x as f64 * (1i64 << SUBPIXEL_BITS) as f64;
    (t + if t >= 0.0 { 0.5 } else { -0.5 }) as i64
}

/// A pixel position (x, row) snapped to 1/256 pixel ([`snap`]), each
/// coordinate an integer count of 1/256 pixel.
#[inline]
pub fn snap_pixel(p: (f32, f32), name: &str, tr: &mut impl Trace) -> [i64; 2] {
    let s = [snap(p.0), snap(p.1)];
    tr.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::Snap(name.to_string())),
            "X = round(256·x),  Y = round(256·row),  round(±(k + ½)) = ±(k + 1)",
        )
        .val(Name::math("(x, row)"), Val::vec2(&p.0, &p.1))
        .res(
            Name::math("(X, Y)"),
            Val::text(format!("({}, {})", s[0], s[1])),
        )
        .res(
            Name::math("(X/256, Y/256)"),
            Val::vec2(&(s[0] as f64 / 256.0), &(s[1] as f64 / 256.0)),
        )
    });
    s
}

/// Whether a window point lies inside the window (edges included).
pub fn inside<T: Scalar>(w: &Window<T>, x: &T, y: &T) -> bool {
    *x >= w.left && *x <= w.right && *y >= w.bottom && *y <= w.top
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tiny_positive_number_is_not_reported_as_plain_0() {
        let en = |e: &Error| crate::report::words::words(&e.message, crate::report::lang::Lang::En);
        let e = validate(&45.0f64, &2.0, &0.0).unwrap_err();
        assert_eq!(e.field, "near");
        assert!(en(&e).contains("below about 5e-324 is 0 too"), "{}", en(&e));
        let e = validate(&45.0f32, &0.0, &0.1).unwrap_err();
        assert!(en(&e).contains("at f32 precision"), "{}", en(&e));
        let e = validate(&45.0f64, &-2.0, &0.1).unwrap_err();
        assert!(en(&e).ends_with("got -2"), "{}", en(&e));
    }
    use crate::stages::trace::NoTrace;

    #[test]
    fn window_of_a_90_degree_view() {
        // fovy 90°: tan 45° = 1, so top = near = 2, right = aspect·2 = 3.
        let w = window(&90.0, &1.5, &2.0, "near", &mut NoTrace).unwrap();
        approx::assert_relative_eq!(w.top, 2.0, epsilon = 1e-15);
        approx::assert_relative_eq!(w.right, 3.0, epsilon = 1e-15);
        approx::assert_relative_eq!(w.width, 6.0, epsilon = 1e-15);
        approx::assert_relative_eq!(w.height, 4.0, epsilon = 1e-15);
        // The window's centre maps to the viewport's centre, its top-right corner to (W, H).
        let c = to_viewport(&w, (&200.0, &100.0), "C", (&0.0, &0.0), &mut NoTrace);
        assert_eq!(c, (100.0, 50.0));
        let tr_ = to_viewport(&w, (&200.0, &100.0), "T", (&3.0, &2.0), &mut NoTrace);
        assert_eq!(tr_, (200.0, 100.0));
    }

    #[test]
    fn bad_windows_are_errors() {
        assert_eq!(
            window(&180.0, &1.0, &1.0, "near", &mut NoTrace)
                .unwrap_err()
                .field,
            "fovy"
        );
        assert_eq!(
            window(&0.0, &1.0, &1.0, "near", &mut NoTrace)
                .unwrap_err()
                .field,
            "fovy"
        );
        assert_eq!(
            window(&45.0, &0.0, &1.0, "near", &mut NoTrace)
                .unwrap_err()
                .field,
            "aspect"
        );
        assert_eq!(
            window(&45.0, &1.0, &-1.0, "near", &mut NoTrace)
                .unwrap_err()
                .field,
            "near"
        );
    }
}
