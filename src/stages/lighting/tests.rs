//! Hand-derived values for every model, the Blinn = Phong invariant, the
//! sum of the models, clamping, attenuation, spot and range boundaries.

use super::*;
use crate::num::vec::{dot, scale};
use crate::stages::trace::NoTrace;
use proptest::prelude::*;

const EPS: f64 = 1e-12;

fn v(x: f64, y: f64, z: f64) -> V3<f64> {
    v3(x, y, z)
}

fn unit_v(x: f64, y: f64, z: f64) -> V3<f64> {
    normalize(&v(x, y, z)).unwrap().0
}

fn surf(n: V3<f64>, view: V3<f64>) -> Surface<f64> {
    Surface {
        normal: n,
        view,
        position: v(0.0, 0.0, 0.0),
        camera: None,
    }
}

fn close(a: &[f64; 3], b: [f64; 3]) {
    for c in 0..3 {
        assert!((a[c] - b[c]).abs() < EPS, "{a:?} vs {b:?}");
    }
}

fn run(model: Model, color: Rgb<f64>, l: V3<f64>, s: &Surface<f64>) -> Shaded<f64> {
    let mut m = Material::text_default(color);
    m.model = model;
    shade(&m, &[Light::directional(l)], s, &mut NoTrace)
}

/// N = (0,1,1)/√2, L = V = (0,0,1), Cs = (1,1,0): L·N = 1/√2,
/// R = 2N(1/√2) − L = (0,1,1) − (0,0,1) = (0,1,0), R·V = 0.
/// diffuse = 0.6·(1/√2)·Cs = (0.3√2, 0.3√2, 0); ambient = 0.4·Cs;
/// specular = 0.7·0⁴ = 0.
#[test]
fn text_models_at_a_tilted_normal() {
    let s = surf(unit_v(0.0, 1.0, 1.0), v(0.0, 0.0, 1.0));
    let l = v(0.0, 0.0, 1.0);
    let y = [1.0, 1.0, 0.0];
    let d = 0.3 * 2f64.sqrt();
    let sh = run(Model::Diffuse, y, l, &s);
    close(&sh.color, [d, d, 0.0]);
    assert!((sh.cos_alpha.unwrap() - 0.5f64.sqrt()).abs() < EPS);
    assert!(
        sh.r.is_none(),
        "the diffuse model does not compute R under NoTrace"
    );
    let sh = run(Model::Phong, y, l, &s);
    let r = sh.r.unwrap();
    close(&[r[0], r[1], r[2]], [0.0, 1.0, 0.0]);
    assert!(sh.cos_beta.unwrap().abs() < EPS);
    close(&run(Model::Ambient, y, l, &s).color, [0.4, 0.4, 0.0]);
    close(&run(Model::Specular, y, l, &s).color, [0.0, 0.0, 0.0]);
    close(
        &run(Model::Lambert, y, l, &s).color,
        [d + 0.4, d + 0.4, 0.0],
    );
    close(&run(Model::Phong, y, l, &s).color, [d + 0.4, d + 0.4, 0.0]);
}

/// N = V = (0,0,1), L = (1,0,1)/√2: R = 2N(√2/2) − L = (−√2/2, 0, √2/2),
/// cos β = √2/2, (√2/2)⁴ = 1/4, specular = 0.7/4 = 0.175 on every channel.
/// Blinn: H = norm((0,0,1) + L) makes 22.5° with N, N·H = cos 22.5°,
/// cos⁴ 22.5° = ((2+√2)/4)² = (3+2√2)/8.
#[test]
fn specular_phong_and_blinn() {
    let s = surf(v(0.0, 0.0, 1.0), v(0.0, 0.0, 1.0));
    let l = unit_v(1.0, 0.0, 1.0);
    let sh = run(Model::Specular, [1.0, 0.0, 0.0], l, &s);
    close(&sh.specular, [0.175, 0.175, 0.175]);
    let b = run(Model::Blinn, [1.0, 0.0, 0.0], l, &s);
    let c4 = (3.0 + 2.0 * 2f64.sqrt()) / 8.0;
    close(&b.specular, [0.7 * c4, 0.7 * c4, 0.7 * c4]);
    let h = b.h.unwrap();
    let half = 22.5f64.to_radians();
    close(&[h[0], h[1], h[2]], [half.sin(), 0.0, half.cos()]);
    // ambient 0.4 + diffuse 0.6·√2/2 + specular on red: over 1, clamped
    assert!(b.unclamped[0] > 1.0);
    assert_eq!(b.color[0], 1.0);
}

/// When V = R (viewer in the mirror direction), H is the bisector of L and V
/// and equals N, so N·H = 1 = R·V: Blinn and Phong give the same color.
#[test]
fn blinn_equals_phong_when_r_is_v() {
    let n = unit_v(0.0, 1.0, 2.0);
    let l = unit_v(1.0, 1.0, 1.0);
    let r = sub(&scale(&n, &(2.0 * dot(&l, &n))), &l);
    let s = surf(n, r);
    let p = run(Model::Phong, [0.2, 0.5, 0.9], l, &s);
    let b = run(Model::Blinn, [0.2, 0.5, 0.9], l, &s);
    close(&p.unclamped, b.unclamped);
    assert!((b.cos_nh.unwrap() - 1.0).abs() < EPS);
}

/// Light behind the surface: N = (0,0,1), L = (0,0,−1), V = (0,0,−1):
/// cos α = −1, R = 2N(−1) − L = (0,0,−1), R·V = 1. The text's code adds
/// ks·1⁴ = 0.7; with `specular_requires_lit` it adds nothing.
#[test]
fn light_behind_the_surface() {
    let s = surf(v(0.0, 0.0, 1.0), v(0.0, 0.0, -1.0));
    let l = v(0.0, 0.0, -1.0);
    let mut m = Material::text_default([1.0, 0.0, 0.0]);
    let lights = [Light::directional(l)];
    let sh = shade(&m, &lights, &s, &mut NoTrace);
    close(&sh.diffuse, [0.0; 3]);
    close(&sh.specular, [0.7; 3]);
    m.specular_requires_lit = true;
    let sh = shade(&m, &lights, &s, &mut NoTrace);
    close(&sh.specular, [0.0; 3]);
    close(&sh.color, [0.4, 0.0, 0.0]);
}

/// Shininess 0: max(cos β, 0)⁰ = 1 everywhere; ks = 0 and specular off skip it.
#[test]
fn shininess_zero_and_specular_off() {
    let s = surf(v(0.0, 0.0, 1.0), v(0.0, 0.0, 1.0));
    let l = v(0.0, 1.0, 0.0); // grazing: cos α = 0, R = −L, R·V = 0
    let mut m = Material::text_default([0.0, 0.0, 1.0]);
    m.shininess = 0.0;
    let sh = shade(&m, &[Light::directional(l)], &s, &mut NoTrace);
    close(&sh.specular, [0.7; 3]);
    m.specular_on = false;
    close(
        &shade(&m, &[Light::directional(l)], &s, &mut NoTrace).specular,
        [0.0; 3],
    );
    m.specular_on = true;
    m.ks = 0.0;
    let sh = shade(&m, &[Light::directional(l)], &s, &mut NoTrace);
    close(&sh.specular, [0.0; 3]);
    assert!(sh.r.is_none(), "R is not computed when nothing uses it");
}

/// Point light at (0,0,4) over the origin, N = (0,0,1): d = 4,
/// Att = 1/(1 + 0.5·4 + 0.25·16) = 1/7; the Lambert diffuse is 0.6/7.
/// With range 4 the point is on the boundary (inside); range 3.99 excludes it.
#[test]
fn attenuation_and_range() {
    let s = surf(v(0.0, 0.0, 1.0), v(0.0, 0.0, 1.0));
    let mut m = Material::text_default([1.0, 1.0, 1.0]);
    m.model = Model::Diffuse;
    let mut light = Light::text_default();
    light.kind = LightKind::Point {
        pos: v(0.0, 0.0, 4.0),
    };
    light.attenuation = [1.0, 0.5, 0.25];
    light.range = Some(4.0);
    let sh = shade(&m, std::slice::from_ref(&light), &s, &mut NoTrace);
    close(&sh.diffuse, [0.6 / 7.0; 3]);
    assert_eq!(sh.lights_used, 1);
    light.range = Some(3.99);
    let sh = shade(&m, &[light], &s, &mut NoTrace);
    assert_eq!(sh.lights_used, 0);
    close(&sh.color, [0.0; 3]);
}

fn spot_at(x: f64, z: f64, falloff: f64) -> f64 {
    let l = unit_v(x, 0.0, z); // from the origin to the light at (x, 0, z)
    spot_factor(
        &l,
        &v(0.0, 0.0, -1.0),
        &60.0,
        &90.0,
        &falloff,
        (0, 1),
        &mut NoTrace,
    )
}

/// Spot along −z, θ = 60° (cos 30° = √3/2), φ = 90° (cos 45° = √2/2).
/// Light at (0,0,5): ρ = 1 → 1. Light at (3,0,4): ρ = 4/5 → penumbra,
/// (0.8 − √2/2)/(√3/2 − √2/2). Light at (4,0,3): ρ = 0.6 → 0. On the inner
/// boundary (ρ = cos 30°, light at (1,0,√3)) → 1; on the outer (ρ = cos 45°)
/// → 0.
#[test]
fn spot_factor_at_its_boundaries() {
    let (ct, cp) = (3f64.sqrt() / 2.0, 2f64.sqrt() / 2.0);
    assert_eq!(spot_at(0.0, 5.0, 1.0), 1.0);
    assert!((spot_at(3.0, 4.0, 1.0) - (0.8 - cp) / (ct - cp)).abs() < EPS);
    assert!((spot_at(3.0, 4.0, 2.0) - ((0.8 - cp) / (ct - cp)).powi(2)).abs() < EPS);
    assert_eq!(spot_at(4.0, 3.0, 1.0), 0.0);
    assert!((spot_at(1.0, 3f64.sqrt(), 1.0) - 1.0).abs() < 1e-9);
    assert!(spot_at(1.0, 1.0, 1.0).abs() < 1e-9);
}

#[test]
fn validation_names_the_field() {
    let mut m = Material::text_default([1.0, 0.5, 0.0]);
    assert!(m.validate("").is_ok());
    m.kd = -0.1;
    assert_eq!(m.validate("shade.").unwrap_err().field, "shade.kd");
    let m = Material::text_default([1.0, 1.5, 0.0]);
    assert_eq!(m.validate("").unwrap_err().field, "color");
    let mut l = Light::<f64>::text_default();
    l.attenuation = [0.0; 3];
    assert_eq!(
        l.validate("light[0]").unwrap_err().field,
        "light[0].attenuation"
    );
    let e = unit("N", "normal", &v(0.0, 0.0, 0.0), &mut NoTrace).unwrap_err();
    assert_eq!(e.field, "normal");
}

/// The text's light: white, directional, toward (0,0,1); one light of the
/// text's model gives exactly the formulas of docs/spec.md §1 at f32 as well.
#[test]
fn text_defaults_at_f32() {
    let s = Surface {
        normal: v3(0.0f32, 0.0, 1.0),
        view: v3(0.0, 0.0, 1.0),
        position: v3(0.0, 0.0, 0.0),
        camera: None,
    };
    let m = Material::text_default([0.5f32, 0.25, 1.0]);
    let sh = shade(&m, &[Light::text_default()], &s, &mut NoTrace);
    // L = N = V: cos α = cos β = 1; C = 0.6·Cs + 0.7 + 0.4·Cs = Cs + 0.7
    let want = [0.5f32 + 0.7, 0.25 + 0.7, 1.0 + 0.7];
    for (got, want) in sh.unclamped.iter().zip(want) {
        assert!((got - want).abs() < 1e-6);
    }
    assert_eq!(sh.color, [1.0, 0.95, 1.0]);
}

fn arb_unit() -> impl Strategy<Value = V3<f64>> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("not tiny", |(x, y, z)| x * x + y * y + z * z > 1e-3)
        .prop_map(|(x, y, z)| unit_v(x, y, z))
}

proptest! {
    #[test]
    fn color_always_in_unit_range(n in arb_unit(), l in arb_unit(), vv in arb_unit(),
                                  c in (0.0..=1.0f64, 0.0..=1.0f64, 0.0..=1.0f64)) {
        let sh = run(Model::Phong, [c.0, c.1, c.2], l, &surf(n, vv));
        for x in sh.color { prop_assert!((0.0..=1.0).contains(&x)); }
    }

    /// Ambient + diffuse + specular models add up to Phong; Lambert ≤ Phong.
    #[test]
    fn models_sum_to_phong(n in arb_unit(), l in arb_unit(), vv in arb_unit(),
                           c in (0.0..=1.0f64, 0.0..=1.0f64, 0.0..=1.0f64)) {
        let s = surf(n, vv);
        let col = [c.0, c.1, c.2];
        let p = run(Model::Phong, col, l, &s).unclamped;
        let a = run(Model::Ambient, col, l, &s).unclamped;
        let d = run(Model::Diffuse, col, l, &s).unclamped;
        let sp = run(Model::Specular, col, l, &s).unclamped;
        let lam = run(Model::Lambert, col, l, &s).unclamped;
        for k in 0..3 {
            prop_assert!((a[k] + d[k] + sp[k] - p[k]).abs() < 1e-12);
            prop_assert!(lam[k] <= p[k] + 1e-15);
        }
    }
}

/// Exact arithmetic: L = (1,1,1) → (√3/3, √3/3, √3/3); with N = (0,1,1)/√2
/// and V = (0,0,1): cos α = √6/3, R = 2N(√6/3) − L = (−√3/3, √3/3, √3/3),
/// cos β = √3/3, (√3/3)⁴ = 1/9, specular = 0.7/9 = 7/90, diffuse = 0.6·√6/3
/// = √6/5 on the yellow channels.
#[test]
fn exact_forms_through_the_generic_code() {
    use crate::num::Real;
    let r = |x: i64| Real::from_i64(x);
    let l = unit("L", "light", &v3(r(1), r(1), r(1)), &mut NoTrace).unwrap();
    assert_eq!(l[0].exact_ascii().as_deref(), Some("sqrt(3)/3"));
    let n = unit("N", "normal", &v3(r(0), r(1), r(1)), &mut NoTrace).unwrap();
    let s = Surface {
        normal: n,
        view: v3(r(0), r(0), r(1)),
        position: v3(r(0), r(0), r(0)),
        camera: None,
    };
    let m = Material::text_default([r(1), r(1), r(0)]);
    let sh = shade(&m, &[Light::directional(l)], &s, &mut NoTrace);
    assert_eq!(sh.specular[2], Real::from_ratio(7, 90));
    assert_eq!(sh.diffuse[0].exact_ascii().as_deref(), Some("sqrt(6)/5"));
    assert_eq!(
        sh.cos_beta.unwrap().exact_ascii().as_deref(),
        Some("sqrt(3)/3")
    );
}
