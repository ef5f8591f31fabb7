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
use crate::tutor::parts::fields::Fields;
use crate::tutor::parts::{names, Solver, Solves, Viewed};
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
    type Result = ViewResult;

    /// `basis`: the camera basis u, v, n; `view`: the basis, the view
    /// matrix and the eye coordinates.
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, asked: &Extent) -> Result<()> {
        match asked {
            Extent::Basis => {
                if let Some((cam, b)) = s.based()? {
                    s.put(basis_result(&b));
                    s.out.parts.push(Given::Basis(camera(&cam)));
                }
            }
            Extent::Whole => {
                let Some(v) = s.viewed()? else {
                    return Ok(());
                };
                s.put(view_result(&v.basis, &v.matrix, &v.eye));
                let world = (s.earlier.points.iter()).map(|(n, q)| (n.clone(), p3(q)));
                let given = Given::View(camera(&v.cam), world.collect());
                s.out.parts.push(given);
            }
        }
        Ok(())
    }

    /// n, u, v, the view matrix, the eye coordinates.
    fn keys(r: &ViewResult) -> Vec<Key> {
        let key = |v: Value| Key::new(Self::PART, v);
        let order = [Axis::N, Axis::U, Axis::V].map(Field::Axis);
        let mut keys: Vec<Key> = (order.iter().chain([&Field::Matrix]))
            .filter(|f| r.field(**f).is_some())
            .map(|f| key(Value::Field(*f)))
            .collect();
        keys.extend(names(r.field(Field::Points)).map(|n| key(Value::Point(n))));
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

/// The view's results: the basis u, v, n; with the whole view, the view
/// matrix V and the eye coordinates P' = V·P of the points.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewResult {
    /// u, to the right.
    pub u: Val,
    /// v, up in the picture.
    pub v: Val,
    /// n, from the look-at point back to the eye.
    pub n: Val,
    /// V (the whole view).
    pub matrix: Option<Val>,
    /// Each point's P', by name (the whole view).
    pub points: Option<Val>,
}

impl Fields for ViewResult {
    const ORDER: &'static [Field] = &[
        Field::Axis(Axis::U),
        Field::Axis(Axis::V),
        Field::Axis(Axis::N),
        Field::Matrix,
        Field::Points,
    ];

    fn field(&self, f: Field) -> Option<&Val> {
        match f {
            Field::Axis(Axis::U) => Some(&self.u),
            Field::Axis(Axis::V) => Some(&self.v),
            Field::Axis(Axis::N) => Some(&self.n),
            Field::Matrix => self.matrix.as_ref(),
            Field::Points => self.points.as_ref(),
            _ => None,
        }
    }

    fn field_mut(&mut self, f: Field) -> Option<&mut Val> {
        match f {
            Field::Axis(Axis::U) => Some(&mut self.u),
            Field::Axis(Axis::V) => Some(&mut self.v),
            Field::Axis(Axis::N) => Some(&mut self.n),
            Field::Matrix => self.matrix.as_mut(),
            Field::Points => self.points.as_mut(),
            _ => None,
        }
    }
}

/// The view's results: u, v, n, the matrix, the eye coordinates.
pub fn view_result<T: Scalar>(b: &Basis<T>, m: &Matrix4<T>, eye: &[Named<T>]) -> ViewResult {
    ViewResult {
        matrix: Some(Val::mat4(m)),
        points: Some(points_val(eye)),
        ..basis_result(b)
    }
}

/// The basis as the view's results.
pub fn basis_result<T: Scalar>(b: &Basis<T>) -> ViewResult {
    ViewResult {
        u: Val::vec3(&b.u),
        v: Val::vec3(&b.v),
        n: Val::vec3(&b.n),
        matrix: None,
        points: None,
    }
}
