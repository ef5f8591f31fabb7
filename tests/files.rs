//! Issue 28: never lose a file, never hang on a file. Every output goes
//! through one writer (a temporary file renamed into place), an existing
//! file is replaced only with --force, an input never, a link is never
//! written through; generate's folder is written whole or not at all;
//! standard output errors are errors, a broken pipe ends quietly; control
//! characters from files are shown escaped.

mod common;
use common::*;
use std::path::{Path, PathBuf};

/// A fresh folder for one test (removed when dropped).
fn scratch() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("grafika-files-")
        .tempdir()
        .unwrap()
}

fn p(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// The names in a folder, recursively, relative to it, sorted.
fn tree(dir: &Path) -> Vec<String> {
    fn walk(base: &Path, d: &Path, out: &mut Vec<String>) {
        for e in std::fs::read_dir(d).unwrap() {
            let e = e.unwrap();
            let path = e.path();
            out.push(path.strip_prefix(base).unwrap().display().to_string());
            if e.file_type().unwrap().is_dir() {
                walk(base, &path, out);
            }
        }
    }
    let mut out = Vec::new();
    if dir.exists() {
        walk(dir, dir, &mut out);
    }
    out.sort();
    out
}

/// No temporary file or folder of the writer is left anywhere below `dir`.
fn no_temporaries(dir: &Path) {
    let left: Vec<String> = tree(dir)
        .into_iter()
        .filter(|n| n.contains(".grafika-tmp-"))
        .collect();
    assert!(left.is_empty(), "temporary files left: {left:?}");
}

/// A small scene (a 32×32 cone) copied into `dir`.
fn small_scene(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(root().join("problems/render/cone-flat.toml")).unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    scene
}

fn refused(args: &[&str], field: &str) -> String {
    let out = grafika().args(args).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(
        err.starts_with(&format!("error: {field}: ")),
        "{args:?}: {err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    err
}

#[test]
fn render_never_writes_over_its_scene_or_its_mesh() {
    let d = scratch();
    let scene = small_scene(d.path());
    let before = std::fs::read(&scene).unwrap();
    let err = refused(&["render", p(&scene), "-o", p(&scene), "--force"], "output");
    assert!(err.contains("own inputs"), "{err}");
    // The same file by another name: a path through `..`, a hard link.
    std::fs::create_dir(d.path().join("sub")).unwrap();
    let dotdot = d.path().join("sub/../scene.toml");
    refused(
        &["render", p(&scene), "-o", p(&dotdot), "--force"],
        "output",
    );
    let hard = d.path().join("hard.png");
    std::fs::hard_link(&scene, &hard).unwrap();
    refused(&["render", p(&scene), "-o", p(&hard), "--force"], "output");
    assert_eq!(std::fs::read(&scene).unwrap(), before);
    // The OBJ file a scene reads is one of its inputs too.
    let obj = d.path().join("tri.obj");
    std::fs::write(&obj, "v 0 0 0\nv 100 0 0\nv 0 100 0\nf 1 2 3\n").unwrap();
    let with_obj = d.path().join("obj.toml");
    std::fs::write(
        &with_obj,
        "[image]\nwidth = 16\nheight = 16\n[[object]]\ntype = \"obj\"\npath = \"tri.obj\"\n",
    )
    .unwrap();
    refused(
        &["render", p(&with_obj), "-o", p(&obj), "--force"],
        "output",
    );
    assert_eq!(
        std::fs::read_to_string(&obj).unwrap(),
        "v 0 0 0\nv 100 0 0\nv 0 100 0\nf 1 2 3\n"
    );
    no_temporaries(d.path());
}

#[test]
fn an_existing_output_is_replaced_only_with_force() {
    let d = scratch();
    let scene = small_scene(d.path());
    let png = d.path().join("cone.png");
    std::fs::write(&png, "the lecturer's picture").unwrap();
    let args = [
        "render",
        p(&scene),
        "-o",
        p(&png),
        "--width",
        "32",
        "--height",
        "32",
    ];
    let err = refused(&args, "output");
    assert!(
        err.contains("already exists") && err.contains("--force"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(&png).unwrap(),
        "the lecturer's picture"
    );
    grafika().args(args).arg("--force").assert().success();
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    // --html and --figure follow the same rule.
    let html = d.path().join("page.html");
    std::fs::write(&html, "mine").unwrap();
    let solve = ["solve", "problems/text-camera.toml", "--html", p(&html)];
    refused(&solve, "html");
    assert_eq!(std::fs::read_to_string(&html).unwrap(), "mine");
    grafika().args(solve).arg("--force").assert().success();
    assert!(std::fs::read_to_string(&html).unwrap().contains("<html"));
    no_temporaries(d.path());
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_is_never_written_through() {
    let d = scratch();
    let scene = small_scene(d.path());
    let victim = d.path().join("victim.txt");
    std::fs::write(&victim, "keep me").unwrap();
    let link = d.path().join("link.png");
    std::os::unix::fs::symlink(&victim, &link).unwrap();
    let err = refused(&["render", p(&scene), "-o", p(&link), "--force"], "output");
    assert!(err.contains("symbolic link"), "{err}");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
}

#[test]
fn check_csv_is_refused_onto_the_problem_the_answers_or_an_existing_file() {
    let d = scratch();
    let prob = d.path().join("prob.toml");
    std::fs::copy(root().join("problems/text-triangle.toml"), &prob).unwrap();
    let before = std::fs::read(&prob).unwrap();
    let siti = "problems/answers/triangle/siti.toml";
    refused(
        &[
            "check",
            p(&prob),
            "--answers",
            siti,
            "--csv",
            p(&prob),
            "--force",
        ],
        "csv",
    );
    assert_eq!(std::fs::read(&prob).unwrap(), before);
    let answers = d.path().join("class");
    std::fs::create_dir(&answers).unwrap();
    std::fs::copy(root().join(siti), answers.join("siti.toml")).unwrap();
    let a = answers.join("siti.toml");
    refused(
        &[
            "check",
            p(&prob),
            "--answers",
            p(&answers),
            "--csv",
            p(&a),
            "--force",
        ],
        "csv",
    );
    let csv = d.path().join("marks.csv");
    std::fs::write(&csv, "last week's marks").unwrap();
    let args = [
        "check",
        p(&prob),
        "--answers",
        p(&answers),
        "--csv",
        p(&csv),
    ];
    refused(&args, "csv");
    assert_eq!(std::fs::read_to_string(&csv).unwrap(), "last week's marks");
    grafika().args(args).arg("--force").assert().success();
    assert!(std::fs::read_to_string(&csv)
        .unwrap()
        .starts_with("student,file,"));
}

#[test]
fn a_class_with_a_broken_file_says_so_on_stderr() {
    let d = scratch();
    let answers = d.path().join("class");
    std::fs::create_dir(&answers).unwrap();
    std::fs::copy(
        root().join("problems/answers/triangle/siti.toml"),
        answers.join("siti.toml"),
    )
    .unwrap();
    std::fs::write(answers.join("broken.toml"), "x = [\n").unwrap();
    let csv = d.path().join("marks.csv");
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            p(&answers),
        ])
        .args(["--csv", p(&csv)])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("1 of the 2 answer files") && err.contains("broken.toml"),
        "{err}"
    );
    assert!(std::fs::read_to_string(&csv)
        .unwrap()
        .contains("broken.toml"));
}

fn generate(out: &Path, count: &str, variants: &str, extra: &[&str]) -> std::process::Output {
    grafika()
        .args([
            "generate",
            "--topic",
            "view",
            "--count",
            count,
            "--variants",
            variants,
        ])
        .args(["--seed", "1", "--format", "md", "--out", p(out)])
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn generate_refuses_a_lecturers_files_before_writing_anything() {
    let d = scratch();
    let out = d.path().join("exam");
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("key.md"), "lecturer").unwrap();
    let o = generate(&out, "2", "1", &[]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(tree(&out), ["key.md"], "nothing written");
    // With --force too: key.md is not generate's own.
    let o = generate(&out, "2", "1", &["--force"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("not written by grafika generate"), "{err}");
    assert_eq!(
        std::fs::read_to_string(out.join("key.md")).unwrap(),
        "lecturer"
    );
    // An existing variant folder is refused as a whole.
    let out2 = d.path().join("exam2");
    std::fs::create_dir_all(out2.join("variant-02")).unwrap();
    std::fs::write(out2.join("variant-02/notes.md"), "x").unwrap();
    assert_eq!(generate(&out2, "1", "3", &[]).status.code(), Some(2));
    assert_eq!(tree(&out2), ["variant-02", "variant-02/notes.md"]);
    no_temporaries(d.path());
}

#[test]
fn generate_force_replaces_its_own_output_whole_and_nothing_else() {
    let d = scratch();
    let out = d.path().join("exam");
    assert!(generate(&out, "3", "4", &[]).status.success());
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let o = generate(&out, "2", "2", &["--force"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut want = vec![
        ".grafika-generated".to_string(),
        "blueprint.json".into(),
        "blueprint.md".into(),
        "notes.txt".into(),
    ];
    for v in 1..=2 {
        want.push(format!("variant-0{v}"));
        for f in [
            "key.md",
            "problem-01.key.toml",
            "problem-01.toml",
            "problem-02.key.toml",
        ] {
            want.push(format!("variant-0{v}/{f}"));
        }
        want.push(format!("variant-0{v}/problem-02.toml"));
        want.push(format!("variant-0{v}/questions.md"));
    }
    want.sort();
    assert_eq!(
        tree(&out),
        want,
        "no stale variant-03, variant-04 or problem-03"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("notes.txt")).unwrap(),
        "mine"
    );
    // A file the lecturer put into a variant folder makes it not generate's own.
    std::fs::write(out.join("variant-01/notes.md"), "mine").unwrap();
    assert_eq!(
        generate(&out, "2", "2", &["--force"]).status.code(),
        Some(2)
    );
    assert_eq!(
        std::fs::read_to_string(out.join("variant-01/notes.md")).unwrap(),
        "mine"
    );
}

#[cfg(unix)]
#[test]
fn generate_force_never_follows_a_planted_link() {
    let d = scratch();
    let out = d.path().join("exam");
    assert!(generate(&out, "1", "1", &[]).status.success());
    let victim = d.path().join("victim.txt");
    std::fs::write(&victim, "keep me").unwrap();
    std::fs::remove_file(out.join("key.md")).unwrap();
    std::os::unix::fs::symlink(&victim, out.join("key.md")).unwrap();
    assert_eq!(
        generate(&out, "1", "1", &["--force"]).status.code(),
        Some(2)
    );
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep me");
}

#[test]
fn solve_figure_writes_all_parts_or_none() {
    let d = scratch();
    let fig = d.path().join("fig.svg");
    std::fs::write(d.path().join("fig-2-project.svg"), "mine").unwrap();
    refused(
        &["solve", "problems/text-triangle.toml", "--figure", p(&fig)],
        "figure",
    );
    assert_eq!(tree(d.path()), ["fig-2-project.svg"], "part 1 not written");
    // A folder is not a file name.
    let err = refused(
        &[
            "solve",
            "problems/text-triangle.toml",
            "--figure",
            &format!("{}/", p(d.path())),
        ],
        "figure",
    );
    assert!(err.contains("is a folder"), "{err}");
    refused(
        &[
            "basis",
            "--eye",
            "3,1,3",
            "--look",
            "2,1,2",
            "--up",
            "0,1,0",
            "--figure",
            p(d.path()),
        ],
        "figure",
    );
    assert_eq!(tree(d.path()), ["fig-2-project.svg"]);
}

#[test]
fn a_write_error_leaves_no_partial_file() {
    let d = scratch();
    let scene = small_scene(d.path());
    let full = |args: &[&str]| {
        let out = grafika()
            .env("GRAFIKA_TEST_FAIL_SYNC", "1")
            .args(args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("no space left"), "{err}");
    };
    let png = d.path().join("c.png");
    full(&[
        "render",
        p(&scene),
        "-o",
        p(&png),
        "--width",
        "16",
        "--height",
        "16",
    ]);
    let html = d.path().join("t.html");
    full(&["solve", "problems/text-camera.toml", "--html", p(&html)]);
    let csv = d.path().join("m.csv");
    full(&[
        "check",
        "problems/text-triangle.toml",
        "--answers",
        "problems/answers/triangle/",
        "--csv",
        p(&csv),
    ]);
    let out = d.path().join("exam");
    full(&[
        "generate",
        "--topic",
        "view",
        "--count",
        "1",
        "--variants",
        "2",
        "--seed",
        "1",
        "--out",
        p(&out),
    ]);
    let quiz = d.path().join("quiz");
    full(&[
        "generate",
        "--topic",
        "view",
        "--count",
        "1",
        "--variants",
        "2",
        "--seed",
        "1",
        "--format",
        "moodle",
        "--out",
        p(&quiz),
    ]);
    assert_eq!(tree(d.path()), ["scene.toml"], "nothing but the scene");
    // And a rerun is not refused because of a partial file.
    grafika()
        .args(["solve", "problems/text-camera.toml", "--html", p(&html)])
        .assert()
        .success();
}

#[cfg(unix)]
#[test]
fn sigterm_during_a_long_generate_leaves_no_partial_file() {
    let d = scratch();
    for (k, wait_ms) in [150u64, 400, 900].into_iter().enumerate() {
        let out = d.path().join(format!("exam{k}"));
        let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("grafika"))
            .args([
                "generate",
                "--topic",
                "pipeline",
                "--count",
                "20",
                "--variants",
                "60",
            ])
            .args(["--seed", "1", "--format", "latex", "--out", p(&out)])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(wait_ms));
        std::process::Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .unwrap();
        let status = child.wait().unwrap();
        let files = tree(&out);
        // Stopped: nothing at all. Finished first: all of it.
        if status.success() {
            assert_eq!(files.len(), 1 + 60 * (1 + 20 * 2 + 2), "complete output");
        } else {
            assert!(
                files.is_empty(),
                "stopped at {wait_ms} ms, left {} entries",
                files.len()
            );
            assert!(!out.exists(), "the folder it created is removed");
        }
    }
    no_temporaries(d.path());
}

#[cfg(unix)]
#[test]
fn standard_output_errors_are_errors_and_a_broken_pipe_is_quiet() {
    let bin = assert_cmd::cargo::cargo_bin("grafika");
    let cases: &[&[&str]] = &[
        &["solve", "problems/text-triangle.toml"],
        &[
            "check",
            "problems/text-triangle.toml",
            "--answers",
            "problems/answers/triangle/",
        ],
        &["man"],
        &["completions", "bash"],
        &["--help"],
    ];
    for args in cases {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let out = std::process::Command::new(&bin)
            .current_dir(root())
            .args(*args)
            .stdout(full)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?} > /dev/full: {err}");
        assert!(
            err.starts_with("error: stdout: cannot write to standard output"),
            "{err}"
        );
        // A closed standard output: refused, not lost.
        let sh = format!("exec {} {} >&-", bin.display(), args.join(" "));
        let out = std::process::Command::new("sh")
            .current_dir(root())
            .args(["-c", &sh])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?} >&-: {err}");
        assert!(err.contains("standard output is closed"), "{err}");
    }
    // More than a pipe holds (64 KB), then the reader goes away.
    let mut cmd = std::process::Command::new(&bin);
    cmd.current_dir(root())
        .args(["view", "--eye", "4,4,4", "--look", "0,1,4", "--up", "0,1,0"]);
    for i in 0..3000 {
        cmd.arg("--point").arg(format!("P{i}={i},1,2"));
    }
    let mut child = cmd
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 1];
    std::io::Read::read_exact(child.stdout.as_mut().unwrap(), &mut first).unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "a broken pipe ends quietly");
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Whether text holds a character that acts on a terminal.
fn raw_control(s: &str) -> bool {
    s.chars().any(|c| {
        (c.is_control() && c != '\n' && c != '\t') || ('\u{202a}'..='\u{202e}').contains(&c)
    })
}

#[test]
fn control_characters_from_files_are_shown_escaped() {
    let d = scratch();
    let answers = d.path().join("a.toml");
    std::fs::write(
        &answers,
        "student = \"A\\u001b[2J\\u0007\\u009b\\u202eB\"\n\"window.top\" = \"0.0414\\u0008\"\n",
    )
    .unwrap();
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            p(&answers),
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(!raw_control(&text), "{text}");
    assert!(
        text.contains("A\\u{1B}[2J\\u{7}\\u{9B}\\u{202E}B"),
        "{text}"
    );
    // JSON reads back to the very name, with nothing raw on the way.
    let out = grafika()
        .args([
            "check",
            "problems/text-triangle.toml",
            "--answers",
            p(&answers),
            "--json",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(!raw_control(&text), "{text}");
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["who"], "A\u{1b}[2J\u{7}\u{9b}\u{202e}B");
    // A backspace and a form feed in a point name: the SVG and the page are
    // well-formed XML.
    let prob = d.path().join("p.toml");
    std::fs::write(
        &prob,
        "title = \"T\\u0008\\u001b[31m\"\nask = [\"view\"]\n[camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n[points]\n\"A\\u0008\\u000c\" = [1, 2, 3]\n",
    )
    .unwrap();
    let fig = d.path().join("f.svg");
    let html = d.path().join("f.html");
    let out = grafika()
        .args(["solve", p(&prob), "--figure", p(&fig), "--html", p(&html)])
        .output()
        .unwrap();
    assert_success(&out);
    assert!(!raw_control(&String::from_utf8_lossy(&out.stdout)));
    let svg = std::fs::read_to_string(d.path().join("f-1-view.svg")).unwrap();
    roxmltree::Document::parse(&svg).expect("well-formed SVG");
    assert!(svg.contains("A\\u{8}\\u{C}"), "the name shown escaped");
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(!raw_control(&page));
}

#[test]
fn practice_reads_a_line_of_at_most_4_kb() {
    // 5 MB of commas on one line: asked again as unreadable, then quit.
    let mut input = ",".repeat(5 << 20);
    input.push_str("\nquit\n");
    let out = grafika()
        .args(["practice", "problems/text-camera.toml", "--json"])
        .write_stdin(input)
        .output()
        .unwrap();
    assert_success(&out);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.lines().all(|l| l.len() < 20_000),
        "no line echoes the 5 MB"
    );
    assert!(text.contains("\"event\":\"summary\""), "{text}");
}
