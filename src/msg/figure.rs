//! What the figures say: each panel's title and description (for the
//! caption and for screen readers), the few words inside them, and the
//! errors of `--figure` and `--html` files.

/// A panel of a drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panel {
    /// The world axes, Peye, Pref, Vup and u, v, n.
    Camera,
    /// Projectors from the centre of projection to the view plane, in 3D.
    Projection,
    /// The projection seen from the side (y–z), similar triangles.
    ProjectionSide,
    /// The images on the view plane (x–y).
    ViewPlane,
    /// The frustum from the eye with the near and far windows.
    Frustum,
    /// The frustum seen from the side (y–z), fovy and top.
    WindowSide,
    /// The window on the near plane with the points in it.
    NearWindow,
    /// The viewport with the pixel positions.
    Viewport,
    /// The clipping box and segment.
    Clip,
    /// The surface and the lighting vectors.
    Shade,
}

/// A word or short phrase written inside a figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FigWord {
    /// The centre of projection.
    Cop,
    /// The eye.
    Eye,
    /// A far window not drawn to scale.
    NotToScale,
    /// The surface.
    Surface,
    /// The legend of u, v, n (followed by the length they are drawn with).
    CameraAxes,
    /// The legend of the zoomed view plane (followed by the factor).
    Zoomed,
    /// Two vectors that coincide, drawn side by side.
    Coincide,
}

/// A figure's message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FigureMsg {
    /// A panel's title.
    Title(Panel),
    /// A panel's description.
    Desc(Panel),
    /// A word inside a figure.
    Word(FigWord),
    /// The file asked for exists (never overwritten): its path.
    Exists(String),
}
