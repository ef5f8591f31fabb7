//! The drawings of a report: one per part that has a figure (view,
//! project, window, clip, shade), each built by its figure kind from what
//! the part was given and its results.

use super::builders::Part;
use super::{camera, clip, project, shade, window, Drawing, Figure};
use crate::report::Style;
use crate::tutor::key;
use crate::tutor::solution::{Given, Report};

/// The drawings of a report, in the order of its parts.
pub fn drawings(r: &Report, st: &Style) -> Vec<Drawing> {
    r.parts
        .iter()
        .filter_map(|g| {
            let panels = figures(r, g, st)?;
            Some(Drawing {
                part: g.name(),
                panels,
            })
        })
        .collect()
}

/// The panels of part `g`.
fn figures(r: &Report, g: &Given, st: &Style) -> Option<Vec<Figure>> {
    let p = Part {
        res: r.part_result(g),
        pixels: None,
        steps: &r.steps,
    };
    match g {
        Given::Basis(c) => camera::figure(&p, st, c, &[]),
        Given::View(c, world) => camera::figure(&p, st, c, world),
        Given::Project {
            projection,
            points,
            chained,
        } => project::figures(&p, st, projection, (points, *chained)),
        Given::Window(w) => {
            // the pixels of a problem file's viewport part join the window's
            let viewport = r.result.of(key::Part::Viewport).and_then(|v| v.one(None));
            let pixels = viewport.and_then(|v| v.field(key::Field::Pixels));
            let p = Part { pixels, ..p };
            window::figures(&p, st, w)
        }
        Given::Clip(c) => clip::figures(&p, st, c),
        Given::Shade(_) => shade::figures(&p, st),
    }
}
