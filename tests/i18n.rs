//! Bahasa Indonesia and English: the text's three worked examples in both
//! languages (snapshot files, read by a person), every JSON identical across
//! languages but for its human-readable strings, an error of each family
//! (scene, mesh and answer files, numbers, flags, clap) with exit status 2
//! on one line, a check report, an exam key and render's summary in
//! Indonesian, and the shipped problems' Indonesian titles and errata.

mod common;
use common::{grafika, refusal, root, scratch, text};
use serde_json::Value;

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
/// A model without a term says so with the model's name as the text writes
/// it (`Lambert`, `Phong`, `Blinn–Phong`), never the file's key (`lambert`):
/// problems/shade-lambert.toml has no specular term, in both languages.
#[test]
fn a_model_without_a_term_is_named_as_the_text_names_it() {
    let en = text("en", &["solve", "problems/shade-lambert.toml"]);
    assert!(
        en.contains("(the Lambert model has no specular term)"),
        "{en}"
    );
    let id = text("id", &["solve", "problems/shade-lambert.toml"]);
    assert!(
        id.contains("(model Lambert tidak memiliki komponen specular)"),
        "{id}"
    );
    for t in [&en, &id] {
        assert!(
            !t.contains("lambert model") && !t.contains("model lambert"),
            "{t}"
        );
    }
}

fn without_words(v: &Value) -> Value {
    const WORDS: [&str; 11] = [
        "title",
        "statement",
        "source",
        "source_notes",
        "formula",
        "note",
        "section",
        "warnings",
        "notes",
        "mistake",
        "why",
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
    let runs: [&[&str]; 6] = [
        &["solve", "problems/text-camera.toml"],
        &[
            "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
        ],
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
        if args[0] != "check" {
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
        "Nilai: 7/18 = 38,9% (7 benar",
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
        "Tentukan viewing window pada near plane",
    ] {
        assert!(all.contains(phrase), "no `{phrase}` in\n{all}");
    }
    // decimal commas and semicolons between components
    assert!(all.contains("ka = 0,4; kd = 0,6"), "{all}");
}

#[test]
fn every_shipped_problem_has_its_texts_in_both_languages_and_its_errata_kinds() {
    let mut kinds = std::collections::BTreeMap::new();
    for entry in std::fs::read_dir(root().join("problems")).expect("problems/") {
        let path = entry.expect("an entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("reads");
        let value: toml::Table = toml::from_str(&text).expect("TOML");
        let pairs = [
            ("title", "title_id"),
            ("statement", "statement_id"),
            ("source", "source_id"),
            ("source_notes", "source_notes_id"),
        ];
        for (en, id) in pairs {
            assert_eq!(
                value.get(en).map(count),
                value.get(id).map(count),
                "{}: {en} and {id} differ",
                path.display()
            );
        }
        // Every shipped problem is posed: a title and a statement.
        assert!(value.contains_key("statement"), "{}", path.display());
        let list = value.get("errata").and_then(|e| e.as_array());
        for e in list.into_iter().flatten() {
            assert!(
                e.get("why_id").and_then(|w| w.as_str()).is_some(),
                "{}: an erratum without why_id: {e}",
                path.display()
            );
            let kind = e.get("kind").and_then(|k| k.as_str());
            *kinds.entry(kind.unwrap_or("none").to_string()).or_insert(0) += 1;
        }
    }
    // text-triangle.toml: the decimals of B'' and C'' are misprints, the
    // height and width use the text's half extent h (a convention), the
    // right edge doubles a rounded h (rounding); text-clip.toml: three
    // misprints (20/6, the x of 2, and the segment through them).
    let want = [("convention", 2), ("misprint", 5), ("rounding", 1)];
    let want: std::collections::BTreeMap<String, i32> =
        want.into_iter().map(|(k, n)| (k.to_string(), n)).collect();
    assert_eq!(kinds, want);
}

/// How many texts a value holds (a list of notes counts its items).
fn count(v: &toml::Value) -> usize {
    v.as_array().map_or(1, |a| a.len())
}

/// Runs grafika with `LANG=id_ID.UTF-8` (and no other language setting)
/// in `dir`, expects exit status 2 and one line on stderr; returns it.
fn refused_in_indonesian(dir: &std::path::Path, args: &[&str]) -> String {
    let mut cmd = grafika();
    cmd.current_dir(dir)
        .env_remove("GRAFIKA_LANG")
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "id_ID.UTF-8");
    refusal(cmd, args).trim_end().to_string()
}

#[test]
fn a_bad_scene_file_is_refused_in_indonesian() {
    let d = scratch("i18n-scene");
    // Line 4 is `r = "1/0"`; its value starts at column 5.
    std::fs::write(
        d.join("s.toml"),
        "[[object]]\ntype = \"sphere\"\nn = 8\nr = \"1/0\"\n",
    )
    .expect("writes");
    let err = refused_in_indonesian(&d, &["render", "s.toml", "-o", "s.png"]);
    assert_eq!(err, "kesalahan: r: s.toml:4:5: `1/0` membagi dengan nol");
    // A scene with no object (an [image] alone) names `object`.
    std::fs::write(d.join("e.toml"), "[image]\nwidth = 10\nheight = 10\n").expect("writes");
    let err = refused_in_indonesian(&d, &["render", "e.toml", "-o", "e.png"]);
    assert!(
        err.starts_with("kesalahan: object: e.toml: scene tidak memiliki objek"),
        "{err}"
    );
    assert!(!d.join("s.png").exists() && !d.join("e.png").exists());
}

#[test]
fn a_bad_mesh_file_is_refused_in_indonesian() {
    let d = scratch("i18n-mesh");
    let scene = "[[object]]\ntype = \"obj\"\npath = \"m.obj\"\n";
    std::fs::write(d.join("s.toml"), scene).expect("writes");
    // Two vertices and no face.
    std::fs::write(d.join("m.obj"), "v 0 0 0\nv 1 0 0\n").expect("writes");
    let err = refused_in_indonesian(&d, &["render", "s.toml", "-o", "s.png"]);
    assert!(
        err.starts_with("kesalahan: object[0].path: s.toml:1:1: "),
        "{err}"
    );
    assert!(err.ends_with("m.obj tidak memiliki bidang (face)"), "{err}");
    // A face whose third index is not a number.
    std::fs::write(d.join("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n").expect("writes");
    let err = refused_in_indonesian(&d, &["render", "s.toml", "-o", "s.png"]);
    assert!(
        err.ends_with("m.obj bukan berkas OBJ yang sah: sebuah bidang (face) tidak dapat dibaca"),
        "{err}"
    );
}

#[test]
fn a_bad_number_in_an_answer_is_said_in_indonesian() {
    let d = scratch("i18n-answer");
    let problem = root().join("problems/text-triangle.toml");
    let problem = problem.to_str().expect("UTF-8 path");
    // Unreadable as TOML: `1.2.3`. The key `window.top` and ` = ` take 13
    // columns, so the value starts at 14 and its second `.` is column 17.
    std::fs::write(d.join("a.toml"), "student = \"Ani\"\nwindow.top = 1.2.3\n").expect("writes");
    let err = refused_in_indonesian(&d, &["check", problem, "--answers", "a.toml"]);
    assert_eq!(
        err,
        "kesalahan: window.top: a.toml:2:17: sintaks TOML tidak sah: bilangan desimal tidak sah"
    );
    // Readable TOML, but not a number: marked `unparseable`, with the
    // reader's reason in Indonesian (`*` at column 3 of `1+*2`).
    std::fs::write(
        d.join("b.toml"),
        "student = \"Ani\"\nwindow.top = \"1+*2\"\n",
    )
    .expect("writes");
    let b = d.join("b.toml").display().to_string();
    let j: Value =
        serde_json::from_str(&text("id", &["check", problem, "--answers", &b, "--json"]))
            .expect("JSON");
    let answers = j["answers"].as_array().expect("answers");
    let top = answers
        .iter()
        .find(|a| a["key"] == "window.top")
        .expect("window.top");
    assert_eq!(top["code"], "unparseable");
    assert_eq!(
        top["note"],
        "tidak dapat dibaca: seharusnya sebuah bilangan di kolom 3, ditemukan `*`"
    );
}

#[test]
fn a_bad_flag_value_is_refused_in_indonesian() {
    let d = root();
    let err = refused_in_indonesian(
        &d,
        &["window", "--fovy", "abc", "--aspect", "1", "--near", "1"],
    );
    assert_eq!(
        err,
        "kesalahan: fovy: `abc`: seharusnya sebuah bilangan di kolom 1, ditemukan `a`"
    );
    let err = refused_in_indonesian(
        &d,
        &["basis", "--eye", "1,2", "--look", "0,0,0", "--up", "0,1,0"],
    );
    assert_eq!(
        err,
        "kesalahan: eye: `1,2`: seharusnya tiga bilangan x,y,z dipisahkan koma, ditemukan 2 dalam `1,2`"
    );
    // clap's refusals too, and with --lang on the refused line itself.
    let err = refused_in_indonesian(&d, &["basis", "--precision", "foo"]);
    assert_eq!(
        err,
        "kesalahan: --precision <PRECISION>: nilai 'foo' tidak sah; nilai yang mungkin: exact, f64, f32 (lihat --help)"
    );
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .env("LANG", "C")
        .args(["--lang", "id", "bassis"])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        err.trim(),
        "kesalahan: argumen: subperintah 'bassis' tidak dikenal; mungkin maksudnya 'basis' (lihat --help)"
    );
}

#[test]
fn an_error_in_json_has_the_same_field_in_both_languages() {
    let e = |lang| {
        common::json_err(&[
            "--lang", lang, "window", "--fovy", "45", "--aspect", "1", "--near", "1/0",
        ])
    };
    let (en, id) = (e("en"), e("id"));
    assert_eq!(en["field"], "near");
    assert_eq!(en["field"], id["field"]);
    assert_eq!(en["message"], "`1/0` divides by zero");
    assert_eq!(id["message"], "`1/0` membagi dengan nol");
}

#[test]
fn render_summary_and_stats_in_indonesian_with_the_same_json_keys() {
    let d = scratch("i18n-render");
    let scene = root().join("problems/render/cone-flat.toml");
    let scene = scene.to_str().expect("UTF-8 path");
    let run = |lang: &str, png: &str, extra: &[&str]| {
        let png = d.join(png).display().to_string();
        text(lang, &[&["render", scene, "-o", &png], extra].concat())
    };
    let t = run("id", "a.png", &["--stats"]);
    for words in [
        "segitiga digambar = ",
        "piksel diwarnai = ",
        "waktu per bingkai = ",
        " Mpiksel/s); encoding PNG ",
        "Statistik",
        "sisi belakang dibuang (mesh tertutup)",
        "waktu: bingkai",
    ] {
        assert!(t.contains(words), "{words}: {t}");
    }
    // Times are written with the decimal comma: `12,34 ms`.
    let line = t
        .lines()
        .find(|l| l.contains("waktu: bingkai"))
        .expect("a frame time");
    assert!(
        line.trim_end().ends_with(" ms") && line.contains(','),
        "{line}"
    );
    let keys = |lang: &str, png: &str| -> Vec<String> {
        let j: Value = serde_json::from_str(&run(lang, png, &["--json"])).expect("JSON");
        let result = j["result"].as_object().expect("a result").clone();
        assert!(result["frame time"]
            .as_str()
            .unwrap_or_default()
            .contains("Mpixels/s"));
        result.keys().cloned().collect()
    };
    assert_eq!(keys("en", "b.png"), keys("id", "c.png"));
}

#[test]
fn a_problems_title_and_statement_follow_the_language() {
    let t = text(
        "id",
        &[
            "check",
            "problems/text-triangle.toml",
            "--answers-from-text",
        ],
    );
    assert!(
        t.starts_with("Segitiga ABC melalui kamera sintetis — jawaban dari "),
        "{t}"
    );
    let t = text(
        "en",
        &[
            "check",
            "problems/text-triangle.toml",
            "--answers-from-text",
        ],
    );
    assert!(
        t.starts_with("Triangle ABC through a synthetic camera — answers of "),
        "{t}"
    );
}

/// The `.rs` files under `dir`, recursively.
fn sources(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("a source directory") {
        let path = entry.expect("an entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_error_is_said_in_english_text() {
    // `Error::new` is gone (it does not compile); an error could still be
    // given words of one language as notation: `Error::said(f, "…".into())`
    // or `Error::said(f, Msg::Math(…))`. None in src/.
    let mut files = Vec::new();
    sources(&root().join("src"), &mut files);
    assert!(files.len() > 50, "{}", files.len());
    for f in files {
        let text = std::fs::read_to_string(&f).expect("reads");
        for (at, _) in text.match_indices("Error::said(") {
            let call: String = text[at..].chars().take(160).collect();
            let call = call.split(";").next().unwrap_or_default();
            assert!(
                !call.contains("Msg::Math")
                    && !call.contains("\".into()")
                    && !call.contains("Msg::from"),
                "{}: an error in words of one language: {call}",
                f.display()
            );
        }
    }
}

/// Words the Indonesian output keeps in English on purpose: the text's own
/// English terms (Bab 6 keeps viewing window, view volume, clipping, region
/// code, near/far plane, viewport, aspect ratio; Bab 9 keeps diffuse
/// scattering, specular reflection, ambient, Lambert's Law, Phong model,
/// flat and Gouraud shading, lightVector, viewVector; the Direct3D page
/// keeps directional, spot, falloff, Power and its constants), the names
/// of the notation (top, near, code0, cos, norm, …), codes an answer or a
/// script uses (clipped, accepted, rejected, none, exact, f64) and the
/// commands typed in practice (hint, show, …), a flag's value (off), a
/// student's and a triangle's names (Budi, ABC); and words Bahasa
/// Indonesia shares with English (basis, errata, global, per, trivial,
/// normal, material, model, status, linear) or that its programmers use
/// (render, renderer, rasterizer, thread, binning, encoding PNG, z-buffer, RGB, the
/// topic `pipeline`), the text's `face`.
const KEPT: &str = "viewing window view volume clipping clip clipped accepted rejected region code \
    plane near far viewport aspect ratio fovy top bottom left right height width xmin xmax ymin \
    ymax zmin zmax yvmax zvmax code0 code1 AND bit Pe Pr Pref Peye Vup Mcam Pl Cp Vp Ldir ambient \
    diffuse Diffuse scattering Scattering specular Specular reflection Reflection Lambert Lambert's \
    Law Phong model Model Blinn Gouraud flat shading highlight lightVector viewVector emissive \
    Direct3D directional spot Spot falloff power Power penumbra theta phi range Att cos tan max \
    min norm sqrt round clamp Liang Barsky status normal material Material hint show skip back \
    quit none eye exact follow through seed Cspecular Cwhite D3DRS_LOCALVIEWER TRUE diagnosis \
    kiri kanan bawah atas depan belakang contoh bab budi abc axis zprp zvp off \
    basis errata global per trivial face linear render renderer rasterizer raster binning thread \
    encoding png buffer rgb row pipeline Is Ia Id Isp ksp cosⁿ";

/// The words of a text, with what is not a sentence's word taken out: the
/// keys of answers (`view.points.A`), the mistake codes
/// (`[height_is_half_extent]`), file names and flags, and the words in a
/// `grafika …` command line.
fn sentence_words(text: &str) -> Vec<String> {
    let mut words = Vec::new();
    // the parts of the keys, also where a table wraps a key (`…right.p` / `oint`)
    let keys: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || "│┆()".contains(c))
        .filter(|t| t.contains('.') && t.chars().any(char::is_alphabetic))
        .collect();
    for line in text.lines() {
        let line = line.split("grafika ").next().unwrap_or_default();
        // code: lighting::shade, object[0]
        let line: String = line
            .split(' ')
            .filter(|t| !t.contains("::") && !t.contains("[0") && !t.contains("[1"))
            .collect::<Vec<_>>()
            .join(" ");
        for token in line.split(|c: char| c.is_whitespace() || "()[]{}:;,=<>\"`|".contains(c)) {
            let t = token.trim_matches(|c: char| !c.is_alphanumeric());
            let code = t.contains('.')
                || t.contains('_')
                || t.starts_with('-')
                || token.starts_with("--")
                || (t.len() > 2 && keys.iter().any(|k| k.contains(t)));
            if code || t.chars().any(|c| c.is_ascii_digit()) {
                continue;
            }
            // names of the notation are short (Ax, Cs, ka, xp, Pe, ...)
            words.extend(
                t.split(['-', '/', '\'', '’', '·'])
                    .filter(|w| w.chars().count() > 2 && w.chars().all(char::is_alphabetic))
                    .map(str::to_lowercase),
            );
        }
    }
    words
}

/// `grafika --lang LANG ARGS` with `stdin`: its standard output, and the
/// text of the file it writes to `page` (an HTML page or a Markdown key),
/// written afresh (the folder `page` is in is emptied first).
fn run_in(lang: &str, args: &[&str], stdin: &str, page: Option<&std::path::Path>) -> String {
    if let Some(dir) = page.and_then(|p| p.parent()) {
        let _ = std::fs::remove_dir_all(dir);
        std::fs::create_dir_all(dir).expect("a folder");
    }
    let mut all = vec!["--lang", lang];
    all.extend_from_slice(args);
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .args(&all)
        .write_stdin(stdin)
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{all:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut text = String::from_utf8(out.stdout).expect("UTF-8");
    if let Some(p) = page.filter(|p| p.extension().is_some_and(|e| e != "png")) {
        // the page's text: tags (and the inline figures) left out
        let html = std::fs::read_to_string(p).expect("the page");
        let body = html.split_once("<body>").map_or(html.as_str(), |x| x.1);
        let html = body
            .split("<svg")
            .map(|s| s.split_once("</svg>").map_or(s, |x| x.1));
        for part in html {
            let mut inside = false;
            let chars: Vec<char> = part.chars().collect();
            for (i, &c) in chars.iter().enumerate() {
                // a tag opens with a name or `/` (a formula's `q < 0` is text)
                let tag = |k: usize| {
                    chars
                        .get(k)
                        .is_some_and(|n| n.is_alphabetic() || *n == '/' || *n == '!')
                };
                match c {
                    '<' if tag(i + 1) => inside = true,
                    '>' => {
                        inside = false;
                        text.push(' ');
                    }
                    c if !inside => text.push(c),
                    _ => {}
                }
            }
        }
    }
    text
}

#[test]
fn no_english_sentence_under_lang_id() {
    let kept: std::collections::BTreeSet<String> =
        KEPT.split_whitespace().map(str::to_lowercase).collect();
    let page = scratch("no-english").join("page.html");
    let page_arg = page.to_str().unwrap().to_string();
    let dir = scratch("no-english-out");
    let (key, png) = (dir.join("key.md"), dir.join("cone.png"));
    let mut runs: Vec<(Vec<String>, String, bool)> = Vec::new();
    let own = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    for entry in std::fs::read_dir(root().join("problems")).expect("problems/") {
        let path = entry.expect("an entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let f = path.to_str().unwrap();
        runs.push((own(&["solve", f, "--html", &page_arg]), String::new(), true));
        // both hints before each answer: the second names the step's values
        let hinted = "hint\nhint\nshow\n".repeat(60);
        runs.push((own(&["practice", f]), hinted, false));
        let text = std::fs::read_to_string(&path).expect("reads");
        if text.contains("[printed]") {
            runs.push((
                own(&["check", f, "--answers-from-text"]),
                String::new(),
                false,
            ));
        }
    }
    let calc: [&[&str]; 6] = [
        &[
            "basis", "--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0",
        ],
        &[
            "view",
            "--eye",
            "4,4,4",
            "--look",
            "0,1,4",
            "--up",
            "0,1,0",
            "--point",
            "Pref=0,1,4",
        ],
        &[
            "project", "--cop", "5", "--plane", "1", "--point", "A=1,2,-3",
        ],
        &[
            "window",
            "--fovy",
            "45",
            "--aspect",
            "2",
            "--near",
            "0.1",
            "--far",
            "10",
            "--viewport",
            "200x100",
            "--point",
            "A=0,-0.02",
        ],
        &[
            "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
        ],
        &[
            "shade", "--light", "0,0,1", "--normal", "0,1,1", "--color", "1,1,0", "--model",
            "blinn",
        ],
    ];
    for args in calc {
        runs.push((own(args), String::new(), false));
    }
    runs.push((
        own(&[
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/budi.toml",
        ]),
        String::new(),
        false,
    ));
    let d = dir.to_str().unwrap();
    let keyed = own(&[
        "generate",
        "--topic",
        "basis,view,project,window,clip,shade,pipeline",
        "--count",
        "7",
        "--out",
        d,
    ]);
    let png_arg = png.to_str().unwrap();
    let pixel = own(&[
        "render",
        "problems/render/cone-flat.toml",
        "-o",
        png_arg,
        "--stats",
        "--explain-pixel",
        "330,150",
    ]);
    let mut found = Vec::new();
    for (args, stdin, with_page) in runs.iter().chain([
        &(keyed, String::new(), true),
        &(pixel, String::new(), false),
    ]) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let written = match args[0] {
            "generate" => Some(key.as_path()),
            "render" => Some(png.as_path()),
            _ => with_page.then_some(page.as_path()),
        };
        let p = written;
        let english: std::collections::BTreeSet<String> =
            sentence_words(&run_in("en", &args, stdin, p))
                .into_iter()
                .collect();
        for w in sentence_words(&run_in("id", &args, stdin, p)) {
            if english.contains(&w) && !kept.contains(&w) {
                found.push(format!("{w} ({})", args[..2].join(" ")));
            }
        }
    }
    found.sort();
    found.dedup();
    assert!(
        found.is_empty(),
        "English under --lang id:\n{}",
        found.join("\n")
    );
}

/// A wrong vector's "expected" note in Indonesian separates its components
/// by `;`, as its decimal commas require: diffuse = kd·cos α·Ld·C =
/// 0.6·(√2/2)·(1, 1, 0) = (3√2/10, 3√2/10, 0) ≈ (0,424264; 0,424264; 0)
/// (with `, ` it read "0,424264, 3√2/10").
#[test]
fn an_expected_vector_in_indonesian_separates_its_components_by_semicolons() {
    let dir = tempfile::tempdir().unwrap();
    let answers = dir.path().join("budi.toml");
    std::fs::write(&answers, "\"shade.diffuse\" = \"(0,6; 0,6; 0)\"\n").unwrap();
    let out = grafika()
        .args([
            "check",
            "problems/shade-phong.toml",
            "--lang",
            "id",
            "--json",
        ])
        .arg("--answers")
        .arg(&answers)
        .output()
        .unwrap();
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let answers = v["answers"].as_array().unwrap();
    let diffuse = answers
        .iter()
        .find(|a| a["key"] == "shade.diffuse")
        .unwrap();
    assert_eq!(
        diffuse["note"],
        "seharusnya (3√2/10 ≈ 0,424264; 3√2/10 ≈ 0,424264; 0)"
    );
}
