//! The window part (step 4 of the text): the window on the near plane
//! from fovy, aspect and near (top = near·tan(fovy/2), right =
//! aspect·top, height = 2·top, width = 2·right), the far plane's when far
//! is given, and which projected points lie inside the view volume.

use crate::error::{Error, Result};
use crate::input::eval;
use crate::input::fields::Num;
use crate::input::part::{Problem, Table};
use crate::input::problem::PerspectiveIn;
use crate::msg::{Bound, ErrMsg, Msg};
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::trace::{Name, Recorder, Step, Subst, Trace, Val};
use crate::stages::window::{self, Window};
use crate::tutor::follow;
use crate::tutor::key::{Edge, Field, Key, Part, Value};
use crate::tutor::parts::fields::Fields;
use crate::tutor::parts::{Out, Solver, Solves, Windowed};
use crate::tutor::run::{in_table, Hooks, Named};
use crate::tutor::solution::{at, Given, WindowAt};
use crate::tutor::topic::Topic;

/// The window part.
pub struct WindowPart;

impl Solves for WindowPart {
    const PART: Part = Part::Window;
    type In = ();
    type Result = WindowResult;

    /// `window`: the window's edges (and the far one's).
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, _: &()) -> Result<()> {
        if let Some(w) = s.windowed()? {
            s.put(w.result);
            s.out.parts.push(Given::Window(w.given));
        }
        Ok(())
    }

    /// The window's top, bottom, left, right, height, width (not the far
    /// window's).
    fn keys(r: &WindowResult) -> Vec<Key> {
        let key = |v: Value| Key::new(Self::PART, v);
        (crate::tutor::parts::fields::entries(r).into_iter())
            .filter(|(f, _)| matches!(f, Field::Edge(_, false)))
            .map(|(f, _)| key(Value::Field(f)))
            .collect()
    }

    fn topic(_: &Value) -> Topic {
        Topic::Window
    }
}

impl<T: Scalar> Solver<'_, '_, T> {
    /// Step 4, worked once: the window on the near plane (and the far one)
    /// and which projected points it contains (when a part asked projects
    /// them); `None` when the perspective sets up no window (refused when
    /// the parts are asked by name).
    pub(crate) fn windowed(&mut self) -> Result<Option<Windowed<T>>> {
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

/// Points (x, y) given on the window, evaluated (each error naming its field).
fn given_on_window<T: Scalar>(
    given: &[(String, String, [Num; 2])],
) -> Result<Vec<(String, (T, T))>> {
    (given.iter())
        .map(|(n, f, [x, y])| Ok((n.clone(), (eval(f, x)?, eval(f, y)?))))
        .collect()
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

/// The window on the near plane from (fovy in degrees, aspect, near, far)
/// (altered by `hooks`), and the far plane's when far is given, which must
/// lie beyond near: the window and its result keys (top … width, and the
/// far window's `far_top` … `far_right`).
pub fn window_run<T: Scalar>(
    (fovy, aspect, near, far): (&T, &T, &T, Option<&T>),
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<(Window<T>, WindowResult)> {
    let mut w = window::window(fovy, aspect, near, "near", rec)?;
    (hooks.window)(&mut w, fovy);
    if let Some(g) = hooks.givens() {
        follow::window(g, aspect, &mut w);
    }
    let mut r = WindowResult {
        near: edges(&w),
        height: Val::num(&w.height),
        width: Val::num(&w.width),
        far: None,
    };
    if let Some(f) = far {
        if f <= near {
            let (near, got) = (near.to_f64(), f.to_f64());
            return Err(Error::why(
                "far",
                ErrMsg::MustBe(Bound::AboveNear(near), got),
            ));
        }
        let fw = window::window(fovy, aspect, f, "far", rec)?;
        // the far window's edges, not its size
        r.far = Some(edges(&fw));
    }
    Ok((w, r))
}

/// A window's edges: top, bottom = −top, left = −right, right = aspect·top.
#[derive(Clone, Debug, PartialEq)]
pub struct Edges {
    /// top, the text's h.
    pub top: Val,
    /// bottom.
    pub bottom: Val,
    /// left.
    pub left: Val,
    /// right.
    pub right: Val,
}

/// The window's results: the near window's edges and size, the far
/// window's edges when far is given (`far_top`, …).
#[derive(Clone, Debug, PartialEq)]
pub struct WindowResult {
    /// The edges on the near plane.
    pub near: Edges,
    /// height = 2·top.
    pub height: Val,
    /// width = 2·right.
    pub width: Val,
    /// The edges on the far plane, when far is given.
    pub far: Option<Edges>,
}

/// The edges of window `w`.
fn edges<T: Scalar>(w: &Window<T>) -> Edges {
    Edges {
        top: Val::num(&w.top),
        bottom: Val::num(&w.bottom),
        left: Val::num(&w.left),
        right: Val::num(&w.right),
    }
}

impl Edges {
    /// Edge `e` (none for a size).
    fn edge(&self, e: Edge) -> Option<&Val> {
        match e {
            Edge::Top => Some(&self.top),
            Edge::Bottom => Some(&self.bottom),
            Edge::Left => Some(&self.left),
            Edge::Right => Some(&self.right),
            Edge::Height | Edge::Width => None,
        }
    }

    /// [`Edges::edge`], to change it.
    fn edge_mut(&mut self, e: Edge) -> Option<&mut Val> {
        match e {
            Edge::Top => Some(&mut self.top),
            Edge::Bottom => Some(&mut self.bottom),
            Edge::Left => Some(&mut self.left),
            Edge::Right => Some(&mut self.right),
            Edge::Height | Edge::Width => None,
        }
    }
}

impl Fields for WindowResult {
    const ORDER: &'static [Field] = &[
        Field::Edge(Edge::Top, false),
        Field::Edge(Edge::Bottom, false),
        Field::Edge(Edge::Left, false),
        Field::Edge(Edge::Right, false),
        Field::Edge(Edge::Height, false),
        Field::Edge(Edge::Width, false),
        Field::Edge(Edge::Top, true),
        Field::Edge(Edge::Bottom, true),
        Field::Edge(Edge::Left, true),
        Field::Edge(Edge::Right, true),
    ];

    fn field(&self, f: Field) -> Option<&Val> {
        match f {
            Field::Edge(Edge::Height, false) => Some(&self.height),
            Field::Edge(Edge::Width, false) => Some(&self.width),
            Field::Edge(e, false) => self.near.edge(e),
            Field::Edge(e, true) => self.far.as_ref()?.edge(e),
            _ => None,
        }
    }

    fn field_mut(&mut self, f: Field) -> Option<&mut Val> {
        match f {
            Field::Edge(Edge::Height, false) => Some(&mut self.height),
            Field::Edge(Edge::Width, false) => Some(&mut self.width),
            Field::Edge(e, false) => self.near.edge_mut(e),
            Field::Edge(e, true) => self.far.as_mut()?.edge_mut(e),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Real;
    use crate::stages::trace::Recorder;

    fn num(r: &WindowResult, key: &str) -> Option<f64> {
        let f = Field::all().into_iter().find(|f| f.key() == key)?;
        match r.field(f)? {
            Val::Num(s) => Some(s.value),
            _ => None,
        }
    }

    /// fovy 90°, aspect 2: top = near·tan 45° = near, right = aspect·top.
    /// Near 1: top 1, right 2, height 2, width 4; far 3: top 3, right 6;
    /// the far window gives its edges, not its height and width.
    #[test]
    fn the_far_window_gives_its_edges_once() {
        let (fovy, aspect, near, far) =
            (Real::from(90), Real::from(2), Real::from(1), Real::from(3));
        let mut rec = Recorder::new();
        let hooks = Hooks::default();
        let (_, r) = window_run((&fovy, &aspect, &near, Some(&far)), &hooks, &mut rec).unwrap();
        let keys: Vec<String> = (crate::tutor::parts::fields::entries(&r).iter())
            .map(|(f, _)| f.key())
            .collect();
        assert_eq!(
            keys,
            [
                "top",
                "bottom",
                "left",
                "right",
                "height",
                "width",
                "far_top",
                "far_bottom",
                "far_left",
                "far_right"
            ]
        );
        assert_eq!(num(&r, "top"), Some(1.0));
        assert_eq!(num(&r, "width"), Some(4.0));
        assert_eq!(num(&r, "far_top"), Some(3.0));
        assert_eq!(num(&r, "far_right"), Some(6.0));
    }

    /// far must lie beyond near: far = near is refused, naming `far`, with
    /// the one message for the rule.
    #[test]
    fn far_at_near_is_refused_by_the_one_rule() {
        let (fovy, aspect, one) = (Real::from(90), Real::from(2), Real::from(1));
        let mut rec = Recorder::new();
        let e = window_run(
            (&fovy, &aspect, &one, Some(&one)),
            &Hooks::default(),
            &mut rec,
        )
        .unwrap_err();
        assert_eq!(e.field, "far");
        assert_eq!(
            e.message,
            crate::msg::Msg::Err(ErrMsg::MustBe(Bound::AboveNear(1.0), 1.0))
        );
    }
}
