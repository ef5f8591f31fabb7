//! The lecturer's view of a class (`grafika check … --answers DIR --report
//! FILE`): a synthetic class of 60 with mistakes at known rates, whose
//! counts, facility, discrimination, point-biserial, mistakes, groups and
//! histogram are computed here from the design, not from the program; a
//! broken file in the class; an exam of 3 problems in 4 variants; CSV that
//! a spreadsheet opens safely.

mod common;

use common::class::{
    answer_file, Student, CROSS_ORDER_KEYS, FOVY_KEYS, HALF_EXTENT_KEYS, KEYS,
    N_NOT_NORMALIZED_KEYS,
};
use common::{assert_success, grafika, root};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("grafika-class-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Student i of the class of 60: each mistake at a known rate, in residues
/// chosen so that no two mistakes touch the same key of one student (but
/// that four leave the pixels out: 14 and 44 of tan(fovy), 29 and 59 of n
/// not normalised). Each mistake is carried through the keys that follow
/// from it ([`CROSS_ORDER_KEYS`], …), except the width, which everyone
/// gets wrong the same way.
fn student(i: usize) -> Student {
    Student {
        name: format!("S{i:02}"),
        form: i % 4,
        cross_order: i.is_multiple_of(10),           // 6 students
        fovy_not_halved: i % 10 == 2 || i % 10 == 4, // 12
        height_is_half_extent: i % 4 == 1,           // 15
        n_not_normalized: i % 6 == 5,                // 10
        n_too_coarse: i % 12 == 6,                   // 5
        v_in_words: i == 13,                         // 1
        no_pixels: i % 15 == 14,                     // 4
        // everyone the same wrong width, written four ways (equal within 0.1 %)
        width: Some(["0.15", "0,15", "3/20", "0.15002"][i % 4].to_string()),
        pixel_slip: i % 12 == 3, // 5: 3, 15, 27, 39, 51, who make no mistake
    }
}

/// The mark the design gives student s on a key: 1 right, ½ too coarse, 0.
fn mark(s: &Student, key: &str) -> f64 {
    let made = |on: bool, keys: &[&str]| on && keys.contains(&key);
    if key == "window.width"
        || (s.no_pixels && key.starts_with("viewport."))
        || made(s.cross_order, &CROSS_ORDER_KEYS)
        || made(s.fovy_not_halved, &FOVY_KEYS)
        || made(s.height_is_half_extent, &HALF_EXTENT_KEYS)
        || made(s.n_not_normalized, &N_NOT_NORMALIZED_KEYS)
        || made(s.v_in_words, &["view.v"])
        || made(s.pixel_slip, &["viewport.pixels.B"])
    {
        0.0
    } else if s.n_too_coarse && key == "view.n" {
        0.5
    } else {
        1.0
    }
}

/// D by its definition: the g = round(0.27·N) highest and lowest totals,
/// students tied at an edge sharing the remaining places.
fn upper_minus_lower(x: &[f64], total: &[f64]) -> f64 {
    let g = (0.27 * x.len() as f64).round();
    let group = |highest: bool| -> f64 {
        let mut levels: Vec<f64> = total.to_vec();
        levels.sort_by(|a, b| {
            if highest {
                b.total_cmp(a)
            } else {
                a.total_cmp(b)
            }
        });
        levels.dedup();
        let (mut left, mut sum) = (g, 0.0);
        for level in levels {
            let at: Vec<usize> = (0..x.len()).filter(|&i| total[i] == level).collect();
            let share = (left / at.len() as f64).min(1.0);
            sum += share * at.iter().map(|&i| x[i]).sum::<f64>();
            left -= share * at.len() as f64;
            if left <= 0.0 {
                break;
            }
        }
        sum / g
    };
    group(true) - group(false)
}

/// Pearson's r, None when either side is constant.
fn pearson(x: &[f64], y: &[f64]) -> Option<f64> {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    let syy: f64 = y.iter().map(|b| (b - my).powi(2)).sum();
    (sxx > 1e-12 && syy > 1e-12).then(|| sxy / (sxx * syy).sqrt())
}

/// Writes the class of 60 and one broken file; returns the folder.
fn class_of_sixty(name: &str) -> PathBuf {
    let dir = scratch(name);
    for i in 0..60 {
        std::fs::write(dir.join(format!("s{i:02}.toml")), answer_file(&student(i))).unwrap();
    }
    // a file a student broke: not marked, reported, not counted
    std::fs::write(
        dir.join("zz-broken.toml"),
        "student = \"Zaki\"\nview.n = [\"1\", \"0\"\n",
    )
    .unwrap();
    dir
}

/// Runs check with a report; returns its exit status, stdout and the report.
fn report(dir: &Path, file: &str, lang: &str) -> (i32, String, String) {
    let out_file = dir.parent().unwrap().join(format!(
        "{}-{file}",
        dir.file_name().unwrap().to_string_lossy()
    ));
    let _ = std::fs::remove_file(&out_file);
    let out = grafika()
        .args([
            "--lang",
            lang,
            "check",
            "problems/text-triangle.toml",
            "--answers",
        ])
        .arg(dir)
        .arg("--report")
        .arg(&out_file)
        .output()
        .unwrap();
    let text = std::fs::read_to_string(&out_file).unwrap_or_default();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        text,
    )
}

fn key<'a>(j: &'a Value, k: &str) -> &'a Value {
    j["keys"]
        .as_array()
        .unwrap()
        .iter()
        .find(|x| x["key"] == k)
        .unwrap_or_else(|| panic!("no key {k}"))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 6e-5
}

#[test]
fn a_class_of_sixty_gives_the_facility_discrimination_and_correlation_of_its_design() {
    let dir = class_of_sixty("sixty");
    let (status, stdout, text) = report(&dir, "report.json", "en");
    assert_eq!(status, 2, "the broken file makes the exit status 2");
    assert!(
        stdout.contains("zz-broken") && stdout.contains("error"),
        "{stdout}"
    );
    let j: Value = serde_json::from_str(&text).expect("the report is JSON");
    assert_eq!(j["students"], 60, "the broken file is not counted");
    assert_eq!(j["not_marked"].as_array().unwrap().len(), 1);
    assert_eq!(j["not_marked"][0]["student"], "zz-broken");
    let class: Vec<Student> = (0..60).map(student).collect();
    let totals: Vec<f64> = class
        .iter()
        .map(|s| KEYS.iter().map(|k| mark(s, k)).sum())
        .collect();
    let keys: Vec<&str> = j["keys"]
        .as_array()
        .unwrap()
        .iter()
        .map(|k| k["key"].as_str().unwrap())
        .collect();
    assert_eq!(keys, KEYS, "every key, in the order of the solution");
    for k in KEYS {
        let x: Vec<f64> = class.iter().map(|s| mark(s, k)).collect();
        let p = x.iter().sum::<f64>() / 60.0;
        let d = upper_minus_lower(&x, &totals.iter().map(|t| t / 18.0).collect::<Vec<_>>());
        let rest: Vec<f64> = totals.iter().zip(&x).map(|(t, x)| (t - x) / 17.0).collect();
        let r = pearson(&x, &rest);
        let got = key(&j, k);
        assert!(
            close(got["facility"].as_f64().unwrap(), p),
            "{k}: p {} vs {p}",
            got["facility"]
        );
        assert!(
            close(got["discrimination"].as_f64().unwrap(), d),
            "{k}: D {} vs {d}",
            got["discrimination"]
        );
        match r {
            Some(r) => assert!(
                close(got["point_biserial"].as_f64().unwrap(), r),
                "{k}: r {} vs {r}",
                got["point_biserial"]
            ),
            None => assert!(
                got["point_biserial"].is_null(),
                "{k}: {}",
                got["point_biserial"]
            ),
        }
        let counts = &got["counts"];
        let correct: u64 = ["correct.exact", "correct.rounded", "correct.tolerance"]
            .iter()
            .map(|c| counts[c].as_u64().unwrap())
            .sum();
        assert_eq!(
            correct,
            x.iter().filter(|&&m| m == 1.0).count() as u64,
            "{k}: {counts}"
        );
        assert_eq!(
            counts["too_coarse"],
            x.iter().filter(|&&m| m == 0.5).count(),
            "{k}"
        );
    }
}

#[test]
fn the_keys_counted_by_hand() {
    let dir = class_of_sixty("by-hand");
    let (_, _, text) = report(&dir, "report.json", "en");
    let j: Value = serde_json::from_str(&text).expect("the report is JSON");
    // view.n is wrong for the 10 with n unnormalised and half right
    // for the 5 too coarse: p = (60 − 10 − 5·½)/60
    assert!(close(
        key(&j, "view.n")["facility"].as_f64().unwrap(),
        47.5 / 60.0
    ));
    assert_eq!(key(&j, "view.n")["counts"]["wrong"], 10);
    // v: wrong for the 6 of u = n × Vup (v = (0, −1, 0)) and the 10 with n
    // unnormalised (v = (0, √2, 0)), unparseable for S13: p = 43/60
    let v = key(&j, "view.v");
    assert_eq!(v["counts"]["wrong"], 16);
    assert_eq!(v["counts"]["unparseable"], 1);
    assert!(close(v["facility"].as_f64().unwrap(), 43.0 / 60.0));
    // pixel A: left out by 4; wrong for the 6 of cross_order and the 10 of
    // tan(fovy) who wrote pixels (n unnormalised leaves A″ and A): p = 40/60
    let a = key(&j, "viewport.pixels.A");
    assert_eq!(a["counts"]["missing"], 4);
    assert_eq!(a["counts"]["wrong"], 16);
    assert!(close(a["facility"].as_f64().unwrap(), 40.0 / 60.0));
    // pixel B: also wrong for the 8 with n unnormalised who wrote pixels and
    // the 5 slips: 6 + 10 + 8 + 5 = 29 wrong, 4 missing, p = 27/60
    let b = key(&j, "viewport.pixels.B");
    assert_eq!(b["counts"]["wrong"], 29);
    assert_eq!(b["counts"]["missing"], 4);
    assert!(close(b["facility"].as_f64().unwrap(), 27.0 / 60.0));
    // the height: 12 with fovy not halved and 15 with the half extent
    assert!(close(
        key(&j, "window.height")["facility"].as_f64().unwrap(),
        33.0 / 60.0
    ));
    // the width everyone gets wrong the same way: very hard, D = 0, no r
    let w = key(&j, "window.width");
    assert_eq!(w["facility"], 0.0);
    assert_eq!(w["discrimination"], 0.0);
    assert!(w["point_biserial"].is_null());
    assert_eq!(w["flags"], serde_json::json!(["very_hard"]));
    assert_eq!(w["counts"]["wrong"], 60);
    // A′: wrong for the 6 of cross_order and the 10 with n unnormalised
    // (A′ = (0, −√2, −6)): p = 44/60
    assert!(close(
        key(&j, "view.points.A")["facility"].as_f64().unwrap(),
        44.0 / 60.0
    ));
    assert_eq!(key(&j, "view.points.A")["counts"]["wrong"], 16);
    // A″, wrong only for the 6 of cross_order (an unnormalised n scales y′
    // and z′ alike, so A″ = (0, −√2/60) stays): p = 0.9, not above, no flag
    let pa = key(&j, "project.points.A");
    assert!(close(pa["facility"].as_f64().unwrap(), 0.9));
    assert_eq!(pa["counts"]["wrong"], 6);
    assert!(pa["flags"].as_array().unwrap().is_empty());
}

#[test]
fn the_mistakes_are_named_with_their_students_keys_and_step_largest_first() {
    let dir = class_of_sixty("mistakes");
    let (_, _, text) = report(&dir, "report.json", "en");
    let j: Value = serde_json::from_str(&text).unwrap();
    let names = |pred: &dyn Fn(&Student) -> bool| -> Vec<String> {
        (0..60)
            .map(student)
            .filter(|s| pred(s))
            .map(|s| s.name)
            .collect()
    };
    // each mistake explains the keys it changes, but the width, which
    // everyone writes the same wrong way (0.15); a student who left the
    // pixels out has fewer, the class the union
    let explained = |keys: &[&'static str]| -> Vec<&'static str> {
        keys.iter()
            .copied()
            .filter(|k| *k != "window.width")
            .collect()
    };
    let want: [(&str, Vec<String>, Vec<&str>); 4] = [
        (
            "height_is_half_extent",
            names(&|s| s.height_is_half_extent),
            explained(&HALF_EXTENT_KEYS),
        ),
        (
            "fovy_not_halved",
            names(&|s| s.fovy_not_halved),
            explained(&FOVY_KEYS),
        ),
        (
            "n_not_normalized",
            names(&|s| s.n_not_normalized),
            explained(&N_NOT_NORMALIZED_KEYS),
        ),
        (
            "cross_order",
            names(&|s| s.cross_order),
            explained(&CROSS_ORDER_KEYS),
        ),
    ];
    let got = j["mistakes"].as_array().unwrap();
    assert_eq!(got.len(), 4, "{got:#?}");
    assert_eq!([15, 12, 10, 6].map(|n| n), want.clone().map(|w| w.1.len()));
    let solve: Value = serde_json::from_slice(
        &grafika()
            .args(["solve", "problems/text-triangle.toml", "--json"])
            .output()
            .unwrap()
            .stdout,
    )
    .unwrap();
    for (m, (code, students, keys)) in got.iter().zip(&want) {
        assert_eq!(m["code"], *code);
        assert_eq!(m["students"], serde_json::json!(students), "{code}");
        assert_eq!(m["keys"], serde_json::json!(keys), "{code}");
        // the step is one of solve's worked solution (where the mistake is made)
        let n = m["step"]["number"].as_u64().unwrap() as usize;
        assert_eq!(m["step"]["title"], solve["steps"][n - 1]["title"], "{code}");
    }
    assert!(
        got[3]["step"]["title"].as_str().unwrap().contains("axis u"),
        "{}",
        got[3]["step"]
    );
}

#[test]
fn the_wrong_answers_no_mistake_explains_are_the_width_and_the_slip() {
    let dir = class_of_sixty("unexplained");
    let (_, _, text) = report(&dir, "report.json", "en");
    let j: Value = serde_json::from_str(&text).unwrap();
    let slipped: Vec<String> = (0..60)
        .map(student)
        .filter(|s| s.pixel_slip)
        .map(|s| s.name)
        .collect();
    // the wrong values no mistake explains, the most common first: the
    // width, 60 times in four forms, and pixel B's slip (142.14 for
    // 124.14), 5 times
    let wrong = j["wrong_answers"].as_array().unwrap();
    assert_eq!(wrong.len(), 2, "{wrong:#?}");
    assert_eq!(wrong[0]["key"], "window.width");
    assert_eq!(
        wrong[0]["values"].as_array().unwrap().len(),
        1,
        "{wrong:#?}"
    );
    assert_eq!(wrong[0]["values"][0]["count"], 60);
    assert_eq!(wrong[0]["values"][0]["value"], "0.15");
    assert_eq!(wrong[1]["key"], "viewport.pixels.B");
    let slips = wrong[1]["values"].as_array().unwrap();
    assert_eq!(slips.len(), 1, "{wrong:#?}");
    assert_eq!(slips[0]["count"], 5);
    assert_eq!(slips[0]["students"], serde_json::json!(slipped));
}

#[test]
fn each_mistake_of_the_design_changes_its_keys_and_no_other() {
    // mark() above counts a mistake wrong on its keys: the answer files
    // must differ from a right student's on exactly those, in every form
    let lines =
        |s: &Student| -> Vec<String> { answer_file(s).lines().skip(1).map(String::from).collect() };
    for form in 0..4 {
        let one = |f: fn(&mut Student)| {
            let mut s = Student {
                form,
                ..Student::default()
            };
            f(&mut s);
            s
        };
        let right = lines(&one(|_| {}));
        let cases: [(Student, &[&str]); 5] = [
            (one(|s| s.cross_order = true), &CROSS_ORDER_KEYS),
            (one(|s| s.fovy_not_halved = true), &FOVY_KEYS),
            (one(|s| s.height_is_half_extent = true), &HALF_EXTENT_KEYS),
            (one(|s| s.n_not_normalized = true), &N_NOT_NORMALIZED_KEYS),
            (one(|s| s.pixel_slip = true), &["viewport.pixels.B"]),
        ];
        for (s, keys) in cases {
            let mine = lines(&s);
            assert_eq!(mine.len(), right.len());
            let changed: Vec<&str> = mine
                .iter()
                .zip(&right)
                .filter(|(a, b)| a != b)
                .map(|(a, _)| a.split(" = ").next().unwrap())
                .collect();
            assert_eq!(changed, keys, "form {form}: {s:?}");
        }
    }
}

#[test]
fn the_histogram_counts_each_score_in_its_tenth() {
    let dir = class_of_sixty("histogram");
    let (_, _, text) = report(&dir, "report.json", "en");
    let j: Value = serde_json::from_str(&text).unwrap();
    let mut want = [0u64; 10];
    for s in (0..60).map(student) {
        let total: f64 = KEYS.iter().map(|k| mark(&s, k)).sum();
        want[((10.0 * total / 18.0).floor() as usize).min(9)] += 1;
    }
    let got: Vec<u64> = j["histogram"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["count"].as_u64().unwrap())
        .collect();
    assert_eq!(got, want);
    assert_eq!(j["histogram"][9]["from"], 90);
    assert_eq!(j["histogram"][9]["to"], 100);
}

#[test]
fn the_report_in_csv_markdown_html_and_indonesian() {
    let dir = class_of_sixty("formats");
    let (_, _, csv) = report(&dir, "report.csv", "en");
    let mut r = csv::Reader::from_reader(csv.as_bytes());
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(&header[..2], ["key", "students"]);
    assert!(
        header.contains(&"facility".to_string()) && header.contains(&"point_biserial".to_string())
    );
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), 18, "one row per key");
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let width = rows.iter().find(|x| &x[0] == "window.width").unwrap();
    assert_eq!(&width[col("flags")], "very_hard");
    assert_eq!(&width[col("wrong")], "60");
    assert_eq!(&width[col("unexplained_wrong")], "60");
    let height = rows.iter().find(|x| &x[0] == "window.height").unwrap();
    assert_eq!(
        &height[col("mistakes")],
        "height_is_half_extent fovy_not_halved"
    );

    let (_, _, md) = report(&dir, "report.md", "en");
    assert!(md.starts_with("# Class report: Triangle ABC"), "{md}");
    assert!(md.contains("| window.width |"), "{md}");
    assert!(
        md.contains("Discrimination D"),
        "the definitions are in the report"
    );
    let (_, _, html) = report(&dir, "report.html", "en");
    let svg = &html[html.find("<svg").unwrap()..html.find("</svg>").unwrap() + 6];
    let doc = roxmltree::Document::parse(svg).expect("the histogram is well-formed SVG");
    assert_eq!(
        doc.descendants().filter(|n| n.has_tag_name("rect")).count(),
        10
    );
    assert!(
        html.contains("S05, S17, S29, S41, S53") || html.contains("S05"),
        "students by mistake"
    );
    let (_, _, id) = report(&dir, "laporan.md", "id");
    assert!(id.starts_with("# Laporan kelas:"), "{id}");
    assert!(
        id.contains("Daya beda D") && id.contains("| 0,55 |"),
        "{id}"
    );
    assert!(id.contains("Siapa membuat kesalahan apa"), "{id}");
}

#[test]
fn a_report_needs_a_known_format_and_a_folder() {
    let dir = class_of_sixty("refusals");
    let out = grafika()
        .args(["check", "problems/text-triangle.toml", "--answers"])
        .arg(&dir)
        .args(["--report", "class.txt", "--json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let e: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(e["error"]["field"], "report");
    let out = grafika()
        .args(["check", "problems/text-triangle.toml", "--answers"])
        .arg(dir.join("s01.toml"))
        .args(["--report", "x.html", "--json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let e: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(e["error"]["field"], "report");
    assert!(!root().join("x.html").exists());
}

#[test]
fn csv_cells_are_quoted_and_formulas_neutralised() {
    let dir = scratch("injection");
    let names = [
        "=HYPERLINK(\"http://x\",\"y\")",
        "Ani\r\nBudi",
        "-1+2",
        "@SUM(A1)",
        "+Tono",
        "Siti, S.Kom",
    ];
    for (i, n) in names.iter().enumerate() {
        let s = Student {
            name: n.to_string(),
            form: i % 4,
            ..Student::default()
        };
        std::fs::write(dir.join(format!("{i}.toml")), answer_file(&s)).unwrap();
    }
    let out = grafika()
        .args(["check", "problems/text-triangle.toml", "--answers"])
        .arg(&dir)
        .args(["--csv", "-"])
        .output()
        .unwrap();
    assert_success(&out);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut r = csv::Reader::from_reader(text.as_bytes());
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(
        rows.len(),
        names.len(),
        "a line break in a name starts no row: {text}"
    );
    let cells: Vec<&str> = rows.iter().map(|r| &r[0]).collect();
    assert_eq!(
        cells,
        [
            "'=HYPERLINK(\"http://x\",\"y\")",
            "Ani\r\nBudi",
            "'-1+2",
            "'@SUM(A1)",
            "'+Tono",
            "Siti, S.Kom"
        ]
    );
    // numbers stay numbers: the score and total columns
    assert_eq!(&rows[0][2], "18");
    assert_eq!(&rows[0][3], "18");
    // every record ends in CRLF (RFC 4180)
    assert!(
        text.ends_with(",\r\n") && text.starts_with("student,file,score"),
        "{text:?}"
    );
}

/// An exam of 3 problems in 4 variants as generate writes it, and answer
/// files made from its keys: two students per variant, all right, except
/// that variant 3's students leave problem 2 out.
fn exam(name: &str) -> (PathBuf, PathBuf) {
    let dir = scratch(name);
    let exam = dir.join("exam");
    let out = grafika()
        .args([
            "generate",
            "--topic",
            "view,window,clip",
            "--count",
            "3",
            "--variants",
            "4",
            "--seed",
            "11",
            "--format",
            "toml",
            "--out",
        ])
        .arg(&exam)
        .output()
        .unwrap();
    assert_success(&out);
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    for v in 1..=4 {
        for who in ["a", "b"] {
            let mut f = format!("student = \"V{v}{who}\"\nvariant = {v}\n");
            for p in 1..=3 {
                if v == 3 && p == 2 {
                    continue;
                }
                let key = std::fs::read_to_string(
                    exam.join(format!("variant-0{v}/problem-0{p}.key.toml")),
                )
                .unwrap();
                f.push_str(&format!("[problem-0{p}]\n{key}"));
            }
            std::fs::write(answers.join(format!("v{v}{who}.toml")), f).unwrap();
        }
    }
    (exam, answers)
}

#[test]
fn an_exam_of_three_problems_in_four_variants() {
    let (exam, answers) = exam("exam");
    std::fs::write(
        answers.join("no-variant.toml"),
        "student = \"Lupa\"\n[problem-01]\nview.n = [\"1\", \"0\", \"0\"]\n",
    )
    .unwrap();
    let report = answers.parent().unwrap().join("exam.json");
    let out = grafika()
        .arg("check")
        .arg(&exam)
        .arg("--answers")
        .arg(&answers)
        .arg("--report")
        .arg(&report)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "the file without its variant is not marked"
    );
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("variant") && stdout.contains("Lupa"),
        "{stdout}"
    );
    let j: Value = serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    assert_eq!(j["students"], 8);
    assert_eq!(j["not_marked"][0]["error"]["field"], "variant");
    let keys: Vec<&str> = j["keys"]
        .as_array()
        .unwrap()
        .iter()
        .map(|k| k["key"].as_str().unwrap())
        .collect();
    for p in ["problem-01.", "problem-02.", "problem-03."] {
        assert!(keys.iter().any(|k| k.starts_with(p)), "{keys:?}");
    }
    assert!(
        keys.iter().position(|k| k.starts_with("problem-02."))
            > keys.iter().position(|k| k.starts_with("problem-01."))
    );
    // problem 2: 6 of 8 students answered it all, 2 left it out: 6/8
    let problems = j["problems"].as_array().unwrap();
    assert_eq!(problems.len(), 3);
    assert_eq!(problems[1]["problem"], "problem-02");
    assert!(
        close(problems[1]["facility"].as_f64().unwrap(), 0.75),
        "{}",
        problems[1]
    );
    assert!(close(problems[0]["facility"].as_f64().unwrap(), 1.0));
    // per variant: variant 3's two students left problem 2 out, but two
    // students are too few to call a variant harder (tests/class_fair.rs
    // flags it with five)
    let variants = j["variants"].as_array().unwrap();
    assert_eq!(variants.len(), 4);
    for v in variants {
        let cell = &v["problems"][1];
        assert!(cell["flag"].is_null() && cell["p_value"].is_null(), "{v}");
        let want = if v["variant"] == 3 { 0.0 } else { 1.0 };
        assert_eq!(cell["facility"], want, "{v}");
        assert_eq!(v["students"], 2);
    }
}

#[test]
fn one_exam_answer_file_is_marked_problem_by_problem() {
    let (exam, answers) = exam("exam-one");
    let out = grafika()
        .arg("check")
        .arg(&exam)
        .arg("--answers")
        .arg(answers.join("v2a.toml"))
        .arg("--json")
        .output()
        .unwrap();
    assert_success(&out);
    let j: Value = serde_json::from_slice(&out.stdout).unwrap();
    let problems = j["problems"].as_array().unwrap();
    assert_eq!(problems.len(), 3);
    for p in problems {
        assert_eq!(
            p["score"]["points"].as_f64(),
            p["score"]["total"].as_f64(),
            "{p}"
        );
    }
    // a variant that is not the exam's
    std::fs::write(answers.join("v9.toml"), "variant = 9\n").unwrap();
    let out = grafika()
        .arg("check")
        .arg(&exam)
        .arg("--answers")
        .arg(answers.join("v9.toml"))
        .arg("--json")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let e: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(e["error"]["field"], "variant");
}

#[test]
fn the_class_in_problems_answers_is_the_one_its_seed_writes() {
    // README: `cargo run --example class -- 2026 problems/answers/class`
    let students = common::class::seeded_class(2026);
    assert!(students.len() >= 20);
    let dir = root().join("problems/answers/class");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    let mut want: Vec<String> = students.iter().map(common::class::file_name).collect();
    want.sort();
    assert_eq!(files, want);
    for s in &students {
        let on_disk = std::fs::read_to_string(dir.join(common::class::file_name(s))).unwrap();
        assert_eq!(on_disk, answer_file(s), "{}", s.name);
    }
}

#[test]
fn the_specs_report_csv_header_is_the_one_written() {
    // docs/spec.md §5 lists the report CSV's columns.
    let spec = std::fs::read_to_string(root().join("docs/spec.md")).unwrap();
    let dir = scratch("spec-header");
    let out = dir.join("class.csv");
    let run = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/",
            "--report",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success());
    let text = std::fs::read_to_string(&out).unwrap();
    let header = text.lines().next().unwrap();
    assert!(spec.contains(&format!("`{header}`")), "{header}");
}
