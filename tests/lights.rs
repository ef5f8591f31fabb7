//! One `[[light]]` table in problem, lights and scene files (issue 24): every
//! light shipped in `problems/` (problem files and scenes) and in the test
//! scene, pasted as written into each other kind of file, is the same light
//! and lights a surface the same; the defaults and the old name of a spot's
//! axis hold in all three. Expected values are derived by hand in comments.

mod common;

use grafika::input::lights::{build, LightsFileIn, Setup, ShadeIn};
use grafika::input::problem::ProblemIn;
use grafika::input::scene::Scene;
use grafika::num::vec::v3;
use grafika::stages::lighting::{self, Light, LightKind, Material, Surface};
use grafika::stages::trace::NoTrace;
use std::path::Path;

/// The `[[light]]` tables of a file, each as written: from its header to
/// the next table header (or the end).
fn light_tables(text: &str) -> Vec<String> {
    let mut tables: Vec<String> = Vec::new();
    let mut inside = false;
    for line in text.lines() {
        if line.trim_start().starts_with('[') {
            inside = line.trim() == "[[light]]";
            if inside {
                tables.push(String::new());
            }
        }
        if let (true, Some(t)) = (inside, tables.last_mut()) {
            t.push_str(line);
            t.push('\n');
        }
    }
    tables
}

/// Every shipped file with `[[light]]` tables, and its tables.
fn shipped() -> Vec<(String, Vec<String>)> {
    let root = common::root();
    let mut files: Vec<_> = ["problems", "problems/render"]
        .iter()
        .flat_map(|d| std::fs::read_dir(root.join(d)).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.push(root.join("tests/common/mixed.toml"));
    files.sort();
    files
        .iter()
        .map(|p| (p.display().to_string(), std::fs::read_to_string(p).unwrap()))
        .map(|(name, text)| (name, light_tables(&text)))
        .filter(|(_, tables)| !tables.is_empty())
        .collect()
}

/// The lighting point of the pasted files: N = (0, 0, 1), white, at the
/// origin, seen along +z.
const SHADE: &str = "[shade]\nnormal = [0, 0, 1]\ncolor = [1, 1, 1]\n";

fn shade_in() -> ShadeIn {
    let p = ProblemIn::parse(&format!("title = \"t\"\n{SHADE}"), "p.toml").unwrap();
    p.shade.unwrap()
}

/// `tables` pasted into a problem file, built at f32 as `solve --precision
/// f32` builds them.
fn in_problem(tables: &str) -> Setup<f32> {
    let p = ProblemIn::parse(&format!("title = \"t\"\n{SHADE}\n{tables}"), "p.toml").unwrap();
    let file = LightsFileIn {
        global_ambient: None,
        material: None,
        light: p.light.clone(),
    };
    build(
        p.shade.as_ref().unwrap(),
        &file,
        "shade.",
        "light",
        &mut NoTrace,
    )
    .unwrap()
}

/// `tables` as a lights file (`shade --lights`), at f32.
fn in_lights_file(tables: &str) -> Vec<Light<f32>> {
    let file = LightsFileIn::parse(tables, "l.toml").unwrap();
    build(&shade_in(), &file, "", "light", &mut NoTrace)
        .unwrap()
        .lights
}

/// `tables` pasted into a scene with one box.
fn in_scene(tables: &str) -> Result<Vec<Light<f32>>, grafika::error::Error> {
    let text = format!("{tables}\n[[object]]\ntype = \"box\"\nsize = [1, 1, 1]\n");
    Scene::parse(&text, "s.toml", Path::new(".")).map(|s| s.lights)
}

/// The colour of a white surface with the text's material under `lights`,
/// at the origin and at (1, −2, 0.5), for several normals.
fn lighting_of(lights: &[Light<f32>]) -> Vec<[f32; 3]> {
    let m = Material::text_default([1.0f32, 1.0, 1.0]);
    let normals = [(0.0, 0.0, 1.0), (0.6, 0.0, 0.8), (0.0, -0.8, 0.6)];
    let points = [(0.0, 0.0, 0.0), (1.0, -2.0, 0.5)];
    let mut out = Vec::new();
    for (px, py, pz) in points {
        for (x, y, z) in normals {
            let s = Surface {
                normal: v3(x, y, z),
                view: v3(0.0, 0.0, 1.0),
                position: v3(px, py, pz),
                camera: None,
            };
            out.push(lighting::shade(&m, lights, &s, &mut NoTrace).color);
        }
    }
    out
}

/// The test: each shipped light, pasted as written into a problem
/// file, a lights file and a scene, is the same light in all three, and so
/// lights the same (the renderer's f32 is what a scene and `solve
/// --precision f32` share).
#[test]
fn every_shipped_light_is_the_same_light_in_every_kind_of_file() {
    let files = shipped();
    let count: usize = files.iter().map(|(_, t)| t.len()).sum();
    // 7 in problems/shade-*.toml, 3 in the scenes of problems/render, 3 in
    // the test scene: a table the reader missed would make this pass idly.
    assert!(count >= 13, "only {count} light tables found in {files:?}");
    for (file, tables) in &files {
        for (i, table) in tables.iter().enumerate() {
            let from_problem = in_problem(table).lights;
            let from_lights = in_lights_file(table);
            let from_scene = in_scene(table).unwrap_or_else(|e| panic!("{file} #{i}: {e}"));
            assert_eq!(from_problem.len(), 1, "{file} #{i}");
            assert_eq!(from_problem, from_lights, "{file} #{i}: lights file");
            assert_eq!(from_problem, from_scene, "{file} #{i}: scene");
            let lit = lighting_of(&from_problem);
            assert_eq!(lit, lighting_of(&from_scene), "{file} #{i}");
        }
        // All the file's lights together light the same as well.
        let all = tables.concat();
        let lit = lighting_of(&in_problem(&all).lights);
        assert_eq!(lit, lighting_of(&in_scene(&all).unwrap()), "{file}");
        assert_eq!(lit, lighting_of(&in_lights_file(&all)), "{file}");
    }
}

/// Each kind of file fills in the same defaults: a directional light along
/// the text's L = (0, 0, 1); a spot with θ = 30°, φ = 45°, falloff 1; white
/// colours, `color` giving diffuse and specular; attenuation (1, 0, 0) and
/// no range.
#[test]
fn the_defaults_are_the_same_in_every_kind_of_file() {
    let tables = "[[light]]\ntype = \"directional\"\n\
                  [[light]]\ntype = \"spot\"\nposition = [0, 0, 5]\naxis = [0, 0, -2]\n\
                  [[light]]\ntype = \"point\"\nposition = [1, 2, 3]\ncolor = [1, 0.5, 0]\n";
    let want = [
        Light::directional(v3(0.0f32, 0.0, 1.0)),
        Light {
            // The axis (0, 0, −2) made a unit vector.
            kind: LightKind::Spot {
                pos: v3(0.0, 0.0, 5.0),
                dir: v3(0.0, 0.0, -1.0),
                theta: 30.0,
                phi: 45.0,
                falloff: 1.0,
            },
            ..Light::directional(v3(0.0, 0.0, 1.0))
        },
        Light {
            kind: LightKind::Point {
                pos: v3(1.0, 2.0, 3.0),
            },
            ambient: [1.0; 3],
            diffuse: [1.0, 0.5, 0.0],
            specular: [1.0, 0.5, 0.0],
            attenuation: [1.0, 0.0, 0.0],
            range: None,
        },
    ];
    assert_eq!(in_problem(tables).lights, want);
    assert_eq!(in_lights_file(tables), want);
    assert_eq!(in_scene(tables).unwrap(), want);
}

/// A spot's axis is `axis`; `direction`, its name in scene files before the
/// one schema, is still read, in every kind of file, as the same axis.
/// Both at once is an error on `direction`, with its line and column.
#[test]
fn a_spots_old_direction_key_is_its_axis() {
    let spot = |key: &str| {
        format!(
            "[[light]]\ntype = \"spot\"\nposition = [0, 0, 4]\n{key} = [0, 1, -1]\ntheta = 20\nphi = \"pi/4 rad\"\n"
        )
    };
    let (new, old) = (spot("axis"), spot("direction"));
    let axis = in_problem(&new).lights;
    // (0, 1, −1)/√2, and φ = π/4 rad = 45°.
    let LightKind::Spot { dir, phi, .. } = &axis[0].kind else {
        panic!("{axis:?}")
    };
    let h = (0.5f32).sqrt();
    assert!((dir[1] - h).abs() < 1e-6 && (dir[2] + h).abs() < 1e-6 && dir[0] == 0.0);
    assert!((phi - 45.0).abs() < 1e-5, "{phi}");
    assert_eq!(in_problem(&old).lights, axis);
    assert_eq!(in_lights_file(&old), axis);
    assert_eq!(in_scene(&old).unwrap(), axis);
    assert_eq!(in_scene(&new).unwrap(), axis);
    let both = format!("{new}direction = [0, 0, -1]\n");
    let e = in_scene(&both).unwrap_err();
    assert_eq!(e.field, "light[0].direction");
    assert!(e.message.plain().starts_with("s.toml:7:13:"), "{e}");
}

/// A bad light is refused alike in every kind of file: the field names the
/// light and its key, the message starts with where the key's value (or,
/// for a key missing, the table) stands, and the reason is the same.
#[test]
fn a_bad_light_is_the_same_error_in_every_kind_of_file() {
    let cases = [
        // (light, field, line:col within the light's text)
        (
            "type = \"point\"\nposition = [0, 0, 2]\ndirection = [0, 0, 1]\n",
            "direction",
            "4:13",
        ),
        (
            "type = \"directional\"\ndirection = [0, 0, 0]\n",
            "direction",
            "3:13",
        ),
        (
            "type = \"spot\"\nposition = [0, 0, 2]\ntheta = 50\nphi = 40\naxis = [0, 0, -1]\n",
            "theta",
            "4:9",
        ),
        (
            "type = \"point\"\nposition = [0, 0, 2]\nrange = \"-1/2\"\n",
            "range",
            "4:9",
        ),
        (
            "type = \"point\"\nposition = [0, 0, 2]\ndiffuse = [1, 1.5, 0]\n",
            "diffuse",
            "4:11",
        ),
        (
            "type = \"directional\"\ncolor = [0, 0, -1]\n",
            "color",
            "3:9",
        ),
        (
            "type = \"point\"\nattenuation = [0, 0, 0]\n",
            "position",
            "1:1",
        ),
    ];
    for (body, key, at) in cases {
        // The second light of each file, after a good one of 3 lines.
        let tables = format!("[[light]]\ntype = \"directional\"\n\n[[light]]\n{body}");
        let (line, col) = at.split_once(':').unwrap();
        let line: usize = line.parse::<usize>().unwrap() + 3;
        let place = |file: &str, first: usize| format!("{file}:{}:{col}:", line + first);
        let problem = format!("title = \"t\"\n{SHADE}\n{tables}");
        let errors = [
            (ProblemIn::parse(&problem, "p.toml").and_then(|p| {
                let file = LightsFileIn {
                    global_ambient: None,
                    material: None,
                    light: p.light.clone(),
                };
                build::<f64>(
                    p.shade.as_ref().unwrap(),
                    &file,
                    "shade.",
                    "light",
                    &mut NoTrace,
                )
            }))
            .unwrap_err(),
            LightsFileIn::parse(&tables, "l.toml")
                .and_then(|f| build::<f64>(&shade_in(), &f, "", "light", &mut NoTrace))
                .unwrap_err(),
            in_scene(&tables).unwrap_err(),
        ];
        let firsts = [("p.toml", 5), ("l.toml", 0), ("s.toml", 0)];
        for (e, (file, first)) in errors.iter().zip(firsts) {
            assert_eq!(e.field, format!("light[1].{key}"), "{body}: {e}");
            let msg = e.message.plain();
            assert!(msg.starts_with(&place(file, first)), "{body}: {e}");
        }
        let reason =
            |e: &grafika::error::Error| e.message.plain().splitn(4, ':').nth(3).map(str::to_string);
        assert_eq!(reason(&errors[0]), reason(&errors[1]), "{body}");
        assert_eq!(reason(&errors[0]), reason(&errors[2]), "{body}");
    }
}

/// The bunny's light, direction (0.4, 0.6, 1), pasted into a lighting
/// problem whose normal is that same direction: L = N, so cos α = 1 and the
/// text's Lambert colour on white is kd + ka = 0.6 + 0.4 = 1 (end to end).
#[test]
fn the_bunnys_light_in_a_problem_lights_along_its_direction() {
    let text = std::fs::read_to_string(common::root().join("problems/render/bunny.toml")).unwrap();
    let tables = light_tables(&text);
    let problem = format!(
        "title = \"t\"\n[shade]\nmodel = \"lambert\"\nnormal = [\"2/5\", \"3/5\", 1]\ncolor = [1, 1, 1]\n\n{}",
        tables.concat()
    );
    let dir = std::env::temp_dir().join(format!("grafika-lights-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("bunny-light.toml");
    std::fs::write(&f, problem).unwrap();
    let j = common::json_ok(&["solve", f.to_str().unwrap()]);
    let s = &j["result"]["shade"];
    assert_eq!(s["cos_alpha"], 1.0, "{s}");
    for c in 0..3 {
        assert_eq!(s["color"][c], 1.0, "{s}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
