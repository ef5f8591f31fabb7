//! The render summary's message keys: the names of its lines and the
//! per-pixel lighting line (their words: report/words/render.rs).

/// A name of the render summary: its JSON key (docs/spec.md §3, the
/// same in every language) is [`Summary::key`], its words in the text
/// `report::words::render::summary`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Summary {
    /// The PNG written.
    Image,
    /// Width × height in pixels.
    Size,
    /// The shadings drawn.
    Shading,
    /// Triangles set up and rasterized.
    TrianglesDrawn,
    /// Pixels coloured.
    PixelsShaded,
    /// The frame time, a median when more than one frame was rendered.
    FrameTime {
        /// Frames rendered (`--repeat`).
        runs: usize,
    },
}

impl Summary {
    /// The key of the JSON's `result` and `exact`: the contract of
    /// docs/spec.md §3, byte for byte, in every language.
    pub fn key(self) -> String {
        match self {
            Summary::Image => "image".into(),
            Summary::Size => "size".into(),
            Summary::Shading => "shading".into(),
            Summary::TrianglesDrawn => "triangles drawn".into(),
            Summary::PixelsShaded => "pixels shaded".into(),
            Summary::FrameTime { runs: 0 | 1 } => "frame time".into(),
            Summary::FrameTime { runs } => format!("frame time (median of {runs})"),
        }
    }
}

/// Where the lighting is evaluated per pixel: everywhere (every object
/// Phong-shaded), on the Phong objects only, or nowhere (the shadings
/// drawn, all per face or per vertex).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum PerPixel {
    /// Every object is Phong-shaded.
    Everywhere,
    /// Some objects are Phong-shaded, the others not.
    PhongObjectsOnly,
    /// No object is Phong-shaded: the shadings drawn, by their names.
    Nowhere(Vec<&'static str>),
}
