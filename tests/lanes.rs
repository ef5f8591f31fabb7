//! The renderer's eight-lane scalar against the one-pixel path: for any
//! material, lights and surfaces, `lighting::shade_color` at `F32x8` gives
//! in lane k exactly (to the bit) what it gives at `Fast32` for lane k's
//! surface — including lanes on different sides of a range, a spot cone,
//! the lit/unlit line and the clamp, which the lane type decides per lane.

use grafika::num::{F32x8, Fast32, Scalar};
use grafika::stages::lighting::{self, Light, LightKind, Material, Model, Surface};
use nalgebra::Vector3;
use proptest::prelude::*;

fn unit(v: [f32; 3]) -> [f32; 3] {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if n < 1e-3 {
        [0.0, 0.0, 1.0]
    } else {
        v.map(|x| x / n)
    }
}

fn v3<T: Scalar>(a: [f32; 3]) -> Vector3<T> {
    Vector3::new(
        T::from_f64(a[0].into()),
        T::from_f64(a[1].into()),
        T::from_f64(a[2].into()),
    )
}

/// A light of `kind` 0 directional, 1 point, 2 spot.
fn light<T: Scalar>(
    kind: u8,
    p: [f32; 3],
    d: [f32; 3],
    range: Option<f32>,
    cone: [f32; 3],
) -> Light<T> {
    let f = |x: f32| T::from_f64(x.into());
    let mut l = Light::<T>::text_default();
    l.kind = match kind {
        0 => LightKind::Directional { dir: v3(unit(d)) },
        1 => LightKind::Point { pos: v3(p) },
        _ => LightKind::Spot {
            pos: v3(p),
            dir: v3(unit(d)),
            theta: f(cone[0]),
            phi: f(cone[0] + cone[1]),
            falloff: f(cone[2]),
        },
    };
    l.attenuation = [f(1.0), f(0.1), f(0.02)];
    l.range = range.map(f);
    l.diffuse = [f(0.9), f(0.8), f(0.7)];
    l
}

fn material<T: Scalar>(model: Model, k: [f32; 3], n: f32, req: bool, c: [f32; 3]) -> Material<T> {
    let f = |x: f32| T::from_f64(x.into());
    let mut m = Material::<T>::text_default(c.map(f));
    m.model = model;
    (m.ka, m.kd, m.ks) = (f(k[0]), f(k[1]), f(k[2]));
    m.shininess = f(n);
    m.specular_requires_lit = req;
    m
}

fn vec3() -> impl Strategy<Value = [f32; 3]> {
    [-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn each_lane_is_the_one_pixel_result(
        model in prop::sample::select(vec![Model::Phong, Model::Blinn, Model::Lambert, Model::Specular]),
        k in [0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0],
        shininess in prop_oneof![(0u32..40).prop_map(|n| n as f32), 0.5f32..20.0],
        req in any::<bool>(),
        lights in prop::collection::vec(
            (0u8..3, vec3(), vec3(), prop::option::of(0.5f32..6.0), [5.0f32..60.0, 0.0f32..40.0, 0.2f32..3.0]),
            1..4,
        ),
        pixels in prop::collection::vec((vec3(), vec3(), [0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0]), 8),
        local in any::<bool>(),
    ) {
        let lights1: Vec<Light<Fast32>> =
            lights.iter().map(|l| light(l.0, l.1, l.2, l.3, l.4)).collect();
        let lights8: Vec<Light<F32x8>> =
            lights.iter().map(|l| light(l.0, l.1, l.2, l.3, l.4)).collect();
        // Lane k's surface colour goes into the material, as the renderer does.
        let lane = |f: &dyn Fn(usize) -> f32| F32x8::from_array(std::array::from_fn(f));
        let mut m8 = material::<F32x8>(model, k, shininess, req, [0.0; 3]);
        m8.color = [0, 1, 2].map(|c| lane(&|i| pixels[i].2[c]));
        let vec8 = |g: &dyn Fn(usize) -> [f32; 3]| {
            Vector3::new(lane(&|i| g(i)[0]), lane(&|i| g(i)[1]), lane(&|i| g(i)[2]))
        };
        let eye = |p: [f32; 3]| [p[0], p[1], p[2] - 5.0];
        let s8 = Surface {
            normal: vec8(&|i| unit(pixels[i].0)),
            view: v3(unit([0.1, 0.2, 1.0])),
            position: vec8(&|i| eye(pixels[i].1)),
            camera: local.then(|| v3([0.0, 0.0, 0.0])),
        };
        let c8 = lighting::shade_color(&m8, &lights8, &s8);
        for (i, px) in pixels.iter().enumerate() {
            let m1 = material::<Fast32>(model, k, shininess, req, px.2);
            let s1 = Surface {
                normal: v3(unit(px.0)),
                view: v3(unit([0.1, 0.2, 1.0])),
                position: v3(eye(px.1)),
                camera: local.then(|| v3([0.0, 0.0, 0.0])),
            };
            let c1 = lighting::shade_color(&m1, &lights1, &s1);
            for c in 0..3 {
                prop_assert_eq!(
                    c8[c].to_array()[i].to_bits(),
                    c1[c].0.to_bits(),
                    "lane {} channel {}: {} vs {}", i, c, c8[c].to_array()[i], c1[c].0
                );
            }
        }
    }
}
