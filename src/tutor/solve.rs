//! The one solver: a typed problem ([`Problem`]: a calculator command's
//! one part, or a problem file's parts) solved part by part through the
//! text's steps — modeling, viewing transformation, projection onto the
//! near plane, window and clipping, viewport — by one exhaustive match
//! over the typed part, each part run by the functions of
//! [`crate::tutor::run`]. What a part takes from earlier parts is worked
//! once, when first needed (`Earlier`); a problem file's results are
//! nested under each part's key, with its section headers and a
//! comparison with the answers the source printed; a command's are not.

use crate::error::{Error, Result};
use crate::input::fields::Num;
use crate::input::part::{ClipIn, PartIn, Problem, ProjectIn, ProjectionIn, ShadePartIn, Table};
use crate::input::problem::{PerspectiveIn, PointRef, ProblemIn};
use crate::input::{eval, eval3};
use crate::msg::{ErrMsg, Msg};
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera::{Basis, Camera};
use crate::stages::clip::ClipBox;
use crate::stages::projection::Projection;
use crate::stages::trace::{Name, Recorder, Step, Subst, Trace, Val};
use crate::stages::window;
use crate::tutor::check::{printed_agrees, settings_for, written};
use crate::tutor::key::{Field, Key, Part};
use crate::tutor::keys::basis_result;
use crate::tutor::run::{
    basis_run, clip_run, eye_run, in_table, light_run, pixels, points_val, project_run,
    view_result, window_run, Hooks, Named,
};
use crate::tutor::solution::{
    at, camera, p3, value_of, Asked, Compared, Comparison, Given, Report, ShadeAt, Tree, WindowAt,
};
use nalgebra::Matrix4;

/// Solves a typed problem at precision `T`: a calculator command's one
/// part or a problem file's parts.
pub fn solve_problem<T: Scalar>(p: &Problem) -> Result<Report> {
    solve_typed::<T>(p, &Hooks::default())
}

/// Solves a parsed problem file at precision `T`.
pub fn solve<T: Scalar>(p: &ProblemIn) -> Result<Report> {
    solve_with::<T>(p, &Hooks::default())
}

/// Solves a parsed problem file at precision `T`, with stage results
/// altered by `hooks` (the mistake catalog, follow-through).
pub fn solve_with<T: Scalar>(p: &ProblemIn, hooks: &Hooks<T>) -> Result<Report> {
    solve_typed::<T>(&Problem::of_file(p.clone())?, hooks)
}

/// Solves a typed problem at precision `T`, with stage results altered by
/// `hooks`: each part asked, in [`Part::all`]'s order, by one exhaustive
/// match over the typed part (`Solver::part`: a new part stops the
/// build there). The view is worked before the projection reads near,
/// which is read whatever is asked (a near that does not evaluate is
/// refused).
pub fn solve_typed<T: Scalar>(p: &Problem, hooks: &Hooks<T>) -> Result<Report> {
    let points: Vec<Named<T>> = (p.shared.points.iter())
        .map(|(n, field, v)| Ok((n.clone(), eval3(field, v)?)))
        .collect::<Result<_>>()?;
    let mut s = Solver {
        p,
        hooks,
        out: Out {
            sections: p.file.is_some(),
            rec: Recorder::quiet(hooks.quiet),
            ..Out::default()
        },
        earlier: Earlier {
            points,
            based: None,
            viewed: None,
            near: None,
            projected: None,
            window: None,
        },
    };
    for part in Part::all() {
        if part == Part::Project {
            if s.projects() {
                s.viewed()?;
            }
            s.near()?;
        }
        for typed in p.parts.iter().filter(|t| t.part() == part) {
            s.part(typed)?;
        }
    }
    let Out {
        rec, result, parts, ..
    } = s.out;
    match &p.file {
        None => Ok(Report::from_recorder::<T>(
            Asked::Command,
            parts,
            result,
            rec,
        )),
        Some(file) => file_report::<T>(file, (rec, result, parts)),
    }
}

/// A problem file's report: lights without a `[shade]` table are refused
/// whatever is asked, and so is a file that asks nothing it can solve;
/// the printed answers compared with the results.
fn file_report<T: Scalar>(
    p: &ProblemIn,
    (rec, result, parts): (Recorder, Tree, Vec<Given>),
) -> Result<Report> {
    if !p.light.is_empty() && p.shade.is_none() {
        return Err(Error::why("shade", ErrMsg::LightsNeedShade));
    }
    if result.is_empty() {
        return Err(Error::why("ask", ErrMsg::NothingToSolve));
    }
    let comparison = compare_printed(p, &result);
    let asked = Asked::File(Box::new(p.clone()));
    let mut report = Report::from_recorder::<T>(asked, parts, result, rec);
    report.comparison = comparison;
    report.source_notes = p.source_notes.clone();
    Ok(report)
}

/// Where the parts write: the steps, the named results, what each part
/// was given; whether section headers are written (a problem file's).
#[derive(Default)]
struct Out {
    rec: Recorder,
    result: Tree,
    parts: Vec<Given>,
    sections: bool,
}

impl Out {
    /// A section header, for a problem file.
    fn section(&mut self, m: Msg) {
        if self.sections {
            self.rec.section(m);
        }
    }
}

/// What the stages produced for the parts after them, each worked (its
/// steps written) once, when a part first needs it; `None`: not yet.
struct Earlier<T> {
    /// The shared points, in order (read for every problem).
    points: Vec<Named<T>>,
    /// The camera and its basis (inside, `None`: no camera).
    based: Option<Option<(Camera<T>, Basis<T>)>>,
    /// The camera's view (inside, `None`: no camera to view with).
    viewed: Option<Option<Viewed<T>>>,
    /// near, when given.
    near: Option<Option<T>>,
    /// The projection and the projected points (inside, `None`: no eye
    /// points to project).
    projected: Option<Option<Projected<T>>>,
    /// The window (inside, `None`: the perspective does not set one up).
    window: Option<Option<Windowed<T>>>,
}

/// Steps 1 and 2 done: the camera, its basis, the view matrix, the eye
/// coordinates of the points.
#[derive(Clone)]
struct Viewed<T> {
    cam: Camera<T>,
    basis: Basis<T>,
    matrix: Matrix4<T>,
    eye: Vec<Named<T>>,
}

/// Step 3 done: the projection and the projected points.
type Projected<T> = (Projection<T>, Vec<Named<T>>);

/// Step 4 done: the window, its result keys, what it was given, and the
/// points given on it (a `window` command's), evaluated.
#[derive(Clone)]
struct Windowed<T> {
    w: window::Window<T>,
    result: Tree,
    given: WindowAt,
    on_window: Option<Vec<(String, (T, T))>>,
}

/// A problem being solved: the problem, the hooks, what is written and
/// what earlier stages produced.
struct Solver<'a, 'h, T> {
    p: &'a Problem,
    hooks: &'a Hooks<'h, T>,
    out: Out,
    earlier: Earlier<T>,
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// One part, by the one exhaustive match over the typed part.
    fn part(&mut self, part: &PartIn) -> Result<()> {
        match part {
            PartIn::Basis => self.basis(),
            PartIn::View => self.view(),
            PartIn::Project(how) => self.project(how),
            PartIn::Window => self.window(),
            PartIn::Viewport => self.viewport(),
            PartIn::Clip(c) => self.clip(c),
            PartIn::Shade(s) => self.shade(s),
        }
    }

    /// A part's results: a problem file's under the part's key, a
    /// command's (one part's map) unnested (docs/spec.md §3).
    fn put(&mut self, part: Part, v: Val) {
        match (&self.p.file, v) {
            (None, Val::Map(kv)) => self.out.result.extend(kv),
            (_, v) => self.out.result.push((part.key(), v)),
        }
    }

    /// Whether a part asked takes the projected points (a problem file's
    /// project or viewport).
    fn projects(&self) -> bool {
        let shared = &self.p.shared;
        self.p.parts.iter().any(|t| t.takes_projected(shared))
    }

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

    /// `project`: the points projected, by a projection given or onto
    /// the near plane (the view's eye coordinates).
    fn project(&mut self, how: &ProjectIn) -> Result<()> {
        let (proj, points, projected) = match how {
            ProjectIn::Given(given) => {
                let proj = projection::<T>(given)?;
                let pts = &self.earlier.points;
                let images = project_run(&proj, pts, self.hooks, &mut self.out.rec)?;
                (proj, pts.clone(), images)
            }
            ProjectIn::Chained => {
                let (Some((proj, projected)), Some(v)) = (self.projected()?, self.viewed()?) else {
                    return Ok(());
                };
                (proj, v.eye, projected)
            }
        };
        let r = vec![(Field::Points.key(), points_val(&projected))];
        self.put(Part::Project, Val::Map(r));
        self.out.parts.push(Given::Project {
            projection: Given::projection(&proj),
            points: (points.iter())
                .map(|(n, e)| (n.clone(), Val::vec3(e)))
                .collect(),
            chained: matches!(how, ProjectIn::Chained),
        });
        Ok(())
    }

    /// `window`: the window's edges (and the far one's).
    fn window(&mut self) -> Result<()> {
        if let Some(w) = self.windowed()? {
            self.put(Part::Window, Val::Map(w.result));
            self.out.parts.push(Given::Window(w.given));
        }
        Ok(())
    }

    /// `viewport`: the pixels of the points on the window (given, or the
    /// projected points); a command given no points writes no pixels.
    fn viewport(&mut self) -> Result<()> {
        let per = self.p.shared.perspective.as_ref();
        let vp = per.and_then(|x| x.table.viewport.as_ref().map(|v| (x, v)));
        let (Some(w), Some((per, vp))) = (self.windowed()?, vp) else {
            return Ok(());
        };
        let shown = match w.on_window {
            Some(given) => given,
            None => self.projected_xy()?,
        };
        let field = per.field("viewport");
        let (vw, vh): (T, T) = (eval(&field, &vp[0])?, eval(&field, &vp[1])?);
        window::validate_viewport(&vw, &vh).map_err(|e| e.in_field(field))?;
        self.out.section(Msg::SecViewport);
        let Out { rec, parts, .. } = &mut self.out;
        let windows = parts.iter_mut().filter_map(|g| match g {
            Given::Window(w) => Some(w),
            _ => None,
        });
        for given in windows {
            given.viewport = Some((at(&vw), at(&vh)));
        }
        let on_window = shown.iter().map(|(n, (x, y))| (n, (x, y)));
        let px = pixels(&w.w, (&vw, &vh), on_window, rec);
        if !(px.is_empty() && self.p.shared.on_window.is_some()) {
            let r = vec![(Field::Pixels.key(), Val::Map(px))];
            self.put(Part::Viewport, Val::Map(r));
        }
        Ok(())
    }

    /// The projected points as points (x, y) on the window.
    fn projected_xy(&mut self) -> Result<Vec<(String, (T, T))>> {
        let projected = self.projected()?.map(|(_, q)| q).unwrap_or_default();
        let xy = |(n, q): Named<T>| (n, (q[0].clone(), q[1].clone()));
        Ok(projected.into_iter().map(xy).collect())
    }

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

    /// `shade`: the lighting at the set-up's point.
    fn shade(&mut self, s: &ShadePartIn) -> Result<()> {
        self.out.section(Msg::SecLighting);
        let set_up = (&s.shade.table, &s.lights, s.shade.prefix);
        let (setup, r) = light_run(set_up, self.hooks, &mut self.out.rec)?;
        self.put(Part::Shade, Val::Map(r));
        (self.out.parts).push(Given::Shade(ShadeAt::of(&setup, s.file.clone())));
        Ok(())
    }

    /// near, when given (read once).
    fn near(&mut self) -> Result<Option<T>> {
        if let Some(near) = &self.earlier.near {
            return Ok(near.clone());
        }
        let near = (self.p.shared.perspective.as_ref())
            .and_then(|x| x.table.near.as_ref().map(|n| eval(&x.field("near"), n)))
            .transpose()?;
        self.earlier.near = Some(near.clone());
        Ok(near)
    }

    /// Step 1 and the start of step 2, worked once: the camera and its
    /// basis (a problem file's modeling section says the points are in
    /// world coordinates already); `None` without a camera (refused when
    /// points need one and the parts are asked by name).
    fn based(&mut self) -> Result<Option<(Camera<T>, Basis<T>)>> {
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
    fn viewed(&mut self) -> Result<Option<Viewed<T>>> {
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

    /// Step 3, worked once: projection of the eye points onto the near
    /// plane (d = −near unless given); `None` without eye points.
    fn projected(&mut self) -> Result<Option<Projected<T>>> {
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

    /// Step 4, worked once: the window on the near plane (and the far one)
    /// and which projected points it contains (when a part asked projects
    /// them); `None` when the perspective sets up no window (refused when
    /// the parts are asked by name).
    fn windowed(&mut self) -> Result<Option<Windowed<T>>> {
        if let Some(done) = &self.earlier.window {
            return Ok(done.clone());
        }
        let (eye, shown) = match self.projects() {
            true => (
                self.viewed()?.map(|v| v.eye).unwrap_or_default(),
                self.projected()?.map(|(_, q)| q).unwrap_or_default(),
            ),
            false => (vec![], vec![]),
        };
        let near = self.near()?;
        let done = match &self.p.shared.perspective {
            Some(per) => {
                let eyes = (eye.as_slice(), shown.as_slice());
                window_steps(
                    self.p,
                    per,
                    (self.hooks, near.as_ref()),
                    eyes,
                    &mut self.out,
                )?
            }
            None => None,
        };
        self.earlier.window = Some(done.clone());
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

/// Points (x, y) given on the window, evaluated (each error naming its field).
fn given_on_window<T: Scalar>(
    given: &[(String, String, [Num; 2])],
) -> Result<Vec<(String, (T, T))>> {
    (given.iter())
        .map(|(n, f, [x, y])| Ok((n.clone(), (eval(f, x)?, eval(f, y)?))))
        .collect()
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

/// Step 4's steps: the window on the near plane (and the far one), and
/// which projected points it contains; `eyes` = (eye points, projected
/// points); `None` when fovy, aspect or near is missing (refused when the
/// parts are asked by name).
fn window_steps<T: Scalar>(
    p: &Problem,
    per: &Table<PerspectiveIn>,
    (hooks, near): (&Hooks<T>, Option<&T>),
    eyes: (&[Named<T>], &[Named<T>]),
    out: &mut Out,
) -> Result<Option<Windowed<T>>> {
    let t = &per.table;
    let (Some(fovy), Some(aspect), Some(near)) = (&t.fovy, &t.aspect, near) else {
        return match p.by_name() {
            true => Err(Error::why("perspective", ErrMsg::WindowNeeds)),
            false => Ok(None),
        };
    };
    let fovy: T = (fovy.0.degrees()).map_err(|m| Error::why(per.field("fovy"), m))?;
    let aspect: T = eval(&per.field("aspect"), aspect)?;
    let far: Option<T> = (t.far.as_ref())
        .map(|f| eval(&per.field("far"), f))
        .transpose()?;
    let on_window = (p.shared.on_window.as_deref())
        .map(given_on_window::<T>)
        .transpose()?;
    // "window and clipping" only where points are tested against the view
    // volume; a problem that asks the window alone is headed by it
    out.section(match eyes.1.is_empty() {
        true => Msg::SecWindow,
        false => Msg::SecWindowClip,
    });
    let rec = &mut out.rec;
    let set_up = (&fovy, &aspect, near, far.as_ref());
    let (w, result) = window_run(set_up, hooks, rec).map_err(|e| in_table(per.prefix, e))?;
    for ((n, q), (_, e)) in eyes.1.iter().zip(eyes.0) {
        point_inside_step(rec, n, q, e, &w, near, far.as_ref());
    }
    let points = match &on_window {
        Some(g) => (g.iter())
            .map(|(n, (x, y))| (n.clone(), Val::vec2(x, y)))
            .collect(),
        None if p.asks(Part::Project) => (eyes.1.iter())
            .map(|(n, q)| (n.clone(), Val::vec3(q)))
            .collect(),
        None => vec![],
    };
    let given = WindowAt {
        fovy: at(&fovy),
        aspect: at(&aspect),
        near: at(near),
        far: far.as_ref().map(at),
        viewport: None,
        points,
        projected: p.shared.on_window.is_none(),
    };
    Ok(Some(Windowed {
        w,
        result,
        given,
        on_window,
    }))
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

/// The text's point-clipping test after projection: inside the window and
/// between the near and far planes (−far ≤ z' ≤ −near).
fn point_inside_step<T: Scalar>(
    rec: &mut Recorder,
    name: &str,
    q: &V3<T>,
    e: &V3<T>,
    w: &window::Window<T>,
    near: &T,
    far: Option<&T>,
) {
    let in_window = window::inside(w, &q[0], &q[1]);
    let in_depth = e[2] <= -near.clone() && far.is_none_or(|f| e[2] >= -f.clone());
    rec.step(|| {
        // left ≤ xp ≤ right, bottom ≤ yp ≤ top, −far ≤ z' ≤ −near
        let mut args = [&w.left, &q[0], &w.right, &w.bottom, &q[1], &w.top]
            .map(Val::num)
            .to_vec();
        let mut form = "{} ≤ {} ≤ {}{,} {} ≤ {} ≤ {}{,} ".to_string();
        if let Some(f) = far {
            form.push_str("{} ≤ ");
            args.push(Val::num(&-f.clone()));
        }
        form.push_str("{} ≤ {}");
        args.extend([Val::num(&e[2]), Val::num(&-near.clone())]);
        Step::new(Msg::InsideVolume(name.to_string()), Msg::FInside)
            .val(Name::Image(name.to_string()), Val::vec2(&q[0], &q[1]))
            .val(Name::EyeZ(name.to_string()), Val::num(&e[2]))
            .res(Name::Inside, Val::Bool(in_window && in_depth))
            .sub(Name::Inside, Subst::new(form, args))
            .note(match (in_window, in_depth) {
                (true, true) => Msg::Inside(true, true),
                (false, w) => Msg::Inside(false, w),
                (true, false) => Msg::Inside(true, false),
            })
    });
}

/// Compares every `[printed]` answer with the computed results, each
/// judged as `check` marks a student's answer, with the problem's
/// settings ([`printed_agrees`]), and shown as written ([`written`]).
fn compare_printed(p: &ProblemIn, result: &[(String, Val)]) -> Option<Comparison> {
    let mut flat = Vec::new();
    crate::input::values::dotted("", &toml::Value::Table(p.printed.clone()), &mut flat);
    if flat.is_empty() {
        return None;
    }
    let settings = settings_for(p, None, None);
    let rows = flat
        .iter()
        .map(|(key, printed)| {
            let k: Option<Key> = key.parse().ok();
            let computed = k.as_ref().and_then(|k| value_of(result, k)).cloned();
            let judged = k.as_ref().zip(computed.as_ref());
            let erratum = p.errata.iter().find(|e| &e.key == key);
            Compared {
                key: key.clone(),
                printed: written(printed),
                agrees: judged.and_then(|(k, c)| printed_agrees(printed, c, k, &settings)),
                computed,
                kind: erratum.and_then(|e| e.kind),
                why: erratum.map(|e| e.why()),
            }
        })
        .collect();
    Some(Comparison {
        source: p.source.clone(),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tutor::key::Key;
    use crate::tutor::keys::ordered_keys;
    use crate::tutor::solution::{lookup, part_value};

    /// Every shipped problem (problems/*.toml), by file name, solved.
    fn shipped() -> Vec<(String, ProblemIn, Report)> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .expect("problems/ is read")
            .map(|e| e.expect("an entry of problems/").path())
            .filter(|f| f.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        let solved = files.into_iter().map(|f| {
            let name = f.display().to_string();
            let p = ProblemIn::read(&f).unwrap_or_else(|e| panic!("{name}: {e}"));
            let r = solve::<f64>(&p).unwrap_or_else(|e| panic!("{name}: {e}"));
            (name, p, r)
        });
        solved.collect()
    }

    /// The answer keys of `part` that practice asks and check follows
    /// through, in a result tree.
    fn keys_of(part: Part, result: &Tree) -> Vec<Key> {
        let of_part = |k: &Key| k.part == Some(part);
        ordered_keys(result).into_iter().filter(of_part).collect()
    }

    /// A new part needs more than the solver's arm the compiler asks for:
    /// the problem file's table it is solved from, and a shipped problem
    /// that asks it. For every part: some shipped problem solves it to
    /// results under its key, with answer keys (`ordered_keys`) for it; and
    /// that problem asking the part alone gives the same results, under
    /// that key only (the part's dependencies on earlier ones are worked
    /// without their results).
    #[test]
    fn every_part_is_solved_by_a_shipped_problem_alone_or_with_others() {
        let shipped = shipped();
        for part in Part::all() {
            let mut solvers =
                (shipped.iter()).filter(|(_, _, r)| r.result.iter().any(|(k, _)| *k == part.key()));
            let Some((name, p, r)) = solvers.next() else {
                panic!("no problem in problems/ solves `{part}`: add one that asks it");
            };
            let keys = keys_of(part, &r.result);
            assert!(!keys.is_empty(), "{name}: no answer key of `{part}`");
            let mut alone = p.clone();
            alone.ask = Some(vec![part]);
            let a = solve::<f64>(&alone).unwrap_or_else(|e| panic!("{name}, {part} alone: {e}"));
            let mine = |t: &Tree| t.iter().find(|(k, _)| *k == part.key()).cloned();
            assert_eq!(a.result.len(), 1, "{name}, {part} alone");
            assert_eq!(mine(&a.result), mine(&r.result), "{name}, {part} alone");
            assert_eq!(keys_of(part, &a.result), keys, "{name}, {part} alone");
        }
    }

    /// A source's printed answers are judged as `check` marks a student's:
    /// the same reader (a decimal comma, `√` and `−`, an Indonesian status,
    /// a segment written as text), the same tolerance and rounding. By
    /// hand: fovy 45°, near 0.1, aspect 2: top = 0.1·tan 22.5° =
    /// 0.1(√2 − 1) = 0.0414214, right = 2·top = 0.0828427 = height, width
    /// = 2·right = 2(√2 − 1)/5 = 0.1656854. The clip example's segment is
    /// clipped to (3, 8/3, 11/6)–(1, 4, 3/2) (the hand working in
    /// problems/text-clip.toml).
    #[test]
    fn printed_answers_are_judged_as_a_students_answers_are() {
        let text = "title = 't'\nask = ['window']\n\
            [perspective]\nnear = 0.1\nfovy = 45\naspect = 2\n\
            [printed]\n\
            'window.top' = '0.041'\n\
            'window.right' = '0.0829'\n\
            'window.left' = '-0.082'\n\
            'window.bottom' = '0.0414'\n\
            'window.height' = '0,0828'\n\
            'window.width' = '2(√2 − 1)/5'\n\
            'window.nowhere' = '1'\n";
        let p = ProblemIn::parse(text, "t.toml").unwrap();
        let expected = [
            ("window.top", Some(true)),     // 0.0414 rounded to 3 decimals
            ("window.right", Some(true)),   // 0.07 % off: within 0.1 %
            ("window.left", Some(false)),   // 1 % off; rounded it is −0.083
            ("window.bottom", Some(false)), // the sign
            ("window.height", Some(true)),  // 0.05 % off, a decimal comma
            ("window.width", Some(true)),   // exactly
            ("window.nowhere", None),       // no such result
        ];
        let rows = |r: Report| r.comparison.expect("printed answers").rows;
        let agrees = |rows: Vec<Compared>| -> Vec<(String, Option<bool>)> {
            rows.into_iter().map(|c| (c.key, c.agrees)).collect()
        };
        let want: Vec<(String, Option<bool>)> = (expected.iter())
            .map(|(k, a)| (k.to_string(), *a))
            .collect();
        let exact = rows(solve::<crate::num::Real>(&p).unwrap());
        assert_eq!(agrees(exact), want, "exact");
        assert_eq!(agrees(rows(solve::<f32>(&p).unwrap())), want, "f32");

        let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/text-clip.toml");
        let mut p = ProblemIn::read(&file).unwrap();
        p.printed = toml::from_str(
            "'clip.status' = 'di-clip'\n\
             'clip.segment' = '(3; 8/3; 11/6), (1; 4; 3/2)'\n\
             'clip.code0' = '000 010'\n\
             'clip.code1' = '001000'\n",
        )
        .unwrap();
        p.errata.clear();
        let got = agrees(rows(solve::<f64>(&p).unwrap()));
        let want = [Some(true), Some(true), Some(true), Some(false)];
        assert_eq!(
            got.iter().map(|(_, a)| *a).collect::<Vec<_>>(),
            want,
            "{got:?}"
        );
    }

    /// A command's flags as a table (fields unprefixed).
    fn flags<X>(table: X) -> Table<X> {
        Table { prefix: "", table }
    }

    /// The numbers of a result (a number, or a vector's or a matrix's).
    fn nums(v: Option<&Val>) -> Vec<f64> {
        match v {
            Some(Val::Num(x)) => vec![x.value],
            Some(Val::List(xs)) => xs.iter().flat_map(|x| nums(Some(x))).collect(),
            other => panic!("not numbers: {other:?}"),
        }
    }

    /// A calculator command and the same part of a problem file run through
    /// the one solver and give the same results and inputs. By hand: eye
    /// (0, 0, 5) looking at the origin, up y: n = (Pe − Pr)/|Pe − Pr| =
    /// (0, 0, 1), u = Vup × n/|…| = (1, 0, 0), v = n × u = (0, 1, 0); the
    /// view matrix translates by −Pe·(u, v, n) = (0, 0, −5); P = (1, 2, 3)
    /// is (1, 2, 3 − 5) = (1, 2, −2) in eye coordinates. Projected onto
    /// z = d = −near = −1: (x·d/z, y·d/z, d) = (0.5, 1, −1). fovy 90°,
    /// aspect 2, near 1: top = near·tan 45° = 1, right = aspect·top = 2.
    #[test]
    fn a_command_and_a_file_give_the_same_part_by_the_one_solver() {
        use crate::input::part::{ProjectionIn, Shared};
        use crate::input::problem::CameraIn;
        use crate::input::{num, vec3};
        use crate::num::Real;
        let text = "title = 't'\nask = ['view', 'project', 'window']\n\
            [camera]\neye = '(0, 0, 5)'\nlook = [0, 0, 0]\nup = [0, 1, 0]\n\
            [points]\nP = [1, 2, 3]\n\
            [perspective]\nnear = 1\nfovy = 90\naspect = 2\n";
        let file = solve::<Real>(&ProblemIn::parse(text, "t.toml").unwrap()).unwrap();
        let of_file = |part| Some(part_value(&file.result, part, None).unwrap().clone());
        let camera = CameraIn {
            eye: vec3("eye", "0,0,5").unwrap(),
            look: vec3("look", "0,0,0").unwrap(),
            up: vec3("up", "0,1,0").unwrap(),
        };
        let view = Shared {
            points: vec![(
                "P".into(),
                "point P".into(),
                vec3("point P", "1,2,3").unwrap(),
            )],
            camera: Some(flags(camera)),
            ..Shared::default()
        };
        let c = solve_problem::<Real>(&Problem::command(vec![PartIn::View], view)).unwrap();
        assert_eq!(nums(lookup(&c.result, "u")), [1.0, 0.0, 0.0]);
        assert_eq!(nums(lookup(&c.result, "v")), [0.0, 1.0, 0.0]);
        assert_eq!(nums(lookup(&c.result, "n")), [0.0, 0.0, 1.0]);
        let m = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, -5.0];
        assert_eq!(nums(lookup(&c.result, "matrix"))[..12], m);
        assert_eq!(nums(lookup(&c.result, "points.P")), [1.0, 2.0, -2.0]);
        assert_eq!(of_file(Part::View), Some(Val::Map(c.result)));
        assert_eq!(c.parts, file.parts[..1]);

        let d = ProjectionIn::Plane(("d".into(), num("d", "-1").unwrap()));
        let project = Shared {
            points: vec![(
                "P".into(),
                "point P".into(),
                vec3("point P", "1,2,-2").unwrap(),
            )],
            ..Shared::default()
        };
        let part = PartIn::Project(ProjectIn::Given(d));
        let c = solve_problem::<Real>(&Problem::command(vec![part], project)).unwrap();
        assert_eq!(nums(lookup(&c.result, "points.P")), [0.5, 1.0, -1.0]);
        assert_eq!(of_file(Part::Project), Some(Val::Map(c.result)));

        let table = PerspectiveIn {
            near: Some(num("near", "1").unwrap()),
            far: None,
            fovy: Some(crate::input::angle("fovy", "90").unwrap()),
            aspect: Some(num("aspect", "2").unwrap()),
            viewport: None,
            d: None,
        };
        let window = Shared {
            perspective: Some(flags(table)),
            on_window: Some(vec![]),
            ..Shared::default()
        };
        let c = solve_problem::<Real>(&Problem::command(vec![PartIn::Window], window)).unwrap();
        let edges = ["top", "bottom", "left", "right", "height", "width"];
        let got: Vec<f64> = edges
            .iter()
            .flat_map(|e| nums(lookup(&c.result, e)))
            .collect();
        assert_eq!(got, [1.0, -1.0, -2.0, 2.0, 2.0, 4.0]);
        assert_eq!(of_file(Part::Window), Some(Val::Map(c.result)));
    }

    /// `ask` names the parts by their one spelling, in the file's order;
    /// any other name is refused in the field `ask`, listing every part.
    #[test]
    fn ask_reads_every_part_by_its_name_and_refuses_others() {
        let names: Vec<&str> = Part::all().into_iter().map(Part::name).collect();
        let listed = names.iter().rev().map(|n| format!("'{n}'"));
        let text = format!(
            "title = 't'\nask = [{}]\n",
            listed.collect::<Vec<_>>().join(", ")
        );
        let p = ProblemIn::parse(&text, "t.toml").expect("every part's name is read");
        let mut all = Part::all();
        all.reverse();
        assert_eq!(p.ask, Some(all));
        for bad in ["View", "camera", ""] {
            let text = format!("title = 't'\nask = ['view', '{bad}']\n");
            let e = ProblemIn::parse(&text, "t.toml").expect_err(bad);
            let why = ErrMsg::UnknownPart(bad.to_string(), names.join(", "));
            assert_eq!((e.field, e.message), ("ask".to_string(), Msg::Err(why)));
        }
    }
}
