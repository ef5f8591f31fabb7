//! One lighting evaluation (the text's Phong model and Blinn–Phong, one
//! directional light) with steps off: at f32 and f64 (the calculator's
//! stable formulas), at `Fast32` (plain f32, the renderer's one-pixel type)
//! and at `F32x8` (eight points per call, the renderer's Phong batches); and
//! the reference scene's point light with a local viewer at `Fast32` and
//! `F32x8`.

use divan::{black_box, Bencher};
use grafika::num::vec::{normalize, v3};
use grafika::num::{F32x8, Fast32, Scalar};
use grafika::stages::lighting::LightKind;
use grafika::stages::lighting::{shade, Light, Material, Model, Surface};
use grafika::stages::trace::NoTrace;

fn main() {
    divan::main();
}

fn setup<T: Scalar>(model: Model) -> (Material<T>, [Light<T>; 1], Surface<T>) {
    let h = |x: i64| T::from_i64(x) / T::from_i64(10);
    let mut m = Material::text_default([h(9), h(5), h(1)]);
    m.model = model;
    let l = normalize(&v3(h(3), h(4), h(10))).unwrap().0;
    let n = normalize(&v3(h(1), h(2), h(10))).unwrap().0;
    let s = Surface {
        normal: n,
        view: v3(T::zero(), T::zero(), T::one()),
        position: v3(T::zero(), T::zero(), T::zero()),
        camera: None,
    };
    (m, [Light::directional(l)], s)
}

#[divan::bench(types = [f32, f64, Fast32, F32x8])]
fn phong<T: Scalar>(b: Bencher) {
    let (m, l, s) = setup::<T>(Model::Phong);
    b.bench(|| shade(black_box(&m), black_box(&l), black_box(&s), &mut NoTrace));
}

#[divan::bench(types = [f32, f64, Fast32, F32x8])]
fn blinn<T: Scalar>(b: Bencher) {
    let (m, l, s) = setup::<T>(Model::Blinn);
    b.bench(|| shade(black_box(&m), black_box(&l), black_box(&s), &mut NoTrace));
}

/// llvmpipe's scene: a point light at (3, 3, 2), the viewer at the origin,
/// specular only where lit, shininess 32.
#[divan::bench(types = [Fast32, F32x8])]
fn phong_point_local<T: Scalar>(b: Bencher) {
    let (mut m, mut l, mut s) = setup::<T>(Model::Phong);
    m.shininess = T::from_i64(32);
    m.specular_requires_lit = true;
    l[0].kind = LightKind::Point {
        pos: v3(T::from_i64(3), T::from_i64(3), T::from_i64(2)),
    };
    s.position = v3(T::from_f64(0.1), T::from_f64(-0.2), T::from_i64(-2));
    s.camera = Some(v3(T::zero(), T::zero(), T::zero()));
    b.bench(|| shade(black_box(&m), black_box(&l), black_box(&s), &mut NoTrace));
}
