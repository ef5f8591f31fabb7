//! The class report says only what its numbers can carry: a variant is
//! flagged harder only with enough students to tell; the same student
//! handed in twice is counted once; a sheet that fits another variant's key
//! says so; an answers folder that cannot be read is named. Each class is
//! written here from the exam's own keys (names with spaces, Indonesian
//! words, decimal commas), and each expected number is worked in a comment.

mod common;

use common::{assert_success, grafika, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// An exam of 3 problems (view, window, clip) in 4 variants as `generate`
/// writes it, in `dir/exam`.
fn exam(dir: &Path) -> PathBuf {
    let exam = dir.join("exam");
    let out = grafika()
        .args(["generate", "--topic", "view,window,clip", "--count", "3"])
        .args([
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
    exam
}

/// An answer file of variant `v` naming `student`, with the key of variant
/// `key_of` for each problem in `problems` (1-based).
fn sheet(exam: &Path, student: &str, v: usize, key_of: usize, problems: &[usize]) -> String {
    let mut f = format!("student = \"{student}\"\nvariant = {v}\n");
    for p in problems {
        let key =
            std::fs::read_to_string(exam.join(format!("variant-0{key_of}/problem-0{p}.key.toml")))
                .unwrap();
        f.push_str(&format!("[problem-0{p}]\n{key}"));
    }
    f
}

/// Runs `check EXAM --answers DIR --report REPORT` with `lang`; returns the
/// exit status and standard output.
fn check(lang: &str, exam: &Path, answers: &Path, report: &Path) -> (Option<i32>, String) {
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .args(["--lang", lang, "check"])
        .arg(exam)
        .arg("--answers")
        .arg(answers)
        .arg("--report")
        .arg(report)
        .output()
        .unwrap();
    (out.status.code(), String::from_utf8(out.stdout).unwrap())
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn one_student_per_variant_flags_no_variant_and_says_why() {
    let dir = scratch("fair-one-per-variant");
    let exam = exam(&dir);
    let answers = dir.join("jawaban");
    std::fs::create_dir_all(&answers).unwrap();
    // one student per variant; the student of variant 3 leaves problem 2
    // out: a facility of 0 against 1 for the other three, which the old
    // rule (0.2 below the others' median) flagged "harder" on one student
    for (v, name) in [
        (1, "Ani Lestari"),
        (2, "Budi Santoso"),
        (3, "Citra Dewi"),
        (4, "Dedi"),
    ] {
        let problems: &[usize] = if v == 3 { &[1, 3] } else { &[1, 2, 3] };
        std::fs::write(
            answers.join(format!("{name}.toml")),
            sheet(&exam, name, v, v, problems),
        )
        .unwrap();
    }
    let report = dir.join("laporan.json");
    let (code, _) = check("id", &exam, &answers, &report);
    assert_eq!(code, Some(0));
    let j = json(&report);
    assert_eq!(j["variant_test"]["min_students"], 5);
    let variants = j["variants"].as_array().unwrap();
    assert_eq!(variants.len(), 4);
    for v in variants {
        assert_eq!(v["students"], 1, "{v}");
        for p in v["problems"].as_array().unwrap() {
            assert!(p["flag"].is_null() && p["p_value"].is_null(), "{v}");
        }
    }
    assert_eq!(variants[2]["problems"][1]["facility"], 0.0);
    // the page says why, in the report's language, with n beside each
    // variant's facility
    for (lang, words) in [
        (
            "id",
            "Terlalu sedikit mahasiswa per varian untuk membandingkan varian: n = 1",
        ),
        (
            "en",
            "Too few students per variant to compare variants: n = 1",
        ),
    ] {
        let md = dir.join(format!("laporan-{lang}.md"));
        let (code, _) = check(lang, &exam, &answers, &md);
        assert_eq!(code, Some(0));
        let text = std::fs::read_to_string(&md).unwrap();
        assert!(text.contains(words), "{text}");
        // no cell is flagged (a flag's cell gives its p; the note after the
        // table explains ▼ and ▲)
        assert!(!text.contains("(p "), "{text}");
        assert!(text.contains("| 3 | 1 |"), "variant 3, n = 1: {text}");
    }
}

#[test]
fn five_students_per_variant_flag_the_variant_all_five_left_out() {
    let dir = scratch("fair-five-per-variant");
    let exam = exam(&dir);
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    for v in 1..=4 {
        for i in 1..=5 {
            let name = format!("Mahasiswa {v}-{i}");
            let problems: &[usize] = if v == 3 { &[1, 3] } else { &[1, 2, 3] };
            std::fs::write(
                answers.join(format!("{name}.toml")),
                sheet(&exam, &name, v, v, problems),
            )
            .unwrap();
        }
    }
    let report = dir.join("class.json");
    let (code, _) = check("en", &exam, &answers, &report);
    assert_eq!(code, Some(0));
    let j = json(&report);
    // problem 2: variant 3 has 0 over 5 students, the rest 1 over 15.
    // p̄ = 15/20 = 0.75, √(0.75·0.25·(1/5 + 1/15)) = √0.05 = 0.223607,
    // z = 1/0.223607 = 4.4721, p = 2·Q(4.4721) = 7.744e-6; Holm over the
    // 4 variants: 4·7.744e-6 = 3.098e-5 < 0.05, flagged harder.
    // Variant 1 (and 2, 4): 1 against (10·1 + 5·0)/15 = 2/3: z =
    // (1/3)/0.223607 = 1.4907, p = 0.1360; Holm: at least 3·0.1360 = 0.41,
    // not flagged.
    let variants = j["variants"].as_array().unwrap();
    for v in variants {
        let cell = &v["problems"][1];
        let p = cell["p_value"].as_f64().unwrap();
        if v["variant"] == 3 {
            assert_eq!(cell["flag"], "harder", "{v}");
            assert!((p - 3.098e-5).abs() < 2e-8, "{p}");
        } else {
            assert!(cell["flag"].is_null(), "{v}");
            assert!((p - 0.4079).abs() < 2e-3, "{p}");
        }
        // problems 1 and 3: everyone right, nothing to test
        assert!(v["problems"][0]["p_value"].is_null(), "{v}");
    }
}

#[test]
fn the_same_student_twice_is_counted_once() {
    let dir = scratch("fair-duplicates");
    let exam = exam(&dir);
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    // each file modified after the one before (the file modified last of
    // a student's is kept)
    let write = |file: &str, text: &str| {
        std::fs::write(answers.join(file), text).unwrap();
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    // Adi hands in twice, the second time as the browser names a second
    // download; his first file lacks problem 3
    write("adi.toml", &sheet(&exam, "Adi Nugroho", 1, 1, &[1, 2]));
    write(
        "adi (1).toml",
        &sheet(&exam, "adi  nugroho", 1, 1, &[1, 2, 3]),
    );
    // Sari twice under two spellings of her name, the same NIM
    let with_nim = |s: String| s.replacen("\nvariant", "\nnim = \"2106 1234\"\nvariant", 1);
    write(
        "sari.toml",
        &with_nim(sheet(&exam, "Sari Lestari", 2, 2, &[1, 2, 3])),
    );
    write(
        "sari-l.toml",
        &with_nim(sheet(&exam, "Sari L.", 2, 2, &[1])),
    );
    // Budi's file saved again under another name without his name in it
    let budi = sheet(&exam, "Budi", 3, 3, &[1, 2, 3]);
    write("budi.toml", &budi);
    write(
        "tugas akhir.toml",
        &budi.replacen("student = \"Budi\"\n", "", 1),
    );
    // two students of the same name and different NIMs are two students
    let nim = |s: String, n: &str| s.replacen("\nvariant", &format!("\nnim = \"{n}\"\nvariant"), 1);
    write(
        "dewi-a.toml",
        &nim(sheet(&exam, "Dewi", 4, 4, &[1, 2, 3]), "1"),
    );
    write(
        "dewi-b.toml",
        &nim(sheet(&exam, "Dewi", 4, 4, &[1, 2]), "2"),
    );
    let report = dir.join("class.json");
    let (code, stdout) = check("en", &exam, &answers, &report);
    assert_eq!(code, Some(0), "{stdout}");
    let j = json(&report);
    // 8 files: Adi, Sari, Budi once each and the two Dewis
    assert_eq!(j["students"], 5, "{}", j["duplicates"]);
    let dups: Vec<(String, String, String)> = j["duplicates"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            let name = |k: &str| {
                Path::new(d[k].as_str().unwrap())
                    .file_name()
                    .unwrap()
                    .to_string_lossy()
                    .into_owned()
            };
            (
                name("file"),
                name("kept"),
                d["same"].as_str().unwrap().to_string(),
            )
        })
        .collect();
    let want = |a: &str, b: &str, c: &str| (a.to_string(), b.to_string(), c.to_string());
    // the file modified last is kept, whatever the order of the names
    assert!(
        dups.contains(&want("adi.toml", "adi (1).toml", "name")),
        "{dups:?}"
    );
    assert!(
        dups.contains(&want("sari.toml", "sari-l.toml", "nim")),
        "{dups:?}"
    );
    assert!(
        dups.contains(&want("budi.toml", "tugas akhir.toml", "answers")),
        "{dups:?}"
    );
    assert_eq!(dups.len(), 3, "{dups:?}");
    assert!(
        stdout.contains("the same student as adi (1).toml (same name): not counted"),
        "{stdout}"
    );
    // in Indonesian
    let md = dir.join("laporan.md");
    let (_, stdout) = check("id", &exam, &answers, &md);
    assert!(
        stdout.contains("mahasiswa yang sama dengan adi (1).toml (nama sama): tidak dihitung"),
        "{stdout}"
    );
    let text = std::fs::read_to_string(&md).unwrap();
    assert!(text.contains("Mahasiswa yang sama dua kali"), "{text}");
}

#[test]
fn a_sheet_that_fits_another_variants_key_says_so() {
    let dir = scratch("fair-fits");
    let exam = exam(&dir);
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    for (v, name) in [(1, "Ani"), (3, "Citra"), (4, "Dedi")] {
        std::fs::write(
            answers.join(format!("{name}.toml")),
            sheet(&exam, name, v, v, &[1, 2, 3]),
        )
        .unwrap();
    }
    // Eko answers variant 2 with Dedi's answers (variant 4's key)
    std::fs::write(
        answers.join("Eko Prasetyo.toml"),
        sheet(&exam, "Eko Prasetyo", 2, 4, &[1, 2, 3]),
    )
    .unwrap();
    let report = dir.join("class.json");
    let (code, stdout) = check("en", &exam, &answers, &report);
    assert_eq!(code, Some(0));
    assert!(
        stdout.contains("these answers fit variant 4's key (100 % of the marks there"),
        "{stdout}"
    );
    let j = json(&report);
    let fits = j["fits"].as_array().unwrap();
    assert_eq!(fits.len(), 1, "{fits:?}");
    assert_eq!(fits[0]["student"], "Eko Prasetyo");
    assert_eq!(fits[0]["variant"], 2);
    assert_eq!(fits[0]["fits_variant"], 4);
    assert_eq!(fits[0]["there"], 1.0);
    // the score counted is still the one against variant 2
    assert!(fits[0]["own"].as_f64().unwrap() <= 0.5);
    let md = dir.join("laporan.md");
    let (_, _) = check("id", &exam, &answers, &md);
    let text = std::fs::read_to_string(&md).unwrap();
    assert!(
        text.contains("Jawaban yang cocok dengan kunci varian lain"),
        "{text}"
    );
    assert!(
        text.contains("jawaban ini cocok dengan kunci varian 4"),
        "{text}"
    );
}

#[test]
fn an_answers_folder_that_cannot_be_read_is_named() {
    let dir = scratch("fair-nosuchdir");
    let exam = exam(&dir);
    for (lang, words) in [
        (
            "en",
            "answers: the folder of answer files nosuchdir cannot be read",
        ),
        (
            "id",
            "answers: folder berkas jawaban nosuchdir tidak dapat dibaca",
        ),
    ] {
        let out = grafika()
            .env_remove("GRAFIKA_LANG")
            .args(["--lang", lang, "check"])
            .arg(&exam)
            .args(["--answers", "nosuchdir", "--report"])
            .arg(dir.join("x.html"))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(words), "{err}");
        assert!(!dir.join("x.html").exists());
    }
}

#[test]
fn the_class_list_names_who_handed_nothing_in() {
    let dir = scratch("fair-roster");
    let exam = exam(&dir);
    let answers = dir.join("answers");
    std::fs::create_dir_all(&answers).unwrap();
    // Adi's file gives his NIM; Sari's name differs from the list's only in
    // case and spaces; Tono is on no list; Joko handed nothing in
    let adi = sheet(&exam, "A. Nugroho", 1, 1, &[1, 2, 3]).replacen(
        "\nvariant",
        "\nnim = \"2106001\"\nvariant",
        1,
    );
    std::fs::write(answers.join("adi.toml"), adi).unwrap();
    std::fs::write(
        answers.join("sari.toml"),
        sheet(&exam, "sari  LESTARI", 2, 2, &[1, 2, 3]),
    )
    .unwrap();
    std::fs::write(answers.join("tono.toml"), sheet(&exam, "Tono", 3, 3, &[1])).unwrap();
    // a spreadsheet's export: semicolons, a NIM with a space
    let list = dir.join("kelas.csv");
    std::fs::write(
        &list,
        "No;NIM;Nama\n1;2106 001;Adi Nugroho\n2;;Sari Lestari\n3;2106003;Joko Widodo\n",
    )
    .unwrap();
    let report = dir.join("class.json");
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .args(["--lang", "id", "check"])
        .arg(&exam)
        .arg("--answers")
        .arg(&answers)
        .arg("--roster")
        .arg(&list)
        .arg("--report")
        .arg(&report)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("Ada di daftar kelas, tanpa berkas jawaban (1): Joko Widodo (NIM 2106003)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("Berkas jawaban yang tidak ada di daftar kelas (1): Tono"),
        "{stdout}"
    );
    let j = json(&report);
    assert_eq!(j["roster"]["listed"], 3);
    assert_eq!(j["roster"]["missing"][0]["name"], "Joko Widodo");
    assert_eq!(j["roster"]["missing"].as_array().unwrap().len(), 1);
    assert_eq!(j["roster"]["not_listed"][0]["student"], "Tono");
    // a class list needs a class
    let out = grafika()
        .args(["check"])
        .arg(&exam)
        .arg("--answers")
        .arg(answers.join("tono.toml"))
        .arg("--roster")
        .arg(&list)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("roster"));
}
