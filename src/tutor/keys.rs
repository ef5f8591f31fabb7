//! The results of the calculator's stages as named values (the result keys
//! of the JSON contract: `u`, `v`, `n`, `top`, `code0`, `segment`, `color`,
//! ...), shared by the calculator commands and `solve`.

use crate::input::lights::Setup;
use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::Scalar;
use crate::stages::camera;
use crate::stages::clip::{self, ClipBox};
use crate::stages::lighting::{self, rgb_val, Highlight, LightTerm, Material};
use crate::stages::trace::{Name, NoTrace, Recorder, Step, Trace, Val};
use crate::stages::window;
use crate::tutor::key::{Axis, Cut, Edge, Factor, Field, Key, Node, Part, Plane, Shading, Value};

/// The basis as named results.
pub fn basis_result<T: Scalar>(b: &camera::Basis<T>) -> Vec<(String, Val)> {
    let axis = |a| Field::Axis(a).key();
    vec![
        (axis(Axis::U), Val::vec3(&b.u)),
        (axis(Axis::V), Val::vec3(&b.v)),
        (axis(Axis::N), Val::vec3(&b.n)),
    ]
}

/// The window's named results (`top`, …; on the far plane `far_top`, …).
pub fn window_result<T: Scalar>(w: &window::Window<T>, far: bool) -> Vec<(String, Val)> {
    [
        (Edge::Top, &w.top),
        (Edge::Bottom, &w.bottom),
        (Edge::Left, &w.left),
        (Edge::Right, &w.right),
        (Edge::Height, &w.height),
        (Edge::Width, &w.width),
    ]
    .into_iter()
    .map(|(e, v)| (Field::Edge(e, far).key(), Val::num(v)))
    .collect()
}

/// Clips one segment by outcodes and by Liang–Barsky and records whether
/// they agree; the outcodes' clipping.
pub fn clip_checked<T: Scalar>(
    b: &ClipBox<T>,
    p0: &V3<T>,
    p1: &V3<T>,
    rec: &mut Recorder,
) -> clip::Clipped<T> {
    let r = clip::clip_segment(b, p0, p1, rec);
    let lb = clip::liang_barsky(b, p0, p1, rec);
    let agree = match (&r.segment, &lb) {
        (None, None) => true,
        (Some((a, z)), Some((c, d))) => close(a, c) && close(z, d),
        _ => false,
    };
    let segment = |s: &Option<(V3<T>, V3<T>)>| match s {
        Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
        None => Val::Null,
    };
    rec.step(|| {
        Step::new(Msg::MethodsAgree, Msg::FMethods)
            .val(Name::Outcodes, segment(&r.segment))
            .val(Name::math("Liang–Barsky"), segment(&lb))
            .res(Name::Agree, Val::Bool(agree))
            .note(if agree {
                Msg::Agree(true)
            } else {
                Msg::Agree(false)
            })
    });
    r
}

/// docs/spec.md's clip result keys of a clipping.
pub fn clip_result<T: Scalar>(r: &clip::Clipped<T>) -> Vec<(String, Val)> {
    vec![
        (Field::Code0.key(), Val::text(clip::code_str(r.code0))),
        (Field::Code1.key(), Val::text(clip::code_str(r.code1))),
        (Field::Status.key(), Val::text(r.status.as_str())),
        (
            Field::Segment.key(),
            match &r.segment {
                Some((a, z)) => Val::List(vec![Val::vec3(a), Val::vec3(z)]),
                None => Val::Null,
            },
        ),
        (
            Field::Intersections.key(),
            Val::Map(r.intersections.iter().map(intersection_val).collect()),
        ),
    ]
}

/// One tried intersection as a result: its plane's key and t, point, code, kept.
fn intersection_val<T: Scalar>(i: &clip::Intersection<T>) -> (String, Val) {
    (
        Node::Plane(Plane::ALL[i.bit]).to_string(),
        Val::Map(vec![
            (Cut::T.key(), Val::num(&i.t)),
            (Cut::Point.key(), Val::vec3(&i.point)),
            (Cut::Code.key(), Val::text(clip::code_str(i.code))),
            (Cut::Kept.key(), Val::Bool(i.code == 0)),
        ]),
    )
}

/// A lighting value's key in the result (`color`, `cos_alpha`, …).
fn key(s: Shading) -> String {
    Field::Shading(s).key()
}

/// Equal up to rounding (exact values compare exactly).
fn close<T: Scalar>(a: &V3<T>, b: &V3<T>) -> bool {
    (0..3).all(|k| {
        let (x, y) = (a[k].to_f64(), b[k].to_f64());
        a[k] == b[k] || (x - y).abs() <= 1e-5 * (1.0 + x.abs().max(y.abs()))
    })
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
) -> Vec<(String, Val)> {
    let m = &s.material;
    let text = lighting::is_text_model(m, &s.lights, &s.global_ambient);
    rec.step(|| material_step(m, text));
    let sh = lighting::shade_with_rules(m, &s.lights, &s.global_ambient, &s.surface, rules, rec);
    let mut out: Vec<(String, Val)> = vec![
        (key(Shading::Color), rgb_val(&sh.color)),
        (key(Shading::Unclamped), rgb_val(&sh.unclamped)),
        (key(Shading::Ambient), rgb_val(&sh.ambient)),
        (key(Shading::Diffuse), rgb_val(&sh.diffuse)),
        (key(Shading::Specular), rgb_val(&sh.specular)),
    ];
    if sh.emissive.iter().any(|x| !x.is_zero_value()) {
        out.push((key(Shading::Emissive), rgb_val(&sh.emissive)));
    }
    if s.lights.len() == 1 {
        let (hl, ca) = (m.model.highlight(), opt_num(&sh.cos_alpha));
        let vs = vectors(hl, &sh.r, &sh.h, &sh.cos_nh, ca, &sh.cos_beta);
        out.extend(vs.into_iter().map(|(s, v)| (key(s), v)));
    } else {
        out.extend(vectors_per_light(s, &sh.view, rules));
    }
    if !s.text_light {
        let per = (0..s.lights.len()).map(|i| light_factors(s, i, &sh.view));
        out.push((Field::Lights.key(), Val::List(per.collect())));
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
) -> Vec<(String, Val)> {
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
        .map(|(j, (s, _))| {
            (
                key(*s),
                Val::List(per.iter().map(|v| v[j].1.clone()).collect()),
            )
        })
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

/// The answer keys of a result tree in the order of the text's solution:
/// n, u, v, the view matrix, the eye coordinates; the projected points;
/// the window's top, bottom, left, right, height, width (not the far
/// window's); the pixels; per segment the outcodes, each plane tried (its
/// t, intersection point and that point's outcode, the text's deciding
/// step), the clipped segment and the status; the lighting's unit L and
/// N, cos α, R (H and N·H for Blinn), cos β, the terms, their sum and the
/// clamped colour. Each key is a typed [`Key`] (spelled by its `Display`); a new
/// part is a new arm here (the match is over every [`Part`]).
pub fn ordered_keys(result: &[(String, Val)]) -> Vec<Key> {
    let mut keys: Vec<Key> = Vec::new();
    for (name, v) in result {
        let Some(Node::Part(part)) = Node::read(name, None) else {
            continue;
        };
        let kv = match v {
            Val::Map(kv) => &kv[..],
            _ => &[],
        };
        let fields = fields(part, kv);
        let key = |v: Value| Key::new(part, v);
        match part {
            Part::View => {
                let axes = [Axis::N, Axis::U, Axis::V].map(Field::Axis);
                let order = [axes[0], axes[1], axes[2], Field::Matrix];
                keys.extend(in_order(&fields, &order).map(|f| key(Value::Field(f))));
                keys.extend(named(kv, Field::Points).map(|n| key(Value::Point(n))));
            }
            Part::Project => keys.extend(named(kv, Field::Points).map(|n| key(Value::Point(n)))),
            Part::Viewport => keys.extend(named(kv, Field::Pixels).map(|n| key(Value::Pixel(n)))),
            Part::Window => keys.extend(
                (fields.iter())
                    .filter(|f| matches!(f, Field::Edge(_, false)))
                    .map(|f| key(Value::Field(*f))),
            ),
            Part::Clip => match v {
                Val::List(runs) => {
                    for (i, r) in runs.iter().enumerate() {
                        if let Val::Map(kv) = r {
                            keys.extend(clip_keys(kv).map(|k| k.of_segment(Some(i))));
                        }
                    }
                }
                _ => keys.extend(clip_keys(kv)),
            },
            Part::Shade => {
                let order = SHADE_ORDER.map(Field::Shading);
                keys.extend(in_order(&fields, &order).map(|f| key(Value::Field(f))));
            }
        }
    }
    keys
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

/// The fields of a part's map (names that are no field of the part left out).
fn fields(part: Part, kv: &[(String, Val)]) -> Vec<Field> {
    let under = Node::Part(part);
    (kv.iter())
        .filter_map(|(k, _)| match Node::read(k, Some(&under)) {
            Some(Node::Field(f)) => Some(f),
            _ => None,
        })
        .collect()
}

/// Each of `order` the part holds, in that order.
fn in_order<'a>(fields: &'a [Field], order: &'a [Field]) -> impl Iterator<Item = Field> + 'a {
    order.iter().copied().filter(|f| fields.contains(f))
}

/// The names of the map held at `inner` (the points, the pixels).
fn named(kv: &[(String, Val)], inner: Field) -> impl Iterator<Item = String> + '_ {
    let inner = Node::Field(inner).to_string();
    let map = match kv.iter().find(|(k, _)| *k == inner) {
        Some((_, Val::Map(m))) => &m[..],
        _ => &[],
    };
    map.iter().map(|(n, _)| n.clone())
}

/// The outcodes, each plane tried (t, intersection, its outcode), the
/// clipped segment, the status.
fn clip_keys(kv: &[(String, Val)]) -> impl Iterator<Item = Key> {
    let key = |v: Value| Key::new(Part::Clip, v);
    let mut keys = vec![
        key(Value::Field(Field::Code0)),
        key(Value::Field(Field::Code1)),
    ];
    let planes = Node::Field(Field::Intersections);
    if let Some((_, Val::Map(tried))) = kv.iter().find(|(k, _)| *k == planes.to_string()) {
        for (pl, _) in tried {
            if let Some(Node::Plane(p)) = Node::read(pl, Some(&planes)) {
                keys.extend([Cut::T, Cut::Point, Cut::Code].map(|c| key(Value::Cut(p, c))));
            }
        }
    }
    keys.push(key(Value::Field(Field::Segment)));
    keys.push(key(Value::Field(Field::Status)));
    keys.into_iter()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(keys: &[&str]) -> Val {
        Val::Map(keys.iter().map(|k| (k.to_string(), Val::Null)).collect())
    }

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
            let shade = Node::Part(Part::Shade);
            let Some((_, Val::Map(kv))) = result.iter().find(|(k, _)| *k == shade.to_string())
            else {
                panic!("no shade results under {m:?}")
            };
            for (k, _) in kv {
                if let Some(Node::Field(Field::Shading(s))) = Node::read(k, Some(&shade)) {
                    shown.push(s);
                }
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

    #[test]
    fn keys_come_in_the_order_of_the_texts_solution() {
        let view = Val::Map(vec![
            ("u".into(), Val::Null),
            ("v".into(), Val::Null),
            ("n".into(), Val::Null),
            ("matrix".into(), Val::Null),
            ("points".into(), map(&["A", "B"])),
        ]);
        let run = Val::Map(vec![
            ("code0".into(), Val::Null),
            ("status".into(), Val::Null),
            ("intersections".into(), map(&["top"])),
        ]);
        let result = vec![
            ("view".to_string(), view),
            ("window".into(), map(&["top", "far_top", "width"])),
            ("clip".into(), Val::List(vec![map(&["code0"]), run])),
            ("shade".into(), map(&["color", "cos_alpha", "L"])),
        ];
        let want = [
            "view.n",
            "view.u",
            "view.v",
            "view.matrix",
            "view.points.A",
            "view.points.B",
            "window.top",
            "window.width",
            "clip.0.code0",
            "clip.0.code1",
            "clip.0.segment",
            "clip.0.status",
            "clip.1.code0",
            "clip.1.code1",
            "clip.1.intersections.top.t",
            "clip.1.intersections.top.point",
            "clip.1.intersections.top.code",
            "clip.1.segment",
            "clip.1.status",
            "shade.L",
            "shade.cos_alpha",
            "shade.color",
        ];
        let got: Vec<String> = ordered_keys(&result).iter().map(Key::to_string).collect();
        assert_eq!(got, want);
    }
}
