//! The solver: a problem ([`solve_problem`]) is a calculator command's one
//! part ([`crate::tutor::part`]) or a whole problem file, solved here
//! through the text's steps — modeling, viewing transformation, projection
//! onto the near plane, window and clipping, viewport — with a comparison
//! with the answers the source printed. Both run their parts by the same
//! functions ([`crate::tutor::run`]).

use crate::error::{Error, Result};
use crate::input::part::Problem;
use crate::input::problem::{PointRef, ProblemIn};
use crate::input::{eval, eval3};
use crate::msg::{ErrMsg, Msg};
use crate::num::format::fmt_dec;
use crate::num::vec::V3;
use crate::num::{Expr, Scalar};
use crate::stages::camera::{Basis, Camera};
use crate::stages::clip::ClipBox;
use crate::stages::projection::Projection;
use crate::stages::trace::{Name, Recorder, Step, Subst, Trace, Val};
use crate::stages::window;
use crate::tutor::key::{Field, Part};
use crate::tutor::run::{
    basis_run, clip_run, eye_run, light_run, pixels, points_val, project_run, view_result,
    window_run, Hooks, Named,
};
use crate::tutor::solution::{
    at, lookup, p3, Asked, CameraAt, Compared, Comparison, Given, Report, ShadeAt, Tree, WindowAt,
};
use nalgebra::Matrix4;

/// Solves a problem at precision `T`: a calculator command's one part or
/// a problem file's parts.
pub fn solve_problem<T: Scalar>(p: &Problem) -> Result<Report> {
    match p {
        Problem::Part(part) => crate::tutor::part::solve_part::<T>(part),
        Problem::File(file) => solve::<T>(file),
    }
}

/// Solves a parsed problem at precision `T`.
pub fn solve<T: Scalar>(p: &ProblemIn) -> Result<Report> {
    solve_with::<T>(p, &Hooks::default())
}

/// Solves a parsed problem at precision `T`, with stage results altered by
/// `hooks`: each part asked, in [`Part::all`]'s order, by one exhaustive
/// match (a new part stops the build here).
pub fn solve_with<T: Scalar>(p: &ProblemIn, hooks: &Hooks<T>) -> Result<Report> {
    let points: Vec<Named<T>> = p
        .points()?
        .iter()
        .map(|(n, v)| Ok((n.clone(), eval3(&format!("points.{n}"), v)?)))
        .collect::<Result<_>>()?;
    let mut s = Solver {
        p,
        hooks,
        out: Out::default(),
        earlier: Earlier {
            points,
            viewed: None,
            near: None,
            projected: None,
            window: None,
        },
    };
    for part in Part::all() {
        match part {
            Part::View => s.view()?,
            Part::Project => s.project()?,
            Part::Window => s.window()?,
            Part::Viewport => s.viewport()?,
            Part::Clip => s.clip()?,
            Part::Shade => s.shade()?,
        }
    }
    let Out { rec, result, parts } = s.out;
    if result.is_empty() {
        return Err(Error::why("ask", ErrMsg::NothingToSolve));
    }

    // Exact printed forms are compared to 1e-9 relative, or to what the
    // precision itself can hold (f32 rounds at about 1e-7).
    let rel = match T::PRECISION {
        crate::num::Precision::F32 => 64.0 * f64::from(f32::EPSILON),
        _ => 1e-9,
    };
    let comparison = compare_printed(p, &result, rel);
    let asked = Asked::File(Box::new(p.clone()));
    let mut report = Report::from_recorder::<T>(asked, parts, result, rec);
    report.comparison = comparison;
    report.source_notes = p.source_notes.clone();
    Ok(report)
}

/// Where the parts write: the steps, the named results, what each part was given.
#[derive(Default)]
struct Out {
    rec: Recorder,
    result: Tree,
    parts: Vec<Given>,
}

/// What the stages produced for the parts after them, each worked (its
/// steps written) once, when a part first needs it; `None`: not yet.
struct Earlier<T> {
    /// The world points, in file order (read for every problem).
    points: Vec<Named<T>>,
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

/// Step 4 done: the window, its result keys and what it was given.
#[derive(Clone)]
struct Windowed<T> {
    w: window::Window<T>,
    result: Tree,
    given: WindowAt,
}

/// A problem file being solved: the problem, the hooks, what is written
/// and what earlier stages produced.
struct Solver<'a, 'h, T> {
    p: &'a ProblemIn,
    hooks: &'a Hooks<'h, T>,
    out: Out,
    earlier: Earlier<T>,
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// Whether a part asked needs the projected points (project, viewport).
    fn projects(&self) -> bool {
        self.p.asks(Part::Project) || self.p.asks(Part::Viewport)
    }

    /// `view`: the basis, the view matrix and the eye coordinates, worked
    /// here whenever a part asked needs them (view, project, viewport).
    fn view(&mut self) -> Result<()> {
        if !(self.p.asks(Part::View) || self.projects()) {
            return Ok(());
        }
        let (Some(v), true) = (self.viewed()?, self.p.asks(Part::View)) else {
            return Ok(());
        };
        let r = view_result(&v.basis, &v.matrix, &v.eye);
        self.out.result.push((Part::View.key(), Val::Map(r)));
        let world = (self.earlier.points.iter()).map(|(n, q)| (n.clone(), p3(q)));
        let given = Given::View(CameraAt::of(&v.cam), world.collect());
        self.out.parts.push(given);
        Ok(())
    }

    /// `project`: the points projected onto the near plane. near is read
    /// here whatever is asked (a near that does not evaluate is refused).
    fn project(&mut self) -> Result<()> {
        self.near()?;
        if !self.p.asks(Part::Project) {
            return Ok(());
        }
        let (Some((proj, projected)), Some(v)) = (self.projected()?, self.viewed()?) else {
            return Ok(());
        };
        let r = vec![(Field::Points.key(), points_val(&projected))];
        self.out.result.push((Part::Project.key(), Val::Map(r)));
        self.out.parts.push(Given::Project {
            projection: Given::projection(&proj),
            points: (v.eye.iter())
                .map(|(n, e)| (n.clone(), Val::vec3(e)))
                .collect(),
            chained: true,
        });
        Ok(())
    }

    /// `window`: the window's edges (and the far one's).
    fn window(&mut self) -> Result<()> {
        if !self.p.asks(Part::Window) {
            return Ok(());
        }
        if let Some(w) = self.windowed()? {
            self.out
                .result
                .push((Part::Window.key(), Val::Map(w.result)));
            self.out.parts.push(Given::Window(w.given));
        }
        Ok(())
    }

    /// `viewport`: the pixels of the projected points (window → pixels).
    fn viewport(&mut self) -> Result<()> {
        let vp = self
            .p
            .perspective
            .as_ref()
            .and_then(|x| x.viewport.as_ref());
        if !self.p.asks(Part::Viewport) {
            return Ok(());
        }
        let (Some(w), Some(vp)) = (self.windowed()?, vp) else {
            return Ok(());
        };
        let projected = self.projected()?.map(|(_, q)| q).unwrap_or_default();
        let (vw, vh): (T, T) = (
            eval("perspective.viewport", &vp[0])?,
            eval("perspective.viewport", &vp[1])?,
        );
        window::validate_viewport(&vw, &vh).map_err(|e| e.in_field("perspective.viewport"))?;
        let Out { rec, result, parts } = &mut self.out;
        rec.section(Msg::SecViewport);
        let windows = parts.iter_mut().filter_map(|g| match g {
            Given::Window(w) => Some(w),
            _ => None,
        });
        for given in windows {
            given.viewport = Some((at(&vw), at(&vh)));
        }
        let on_window = projected.iter().map(|(n, q)| (n, (&q[0], &q[1])));
        let px = pixels(&w.w, (&vw, &vh), on_window, rec);
        let r = vec![(Field::Pixels.key(), Val::Map(px))];
        result.push((Part::Viewport.key(), Val::Map(r)));
        Ok(())
    }

    /// `clip`: the clipping of each segment against the box.
    fn clip(&mut self) -> Result<()> {
        let (true, Some(c)) = (self.p.asks(Part::Clip), &self.p.clip) else {
            return Ok(());
        };
        let Out { rec, result, parts } = &mut self.out;
        let b = ClipBox {
            min: eval3("clip.min", &c.min)?,
            max: eval3("clip.max", &c.max)?,
        };
        b.validate().map_err(|e| e.in_field("clip.min"))?;
        let mut all = Vec::new();
        let several = c.segment.len() > 1;
        for (i, s) in c.segment.iter().enumerate() {
            let f = format!("clip.segment[{i}]");
            let p0: V3<T> = point_ref(&format!("{f}.from"), &s.from, &self.earlier.points)?;
            let p1: V3<T> = point_ref(&format!("{f}.to"), &s.to, &self.earlier.points)?;
            rec.section(Msg::SecLineClip(several.then_some(i + 1)));
            let segment = several.then_some(i);
            let given = Given::clip(&b, (&p0, &p1), segment);
            let hooks = (self.hooks, segment);
            all.push(Val::Map(clip_run(&b, (&p0, &p1), hooks, rec)));
            parts.push(given);
        }
        match all.len() {
            0 => {}
            1 => result.push((Part::Clip.key(), all.remove(0))),
            _ => result.push((Part::Clip.key(), Val::List(all))),
        }
        Ok(())
    }

    /// `shade`: the lighting at the `[shade]` point; lights without a
    /// `[shade]` table are refused whatever is asked.
    fn shade(&mut self) -> Result<()> {
        let p = self.p;
        let Out { rec, result, parts } = &mut self.out;
        match (p.asks(Part::Shade), &p.shade) {
            (true, Some(sh)) => {
                rec.section(Msg::SecLighting);
                let file = crate::input::lights::LightsFileIn {
                    global_ambient: p.global_ambient.clone(),
                    material: None,
                    light: p.light.clone(),
                };
                let (setup, r) = light_run((sh, &file, "shade."), self.hooks, rec)?;
                result.push((Part::Shade.key(), Val::Map(r)));
                parts.push(Given::Shade(ShadeAt::of(&setup, None)));
                Ok(())
            }
            _ if !p.light.is_empty() && p.shade.is_none() => {
                Err(Error::why("shade", ErrMsg::LightsNeedShade))
            }
            _ => Ok(()),
        }
    }

    /// near, when given (read once).
    fn near(&mut self) -> Result<Option<T>> {
        if let Some(near) = &self.earlier.near {
            return Ok(near.clone());
        }
        let near = (self.p.perspective.as_ref())
            .and_then(|x| x.near.as_ref())
            .map(|n| eval("perspective.near", n))
            .transpose()?;
        self.earlier.near = Some(near.clone());
        Ok(near)
    }

    /// Steps 1 and 2, modeling and viewing transformation, worked once:
    /// the basis, the view matrix and the eye coordinates of the points;
    /// `None` without a camera (refused when points need one and the parts
    /// are asked by name).
    fn viewed(&mut self) -> Result<Option<Viewed<T>>> {
        if let Some(v) = &self.earlier.viewed {
            return Ok(v.clone());
        }
        let (p, hooks, points) = (self.p, self.hooks, &self.earlier.points);
        let rec = &mut self.out.rec;
        let c = match &p.camera {
            Some(c) => c,
            None if !points.is_empty() && p.ask.is_some() => {
                return Err(Error::why("camera", ErrMsg::NoCameraTable))
            }
            None => {
                self.earlier.viewed = Some(None);
                return Ok(None);
            }
        };
        let cam = Camera {
            pe: eval3("camera.eye", &c.eye)?,
            pr: eval3("camera.look", &c.look)?,
            vup: eval3("camera.up", &c.up)?,
        };
        rec.section(Msg::SecModeling);
        rec.step(|| Step::new(Msg::NothingToDo, "").note(Msg::AlreadyWorld));
        rec.section(Msg::SecViewing);
        let basis = basis_run(&cam, hooks, rec).map_err(camera_field)?;
        let (matrix, eye) = eye_run(&basis, &cam, points, (hooks, camera_field), rec)?;
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
        let done = match eye.is_empty() {
            true => None,
            false => Some(project_steps(
                self.p,
                self.hooks,
                &eye,
                near.as_ref(),
                &mut self.out.rec,
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
        let rec = &mut self.out.rec;
        let done = match &self.p.perspective {
            Some(_) => window_steps(self.p, self.hooks, near.as_ref(), (&eye, &shown), rec)?,
            None => None,
        };
        self.earlier.window = Some(done.clone());
        Ok(done)
    }
}

/// Step 3's steps: d (−near unless given), the projection, the images of
/// the eye points.
fn project_steps<T: Scalar>(
    p: &ProblemIn,
    hooks: &Hooks<T>,
    eye_pts: &[Named<T>],
    near: Option<&T>,
    rec: &mut Recorder,
) -> Result<Projected<T>> {
    let given = p.perspective.as_ref().and_then(|x| x.d.as_ref());
    let d: T = match (given, near) {
        (Some(d), _) => eval("perspective.d", d)?,
        (None, Some(n)) => -n.clone(),
        (None, None) => return Err(Error::why("perspective.near", ErrMsg::ProjectionNeedsNear)),
    };
    rec.section(Msg::SecProjection);
    rec.step(|| match (given, near) {
        (None, Some(n)) => Step::new(Msg::ProjPlane, Msg::FProjPlane)
            .val(Name::math("near"), Val::num(n))
            .res(Name::math("d"), Val::num(&d))
            .sub(Name::math("d"), Subst::new("−{}", vec![Val::num(n)])),
        _ => Step::new(Msg::ProjPlane, "z = d").val(Name::math("d"), Val::num(&d)),
    });
    let proj = Projection::Plane { d };
    proj.validate().map_err(|e| e.in_field("perspective.d"))?;
    let projected = project_run(&proj, eye_pts, hooks, rec)?;
    Ok((proj, projected))
}

/// Step 4's steps: the window on the near plane (and the far one), and
/// which projected points it contains; `eyes` = (eye points, projected
/// points); `None` when fovy, aspect or near is missing (refused when the
/// parts are asked by name).
fn window_steps<T: Scalar>(
    p: &ProblemIn,
    hooks: &Hooks<T>,
    near: Option<&T>,
    eyes: (&[Named<T>], &[Named<T>]),
    rec: &mut Recorder,
) -> Result<Option<Windowed<T>>> {
    let Some(per) = &p.perspective else {
        return Ok(None);
    };
    let (Some(fovy), Some(aspect), Some(near)) = (&per.fovy, &per.aspect, near) else {
        return match p.ask {
            Some(_) => Err(Error::why("perspective", ErrMsg::WindowNeeds)),
            None => Ok(None),
        };
    };
    let fovy: T = fovy
        .0
        .degrees()
        .map_err(|m| Error::why("perspective.fovy", m))?;
    let aspect: T = eval("perspective.aspect", aspect)?;
    let far: Option<T> = per
        .far
        .as_ref()
        .map(|f| eval("perspective.far", f))
        .transpose()?;
    rec.section(Msg::SecWindowClip);
    let set_up = (&fovy, &aspect, near, far.as_ref());
    let (w, result) = window_run(set_up, hooks, rec).map_err(perspective_field)?;
    for ((n, q), (_, e)) in eyes.1.iter().zip(eyes.0) {
        point_inside_step(rec, n, q, e, &w, near, far.as_ref());
    }
    let given = WindowAt {
        fovy: at(&fovy),
        aspect: at(&aspect),
        near: at(near),
        far: far.as_ref().map(at),
        viewport: None,
        points: match p.asks(Part::Project) {
            true => (eyes.1.iter())
                .map(|(n, q)| (n.clone(), Val::vec3(q)))
                .collect(),
            false => vec![],
        },
        projected: true,
    };
    Ok(Some(Windowed { w, result, given }))
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

fn camera_field(e: Error) -> Error {
    let f = format!("camera.{}", e.field);
    e.in_field(f)
}

fn perspective_field(e: Error) -> Error {
    let f = format!("perspective.{}", e.field);
    e.in_field(f)
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
        Step::new(Msg::InsideVolume(name.to_string()), Msg::FInside)
            .val(Name::Image(name.to_string()), Val::vec2(&q[0], &q[1]))
            .val(Name::EyeZ(name.to_string()), Val::num(&e[2]))
            .res(Name::Inside, Val::Bool(in_window && in_depth))
            .note(match (in_window, in_depth) {
                (true, true) => Msg::Inside(true, true),
                (false, w) => Msg::Inside(false, w),
                (true, false) => Msg::Inside(true, false),
            })
    });
}

/// Flattens a nested TOML table into dotted keys.
fn flatten(prefix: &str, t: &toml::Table, out: &mut Vec<(String, toml::Value)>) {
    for (k, v) in t {
        let key = if prefix.is_empty() {
            k.clone()
        } else {
            format!("{prefix}.{k}")
        };
        match v {
            toml::Value::Table(inner) => flatten(&key, inner, out),
            other => out.push((key, other.clone())),
        }
    }
}

/// Whether a printed value agrees with a computed one: texts equal; numbers
/// equal to the digits the text wrote (a printed 0.041 agrees with 0.04142),
/// or to `rel` (relative, at least absolute near zero) when the printed form
/// is exact (−6/sqrt(2)); lists element by element (a printed (x, y) is
/// compared with the first two of (x, y, z)).
pub fn agrees(printed: &toml::Value, computed: &Val, rel: f64) -> Option<bool> {
    match (printed, computed) {
        (toml::Value::Array(ps), Val::List(cs)) => {
            if ps.len() > cs.len() {
                return Some(false);
            }
            let mut all = true;
            for (p, c) in ps.iter().zip(cs) {
                all &= agrees(p, c, rel)?;
            }
            Some(all)
        }
        (toml::Value::String(s), Val::Text(t)) => Some(s == t),
        (p, Val::Num(c)) => {
            let text = match p {
                toml::Value::String(s) => s.clone(),
                toml::Value::Integer(i) => i.to_string(),
                toml::Value::Float(f) => format!("{f}"),
                _ => return None,
            };
            let e: Expr = crate::num::parse_expr(&text.replace(',', ".")).ok()?;
            let v: f64 = e.eval::<f64>().ok()?;
            Some((v - c.value).abs() <= written_tolerance(&text).max(rel * c.value.abs().max(1.0)))
        }
        (toml::Value::String(s), Val::Null) => Some(s == "none" || s == "null"),
        _ => None,
    }
}

/// Half a unit in the last decimal place written (0 for exact forms).
fn written_tolerance(text: &str) -> f64 {
    let mut best: f64 = 0.0;
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        if chars[i] == '.' || chars[i] == ',' {
            let mut k = 0;
            while i + 1 + k < chars.len() && chars[i + 1 + k].is_ascii_digit() {
                k += 1;
            }
            best = best.max(0.5 * 10f64.powi(-(k as i32)));
            i += k;
        }
        i += 1;
    }
    best * 1.000001
}

/// Compares every `[printed]` answer with the computed results.
fn compare_printed(p: &ProblemIn, result: &[(String, Val)], rel: f64) -> Option<Comparison> {
    let mut flat = Vec::new();
    flatten("", &p.printed, &mut flat);
    if flat.is_empty() {
        return None;
    }
    let rows = flat
        .iter()
        .map(|(key, printed)| {
            let computed = lookup(result, key).cloned();
            let erratum = p.errata.iter().find(|e| &e.key == key);
            Compared {
                key: key.clone(),
                printed: printed_text(printed),
                agrees: computed.as_ref().and_then(|v| agrees(printed, v, rel)),
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

/// A printed value as the text wrote it.
fn printed_text(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Array(a) => format!(
            "({})",
            a.iter().map(printed_text).collect::<Vec<_>>().join(", ")
        ),
        toml::Value::Float(f) => fmt_dec(*f, 17),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tutor::key::Key;
    use crate::tutor::keys::ordered_keys;

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
