//! Checks that need a program from outside Rust: headless Chromium (Debian's
//! `chromium`) opens the worked-solution page and its screenshot is checked
//! to be non-blank; `pdflatex` (texlive-latex-base, texlive-pictures)
//! compiles an exam key. `.ci/install-test-tools` installs both where it
//! can. This file has its own `main` (no test harness), so that a check
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

fn s(p: &Path) -> String {
    p.display().to_string()
}
