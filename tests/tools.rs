//! Checks that need a program from outside Rust: headless Chromium (Debian's
//! `chromium`) opens the worked-solution page and its screenshot is checked
//! to be non-blank; `pdflatex` (texlive-latex-base, texlive-pictures)
//! compiles an exam key. `.ci/install-test-tools` installs both where it
//! can. With `GRAFIKA_MOODLE` set to the root of a Moodle 5.x installed for
//! testing (docs/contributing.md), a quiz goes the whole way round: Moodle
//! takes 30 students' attempts, grafika re-marks its Responses download and
//! Moodle's gradebook imports grafika's grades, read back equal. This file has its own `main` (no test harness), so that a check
//! that cannot run says SKIPPED on the console instead of passing quietly.

use std::path::Path;
use std::process::Command;

fn main() {
    let dir = std::env::temp_dir().join(format!("grafika-tools-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let mut failed = false;
    for (name, check) in [
        (
            "chromium renders the triangle page",
            chromium as fn(&Path) -> Outcome,
        ),
        (
            "pdflatex compiles an exam key with its TikZ figures",
            pdflatex,
        ),
        (
            "a live Moodle's quiz is re-marked and its grades imported back",
            moodle,
        ),
    ] {
        match check(&dir) {
            Outcome::Passed => println!("test {name} ... ok"),
            Outcome::Skipped(why) => println!("test {name} ... SKIPPED: {why}"),
            Outcome::Failed(why) => {
                println!("test {name} ... FAILED: {why}");
                failed = true;
            }
        }
    }
    if failed {
        std::process::exit(1);
    }
}

enum Outcome {
    Passed,
    Skipped(String),
    Failed(String),
}

/// grafika with these arguments, expecting success.
fn grafika(args: &[&str]) -> Result<(), String> {
    let out = Command::new(env!("CARGO_BIN_EXE_grafika"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("GRAFIKA_LANG")
        .args(args)
        .output()
        .map_err(|e| e.to_string())?;
    match out.status.success() {
        true => Ok(()),
        false => Err(String::from_utf8_lossy(&out.stderr).into_owned()),
    }
}

/// Whether a program runs at all (`--version`).
fn available(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

fn chromium(dir: &Path) -> Outcome {
    let Some(browser) = ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|p| available(p))
    else {
        return Outcome::Skipped("no chromium (run .ci/install-test-tools)".into());
    };
    let page = dir.join("triangle.html");
    let shot = dir.join("triangle.png");
    if let Err(e) = grafika(&["solve", "problems/text-triangle.toml", "--html", &s(&page)]) {
        return Outcome::Failed(e);
    }
    let run = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
        ])
        .arg("--window-size=800,1200")
        .arg(format!("--screenshot={}", s(&shot)))
        .arg(format!("file://{}", s(&page)))
        .output();
    if let Err(e) = run {
        return Outcome::Failed(format!("{browser}: {e}"));
    }
    match ink(&shot) {
        Ok(f) if f > 0.01 => Outcome::Passed,
        Ok(f) => Outcome::Failed(format!("the screenshot is blank ({:.4} of it drawn)", f)),
        Err(e) => Outcome::Failed(e),
    }
}

/// The share of a PNG's pixels that are not near-white.
fn ink(path: &Path) -> Result<f64, String> {
    let file = std::fs::File::open(path).map_err(|e| format!("no screenshot: {e}"))?;
    let mut dec = png::Decoder::new(std::io::BufReader::new(file));
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().map_err(|e| e.to_string())?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let channels = info.color_type.samples();
    let pixels = &buf[..info.buffer_size()];
    let dark = pixels
        .chunks(channels)
        .filter(|p| p.iter().take(3).any(|&c| c < 200))
        .count();
    Ok(dark as f64 / (pixels.len() / channels).max(1) as f64)
}

fn pdflatex(dir: &Path) -> Outcome {
    if !available("pdflatex") {
        return Outcome::Skipped("no pdflatex (run .ci/install-test-tools)".into());
    }
    let out = dir.join("exam");
    // One problem of each topic, so the key has every kind of figure.
    let args = [
        "generate",
        "--topic",
        "basis,view,project,window,clip,shade,pipeline",
        "--count",
        "7",
        "--seed",
        "3",
        "--format",
        "latex",
        "--out",
    ];
    if let Err(e) = grafika(&[&args[..], &[&s(&out)]].concat()) {
        return Outcome::Failed(e);
    }
    let key = std::fs::read_to_string(out.join("key.tex")).unwrap_or_default();
    // Every problem of these topics has a figure of one panel or more.
    let pictures = key.matches("\\begin{tikzpicture}").count();
    if pictures < 7 {
        return Outcome::Failed(format!(
            "the key has {pictures} TikZ pictures, not one per problem at least"
        ));
    }
    let run = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "key.tex"])
        .current_dir(&out)
        .output();
    match run {
        Ok(o) if o.status.success() && out.join("key.pdf").exists() => Outcome::Passed,
        Ok(o) => Outcome::Failed(String::from_utf8_lossy(&o.stdout).into_owned()),
        Err(e) => Outcome::Failed(e.to_string()),
    }
}

/// The quiz of seed 2026 through a live Moodle and back: the grades the
/// gradebook holds after the import are grafika's, for every student
/// re-marked.
fn moodle(dir: &Path) -> Outcome {
    let Some(root) = std::env::var_os("GRAFIKA_MOODLE") else {
        return Outcome::Skipped(
            "GRAFIKA_MOODLE is not set (a Moodle 5.x test site's root)".into(),
        );
    };
    if !available("php") {
        return Outcome::Skipped("no php".into());
    }
    match moodle_round_trip(dir, Path::new(&root)) {
        Ok(()) => Outcome::Passed,
        Err(e) => Outcome::Failed(e),
    }
}

fn moodle_round_trip(dir: &Path, root: &Path) -> Result<(), String> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/moodle/responses.php");
    let php = |args: &[String]| -> Result<String, String> {
        let out = Command::new("php")
            .arg(&script)
            .arg(format!("--moodle={}", s(root)))
            .args(args)
            .output()
            .map_err(|e| e.to_string())?;
        match out.status.success() {
            true => Ok(String::from_utf8_lossy(&out.stdout).into_owned()),
            false => Err(String::from_utf8_lossy(&out.stderr).into_owned()),
        }
    };
    let (quiz, exam) = (dir.join("moodle-quiz"), dir.join("moodle-exam"));
    for (format, out) in [("moodle", &quiz), ("json", &exam)] {
        let args = ["generate", "--topic", "view,window,clip", "--count", "3"];
        let more = [
            "--variants",
            "2",
            "--seed",
            "2026",
            "--format",
            format,
            "--out",
        ];
        grafika(&[&args[..], &more[..], &[&s(out)]].concat())?;
    }
    let made = php(&[
        format!("--file={}", s(&quiz.join("quiz.xml"))),
        "--students=30".into(),
    ])?;
    let made: serde_json::Value = serde_json::from_str(made.trim()).map_err(|e| e.to_string())?;
    let course = format!("--course={}", made["course"]);
    let report = dir.join("responses.csv");
    let csv = php(&["--download=csv".into(), course.clone()])?;
    std::fs::write(&report, csv).map_err(|e| e.to_string())?;
    let grades = dir.join("grades.csv");
    let (e, r, g) = (s(&exam), s(&report), s(&grades));
    grafika(&[
        "check",
        &e,
        "--moodle-responses",
        &r,
        "--follow-through",
        "--grades",
        &g,
    ])?;
    // Email address,ID number,Name,grafika,Moodle
    let mut read = csv::Reader::from_path(&grades).map_err(|e| e.to_string())?;
    let ours: Vec<(String, f64)> = (read.records().flatten())
        .filter_map(|r| Some((r.get(0)?.to_string(), r.get(3)?.parse().ok()?)))
        .collect();
    let back = php(&[format!("--import={g}"), course])?;
    let mut same = 0;
    for line in back.lines() {
        let v: serde_json::Value = serde_json::from_str(line).map_err(|e| e.to_string())?;
        let Some((_, mine)) = ours.iter().find(|(m, _)| v["email"] == m.as_str()) else {
            continue;
        };
        let theirs: f64 = v["grade"]
            .as_str()
            .and_then(|t| t.parse().ok())
            .unwrap_or(f64::NAN);
        if (theirs - mine).abs() > 0.005 {
            return Err(format!(
                "{}: Moodle holds {theirs}, grafika gave {mine}",
                v["email"]
            ));
        }
        same += 1;
    }
    match same == 29 && ours.len() == 29 {
        true => Ok(()),
        false => Err(format!(
            "{same} grades read back of {} re-marked, not 29",
            ours.len()
        )),
    }
}

fn s(p: &Path) -> String {
    p.display().to_string()
}
