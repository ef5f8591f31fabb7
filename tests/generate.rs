//! `grafika generate`: reproducible exams whose problems solve, whose keys
//! score full marks, and in which a planted mistake is caught and named.

mod common;
use common::*;
use grafika::stages::trace::Val;
use grafika::tutor::check::{self, Settings, Verdict};
use grafika::tutor::diagnose::Code;
use grafika::tutor::generate::{self, answer_toml, Difficulty, Topic};
use grafika::tutor::key::{Key, Part};
use std::path::{Path, PathBuf};

const TOPICS: [Topic; 7] = Topic::ALL;
const LEVELS: [Difficulty; 3] = Difficulty::ALL;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("grafika-gen-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().display().to_string();
                out.push((rel, std::fs::read(&p).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn the_same_seed_gives_the_same_files_byte_for_byte() {
    let (a, b, c) = (tmp("a"), tmp("b"), tmp("c"));
    for (dir, seed) in [(&a, "42"), (&b, "42"), (&c, "43")] {
        grafika()
            .args([
                "generate",
                "--topic",
                "pipeline",
                "--count",
                "2",
                "--variants",
                "2",
            ])
            .args([
                "--seed",
                seed,
                "--format",
                "md",
                "--out",
                dir.to_str().unwrap(),
            ])
            .assert()
            .success();
    }
    let (fa, fb, fc) = (files(&a), files(&b), files(&c));
    // 2 variants × (2 problems + 2 keys + questions + key), the blueprint
    // (.md, .json) and the list of generate's own files (.grafika-generated)
    assert_eq!(fa.len(), 15);
    assert_eq!(fa, fb);
    assert_ne!(fa, fc);
    // the variants differ from each other
    let v1 = &fa
        .iter()
        .find(|(n, _)| n.ends_with("variant-01/problem-01.toml"))
        .unwrap()
        .1;
    let v2 = &fa
        .iter()
        .find(|(n, _)| n.ends_with("variant-02/problem-01.toml"))
        .unwrap()
        .1;
    assert_ne!(v1, v2);
}

#[test]
fn every_generated_problem_solves_and_its_key_scores_full_marks() {
    for topic in TOPICS {
        for level in LEVELS {
            let exam = generate::exam(&[topic], level, 3, 9).expect("generates");
            for g in &exam {
                let answers: Vec<(check::Name, toml::Value)> = g
                    .keys
                    .iter()
                    .map(|k| {
                        (
                            check::Name::parse(&k.to_string()),
                            answer_toml(&g.report.result.get(k).unwrap()),
                        )
                    })
                    .collect();
                assert!(!answers.is_empty());
                let m =
                    check::mark(&g.problem, "key", &answers, Settings::default(), false).unwrap();
                assert_eq!(
                    m.score(),
                    m.total() as f64,
                    "{topic:?} {level:?}: {}\n{:?}",
                    g.body,
                    m.answers
                        .iter()
                        .filter(|a| !a.verdict.is_correct())
                        .collect::<Vec<_>>()
                );
            }
        }
    }
}

#[test]
fn a_planted_mistake_is_caught_and_named() {
    let mut planted = std::collections::BTreeSet::new();
    for topic in [Topic::View, Topic::Pipeline, Topic::Clip, Topic::Shade] {
        for level in LEVELS {
            // `--clip mixed`: the clipping mistakes of every status
            let mixed = generate::ClipCase::Mixed;
            for g in drawn(&[topic], level, (3, 1), 5, mixed).remove(0) {
                let keys: Vec<String> = g.keys.iter().map(Key::to_string).collect();
                for m in Code::all() {
                    if plant(m, &g.problem, &keys, &g.report.result, &g.body) {
                        planted.insert(m.as_str());
                    }
                }
            }
        }
    }
    // The shipped problems too: the text's misprints (a generated problem
    // has no errata), the spot lights (generated lighting problems have
    // none) and a specular term that max(0, cos β) clamps (a generated
    // problem's specular term shows, so cos β > 0) show the mistakes no
    // generated problem can.
    let mut shipped: Vec<PathBuf> = std::fs::read_dir(root().join("problems"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    shipped.sort();
    for path in shipped {
        let p = grafika::input::problem::ProblemIn::read(&path).unwrap();
        let marker = check::Marker::new(&p, Settings::default()).unwrap();
        let keys: Vec<String> = marker.order.iter().map(Key::to_string).collect();
        let name = path.display().to_string();
        for m in Code::all() {
            if plant(m, &p, &keys, &marker.result, &name) {
                planted.insert(m.as_str());
            }
        }
    }
    // Every mistake of the catalog was planted somewhere, and caught, but
    // leaving out max(0, cos β): a generated problem's specular term shows
    // (cos β > 0, so the max changes nothing), and no shipped problem asks
    // a specular term with cos β < 0.
    let not_planted = ["specular_no_max"];
    for code in Code::all() {
        let code = code.as_str();
        let can = !not_planted.contains(&code);
        assert_eq!(planted.contains(code), can, "{code}: planted {planted:?}");
    }
}

/// Plants mistake `m` in a sheet of the problem's `keys` (the view matrix
/// too, when the mistake changes it): its first variant's value wherever
/// it differs from the right one, the right value elsewhere. Asserts that
/// `check` marks some answer wrong and names `m` for every wrong one;
/// false when the mistake does not apply or changes no answer.
fn plant(
    m: Code,
    p: &grafika::input::problem::ProblemIn,
    keys: &[String],
    right: &check::Results,
    what: &str,
) -> bool {
    let Some(variants) = m.apply(p) else {
        return false;
    };
    let mut keys = keys.to_vec();
    keys.push("view.matrix".into());
    let tree = &variants[0];
    let mut answers = Vec::new();
    let mut changed = 0;
    for k in &keys {
        let (Some(right), Some(wrong)) = (
            right.lookup(k).map(|v| v.into_owned()),
            tree.lookup(k).map(|v| v.into_owned()),
        ) else {
            continue;
        };
        if differs(&right, &wrong) {
            changed += 1;
            answers.push((check::Name::parse(k), answer_toml(&wrong)));
        } else if k != "view.matrix" {
            answers.push((check::Name::parse(k), answer_toml(&right)));
        }
    }
    if changed == 0 {
        return false;
    }
    let mk = check::mark(p, "planted", &answers, Settings::default(), false).unwrap();
    let wrong: Vec<_> = mk
        .answers
        .iter()
        .filter(|a| a.verdict == Verdict::Wrong)
        .collect();
    assert!(!wrong.is_empty(), "{m} not caught in {what}");
    for a in &wrong {
        assert!(
            a.diagnosis.contains(&m),
            "{m}: {} diagnosed as {:?} in\n{what}",
            a.key,
            a.diagnosis
        );
    }
    true
}

/// The numbers of a value (of a list or a map, in order).
fn leaves(v: &Val) -> Vec<f64> {
    match v {
        Val::Num(x) => vec![x.value],
        Val::List(items) => items.iter().flat_map(leaves).collect(),
        Val::Map(kv) => kv.iter().flat_map(|(_, x)| leaves(x)).collect(),
        _ => vec![],
    }
}

/// The value with its numbers left out: its shape, words and yes or no.
fn shape(v: &Val) -> String {
    match v {
        Val::Num(_) => "#".into(),
        Val::List(items) => format!(
            "[{}]",
            items.iter().map(shape).collect::<Vec<_>>().join(",")
        ),
        Val::Map(kv) => format!(
            "{{{}}}",
            kv.iter()
                .map(|(k, x)| format!("{k}:{}", shape(x)))
                .collect::<Vec<_>>()
                .join(",")
        ),
        other => format!("{other:?}"),
    }
}

/// Whether a mistaken value can be told from the right one at the default
/// tolerance (0.1 %, a zero by its answer's largest magnitude): what a
/// marker can see. Other values are planted, and differ, as right ones.
fn differs(a: &Val, b: &Val) -> bool {
    let (x, y) = (leaves(a), leaves(b));
    if shape(a) != shape(b) {
        return true;
    }
    let scale = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let t = |x: f64, s: f64| check::tolerance::absolute(x, s, 1e-3);
    let (sx, sy) = (scale(&x), scale(&y));
    x.iter()
        .zip(&y)
        .any(|(p, q)| check::tolerance::apart(*p, t(*p, sx), *q, t(*q, sy)))
}

/// The problems of every variant of an exam, `[variant][position]`.
fn drawn(
    topics: &[Topic],
    level: Difficulty,
    (count, variants): (u32, u32),
    seed: u64,
    clip: generate::ClipCase,
) -> Vec<Vec<generate::Generated>> {
    let spec = generate::Spec {
        topics: topics.to_vec(),
        difficulty: level,
        count,
        variants,
        seed,
        clip,
    };
    generate::exams(&spec, &mut |_| {})
        .expect("generates")
        .variants
}

#[test]
fn clipping_covers_accept_reject_and_partial_at_every_level() {
    // `--clip mixed`: three clipping problems take the three statuses.
    for level in LEVELS {
        let exam = drawn(&[Topic::Clip], level, (3, 1), 1, generate::ClipCase::Mixed).remove(0);
        let mut statuses = clip_statuses(&exam);
        statuses.sort();
        assert_eq!(statuses, ["accepted", "clipped", "rejected"], "{level:?}");
        for g in &exam {
            // no endpoint on a box plane, so no segment lies in one
            let c = g.problem.clip.as_ref().unwrap();
            let min: Vec<f64> = c.min.iter().map(|n| n.0.eval::<f64>().unwrap()).collect();
            let max: Vec<f64> = c.max.iter().map(|n| n.0.eval::<f64>().unwrap()).collect();
            for s in &c.segment {
                for end in [&s.from, &s.to] {
                    let grafika::input::problem::PointRef::At(p) = end else {
                        panic!()
                    };
                    for k in 0..3 {
                        let x = p[k].0.eval::<f64>().unwrap();
                        assert!(x != min[k] && x != max[k], "{}", g.body);
                    }
                }
            }
        }
    }
}

#[test]
fn easy_cameras_have_rational_axes() {
    // Pythagorean directions: |Pe − Pr| and |Vup × (Pe − Pr)| are integers,
    // so n, u, v are rational — their exact forms have no square root.
    for g in generate::exam(&[Topic::Basis], Difficulty::Easy, 6, 3).unwrap() {
        for k in ["view.u", "view.v", "view.n"] {
            let Some(Val::List(c)) = g.report.result.lookup(k).map(|v| v.into_owned()) else {
                panic!()
            };
            for x in c {
                let Val::Num(s) = x else { panic!() };
                let e = s.exact.as_deref().unwrap_or("?");
                assert!(!e.contains("sqrt") && e != "?", "{k} = {e} in {}", g.body);
            }
        }
    }
}

#[test]
fn latex_keys_are_ascii() {
    // Every topic in both languages: the shading steps carry Σ and (N·H)ⁿ.
    let all = "basis,view,project,window,clip,shade,pipeline";
    for lang in ["en", "id"] {
        let dir = tmp(&format!("tex-{lang}"));
        grafika()
            .args(["generate", "--topic", all, "--count", "7", "--seed", "3"])
            .args(["--lang", lang, "--format", "latex"])
            .args(["--out", dir.to_str().unwrap()])
            .assert()
            .success();
        for f in ["questions.tex", "key.tex"] {
            let t = std::fs::read_to_string(dir.join(f)).unwrap();
            assert!(t.is_ascii(), "{lang} {f} has non-ASCII characters");
            assert!(!t.contains("[U+"), "{lang} {f} has an unmapped symbol");
        }
    }
    let dir = tmp("tex");
    grafika()
        .args([
            "generate", "--topic", "pipeline", "--count", "2", "--seed", "3",
        ])
        .args(["--format", "latex", "--out", dir.to_str().unwrap()])
        .assert()
        .success();
    let key = std::fs::read_to_string(dir.join("key.tex")).unwrap();
    assert!(key.contains("\\sqrt{"), "exact forms are set with \\sqrt");
    // tests/tools.rs compiles a key with pdflatex (or says it was skipped).
}

#[test]
fn json_and_toml_formats() {
    let dir = tmp("json");
    let v = json_ok(&[
        "generate",
        "--topic",
        "window",
        "--count",
        "2",
        "--seed",
        "8",
        "--format",
        "json",
        "--out",
        dir.to_str().unwrap(),
    ]);
    // 2 problems, 2 keys, exam.json, blueprint.md and blueprint.json
    assert_eq!(v["files"].as_array().unwrap().len(), 7);
    let exam: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("exam.json")).unwrap()).unwrap();
    let p = &exam["problems"][0];
    // The window's height is twice its top, whatever the numbers drawn.
    let top = f(&p["answers"]["window.top"]["decimal"]);
    close(
        f(&p["answers"]["window.height"]["decimal"]),
        2.0 * top,
        1e-12,
    );
    assert!(p["solution"]["steps"].as_array().unwrap().len() >= 2);
    // a count of 0 is refused on the command line
    let e = json_err(&[
        "generate",
        "--topic",
        "view",
        "--count",
        "0",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(e["field"].as_str().unwrap().contains("count"), "{e}");
}

#[test]
fn several_topics_alternate_through_the_exam() {
    let mixed = generate::ClipCase::Mixed;
    let exam = drawn(
        &[Topic::View, Topic::Clip],
        Difficulty::Medium,
        (4, 1),
        2,
        mixed,
    )
    .remove(0);
    let kinds: Vec<bool> = exam.iter().map(|g| g.problem.clip.is_some()).collect();
    assert_eq!(kinds, [false, true, false, true]);
    // `--clip mixed`: the two clipping problems have two different statuses
    let st = clip_statuses(&exam);
    assert_eq!(st.len(), 2);
    assert_ne!(st[0], st[1]);
    let dir = tmp("mixed");
    grafika()
        .args([
            "generate",
            "--topic",
            "view,clip,shade",
            "--count",
            "3",
            "--format",
            "md",
        ])
        .args(["--out", dir.to_str().unwrap()])
        .assert()
        .success();
    let q = std::fs::read_to_string(dir.join("questions.md")).unwrap();
    assert!(
        q.contains("Problem 2: Line clipping") && q.contains("Problem 3: Lighting"),
        "{q}"
    );
}

#[test]
fn generate_refuses_huge_outputs_without_force() {
    let dir = tmp("huge");
    let e = json_err(&[
        "generate",
        "--topic",
        "view",
        "--count",
        "500",
        "--variants",
        "500",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(e["field"], "count");
    assert!(e["message"].as_str().unwrap().contains("--force"), "{e}");
    assert!(!dir.exists(), "nothing is written");
}

#[test]
fn generate_never_overwrites_files_without_force() {
    let dir = tmp("again");
    let args = [
        "generate",
        "--topic",
        "view",
        "--count",
        "1",
        "--out",
        dir.to_str().unwrap(),
    ];
    grafika().args(args).assert().success();
    let e = json_err(&args);
    assert_eq!(e["field"], "out");
    assert!(
        e["message"].as_str().unwrap().contains("already exists"),
        "{e}"
    );
    grafika().args(args).arg("--force").assert().success();
}

#[test]
fn generate_out_naming_a_file_says_so() {
    let e = json_err(&[
        "generate",
        "--topic",
        "view",
        "--count",
        "1",
        "--out",
        "/dev/null",
    ]);
    assert_eq!(e["field"], "out");
    assert!(
        e["message"].as_str().unwrap().contains("not a directory"),
        "{e}"
    );
}

/// Issue 18: the question sheet does not print the seed (a student could
/// regenerate the key from it); the key does.
#[test]
fn the_question_sheet_does_not_print_the_seed() {
    let dir = tmp("noseed");
    grafika()
        .args([
            "generate", "--topic", "view", "--count", "1", "--seed", "987654",
        ])
        .args(["--format", "md", "--out", dir.to_str().unwrap()])
        .assert()
        .success();
    let q = std::fs::read_to_string(dir.join("questions.md")).unwrap();
    let k = std::fs::read_to_string(dir.join("key.md")).unwrap();
    assert!(!q.contains("987654"), "the question sheet shows the seed");
    assert!(k.contains("987654"), "the key lost its seed");
}

/// The clipping statuses of an exam's clipping problems, in order.
fn clip_statuses(exam: &[generate::Generated]) -> Vec<String> {
    exam.iter()
        .filter_map(|g| {
            match g
                .report
                .result
                .lookup("clip.status")
                .map(|v| v.into_owned())
            {
                Some(Val::Text(s)) => Some(s.clone()),
                _ => None,
            }
        })
        .collect()
}

#[test]
fn a_two_clip_exam_can_have_a_rejected_segment() {
    // `--clip mixed`: the statuses follow an order drawn from the seed,
    // not the position: over 30 seeds every status comes first and second
    // at least once.
    let mut seen = std::collections::BTreeSet::new();
    for seed in 0..30 {
        let mixed = generate::ClipCase::Mixed;
        let exam = drawn(&[Topic::Clip], Difficulty::Easy, (2, 1), seed, mixed).remove(0);
        let st = clip_statuses(&exam);
        assert_ne!(st[0], st[1], "seed {seed}");
        seen.insert((0, st[0].clone()));
        seen.insert((1, st[1].clone()));
    }
    assert_eq!(seen.len(), 6, "{seen:?}");
}

/// How many different problem bodies an exam has.
fn distinct(exam: &[generate::Generated]) -> usize {
    let mut bodies: Vec<&str> = exam.iter().map(|g| g.body.as_str()).collect();
    bodies.sort();
    bodies.dedup();
    bodies.len()
}

#[test]
fn problems_do_not_repeat_within_an_exam() {
    // The case: easy window problems, 6 per exam, 3 variants: no
    // statement twice in the 18 problems of the exam.
    let clipped = generate::ClipCase::Clipped;
    let all = drawn(&[Topic::Window], Difficulty::Easy, (6, 3), 20261, clipped);
    assert_eq!(distinct(&all.into_iter().flatten().collect::<Vec<_>>()), 18);
    for t in TOPICS {
        for level in LEVELS {
            let exam = generate::exam(&[t], level, 12, 5).unwrap();
            assert_eq!(distinct(&exam), 12, "{t:?} {level:?}");
        }
    }
}

#[test]
fn an_exam_larger_than_the_distinct_problems_is_refused() {
    // Easy windows: fovy = 90° (tan 45° = 1, every answer rational), 10
    // aspects × 10 nears: 100 different problems. 100 variants are drawn,
    // all different; a 101st cannot be, and generate says how many it can
    // make, in each language.
    let clipped = generate::ClipCase::Clipped;
    let hundred = drawn(&[Topic::Window], Difficulty::Easy, (1, 100), 1, clipped);
    assert_eq!(
        distinct(&hundred.into_iter().flatten().collect::<Vec<_>>()),
        100
    );
    let out = tmp("few");
    let args = |lang| {
        vec![
            "generate",
            "--topic",
            "window",
            "--difficulty",
            "easy",
            "--variants",
            "101",
            "--lang",
            lang,
            "--out",
            out.to_str().unwrap(),
        ]
    };
    let e = json_err(&args("en"));
    assert_eq!(e["field"], "variants", "{e}");
    let m = e["message"].as_str().unwrap();
    assert!(
        m.contains("only 100 different variants") && m.contains("101"),
        "{e}"
    );
    let e = json_err(&args("id"));
    let m = e["message"].as_str().unwrap();
    assert!(m.contains("100 varian berbeda") && m.contains("101"), "{e}");
    assert!(!out.exists(), "a refused exam wrote files");
}

#[test]
fn points_of_a_problem_are_all_different() {
    for level in LEVELS {
        for seed in 0..10 {
            for g in generate::exam(&[Topic::View, Topic::Pipeline], level, 4, seed).unwrap() {
                let pts: Vec<String> = g.problem.points.values().map(|v| v.to_string()).collect();
                let mut d = pts.clone();
                d.sort();
                d.dedup();
                assert_eq!(d.len(), pts.len(), "{}", g.body);
            }
        }
    }
}

/// The distinct radicands in the exact forms of a problem's key.
fn radicands(g: &generate::Generated) -> std::collections::BTreeSet<String> {
    let key = generate::key_lines(g);
    key.split("sqrt(")
        .skip(1)
        .map(|r| r.split(')').next().unwrap().to_string())
        .collect()
}

#[test]
fn medium_problems_have_at_most_one_surd_and_easy_ones_none() {
    for t in TOPICS {
        for seed in 0..6 {
            for g in generate::exam(&[t], Difficulty::Medium, 3, seed).unwrap() {
                let r = radicands(&g);
                assert!(r.len() <= 1, "{t:?}: {r:?} in\n{}", generate::key_lines(&g));
            }
            for g in generate::exam(&[t], Difficulty::Easy, 3, seed).unwrap() {
                let r = radicands(&g);
                assert!(r.is_empty(), "{t:?}: {r:?} in\n{}", generate::key_lines(&g));
            }
        }
    }
}

/// Whether a value has a number without an exact form.
fn has_inexact(v: &Val) -> bool {
    match v {
        Val::Num(n) => n.exact.is_none(),
        Val::List(items) => items.iter().any(has_inexact),
        Val::Map(kv) => kv.iter().any(|(_, x)| has_inexact(x)),
        _ => false,
    }
}

#[test]
fn hard_keys_are_exact_where_an_exact_form_exists() {
    // A decimal-only answer is allowed only where it rests on tan(fovy/2)
    // for an angle that is not constructible: one whose tangent has a form
    // in square roots is 3°·m/2^k (tan 37.5° = √6 − √3 + √2 − 2 has one;
    // tan 20°, 25°, 35°, 40° have none).
    for t in TOPICS {
        for seed in 0..6 {
            for g in generate::exam(&[t], Difficulty::Hard, 3, seed).unwrap() {
                let fovy = g
                    .problem
                    .perspective
                    .as_ref()
                    .and_then(|p| p.fovy.as_ref())
                    .map(|f| f.0.degrees::<f64>().unwrap());
                if let Some(f) = fovy {
                    let dyadic = (f / 2.0 / 3.0 * 1024.0).fract() == 0.0;
                    assert!(!dyadic, "tan({f}°/2) has an exact form: {}", g.body);
                }
                for k in &g.keys {
                    let v = g.report.result.get(k).unwrap();
                    let allowed = matches!(k.part, Some(Part::Window | Part::Viewport));
                    assert!(allowed || !has_inexact(&v), "{k} inexact in\n{}", g.body);
                }
            }
        }
    }
}

#[test]
fn the_variants_of_a_position_are_parallel_forms() {
    // Over 40 variants of several seeds, the variants of each position
    // ask the same keys with the same marks, of the same number class
    // (numbers::classify), with the same clipping status and outcodes'
    // bits; no two statements of the exam are equal; and the default clip
    // case is a real clipping problem (status clipped, at least one
    // intersection computed).
    use grafika::tutor::generate::numbers::classes;
    // each topic alone: the pipeline's positions are the others'
    let topics: Vec<Topic> = (Topic::ALL.into_iter())
        .filter(|t| *t != Topic::Pipeline)
        .collect();
    for level in LEVELS {
        for seed in [4242, 7] {
            let clipped = generate::ClipCase::Clipped;
            let all = drawn(&topics, level, (6, 40), seed, clipped);
            let sig = |g: &generate::Generated| {
                let marks: Vec<(String, Option<u32>, usize)> = (g.keys.iter())
                    .map(|k| {
                        let item = g.scheme.item(k);
                        (
                            k.to_string(),
                            item.map(|i| i.marks),
                            item.map_or(0, |i| i.method.len()),
                        )
                    })
                    .collect();
                // the status, and how many planes each end lies beyond
                let clip = ["clip.status", "clip.code0", "clip.code1"].map(|k| {
                    match g.report.result.lookup(k).map(|v| v.into_owned()) {
                        Some(Val::Text(s)) if k == "clip.status" => s.clone(),
                        Some(Val::Text(s)) => s.matches('1').count().to_string(),
                        _ => String::new(),
                    }
                });
                let points = g.problem.points.len();
                (marks, classes(&g.report.result, &g.keys), clip, points)
            };
            for i in 0..6 {
                let first = sig(&all[0][i]);
                for (v, exam) in all.iter().enumerate() {
                    assert_eq!(
                        sig(&exam[i]),
                        first,
                        "{level:?} seed {seed} problem {i} variant {v}"
                    );
                }
            }
            let mut statements: Vec<&str> = all.iter().flatten().map(|g| g.body.as_str()).collect();
            statements.sort();
            statements.dedup();
            assert_eq!(statements.len(), 6 * 40, "{level:?} seed {seed}");
            for exam in &all {
                let st = clip_statuses(exam);
                assert_eq!(st, ["clipped"], "{level:?} seed {seed}");
                let cuts = exam[4]
                    .report
                    .result
                    .lookup("clip.intersections")
                    .map(|v| v.into_owned());
                assert!(
                    matches!(cuts, Some(Val::Map(m)) if !m.is_empty()),
                    "{}",
                    exam[4].body
                );
            }
        }
    }
}

/// The numbers of a key file's answer (a TOML string expression, or a
/// list of them), evaluated.
fn key_numbers(v: &toml::Value, out: &mut Vec<f64>) {
    match v {
        toml::Value::String(s) => {
            if let Ok(x) = grafika::num::expr::parse_expr(s).and_then(|e| e.eval::<f64>()) {
                out.push(x);
            }
        }
        toml::Value::Integer(i) => out.push(*i as f64),
        toml::Value::Float(x) => out.push(*x),
        toml::Value::Array(items) => items.iter().for_each(|x| key_numbers(x, out)),
        _ => {}
    }
}

/// The blueprint beside a 6-problem, 40-variant exam, checked against the
/// exam's own files rather than against the program's words: for every
/// position, the distinct statements are counted from the problem files,
/// the marks summed from exam.json, a clipping case's status and outcode
/// bits read from every variant's key file (the count of 1s in code0 and
/// code1), and each answer's range is the least and greatest number of
/// that key over the 40 key files. The printed table and blueprint.md
/// name the level and the case in words, in both languages.
#[test]
fn the_blueprint_says_what_every_variant_asks_alike() {
    let dir = tmp("blueprint");
    let out = grafika()
        .args([
            "generate",
            "--topic",
            "basis,view,project,window,clip,shade",
        ])
        .args(["--count", "6", "--variants", "40", "--seed", "4242"])
        .args(["--format", "json", "--out", dir.to_str().unwrap()])
        .output()
        .unwrap();
    assert_success(&out);
    let printed = String::from_utf8(out.stdout).unwrap();
    assert!(printed.contains("| Problem | Topic | Case |"), "{printed}");
    let bp: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("blueprint.json")).unwrap())
            .unwrap();
    assert_eq!(bp["variants"], 40);
    let positions = bp["positions"].as_array().unwrap();
    assert_eq!(positions.len(), 6);
    let mut total = 0;
    for (i, p) in positions.iter().enumerate() {
        let name = format!("problem-{:02}", i + 1);
        let mut statements = std::collections::HashSet::new();
        let mut ranges: std::collections::BTreeMap<String, (f64, f64)> = Default::default();
        for v in 1..=40 {
            let var = dir.join(format!("variant-{v:02}"));
            statements.insert(std::fs::read_to_string(var.join(format!("{name}.toml"))).unwrap());
            let key_path = var.join(format!("{name}.key.toml"));
            let key: toml::Table =
                toml::from_str(&std::fs::read_to_string(&key_path).unwrap()).unwrap();
            for (k, v) in &key_entries(&key_path) {
                let mut nums = Vec::new();
                key_numbers(v, &mut nums);
                for x in nums {
                    let r = ranges.entry(k.clone()).or_insert((x, x));
                    *r = (r.0.min(x), r.1.max(x));
                }
            }
            if p["topic"] == "clip" {
                let text = |k: &str| key["clip"][k].as_str().unwrap().to_string();
                let ones = |c: String| c.chars().filter(|&c| c == '1').count();
                assert_eq!(p["case"]["status"].as_str().unwrap(), text("status"));
                assert_eq!(p["case"]["bits"][0], ones(text("code0")));
                assert_eq!(p["case"]["bits"][1], ones(text("code1")));
            }
            let exam: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(var.join("exam.json")).unwrap())
                    .unwrap();
            assert_eq!(
                exam["problems"][i]["total"], p["total"],
                "{name} variant {v}"
            );
        }
        assert_eq!(p["distinct"], statements.len(), "{name}");
        assert_eq!(p["distinct"], 40, "no statement twice");
        assert_eq!(p["same_marks"], true);
        assert_eq!(p["same_class"], 40, "{name}");
        for (k, span) in p["spread"].as_object().unwrap() {
            if let Some(span) = span.as_array() {
                let (lo, hi) = ranges[k];
                let close = |a: &serde_json::Value, b: f64| (a.as_f64().unwrap() - b).abs() < 1e-9;
                assert!(
                    close(&span[0], lo) && close(&span[1], hi),
                    "{k}: {span:?} vs {lo}..{hi}"
                );
            }
        }
        total += p["total"].as_u64().unwrap();
    }
    assert_eq!(bp["total"], total);
    let md = std::fs::read_to_string(dir.join("blueprint.md")).unwrap();
    assert!(md.starts_with("# Exam blueprint\n"), "{md}");
    assert!(md.contains(&format!("Blueprint: 40 variants, each worth {total} marks")));
    // in Indonesian, the case and the class in the text's words
    let id = tmp("blueprint-id");
    let out = grafika()
        .args(["--lang", "id", "generate", "--topic", "clip,shade"])
        .args([
            "--count",
            "2",
            "--variants",
            "5",
            "--seed",
            "7",
            "--difficulty",
            "easy",
        ])
        .args(["--out", id.to_str().unwrap()])
        .output()
        .unwrap();
    let printed = String::from_utf8(out.stdout).unwrap();
    assert!(
        printed.contains("| Soal | Topik | Kasus | Bilangan | Poin | Teks soal |"),
        "{printed}"
    );
    assert!(printed.contains("di-clip: P0 di luar"), "{printed}");
    assert!(printed.contains("rasional (semua 5)"), "{printed}");
    assert!(printed.contains("5 berbeda dari 5"), "{printed}");
}
