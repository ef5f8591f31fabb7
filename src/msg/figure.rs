//! What the figures say: each panel's title and description (for the
//! caption and for screen readers), the few words inside them, and the
//! errors of `--figure` and `--html` files.

/// A panel of a drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Panel {
    /// The world axes, Peye, Pref, Vup and u, v, n.
    #[cfg_attr(test, default)]
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
    /// The clipping box and segment, in 3D.
    Clip,
    /// The segment along its parameter t, with the intersections tried.
    ClipAlong,
    /// The lighting vectors in the plane of incidence (one light).
    Shade,
    /// The plane of incidence of light k (of several).
    ShadeLight(usize),
    /// The plane of R and V (when V leaves the plane of incidence).
    ShadeRV,
    /// The plane of N and H (when H leaves the plane of incidence).
    ShadeNH,
}

/// A word or short phrase written inside a figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum FigWord {
    /// The centre of projection.
    #[cfg_attr(test, default)]
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
    /// A region code (the text's term; "outcode" in English).
    Outcode,
    /// An intersection that bounds the kept part.
    Kept,
    /// An intersection outside the box (its part is cut off).
    CutOff,
    /// The angle between N and H (Blinn's), as a label names it.
    AngleNH,
    /// Both ends' codes are 000000: the segment is kept whole.
    Accepted,
    /// No intersection tried is in the box: the segment misses it.
    Missed,
}

/// A figure's message.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum FigureMsg {
    /// A panel's title.
    Title(Panel),
    /// A panel's description.
    Desc(Panel),
    /// A word inside a figure.
    Word(FigWord),
    /// The view a 3D panel is drawn in: the direction toward the viewer
    /// `(x, y, z)`, its azimuth and its elevation (degrees), as written.
    View {
        /// The direction.
        from: String,
        /// The azimuth.
        az: String,
        /// The elevation.
        el: String,
    },
    /// A vector (its name) that leaves the plane of incidence by an angle
    /// (degrees, as written), drawn in a further panel.
    OffPlane(String, String),
    /// A plane of the clip box by its bit (0 = left … 5 = back), with its
    /// equation (`x = 3`) when given: `x = 3 kanan`, `x = 3 (right)`.
    Plane(usize, Option<String>),
    /// Light k (from 1) is out of range: it has no plane drawn.
    OutOfRange(usize),
    /// The ends' codes ANDed (not 000000): the segment is rejected without
    /// intersections.
    Rejected(String),
}

/// For the tests' iteration over the message keys (`strum::EnumIter`
/// fills a variant's fields with their defaults).
#[cfg(test)]
impl Default for FigureMsg {
    fn default() -> FigureMsg {
        FigureMsg::Word(FigWord::default())
    }
}
