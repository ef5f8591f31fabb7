//! The renderer from first principles: pixel colours that `lighting::shade`
//! predicts, background outside silhouettes, depth order, near-plane
//! clipping, open meshes, bad scene files and determinism across threads.

use assert_cmd::Command;
use grafika::input::scene::Scene;
use grafika::render::{self, Frame, Options};
use grafika::stages::lighting::{self, Light, Material, Surface};
use grafika::stages::trace::NoTrace;
use nalgebra::Vector3;
use std::path::Path;

fn scene(text: &str) -> Scene {
    Scene::parse(text, "test.toml", Path::new(".")).unwrap()
}

fn draw(text: &str) -> Frame {
    let s = scene(text);
    render::render(&s, &Options::of(&s)).unwrap()
}

fn pixel(f: &Frame, x: u32, y: u32) -> [u8; 3] {
    let k = 3 * (y * f.width + x) as usize;
    [f.rgb[k], f.rgb[k + 1], f.rgb[k + 2]]
}

/// What `lighting::shade` gives for a surface with normal N seen along +z
/// under the text's default light and material, as 8-bit.
fn expected(color: [f32; 3], n: Vector3<f32>) -> [u8; 3] {
    let s = Surface {
        normal: n,
        view: Vector3::new(0.0, 0.0, 1.0),
        position: Vector3::zeros(),
        camera: None,
    };
    let c = lighting::shade(
        &Material::text_default(color),
        &[Light::text_default()],
        &s,
        &mut NoTrace,
    );
    render::to_u8(c.color)
}

fn close(a: [u8; 3], b: [u8; 3]) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (*x as i32 - y as i32).abs() <= 1)
}

#[test]
fn centre_of_a_head_on_sphere_has_the_colour_shade_gives_for_n_v_l_equal() {
    // Tilt 0: the viewer and the light are along +z. A 41×41 image puts the
    // centre of pixel (20, 20) at x = y = 0, where the sphere's normal is
    // (0, 0, 1) = V = L (a vertex sits there: slices divisible by 4, even
    // stacks). With ka 0.4, kd 0.6, ks 0.7: C·(0.4 + 0.6·1) + 0.7·1ⁿ =
    // (1, 0.7, 0.7) for red — and shade must agree.
    for shading in ["phong", "gouraud"] {
        let f = draw(&format!(
            "shading = \"{shading}\"\n[image]\nwidth = 41\nheight = 41\n\
             [[object]]\ntype = \"sphere\"\nn = 16\nr = 15\ncolor = [1, 0, 0]\n"
        ));
        let want = expected([1.0, 0.0, 0.0], Vector3::new(0.0, 0.0, 1.0));
        assert!(close(want, [255, 179, 179]), "{want:?}");
        assert!(
            close(pixel(&f, 20, 20), want),
            "{shading}: {:?}",
            pixel(&f, 20, 20)
        );
    }
}

#[test]
fn a_flat_face_has_the_colour_shade_gives_for_its_normal() {
    // A box turned 0.5 rad about y: its front face has N = (sin 0.5, 0, cos 0.5).
    let f = draw(
        "[image]\nwidth = 61\nheight = 61\n[[object]]\ntype = \"box\"\nsize = [40, 40, 40]\n\
         color = [0, 1, 0]\ntransform = [{ rotate_y = 0.5 }]\n",
    );
    let n = Vector3::new(0.5f32.sin(), 0.0, 0.5f32.cos());
    // The centre pixel sees the front face (it is nearest along +z there).
    assert_eq!(pixel(&f, 30, 30), expected([0.0, 1.0, 0.0], n));
    // Flat: one evaluation per triangle drawn, none per pixel.
    assert_eq!(f.stats.lighting_evals, f.stats.drawn);
}

#[test]
fn pixels_outside_the_silhouette_keep_the_background() {
    // A sphere of radius 10 at the centre of 41×41: every pixel centre
    // farther than 10 from the centre is background.
    let f = draw(
        "[image]\nwidth = 41\nheight = 41\nbackground = [0.2, 0.4, 0.6]\n\
         [[object]]\ntype = \"sphere\"\nn = 24\nr = 10\ncolor = [1, 1, 1]\n",
    );
    let bg = render::to_u8([0.2, 0.4, 0.6]);
    for y in 0..41 {
        for x in 0..41 {
            let (dx, dy) = (x as f32 - 20.0, y as f32 - 20.0);
            if (dx * dx + dy * dy).sqrt() > 10.5 {
                assert_eq!(pixel(&f, x, y), bg, "({x}, {y})");
            }
        }
    }
    assert_ne!(pixel(&f, 20, 20), bg);
}

#[test]
fn overlapping_objects_resolve_by_depth_whichever_is_drawn_first() {
    // Red box in front (z = +50, toward the viewer), blue behind at z = 0.
    let red = "[[object]]\ntype = \"box\"\nsize = [20, 20, 20]\ncolor = [1, 0, 0]\ntransform = [{ translate = [0, 0, 50] }]\n";
    let blue = "[[object]]\ntype = \"box\"\nsize = [30, 30, 30]\ncolor = [0, 0, 1]\n";
    // ks = 0: no white highlight, so red stays (1, 0, 0)·(ka + kd·N·L).
    let head = "[image]\nwidth = 41\nheight = 41\n[material]\nks = 0\n";
    let a = draw(&format!("{head}{red}{blue}"));
    let b = draw(&format!("{head}{blue}{red}"));
    for f in [&a, &b] {
        let c = pixel(f, 20, 20);
        assert!(c[0] > 0 && c[2] == 0, "{c:?}");
        // Where only the blue box is (|x| between 10 and 15): blue.
        let c = pixel(f, 20 + 13, 20);
        assert!(c[2] > 0 && c[0] == 0, "{c:?}");
    }
    assert_eq!(a.rgb, b.rgb);
}

#[test]
fn a_frame_rendered_into_the_last_frames_buffers_is_the_same() {
    // `render_observed` draws into the previous frame's buffers (and each
    // worker thread's z-buffer): the same scene drawn again, and after a
    // different scene of the same size, must give the same frame as a
    // fresh render, down to the depth per pixel.
    let s = scene(MIXED);
    let opt = Options::of(&s);
    let fresh = render::render(&s, &opt).unwrap();
    let other = scene(&MIXED.replace("[0, 0, 0]", "[0.3, -0.2, 0.5]"));
    let mut last = render::render(&other, &opt).unwrap();
    assert_ne!(last.rgb, fresh.rgb);
    for _ in 0..3 {
        last = render::render_observed(&s, &opt, Some(last), &|| {}).unwrap();
        assert_eq!(last.rgb, fresh.rgb);
        assert_eq!(last.ids, fresh.ids);
    }
    let (a, b) = (last.depth(), fresh.depth());
    assert!(a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()));
    // The depth is the z-buffer's: finite where a triangle is, ∞ elsewhere.
    for (z, &id) in a.iter().zip(&last.ids) {
        assert_eq!(z.is_finite(), id != grafika::render::raster::NONE);
    }
}

#[test]
fn a_floor_crossing_the_near_plane_is_clipped_without_artifacts() {
    // Camera 1 above a floor that extends behind it, looking level: the
    // floor's triangles cross the near plane and the plane through the eye.
    // Nothing of the floor can appear above the horizon (the middle row).
    let f = draw(
        "[image]\nwidth = 80\nheight = 60\n\
         [camera]\neye = [0, 1, 0]\nlook = [0, 1, -1]\nup = [0, 1, 0]\n\
         [perspective]\nfovy = 60\nnear = 0.1\nfar = 100\n\
         [[object]]\ntype = \"plane\"\nnx = 5\nnz = 5\ndx = 10\ndz = 10\ncolor = [1, 1, 1]\n\
         transform = [{ translate = [-20, 0, -20] }]\n",
    );
    assert!(f.stats.clipped > 0, "{:?}", f.stats);
    for y in 0..29 {
        for x in 0..80 {
            assert_eq!(
                pixel(&f, x, y),
                [0, 0, 0],
                "floor above the horizon at ({x}, {y})"
            );
        }
    }
    // The bottom row is floor.
    assert!(pixel(&f, 40, 59) != [0, 0, 0]);
    assert!(f.depth().iter().all(|z| !z.is_nan()));
}

#[test]
fn an_open_mesh_seen_from_behind_is_not_culled() {
    // A plane faces +y; tilted by −0.5 about x it shows its underside to
    // the viewer. It has open edges, so it must still be drawn.
    let f = draw(
        "[image]\nwidth = 60\nheight = 60\n[tilt]\nx = -0.5\n\
         [[object]]\ntype = \"plane\"\nnx = 3\nnz = 3\ndx = 20\ndz = 20\ncolor = [1, 1, 1]\n\
         transform = [{ translate = [-20, 0, -20] }]\n",
    );
    assert_eq!(f.stats.culled, 0);
    assert!(f.stats.pixels_shaded > 100, "{:?}", f.stats);
    // A closed box seen the same way has its back faces culled.
    let g =
        draw("[image]\nwidth = 60\nheight = 60\n[[object]]\ntype = \"box\"\nsize = [20, 20, 20]\n");
    // Seen along z only the +z face faces the viewer; the other five (four
    // edge-on, one turned away) are culled: 5 faces × 2 triangles.
    assert_eq!(g.stats.culled, 10);
}

fn grafika() -> Command {
    Command::cargo_bin("grafika").unwrap()
}

fn bad(text: &str, want: &[&str]) {
    let dir = std::env::temp_dir().join(format!("grafika-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(format!("s{}.toml", text.len()));
    std::fs::write(&p, text).unwrap();
    let out = grafika()
        .args(["render"])
        .arg(&p)
        .args(["-o"])
        .arg(dir.join("x.png"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    for w in want {
        assert!(err.contains(w), "`{w}` not in: {err}");
    }
}

#[test]
fn bad_scene_files_name_line_and_column_and_exit_2() {
    bad("[[object]]\ntype = \"pyramid\"\n", &[":2:", "pyramid"]);
    bad(
        "[[object]]\ntype = \"cone\"\nn = -4\nr = 1\nh = 1\n",
        &[":3:", "-4"],
    );
    bad(
        "[[object]]\ntype = \"sphere\"\nn = 8\nr = inf\n",
        &[":4:", "finite"],
    );
    bad(
        "\n\n[[object]]\ntype = \"obj\"\npath = \"no/such/model.obj\"\n",
        &[":3:", "model.obj"],
    );
    bad(
        "[[object]]\ntype = \"sphere\"\nn = 8\nr = 1\nwobble = 2\n",
        &[":5:", "wobble"],
    );
}

#[test]
fn same_png_bytes_at_any_thread_count() {
    let dir = std::env::temp_dir().join(format!("grafika-thr-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "shading = \"phong\"\n[image]\nwidth = 96\nheight = 96\n\
         [[object]]\ntype = \"sphere\"\nn = 12\nr = 40\nface_colors = [[1, 0, 0], [0, 1, 0]]\n\
         [[object]]\ntype = \"box\"\nsize = [50, 50, 50]\ncolor = [0, 0, 1]\n",
    )
    .unwrap();
    let mut bytes = Vec::new();
    for t in ["1", "2", "3"] {
        let png = dir.join(format!("t{t}.png"));
        grafika()
            .arg("render")
            .arg(&scene)
            .arg("-o")
            .arg(&png)
            .args(["--threads", t])
            .assert()
            .success();
        bytes.push(std::fs::read(&png).unwrap());
    }
    assert_eq!(bytes[0], bytes[1]);
    assert_eq!(bytes[0], bytes[2]);
}

#[test]
fn explain_pixel_shows_the_lighting_steps_and_the_pixel() {
    let dir = std::env::temp_dir().join(format!("grafika-exp-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("s.toml");
    std::fs::write(
        &scene,
        "shading = \"phong\"\n[image]\nwidth = 41\nheight = 41\n\
         [[object]]\ntype = \"sphere\"\nn = 16\nr = 15\ncolor = [1, 0, 0]\n",
    )
    .unwrap();
    let out = grafika()
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(dir.join("e.png"))
        .args(["--explain-pixel", "20,20"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("Barycentric"), "{text}");
    assert!(text.contains("lighting::shade"), "{text}");
    assert!(
        text.contains("(255, 179, 179)") || text.contains("(255, 178, 178)"),
        "{text}"
    );
    // A background pixel says so.
    let out = grafika()
        .arg("render")
        .arg(&scene)
        .arg("-o")
        .arg(dir.join("e.png"))
        .args(["--explain-pixel", "0,0", "--force"])
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&out.stdout).contains("background"));
}

#[test]
fn what_a_scene_does_not_need_is_skipped_and_counted() {
    // A box far to the right of the 41-pixel-wide window: its bounding box
    // is wholly beyond x = xmax, so it is rejected whole (12 triangles).
    // A point light 10 units from the visible box with range 1 never
    // reaches it; ks = 0 means no specular work at all.
    let f = draw(
        "[image]\nwidth = 41\nheight = 41\n[material]\nks = 0\n\
         [[light]]\ntype = \"point\"\nposition = [0, 0, 30]\nrange = 1\n\
         [[light]]\ntype = \"directional\"\ndirection = [0, 0, 1]\n\
         [[object]]\ntype = \"box\"\nsize = [10, 10, 10]\ncolor = [1, 1, 1]\n\
         [[object]]\ntype = \"box\"\nsize = [10, 10, 10]\ntransform = [{ translate = [500, 0, 0] }]\n",
    );
    assert_eq!(f.stats.objects_rejected, 1);
    assert_eq!(f.stats.rejected, 12);
    assert_eq!(f.stats.lights_skipped, 1, "{:?}", f.stats);
    // Counted for the object that is drawn (the rejected one never gets that far).
    assert_eq!(f.stats.specular_skipped, 1);
    // The front face (N = L = (0,0,1)) lit by the directional light only:
    // ka + kd·1 = 0.4 + 0.6 = 1 → white.
    assert_eq!(pixel(&f, 20, 20), [255, 255, 255]);
}

/// Every scene in problems/render/ renders (at a small size, to stay fast),
/// writes a PNG of that size, and draws something besides the background.
#[test]
fn every_scene_in_problems_render_renders() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/render");
    let out = std::env::temp_dir().join(format!("grafika-scenes-{}", std::process::id()));
    std::fs::create_dir_all(&out).unwrap();
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let png = out.join(path.file_stem().unwrap()).with_extension("png");
        grafika()
            .args([
                "render",
                path.to_str().unwrap(),
                "-o",
                png.to_str().unwrap(),
                "--width",
                "160",
                "--height",
                "120",
                "--json",
            ])
            .assert()
            .success();
        let decoder =
            png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&png).unwrap()));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (160, 120), "{path:?}");
        let px = info.line_size / info.width as usize;
        let first = &buf[..px];
        let drawn = buf[..info.buffer_size()]
            .chunks(px)
            .filter(|p| *p != first)
            .count();
        assert!(drawn > 100, "{path:?} drew only {drawn} pixels");
        n += 1;
    }
    assert!(n >= 14, "expected the chapter's scenes, the camera scene, the bunny and the bench sphere; found {n}");
    let _ = std::fs::remove_dir_all(&out);
}

/// A camera scene that sends the eight-lane Phong batches down every
/// branch: vertex colours (interpolated) beside one-colour triangles, a
/// point light whose range ends inside the picture, a spot light whose
/// cones cross the surfaces, a directional light, and the specular term
/// only where the surface is lit.
const MIXED: &str = include_str!("common/mixed.toml");

#[test]
fn phong_pixels_lit_eight_at_a_time_match_the_one_pixel_path() {
    // The band pass lights Phong pixels in batches of eight lanes; the
    // explainer (`pixel_color`) lights one pixel at a time through the
    // same `lighting::shade` body at Fast32. Every lane is computed with
    // the same f32 operations, so every pixel must agree to the bit.
    // A Phong frame keeps no corners: they are made again per triangle
    // through the renderer's own geometry (`explain_geometry`).
    let s = scene(MIXED);
    let opt = Options::of(&s);
    let f = render::render(&s, &opt).unwrap();
    let mut made = std::collections::HashMap::new();
    let mut checked = 0;
    for y in 0..f.height {
        for x in 0..f.width {
            let t = f.ids[(y * f.width + x) as usize];
            if t == grafika::render::raster::NONE {
                continue;
            }
            let g = made.entry(t).or_insert_with(|| {
                let mut rec = grafika::stages::trace::Recorder::new();
                grafika::tutor::pixel::explain_geometry(&s, &opt, &f, t, &mut rec).unwrap()
            });
            assert!(g.same, "triangle {t}");
            let (tri, c) = (&f.tris[t as usize], &g.corners);
            let one = render::pixel_color(tri, c, x, y, &f.looks, f.ortho, &mut NoTrace);
            assert_eq!(pixel(&f, x, y), render::to_u8(one), "pixel ({x}, {y})");
            checked += 1;
        }
    }
    // Both objects are in view and cover a good part of the picture.
    assert!(checked > 1500, "{checked}");
    assert!(f.looks.len() == 2 && f.stats.lights_skipped == 0);
}

#[test]
fn a_spot_light_lights_its_cone_and_leaves_the_rest_ambient() {
    // A white wall z = −2 facing the camera, lit only by a spot at the eye
    // pointing down −z with full cones θ = 20°, φ = 40°. Along the axis ρ = 1
    // ≥ cos 10°: full light, N·L = 1, so C = ka + kd = 0.2 + 0.7 = 0.9 (no
    // specular: ks = 0). At the picture's corner the angle off the axis is
    // atan(√(tan²(fovy/2)·(1 + aspect²))) ≈ 34.7° > 20° = φ/2: outside the
    // outer cone the spot adds nothing, not even its ambient (Spot = 0), so
    // C = 0 from the light and the pixel is black.
    let f = draw(
        "shading = \"phong\"\n[image]\nwidth = 81\nheight = 61\n\
         [camera]\neye = [0, 0, 0]\nlook = [0, 0, -1]\nup = [0, 1, 0]\n\
         [perspective]\nfovy = 50\nnear = 0.1\nfar = 50\n\
         [material]\nka = 0.2\nkd = 0.7\nks = 0\n\
         [[light]]\ntype = \"spot\"\nposition = [0, 0, 0]\naxis = [0, 0, -1]\n\
         theta = 20\nphi = 40\n\
         [[object]]\ntype = \"plane\"\nnx = 4\nnz = 4\ndx = 2\ndz = 2\ncolor = [1, 1, 1]\n\
         transform = [{ rotate_x = 1.5707963267948966 }, { translate = [-4, 4, -2] }]\n",
    );
    let want = render::to_u8([0.9, 0.9, 0.9]);
    assert!(close(pixel(&f, 40, 30), want), "{:?}", pixel(&f, 40, 30));
    assert_eq!(pixel(&f, 0, 0), [0, 0, 0]);
    assert_eq!(pixel(&f, 80, 60), [0, 0, 0]);
}

/// Issue 18: `render -o -` writes the PNG, and only the PNG, on standard
/// output (the summary goes to stderr); the bytes equal those of a file.
#[test]
fn render_to_stdout_writes_only_the_png() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/render/cone-flat.toml");
    let out = grafika()
        .args(["render", scene.to_str().unwrap(), "-o", "-"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(
        &out.stdout[..8],
        b"\x89PNG\r\n\x1a\n",
        "not a PNG signature"
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("image = -"));
    let dir = std::env::temp_dir().join(format!("grafika-stdout-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("cone.png");
    grafika()
        .args([
            "render",
            scene.to_str().unwrap(),
            "-o",
            file.to_str().unwrap(),
        ])
        .assert()
        .success();
    assert_eq!(std::fs::read(&file).unwrap(), out.stdout);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The JSON steps of `render SCENE --explain-pixel X,Y --json` (extra
/// arguments after), the PNG written to a temporary file.
fn explain_steps(scene: &str, px: &str, extra: &[&str]) -> Vec<serde_json::Value> {
    let dir = std::env::temp_dir().join(format!("grafika-explain-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = grafika()
        .arg("render")
        .arg(root.join(scene))
        .arg("-o")
        .arg(dir.join(format!("{}.png", px.replace(',', "-"))))
        .args(["--explain-pixel", px, "--json", "--force"])
        .args(extra)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    v["steps"].as_array().unwrap().clone()
}

/// The first step whose title starts with `title`.
fn step<'a>(steps: &'a [serde_json::Value], title: &str) -> &'a serde_json::Value {
    steps
        .iter()
        .find(|s| s["title"].as_str().unwrap().starts_with(title))
        .unwrap_or_else(|| panic!("no step `{title}`"))
}

/// A list of numbers in a step as f64.
fn nums(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn near(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= tol, "{got:?} vs {want:?}");
    }
}

/// "(X, Y)" as two integers.
fn pair(v: &serde_json::Value) -> [i64; 2] {
    let s = v.as_str().unwrap().trim_matches(|c| c == '(' || c == ')');
    let (a, b) = s.split_once(", ").unwrap();
    [a.parse().unwrap(), b.parse().unwrap()]
}

#[test]
fn explain_pixel_runs_a_vertex_through_the_stages_as_derived_by_hand() {
    // camera-triangle-scene: eye Pe = (3, 1, 3), look-at (2, 1, 2), up
    // (0, 1, 0), near 0.1, far 10, fovy 45°, aspect 2, 400 × 200 pixels.
    // Pixel (200, 195) is on the floor (translated by (−3.25, 0, −3.25));
    // its triangle's first vertex is the object point (4, 0, 4), so by hand:
    //   world  Pw = (0.75, 0, 0.75);
    //   n = (Pe − Pr)/|Pe − Pr| = (1, 0, 1)/√2, u = Vup × n/|…| =
    //   (1, 0, −1)/√2, v = n × u = (0, 1, 0); Pw − Pe = (−2.25, −1, −2.25):
    //   eye    P' = (u·, v·, n·) = (0, −1, −4.5/√2 = −2.25√2 ≈ −3.181981);
    //   top = 0.1·tan 22.5° = 0.1(√2 − 1), right = 2·top: near/right =
    //   (√2 + 1)/2, near/top = √2 + 1, and z_c = −(10.1/9.9)·z − 2/9.9,
    //   w = −z:
    //   clip   c = (0, −(√2 + 1), (22.725√2 − 2)/9.9, 2.25√2)
    //            ≈ (0, −2.414214, 3.044239, 3.181981);
    //   division yn = −(√2 + 1)/(2.25√2) ≈ −0.758714, xn = 0;
    //   viewport px = (xn + 1)/2·400 = 200, py = (yn + 1)/2·200 ≈ 24.1286,
    //   row = 200 − py ≈ 175.8714; snapped X = 256·200 = 51200,
    //   Y = round(256·175.8714) = round(45023.07) = 45023.
    let steps = explain_steps("problems/render/camera-triangle-scene.toml", "200,195", &[]);
    let r2 = std::f64::consts::SQRT_2;
    let world = step(&steps, "World coordinates of V0");
    near(&nums(&world["values"]["V0"]), &[4.0, 0.0, 4.0], 0.0);
    near(&nums(&world["result"]["V0w"]), &[0.75, 0.0, 0.75], 1e-6);
    let eye = step(&steps, "Eye coordinates of V0");
    near(&nums(&eye["result"]["V0'"]), &[0.0, -1.0, -2.25 * r2], 1e-5);
    let clip = step(&steps, "Clip coordinates of V0");
    let want = [0.0, -(r2 + 1.0), (22.725 * r2 - 2.0) / 9.9, 2.25 * r2];
    near(&nums(&clip["result"]["c"]), &want, 1e-5);
    let code = step(&steps, "Outcode of V0");
    assert_eq!(code["result"]["code"], "000000");
    let div = step(&steps, "Perspective division of V0");
    let yn = -(r2 + 1.0) / (2.25 * r2);
    near(&nums(&div["result"]["(xn, yn, zn)"])[..2], &[0.0, yn], 1e-6);
    let row = step(&steps, "Pixel row of V0");
    near(
        &nums(&row["result"]["(x, row)"]),
        &[200.0, 200.0 - (yn + 1.0) * 100.0],
        1e-4,
    );
    let snap = step(&steps, "Snapping V0");
    assert_eq!(pair(&snap["result"]["(X, Y)"]), [51200, 45023]);
    // The pixel position explained is the one the rasterizer used: the
    // triangle made again equals the frame's, and the pixel's centre
    // (256·200 + 128, 256·195 + 128) is inside its snapped vertices.
    let set_up = step(&steps, "The triangle set up");
    assert_eq!(set_up["result"]["same as the rasterizer's"], true);
    let v: Vec<[i64; 2]> = (0..3)
        .map(|k| pair(&set_up["values"][format!("vertex {k} (X, Y)")]))
        .collect();
    assert_eq!(v[0], [51200, 45023]);
    let (cx, cy) = (200 * 256 + 128, 195 * 256 + 128);
    let edge = |a: [i64; 2], b: [i64; 2]| (b[0] - a[0]) * (cy - a[1]) - (b[1] - a[1]) * (cx - a[0]);
    let e = [edge(v[0], v[1]), edge(v[1], v[2]), edge(v[2], v[0])];
    assert!(
        e.iter().all(|&x| x >= 0) || e.iter().all(|&x| x <= 0),
        "{e:?}"
    );
    // In the order the course teaches, before the pixel's own steps.
    let at = |t: &str| {
        steps
            .iter()
            .position(|s| s["title"].as_str().unwrap().starts_with(t))
    };
    let order = [
        "World coordinates of V0",
        "Eye coordinates of V0",
        "Clip coordinates of V0",
        "Outcode of V0",
        "Perspective division of V0",
        "Window point of V0",
        "Viewport coordinates of V0",
        "Pixel row of V0",
        "Snapping V0",
        "The triangle set up",
        "Depth at the pixel",
        "Barycentric",
    ];
    let pos: Vec<usize> = order.iter().map(|t| at(t).unwrap()).collect();
    assert!(pos.windows(2).all(|w| w[0] < w[1]), "{pos:?}");
    assert!(at("Projection matrix").unwrap() < pos[0]);
}

#[test]
fn explain_pixel_shows_the_clipping_of_a_triangle_that_crosses_a_plane() {
    // Pixel (10, 195): a floor triangle that reaches past the left edge of
    // the view: its polygon is clipped (Sutherland–Hodgman in clip space),
    // and the explained fan triangle is the rasterizer's.
    let steps = explain_steps("problems/render/camera-triangle-scene.toml", "10,195", &[]);
    let clip: Vec<&serde_json::Value> = steps
        .iter()
        .filter(|s| s["title"].as_str().unwrap().starts_with("Clipping against"))
        .collect();
    assert!(!clip.is_empty());
    let left = step(&steps, "Clipping against the left plane (bit 1)");
    for t in nums(&left["result"]["t"]) {
        assert!((0.0..=1.0).contains(&t), "{t}");
    }
    // Every vertex of the clipped polygon lies on or inside x = −w.
    for v in left["result"]["clipped polygon"].as_array().unwrap() {
        let c = nums(v);
        assert!(c[0] + c[3] >= -1e-5 * c[3].abs(), "{c:?}");
    }
    let some_vertex_is_out =
        (0..3).any(|k| step(&steps, &format!("Outcode of V{k}"))["result"]["code"] != "000000");
    assert!(some_vertex_is_out);
    let set_up = step(&steps, "The triangle set up");
    assert_eq!(set_up["result"]["same as the rasterizer's"], true);
    assert!(steps
        .iter()
        .any(|s| s["title"] == "Snapping Q0 to 1/256 pixel"));
}

/// The values of a step are named in the reader's words in the text (the
/// polygon clipped plane by plane was named in English under `--lang id`)
/// and under the same English keys in the JSON of every language.
#[test]
fn explain_pixel_names_the_clipped_polygon_in_indonesian_and_keys_it_in_english() {
    let scene = "problems/render/camera-triangle-scene.toml";
    let id = explain_steps(scene, "10,195", &["--lang", "id"]);
    let clipped = id
        .iter()
        .filter(|s| s["result"]["clipped polygon"].is_array());
    assert!(clipped.count() >= 1);
    assert!(id
        .iter()
        .any(|s| s["values"]["polygon (x, y, z, w)"].is_array()));
    let dir = std::env::temp_dir().join(format!("grafika-poligon-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = grafika()
        .args(["--lang", "id", "render"])
        .arg(root.join(scene))
        .arg("-o")
        .arg(dir.join("cut.png"))
        .args(["--explain-pixel", "10,195", "--force"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("\n    poligon (x, y, z, w) =\n"), "{text}");
    assert!(text.contains("\n  ⇒ poligon hasil clipping =\n"), "{text}");
    assert!(!text.contains("polygon"), "{text}");
}

#[test]
fn explain_pixel_speaks_indonesian_with_the_same_numbers() {
    let en = explain_steps("problems/render/cone-flat.toml", "330,150", &[]);
    let id = explain_steps(
        "problems/render/cone-flat.toml",
        "330,150",
        &["--lang", "id"],
    );
    assert_eq!(en.len(), id.len());
    // The cone's box is inside the view volume: the renderer took every
    // code as 000000, and the explainer still shows the test, saying so.
    let code = step(&en, "Outcode of V0");
    assert_eq!(code["result"]["code"], "000000");
    assert!(code["note"]
        .as_str()
        .unwrap()
        .contains("bounding box is inside"));
    assert!(id.iter().any(|s| s["title"] == "Koordinat clip titik V0"));
    assert!(id
        .iter()
        .any(|s| s["title"] == "Pembagian perspektif titik V1"));
    for (a, b) in en.iter().zip(&id) {
        assert_eq!(a["result"], b["result"]);
    }
}

/// `--stats` of a scene mixing flat and Gouraud objects, in both
/// languages: the summary is headed as a render (it answers no question),
/// every value of the table starts in one column (after the longest
/// label), and the per-pixel line names both shadings drawn.
#[test]
fn render_stats_line_up_and_name_every_shading_drawn() {
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/render/spheres-flat-gouraud.toml"
    );
    for (lang, heading, per_pixel) in [
        ("en", "Render", "none (flat and gouraud shading)"),
        ("id", "Hasil render", "tidak ada (flat dan gouraud shading)"),
    ] {
        let out = grafika()
            .args(["render", scene, "-o", "-", "--stats", "--lang", lang])
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stderr).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines.contains(&heading), "{lang}: {text}");
        assert!(
            !text.contains("Answer") && !text.contains("Jawaban"),
            "{text}"
        );
        let at = lines.iter().position(|l| l.starts_with("Stat")).unwrap();
        let rows: Vec<&str> = lines[at + 1..]
            .iter()
            .copied()
            .filter(|l| !l.is_empty())
            .collect();
        assert!(rows.len() > 15, "{text}");
        // Every value but the per-pixel words starts with a digit, and no
        // label has one: the column of a value is its first digit's.
        let column = |l: &str| l.chars().position(|c| c.is_ascii_digit());
        let first = column(rows[0]).unwrap();
        for l in rows.iter().filter(|l| !l.contains(per_pixel)) {
            assert_eq!(column(l), Some(first), "{lang}: {l:?} in\n{text}");
        }
        let row = rows.iter().find(|l| l.ends_with(per_pixel));
        let row = row.unwrap_or_else(|| panic!("{lang}: {text}"));
        assert_eq!(
            row.chars().count() - per_pixel.chars().count(),
            first,
            "{text}"
        );
    }
}

/// The HTML page of a render names the summary in the page's language
/// (its JSON key in each row's title), under a render's heading.
#[test]
fn render_page_names_the_summary_in_indonesian() {
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/render/cone-flat.toml"
    );
    let dir = std::env::temp_dir().join(format!("grafika-render-page-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("cone.html");
    let _ = std::fs::remove_file(&page);
    grafika()
        .args([
            "render", scene, "-o", "-", "--repeat", "3", "--lang", "id", "--html",
        ])
        .arg(&page)
        .assert()
        .success();
    let html = std::fs::read_to_string(&page).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(html.contains("<h2>Hasil render</h2>"), "{html}");
    for (key, words) in [
        ("triangles drawn", "segitiga digambar"),
        ("pixels shaded", "piksel diwarnai"),
        ("frame time (median of 3)", "waktu per bingkai"),
    ] {
        let row = html.find(&format!("<th title=\"{key}\">")).unwrap();
        let cell = &html[row..row + html[row..].find("</th>").unwrap()];
        assert!(cell.contains(words), "{key}: {cell}");
        assert!(!cell.contains(&format!(">{key}<")), "{key}: {cell}");
    }
}
