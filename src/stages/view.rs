//! The view: how a scene is seen, and the transforms that follow from it
//! at an image size — a camera (`camera::view_matrix`) with a perspective
//! projection over its window (`window::window`,
//! `projection::perspective_matrix`), or the text's tilt view (a rotation
//! and an orthographic projection, `projection::ortho_matrix`).

use crate::error::Result;
use crate::stages::trace::{NoTrace, Trace};
use crate::stages::window::Window;
use crate::stages::{camera, projection, window};
use nalgebra::{Matrix4, Vector3};

/// How the scene is seen.
#[derive(Clone, Debug, PartialEq)]
pub enum View {
    /// The text's userdraw view: objects rotated by Rx(x)·Ry(y) (radians),
    /// orthographic, 1 unit = 1 pixel, origin at the image centre.
    Tilt {
        /// Rotation about x.
        x: f64,
        /// Rotation about y.
        y: f64,
    },
    /// A synthetic camera with a perspective projection.
    Camera {
        /// Pe, Pr, Vup.
        camera: camera::Camera<f64>,
        /// Vertical field of view, degrees.
        fovy: f64,
        /// Width/height of the window (default: the image's).
        aspect: Option<f64>,
        /// Near-plane distance.
        near: f64,
        /// Far-plane distance.
        far: f64,
    },
}

/// The view transforms of a scene at an image size.
#[derive(Clone, Debug)]
pub struct ViewSetup {
    /// World → eye.
    pub eye_from_world: Matrix4<f64>,
    /// Eye → clip.
    pub clip_from_eye: Matrix4<f64>,
    /// The window on the near plane (or the tilt view's pixel window).
    pub win: Window<f32>,
    /// Orthographic (the text's tilt view): the viewer is along +z.
    pub ortho: bool,
}

/// The view at an image of w × h pixels: the camera's view matrix and the
/// perspective over its window, or the tilt rotation and an orthographic
/// window of w × h units centred on the origin (1 unit = 1 pixel); with its
/// steps (the view matrix, the window, the projection matrix).
pub fn setup(view: &View, w: u32, h: u32, tr: &mut impl Trace) -> Result<ViewSetup> {
    let vs = view_of(view, w, h, tr)?;
    projection::projection_step(&vs.clip_from_eye, vs.ortho, tr);
    Ok(vs)
}

/// [`setup`] before the step of the projection matrix.
fn view_of(view: &View, w: u32, h: u32, tr: &mut impl Trace) -> Result<ViewSetup> {
    let (wf, hf) = (w as f64, h as f64);
    match view {
        View::Tilt { x, y } => {
            let rot = Matrix4::from_axis_angle(&Vector3::x_axis(), *x)
                * Matrix4::from_axis_angle(&Vector3::y_axis(), *y);
            let win = Window {
                top: hf / 2.0,
                bottom: -hf / 2.0,
                left: -wf / 2.0,
                right: wf / 2.0,
                height: hf,
                width: wf,
            };
            // Depth range ±10⁶ units: nothing the text draws comes near it.
            let clip = projection::ortho_matrix(&win, &-1e6, &1e6);
            Ok(ViewSetup {
                eye_from_world: rot,
                clip_from_eye: clip,
                win: win.map(|&x| x as f32),
                ortho: true,
            })
        }
        View::Camera {
            camera,
            fovy,
            aspect,
            near,
            far,
        } => {
            let b = camera::basis(camera, &mut NoTrace)?;
            let v = camera::view_matrix(&b, &camera.pe, tr)?;
            let aspect = aspect.unwrap_or(wf / hf);
            let win = window::window(fovy, &aspect, near, "near", tr)?;
            let p = projection::perspective_matrix(&win, near, far);
            Ok(ViewSetup {
                eye_from_world: v,
                clip_from_eye: p,
                win: win.map(|&x| x as f32),
                ortho: false,
            })
        }
    }
}
