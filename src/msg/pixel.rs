//! What `render --explain-pixel` says about the geometry the renderer ran
//! for a pixel's triangle: step titles, sections and notes as data;
//! `report::words` writes them in each language.

/// A title, section or note of the pixel explainer's geometry steps.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum PixelMsg {
    /// Section: vertex k of the covering triangle, object to clip space.
    SecVertex(usize),
    /// Section: clipping the triangle against the planes it crosses.
    #[cfg_attr(test, default)]
    SecClip,
    /// Section: the view matrix V and the projection matrix P of the scene.
    SecMatrices,
    /// Section: vertex k of the set-up triangle, clip space to pixels.
    SecScreen(usize),
    /// The matrices of an object: M, V·M and P·V·M.
    Matrices(String),
    /// World coordinates of a point: Pw = M·P.
    World(String),
    /// Eye coordinates by the matrix V·M.
    Eye(String),
    /// The perspective (or the tilt view's orthographic) projection matrix.
    ProjMatrix,
    /// Clip coordinates of a point: c = P·V·M·P.
    Clip(String),
    /// The clip-space outcode of a point.
    Outcode(String),
    /// Clipping the polygon against one plane (its bit, 0…5).
    ClipPlane(usize),
    /// Perspective division of a point.
    Divide(String),
    /// The window point of a point's normalized coordinates.
    WindowPoint(String),
    /// The pixel row counted from the top.
    Row(String),
    /// Snapping to 1/256 pixel.
    Snap(String),
    /// The set-up triangle from the snapped vertices.
    SetUp,
    /// Formula with words: the clip-space outcode.
    FOutcode,
    /// Note: the renderer multiplies the model point by V·M at once.
    Composed,
    /// Note: the object's box is inside, so the renderer took every code as 0.
    BoxInside,
    /// Note: a vertex outside a plane gets no pixel of its own.
    Outside,
    /// Note: the set-up triangle is (true) or is not the rasterizer's.
    SameAsRaster(bool),
}
