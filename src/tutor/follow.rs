//! Follow-through (error carried forward): the values a student's own
//! earlier answers lead to, computed by the stages themselves.
//!
//! `solve` runs the text's steps; where a result is given here (the
//! student's own value of an earlier key, [`Givens`]), the steps after it
//! go on from the given value instead of the stage's. No formula is
//! written again here: each function below puts a given value where the
//! stage would have put its own, and calls the stage for the rest:
//!
//! - n given: u from [`camera::basis`] of a camera looking along the
//!   student's n (u = (Vup × n)/|Vup × n|), v = [`camera::v_axis`]
//!   (v = n × u) from the n and u in use; the view matrix and the eye
//!   coordinates from these axes ([`camera::view_matrix`],
//!   [`camera::to_eye`], exact);
//! - eye coordinates given: the projection of them; projected points and
//!   window edges given: the pixels from them ([`window::to_viewport`]);
//! - the window's top given: its other edges ([`window::edges`]);
//! - outcodes given: the status by the trivial tests ([`clip::trivial`]);
//!   an intersection point given (on its plane: a point off it is no
//!   intersection) or its code: the clipped segment ([`clip::kept_part`]);
//! - L or N given: the lighting stage with them; cos α, R, cos β, the terms
//!   and their sum given: the stage goes on from them
//!   ([`crate::stages::lighting::RuleSet`]'s `given_*`).
//!
//! The problem's own inputs (Pe, Pr, Vup, the points, d, the viewport, the
//! segment's ends, the lighting constants) are never the student's.

use crate::input::lights::Setup;
use crate::num::vec::{self, V3};
use crate::num::Scalar;
use crate::stages::camera::{self, Basis, Camera};
use crate::stages::clip::{self, ClipBox, Clipped, Status, PLANES};
use crate::stages::lighting::{LightKind, Part, Rgb, RuleSet, Rules};
use crate::stages::trace::NoTrace;
use crate::stages::window::{self, Window};
use crate::tutor::key::{self, Axis, Cut, Edge, Field, Key, Plane, Shading, Value};

/// A value given in place of one a stage computes: its numbers (a point's
/// coordinates, a matrix by rows) or its word (an outcode).
#[derive(Clone, Debug, PartialEq)]
pub enum Given<T> {
    /// The numbers, depth first.
    Nums(Vec<T>),
    /// An outcode.
    Word(String),
}

/// The values given, by result key (`view.n`, `clip.code0`,
/// `shade.cos_alpha`); None for a key the stages compute.
pub type Lookup<'a, T> = dyn Fn(&Key) -> Option<Given<T>> + 'a;

/// Typed access to the values given.
pub struct Givens<'a, T>(pub &'a Lookup<'a, T>);

// a reference, copied whatever T is
impl<T> Clone for Givens<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for Givens<'_, T> {}

impl<T: Scalar> Givens<'_, T> {
    fn nums(&self, key: &Key) -> Option<Vec<T>> {
        match (self.0)(key)? {
            Given::Nums(v) => Some(v),
            Given::Word(_) => None,
        }
    }
    /// A given number.
    pub fn num(&self, key: &Key) -> Option<T> {
        match &self.nums(key)?[..] {
            [x] => Some(x.clone()),
            _ => None,
        }
    }
    /// A given vector.
    pub fn vec3(&self, key: &Key) -> Option<V3<T>> {
        match &self.nums(key)?[..] {
            [x, y, z] => Some(vec::v3(x.clone(), y.clone(), z.clone())),
            _ => None,
        }
    }
    fn rgb(&self, key: &Key) -> Option<Rgb<T>> {
        let v = self.vec3(key)?;
        Some([v[0].clone(), v[1].clone(), v[2].clone()])
    }
    /// A given outcode.
    fn code(&self, key: &Key) -> Option<u8> {
        match (self.0)(key)? {
            Given::Word(w) => u8::from_str_radix(&w, 2).ok(),
            Given::Nums(_) => None,
        }
    }
}

/// The basis with the student's axes where they are given: a given n
/// takes u from the basis of a camera looking along it; v = n × u from the
/// n and u in use (the student's where given), unless v is given too.
pub fn basis<T: Scalar>(g: Givens<T>, cam: &Camera<T>, b: &mut Basis<T>) {
    let axis = |a| g.vec3(&Key::new(key::Part::View, Value::Field(Field::Axis(a))));
    let [n, u, v] = [Axis::N, Axis::U, Axis::V].map(axis);
    if n.is_none() && u.is_none() && v.is_none() {
        return;
    }
    if let Some(n) = n {
        let along = Camera {
            pe: vec::add(&cam.pr, &n),
            pr: cam.pr.clone(),
            vup: cam.vup.clone(),
        };
        if let Ok(b2) = camera::basis(&along, &mut NoTrace) {
            *b = b2;
        }
        b.n = n;
    }
    if let Some(u) = u {
        b.u = u;
    }
    b.v = v.unwrap_or_else(|| camera::v_axis(&b.n, &b.u));
    b.given = true;
}

/// The window with the student's edges where they are given: a given top
/// makes the others by [`window::edges`], and each edge given stands.
pub fn window<T: Scalar>(g: Givens<T>, aspect: &T, w: &mut Window<T>) {
    let edge = |e| {
        g.num(&Key::new(
            key::Part::Window,
            Value::Field(Field::Edge(e, false)),
        ))
    };
    if let Some(top) = edge(Edge::Top) {
        *w = window::edges(top, aspect);
    }
    let Window {
        bottom,
        left,
        right,
        height,
        width,
        ..
    } = w;
    for (e, slot) in [
        (Edge::Bottom, bottom),
        (Edge::Left, left),
        (Edge::Right, right),
        (Edge::Height, height),
        (Edge::Width, width),
    ] {
        if let Some(x) = edge(e) {
            *slot = x;
        }
    }
}

/// One segment's clipping with the student's outcodes, intersection points
/// and their codes where given (in `segment` of a clip with several): the status
/// by the trivial tests of the codes in use (clipped when neither holds),
/// each given point that lies on its plane with its own outcode, and the
/// segment kept between them.
pub fn clipping<T: Scalar>(
    g: Givens<T>,
    segment: Option<usize>,
    b: &ClipBox<T>,
    ends: (&V3<T>, &V3<T>),
    r: &mut Clipped<T>,
) {
    let at = |v| Key::new(key::Part::Clip, v).of_segment(segment);
    let codes = (
        g.code(&at(Value::Field(Field::Code0))),
        g.code(&at(Value::Field(Field::Code1))),
    );
    if codes.0.is_some() || codes.1.is_some() {
        let (c0, c1) = (codes.0.unwrap_or(r.code0), codes.1.unwrap_or(r.code1));
        r.status = clip::trivial(c0, c1).unwrap_or(match clip::trivial(r.code0, r.code1) {
            None => r.status,
            Some(_) => Status::Clipped,
        });
    }
    let mut moved = false;
    for i in &mut r.intersections {
        let plane = Plane::ALL[i.bit];
        let (axis, is_max, _, _) = PLANES[i.bit];
        let bound = if is_max { &b.max[axis] } else { &b.min[axis] };
        if let Some(q) = g
            .vec3(&at(Value::Cut(plane, Cut::Point)))
            .filter(|q| q[axis] == *bound)
        {
            i.code = clip::outcode(b, &q);
            i.point = q;
            moved = true;
        }
        if let Some(c) = g.code(&at(Value::Cut(plane, Cut::Code))) {
            i.code = c;
            moved = true;
        }
    }
    if moved {
        r.segment = clip::kept_part(&r.intersections, (ends.0, r.code0), (ends.1, r.code1));
    }
}

/// The lighting set-up with the student's unit vectors where given: N as
/// the surface's normal, L as the direction of the one directional light.
pub fn setup<T: Scalar>(g: Givens<T>, s: &mut Setup<T>) {
    let shade = |x| Key::new(key::Part::Shade, Value::Field(Field::Shading(x)));
    if let Some(n) = g.vec3(&shade(Shading::N)) {
        s.surface.normal = n;
    }
    if let (Some(l), [light]) = (g.vec3(&shade(Shading::L)), &mut s.lights[..]) {
        if let LightKind::Directional { dir } = &mut light.kind {
            *dir = l;
        }
    }
}

/// The lighting stage's rules, going on from the student's values of its
/// [`Part`]s where they are given (one light).
pub struct GivenRules<'a, T> {
    /// The rules the stage runs with.
    pub rules: &'a Rules<T>,
    /// The values given.
    pub given: Givens<'a, T>,
}

impl<T: Scalar> RuleSet<T> for GivenRules<'_, T> {
    fn reflect(&self, n: &V3<T>, l: &V3<T>, two_ln: &T) -> V3<T> {
        self.rules.reflect(n, l, two_ln)
    }
    fn highlight_base(&self, cos: &T) -> T {
        self.rules.highlight_base(cos)
    }
    fn given_num(&self, part: Part, computed: T) -> T {
        self.given.num(&shade_key(part)).unwrap_or(computed)
    }
    fn given_vec(&self, part: Part, computed: V3<T>) -> V3<T> {
        self.given.vec3(&shade_key(part)).unwrap_or(computed)
    }
    fn given_rgb(&self, part: Part, computed: Rgb<T>) -> Rgb<T> {
        self.given.rgb(&shade_key(part)).unwrap_or(computed)
    }
}

/// The key of a value of the lighting stage: `shade.cos_alpha`, …
fn shade_key(part: Part) -> Key {
    let value = match part {
        Part::CosAlpha => Shading::CosAlpha,
        Part::R => Shading::R,
        Part::CosBeta => Shading::CosBeta,
        Part::Ambient => Shading::Ambient,
        Part::Diffuse => Shading::Diffuse,
        Part::Specular => Shading::Specular,
        Part::Unclamped => Shading::Unclamped,
    };
    Key::new(key::Part::Shade, Value::Field(Field::Shading(value)))
}
