//! What every part's run through the stages shares: the [`Hooks`] that
//! the mistake catalog and follow-through use to alter a stage's results
//! between stages, named points, and a stage's error named by its table's
//! field. Each part's run functions are in its module of
//! [`crate::tutor::parts`].

use crate::error::Error;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera::{self, Basis};
use crate::stages::clip::ClipBox;
use crate::stages::trace::Val;
use crate::stages::window;
use crate::tutor::follow;
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
