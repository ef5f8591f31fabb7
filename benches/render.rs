//! Renderer benchmarks (divan): llvmpipe's reference sphere in each shading
//! mode at 1024×1024, the same at 1920×1080, and the text's landscape.
//! Run with `cargo bench --bench render`.

use grafika::input::scene::{Scene, Shading};
use grafika::render::{self, Options};
use std::path::Path;

fn main() {
    divan::main();
}

fn scene(name: &str) -> Scene {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("problems/render")
        .join(name);
    Scene::read(&p, grafika::input::scene::WORK_LIMIT).expect("scene")
}

#[divan::bench(args = [Shading::Flat, Shading::Gouraud, Shading::Phong], sample_count = 20)]
fn bench_sphere_1024(b: divan::Bencher, shading: Shading) {
    let s = scene("bench-sphere.toml");
    let mut o = Options::of(&s);
    o.shading = shading;
    o.force_shading = true;
    b.bench(|| render::render(&s, &o).expect("render"));
}

#[divan::bench(sample_count = 20)]
fn bench_sphere_1920x1080_phong(b: divan::Bencher) {
    let s = scene("bench-sphere.toml");
    let mut o = Options::of(&s);
    (o.width, o.height) = (1920, 1080);
    b.bench(|| render::render(&s, &o).expect("render"));
}

#[divan::bench(args = ["landscape-flat.toml", "landscape-gouraud.toml"], sample_count = 20)]
fn landscape(b: divan::Bencher, name: &str) {
    let s = scene(name);
    let o = Options::of(&s);
    b.bench(|| render::render(&s, &o).expect("render"));
}
