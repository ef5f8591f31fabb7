//! The worked solution reads like the text: over every shipped problem,
//! in both languages, exact forms where they help (never a number of more
//! than 8 digits in a fraction, never an empty exact form `= ≈`).

mod common;
use common::{grafika, json_ok, root};

/// The shipped problem files.
fn problems() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(root().join("problems"))
        .expect("problems/")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    v.sort();
    assert!(v.len() >= 20, "{v:?}");
    v
}

/// `grafika --lang LANG solve FILE`, expecting success.
fn solved(lang: &str, file: &str) -> String {
    let out = grafika()
        .args(["--lang", lang, "solve", file])
        .output()
        .expect("runs");
    assert!(out.status.success(), "{file}");
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The longest run of digits in a line that is not a decimal (digits
/// after a decimal mark are a decimal's, not a fraction's).
fn longest_integer(line: &str) -> usize {
    let chars: Vec<char> = line.chars().collect();
    let mut best = 0;
    let mut i = 0;
    while i < chars.len() {
        if chars[i].is_ascii_digit() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            let after_mark = start > 0 && matches!(chars[start - 1], '.' | ',');
            let before_mark = matches!(chars.get(i), Some('.' | ','))
                && chars.get(i + 1).is_some_and(|c| c.is_ascii_digit());
            if !after_mark && !before_mark {
                best = best.max(i - start);
            }
        } else {
            i += 1;
        }
    }
    best
}

#[test]
fn exact_forms_help_and_are_never_empty() {
    for file in problems() {
        for lang in ["en", "id"] {
            for line in solved(lang, &file).lines() {
                assert!(!line.contains("= ≈"), "{file} ({lang}): {line}");
                // A year or a long integer may stand alone; a fraction of
                // such numbers is shown as its decimal.
                if line.contains('/') && !line.contains("sqrt") {
                    assert!(longest_integer(line) <= 8, "{file} ({lang}): {line}");
                }
            }
        }
    }
    // Direct3D's local viewer (problems/shade-blinn-local.toml): V = (−3, 0, 4)/5,
    // V + L = (−3/5, 0, 9/5), |V + L| = √(18/5), N·H = (9/5)/√(18/5) = 3/√10,
    // (N·H)^20 = 0.9^10 = 0.3486784401, specular = ½·0.9^10 = 3486784401/20000000000
    // ≈ 0.1743: the decimal is shown, the exact form stays in the JSON.
    let t = solved("en", "problems/shade-blinn-local.toml");
    assert!(t.contains("specular ≈ (0.1743, 0.1743, 0.1743)"), "{t}");
    let v = json_ok(&["solve", "problems/shade-blinn-local.toml"]);
    assert_eq!(v["exact"]["shade"]["specular"][0], "3486784401/20000000000");
}
