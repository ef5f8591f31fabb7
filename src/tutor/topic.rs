//! What a problem is about: the topics `generate` and `practice` ask by
//! name (`--topic`), each part's values practising one of them (a part's
//! module says which, `Solves::topic` in `tutor::parts`). Its own
//! module, beneath the generator and the parts alike, so that neither
//! imports the other for it.

/// What the problems are about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Topic {
    /// The camera basis u, v, n.
    Basis,
    /// The basis and eye coordinates of points.
    View,
    /// Projection onto the near plane.
    Project,
    /// The viewing window from fovy, aspect and near.
    Window,
    /// Line clipping with outcodes.
    Clip,
    /// Lighting at one point.
    Shade,
    /// The whole chain: view, projection, window, viewport.
    Pipeline,
}

impl Topic {
    /// Every topic, in the order `--topic` lists them.
    pub const ALL: [Topic; 7] = [
        Topic::Basis,
        Topic::View,
        Topic::Project,
        Topic::Window,
        Topic::Clip,
        Topic::Shade,
        Topic::Pipeline,
    ];

    /// Its name as `--topic` and the exam titles spell it (`basis`).
    pub fn name(self) -> &'static str {
        match self {
            Topic::Basis => "basis",
            Topic::View => "view",
            Topic::Project => "project",
            Topic::Window => "window",
            Topic::Clip => "clip",
            Topic::Shade => "shade",
            Topic::Pipeline => "pipeline",
        }
    }
}
