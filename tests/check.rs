//! `grafika check`: verdicts, the mistake diagnosis, the text's printed
//! answers, directories of students, and the JSON for autograders.

mod common;
use common::*;
use grafika::tutor::diagnose::Code;
use serde_json::Value;
use std::path::PathBuf;

/// The marking of one answer in the JSON.
fn answer<'a>(v: &'a Value, key: &str) -> &'a Value {
    v["answers"]
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["key"] == key)
        .unwrap_or_else(|| panic!("no answer {key} in {v}"))
}

fn codes(a: &Value) -> Vec<String> {
    a["diagnosis"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap().to_string())
        .collect()
}

/// Writes an answer file in a fresh temporary directory.
fn answers_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("grafika-check-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join(format!("{name}.toml"));
    std::fs::write(&f, text).unwrap();
    f
}

#[test]
fn the_texts_printed_answers_are_marked_and_its_errors_found() {
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers-from-text",
    ]);
    // A' = (0, −1, −6/√2): right, written in another form than −3√2.
    assert_eq!(answer(&v, "view.points.A")["code"], "correct.exact");
    // B'' printed (0.0067, −0.0283), but xp = d·x/z = (−0.1)(1/√2)/(−5/√2)
    // = 1/50 = 0.02; no known mistake gives 0.0067.
    let b = answer(&v, "project.points.B");
    assert_eq!(b["verdict"], "wrong");
    assert!(codes(b).is_empty(), "{b}");
    // The text's h = 0.1·tan 22.5° = 0.0414 is the half height (top):
    // as top it is right (0.041 rounds 0.041421 to 2 figures) ...
    assert_eq!(answer(&v, "window.top")["code"], "correct.rounded");
    // ... as the height it is wrong (height = 2·top ≈ 0.0828), and the
    // diagnosis names the half extent given as the height.
    let h = answer(&v, "window.height");
    assert_eq!(h["verdict"], "wrong");
    assert!(
        codes(h).contains(&"height_is_half_extent".to_string()),
        "{h}"
    );
    let d = v["diagnosis"].as_array().unwrap();
    assert_eq!(d[0]["code"], "height_is_half_extent");
    // The file's errata give the reason in the note.
    assert!(h["why"].as_str().unwrap().contains("half-height"), "{h}");
}

#[test]
fn the_texts_clipping_errors_are_found() {
    let v = json_ok(&["check", "problems/text-clip.toml", "--answers-from-text"]);
    // P(t) = (4 − 6t, 2 + 4t, 2 − t). x = 3: t = 1/6, y = 2 + 4/6 = 8/3, not 20/6.
    let a = answer(&v, "clip.intersections.right.point");
    assert_eq!(a["verdict"], "wrong");
    assert_eq!(a["expected"]["exact"][1], "8/3");
    // y = 4: t = 1/2, x = 4 − 3 = 1, not 2.
    let c = answer(&v, "clip.intersections.top.point");
    assert_eq!(c["verdict"], "wrong");
    assert_eq!(c["expected"]["exact"][0], "1");
    // The outcodes the text gives are right: P0 (4,2,2) is right of x = 3
    // (bit 2) → 000010; P1 (−2,6,1) is left (bit 1) and above y = 4 (bit 4) → 001001.
    assert_eq!(answer(&v, "clip.code0")["verdict"], "correct");
    assert_eq!(answer(&v, "clip.code1")["verdict"], "correct");
}

#[test]
fn a_sign_flipped_basis_is_diagnosed_once() {
    // u = n × Vup for the triangle example: the right u is (√2/2, 0, −√2/2),
    // n × Vup = −u; v = n × (−u) = −v = (0, −1, 0); every x', y' flips.
    let file = answers_file(
        "flip",
        r#"
view.u = ["-sqrt(2)/2", "0", "sqrt(2)/2"]
view.v = ["0", "-1", "0"]
view.points.A = ["0", "1", "-3*sqrt(2)"]
view.points.B = ["-0.7071", "1", "-3.536"]
"#,
    );
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        file.to_str().unwrap(),
    ]);
    for k in ["view.u", "view.v", "view.points.A", "view.points.B"] {
        let a = answer(&v, k);
        assert_eq!(a["verdict"], "wrong", "{a}");
        assert!(codes(a).contains(&"cross_order".to_string()), "{a}");
    }
    // Said once, for all four answers.
    let d = v["diagnosis"].as_array().unwrap();
    assert_eq!(d.iter().filter(|x| x["code"] == "cross_order").count(), 1);
    assert_eq!(d[0]["code"], "cross_order");
    assert_eq!(d[0]["keys"].as_array().unwrap().len(), 4);
}

#[test]
fn verdicts_codes_and_score() {
    // top = 0.1·tan 22.5° = (√2 − 1)/10 = 0.0414213...
    let file = answers_file(
        "verdicts",
        r#"
student = "Ani"
window.top = "0.041"
window.bottom = "(1-sqrt(2))/10"
window.height = "0.0414"
window.right = "0.08"
window.left = "-0.0828"
view.u = ["sqrt 2/2", "0", "-0.7071"]
view.n = ["0.7071", "0", "0.7071"]
"#,
    );
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        file.to_str().unwrap(),
    ]);
    assert_eq!(v["who"], "Ani");
    assert_eq!(answer(&v, "window.top")["code"], "correct.rounded");
    assert_eq!(answer(&v, "window.bottom")["code"], "correct.exact");
    assert_eq!(answer(&v, "window.left")["code"], "correct.tolerance");
    // right = 2·top = 0.0828...; 0.08 is 3.4% off and one significant figure
    // short of a correct rounding (0.08 would need |0.0828 − 0.08| ≤ 0.005: it
    // is, so it is rounded correctly, but to 1 figure).
    assert_eq!(answer(&v, "window.right")["verdict"], "too_coarse");
    // height = 2·top ≈ 0.0828, and 0.0414 is what half extent gives.
    assert_eq!(answer(&v, "window.height")["verdict"], "wrong");
    assert_eq!(answer(&v, "view.u")["verdict"], "unparseable");
    assert_eq!(answer(&v, "view.v")["verdict"], "missing");
    assert_eq!(answer(&v, "view.n")["verdict"], "correct");
    // expected values in decimal and exact form
    let t = &answer(&v, "window.top")["expected"];
    close(f(&t["decimal"]), 0.1 * (2f64.sqrt() - 1.0), 1e-15);
    assert_eq!(t["exact"], "(sqrt(2)-1)/10");
    // score: correct 1, too coarse ½, others 0
    let s = &v["score"];
    let c = &v["counts"];
    let want = f(&c["correct"]) + 0.5 * f(&c["too_coarse"]);
    close(f(&s["points"]), want, 0.0);
    assert_eq!(s["total"], 18);
}

#[test]
fn sig_figs_and_tolerance_flags_override() {
    let file = answers_file(
        "flags",
        "window.top = \"0.041\"\nwindow.right = \"0.0829\"\n",
    );
    let p = file.to_str().unwrap();
    // 0.041 has 2 significant figures: too coarse when 3 are required.
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        p,
        "--sig-figs",
        "3",
    ]);
    assert_eq!(answer(&v, "window.top")["verdict"], "too_coarse");
    // right = 0.0828427; 0.0829 is 0.07% off: correct at 0.1%, wrong at 0.01%.
    assert_eq!(answer(&v, "window.right")["code"], "correct.tolerance");
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        p,
        "--tolerance",
        "1e-4",
    ]);
    assert_eq!(answer(&v, "window.right")["verdict"], "wrong");
}

#[test]
fn a_directory_gives_one_row_per_student_and_a_csv() {
    let csv = std::env::temp_dir().join(format!("grafika-check-{}.csv", std::process::id()));
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle",
            "--csv",
            csv.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    for s in ["Budi", "Siti", "Tono"] {
        assert!(text.contains(s), "{text}");
    }
    let c = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = c.lines().collect();
    assert_eq!(lines.len(), 4, "{c}");
    assert!(lines[0].starts_with("student,file,score,total"));
    // Budi took u = n × Vup (see his file); Siti gave the half extents.
    assert!(
        lines[1].starts_with("Budi,") && lines[1].ends_with(",cross_order,"),
        "{c}"
    );
    assert!(lines[2].contains("height_is_half_extent"), "{c}");
}

#[test]
fn check_needs_exactly_one_source_of_answers() {
    let e = json_err(&["check", "problems/text-triangle.toml"]);
    assert_eq!(e["field"], "answers");
    let e = json_err(&["check", "problems/view-surds.toml", "--answers-from-text"]);
    assert_eq!(e["field"], "answers-from-text");
}

#[test]
fn per_problem_check_settings_apply_and_flags_override_them() {
    // A problem that asks only for the window top, with a 1% tolerance.
    let dir = std::env::temp_dir().join(format!("grafika-check-{}-settings", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prob = dir.join("p.toml");
    std::fs::write(
        &prob,
        "title = \"window\"\nask = [\"window\"]\n[perspective]\nnear = 1\nfovy = 90\naspect = 1\n[check]\ntolerance = 0.01\nkeys = [\"window.top\"]\n",
    )
    .unwrap();
    // fovy 90°: top = 1·tan 45° = 1; 1.005 is 0.5% off.
    let ans = dir.join("a.toml");
    std::fs::write(&ans, "window.top = \"1.005\"\n").unwrap();
    let (p, a) = (prob.to_str().unwrap(), ans.to_str().unwrap());
    let v = json_ok(&["check", p, "--answers", a]);
    assert_eq!(v["score"]["total"], 1);
    assert_eq!(answer(&v, "window.top")["code"], "correct.tolerance");
    let v = json_ok(&["check", p, "--answers", a, "--tolerance", "0.001"]);
    assert_eq!(answer(&v, "window.top")["verdict"], "wrong");
}

#[test]
fn lighting_mistakes_are_diagnosed() {
    // The text's Phong point: N = (0,1,1)/√2, L = V = (0,0,1).
    // cos α = 1/√2; R = 2N(L·N) − L = (0,1,1) − (0,0,1) = (0,1,0); cos β = 0.
    // With R = 2N(L·N) + L = (0,1,2): cos β = R·V = 2.
    let file = answers_file(
        "reflect",
        "shade.R = [\"0\", \"1\", \"2\"]\nshade.cos_beta = \"2\"\nshade.cos_alpha = \"sqrt(2)/2\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/shade-phong.toml",
        "--answers",
        file.to_str().unwrap(),
    ]);
    assert_eq!(answer(&v, "shade.cos_alpha")["code"], "correct.exact");
    for k in ["shade.R", "shade.cos_beta"] {
        assert!(codes(answer(&v, k)).contains(&"reflect_plus_l".to_string()));
    }
    // A point where cos β < 0: N = (4,0,3)/5, L = V = (0,0,1): cos α = 3/5,
    // R = (24/25, 0, −7/25), cos β = −7/25, so the highlight max(cos β,0)⁴ = 0.
    // Without the max: 0.7·(7/25)⁴ = 0.7·2401/390625 = 0.004302592 per channel.
    let dir = std::env::temp_dir().join(format!("grafika-check-{}-nomax", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let prob = dir.join("p.toml");
    std::fs::write(
        &prob,
        "title = \"t\"\n[shade]\nlight = [0, 0, 1]\nnormal = [4, 0, 3]\nview = [0, 0, 1]\ncolor = [1, 0.5, 0]\n",
    )
    .unwrap();
    let ans = dir.join("a.toml");
    std::fs::write(
        &ans,
        "shade.specular = [\"0.0043\", \"0.0043\", \"0.0043\"]\nshade.cos_beta = \"-7/25\"\n",
    )
    .unwrap();
    let v = json_ok(&[
        "check",
        prob.to_str().unwrap(),
        "--answers",
        ans.to_str().unwrap(),
    ]);
    assert_eq!(answer(&v, "shade.cos_beta")["verdict"], "correct");
    let s = answer(&v, "shade.specular");
    assert_eq!(s["verdict"], "wrong");
    assert_eq!(codes(s), ["specular_no_max"]);
}

/// A class directory: the three students of problems/answers/triangle, one
/// malformed file, an empty one, a subdirectory and a text file.
fn class_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("grafika-class-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("late")).unwrap();
    for s in ["budi", "siti", "tono"] {
        let from = root().join(format!("problems/answers/triangle/{s}.toml"));
        std::fs::copy(from, dir.join(format!("{s}.toml"))).unwrap();
    }
    std::fs::write(dir.join("broken.toml"), "window.top = \"0.04\n").unwrap();
    std::fs::write(dir.join("empty.toml"), "").unwrap();
    std::fs::write(dir.join("late/dewi.toml"), "window.top = \"0.0414\"\n").unwrap();
    std::fs::write(dir.join("notes.txt"), "not answers").unwrap();
    dir
}

#[test]
fn check_answers_dir_with_a_broken_file_marks_everyone_else() {
    let dir = class_dir("broken");
    let csv = dir.join("class.csv");
    let out = grafika()
        .args(["check", "problems/text-triangle.toml", "--answers"])
        .arg(&dir)
        .arg("--csv")
        .arg(&csv)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "a broken file makes the status 2"
    );
    let text = String::from_utf8(out.stdout).unwrap();
    for s in ["Budi", "Siti", "Tono", "broken", "empty"] {
        assert!(text.contains(s), "{s} missing from\n{text}");
    }
    assert!(text.contains("error:"), "{text}");
    assert!(text.contains("subdirectory"), "{text}");
    assert!(text.contains("notes.txt"), "{text}");
    assert!(text.contains("holds no answers"), "{text}");
    // The CSV has a row for each of the five files, the broken one with its error.
    let c = std::fs::read_to_string(&csv).unwrap();
    assert!(
        c.lines().next().unwrap().ends_with(",mistakes,error"),
        "{c}"
    );
    assert_eq!(c.lines().count(), 6, "{c}");
    let broken = c.lines().find(|l| l.starts_with("broken,")).unwrap();
    assert!(broken.contains(",,,,,,,,,"), "{broken}");
    // And the JSON names it too.
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--json",
            "--answers",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let students = v["students"].as_array().unwrap();
    assert_eq!(students.len(), 5);
    assert!(students.iter().any(|s| s["error"]["message"].is_string()));
    // late/, notes.txt and the class.csv written above.
    assert_eq!(v["skipped"].as_array().unwrap().len(), 3);
}

#[test]
fn check_csv_to_stdout_prints_only_the_csv_and_refuses_json() {
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/",
            "--csv",
            "-",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("student,file,score"), "{text}");
    assert_eq!(text.lines().count(), 4, "{text}");
    let e = json_err(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        "problems/answers/triangle/",
        "--csv",
        "-",
    ]);
    assert_eq!(e["field"], "csv");
}

#[test]
fn check_csv_to_stdout_with_one_answer_file_refuses_json() {
    // docs/spec.md §5: `--csv -` writes only the CSV, so it cannot be
    // combined with `--json`; an earlier version printed the CSV and exited 0
    // when the answers were one file rather than a directory.
    let e = json_err(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        "problems/answers/triangle/siti.toml",
        "--csv",
        "-",
    ]);
    assert_eq!(e["field"], "csv");
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/siti.toml",
            "--csv",
            "-",
            "--json",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(!String::from_utf8(out.stdout)
        .unwrap()
        .contains("student,file"));
}

#[test]
fn check_csv_with_one_answer_file_writes_its_row() {
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/siti.toml",
            "--csv",
            "-",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    assert!(lines[1].starts_with("Siti,"), "{text}");
}

#[test]
fn check_a_100000_digit_number_is_unparseable_not_slow() {
    let digits = format!("window.top = \"0.{}\"\n", "4".repeat(100_000));
    let f = answers_file("long", &digits);
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    assert_eq!(answer(&v, "window.top")["verdict"], "unparseable");
}

#[test]
fn a_one_figure_answer_is_not_explained_by_a_mistake() {
    // window-60: near = 1, fovy = 60°, so top = tan 30° ≈ 0.5774; with the
    // degrees given to tan as radians, top = tan(30 rad) ≈ −6.4053.
    let mark = |top: &str| {
        let f = answers_file(
            &format!("one-figure{}", top.len()),
            &format!("window.top = \"{top}\"\n"),
        );
        let v = json_ok(&[
            "check",
            "problems/window-60.toml",
            "--answers",
            f.to_str().unwrap(),
        ]);
        answer(&v, "window.top").clone()
    };
    let four = mark("-6.405");
    assert_eq!(four["verdict"], "wrong", "{four}");
    assert_eq!(codes(&four), ["degrees_as_radians"], "{four}");
    // "-6" has one figure: as close to a dozen other wrong values.
    let one = mark("-6");
    assert_eq!(one["verdict"], "wrong", "{one}");
    assert!(codes(&one).is_empty(), "{one}");
}

#[test]
fn the_spec_lists_every_mistake_code_in_the_catalogs_order() {
    // docs/spec.md §5 names the codes a diagnosis can give: every one the
    // catalog has, spelled as the JSON and CSV write it.
    let spec = std::fs::read_to_string(root().join("docs/spec.md")).unwrap();
    let (_, rest) = spec.split_once("The codes: ").unwrap();
    let (list, _) = rest.split_once(" (the value the source printed").unwrap();
    let listed: Vec<&str> = list.split('`').skip(1).step_by(2).collect();
    let codes: Vec<&str> = Code::all().into_iter().map(Code::as_str).collect();
    assert_eq!(listed, codes);
}

#[test]
fn the_specs_check_csv_header_has_the_follow_through_column() {
    // docs/spec.md §5 lists the CSV's columns; they must be the ones printed.
    let spec = std::fs::read_to_string(root().join("docs/spec.md")).unwrap();
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/siti.toml",
            "--csv",
            "-",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let header = text.lines().next().unwrap();
    assert!(header.contains(",follow_through,"), "{header}");
    assert!(spec.contains(&format!("`{header}`")), "{header}");
}

/// The triangle example by hand (problems/text-triangle.toml): Pe − Pr =
/// (1, 0, 1), |Pe − Pr| = √2, n = (1/√2, 0, 1/√2); Vup × n = (1/√2, 0,
/// −1/√2) of length 1, so u is that; v = n × u = (0, 1, 0). A − Pe =
/// (−3, −1, −3): A′ = (0, −1, −6/√2); B − Pe = (−2, −1, −3): B′ = (1/√2,
/// −1, −5/√2); C − Pe = (−3, −1, −2): C′ = (−1/√2, −1, −5/√2). d = −0.1:
/// A″ = (0, −√2/60, −1/10), B″ = (1/50, −√2/50, −1/10), C″ = (−1/50,
/// −√2/50, −1/10). top = 0.1·tan 22.5° = (√2 − 1)/10 ≈ 0.04142, right =
/// 2·top ≈ 0.08284, height = 2·top, width = 2·right ≈ 0.1657. Pixels
/// (200 × 100): A = (100, (100 − 25√2)/3 ≈ 21.55), B = (110 + 10√2 ≈
/// 124.14, 30 − 10√2 ≈ 15.86), C = (90 − 10√2 ≈ 75.86, 15.86); measured
/// from the top edge their py would be 78.45, 84.14, 84.14.
const TRIANGLE_READING: &str = r#"
view.n = "(1/sqrt(2), 0, 1/sqrt(2))"
view.u = "1/sqrt(2), 0, -1/sqrt(2)"
view.v = "[0, 1, 0]"
view.matrix = "1/sqrt(2), 0, −1/√2, 0; 0, 1, 0, -1; (1/2)sqrt(2), 0, √2/2, -3*sqrt(2); 0, 0, 0, 1"
view.points.A = "0, −1, −6/√2"
view.points.B = "(√2/2; −1; −5√2/2)"
view.points.C = "(-0,7071; -1; -3,536)"
project.points.A = "0, -sqrt(2)/60"
project.points.B = "(1/50, -sqrt(2)/50, -1/10)"
project.points.C = "-0,02; -0,02828"
window.top = "0,04142"
window.bottom = "(1-√2)/10"
window.left = "-2(sqrt(2)-1)/10"
window.right = "0.08284"
window.height = "(√2−1)/5"
window.width = "2(√2 − 1)/5"
viewport.pixels.A = "(100; 21,55)"
viewport.pixels.B = "110 + 10√2, 30 - 10sqrt(2)"
viewport.pixels.C = ["90 - 10*sqrt(2)", "15.86"]
"#;

#[test]
fn every_written_form_of_the_texts_answers_is_read() {
    // TOML arrays, (a, b, c), [a, b, c], bare a, b, c; a last part ending
    // in sqrt(2) or √2; unicode √ and −; implicit products; decimal commas
    // with ;; the view matrix by rows: all of the triangle example right
    let f = answers_file("reading", TRIANGLE_READING);
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    for a in v["answers"].as_array().unwrap() {
        assert_eq!(a["verdict"], "correct", "{a}");
    }
    // the view matrix is working (the scheme asks the other 18): marked
    // and right, never counted
    assert_eq!(v["score"]["points"], 18.0);
    assert_eq!(v["score"]["total"], 18);
    assert_eq!(v["working"]["correct"], 1);
    // the clipping example: outcodes with a space, the status in Indonesian
    let f = answers_file(
        "reading-clip",
        "clip.code0 = \"000 010\"\nclip.code1 = \"1001\"\nclip.status = \"DI-CLIP\"\n\
         clip.segment = \"(3, 8/3, 11/6); (1, 4, 3/2)\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/text-clip.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    for a in v["answers"].as_array().unwrap() {
        assert_eq!(a["verdict"], "correct", "{a}");
    }
    for (status, ok) in [
        ("ditolak", false),
        ("Clipped (di-clip)", true),
        ("diterima", false),
    ] {
        let f = answers_file("status", &format!("clip.status = \"{status}\"\n"));
        let v = json_ok(&[
            "check",
            "problems/text-clip.toml",
            "--answers",
            f.to_str().unwrap(),
        ]);
        assert_eq!(
            answer(&v, "clip.status")["verdict"] == "correct",
            ok,
            "{status}"
        );
    }
}

#[test]
fn an_unreadable_answer_names_the_part_and_the_column_in_both_languages() {
    // `1/sqrt(2, 0, 1`: the x part lacks its `)`, at column 10 of the answer
    let f = answers_file("unreadable", "view.n = \"(1/sqrt(2, 0, 1)\"\n");
    let args = [
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ];
    let v = json_ok(&args);
    let n = answer(&v, "view.n");
    assert_eq!(n["verdict"], "unparseable");
    assert!(n["note"].as_str().unwrap().starts_with("x: "), "{n}");
    assert!(n["note"].as_str().unwrap().contains("column 10"), "{n}");
    let mut id = vec!["--lang", "id"];
    id.extend(args);
    let v = json_ok(&id);
    assert!(answer(&v, "view.n")["note"]
        .as_str()
        .unwrap()
        .contains("kolom 10"));
}

#[test]
fn a_mistakes_value_is_wrong_and_named_never_rounded() {
    // n = (1, 0, 1) is Pe − Pr not divided by √2: 1 keeps no figure of
    // 0.7071, and it is the catalog's value
    let f = answers_file("unnormalized", "view.n = \"1, 0, 1\"\n");
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    let n = answer(&v, "view.n");
    assert_eq!(n["verdict"], "wrong", "{n}");
    assert_eq!(codes(n), ["n_not_normalized"]);
    // the text's Phong point: N = (0, 1, 1) not divided by √2 gives
    // cos α = L·N = (0, 0, 1)·(0, 1, 1) = 1 instead of 1/√2
    let f = answers_file("cos-alpha", "shade.cos_alpha = \"1\"\n");
    let v = json_ok(&[
        "check",
        "problems/shade-phong.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    let c = answer(&v, "shade.cos_alpha");
    assert_eq!(c["verdict"], "wrong", "{c}");
    assert_eq!(codes(c), ["normal_not_normalized"]);
}

/// The triangle example right up to the window, then `pixels`.
fn triangle_with_pixels(name: &str, pixels: &str) -> PathBuf {
    let head: String = TRIANGLE_READING
        .lines()
        .filter(|l| !l.starts_with("viewport"))
        .map(|l| format!("{l}\n"))
        .collect();
    answers_file(name, &(head + pixels))
}

#[test]
fn pixels_from_the_top_name_that_mistake_and_nothing_else() {
    // the student's n, u and projected points are right: n_reversed,
    // cross_order and d_sign would have changed them
    let f = triangle_with_pixels(
        "from-top",
        "viewport.pixels.A = \"100, 78.45\"\nviewport.pixels.B = \"124.14, 84.14\"\n\
         viewport.pixels.C = \"75.86, 84.14\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    for k in [
        "viewport.pixels.A",
        "viewport.pixels.B",
        "viewport.pixels.C",
    ] {
        assert_eq!(codes(answer(&v, k)), ["pixel_y_from_top"], "{k}");
    }
    let d = v["diagnosis"].as_array().unwrap();
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "pixel_y_from_top");
    assert!(d[0]["also"].as_array().unwrap().is_empty(), "{d:?}");
}

#[test]
fn the_sign_of_d_alone_is_not_blamed_on_the_cross_product() {
    // d = +0.1: A″ = (0, √2/60, 1/10), B″ = (−1/50, √2/50, 1/10), C″ =
    // (1/50, √2/50, 1/10); u is right, so u = n × Vup cannot be the mistake
    let f = answers_file(
        "d-sign",
        "view.u = \"1/sqrt(2), 0, -1/sqrt(2)\"\nview.v = \"0, 1, 0\"\n\
         project.points.A = \"0, sqrt(2)/60, 0.1\"\nproject.points.B = \"-1/50, sqrt(2)/50, 0.1\"\n\
         project.points.C = \"1/50, sqrt(2)/50, 0.1\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    let d = v["diagnosis"].as_array().unwrap();
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "d_sign");
    assert_eq!(d[0]["keys"].as_array().unwrap().len(), 3);
}

#[test]
fn a_wrong_answer_no_mistake_explains_is_said_plainly() {
    // top = 0.05 is 21% off 0.0414 and no mistake of the catalog gives it
    let f = answers_file("plain", "window.top = \"0.05\"\n");
    let out = grafika()
        .args(["check", "problems/text-triangle.toml", "--answers"])
        .arg(&f)
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("No known mistake explains window.top"),
        "{text}"
    );
    assert!(!text.contains("Diagnosis:"), "{text}");
}

#[test]
fn the_new_mistakes_on_the_texts_examples() {
    let mark = |problem: &str, name: &str, text: &str| {
        let f = answers_file(name, text);
        json_ok(&["check", problem, "--answers", f.to_str().unwrap()])
    };
    // Peye not subtracted: B′ = (u·B, v·B, n·B) = (1/√2, 0, 1/√2),
    // C′ = (u·C, v·C, n·C) = (−1/√2, 0, 1/√2)
    let v = mark(
        "problems/text-triangle.toml",
        "no-translation",
        "view.points.B = \"1/sqrt(2), 0, 1/sqrt(2)\"\nview.points.C = \"-0.7071, 0, 0.7071\"\n",
    );
    for k in ["view.points.B", "view.points.C"] {
        assert_eq!(codes(answer(&v, k)), ["eye_no_translation"], "{k}");
    }
    // right = top/aspect = (√2 − 1)/20 ≈ 0.02071, width = (√2 − 1)/10
    let v = mark(
        "problems/text-triangle.toml",
        "aspect",
        "window.right = \"0.0207\"\nwindow.width = \"(sqrt(2)-1)/10\"\n",
    );
    for k in ["window.right", "window.width"] {
        assert!(
            codes(answer(&v, k)).contains(&"aspect_inverted".to_string()),
            "{k}"
        );
    }
    // L = (1, 0, 1) not divided by √2, N = V = (0, 0, 1): cos α = 1,
    // R = 2N·1 − L = (−1, 0, 1), cos β = 1, specular = 0.7·1⁴ = 0.7
    // (right: cos α = 1/√2, R = (−1/√2, 0, 1/√2), specular 0.7/4 = 0.175)
    let v = mark(
        "problems/shade-specular.toml",
        "light",
        "shade.cos_alpha = \"1\"\nshade.R = \"-1, 0, 1\"\nshade.cos_beta = \"1\"\n\
         shade.specular = \"0.7, 0.7, 0.7\"\n",
    );
    for k in [
        "shade.cos_alpha",
        "shade.R",
        "shade.cos_beta",
        "shade.specular",
    ] {
        assert_eq!(codes(answer(&v, k)), ["light_not_normalized"], "{k}");
    }
    // the text's misprints copied: the erratum is named, with its reason
    let v = mark(
        "problems/text-clip.toml",
        "misprint",
        "clip.intersections.right.point = \"3, 20/6, 11/6\"\n\
         clip.intersections.top.point = \"(2, 4, 3/2)\"\n",
    );
    let r = answer(&v, "clip.intersections.right.point");
    assert_eq!(codes(r), ["copied_misprint"]);
    assert!(r["why"].as_str().unwrap().contains("not 20/6"), "{r}");
    assert_eq!(
        codes(answer(&v, "clip.intersections.top.point")),
        ["copied_misprint"]
    );
    // h = 0.041 as the height: the text's misprint, and the half extent
    let v = mark(
        "problems/text-triangle.toml",
        "h",
        "window.height = \"0.041\"\n",
    );
    let h = answer(&v, "window.height");
    let c = codes(h);
    assert!(
        c.contains(&"copied_misprint".into()) && c.contains(&"height_is_half_extent".into()),
        "{h}"
    );
    assert!(h["why"].as_str().unwrap().contains("half-height"), "{h}");
}

#[test]
fn a_wrong_basis_is_carried_through_every_later_key_and_a_slip_after_it_is_not() {
    // u = n × Vup = (−1/√2, 0, 1/√2): v = n × u = (0, −1, 0); every x′, y′
    // flips: A′ = (0, 1, −6/√2), B′ = (−1/√2, 1, −5/√2), C′ = (1/√2, 1,
    // −5/√2); so do xp, yp: A″ = (0, √2/60), B″ = (−1/50, √2/50), C″ =
    // (1/50, √2/50); and the pixels mirror: A = (100, 78.45), B = (75.86,
    // 84.14), C = (124.14, 84.14). C is given as (124.14, 15.86): wrong,
    // even given the student's own C″.
    let f = answers_file(
        "carried",
        "view.n = \"√2/2, 0, √2/2\"\nview.u = \"-√2/2, 0, √2/2\"\nview.v = \"0, -1, 0\"\n\
         view.points.A = \"0, 1, -3√2\"\nview.points.B = \"-1/√2, 1, -5/√2\"\n\
         view.points.C = \"1/√2, 1, -5/√2\"\nproject.points.A = \"0, √2/60\"\n\
         project.points.B = \"-0.02, 0.02828\"\nproject.points.C = \"0.02, 0.02828\"\n\
         window.top = \"0.04142\"\nwindow.bottom = \"-0.04142\"\nwindow.left = \"-0.08284\"\n\
         window.right = \"0.08284\"\nwindow.height = \"0.08284\"\nwindow.width = \"0.1657\"\n\
         viewport.pixels.A = \"100, 78.45\"\nviewport.pixels.B = \"75.86, 84.14\"\n\
         viewport.pixels.C = \"124.14, 15.86\"\n",
    );
    let args = [
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ];
    let mut ft = args.to_vec();
    ft.push("--follow-through");
    let v = json_ok(&ft);
    for k in [
        "view.v",
        "view.points.A",
        "view.points.B",
        "view.points.C",
        "project.points.A",
        "project.points.B",
        "project.points.C",
        "viewport.pixels.A",
        "viewport.pixels.B",
    ] {
        assert_eq!(answer(&v, k)["code"], "correct.follow_through", "{k}");
    }
    assert_eq!(answer(&v, "view.u")["verdict"], "wrong");
    assert_eq!(codes(answer(&v, "view.u")), ["cross_order"]);
    assert_eq!(answer(&v, "viewport.pixels.C")["verdict"], "wrong");
    assert_eq!(v["counts"]["follow_through"], 9);
    // without the flag, cross_order explains them all (but the slip)
    let v = json_ok(&args);
    let d = v["diagnosis"].as_array().unwrap();
    assert_eq!(d[0]["code"], "cross_order");
    assert_eq!(d[0]["keys"].as_array().unwrap().len(), 10);
}

#[test]
fn the_new_mistakes_reach_the_quiz_feedback() {
    // generated problems have no errata, so copied_misprint never applies
    // there; each of the others names itself in a generated Moodle quiz
    let dir = std::env::temp_dir().join(format!("grafika-check-{}-quiz", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = grafika()
        .args([
            "generate",
            "--topic",
            "pipeline,shade",
            "--count",
            "6",
            "--variants",
            "3",
            "--seed",
            "7",
            "--difficulty",
            "hard",
            "--format",
            "moodle",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_success(&out);
    let xml = std::fs::read_to_string(dir.join("quiz.xml")).unwrap();
    for words in [
        // the quiz writes a minus Moodle reads back
        "measured from the top edge (H - py)",
        "Peye not subtracted",
        "top / aspect instead of aspect·top",
        "L not divided by |L|",
        "N not divided by |N|",
    ] {
        assert!(xml.contains(words), "no feedback with {words}");
    }
}

#[test]
fn mistakes_the_independent_check_found_unnamed() {
    let mark = |problem: &str, name: &str, text: &str| {
        let f = answers_file(name, text);
        json_ok(&["check", problem, "--answers", f.to_str().unwrap()])
    };
    // n = Pe − Pr = (1, 0, 1) not normalized: v = n × u = (0, √2, 0); the
    // view matrix's rows are u, v, n with last column −(u·Pe, v·Pe, n·Pe) =
    // −(3/√2 − 3/√2, √2, 3 + 3) = (0, −√2, −6): the translation scales too
    let v = mark(
        "problems/text-triangle.toml",
        "matrix-n",
        "view.matrix = \"√2/2, 0, −√2/2, 0; 0, √2, 0, −√2; 1, 0, 1, −6; 0, 0, 0, 1\"\n",
    );
    assert_eq!(codes(answer(&v, "view.matrix")), ["n_not_normalized"]);
    // Peye not subtracted: A = (0, 0, 0) gives A′ = (0, 0, 0), though its
    // projection is then undefined
    let v = mark(
        "problems/text-triangle.toml",
        "a-origin",
        "view.points.A = \"0, 0, 0\"\n",
    );
    assert_eq!(codes(answer(&v, "view.points.A")), ["eye_no_translation"]);
    // the left intersection (0, 14/3, 4/3) is above y = 4: 001000, and
    // written in the wrong order 000100
    let v = mark(
        "problems/text-clip.toml",
        "code-reversed",
        "clip.intersections.left.code = \"000100\"\n",
    );
    assert_eq!(
        codes(answer(&v, "clip.intersections.left.code")),
        ["outcode_reversed"]
    );
}

#[test]
fn one_misprint_copied_is_named_though_the_others_are_not() {
    // Everything right but the width, copied from the text's printed
    // W = 0.082 (its erratum: the half-width, right = aspect·top ≈ 0.0828;
    // the width is 2·right ≈ 0.1657). The text's other misprints (h =
    // 0.041 as the height, 0.0067 in B″ and C″, right = 0.082) were not
    // copied: the height, B″, C″ and right are right, so the misprint the
    // student copied must be named on its own.
    let f = answers_file(
        "one-misprint",
        "view.n = \"√2/2, 0, √2/2\"\nview.u = \"√2/2, 0, −√2/2\"\nview.v = \"0, 1, 0\"\n\
         view.points.A = \"0, −1, −3√2\"\nview.points.B = \"√2/2, −1, −5√2/2\"\n\
         view.points.C = \"−√2/2, −1, −5√2/2\"\nproject.points.A = \"0, −√2/60\"\n\
         project.points.B = \"1/50, −√2/50\"\nproject.points.C = \"−1/50, −√2/50\"\n\
         window.top = \"(√2−1)/10\"\nwindow.bottom = \"(1−√2)/10\"\n\
         window.left = \"(1−√2)/5\"\nwindow.right = \"(√2−1)/5\"\n\
         window.height = \"(√2−1)/5\"\nwindow.width = \"0.082\"\n\
         viewport.pixels.A = \"100, (100−25√2)/3\"\nviewport.pixels.B = \"110+10√2, 30−10√2\"\n\
         viewport.pixels.C = \"90−10√2, 30−10√2\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    assert_eq!(v["score"]["points"], 17.0, "{v}");
    let w = answer(&v, "window.width");
    assert_eq!(codes(w), ["copied_misprint"], "{w}");
    assert!(w["why"].as_str().unwrap().contains("half-width"), "{w}");
    let d = v["diagnosis"].as_array().unwrap();
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["keys"], serde_json::json!(["window.width"]));
}

/// `--answers-from-text` takes `--csv` as a student's sheet does (it wrote
/// nothing and exited 0), refuses `--report` (a class report needs a
/// class), and does not call an erratum's printed answer unexplained.
#[test]
fn the_texts_answers_go_to_a_csv_and_their_errata_explain_them() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("text.csv");
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers-from-text",
        ])
        .args(["--lang", "en", "--csv", csv.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let table = String::from_utf8_lossy(&out.stdout);
    // B'' and C'' are misprints, window.right a rounding: the errata above
    // the diagnosis say why; no line calls them unexplained.
    assert!(table.contains("a misprint in the text"), "{table}");
    assert!(!table.contains("No known mistake explains"), "{table}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(rows.len(), 2, "{text}");
    // 5 of the 10 printed answers are right: A', B', C', A'' and top.
    assert!(rows[1].contains(",5,10,5,0,5,0,0,0,"), "{text}");
    let report = dir.path().join("class.md");
    let e = json_err(&[
        "check",
        "problems/text-triangle.toml",
        "--answers-from-text",
        "--report",
        report.to_str().unwrap(),
    ]);
    assert_eq!(e["field"], "report");
    assert!(!report.exists());
}

#[test]
fn a_segments_own_outcodes_carry_to_its_status_and_no_other_segment() {
    // clip-cases.toml's 6th segment (clip.5): P0 = (1, 1, 1) is inside,
    // P1 = (1, 1, 5) is behind z = 3, code1 = 100000, so it is clipped. A
    // student who reads P1 as inside (code1 = 000000) gets AND = 0 and OR = 0:
    // accepted, right given their own codes. The 5th segment (clip.4) is
    // given nothing of the kind, so its status stays simply wrong.
    let f = answers_file(
        "segment",
        "clip.5.code0 = \"000000\"\nclip.5.code1 = \"000000\"\nclip.5.status = \"accepted\"\n\
         clip.4.status = \"accepted\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/clip-cases.toml",
        "--answers",
        f.to_str().unwrap(),
        "--follow-through",
    ]);
    assert_eq!(answer(&v, "clip.5.code0")["verdict"], "correct");
    assert_eq!(answer(&v, "clip.5.code1")["verdict"], "wrong");
    assert_eq!(
        answer(&v, "clip.5.status")["code"],
        "correct.follow_through"
    );
    assert_eq!(answer(&v, "clip.4.status")["verdict"], "wrong");
}

#[test]
fn several_segments_are_asked_what_one_segment_is() {
    // A lone segment is not asked the planes it tried (text-clip.toml);
    // neither is each of clip-cases.toml's seven: a student is marked on
    // code0, code1, segment and status of each. Segment 1 (clip.0) runs
    // from (1, 1, 1) to (2, 3, 2), inside the box: both codes 000000.
    let file = answers_file(
        "segments",
        "\"clip.0.code0\" = \"000 000\"\n\"clip[0].code1\" = \"000000\"\n",
    );
    let v = json_ok(&[
        "check",
        "problems/clip-cases.toml",
        "--answers",
        file.to_str().unwrap(),
    ]);
    let keys: Vec<&str> = (v["answers"].as_array().unwrap().iter())
        .map(|a| a["key"].as_str().unwrap())
        .collect();
    assert!(
        keys.iter().all(|k| !k.contains("intersections")),
        "{keys:?}"
    );
    for i in 0..7 {
        for f in ["code0", "code1", "segment", "status"] {
            assert!(
                keys.contains(&format!("clip.{i}.{f}").as_str()),
                "clip.{i}.{f}: {keys:?}"
            );
        }
    }
    assert_eq!(answer(&v, "clip.0.code0")["code"], "correct.exact");
    assert_eq!(answer(&v, "clip.0.code1")["code"], "correct.exact");
}

/// Marks `answers` (an answer file's text) against `problem` in JSON.
fn marked(problem: &str, name: &str, answers: &str, more: &[&str]) -> Value {
    let f = answers_file(name, answers);
    let mut args = vec!["check", problem, "--answers", f.to_str().unwrap()];
    args.extend(more);
    json_ok(&args)
}

/// The answers of issue 35, as students and the text write them, each
/// judged by what it is (values by hand in the comments).
#[test]
fn answers_in_the_forms_students_and_the_text_write() {
    // the text's clipping example: right (x = 3) at t = 1/6, (3, 8/3,
    // 11/6), kept; left (x = 0) at (0, 14/3, 4/3), y > 4, not kept; top
    // (y = 4) at (1, 4, 3/2), kept
    let v = marked(
        "problems/text-clip.toml",
        "clip-words",
        "\"clip.intersections.right.point\" = \"A(3; 8/3; 11/6)\"\n\
         \"clip.intersections.right.kept\" = \"ya\"\n\
         \"clip.intersections.left.kept\" = \"tidak\"\n\
         \"clip.intersections.top.kept\" = \"yes\"\n\
         \"clip.intersections.top.point\" = \"B(1; 4; 3/2)\"\n\
         \"clip.segment\" = \"A(3; 8/3; 11/6), B(1; 4; 3/2)\"\n",
        &[],
    );
    for k in [
        "right.point",
        "right.kept",
        "left.kept",
        "top.kept",
        "top.point",
    ] {
        let a = answer(&v, &format!("clip.intersections.{k}"));
        assert_eq!(a["code"], "correct.exact", "{a}");
    }
    assert_eq!(answer(&v, "clip.segment")["code"], "correct.exact");
    let v = marked(
        "problems/text-clip.toml",
        "clip-bools",
        "\"clip.intersections.right.kept\" = true\n\"clip.intersections.left.kept\" = \"no\"\n\
         \"clip.intersections.top.kept\" = \"false\"\n",
        &[],
    );
    assert_eq!(
        answer(&v, "clip.intersections.right.kept")["code"],
        "correct.exact"
    );
    assert_eq!(
        answer(&v, "clip.intersections.left.kept")["code"],
        "correct.exact"
    );
    let top = answer(&v, "clip.intersections.top.kept");
    assert_eq!(
        (&top["verdict"], &top["note"]),
        (&"wrong".into(), &"expected yes".into())
    );

    // eye (3, 4, 12) at the origin: u = (4√17/17, 0, −√17/17), v =
    // (−4, 51, −16)/(13√17), n = (3, 4, 12)/13: exact in every form
    let v = marked(
        "problems/view-surds.toml",
        "surds",
        "\"view.u\" = \"(4/sqrt(17), 0, -17/(17*sqrt(17)))\"\n\
         \"view.v\" = \"(−4/(13√17), 3√17/13, −16/(13√17))\"\n\
         \"view.n\" = \"(3, 4, 12)/13\"\n",
        &[],
    );
    for k in ["view.u", "view.v", "view.n"] {
        assert_eq!(answer(&v, k)["code"], "correct.exact", "{}", answer(&v, k));
    }

    // the text's example 6.1: V = [0 0 −1 4; −3/5 4/5 0 −4/5; 4/5 3/5 0
    // −28/5; 0 0 0 1], as rows of numbers by spaces with decimal commas
    let v = marked(
        "problems/text-camera.toml",
        "rows",
        "\"view.matrix\" = \"0 0 -1 4; -0,6 0,8 0 -0,8; 0,8 0,6 0 -5,6; 0 0 0 1\"\n\
         \"view.n\" = \"0,8, 0,6, 0\"\n",
        &[],
    );
    assert_eq!(answer(&v, "view.matrix")["code"], "correct.exact");
    let n = answer(&v, "view.n");
    assert_eq!(n["verdict"], "unparseable", "{n}");
    let note = n["note"].as_str().unwrap();
    assert!(
        note.contains("0,7071; 0; 0,7071") && note.contains("0.7071, 0, 0.7071"),
        "{note}"
    );
    let f = answers_file("ambiguous-id", "\"view.n\" = \"0,8, 0,6, 0\"\n");
    let id = json_ok(&[
        "--lang",
        "id",
        "check",
        "problems/text-camera.toml",
        "--answers",
        f.to_str().unwrap(),
    ]);
    let note = answer(&id, "view.n")["note"].as_str().unwrap().to_string();
    assert!(
        note.contains("koma") && note.contains("0,7071; 0; 0,7071"),
        "{note}"
    );

    // the triangle's n = (1, 0, 1)/√2 and u = (1, 0, −1)/√2, as grafika prints them
    let v = marked(
        "problems/text-triangle.toml",
        "over-root",
        "\"view.n\" = \"(1, 0, 1)/√2\"\n\"view.u\" = \"√2/2·(1, 0, −1)\"\n",
        &[],
    );
    assert_eq!(answer(&v, "view.n")["code"], "correct.exact");
    assert_eq!(answer(&v, "view.u")["code"], "correct.exact");

    // cos α = 26/√677 = 0.99926 for L = (1, 0, 26), N = (0, 0, 1): 1.0 is
    // 0.074 % off, within the tolerance: correct, not too coarse
    let dir = scratch("issue-35-problems");
    let cos = dir.join("cos.toml");
    std::fs::write(
        &cos,
        "title = 'c'\n[shade]\nmodel = 'diffuse'\nlight = [1, 0, 26]\nnormal = [0, 0, 1]\n\
         view = [0, 0, 1]\ncolor = [1, 1, 1]\n",
    )
    .unwrap();
    let v = marked(
        cos.to_str().unwrap(),
        "cos",
        "\"shade.cos_alpha\" = \"1.0\"\n",
        &[],
    );
    assert_eq!(answer(&v, "shade.cos_alpha")["code"], "correct.tolerance");
    // A = (3, −1, −√10) onto z = −1: (3/√10, −1/√10) = (0.9487, −0.3162);
    // (0.9, −0.3) keeps one figure of each: too coarse
    let proj = dir.join("proj.toml");
    std::fs::write(
        &proj,
        "title = 'p'\nask = ['project']\n[perspective]\nd = -1\nnear = 1\n\
         [camera]\neye = [0, 0, 0]\nlook = [0, 0, -1]\nup = [0, 1, 0]\n\
         [points]\nA = ['3', '-1', '-sqrt(10)']\n",
    )
    .unwrap();
    let v = marked(
        proj.to_str().unwrap(),
        "proj",
        "\"project.points.A\" = \"(0.9, −0.3)\"\n",
        &[],
    );
    assert_eq!(answer(&v, "project.points.A")["verdict"], "too_coarse");
}

/// The four mistakes issue 35 adds, each made on a shipped problem and
/// named (values by hand).
#[test]
fn the_new_mistakes_are_named() {
    // example 6.1 with u and v swapped: u = (−3/5, 4/5, 0), v = (0, 0, −1)
    let v = marked(
        "problems/text-camera.toml",
        "uv",
        "\"view.n\" = \"4/5, 3/5, 0\"\n\"view.u\" = \"-3/5, 4/5, 0\"\n\"view.v\" = \"0, 0, -1\"\n",
        &[],
    );
    assert!(codes(answer(&v, "view.u")).contains(&"uv_swapped".to_string()));
    // Mcam (columns u, v, n, Pe = (4, 4, 4)) as the view matrix
    let v = marked(
        "problems/text-camera.toml",
        "mcam",
        "\"view.matrix\" = \"0, -0.6, 0.8, 4; 0, 0.8, 0.6, 4; -1, 0, 0, 4; 0, 0, 0, 1\"\n",
        &[],
    );
    assert_eq!(codes(answer(&v, "view.matrix")), ["mcam_as_view"]);
    // t from P1 in the clipping example: 5/6 for x = 3, 1/3 for x = 0
    let v = marked(
        "problems/text-clip.toml",
        "t",
        "\"clip.intersections.right.t\" = \"5/6\"\n\"clip.intersections.left.t\" = \"1/3\"\n\
         \"clip.intersections.right.point\" = \"(3, 8/3, 11/6)\"\n",
        &[],
    );
    assert_eq!(
        codes(answer(&v, "clip.intersections.right.t")),
        ["t_from_p1"]
    );
    // the penumbra spot with cos taken in radians: spot 1, colour 0.48
    let v = marked(
        "problems/shade-spot-penumbra.toml",
        "rad",
        "\"shade.color\" = \"0.48, 0.48, 0.48\"\n",
        &[],
    );
    assert!(codes(answer(&v, "shade.color")).contains(&"cos_in_radians".to_string()));
}
