//! The answer keys of the results in the order of the text's solution
//! (each part's order is its module's, [`crate::tutor::parts`]).

use crate::tutor::key::Key;
use crate::tutor::parts::result::Results;

/// The answer keys of the results in the order of the text's solution:
/// n, u, v, the view matrix, the eye coordinates; the projected points;
/// the window's top, bottom, left, right, height, width (not the far
/// window's); the pixels; per segment the outcodes, each plane tried (its
/// t, intersection point and that point's outcode, the text's deciding
/// step), the clipped segment and the status; the lighting's unit L and
/// N, cos α, R (H and N·H for Blinn), cos β, the terms, their sum and the
/// clamped colour. Each key is a typed [`Key`] (spelled by its `Display`),
/// each part's in its module's order ([`parts::Solves::keys`]).
pub fn ordered_keys(result: &Results) -> Vec<Key> {
    let mut keys: Vec<Key> = Vec::new();
    for r in result.parts.iter().filter(|_| result.nested) {
        for (segment, one) in r.segments() {
            keys.extend(one.keys().into_iter().map(|k| k.of_segment(segment)));
        }
    }
    keys
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stages::trace::Val;
    use crate::tutor::parts::clip::ClipResult;
    use crate::tutor::parts::result::PartResult;
    use crate::tutor::parts::shade::ShadeResult;
    use crate::tutor::parts::view::ViewResult;
    use crate::tutor::parts::window::{Edges, WindowResult};

    fn map(keys: &[&str]) -> Val {
        Val::Map(keys.iter().map(|k| (k.to_string(), Val::Null)).collect())
    }

    fn segment(tried: &[&str]) -> ClipResult {
        ClipResult {
            code0: Val::Null,
            code1: Val::Null,
            status: Val::Null,
            segment: Val::Null,
            intersections: map(tried),
        }
    }

    #[test]
    fn keys_come_in_the_order_of_the_texts_solution() {
        let view = ViewResult {
            u: Val::Null,
            v: Val::Null,
            n: Val::Null,
            matrix: Some(Val::Null),
            points: Some(map(&["A", "B"])),
        };
        let edges = || Edges {
            top: Val::Null,
            bottom: Val::Null,
            left: Val::Null,
            right: Val::Null,
        };
        let window = WindowResult {
            near: edges(),
            height: Val::Null,
            width: Val::Null,
            far: Some(edges()),
        };
        let shade = ShadeResult {
            l: Some(Val::Null),
            color: Some(Val::Null),
            cos_alpha: Some(Val::Null),
            ..ShadeResult::default()
        };
        let result = Results {
            nested: true,
            parts: vec![
                PartResult::View(Box::new(view)),
                PartResult::Window(Box::new(window)),
                PartResult::Clip(vec![segment(&[]), segment(&["top"])]),
                PartResult::Shade(Box::new(shade)),
            ],
        };
        let want = [
            "view.n",
            "view.u",
            "view.v",
            "view.matrix",
            "view.points.A",
            "view.points.B",
            "window.top",
            "window.bottom",
            "window.left",
            "window.right",
            "window.height",
            "window.width",
            "clip.0.code0",
            "clip.0.code1",
            "clip.0.segment",
            "clip.0.status",
            "clip.1.code0",
            "clip.1.code1",
            "clip.1.intersections.top.t",
            "clip.1.intersections.top.point",
            "clip.1.intersections.top.code",
            "clip.1.segment",
            "clip.1.status",
            "shade.L",
            "shade.cos_alpha",
            "shade.color",
        ];
        let got: Vec<String> = ordered_keys(&result).iter().map(Key::to_string).collect();
        assert_eq!(got, want);
        // a command's results answer no key of a part
        let command = Results {
            nested: false,
            ..result
        };
        assert!(ordered_keys(&command).is_empty());
    }
}
