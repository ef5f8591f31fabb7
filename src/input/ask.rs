//! The parts a problem can ask for ([`Part`]): what a problem file's
//! `ask` names and the first name of every `solve` key, each spelled here
//! once. Its own module, so the problem file ([`crate::input::problem`])
//! and the typed problem ([`crate::input::part`]) both take it from below.

use std::fmt;

/// A part of a problem: what a problem file's `ask` names, and the first
/// name of a `solve` key (`tutor::key` re-exports it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Part {
    /// `view`: the camera basis, the view matrix, the eye coordinates.
    View,
    /// `project`: the points projected onto the near plane.
    Project,
    /// `window`: the viewing window's edges and size.
    Window,
    /// `viewport`: the pixels of the projected points.
    Viewport,
    /// `clip`: the outcodes, intersections and clipped segment.
    Clip,
    /// `shade`: the lighting of one point.
    Shade,
}

impl Part {
    /// Every part, in the order of the text's solution (the order solve
    /// runs them).
    pub fn all() -> Vec<Part> {
        std::iter::successors(Some(Part::View), |p| p.next()).collect()
    }

    /// The part after this one: an exhaustive match, so a new part is
    /// listed (asked, solved and read from a key) as soon as it compiles.
    fn next(self) -> Option<Part> {
        match self {
            Part::View => Some(Part::Project),
            Part::Project => Some(Part::Window),
            Part::Window => Some(Part::Viewport),
            Part::Viewport => Some(Part::Clip),
            Part::Clip => Some(Part::Shade),
            Part::Shade => None,
        }
    }

    /// Its name (in `ask`, and first in its answers' keys): the one place
    /// it is spelled.
    pub fn name(self) -> &'static str {
        match self {
            Part::View => "view",
            Part::Project => "project",
            Part::Window => "window",
            Part::Viewport => "viewport",
            Part::Clip => "clip",
            Part::Shade => "shade",
        }
    }

    /// The part of that name, if any.
    pub fn named(name: &str) -> Option<Part> {
        Part::all().into_iter().find(|p| p.name() == name)
    }
}

impl fmt::Display for Part {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.name())
    }
}
