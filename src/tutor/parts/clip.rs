//! The clip part: each segment P0P1 clipped against the box (min, max) by
//! outcodes (the region code of each end; accepted, rejected, or cut at
//! each plane tried, P(t) = P0 + t(P1 − P0)), cross-checked by
//! Liang–Barsky.

use crate::error::{Error, Result};
use crate::input::eval3;
use crate::input::part::ClipIn;
use crate::input::problem::PointRef;
use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::clip::{self, ClipBox};
use crate::stages::trace::{Name, Recorder, Step, Trace, Val};
use crate::tutor::follow;
use crate::tutor::key::{Cut, Field, Key, Node, Part, Plane, Value};
use crate::tutor::parts::{map_of, Solver, Solves};
use crate::tutor::run::{in_table, Hooks};
use crate::tutor::solution::Given;
use crate::tutor::topic::Topic;

/// The clip part.
pub struct ClipPart;

impl Solves for ClipPart {
    const PART: Part = Part::Clip;
    type In = ClipIn;

    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, c: &ClipIn) -> Result<()> {
        s.clip(c)
    }

    /// Per segment (of several: each its own), the outcodes, each plane
    /// tried, the clipped segment, the status.
    fn keys(v: &Val) -> Vec<Key> {
        let mut keys = Vec::new();
        match v {
            Val::List(runs) => {
                for (i, r) in runs.iter().enumerate() {
                    if let Val::Map(kv) = r {
                        keys.extend(clip_keys(kv).map(|k| k.of_segment(Some(i))));
                    }
                }
            }
            _ => keys.extend(clip_keys(map_of(v))),
        }
        keys
    }

    fn topic(_: &Value) -> Topic {
        Topic::Clip
    }
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// `clip`: the clipping of each segment against the box.
    fn clip(&mut self, c: &ClipIn) -> Result<()> {
        let [min, max] = &c.bounds.table;
        let b = ClipBox {
            min: eval3(&c.bounds.field("min"), min)?,
            max: eval3(&c.bounds.field("max"), max)?,
        };
        b.validate().map_err(|e| in_table(c.bounds.prefix, e))?;
        let mut all = Vec::new();
        let several = c.segments.len() > 1;
        for (i, [(ff, from), (tf, to)]) in c.segments.iter().enumerate() {
            let p0: V3<T> = point_ref(ff, from, &self.earlier.points)?;
            let p1: V3<T> = point_ref(tf, to, &self.earlier.points)?;
            self.out.section(Msg::SecLineClip(several.then_some(i + 1)));
            let segment = several.then_some(i);
            let given = Given::clip(&b, (&p0, &p1), segment);
            let hooks = (self.hooks, segment);
            all.push(Val::Map(clip_run(&b, (&p0, &p1), hooks, &mut self.out.rec)));
            self.out.parts.push(given);
        }
        match all.len() {
            0 => {}
            1 => self.put(Part::Clip, all.remove(0)),
            _ => self.put(Part::Clip, Val::List(all)),
        }
        Ok(())
    }
}

/// A segment end: its coordinates, or the named point's.
pub fn point_ref<T: Scalar>(
    field: &str,
    r: &PointRef,
    points: &[(String, V3<T>)],
) -> Result<V3<T>> {
    match r {
        PointRef::At(v) => eval3(field, v),
        PointRef::Named(name) => points
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| p.clone())
            .ok_or_else(|| {
                let known: Vec<&str> = points.iter().map(|(n, _)| n.as_str()).collect();
                Error::said(
                    field,
                    Msg::ErrUnknownPoint(
                        name.to_string(),
                        (!known.is_empty()).then(|| known.join(", ")),
                    ),
                )
            }),
    }
}

/// Segment (P0, P1) clipped by outcodes against box `b` (cross-checked by
/// Liang–Barsky), the clipping of `segment` (of a clip with several)
/// given by `hooks`: its result keys.
pub fn clip_run<T: Scalar>(
    b: &ClipBox<T>,
    (p0, p1): (&V3<T>, &V3<T>),
    (hooks, segment): (&Hooks<T>, Option<usize>),
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
    let mut r = clip_checked(b, p0, p1, rec);
    (hooks.clip)(&mut r, b, (p0, p1));
    if let Some(g) = hooks.givens() {
        follow::clipping(g, segment, b, (p0, p1), &mut r);
    }
    clip_result(&r)
}

/// Clips one segment by outcodes and by Liang–Barsky and records whether
/// they agree; the outcodes' clipping.
pub fn clip_checked<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    rec: &mut Recorder,
) -> clip::Clipped<T> {
    let r = clip::clip_segment(b, p0, p1, rec);
    let lb = clip::liang_barsky(b, p0, p1, rec);
    let agree = match (&r.segment, &lb) {
        (None, None) => true,
        (Some((a, z)), Some((c, d))) => close(a, c) && close(z, d),
        _ => false,
    };
    let segment = |s: &Option<(V3<T>, V3<T>)>| match s {
        Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
        None => Val::Null,
    };
    rec.step(|| {
        Step::new(Msg::MethodsAgree, Msg::FMethods)
            .val(Name::Outcodes, segment(&r.segment))
            .val(Name::math("Liang–Barsky"), segment(&lb))
            .res(Name::Agree, Val::Bool(agree))
            .note(if agree {
                Msg::Agree(true)
            } else {
                Msg::Agree(false)
            })
    });
    r
}

/// docs/spec.md's clip result keys of a clipping.
pub fn clip_result<T: Scalar>(r: &clip::Clipped<T>) -> Vec<(String, Val)> {
    vec![
        (Field::Code0.key(), Val::text(clip::code_str(r.code0))),
        (Field::Code1.key(), Val::text(clip::code_str(r.code1))),
        (Field::Status.key(), Val::text(r.status.as_str())),
        (
            Field::Segment.key(),
            match &r.segment {
                Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
                None => Val::Null,
            },
        ),
        (
            Field::Intersections.key(),
            Val::Map(r.intersections.iter().map(intersection_val).collect()),
        ),
    ]
}

/// One tried intersection as a result: its plane's key and t, point, code, kept.
fn intersection_val<T: Scalar>(i: &clip::Intersection<T>) -> (String, Val) {
    (
        Node::Plane(Plane::ALL[i.bit]).to_string(),
        Val::Map(vec![
            (Cut::T.key(), Val::num(&i.t)),
            (Cut::Point.key(), Val::vec3(&i.point)),
            (Cut::Code.key(), Val::text(clip::code_str(i.code))),
            (Cut::Kept.key(), Val::Bool(i.code == 0)),
        ]),
    )
}

/// Equal up to rounding (exact values compare exactly).
fn close<T: Scalar>(a: &V3<T>, b: &V3<T>) -> bool {
    (0..3).all(|k| {
        let (x, y) = (a[k].to_f64(), b[k].to_f64());
        a[k] == b[k] || (x - y).abs() <= 1e-5 * (1.0 + x.abs().max(y.abs()))
    })
}

/// The outcodes, each plane tried (t, intersection, its outcode), the
/// clipped segment, the status.
fn clip_keys(kv: &[(String, Val)]) -> impl Iterator<Item = Key> {
    let key = |v: Value| Key::new(Part::Clip, v);
    let mut keys = vec![
        key(Value::Field(Field::Code0)),
        key(Value::Field(Field::Code1)),
    ];
    let planes = Node::Field(Field::Intersections);
    if let Some((_, Val::Map(tried))) = kv.iter().find(|(k, _)| *k == planes.to_string()) {
        for (pl, _) in tried {
            if let Some(Node::Plane(p)) = Node::read(pl, Some(&planes)) {
                keys.extend([Cut::T, Cut::Point, Cut::Code].map(|c| key(Value::Cut(p, c))));
            }
        }
    }
    keys.push(key(Value::Field(Field::Segment)));
    keys.push(key(Value::Field(Field::Status)));
    keys.into_iter()
}
