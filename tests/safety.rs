//! Issue 37: never lose a file, never hang, round 2. Outputs that are not
//! regular files are written directly (a character device) or refused,
//! never replaced; a replaced file keeps its mode; generate's list must be
//! its own, one run at a time writes a folder, and a stale temporary file
//! is removed; the same file given twice is refused first; only a truly
//! closed standard stream is closed; inputs are regular files of bounded
//! size and shape.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// A fresh folder for one test (removed when dropped).
fn scratch() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("grafika-safety-")
        .tempdir()
        .unwrap()
}

fn p(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// Runs grafika with `args`; a hang fails the test (no command here waits
/// for anything).
fn run(args: &[&str]) -> std::process::Output {
    grafika()
        .args(args)
        .timeout(Duration::from_secs(60))
        .output()
        .unwrap()
}

/// Expects exit status 2 with an error on `field`; returns stderr.
fn refused(args: &[&str], field: &str) -> String {
    let out = run(args);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(
        err.starts_with(&format!("error: {field}: ")),
        "{args:?}: {err}"
    );
    err
}

/// The names in a folder, sorted (not recursive).
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Makes a FIFO (named pipe) at `path`, if the system can.
#[cfg(unix)]
fn mkfifo(path: &Path) -> bool {
    std::process::Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success())
}

#[cfg(unix)]
fn is_fifo(path: &Path) -> bool {
    use std::os::unix::fs::FileTypeExt;
    std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_fifo())
}

const TRIANGLE: &str = "problems/text-triangle.toml";
const SITI: &str = "problems/answers/triangle/siti.toml";

#[cfg(unix)]
#[test]
fn a_fifo_or_a_socket_is_never_replaced_by_an_output() {
    let d = scratch();
    let fifo = d.path().join("out.csv");
    if !mkfifo(&fifo) {
        eprintln!("SKIPPED: mkfifo is not available");
        return;
    }
    for flag in [["--csv"], ["--report"]] {
        let err = refused(
            &["check", TRIANGLE, "--answers", "problems/answers/triangle/"]
                .iter()
                .copied()
                .chain(flag)
                .chain([p(&fifo), "--force"])
                .collect::<Vec<_>>(),
            &flag[0][2..],
        );
        assert!(err.contains("is a FIFO (named pipe)"), "{err}");
        assert!(is_fifo(&fifo), "still a FIFO");
    }
    let html = d.path().join("page.html");
    assert!(mkfifo(&html));
    let err = refused(&["solve", TRIANGLE, "--html", p(&html), "--force"], "html");
    assert!(err.contains("FIFO"), "{err}");
    assert!(is_fifo(&html));
    let png = d.path().join("c.png");
    assert!(mkfifo(&png));
    let scene = "problems/render/cone-flat.toml";
    refused(&["render", scene, "-o", p(&png), "--force"], "output");
    assert!(is_fifo(&png));
    // A socket likewise.
    let sock = d.path().join("s.svg");
    let _listener = std::os::unix::net::UnixListener::bind(&sock).unwrap();
    let err = refused(
        &[
            "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
        ]
        .iter()
        .copied()
        .chain(["--figure", p(&sock), "--force"])
        .collect::<Vec<_>>(),
        "figure",
    );
    assert!(err.contains("a socket"), "{err}");
}

#[cfg(unix)]
#[test]
fn a_character_device_is_written_directly_and_never_replaced() {
    use std::os::unix::fs::FileTypeExt;
    // /dev/null without --force: written into as `cat > /dev/null` would
    // (a device is not a file grafika replaces, so it needs no --force).
    let out = run(&["solve", TRIANGLE, "--html", "/dev/null"]);
    assert_success(&out);
    let out = run(&[
        "check",
        TRIANGLE,
        "--answers",
        "problems/answers/triangle/",
        "--csv",
        "/dev/null",
    ]);
    assert_success(&out);
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // With --force, on a device of our own (where the system lets us make
    // one): still a device afterwards, and what was written went into it.
    let d = scratch();
    let dev = d.path().join("null");
    let made = std::process::Command::new("mknod")
        .args([p(&dev), "c", "1", "3"])
        .status()
        .is_ok_and(|s| s.success());
    if !made {
        eprintln!("SKIPPED (the --force part): mknod needs privileges here");
        return;
    }
    let scene = "problems/render/cone-flat.toml";
    for args in [
        vec![
            "render",
            scene,
            "-o",
            p(&dev),
            "--force",
            "--width",
            "16",
            "--height",
            "16",
        ],
        vec!["solve", TRIANGLE, "--html", p(&dev), "--force"],
        vec![
            "check",
            TRIANGLE,
            "--answers",
            SITI,
            "--csv",
            p(&dev),
            "--force",
        ],
    ] {
        let out = run(&args);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let m = std::fs::symlink_metadata(&dev).unwrap();
        assert!(m.file_type().is_char_device(), "{args:?}: replaced");
    }
    assert_eq!(names(d.path()), ["null"], "no temporary file left");
}

#[cfg(unix)]
#[test]
fn force_keeps_the_files_mode() {
    use std::os::unix::fs::PermissionsExt;
    let d = scratch();
    let csv = d.path().join("marks.csv");
    std::fs::write(&csv, "old").unwrap();
    std::fs::set_permissions(&csv, std::fs::Permissions::from_mode(0o600)).unwrap();
    let out = run(&[
        "check",
        TRIANGLE,
        "--answers",
        SITI,
        "--csv",
        p(&csv),
        "--force",
    ]);
    assert_success(&out);
    assert!(std::fs::read_to_string(&csv)
        .unwrap()
        .starts_with("student,"));
    let mode = std::fs::metadata(&csv).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600, "600 stays 600 (it was 644 before issue 37)");
    // Not the set-user-ID bit: a replaced file is never made one.
    std::fs::set_permissions(&csv, std::fs::Permissions::from_mode(0o4755)).unwrap();
    assert!(run(&[
        "check",
        TRIANGLE,
        "--answers",
        SITI,
        "--csv",
        p(&csv),
        "--force"
    ])
    .status
    .success());
    let mode = std::fs::metadata(&csv).unwrap().permissions().mode() & 0o7777;
    assert_eq!(mode, 0o755);
}

#[test]
fn the_same_file_given_twice_is_refused_before_anything_is_written() {
    let d = scratch();
    let same = d.path().join("same.csv");
    let dotted = format!("{}/./same.csv", p(d.path()));
    let err = refused(
        &[
            "check",
            TRIANGLE,
            "--answers",
            "problems/answers/triangle/",
            "--csv",
            p(&same),
            "--report",
            &dotted,
        ],
        "report",
    );
    assert!(err.contains("is also the file of --csv"), "{err}");
    assert!(!err.contains("own inputs"), "{err}");
    assert!(names(d.path()).is_empty(), "nothing written");
    // An existing file: the same refusal, not "already exists".
    std::fs::write(&same, "mine").unwrap();
    let err = refused(
        &[
            "check",
            TRIANGLE,
            "--answers",
            "problems/answers/triangle/",
            "--csv",
            p(&same),
            "--report",
            &dotted,
            "--force",
        ],
        "report",
    );
    assert!(err.contains("is also the file of --csv"), "{err}");
    assert_eq!(std::fs::read_to_string(&same).unwrap(), "mine");
    // --html and --figure of a calculator command alike, through a folder
    // and back (`sub/..` names the same file).
    let svg = d.path().join("f.svg");
    std::fs::create_dir(d.path().join("sub")).unwrap();
    let err = refused(
        &[
            "basis",
            "--eye",
            "3,1,3",
            "--look",
            "2,1,2",
            "--up",
            "0,1,0",
            "--figure",
            p(&svg),
        ]
        .iter()
        .copied()
        .chain(["--html", &format!("{}/sub/../f.svg", p(d.path()))])
        .collect::<Vec<_>>(),
        "figure",
    );
    assert!(err.contains("is also the file of --html"), "{err}");
}

#[cfg(unix)]
#[test]
fn only_a_truly_closed_standard_output_is_closed() {
    // Read-write on /dev/null, as Python's subprocess.DEVNULL and
    // `1<>/dev/null` open it: the output is discarded as asked.
    let devnull = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open("/dev/null")
        .unwrap();
    let bin = assert_cmd::cargo::cargo_bin("grafika");
    let out = std::process::Command::new(&bin)
        .current_dir(root())
        .args(["solve", TRIANGLE])
        .stdout(devnull)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let sh = |redirect: &str| {
        let line = format!("exec {} solve {TRIANGLE} {redirect}", bin.display());
        std::process::Command::new("sh")
            .current_dir(root())
            .args(["-c", &line])
            .output()
            .unwrap()
    };
    assert_eq!(sh("1<>/dev/null").status.code(), Some(0));
    // Closed: refused (tests/files.rs checks more commands).
    let out = sh(">&-");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("standard output is closed"));
}

#[cfg(unix)]
#[test]
fn a_closed_standard_input_is_an_error_not_an_empty_file() {
    let bin = assert_cmd::cargo::cargo_bin("grafika");
    let line = format!("exec {} check {TRIANGLE} --answers - <&-", bin.display());
    let out = std::process::Command::new("sh")
        .current_dir(root())
        .args(["-c", &line])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(2),
        "it scored 0/18 with exit 0: {err}"
    );
    assert!(
        err.starts_with("error: answers: standard input is closed"),
        "{err}"
    );
    let line = format!("exec {} solve - <&-", bin.display());
    let out = std::process::Command::new("sh")
        .current_dir(root())
        .args(["-c", &line])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    // An empty standard input is still read (as an empty file).
    let out = grafika()
        .args(["check", TRIANGLE, "--answers", "-"])
        .write_stdin("")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
}

#[cfg(unix)]
#[test]
fn inputs_that_are_not_regular_files_are_refused_without_waiting() {
    let d = scratch();
    let fifo = d.path().join("problem.toml");
    if !mkfifo(&fifo) {
        eprintln!("SKIPPED: mkfifo is not available");
        return;
    }
    // Nobody writes into the FIFO: reading it would wait forever.
    let err = refused(&["solve", p(&fifo)], "file");
    assert!(
        err.contains("is a FIFO (named pipe), not a regular file"),
        "{err}"
    );
    refused(&["check", p(&fifo), "--answers", SITI], "file");
    refused(&["check", TRIANGLE, "--answers", p(&fifo)], "answers");
    refused(
        &["render", p(&fifo), "-o", p(&d.path().join("x.png"))],
        "scene",
    );
    let lights = ["--normal", "0,1,1", "--view", "0,0,1", "--color", "1,1,0"];
    let err = refused(
        &["shade", "--lights", p(&fifo)]
            .iter()
            .copied()
            .chain(lights)
            .collect::<Vec<_>>(),
        "lights",
    );
    assert!(err.contains("FIFO"), "{err}");
    // An OBJ path to a FIFO.
    let mesh = d.path().join("m.obj");
    assert!(mkfifo(&mesh));
    let scene = d.path().join("s.toml");
    std::fs::write(&scene, "[[object]]\ntype = \"obj\"\npath = \"m.obj\"\n").unwrap();
    let err = refused(
        &["render", p(&scene), "-o", p(&d.path().join("x.png"))],
        "object[0].path",
    );
    assert!(err.contains("m.obj is a FIFO"), "{err}");
    // A folder is not a problem file either; standard input still is one.
    let err = refused(&["solve", "problems/"], "file");
    assert!(err.contains("a folder"), "{err}");
    let text = std::fs::read_to_string(root().join(TRIANGLE)).unwrap();
    let out = grafika()
        .args(["solve", "-"])
        .write_stdin(text)
        .output()
        .unwrap();
    assert!(out.status.success());
}

#[test]
fn toml_inputs_are_bounded_before_they_are_read() {
    // More than 1 MB, from a file and from standard input.
    let d = scratch();
    let big = d.path().join("big.toml");
    let text = format!("title = \"t\"\n# {}\n", "x".repeat(1 << 20));
    std::fs::write(&big, &text).unwrap();
    let err = refused(&["solve", p(&big)], "file");
    assert!(err.contains(&format!("has {} bytes", text.len())), "{err}");
    let out = grafika()
        .args(["solve", "-"])
        .write_stdin(text)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("- has more than 1048576 bytes"), "{err}");
    // 100,001 values in one array (200 KB): refused before the TOML reader
    // allocates them (10 million took 2.7 GB).
    let many = format!("title = \"t\"\nx = [{}1]\n", "1,".repeat(100_000));
    let out = grafika()
        .args(["solve", "-"])
        .write_stdin(many)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(err.contains("more than 100000 values"), "{err}");
    // Arrays nested 33 deep.
    let deep = format!("x = {}{}\n", "[".repeat(33), "]".repeat(33));
    let out = grafika()
        .args(["solve", "-"])
        .write_stdin(deep)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("-:1:37") && err.contains("nested more than 32 deep"),
        "{err}"
    );
    // The same bounds for scenes and answer files.
    let scene = d.path().join("s.toml");
    std::fs::write(
        &scene,
        format!("x = {}{}\n", "[".repeat(40), "]".repeat(40)),
    )
    .unwrap();
    refused(
        &["render", p(&scene), "-o", p(&d.path().join("x.png"))],
        "file",
    );
    let answers = d.path().join("a.toml");
    std::fs::write(
        &answers,
        format!("\"view.n\" = [{}1]\n", "1,".repeat(100_000)),
    )
    .unwrap();
    refused(&["check", TRIANGLE, "--answers", p(&answers)], "file");
}

#[test]
fn a_deeply_nested_name_gives_a_page_in_bounded_size() {
    // A point named √(√(…( 20,000 deep (it took 10 GB and overflowed the
    // stack writing --html): the page holds the name, set as text past
    // 16 levels of roots.
    let d = scratch();
    let name = "√(".repeat(20_000);
    let problem = d.path().join("p.toml");
    std::fs::write(
        &problem,
        format!(
            "title = \"t\"\nask = [\"view\"]\n[camera]\neye = [3, 1, 3]\nlook = [2, 1, 2]\n\
             up = [0, 1, 0]\n[points]\n\"{name}\" = [0, 0, 0]\n"
        ),
    )
    .unwrap();
    let html = d.path().join("p.html");
    let out = run(&["solve", p(&problem), "--html", p(&html)]);
    assert_success(&out);
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.len() < 40 * name.len(), "{} bytes", page.len());
}

#[test]
fn a_long_students_name_is_cut_to_80_characters_everywhere() {
    let d = scratch();
    let class = d.path().join("class");
    std::fs::create_dir(&class).unwrap();
    let long = "N".repeat(100_000);
    std::fs::write(
        class.join("a.toml"),
        format!("student = \"{long}\"\n\"window.top\" = \"0.0414\"\n"),
    )
    .unwrap();
    std::fs::write(
        class.join("b.toml"),
        "student = \"Budi\"\n\"window.top\" = \"0.04\"\n",
    )
    .unwrap();
    let shown = format!("{}…", "N".repeat(79));
    let csv = d.path().join("c.csv");
    let report = d.path().join("r.md");
    let out = run(&[
        "check",
        TRIANGLE,
        "--answers",
        p(&class),
        "--csv",
        p(&csv),
        "--report",
        p(&report),
    ]);
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.contains(&shown), "the table");
    assert!(!table.contains(&"N".repeat(81)));
    for file in [&csv, &report] {
        let text = std::fs::read_to_string(file).unwrap();
        assert!(
            text.contains(&shown) && !text.contains(&"N".repeat(81)),
            "{file:?}"
        );
    }
    // The whole output stays small: one row's width, not 100,000 columns
    // on every row (10,000 students took 658 MB).
    assert!(table.len() < 10_000, "{} bytes", table.len());
    let v = json_ok(&["check", TRIANGLE, "--answers", p(&class)]);
    assert_eq!(v["students"][0]["who"], shown.as_str());
}

/// The files of a generate folder with their content, recursively.
fn contents(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for e in walk(dir) {
        if e.is_file() {
            let rel = e.strip_prefix(dir).unwrap().display().to_string();
            out.push((rel, std::fs::read(&e).unwrap()));
        }
    }
    out.sort();
    out
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        if path.is_dir() {
            v.extend(walk(&path));
        }
        v.push(path);
    }
    v
}

fn generate(out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "generate",
        "--topic",
        "view",
        "--count",
        "2",
        "--variants",
        "2",
        "--seed",
        "1",
        "--out",
    ];
    args.push(p(out));
    args.extend(extra);
    run(&args)
}

#[test]
fn a_planted_list_deletes_nothing() {
    let d = scratch();
    let out = d.path().join("exam");
    std::fs::create_dir_all(out.join("grades")).unwrap();
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    std::fs::write(out.join("grades/a.csv"), "marks").unwrap();
    // The list as grafika wrote it before issue 37, planted.
    std::fs::write(out.join(".grafika-generated"), "notes.txt\ngrades/a.csv\n").unwrap();
    let err = refused(
        &["generate", "--topic", "view", "--out", p(&out), "--force"],
        "out",
    );
    assert!(
        err.contains("is not a list that grafika generate wrote"),
        "{err}"
    );
    // In the new format, with the true hashes of the files it names.
    let sha = |b: &[u8]| {
        use sha2::Digest;
        let h = sha2::Sha256::digest(b);
        h.iter().map(|b| format!("{b:02x}")).collect::<String>()
    };
    let planted = format!(
        "grafika-generated 2\n{}  notes.txt\n{}  grades/a.csv\n",
        sha(b"mine"),
        sha(b"marks")
    );
    std::fs::write(out.join(".grafika-generated"), planted).unwrap();
    let err = refused(
        &["generate", "--topic", "view", "--out", p(&out), "--force"],
        "out",
    );
    assert!(
        err.contains("line 2 names notes.txt, which generate never writes"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("notes.txt")).unwrap(),
        "mine"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("grades/a.csv")).unwrap(),
        "marks"
    );
    // A list is never replaced without --force.
    let out2 = d.path().join("exam2");
    assert!(generate(&out2, &[]).status.success());
    let before = contents(&out2);
    let err = refused(&["generate", "--topic", "clip", "--out", p(&out2)], "out");
    assert!(err.contains(".grafika-generated already exists"), "{err}");
    assert_eq!(contents(&out2), before);
}

#[test]
fn generate_lists_each_file_with_its_sha256_and_replaces_only_unchanged_ones() {
    let d = scratch();
    let out = d.path().join("exam");
    assert!(generate(&out, &[]).status.success());
    let list = std::fs::read_to_string(out.join(".grafika-generated")).unwrap();
    assert!(
        list.starts_with("grafika-generated 2 (seed 1, topic view,"),
        "{list}"
    );
    let files: Vec<(String, Vec<u8>)> = contents(&out)
        .into_iter()
        .filter(|(n, _)| n != ".grafika-generated")
        .collect();
    // 2 variants × 6 files, and the blueprint (.md, .json)
    assert_eq!(files.len(), 14);
    for (name, bytes) in &files {
        use sha2::Digest;
        let h: String = sha2::Sha256::digest(bytes)
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        assert!(list.contains(&format!("{h}  {name}\n")), "{name}");
    }
    // The same command writes the same list (the run is its seed, …).
    let again = d.path().join("again");
    assert!(generate(&again, &[]).status.success());
    assert_eq!(contents(&again), contents(&out));
    // A key the lecturer edited is not generate's own any more.
    std::fs::write(out.join("variant-01/key.md"), "edited").unwrap();
    let err = refused(
        &[
            "generate",
            "--topic",
            "view",
            "--count",
            "2",
            "--variants",
            "2",
            "--out",
            p(&out),
            "--force",
        ],
        "out",
    );
    assert!(
        err.contains("has changed since grafika generate wrote it"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("variant-01/key.md")).unwrap(),
        "edited"
    );
}

#[test]
fn one_generate_at_a_time_writes_a_folder() {
    let d = scratch();
    let out = d.path().join("exam");
    std::fs::create_dir(&out).unwrap();
    // Another run holds the folder's lock.
    let lock = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(out.join(".grafika-lock"))
        .unwrap();
    lock.lock().unwrap();
    let err = refused(&["generate", "--topic", "view", "--out", p(&out)], "out");
    assert!(
        err.contains("another grafika generate is writing into"),
        "{err}"
    );
    assert_eq!(names(&out), [".grafika-lock"], "nothing written");
    // Released (as the system does when a run ends, even by SIGKILL): the
    // next run takes the lock, writes, and removes the lock file.
    drop(lock);
    assert!(generate(&out, &[]).status.success());
    assert!(!out.join(".grafika-lock").exists());
    // Runs at once into one folder: each is whole or refused, the list
    // matches the files, and a file of the lecturer's stays.
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let bin = assert_cmd::cargo::cargo_bin("grafika");
    for _ in 0..3 {
        let children: Vec<_> = (1..=3)
            .map(|v| {
                std::process::Command::new(&bin)
                    .current_dir(root())
                    .args(["generate", "--topic", "view", "--count", "2", "--variants"])
                    .arg(v.to_string())
                    .args(["--seed", "1", "--force", "--out", p(&out)])
                    .stdout(std::process::Stdio::null())
                    .stderr(std::process::Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        let outs: Vec<_> = children
            .into_iter()
            .map(|c| c.wait_with_output().unwrap())
            .collect();
        for o in &outs {
            let err = String::from_utf8_lossy(&o.stderr);
            match o.status.code() {
                Some(0) => {}
                Some(2) => assert!(err.contains("another grafika generate"), "{err}"),
                other => panic!("{other:?}: {err}"),
            }
        }
        assert!(outs.iter().any(|o| o.status.success()));
        assert_eq!(
            std::fs::read_to_string(out.join("notes.txt")).unwrap(),
            "mine"
        );
        list_matches_files(&out);
    }
}

/// The folder's list names every file but the lecturer's notes.txt, each
/// with its true SHA-256, and no lock or temporary file is left.
fn list_matches_files(out: &Path) {
    use sha2::Digest;
    let list = std::fs::read_to_string(out.join(".grafika-generated")).unwrap();
    let listed: Vec<(String, String)> = list
        .lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let (h, n) = l.split_once("  ").unwrap();
            (n.to_string(), h.to_string())
        })
        .collect();
    let files: Vec<(String, Vec<u8>)> = contents(out)
        .into_iter()
        .filter(|(n, _)| n != ".grafika-generated" && n != "notes.txt")
        .collect();
    assert_eq!(files.len(), listed.len(), "{list}");
    for (name, bytes) in &files {
        let h: String = sha2::Sha256::digest(bytes)
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        assert!(listed.contains(&(name.clone(), h)), "{name}");
    }
}

/// This process's start time, as `/proc/self/stat` gives it (field 22).
#[cfg(target_os = "linux")]
fn own_start() -> u64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap();
    let rest = &stat[stat.rfind(')').unwrap() + 1..];
    rest.split_whitespace().nth(19).unwrap().parse().unwrap()
}

/// Sets a file's or folder's modification time an hour back.
#[cfg(target_os = "linux")]
fn an_hour_ago(path: &Path) {
    let t = std::time::SystemTime::now() - Duration::from_secs(3600);
    std::fs::File::open(path).unwrap().set_modified(t).unwrap();
}

#[cfg(target_os = "linux")]
#[test]
fn a_temporary_file_left_by_a_stopped_run_is_removed_and_said() {
    let d = scratch();
    // A process that has ended (its number, started at tick 1: no process
    // now running started then).
    let mut gone = std::process::Command::new("true").spawn().unwrap();
    let pid = gone.id();
    gone.wait().unwrap();
    let stale = d.path().join(format!(".grafika-tmp-{pid}-1-abcdef"));
    std::fs::write(&stale, "half a PNG").unwrap();
    an_hour_ago(&stale);
    let stale_dir = d.path().join(format!(".grafika-tmp-{pid}-1-folder"));
    std::fs::create_dir(&stale_dir).unwrap();
    std::fs::write(stale_dir.join("key.md"), "half an exam").unwrap();
    an_hour_ago(&stale_dir);
    // One of a process that runs (this test): kept, however old.
    let live = d.path().join(format!(
        ".grafika-tmp-{}-{}-live",
        std::process::id(),
        own_start()
    ));
    std::fs::write(&live, "being written").unwrap();
    an_hour_ago(&live);
    // One just written by a process this one cannot see (another PID
    // namespace's): kept until it has been left a minute.
    let fresh = d.path().join(format!(".grafika-tmp-{pid}-1-fresh"));
    std::fs::write(&fresh, "being written").unwrap();
    // An older grafika's name, without the process: never taken as stale.
    let old_style = d.path().join(".grafika-tmp-Xy12Ab");
    std::fs::write(&old_style, "?").unwrap();
    an_hour_ago(&old_style);
    let csv = d.path().join("marks.csv");
    let out = run(&["check", TRIANGLE, "--answers", SITI, "--csv", p(&csv)]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    for removed in [&stale, &stale_dir] {
        assert!(!removed.exists(), "{removed:?}");
        let said = format!(
            "warning: removed {}, a temporary file left by grafika process {pid}, which is no longer running",
            removed.display()
        );
        assert!(err.contains(&said), "{err}");
    }
    assert!(live.exists() && fresh.exists() && old_style.exists());
    assert_eq!(err.lines().count(), 2, "{err}");
}
