//! The answer keys of a result tree in the order of the text's solution
//! (each part's order is its module's, [`crate::tutor::parts`]).

use crate::stages::trace::Val;
use crate::tutor::key::{Key, Node};
use crate::tutor::parts;

/// The answer keys of a result tree in the order of the text's solution:
/// n, u, v, the view matrix, the eye coordinates; the projected points;
/// the window's top, bottom, left, right, height, width (not the far
/// window's); the pixels; per segment the outcodes, each plane tried (its
/// t, intersection point and that point's outcode, the text's deciding
/// step), the clipped segment and the status; the lighting's unit L and
/// N, cos α, R (H and N·H for Blinn), cos β, the terms, their sum and the
/// clamped colour. Each key is a typed [`Key`] (spelled by its `Display`),
/// each part's in its module's order ([`parts::Solves::keys`]).
pub fn ordered_keys(result: &[(String, Val)]) -> Vec<Key> {
    let mut keys: Vec<Key> = Vec::new();
    for (name, v) in result {
        let Some(Node::Part(part)) = Node::read(name, None) else {
            continue;
        };
        keys.extend((parts::of(part).keys)(v));
    }
    keys
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(keys: &[&str]) -> Val {
        Val::Map(keys.iter().map(|k| (k.to_string(), Val::Null)).collect())
    }

    #[test]
    fn keys_come_in_the_order_of_the_texts_solution() {
        let view = Val::Map(vec![
            ("u".into(), Val::Null),
            ("v".into(), Val::Null),
            ("n".into(), Val::Null),
            ("matrix".into(), Val::Null),
            ("points".into(), map(&["A", "B"])),
        ]);
        let run = Val::Map(vec![
            ("code0".into(), Val::Null),
            ("status".into(), Val::Null),
            ("intersections".into(), map(&["top"])),
        ]);
        let result = vec![
            ("view".to_string(), view),
            ("window".into(), map(&["top", "far_top", "width"])),
            ("clip".into(), Val::List(vec![map(&["code0"]), run])),
            ("shade".into(), map(&["color", "cos_alpha", "L"])),
        ];
        let want = [
            "view.n",
            "view.u",
            "view.v",
            "view.matrix",
            "view.points.A",
            "view.points.B",
            "window.top",
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
    }
}
