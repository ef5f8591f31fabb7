//! The shade part: the lighting of one point, I = ka·Ia + Σ (kd·Il·cos α +
//! ks·Il·cosⁿ β) term by term (Blinn–Phong's N·H in place of R·V), per
//! light when there are several, with each light's factors (attenuation,
//! spot) for lights from a file.

use crate::error::Result;
use crate::input::lights::{LightsFileIn, Setup, ShadeIn};
use crate::input::part::ShadePartIn;
use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::lighting::{self, rgb_val, Highlight, LightTerm, Material};
use crate::stages::trace::{Name, NoTrace, Recorder, Step, Trace, Val};
use crate::tutor::follow;
use crate::tutor::key::{Factor, Field, Key, Part, Shading, Value};
use crate::tutor::parts::fields::Fields;
use crate::tutor::parts::{Solver, Solves};
use crate::tutor::run::Hooks;
use crate::tutor::solution::{Given, ShadeAt};
use crate::tutor::topic::Topic;

/// The shade part.
pub struct ShadePart;

impl Solves for ShadePart {
    const PART: Part = Part::Shade;
    type In = ShadePartIn;
    type Result = ShadeResult;

    /// `shade`: the lighting at the set-up's point.
    fn solve<T: Scalar>(s: &mut Solver<'_, '_, T>, asked: &ShadePartIn) -> Result<()> {
        s.out.section(Msg::SecLighting);
        let set_up = (&asked.shade.table, &asked.lights, asked.shade.prefix);
        let (setup, r) = light_run(set_up, s.hooks, &mut s.out.rec)?;
        s.put(r);
        (s.out.parts).push(Given::Shade(ShadeAt::of(&setup, asked.file.clone())));
        Ok(())
    }

    /// The unit L and N, cos α, R (H and N·H for Blinn), cos β, the
    /// terms, their sum and the clamped colour.
    fn keys(r: &ShadeResult) -> Vec<Key> {
        let key = |v: Value| Key::new(Self::PART, v);
        (SHADE_ORDER.map(Field::Shading).into_iter())
            .filter(|f| r.field(*f).is_some())
            .map(|f| key(Value::Field(f)))
            .collect()
    }

    fn topic(_: &Value) -> Topic {
        Topic::Shade
    }
}

/// The lighting set-up of a `[shade]` table and lights (fields under
/// `prefix`), altered by `hooks`, lit: the set-up and the result keys.
pub fn light_run<T: Scalar>(
    (sh, file, prefix): (&ShadeIn, &LightsFileIn, &str),
    hooks: &Hooks<T>,
    rec: &mut Recorder,
) -> Result<(Setup<T>, ShadeResult)> {
    let mut setup = crate::input::lights::build::<T>(sh, file, prefix, "light", rec)?;
    if let Some(f) = hooks.setup {
        f(&mut setup);
    }
    let r = match hooks.givens() {
        Some(given) if setup.lights.len() == 1 => {
            follow::setup(given, &mut setup);
            let rules = follow::GivenRules {
                rules: &hooks.shade,
                given,
            };
            shade_run(&setup, &rules, rec)
        }
        _ => shade_run(&setup, &hooks.shade, rec),
    };
    Ok((setup, r))
}

/// The lighting's results: the unit L and N (which check takes from
/// the steps), the terms, their sum and the clamped colour, the emissive
/// term when the material has one, R (H and N·H for Blinn–Phong), cos α
/// and cos β (lists, one per light, with several lights), and each
/// light's factors for lights from a file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShadeResult {
    /// L.
    pub l: Option<Val>,
    /// N.
    pub n: Option<Val>,
    /// The colour, clamped to [0, 1].
    pub color: Option<Val>,
    /// The sum of the terms.
    pub unclamped: Option<Val>,
    /// The ambient term.
    pub ambient: Option<Val>,
    /// The diffuse term.
    pub diffuse: Option<Val>,
    /// The specular term.
    pub specular: Option<Val>,
    /// The material's own light.
    pub emissive: Option<Val>,
    /// R, the reflection of L.
    pub r: Option<Val>,
    /// H, the half-way vector (Blinn–Phong).
    pub h: Option<Val>,
    /// N·H (Blinn–Phong).
    pub n_dot_h: Option<Val>,
    /// cos α = L·N.
    pub cos_alpha: Option<Val>,
    /// cos β = R·V.
    pub cos_beta: Option<Val>,
    /// Each light's factors (lights from a file).
    pub lights: Option<Val>,
}

impl ShadeResult {
    /// The place of lighting value `s`.
    pub fn value_mut(&mut self, s: Shading) -> &mut Option<Val> {
        match s {
            Shading::L => &mut self.l,
            Shading::N => &mut self.n,
            Shading::Color => &mut self.color,
            Shading::Unclamped => &mut self.unclamped,
            Shading::Ambient => &mut self.ambient,
            Shading::Diffuse => &mut self.diffuse,
            Shading::Specular => &mut self.specular,
            Shading::Emissive => &mut self.emissive,
            Shading::R => &mut self.r,
            Shading::H => &mut self.h,
            Shading::NDotH => &mut self.n_dot_h,
            Shading::CosAlpha => &mut self.cos_alpha,
            Shading::CosBeta => &mut self.cos_beta,
        }
    }

    /// Lighting value `s`, if the results hold it.
    pub fn value(&self, s: Shading) -> Option<&Val> {
        match s {
            Shading::L => self.l.as_ref(),
            Shading::N => self.n.as_ref(),
            Shading::Color => self.color.as_ref(),
            Shading::Unclamped => self.unclamped.as_ref(),
            Shading::Ambient => self.ambient.as_ref(),
            Shading::Diffuse => self.diffuse.as_ref(),
            Shading::Specular => self.specular.as_ref(),
            Shading::Emissive => self.emissive.as_ref(),
            Shading::R => self.r.as_ref(),
            Shading::H => self.h.as_ref(),
            Shading::NDotH => self.n_dot_h.as_ref(),
            Shading::CosAlpha => self.cos_alpha.as_ref(),
            Shading::CosBeta => self.cos_beta.as_ref(),
        }
    }

    /// Sets lighting value `s`.
    fn set(&mut self, s: Shading, v: Val) {
        *self.value_mut(s) = Some(v);
    }
}

impl Fields for ShadeResult {
    const ORDER: &'static [Field] = &[
        Field::Shading(Shading::L),
        Field::Shading(Shading::N),
        Field::Shading(Shading::Color),
        Field::Shading(Shading::Unclamped),
        Field::Shading(Shading::Ambient),
        Field::Shading(Shading::Diffuse),
        Field::Shading(Shading::Specular),
        Field::Shading(Shading::Emissive),
        Field::Shading(Shading::R),
        Field::Shading(Shading::H),
        Field::Shading(Shading::NDotH),
        Field::Shading(Shading::CosAlpha),
        Field::Shading(Shading::CosBeta),
        Field::Lights,
    ];

    fn field(&self, f: Field) -> Option<&Val> {
        match f {
            Field::Shading(s) => self.value(s),
            Field::Lights => self.lights.as_ref(),
            _ => None,
        }
    }

    fn field_mut(&mut self, f: Field) -> Option<&mut Val> {
        match f {
            Field::Shading(s) => self.value_mut(s).as_mut(),
            Field::Lights => self.lights.as_mut(),
            _ => None,
        }
    }
}

fn opt_vec<T: Scalar>(v: &Option<V3<T>>) -> Val {
    v.as_ref().map(Val::vec3).unwrap_or(Val::Null)
}

fn opt_num<T: Scalar>(v: &Option<T>) -> Val {
    v.as_ref().map(Val::num).unwrap_or(Val::Null)
}

/// Lights the set-up under `rules` (the text's, `Rules::default()`, or the
/// mistake catalog's), steps into `rec`, and returns docs/spec.md §3's shade
/// keys: `color`, `unclamped`, `ambient`, `diffuse`, `specular`, `R`, `H`
/// (Blinn), `cos_alpha`, `cos_beta` — per light (lists) when there are
/// several, with `lights` (attenuation, spot, in range) for lights from a
/// file.
pub fn shade_run<T: Scalar, R: lighting::RuleSet<T>>(
    s: &Setup<T>,
    rules: &R,
    rec: &mut Recorder,
) -> ShadeResult {
    let m = &s.material;
    let text = lighting::is_text_model(m, &s.lights, &s.global_ambient);
    rec.step(|| material_step(m, text));
    let sh = lighting::shade_with_rules(m, &s.lights, &s.global_ambient, &s.surface, rules, rec);
    let mut out = ShadeResult::default();
    out.set(Shading::Color, rgb_val(&sh.color));
    out.set(Shading::Unclamped, rgb_val(&sh.unclamped));
    out.set(Shading::Ambient, rgb_val(&sh.ambient));
    out.set(Shading::Diffuse, rgb_val(&sh.diffuse));
    out.set(Shading::Specular, rgb_val(&sh.specular));
    if sh.emissive.iter().any(|x| !x.is_zero_value()) {
        out.set(Shading::Emissive, rgb_val(&sh.emissive));
    }
    let vs = if s.lights.len() == 1 {
        let (hl, ca) = (m.model.highlight(), opt_num(&sh.cos_alpha));
        vectors(hl, &sh.r, &sh.h, &sh.cos_nh, ca, &sh.cos_beta)
    } else {
        vectors_per_light(s, &sh.view, rules)
    };
    vs.into_iter().for_each(|(s, v)| out.set(s, v));
    if !s.text_light {
        let per = (0..s.lights.len()).map(|i| light_factors(s, i, &sh.view));
        out.lights = Some(Val::List(per.collect()));
    }
    out
}

/// The step that shows the material and the model; the specular colour
/// is the text's Cwhite in the text's own model (`text`).
fn material_step<T: Scalar>(m: &Material<T>, text: bool) -> Step {
    Step::new(Msg::Material, format!("model = {}", m.model.name()))
        .val(Name::math("ka"), Val::num(&m.ka))
        .val(Name::math("kd"), Val::num(&m.kd))
        .val(Name::math("ks"), Val::num(&m.ks))
        .val(Name::math("n"), Val::num(&m.shininess))
        .val(Name::math("Cs"), rgb_val(&m.color))
        .val(
            Name::math(if text { "Cwhite" } else { "Cspecular" }),
            rgb_val(&m.specular),
        )
        .note(
            if m.ka == T::one() && m.kd == T::one() && m.ks == T::one() {
                Msg::MaterialD3d
            } else {
                Msg::MaterialText
            },
        )
}

/// One light's vectors and cosines in the results' order: R, the values
/// of the model's highlight base ([`Highlight`]: none of their own for
/// R·V, whose R and cos β every model shows; H and N·H for Blinn–Phong's
/// N·H), cos α, cos β. An exhaustive match: a new base says here which
/// values it adds.
fn vectors<T: Scalar>(
    hl: Highlight,
    r: &Option<V3<T>>,
    h: &Option<V3<T>>,
    cos_nh: &Option<T>,
    cos_alpha: Val,
    cos_beta: &Option<T>,
) -> Vec<(Shading, Val)> {
    let mut out = vec![(Shading::R, opt_vec(r))];
    match hl {
        Highlight::RDotV => {}
        Highlight::NDotH => {
            out.push((Shading::H, opt_vec(h)));
            out.push((Shading::NDotH, opt_num(cos_nh)));
        }
    }
    out.push((Shading::CosAlpha, cos_alpha));
    out.push((Shading::CosBeta, opt_num(cos_beta)));
    out
}

/// With several lights: [`vectors`] as lists, one entry per light (null
/// for a light out of range; recomputed without steps: they are recorded
/// already).
fn vectors_per_light<T: Scalar, R: lighting::RuleSet<T>>(
    s: &Setup<T>,
    view: &V3<T>,
    rules: &R,
) -> Vec<(Shading, Val)> {
    let (m, n) = (&s.material, s.lights.len());
    let hl = m.model.highlight();
    let none = vectors::<T>(hl, &None, &None, &None, Val::Null, &None);
    let per: Vec<Vec<(Shading, Val)>> = (s.lights.iter().enumerate())
        .map(|(i, l)| {
            let at = (i, n);
            let t =
                lighting::light_term_with(m, l, at, &s.surface, view, true, rules, &mut NoTrace);
            match t {
                Some(t) => vectors(
                    hl,
                    &t.r,
                    &t.h,
                    &t.cos_nh,
                    Val::num(&t.cos_alpha),
                    &t.cos_beta,
                ),
                None => none.clone(),
            }
        })
        .collect();
    (none.iter().enumerate())
        .map(|(j, (s, _))| (*s, Val::List(per.iter().map(|v| v[j].1.clone()).collect())))
        .collect()
}

/// Light i's range, distance, attenuation and spot factor.
fn light_factors<T: Scalar>(s: &Setup<T>, i: usize, view: &V3<T>) -> Val {
    let (m, l, n) = (&s.material, &s.lights[i], s.lights.len());
    let rules = &lighting::TextRules;
    let t = lighting::light_term_with(m, l, (i, n), &s.surface, view, false, rules, &mut NoTrace);
    let or_null = |f: &dyn Fn(&LightTerm<T>) -> Val| t.as_ref().map(f).unwrap_or(Val::Null);
    Val::Map(vec![
        (Factor::InRange.key(), Val::Bool(t.is_some())),
        (Factor::Distance.key(), or_null(&|t| opt_num(&t.distance))),
        (
            Factor::Attenuation.key(),
            or_null(&|t| Val::num(&t.attenuation)),
        ),
        (Factor::Spot.key(), or_null(&|t| Val::num(&t.spot))),
    ])
}

/// The lighting's values in the order of the text's solution (the
/// emissive term is the material's own, not asked).
const SHADE_ORDER: [Shading; 12] = [
    Shading::L,
    Shading::N,
    Shading::CosAlpha,
    Shading::R,
    Shading::H,
    Shading::NDotH,
    Shading::CosBeta,
    Shading::Ambient,
    Shading::Diffuse,
    Shading::Specular,
    Shading::Unclamped,
    Shading::Color,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_lighting_value_is_asked_in_order() {
        for s in Shading::all() {
            let asked = SHADE_ORDER.contains(&s);
            assert!(
                asked != (s == Shading::Emissive),
                "{s:?}: add it to SHADE_ORDER"
            );
        }
    }

    /// The lighting values in the results of a problem with `lights`
    /// (and an emissive material), under every model.
    fn shown_by_some_model(lights: &str) -> Vec<Shading> {
        let mut shown = Vec::new();
        for m in lighting::Model::all() {
            let text = format!(
                "title = 't'\n[shade]\nmodel = '{}'\nnormal = [0, 0, 1]\ncolor = [1, 0, 0]\n{lights}\n[shade.material]\nemissive = [0.1, 0, 0]\n",
                m.name()
            );
            let p = crate::input::problem::ProblemIn::parse(&text, "t").unwrap();
            let result = crate::tutor::solve::solve::<f64>(&p).unwrap().result;
            assert!(
                result.of(Part::Shade).is_some(),
                "no shade results under {m:?}"
            );
            for s in Shading::all() {
                let key = Key::new(Part::Shade, Value::Field(Field::Shading(s)));
                shown.extend(result.get(&key).map(|_| s));
            }
        }
        shown
    }

    #[test]
    fn every_lighting_value_is_in_some_models_results() {
        // With one light and with two, some model's run must put each
        // value in the results (L and N, the unit vectors, are steps of the
        // solution that check reads from the steps): a new value no run
        // produces fails here.
        let one = shown_by_some_model("light = [1, 0, 1]");
        let two = shown_by_some_model(
            "[[light]]\ntype = 'directional'\ndirection = [0, 0, 1]\n[[light]]\ntype = 'point'\nposition = [0, 3, 4]\n",
        );
        for s in Shading::all() {
            let given = matches!(s, Shading::L | Shading::N);
            let missing = "no model's run puts it in the results (shade_run)";
            assert_eq!(one.contains(&s), !given, "{s:?}, one light: {missing}");
            assert_eq!(two.contains(&s), !given, "{s:?}, two lights: {missing}");
        }
    }
}
