//! The parts of a problem run through the stages, once for every way a
//! problem is given (a calculator command's flags, a problem file's
//! tables): the camera basis, the view matrix and eye coordinates, the
//! projection of points, the window (and the far one), the viewport's
//! pixels, the clipping of a segment and the lighting of a point; each
//! with the [`Hooks`] that the mistake catalog and follow-through use.
//! Where the inputs come from, and how the results are keyed, is the
//! caller's.

use crate::error::{Error, Result};
use crate::input::lights::{LightsFileIn, Setup, ShadeIn};
use crate::msg::{Bound, ErrMsg};
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera::{self, Basis, Camera};
use crate::stages::clip::ClipBox;
use crate::stages::projection::{self, Projection};
use crate::stages::trace::{Recorder, Val};
use crate::stages::window::{self, Window};
use crate::tutor::follow;
use crate::tutor::key::{Edge, Field, Key, Part, Value};
use crate::tutor::keys::{basis_result, clip_checked, clip_result, shade_run, window_result};
use crate::tutor::solution::Tree;
use nalgebra::Matrix4;

/// A named point.
pub type Named<T> = (String, V3<T>);

/// An alteration of the lighting set-up.
pub type SetupHook<T> = dyn Fn(&mut crate::input::lights::Setup<T>);

/// A matrix from the camera basis and Pe (Mcam: [`camera::camera_matrix`]).
pub type ViewHook<T> = fn(&Basis<T>, &V3<T>) -> Matrix4<T>;

/// An alteration of a segment's clipping, given the box and its ends.
pub type ClipHook<T> = fn(&mut crate::stages::clip::Clipped<T>, &ClipBox<T>, (&V3<T>, &V3<T>));

/// Alterations applied to stage results between stages. Solving uses none;
/// the mistake catalog (`diagnose`) sets one to re-run the real stages with
/// one step done the wrong way, instead of copying the pipeline's math;
/// follow-through gives the student's own values for the steps after them
/// to go on from ([`follow`]).
pub struct Hooks<'a, T> {
    /// Applied to the camera basis before it is used.
    pub basis: fn(&mut camera::Basis<T>),
    /// A matrix written in place of the view matrix, from the basis and
    /// Pe, and whether the eye coordinates are then that matrix times the
    /// point (P' = M·P) instead of the text's (u·(P − Pe), …).
    pub view: Option<(ViewHook<T>, bool)>,
    /// Applied to the near-plane window before it is used (given fovy in degrees).
    pub window: fn(&mut window::Window<T>, &T),
    /// Applied to a segment's clipping, given the box and the ends P0, P1.
    pub clip: ClipHook<T>,
    /// The lighting stage's rules (the text's by default).
    pub shade: crate::stages::lighting::Rules<T>,
    /// Applied to the lighting set-up (its lights, its surface) before it is used.
    pub setup: Option<&'a SetupHook<T>>,
    /// Values given in place of the stages' own, by result key
    /// (follow-through): the steps after them go on from them.
    pub given: Option<&'a follow::Lookup<'a, T>>,
    /// Make no steps: only the results are wanted (follow-through).
    pub quiet: bool,
}

impl<T: Scalar> Default for Hooks<'_, T> {
    fn default() -> Self {
        Hooks {
            basis: |_| {},
            view: None,
            window: |_, _| {},
            clip: |_, _, _| {},
            shade: crate::stages::lighting::Rules::default(),
            setup: None,
            given: None,
            quiet: false,
        }
    }
}

impl<'a, T: Scalar> Hooks<'a, T> {
    /// The values given, if any.
    pub(crate) fn givens(&self) -> Option<follow::Givens<'a, T>> {
        self.given.map(follow::Givens)
    }
}

/// The camera basis u, v, n (altered by `hooks`).
pub fn basis_run<T: Scalar>(
    cam: &Camera<T>,
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<Basis<T>> {
    let mut b = camera::basis(cam, rec)?;
    (hooks.basis)(&mut b);
    if let Some(g) = hooks.givens() {
        follow::basis(g, cam, &mut b);
    }
    Ok(b)
}

/// The view matrix (its errors' fields under `prefix`: `camera.eye`) and
/// the eye coordinates of `points` (each `view.points.A` given by `hooks`
/// in place of its own).
pub fn eye_run<T: Scalar>(
    b: &Basis<T>,
    cam: &Camera<T>,
    points: &[Named<T>],
    (hooks, prefix): (&Hooks<T>, &str),
    rec: &mut Recorder,
) -> Result<(Matrix4<T>, Vec<Named<T>>)> {
    let mut m = camera::view_matrix(b, &cam.pe, rec).map_err(|e| in_table(prefix, e))?;
    let mut by_matrix = false;
    if let Some((written, used)) = hooks.view {
        m = written(b, &cam.pe);
        by_matrix = used;
    }
    let mut eye = Vec::new();
    for (n, q) in points {
        let e = if by_matrix {
            camera::apply(&m, q).xyz()
        } else {
            camera::to_eye(b, &cam.pe, n, q, rec)?
        };
        let given = hooks
            .givens()
            .and_then(|g| g.vec3(&Key::new(Part::View, Value::Point(n.clone()))));
        eye.push((n.clone(), given.unwrap_or(e)));
    }
    Ok((m, eye))
}

/// A stage's error reported against the field of the table its input came
/// from (`up` → `camera.up` in a problem file; no prefix for a flag).
pub fn in_table(prefix: &str, e: Error) -> Error {
    let f = format!("{prefix}{}", e.field);
    e.in_field(f)
}

/// Named points as a result map.
pub fn points_val<T: Scalar>(pts: &[Named<T>]) -> Val {
    Val::Map(pts.iter().map(|(n, e)| (n.clone(), Val::vec3(e))).collect())
}

/// The view's result keys: u, v, n, the matrix, the eye coordinates.
pub fn view_result<T: Scalar>(
    b: &Basis<T>,
    m: &Matrix4<T>,
    eye: &[Named<T>],
) -> Vec<(String, Val)> {
    let mut r = basis_result(b);
    r.push((Field::Matrix.key(), Val::mat4(m)));
    r.push((Field::Points.key(), points_val(eye)));
    r
}

/// The images of `points` under `proj` (each `project.points.A` given by
/// `hooks` in place of its own).
pub fn project_run<T: Scalar>(
    proj: &Projection<T>,
    points: &[Named<T>],
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<Vec<Named<T>>> {
    let mut out = Vec::new();
    for (n, e) in points {
        let q = projection::project(proj, n, e, rec)?;
        let given = hooks
            .givens()
            .and_then(|g| g.vec3(&Key::new(Part::Project, Value::Point(n.clone()))));
        out.push((n.clone(), given.unwrap_or(q)));
    }
    Ok(out)
}

/// The window on the near plane from (fovy in degrees, aspect, near, far)
/// (altered by `hooks`), and the far plane's when far is given, which must
/// lie beyond near: the window and its result keys (top … width, and the
/// far window's `far_top` … `far_right`).
pub fn window_run<T: Scalar>(
    (fovy, aspect, near, far): (&T, &T, &T, Option<&T>),
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<(Window<T>, Tree)> {
    let mut w = window::window(fovy, aspect, near, "near", rec)?;
    (hooks.window)(&mut w, fovy);
    if let Some(g) = hooks.givens() {
        follow::window(g, aspect, &mut w);
    }
    let mut r = window_result(&w, false);
    if let Some(f) = far {
        if f <= near {
            let (near, got) = (near.to_f64(), f.to_f64());
            return Err(Error::why(
                "far",
                ErrMsg::MustBe(Bound::AboveNear(near), got),
            ));
        }
        let fw = window::window(fovy, aspect, f, "far", rec)?;
        // the far window's edges, not its size
        let size = [Edge::Height, Edge::Width].map(|e| Field::Edge(e, true).key());
        r.extend(
            window_result(&fw, true)
                .into_iter()
                .filter(|(k, _)| !size.contains(k)),
        );
    }
    Ok((w, r))
}

/// The pixels of points (x, y) on window `w` in the viewport W × H.
pub fn pixels<'p, T: Scalar + 'p>(
    w: &Window<T>,
    (vw, vh): (&T, &T),
    points: impl Iterator<Item = (&'p String, (&'p T, &'p T))>,
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
    points
        .map(|(n, xy)| {
            let (a, b) = window::to_viewport(w, (vw, vh), n, xy, rec);
            (n.clone(), Val::vec2(&a, &b))
        })
        .collect()
}

/// Segment (P0, P1) clipped by outcodes against box `b` (cross-checked by
/// Liang–Barsky), the clipping of `segment` (of a clip with several)
/// given by `hooks`: its result keys.
pub fn clip_run<T: Scalar>(
    b: &ClipBox<T>,
    (p0, p1): (&V3<T>, &V3<T>),
    (hooks, segment): (&Hooks<T>, Option<usize>),
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
    let mut r = clip_checked(b, p0, p1, rec);
    (hooks.clip)(&mut r, b, (p0, p1));
    if let Some(g) = hooks.givens() {
        follow::clipping(g, segment, b, (p0, p1), &mut r);
    }
    clip_result(&r)
}

/// The lighting set-up of a `[shade]` table and lights (fields under
/// `prefix`), altered by `hooks`, lit: the set-up and the result keys.
pub fn light_run<T: Scalar>(
    (sh, file, prefix): (&ShadeIn, &LightsFileIn, &str),
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<(Setup<T>, Tree)> {
    let mut setup = crate::input::lights::build::<T>(sh, file, prefix, "light", rec)?;
    if let Some(f) = hooks.setup {
        f(&mut setup);
    }
    let r = match hooks.givens() {
        Some(given) if setup.lights.len() == 1 => {
            follow::setup(given, &mut setup);
            let rules = follow::GivenRules {
                rules: &hooks.shade,
                given,
            };
            shade_run(&setup, &rules, rec)
        }
        _ => shade_run(&setup, &hooks.shade, rec),
    };
    Ok((setup, r))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Real;

    fn num(r: &Tree, key: &str) -> Option<f64> {
        match crate::tutor::solution::lookup(r, key)? {
            Val::Num(s) => Some(s.value),
            _ => None,
        }
    }

    /// fovy 90°, aspect 2: top = near·tan 45° = near, right = aspect·top.
    /// Near 1: top 1, right 2, height 2, width 4; far 3: top 3, right 6;
    /// the far window gives its edges, not its height and width.
    #[test]
    fn the_far_window_gives_its_edges_once() {
        let (fovy, aspect, near, far) =
            (Real::from(90), Real::from(2), Real::from(1), Real::from(3));
        let mut rec = Recorder::new();
        let hooks = Hooks::default();
        let (_, r) = window_run((&fovy, &aspect, &near, Some(&far)), &hooks, &mut rec).unwrap();
        let keys: Vec<&str> = r.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(
            keys,
            [
                "top",
                "bottom",
                "left",
                "right",
                "height",
                "width",
                "far_top",
                "far_bottom",
                "far_left",
                "far_right"
            ]
        );
        assert_eq!(num(&r, "top"), Some(1.0));
        assert_eq!(num(&r, "width"), Some(4.0));
        assert_eq!(num(&r, "far_top"), Some(3.0));
        assert_eq!(num(&r, "far_right"), Some(6.0));
    }

    /// far must lie beyond near: far = near is refused, naming `far`, with
    /// the one message for the rule.
    #[test]
    fn far_at_near_is_refused_by_the_one_rule() {
        let (fovy, aspect, one) = (Real::from(90), Real::from(2), Real::from(1));
        let mut rec = Recorder::new();
        let e = window_run(
            (&fovy, &aspect, &one, Some(&one)),
            &Hooks::default(),
            &mut rec,
        )
        .unwrap_err();
        assert_eq!(e.field, "far");
        assert_eq!(
            e.message,
            crate::msg::Msg::Err(ErrMsg::MustBe(Bound::AboveNear(1.0), 1.0))
        );
    }
}
