//! Figures: facts of each figure checked from its description against
//! values worked by hand, and the SVG written by `--figure` parses.

use assert_cmd::Command;
use clap::Parser;
use grafika::cli::args::Cli;
use grafika::report::figure::{
    builders::figure_of, cabinet, svg::to_svg, tikz::to_tikz, Item, Pen,
};
use grafika::report::lang::Lang;
use grafika::report::Style;

fn clip_figure(args: &[&str]) -> grafika::report::figure::Figure {
    let mut all = vec!["grafika", "clip"];
    all.extend_from_slice(args);
    let cli = Cli::try_parse_from(all).expect("arguments parse");
    let report = grafika::cli::run(&cli).expect("clip runs");
    figure_of(&report, &Style::new(6, false, Lang::En)).expect("clip draws a figure")
}

fn segments(f: &grafika::report::figure::Figure, pen: Pen) -> Vec<([f64; 2], [f64; 2])> {
    f.items
        .iter()
        .filter_map(|it| match it {
            Item::Segment { a, b, pen: p } if *p == pen => Some((*a, *b)),
            _ => None,
        })
        .collect()
}

fn near(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9
}

/// Unit box, P0 = (−1, ½, ½), P1 = (2, ½, ½): by hand the segment enters at
/// x = 0 (t = 1/3) and leaves at x = 1 (t = 2/3), so the kept part is
/// (0, ½, ½)–(1, ½, ½) and the parts beyond are cut off.
#[test]
fn clip_solid_part_ends_at_the_clipped_points() {
    let f = clip_figure(&[
        "--min",
        "0,0,0",
        "--max",
        "1,1,1",
        "--from",
        "-1,0.5,0.5",
        "--to",
        "2,0.5,0.5",
    ]);
    let kept = segments(&f, Pen::Kept);
    assert_eq!(kept.len(), 1);
    assert!(near(kept[0].0, cabinet([0.0, 0.5, 0.5])));
    assert!(near(kept[0].1, cabinet([1.0, 0.5, 0.5])));
    let cut = segments(&f, Pen::Cut);
    assert_eq!(cut.len(), 2);
    assert!(near(cut[0].0, cabinet([-1.0, 0.5, 0.5])) && near(cut[0].1, cabinet([0.0, 0.5, 0.5])));
    assert!(near(cut[1].0, cabinet([1.0, 0.5, 0.5])) && near(cut[1].1, cabinet([2.0, 0.5, 0.5])));
    assert_eq!(segments(&f, Pen::Frame).len(), 12, "a box has 12 edges");
    let labels: Vec<&str> = f
        .items
        .iter()
        .filter_map(|it| match it {
            Item::Label { text, .. } => Some(text.as_str()),
            _ => None,
        })
        .collect();
    assert!(
        labels.contains(&"left: t = 1/3 ≈ 0.333333, outcode 000000"),
        "{labels:?}"
    );
    assert!(
        labels.contains(&"right: t = 2/3 ≈ 0.666667, outcode 000000"),
        "{labels:?}"
    );
}

/// A segment wholly outside is all cut off: no solid part.
#[test]
fn clip_rejected_segment_is_all_dashed() {
    let f = clip_figure(&[
        "--min", "0,0,0", "--max", "1,1,1", "--from", "2,2,2", "--to", "3,2,2",
    ]);
    assert!(segments(&f, Pen::Kept).is_empty());
    assert_eq!(
        segments(&f, Pen::Cut),
        vec![(cabinet([2.0, 2.0, 2.0]), cabinet([3.0, 2.0, 2.0]))]
    );
}

/// The cabinet projection as stated: z drawn at 45°, half length.
#[test]
fn cabinet_projection_is_as_stated() {
    let p = cabinet([0.0, 0.0, 2.0]);
    let len = (p[0] * p[0] + p[1] * p[1]).sqrt();
    assert!((len - 1.0).abs() < 1e-12 && (p[0] - p[1]).abs() < 1e-12 && p[0] < 0.0);
}

#[test]
fn figure_flag_writes_svg_that_parses_and_never_overwrites() {
    let dir = std::env::temp_dir().join(format!("grafika-fig-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("clip.svg");
    let _ = std::fs::remove_file(&file);
    let args = [
        "clip",
        "--min",
        "0,0,0",
        "--max",
        "1,1,1",
        "--from",
        "-1,0.5,0.5",
        "--to",
        "2,0.5,0.5",
        "--figure",
    ];
    Command::cargo_bin("grafika")
        .unwrap()
        .args(args)
        .arg(&file)
        .assert()
        .success();
    let text = std::fs::read_to_string(&file).unwrap();
    let doc = roxmltree::Document::parse(&text).expect("SVG parses as XML");
    let root = doc.root_element();
    assert_eq!(root.attribute("width"), Some("600"));
    let names: Vec<&str> = root
        .children()
        .filter(|n| n.is_element())
        .map(|n| n.tag_name().name())
        .collect();
    assert_eq!(&names[..2], &["title", "desc"]);
    assert!(root
        .descendants()
        .any(|n| n.has_tag_name("text") && n.text().is_some_and(|t| t.starts_with("P0"))));
    let again = Command::cargo_bin("grafika")
        .unwrap()
        .args(args)
        .arg(&file)
        .assert()
        .code(2);
    let err = String::from_utf8_lossy(&again.get_output().stderr).to_string();
    assert!(err.contains("figure"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The same description written as TikZ has the same marks.
#[test]
fn tikz_has_the_same_marks() {
    let f = clip_figure(&[
        "--min",
        "0,0,0",
        "--max",
        "1,1,1",
        "--from",
        "-1,0.5,0.5",
        "--to",
        "2,0.5,0.5",
    ]);
    let t = to_tikz(&f);
    assert_eq!(t.matches("\\draw[").count(), 12 + 3);
    assert!(t.contains("dashed") && to_svg(&f).contains("stroke-dasharray"));
}
