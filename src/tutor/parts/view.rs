//! The view part (steps 1 and 2 of the text): the camera basis u, v, n,
//! the view matrix V and the eye coordinates P' of the points; a `basis`
//! command asks the basis alone.

use crate::error::{Error, Result};
use crate::input::eval3;
use crate::msg::{ErrMsg, Msg};
use crate::num::Scalar;
use crate::stages::camera::{self, Basis, Camera};
use crate::stages::trace::{Recorder, Step, Trace, Val};
use crate::tutor::follow;
use crate::tutor::key::{Axis, Field, Key, Part, Value};
use crate::tutor::parts::{fields, in_order, map_of, named, Solver, Solves, Viewed};
use crate::tutor::run::{in_table, points_val, Hooks, Named};
use crate::tutor::solution::{camera, p3, Given};
use crate::tutor::topic::Topic;
use nalgebra::Matrix4;

/// The view part.
pub struct ViewPart;

/// What a view part is asked: the basis alone (a `basis` command) or the
/// whole view.
pub enum Extent {
    /// The camera basis u, v, n.
    Basis,
    /// The basis, the view matrix and the eye coordinates.
    Whole,
}

impl Solves for ViewPart {
    const PART: Part = Part::View;
    type In = Extent;

    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, asked: &Extent) -> Result<()> {
        match asked {
            Extent::Basis => s.basis(),
            Extent::Whole => s.view(),
        }
    }

    /// n, u, v, the view matrix, the eye coordinates.
    fn keys(v: &Val) -> Vec<Key> {
        let kv = map_of(v);
        let fields = fields(Self::PART, kv);
        let key = |v: Value| Key::new(Self::PART, v);
        let axes = [Axis::N, Axis::U, Axis::V].map(Field::Axis);
        let order = [axes[0], axes[1], axes[2], Field::Matrix];
        let mut keys: Vec<Key> = in_order(&fields, &order)
            .map(|f| key(Value::Field(f)))
            .collect();
        keys.extend(named(kv, Field::Points).map(|n| key(Value::Point(n))));
        keys
    }

    /// The eye coordinates practise the view; the basis and the matrix,
    /// the basis.
    fn topic(value: &Value) -> Topic {
        match value {
            Value::Point(_) | Value::Field(Field::Points) => Topic::View,
            _ => Topic::Basis,
        }
    }
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// `basis`: the camera basis u, v, n.
    fn basis(&mut self) -> Result<()> {
        if let Some((cam, b)) = self.based()? {
            self.put(Part::View, Val::Map(basis_result(&b)));
            self.out.parts.push(Given::Basis(camera(&cam)));
        }
        Ok(())
    }

    /// `view`: the basis, the view matrix and the eye coordinates.
    fn view(&mut self) -> Result<()> {
        let Some(v) = self.viewed()? else {
            return Ok(());
        };
        self.put(
            Part::View,
            Val::Map(view_result(&v.basis, &v.matrix, &v.eye)),
        );
        let world = (self.earlier.points.iter()).map(|(n, q)| (n.clone(), p3(q)));
        let given = Given::View(camera(&v.cam), world.collect());
        self.out.parts.push(given);
        Ok(())
    }

    /// Step 1 and the start of step 2, worked once: the camera and its
    /// basis (a problem file's modeling section says the points are in
    /// world coordinates already); `None` without a camera (refused when
    /// points need one and the parts are asked by name).
    pub(crate) fn based(&mut self) -> Result<Option<(Camera<T>, Basis<T>)>> {
        if let Some(b) = &self.earlier.based {
            return Ok(b.clone());
        }
        let c = match &self.p.shared.camera {
            Some(c) => c,
            None if !self.earlier.points.is_empty() && self.p.by_name() => {
                return Err(Error::why("camera", ErrMsg::NoCameraTable))
            }
            None => {
                self.earlier.based = Some(None);
                return Ok(None);
            }
        };
        let cam = Camera {
            pe: eval3(&c.field("eye"), &c.table.eye)?,
            pr: eval3(&c.field("look"), &c.table.look)?,
            vup: eval3(&c.field("up"), &c.table.up)?,
        };
        let out = &mut self.out;
        out.section(Msg::SecModeling);
        if out.sections {
            (out.rec).step(|| Step::new(Msg::NothingToDo, "").note(Msg::AlreadyWorld));
        }
        out.section(Msg::SecViewing);
        let basis = basis_run(&cam, self.hooks, &mut out.rec).map_err(|e| in_table(c.prefix, e))?;
        self.earlier.based = Some(Some((cam.clone(), basis.clone())));
        Ok(Some((cam, basis)))
    }

    /// Step 2, worked once: the basis, the view matrix and the eye
    /// coordinates of the points; `None` without a camera.
    pub(crate) fn viewed(&mut self) -> Result<Option<Viewed<T>>> {
        if let Some(v) = &self.earlier.viewed {
            return Ok(v.clone());
        }
        let Some((cam, basis)) = self.based()? else {
            self.earlier.viewed = Some(None);
            return Ok(None);
        };
        let prefix = self.p.shared.camera.as_ref().map_or("", |c| c.prefix);
        let (hooks, points, rec) = (self.hooks, &self.earlier.points, &mut self.out.rec);
        let (matrix, eye) = eye_run(&basis, &cam, points, (hooks, prefix), rec)?;
        let v = Viewed {
            cam,
            basis,
            matrix,
            eye,
        };
        self.earlier.viewed = Some(Some(v.clone()));
        Ok(Some(v))
    }
}

/// The camera basis u, v, n (altered by `hooks`).
pub fn basis_run<T: Scalar>(
    cam: &Camera<T>,
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<Basis<T>> {
    let mut b = camera::basis(cam, rec)?;
    (hooks.basis)(&mut b);
    if let Some(g) = hooks.givens() {
        follow::basis(g, cam, &mut b);
    }
    Ok(b)
}

/// The view matrix (its errors' fields under `prefix`: `camera.eye`) and
/// the eye coordinates of `points` (each `view.points.A` given by `hooks`
/// in place of its own).
pub fn eye_run<T: Scalar>(
    b: &Basis<T>,
    cam: &Camera<T>,
    points: &[Named<T>],
    (hooks, prefix): (&Hooks<T>, &str),
    rec: &mut Recorder,
) -> Result<(Matrix4<T>, Vec<Named<T>>)> {
    let mut m = camera::view_matrix(b, &cam.pe, rec).map_err(|e| in_table(prefix, e))?;
    let mut by_matrix = false;
    if let Some((written, used)) = hooks.view {
        m = written(b, &cam.pe);
        by_matrix = used;
    }
    let mut eye = Vec::new();
    for (n, q) in points {
        let e = if by_matrix {
            camera::apply(&m, q).xyz()
        } else {
            camera::to_eye(b, &cam.pe, n, q, rec)?
        };
        let given = hooks
            .givens()
            .and_then(|g| g.vec3(&Key::new(Part::View, Value::Point(n.clone()))));
        eye.push((n.clone(), given.unwrap_or(e)));
    }
    Ok((m, eye))
}

/// The view's result keys: u, v, n, the matrix, the eye coordinates.
pub fn view_result<T: Scalar>(
    b: &Basis<T>,
    m: &Matrix4<T>,
    eye: &[Named<T>],
) -> Vec<(String, Val)> {
    let mut r = basis_result(b);
    r.push((Field::Matrix.key(), Val::mat4(m)));
    r.push((Field::Points.key(), points_val(eye)));
    r
}

/// The basis as named results.
pub fn basis_result<T: Scalar>(b: &camera::Basis<T>) -> Vec<(String, Val)> {
    let axis = |a| Field::Axis(a).key();
    vec![
        (axis(Axis::U), Val::vec3(&b.u)),
        (axis(Axis::V), Val::vec3(&b.v)),
        (axis(Axis::N), Val::vec3(&b.n)),
    ]
}
