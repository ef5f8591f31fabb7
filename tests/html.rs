//! `--html FILE`: one self-contained page per worked solution, formulas in
//! MathML, figures inline; `generate --format html`. The page is checked as
//! XML (well-formed), for what it must not fetch, and for facts of the
//! text's examples derived by hand.

mod common;
use common::*;
use std::path::PathBuf;

/// A new file `name` in a folder of this test run; tests run in parallel,
/// so each call gets a folder of its own (two tests may write the same name).
fn tmp(name: &str) -> PathBuf {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let d = std::env::temp_dir().join(format!("grafika-html-{}-{k}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let f = d.join(name);
    let _ = std::fs::remove_file(&f);
    f
}

/// Runs grafika with `--html FILE` and returns the page.
fn page(name: &str, args: &[&str]) -> String {
    let f = tmp(name);
    grafika()
        .args(args)
        .args(["--html", f.to_str().unwrap()])
        .assert()
        .success();
    std::fs::read_to_string(&f).unwrap()
}

/// The page parses as XML (every tag closed, every character escaped).
fn well_formed(html: &str) {
    let doc = roxmltree::Document::parse_with_options(
        html,
        roxmltree::ParsingOptions {
            allow_dtd: true,
            ..Default::default()
        },
    );
    assert!(doc.is_ok(), "{:?}", doc.err());
}

/// Nothing is fetched: no script, no link, no external image or font
/// (`url(#…)` names a marker inside the page itself).
fn self_contained(html: &str) {
    for bad in ["<script", "<link", " src=", " href=", "@import"] {
        assert!(!html.contains(bad), "the page has {bad}");
    }
    for (i, _) in html.match_indices("url(") {
        assert!(
            html[i + 4..].starts_with('#'),
            "the page fetches {}",
            &html[i..i + 20]
        );
    }
}

/// Every `id` in the page is unique (several inline SVGs each define their
/// arrow heads).
fn unique_ids(html: &str) {
    let mut ids: Vec<&str> = html
        .match_indices(" id=\"")
        .map(|(i, _)| {
            let rest = &html[i + 5..];
            &rest[..rest.find('"').unwrap_or(0)]
        })
        .collect();
    let n = ids.len();
    ids.sort();
    ids.dedup();
    assert_eq!(ids.len(), n, "an id is repeated");
}

/// `--html` on every calculator command and on `solve` writes a page with
/// the figure inline (solve: one per part; the triangle has view, project
/// and window).
#[test]
fn every_command_has_its_figures_inline() {
    let cam = ["--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0"];
    let cases: Vec<(&str, Vec<&str>, usize)> = vec![
        ("all-basis.html", [&["basis"], &cam[..]].concat(), 1),
        (
            "view.html",
            [&["view"], &cam[..], &["--point", "A=0,0,0"]].concat(),
            1,
        ),
        (
            "project.html",
            vec!["project", "--d", "-0.1", "--point", "A=0,-1,-6/sqrt(2)"],
            1,
        ),
        (
            "window.html",
            vec![
                "window",
                "--fovy",
                "45",
                "--aspect",
                "2",
                "--near",
                "0.1",
                "--viewport",
                "200x100",
                "--point",
                "A=0,-sqrt(2)/60",
            ],
            1,
        ),
        (
            "clip.html",
            vec![
                "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
            ],
            1,
        ),
        (
            "shade.html",
            vec![
                "shade", "--light", "0,0,1", "--normal", "0,1,1", "--color", "1,1,0", "--model",
                "blinn",
            ],
            1,
        ),
        (
            "solve.html",
            vec!["solve", "problems/text-triangle.toml"],
            3,
        ),
        (
            "solve-clip.html",
            vec!["solve", "problems/text-clip.toml"],
            1,
        ),
    ];
    for (name, args, figures) in cases {
        let html = page(name, &args);
        well_formed(&html);
        self_contained(&html);
        unique_ids(&html);
        assert_eq!(html.matches("<figure>\n<svg ").count(), figures, "{name}");
        assert!(html.contains("<figcaption>"), "{name}");
        // solve: each part's figure stands under its part's heading (h4);
        // a calculator command's figure comes before its steps.
        let (fig, part) = (html.find("<figure>"), html.find("<h4>"));
        match args[0] {
            "solve" => assert!(part < fig, "{name}: the figure is not under its part"),
            _ => assert!(part.is_none(), "{name}"),
        }
    }
}

#[test]
fn the_triangle_example_as_a_page() {
    let html = page("triangle.html", &["solve", "problems/text-triangle.toml"]);
    well_formed(&html);
    self_contained(&html);
    assert!(html.starts_with("<!DOCTYPE html>\n<html lang=\"en\">"));
    // Pe − Pr = (1, 0, 1), so n = (√2/2, 0, √2/2): in MathML.
    assert!(
        html.contains(concat!(
            r#"<mi>n</mi><mo form="infix">=</mo><mo stretchy="false" lspace="0" rspace="0">(</mo>"#,
            r#"<msqrt><mn>2</mn></msqrt><mo lspace="0" rspace="0">/</mo><mn>2</mn>"#,
            r#"<mo separator="true" lspace="0" rspace="0.35em">,</mo><mn>0</mn>"#
        )),
        "n = (√2/2, 0, √2/2) is not set in MathML"
    );
    // every part and step of the text report is on the page
    let text = grafika()
        .args(["solve", "problems/text-triangle.toml"])
        .output()
        .unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    let steps = text.lines().filter(|l| l.starts_with("Step ")).count();
    assert!(steps > 10);
    assert_eq!(html.matches("<section class=\"step\">").count(), steps);
    assert!(html.contains("@page{size:A4"), "prints on A4");
    assert!(html.contains("<table class=\"answers\">"));
}

#[test]
fn the_clip_page_has_its_figure_inline() {
    let html = page(
        "clip.html",
        &[
            "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
        ],
    );
    well_formed(&html);
    self_contained(&html);
    assert!(html.contains("<figure>\n<svg "), "no inline figure");
    assert!(html.contains("<figcaption>"));
}

/// A step's line too long for the column (view-surds' v = n × u, its
/// components sums of √17 over 221) scrolls within its own line: seen in
/// Chromium at 1,200 px, the page grew wider than the window and the line
/// was cut at its edge. Each line of a step is an `<li>` whose style lets
/// it scroll, and the long line is one; the answer table scrolls too.
#[test]
fn a_long_line_of_a_step_scrolls_within_itself() {
    let html = page("surds.html", &["solve", "problems/view-surds.toml"]);
    well_formed(&html);
    let style = &html[html.find("<style>").unwrap()..html.find("</style>").unwrap()];
    let rule = style
        .split('}')
        .find(|r| r.starts_with("section.step li{"))
        .expect("a rule for a step's lines");
    assert!(
        rule.contains("overflow-x:auto") && rule.contains("max-width:100%"),
        "{rule}"
    );
    let long = html
        .split("<li>")
        .skip(1)
        .map(|li| &li[..li.find("</li>").unwrap_or(li.len())])
        .any(|li| li.contains("<mi>v</mi>") && li.matches("221").count() >= 2);
    assert!(
        long,
        "the line of v with its /221 components is a step's line"
    );
    // shade-spot-penumbra's answer table (its colour, sums of √2, √3 and
    // √6 over 125) scrolls within itself likewise.
    let table = style
        .split('}')
        .find(|r| r.starts_with("table.answers{"))
        .expect("a rule for the answer table");
    assert!(
        table.contains("overflow-x:auto") && table.contains("display:block"),
        "{table}"
    );
}

#[test]
fn a_page_in_indonesian() {
    let html = page(
        "id.html",
        &[
            "--lang", "id", "window", "--fovy", "45", "--aspect", "1.5", "--near", "0.1",
        ],
    );
    well_formed(&html);
    assert!(html.contains("<html lang=\"id\">"));
    assert!(html.contains("Langkah 1."), "step titles in Indonesian");
    // top = 0.1·tan 22.5° = (√2 − 1)/10 ≈ 0,04142: the decimal comma in an <mn>
    assert!(html.contains("<mn>0,04142</mn>"), "no decimal comma");
}

#[test]
fn an_existing_page_is_never_overwritten() {
    let f = tmp("keep.html");
    std::fs::write(&f, "mine").unwrap();
    grafika()
        .args([
            "basis", "--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0",
        ])
        .args(["--html", f.to_str().unwrap()])
        .assert()
        .code(2);
    assert_eq!(std::fs::read_to_string(&f).unwrap(), "mine");
}

#[test]
fn html_is_refused_where_there_is_no_worked_solution() {
    // bench does not take --html after its name (its --help does not
    // list it), nor before it: the same refusal, with where pages come from.
    for args in [
        ["bench", "--quick", "--html", "x.html"],
        ["--html", "x.html", "bench", "--quick"],
    ] {
        let e = json_err(&args);
        assert_eq!(e["field"], "html", "{e}");
        assert!(
            e["message"]
                .as_str()
                .unwrap()
                .contains("generate --format html"),
            "{e}"
        );
    }
}

#[test]
fn generate_writes_html_sheets_and_keys() {
    let dir = std::env::temp_dir().join(format!("grafika-html-exam-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    grafika()
        .args([
            "generate",
            "--topic",
            "view,clip",
            "--count",
            "2",
            "--seed",
            "4",
        ])
        .args(["--format", "html", "--out", dir.to_str().unwrap()])
        .assert()
        .success();
    for f in ["questions.html", "key.html"] {
        let html = std::fs::read_to_string(dir.join(f)).unwrap();
        well_formed(&html);
        self_contained(&html);
    }
    let key = std::fs::read_to_string(dir.join("key.html")).unwrap();
    assert!(key.contains("<section class=\"step\">") && key.contains("<math"));
    // The exam's two problems (a view and a clip) each have a figure.
    assert_eq!(key.matches("<figure>\n<svg ").count(), 2);
    unique_ids(&key);
    let q = std::fs::read_to_string(dir.join("questions.html")).unwrap();
    assert!(
        !q.contains("<section class=\"step\">"),
        "the questions show no solution"
    );
}

/// Issue 26 point 7: the worked solution's page of the text's triangle in
/// Indonesian states the problem first, names the answers as the steps
/// name them, compares with the printed answers in a table, and keeps the
/// spaces of the text in its MathML.
#[test]
fn the_page_reads_like_the_text() {
    let html = page(
        "reads.html",
        &["--lang", "id", "solve", "problems/text-triangle.toml"],
    );
    well_formed(&html);
    // the statement stands before the first step
    let statement = html.find("<p class=\"statement\">").expect("no statement");
    assert!(statement < html.find("<section class=\"step\">").unwrap());
    // the answer table: the steps' names, the answer keys only in a title
    let answers = &html[html.find("<table class=\"answers\">").unwrap()..];
    let answers = &answers[..answers.find("</table>").unwrap()];
    assert!(
        answers.contains("title=\"view.points.A\"><math><mrow><mi>A</mi><mo>'</mo></mrow>"),
        "A' has no row"
    );
    assert!(
        answers.contains("<mtext>piksel</mtext>"),
        "pixel A is not 'piksel A'"
    );
    assert!(
        answers.contains("<mtext>far plane</mtext>"),
        "far_top is not named as the steps name it"
    );
    for key in ["view.points", "viewport.pixels", "far_top"] {
        let shown = answers.replace(&format!("title=\"{key}"), "");
        assert!(
            !shown.contains(&format!(">{key}")),
            "{key} shown as a label"
        );
    }
    // no stray '=' before the answer's matrix
    assert!(
        !answers.contains(">=</mo>"),
        "a stray = in the answer table"
    );
    // the comparison as a table, each verdict a word of the text's kinds
    let cmp = &html[html
        .find("<table class=\"answers comparison\">")
        .expect("no table")..];
    assert!(cmp.contains("<th>tercetak</th>") && cmp.contains("<th>yang benar</th>"));
    assert!(cmp.contains("salah cetak"), "B'' is a misprint");
    assert!(cmp.contains("konvensi"), "the height is another convention");
    assert!(cmp.contains("pembulatan"), "right is a rounding");
    assert!(
        !html.contains("<p class=\"note\">Dibandingkan"),
        "the comparison as a paragraph"
    );
    // words keep their spaces in MathML; `;` is followed by a space
    assert!(html.contains("<mtext>dari</mtext>") || html.contains("<mspace"));
    assert!(html.contains("<mo separator=\"true\" lspace=\"0\" rspace=\"0.35em\">;</mo>"));
}
