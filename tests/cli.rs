//! The binary end to end: every problem file, the text's worked examples
//! checked against values derived by hand, and every kind of bad input.

mod common;
use common::*;
use std::f64::consts::SQRT_2;

#[test]
fn every_problem_file_solves_at_every_precision() {
    let mut n = 0;
    for entry in std::fs::read_dir(root().join("problems")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            for p in ["exact", "f64", "f32"] {
                let v = json_ok(&["solve", path.to_str().unwrap(), "--precision", p]);
                assert_eq!(v["command"], "solve");
                assert!(v["result"].is_object() && v["steps"].is_array(), "{path:?}");
                assert!(!v["steps"].as_array().unwrap().is_empty());
            }
            // and the worked solution as text
            grafika()
                .args(["solve", path.to_str().unwrap()])
                .assert()
                .success();
            n += 1;
        }
    }
    assert!(
        n >= 8,
        "expected the text's three examples and at least five more, found {n}"
    );
}

#[test]
fn every_error_file_fails_naming_its_field() {
    let mut n = 0;
    for entry in std::fs::read_dir(root().join("problems/errors")).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        let want = text
            .lines()
            .find_map(|l| l.strip_prefix("expect_error = "))
            .map(|s| s.trim_matches('"').to_string())
            .unwrap_or_else(|| panic!("{path:?} has no expect_error"));
        for p in ["exact", "f64", "f32"] {
            let e = json_err(&["solve", path.to_str().unwrap(), "--precision", p]);
            assert_eq!(e["field"], want.as_str(), "{path:?}: {e}");
        }
        n += 1;
    }
    assert!(n >= 8);
}

#[test]
fn text_triangle_example_by_hand() {
    let v = json_ok(&["solve", "problems/text-triangle.toml", "--precision", "f64"]);
    let r = &v["result"];
    // n = (1,0,1)/√2, u = (Vup × n)/|..| = (1,0,−1)/√2, v = (0,1,0).
    let h = SQRT_2 / 2.0;
    close_vec(&r["view"]["n"], &[h, 0.0, h], 1e-15);
    close_vec(&r["view"]["u"], &[h, 0.0, -h], 1e-15);
    close_vec(&r["view"]["v"], &[0.0, 1.0, 0.0], 1e-15);
    // A − Pe = (−3,−1,−3): (0, −1, −6/√2); B − Pe = (−2,−1,−3): (1/√2, −1, −5/√2).
    close_vec(
        &r["view"]["points"]["A"],
        &[0.0, -1.0, -6.0 / SQRT_2],
        1e-14,
    );
    close_vec(
        &r["view"]["points"]["B"],
        &[1.0 / SQRT_2, -1.0, -5.0 / SQRT_2],
        1e-14,
    );
    // d = −0.1: A'' = (0, (−0.1)(−1)/(−6/√2)) = (0, −√2/60); B'' = (1/50, −√2/50).
    close_vec(
        &r["project"]["points"]["A"],
        &[0.0, -SQRT_2 / 60.0, -0.1],
        1e-15,
    );
    close_vec(
        &r["project"]["points"]["B"],
        &[0.02, -SQRT_2 / 50.0, -0.1],
        1e-15,
    );
    // top = 0.1·tan 22.5° = (√2 − 1)/10; right = 2·top; height = 2·top; width = 4·top.
    let top = (SQRT_2 - 1.0) / 10.0;
    close(f(&r["window"]["top"]), top, 1e-16);
    close(f(&r["window"]["right"]), 2.0 * top, 1e-16);
    close(f(&r["window"]["height"]), 2.0 * top, 1e-16);
    close(f(&r["window"]["width"]), 4.0 * top, 1e-16);
    close(f(&r["window"]["far_top"]), 100.0 * top, 1e-13);
    // px = (0 + 2top)/(4top)·200 = 100; py = (−√2/60 + top)/(2top)·100 = 25(4 − √2)/3.
    close_vec(
        &r["viewport"]["pixels"]["A"],
        &[100.0, 25.0 * (4.0 - SQRT_2) / 3.0],
        1e-12,
    );
}

#[test]
fn text_triangle_finds_the_texts_wrong_answers() {
    let v = json_ok(&["solve", "problems/text-triangle.toml"]);
    let cmp = v["comparison"].as_array().unwrap();
    let verdict = |k: &str| {
        cmp.iter()
            .find(|c| c["key"] == k)
            .map(|c| c["agrees"].clone())
            .unwrap()
    };
    assert_eq!(verdict("view.points.A"), true);
    assert_eq!(verdict("project.points.A"), true);
    assert_eq!(verdict("project.points.B"), false); // 0.0067 printed for 1/50
    assert_eq!(verdict("project.points.C"), false);
    assert_eq!(verdict("window.top"), true); // 0.041 ≈ 0.0414 to the digits printed
    assert_eq!(verdict("window.height"), false); // the half-height given as the height
    assert_eq!(verdict("window.width"), false);
}

#[test]
fn printed_exact_forms_agree_at_every_precision() {
    // Regression: at f32 the text's exact A' = (0, −1, −6/√2) was reported as
    // wrong, because it was compared to 1e-9 while f32 rounds at about 1e-7.
    // The same answers must agree or differ whatever the precision.
    let wrong = |p: &str| -> Vec<String> {
        let v = json_ok(&["solve", "problems/text-triangle.toml", "--precision", p]);
        v["comparison"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["agrees"] == false)
            .map(|c| c["key"].as_str().unwrap().to_string())
            .collect()
    };
    let exact = wrong("exact");
    assert_eq!(
        exact,
        [
            "project.points.B",
            "project.points.C",
            "window.right",
            "window.height",
            "window.width"
        ]
    );
    assert_eq!(wrong("f64"), exact);
    assert_eq!(wrong("f32"), exact);
}

#[test]
fn text_clip_example_by_hand() {
    let v = json_ok(&["solve", "problems/text-clip.toml", "--precision", "f64"]);
    let c = &v["result"]["clip"];
    assert_eq!(c["code0"], "000010");
    assert_eq!(c["code1"], "001001");
    assert_eq!(c["status"], "clipped");
    // P(t) = (4 − 6t, 2 + 4t, 2 − t): x = 3 at t = 1/6, y = 4 at t = 1/2.
    close_vec(&c["segment"][0], &[3.0, 8.0 / 3.0, 11.0 / 6.0], 1e-15);
    close_vec(&c["segment"][1], &[1.0, 4.0, 1.5], 1e-15);
    assert_eq!(c["intersections"]["left"]["code"], "001000");
    assert_eq!(c["intersections"]["left"]["kept"], false);
    let cmp = v["comparison"].as_array().unwrap();
    let wrong: Vec<&str> = cmp
        .iter()
        .filter(|c| c["agrees"] == false)
        .map(|c| c["key"].as_str().unwrap())
        .collect();
    assert_eq!(
        wrong,
        [
            "clip.intersections.right.point",
            "clip.intersections.top.point",
            "clip.segment"
        ]
    );
}

#[test]
fn text_camera_example_by_hand() {
    let v = json_ok(&["solve", "problems/text-camera.toml", "--precision", "f64"]);
    let r = &v["result"]["view"];
    close_vec(&r["n"], &[0.8, 0.6, 0.0], 1e-15);
    close_vec(&r["u"], &[0.0, 0.0, -1.0], 1e-15);
    close_vec(&r["v"], &[-0.6, 0.8, 0.0], 1e-15);
    close_vec(&r["points"]["Pref"], &[0.0, 0.0, -5.0], 1e-14);
    // V's translation column is −(u·Pe, v·Pe, n·Pe) = −(−4, 4/5, 28/5).
    let m = &r["matrix"];
    close_vec(&m[0], &[0.0, 0.0, -1.0, 4.0], 1e-15);
    close_vec(&m[1], &[-0.6, 0.8, 0.0, -0.8], 1e-15);
    close_vec(&m[2], &[0.8, 0.6, 0.0, -5.6], 1e-14);
}

#[test]
fn clip_cases_cover_every_outcome() {
    let v = json_ok(&["solve", "problems/clip-cases.toml", "--precision", "f64"]);
    let segs = v["result"]["clip"].as_array().unwrap();
    let status: Vec<&str> = segs.iter().map(|s| s["status"].as_str().unwrap()).collect();
    assert_eq!(
        status,
        ["accepted", "rejected", "rejected", "rejected", "clipped", "clipped", "clipped"]
    );
    assert_eq!(segs[3]["segment"], serde_json::Value::Null);
    // Case 5 touches only the edge point (3, 4, 1): both ends equal.
    close_vec(&segs[4]["segment"][0], &[3.0, 4.0, 1.0], 1e-15);
    close_vec(&segs[4]["segment"][1], &[3.0, 4.0, 1.0], 1e-15);
    close_vec(&segs[5]["segment"][1], &[1.0, 1.0, 3.0], 1e-15);
    // Case 7 names its ends: A(−1,2,2) → B(2,2,2) enters the box at x = 0.
    close_vec(&segs[6]["segment"][0], &[0.0, 2.0, 2.0], 1e-15);
}

#[test]
fn behind_the_eye_is_a_warning_not_an_error() {
    let v = json_ok(&[
        "solve",
        "problems/project-behind.toml",
        "--precision",
        "f64",
    ]);
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|x| x.as_str().unwrap().contains("B is behind")),
        "{w:?}"
    );
    // B(1,1,2): d·x/z = −1·1/2 = −0.5 (inverted image).
    close_vec(
        &v["result"]["project"]["points"]["B"],
        &[-0.5, -0.5, -1.0],
        1e-15,
    );
}

#[test]
fn subcommands_by_flags_with_negative_values() {
    let v = json_ok(&[
        "basis",
        "--eye",
        "4,4,4",
        "--look",
        "0,1,4",
        "--up",
        "0,1,0",
        "--precision",
        "f64",
    ]);
    close_vec(&v["result"]["u"], &[0.0, 0.0, -1.0], 1e-15);
    let v = json_ok(&[
        "project",
        "--d",
        "-0.1",
        "--point",
        "B=1/sqrt(2),-1,-5/sqrt(2)",
        "--precision",
        "f64",
    ]);
    close_vec(
        &v["result"]["points"]["B"],
        &[0.02, -SQRT_2 / 50.0, -0.1],
        1e-15,
    );
    // COP on +z at d = 10, plane z = 0: xp = x·d/(d − z) = 4·10/20 = 2.
    let v = json_ok(&[
        "project",
        "--cop",
        "10",
        "--plane",
        "0",
        "--point",
        "P=4,-6,-10",
        "--precision",
        "f64",
    ]);
    close_vec(&v["result"]["points"]["P"], &[2.0, -3.0, 0.0], 1e-15);
    let v = json_ok(&["project", "--ortho", "--point", "P=4,-6,-10"]);
    close_vec(&v["result"]["points"]["P"], &[4.0, -6.0, 0.0], 0.0);
    let v = json_ok(&[
        "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
    ]);
    assert_eq!(v["result"]["status"], "clipped");
    let v = json_ok(&[
        "window",
        "--fovy",
        "90",
        "--aspect",
        "2",
        "--near",
        "1",
        "--viewport",
        "200x100",
        "--point",
        "A=-2,-1",
    ]);
    close(f(&v["result"]["right"]), 2.0, 1e-15);
    close_vec(&v["result"]["pixels"]["A"], &[0.0, 0.0], 1e-13);
    let v = json_ok(&[
        "window",
        "--fovy",
        "pi/2 rad",
        "--aspect",
        "1",
        "--near",
        "1",
        "--precision",
        "f64",
    ]);
    close(f(&v["result"]["top"]), 1.0, 1e-15);
}

#[test]
fn f32_results_print_as_f32() {
    // 1/10 as f32 is 0.100000001490116…; the JSON must say 0.1 (its shortest form).
    let out = grafika()
        .args([
            "project",
            "--ortho",
            "--point",
            "P=0.1,0.2,0.3",
            "--precision",
            "f32",
            "--json",
        ])
        .output()
        .unwrap();
    let s = String::from_utf8(out.stdout).unwrap();
    assert!(s.contains("0.1,") || s.contains("0.1\n"), "{s}");
    assert!(!s.contains("0.10000000149"), "{s}");
}

#[test]
fn bad_flags_name_the_field() {
    let cam = |eye: &str, look: &str, up: &str| {
        json_err(&["basis", "--eye", eye, "--look", look, "--up", up])["field"].clone()
    };
    assert_eq!(cam("0,5,0", "0,0,0", "0,1,0"), "up"); // parallel
    assert_eq!(cam("1,1,1", "1,1,1", "0,1,0"), "look"); // eye = look
    assert_eq!(cam("0,0,5", "0,0,0", "0,0,0"), "up"); // zero up
    assert_eq!(cam("1e999,0,0", "0,0,0", "0,1,0"), "eye"); // not finite
    assert_eq!(cam("1+,0,0", "0,0,0", "0,1,0"), "eye"); // malformed
    assert_eq!(cam("1,2", "0,0,0", "0,1,0"), "eye"); // two components
    let win = |fovy: &str, aspect: &str, near: &str| {
        json_err(&["window", "--fovy", fovy, "--aspect", aspect, "--near", near])["field"].clone()
    };
    assert_eq!(win("180", "1", "1"), "fovy");
    assert_eq!(win("-5", "1", "1"), "fovy");
    assert_eq!(win("45", "0", "1"), "aspect");
    assert_eq!(win("45", "1", "-0.1"), "near");
    assert_eq!(
        json_err(&["window", "--fovy", "45", "--aspect", "1", "--near", "2", "--far", "1"])
            ["field"],
        "far"
    );
    assert_eq!(
        json_err(&["project", "--d", "0", "--point", "A=1,1,1"])["field"],
        "d"
    );
    assert_eq!(
        json_err(&["project", "--d", "-1", "--point", "A=1,1,0"])["field"],
        "points.A"
    );
    assert_eq!(
        json_err(&["project", "--d", "-1", "--point", "A1,1,0"])["field"],
        "point"
    );
    assert_eq!(json_err(&["project", "--point", "A=1,1,1"])["field"], "d");
    assert_eq!(
        json_err(&["clip", "--min", "5,0,0", "--max", "3,4,3", "--from", "0,0,0", "--to", "1,1,1"])
            ["field"],
        "min"
    );
    assert_eq!(
        json_err(&[
            "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "1/0,0,0", "--to", "1,1,1"
        ])["field"],
        "from"
    );
    assert_eq!(json_err(&["solve", "no/such/file.toml"])["field"], "file");
    // clap-level errors: missing flag, unknown flag
    assert_eq!(
        json_err(&["basis", "--eye", "1,2,3", "--look", "0,0,0"])["field"],
        "--up <X,Y,Z>"
    );
    let e = json_err(&["basis", "--bogus"]);
    assert!(e["message"].as_str().unwrap().contains("argument"), "{e}");
}

#[test]
fn text_output_is_a_worked_solution() {
    let out = grafika()
        .args(["solve", "problems/text-triangle.toml"])
        .output()
        .unwrap();
    let s = String::from_utf8(out.stdout).unwrap();
    for needle in [
        "Stage 1: modeling",
        "Stage 2: viewing",
        "Stage 3: projection",
        "Stage 4: window",
        "n = (Pe − Pr) / |Pe − Pr|",
        // each difference from the printed answers worded as what it is
        "— a misprint in the text: the text's exact form B''",
        "— a rounding error in the text: the text doubles",
        "— the text uses another convention: the question asks for the height h",
    ] {
        assert!(s.contains(needle), "missing {needle:?}");
    }
}

#[test]
fn exact_forms_of_the_text_examples() {
    // The text's own exact answers, in canonical form: −6/√2 = −3√2, −5/√2 = −5√2/2,
    // A'' = (0, −√2/60), B'' = (1/50, −√2/50), top = 0.1·tan 22.5° = (√2 − 1)/10.
    let v = json_ok(&["solve", "problems/text-triangle.toml"]);
    let e = &v["exact"];
    assert_eq!(
        e["view"]["points"]["A"],
        serde_json::json!(["0", "-1", "-3*sqrt(2)"])
    );
    assert_eq!(
        e["view"]["points"]["B"],
        serde_json::json!(["sqrt(2)/2", "-1", "-5*sqrt(2)/2"])
    );
    assert_eq!(
        e["project"]["points"]["A"],
        serde_json::json!(["0", "-sqrt(2)/60", "-1/10"])
    );
    assert_eq!(
        e["project"]["points"]["B"],
        serde_json::json!(["1/50", "-sqrt(2)/50", "-1/10"])
    );
    assert_eq!(e["window"]["top"], "(sqrt(2)-1)/10");
    let c = json_ok(&["solve", "problems/text-clip.toml"]);
    assert_eq!(
        c["exact"]["clip"]["segment"],
        serde_json::json!([["3", "8/3", "11/6"], ["1", "4", "3/2"]])
    );
    // f64 runs have no exact forms.
    let f = json_ok(&[
        "basis",
        "--eye",
        "3,1,3",
        "--look",
        "2,1,2",
        "--up",
        "0,1,0",
        "--precision",
        "f64",
    ]);
    assert_eq!(f["exact"]["u"], serde_json::json!([null, null, null]));
}

#[test]
fn bench_quick_prints_every_stage_and_precision() {
    let out = common::grafika()
        .args(["bench", "--quick", "--json"])
        .output()
        .expect("runs");
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let rows = v["rows"].as_array().expect("rows");
    // 5 stages × 3 precisions.
    assert_eq!(rows.len(), 15);
    for r in rows {
        assert!(r["ns_per_op"].as_f64().is_some_and(|t| t > 0.0), "{r}");
        if r["precision"] != "exact" && r["stage"] != "window" {
            // The 4-ulp target on the integer inputs.
            let max = r["ulps"]["target"]["max"].as_f64().expect("finite max");
            assert!(max <= 4.0, "{r}");
        }
    }
    let text = common::grafika()
        .args(["bench", "--quick"])
        .output()
        .expect("runs");
    let s = String::from_utf8_lossy(&text.stdout);
    for w in [
        "basis", "view", "project", "window", "clip", "exact", "f64", "f32", "time/op",
    ] {
        assert!(s.contains(w), "{w} missing from\n{s}");
    }
}

#[test]
fn own_problems_by_hand_in_exact_form() {
    // view-surds: u = (4,0,−1)/√17, v = (−4,51,−16)/(13√17), n = (3,4,12)/13,
    // A' = (4/√17, −4/(13√17), −166/13) — derived in the file's comments.
    let v = json_ok(&["solve", "problems/view-surds.toml"]);
    let e = &v["exact"]["view"];
    assert_eq!(
        e["u"],
        serde_json::json!(["4*sqrt(17)/17", "0", "-sqrt(17)/17"])
    );
    assert_eq!(
        e["v"],
        serde_json::json!(["-4*sqrt(17)/221", "3*sqrt(17)/13", "-16*sqrt(17)/221"])
    );
    assert_eq!(e["n"], serde_json::json!(["3/13", "4/13", "12/13"]));
    assert_eq!(
        e["points"]["A"],
        serde_json::json!(["4*sqrt(17)/17", "-4*sqrt(17)/221", "-166/13"])
    );
    // window-60: top = tan 30° = √3/3, right = 4√3/9; P pixel (320 + 120√3, 240 + 60√3).
    let w = json_ok(&["solve", "problems/window-60.toml"]);
    assert_eq!(w["exact"]["window"]["top"], "sqrt(3)/3");
    assert_eq!(w["exact"]["window"]["right"], "4*sqrt(3)/9");
    assert_eq!(
        w["exact"]["viewport"]["pixels"]["P"],
        serde_json::json!(["320+120*sqrt(3)", "240+60*sqrt(3)"])
    );
    // view-axis-aligned: P'' = (1/2, 1) lands on the top edge, pixel (75, 100).
    let a = json_ok(&["solve", "problems/view-axis-aligned.toml"]);
    assert_eq!(
        a["exact"]["viewport"]["pixels"]["P"],
        serde_json::json!(["75", "100"])
    );
}

#[test]
fn no_file_of_the_project_reaches_outside_the_repository() {
    // The tracked text files (sources, problems, scenes, docs) never name
    // a folder beside the repository.
    let mut stack = vec![root()];
    let mut n = 0;
    while let Some(dir) = stack.pop() {
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            let name = p.file_name().unwrap().to_string_lossy().to_string();
            if name.starts_with('.') || name == "target" {
                continue;
            }
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            let Ok(text) = std::fs::read_to_string(&p) else {
                continue;
            };
            n += 1;
            // Spelled in pieces so that this file does not hold them itself.
            let bad = [["..", "shared"].join("/"), ["..", "..", ".."].join("/")];
            for b in &bad {
                assert!(!text.contains(b.as_str()), "{p:?} contains {b}");
            }
        }
    }
    assert!(n > 50, "read only {n} files");
}

#[test]
fn render_scene_with_no_objects_is_an_error() {
    // an empty file (a device such as /dev/null is refused as a scene
    // before it is read: not a regular file)
    let dir = std::env::temp_dir().join(format!("grafika-empty-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("empty.toml");
    std::fs::write(&scene, "").unwrap();
    let out = dir.join("empty.png");
    let e = json_err(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(e["field"], "object");
    let e = json_err(&["render", "/dev/null", "-o", out.to_str().unwrap()]);
    assert_eq!(e["field"], "scene");
}

#[test]
fn overflowing_results_are_refused_never_printed_as_nan_or_inf() {
    let cases: &[&[&str]] = &[
        &[
            "window",
            "--fovy",
            "45",
            "--aspect",
            "2",
            "--near",
            "0.1",
            "--viewport",
            "200x100",
            "--point",
            "A=1e308,1e308",
            "--precision",
            "f64",
        ],
        &[
            "shade",
            "--normal",
            "1e-320,0,0",
            "--light",
            "0,0,1",
            "--view",
            "0,0,1",
            "--color",
            "1,1,0",
            "--precision",
            "f64",
        ],
        &[
            "project",
            "--d",
            "-0.1",
            "--point",
            "A=1,1,1e-320",
            "--precision",
            "f64",
        ],
        &[
            "basis",
            "--eye",
            "1e308,0,0",
            "--look=-1e308,0,0",
            "--up",
            "0,1,0",
            "--precision",
            "f64",
        ],
    ];
    for args in cases {
        let out = grafika().args(*args).arg("--json").output().unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        if out.status.success() {
            for bad in ["NaN", "inf", "null"] {
                assert!(!stdout.contains(bad), "{args:?} printed {bad}: {stdout}");
            }
        } else {
            assert_eq!(out.status.code(), Some(2), "{args:?}");
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        }
    }
}

#[test]
fn eye_in_parentheses_is_read_like_answer_files() {
    let a = json_ok(&[
        "basis", "--eye", "(3,1,3)", "--look", "[2,1,2]", "--up", "0,1,0",
    ]);
    let b = json_ok(&[
        "basis", "--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0",
    ]);
    assert_eq!(a["result"], b["result"]);
}

#[test]
fn clap_errors_are_one_line() {
    for args in [
        &["basis", "--eye"][..],
        &["basis", "--nonsense", "1"],
        &["frobnicate"],
    ] {
        let out = grafika().args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error: "), "{err}");
    }
}

#[test]
fn a_long_echoed_input_is_cut_in_the_error() {
    let long = "x".repeat(100_000);
    let out = grafika()
        .args(["basis", "--eye", &long, "--look", "0,0,0", "--up", "0,1,0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.len() < 1000, "{} bytes", err.len());
    assert!(err.contains("characters cut"), "{err}");
}

#[test]
fn render_refuses_precision_it_would_ignore() {
    let out = std::env::temp_dir().join(format!("grafika-prec-{}.png", std::process::id()));
    // render does not take --precision (its --help does not list it), and
    // says why, after its name ...
    let e = json_err(&[
        "render",
        "problems/render/cone-flat.toml",
        "-o",
        out.to_str().unwrap(),
        "--precision",
        "f64",
    ]);
    assert_eq!(e["field"], "precision");
    assert!(e["message"].as_str().unwrap().contains("f32"), "{e}");
    // ... as before its name.
    let e = json_err(&[
        "--precision",
        "f64",
        "render",
        "problems/render/cone-flat.toml",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(e["field"], "precision");
    assert!(!out.exists());
}

#[test]
fn render_summary_names_every_objects_shading() {
    let dir = std::env::temp_dir().join(format!("grafika-mixed-shading-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("two.toml");
    std::fs::write(
        &scene,
        "[image]\nwidth = 64\nheight = 64\n\n[[object]]\ntype = \"sphere\"\nn = 8\nr = 10\n\n\
         [[object]]\ntype = \"sphere\"\nn = 8\nr = 10\nshading = \"gouraud\"\n\
         transform = [ { translate = [20, 0, 0] } ]\n",
    )
    .unwrap();
    let png = dir.join("two.png");
    let v = json_ok(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(v["result"]["shading"], "flat, gouraud", "{}", v["result"]);
}

#[test]
fn solve_reads_the_problem_from_standard_input() {
    let text = std::fs::read_to_string(root().join("problems/text-camera.toml")).unwrap();
    let out = grafika()
        .args(["solve", "-", "--json"])
        .write_stdin(text)
        .output()
        .unwrap();
    assert_success(&out);
    let from_stdin: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let from_file = json_ok(&["solve", "problems/text-camera.toml"]);
    assert_eq!(from_stdin["result"], from_file["result"]);
}

/// Issue 18: shell completions cover every subcommand and flag.
#[test]
fn completions_for_bash_name_every_subcommand_and_flag() {
    let out = grafika().args(["completions", "bash"]).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for word in [
        "basis",
        "view",
        "project",
        "window",
        "clip",
        "shade",
        "solve",
        "check",
        "practice",
        "generate",
        "render",
        "bench",
        "--precision",
        "--lang",
        "--explain-pixel",
        "--follow-through",
    ] {
        assert!(text.contains(word), "bash completion lacks {word}");
    }
    for shell in ["zsh", "fish", "elvish", "powershell"] {
        grafika().args(["completions", shell]).assert().success();
    }
}

/// Issue 18: a man page in roff, naming the program and its commands.
#[test]
fn man_page_is_roff_with_the_commands() {
    let out = grafika().arg("man").output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains(".TH grafika 1"), "no title header");
    for cmd in ["solve", "check", "practice", "generate", "render"] {
        assert!(text.contains(cmd), "man page lacks {cmd}");
    }
    // Each command has its section on this page, with the flags it takes
    // (the page listed the commands as grafika-basis(1), … never written).
    for (cmd, flag) in [
        ("BASIS", "eye"),
        ("CHECK", "answers"),
        ("RENDER", "explain\\-pixel"),
    ] {
        let at = text
            .find(&format!(".SH \"GRAFIKA {cmd}\""))
            .unwrap_or_else(|| panic!("{cmd}"));
        let section = text[at + 4..].split("\n.SH ").next().unwrap();
        assert!(
            section.contains(&format!("\\-\\-{flag}")),
            "{cmd} lacks --{flag}"
        );
    }
    assert!(!text.contains("(1)\n"), "a page of its own is named");
}

/// Issue 18: an unknown shell is a one-line error, exit 2.
#[test]
fn completions_for_an_unknown_shell_is_an_error() {
    let out = grafika().args(["completions", "cmd.exe"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.trim().lines().count(), 1, "{err}");
}

/// Issue 18: every subcommand's `--help` ends with examples.
#[test]
fn every_subcommand_help_has_examples() {
    for cmd in [
        "basis",
        "view",
        "project",
        "window",
        "clip",
        "shade",
        "solve",
        "check",
        "practice",
        "generate",
        "render",
        "bench",
        "completions",
        "man",
    ] {
        let out = grafika().args([cmd, "--help"]).output().unwrap();
        assert!(out.status.success(), "{cmd} --help failed");
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(
            text.contains("Examples / Contoh:"),
            "{cmd} --help has no examples"
        );
    }
}

/// Runs grafika in English (whatever the machine's locale), expects exit 2,
/// returns its one line on stderr.
fn english_error(args: &[&str]) -> String {
    let mut cmd = grafika();
    cmd.env_remove("GRAFIKA_LANG")
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "C");
    refusal(cmd, args)
}

#[test]
fn missing_required_arguments_are_named_in_english() {
    // clap lists the missing arguments on the lines after its first: an
    // earlier version printed "…were not provided: (see --help)".
    let err = english_error(&["solve"]);
    assert!(
        err.contains("were not provided: <FILE> (see --help)"),
        "{err}"
    );
    let err = english_error(&["basis", "--eye", "3,1,3"]);
    assert!(
        err.contains("were not provided: --look <X,Y,Z>, --up <X,Y,Z> (see --help)"),
        "{err}"
    );
}

#[test]
fn an_invalid_choice_lists_the_possible_values_in_english() {
    // as the Indonesian does: docs/spec.md's precisions and lighting models
    let err = english_error(&["project", "--precision", "f16"]);
    assert!(
        err.contains("invalid value 'f16'") && err.contains("possible values: exact, f64, f32"),
        "{err}"
    );
    let err = english_error(&["shade", "--model", "foo"]);
    assert!(
        err.contains("possible values: ambient, diffuse, specular, lambert, phong, blinn"),
        "{err}"
    );
}

#[test]
fn the_image_of_a_point_on_the_cop_plane_is_too_large_not_mangled() {
    // d = −1, A = (1, 1, 1e-320): A'' = (d·x/z, d·y/z) = (−1e320, −1e320),
    // beyond the largest double (≈ 1.8e308). An earlier version replaced
    // every 'a' after the first word and printed "the imAge of A is too lArge".
    let err = english_error(&[
        "project",
        "--d",
        "-1",
        "--point",
        "A=1,1,1e-320",
        "--precision",
        "f64",
    ]);
    assert!(err.contains("the image of A is too large"), "{err}");
    assert!(!err.contains("imAge") && !err.contains("lArge"), "{err}");
}

#[test]
fn several_clipped_segments_print_one_numbered_block_each_not_one_line() {
    // problems/clip-cases.toml, box 0 ≤ x ≤ 3, 0 ≤ y ≤ 4, 0 ≤ z ≤ 3:
    // segment 1, (1, 1, 1)–(2, 3, 2), is inside (codes 000000, accepted, no
    // intersections); segment 2, (1, 5, 1)–(2, 6, 2), is above (y > 4: bit 4,
    // 001000 at both ends, AND ≠ 0, rejected, no segment).
    let out = grafika()
        .args(["solve", "problems/clip-cases.toml", "--lang", "en"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let answer = &text[text.find("\nAnswer\n").unwrap()..];
    for l in answer.lines() {
        assert!(l.chars().count() < 200 || l.contains("printed"), "{l}");
    }
    assert!(
        answer
            .contains("  clip 1:\n    code0 = 000000\n    code1 = 000000\n    status = accepted\n"),
        "{answer}"
    );
    assert!(answer.contains("    intersections = none\n  clip 2:\n    code0 = 001000\n    code1 = 001000\n    status = rejected\n    segment = none\n"), "{answer}");
    assert!(answer.contains("  clip 5:\n"), "{answer}");
    assert!(!answer.contains("intersections = ,"), "{answer}");
    // the HTML page numbers them the same way, one row per value, named
    // as the steps name it with the answer key in the row's title
    let page = std::env::temp_dir().join(format!("grafika-clip-cases-{}.html", std::process::id()));
    let _ = std::fs::remove_file(&page);
    grafika()
        .args(["solve", "problems/clip-cases.toml", "--html"])
        .arg(&page)
        .assert()
        .success();
    let html = std::fs::read_to_string(&page).unwrap();
    let _ = std::fs::remove_file(&page);
    assert!(html.contains("<th title=\"clip.0.status\">"), "{html}");
    assert!(html.contains("<th title=\"clip.4.code1\">"), "{html}");
    assert!(html.contains("<mtext>segment</mtext>"), "{html}");
    // and the JSON keeps its list of objects
    let v = json_ok(&["solve", "problems/clip-cases.toml"]);
    assert_eq!(v["result"]["clip"][1]["code0"], "001000");
    assert_eq!(v["result"]["clip"][1]["status"], "rejected");
}

#[test]
fn explain_pixel_matrices_are_not_under_the_solve_viewing_heading() {
    // `render --explain-pixel` records the projection matrix and each
    // object's M, V·M, P·V·M in a section of their own; it stood under
    // solve's "Stage 2: viewing transformation (world → eye coordinates)"
    // heading with no Stage 1/3 sections around it.
    let png = std::env::temp_dir().join(format!("grafika-cone-{}.png", std::process::id()));
    for (lang, heading) in [
        ("en", "== The view and projection matrices =="),
        ("id", "== Matriks pandang dan matriks proyeksi =="),
    ] {
        let _ = std::fs::remove_file(&png);
        let out = grafika()
            .args(["render", "problems/render/cone-flat.toml", "-o"])
            .arg(&png)
            .args(["--explain-pixel", "330,150", "--lang", lang])
            .output()
            .unwrap();
        assert_success(&out);
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.contains(heading), "{text}");
        assert!(!text.contains("world → eye coordinates) =="), "{text}");
        assert!(!text.contains("dunia → kamera) =="), "{text}");
    }
    let _ = std::fs::remove_file(&png);
}

/// A problem file's vectors as people write them (one string, in brackets
/// or not, `;` between parts, the minus sign `−`) read as the TOML arrays
/// do: the text's triangle and clipping examples give the same results.
#[test]
fn a_problem_files_vectors_may_be_written_as_one_string() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "text-triangle.toml",
            vec![
                ("eye = [3, 1, 3]", "eye = \"(3; 1; 3)\""),
                ("look = [2, 1, 2]", "look = \"2, 1, 2\""),
                ("up = [0, 1, 0]", "up = \"[0, 1, 0]\""),
                ("B = [1, 0, 0]", "B = \"(1, 0, 0)\""),
            ],
        ),
        (
            "text-clip.toml",
            vec![
                ("max = [3, 4, 3]", "max = \"(3, 4, 3)\""),
                ("from = [4, 2, 2]", "from = \"(4, 2, 2)\""),
                ("to = [-2, 6, 1]", "to = \"(−2; 6; 1)\""),
            ],
        ),
    ];
    for (name, edits) in cases {
        let original = root().join("problems").join(name);
        let mut text = std::fs::read_to_string(&original).unwrap();
        for (array, string) in edits {
            assert!(text.contains(array), "{name} has no `{array}`");
            text = text.replacen(array, string, 1);
        }
        let edited = dir.path().join(name);
        std::fs::write(&edited, text).unwrap();
        let a = json_ok(&["solve", original.to_str().unwrap()]);
        let b = json_ok(&["solve", edited.to_str().unwrap()]);
        assert_eq!(a["result"], b["result"], "{name}");
        assert_eq!(a["exact"], b["exact"], "{name}");
    }
}

/// far ≤ near is one rule with one message, whether the problem comes from
/// the flags or from a file; each error names the field as it was spelled
/// (`far`, `perspective.far`), in both languages (0.5 written 0,5 in
/// Indonesian).
#[test]
fn far_not_beyond_near_is_one_rule_for_flags_and_files() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("far.toml");
    let problem = "title = \"far\"\nask = [\"window\"]\n\
                   [perspective]\nnear = 1\nfar = 0.5\nfovy = 45\naspect = 2\n";
    std::fs::write(&file, problem).unwrap();
    let flags = [
        "window", "--fovy", "45", "--aspect", "2", "--near", "1", "--far", "0,5",
    ];
    let solve = ["solve", file.to_str().unwrap()];
    let said = "must be greater than near = 1, got 0.5";
    assert_eq!(english_error(&flags), format!("error: far: {said}\n"));
    assert_eq!(
        english_error(&solve),
        format!("error: perspective.far: {said}\n")
    );
    let said = "harus lebih besar daripada near = 1, diberikan 0,5";
    for (args, field) in [(&flags[..], "far"), (&solve[..], "perspective.far")] {
        let out = grafika()
            .arg("--lang")
            .arg("id")
            .args(args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err, format!("kesalahan: {field}: {said}\n"));
    }
}

/// A window point is written as a vector flag is: `A=0.5,0`, or `A=(0,5;
/// 0)` with the decimal comma. fovy 90°, aspect 1, near 1: the window is
/// −1..1 both ways, so x = 0.5 is at (0.5 − (−1))/2 = 3/4 of 100 pixels and
/// y = 0 at half: (75, 50).
#[test]
fn a_window_point_takes_the_decimal_comma_as_a_vector_does() {
    for point in ["A=0.5,0", "A=(0,5; 0)"] {
        let out = grafika()
            .args(["window", "--fovy", "90", "--aspect", "1", "--near", "1"])
            .args(["--viewport", "100x100", "--point", point, "--lang", "en"])
            .output()
            .unwrap();
        assert!(out.status.success(), "{point}");
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.contains("    A = (75, 50)\n"), "{point}: {text}");
    }
}

/// A calculator command is the same part of a problem file, solved by the
/// same solver: for the same inputs, typed as people type them, the
/// command's (unnested) results are the file's results under the part's
/// key. By hand for the view: eye (0, 0, 5) looking at the origin, up y:
/// n = (0, 0, 1), u = (1, 0, 0), v = (0, 1, 0); P = (1, 2, 3) is
/// (1, 2, −2) in eye coordinates. The window: fovy 90°, aspect 2, near 1:
/// top = tan 45° = 1, right = 2.
#[test]
fn a_calculator_command_gives_the_results_of_the_same_part_of_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("same.toml");
    let toml = "title = 'same'\n\
        [camera]\neye = '(0; 0; 5)'\nlook = [0, 0, 0]\nup = '0, 1, 0'\n\
        [points]\nP = '(1, 2, 3)'\n\
        [perspective]\nnear = 1\nfovy = 90\naspect = '4/2'\n\
        [clip]\nmin = [0, 0, 0]\nmax = [3, 4, 3]\n\
        [[clip.segment]]\nfrom = [4, 2, 2]\nto = '(−2, 6, 1)'\n\
        [shade]\nlight = [0, 0, 1]\nnormal = '(0, 1/√2, 1/√2)'\nview = [0, 0, 1]\ncolor = [1, 1, 0]\n";
    std::fs::write(&file, toml).unwrap();
    let solved = json_ok(&["solve", file.to_str().unwrap()]);
    let cases: [(&str, Vec<&str>); 4] = [
        (
            "view",
            vec![
                "view",
                "--eye",
                "(0; 0; 5)",
                "--look",
                "0,0,0",
                "--up",
                "0,1,0",
                "--point",
                "P=(1, 2, 3)",
            ],
        ),
        (
            "window",
            vec!["window", "--fovy", "90", "--aspect", "4/2", "--near", "1"],
        ),
        (
            "clip",
            vec![
                "clip",
                "--min",
                "0,0,0",
                "--max",
                "3,4,3",
                "--from",
                "4,2,2",
                "--to",
                "(−2, 6, 1)",
            ],
        ),
        (
            "shade",
            vec![
                "shade",
                "--light",
                "0,0,1",
                "--normal",
                "(0, 1/√2, 1/√2)",
                "--view",
                "0,0,1",
                "--color",
                "1,1,0",
            ],
        ),
    ];
    for (part, args) in cases {
        let command = json_ok(&args);
        assert_eq!(command["command"], part);
        assert_eq!(command["result"], solved["result"][part], "{part}");
    }
    let view = &solved["result"]["view"];
    for (key, want) in [
        ("u", [1.0, 0.0, 0.0]),
        ("v", [0.0, 1.0, 0.0]),
        ("n", [0.0, 0.0, 1.0]),
    ] {
        assert_eq!(view[key], serde_json::json!(want), "{key}");
    }
    assert_eq!(view["points"]["P"], serde_json::json!([1.0, 2.0, -2.0]));
    assert_eq!(solved["result"]["window"]["top"], 1.0);
    assert_eq!(solved["result"]["window"]["right"], 2.0);
}
