//! Lighting inputs: the one `[[light]]` table of problem, lights and scene
//! files ([`LightIn`], built by [`light`]); the `[shade]` table, lights
//! files (`--lights FILE.toml`) and the `shade` flags, all turned into one
//! validated set-up for [`crate::stages::lighting`], which
//! `tutor::parts::shade::shade_run` lights and keys as docs/spec.md §3 says.
//!
//! A lights file:
//!
//! ```toml
//! global_ambient = [0, 0, 0]       # Ga (optional)
//! [material]                       # Direct3D material (optional): ka = kd = ks = 1
//! diffuse = [1, 0, 0]              # ambient, diffuse, specular, emissive, power
//! [[light]]
//! type = "spot"                    # "directional" (direction = toward the light),
//! position = [0, 0, 5]             # "point" (position) or "spot" (position, axis =
//! axis = [0, 0, -1]                # the way it shines, theta, phi full cone angles
//! theta = 30                       # in degrees, falloff)
//! phi = 60
//! attenuation = [1, 0, 0]          # a0, a1, a2; range = R; colors color, ambient,
//! ```                              # diffuse, specular (white by default)

use crate::error::{Error, Result};
use crate::input::fields::{line_col, AngleIn, Num, Vec3In};
use crate::input::{eval as ev, eval3 as ev3};
use crate::msg::{ErrMsg, Msg, Thing, Twice};
use crate::num::vec::{normalize, sub, v3, V3};
use crate::num::Scalar;
use crate::stages::lighting::{
    self, check_color, gray, Light, LightKind, Material, Model, Rgb, Surface,
};
use crate::stages::trace::{Name, Step, Trace, Val};
use serde::Deserialize;
use std::path::Path;
use toml::Spanned;

/// The `[shade]` table (and the `shade` flags): the text's single light and
/// vectors, the model and coefficients, and the Direct3D extras.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShadeIn {
    /// The lighting model (default phong).
    pub model: Option<Model>,
    /// L, toward the light (one white directional light); not with `[[light]]`.
    pub light: Option<Vec3In>,
    /// N.
    pub normal: Option<Vec3In>,
    /// V (default (0, 0, 1), the text's viewVector); not with `camera`.
    pub view: Option<Vec3In>,
    /// Cs.
    pub color: Option<Vec3In>,
    /// ka (default 0.4; 1 with a Direct3D material).
    pub ka: Option<Num>,
    /// kd (default 0.6; 1 with a Direct3D material).
    pub kd: Option<Num>,
    /// ks (default 0.7; 1 with a Direct3D material).
    pub ks: Option<Num>,
    /// n (default 4).
    pub shininess: Option<Num>,
    /// Cp: the camera position (local viewer).
    pub camera: Option<Vec3In>,
    /// Vp: the surface point (default the origin).
    pub position: Option<Vec3In>,
    /// Whether the specular term is on (default true).
    pub specular: Option<bool>,
    /// Whether the specular term needs cos α > 0 (default false, as the text's code).
    pub specular_requires_lit: Option<bool>,
    /// Ga, the global ambient light.
    pub global_ambient: Option<Vec3In>,
    /// A Direct3D material.
    pub material: Option<MaterialIn>,
}

/// A Direct3D material (D3DMATERIAL9): its colors carry the coefficients.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialIn {
    /// Ca (default Cs).
    pub ambient: Option<Vec3In>,
    /// Cd = Cs.
    pub diffuse: Option<Vec3In>,
    /// The specular color (default white).
    pub specular: Option<Vec3In>,
    /// Ce (default black).
    pub emissive: Option<Vec3In>,
    /// P, the specular power (same as shininess).
    pub power: Option<Num>,
}

/// The type of a `[[light]]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LightType {
    /// Infinitely far, along `direction`.
    Directional,
    /// At `position`.
    Point,
    /// At `position`, shining along `axis` in a cone.
    Spot,
}

impl LightType {
    /// The type as written in a file (`spot`).
    pub fn name(self) -> &'static str {
        match self {
            LightType::Directional => "directional",
            LightType::Point => "point",
            LightType::Spot => "spot",
        }
    }

    /// The keys that do not apply to a light of this type.
    fn foreign_keys(self) -> &'static [&'static str] {
        match self {
            LightType::Directional => &[
                "position",
                "axis",
                "theta",
                "phi",
                "falloff",
                "attenuation",
                "range",
            ],
            LightType::Point => &["direction", "axis", "theta", "phi", "falloff"],
            LightType::Spot => &[],
        }
    }
}

/// One `[[light]]` table: the same keys, defaults and rules in problem
/// files, lights files and scene files (docs/spec.md §5). Every number is
/// an expression; directions are made unit vectors when the light is built.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightIn {
    /// directional, point or spot.
    #[serde(rename = "type")]
    pub kind: LightType,
    /// Directional: the vector toward the light (the text's L; default
    /// (0, 0, 1)). Spot: the old name of `axis`, still read.
    pub direction: Option<Vec3In>,
    /// Point and spot: where the light is (eye space).
    pub position: Option<Vec3In>,
    /// Spot: the direction it shines (away from the light).
    pub axis: Option<Vec3In>,
    /// Ld and Ls together (default white); `diffuse`, `specular` override it.
    pub color: Option<Vec3In>,
    /// La (default white).
    pub ambient: Option<Vec3In>,
    /// Ld (default `color`).
    pub diffuse: Option<Vec3In>,
    /// Ls (default `color`).
    pub specular: Option<Vec3In>,
    /// Point and spot: [a0, a1, a2] (default [1, 0, 0]).
    pub attenuation: Option<Vec3In>,
    /// Point and spot: the range (default none).
    pub range: Option<Num>,
    /// Spot: full inner cone angle (default 30°).
    pub theta: Option<AngleIn>,
    /// Spot: full outer cone angle (default 45°).
    pub phi: Option<AngleIn>,
    /// Spot: falloff exponent (default 1).
    pub falloff: Option<Num>,
    /// Where the table and its keys are in the file, for the errors found
    /// when the light is built ([`place`] fills it in).
    #[serde(skip)]
    pub at: Places,
}

impl LightIn {
    /// Whether each key that only some types take is given.
    fn given(&self) -> [(&'static str, bool); 8] {
        [
            ("position", self.position.is_some()),
            ("direction", self.direction.is_some()),
            ("axis", self.axis.is_some()),
            ("theta", self.theta.is_some()),
            ("phi", self.phi.is_some()),
            ("falloff", self.falloff.is_some()),
            ("attenuation", self.attenuation.is_some()),
            ("range", self.range.is_some()),
        ]
    }
}

/// Where a `[[light]]` table and each of its keys' values stand in their
/// file (`file:line:col`); empty for a light from no file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Places {
    table: Option<String>,
    keys: Vec<(String, String)>,
}

impl Places {
    /// `e` placed at the value of the key its field ends with
    /// (`light[1].axis`), else at the table.
    fn place(&self, e: Error) -> Error {
        let key = e.field.rsplit('.').next().unwrap_or_default();
        let at = self.keys.iter().find(|(k, _)| k == key).map(|(_, p)| p);
        match at.or(self.table.as_ref()) {
            Some(p) => e.at(p.clone()),
            None => e,
        }
    }
}

/// The most lights one file may have, problem, lights or scene file
/// alike: Direct3D 9's usual eight active lights (the work grows with
/// lights × points lit).
pub const MAX_LIGHTS: usize = 8;

/// Fills in where each of `lights` (the `[[light]]` tables read from
/// `text`) and its keys are, as `origin:line:col`. The places come from a
/// second read of the same text that keeps only the positions. More than
/// [`MAX_LIGHTS`] lights are refused first, before anything is placed or
/// evaluated.
pub fn place(lights: &mut [LightIn], text: &str, origin: &str) -> Result<()> {
    if lights.len() > MAX_LIGHTS {
        return Err(Error::why(
            "light",
            ErrMsg::TooManyLights(lights.len(), MAX_LIGHTS),
        ));
    }
    type Table = std::collections::BTreeMap<String, Spanned<serde::de::IgnoredAny>>;
    #[derive(Deserialize)]
    struct Spans {
        #[serde(default)]
        light: Vec<Spanned<Table>>,
    }
    let Ok(spans) = toml::from_str::<Spans>(text) else {
        return Ok(());
    };
    let at = |offset: usize| {
        let (line, col) = line_col(text, offset);
        format!("{origin}:{line}:{col}")
    };
    for (l, t) in lights.iter_mut().zip(&spans.light) {
        l.at = Places {
            table: Some(at(t.span().start)),
            keys: (t.get_ref().iter())
                .map(|(k, v)| (k.clone(), at(v.span().start)))
                .collect(),
        };
    }
    Ok(())
}

/// A lights file.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightsFileIn {
    /// Ga.
    pub global_ambient: Option<Vec3In>,
    /// A Direct3D material.
    pub material: Option<MaterialIn>,
    /// The lights.
    #[serde(default)]
    pub light: Vec<LightIn>,
}

impl LightsFileIn {
    /// Reads a lights file; TOML errors carry file:line:col.
    pub fn read(path: &Path) -> Result<LightsFileIn> {
        let text = crate::input::read_text("lights", path)?;
        LightsFileIn::parse(&text, &path.display().to_string())
    }

    /// Parses lights-file text; `origin` names it in messages.
    pub fn parse(text: &str, origin: &str) -> Result<LightsFileIn> {
        let mut f: LightsFileIn = crate::input::fields::parse_toml(text, origin)?;
        if f.light.is_empty() {
            return Err(Error::why(
                "lights",
                ErrMsg::NoLightTable(origin.to_string()),
            ));
        }
        place(&mut f.light, text, origin)?;
        Ok(f)
    }
}

/// Everything `shade` needs, validated.
#[derive(Clone, Debug)]
pub struct Setup<T> {
    /// The material.
    pub material: Material<T>,
    /// The lights.
    pub lights: Vec<Light<T>>,
    /// Ga.
    pub global_ambient: Rgb<T>,
    /// The point.
    pub surface: Surface<T>,
    /// Whether the light came from `light = L` (the text's single light).
    pub text_light: bool,
}

fn rgb<T: Scalar>(field: &str, v: &Vec3In) -> Result<Rgb<T>> {
    let c = ev3::<T>(field, v)?;
    let c = [c[0].clone(), c[1].clone(), c[2].clone()];
    check_color(field, &c)?;
    Ok(c)
}

fn opt_rgb<T: Scalar>(field: &str, v: &Option<Vec3In>, default: Rgb<T>) -> Result<Rgb<T>> {
    v.as_ref()
        .map(|v| rgb(field, v))
        .transpose()
        .map(|c| c.unwrap_or(default))
}

/// Builds and validates a set-up; `prefix` is prepended to field names
/// (`"shade."` in problem files), `lights_prefix` names the lights
/// (`"light"`, `"lights"`). Normalizing N, V and L is recorded as steps.
pub fn build<T: Scalar>(
    sh: &ShadeIn,
    file: &LightsFileIn,
    prefix: &str,
    lights_prefix: &str,
    tr: &mut impl Trace,
) -> Result<Setup<T>> {
    let f = |k: &str| format!("{prefix}{k}");
    let material = material(sh, file, prefix)?;
    let surface = surface(sh, &f, tr)?;
    let lights = lights(sh, file, &f, lights_prefix, &surface.position, tr)?;
    if file.global_ambient.is_some() && sh.global_ambient.is_some() {
        return Err(Error::why(f("global_ambient"), Twice::GlobalAmbient));
    }
    let ga = match file.global_ambient.as_ref().or(sh.global_ambient.as_ref()) {
        Some(g) => rgb(&f("global_ambient"), g)?,
        None => gray(T::zero()),
    };
    Ok(Setup {
        material,
        lights,
        global_ambient: ga,
        surface,
        text_light: sh.light.is_some(),
    })
}

/// The material: the surface colour Cs, the text's constants or a
/// Direct3D material (ka = kd = ks = 1), then the coefficients given.
fn material<T: Scalar>(sh: &ShadeIn, file: &LightsFileIn, prefix: &str) -> Result<Material<T>> {
    let f = |k: &str| format!("{prefix}{k}");
    let d3d = file.material.as_ref().or(sh.material.as_ref());
    if file.material.is_some() && sh.material.is_some() {
        return Err(Error::why(f("material"), Twice::Material));
    }
    let color = match (&sh.color, d3d.and_then(|m| m.diffuse.as_ref())) {
        (Some(c), None) => rgb(&f("color"), c)?,
        (None, Some(c)) => rgb(&f("material.diffuse"), c)?,
        (Some(_), Some(_)) => return Err(Error::why(f("color"), Twice::Color)),
        (None, None) => return Err(Error::why(f("color"), ErrMsg::ColorMissing)),
    };
    let mut mat = Material::text_default(color);
    mat.model = sh.model.unwrap_or_default();
    if let Some(m) = d3d {
        direct3d_material(&mut mat, m, sh.shininess.is_some(), &f)?;
    }
    for (k, slot) in [
        ("ka", &sh.ka),
        ("kd", &sh.kd),
        ("ks", &sh.ks),
        ("shininess", &sh.shininess),
    ] {
        if let Some(n) = slot {
            let x: T = ev(&f(k), n)?;
            match k {
                "ka" => mat.ka = x,
                "kd" => mat.kd = x,
                "ks" => mat.ks = x,
                _ => mat.shininess = x,
            }
        }
    }
    mat.specular_on = sh.specular.unwrap_or(true);
    mat.specular_requires_lit = sh.specular_requires_lit.unwrap_or(false);
    mat.validate(prefix)?;
    Ok(mat)
}

/// A Direct3D material's colours and power (ka = kd = ks = 1).
fn direct3d_material<T: Scalar>(
    mat: &mut Material<T>,
    m: &MaterialIn,
    shininess_given: bool,
    f: &dyn Fn(&str) -> String,
) -> Result<()> {
    mat.ka = T::one();
    mat.kd = T::one();
    mat.ks = T::one();
    mat.ambient_color = m
        .ambient
        .as_ref()
        .map(|c| rgb(&f("material.ambient"), c))
        .transpose()?;
    mat.specular = opt_rgb(&f("material.specular"), &m.specular, gray(T::one()))?;
    mat.emissive = opt_rgb(&f("material.emissive"), &m.emissive, gray(T::zero()))?;
    if let Some(p) = &m.power {
        if shininess_given {
            return Err(Error::why(f("shininess"), Twice::Shininess));
        }
        mat.shininess = ev(&f("material.power"), p)?;
    }
    Ok(())
}

/// The surface point: unit N, the viewer (V, the local viewer's camera, or
/// the text's (0, 0, 1)) and the position.
fn surface<T: Scalar>(
    sh: &ShadeIn,
    f: &dyn Fn(&str) -> String,
    tr: &mut impl Trace,
) -> Result<Surface<T>> {
    let normal_in = sh
        .normal
        .as_ref()
        .ok_or_else(|| Error::why(f("normal"), ErrMsg::NormalMissing))?;
    let normal = lighting::unit("N", &f("normal"), &ev3(&f("normal"), normal_in)?, tr)?;
    let position = match &sh.position {
        Some(p) => ev3(&f("position"), p)?,
        None => v3(T::zero(), T::zero(), T::zero()),
    };
    let camera = sh
        .camera
        .as_ref()
        .map(|c| ev3::<T>(&f("camera"), c))
        .transpose()?;
    let view = match (&sh.view, &camera) {
        (Some(_), Some(_)) => return Err(Error::why(f("view"), Twice::View)),
        (Some(v), None) => lighting::unit("V", &f("view"), &ev3(&f("view"), v)?, tr)?,
        (None, Some(c)) => {
            normalize(&sub(c, &position))
                .ok_or_else(|| Error::why(f("camera"), ErrMsg::CameraAtPoint))?
                .0
        }
        (None, None) => {
            let v = v3(T::zero(), T::zero(), T::one());
            tr.step(|| {
                Step::new(Msg::UnitVector("V".into()), "")
                    .res(Name::math("V"), Val::vec3(&v))
                    .note(Msg::DefaultView)
            });
            v
        }
    };
    Ok(Surface {
        normal,
        view,
        position,
        camera,
    })
}

/// The lights: the text's one directional L, or the `[[light]]` tables.
fn lights<T: Scalar>(
    sh: &ShadeIn,
    file: &LightsFileIn,
    f: &dyn Fn(&str) -> String,
    lights_prefix: &str,
    position: &V3<T>,
    tr: &mut impl Trace,
) -> Result<Vec<Light<T>>> {
    match (&sh.light, file.light.is_empty()) {
        (Some(l), true) => {
            let l = lighting::unit("L", &f("light"), &ev3(&f("light"), l)?, tr)?;
            Ok(vec![Light::directional(l)])
        }
        (None, false) => (file.light.iter().enumerate())
            .map(|(i, l)| lit_from(l, &format!("{lights_prefix}[{i}]"), position, tr))
            .collect(),
        (Some(_), false) => Err(Error::why(f("light"), Twice::Light)),
        (None, true) => Err(Error::why(f("light"), ErrMsg::NoLight)),
    }
}

/// One `[[light]]` table lighting the surface point `point`, which it
/// must not stand on.
fn lit_from<T: Scalar>(
    l: &LightIn,
    field: &str,
    point: &V3<T>,
    tr: &mut impl Trace,
) -> Result<Light<T>> {
    let out = light(l, field, tr)?;
    match &out.kind {
        LightKind::Point { pos } | LightKind::Spot { pos, .. } if pos == point => {
            let e = Error::why(format!("{field}.position"), ErrMsg::LightAtPoint);
            Err(l.at.place(e))
        }
        _ => Ok(out),
    }
}

/// One `[[light]]` table into a validated [`Light`] named `field`
/// (`light[0]`): its defaults filled in, `direction` (L) or `axis` made a
/// unit vector (the step goes to `tr`), an error placed in its file.
pub fn light<T: Scalar>(l: &LightIn, field: &str, tr: &mut impl Trace) -> Result<Light<T>> {
    build_light(l, field, tr).map_err(|e| l.at.place(e))
}

/// [`light`], its error not yet placed.
fn build_light<T: Scalar>(l: &LightIn, field: &str, tr: &mut impl Trace) -> Result<Light<T>> {
    let k = |s: &str| format!("{field}.{s}");
    forbid(l, &k)?;
    let kind = match l.kind {
        LightType::Directional => {
            let d = match &l.direction {
                Some(d) => ev3(&k("direction"), d)?,
                None => v3(T::zero(), T::zero(), T::one()),
            };
            LightKind::Directional {
                dir: lighting::unit("L", &k("direction"), &d, tr)?,
            }
        }
        LightType::Point => LightKind::Point {
            pos: need(l, &k, &l.position, "position")?,
        },
        LightType::Spot => spot(l, &k, tr)?,
    };
    let att = match &l.attenuation {
        Some(a) => {
            let a = ev3::<T>(&k("attenuation"), a)?;
            [a[0].clone(), a[1].clone(), a[2].clone()]
        }
        None => [T::one(), T::zero(), T::zero()],
    };
    let color = opt_rgb(&k("color"), &l.color, gray(T::one()))?;
    let out = Light {
        kind,
        ambient: opt_rgb(&k("ambient"), &l.ambient, gray(T::one()))?,
        diffuse: opt_rgb(&k("diffuse"), &l.diffuse, color.clone())?,
        specular: opt_rgb(&k("specular"), &l.specular, color)?,
        attenuation: att,
        range: l.range.as_ref().map(|n| ev(&k("range"), n)).transpose()?,
    };
    out.validate(field)?;
    Ok(out)
}

/// A spot light: its position, unit axis (`direction` is its old name),
/// cone angles theta and phi (full angles, 30° and 45° unless given) and
/// falloff (1 unless given).
fn spot<T: Scalar>(
    l: &LightIn,
    k: &dyn Fn(&str) -> String,
    tr: &mut impl Trace,
) -> Result<LightKind<T>> {
    let pos = need(l, k, &l.position, "position")?;
    let (key, axis) = match (&l.axis, &l.direction) {
        (Some(_), Some(_)) => return Err(Error::why(k("direction"), Twice::Axis)),
        (None, Some(d)) => ("direction", d),
        _ => ("axis", need_given(l, k, &l.axis, "axis")?),
    };
    let axis = lighting::unit("axis", &k(key), &ev3(&k(key), axis)?, tr)?;
    let angle = |a: &Option<AngleIn>, key: &str, default: i64| -> Result<T> {
        match a {
            Some(a) => a.0.degrees::<T>().map_err(|m| Error::why(k(key), m)),
            None => Ok(T::from_i64(default)),
        }
    };
    Ok(LightKind::Spot {
        pos,
        dir: axis,
        theta: angle(&l.theta, "theta", 30)?,
        phi: angle(&l.phi, "phi", 45)?,
        falloff: l
            .falloff
            .as_ref()
            .map(|n| ev(&k("falloff"), n))
            .transpose()?
            .unwrap_or_else(T::one),
    })
}

/// A vector the light's type needs (`key` names it), evaluated.
fn need<T: Scalar>(
    l: &LightIn,
    k: &dyn Fn(&str) -> String,
    v: &Option<Vec3In>,
    key: &str,
) -> Result<V3<T>> {
    ev3(&k(key), need_given(l, k, v, key)?)
}

/// A vector the light's type needs, as written.
fn need_given<'a>(
    l: &LightIn,
    k: &dyn Fn(&str) -> String,
    v: &'a Option<Vec3In>,
    key: &str,
) -> Result<&'a Vec3In> {
    v.as_ref().ok_or_else(|| {
        let kind = Thing::Light(l.kind.name().to_string());
        Error::why(k(key), ErrMsg::Needs(kind, key.to_string()))
    })
}

/// Refuses the first key given that does not apply to the light's type.
fn forbid(l: &LightIn, k: &dyn Fn(&str) -> String) -> Result<()> {
    let foreign = l.kind.foreign_keys();
    match l
        .given()
        .iter()
        .find(|(key, here)| *here && foreign.contains(key))
    {
        Some((key, _)) => Err(Error::why(
            k(key),
            ErrMsg::NotApplicable(key.to_string(), l.kind.name().to_string()),
        )),
        None => Ok(()),
    }
}
