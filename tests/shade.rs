//! `grafika shade` and lighting problems end to end. Expected values are
//! derived by hand in the comments.

use assert_cmd::Command;
use serde_json::Value;

fn grafika() -> Command {
    Command::cargo_bin("grafika").unwrap()
}

fn json(args: &[&str]) -> Value {
    let out = grafika().args(args).arg("--json").output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn rgb(v: &Value) -> [f64; 3] {
    [num(&v[0]), num(&v[1]), num(&v[2])]
}

fn close(a: [f64; 3], b: [f64; 3]) {
    for c in 0..3 {
        assert!((a[c] - b[c]).abs() < 1e-9, "{a:?} vs {b:?}");
    }
}

/// Phong with the text's constants, N = (0,1,1), L = V = (0,0,1), yellow:
/// cos α = √2/2, R = (0,1,0), cos β = 0; C = 0.6·(√2/2)·Cs + 0.4·Cs.
#[test]
fn phong_at_the_texts_defaults() {
    let j = json(&[
        "shade",
        "--light",
        "0,0,1",
        "--normal",
        "0,1,1",
        "--view",
        "0,0,1",
        "--color",
        "1,1,0",
        "--precision",
        "f64",
    ]);
    let r = &j["result"];
    let d = 0.3 * 2f64.sqrt();
    close(rgb(&r["color"]), [d + 0.4, d + 0.4, 0.0]);
    close(rgb(&r["ambient"]), [0.4, 0.4, 0.0]);
    close(rgb(&r["R"]), [0.0, 1.0, 0.0]);
    assert!((num(&r["cos_alpha"]) - 0.5f64.sqrt()).abs() < 1e-12);
    assert!(num(&r["cos_beta"]).abs() < 1e-12);
    assert!(r.get("H").is_none(), "H is for Blinn only");
    assert_eq!(j["command"], "shade");
}

/// Blinn, local viewer: Cp = (−3,0,4), Vp = 0, L = N = (0,0,1):
/// V = (−3/5, 0, 4/5), H = norm((−3/5, 0, 9/5)) = (−1, 0, 3)/√10, N·H = 3/√10.
#[test]
fn blinn_with_a_local_viewer() {
    let j = json(&[
        "shade",
        "--light",
        "0,0,1",
        "--normal",
        "0,0,1",
        "--color",
        "1,0,0",
        "--model",
        "blinn",
        "--camera",
        "-3,0,4",
        "--position",
        "0,0,0",
        "--ks",
        "1",
        "--shininess",
        "2",
    ]);
    let r = &j["result"];
    let k = 10f64.sqrt();
    close(rgb(&r["H"]), [-1.0 / k, 0.0, 3.0 / k]);
    // (3/√10)² = 9/10, times ks = 1
    close(rgb(&r["specular"]), [0.9; 3]);
}

/// Spot penumbra problem file: ρ = 0.8, factor (0.8 − √2/2)/(√3/2 − √2/2);
/// Lambert diffuse 0.6·0.8·factor on white, the light has no ambient.
#[test]
fn solve_spot_penumbra() {
    let j = json(&["solve", "problems/shade-spot-penumbra.toml"]);
    let s = &j["result"]["shade"];
    let (ct, cp) = (3f64.sqrt() / 2.0, 2f64.sqrt() / 2.0);
    let f = (0.8 - cp) / (ct - cp);
    assert!((num(&s["lights"][0]["spot"]) - f).abs() < 1e-9);
    close(rgb(&s["color"]), [0.48 * f; 3]);
}

/// Out of range: only the directional light counts, Lambert on green =
/// 0.6 + 0.4 = 1 on green.
#[test]
fn solve_out_of_range() {
    let j = json(&["solve", "problems/shade-out-of-range.toml"]);
    let s = &j["result"]["shade"];
    assert_eq!(s["lights"][1]["in_range"], Value::Bool(false));
    close(rgb(&s["color"]), [0.0, 1.0, 0.0]);
}

/// Two lights: white directional along N and a blue point light at (0,3,4)
/// with Att = 1/(0.2·5) = 1: L₂ = (0, 0.6, 0.8), cos α₂ = 0.8,
/// R₂ = (0, −0.6, 0.8), cos β₂ = 0.8, 0.8⁴ = 0.4096.
/// blue = 0.4 + 0.6·(1 + 0.8) + 0.7·(1 + 0.4096) = 2.46672; red = 1.7.
#[test]
fn solve_two_lights() {
    let j = json(&["solve", "problems/shade-two-lights.toml"]);
    let s = &j["result"]["shade"];
    close(rgb(&s["unclamped"]), [1.7, 1.7, 2.46672]);
    close(rgb(&s["color"]), [1.0; 3]);
}

#[test]
fn every_lighting_problem_solves() {
    for e in std::fs::read_dir("problems").unwrap() {
        let p = e.unwrap().path();
        if p.file_name()
            .unwrap()
            .to_string_lossy()
            .starts_with("shade-")
        {
            grafika().arg("solve").arg(&p).assert().success();
        }
    }
}

#[test]
fn lights_file() {
    let dir = std::env::temp_dir().join(format!("grafika-lights-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("l.toml");
    // A point light at (0,0,2) with Att = 1/(a2·d²) = 1/(0.25·4) = 1,
    // straight above N: Lambert on white = 0.6 + 0.4·(Ga 0.5 + La 1) = 1.2 → 1.
    std::fs::write(&f, "global_ambient = [0.5, 0.5, 0.5]\n[[light]]\ntype = \"point\"\nposition = [0, 0, 2]\nattenuation = [0, 0, 0.25]\n").unwrap();
    let j = json(&[
        "shade",
        "--lights",
        f.to_str().unwrap(),
        "--normal",
        "0,0,1",
        "--color",
        "1,1,1",
        "--model",
        "lambert",
    ]);
    close(rgb(&j["result"]["unclamped"]), [1.2; 3]);
    // A spot's axis given twice, as `axis` and by its old name `direction`:
    // the error names the second and where it stands.
    std::fs::write(
        &f,
        "[[light]]\ntype = \"spot\"\nposition = [0, 0, 2]\naxis = [0, 0, -1]\ndirection = [0, 0, -1]\n",
    )
    .unwrap();
    let out = grafika()
        .args([
            "shade",
            "--lights",
            f.to_str().unwrap(),
            "--normal",
            "0,0,1",
            "--color",
            "1,1,1",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("light[0].direction") && err.contains("l.toml:5:13"),
        "{err}"
    );
    // An unknown key is a TOML error with file:line:col
    std::fs::write(
        &f,
        "[[light]]\ntype = \"point\"\nposition = [0, 0, 2]\ncolour = [1, 1, 1]\n",
    )
    .unwrap();
    let out = grafika()
        .args([
            "shade",
            "--lights",
            f.to_str().unwrap(),
            "--normal",
            "0,0,1",
            "--color",
            "1,1,1",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("colour") && err.contains("l.toml:4:"), "{err}");
}

fn fails_naming(args: &[&str], field: &str) {
    let out = grafika().args(args).arg("--json").output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    let j: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["error"]["field"], field, "{j}");
}

#[test]
fn errors_exit_2_and_name_the_field() {
    fails_naming(
        &[
            "shade", "--light", "0,0,0", "--normal", "0,0,1", "--color", "1,0,0",
        ],
        "light",
    );
    fails_naming(
        &[
            "shade", "--light", "0,0,1", "--normal", "0,0,0", "--color", "1,0,0",
        ],
        "normal",
    );
    fails_naming(
        &[
            "shade", "--light", "0,0,1", "--normal", "0,0,1", "--view", "0,0,0", "--color", "1,0,0",
        ],
        "view",
    );
    fails_naming(
        &[
            "shade", "--light", "0,0,1", "--normal", "0,0,1", "--color", "1,2,0",
        ],
        "color",
    );
    fails_naming(
        &[
            "shade", "--light", "0,0,1", "--normal", "0,0,1", "--color", "1,0,0", "--ka", "-1",
        ],
        "ka",
    );
    fails_naming(&["shade", "--normal", "0,0,1", "--color", "1,0,0"], "light");
}

/// The explanation states that the text's code adds specular behind the surface.
#[test]
fn light_behind_is_explained() {
    let out = grafika()
        .args([
            "shade", "--light", "0,0,-1", "--normal", "0,0,1", "--view", "0,0,-1", "--color",
            "1,0,0",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("--specular-requires-lit"), "{text}");
    let j = json(&[
        "shade",
        "--light",
        "0,0,-1",
        "--normal",
        "0,0,1",
        "--view",
        "0,0,-1",
        "--color",
        "1,0,0",
        "--specular-requires-lit",
    ]);
    close(rgb(&j["result"]["specular"]), [0.0; 3]);
}

/// Errors inside a problem's `[shade]` table name `shade.<key>`; unknown keys
/// are TOML errors with file:line:col.
#[test]
fn problem_errors() {
    let dir = std::env::temp_dir().join(format!("grafika-shade-prob-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("p.toml");
    std::fs::write(
        &f,
        "title = 't'\n[shade]\nlight = [0, 0, 1]\nnormal = [0, 0, 0]\ncolor = [1, 0, 0]\n",
    )
    .unwrap();
    let out = grafika()
        .arg("solve")
        .arg(&f)
        .arg("--json")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let j: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(j["error"]["field"], "shade.normal");
    std::fs::write(
        &f,
        "title = 't'\n[shade]\nlight = [0, 0, 1]\nnormal = [0, 0, 1]\nkolor = [1, 0, 0]\n",
    )
    .unwrap();
    let out = grafika().arg("solve").arg(&f).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("kolor") && err.contains("p.toml:5:"), "{err}");
}

/// The Blinn step explains the handedness of Direct3D's (0,0,1).
#[test]
fn blinn_explains_the_d3d_viewer_axis() {
    let out = grafika()
        .args([
            "shade", "--light", "1,0,1", "--normal", "0,0,1", "--color", "1,0,0", "--model",
            "blinn",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("left-handed") && text.contains("right-handed"),
        "{text}"
    );
}

#[test]
fn every_model_is_taken_by_its_name_and_listed_in_the_docs() {
    // `--model` takes each model by the name the reports print, and
    // docs/spec.md's synopsis and README's shade section list them all.
    use grafika::stages::lighting::Model;
    let names: std::collections::BTreeSet<&str> =
        Model::all().into_iter().map(Model::name).collect();
    for name in &names {
        let j = json(&[
            "shade", "--model", name, "--light", "0,0,1", "--normal", "0,0,1", "--view", "0,0,1",
            "--color", "1,1,1",
        ]);
        assert_eq!(j["input"]["model"], *name);
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    for (file, start) in [("docs/spec.md", "[--model "), ("README.md", "`--model ")] {
        let text = std::fs::read_to_string(root.join(file)).unwrap();
        let (_, rest) = text.split_once(start).expect("the --model choices");
        let list = rest.split([']', '`']).next().unwrap_or_default();
        let listed: std::collections::BTreeSet<&str> = list.split('|').collect();
        assert_eq!(listed, names, "{file}");
    }
}
