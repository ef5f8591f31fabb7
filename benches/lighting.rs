//! One lighting evaluation (the text's Phong model and Blinn–Phong, one
//! directional light) at f32 and f64 with steps off, as the renderer calls it.

use divan::{black_box, Bencher};
use grafika::lighting::{shade, Light, Material, Model, Surface};
use grafika::num::Scalar;
use grafika::trace::NoTrace;
use grafika::vec::{normalize, v3};

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

#[divan::bench(types = [f32, f64])]
fn phong<T: Scalar>(b: Bencher) {
    let (m, l, s) = setup::<T>(Model::Phong);
    b.bench(|| shade(black_box(&m), black_box(&l), black_box(&s), &mut NoTrace));
}

#[divan::bench(types = [f32, f64])]
fn blinn<T: Scalar>(b: Bencher) {
    let (m, l, s) = setup::<T>(Model::Blinn);
    b.bench(|| shade(black_box(&m), black_box(&l), black_box(&s), &mut NoTrace));
}
