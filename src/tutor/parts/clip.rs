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
use crate::tutor::parts::fields::Fields;
use crate::tutor::parts::{names, Solver, Solves};
use crate::tutor::run::{in_table, Hooks};
use crate::tutor::solution::Given;
use crate::tutor::topic::Topic;

/// The clip part.
pub struct ClipPart;

impl Solves for ClipPart {
    const PART: Part = Part::Clip;
    type In = ClipIn;
    type Result = ClipResult;

    /// `clip`: the clipping of each segment against the box.
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, c: &ClipIn) -> Result<()> {
        let [min, max] = &c.bounds.table;
        let b = ClipBox {
            min: eval3(&c.bounds.field("min"), min)?,
            max: eval3(&c.bounds.field("max"), max)?,
        };
        b.validate().map_err(|e| in_table(c.bounds.prefix, e))?;
        let mut all = Vec::new();
        let several = c.segments.len() > 1;
        for (i, [(ff, from), (tf, to)]) in c.segments.iter().enumerate() {
            let p0: V3<T> = point_ref(ff, from, &s.earlier.points)?;
            let p1: V3<T> = point_ref(tf, to, &s.earlier.points)?;
            s.out.section(Msg::SecLineClip(several.then_some(i + 1)));
            let segment = several.then_some(i);
            let given = Given::clip(&b, (&p0, &p1), segment);
            let hooks = (s.hooks, segment);
            all.push(clip_run(&b, (&p0, &p1), hooks, &mut s.out.rec));
            s.out.parts.push(given);
        }
        if !all.is_empty() {
            s.put(all);
        }
        Ok(())
    }

    /// The outcodes, each plane tried, the clipped segment, the status
    /// (of each segment of several: the results' order numbers them).
    fn keys(r: &ClipResult) -> Vec<Key> {
        let key = |v: Value| Key::new(Part::Clip, v);
        let mut keys = vec![
            key(Value::Field(Field::Code0)),
            key(Value::Field(Field::Code1)),
        ];
        let under = Node::Field(Field::Intersections);
        for pl in names(r.field(Field::Intersections)) {
            if let Some(Node::Plane(p)) = Node::read(&pl, Some(&under)) {
                keys.extend([Cut::T, Cut::Point, Cut::Code].map(|c| key(Value::Cut(p, c))));
            }
        }
        keys.push(key(Value::Field(Field::Segment)));
        keys.push(key(Value::Field(Field::Status)));
        keys
    }

    fn topic(_: &Value) -> Topic {
        Topic::Clip
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
) -> ClipResult {
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

/// One segment's clipping as results: the outcodes of its ends, the
/// status, the clipped segment (null when rejected), each plane tried.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipResult {
    /// P0's outcode.
    pub code0: Val,
    /// P1's outcode.
    pub code1: Val,
    /// accepted, rejected or clipped.
    pub status: Val,
    /// The clipped segment's ends.
    pub segment: Val,
    /// Each plane tried, by name: t, P(t), its outcode, whether kept.
    pub intersections: Val,
}

impl Fields for ClipResult {
    const ORDER: &'static [Field] = &[
        Field::Code0,
        Field::Code1,
        Field::Status,
        Field::Segment,
        Field::Intersections,
    ];

    fn field(&self, f: Field) -> Option<&Val> {
        match f {
            Field::Code0 => Some(&self.code0),
            Field::Code1 => Some(&self.code1),
            Field::Status => Some(&self.status),
            Field::Segment => Some(&self.segment),
            Field::Intersections => Some(&self.intersections),
            _ => None,
        }
    }

    fn field_mut(&mut self, f: Field) -> Option<&mut Val> {
        match f {
            Field::Code0 => Some(&mut self.code0),
            Field::Code1 => Some(&mut self.code1),
            Field::Status => Some(&mut self.status),
            Field::Segment => Some(&mut self.segment),
            Field::Intersections => Some(&mut self.intersections),
            _ => None,
        }
    }
}

/// A clipping's results.
pub fn clip_result<T: Scalar>(r: &clip::Clipped<T>) -> ClipResult {
    ClipResult {
        code0: Val::text(clip::code_str(r.code0)),
        code1: Val::text(clip::code_str(r.code1)),
        status: Val::text(r.status.as_str()),
        segment: match &r.segment {
            Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
            None => Val::Null,
        },
        intersections: Val::Map(r.intersections.iter().map(intersection_val).collect()),
    }
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
