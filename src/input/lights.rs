//! Lighting inputs: the `[shade]` table and `[[light]]` tables of problem
//! files, lights files (`--lights FILE.toml`), and the `shade` flags, all
//! turned into one validated set-up for [`crate::stages::lighting`], and the
//! set-up's results keyed as docs/spec.md §3 says.
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
//! attenuation = [1, 0, 0]          # a0, a1, a2; range = R; colors ambient,
//! ```                              # diffuse, specular (white by default)

use crate::error::{Error, Result};
use crate::input;
use crate::input::fields::{toml_error, AngleIn, Num, Vec3In};
use crate::msg::{ErrMsg, Msg, Thing, Twice};
use crate::num::vec::{normalize, sub, v3, V3};
use crate::num::Scalar;
use crate::stages::lighting::{
    self, check_color, gray, Light, LightKind, LightTerm, Material, Model, Rgb, Surface,
};
use crate::stages::trace::{NoTrace, Recorder, Step, Trace, Val};
use serde::Deserialize;
use std::path::Path;

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

/// One `[[light]]` table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightIn {
    /// directional, point or spot.
    #[serde(rename = "type")]
    pub kind: LightType,
    /// Directional: the vector toward the light (the text's L).
    pub direction: Option<Vec3In>,
    /// Point and spot: where the light is (eye space).
    pub position: Option<Vec3In>,
    /// Spot: the direction it shines (away from the light).
    pub axis: Option<Vec3In>,
    /// La (default white).
    pub ambient: Option<Vec3In>,
    /// Ld (default white).
    pub diffuse: Option<Vec3In>,
    /// Ls (default white).
    pub specular: Option<Vec3In>,
    /// [a0, a1, a2] (default [1, 0, 0]).
    pub attenuation: Option<Vec3In>,
    /// Range (default none).
    pub range: Option<Num>,
    /// Spot: full inner cone angle (degrees).
    pub theta: Option<AngleIn>,
    /// Spot: full outer cone angle (degrees).
    pub phi: Option<AngleIn>,
    /// Spot: falloff exponent (default 1).
    pub falloff: Option<Num>,
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
        let f: LightsFileIn = toml::from_str(&text)
            .map_err(|e| toml_error(&path.display().to_string(), &text, &e))?;
        if f.light.is_empty() {
            return Err(Error::why(
                "lights",
                ErrMsg::NoLightTable(path.display().to_string()),
            ));
        }
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

fn ev<T: Scalar>(field: &str, n: &Num) -> Result<T> {
    input::eval(field, &n.0)
}

fn ev3<T: Scalar>(field: &str, v: &Vec3In) -> Result<V3<T>> {
    Ok(v3(ev(field, &v[0])?, ev(field, &v[1])?, ev(field, &v[2])?))
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
                    .res("V", Val::vec3(&v))
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
        (None, false) => file
            .light
            .iter()
            .enumerate()
            .map(|(i, l)| light::<T>(l, &format!("{lights_prefix}[{i}]"), position, tr))
            .collect(),
        (Some(_), false) => Err(Error::why(f("light"), Twice::Light)),
        (None, true) => Err(Error::why(f("light"), ErrMsg::NoLight)),
    }
}

/// One `[[light]]` into a validated [`Light`].
pub fn light<T: Scalar>(
    l: &LightIn,
    field: &str,
    point: &V3<T>,
    tr: &mut impl Trace,
) -> Result<Light<T>> {
    let k = |s: &str| format!("{field}.{s}");
    let kind = match l.kind {
        LightType::Directional => {
            forbid(l, &k, &["position", "axis", "range", "attenuation"])?;
            let d = need(l, &k, &l.direction, "direction")?;
            LightKind::Directional {
                dir: lighting::unit("L", &k("direction"), &d, tr)?,
            }
        }
        LightType::Point | LightType::Spot => {
            forbid(l, &k, &["direction"])?;
            let pos = need(l, &k, &l.position, "position")?;
            if pos == *point {
                return Err(Error::why(k("position"), ErrMsg::LightAtPoint));
            }
            if l.kind == LightType::Point {
                forbid(l, &k, &["axis", "theta", "phi", "falloff"])?;
                LightKind::Point { pos }
            } else {
                spot(l, &k, pos, tr)?
            }
        }
    };
    let att = match &l.attenuation {
        Some(a) => {
            let a = ev3::<T>(&k("attenuation"), a)?;
            [a[0].clone(), a[1].clone(), a[2].clone()]
        }
        None => [T::one(), T::zero(), T::zero()],
    };
    let out = Light {
        kind,
        ambient: opt_rgb(&k("ambient"), &l.ambient, gray(T::one()))?,
        diffuse: opt_rgb(&k("diffuse"), &l.diffuse, gray(T::one()))?,
        specular: opt_rgb(&k("specular"), &l.specular, gray(T::one()))?,
        attenuation: att,
        range: l.range.as_ref().map(|n| ev(&k("range"), n)).transpose()?,
    };
    out.validate(field)?;
    Ok(out)
}

/// A spot light at `pos`: its unit axis, cone angles theta and phi (full
/// angles, degrees) and falloff (1 unless given).
fn spot<T: Scalar>(
    l: &LightIn,
    k: &dyn Fn(&str) -> String,
    pos: V3<T>,
    tr: &mut impl Trace,
) -> Result<LightKind<T>> {
    let axis = need(l, k, &l.axis, "axis")?;
    let axis = lighting::unit("axis", &k("axis"), &axis, tr)?;
    let angle = |a: &Option<AngleIn>, key: &str| -> Result<T> {
        let a = a
            .as_ref()
            .ok_or_else(|| Error::why(k(key), ErrMsg::SpotNeeds(key.to_string())))?;
        a.0.degrees::<T>().map_err(|m| Error::why(k(key), m))
    };
    Ok(LightKind::Spot {
        pos,
        dir: axis,
        theta: angle(&l.theta, "theta")?,
        phi: angle(&l.phi, "phi")?,
        falloff: l
            .falloff
            .as_ref()
            .map(|n| ev(&k("falloff"), n))
            .transpose()?
            .unwrap_or_else(T::one),
    })
}

/// A vector the light's type needs (`key` names it).
fn need<T: Scalar>(
    l: &LightIn,
    k: &dyn Fn(&str) -> String,
    v: &Option<Vec3In>,
    key: &str,
) -> Result<V3<T>> {
    let v = v.as_ref().ok_or_else(|| {
        let kind = format!("{:?}", l.kind).to_lowercase();
        Error::why(k(key), ErrMsg::Needs(Thing::Light(kind), key.to_string()))
    })?;
    ev3(&k(key), v)
}

/// Refuses the first of `keys` that is given but does not apply to the
/// light's type.
fn forbid(l: &LightIn, k: &dyn Fn(&str) -> String, keys: &[&str]) -> Result<()> {
    let given = |key: &str| match key {
        "position" => l.position.is_some(),
        "direction" => l.direction.is_some(),
        "axis" => l.axis.is_some(),
        "range" => l.range.is_some(),
        "attenuation" => l.attenuation.is_some(),
        "theta" => l.theta.is_some(),
        "phi" => l.phi.is_some(),
        _ => l.falloff.is_some(),
    };
    match keys.iter().find(|key| given(key)) {
        Some(key) => Err(Error::why(
            k(key),
            ErrMsg::NotApplicable(key.to_string(), format!("{:?}", l.kind).to_lowercase()),
        )),
        None => Ok(()),
    }
}

fn rgb_val<T: Scalar>(c: &Rgb<T>) -> Val {
    Val::List(c.iter().map(Val::num).collect())
}

fn opt_vec<T: Scalar>(v: &Option<V3<T>>) -> Val {
    v.as_ref().map(Val::vec3).unwrap_or(Val::Null)
}

fn opt_num<T: Scalar>(v: &Option<T>) -> Val {
    v.as_ref().map(Val::num).unwrap_or(Val::Null)
}

/// Runs the set-up (steps into `rec`) and returns the docs/spec.md §3 shade keys:
/// `color`, `unclamped`, `ambient`, `diffuse`, `specular`, `R`, `H` (Blinn),
/// `cos_alpha`, `cos_beta` — per light (lists) when there are several, with
/// `lights` (attenuation, spot, in range) for lights from a file.
pub fn run<T: Scalar>(s: &Setup<T>, rec: &mut Recorder) -> Vec<(String, Val)> {
    run_with(s, &lighting::Rules::default(), rec)
}

/// [`run`] under the given lighting rules (the mistake catalog's way in).
pub fn run_with<T: Scalar>(
    s: &Setup<T>,
    rules: &lighting::Rules<T>,
    rec: &mut Recorder,
) -> Vec<(String, Val)> {
    let m = &s.material;
    rec.step(|| material_step(m));
    let sh = lighting::shade_with_rules(m, &s.lights, &s.global_ambient, &s.surface, rules, rec);
    let mut out: Vec<(String, Val)> = vec![
        ("color".into(), rgb_val(&sh.color)),
        ("unclamped".into(), rgb_val(&sh.unclamped)),
        ("ambient".into(), rgb_val(&sh.ambient)),
        ("diffuse".into(), rgb_val(&sh.diffuse)),
        ("specular".into(), rgb_val(&sh.specular)),
    ];
    if sh.emissive.iter().any(|x| !x.is_zero_value()) {
        out.push(("emissive".into(), rgb_val(&sh.emissive)));
    }
    let blinn = m.model == Model::Blinn;
    if s.lights.len() == 1 {
        out.push(("R".into(), opt_vec(&sh.r)));
        if blinn {
            out.push(("H".into(), opt_vec(&sh.h)));
            out.push(("N_dot_H".into(), opt_num(&sh.cos_nh)));
        }
        out.push(("cos_alpha".into(), opt_num(&sh.cos_alpha)));
        out.push(("cos_beta".into(), opt_num(&sh.cos_beta)));
    } else {
        out.extend(vectors_per_light(s, &sh.view, rules));
    }
    if !s.text_light {
        let per = (0..s.lights.len()).map(|i| light_factors(s, i, &sh.view));
        out.push(("lights".into(), Val::List(per.collect())));
    }
    out
}

/// The step that shows the material and the model.
fn material_step<T: Scalar>(m: &Material<T>) -> Step {
    Step::new(Msg::Material, format!("model = {}", m.model.name()))
        .val("ka", Val::num(&m.ka))
        .val("kd", Val::num(&m.kd))
        .val("ks", Val::num(&m.ks))
        .val("n", Val::num(&m.shininess))
        .val("Cs", rgb_val(&m.color))
        .val("Cspecular", rgb_val(&m.specular))
        .note(
            if m.ka == T::one() && m.kd == T::one() && m.ks == T::one() {
                Msg::MaterialD3d
            } else {
                Msg::MaterialText
            },
        )
}

/// With several lights: R (H, N·H), cos α and cos β as lists, one entry per
/// light (recomputed without steps: they are recorded already).
fn vectors_per_light<T: Scalar>(
    s: &Setup<T>,
    view: &V3<T>,
    rules: &lighting::Rules<T>,
) -> Vec<(String, Val)> {
    let m = &s.material;
    let n = s.lights.len();
    let terms: Vec<Option<LightTerm<T>>> = (s.lights.iter().enumerate())
        .map(|(i, l)| {
            let at = (i, n);
            lighting::light_term_with(m, l, at, &s.surface, view, true, rules, &mut NoTrace)
        })
        .collect();
    let list = |f: &dyn Fn(&LightTerm<T>) -> Val| {
        Val::List(
            terms
                .iter()
                .map(|t| t.as_ref().map(f).unwrap_or(Val::Null))
                .collect(),
        )
    };
    let mut out = vec![("R".to_string(), list(&|t| opt_vec(&t.r)))];
    if m.model == Model::Blinn {
        out.push(("H".into(), list(&|t| opt_vec(&t.h))));
        out.push(("N_dot_H".into(), list(&|t| opt_num(&t.cos_nh))));
    }
    out.push(("cos_alpha".into(), list(&|t| Val::num(&t.cos_alpha))));
    out.push(("cos_beta".into(), list(&|t| opt_num(&t.cos_beta))));
    out
}

/// Light i's range, distance, attenuation and spot factor.
fn light_factors<T: Scalar>(s: &Setup<T>, i: usize, view: &V3<T>) -> Val {
    let (m, l, n) = (&s.material, &s.lights[i], s.lights.len());
    let rules = &lighting::TextRules;
    let t = lighting::light_term_with(m, l, (i, n), &s.surface, view, false, rules, &mut NoTrace);
    let or_null = |f: &dyn Fn(&LightTerm<T>) -> Val| t.as_ref().map(f).unwrap_or(Val::Null);
    Val::Map(vec![
        ("in_range".into(), Val::Bool(t.is_some())),
        ("distance".into(), or_null(&|t| opt_num(&t.distance))),
        ("attenuation".into(), or_null(&|t| Val::num(&t.attenuation))),
        ("spot".into(), or_null(&|t| Val::num(&t.spot))),
    ])
}
