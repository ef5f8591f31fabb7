//! Helpers shared by the integration tests: run the binary, read its JSON.
#![allow(dead_code)]

pub mod class;

use assert_cmd::Command;
use serde_json::Value;
use std::path::PathBuf;

/// The repository root (where problems/ lives).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// An empty scratch folder `name` under cargo's temporary folder for
/// integration tests (emptied first).
pub fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("creates the directory");
    d
}

/// A command for the grafika binary, run from the repository root.
pub fn grafika() -> Command {
    let mut c = Command::cargo_bin("grafika").expect("binary builds");
    c.current_dir(root());
    c
}

/// Asserts that a run succeeded, with its standard error as the message
/// when it did not.
#[track_caller]
pub fn assert_success(out: &std::process::Output) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
}

/// Runs `cmd` (a [`grafika`] command with its settings) with `args`,
/// expects exit status 2 and one line on stderr; returns stderr as written.
pub fn refusal(mut cmd: Command, args: &[&str]) -> String {
    let out = cmd.args(args).output().expect("runs");
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    let err = String::from_utf8(out.stderr).expect("UTF-8");
    assert_eq!(err.lines().count(), 1, "{args:?}: one line: {err}");
    err
}

/// The output of `grafika --lang LANG ARGS`, expecting success.
pub fn text(lang: &str, args: &[&str]) -> String {
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

/// Runs grafika with `args` plus `--json`, expects success, returns the JSON.
pub fn json_ok(args: &[&str]) -> Value {
    let out = grafika().args(args).arg("--json").output().expect("runs");
    assert!(
        out.status.success(),
        "grafika {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("stdout is one JSON object")
}

/// Runs grafika with `args` plus `--json`, expects exit 2, returns the error object.
pub fn json_err(args: &[&str]) -> Value {
    let out = grafika().args(args).arg("--json").output().expect("runs");
    assert_eq!(
        out.status.code(),
        Some(2),
        "grafika {args:?} should fail with 2; stdout {}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(!out.stderr.is_empty(), "an error message on stderr");
    let v: Value = serde_json::from_slice(&out.stdout).expect("stdout is one JSON object");
    v["error"].clone()
}

/// A number from JSON.
pub fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Asserts |a − b| ≤ tol.
pub fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tolerance {tol})");
}

/// Asserts a JSON array of numbers equals `want` to `tol`.
pub fn close_vec(v: &Value, want: &[f64], tol: f64) {
    let a = v.as_array().unwrap_or_else(|| panic!("not an array: {v}"));
    assert!(a.len() >= want.len(), "{v} shorter than {want:?}");
    for (x, w) in a.iter().zip(want) {
        close(f(x), *w, tol);
    }
}

/// A key file's answers by their dotted keys, in order: `view.points.A`
/// with its value (a string, a number or a list of them).
pub fn key_entries(path: &std::path::Path) -> Vec<(String, toml::Value)> {
    let text = std::fs::read_to_string(path).expect("a key file");
    let t: toml::Table = toml::from_str(&text).expect("a key file's TOML");
    (grafika::tutor::check::named_leaves(&t).into_iter())
        .map(|(name, v)| (name.to_string(), v))
        .collect()
}
