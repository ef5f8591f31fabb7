//! 3D clipping against an axis-aligned box: 6-bit outcodes (the text's region
//! codes), the text's outcode line clipping (intersect with each violated
//! plane, keep intersections whose own code is 000000), and Liang–Barsky as
//! an independent cross-check.

use crate::error::{Error, Result};
use crate::msg::{Compared, Msg, PixelMsg, Trivial};
use crate::num::vec::{self, V3};
use crate::num::Scalar;
use crate::stages::trace::{Name, Step, Subst, Trace, Val};

/// The box xmin ≤ x ≤ xmax, ymin ≤ y ≤ ymax, zmin ≤ z ≤ zmax (boundary inside).
#[derive(Clone, Debug, PartialEq)]
pub struct ClipBox<T> {
    /// (xmin, ymin, zmin).
    pub min: V3<T>,
    /// (xmax, ymax, zmax).
    pub max: V3<T>,
}

impl<T: Scalar> ClipBox<T> {
    /// Checks min ≤ max on every axis.
    pub fn validate(&self) -> Result<()> {
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            if self.min[k] > self.max[k] {
                return Err(Error::said(
                    "min",
                    Msg::ErrBoxInverted(
                        axis.to_string(),
                        self.min[k].to_f64(),
                        self.max[k].to_f64(),
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// The outcome of clipping a segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Status {
    /// Both ends inside: kept whole.
    Accepted,
    /// Nothing of it inside.
    Rejected,
    /// Cut to the part inside.
    Clipped,
}

impl Status {
    /// docs/spec.md's word for it.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Accepted => "accepted",
            Status::Rejected => "rejected",
            Status::Clipped => "clipped",
        }
    }
}

/// The result of clipping P0P1.
#[derive(Clone, Debug, PartialEq)]
pub struct Clipped<T> {
    /// Outcode of P0.
    pub code0: u8,
    /// Outcode of P1.
    pub code1: u8,
    /// Accepted, rejected or clipped.
    pub status: Status,
    /// The part inside, in the direction P0 → P1.
    pub segment: Option<(V3<T>, V3<T>)>,
    /// Every intersection tried, in bit order.
    pub intersections: Vec<Intersection<T>>,
}

/// One intersection of the line with a plane an endpoint violates.
#[derive(Clone, Debug, PartialEq)]
pub struct Intersection<T> {
    /// The plane's bit (0 = bit 1, x < xmin, ... 5 = bit 6, z > zmax).
    pub bit: usize,
    /// The line parameter t.
    pub t: T,
    /// The point P(t).
    pub point: V3<T>,
    /// Its outcode (000000: kept).
    pub code: u8,
}

/// The short names of the six planes in bit order, as result keys.
pub const PLANE_KEYS: [&str; 6] = ["left", "right", "bottom", "top", "front", "back"];

/// The six planes in bit order: (axis, is_max, equation, the text's name).
pub const PLANES: [(usize, bool, &str, &str); 6] = [
    (0, false, "x = xmin", "kiri (left)"),
    (0, true, "x = xmax", "kanan (right)"),
    (1, false, "y = ymin", "bawah (bottom)"),
    (1, true, "y = ymax", "atas (top)"),
    (2, false, "z = zmin", "depan (front)"),
    (2, true, "z = zmax", "belakang (back)"),
];

/// The 6-bit outcode: bit 1 (rightmost) x < xmin, bit 2 x > xmax, bit 3
/// y < ymin, bit 4 y > ymax, bit 5 z < zmin, bit 6 z > zmax.
pub fn outcode<T: Scalar>(b: &ClipBox<T>, p: &V3<T>) -> u8 {
    let mut c = 0u8;
    for (bit, &(axis, is_max, _, _)) in PLANES.iter().enumerate() {
        let out = if is_max {
            p[axis] > b.max[axis]
        } else {
            p[axis] < b.min[axis]
        };
        if out {
            c |= 1 << bit;
        }
    }
    c
}

/// The 6-bit outcode of a point in homogeneous clip space (x, y, z, w),
/// against the view volume −w ≤ x, y, z ≤ w, in the same bit order as
/// [`outcode`] (the box [−w, w]³): bit 1 x < −w, bit 2 x > w, bit 3 y < −w,
/// bit 4 y > w, bit 5 z < −w (in front of the near plane), bit 6 z > w
/// (beyond the far plane). Comparing with w instead of dividing by it means
/// no division happens, so points at or behind the eye (w ≤ 0) get codes too.
#[inline]
pub fn outcode_clip_space<T: Scalar>(p: &nalgebra::Vector4<T>) -> u8 {
    let w = &p[3];
    let nw = -w.clone();
    let mut c = 0u8;
    for axis in 0..3 {
        if p[axis] < nw {
            c |= 1 << (2 * axis);
        }
        if p[axis] > *w {
            c |= 1 << (2 * axis + 1);
        }
    }
    c
}

/// [`outcode_clip_space`] as a step: each bit's comparison with ±w.
pub fn outcode_clip<T: Scalar>(c: &nalgebra::Vector4<T>, name: &str, tr: &mut impl Trace) -> u8 {
    let code = outcode_clip_space(c);
    tr.step(|| {
        let mut s = Step::new(
            Msg::Pixel(PixelMsg::Outcode(name.to_string())),
            Msg::Pixel(PixelMsg::FOutcode),
        )
        .val(Name::math("c"), crate::stages::projection::vec4(c));
        for (bit, &(axis, is_max, _, side)) in PLANES.iter().enumerate() {
            let a = ["x", "y", "z"][axis];
            let (op, lim) = if is_max { (">", "w") } else { ("<", "−w") };
            let set = code & (1 << bit) != 0;
            let bound = if is_max { c[3].clone() } else { -c[3].clone() };
            let values = Box::new(Compared(c[axis].shown(), op, bound.shown()));
            s = s.val(
                Name::Bit(bit, side),
                Val::said(crate::msg::Said::BitTest(
                    set,
                    format!("{a} {op} {lim}"),
                    values,
                )),
            );
        }
        s.res(Name::RegionCode, Val::text(code_str(code)))
    });
    code
}

/// The signed distance of clip-space point c = (x, y, z, w) to the plane of
/// outcode bit `bit` (in [`outcode_clip_space`]'s order), ≥ 0 on the inside:
/// w + x for x ≥ −w (bit 1), w − x for x ≤ w (bit 2), w + y, w − y, w + z,
/// w − z.
#[inline]
pub fn plane_distance<T: Scalar>(c: &[T], bit: usize) -> T {
    let v = c[bit / 2].clone();
    if bit.is_multiple_of(2) {
        c[3].clone() + v
    } else {
        c[3].clone() - v
    }
}

/// Clips a convex polygon in homogeneous clip space against the planes
/// whose outcode bits are set in `mask`, plane by plane in bit order
/// (Sutherland–Hodgman). A vertex is (x, y, z, w) followed by attributes;
/// for each edge P→Q with distances dP, dQ to the plane
/// ([`plane_distance`]): P is kept when dP ≥ 0, and where the edge crosses
/// the plane (dP ≥ 0 ≠ dQ ≥ 0) the point
///
/// t = dP/(dP − dQ),  R = P + t·(Q − P)
///
/// is added, every component (clip coordinates and attributes alike)
/// interpolated with the same t: they are linear in clip space, so no
/// division by w ≤ 0 ever happens. Stops when fewer than 3 vertices are
/// left (nothing inside). `tmp` is working space.
pub fn clip_polygon<T: Scalar + Copy, const N: usize, Tr: Trace>(
    poly: &mut Vec<[T; N]>,
    mask: u8,
    tmp: &mut Vec<[T; N]>,
    tr: &mut Tr,
) {
    for bit in 0..6 {
        if mask & (1 << bit) == 0 {
            continue;
        }
        tmp.clear();
        let mut ts = Vec::new();
        for k in 0..poly.len() {
            let (p, q) = (&poly[k], &poly[(k + 1) % poly.len()]);
            let (dp, dq) = (plane_distance(p, bit), plane_distance(q, bit));
            if dp >= T::zero() {
                tmp.push(*p);
            }
            if (dp >= T::zero()) != (dq >= T::zero()) {
                let t = dp / (dp - dq);
                tmp.push(std::array::from_fn(|i| p[i] + t * (q[i] - p[i])));
                if Tr::ON {
                    ts.push(Val::num(&t));
                }
            }
        }
        tr.step(|| clip_plane_step(bit, poly, tmp, ts));
        std::mem::swap(poly, tmp);
        if poly.len() < 3 {
            return;
        }
    }
}

/// The step of one plane of [`clip_polygon`]: the polygon before and after
/// (clip coordinates) and the t of each intersection.
fn clip_plane_step<T: Scalar, const N: usize>(
    bit: usize,
    before: &[[T; N]],
    after: &[[T; N]],
    ts: Vec<Val>,
) -> Step {
    let pts = |v: &[[T; N]]| {
        Val::List(
            v.iter()
                .map(|p| Val::List(p[..4].iter().map(Val::num).collect()))
                .collect(),
        )
    };
    let d = ["w + x", "w − x", "w + y", "w − y", "w + z", "w − z"][bit];
    Step::new(
        Msg::Pixel(PixelMsg::ClipPlane(bit)),
        format!("d = {d} (≥ 0 inside),  t = d₀/(d₀ − d₁),  R = P₀ + t·(P₁ − P₀)"),
    )
    .val(Name::Polygon, pts(before))
    .res(Name::math("t"), Val::List(ts))
    .res(Name::ClippedPolygon, pts(after))
}

/// An outcode written bit 6 first, as the text writes it (`001001`).
pub fn code_str(c: u8) -> String {
    format!("{c:06b}")
}

/// Clips the segment P0P1 to the box the text's way:
///
/// P(t) = P0 + t·(P1 − P0), 0 ≤ t ≤ 1. Both codes 000000: accept;
/// code0 AND code1 ≠ 0: reject; otherwise intersect with each plane an
/// endpoint violates (t = (plane − P0)/(P1 − P0) on that axis) and keep the
/// intersections whose own code is 000000; the kept points and the inside
/// endpoints bound the clipped segment.
pub fn clip_segment<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    tr: &mut impl Trace,
) -> Clipped<T> {
    // Compute outcodes for both endpoints
    let (code0, code1) = (outcode(b, p0), outcode(b, p1));
    tr.step(|| code_step("P0", b, p0, code0));
    tr.step(|| code_step("P1", b, p1, code1));
    tr.step(|| trivial_step(code0, code1));
    let decided = |status, segment| Clipped {
        code0,
        code1,
        status,
        segment,
        intersections: vec![],
    };
    match trivial(code0, code1) {
        Some(Status::Accepted) => return decided(Status::Accepted, Some((p0.clone(), p1.clone()))),
        Some(status) => return decided(status, None),
        None => {}
    }

    // Intersect with every plane one endpoint violates
    let intersections = intersect_planes(b, p0, p1, code0 | code1, tr);
    let kept = kept_points(&intersections, (p0, code0), (p1, code1));
    let segment = ends(&kept);
    let result = Clipped {
        code0,
        code1,
        status: if segment.is_some() {
            Status::Clipped
        } else {
            Status::Rejected
        },
        segment,
        intersections,
    };
    let ts: Vec<T> = kept.into_iter().map(|(t, _)| t).collect();
    tr.step(|| segment_step(&result.segment, &ts));
    result
}

/// The point of the line at t: the text's P(t) = P0 + t·(P1 − P0).
pub fn point_at<T: Scalar>(p0: &V3<T>, p1: &V3<T>, t: &T) -> V3<T> {
    vec::add(p0, &vec::scale(&vec::sub(p1, p0), t))
}

/// The trivial tests of the two outcodes: both 000000, accepted;
/// code0 AND code1 ≠ 0, rejected; otherwise None: the segment is clipped.
pub fn trivial(code0: u8, code1: u8) -> Option<Status> {
    if code0 | code1 == 0 {
        Some(Status::Accepted)
    } else if code0 & code1 != 0 {
        Some(Status::Rejected)
    } else {
        None
    }
}

/// The part of P0P1 inside the box: from the least to the greatest t of
/// the intersections kept (own code 000000) and the ends inside (P0 at
/// t = 0, P1 at t = 1, each with its code); None when nothing is kept.
pub fn kept_part<T: Scalar>(
    intersections: &[Intersection<T>],
    end0: (&V3<T>, u8),
    end1: (&V3<T>, u8),
) -> Option<(V3<T>, V3<T>)> {
    ends(&kept_points(intersections, end0, end1))
}

/// The first and the last of the kept points (sorted by t).
fn ends<T: Scalar>(kept: &[(T, V3<T>)]) -> Option<(V3<T>, V3<T>)> {
    match (kept.first(), kept.last()) {
        (Some(a), Some(z)) => Some((a.1.clone(), z.1.clone())),
        _ => None,
    }
}

/// The points that bound the clipped segment, by t: the intersections
/// whose own code is 000000 and the ends inside (P0 at t = 0, P1 at t = 1).
fn kept_points<T: Scalar>(
    intersections: &[Intersection<T>],
    (p0, code0): (&V3<T>, u8),
    (p1, code1): (&V3<T>, u8),
) -> Vec<(T, V3<T>)> {
    let mut kept: Vec<(T, V3<T>)> = (intersections.iter())
        .filter(|i| i.code == 0)
        .map(|i| (i.t.clone(), i.point.clone()))
        .collect();
    if code0 == 0 {
        kept.push((T::zero(), p0.clone()));
    }
    if code1 == 0 {
        kept.push((T::one(), p1.clone()));
    }
    kept.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
    kept
}

/// The step of the trivial accept and reject tests.
fn trivial_step(code0: u8, code1: u8) -> Step {
    let and = code0 & code1;
    Step::new(Msg::TrivialTests, Msg::FTrivial)
        .val(Name::math("code0"), Val::text(code_str(code0)))
        .val(Name::math("code1"), Val::text(code_str(code1)))
        .res(Name::math("code0 AND code1"), Val::text(code_str(and)))
        .sub(
            Name::math("code0 AND code1"),
            Subst::new(
                "{} AND {}",
                vec![Val::text(code_str(code0)), Val::text(code_str(code1))],
            ),
        )
        .note(if code0 | code1 == 0 {
            Msg::TrivialNote(Trivial::Accept)
        } else if and != 0 {
            Msg::TrivialNote(Trivial::Reject)
        } else {
            Msg::TrivialNote(Trivial::Clip)
        })
}

/// The intersections of P0P1 with every plane whose bit is set in `codes`
/// (in floats, on the problem halved when P1 − P0 would overflow: the same
/// t and points), each with its t, point and outcode.
fn intersect_planes<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    codes: u8,
    tr: &mut impl Trace,
) -> Vec<Intersection<T>> {
    let (hb, hp0, hp1, back) = halved_if_overflowing(b, p0, p1);
    let delta = vec::sub(&hp1, &hp0);
    let mut intersections = Vec::new();
    for (bit, &(axis, is_max, _, _)) in PLANES.iter().enumerate() {
        if codes & (1 << bit) == 0 {
            continue;
        }
        let bound = if is_max { &hb.max[axis] } else { &hb.min[axis] };
        // delta[axis] ≠ 0: exactly one end is outside this plane.
        let t = (bound.clone() - hp0[axis].clone()) / delta[axis].clone();
        let mut q = intersection_point(&hp0, &hp1, &delta, axis, bound);
        if let Some(two) = &back {
            q = vec::scale(&q, two);
            q[axis] = if is_max { &b.max[axis] } else { &b.min[axis] }.clone();
        }
        let code = outcode(b, &q);
        let i = Intersection {
            bit,
            t,
            point: q,
            code,
        };
        tr.step(|| intersection_step(&i, p0, p1));
        intersections.push(i);
    }
    intersections
}

/// The step of one intersection of P0P1: t, P(t), its code, kept or not.
fn intersection_step<T: Scalar>(i: &Intersection<T>, p0: &V3<T>, p1: &V3<T>) -> Step {
    let (axis, _, plane, _) = PLANES[i.bit];
    // t = (bound − P0ₐ)/(P1ₐ − P0ₐ); the point lies on the plane: its ₐ is the bound
    let (bound, a0, a1) = (&i.point[axis], &p0[axis], &p1[axis]);
    let t_values = [bound, a0, a1, a0].map(Val::num).to_vec();
    Step::new(
        Msg::Intersection(i.bit, plane.to_string()),
        format!(
            "t = ({plane_side} − {a}0)/({a}1 − {a}0),  P(t) = P0 + t·(P1 − P0)",
            plane_side = &plane[4..],
            a = ["x", "y", "z"][axis]
        ),
    )
    .val(Name::math("t"), Val::num(&i.t))
    .sub(Name::math("t"), Subst::new("({} − {})/({} − {})", t_values))
    .res(Name::math("P(t)"), Val::vec3(&i.point))
    .sub(
        Name::math("P(t)"),
        Subst::new(
            "{} + {}·{}",
            vec![Val::vec3(p0), Val::num(&i.t), Val::vec3(&vec::sub(p1, p0))],
        ),
    )
    .res(Name::RegionCode, Val::text(code_str(i.code)))
    .note(if i.code == 0 {
        Msg::Kept(true)
    } else {
        Msg::Kept(false)
    })
}

/// The step of the clipped segment (or of its rejection), from the t of
/// the points kept, smallest first.
fn segment_step<T: Scalar>(segment: &Option<(V3<T>, V3<T>)>, kept: &[T]) -> Step {
    let ts = match kept {
        [] => Val::Null,
        _ => Val::List(kept.iter().map(Val::num).collect()),
    };
    let s = Step::new(Msg::ClippedSegment, Msg::FSegment).val(Name::TKept, ts);
    match segment {
        Some((a, z)) => s
            .res(Name::From, Val::vec3(a))
            .res(Name::To, Val::vec3(z))
            .note(if a == z {
                Msg::TouchesPoint
            } else {
                Msg::InsidePart
            }),
        None => s.res(Name::Segment, Val::Null).note(Msg::Misses),
    }
}

/// P(t) = P0 + t·Δ on the plane `axis` = `bound`, where t = (bound − P0ₐ)/Δₐ.
///
/// Each other coordinate is evaluated as one quotient of the exact
/// differences, (Pₖ·Δₐ + (bound − Pₐ)·Δₖ)/Δₐ with P the end nearer the plane, with the numerator a sum of
/// products rounded once ([`Scalar::sum_of_products`]); the same value as
/// P0ₖ + t·Δₖ in exact arithmetic, but without the rounding of t being
/// magnified when P(t) lies much nearer the origin than P0. Should the
/// products overflow the float range, Pₖ + (bound − Pₐ)·(Δₖ/Δₐ) is used. The plane's
/// own coordinate is the bound itself, whatever the rounding.
fn intersection_point<T: Scalar>(
    p0: &V3<T>,
    p1: &V3<T>,
    delta: &V3<T>,
    axis: usize,
    bound: &T,
) -> V3<T> {
    // Measured from the end nearer the plane (the same point exactly, since
    // P(t) = P1 + (t − 1)·Δ): its difference to the plane is the smaller,
    // most accurately rounded one.
    let num0 = bound.clone() - p0[axis].clone();
    let num1 = bound.clone() - p1[axis].clone();
    let (base, num) = if num1.abs() < num0.abs() {
        (p1, num1)
    } else {
        (p0, num0)
    };
    let mut q = p0.clone();
    for k in 0..3 {
        q[k] = if k == axis {
            bound.clone()
        } else {
            let r =
                T::sum_of_products(&base[k], &delta[axis], &num, &delta[k]) / delta[axis].clone();
            if r.is_finite() {
                r
            } else {
                // The products overflow (floats only): the ratio first.
                base[k].clone() + num.clone() * (delta[k].clone() / delta[axis].clone())
            }
        };
    }
    q
}

/// The step explaining one endpoint's outcode, bit by bit.
fn code_step<T: Scalar>(name: &str, b: &ClipBox<T>, p: &V3<T>, code: u8) -> Step {
    let mut s = Step::new(Msg::OutcodeOf(name.to_string()), Msg::FOutcode)
        .val(Name::math(name), Val::vec3(p));
    for (bit, &(axis, is_max, _, side)) in PLANES.iter().enumerate() {
        let a = ["x", "y", "z"][axis];
        let (op, lim) = if is_max {
            (">", &b.max[axis])
        } else {
            ("<", &b.min[axis])
        };
        let set = code & (1 << bit) != 0;
        let test = format!("{a} {op} {a}{}", if is_max { "max" } else { "min" });
        let values = Box::new(Compared(p[axis].shown(), op, lim.shown()));
        s = s.val(
            Name::Bit(bit, side),
            Val::said(crate::msg::Said::BitTest(set, test, values)),
        );
    }
    s.res(Name::RegionCode, Val::text(code_str(code)))
}

/// Liang–Barsky: with Δ = P1 − P0, for each of the six pairs
/// p_k = −Δx, Δx, −Δy, Δy, −Δz, Δz and q_k = x0 − xmin, xmax − x0, ...:
/// p_k = 0 and q_k < 0 → outside; p_k < 0 → t0 = max(t0, q_k/p_k);
/// p_k > 0 → t1 = min(t1, q_k/p_k); the segment is P(t0)..P(t1) if t0 ≤ t1.
pub fn liang_barsky<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    tr: &mut impl Trace,
) -> Option<(V3<T>, V3<T>)> {
    let (hb, hp0, hp1, back) = halved_if_overflowing(b, p0, p1);
    let delta = vec::sub(&hp1, &hp0);
    let (b, p0h) = (&hb, &hp0);
    let (mut t0, mut t1) = (T::zero(), T::one());
    let mut inside = true;
    let mut pqs = Vec::with_capacity(6);
    for axis in 0..3 {
        for (p, q) in [
            (
                -delta[axis].clone(),
                p0h[axis].clone() - b.min[axis].clone(),
            ),
            (delta[axis].clone(), b.max[axis].clone() - p0h[axis].clone()),
        ] {
            pqs.push((p.clone(), q.clone()));
            if p.is_zero_value() {
                if q < T::zero() {
                    inside = false;
                }
            } else {
                let r = q / p.clone();
                if p < T::zero() {
                    if r > t0 {
                        t0 = r;
                    }
                } else if r < t1 {
                    t1 = r;
                }
            }
        }
    }
    let result = if inside && t0 <= t1 {
        let at = |t: &T| {
            let mut q = vec::add(p0h, &vec::scale(&delta, t));
            snap(b, &mut q);
            match &back {
                Some(two) => vec::scale(&q, two),
                None => q,
            }
        };
        Some((
            if t0.is_zero_value() {
                p0.clone()
            } else {
                at(&t0)
            },
            if t1 == T::one() { p1.clone() } else { at(&t1) },
        ))
    } else {
        None
    };
    tr.step(|| {
        let worked = LbWorked {
            b,
            p0: p0h,
            p1: &hp1,
            delta: &delta,
            pqs: &pqs,
        };
        lb_step(&worked, (&t0, &t1), &result)
    });
    result
}

/// What Liang–Barsky worked with, for its step: the box and the ends (as
/// the stage took them), Δ = P1 − P0 and each plane's (p, q) in the order
/// of [`PLANES`].
struct LbWorked<'a, T> {
    b: &'a ClipBox<T>,
    p0: &'a V3<T>,
    p1: &'a V3<T>,
    delta: &'a V3<T>,
    pqs: &'a [(T, T)],
}

/// The step of Liang–Barsky: Δ, each plane's p and q substituted (p = −Δx,
/// q = x0 − xmin at x = xmin; p = Δx, q = xmax − x0 at x = xmax; …), then
/// t0 = max(0, q/p where p < 0) and t1 = min(1, q/p where p > 0) with
/// their quotients, and the ends P0 + t·Δ.
fn lb_step<T: Scalar>(
    w: &LbWorked<'_, T>,
    (t0, t1): (&T, &T),
    result: &Option<(V3<T>, V3<T>)>,
) -> Step {
    let delta_name = Name::math("Δ = P1 − P0");
    let mut s = Step::new(Msg::LiangBarsky, Msg::FLiangBarsky)
        .val(delta_name.clone(), Val::vec3(w.delta))
        .sub(delta_name, Subst::difference(w.p1, w.p0));
    let (mut entering, mut leaving) = (Vec::new(), Vec::new());
    for (k, (p, q)) in w.pqs.iter().enumerate() {
        let (axis, is_max, plane, _) = PLANES[k];
        let name = Name::math(format!("p, q ({plane})"));
        let d = Val::num(&w.delta[axis]);
        let sub = if is_max {
            Subst::new(
                "({}{,}{} − {})",
                vec![d, Val::num(&w.b.max[axis]), Val::num(&w.p0[axis])],
            )
        } else {
            Subst::new(
                "(−{}{,}{} − {})",
                vec![d, Val::num(&w.p0[axis]), Val::num(&w.b.min[axis])],
            )
        };
        s = s.val(name.clone(), Val::vec2(p, q)).sub(name, sub);
        if *p < T::zero() {
            entering.extend([Val::num(q), Val::num(p)]);
        } else if *p > T::zero() {
            leaving.extend([Val::num(q), Val::num(p)]);
        }
    }
    let bound = |first: &str, args: Vec<Val>| {
        let form = format!("{first}(0{})", "{,}{}/{}".repeat(args.len() / 2));
        Subst::new(form, args)
    };
    let t1_form = bound("min", leaving);
    let t1_form = Subst::new(t1_form.form.replacen("(0", "(1", 1), t1_form.args);
    s = s
        .val(Name::math("t0"), Val::num(t0))
        .sub(Name::math("t0"), bound("max", entering))
        .val(Name::math("t1"), Val::num(t1))
        .sub(Name::math("t1"), t1_form);
    let at = |t: &T| {
        Subst::new(
            "{} + {}·{}",
            vec![Val::vec3(w.p0), Val::num(t), Val::vec3(w.delta)],
        )
    };
    match result {
        Some((a, z)) => s
            .res(Name::From, Val::vec3(a))
            .sub(Name::From, at(t0))
            .res(Name::To, Val::vec3(z))
            .sub(Name::To, at(t1)),
        None => s.res(Name::Segment, Val::Null),
    }
}

/// The box and the ends halved (exactly, barring subnormals) when P1 − P0
/// overflows the float range, with the factor 2 to scale points back; the
/// inputs themselves otherwise (always for exact numbers).
#[allow(clippy::type_complexity)]
fn halved_if_overflowing<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
) -> (ClipBox<T>, V3<T>, V3<T>, Option<T>) {
    let fits = |x: &V3<T>| vec::is_finite(x);
    let span = |lo: &V3<T>, hi: &V3<T>| fits(&vec::sub(hi, lo));
    if span(p0, p1) && span(p0, &b.min) && span(p0, &b.max) && span(p1, &b.min) && span(p1, &b.max)
    {
        return (b.clone(), p0.clone(), p1.clone(), None);
    }
    let half = T::one() / T::from_i64(2);
    let h = |x: &V3<T>| vec::scale(x, &half);
    (
        ClipBox {
            min: h(&b.min),
            max: h(&b.max),
        },
        h(p0),
        h(p1),
        Some(T::from_i64(2)),
    )
}

/// Moves coordinates that rounding put a hair outside the box back onto it.
fn snap<T: Scalar>(b: &ClipBox<T>, q: &mut V3<T>) {
    for k in 0..3 {
        if q[k] < b.min[k] {
            q[k] = b.min[k].clone();
        } else if q[k] > b.max[k] {
            q[k] = b.max[k].clone();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stages::trace::NoTrace;

    #[test]
    fn clip_space_outcode_is_the_box_outcode_of_minus_w_to_w() {
        // With w = 2 the volume is the box [−2, 2]³: the same bits as outcode().
        let b = ClipBox {
            min: V3::new(-2.0, -2.0, -2.0),
            max: V3::new(2.0, 2.0, 2.0),
        };
        for p in [
            [3.0, 0.0, 0.0],
            [-3.0, 2.5, 0.0],
            [0.0, -9.0, -2.5],
            [1.0, 1.0, 7.0],
            [2.0, -2.0, 2.0],
        ] {
            let h = nalgebra::Vector4::new(p[0], p[1], p[2], 2.0);
            assert_eq!(
                outcode_clip_space(&h),
                outcode(&b, &V3::new(p[0], p[1], p[2]))
            );
        }
        // A point behind the eye (w < 0) is outside on some plane.
        assert_ne!(
            outcode_clip_space(&nalgebra::Vector4::new(0.0, 0.0, 1.0, -1.0)),
            0
        );
    }

    fn bx() -> ClipBox<f64> {
        ClipBox {
            min: V3::new(0.0, 0.0, 0.0),
            max: V3::new(3.0, 4.0, 3.0),
        }
    }

    #[test]
    fn text_example_outcodes_and_clip() {
        // P0 (4,2,2): x > 3 → bit 2 → 000010. P1 (−2,6,1): x < 0 (bit 1), y > 4 (bit 4) → 001001.
        let (p0, p1) = (V3::new(4.0, 2.0, 2.0), V3::new(-2.0, 6.0, 1.0));
        let r = clip_segment(&bx(), &p0, &p1, &mut NoTrace);
        assert_eq!(code_str(r.code0), "000010");
        assert_eq!(code_str(r.code1), "001001");
        assert_eq!(r.status, Status::Clipped);
        // x = 3: t = (3−4)/(−6) = 1/6 → (3, 2 + 4/6, 2 − 1/6) = (3, 8/3, 11/6).
        // y = 4: t = (4−2)/4 = 1/2 → (4 − 3, 4, 2 − 1/2) = (1, 4, 3/2).
        let (a, c) = r.segment.unwrap();
        approx::assert_relative_eq!(a, V3::new(3.0, 8.0 / 3.0, 11.0 / 6.0), epsilon = 1e-15);
        approx::assert_relative_eq!(c, V3::new(1.0, 4.0, 1.5), epsilon = 1e-15);
        let lb = liang_barsky(&bx(), &p0, &p1, &mut NoTrace).unwrap();
        approx::assert_relative_eq!(lb.0, a, epsilon = 1e-15);
        approx::assert_relative_eq!(lb.1, c, epsilon = 1e-15);
    }

    #[test]
    fn text_and_rule() {
        // The text's P3 (010101) and P4 (100110): AND = 000100.
        assert_eq!(code_str(0b010101 & 0b100110), "000100");
    }

    #[test]
    fn trivial_cases_and_misses() {
        let inside = clip_segment(
            &bx(),
            &V3::new(1.0, 1.0, 1.0),
            &V3::new(2.0, 2.0, 2.0),
            &mut NoTrace,
        );
        assert_eq!(inside.status, Status::Accepted);
        let same_side = clip_segment(
            &bx(),
            &V3::new(-1.0, 1.0, 1.0),
            &V3::new(-2.0, 2.0, 2.0),
            &mut NoTrace,
        );
        assert_eq!(same_side.status, Status::Rejected);
        // Passes the corner (3,4) region diagonally outside: x + y = 8 never meets x ≤ 3, y ≤ 4.
        let miss = clip_segment(
            &bx(),
            &V3::new(2.0, 6.0, 1.0),
            &V3::new(6.0, 2.0, 1.0),
            &mut NoTrace,
        );
        assert_eq!(miss.status, Status::Rejected);
        // Touches the corner (3,4,1) exactly: x + y = 7.
        let touch = clip_segment(
            &bx(),
            &V3::new(2.0, 5.0, 1.0),
            &V3::new(5.0, 2.0, 1.0),
            &mut NoTrace,
        );
        assert_eq!(touch.status, Status::Clipped);
        let (a, b) = touch.segment.unwrap();
        assert_eq!(a, b);
        assert_eq!(a, V3::new(3.0, 4.0, 1.0));
    }

    #[test]
    fn inverted_box_is_an_error() {
        let b = ClipBox {
            min: V3::new(0.0, 5.0, 0.0),
            max: V3::new(1.0, 4.0, 1.0),
        };
        assert!(
            matches!(b.validate().unwrap_err().message, Msg::ErrBoxInverted(a, _, _) if a == "y")
        );
    }
}
