//! Scene files for `render` (docs/spec.md §6): the TOML schema (unknown keys are
//! errors), values checked while they are read so that every error carries
//! the file, line and column, and the validated [`Scene`] the renderer draws.

use crate::error::{Error, Result};
use crate::input::fields::{line_col, value_error, Num};
use crate::input::lights::{light, place, LightIn};
use crate::input::mesh::{self, Height, Mesh};
use crate::input::problem::{CameraIn, PerspectiveIn};
use crate::msg::{Bound, ErrMsg, Thing, TomlErr, Twice};
use crate::num::vec::V3;
use crate::stages::lighting::{Light, Material, Model};
use crate::stages::trace::NoTrace;
use nalgebra::{Matrix4, Vector3};
use serde::de::Deserializer;
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// The most triangles one scene may have, all its objects together
/// (memory: about 350 bytes each; checked before any mesh is built).
pub const MAX_TRIANGLES: usize = 4_000_000;

/// The most work a render may take unless `render --work-limit` allows
/// more, in millions of steps: a step is about one pixel test of the
/// rasterizer (2 ns of wall time on 2 cores; 4,000 million, about 10 s).
/// Height formulas count 4 steps per operation evaluated (checked here,
/// before any is evaluated); the renderer's estimate of a frame, the rest
/// (`render::work`).
pub const WORK_LIMIT: u64 = 4_000;

/// Steps per height-formula operation evaluated (a tree walk of about 10
/// ns per node, single-threaded, against 2 ns of wall time per pixel test).
pub const FORMULA_STEP: u64 = 4;

/// A finite number, evaluated from a TOML number or an expression string
/// while the file is read (so a bad value is reported at its position).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct F(pub f64);

impl<'de> Deserialize<'de> for F {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<F, D::Error> {
        let n = Num::deserialize(d)?;
        n.0.eval::<f64>()
            .map(F)
            .map_err(|e| value_error(TomlErr::Num(e)))
    }
}

/// A positive finite number (a radius, a height, a spacing).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pos(pub f64);

impl<'de> Deserialize<'de> for Pos {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Pos, D::Error> {
        let F(v) = F::deserialize(d)?;
        if v > 0.0 {
            Ok(Pos(v))
        } else {
            Err(value_error(TomlErr::MustBe(Bound::Positive, v)))
        }
    }
}

/// A count of subdivisions: a whole number from 3 to 4096.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Count(pub u32);

impl<'de> Deserialize<'de> for Count {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Count, D::Error> {
        let v = i64::deserialize(d)?;
        if (3..=4096).contains(&v) {
            Ok(Count(v as u32))
        } else {
            Err(value_error(TomlErr::WholeRange(3, 4096, v)))
        }
    }
}

/// A grid size: a whole number from 2 to 4096.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridCount(pub u32);

impl<'de> Deserialize<'de> for GridCount {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<GridCount, D::Error> {
        let v = i64::deserialize(d)?;
        if (2..=4096).contains(&v) {
            Ok(GridCount(v as u32))
        } else {
            Err(value_error(TomlErr::WholeRange(2, 4096, v)))
        }
    }
}

/// A colour component list [r, g, b], each from 0 to 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rgb(pub [f32; 3]);

impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Rgb, D::Error> {
        let c = <[F; 3]>::deserialize(d)?;
        if c.iter().any(|x| !(0.0..=1.0).contains(&x.0)) {
            return Err(value_error(TomlErr::Colour(c.map(|x| x.0))));
        }
        Ok(Rgb(c.map(|x| x.0 as f32)))
    }
}

/// Shading mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Shading {
    /// One lighting evaluation per face, with the face normal.
    #[default]
    Flat,
    /// Lighting per vertex, colours interpolated.
    Gouraud,
    /// Normals interpolated, lighting per pixel.
    Phong,
}

impl Shading {
    /// The name in a scene file and on the command line (`flat`).
    pub fn name(self) -> &'static str {
        match self {
            Shading::Flat => "flat",
            Shading::Gouraud => "gouraud",
            Shading::Phong => "phong",
        }
    }
}

/// Where vertex normals come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Normals {
    /// The normalised average of the adjacent face normals.
    #[default]
    Average,
    /// The text's `draw3Dcg`: the transformed vertex position, normalised
    /// (right only for a sphere centred at the origin).
    Position,
}

impl Normals {
    /// The name in a scene file (`average`), as serde reads it.
    pub fn name(self) -> &'static str {
        match self {
            Normals::Average => "average",
            Normals::Position => "position",
        }
    }
}

/// `[image]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImageIn {
    width: Option<u32>,
    height: Option<u32>,
    background: Option<Rgb>,
}

/// `[tilt]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TiltIn {
    #[serde(default)]
    x: Option<F>,
    #[serde(default)]
    y: Option<F>,
}

/// `[material]` (all optional; the text's defaults otherwise).
#[derive(Clone, Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct MaterialIn {
    model: Option<Model>,
    ka: Option<F>,
    kd: Option<F>,
    ks: Option<F>,
    shininess: Option<F>,
    specular: Option<Rgb>,
    emissive: Option<Rgb>,
    specular_requires_lit: Option<bool>,
}

/// One step of an object's transform list.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum TransformIn {
    /// Translation by (x, y, z).
    Translate([F; 3]),
    /// Rotation about x (radians).
    RotateX(F),
    /// Rotation about y (radians).
    RotateY(F),
    /// Rotation about z (radians).
    RotateZ(F),
    /// Uniform or per-axis scale.
    Scale(ScaleIn),
}

/// A scale: one factor or [sx, sy, sz].
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum ScaleIn {
    /// Same on every axis.
    One(F),
    /// Per axis.
    Axes([F; 3]),
}

#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "lowercase")]
#[cfg_attr(test, derive(strum::EnumIter))]
enum ObjectType {
    Cone,
    Sphere,
    Cylinder,
    Box,
    Plane,
    Obj,
}

impl ObjectType {
    /// Its name as a scene file's `type` spells it (`sphere`).
    fn name(self) -> &'static str {
        match self {
            ObjectType::Cone => "cone",
            ObjectType::Sphere => "sphere",
            ObjectType::Cylinder => "cylinder",
            ObjectType::Box => "box",
            ObjectType::Plane => "plane",
            ObjectType::Obj => "obj",
        }
    }
}

/// `[[object]]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectIn {
    #[serde(rename = "type")]
    kind: ObjectType,
    n: Option<Count>,
    stacks: Option<Count>,
    r: Option<Pos>,
    h: Option<Pos>,
    size: Option<[Pos; 3]>,
    nx: Option<GridCount>,
    nz: Option<GridCount>,
    dx: Option<Pos>,
    dz: Option<Pos>,
    height: Option<Spanned<String>>,
    path: Option<Spanned<String>>,
    #[serde(default)]
    transform: Vec<TransformIn>,
    color: Option<Rgb>,
    face_colors: Option<Vec<Rgb>>,
    vertex_colors: Option<Vec<Rgb>>,
    material: Option<MaterialIn>,
    shading: Option<Shading>,
}

/// A scene file as written.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneIn {
    title: Option<String>,
    /// Where the scene comes from: for people reading the file; not drawn.
    #[allow(dead_code)]
    source: Option<String>,
    /// What the scene shows: for people reading the file; not drawn.
    #[allow(dead_code)]
    statement: Option<String>,
    shading: Option<Shading>,
    normals: Option<Normals>,
    cull: Option<bool>,
    image: Option<ImageIn>,
    tilt: Option<TiltIn>,
    camera: Option<CameraIn>,
    perspective: Option<PerspectiveIn>,
    material: Option<MaterialIn>,
    /// The lights, as in problem and lights files.
    #[serde(default)]
    light: Vec<LightIn>,
    #[serde(default)]
    object: Vec<Spanned<ObjectIn>>,
}

pub use crate::stages::view::View;

/// Where an object's colours come from.
#[derive(Clone, Debug, PartialEq)]
pub enum Colors {
    /// One colour.
    One([f32; 3]),
    /// Polygon i gets colour i mod len (the text's i%2, i%3, i%5).
    Faces(Vec<[f32; 3]>),
    /// Vertex i gets colour i mod len.
    Vertices(Vec<[f32; 3]>),
}

/// A validated object.
#[derive(Clone, Debug)]
pub struct Object {
    /// `object[i] (type)`, for stats and errors.
    pub name: String,
    /// The mesh in model coordinates.
    pub mesh: Mesh,
    /// Model matrix (the transform list, first entry applied first).
    pub model: Matrix4<f64>,
    /// Colours.
    pub colors: Colors,
    /// Material (the scene's, overridden per object).
    pub material: Material<f32>,
    /// Shading of this object, if it differs from the scene's.
    pub shading: Option<Shading>,
    /// The mesh's triangles (computed once, when the scene is read).
    pub tris: mesh::Triangles,
    /// Whether the mesh is closed (back faces may be culled).
    pub closed: bool,
    /// Vertex normals in model coordinates.
    pub vnormals: Vec<[f32; 3]>,
    /// The mesh's bounding box in model coordinates ([`Mesh::bounds`]).
    pub bounds: [[f32; 3]; 2],
}

/// A validated scene.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Title, if given.
    pub title: Option<String>,
    /// Shading mode.
    pub shading: Shading,
    /// Vertex-normal source.
    pub normals: Normals,
    /// Whether back faces of closed meshes are culled.
    pub cull: bool,
    /// Image size.
    pub width: u32,
    /// Image size.
    pub height: u32,
    /// Background colour.
    pub background: [f32; 3],
    /// The view.
    pub view: View,
    /// Lights, in eye space.
    pub lights: Vec<Light<f32>>,
    /// Objects.
    pub objects: Vec<Object>,
    /// The files the scene read besides itself (its OBJ meshes).
    pub files: Vec<PathBuf>,
}

impl Scene {
    /// Reads and validates a scene file; paths inside are relative to it.
    /// Its height formulas may take up to `work_limit` million steps.
    pub fn read(path: &Path, work_limit: u64) -> Result<Scene> {
        let text = crate::input::read_text("scene", path)?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Scene::parse_within(&text, &path.display().to_string(), &dir, work_limit)
    }

    /// Parses and validates scene text; `origin` names it in messages and
    /// `dir` is where relative OBJ paths start (within [`WORK_LIMIT`]).
    pub fn parse(text: &str, origin: &str, dir: &Path) -> Result<Scene> {
        Scene::parse_within(text, origin, dir, WORK_LIMIT)
    }

    /// [`Scene::parse`] with height formulas of up to `work_limit` million
    /// steps.
    pub fn parse_within(text: &str, origin: &str, dir: &Path, work_limit: u64) -> Result<Scene> {
        let mut s: SceneIn = crate::input::fields::parse_toml(text, origin)?;
        place(&mut s.light, text, origin)?;
        let at = |span: std::ops::Range<usize>| {
            let (l, c) = line_col(text, span.start);
            format!("{origin}:{l}:{c}")
        };
        // The place of a table, for errors found after reading.
        let find = |key: &str| {
            let off = text
                .find(&format!("[{key}]"))
                .or_else(|| text.find(key))
                .unwrap_or(0);
            at(off..off)
        };
        let placed = |key: &str| {
            let here = find(key);
            move |e: Error| e.at(here.clone())
        };
        let (width, height, background) = image(&s).map_err(placed("image"))?;
        let view = view(&s, &find)?;
        let base = match &s.material {
            Some(m) => material(m, Material::text_default([1.0, 1.0, 1.0]))?,
            None => Material::text_default([1.0, 1.0, 1.0]),
        };
        budget(&s, work_limit).map_err(|e| e.at(origin))?;
        let mut lights = Vec::new();
        for (i, l) in s.light.iter().enumerate() {
            // At the renderer's precision: the light `shade --precision f32`
            // builds from the same table.
            lights.push(light::<f32>(l, &format!("light[{i}]"), &mut NoTrace)?);
        }
        if s.light.is_empty() {
            lights.push(Light::text_default());
        }
        let mut objects: Vec<Object> = Vec::new();
        for (i, o) in s.object.iter().enumerate() {
            let obj = object(i, o.get_ref(), &base, dir).map_err(|e| e.at(at(o.span())))?;
            objects.push(obj);
            // OBJ files count once read: the whole scene stays in budget.
            let total: usize = objects.iter().map(|o| o.tris.tris.len()).sum();
            if total > MAX_TRIANGLES {
                let e = ErrMsg::TooManyTriangles(total, MAX_TRIANGLES);
                return Err(Error::why("object", e).at(at(o.span())));
            }
        }
        if objects.is_empty() {
            return Err(Error::why("object", ErrMsg::NoObjects).at(origin));
        }
        let files = s
            .object
            .iter()
            .filter_map(|o| o.get_ref().path.as_ref())
            .map(|p| dir.join(p.get_ref()))
            .collect();
        Ok(Scene {
            title: s.title,
            shading: s.shading.unwrap_or_default(),
            normals: s.normals.unwrap_or_default(),
            cull: s.cull.unwrap_or(true),
            width,
            height,
            background,
            view,
            lights,
            objects,
            files,
        })
    }
}

/// The image's width, height (from `[image]`, else the viewport, else
/// 640×480) and background colour.
fn image(s: &SceneIn) -> Result<(u32, u32, [f32; 3])> {
    let viewport = match s.perspective.as_ref().and_then(|p| p.viewport.clone()) {
        Some([w, h]) => Some((
            eval_u32(&w, "perspective.viewport")?,
            eval_u32(&h, "perspective.viewport")?,
        )),
        None => None,
    };
    let img = s.image.as_ref();
    let width = img
        .and_then(|i| i.width)
        .or(viewport.map(|v| v.0))
        .unwrap_or(640);
    let height = img
        .and_then(|i| i.height)
        .or(viewport.map(|v| v.1))
        .unwrap_or(480);
    check_size(width, height)?;
    let background = img.and_then(|i| i.background).map_or([0.0; 3], |c| c.0);
    Ok((width, height, background))
}

/// How the scene is seen: `[tilt]` (the text's rotations) or a `[camera]`
/// with its `[perspective]`; `find` gives a table's place for errors.
fn view(s: &SceneIn, find: &dyn Fn(&str) -> String) -> Result<View> {
    match (&s.tilt, &s.camera) {
        (Some(_), Some(_)) => Err(Error::why("tilt", Twice::TiltCamera).at(find("tilt"))),
        (None, None) => Ok(View::Tilt { x: 0.0, y: 0.0 }),
        (Some(t), None) => Ok(View::Tilt {
            x: t.x.map_or(0.0, |v| v.0),
            y: t.y.map_or(0.0, |v| v.0),
        }),
        (None, Some(c)) => {
            let p = s.perspective.as_ref().ok_or_else(|| {
                Error::why("perspective", ErrMsg::CameraNeedsPerspective).at(find("camera"))
            })?;
            camera_view(c, p).map_err(|e| e.at(find("perspective")))
        }
    }
}

/// Checks an image size: 1 to 8192 pixels each way.
pub fn check_size(w: u32, h: u32) -> Result<()> {
    if !(1..=8192).contains(&w) || !(1..=8192).contains(&h) {
        return Err(Error::why(
            "image",
            ErrMsg::ImageSize(w.to_string(), h.to_string()),
        ));
    }
    Ok(())
}

fn eval_u32(n: &Num, field: &str) -> Result<u32> {
    let v = n.0.eval::<f64>().map_err(|m| Error::why(field, m))?;
    if v.fract() != 0.0 || !(1.0..=16384.0).contains(&v) {
        return Err(Error::why(field, ErrMsg::MustBe(Bound::WholePixels, v)));
    }
    Ok(v as u32)
}

fn f3(v: &[F; 3]) -> V3<f64> {
    Vector3::new(v[0].0, v[1].0, v[2].0)
}

fn camera_view(c: &CameraIn, p: &PerspectiveIn) -> Result<View> {
    let ev = |e: &Num, f: &str| e.0.eval::<f64>().map_err(|m| Error::why(f, m));
    let v3 = |a: &[Num; 3], f: &str| -> Result<V3<f64>> {
        Ok(Vector3::new(ev(&a[0], f)?, ev(&a[1], f)?, ev(&a[2], f)?))
    };
    let camera = crate::stages::camera::Camera {
        pe: v3(&c.eye, "camera.eye")?,
        pr: v3(&c.look, "camera.look")?,
        vup: v3(&c.up, "camera.up")?,
    };
    let fovy = match &p.fovy {
        Some(a) => {
            a.0.degrees::<f64>()
                .map_err(|m| Error::why("perspective.fovy", m))?
        }
        None => return Err(Error::why("perspective.fovy", ErrMsg::NeededToRender)),
    };
    let near = ev(
        p.near
            .as_ref()
            .ok_or_else(|| Error::why("perspective.near", ErrMsg::NeededToRender))?,
        "perspective.near",
    )?;
    let far = ev(
        p.far
            .as_ref()
            .ok_or_else(|| Error::why("perspective.far", ErrMsg::NeededToRender))?,
        "perspective.far",
    )?;
    let aspect = p
        .aspect
        .as_ref()
        .map(|a| ev(a, "perspective.aspect"))
        .transpose()?;
    crate::stages::window::validate(&fovy, &aspect.unwrap_or(1.0), &near).map_err(|e| {
        let f = format!("perspective.{}", e.field);
        e.in_field(f)
    })?;
    if far <= near {
        return Err(Error::why(
            "perspective.far",
            ErrMsg::MustBe(Bound::AboveNear(near), far),
        ));
    }
    // Fails early on a degenerate camera (Pe = Pr, Vup ∥ view direction).
    crate::stages::camera::basis(&camera, &mut crate::stages::trace::NoTrace)
        .map_err(|e| e.in_field(format!("camera.{}", "look/up")))?;
    Ok(View::Camera {
        camera,
        fovy,
        aspect,
        near,
        far,
    })
}

fn material(m: &MaterialIn, base: Material<f32>) -> Result<Material<f32>> {
    let mut out = base;
    if let Some(model) = m.model {
        out.model = model;
    }
    for (name, v, slot) in [
        ("ka", m.ka, &mut out.ka),
        ("kd", m.kd, &mut out.kd),
        ("ks", m.ks, &mut out.ks),
        ("shininess", m.shininess, &mut out.shininess),
    ] {
        if let Some(F(x)) = v {
            if x < 0.0 {
                return Err(Error::why(
                    format!("material.{name}"),
                    ErrMsg::MustBe(Bound::NotNegative, x),
                ));
            }
            *slot = x as f32;
        }
    }
    if let Some(c) = m.specular {
        out.specular = c.0;
    }
    if let Some(c) = m.emissive {
        out.emissive = c.0;
    }
    if let Some(b) = m.specular_requires_lit {
        out.specular_requires_lit = b;
    }
    out.validate("material")?;
    Ok(out)
}

/// The matrix of one transform step.
pub fn transform_matrix(t: &TransformIn) -> Matrix4<f64> {
    match t {
        TransformIn::Translate(v) => Matrix4::new_translation(&f3(v)),
        TransformIn::RotateX(a) => Matrix4::from_axis_angle(&Vector3::x_axis(), a.0),
        TransformIn::RotateY(a) => Matrix4::from_axis_angle(&Vector3::y_axis(), a.0),
        TransformIn::RotateZ(a) => Matrix4::from_axis_angle(&Vector3::z_axis(), a.0),
        TransformIn::Scale(ScaleIn::One(s)) => Matrix4::new_scaling(s.0),
        TransformIn::Scale(ScaleIn::Axes(v)) => Matrix4::new_nonuniform_scaling(&f3(v)),
    }
}

fn object(i: usize, o: &ObjectIn, base: &Material<f32>, dir: &Path) -> Result<Object> {
    let tname = o.kind.name();
    let field = format!("object[{i}]");
    let f = |k: &str| format!("{field}.{k}");
    check_fields(o, tname, &f)?;
    let mesh = object_mesh(o, tname, &f, dir)?;
    mesh.validate(&field)?;
    let mut model = Matrix4::identity();
    for t in &o.transform {
        model = transform_matrix(t) * model;
    }
    let material = match &o.material {
        Some(m) => material(m, base.clone()).map_err(|e| e.in_field(f("material")))?,
        None => base.clone(),
    };
    Ok(Object {
        name: format!("{field} ({tname})"),
        model,
        colors: object_colors(o, &f)?,
        material,
        shading: o.shading,
        tris: mesh.triangles(),
        closed: mesh.is_closed(),
        vnormals: mesh.vertex_normals(),
        bounds: mesh.bounds(),
        mesh,
    })
}

/// The scene's triangle budget, checked before any mesh or height formula
/// is evaluated: at most [`MAX_TRIANGLES`] triangles from the shapes' own
/// counts (an OBJ file's are counted when it is read), and height formulas
/// of at most `work_limit` million steps ([`formula_steps`]). Its lights
/// were counted when they were placed (`lights::MAX_LIGHTS`).
fn budget(s: &SceneIn, work_limit: u64) -> Result<()> {
    let total = (s.object.iter()).fold(0u64, |t, o| t.saturating_add(shape_triangles(o.get_ref())));
    if total > MAX_TRIANGLES as u64 {
        return Err(Error::why(
            "object",
            ErrMsg::TooManyTriangles(total as usize, MAX_TRIANGLES),
        ));
    }
    let (evals, size, steps) = formula_steps(s);
    if steps > work_limit.saturating_mul(1_000_000) {
        let need = steps.div_ceil(1_000_000);
        return Err(Error::why(
            "object",
            ErrMsg::FormulaWork(evals, size, need, work_limit),
        ));
    }
    Ok(())
}

/// The height formulas' work: how many evaluations (nx·nz per plane), the
/// size of the largest formula (its operations and operands) and the
/// steps of them all, [`FORMULA_STEP`] per node evaluated. A formula that
/// does not parse counts nothing (its error comes when it is built).
fn formula_steps(s: &SceneIn) -> (u64, usize, u64) {
    let (mut evals, mut size, mut steps) = (0u64, 0usize, 0u64);
    for o in s.object.iter().map(|o| o.get_ref()) {
        let Some(h) = o
            .height
            .as_ref()
            .and_then(|h| Height::parse(h.get_ref()).ok())
        else {
            continue;
        };
        let n = u64::from(o.nx.map_or(0, |c| c.0)) * u64::from(o.nz.map_or(0, |c| c.0));
        evals = evals.saturating_add(n);
        size = size.max(h.size());
        steps = steps.saturating_add(n.saturating_mul(h.size() as u64 * FORMULA_STEP));
    }
    (evals, size, steps)
}

/// The triangles a shape's mesh will have, from its counts alone (0 for an
/// OBJ file, and for counts missing: their errors come later):
/// cone 2n − 2 (n sides, an n-gon base), cylinder 4n − 4, sphere
/// 2·slices·(stacks − 1), box 12, plane 2(nx − 1)(nz − 1).
fn shape_triangles(o: &ObjectIn) -> u64 {
    let n = o.n.map_or(0, |c| u64::from(c.0));
    let count = |g: Option<GridCount>| g.map_or(0, |c| u64::from(c.0));
    let stacks = o.stacks.map_or(n, |c| u64::from(c.0));
    match o.kind {
        ObjectType::Cone => (2 * n).saturating_sub(2),
        ObjectType::Cylinder => (4 * n).saturating_sub(4),
        ObjectType::Sphere => (2 * n).saturating_mul(stacks.saturating_sub(1)),
        ObjectType::Box => 12,
        ObjectType::Plane => {
            (2 * count(o.nx).saturating_sub(1)).saturating_mul(count(o.nz).saturating_sub(1))
        }
        ObjectType::Obj => 0,
    }
}

/// Refuses a field that the object's type does not have.
fn check_fields(o: &ObjectIn, tname: &str, f: &dyn Fn(&str) -> String) -> Result<()> {
    let allowed: &[&str] = match o.kind {
        ObjectType::Cone | ObjectType::Cylinder => &["n", "r", "h"],
        ObjectType::Sphere => &["n", "stacks", "r"],
        ObjectType::Box => &["size"],
        ObjectType::Plane => &["nx", "nz", "dx", "dz", "height"],
        ObjectType::Obj => &["path"],
    };
    let present = [
        ("n", o.n.is_some()),
        ("stacks", o.stacks.is_some()),
        ("r", o.r.is_some()),
        ("h", o.h.is_some()),
        ("size", o.size.is_some()),
        ("nx", o.nx.is_some()),
        ("nz", o.nz.is_some()),
        ("dx", o.dx.is_some()),
        ("dz", o.dz.is_some()),
        ("height", o.height.is_some()),
        ("path", o.path.is_some()),
    ];
    match present
        .iter()
        .find(|(k, here)| *here && !allowed.contains(k))
    {
        Some((k, _)) => Err(Error::why(
            f(k),
            ErrMsg::NoSuchKey(tname.to_string(), k.to_string(), allowed.join(", ")),
        )),
        None => Ok(()),
    }
}

/// The object's mesh, built from its type's fields.
fn object_mesh(o: &ObjectIn, tname: &str, f: &dyn Fn(&str) -> String, dir: &Path) -> Result<Mesh> {
    let need = |v: Option<f64>, k: &str| v.ok_or_else(|| Error::why(f(k), needs(tname, k)));
    let n = || need(o.n.map(|c| c.0 as f64), "n").map(|n| n as u32);
    let r = || need(o.r.map(|c| c.0), "r");
    let h = || need(o.h.map(|c| c.0), "h");
    Ok(match o.kind {
        ObjectType::Cone => mesh::cone(n()?, r()?, h()?),
        ObjectType::Cylinder => mesh::cylinder(n()?, r()?, h()?),
        ObjectType::Sphere => {
            let n = n()?;
            mesh::sphere(n, o.stacks.map_or(n, |c| c.0), r()?)
        }
        ObjectType::Box => {
            let s = o
                .size
                .ok_or_else(|| Error::why(f("size"), needs("box", "size = [w, h, d]")))?;
            mesh::cuboid(s[0].0, s[1].0, s[2].0)
        }
        ObjectType::Plane => plane_mesh(o, f)?,
        ObjectType::Obj => {
            let p = o
                .path
                .as_ref()
                .ok_or_else(|| Error::why(f("path"), needs("obj", "path")))?;
            let full: PathBuf = dir.join(p.get_ref());
            mesh::load_obj(&full, &f("path"))?
        }
    })
}

/// "an object of type `tname` needs `key`".
fn needs(tname: &str, key: &str) -> ErrMsg {
    ErrMsg::Needs(Thing::Object(tname.to_string()), key.to_string())
}

/// A plane's grid, lifted by its height formula (which must stay finite).
fn plane_mesh(o: &ObjectIn, f: &dyn Fn(&str) -> String) -> Result<Mesh> {
    let nx =
        o.nx.ok_or_else(|| Error::why(f("nx"), needs("plane", "nx")))?
            .0;
    let nz =
        o.nz.ok_or_else(|| Error::why(f("nz"), needs("plane", "nz")))?
            .0;
    let need = |v: Option<Pos>, k: &str| {
        v.map(|c| c.0)
            .ok_or_else(|| Error::why(f(k), needs("plane", k)))
    };
    let (dx, dz) = (need(o.dx, "dx")?, need(o.dz, "dz")?);
    let h = match &o.height {
        Some(s) => Some(
            Height::parse(s.get_ref())
                .map_err(|m| Error::why(f("height"), m.quoted(s.get_ref())))?,
        ),
        None => None,
    };
    let height = |x, z| h.as_ref().map_or(0.0, |h| h.eval(x, z));
    mesh::finite_plane(nx, nz, dx, dz, height)
        .ok_or_else(|| Error::why(f("height"), ErrMsg::FormulaNotFinite))
}

/// The object's colours: one of `color`, `face_colors`, `vertex_colors`
/// (white when none is given).
fn object_colors(o: &ObjectIn, f: &dyn Fn(&str) -> String) -> Result<Colors> {
    let given = [
        o.color.is_some(),
        o.face_colors.is_some(),
        o.vertex_colors.is_some(),
    ];
    if given.iter().filter(|&&b| b).count() > 1 {
        return Err(Error::why(f("color"), Twice::Colors));
    }
    let list = |v: &Vec<Rgb>, k: &str| {
        if v.is_empty() {
            Err(Error::why(f(k), ErrMsg::NeedsColour))
        } else {
            Ok(v.iter().map(|c| c.0).collect())
        }
    };
    Ok(if let Some(c) = o.color {
        Colors::One(c.0)
    } else if let Some(v) = &o.face_colors {
        Colors::Faces(list(v, "face_colors")?)
    } else if let Some(v) = &o.vertex_colors {
        Colors::Vertices(list(v, "vertex_colors")?)
    } else {
        Colors::One([1.0, 1.0, 1.0])
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msg::Msg;

    fn parse(s: &str) -> Result<Scene> {
        Scene::parse(s, "s.toml", Path::new("."))
    }

    #[test]
    fn a_bad_aspect_names_perspective_aspect_alone() {
        let text = "[camera]\neye = [0, 0, 5]\nlook = [0, 0, 0]\nup = [0, 1, 0]\n\
                    [perspective]\nnear = 1\nfar = 10\nfovy = 45\naspect = -2\n\
                    [[object]]\ntype = \"sphere\"\nn = 8\nr = 1\n";
        let e = parse(text).unwrap_err();
        assert_eq!(e.field, "perspective.aspect", "{e}");
    }

    #[test]
    fn render_scene_with_no_objects_is_an_error() {
        for text in [
            "",
            "# only a comment\n",
            "[image]\nwidth = 10\nheight = 10\n",
        ] {
            let e = parse(text).unwrap_err();
            assert_eq!(e.field, "object", "{text:?}");
            let no_objects = Msg::At("s.toml".into(), Box::new(Msg::Err(ErrMsg::NoObjects)));
            assert_eq!(e.message, no_objects, "{e}");
        }
    }

    #[test]
    fn a_toml_syntax_error_names_the_key_not_a_stray_token() {
        let e = parse("[image]\nwidth = 10 # ten\nheight = 1 0\n").unwrap_err();
        assert_eq!(e.field, "height", "{e}");
        let e = parse("[image]\n# a comment\n=\n").unwrap_err();
        assert_eq!(e.field, "file", "{e}");
    }

    /// A scene file's `normals` is read by the name the render's JSON
    /// writes (`Normals::name`), for every choice.
    #[test]
    fn normals_are_read_by_the_name_they_are_written_by() {
        for n in [Normals::Average, Normals::Position] {
            let text = format!(
                "normals = \"{}\"\n[[object]]\ntype = \"sphere\"\nn = 8\nr = 1\n",
                n.name()
            );
            assert_eq!(parse(&text).map(|s| s.normals).ok(), Some(n), "{text}");
        }
    }

    /// The names the program writes (errors, `--shading`'s choices) are
    /// the ones a scene file is read by: serde's lowercase spelling.
    #[test]
    fn every_choice_is_read_by_the_name_it_is_written_by() {
        fn reads<X: serde::de::DeserializeOwned + PartialEq + std::fmt::Debug>(x: X, name: &str) {
            let read: X = toml::Value::String(name.into()).try_into().expect(name);
            assert_eq!(read, x, "{name}");
        }
        use strum::IntoEnumIterator;
        for t in ObjectType::iter() {
            reads(t, t.name());
        }
        for s in Shading::iter() {
            reads(s, s.name());
        }
    }

    #[test]
    fn text_defaults() {
        let s = parse("[[object]]\ntype = \"sphere\"\nn = 8\nr = 10\n").unwrap();
        assert_eq!(s.shading, Shading::Flat);
        assert_eq!((s.width, s.height), (640, 480));
        assert_eq!(s.lights.len(), 1);
        let m = &s.objects[0].material;
        assert_eq!((m.ka, m.kd, m.ks, m.shininess), (0.4, 0.6, 0.7, 4.0));
    }

    #[test]
    fn errors_carry_line_and_column() {
        let e = parse("[[object]]\ntype = \"pyramid\"\n").unwrap_err();
        assert!(e.message.plain().starts_with("s.toml:2:"), "{e}");
        let e = parse("[[object]]\ntype = \"sphere\"\nn = -3\nr = 1\n").unwrap_err();
        assert!(e.message.plain().starts_with("s.toml:3:"), "{e}");
        let e = parse("[[object]]\ntype = \"sphere\"\nn = 5\nr = nan\n").unwrap_err();
        assert!(e.message.plain().starts_with("s.toml:4:"), "{e}");
        let e = parse("[[object]]\ntype = \"sphere\"\nn = 5\nr = \"1/0\"\n").unwrap_err();
        assert!(e.message.plain().starts_with("s.toml:4:"), "{e}");
        let e = parse("\n[[object]]\ntype = \"obj\"\npath = \"nope.obj\"\n").unwrap_err();
        assert!(
            e.message.plain().starts_with("s.toml:2:") && e.message.plain().contains("nope.obj"),
            "{e}"
        );
        let e = parse("[[object]]\ntype = \"box\"\nsize = [1, 1, 1]\nr = 2\n").unwrap_err();
        assert_eq!(e.field, "object[0].r");
    }

    #[test]
    fn transforms_apply_in_the_order_listed() {
        // translate (1,0,0) then rotate_z 90°: (0,0,0) → (1,0,0) → (0,1,0).
        let s = parse("[[object]]\ntype = \"box\"\nsize = [1,1,1]\ntransform = [{ translate = [1, 0, 0] }, { rotate_z = \"pi/2\" }]\n").unwrap();
        let p = s.objects[0].model * nalgebra::Vector4::new(0.0, 0.0, 0.0, 1.0);
        assert!((p.x).abs() < 1e-12 && (p.y - 1.0).abs() < 1e-12, "{p:?}");
    }
}
