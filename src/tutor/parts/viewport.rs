//! The viewport part (step 5 of the text): the pixel of each point (x, y)
//! on the window in the viewport W × H, xv = (x − left)·W/width, yv =
//! (y − bottom)·H/height; the points are given on the window or are the
//! projected points.

use crate::error::Result;
use crate::input::eval;
use crate::msg::Msg;
use crate::num::Scalar;
use crate::stages::trace::{Recorder, Val};
use crate::stages::window::{self, Window};
use crate::tutor::key::{Field, Key, Part, Value};
use crate::tutor::parts::fields::Fields;
use crate::tutor::parts::{names, Out, Solver, Solves};
use crate::tutor::run::Named;
use crate::tutor::solution::{at, Given};
use crate::tutor::topic::Topic;

/// The viewport part.
pub struct ViewportPart;

impl Solves for ViewportPart {
    const PART: Part = Part::Viewport;
    type In = ();
    type Result = ViewportResult;

    /// `viewport`: the pixels of the points on the window (given, or the
    /// projected points); a command given no points writes no pixels.
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, _: &()) -> Result<()> {
        let per = s.p.shared.perspective.as_ref();
        let vp = per.and_then(|x| x.table.viewport.as_ref().map(|v| (x, v)));
        let (Some(w), Some((per, vp))) = (s.windowed()?, vp) else {
            return Ok(());
        };
        let shown = match w.on_window {
            Some(given) => given,
            None => s.projected_xy()?,
        };
        let field = per.field("viewport");
        let (vw, vh): (T, T) = (eval(&field, &vp[0])?, eval(&field, &vp[1])?);
        window::validate_viewport(&vw, &vh).map_err(|e| e.in_field(field))?;
        s.out.section(Msg::SecViewport);
        let Out { rec, parts, .. } = &mut s.out;
        let windows = parts.iter_mut().filter_map(|g| match g {
            Given::Window(w) => Some(w),
            _ => None,
        });
        for given in windows {
            given.viewport = Some((at(&vw), at(&vh)));
        }
        let on_window = shown.iter().map(|(n, (x, y))| (n, (x, y)));
        let px = pixels(&w.w, (&vw, &vh), on_window, rec);
        if !(px.is_empty() && s.p.shared.on_window.is_some()) {
            let pixels = Val::Map(px);
            s.put(ViewportResult { pixels });
        }
        Ok(())
    }

    /// The pixels.
    fn keys(r: &ViewportResult) -> Vec<Key> {
        let key = |v: Value| Key::new(Self::PART, v);
        names(r.field(Field::Pixels))
            .map(|n| key(Value::Pixel(n)))
            .collect()
    }

    /// The pixels come at the end of the whole chain.
    fn topic(_: &Value) -> Topic {
        Topic::Pipeline
    }
}

/// The viewport part's results: each point's pixel (xv, yv), by name.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewportResult {
    /// The pixels.
    pub pixels: Val,
}

impl Fields for ViewportResult {
    const ORDER: &'static [Field] = &[Field::Pixels];

    fn field(&self, f: Field) -> Option<&Val> {
        (f == Field::Pixels).then_some(&self.pixels)
    }

    fn field_mut(&mut self, f: Field) -> Option<&mut Val> {
        (f == Field::Pixels).then_some(&mut self.pixels)
    }
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// The projected points as points (x, y) on the window.
    fn projected_xy(&mut self) -> Result<Vec<(String, (T, T))>> {
        let projected = self.projected()?.map(|(_, q)| q).unwrap_or_default();
        let xy = |(n, q): Named<T>| (n, (q[0].clone(), q[1].clone()));
        Ok(projected.into_iter().map(xy).collect())
    }
}

/// The pixels of points (x, y) on window `w` in the viewport W × H.
pub fn pixels<'p, T: Scalar + 'p>(
    w: &Window<T>,
    (vw, vh): (&T, &T),
    points: impl Iterator<Item = (&'p String, (&'p T, &'p T))>,
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
    points
        .map(|(n, xy)| {
            let (a, b) = window::to_viewport(w, (vw, vh), n, xy, rec);
            (n.clone(), Val::vec2(&a, &b))
        })
        .collect()
}
