//! Bahasa Indonesia and English: the text's three worked examples in both
//! languages (snapshot files, read by a person), every JSON identical across
//! languages but for its human-readable strings, and an error, a check report
//! and an exam key in Indonesian.

mod common;
use common::{grafika, root};
use serde_json::Value;

/// The output of `grafika --lang LANG ARGS`, expecting success.
fn text(lang: &str, args: &[&str]) -> String {
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .args(["--lang", lang])
        .args(args)
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// Compares with tests/snapshots/NAME; `GRAFIKA_SNAPSHOTS=write` writes it.
fn snapshot(name: &str, got: &str) {
    let path = root().join("tests/snapshots").join(name);
    if std::env::var("GRAFIKA_SNAPSHOTS").as_deref() == Ok("write") {
        std::fs::write(&path, got).expect("writes the snapshot");
    }
    let want = std::fs::read_to_string(&path).expect("the snapshot exists");
    assert!(want == got, "{name} differs from its snapshot:\n{got}");
}

#[test]
fn the_texts_three_worked_examples_in_both_languages() {
    for ex in ["camera", "triangle", "clip"] {
        for lang in ["en", "id"] {
            let file = format!("problems/text-{ex}.toml");
            snapshot(
                &format!("solve-text-{ex}.{lang}.txt"),
                &text(lang, &["solve", &file]),
            );
        }
    }
}

#[test]
fn indonesian_text_uses_the_decimal_comma_and_the_texts_terms() {
    let t = text("id", &["solve", "problems/text-camera.toml"]);
    assert!(t.contains("n = (4/5; 3/5; 0) = (0,8; 0,6; 0)"), "{t}");
    assert!(t.contains("Sumbu kamera n"), "{t}");
    assert!(t.contains("sistem koordinat dunia"), "{t}");
    let t = text("id", &["solve", "problems/text-clip.toml"]);
    assert!(t.contains("Region code titik"), "{t}");
    assert!(t.contains("Titik potong dengan bidang"), "{t}");
}

/// Drops the human-readable strings of a report's JSON.
fn without_words(v: &Value) -> Value {
    const WORDS: [&str; 8] = [
        "title", "formula", "note", "section", "warnings", "notes", "mistake", "why",
    ];
    match v {
        Value::Object(m) => Value::Object(
            m.iter()
                .filter(|(k, _)| !WORDS.contains(&k.as_str()))
                .map(|(k, v)| (k.clone(), without_words(v)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.iter().map(without_words).collect()),
        other => other.clone(),
    }
}

#[test]
fn json_is_the_same_in_both_languages_but_for_its_words() {
    let runs: [&[&str]; 5] = [
        &["solve", "problems/text-camera.toml"],
        &["solve", "problems/text-triangle.toml"],
        &["solve", "problems/text-clip.toml"],
        &["solve", "problems/shade-two-lights.toml"],
        &[
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/budi.toml",
        ],
    ];
    for args in runs {
        let j = |lang| -> Value {
            serde_json::from_str(&text(lang, &[args, &["--json"]].concat())).expect("JSON")
        };
        let (en, id) = (j("en"), j("id"));
        assert_eq!(without_words(&en), without_words(&id), "{args:?}");
        if args[0] == "solve" {
            assert_ne!(
                en["steps"][0]["title"], id["steps"][0]["title"],
                "{args:?}: titles translated"
            );
        }
    }
}

#[test]
fn an_error_in_indonesian_names_the_field_as_spelled() {
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .env("LANG", "id_ID.UTF-8")
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .args([
            "basis", "--eye", "4,4,4", "--look", "4,4,4", "--up", "0,1,0",
        ])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        err.trim(),
        "kesalahan: look: posisi mata Peye dan titik referensi Pref adalah titik yang sama (4; 4; 4)"
    );
    let j = common::json_err(&["--lang", "id", "solve", "problems/errors/fovy-180.toml"]);
    assert_eq!(j["field"], "perspective.fovy");
    let msg = j["message"].as_str().unwrap_or_default();
    assert!(msg.starts_with("harus di antara 0° dan 180°"), "{msg}");
}

#[test]
fn a_check_report_in_indonesian() {
    let t = text(
        "id",
        &[
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/budi.toml",
        ],
    );
    for w in [
        "penilaian",
        "seharusnya",
        "Diagnosis:",
        "menghasilkan ulang",
        "Nilai: 7/18 (7 benar",
        "salah",
    ] {
        assert!(t.contains(w), "{w} missing in:\n{t}");
    }
    assert!(t.contains("u = n × Vup, bukan Vup × n"), "{t}");
    assert!(
        t.contains("(0,7071; 0; −0,7071)") || t.contains("≈ (0,7071;"),
        "{t}"
    );
}

#[test]
fn check_accepts_both_decimal_marks() {
    let dir = std::env::temp_dir().join(format!("grafika-i18n-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let f = dir.join("ani.toml");
    std::fs::write(
        &f,
        "student = \"Ani\"\nview.n = \"(0,7071; 0; 0,7071)\"\nwindow.top = \"0,04142\"\nview.v = [\"0\", \"1\", \"0\"]\n",
    )
    .expect("writes");
    let j: Value = serde_json::from_str(&text(
        "id",
        &[
            "check",
            "problems/text-triangle.toml",
            "--answers",
            f.to_str().unwrap_or_default(),
            "--json",
        ],
    ))
    .expect("JSON");
    let verdict = |k: &str| {
        j["answers"]
            .as_array()
            .and_then(|a| a.iter().find(|x| x["key"] == k))
            .map(|x| x["verdict"].clone())
    };
    assert_eq!(verdict("view.n"), Some(Value::from("correct")), "{j}");
    assert_eq!(verdict("window.top"), Some(Value::from("correct")), "{j}");
    assert_eq!(verdict("view.v"), Some(Value::from("correct")), "{j}");
}

#[test]
fn an_exam_key_in_indonesian() {
    let dir = std::env::temp_dir().join(format!("grafika-i18n-exam-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    grafika()
        .args([
            "--lang", "id", "generate", "--topic", "pipeline", "--count", "1", "--seed", "7",
        ])
        .args(["--format", "md", "--out", dir.to_str().unwrap_or_default()])
        .assert()
        .success();
    let mut all = String::new();
    for e in std::fs::read_dir(&dir).expect("the exam directory") {
        let p = e.expect("entry").path();
        if p.extension().is_some_and(|x| x == "md") {
            all.push_str(&std::fs::read_to_string(&p).expect("reads"));
        }
    }
    assert!(all.contains("Langkah 1."), "{all}");
    assert!(all.contains("Sumbu kamera n"), "{all}");
    assert!(!all.contains("**Step "), "{all}");
}

/// The files an exam of `lang` writes: (name, text), sorted by name.
fn exam_files(lang: &str, topics: &str) -> Vec<(String, String)> {
    let dir = std::env::temp_dir().join(format!(
        "grafika-i18n-statements-{lang}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    grafika()
        .args([
            "--lang", lang, "generate", "--topic", topics, "--count", "6",
        ])
        .args(["--seed", "3", "--out", dir.to_str().unwrap_or_default()])
        .assert()
        .success();
    let mut files: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("the exam directory")
        .map(|e| {
            let p = e.expect("entry").path();
            let name = p
                .file_name()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned();
            (name, std::fs::read_to_string(&p).expect("reads"))
        })
        .collect();
    files.sort();
    files
}

#[test]
fn generated_statements_in_indonesian_with_the_same_problems() {
    let topics = "view,clip,shade,pipeline,window,project";
    let (en, id) = (exam_files("en", topics), exam_files("id", topics));
    assert_eq!(en.len(), id.len());
    for ((name, e), (_, i)) in en.iter().zip(&id) {
        if name.ends_with(".key.toml") {
            // the answers are the same; only the comment's title differs
            let body = |t: &str| t.lines().skip(1).collect::<Vec<_>>().join("\n");
            assert_eq!(body(e), body(i), "{name}");
            assert!(i.starts_with("# Kunci jawaban: "), "{i}");
        } else if name.ends_with(".toml") {
            // the data are the same; the title and statement are Indonesian
            let data = |t: &str| t.lines().skip(2).collect::<Vec<_>>().join("\n");
            assert_eq!(data(e), data(i), "{name}");
            assert!(!i.contains("Find ") && !i.contains("A camera"), "{i}");
        }
    }
    let all: String = id.iter().map(|(_, t)| t.as_str()).collect();
    for phrase in [
        "posisi mata Peye",
        "titik referensi Pref",
        "Tentukan sumbu kamera n, u, v dan koordinat kamera",
        "region code P0 dan P1",
        "kiri, kanan, bawah, atas, depan, belakang",
        "vektor normal N",
        "Tentukan bidang pandang",
    ] {
        assert!(all.contains(phrase), "no `{phrase}` in\n{all}");
    }
    // decimal commas and semicolons between components
    assert!(all.contains("ka = 0,4; kd = 0,6"), "{all}");
}

#[test]
fn every_erratum_of_the_shipped_problems_has_its_indonesian_why() {
    let mut errata = 0;
    for entry in std::fs::read_dir(root().join("problems")).expect("problems/") {
        let path = entry.expect("an entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("reads");
        let value: toml::Table = toml::from_str(&text).expect("TOML");
        let list = value.get("errata").and_then(|e| e.as_array());
        for e in list.into_iter().flatten() {
            errata += 1;
            assert!(
                e.get("why_id").and_then(|w| w.as_str()).is_some(),
                "{}: an erratum without why_id: {e}",
                path.display()
            );
        }
    }
    // text-triangle.toml has 5 errata and text-clip.toml 3.
    assert_eq!(errata, 8);
}
