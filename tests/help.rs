//! `--help` of every command says only what the command does: each of the
//! options several commands share (`--precision`, `--digits`, `--json`,
//! `--lang`, `--html`, `--force`) is listed by a command's help exactly when the
//! command takes it, and then it changes what the command prints or
//! writes; an option it does not list is refused (exit status 2, the
//! option named).

mod common;
use common::{grafika, root};
use std::path::{Path, PathBuf};

/// A folder of its own for one run.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("grafika-help-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Each command with a command line that succeeds quickly (`OUT` is a
/// folder of the run) and the text it reads on standard input.
fn commands() -> Vec<(&'static str, Vec<&'static str>, &'static str)> {
    let cam = vec!["--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0"];
    let with = |a: &[&'static str], b: &[&'static str]| [a, b].concat();
    vec![
        ("basis", cam.clone(), ""),
        ("view", with(&cam, &["--point", "A=0,0,0"]), ""),
        (
            "project",
            vec!["--d", "-0.1", "--point", "A=0,-1,-6/sqrt(2)"],
            "",
        ),
        (
            "window",
            vec!["--fovy", "45", "--aspect", "2", "--near", "0.1"],
            "",
        ),
        (
            "clip",
            vec![
                "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
            ],
            "",
        ),
        (
            "shade",
            vec![
                "--light", "0,0,1", "--normal", "0,1,1", "--view", "0,0,1", "--color", "1,1,0",
            ],
            "",
        ),
        ("solve", vec!["problems/text-triangle.toml"], ""),
        (
            "render",
            vec![
                "problems/render/cone-flat.toml",
                "-o",
                "OUT/cone.png",
                "--width",
                "64",
                "--height",
                "48",
                "--explain-pixel",
                "30,20",
            ],
            "",
        ),
        (
            "check",
            vec!["problems/text-triangle.toml", "--answers-from-text"],
            "",
        ),
        (
            "practice",
            vec!["problems/text-triangle.toml"],
            "show\nquit\n",
        ),
        (
            "generate",
            vec!["--topic", "window", "--count", "1", "--out", "OUT/exam"],
            "",
        ),
        ("bench", vec!["--quick", "--cases", "2"], ""),
        ("completions", vec!["bash"], ""),
        ("man", vec![], ""),
    ]
}

/// The long flags `grafika COMMAND --help` lists.
fn listed(command: &str) -> Vec<String> {
    let out = grafika().args([command, "--help"]).output().unwrap();
    assert!(out.status.success(), "{command} --help");
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .filter_map(|l| {
            let l = l
                .trim_start()
                .trim_start_matches("-h, ")
                .trim_start_matches("-o, ");
            let flag = l.strip_prefix("--")?;
            Some(flag.split([' ', '\t']).next()?.to_string())
        })
        .collect()
}

/// What a run printed and wrote: its exit status, standard output, and
/// the files under `out` with their bytes.
#[derive(Debug, PartialEq)]
struct Run {
    status: Option<i32>,
    stdout: String,
    stderr: String,
    files: Vec<(PathBuf, Vec<u8>)>,
}

/// Runs `command args extra` with `OUT` replaced by a fresh folder.
fn run(name: &str, command: &str, args: &[&str], stdin: &str, extra: &[&str]) -> Run {
    run_in(&scratch(name), command, args, stdin, extra)
}

/// Runs `command args extra` with `OUT` replaced by the folder `out`.
fn run_in(out: &Path, command: &str, args: &[&str], stdin: &str, extra: &[&str]) -> Run {
    let mut all = vec![command.to_string()];
    for a in args.iter().chain(extra) {
        all.push(a.replace("OUT", out.to_str().unwrap()));
    }
    let o = grafika()
        .env_remove("GRAFIKA_LANG")
        .env("LANG", "C")
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .args(&all)
        .write_stdin(stdin)
        .output()
        .unwrap();
    let mut files = Vec::new();
    collect(out, out, &mut files);
    files.sort();
    Run {
        status: o.status.code(),
        stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
        files,
    }
}

fn collect(base: &Path, dir: &Path, out: &mut Vec<(PathBuf, Vec<u8>)>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            collect(base, &p, out);
        } else {
            let rel = p.strip_prefix(base).unwrap().to_path_buf();
            out.push((rel, std::fs::read(&p).unwrap()));
        }
    }
}

/// The shared options, each with the value that should change the output
/// (`OUT/page.html`: a new page); `--force` changes it only where the
/// output exists ([`force_matters`]).
const SHARED: [(&str, &[&str]); 6] = [
    ("precision", &["--precision", "f64"]),
    ("digits", &["--digits", "9"]),
    ("json", &["--json"]),
    ("lang", &["--lang", "id"]),
    ("html", &["--html", "OUT/page.html"]),
    ("force", &["--force"]),
];

/// The arguments that make `command` write an output file `--force` may
/// replace (check marks a class into a CSV file).
fn writing<'a>(command: &str, args: &[&'a str]) -> Vec<&'a str> {
    let answers = [
        "problems/text-triangle.toml",
        "--answers",
        "problems/answers/triangle/",
    ];
    match command {
        "render" | "generate" => args.to_vec(),
        "check" => [&answers[..], &["--csv", "OUT/marks.csv"]].concat(),
        _ => [args, &["--html", "OUT/page.html"]].concat(),
    }
}

/// A command that lists `--force`: run twice into one folder, the second
/// run is refused without `--force` (the output exists) and replaces the
/// output with it.
fn force_matters(command: &str, args: &[&str], stdin: &str) {
    let out = scratch(&format!("{command}-force-twice"));
    let args = writing(command, args);
    let first = run_in(&out, command, &args, stdin, &["--lang", "en"]);
    assert_eq!(first.status, Some(0), "{command}: {}", first.stderr);
    let again = run_in(&out, command, &args, stdin, &["--lang", "en"]);
    assert_eq!(
        again.status,
        Some(2),
        "{command} wrote over its output without --force"
    );
    assert!(
        again.stderr.contains("--force"),
        "{command}: {}",
        again.stderr
    );
    let forced = run_in(&out, command, &args, stdin, &["--lang", "en", "--force"]);
    assert_eq!(
        forced.status,
        Some(0),
        "{command} --force: {}",
        forced.stderr
    );
}

#[test]
fn every_command_lists_exactly_the_shared_options_it_takes() {
    assert!(root().join("problems").is_dir());
    for (command, args, stdin) in commands() {
        let flags = listed(command);
        let plain = run(
            &format!("{command}-plain"),
            command,
            &args,
            stdin,
            &["--lang", "en"],
        );
        assert_eq!(plain.status, Some(0), "{command}: {}", plain.stderr);
        for (option, given) in SHARED {
            let tag = format!("{command}-{option}");
            let mut extra = given.to_vec();
            if option != "lang" {
                extra.extend(["--lang", "en"]);
            }
            let with = run(&tag, command, &args, stdin, &extra);
            if flags.iter().any(|f| f == option) {
                assert_eq!(
                    with.status,
                    Some(0),
                    "{command} lists --{option} but refuses it: {}",
                    with.stderr
                );
                if option == "force" {
                    force_matters(command, &args, stdin);
                    continue;
                }
                // --lang of completions and man changes only their errors.
                let words = matches!(command, "completions" | "man") && option == "lang";
                assert!(
                    words || with != plain,
                    "{command} lists --{option}, which changes nothing it prints or writes"
                );
            } else {
                assert_eq!(
                    with.status,
                    Some(2),
                    "{command} takes --{option} without listing it"
                );
                // named as clap names it, or as a shared option the command
                // does not take (`error: precision: grafika check does not take …`)
                assert!(
                    with.stderr.contains(&format!("--{option}"))
                        || with.stderr.starts_with(&format!("error: {option}: ")),
                    "{command} --{option}: {}",
                    with.stderr
                );
            }
        }
    }
}

#[test]
fn an_option_before_a_command_that_does_not_take_it_is_refused() {
    // check marks answers: it has no precision of its own.
    let out = grafika()
        .args(["--precision", "f64", "check", "problems/text-camera.toml"])
        .args(["--answers-from-text", "--lang", "en"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.starts_with("error: precision: grafika check does not take"),
        "{err}"
    );
    // ... and one it takes is used there as after the command.
    let before = grafika()
        .args(["--lang", "id", "--digits", "8", "basis"])
        .args(["--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0"])
        .output()
        .unwrap();
    let after = grafika()
        .args([
            "basis", "--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0",
        ])
        .args(["--lang", "id", "--digits", "8"])
        .output()
        .unwrap();
    assert!(before.status.success());
    assert_eq!(before.stdout, after.stdout);
    assert!(String::from_utf8_lossy(&after.stdout).contains("0,70710678"));
}

#[test]
fn practice_help_says_it_prints_json_lines() {
    let out = grafika().args(["practice", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(help.contains("JSON Lines"), "{help}");
    assert!(!help.contains("--html"), "{help}");
}

/// A shared option after a command that does not take it is refused as
/// before the command (clap's own line told a student to write
/// `-- --html`, as if the option were a value).
#[test]
fn an_option_after_a_command_that_does_not_take_it_is_refused_by_name() {
    for (args, field, words) in [
        (
            vec![
                "check",
                "problems/text-triangle.toml",
                "--answers-from-text",
                "--html",
                "x.html",
            ],
            "html",
            "for exams use generate --format html",
        ),
        (
            vec!["practice", "problems/text-triangle.toml", "--force"],
            "force",
            "grafika practice does not take",
        ),
    ] {
        let out = grafika()
            .args(&args)
            .args(["--lang", "en"])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with(&format!("error: {field}: ")), "{err}");
        assert!(err.contains(words) && !err.contains("-- --"), "{err}");
    }
}
