//! Lighting at one surface point: the text's five optical-view models
//! (diffuse, specular, ambient, Lambert, Phong) and Direct3D 9's
//! Blinn–Phong with directional, point and spot lights.
//!
//! All vectors are in grafika's right-handed eye space (+z toward the
//! viewer) and unit length where they are directions: `L` points to the
//! light, `V` to the viewer, `N` is the surface normal.
//!
//! ```text
//! R = 2N(L·N) − L,   cos α = L·N,   cos β = R·V  (Blinn: N·H)
//! ambient  = ka · Ca ⊙ (Ga + Σᵢ Attᵢ·Spotᵢ·Laᵢ)
//! diffuse  = kd · Cs ⊙ Σᵢ Attᵢ·Spotᵢ·Ldᵢ · max(cos αᵢ, 0)
//! specular = ks · Csp ⊙ Σᵢ Attᵢ·Spotᵢ·Lsᵢ · max(cos βᵢ, 0)ⁿ
//! color    = clamp₀₁(ambient + diffuse + specular + emissive)
//! ```
//!
//! **How the text and Direct3D agree.** The text's model is Direct3D's
//! equation with one white directional light (La = Ld = Ls = white,
//! Att = Spot = 1), no global ambient (Ga = 0), and the material colors
//! Direct3D would use being `ka·Cs`, `kd·Cs` and `ks·white` — the text's
//! "Iₐ = Iₛ kₐ" takes the ambient intensity from the light source, so the
//! light carries the ambient. With those values every sum above has one
//! term equal to 1 and the formulas reduce to docs/spec.md §1 exactly. A Direct3D
//! material (colors given) uses ka = kd = ks = 1: its colors already carry
//! the coefficients.
//!
//! [`shade`] is the renderer's per-pixel function: no allocation, nothing
//! built for explanation unless the recorder listens, the specular term
//! skipped when it cannot contribute, and lights out of range never
//! evaluated. Inputs are checked once beforehand ([`Material::validate`],
//! [`Light::validate`], [`unit`](fn@unit)).

use crate::error::{Error, Result};
use crate::msg::{LightPart, Msg, Term};
use crate::num::vec::{normalize, sub, v3, V3};
use crate::num::Scalar;
use crate::stages::trace::{Name, Step, Subst, Trace, Val};

mod light;
pub use light::{light_term_with, spot_factor};

/// The lighting model (`--model`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Model {
    /// Ambient only: ka·Cs.
    Ambient,
    /// Diffuse scattering only: kd·max(cos α, 0)·Cs.
    Diffuse,
    /// Specular reflection only: ks·max(cos β, 0)ⁿ·white.
    Specular,
    /// Lambert's law: diffuse + ambient.
    Lambert,
    /// The Phong model: diffuse + specular + ambient (the text's default).
    #[default]
    Phong,
    /// Blinn–Phong (Direct3D 9): the specular term uses N·H.
    Blinn,
}

/// The base of a model's highlight max(·, 0)ⁿ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Highlight {
    /// The text's cos β = R·V, R = 2N(L·N) − L.
    RDotV,
    /// Blinn–Phong's N·H, H = norm(L + V) (Direct3D 9).
    NDotH,
}

impl Model {
    /// Every model, in `--model`'s order.
    pub fn all() -> Vec<Model> {
        std::iter::successors(Some(Model::Ambient), |m| m.next()).collect()
    }

    /// The model after this one: an exhaustive match, so a new model is
    /// listed as soon as it compiles.
    fn next(self) -> Option<Model> {
        match self {
            Model::Ambient => Some(Model::Diffuse),
            Model::Diffuse => Some(Model::Specular),
            Model::Specular => Some(Model::Lambert),
            Model::Lambert => Some(Model::Phong),
            Model::Phong => Some(Model::Blinn),
            Model::Blinn => None,
        }
    }

    /// The base of the model's highlight (where it has a specular term):
    /// R·V, or N·H for Blinn–Phong. The stage computes it and the
    /// results show its values (H and N·H) by this, so a new model says
    /// here which it uses.
    pub fn highlight(self) -> Highlight {
        match self {
            Model::Blinn => Highlight::NDotH,
            Model::Ambient | Model::Diffuse | Model::Specular | Model::Lambert | Model::Phong => {
                Highlight::RDotV
            }
        }
    }

    /// Which terms the model adds: (ambient, diffuse, specular).
    pub fn terms(self) -> (bool, bool, bool) {
        match self {
            Model::Ambient => (true, false, false),
            Model::Diffuse => (false, true, false),
            Model::Specular => (false, false, true),
            Model::Lambert => (true, true, false),
            Model::Phong | Model::Blinn => (true, true, true),
        }
    }
    /// The name as `--model` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Model::Ambient => "ambient",
            Model::Diffuse => "diffuse",
            Model::Specular => "specular",
            Model::Lambert => "lambert",
            Model::Phong => "phong",
            Model::Blinn => "blinn",
        }
    }
}

/// An RGB color, each channel in [0, 1].
pub type Rgb<T> = [T; 3];

/// (c, c, c).
pub fn gray<T: Scalar>(c: T) -> Rgb<T> {
    [c.clone(), c.clone(), c]
}

/// The material at the point.
#[derive(Clone, Debug, PartialEq)]
pub struct Material<T> {
    /// The lighting model.
    pub model: Model,
    /// Ambient coefficient ka.
    pub ka: T,
    /// Diffuse coefficient kd.
    pub kd: T,
    /// Specular coefficient ks.
    pub ks: T,
    /// Specular exponent n (Direct3D's Power); integers use exact powers.
    pub shininess: T,
    /// Cs, the surface color (the diffuse color, and the ambient one unless
    /// `ambient_color` is set).
    pub color: Rgb<T>,
    /// The specular color (the text's Cwhite).
    pub specular: Rgb<T>,
    /// The emissive color, added unlit (Direct3D's Ce; black in the text).
    pub emissive: Rgb<T>,
    /// Whether the specular term is on (Direct3D's D3DRS_SPECULARENABLE).
    pub specular_on: bool,
    /// Whether the specular term needs cos α > 0 (the usual rule); the
    /// text's code adds it even when the light is behind the surface.
    pub specular_requires_lit: bool,
    /// A separate ambient color Ca (Direct3D material); `None` = Cs.
    pub ambient_color: Option<Rgb<T>>,
}

impl<T: Scalar> Material<T> {
    /// The material at another precision, each number through f64 (exact
    /// from f32 and f64).
    pub fn cast<U: Scalar>(&self) -> Material<U> {
        let t = |x: &T| U::from_f64(x.to_f64());
        Material {
            model: self.model,
            ka: t(&self.ka),
            kd: t(&self.kd),
            ks: t(&self.ks),
            shininess: t(&self.shininess),
            color: self.color.each_ref().map(t),
            specular: self.specular.each_ref().map(t),
            emissive: self.emissive.each_ref().map(t),
            specular_on: self.specular_on,
            specular_requires_lit: self.specular_requires_lit,
            ambient_color: self.ambient_color.as_ref().map(|c| c.each_ref().map(t)),
        }
    }
    /// The text's material: Phong, ka = 0.4, kd = 0.6, ks = 0.7, n = 4,
    /// white specular, no emission.
    pub fn text_default(color: Rgb<T>) -> Self {
        let tenth = |k: i64| T::from_i64(k) / T::from_i64(10);
        Material {
            model: Model::Phong,
            ka: tenth(4),
            kd: tenth(6),
            ks: tenth(7),
            shininess: T::from_i64(4),
            color,
            specular: gray(T::one()),
            emissive: gray(T::zero()),
            specular_on: true,
            specular_requires_lit: false,
            ambient_color: None,
        }
    }

    /// Checks coefficients (≥ 0), shininess (≥ 0) and colors (in [0, 1]);
    /// field names are prefixed with `prefix` (`""`, `"shade."`).
    pub fn validate(&self, prefix: &str) -> Result<()> {
        for (k, v) in [
            ("ka", &self.ka),
            ("kd", &self.kd),
            ("ks", &self.ks),
            ("shininess", &self.shininess),
        ] {
            if !v.is_finite() || *v < T::zero() {
                return Err(Error::why(
                    format!("{prefix}{k}"),
                    crate::msg::ErrMsg::MustBe(crate::msg::Bound::NumberAtLeastZero, v.to_f64()),
                ));
            }
        }
        check_color(&format!("{prefix}color"), &self.color)?;
        check_color(&format!("{prefix}material.specular"), &self.specular)?;
        check_color(&format!("{prefix}material.emissive"), &self.emissive)?;
        if let Some(a) = &self.ambient_color {
            check_color(&format!("{prefix}material.ambient"), a)?;
        }
        Ok(())
    }
}

/// Errors unless every channel is in [0, 1].
pub fn check_color<T: Scalar>(field: &str, c: &Rgb<T>) -> Result<()> {
    for (ch, v) in crate::msg::Channel::RGB.into_iter().zip(c) {
        if !v.is_finite() || *v < T::zero() || *v > T::one() {
            return Err(Error::why(
                field,
                crate::msg::ErrMsg::Channel(ch, v.to_f64()),
            ));
        }
    }
    Ok(())
}

/// What kind of light, and where.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind<T> {
    /// Infinitely far: `dir` is the unit vector TO the light (the text's L).
    Directional {
        /// Unit vector toward the light.
        dir: V3<T>,
    },
    /// At a point (eye space), shining in every direction.
    Point {
        /// Position of the light.
        pos: V3<T>,
    },
    /// At a point, shining along `dir` (unit, from the light outward —
    /// Direct3D's Direction) in a cone: full inner angle `theta`, full outer
    /// angle `phi` (degrees; halved in the formula), `falloff` between.
    Spot {
        /// Position of the light.
        pos: V3<T>,
        /// Unit axis of the cone, pointing away from the light.
        dir: V3<T>,
        /// Full angle of the inner cone (degrees).
        theta: T,
        /// Full angle of the outer cone (degrees).
        phi: T,
        /// Exponent of the penumbra falloff.
        falloff: T,
    },
}

/// A light and its colors.
#[derive(Clone, Debug, PartialEq)]
pub struct Light<T> {
    /// Kind and geometry.
    pub kind: LightKind<T>,
    /// La.
    pub ambient: Rgb<T>,
    /// Ld.
    pub diffuse: Rgb<T>,
    /// Ls.
    pub specular: Rgb<T>,
    /// a0, a1, a2 of Att = 1/(a0 + a1·d + a2·d²) (point and spot lights).
    pub attenuation: [T; 3],
    /// Beyond this distance the light does nothing (point and spot lights).
    pub range: Option<T>,
}

impl<T: Scalar> Light<T> {
    /// The light at another precision, each number through f64 (exact from
    /// f32 and f64).
    pub fn cast<U: Scalar>(&self) -> Light<U> {
        let t = |x: &T| U::from_f64(x.to_f64());
        let v = |a: &V3<T>| v3(t(&a[0]), t(&a[1]), t(&a[2]));
        Light {
            kind: match &self.kind {
                LightKind::Directional { dir } => LightKind::Directional { dir: v(dir) },
                LightKind::Point { pos } => LightKind::Point { pos: v(pos) },
                LightKind::Spot {
                    pos,
                    dir,
                    theta,
                    phi,
                    falloff,
                } => LightKind::Spot {
                    pos: v(pos),
                    dir: v(dir),
                    theta: t(theta),
                    phi: t(phi),
                    falloff: t(falloff),
                },
            },
            ambient: self.ambient.each_ref().map(t),
            diffuse: self.diffuse.each_ref().map(t),
            specular: self.specular.each_ref().map(t),
            attenuation: self.attenuation.each_ref().map(t),
            range: self.range.as_ref().map(t),
        }
    }
    /// The text's light: white, directional, along (0, 0, 1).
    pub fn text_default() -> Self {
        Light::directional(v3(T::zero(), T::zero(), T::one()))
    }

    /// A white directional light toward unit `dir`.
    pub fn directional(dir: V3<T>) -> Self {
        Light {
            kind: LightKind::Directional { dir },
            ambient: gray(T::one()),
            diffuse: gray(T::one()),
            specular: gray(T::one()),
            attenuation: [T::one(), T::zero(), T::zero()],
            range: None,
        }
    }

    /// Checks colors, attenuation (≥ 0, not all zero), range (> 0) and the
    /// spot cone (0 ≤ θ ≤ φ ≤ 180°, falloff ≥ 0); `field` names the light.
    pub fn validate(&self, field: &str) -> Result<()> {
        check_color(&format!("{field}.ambient"), &self.ambient)?;
        check_color(&format!("{field}.diffuse"), &self.diffuse)?;
        check_color(&format!("{field}.specular"), &self.specular)?;
        let a = &self.attenuation;
        if a.iter().any(|x| !x.is_finite() || *x < T::zero()) || a.iter().all(|x| x.is_zero_value())
        {
            return Err(Error::why(
                format!("{field}.attenuation"),
                crate::msg::ErrMsg::Attenuation(a[0].to_f64(), a[1].to_f64(), a[2].to_f64()),
            ));
        }
        if let Some(r) = &self.range {
            if *r <= T::zero() {
                return Err(Error::why(
                    format!("{field}.range"),
                    crate::msg::ErrMsg::MustBe(crate::msg::Bound::AboveZero, r.to_f64()),
                ));
            }
        }
        if let LightKind::Spot {
            theta,
            phi,
            falloff,
            ..
        } = &self.kind
        {
            let full = T::from_i64(180);
            if *theta < T::zero() || *theta > *phi || *phi > full {
                return Err(Error::why(
                    format!("{field}.theta"),
                    crate::msg::ErrMsg::Cones(theta.to_f64(), phi.to_f64()),
                ));
            }
            if *falloff < T::zero() {
                return Err(Error::why(
                    format!("{field}.falloff"),
                    crate::msg::ErrMsg::MustBe(crate::msg::Bound::AtLeastZero, falloff.to_f64()),
                ));
            }
        }
        Ok(())
    }
}

/// The surface point.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface<T> {
    /// Unit normal N.
    pub normal: V3<T>,
    /// Unit vector to the viewer V (used when `camera` is `None`).
    pub view: V3<T>,
    /// Position in eye space (for point and spot lights, and the local viewer).
    pub position: V3<T>,
    /// Camera position: `Some` = local viewer, V = norm(Cp − Vp).
    pub camera: Option<V3<T>>,
}

/// What one light does at the point.
#[derive(Clone, Debug, PartialEq)]
pub struct LightTerm<T> {
    /// Unit vector to the light, L.
    pub l: V3<T>,
    /// Distance to the light (point and spot lights).
    pub distance: Option<T>,
    /// Attenuation factor.
    pub attenuation: T,
    /// Spot factor.
    pub spot: T,
    /// cos α = L·N.
    pub cos_alpha: T,
    /// R = 2N(L·N) − L (when the specular term is evaluated or explained).
    pub r: Option<V3<T>>,
    /// cos β = R·V.
    pub cos_beta: Option<T>,
    /// Half vector H (Blinn).
    pub h: Option<V3<T>>,
    /// N·H (Blinn).
    pub cos_nh: Option<T>,
    /// max(cos, 0)ⁿ of the model's specular cosine (0 when skipped).
    pub highlight: T,
}

/// The lighting result.
#[derive(Clone, Debug, PartialEq)]
pub struct Shaded<T> {
    /// The final color, each channel clamped to [0, 1].
    pub color: Rgb<T>,
    /// ambient + diffuse + specular + emissive before clamping.
    pub unclamped: Rgb<T>,
    /// The ambient term.
    pub ambient: Rgb<T>,
    /// The diffuse term.
    pub diffuse: Rgb<T>,
    /// The specular term.
    pub specular: Rgb<T>,
    /// The emissive term.
    pub emissive: Rgb<T>,
    /// The viewer direction used.
    pub view: V3<T>,
    /// R of the first light evaluated.
    pub r: Option<V3<T>>,
    /// H of the first light evaluated (Blinn).
    pub h: Option<V3<T>>,
    /// cos α of the first light evaluated.
    pub cos_alpha: Option<T>,
    /// cos β = R·V of the first light evaluated.
    pub cos_beta: Option<T>,
    /// N·H of the first light evaluated (Blinn).
    pub cos_nh: Option<T>,
    /// How many lights were in range.
    pub lights_used: usize,
}

/// The unit vector of `v`, recorded as a step; the zero vector is an error
/// naming `field`.
pub fn unit<T: Scalar>(name: &str, field: &str, v: &V3<T>, tr: &mut impl Trace) -> Result<V3<T>> {
    let (u, len) =
        normalize(v).ok_or_else(|| Error::said(field, Msg::ErrZeroUnit(name.to_string())))?;
    tr.step(|| {
        let s = Step::new(
            Msg::UnitVector(name.to_string()),
            format!("{name} = v/|v|,  |v| = √(v₀² + v₁² + v₂²)"),
        )
        .val(Name::math("v"), Val::vec3(v))
        .val(Name::math("|v|"), Val::length(v, &len))
        .sub(Name::math("|v|"), Subst::norm(v))
        .res(Name::math(name), Val::vec3(&u))
        .sub(
            Name::math(name),
            match len == T::one() {
                true => Subst::default(),
                false => Subst::quotient(Val::vec3(v), Val::length(v, &len)),
            },
        );
        if len == T::one() {
            s.note(Msg::AlreadyUnit)
        } else {
            s
        }
    });
    Ok(u)
}

/// xⁿ: exact repeated multiplication for a whole n ≥ 0, otherwise through
/// f64, marked approximate in exact arithmetic (Direct3D's Power and
/// falloff may be fractional).
#[inline(always)]
pub fn pow<T: Scalar>(x: &T, n: &T) -> T {
    match n.as_whole() {
        Some(k) => x.powi(k),
        None => x.powf(n),
    }
}

/// max(x, 0) (per lane for a lane type).
#[inline(always)]
fn max0<T: Scalar>(x: &T) -> T {
    x.max_of(&T::zero())
}

fn listening<Tr: Trace>(_: &Tr) -> bool {
    Tr::ON
}

/// A step title, prefixed "Light i: " when there are several lights.
fn label(at: (usize, usize), what: LightPart) -> Msg {
    Msg::Light(at, what)
}

/// Two rules of the lighting stage, as replaceable functions: the text's
/// (the default) or, for the mistake catalog (`diagnose`), one done the way
/// a student might get it wrong — so that a mistaken answer is reproduced by
/// re-running this stage, not by a second copy of its math.
#[derive(Clone, Copy)]
pub struct Rules<T> {
    /// R from N, L and 2(L·N): the text's R = 2N(L·N) − L.
    pub reflect: fn(&V3<T>, &V3<T>, &T) -> V3<T>,
    /// The base of the highlight power: the text's max(cos β, 0) (N·H for Blinn).
    pub highlight_base: fn(&T) -> T,
}

impl<T: Scalar> Default for Rules<T> {
    fn default() -> Self {
        Rules {
            reflect: text_reflect,
            highlight_base: max0,
        }
    }
}

/// The text's R = 2N(L·N) − L, from N, L and 2(L·N).
#[inline(always)]
fn text_reflect<T: Scalar>(n: &V3<T>, l: &V3<T>, two_ln: &T) -> V3<T> {
    sub(&crate::num::vec::scale(n, two_ln), l)
}

/// A value the lighting stage computes on its way to the colour, which a
/// rule set may replace by a given one ([`RuleSet::given_num`] and its
/// siblings): named by its result key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// cos α = L·N.
    CosAlpha,
    /// R = 2N(L·N) − L.
    R,
    /// cos β = R·V.
    CosBeta,
    /// The ambient term.
    Ambient,
    /// The diffuse term.
    Diffuse,
    /// The specular term.
    Specular,
    /// The sum of the terms before the clamp.
    Unclamped,
}

/// The two replaceable rules as a trait: [`Rules`] (functions chosen at run
/// time, for `diagnose`) or [`TextRules`] (the text's, known at compile
/// time, so the renderer's per-pixel call inlines them).
///
/// The `given_*` methods see each value of [`Part`] as the stage computes
/// it and return the one the stage goes on with: that value itself for
/// the text's rules (the default, which compiles away); a student's own
/// earlier answer for follow-through, so that the later values come from
/// this stage and not from a second copy of its formulas.
pub trait RuleSet<T> {
    /// R from N, L and 2(L·N).
    fn reflect(&self, n: &V3<T>, l: &V3<T>, two_ln: &T) -> V3<T>;
    /// The base of the highlight power.
    fn highlight_base(&self, cos: &T) -> T;
    /// A number of the stage (cos α, cos β), or the one given in its place.
    #[inline(always)]
    fn given_num(&self, _part: Part, computed: T) -> T {
        computed
    }
    /// A vector of the stage (R), or the one given in its place.
    #[inline(always)]
    fn given_vec(&self, _part: Part, computed: V3<T>) -> V3<T> {
        computed
    }
    /// A colour of the stage (a term, the sum), or the one given in its place.
    #[inline(always)]
    fn given_rgb(&self, _part: Part, computed: Rgb<T>) -> Rgb<T> {
        computed
    }
}

impl<T: Scalar> RuleSet<T> for Rules<T> {
    #[inline]
    fn reflect(&self, n: &V3<T>, l: &V3<T>, two_ln: &T) -> V3<T> {
        (self.reflect)(n, l, two_ln)
    }
    #[inline]
    fn highlight_base(&self, cos: &T) -> T {
        (self.highlight_base)(cos)
    }
}

/// The text's rules, the same functions [`Rules::default`] holds.
#[derive(Clone, Copy, Debug, Default)]
pub struct TextRules;

impl<T: Scalar> RuleSet<T> for TextRules {
    #[inline(always)]
    fn reflect(&self, n: &V3<T>, l: &V3<T>, two_ln: &T) -> V3<T> {
        text_reflect(n, l, two_ln)
    }
    #[inline(always)]
    fn highlight_base(&self, cos: &T) -> T {
        max0(cos)
    }
}

/// [f(0), f(1), f(2)], always inlined (the per-pixel path).
#[inline(always)]
fn per_channel<T>(mut f: impl FnMut(usize) -> T) -> Rgb<T> {
    [f(0), f(1), f(2)]
}

/// A colour as a value: its three channels.
pub fn rgb_val<T: Scalar>(c: &Rgb<T>) -> Val {
    Val::List(c.iter().map(Val::num).collect())
}

/// The lighting of one point by `lights`, with no global ambient.
///
/// See the module documentation for the formulas.
#[inline]
pub fn shade<T: Scalar>(
    mat: &Material<T>,
    lights: &[Light<T>],
    s: &Surface<T>,
    tr: &mut impl Trace,
) -> Shaded<T> {
    shade_with_ambient(mat, lights, &gray(T::zero()), s, tr)
}

/// [`shade`] with a global ambient light Ga (Direct3D's D3DRS_AMBIENT).
#[inline]
pub fn shade_with_ambient<T: Scalar>(
    mat: &Material<T>,
    lights: &[Light<T>],
    global_ambient: &Rgb<T>,
    s: &Surface<T>,
    tr: &mut impl Trace,
) -> Shaded<T> {
    shade_with_rules(mat, lights, global_ambient, s, &TextRules, tr)
}

/// The color alone of [`shade`], nothing recorded: the renderer's
/// per-pixel call. The same computation as [`shade`] (one body,
/// [`shade_with_rules`]), inlined into the caller so that the parts of the report
/// nobody reads (R, H, the separate terms) are never built.
#[inline(always)]
pub fn shade_color<T: Scalar>(mat: &Material<T>, lights: &[Light<T>], s: &Surface<T>) -> Rgb<T> {
    shade_with_rules(
        mat,
        lights,
        &gray(T::zero()),
        s,
        &TextRules,
        &mut crate::stages::trace::NoTrace,
    )
    .color
}

/// [`shade_with_ambient`] under the given rules ([`Rules`] or [`TextRules`]):
/// the body of every `shade*` function, always inlined into its caller.
#[inline(always)]
pub fn shade_with_rules<T: Scalar, R: RuleSet<T>>(
    mat: &Material<T>,
    lights: &[Light<T>],
    global_ambient: &Rgb<T>,
    s: &Surface<T>,
    rules: &R,
    tr: &mut impl Trace,
) -> Shaded<T> {
    let (want_a, want_d, want_s) = mat.model.terms();
    let want_spec = want_s && mat.specular_on && !mat.ks.is_zero_value();
    let v = view_vector(s, tr);
    let (sums, first, used) = sum_lights(mat, lights, global_ambient, s, &v, want_spec, rules, tr);
    let [sum_a, sum_d, sum_s] = &sums;

    // The three terms, the sum and the clamp
    let ca = mat.ambient_color.as_ref().unwrap_or(&mat.color);
    let ambient = rules.given_rgb(Part::Ambient, term(want_a, &mat.ka, sum_a, ca));
    let diffuse = rules.given_rgb(Part::Diffuse, term(want_d, &mat.kd, sum_d, &mat.color));
    let specular = term(want_spec, &mat.ks, sum_s, &mat.specular);
    let specular = rules.given_rgb(Part::Specular, specular);
    let emissive = mat.emissive.clone();
    let unclamped: Rgb<T> = per_channel(|c| {
        ambient[c].clone() + diffuse[c].clone() + specular[c].clone() + emissive[c].clone()
    });
    let unclamped = rules.given_rgb(Part::Unclamped, unclamped);
    let color: Rgb<T> = per_channel(|c| {
        let x = &unclamped[c];
        // min(x, 1), then max(·, 0): 1 above, 0 below (and for NaN).
        max0(&x.min_of(&T::one()))
    });
    let text = listening(tr) && is_text_model(mat, lights, global_ambient);
    if text {
        let on = [want_a, want_d, want_spec];
        let results = [&ambient, &diffuse, &specular];
        for (i, result) in results.into_iter().enumerate() {
            tr.step(|| text_term_step(mat, i, on[i], first.as_ref(), result));
        }
    } else if listening(tr) {
        let worked = worked_sums(mat, lights, global_ambient, s, &v, want_spec, rules);
        record_totals(
            mat,
            (want_a, want_d, want_spec),
            ([sum_a, sum_d, sum_s], worked),
            [&ambient, &diffuse, &specular],
            global_ambient,
            lights,
            tr,
        );
    }
    let terms = [&ambient, &diffuse, &specular, &emissive];
    tr.step(|| sum_step(mat.model, text, terms, &unclamped));
    tr.step(|| clamp_step(&unclamped, &color));

    let (r, h, cos_alpha, cos_beta, cos_nh) = match first {
        Some(t) => (t.r, t.h, Some(t.cos_alpha), t.cos_beta, t.cos_nh),
        None => (None, None, None, None, None),
    };
    Shaded {
        color,
        unclamped,
        ambient,
        diffuse,
        specular,
        emissive,
        view: v,
        r,
        h,
        cos_alpha,
        cos_beta,
        cos_nh,
        lights_used: used,
    }
}

/// Each light's contribution summed per channel: ambient Σ Lambientᵢ·fᵢ
/// (from Ga), diffuse Σ Ldiffuseᵢ·fᵢ·max(cos αᵢ, 0), specular
/// Σ Lspecularᵢ·fᵢ·highlightᵢ, with fᵢ = attenuation·spot; also the first
/// light's term (for R, H, cos α, cos β) and how many lights reached the point.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn sum_lights<T: Scalar, R: RuleSet<T>>(
    mat: &Material<T>,
    lights: &[Light<T>],
    global_ambient: &Rgb<T>,
    s: &Surface<T>,
    v: &V3<T>,
    want_spec: bool,
    rules: &R,
    tr: &mut impl Trace,
) -> ([Rgb<T>; 3], Option<LightTerm<T>>, usize) {
    let (mut sum_a, mut sum_d, mut sum_s) =
        (global_ambient.clone(), gray(T::zero()), gray(T::zero()));
    let mut first: Option<LightTerm<T>> = None;
    let mut used = 0;
    for (i, light) in lights.iter().enumerate() {
        let Some(t) =
            light::light_term_with(mat, light, (i, lights.len()), s, v, want_spec, rules, tr)
        else {
            continue;
        };
        used += 1;
        let f = t.attenuation.clone() * t.spot.clone();
        let fd = f.clone() * max0(&t.cos_alpha);
        let fs = f.clone() * t.highlight.clone();
        for c in 0..3 {
            sum_a[c] += light.ambient[c].clone() * f.clone();
            sum_d[c] += light.diffuse[c].clone() * fd.clone();
            sum_s[c] += light.specular[c].clone() * fs.clone();
        }
        if first.is_none() {
            first = Some(t);
        }
    }
    ([sum_a, sum_d, sum_s], first, used)
}

/// How [`sum_lights`] summed, light by light, for the steps: `Ga +
/// Att·Spot·La + …`, `Att·Spot·Ld·max(cos α, 0) + …` and
/// `Att·Spot·Ls·highlight + …`. Each light's term is recomputed without
/// steps (they are recorded already); the renderer, which never explains,
/// never calls it.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn worked_sums<T: Scalar, R: RuleSet<T>>(
    mat: &Material<T>,
    lights: &[Light<T>],
    global_ambient: &Rgb<T>,
    s: &Surface<T>,
    v: &V3<T>,
    want_spec: bool,
    rules: &R,
) -> [Subst; 3] {
    let mut forms: [Vec<&str>; 3] = [vec!["{}"], vec![], vec![]];
    let mut args: [Vec<Val>; 3] = [vec![rgb_val(global_ambient)], vec![], vec![]];
    let n = lights.len();
    for (i, light) in lights.iter().enumerate() {
        let mut quiet = crate::stages::trace::NoTrace;
        let at = (i, n);
        let Some(t) = light::light_term_with(mat, light, at, s, v, want_spec, rules, &mut quiet)
        else {
            continue;
        };
        let af = [&t.attenuation, &t.spot].map(Val::num);
        let last = [None, Some(max0(&t.cos_alpha)), Some(t.highlight.clone())];
        let colours = [&light.ambient, &light.diffuse, &light.specular];
        for (k, col) in colours.into_iter().enumerate() {
            forms[k].push(if k == 0 {
                "{}·{}·{}"
            } else {
                "{}·{}·{}·{}"
            });
            args[k].extend(af.iter().cloned().chain([rgb_val(col)]));
            args[k].extend(last[k].as_ref().map(Val::num));
        }
    }
    [0, 1, 2].map(|k| Subst::new(forms[k].join(" + "), std::mem::take(&mut args[k])))
}

/// k·sum⊙col, or zero when the model has no such term.
#[inline(always)]
fn term<T: Scalar>(on: bool, k: &T, sum: &Rgb<T>, col: &Rgb<T>) -> Rgb<T> {
    per_channel(|c| {
        if on {
            k.clone() * sum[c].clone() * col[c].clone()
        } else {
            T::zero()
        }
    })
}

/// The step of the sum: Direct3D's C = ambient + diffuse + specular +
/// emissive, or, for the text's model (`text`), the terms it has, as the
/// text writes them: Phong's C = Cs·(kd·max(cos α, 0) + ka) +
/// Cwhite·ks·max(cos β, 0)ⁿ, Lambert's C = Cs·(kd·max(cos α, 0) + ka).
fn sum_step<T: Scalar>(model: Model, text: bool, terms: [&Rgb<T>; 4], unclamped: &Rgb<T>) -> Step {
    let (a, d, s) = model.terms();
    let names = ["ambient", "diffuse", "specular", "emissive"];
    let on = if text { [a, d, s, false] } else { [true; 4] };
    let shown: Vec<usize> = (0..4).filter(|&i| on[i]).collect();
    let sum = shown
        .iter()
        .map(|&i| names[i])
        .collect::<Vec<_>>()
        .join(" + ");
    let texts = match model {
        Model::Phong => "Cs·(kd·max(cos α, 0) + ka) + Cwhite·ks·max(cos β, 0)ⁿ = ",
        Model::Lambert => "Cs·(kd·max(cos α, 0) + ka) = ",
        Model::Ambient | Model::Diffuse | Model::Specular | Model::Blinn => "",
    };
    let formula = format!("C = {}{sum}", if text { texts } else { "" });
    let step = shown
        .iter()
        .fold(Step::new(Msg::SumOfTerms, formula), |st, &i| {
            st.val(Name::math(names[i]), rgb_val(terms[i]))
        });
    let form = vec!["{}"; shown.len()].join(" + ");
    let args = shown.iter().map(|&i| rgb_val(terms[i])).collect();
    let step = step.res(Name::Unclamped, rgb_val(unclamped));
    match shown.len() {
        1 => step,
        _ => step.sub(Name::Unclamped, Subst::new(form, args)),
    }
}

/// Whether the lighting is the text's own model: one of its five models
/// with its single white directional light, no global ambient, and a
/// material of the text's (white specular, no Direct3D ambient colour, no
/// emission). Its steps are then written in the text's notation.
pub fn is_text_model<T: Scalar>(mat: &Material<T>, lights: &[Light<T>], ga: &Rgb<T>) -> bool {
    let text_model = match mat.model {
        Model::Ambient | Model::Diffuse | Model::Specular | Model::Lambert | Model::Phong => true,
        Model::Blinn => false,
    };
    text_model
        && is_text_setting(lights, ga)
        && mat.ambient_color.is_none()
        && mat.emissive.iter().all(|x| x.is_zero_value())
        && mat.specular.iter().all(|x| *x == T::one())
}

/// One term of the text's model (`i`: ambient, diffuse, specular) as the
/// text writes it: ka·Cs, kd·max(cos α, 0)·Cs, ks·max(cos β, 0)ⁿ·Cwhite
/// with its light's cos α and highlight (`lit`); a term the model does
/// not have is 0, and a skipped specular term too (`on` false).
fn text_term_step<T: Scalar>(
    mat: &Material<T>,
    i: usize,
    on: bool,
    lit: Option<&LightTerm<T>>,
    result: &Rgb<T>,
) -> Step {
    let (term, _, k, _, _, name) = TERMS[i];
    let step = Step::new(Msg::TermStep(term), "");
    if !on {
        let note = match mat.model.terms() {
            (_, _, true) if i == 2 => Msg::SpecularSkipped,
            _ => Msg::NoTermInModel(mat.model.name().to_string(), term),
        };
        return step.res(Name::math(name), rgb_val(result)).note(note);
    }
    let zero = T::zero();
    let (formula, coefficient, factor, colour) = match term {
        Term::Ambient => ("ambient = ka·Cs", &mat.ka, None, ("Cs", &mat.color)),
        Term::Diffuse => (
            "diffuse = kd·max(cos α, 0)·Cs",
            &mat.kd,
            Some((
                "max(cos α, 0)",
                lit.map_or(zero.clone(), |t| max0(&t.cos_alpha)),
            )),
            ("Cs", &mat.color),
        ),
        Term::Specular => (
            "specular = ks·max(cos β, 0)ⁿ·Cwhite",
            &mat.ks,
            Some(("max(cos β, 0)ⁿ", lit.map_or(zero, |t| t.highlight.clone()))),
            ("Cwhite", &mat.specular),
        ),
    };
    let mut args = vec![Val::num(coefficient)];
    let mut step = Step {
        formula: formula.into(),
        ..step
    }
    .val(Name::math(k), Val::num(coefficient));
    if let Some((f, x)) = factor {
        step = step.val(Name::math(f), Val::num(&x));
        args.push(Val::num(&x));
    }
    args.push(rgb_val(colour.1));
    let form = vec!["{}"; args.len()].join("·");
    step.val(Name::math(colour.0), rgb_val(colour.1))
        .res(Name::math(name), rgb_val(result))
        .sub(Name::math(name), Subst::new(form, args))
        .note(Msg::TextTerm(term))
}

/// The step of the clamp to [0, 1], each channel worked where one is
/// clamped.
fn clamp_step<T: Scalar>(unclamped: &Rgb<T>, color: &Rgb<T>) -> Step {
    let clipped = unclamped.iter().any(|x| *x > T::one() || *x < T::zero());
    let step = Step::new(Msg::Clamp, Msg::FClamp)
        .val(Name::math("C"), rgb_val(unclamped))
        .res(Name::Color, rgb_val(color));
    if clipped {
        let form = "(min(max({}{,}0){,}1){,}min(max({}{,}0){,}1){,}min(max({}{,}0){,}1))";
        step.sub(
            Name::Color,
            Subst::new(form, unclamped.iter().map(Val::num).collect()),
        )
        .note(Msg::Saturates)
    } else {
        step.note(Msg::InRange)
    }
}

/// V: the given unit view vector, or norm(Cp − Vp) with a local viewer.
#[inline(always)]
fn view_vector<T: Scalar>(s: &Surface<T>, tr: &mut impl Trace) -> V3<T> {
    let Some(cp) = &s.camera else {
        return s.view.clone();
    };
    let d = sub(cp, &s.position);
    let (v, len) = normalize(&d).unwrap_or_else(|| (s.view.clone(), T::one()));
    tr.step(|| {
        Step::new(Msg::ViewerLocal, "V = norm(Cp − Vp)")
            .val(Name::math("Cp"), Val::vec3(cp))
            .val(Name::math("Vp"), Val::vec3(&s.position))
            .val(Name::math("Cp − Vp"), Val::vec3(&d))
            .sub(Name::math("Cp − Vp"), Subst::difference(cp, &s.position))
            .val(Name::math("|Cp − Vp|"), Val::length(&d, &len))
            .sub(Name::math("|Cp − Vp|"), Subst::norm(&d))
            .res(Name::math("V"), Val::vec3(&v))
            .sub(
                Name::math("V"),
                Subst::quotient(Val::vec3(&d), Val::length(&d, &len)),
            )
    });
    v
}

/// Whether the lights are the text's: one white directional light, Ga = 0.
fn is_text_setting<T: Scalar>(lights: &[Light<T>], ga: &Rgb<T>) -> bool {
    let white = |c: &Rgb<T>| c.iter().all(|x| *x == T::one());
    matches!(lights, [l] if matches!(l.kind, LightKind::Directional { .. })
        && white(&l.ambient) && white(&l.diffuse) && white(&l.specular))
        && ga.iter().all(|x| x.is_zero_value())
}

/// A term worked per channel, k·sum·colour (`0.4·(1, 1, 1)·(1, 1, 0)`),
/// for a term the model has; nothing to work for one it does not (the
/// term is 0, and the note says why).
fn product(on: bool) -> &'static str {
    if on {
        "{}·{}·{}"
    } else {
        ""
    }
}

/// Records how the per-light sums (`worked` light by light) become the three
/// terms (called only when someone listens).
fn record_totals<T: Scalar>(
    mat: &Material<T>,
    on: (bool, bool, bool),
    (sums, worked): ([&Rgb<T>; 3], [Subst; 3]),
    [ra, rd, rs]: [&Rgb<T>; 3],
    ga: &Rgb<T>,
    lights: &[Light<T>],
    tr: &mut impl Trace,
) {
    let ca = mat.ambient_color.as_ref().unwrap_or(&mat.color);
    let one_note = |on: bool, what: Term| {
        if !on {
            Msg::NoTermInModel(mat.model.name().to_string(), what)
        } else if is_text_setting(lights, ga) {
            Msg::TextSetting
        } else {
            Msg::SummedInRange
        }
    };
    let coefficients = [&mat.ka, &mat.kd, &mat.ks];
    let colours = [ca, &mat.color, &mat.specular];
    let results = [ra, rd, rs];
    let on = [on.0, on.1, on.2];
    for (i, w) in worked.into_iter().enumerate() {
        let (term, formula, k, sum, c, name) = TERMS[i];
        let note = match term {
            Term::Specular if !on[i] && mat.model.terms().2 => Msg::SpecularSkipped,
            _ => one_note(on[i], term),
        };
        let given = || {
            vec![
                Val::num(coefficients[i]),
                rgb_val(sums[i]),
                rgb_val(colours[i]),
            ]
        };
        tr.step(|| {
            Step::new(Msg::TermStep(term), formula)
                .val(Name::math(k), Val::num(coefficients[i]))
                .val(Name::math(sum), rgb_val(sums[i]))
                .sub(Name::math(sum), w)
                .val(Name::math(c), rgb_val(colours[i]))
                .res(Name::math(name), rgb_val(results[i]))
                .sub(Name::math(name), Subst::new(product(on[i]), given()))
                .note(note)
        });
    }
}

/// The three terms as the text writes them: the term, its formula, and the
/// names of its coefficient, of its sum over the lights, of its colour and
/// of itself.
type TermNames = (
    Term,
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    &'static str,
);

/// [`TermNames`] of ambient, diffuse and specular.
const TERMS: [TermNames; 3] = [
    (
        Term::Ambient,
        "ambient = ka · (Ga + Σ Att·Spot·La) · Ca",
        "ka",
        "Ga + Σ Att·Spot·La",
        "Ca",
        "ambient",
    ),
    (
        Term::Diffuse,
        "diffuse = kd · Σ Att·Spot·Ld·max(cos α, 0) · Cs",
        "kd",
        "Σ Att·Spot·Ld·max(cos α, 0)",
        "Cs",
        "diffuse",
    ),
    (
        Term::Specular,
        "specular = ks · Σ Att·Spot·Ls·highlight · Cspecular",
        "ks",
        "Σ Att·Spot·Ls·highlight",
        "Cspecular",
        "specular",
    ),
];

#[cfg(test)]
mod tests;
