//! A problem's results as data (docs/spec.md §3's keys): each part's its
//! own struct, defined in its module ([`super::view::ViewResult`], …),
//! whose fields are its values ([`Val`]: a number, a vector, a matrix, a
//! status, the map of a part's points); [`Results`] holds them in the
//! order the parts were solved. A key is found by the part's exhaustive
//! match over its fields ([`Fields::field`]); the names the JSON and the
//! text show are the keys' one spelling ([`Node`]'s `Display`).

use crate::stages::trace::Val;
use crate::tutor::key::{Field, Key, Node, Part, Value};
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::borrow::Cow;

use super::clip::{ClipPart, ClipResult};
pub use super::fields::{entries, Fields};
use super::project::{ProjectPart, ProjectResult};
use super::shade::{ShadePart, ShadeResult};
use super::view::{ViewPart, ViewResult};
use super::viewport::{ViewportPart, ViewportResult};
use super::window::{WindowPart, WindowResult};
use super::Solves;

/// One part's results; a clip's, one per segment.
#[derive(Clone, Debug, PartialEq)]
pub enum PartResult {
    /// The basis, and the view matrix and eye coordinates.
    View(Box<ViewResult>),
    /// The projected points.
    Project(ProjectResult),
    /// The window's edges.
    Window(Box<WindowResult>),
    /// The pixels.
    Viewport(ViewportResult),
    /// Each segment's clipping.
    Clip(Vec<ClipResult>),
    /// The lighting.
    Shade(Box<ShadeResult>),
}

/// A part's results, or one segment's of a clip.
#[derive(Clone, Copy)]
pub enum One<'a> {
    View(&'a ViewResult),
    Project(&'a ProjectResult),
    Window(&'a WindowResult),
    Viewport(&'a ViewportResult),
    Clip(&'a ClipResult),
    Shade(&'a ShadeResult),
}

impl PartResult {
    /// The part it is.
    pub fn part(&self) -> Part {
        match self {
            PartResult::View(_) => Part::View,
            PartResult::Project(_) => Part::Project,
            PartResult::Window(_) => Part::Window,
            PartResult::Viewport(_) => Part::Viewport,
            PartResult::Clip(_) => Part::Clip,
            PartResult::Shade(_) => Part::Shade,
        }
    }

    /// Its results, or one segment's of a clip with several (`None`: the
    /// one segment of a clip with one); `None` for no such segment.
    pub fn one(&self, segment: Option<usize>) -> Option<One<'_>> {
        Some(match (self, segment) {
            (PartResult::Clip(runs), s) => One::Clip(&runs[segment_index(runs.len(), s)?]),
            (_, Some(_)) => return None,
            (PartResult::View(r), None) => One::View(r),
            (PartResult::Project(r), None) => One::Project(r),
            (PartResult::Window(r), None) => One::Window(r),
            (PartResult::Viewport(r), None) => One::Viewport(r),
            (PartResult::Shade(r), None) => One::Shade(r),
        })
    }

    /// Its results, or each segment's of a clip, with the segment's
    /// index in its keys (none for a part, or a clip's one segment).
    pub fn segments(&self) -> Vec<(Option<usize>, One<'_>)> {
        match self {
            PartResult::Clip(runs) if runs.len() > 1 => (runs.iter().enumerate())
                .map(|(i, r)| (Some(i), One::Clip(r)))
                .collect(),
            _ => self.one(None).map(|o| (None, o)).into_iter().collect(),
        }
    }

    /// Field `f` of one segment (or the part), to change it.
    fn field_mut(&mut self, segment: Option<usize>, f: Field) -> Option<&mut Val> {
        match (self, segment) {
            (PartResult::Clip(runs), s) => {
                let i = segment_index(runs.len(), s)?;
                runs[i].field_mut(f)
            }
            (_, Some(_)) => None,
            (PartResult::View(r), None) => r.field_mut(f),
            (PartResult::Project(r), None) => r.field_mut(f),
            (PartResult::Window(r), None) => r.field_mut(f),
            (PartResult::Viewport(r), None) => r.field_mut(f),
            (PartResult::Shade(r), None) => r.field_mut(f),
        }
    }

    /// The whole part as one value: its fields as a map, a clip's several
    /// segments as a list of maps.
    pub fn whole(&self) -> Val {
        match self {
            PartResult::Clip(runs) if runs.len() != 1 => {
                Val::List(runs.iter().map(|r| One::Clip(r).whole()).collect())
            }
            _ => self.one(None).map_or(Val::Null, |o| o.whole()),
        }
    }
}

impl<'a> One<'a> {
    /// Its fields in order, with their values.
    pub fn entries(self) -> Vec<(Field, &'a Val)> {
        match self {
            One::View(r) => entries(r),
            One::Project(r) => entries(r),
            One::Window(r) => entries(r),
            One::Viewport(r) => entries(r),
            One::Clip(r) => entries(r),
            One::Shade(r) => entries(r),
        }
    }

    /// Field `f`, if it holds it.
    pub fn field(self, f: Field) -> Option<&'a Val> {
        match self {
            One::View(r) => r.field(f),
            One::Project(r) => r.field(f),
            One::Window(r) => r.field(f),
            One::Viewport(r) => r.field(f),
            One::Clip(r) => r.field(f),
            One::Shade(r) => r.field(f),
        }
    }

    /// Its answer keys in the order of the text's solution: its part's
    /// ([`Solves::keys`]; an exhaustive match, the list of parts).
    pub fn keys(self) -> Vec<Key> {
        match self {
            One::View(r) => ViewPart::keys(r),
            One::Project(r) => ProjectPart::keys(r),
            One::Window(r) => WindowPart::keys(r),
            One::Viewport(r) => ViewportPart::keys(r),
            One::Clip(r) => ClipPart::keys(r),
            One::Shade(r) => ShadePart::keys(r),
        }
    }

    /// Its fields as a map (a whole part's value).
    pub fn whole(self) -> Val {
        Val::Map(
            self.entries()
                .into_iter()
                .map(|(f, v)| (f.key(), v.clone()))
                .collect(),
        )
    }
}

impl From<ViewResult> for PartResult {
    fn from(r: ViewResult) -> PartResult {
        PartResult::View(Box::new(r))
    }
}

impl From<ProjectResult> for PartResult {
    fn from(r: ProjectResult) -> PartResult {
        PartResult::Project(r)
    }
}

impl From<WindowResult> for PartResult {
    fn from(r: WindowResult) -> PartResult {
        PartResult::Window(Box::new(r))
    }
}

impl From<ViewportResult> for PartResult {
    fn from(r: ViewportResult) -> PartResult {
        PartResult::Viewport(r)
    }
}

impl From<Vec<ClipResult>> for PartResult {
    fn from(r: Vec<ClipResult>) -> PartResult {
        PartResult::Clip(r)
    }
}

impl From<ShadeResult> for PartResult {
    fn from(r: ShadeResult) -> PartResult {
        PartResult::Shade(Box::new(r))
    }
}

/// The named results of a command: each part's, in the order solved; a
/// problem file's nest under the part's key (`view.u`), a calculator
/// command's do not (`u`: docs/spec.md §3).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Results {
    /// Whether the parts nest under their keys (a problem file's).
    pub nested: bool,
    /// Each part's results, in the order solved.
    pub parts: Vec<PartResult>,
}

impl Results {
    /// No results, nested or not.
    pub fn new(nested: bool) -> Results {
        Results {
            nested,
            parts: Vec::new(),
        }
    }

    /// The results as named values, in order: a problem file's parts
    /// under their keys (a clip's several segments as a list), a
    /// command's fields unnested.
    pub fn tree(&self) -> Vec<(String, Val)> {
        let mut t = Vec::new();
        for p in &self.parts {
            match (self.nested, p.one(None)) {
                (true, _) => t.push((p.part().key(), p.whole())),
                (false, Some(o)) => {
                    t.extend(o.entries().into_iter().map(|(f, v)| (f.key(), v.clone())))
                }
                (false, None) => {}
            }
        }
        t
    }

    /// The results of `part`.
    pub fn of(&self, part: Part) -> Option<&PartResult> {
        self.parts.iter().find(|p| p.part() == part)
    }

    /// [`Results::of`], to change them.
    pub fn of_mut(&mut self, part: Part) -> Option<&mut PartResult> {
        self.parts.iter_mut().find(|p| p.part() == part)
    }

    /// The part (or segment) a key's value is in: a nested key's part; a
    /// command's key (no part) the one part that holds its field.
    fn holding(&self, key: &Key) -> Option<(Part, Option<usize>)> {
        match (self.nested, key.part) {
            (true, Some(p)) => Some((p, key.segment)),
            (false, None) => {
                let f = field_of(&key.value)?;
                let p = self
                    .parts
                    .iter()
                    .map(PartResult::part)
                    .find(|p| f.in_part(*p))?;
                Some((p, None))
            }
            _ => None,
        }
    }

    /// The value of an answer key: the part, the segment, the field,
    /// then the name or index inside it (a point, a plane tried, a
    /// light), then the component's indices. A whole part (`view`,
    /// `clip.1`) or a part's map (`view.points`) is its value as a map.
    pub fn get(&self, key: &Key) -> Option<Cow<'_, Val>> {
        let (part, segment) = self.holding(key)?;
        let r = self.of(part)?;
        let v = match (&key.value, segment) {
            (Value::Whole, None) => Cow::Owned(r.whole()),
            (Value::Whole, Some(_)) => Cow::Owned(r.one(segment)?.whole()),
            (value, _) => Cow::Borrowed(inside(r.one(segment)?.field(field_of(value)?)?, value)?),
        };
        key.component.iter().try_fold(v, |v, i| match v {
            Cow::Borrowed(Val::List(items)) => items.get(*i).map(Cow::Borrowed),
            Cow::Owned(Val::List(mut items)) if *i < items.len() => {
                Some(Cow::Owned(items.swap_remove(*i)))
            }
            _ => None,
        })
    }

    /// The value of a key as a file spells it (`clip[1].status` as
    /// `clip.1.status`); None for a name that is no key.
    pub fn lookup(&self, key: &str) -> Option<Cow<'_, Val>> {
        self.get(&key.parse().ok()?)
    }

    /// The value of an answer key inside a field (not a whole part), to
    /// change it: a mistake's results are the right ones with one value
    /// changed.
    pub fn get_mut(&mut self, key: &Key) -> Option<&mut Val> {
        let (part, segment) = self.holding(key)?;
        let f = field_of(&key.value)?;
        let v = self.of_mut(part)?.field_mut(segment, f)?;
        let v = inside_mut(v, &key.value)?;
        key.component.iter().try_fold(v, |v, i| match v {
            Val::List(items) => items.get_mut(*i),
            _ => None,
        })
    }
}

/// Which of a clip's `n` segments a key's `segment` names: the one of a
/// clip with one (a key with no segment), the i-th of several (a key with
/// segment i); none otherwise.
fn segment_index(n: usize, segment: Option<usize>) -> Option<usize> {
    match (n, segment) {
        (1, None) => Some(0),
        (n, Some(i)) if n > 1 && i < n => Some(i),
        _ => None,
    }
}

/// The field a key's value is in (none for a whole part).
fn field_of(value: &Value) -> Option<Field> {
    Some(match value {
        Value::Whole => return None,
        Value::Field(f) => *f,
        Value::Point(_) => Field::Points,
        Value::Pixel(_) => Field::Pixels,
        Value::Plane(_) | Value::Cut(..) => Field::Intersections,
        Value::Light(_) | Value::Factor(..) => Field::Lights,
    })
}

/// The names (or the index) a key's value has inside its field's value:
/// a point's name, a plane's and a cut's, a light's index and a factor's.
fn names_inside(value: &Value) -> Vec<Inside> {
    let name = |n: Node| Inside::Name(n.to_string());
    match value {
        Value::Whole | Value::Field(_) => vec![],
        Value::Point(n) | Value::Pixel(n) => vec![Inside::Name(n.clone())],
        Value::Plane(p) => vec![name(Node::Plane(*p))],
        Value::Cut(p, c) => vec![name(Node::Plane(*p)), name(Node::Cut(*c))],
        Value::Light(i) => vec![Inside::Nth(*i)],
        Value::Factor(i, x) => vec![Inside::Nth(*i), name(Node::Factor(*x))],
    }
}

/// One step inside a field's value: a name in a map, an item of a list.
enum Inside {
    Name(String),
    Nth(usize),
}

/// The value a key names inside its field's value `v`.
fn inside<'a>(v: &'a Val, value: &Value) -> Option<&'a Val> {
    names_inside(value)
        .iter()
        .try_fold(v, |v, step| match (step, v) {
            (Inside::Name(n), Val::Map(kv)) => kv.iter().find(|(k, _)| k == n).map(|(_, x)| x),
            (Inside::Nth(i), Val::List(items)) => items.get(*i),
            _ => None,
        })
}

/// [`inside`], to change it.
fn inside_mut<'a>(v: &'a mut Val, value: &Value) -> Option<&'a mut Val> {
    names_inside(value)
        .iter()
        .try_fold(v, |v, step| match (step, v) {
            (Inside::Name(n), Val::Map(kv)) => kv.iter_mut().find(|(k, _)| k == n).map(|(_, x)| x),
            (Inside::Nth(i), Val::List(items)) => items.get_mut(*i),
            _ => None,
        })
}

/// A part's (or a segment's) fields as a JSON object, named by their keys.
struct AsMap<'a>(Vec<(Field, &'a Val)>);

impl Serialize for AsMap<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (f, v) in &self.0 {
            m.serialize_entry(&Node::Field(*f), v)?;
        }
        m.end()
    }
}

impl Serialize for PartResult {
    /// Its fields as an object; a clip's several segments as a list.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            PartResult::Clip(runs) if runs.len() != 1 => {
                s.collect_seq(runs.iter().map(|r| AsMap(One::Clip(r).entries())))
            }
            _ => AsMap(self.one(None).map(One::entries).unwrap_or_default()).serialize(s),
        }
    }
}

impl Serialize for Results {
    /// docs/spec.md §3's `result` (and, inside
    /// [`crate::stages::trace::exact_forms`], `exact`): a problem file's
    /// parts under their keys, a command's fields unnested.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        for p in &self.parts {
            if self.nested {
                m.serialize_entry(&Node::Part(p.part()), p)?;
            } else {
                for (f, v) in p.one(None).map(One::entries).unwrap_or_default() {
                    m.serialize_entry(&Node::Field(f), v)?;
                }
            }
        }
        m.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;

    fn text(s: &str) -> Val {
        Val::Text(s.to_string())
    }

    fn map(kv: &[(&str, Val)]) -> Val {
        Val::Map(kv.iter().map(|(k, v)| (k.to_string(), v.clone())).collect())
    }

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    fn segment(status: &str) -> ClipResult {
        ClipResult {
            code0: text("000000"),
            code1: text("000000"),
            status: text(status),
            segment: Val::Null,
            intersections: map(&[("left", map(&[("code", text("000001"))]))]),
        }
    }

    fn view(points: Val) -> ViewResult {
        ViewResult {
            u: text("u"),
            v: text("v"),
            n: text("n"),
            matrix: None,
            points: Some(points),
        }
    }

    #[test]
    fn a_typed_key_walks_to_its_value() {
        let lights = Val::List(vec![text("l0"), map(&[("spot", text("s1"))])]);
        let shade = ShadeResult {
            lights: Some(lights),
            ..ShadeResult::default()
        };
        let results = Results {
            nested: true,
            parts: vec![
                PartResult::View(Box::new(view(map(&[("A", text("a"))])))),
                PartResult::Clip(vec![segment("accepted"), segment("clipped")]),
                PartResult::Shade(Box::new(shade)),
            ],
        };
        let at = |k: &str| results.lookup(k).map(Cow::into_owned);
        assert_eq!(at("view.points.A"), Some(text("a")));
        assert_eq!(at("view.u"), Some(text("u")));
        assert_eq!(at("clip.1.status"), Some(text("clipped")));
        assert_eq!(at("clip[0].status"), Some(text("accepted")));
        assert_eq!(at("clip.0.intersections.left.code"), Some(text("000001")));
        assert_eq!(at("shade.lights.0"), Some(text("l0")));
        assert_eq!(at("shade.lights[1].spot"), Some(text("s1")));
        // a whole part, a whole segment: its fields as a map
        assert_eq!(at("clip.1"), Some(One::Clip(&segment("clipped")).whole()));
        // not in the results: no segment 2, no point B, a clip of several
        // segments asked without one, a light's factor not computed, a
        // part not solved, a command's key in a problem file's results
        for k in [
            "clip.2.status",
            "view.points.B",
            "clip.status",
            "shade.lights.0.spot",
            "window.top",
            "u",
        ] {
            assert_eq!(at(k), None, "{k}");
        }
        // a command's results are its fields, not under the part
        let command = Results {
            nested: false,
            parts: vec![PartResult::View(Box::new(view(map(&[("A", text("a"))]))))],
        };
        assert_eq!(command.lookup("points.A").as_deref(), Some(&text("a")));
        assert_eq!(command.lookup("view.points.A"), None);
    }

    /// A mistake's results are the right ones with one value changed:
    /// `get_mut` changes the value `get` finds.
    #[test]
    fn a_value_changed_is_the_value_found() {
        let mut results = Results {
            nested: true,
            parts: vec![PartResult::Clip(vec![
                segment("accepted"),
                segment("clipped"),
            ])],
        };
        let k = key("clip.1.intersections.left.code");
        *results.get_mut(&k).expect("a code") = text("100000");
        assert_eq!(results.get(&k).as_deref(), Some(&text("100000")));
        assert_eq!(
            results.lookup("clip.0.intersections.left.code").as_deref(),
            Some(&text("000001"))
        );
        assert!(
            results.get_mut(&key("clip.1")).is_none(),
            "a whole segment is no value to change"
        );
    }

    /// Every name and index of a shipped problem's results, spelled as a
    /// dotted key (`view.points.A.1`, `clip.0`, `view`), is a `Key`, and
    /// `get` finds that very value: an answer file can name nothing in
    /// the results that no `Key` names.
    #[test]
    fn every_place_in_the_results_is_a_key() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .expect("problems/")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        let mut n = 0;
        for f in &files {
            let p = ProblemIn::read(f).expect("a shipped problem reads");
            let results = crate::tutor::solve::solve::<crate::num::Real>(&p)
                .expect("a shipped problem solves")
                .result;
            let tree = results.tree();
            let mut all = Vec::new();
            let index = |at: &str, i: usize| format!("{at}.{i}");
            for (k, v) in &tree {
                v.walk(k, &index, &mut |at, x| {
                    all.push((at.to_string(), x));
                    true
                });
            }
            for (at, v) in all {
                let found = results.get(&key(&at));
                assert_eq!(found.as_deref(), Some(v), "{at} in {f:?}");
                n += 1;
            }
        }
        assert!(n > 500, "{n}");
    }
}
