//! `check EXAM --moodle-responses FILE` on a Responses report downloaded
//! from a real Moodle 5.1 (tests/moodle/fixtures/responses-seed2026.csv,
//! made by tests/moodle/responses.php from the quiz of
//! `generate --topic view,window,clip --count 3 --variants 2 --seed 2026
//! --format moodle`; fake students), against the exam folder generated
//! with the same seed and options (`--format json`), committed beside it
//! as a lecturer keeps the exam of a quiz they gave.
//!
//! Every problem's default scheme gives each answer asked 1 mark:
//! problem 1 asks u, v, n, A', B' (5 marks), problem 2 top, bottom, left,
//! right, height, width (6), problem 3 the two region codes, the status
//! and the segment (4): 15 marks, and the quiz's maximum grade is 100, so
//! a grade is marks / 15 · 100.

mod common;
use common::*;
use std::path::Path;

const FIXTURE: &str = "tests/moodle/fixtures/responses-seed2026.csv";

/// The exam folder the fixture's quiz was generated with.
const EXAM: &str = "tests/moodle/fixtures/exam-seed2026";

/// Runs `check EXAM --moodle-responses report` with `args` (in English),
/// expecting success; returns standard output and standard error.
fn check_responses(report: &Path, args: &[&std::ffi::OsStr]) -> (Vec<u8>, String) {
    let out = grafika()
        .env_remove("GRAFIKA_LANG")
        .arg("check")
        .arg(root().join(EXAM))
        .arg("--moodle-responses")
        .arg(report)
        .args(args)
        .output()
        .expect("runs");
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{err}");
    (out.stdout, err)
}

/// Runs check on `report` with `--grades` and `--follow-through`; returns
/// the grades CSV's rows by email (grafika's grade, Moodle's) and stderr.
fn remark(dir: &Path, report: &Path, extra: &[&str]) -> (Vec<Vec<String>>, String) {
    let grades = dir.join("grades.csv");
    let mut args = vec!["--grades".as_ref(), grades.as_os_str()];
    args.extend(extra.iter().map(std::ffi::OsStr::new));
    let (_, err) = check_responses(report, &args);
    let text = std::fs::read_to_string(&grades).expect("grades written");
    let rows = csv::ReaderBuilder::new()
        .from_reader(text.as_bytes())
        .records()
        .map(|r| r.expect("a record").iter().map(str::to_string).collect())
        .collect();
    (rows, err)
}

fn row<'a>(rows: &'a [Vec<String>], email_start: &str) -> &'a Vec<String> {
    rows.iter()
        .find(|r| r[0].starts_with(email_start))
        .unwrap_or_else(|| panic!("{email_start} in the grades"))
}

#[test]
fn a_real_responses_report_is_re_marked_by_the_exam() {
    let dir = scratch("moodle-responses-real");
    let (rows, err) = remark(&dir, &root().join(FIXTURE), &["--follow-through"]);
    // 30 attempts, the last one in progress: 29 marked, one row each.
    assert_eq!(rows.len(), 29, "{rows:?}");
    assert!(err.contains("re-marked 29 of 30 attempts"), "{err}");
    assert!(
        err.contains("not finished, not marked: Eko Lestari (In progress)"),
        "{err}"
    );
    // student001 answered every blank with the key: 15/15 = 100, as Moodle.
    let r = row(&rows, "student001.");
    assert_eq!((r[3].as_str(), r[4].as_str()), ("100.00", "100.00"));
    // student003 typed every number with a decimal comma, right; an
    // English Moodle reads 0,44721 as 44721 and marks only the whole
    // numbers right: in problem 1 the 0 of u and the -2 of A' (2 of 15
    // blanks of weight 1: 2/15 of 5 marks), in problem 2 none, in problem
    // 3 the codes, the status and 5 of the segment's 6 numbers (-0,5 is
    // wrong: 23 of the weights 6 + 6 + 6 + 6·1 = 24, of 4 marks). Moodle's
    // grade, kept beside grafika's: (2/3 + 23/6) / 15 · 100 = 30; grafika
    // reads the comma: 15/15 = 100.
    let r = row(&rows, "student003.");
    assert_eq!((r[3].as_str(), r[4].as_str()), ("100.00", "30.00"));
    // student005 typed "tidak tahu" in the first blank (u's x, top) and
    // left the second (u's y, bottom, P1's region code) empty: u, top,
    // bottom and P1's code are not earned, the other 11 answers are:
    // 11/15 = 73.33; the three unreadable parts are named.
    let r = row(&rows, "student005.");
    assert_eq!(r[3], "73.33");
    assert!(
        err.contains(
            "Rina =HYPERLINK(\"x\"): problem-01.view.u cannot be read as typed: \"tidak tahu\""
        ),
        "{err}"
    );
    assert!(
        err.contains("Rina =HYPERLINK(\"x\"): problem-03.clip.code1 left empty"),
        "{err}"
    );
    // The name that starts with = is neutralised in the CSV's name column.
    assert_eq!(r[2], "Rina =HYPERLINK(\"x\")");
    let text = std::fs::read_to_string(dir.join("grades.csv")).expect("grades");
    assert!(
        text.starts_with("Email address,ID number,Name,grafika,Moodle\r\n"),
        "{text}"
    );
}

#[test]
fn a_question_not_of_the_exam_is_listed_and_skipped() {
    let dir = scratch("moodle-responses-foreign");
    let text = std::fs::read_to_string(root().join(FIXTURE)).expect("fixture");
    // Row 2's third question replaced by another one's text.
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    lines[1] = lines[1].replacen("The view volume is the box", "What is a pixel? The box", 1);
    let report = dir.join("foreign.csv");
    std::fs::write(&report, lines.join("\n")).expect("writes");
    let (rows, err) = remark(&dir, &report, &[]);
    assert!(
        err.contains("question 3 is not a problem of this exam, skipped: What is a pixel?"),
        "{err}"
    );
    // Row 2 is marked on its two problems of the exam: 11/15 (its third
    // problem's 4 marks unanswered) = 73.33.
    assert_eq!(row(&rows, "student001.")[3], "73.33");
}

/// The grades of the same report downloaded in another format (each
/// test its own folder: `test`).
fn grades_of(test: &str, download: &str) -> (Vec<Vec<String>>, String) {
    let name = format!("moodle-responses-{test}-{}", download.replace('.', "-"));
    let file = format!("tests/moodle/fixtures/responses-seed2026.{download}");
    remark(&scratch(&name), &root().join(file), &[])
}

#[test]
fn the_json_excel_and_indonesian_downloads_give_the_same_grades_as_the_csv() {
    let (csv_rows, _) = grades_of("formats", "csv");
    // Moodle's Indonesian columns: "Nama akhir", "Alamat surel", "Keadaan"
    // (Selesai), "Nilai/100,00" with its grades "73,33", "Soal 1",
    // "Jawaban 1"; the grades come back with a point.
    for download in ["json", "xlsx", "id.csv"] {
        let (rows, err) = grades_of("formats", download);
        assert_eq!(rows, csv_rows, "{download}");
        assert!(
            err.contains("re-marked 29 of 30 attempts"),
            "{download}: {err}"
        );
    }
    let (rows, _) = grades_of("formats", "id.csv");
    assert_eq!(row(&rows, "student004.")[4], "33.33");
}

#[test]
fn the_opendocument_download_is_read_but_moodle_breaks_a_cell_that_begins_with_equals() {
    // Moodle 5.1's ODS writer writes the cell of the last name
    // =HYPERLINK("x") as a broken tag, and the rest of that row moves one
    // column to the left: its "Status" holds the start date, so the row
    // is listed as not finished (with what it holds), never marked on
    // the wrong columns. Every other row is read as in the CSV.
    let (csv_rows, _) = grades_of("ods", "csv");
    let (rows, err) = grades_of("ods", "ods");
    let others: Vec<_> = (csv_rows.iter())
        .filter(|r| !r[0].starts_with("student005."))
        .cloned()
        .collect();
    assert_eq!(rows, others);
    assert!(err.contains("re-marked 28 of 30 attempts"), "{err}");
    assert!(
        err.contains("not finished, not marked: student005."),
        "{err}"
    );
}

#[test]
fn a_student_with_two_attempts_counts_once_by_the_higher_grade() {
    // student004's second attempt: student001's row (every answer right,
    // its own draw) under student004's name and email. The gradebook gets
    // one row for student004, the higher grade (100, Moodle's 100 of that
    // attempt); the class counts 29 students, the first attempt listed as
    // another attempt of the second.
    let dir = scratch("moodle-responses-twice");
    let text = std::fs::read_to_string(root().join(FIXTURE)).expect("fixture");
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(text.trim_start_matches('\u{feff}').as_bytes());
    let mut rows: Vec<csv::StringRecord> = reader.records().map(|r| r.expect("a row")).collect();
    let mut again: Vec<String> = rows[1].iter().map(str::to_string).collect();
    for c in 0..3 {
        again[c] = rows[4][c].to_string(); // last name, first name, email
    }
    rows.push(csv::StringRecord::from(again));
    let report = dir.join("twice.csv");
    let mut w = csv::Writer::from_path(&report).expect("writes");
    rows.iter().for_each(|r| w.write_record(r).expect("a row"));
    w.flush().expect("written");
    drop(w);
    let (grades, err) = remark(&dir, &report, &["--follow-through"]);
    assert!(err.contains("re-marked 30 of 31 attempts"), "{err}");
    assert_eq!(grades.len(), 29, "{grades:?}");
    let r = row(&grades, "student004.");
    assert_eq!((r[3].as_str(), r[4].as_str()), ("100.00", "100.00"));
    let md_file = dir.join("class.md");
    check_responses(&report, &["--report".as_ref(), md_file.as_os_str()]);
    let md = std::fs::read_to_string(dir.join("class.md")).expect("report");
    assert!(md.contains("29 students marked"), "{md}");
    assert!(md.contains("another attempt at the quiz"), "{md}");
}

#[test]
fn a_file_that_is_not_a_responses_report_is_refused_with_its_reason() {
    let err = refusal(
        grafika(),
        &[
            "check",
            "problems/text-triangle.toml",
            "--moodle-responses",
            "README.md",
        ],
    );
    assert!(err.contains("moodle-responses"), "{err}");
}

#[test]
fn each_problem_counts_under_the_variant_its_slot_drew() {
    // student001's slots hold problem 1 of variant 1 (Pe = (3, 0, -2)),
    // problem 2 of variant 2 (fovy = 120°) and problem 3 of variant 2 (the
    // box from (-1, -2, 0)): the exam's variant of each problem, not a
    // draw's number. The exam has 2 variants, so the variants table has
    // 2 rows, whatever the draws.
    let dir = scratch("moodle-responses-drawn");
    let html_file = dir.join("class.html");
    let args = [
        "--json".as_ref(),
        "--report".as_ref(),
        html_file.as_os_str(),
    ];
    let (stdout, _) = check_responses(&root().join(FIXTURE), &args);
    let j: serde_json::Value = serde_json::from_slice(&stdout).expect("JSON");
    let first = &j["students"][0];
    assert_eq!(first["student"], "Siti Rahayu");
    assert_eq!(first["variant"], serde_json::json!([1, 2, 2]));
    let html = std::fs::read_to_string(dir.join("class.html")).expect("report");
    let table = html
        .split("<h2>Variants</h2>")
        .nth(1)
        .expect("a variants table");
    let table = table.split("</table>").next().expect("its end");
    assert_eq!(table.matches("<tr><td>").count(), 2, "{table}");
    assert!(html.contains("each problem's variant was drawn by itself"));
}
