//! The marking scheme (docs/spec.md §5): a paper's grade depends only on
//! its answers, never on the working a student chose to show; `[marks]`
//! weighs the values asked and gives method marks to their working;
//! follow-through starts only from earlier values that could be what their
//! step gives. The papers are written by hand as students write them
//! (strings, `√`, `−`, decimal commas, Indonesian words), and every value
//! is derived by hand in the comments.

mod common;
use common::*;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn paper(name: &str, text: &str) -> PathBuf {
    let f = scratch(&format!("scheme-{name}")).join(format!("{name}.toml"));
    std::fs::write(&f, text).expect("writes the paper");
    f
}

fn check(problem: &str, f: &Path, extra: &[&str]) -> Value {
    let mut args = vec!["check", problem, "--answers", f.to_str().unwrap()];
    args.extend(extra);
    json_ok(&args)
}

fn answer<'a>(v: &'a Value, key: &str) -> &'a Value {
    (v["answers"].as_array().unwrap().iter())
        .find(|a| a["key"] == key)
        .unwrap_or_else(|| panic!("{key} not marked: {v}"))
}

fn score(v: &Value) -> (f64, u64) {
    (
        f(&v["score"]["points"]),
        v["score"]["total"].as_u64().unwrap(),
    )
}

/// The clipping example, P0(4, 2, 2)–P1(−2, 6, 1) against 0 ≤ x ≤ 3,
/// 0 ≤ y ≤ 4, 0 ≤ z ≤ 3: P(t) = (4 − 6t, 2 + 4t, 2 − t). P0 is right of
/// x = 3 (bit 2: 000010), P1 left of x = 0 and above y = 4 (bits 1 and 4:
/// 001001); their AND is 0 and they are not both 0: clipped. x = 3 at
/// t = 1/6: (3, 8/3, 11/6), inside; x = 0 at t = 2/3: (0, 14/3, 4/3),
/// above y = 4 (001000); y = 4 at t = 1/2: (1, 4, 3/2), inside. The
/// segment kept runs from (3, 8/3, 11/6) to (1, 4, 3/2).
const CLIP_FINAL: &str = "[clip]\ncode0 = \"000 010\"\ncode1 = \"001 001\"\n\
    status = \"di-clip\"\nsegment = \"(3; 8/3; 11/6), (1; 4; 3/2)\"\n";

#[test]
fn the_same_answers_get_the_same_grade_whatever_working_is_shown() {
    let bare = check("problems/text-clip.toml", &paper("bare", CLIP_FINAL), &[]);
    let working = format!(
        "{CLIP_FINAL}[clip.intersections.right]\nt = \"1/6\"\npoint = \"(3; 2,667; 1,833)\"\n\
         code = \"000000\"\n[clip.intersections.left]\nt = \"2/3\"\npoint = \"0, 14/3, 4/3\"\n\
         code = \"001000\"\n[clip.intersections.top]\nt = \"0,5\"\npoint = \"(1; 4; 1,5)\"\n\
         code = \"000 000\"\n"
    );
    let full = check("problems/text-clip.toml", &paper("working", &working), &[]);
    assert_eq!(score(&bare), (4.0, 4));
    assert_eq!(score(&full), (4.0, 4));
    // the working is marked, right, and counted apart
    assert_eq!(full["working"]["answers"], 9);
    assert_eq!(full["working"]["correct"], 9);
    let t = answer(&full, "clip.intersections.right.t");
    assert_eq!(t["verdict"], "correct");
    assert_eq!(t["marks"], Value::Null);
    // wrong working never lowers the grade either
    let wrong = format!("{CLIP_FINAL}[clip.intersections.left]\nt = \"1/3\"\n");
    assert_eq!(
        score(&check(
            "problems/text-clip.toml",
            &paper("wrong-working", &wrong),
            &[]
        )),
        (4.0, 4)
    );
}

/// The text's Phong example: N = (0, 1, 1)/√2, L = V = (0, 0, 1),
/// Cs = (1, 1, 0), kd 0.6, ks 0.7, ka 0.4, n 4. cos α = L·N = √2/2; R =
/// 2N(L·N) − L = (0, 1, 1) − (0, 0, 1) = (0, 1, 0); cos β = R·V = 0.
/// ambient = 0.4·Cs = (0.4, 0.4, 0); diffuse = 0.6·(√2/2)·Cs =
/// (3√2/10, 3√2/10, 0) ≈ (0.4243, 0.4243, 0); specular = 0.7·0⁴ = 0;
/// colour = ((4 + 3√2)/10, (4 + 3√2)/10, 0) ≈ (0.8243, 0.8243, 0). The
/// file's `[marks]`: the colour 4, the three terms 1 each as method marks.
#[test]
fn a_lighting_problem_asks_its_colour_and_its_working_earns_method_marks() {
    let all = "[shade]\ncos_alpha = \"1/√2\"\nR = \"(0, 1, 0)\"\ncos_beta = \"0\"\n\
        ambient = \"(0,4; 0,4; 0)\"\ndiffuse = \"(3√2/10, 3√2/10, 0)\"\nspecular = \"0, 0, 0\"\n\
        unclamped = \"(0,8243; 0,8243; 0)\"\ncolor = \"((4 + 3√2)/10, (4 + 3√2)/10, 0)\"\n";
    let v = check("problems/shade-phong.toml", &paper("phong-all", all), &[]);
    assert_eq!(score(&v), (4.0, 4), "{v}");
    // unclamped, ambient, diffuse, … are working: never counted
    assert_eq!(answer(&v, "shade.unclamped")["marks"], Value::Null);
    let colour = "[shade]\ncolor = \"0.8243, 0.8243, 0\"\n";
    let v = check(
        "problems/shade-phong.toml",
        &paper("phong-colour", colour),
        &[],
    );
    assert_eq!(score(&v), (4.0, 4));
    // the terms right and their sum wrong (0.4 + 0.4243 as 0.8343): 3 of 4
    let slip = "[shade]\nambient = \"(0,4; 0,4; 0)\"\ndiffuse = \"(0,4243; 0,4243; 0)\"\n\
        specular = \"(0; 0; 0)\"\ncolor = \"(0,8343; 0,8343; 0)\"\n";
    let v = check("problems/shade-phong.toml", &paper("phong-slip", slip), &[]);
    assert_eq!(score(&v), (3.0, 4));
    let c = answer(&v, "shade.color");
    assert_eq!(c["verdict"], "wrong");
    assert_eq!(c["marks"]["earned"], 3.0);
    assert_eq!(
        c["method"],
        serde_json::json!(["shade.ambient", "shade.diffuse", "shade.specular"])
    );
    assert_eq!(v["score"]["method"], 3.0);
    // a right colour earns its 4 whatever the working says
    let both = slip.replace("(0,8343; 0,8343; 0)", "(0,8243; 0,8243; 0)");
    let both = both.replace("(0,4; 0,4; 0)", "(0,5; 0,5; 0)");
    assert_eq!(
        score(&check(
            "problems/shade-phong.toml",
            &paper("phong-right", &both),
            &[]
        )),
        (4.0, 4)
    );
}

/// The text's specular example: N = (0, 0, 1), L = (1, 0, 1)/√2, V =
/// (0, 0, 1): R = 2N(L·N) − L = (0, 0, √2) − (√2/2, 0, √2/2) = (−√2/2, 0,
/// √2/2); cos β = R·V = √2/2; specular = 0.7·(√2/2)⁴ = 0.7/4 = 0.175 per
/// channel (white). The question asks the specular reflection (2 marks,
/// cos β 1 of them), not the ambient and diffuse terms (0 here).
#[test]
fn keys_the_question_never_asks_are_not_counted() {
    let text = "[shade]\nspecular = \"0,175; 0,175; 0,175\"\nambient = \"0, 0, 0\"\n\
        diffuse = \"(0, 0, 0)\"\nunclamped = \"7/40, 7/40, 7/40\"\ncos_beta = \"√2/2\"\n";
    let v = check(
        "problems/shade-specular.toml",
        &paper("specular", text),
        &[],
    );
    assert_eq!(score(&v), (2.0, 2), "{v}");
    for k in [
        "shade.ambient",
        "shade.diffuse",
        "shade.unclamped",
        "shade.cos_beta",
    ] {
        assert_eq!(answer(&v, k)["marks"], Value::Null, "{k}");
    }
}

#[test]
fn the_text_shows_marks_and_a_percentage() {
    // Siti (problems/answers/triangle): 16 of the 18 values the triangle
    // example asks, 16/18 = 88.9 %
    let siti = [
        "check",
        "problems/text-triangle.toml",
        "--answers",
        "problems/answers/triangle/siti.toml",
    ];
    let text = text("en", &siti);
    assert!(text.contains("Score: 16/18 = 88.9% (16 correct"), "{text}");
    assert!(text.contains("┆ marks ┆"), "{text}");
    let text = common::text("id", &siti);
    assert!(text.contains("Nilai: 16/18 = 88,9% (16 benar"), "{text}");
}

#[test]
fn the_texts_misprint_is_never_credited_by_follow_through() {
    // the text printed the intersections (3, 20/6, 11/6) and (2, 4, 3/2)
    // and the segment between them: on their planes, but not on P0P1
    // (P(1/6) = (3, 8/3, 11/6), P(1/2) = (1, 4, 3/2))
    let v = json_ok(&[
        "check",
        "problems/text-clip.toml",
        "--answers-from-text",
        "--follow-through",
    ]);
    assert_eq!(answer(&v, "clip.segment")["verdict"], "wrong");
    assert_eq!(v["counts"]["follow_through"], 0);
    // a student who copied them: the misprint is named, not credited
    let copy = "[clip]\ncode0 = \"000010\"\ncode1 = \"001001\"\nstatus = \"clipped\"\n\
        segment = \"(3, 20/6, 11/6), (2, 4, 3/2)\"\n\
        intersections.right.point = \"(3, 20/6, 11/6)\"\nintersections.top.point = \"(2; 4; 1,5)\"\n";
    let v = check(
        "problems/text-clip.toml",
        &paper("copy", copy),
        &["--follow-through"],
    );
    let s = answer(&v, "clip.segment");
    assert_eq!(s["verdict"], "wrong");
    assert_eq!(s["diagnosis"], serde_json::json!(["copied_misprint"]));
    assert_eq!(score(&v), (3.0, 4));
}

/// The triangle example: n = (√2/2, 0, √2/2). A u of (1, 2, 3) is no unit
/// vector (|u| = √14), so nothing follows from it: v = n × u = (0·3 −
/// (√2/2)·2, (√2/2)·1 − (√2/2)·3, (√2/2)·2 − 0·1) = (−√2, −√2, √2) is
/// not credited, and the note says why. Budi's u = n × Vup = (−√2/2, 0,
/// √2/2) is a unit vector perpendicular to n, so v = n × u = (0, −1, 0)
/// follows from it.
#[test]
fn follow_through_starts_only_from_a_plausible_value() {
    let text = "[view]\nn = \"(√2/2, 0, √2/2)\"\nu = \"(1, 2, 3)\"\nv = \"(−√2, −√2, √2)\"\n";
    let v = check(
        "problems/text-triangle.toml",
        &paper("u123", text),
        &["--follow-through"],
    );
    let a = answer(&v, "view.v");
    assert_eq!(a["verdict"], "wrong");
    let note = a["note"].as_str().unwrap();
    assert!(
        note.contains("u is not a unit vector, so v can't follow from it"),
        "{note}"
    );
    let text = "[view]\nn = \"(√2/2, 0, √2/2)\"\nu = \"(−0,7071; 0; 0,7071)\"\nv = \"0, −1, 0\"\n";
    let v = check(
        "problems/text-triangle.toml",
        &paper("budi-u", text),
        &["--follow-through"],
    );
    assert_eq!(answer(&v, "view.v")["code"], "correct.follow_through");
    // in Indonesian the note is Indonesian
    let out = grafika()
        .args([
            "--lang",
            "id",
            "check",
            "problems/text-triangle.toml",
            "--answers",
        ])
        .arg(paper(
            "u123-id",
            "[view]\nu = \"1, 2, 3\"\nv = \"(−√2; −√2; √2)\"\n",
        ))
        .arg("--follow-through")
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("u bukan vektor satuan"), "{text}");
}

#[test]
fn a_marks_table_that_cannot_be_is_refused_naming_the_key() {
    let base = std::fs::read_to_string(root().join("problems/shade-lambert.toml")).unwrap();
    let base = base.split("[marks]").next().unwrap().to_string();
    let cases = [
        ("\"shade.colour\" = 2\n", "marks.\"shade.colour\""),
        ("\"shade.color\" = 1.5\n", "marks.\"shade.color\""),
        ("\"shade.color\" = -1\n", "marks.\"shade.color\""),
        (
            "\"shade.color\" = { marks = 2, method = { \"shade.ambient\" = 2, \"shade.diffuse\" = 1 } }\n",
            "marks.\"shade.color\".method",
        ),
        (
            "\"shade.color\" = { mark = 2 }\n",
            "marks.\"shade.color\".mark",
        ),
        (
            "\"shade.color\" = { marks = 2, method = { \"shade.nope\" = 1 } }\n",
            "marks.\"shade.color\".method.\"shade.nope\"",
        ),
    ];
    for (i, (marks, field)) in cases.iter().enumerate() {
        let p = scratch(&format!("scheme-bad-{i}")).join("p.toml");
        std::fs::write(&p, format!("{base}[marks]\n{marks}")).unwrap();
        let e = json_err(&[
            "check",
            p.to_str().unwrap(),
            "--answers",
            "problems/answers/phong/eko.toml",
        ]);
        assert_eq!(e["field"], *field, "{marks}: {e}");
    }
}

#[test]
fn a_generated_question_sheet_shows_each_questions_marks() {
    let out = scratch("scheme-generate");
    let dir = out.join("exam");
    grafika()
        .args([
            "generate", "--topic", "view", "--count", "1", "--seed", "11",
        ])
        .args(["--difficulty", "easy", "--out"])
        .arg(&dir)
        .assert()
        .success();
    let sheet = std::fs::read_to_string(dir.join("questions.md")).unwrap();
    let problem = std::fs::read_to_string(dir.join("problem-01.toml")).unwrap();
    // the view topic asks n, u, v and each point's eye coordinates: one
    // mark each
    let points = problem.lines().skip_while(|l| *l != "[points]").skip(1);
    let n = points
        .take_while(|l| !l.starts_with('[') && !l.is_empty())
        .count() as u32;
    let marks = 3 + n;
    assert!(
        sheet.contains(&format!("({marks} marks)")),
        "{marks} marks: {sheet}"
    );
}
