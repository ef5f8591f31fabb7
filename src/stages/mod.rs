//! The stages the course text teaches, one module each: the camera basis and
//! view matrix ([`camera`]), projection ([`projection`]), the viewing window
//! and viewport ([`window`]), 3D line clipping with outcodes ([`clip`]),
//! the lighting models ([`lighting`]), and the view a scene is seen with,
//! which composes camera, window and projection ([`view`]). Every stage
//! writes its worked steps to a [`trace::Trace`]; the renderer passes one
//! that records nothing.

pub mod camera;
pub mod clip;
pub mod lighting;
pub mod projection;
pub mod trace;
pub mod view;
pub mod window;
