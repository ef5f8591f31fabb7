//! What a generated problem says: its title and statement as data (the
//! numbers already written as notation, `.` for the decimal point and `, `
//! between components); `report::words` writes them in each language.

/// The title of a generated problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawnTitle {
    /// The camera basis u, v, n.
    Basis,
    /// Eye coordinates of points.
    EyeCoordinates,
    /// Projection onto the near plane.
    Projection,
    /// The whole viewing pipeline.
    Pipeline,
    /// The viewing window.
    Window,
    /// Line clipping.
    Clipping,
    /// Lighting at a point.
    Lighting,
}

/// A camera as stated: Pe, Pr and Vup, each `(x, y, z)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CameraText {
    /// Pe.
    pub eye: String,
    /// Pr.
    pub look: String,
    /// Vup.
    pub up: String,
}

/// What a lighting problem asks for, by model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadeAsked {
    /// cos α, the ambient and diffuse terms.
    Lambert,
    /// cos α, H and N·H, the three terms.
    Blinn,
    /// cos α, R and cos β, the three terms.
    Phong,
}

/// The statement of a generated problem.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Statement {
    /// Find n, u, v.
    Basis(CameraText),
    /// Find n, u, v and the eye coordinates of the points (`A(1, 2, 3), …`).
    View(CameraText, String),
    /// Project the points onto the near plane (near).
    Project(CameraText, String, String),
    /// The four parts of the pipeline: camera, points, near, fovy (degrees),
    /// aspect, viewport (`200x100`).
    Pipeline {
        /// The camera.
        camera: CameraText,
        /// The points.
        points: String,
        /// near.
        near: String,
        /// fovy in degrees.
        fovy: String,
        /// The aspect ratio.
        aspect: String,
        /// The viewport, `WxH`.
        viewport: String,
    },
    /// The window from fovy (degrees), aspect and near.
    Window(String, String, String),
    /// Clip the segment P0 P1 against the box with corners min and max:
    /// (min, max, P0, P1).
    Clip(String, String, String, String),
    /// Lighting at a point.
    Shade {
        /// N.
        normal: String,
        /// Cs, `r, g, b`.
        color: String,
        /// L.
        light: String,
        /// V.
        view: String,
        /// phong, blinn or lambert (as in the file).
        model: String,
        /// The constants, `ka = 0.4, kd = 0.6, …`.
        constants: String,
        /// What is asked.
        asked: ShadeAsked,
    },
}
