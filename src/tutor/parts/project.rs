//! The project part (step 3 of the text): the points projected, by a
//! projection given (COP at the origin onto z = d, a general one, or
//! orthographic) or, chained, the view's eye coordinates onto the near
//! plane z = d (d = −near unless given): P'' = (x·d/z, y·d/z, d).

use crate::error::{Error, Result};
use crate::input::eval;
use crate::input::part::{ProjectIn, ProjectionIn, Table};
use crate::input::problem::PerspectiveIn;
use crate::msg::{ErrMsg, Msg};
use crate::num::Scalar;
use crate::stages::projection::{self, Projection};
use crate::stages::trace::{Name, Recorder, Step, Subst, Trace, Val};
use crate::tutor::key::{Field, Key, Part, Value};
use crate::tutor::parts::fields::Fields;
use crate::tutor::parts::{names, Out, Projected, Solver, Solves};
use crate::tutor::run::{points_val, Hooks, Named};
use crate::tutor::solution::Given;
use crate::tutor::topic::Topic;

/// The project part.
pub struct ProjectPart;

impl Solves for ProjectPart {
    const PART: Part = Part::Project;
    type In = ProjectIn;
    type Result = ProjectResult;

    /// `project`: the points projected, by a projection given or onto
    /// the near plane (the view's eye coordinates).
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, how: &ProjectIn) -> Result<()> {
        let (proj, points, projected) = match how {
            ProjectIn::Given(given) => {
                let proj = projection::<T>(given)?;
                let pts = &s.earlier.points;
                let images = project_run(&proj, pts, s.hooks, &mut s.out.rec)?;
                (proj, pts.clone(), images)
            }
            ProjectIn::Chained => {
                let (Some((proj, projected)), Some(v)) = (s.projected()?, s.viewed()?) else {
                    return Ok(());
                };
                (proj, v.eye, projected)
            }
        };
        let images = points_val(&projected);
        s.put(ProjectResult { points: images });
        s.out.parts.push(Given::Project {
            projection: Given::projection(&proj),
            points: (points.iter())
                .map(|(n, e)| (n.clone(), Val::vec3(e)))
                .collect(),
            chained: matches!(how, ProjectIn::Chained),
        });
        Ok(())
    }

    /// The projected points.
    fn keys(r: &ProjectResult) -> Vec<Key> {
        let key = |v: Value| Key::new(Self::PART, v);
        names(r.field(Field::Points))
            .map(|n| key(Value::Point(n)))
            .collect()
    }

    fn topic(_: &Value) -> Topic {
        Topic::Project
    }
}

/// The project part's results: each point's projection P'', by name.
#[derive(Clone, Debug, PartialEq)]
pub struct ProjectResult {
    /// The projected points.
    pub points: Val,
}

impl Fields for ProjectResult {
    const ORDER: &'static [Field] = &[Field::Points];

    fn field(&self, f: Field) -> Option<&Val> {
        (f == Field::Points).then_some(&self.points)
    }

    fn field_mut(&mut self, f: Field) -> Option<&mut Val> {
        (f == Field::Points).then_some(&mut self.points)
    }
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// Step 3, worked once: projection of the eye points onto the near
    /// plane (d = −near unless given); `None` without eye points.
    pub(crate) fn projected(&mut self) -> Result<Option<Projected<T>>> {
        if let Some(done) = &self.earlier.projected {
            return Ok(done.clone());
        }
        let eye = self.viewed()?.map(|v| v.eye).unwrap_or_default();
        let near = self.near()?;
        let per = self.p.shared.perspective.as_ref();
        let done = match eye.is_empty() {
            true => None,
            false => Some(project_steps(
                per,
                self.hooks,
                &eye,
                near.as_ref(),
                &mut self.out,
            )?),
        };
        self.earlier.projected = Some(done.clone());
        Ok(done)
    }
}

/// A projection given, its numbers evaluated (each error naming its flag)
/// and checked.
fn projection<T: Scalar>(given: &ProjectionIn) -> Result<Projection<T>> {
    let proj = match given {
        ProjectionIn::Plane((f, d)) => Projection::Plane { d: eval(f, d)? },
        ProjectionIn::General((fc, c), (fp, p)) => Projection::General {
            zprp: eval(fc, c)?,
            zvp: eval(fp, p)?,
        },
        ProjectionIn::Ortho => Projection::Ortho,
    };
    proj.validate()?;
    Ok(proj)
}

/// Step 3's steps: d (−near unless given), the projection, the images of
/// the eye points.
fn project_steps<T: Scalar>(
    per: Option<&Table<PerspectiveIn>>,
    hooks: &Hooks<T>,
    eye_pts: &[Named<T>],
    near: Option<&T>,
    out: &mut Out,
) -> Result<Projected<T>> {
    let prefix = per.map_or("perspective.", |x| x.prefix);
    let given = per.and_then(|x| x.table.d.as_ref());
    let d_field = format!("{prefix}d");
    let d: T = match (given, near) {
        (Some(d), _) => eval(&d_field, d)?,
        (None, Some(n)) => -n.clone(),
        (None, None) => {
            let field = format!("{prefix}near");
            return Err(Error::why(field, ErrMsg::ProjectionNeedsNear));
        }
    };
    out.section(Msg::SecProjection);
    out.rec.step(|| match (given, near) {
        (None, Some(n)) => Step::new(Msg::ProjPlane, Msg::FProjPlane)
            .val(Name::math("near"), Val::num(n))
            .res(Name::math("d"), Val::num(&d))
            .sub(Name::math("d"), Subst::new("−{}", vec![Val::num(n)])),
        _ => Step::new(Msg::ProjPlane, "z = d").val(Name::math("d"), Val::num(&d)),
    });
    let proj = Projection::Plane { d };
    proj.validate().map_err(|e| e.in_field(d_field))?;
    let projected = project_run(&proj, eye_pts, hooks, &mut out.rec)?;
    Ok((proj, projected))
}

/// The images of `points` under `proj` (each `project.points.A` given by
/// `hooks` in place of its own).
pub fn project_run<T: Scalar>(
    proj: &Projection<T>,
    points: &[Named<T>],
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<Vec<Named<T>>> {
    let mut out = Vec::new();
    for (n, e) in points {
        let q = projection::project(proj, n, e, rec)?;
        let given = hooks
            .givens()
            .and_then(|g| g.vec3(&Key::new(Part::Project, Value::Point(n.clone()))));
        out.push((n.clone(), given.unwrap_or(q)));
    }
    Ok(out)
}
