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

/// The steps of `solve FILE --json`.
fn steps(file: &str) -> Vec<serde_json::Value> {
    let v = json_ok(&["solve", file]);
    v["steps"].as_array().expect("steps").clone()
}

/// Whether a formula has a letter (it is more than a number).
fn has_letters(f: &str) -> bool {
    f.chars().any(char::is_alphabetic)
}

/// Whether a result named `name` is worked from a formula whose numbers a
/// student substitutes: clip's P(t), the dot products (cos α, cos β, N·H),
/// the camera axes, the projected points, the window's edges and size, the
/// unit vectors, the attenuation, the highlight and the lighting terms.
fn worked_result(name: &str) -> bool {
    let names = [
        "P(t)",
        "n",
        "u",
        "v",
        "L",
        "H",
        "R",
        "d",
        "Att",
        "cos α",
        "cos β",
        "N·H",
        "top",
        "right",
        "bottom",
        "left",
        "height",
        "width",
        "highlight",
        "ambient",
        "diffuse",
        "specular",
        "max(cos α, 0)",
    ];
    names.contains(&name) || name.ends_with("''")
}

/// Whether a value named `name` is itself worked out in its step (not an
/// input repeated from an earlier step): clip's t, every norm |…|, the
/// differences and dot products, the pixel coordinates, d/z, the sums over
/// the lights.
fn worked_value(name: &str) -> bool {
    let names = [
        "t",
        "px",
        "py",
        "d/z",
        "ρ",
        "2(L·N)",
        "V + L",
        "Pl − P",
        "Pe − Pr",
        "Vup × n",
        "fovy/2 (degrees)",
        "tan(fovy/2)",
        "a0 + a1·d + a2·d²",
    ];
    names.contains(&name)
        || (name.starts_with('|') && name.ends_with('|'))
        || name.ends_with(" − Pe)")
        || name.ends_with(" − Pe")
        || name.starts_with("Σ ")
        || name.starts_with("Ga + Σ")
}

#[test]
fn every_step_substitutes_its_values_before_its_result() {
    let mut worked = 0;
    for file in problems() {
        for s in steps(&file) {
            let title = s["title"].as_str().unwrap_or_default();
            let formula = s["formula"].as_str().unwrap_or_default();
            let values = s["values"].as_object().expect("values");
            let result = s["result"].as_object().expect("result");
            // A formula with letters is followed by its values, not at
            // once by the result.
            assert!(
                !(has_letters(formula) && values.is_empty() && !result.is_empty()),
                "{file}: step \"{title}\" ({formula}) goes straight to its result"
            );
            let subs = s.get("substituted").and_then(|x| x.as_object());
            let worked_here = values
                .iter()
                .filter(|(n, _)| worked_value(n))
                .chain(result.iter().filter(|(n, _)| worked_result(n)));
            for (name, value) in worked_here {
                // A value given (a unit vector, a zero term of a model
                // without it, a spot factor decided by its cone, a
                // vector divided by its norm 1) has nothing to substitute.
                let norm_one = values
                    .iter()
                    .any(|(n, v)| n.starts_with('|') && v.as_f64() == Some(1.0));
                let given = value.as_f64() == Some(0.0)
                    || value
                        .as_array()
                        .is_some_and(|a| a.iter().all(|x| x.as_f64() == Some(0.0)))
                    || (name == "Spot" && matches!(value.as_f64(), Some(x) if x == 1.0))
                    || s["note"]
                        .as_str()
                        .is_some_and(|n| n.contains("already a unit vector"))
                    || (norm_one && ["u", "n", "L", "N", "V", "H"].contains(&name.as_str()))
                    || formula.is_empty();
                if !given {
                    let sub = subs.and_then(|m| m.get(name));
                    assert!(
                        sub.is_some(),
                        "{file}: \"{title}\": {name} is not substituted"
                    );
                    worked += 1;
                }
            }
        }
    }
    assert!(worked > 300, "{worked} substitutions");
}

/// Whether a JSON value is a number (not a yes/no).
fn is_number(v: &serde_json::Value) -> bool {
    v.is_number()
}

/// Whether a JSON value is a number or a list of numbers (a vector, a
/// colour, a point), not a matrix.
fn is_numeric(v: &serde_json::Value) -> bool {
    is_number(v) || v.as_array().is_some_and(|a| a.iter().all(is_number))
}

/// Whether a value is zero (a term a model does not have, a spot factor
/// outside its cone: decided, not computed).
fn is_zero(v: &serde_json::Value) -> bool {
    v.as_f64() == Some(0.0)
        || v.as_array()
            .is_some_and(|a| a.iter().all(|x| x.as_f64() == Some(0.0)))
}

/// Why a step with a formula shows a result (or a product) without the
/// line of its numbers, or `None` when every one is worked: each numeric
/// result (not a matrix) is substituted unless it is one of the step's
/// values (or made of their components), a value shown in an earlier
/// step (a point chosen, not computed), or zero; each product named with
/// `·` or `×` (u·v, Vup × n, −u·Pe) is substituted unless shown earlier;
/// a yes/no decided on numbers (inside, contributes) shows the
/// comparison; and a cross product is worked by its components, never
/// left as `a × b`.
fn unworked(s: &serde_json::Value, earlier: &[serde_json::Value]) -> Option<String> {
    let formula = s["formula"].as_str().unwrap_or_default();
    if formula.trim().is_empty() {
        return None;
    }
    let values = s["values"].as_object().expect("values");
    let result = s["result"].as_object().expect("result");
    let empty = serde_json::Map::new();
    let subs = s["substituted"].as_object().unwrap_or(&empty);
    let seen = |v: &serde_json::Value| earlier.contains(v);
    let sizes = ["W × H", "width × height"];
    for (name, v) in values.iter().chain(result) {
        let product = (name.contains('·') || name.contains('×')) && !sizes.contains(&name.as_str());
        if product && is_numeric(v) && !subs.contains_key(name) && !seen(v) {
            return Some(format!("the product {name} has no line of numbers"));
        }
    }
    let components: Vec<&serde_json::Value> = values
        .values()
        .flat_map(|v| match v.as_array() {
            Some(a) => a.iter().collect(),
            None => vec![v],
        })
        .filter(|v| is_number(v))
        .collect();
    for (name, v) in result {
        if subs.contains_key(name) {
            continue;
        }
        if v.is_boolean() {
            if values.values().any(is_numeric) {
                return Some(format!(
                    "{name} is decided with no comparison of its numbers"
                ));
            }
            continue;
        }
        let copied = values.values().any(|x| x == v)
            || v.as_array()
                .is_some_and(|a| a.iter().all(|x| components.contains(&x)));
        if is_numeric(v) && !copied && !seen(v) && !is_zero(v) {
            return Some(format!("{name} has no line of substituted numbers"));
        }
    }
    subs.iter()
        .find(|(_, sub)| sub.as_str().is_some_and(|t| t.contains(" × ")))
        .map(|(name, _)| format!("{name} is a cross product not worked by its components"))
}

/// Every step of every shipped problem (and of the calculator's set-ups
/// no problem file asks: the orthographic projection, Blinn–Phong with a
/// local viewer and a clamp) that has a formula and a result shows the
/// line of its numbers: the orthonormality check, the sums of the terms,
/// Liang–Barsky, the cross products by their components, the clamp.
#[test]
fn every_step_with_a_formula_shows_its_numbers() {
    let mut runs: Vec<Vec<String>> = problems()
        .into_iter()
        .map(|f| vec!["solve".to_string(), f])
        .collect();
    for extra in [
        "project --ortho --point A=1,2,-3",
        "shade --model blinn --light 1,0,1 --normal 0,0,1 --color 1,0,0 --camera -3,0,4 --position 0,0,0",
        "window --fovy 45 --aspect 2 --near 0.1 --far 10 --viewport 200x100 --point A=0,-0.02",
    ] {
        runs.push(extra.split(' ').map(String::from).collect());
    }
    let mut checked = 0;
    for args in runs {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let v = json_ok(&args);
        let mut earlier = Vec::new();
        for s in v["steps"].as_array().expect("steps") {
            if let Some(why) = unworked(s, &earlier) {
                panic!("{args:?}: step \"{}\": {why}\n{s:#}", s["title"]);
            }
            checked += 1;
            for part in ["values", "result"] {
                earlier.extend(s[part].as_object().expect("map").values().cloned());
            }
        }
    }
    assert!(checked > 300, "{checked} steps");
}

#[test]
fn the_texts_examples_substitute_as_a_tutor_writes_them() {
    // Clipping P0(4, 2, 2)–P1(−2, 6, 1) at x = xmin = 0:
    // t = (0 − 4)/(−2 − 4) = 2/3, P(t) = P0 + t·(P1 − P0).
    let clip = solved("id", "problems/text-clip.toml");
    for line in [
        "    t = (0 − 4)/(−2 − 4) = 2/3 ≈ 0,6667",
        "  ⇒ P(t) = (4; 2; 2) + (2/3)·(−6; 4; −1) = (0; 14/3; 4/3) ≈ (0; 4,667; 1,333)",
        "    t = (4 − 2)/(6 − 2) = 1/2 = 0,5",
    ] {
        assert!(clip.contains(line), "{line}\n{clip}");
    }
    // Contoh 6.1: Pe − Pr = (4, 3, 0), |Pe − Pr| = √(16 + 9 + 0) = 5.
    let camera = solved("en", "problems/text-camera.toml");
    for line in [
        "    Pe − Pr = (4 − 0, 4 − 1, 4 − 4) = (4, 3, 0)",
        "    |Pe − Pr| = √(4² + 3² + 0²) = 5",
        "  ⇒ n = (4, 3, 0)/5 = (4/5, 3/5, 0) = (0.8, 0.6, 0)",
    ] {
        assert!(camera.contains(line), "{line}\n{camera}");
    }
    // The text's Phong model: ka·Cs = 0.4·(1, 1, 0); kd·max(cos α, 0)·Cs
    // with cos α = L·N = 1·√2/2.
    let phong = solved("id", "problems/shade-phong.toml");
    for line in [
        "  ⇒ cos α = 0·0 + 0·√2/2 + 1·√2/2 = √2/2 ≈ 0,7071",
        // the text's own model, in its notation: Ia = Is·ka on Cs, no Direct3D sums
        "    ambient = ka·Cs",
        "  ⇒ ambient = 0,4·(1; 1; 0) = (2/5; 2/5; 0) = (0,4; 0,4; 0)",
        "  ⇒ diffuse = 0,6·(√2/2)·(1; 1; 0) = (3√2/10; 3√2/10; 0) ≈ (0,4243; 0,4243; 0)",
        "    C = Cs·(kd·max(cos α, 0) + ka) + Cwhite·ks·max(cos β, 0)ⁿ = ambient + diffuse + specular",
        // the sum, substituted: 2/5 + 3√2/10 = (4+3√2)/10
        "  ⇒ sebelum dibatasi = (0,4; 0,4; 0) + (3√2/10; 3√2/10; 0) + (0; 0; 0) = ((4+3√2)/10; (4+3√2)/10; 0) ≈ (0,8243; 0,8243; 0)",
    ] {
        assert!(phong.contains(line), "{line}\n{phong}");
    }
    assert!(
        !phong.contains("Ga + Σ") && !phong.contains("emissive"),
        "{phong}"
    );
    // Contoh 6.1's basis checked by its numbers: u = (0, 0, −1), v = (−3/5, 4/5, 0).
    for line in [
        // (a short decimal is written where it is exact: 0.6 for 3/5)
        "    u·v = 0·(−0.6) + 0·0.8 + (−1)·0 = 0",
        "    u × v = (0·0 − (−1)·0.8, (−1)·(−0.6) − 0·0, 0·0.8 − 0·(−0.6)) = (4/5, 3/5, 0) = (0.8, 0.6, 0)",
        "  ⇒ (u × v)·n = 0.8·0.8 + 0.6·0.6 + 0·0 = 1",
        // Vup × n with Vup = (0, 1, 0), n = (4/5, 3/5, 0): (1·0 − 0·3/5, 0·4/5 − 0·0, 0·3/5 − 1·4/5)
        "    Vup × n = (1·0 − 0·0.6, 0·0.8 − 0·0, 0·0.6 − 1·0.8) = (0, 0, −4/5) = (0, 0, −0.8)",
    ] {
        assert!(camera.contains(line), "{line}\n{camera}");
    }
    // Liang–Barsky on P0(4, 2, 2)–P1(−2, 6, 1), Δ = (−6, 4, −1): at x = xmax,
    // p = Δx = −6, q = 3 − 4 = −1 (entering, t = 1/6); at y = ymax, p = 4,
    // q = 4 − 2 = 2 (leaving, t = 1/2).
    let clip_en = solved("en", "problems/text-clip.toml");
    for line in [
        "    Δ = P1 − P0 = (−2 − 4, 6 − 2, 1 − 2) = (−6, 4, −1)",
        "    p, q (x = xmax) = (−6, 3 − 4) = (−6, −1)",
        "    p, q (y = ymax) = (4, 4 − 2) = (4, 2)",
        "    t0 = max(0, −1/(−6), 2/(−4), 1/(−1)) = 1/6 ≈ 0.1667",
        "    t1 = min(1, 4/6, 2/4, 2/1) = 1/2 = 0.5",
        "  ⇒ from = (4, 2, 2) + (1/6)·(−6, 4, −1) = (3, 8/3, 11/6) ≈ (3, 2.667, 1.833)",
        "  ⇒ code0 AND code1 = 000010 AND 001001 = 000000",
    ] {
        assert!(clip_en.contains(line), "{line}\n{clip_en}");
    }
    // Blinn without a local viewer: V + L = (√2/2, 0, 1 + √2/2),
    // |V + L|² = 1/2 + 3/2 + √2 = 2 + √2, which has no square root in surds.
    let blinn = solved("en", "problems/shade-blinn.toml");
    for line in [
        "    |V + L| = √((√2/2)² + 0² + ((2+√2)/2)²) = √(2+√2) ≈ 1.848",
        "  ⇒ H = (√2/2, 0, (2+√2)/2)/√(2+√2) ≈ (0.3827, 0, 0.9239)",
    ] {
        assert!(blinn.contains(line), "{line}\n{blinn}");
    }
    // The window: top = 0.1·tan 22.5° = 0.1·(√2 − 1); right = 2·top.
    let tri = solved("en", "problems/text-triangle.toml");
    for line in [
        "    tan(fovy/2) = tan(22.5°) = √2−1 ≈ 0.4142",
        "  ⇒ top = 0.1·(√2−1) = (√2−1)/10 ≈ 0.04142",
        "  ⇒ right = 2·(√2−1)/10 = (√2−1)/5 ≈ 0.08284",
    ] {
        assert!(tri.contains(line), "{line}\n{tri}");
    }
}
