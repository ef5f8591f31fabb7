//! `grafika practice`: scripted sessions through standard input for every
//! topic (all correct; a wrong early step with consistent later steps,
//! credited as follow-through; a diagnosed mistake), the commands (hint,
//! show, skip, back, quit), bad input at a prompt, the JSON Lines protocol,
//! `check --follow-through`, and one session on a real terminal (tmux).
//!
//! Every expected value is derived by hand in the comments of the problems.

mod common;
use common::*;
use serde_json::Value;
use std::path::PathBuf;

/// Writes a file into a fresh temporary directory of this test process.
fn temp_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("grafika-practice-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The pipeline: Pe = (0, 0, 5), Pr = the origin, Vup = (0, 1, 0), near 1,
/// fovy 90°, aspect 2, viewport 400 × 200, one point A = (1, 2, 0).
///   n = (Pe − Pr)/|Pe − Pr| = (0, 0, 5)/5 = (0, 0, 1)
///   u = Vup × n = (1·1 − 0·0, 0·0 − 0·1, 0·0 − 1·0) = (1, 0, 0)
///   v = n × u = (0·0 − 1·0, 1·1 − 0·0, 0·0 − 0·1) = (0, 1, 0)
///   V = rows (u, −u·Pe) = (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, −5), (0, 0, 0, 1)
///   A' = (u·(A − Pe), v·(A − Pe), n·(A − Pe)), A − Pe = (1, 2, −5): (1, 2, −5)
///   d = −near = −1: A'' = (d·x/z, d·y/z, d) = (1/5, 2/5, −1)
///   top = near·tan 45° = 1, bottom −1, right = aspect·top = 2, left −2,
///   height 2, width 4
///   px = (xp − left)/width·400 = 2.2·100 = 220, py = (yp − bottom)/height·200 = 140
const PIPELINE: &str = r#"
title = "Pipeline by hand"
ask = ["view", "project", "window", "viewport"]
[camera]
eye = [0, 0, 5]
look = [0, 0, 0]
up = [0, 1, 0]
[perspective]
near = 1
fovy = 90
aspect = 2
viewport = [400, 200]
[points]
A = [1, 2, 0]
"#;

/// The pipeline's answers, all correct, in the order asked.
const PIPELINE_RIGHT: [&str; 14] = [
    "0, 0, 1",
    "1, 0, 0",
    "0, 1, 0",
    "1, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, -5; 0, 0, 0, 1",
    "1, 2, -5",
    "1/5, 2/5, -1",
    "1",
    "-1",
    "-2",
    "2",
    "2",
    "4",
    "220, 140",
    "",
];

/// The camera of the basis, view and projection problems: Pe = (4, 0, 3),
/// Pr = the origin, Vup = (0, 1, 0).
///   n = (4, 0, 3)/5 = (4/5, 0, 3/5)
///   u = Vup × n = (1·3/5 − 0, 0 − 0, 0 − 1·4/5) = (3/5, 0, −4/5)
///   v = n × u = (0·(−4/5) − 3/5·0, 3/5·3/5 + 4/5·4/5, 0) = (0, 1, 0)
const CAMERA: &str = "[camera]\neye = [4, 0, 3]\nlook = [0, 0, 0]\nup = [0, 1, 0]\n";

/// The lighting problem (phong, ka 0.4, kd 0.6, ks 0.7, n 4 by default):
///   N = (4, 0, 3)/5 = (0.8, 0, 0.6), L = (0, 0, 1), V = (0, 0, 1)
///   cos α = L·N = 0.6;  R = 2N(L·N) − L = (0.96, 0, 0.72) − (0, 0, 1) = (0.96, 0, −0.28)
///   cos β = R·V = −0.28;  ambient = 0.4·Cs = (0.4, 0.2, 0)
///   diffuse = 0.6·0.6·Cs = (0.36, 0.18, 0);  specular = 0.7·max(−0.28, 0)⁴ = 0
///   color = (0.76, 0.38, 0)
const SHADE: &str = r#"
title = "Lighting by hand"
ask = ["shade"]
[shade]
model = "phong"
light = [0, 0, 1]
normal = [4, 0, 3]
view = [0, 0, 1]
color = [1, 0.5, 0]
"#;

/// Runs a practice session with `--json`; the events, one per line.
fn session(args: &[&str], lines: &[&str]) -> Vec<Value> {
    let input = lines.join("\n") + "\n";
    let out = grafika()
        .arg("practice")
        .args(args)
        .arg("--json")
        .write_stdin(input)
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "practice failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON: {l}: {e}")))
        .collect()
}

/// A session on a problem text written to a temporary file.
fn session_on(name: &str, problem: &str, lines: &[&str]) -> Vec<Value> {
    let f = temp_file(name, problem);
    session(&[f.to_str().unwrap()], lines)
}

fn of_kind<'a>(events: &'a [Value], kind: &str) -> Vec<&'a Value> {
    events.iter().filter(|e| e["event"] == kind).collect()
}

/// The codes of the verdicts, in order.
fn codes(events: &[Value]) -> Vec<String> {
    of_kind(events, "verdict")
        .iter()
        .map(|v| v["code"].as_str().unwrap().to_string())
        .collect()
}

fn keys(events: &[Value], kind: &str) -> Vec<String> {
    of_kind(events, kind)
        .iter()
        .map(|v| v["key"].as_str().unwrap().to_string())
        .collect()
}

fn summary(events: &[Value]) -> &Value {
    let s = events.last().expect("events");
    assert_eq!(s["event"], "summary", "the last event is the summary");
    s
}

/// Every one of the `n` values right, and every one of the scheme's
/// `marks` earned (the steps between the values a problem asks are
/// working, worth nothing of their own).
fn all_correct(events: &[Value], n: usize, marks: u32) {
    let c = codes(events);
    assert_eq!(c.len(), n, "{c:?}");
    assert!(
        c.iter()
            .all(|c| c.starts_with("correct.") && c != "correct.follow_through"),
        "{c:?}"
    );
    let s = summary(events);
    assert_eq!(s["score"]["points"], f64::from(marks));
    assert_eq!(s["score"]["total"], marks);
    assert_eq!(s["steps"], n);
    assert_eq!(s["counts"]["follow_through"], 0);
}

#[test]
fn pipeline_all_correct_in_the_texts_order() {
    let ev = session_on("pipeline.toml", PIPELINE, &PIPELINE_RIGHT);
    assert_eq!(
        keys(&ev, "ask"),
        [
            "view.n",
            "view.u",
            "view.v",
            "view.matrix",
            "view.points.A",
            "project.points.A",
            "window.top",
            "window.bottom",
            "window.left",
            "window.right",
            "window.height",
            "window.width",
            "viewport.pixels.A"
        ]
    );
    // the view matrix is working: the other 12 values are asked
    all_correct(&ev, 13, 12);
}

#[test]
fn pipeline_follow_through_from_a_reversed_n() {
    // n given as Pr − Pe normalized, (0, 0, −1): a unit vector, so later
    // steps may follow from it. u = Vup × n = (1·(−1) − 0·0, 0·0 − 0·(−1),
    // 0·0 − 1·0) = (−1, 0, 0); v = n × u = (0·0 − (−1)·0, (−1)(−1) − 0·0,
    // 0·0 − 0·(−1)) = (0, 1, 0), which is right. V rows (−1, 0, 0, 0),
    // (0, 1, 0, 0), (0, 0, −1, 5); A − Pe = (1, 2, −5): A' = (−1, 2, 5);
    // A'' = (−1·(−1)/5, −1·2/5, −1) = (1/5, −2/5, −1); px = (1/5 + 2)/4·400
    // = 220, py = (−2/5 + 1)/2·200 = 60.
    let ev = session_on(
        "pipeline-ft.toml",
        PIPELINE,
        &[
            "0, 0, -1",
            "-1, 0, 0",
            "0, 1, 0",
            "-1, 0, 0, 0; 0, 1, 0, 0; 0, 0, -1, 5; 0, 0, 0, 1",
            "-1, 2, 5",
            "0.2; -0,4; -1",
            "1",
            "-1",
            "-2",
            "2",
            "2",
            "4",
            "220, 60",
        ],
    );
    let c = codes(&ev);
    assert_eq!(c[0], "wrong");
    assert_eq!(c[2], "correct.exact");
    for k in [1, 3, 4, 5, 12] {
        assert_eq!(c[k], "correct.follow_through", "answer {k}: {c:?}");
    }
    let v = of_kind(&ev, "verdict");
    assert_eq!(v[1]["follow_through"], serde_json::json!([-1.0, 0.0, 0.0]));
    let s = summary(&ev);
    assert_eq!(s["counts"]["follow_through"], 5);
    assert_eq!(s["counts"]["correct"], 12);
    assert_eq!(s["counts"]["wrong"], 1);
    // every value asked but n: 11 of the 12 marks (the matrix is working)
    assert_eq!(s["score"]["points"], 11.0);
}

#[test]
fn no_follow_through_from_an_unnormalized_n() {
    // n given as Pe − Pr = (0, 0, 5), not divided by |Pe − Pr| = 5: no
    // unit vector, so nothing follows from it, and the note says why. v =
    // n × u = (0, 0, 5) × (1, 0, 0) = (0, 5, 0) would.
    let ev = session_on(
        "pipeline-no-ft.toml",
        PIPELINE,
        &["0, 0, 5", "1, 0, 0", "0, 5, 0", "quit"],
    );
    assert_eq!(codes(&ev), ["wrong", "correct.exact", "wrong"]);
    let v = of_kind(&ev, "verdict");
    let note = v[2]["note"].as_str().unwrap();
    assert!(
        note.contains("n is not a unit vector, so v can't follow from it"),
        "{note}"
    );
    assert_eq!(v[0]["mistakes"], serde_json::json!(["n_not_normalized"]));
}

#[test]
fn pixels_follow_from_the_students_window() {
    // top given as 2 (twice the right 1): bottom −2, right = 2·2 = 4, left −4,
    // height 4, width 8; A'' = (1/5, 2/5): px = (0.2 + 4)/8·400 = 210,
    // py = (0.4 + 2)/4·200 = 120.
    let mut lines = PIPELINE_RIGHT[..6].to_vec();
    lines.extend(["2", "-2", "-4", "4", "4", "8", "210, 120"]);
    let ev = session_on("pipeline-window.toml", PIPELINE, &lines);
    let c = codes(&ev);
    assert_eq!(c[6], "wrong");
    assert!(
        c[7..].iter().all(|c| c == "correct.follow_through"),
        "{c:?}"
    );
}

#[test]
fn a_diagnosed_mistake_cross_order() {
    // u = n × Vup = (0, 0, 1) × (0, 1, 0) = (0·0 − 1·1, 1·0 − 0·0, 0) = (−1, 0, 0)
    let ev = session_on(
        "pipeline-cross.toml",
        PIPELINE,
        &["0, 0, 1", "-1, 0, 0", "quit"],
    );
    let v = of_kind(&ev, "verdict");
    assert_eq!(v[1]["code"], "wrong");
    assert!(
        v[1]["mistakes"]
            .as_array()
            .unwrap()
            .contains(&"cross_order".into()),
        "{}",
        v[1]
    );
    let s = summary(&ev);
    assert_eq!(s["mistakes"][0]["code"], "cross_order");
    assert_eq!(s["counts"]["unanswered"], 11);
    // the weakest topic is the basis, and under half the points: easier
    assert_eq!(s["next"]["topic"], "basis");
    assert_eq!(s["next"]["difficulty"], "easy");
}

#[test]
fn basis_all_correct_with_decimals_and_decimal_commas() {
    let p = format!("title = \"Basis\"\nask = [\"view\"]\n[check]\nkeys = [\"view.n\", \"view.u\", \"view.v\"]\n{CAMERA}");
    let ev = session_on(
        "basis.toml",
        &p,
        &["0,8; 0; 0,6", "0.6, 0, -0.8", "0, 1, 0"],
    );
    assert_eq!(keys(&ev, "ask"), ["view.n", "view.u", "view.v"]);
    all_correct(&ev, 3, 3);
}

#[test]
fn view_all_correct() {
    // Q = the origin: Q − Pe = (−4, 0, −3): Q' = (−12/5 + 12/5, 0, −16/5 − 9/5) = (0, 0, −5);
    // V's last column: −u·Pe = −(12/5 − 12/5) = 0, −v·Pe = 0, −n·Pe = −(16/5 + 9/5) = −5.
    let p = format!("title = \"View\"\nask = [\"view\"]\n{CAMERA}[points]\nQ = [0, 0, 0]\n");
    let ev = session_on(
        "view.toml",
        &p,
        &[
            "4/5, 0, 3/5",
            "3/5, 0, -4/5",
            "0, 1, 0",
            "3/5, 0, -4/5, 0; 0, 1, 0, 0; 4/5, 0, 3/5, -5; 0, 0, 0, 1",
            "0, 0, -5",
        ],
    );
    // the view matrix is working: u, v, n and Q' are asked
    all_correct(&ev, 5, 4);
}

#[test]
fn project_all_correct_with_or_without_zp() {
    // near 1, d = −1. Q' = (0, 0, −5) → Q'' = (0, 0, −1);
    // R = (0, 2, 0): R − Pe = (−4, 2, −3), R' = (−12/5 + 12/5, 2, −16/5 − 9/5) = (0, 2, −5)
    // → R'' = (0, −1·2/−5, −1) = (0, 2/5, −1).
    let p = format!(
        "title = \"Project\"\nask = [\"project\"]\n{CAMERA}[perspective]\nnear = 1\n[points]\nQ = [0, 0, 0]\nR = [0, 2, 0]\n"
    );
    let ev = session_on("project.toml", &p, &["0, 0, -1", "0, 0.4"]);
    assert_eq!(keys(&ev, "ask"), ["project.points.Q", "project.points.R"]);
    all_correct(&ev, 2, 2);
}

#[test]
fn window_all_correct() {
    // near 2, fovy 60°, aspect 3/2: top = 2·tan 30° = 2/√3 = 2√3/3 ≈ 1.1547,
    // right = 3/2·top = √3, height = 4√3/3, width = 2√3.
    let p = "title = \"Window\"\nask = [\"window\"]\n[perspective]\nnear = 2\nfovy = 60\naspect = 1.5\n";
    let ev = session_on(
        "window.toml",
        p,
        &[
            "2/sqrt(3)",
            "-1.1547",
            "-sqrt(3)",
            "1.732",
            "4*sqrt(3)/3",
            "3,464",
        ],
    );
    all_correct(&ev, 6, 6);
}

#[test]
fn a_too_coarse_answer_earns_half() {
    // near 0.1, fovy 60°: top = 0.1·tan 30° = 0.1/√3 ≈ 0.057735. "0.06" is
    // that rounded to one significant figure (the default asks for two);
    // "0.058" to two; "1" is wrong.
    let p = "title = \"Window\"\nask = [\"window\"]\n[perspective]\nnear = 0.1\nfovy = 60\naspect = 1.5\n";
    let c = |answer: &str| codes(&session_on("coarse.toml", p, &[answer, "quit"]));
    assert_eq!(c("1"), ["wrong"]);
    assert_eq!(c("0.058"), ["correct.rounded"]);
    assert_eq!(c("0.06"), ["too_coarse"]);
    let ev = session_on("coarse.toml", p, &["0.06", "quit"]);
    assert_eq!(summary(&ev)["score"]["points"], 0.5);
}

/// The text's clipping example: P(t) = (4 − 6t, 2 + 4t, 2 − t) (see
/// problems/text-clip.toml): codes 000010 and 001001; left t = 2/3 at
/// (0, 14/3, 4/3), above y = 4: code 001000; right t = 1/6 at
/// (3, 8/3, 11/6), inside: 000000; top t = 1/2 at (1, 4, 3/2), inside:
/// 000000; the segment from (3, 8/3, 11/6) to (1, 4, 3/2); clipped.
const CLIP_RIGHT: [&str; 13] = [
    "000010",
    "1001",
    "2/3",
    "0, 14/3, 4/3",
    "001 000",
    "1/6",
    "3, 8/3, 11/6",
    "0",
    "0.5",
    "(1, 4, 1.5)",
    "000000",
    "(3, 8/3, 11/6); (1, 4, 3/2)",
    "di-clip",
];

#[test]
fn clip_all_correct() {
    let ev = session(&["problems/text-clip.toml"], &CLIP_RIGHT);
    assert_eq!(
        keys(&ev, "ask"),
        [
            "clip.code0",
            "clip.code1",
            "clip.intersections.left.t",
            "clip.intersections.left.point",
            "clip.intersections.left.code",
            "clip.intersections.right.t",
            "clip.intersections.right.point",
            "clip.intersections.right.code",
            "clip.intersections.top.t",
            "clip.intersections.top.point",
            "clip.intersections.top.code",
            "clip.segment",
            "clip.status"
        ]
    );
    // the intersections are working: the codes, the segment and the
    // status are asked
    all_correct(&ev, 13, 4);
}

#[test]
fn clip_follow_through_from_a_wrong_code_but_not_a_misprinted_point() {
    // code0 001000 (wrong): AND with 001001 is 001000 ≠ 0, so "rejected"
    // follows. The right intersection as the text printed it, (3, 20/6,
    // 11/6), is on its plane x = 3 but not on the segment (at t = 1/6 the
    // segment is at (3, 8/3, 11/6)): the clipped segment from it to (1, 4,
    // 3/2) does not follow, and the note says why.
    let mut lines = CLIP_RIGHT.to_vec();
    lines[0] = "001000";
    lines[6] = "3, 20/6, 11/6";
    lines[11] = "(3, 20/6, 11/6); (1, 4, 1.5)";
    lines[12] = "rejected";
    let ev = session(&["problems/text-clip.toml"], &lines);
    let c = codes(&ev);
    assert_eq!(c[0], "wrong");
    assert_eq!(c[6], "wrong");
    // the text's misprint, named with the erratum's reason
    let v = of_kind(&ev, "verdict");
    assert_eq!(v[6]["mistakes"], serde_json::json!(["copied_misprint"]));
    assert!(v[6]["why"].as_str().unwrap().contains("20/6"), "{}", v[6]);
    assert_eq!(c[11], "wrong");
    let note = v[11]["note"].as_str().unwrap();
    assert!(note.contains("is not on the segment P0P1"), "{note}");
    assert_eq!(c[12], "correct.follow_through");
    assert_eq!(summary(&ev)["counts"]["follow_through"], 1);
}

#[test]
fn an_intersection_off_its_plane_is_not_credited() {
    // left t given as 1/3 (wrong): P(1/3) = (4 − 2, 2 + 4/3, 2 − 1/3) =
    // (2, 10/3, 5/3), which is not on the left plane x = 0: no
    // intersection, so no follow-through.
    let mut lines = CLIP_RIGHT[..2].to_vec();
    lines.extend(["1/3", "2, 10/3, 5/3", "quit"]);
    let ev = session(&["problems/text-clip.toml"], &lines);
    assert_eq!(
        codes(&ev),
        ["correct.exact", "correct.exact", "wrong", "wrong"]
    );
}

#[test]
fn clip_outcode_reversed_is_diagnosed() {
    let ev = session(&["problems/text-clip.toml"], &["010000", "quit"]);
    let v = of_kind(&ev, "verdict");
    assert_eq!(v[0]["mistakes"], serde_json::json!(["outcode_reversed"]));
}

#[test]
fn shade_all_correct() {
    let ev = session_on(
        "shade.toml",
        SHADE,
        &[
            "0, 0, 1",
            "0.8, 0, 0.6",
            "3/5",
            "0.96, 0, -0.28",
            "-0.28",
            "0.4, 0.2, 0",
            "0.36, 0.18, 0",
            "0, 0, 0",
            "0.76, 0.38, 0",
            "0.76, 0.38, 0",
        ],
    );
    assert_eq!(
        keys(&ev, "ask"),
        [
            "shade.L",
            "shade.N",
            "shade.cos_alpha",
            "shade.R",
            "shade.cos_beta",
            "shade.ambient",
            "shade.diffuse",
            "shade.specular",
            "shade.unclamped",
            "shade.color"
        ]
    );
    // a lighting problem asks its colour; the rest is working
    all_correct(&ev, 10, 1);
}

#[test]
fn shade_follow_through_from_a_wrong_unit_normal() {
    // N given as (0.6, 0, 0.8), a unit vector but not (4, 0, 3)/5:
    // cos α = L·N = 0.8; R = 2·0.8·(0.6, 0, 0.8) − (0, 0, 1) = (0.96, 0,
    // 0.28); cos β = R·V = 0.28; diffuse = 0.6·0.8·Cs = (0.48, 0.24, 0);
    // specular = 0.7·0.28⁴ = 0.7·0.00614656 = 0.004302592 per channel;
    // the sum (0.4 + 0.48 + 0.0043026, 0.2 + 0.24 + 0.0043026, 0.0043026)
    // = (0.8843026, 0.4443026, 0.0043026), which needs no clamping.
    let ev = session_on(
        "shade-ft.toml",
        SHADE,
        &[
            "0, 0, 1",
            "0.6, 0, 0.8",
            "0.8",
            "0.96, 0, 0.28",
            "0.28",
            "0.4, 0.2, 0",
            "0.48, 0.24, 0",
            "0.0043026, 0.0043026, 0.0043026",
            "0,8843; 0,4443; 0,004303",
            "0.8843, 0.4443, 0.004303",
        ],
    );
    let c = codes(&ev);
    assert_eq!(c[1], "wrong");
    assert_eq!(c[5], "correct.exact");
    for k in [2, 3, 4, 6, 7, 8, 9] {
        assert_eq!(c[k], "correct.follow_through", "answer {k}: {c:?}");
    }
}

#[test]
fn no_follow_through_from_an_unnormalized_normal() {
    // N given as (4, 0, 3), not divided by 5: cos α = L·N = 3 would follow
    // from it, but it is no unit vector.
    let ev = session_on(
        "shade-no-ft.toml",
        SHADE,
        &["0, 0, 1", "4, 0, 3", "3", "quit"],
    );
    assert_eq!(codes(&ev), ["correct.exact", "wrong", "wrong"]);
    let note = of_kind(&ev, "verdict")[2]["note"]
        .as_str()
        .unwrap()
        .to_string();
    assert!(note.contains("N is not a unit vector"), "{note}");
}

#[test]
fn shade_reflect_plus_l_is_diagnosed() {
    // R = 2N(L·N) + L = (0.96, 0, 0.72) + (0, 0, 1) = (0.96, 0, 1.72)
    let ev = session_on(
        "shade-r.toml",
        SHADE,
        &["0, 0, 1", "0.8, 0, 0.6", "0.6", "0.96, 0, 1.72", "quit"],
    );
    let v = of_kind(&ev, "verdict");
    assert_eq!(v[3]["mistakes"], serde_json::json!(["reflect_plus_l"]));
}

#[test]
fn hint_show_skip_back_quit() {
    let ev = session_on(
        "commands.toml",
        PIPELINE,
        &[
            "back", "hint", "hint", "hint", "0, 0, 1", "skip", "back", "show", "0, 1, 0", "quit",
        ],
    );
    let kinds: Vec<&str> = ev.iter().map(|e| e["event"].as_str().unwrap()).collect();
    assert_eq!(
        kinds,
        [
            "ask", "ask", "hint", "hint", "ask", "verdict", "ask", "skip", "ask", "ask", "show",
            "ask", "verdict", "ask", "summary"
        ]
    );
    assert_eq!(ev[1]["again"], "nothing_before");
    assert_eq!(ev[2]["level"], 1);
    assert_eq!(ev[2]["formula"], "n = (Pe − Pr) / |Pe − Pr|");
    assert!(ev[2]["values"].is_null(), "level 1 gives the formula only");
    assert_eq!(ev[3]["level"], 2);
    assert!(
        ev[3]["values"]["Pe"].is_array(),
        "level 2 substitutes: {}",
        ev[3]
    );
    assert_eq!(ev[4]["again"], "no_more_hints");
    // skip u, go back to it, reveal it
    assert_eq!(ev[7]["key"], "view.u");
    assert_eq!(ev[9]["key"], "view.u");
    assert_eq!(
        ev[10]["expected"]["exact"],
        serde_json::json!(["1", "0", "0"])
    );
    let s = summary(&ev);
    assert_eq!(s["counts"]["revealed"], 1);
    assert_eq!(s["counts"]["skipped"], 0, "the skip was taken back");
    assert_eq!(s["counts"]["correct"], 2);
    assert_eq!(s["hints"], 2);
    assert_eq!(s["counts"]["unanswered"], 10);
}

#[test]
fn bad_input_is_asked_again_with_a_reason() {
    let ev = session_on(
        "bad.toml",
        PIPELINE,
        &["", "1/(", "1, 2", "0, 0, x", "zero", "0, 0, 1", "quit"],
    );
    let kinds: Vec<&str> = ev.iter().map(|e| e["event"].as_str().unwrap()).collect();
    assert_eq!(
        kinds,
        [
            "ask", "ask", "verdict", "ask", "verdict", "ask", "verdict", "ask", "verdict", "ask",
            "verdict", "ask", "summary"
        ]
    );
    assert_eq!(ev[1]["again"], "empty");
    assert_eq!(
        codes(&ev),
        [
            "unparseable",
            "unparseable",
            "unparseable",
            "unparseable",
            "correct.exact"
        ]
    );
    assert!(of_kind(&ev, "ask")[2..5]
        .iter()
        .all(|a| a["key"] == "view.n" && a["again"] == "unreadable"));
    assert_eq!(summary(&ev)["score"]["points"], 1.0);
}

#[test]
fn end_of_input_quits_with_a_summary() {
    let ev = session_on("eof.toml", PIPELINE, &["0, 0, 1"]);
    assert_eq!(summary(&ev)["counts"]["unanswered"], 12);
}

#[test]
fn a_drawn_problem_for_every_topic() {
    for topic in [
        "basis", "view", "project", "window", "clip", "shade", "pipeline",
    ] {
        let ev = session(
            &["--topic", topic, "--difficulty", "easy", "--seed", "7"],
            &["skip"; 40],
        );
        let s = summary(&ev);
        let n = s["steps"].as_u64().unwrap();
        assert!(n >= 2, "{topic}: {n} values");
        assert_eq!(s["counts"]["skipped"], n, "{topic}");
        assert_eq!(
            s["next"]["difficulty"], "easy",
            "{topic}: nothing right, stay easy"
        );
    }
}

#[test]
fn text_session_fits_80_columns_and_speaks_indonesian() {
    let f = temp_file("text.toml", PIPELINE);
    // n reversed (Pr − Pe): u follows from it, v is right
    let input = "0,0,-1\n-1,0,0\n0;1;0\nhint\nhint\nshow\nfoo\nquit\n";
    for lang in ["en", "id"] {
        let out = grafika()
            .args(["practice", f.to_str().unwrap(), "--lang", lang])
            .env("NO_COLOR", "1")
            .write_stdin(input)
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap();
        for line in text.lines() {
            assert!(line.chars().count() <= 80, "{lang}: too wide: {line}");
        }
        assert!(!text.contains('\x1b'), "no colour off a terminal");
        let (ft, sum) = match lang {
            "en" => (
                "correct given your earlier answers",
                "Summary: 2/12 marks = 16.7% (the values the problem asks; 13 steps)",
            ),
            _ => (
                "benar menurut jawabanmu sebelumnya",
                "Ringkasan: 2/12 poin = 16,7% (jawaban yang ditanyakan soal; 13 langkah)",
            ),
        };
        assert!(text.contains(ft), "{lang}: {text}");
        assert!(text.contains(sum), "{lang}: {text}");
        assert!(
            text.contains("> 0;1;0"),
            "answers are echoed off a terminal"
        );
    }
}

#[test]
fn practice_errors_name_the_field() {
    let err = json_err(&["practice"]);
    assert_eq!(err["field"], "<FILE>");
    let err = json_err(&["practice", "-"]);
    assert_eq!(err["field"], "file");
    let err = json_err(&["practice", "--topic", "clip", "--tolerance=-1"]);
    assert_eq!(err["field"], "tolerance");
}

#[test]
fn check_follow_through_marks_answer_files_the_same_way() {
    let p = temp_file("ft-problem.toml", PIPELINE);
    // top 2 (wrong) and the rest of the window and the pixel from it
    let answers = temp_file(
        "ft-answers.toml",
        r#"
"view.n" = "0, 0, 1"
"view.u" = "1, 0, 0"
"view.v" = "0, 1, 0"
"view.points.A" = "1, 2, -5"
"project.points.A" = "1/5, 2/5, -1"
"window.top" = "2"
"window.bottom" = "-2"
"window.left" = "-4"
"window.right" = "4"
"window.height" = "4"
"window.width" = "8"
"viewport.pixels.A" = "210, 120"
"#,
    );
    let (p, a) = (p.to_str().unwrap(), answers.to_str().unwrap());
    let plain = json_ok(&["check", p, "--answers", a]);
    assert_eq!(plain["counts"]["wrong"], 7);
    assert_eq!(plain["counts"]["follow_through"], 0);
    let ft = json_ok(&["check", p, "--answers", a, "--follow-through"]);
    assert_eq!(ft["counts"]["wrong"], 1);
    assert_eq!(ft["counts"]["follow_through"], 6);
    assert_eq!(ft["settings"]["follow_through"], true);
    let px = ft["answers"]
        .as_array()
        .unwrap()
        .iter()
        .find(|x| x["key"] == "viewport.pixels.A")
        .unwrap();
    assert_eq!(px["code"], "correct.follow_through");
    // a directory of students: the CSV has the count
    let dir = answers.parent().unwrap().join("class");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(&answers, dir.join("ani.toml")).unwrap();
    let out = grafika()
        .args([
            "check",
            p,
            "--answers",
            dir.to_str().unwrap(),
            "--follow-through",
            "--csv",
            "-",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let csv: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("student,"))
        .collect();
    assert!(
        csv[0].contains(",unparseable,follow_through,mistakes"),
        "{}",
        csv[0]
    );
    assert!(csv[1].starts_with("ani,"), "{}", csv[1]);
    assert!(csv[1].contains(",0,6,"), "6 by follow-through: {}", csv[1]);
}

#[test]
fn budis_one_slip_costs_one_answer_with_follow_through() {
    // Budi took u = n × Vup (problems/answers/triangle/budi.toml): u is
    // wrong; v = n × u, the eye coordinates, the projections and the pixels
    // computed from it are right given his u (10 answers); n and the window
    // do not depend on u (7 right).
    let m = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        "problems/answers/triangle/budi.toml",
        "--follow-through",
    ]);
    assert_eq!(m["counts"]["wrong"], 1);
    assert_eq!(m["counts"]["correct"], 17);
    assert_eq!(m["counts"]["follow_through"], 10);
    assert_eq!(m["diagnosis"][0]["code"], "cross_order");
}

/// The interactive terminal, through tmux: the prompt, a verdict in colour,
/// and no colour with NO_COLOR. Skipped (with a message) without tmux.
#[test]
fn interactive_terminal_through_tmux() {
    if std::process::Command::new("tmux")
        .arg("-V")
        .output()
        .is_err()
    {
        eprintln!("SKIPPED interactive_terminal_through_tmux: tmux is not installed");
        return;
    }
    let bin = assert_cmd::cargo::cargo_bin("grafika");
    let f = temp_file("tmux.toml", PIPELINE);
    for (no_color, want_escape) in [(false, true), (true, false)] {
        let name = format!("grafika-practice-{}-{no_color}", std::process::id());
        let env = if no_color { "NO_COLOR=1 " } else { "" };
        let cmd = format!(
            "{env}{} practice {} --lang en; sleep 30",
            bin.display(),
            f.display()
        );
        let tmux = |args: &[&str]| {
            std::process::Command::new("tmux")
                .args(args)
                .output()
                .expect("tmux runs")
        };
        let started = tmux(&[
            "new-session",
            "-d",
            "-s",
            &name,
            "-x",
            "80",
            "-y",
            "40",
            &cmd,
        ]);
        if !started.status.success() {
            eprintln!("SKIPPED interactive_terminal_through_tmux: tmux cannot start a session");
            return;
        }
        // wait (by polling, not by a timed assertion) for the first prompt
        let screen = |escapes: bool| {
            let mut a = vec!["capture-pane", "-p", "-t", name.as_str()];
            if escapes {
                a.push("-e");
            }
            String::from_utf8_lossy(&tmux(&a).stdout).into_owned()
        };
        let wait_for = |text: &str| {
            for _ in 0..200 {
                if screen(false).contains(text) {
                    return true;
                }
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            false
        };
        let ready = wait_for("[1/13]");
        if ready {
            tmux(&["send-keys", "-t", &name, "0, 0, 1", "Enter"]);
        }
        let judged = ready && wait_for("[2/13]");
        let plain = screen(false);
        let coloured = screen(true);
        tmux(&["kill-session", "-t", &name]);
        assert!(
            judged,
            "the session did not reach the second value:\n{plain}"
        );
        assert!(
            plain.contains("> 0, 0, 1"),
            "the prompt and the typed answer:\n{plain}"
        );
        assert!(plain.contains("✓ correct"), "{plain}");
        assert_eq!(
            coloured.contains("\x1b[32m"),
            want_escape,
            "colour on a terminal unless NO_COLOR:\n{coloured}"
        );
    }
}

#[test]
fn practice_says_the_likely_mistake_in_indonesian() {
    // seed 3, basis, easy: Pe = (5, −10, −1), Pr = (1, 2, 2), so
    // Pe − Pr = (4, −12, −3), |Pe − Pr| = √(16 + 144 + 9) = 13 and n =
    // (4/13, −12/13, −3/13). Answering (4, −12, −3) is the catalog's
    // n_not_normalized; under an
    // Indonesian locale its description is said in Indonesian, both in the
    // verdict and in the summary (an earlier version said it in English).
    let out = grafika()
        .args([
            "practice",
            "--topic",
            "basis",
            "--difficulty",
            "easy",
            "--seed",
            "3",
        ])
        .env_remove("GRAFIKA_LANG")
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "id_ID.UTF-8")
        .write_stdin("4, -12, -3\n")
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("Peye = (5; -10; -1)"), "{text}");
    assert!(text.contains("[n_not_normalized]"), "{text}");
    assert!(!text.contains("not divided"), "{text}");
    let unwrapped = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let said = "n = Pe − Pr tidak dibagi dengan |Pe − Pr|";
    assert!(
        unwrapped.contains(&format!("Kemungkinan kesalahan: {said}")),
        "{text}"
    );
    assert!(unwrapped.contains(&format!("• {said}")), "{text}");
}

/// The numbers of a JSON value (a number, or lists of them).
fn json_numbers(v: &Value, out: &mut Vec<f64>) {
    match v {
        Value::Number(n) => out.extend(n.as_f64()),
        Value::Array(a) => a.iter().for_each(|x| json_numbers(x, out)),
        Value::Object(o) => o.values().for_each(|x| json_numbers(x, out)),
        _ => {}
    }
}

/// How many significant figures the shortest decimal of x has.
fn figures(x: f64) -> usize {
    let s = format!("{:e}", x.abs());
    s.split('e')
        .next()
        .unwrap()
        .chars()
        .filter(char::is_ascii_digit)
        .count()
}

#[test]
fn no_hint_gives_the_answer_away_on_any_shipped_problem() {
    // Every key of every shipped problem: hint, hint, show. A hint may not
    // hold the value asked (the exact form shown), nor any of its numbers
    // with three or more significant figures (up to sign) other than 0, ±1
    // and the numbers the problem states (its inputs, as `solve --json`
    // gives them). `show` is what reveals it.
    let mut asked = 0;
    for entry in std::fs::read_dir(root().join("problems")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|x| x != "toml") {
            continue;
        }
        let file = path.to_str().unwrap().to_string();
        let Ok(solved) = std::panic::catch_unwind(|| json_ok(&["solve", &file])) else {
            continue;
        };
        let mut stated = Vec::new();
        json_numbers(&solved["input"], &mut stated);
        let lines: Vec<&str> = std::iter::repeat_n(["hint", "hint", "show"], 60)
            .flatten()
            .collect();
        let ev = session(&[&file], &lines);
        let mut hints: Vec<&Value> = Vec::new();
        for e in &ev {
            match e["event"].as_str().unwrap() {
                "hint" => hints.push(e),
                "show" => {
                    asked += 1;
                    let key = e["key"].as_str().unwrap();
                    let exact = e["expected"]["exact"].to_string();
                    let mut nums = Vec::new();
                    json_numbers(&e["expected"]["decimal"], &mut nums);
                    let telling: Vec<f64> = nums
                        .into_iter()
                        .filter(|x| figures(*x) >= 3)
                        .filter(|x| {
                            !stated
                                .iter()
                                .any(|s| (s.abs() - x.abs()).abs() <= 1e-9 * x.abs())
                        })
                        .collect();
                    for h in hints.drain(..) {
                        let mut shown = Vec::new();
                        json_numbers(&h["values"], &mut shown);
                        for x in &telling {
                            assert!(
                                !shown
                                    .iter()
                                    .any(|y| (y.abs() - x.abs()).abs() <= 1e-9 * x.abs()),
                                "{file} {key}: hint {} shows {x}: {h}",
                                h["level"]
                            );
                        }
                        assert!(
                            exact.len() < 4 || exact == "null" || !h.to_string().contains(&exact),
                            "{file} {key}: hint {} holds {exact}: {h}",
                            h["level"]
                        );
                        if e["expected"]["decimal"].is_string() {
                            // an outcode or status: the hint holds no such word
                            let word = e["expected"]["decimal"].as_str().unwrap();
                            let shown = h["values"].to_string();
                            assert!(!shown.contains(word), "{file} {key}: {h}");
                        }
                    }
                }
                _ => {}
            }
        }
    }
    assert!(asked > 150, "only {asked} values asked");
}

#[test]
fn the_texts_forms_are_read_at_the_prompt_and_echoed_as_read() {
    // The triangle example (values by hand in tests/check.rs): n, u, v,
    // the view matrix by rows, A′ ending in −6/√2, B′ with decimal commas
    // and ;, C′ as (x; y; z) with a unicode minus
    let lines = [
        "1/sqrt(2), 0, 1/sqrt(2)",
        "(√2/2, 0, −√2/2)",
        "[0, 1, 0]",
        "1/√2, 0, -1/√2, 0; 0, 1, 0, -1; (1/2)sqrt(2), 0, √2/2, -3sqrt(2); 0, 0, 0, 1",
        "0, -1, -6/sqrt(2)",
        "(0,7071; −1; −3,536)",
        "(−1/√2; −1; −5/√2)",
        "quit",
    ];
    let ev = session(&["problems/text-triangle.toml"], &lines);
    let c = codes(&ev);
    assert_eq!(c.len(), 7, "{c:?}");
    assert!(c.iter().all(|c| c.starts_with("correct.")), "{c:?}");
    let v = of_kind(&ev, "verdict");
    let r = std::f64::consts::FRAC_1_SQRT_2;
    let read: Vec<f64> = v[0]["read"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!((read[0] - r).abs() < 1e-15 && read[1] == 0.0 && (read[2] - r).abs() < 1e-15);
    // the text shows how each answer was read, in the student's language
    for (lang, read_as) in [
        ("en", "read as (√2/2, 0, √2/2)"),
        ("id", "dibaca sebagai (√2/2; 0; √2/2)"),
    ] {
        let out = grafika()
            .args(["practice", "problems/text-triangle.toml", "--lang", lang])
            .write_stdin("1/sqrt(2), 0, 1/sqrt(2)\nquit\n")
            .output()
            .unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.contains(read_as), "{lang}: {text}");
    }
}

#[test]
fn an_unreadable_answer_says_where_and_is_asked_again() {
    // `1/sqrt(2, 0, 1`: the `)` of sqrt is missing at column 9 of the answer
    for (lang, words) in [("en", "at column 9"), ("id", "di kolom 9")] {
        let out = grafika()
            .args(["practice", "problems/text-triangle.toml", "--lang", lang])
            .env("NO_COLOR", "1")
            .write_stdin("1/sqrt(2, 0, 1\nquit\n")
            .output()
            .unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(flat.contains(words), "{lang}: {text}");
        assert_eq!(text.matches("[1/19]").count(), 2, "asked again: {text}");
    }
}

#[test]
fn a_missing_last_bracket_is_named_once_at_the_end() {
    // `(1/sqrt(2), 0, 1/sqrt(2)` (24 characters): only the list's closing
    // `)` is missing, at column 25; the line says "cannot read" once.
    for (lang, words, once) in [
        ("en", "expected `)` at column 25, found the end", "cannot"),
        (
            "id",
            "seharusnya `)` di kolom 25, ditemukan akhir teks",
            "terbaca",
        ),
    ] {
        let out = grafika()
            .args(["practice", "problems/text-triangle.toml", "--lang", lang])
            .env("NO_COLOR", "1")
            .write_stdin("(1/sqrt(2), 0, 1/sqrt(2)\nquit\n")
            .output()
            .unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        let flat = text.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(flat.contains(words), "{lang}: {text}");
        let line = flat.split("✗").nth(1).unwrap_or_default();
        let line = line.split("[1/19]").next().unwrap_or_default();
        assert_eq!(line.matches(once).count(), 1, "{lang}: {line}");
    }
}

#[test]
fn a_revealed_value_stays_revealed_and_a_retry_counts_apart() {
    // n shown, then back, then answered right: still revealed. u answered
    // wrong, back, right: the first verdict stands; the retry is shown.
    let ev = session_on(
        "honest.toml",
        PIPELINE,
        &[
            "show", "back", "0, 0, 1", "-1, 0, 0", "back", "1, 0, 0", "quit",
        ],
    );
    let v = of_kind(&ev, "verdict");
    assert_eq!(v[0]["retry"], true);
    assert_eq!(v[1]["code"], "wrong");
    assert_eq!(v[1]["retry"], false);
    assert_eq!(v[2]["code"], "correct.exact");
    assert_eq!(v[2]["retry"], true);
    let s = summary(&ev);
    assert_eq!(s["score"]["points"], 0.0);
    assert_eq!(s["counts"]["revealed"], 1);
    assert_eq!(s["counts"]["wrong"], 1);
    assert_eq!(s["counts"]["correct"], 0);
    assert_eq!(
        s["retries"],
        serde_json::json!({"answered": 2, "correct": 2})
    );
}

/// The view matrix as the Indonesian prompt shows it, each row in brackets
/// with decimal commas: V's rows are (u, −u·Pe), (v, −v·Pe), (n, −n·Pe),
/// (0, 0, 0, 1) with u = (√2/2, 0, −√2/2), v = (0, 1, 0), n = (√2/2, 0, √2/2)
/// and Pe = (3, 1, 3): −u·Pe = 0, −v·Pe = −1, −n·Pe = −3√2 ≈ −4,2426.
#[test]
fn a_matrix_with_decimal_commas_is_read_as_the_prompt_shows() {
    let out = grafika()
        .args(["practice", "problems/text-triangle.toml", "--lang", "id"])
        .env("NO_COLOR", "1")
        .write_stdin(
            "skip\nskip\nskip\n(0,7071; 0; -0,7071; 0); (0; 1; 0; -1); \
             (0,7071; 0; 0,7071; -4,2426); (0; 0; 0; 1)\nquit\n",
        )
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("4 baris (a; b; c; d); (…); …"), "{text}");
    let after = text.split("[4/19]").nth(1).unwrap_or_default();
    assert!(after.contains("✓ benar"), "{text}");
}

#[test]
fn the_half_way_vector_is_asked_as_a_vector_and_the_terms_as_colours() {
    // H = (L + V)/|L + V| is a direction (x, y, z); the terms and the
    // colour are (r, g, b). The three are all 3-vectors under `shade.`.
    let out = grafika()
        .args(["practice", "problems/shade-blinn.toml"])
        .write_stdin("skip\n".repeat(12))
        .output()
        .expect("runs");
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("H (shade.H)  (x, y, z)"), "{text}");
    assert!(text.contains("(shade.specular)  (r, g, b)"), "{text}");
    assert!(text.contains("(shade.L)  (x, y, z)"), "{text}");
}
