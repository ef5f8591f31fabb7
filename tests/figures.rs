//! Figures: facts of each figure checked from its description against
//! values worked by hand (derivations in the comments), the SVG written by
//! `--figure` parses with its title and description first, and the TikZ
//! picture carries the same marks.

use assert_cmd::Command;
use clap::Parser;
use grafika::cli::args::Cli;
use grafika::report::figure::{
    cabinet, drawings::drawings, svg::to_svg, tikz::to_tikz, Drawing, Figure, Item, Pen,
};
use grafika::report::lang::Lang;
use grafika::report::Style;

/// The drawings of a command line (`grafika` is prepended), in English
/// with exact forms, as the command line writes them.
fn drawn_in(lang: Lang, args: &[&str]) -> Vec<Drawing> {
    let mut all = vec!["grafika"];
    all.extend_from_slice(args);
    let cli = Cli::try_parse_from(all).expect("arguments parse");
    let report = grafika::cli::run(&cli).expect("the command runs");
    drawings(&report, &Style::new(4, true, lang))
}

fn drawn(args: &[&str]) -> Vec<Drawing> {
    drawn_in(Lang::En, args)
}

/// The one panel of a one-panel drawing.
fn only(args: &[&str]) -> Figure {
    let d = drawn(args);
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].panels.len(), 1);
    d[0].panels[0].clone()
}

fn clip_figure(args: &[&str]) -> Figure {
    let mut all = vec!["clip"];
    all.extend_from_slice(args);
    only(&all)
}

fn segments(f: &Figure, pen: Pen) -> Vec<([f64; 2], [f64; 2])> {
    f.items
        .iter()
        .filter_map(|it| match it {
            Item::Segment { a, b, pen: p } if *p == pen => Some((*a, *b)),
            _ => None,
        })
        .collect()
}

fn arrows(f: &Figure, pen: Pen) -> Vec<([f64; 2], [f64; 2])> {
    f.items
        .iter()
        .filter_map(|it| match it {
            Item::Arrow { a, b, pen: p } if *p == pen => Some((*a, *b)),
            _ => None,
        })
        .collect()
}

fn dots(f: &Figure, pen: Pen) -> Vec<[f64; 2]> {
    f.items
        .iter()
        .filter_map(|it| match it {
            Item::Dot { at, pen: p } if *p == pen => Some(*at),
            _ => None,
        })
        .collect()
}

fn labels(f: &Figure) -> Vec<String> {
    f.items
        .iter()
        .filter_map(|it| match it {
            Item::Label { text, .. } | Item::Note { text } => Some(text.clone()),
            _ => None,
        })
        .collect()
}

fn has_label(f: &Figure, want: &str) {
    let l = labels(f);
    assert!(l.iter().any(|t| t == want), "no label {want:?} in {l:?}");
}

fn near(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9
}

/// Whether c lies on the segment a–b (collinear, between the ends).
fn on_segment(c: [f64; 2], a: [f64; 2], b: [f64; 2]) -> bool {
    let (ux, uy) = (b[0] - a[0], b[1] - a[1]);
    let (wx, wy) = (c[0] - a[0], c[1] - a[1]);
    let len2 = ux * ux + uy * uy;
    let cross = ux * wy - uy * wx;
    let t = (ux * wx + uy * wy) / len2;
    cross.abs() <= 1e-9 * len2.max(1.0) && (-1e-9..=1.0 + 1e-9).contains(&t)
}

// ---- clip ----

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
    has_label(&f, "left: t = 1/3 ≈ 0.3333, outcode 000000");
    has_label(&f, "right: t = 2/3 ≈ 0.6667, outcode 000000");
    // Beside each dot only its plane's name (short enough to sit off the
    // box's edges); t and the outcode are in the notes above.
    let beside: Vec<String> = f
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Label { text, .. } => Some(text.clone()),
            _ => None,
        })
        .collect();
    assert!(beside.contains(&"left".to_string()) && beside.contains(&"right".to_string()));
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

/// Runs grafika with `--figure FILE` and returns the SVG's text; a second
/// run must refuse to overwrite it (exit 2, a one-line error on figure).
fn svg_of(name: &str, args: &[&str]) -> String {
    let dir = std::env::temp_dir().join(format!("grafika-fig-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(name);
    let _ = std::fs::remove_file(&file);
    let run = || {
        let mut c = Command::cargo_bin("grafika").unwrap();
        c.args(args).arg("--figure").arg(&file);
        c
    };
    run().assert().success();
    let text = std::fs::read_to_string(&file).unwrap();
    let again = run().assert().code(2);
    let err = String::from_utf8_lossy(&again.get_output().stderr).to_string();
    assert!(
        err.starts_with("error: figure: ") && err.contains("exists"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), text, "overwritten");
    std::fs::remove_file(&file).unwrap();
    text
}

/// The SVG parses, is 600 px wide, has `<title>` and `<desc>` first, and
/// each panel group has its own title and desc first; returns its texts.
fn check_svg(text: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(text).expect("SVG parses as XML");
    let root = doc.root_element();
    assert_eq!(root.attribute("width"), Some("600"));
    let first = |n: roxmltree::Node| -> Vec<String> {
        n.children()
            .filter(|c| c.is_element())
            .take(2)
            .map(|c| c.tag_name().name().to_string())
            .collect()
    };
    assert_eq!(first(root), ["title", "desc"]);
    for g in root.children().filter(|n| n.has_tag_name("g")) {
        assert_eq!(first(g), ["title", "desc"]);
        assert!(g
            .children()
            .any(|c| c.has_tag_name("title") && c.text().is_some_and(|t| !t.is_empty())));
    }
    root.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(str::to_string))
        .collect()
}

#[test]
fn clip_figure_flag_writes_svg_that_parses_and_never_overwrites() {
    let svg = svg_of(
        "clip.svg",
        &[
            "clip",
            "--min",
            "0,0,0",
            "--max",
            "1,1,1",
            "--from",
            "-1,0.5,0.5",
            "--to",
            "2,0.5,0.5",
        ],
    );
    let texts = check_svg(&svg);
    assert!(texts.iter().any(|t| t.starts_with("P0")), "{texts:?}");
}

/// The same description written as TikZ has the same marks: one `\draw`
/// per line, arrow and polygon, one `\fill` per dot, one `\node` per label.
fn same_marks_in_tikz(d: &Drawing) {
    let t = to_tikz(d);
    let count = |f: &dyn Fn(&Item) -> bool| -> usize {
        d.panels
            .iter()
            .flat_map(|p| &p.items)
            .filter(|i| f(i))
            .count()
    };
    let lines = count(&|i| {
        matches!(
            i,
            Item::Segment { .. } | Item::Arrow { .. } | Item::Polygon { .. } | Item::Path { .. }
        )
    });
    let arrows = count(&|i| matches!(i, Item::Arrow { .. }));
    let dots = count(&|i| matches!(i, Item::Dot { .. }));
    let labels = count(&|i| matches!(i, Item::Label { .. } | Item::Note { .. }));
    let headings = if d.panels.len() > 1 {
        d.panels.len()
    } else {
        0
    };
    assert_eq!(t.matches("\\draw[").count(), lines);
    assert_eq!(t.matches("\\draw[->").count(), arrows);
    assert_eq!(t.matches("\\fill[").count(), dots);
    assert_eq!(t.matches("\\node[").count(), labels + headings);
    assert_eq!(t.matches("\\begin{tikzpicture}").count(), d.panels.len());
    let svg = to_svg(d);
    assert_eq!(svg.matches("<text").count(), labels + headings);
    assert_eq!(svg.matches("marker-end").count(), arrows);
}

#[test]
fn tikz_has_the_same_marks() {
    let d = drawn(&[
        "clip",
        "--min",
        "0,0,0",
        "--max",
        "1,1,1",
        "--from",
        "-1,0.5,0.5",
        "--to",
        "2,0.5,0.5",
    ]);
    same_marks_in_tikz(&d[0]);
    let t = to_tikz(&d[0]);
    assert!(t.contains("dashed") && to_svg(&d[0]).contains("stroke-dasharray"));
}

// ---- basis and view ----

/// The text's camera example (problems/text-camera.toml): Pe = (4, 4, 4),
/// Pr = (0, 1, 4), Vup = (0, 1, 0). By hand:
/// n = (Pe − Pr)/|Pe − Pr| = (4, 3, 0)/5 = (4/5, 3/5, 0);
/// u = Vup × n / |…| = (1·0 − 0·3/5, 0·4/5 − 0·0, 0·3/5 − 1·4/5)/(4/5)
///   = (0, 0, −1);
/// v = n × u = (3/5·(−1) − 0, 0 − 4/5·(−1), 0) = (−3/5, 4/5, 0);
/// Pref' = (u·d, v·d, n·d) with d = Pref − Pe = (−4, −3, 0):
///   (0, 12/5 − 12/5, −16/5 − 9/5) = (0, 0, −5).
/// The scene lies within 8 of the origin, so the arrows are 1 long: each
/// runs from cabinet(Pe) to cabinet(Pe + vector).
#[test]
fn camera_arrows_point_along_u_v_n_under_the_cabinet_projection() {
    let d = drawn(&["solve", "problems/text-camera.toml"]);
    assert_eq!(d.len(), 1);
    assert_eq!(d[0].part, "view");
    let f = &d[0].panels[0];
    let pe = [4.0, 4.0, 4.0];
    // u, v, n are drawn 2 units long (twice Vup's unit length; the note
    // says so), each in its own pen: u green solid, v purple dash-dot, n
    // vermillion dashed.
    let tip = |v: [f64; 3]| cabinet([pe[0] + 2.0 * v[0], pe[1] + 2.0 * v[1], pe[2] + 2.0 * v[2]]);
    let want = [
        (Pen::Vector, tip([0.0, 0.0, -1.0])),
        (Pen::Other, tip([-0.6, 0.8, 0.0])),
        (Pen::Cut, tip([0.8, 0.6, 0.0])),
    ];
    let mut tips = vec![];
    for (pen, wb) in want {
        let got = arrows(f, pen);
        assert_eq!(got.len(), 1, "{pen:?}");
        let (a, b) = got[0];
        assert!(
            near(a, cabinet(pe)) && near(b, wb),
            "{a:?}–{b:?} is not to {wb:?}"
        );
        tips.push(b);
    }
    // No two overlap: by hand the page directions are u → (k, k) with
    // k = 1/(2√2) (45°), v → (−0.6, 0.8) (127°), n → (0.8, 0.6) (37°): u
    // and n are 8° apart, so their tips, at 2·√2·k = 1 and 2 from Peye,
    // lie 1 page unit apart, and no two pens are alike.
    for i in 0..3 {
        for j in 0..i {
            let d = (tips[i][0] - tips[j][0]).hypot(tips[i][1] - tips[j][1]);
            assert!(d > 0.9, "tips {i} and {j} are {d} apart");
        }
    }
    has_label(
        f,
        "u green, v purple dash-dot, n vermillion dashed; length 2",
    );
    // Vup at Pref, along (0, 1, 0).
    assert_eq!(
        arrows(f, Pen::Given),
        vec![(cabinet([0.0, 1.0, 4.0]), cabinet([0.0, 2.0, 4.0]))]
    );
    // The line of sight from Peye to Pref, and the two blue dots.
    assert_eq!(
        segments(f, Pen::Tried),
        vec![(cabinet(pe), cabinet([0.0, 1.0, 4.0]))]
    );
    assert_eq!(
        dots(f, Pen::Kept),
        vec![cabinet(pe), cabinet([0.0, 1.0, 4.0])]
    );
    // World axes x, y, z from the origin.
    assert_eq!(arrows(f, Pen::Frame).len(), 3);
    for want in [
        "u = (0, 0, −1)",
        "v = (−3/5, 4/5, 0)",
        "n = (4/5, 3/5, 0)",
        "Peye (4, 4, 4)",
        "Pref (0, 1, 4)",
        "Vup = (0, 1, 0)",
        "Pref (0, 1, 4): Pref' = (0, 0, −5)",
    ] {
        has_label(f, want);
    }
}

/// `basis` draws the same camera without points; `view --figure` writes
/// an SVG that parses, whose texts carry the same values.
#[test]
fn basis_and_view_figures() {
    let cam = ["--eye", "4,4,4", "--look", "0,1,4", "--up", "0,1,0"];
    let b = only(&[&["basis"], &cam[..]].concat());
    for pen in [Pen::Vector, Pen::Other, Pen::Cut] {
        assert_eq!(arrows(&b, pen).len(), 1, "u, v, n: one arrow each");
    }
    assert!(dots(&b, Pen::Frame).is_empty(), "basis has no named points");
    let svg = svg_of(
        "view.svg",
        &[&["view"], &cam[..], &["--point", "Pref=0,1,4"]].concat(),
    );
    let texts = check_svg(&svg);
    for want in ["n = (4/5, 3/5, 0)", "Pref (0, 1, 4): Pref' = (0, 0, −5)"] {
        assert!(texts.iter().any(|t| t == want), "{want:?} not in {texts:?}");
    }
    same_marks_in_tikz(&drawn(&[&["view"], &cam[..], &["--point", "Pref=0,1,4"]].concat())[0]);
}

/// In Indonesian the labels use the decimal comma and `;`, and the title
/// is Indonesian.
#[test]
fn camera_figure_in_indonesian() {
    let d = drawn_in(
        Lang::Id,
        &[
            "basis", "--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0",
        ],
    );
    let f = &d[0].panels[0];
    assert_eq!(f.title, "Kamera dalam sistem koordinat dunia");
    // n = (1, 0, 1)/√2 = (√2/2; 0; √2/2) ≈ (0,7071; 0; 0,7071)
    has_label(f, "n = (√2/2; 0; √2/2)");
}

// ---- project ----

/// The text's triangle, point A' = (0, −1, −3√2) projected onto z = d =
/// −0.1 with the centre at the origin. By hand: xp = d·x/z = 0,
/// yp = d·y/z = (−0.1)(−1)/(−3√2) = −1/(30√2) = −√2/60 ≈ −0.02357, so the
/// image is (0, −√2/60, −0.1). It lies on the projector from the centre
/// (0, 0, 0) to A (the image is nearer the centre: t = d/z ≈ 0.0236).
#[test]
fn project_projector_passes_through_the_point_and_its_image() {
    let a = [0.0, -1.0, -3.0 * 2f64.sqrt()];
    let img = [0.0, -(2f64.sqrt()) / 60.0, -0.1];
    let d = drawn(&["project", "--d", "-0.1", "--point", "A=0,-1,-6/sqrt(2)"]);
    assert_eq!(d[0].panels.len(), 3, "3D, side view, view plane");
    let (f3, side, plane) = (&d[0].panels[0], &d[0].panels[1], &d[0].panels[2]);
    let proj = segments(f3, Pen::Tried);
    assert_eq!(proj.len(), 1);
    assert!(near(proj[0].0, cabinet([0.0; 3])) && near(proj[0].1, cabinet(a)));
    assert!(on_segment(cabinet(img), proj[0].0, proj[0].1));
    // The plane (|d| = 0.1) is under an eighth of the scene (4.243): the
    // image is drawn in the inset, the plane's front view enlarged m
    // times, m = the largest 1, 2, 5·10^k ≤ 0.8·hi/|yp| with hi = 0.3·ext
    // = 0.9·√2 (the inset's half size): 0.8·0.9√2/(√2/60) = 43.2 → 20.
    has_label(
        f3,
        "inset: the view plane near the centre of projection, enlarged ×20",
    );
    let planes: Vec<Vec<[f64; 2]>> = f3
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Polygon {
                pts,
                pen: Pen::Given,
            } => Some(pts.clone()),
            _ => None,
        })
        .collect();
    assert_eq!(planes.len(), 2, "the view plane and its inset");
    let inset = &planes[1];
    let hi = 0.3 * 3.0 * 2f64.sqrt();
    assert!((inset[1][0] - inset[0][0] - 2.0 * hi).abs() < 1e-9);
    let centre = [
        (inset[0][0] + inset[2][0]) / 2.0,
        (inset[0][1] + inset[2][1]) / 2.0,
    ];
    let zoomed = [centre[0], centre[1] + 20.0 * -(2f64.sqrt()) / 60.0];
    assert_eq!(dots(f3, Pen::Kept).len(), 1, "the image only in the inset");
    assert!(near(dots(f3, Pen::Kept)[0], zoomed));
    has_label(f3, "A''");
    has_label(f3, "A = (0, −1, −3√2)");
    has_label(f3, "z = d = −0.1");
    // Side view (−z, y): the projector from (0, 0) to (3√2, −1) passes
    // through the image (0.1, −√2/60): similar triangles, yp/d = y/z.
    let s = segments(side, Pen::Tried);
    assert_eq!(s.len(), 2, "the projector, and its start in the inset");
    assert!(near(s[0].0, [0.0, 0.0]) && near(s[0].1, [3.0 * 2f64.sqrt(), -1.0]));
    assert!(on_segment([0.1, -(2f64.sqrt()) / 60.0], s[0].0, s[0].1));
    // The legs: y of the point (black) in the side view, yp of the image
    // (blue) in the inset under it, enlarged m times uniformly (so the
    // small triangle keeps its shape): m = the largest 1, 2, 5·10^k ≤
    // 0.9·(hi − lo)/(1.5·0.1) with lo = 0, hi = 3√2: 25.5 → 20.
    let (leg, small) = (segments(side, Pen::Frame), segments(side, Pen::Kept));
    let z = 3.0 * 2f64.sqrt();
    assert!(leg
        .iter()
        .any(|l| near(l.0, [z, 0.0]) && near(l.1, [z, -1.0])));
    let yp = -(2f64.sqrt()) / 60.0;
    assert_eq!(small.len(), 1);
    let (foot, img) = small[0];
    // The leg is vertical, 20·|yp| long, on the inset's plane line, at
    // 20·0.1 = 2 to the right of the inset's centre of projection.
    assert!((foot[0] - img[0]).abs() < 1e-9 && (img[1] - foot[1] - 20.0 * yp).abs() < 1e-9);
    let plane_line = segments(side, Pen::Given);
    assert!(plane_line.iter().any(|(a, b)| on_segment(img, *a, *b)));
    let cops = dots(side, Pen::Frame);
    assert!(cops
        .iter()
        .any(|c| (foot[0] - c[0] - 2.0).abs() < 1e-9 && (foot[1] - c[1]).abs() < 1e-9));
    has_label(side, "z = d = −0.1 (×20)");
    // The inset's projector runs from its centre through the image.
    assert!(on_segment(img, s[1].0, s[1].1));
    has_label(side, "A: y = −1, z = −3√2 ≈ −4.243");
    has_label(side, "A'': yp = −√2/60 ≈ −0.02357");
    has_label(side, "yp/d = y/z  ⇒  yp = d·y/z");
    // The view plane: the image at (0, −√2/60).
    let images = dots(plane, Pen::Kept);
    assert!(images.len() == 1 && near(images[0], [0.0, yp]));
    has_label(plane, "A'' = (0, −√2/60)");
    same_marks_in_tikz(&d[0]);
}

/// The general form: centre (0, 0, 5), plane z = 0, A = (1, 2, −3). By
/// hand: xp = x·(zprp − zvp)/(zprp − z) = 1·5/8 = 5/8, yp = 2·5/8 = 5/4.
/// The image (5/8, 5/4, 0) lies between the centre and A.
#[test]
fn project_general_form_projector() {
    let d = drawn(&[
        "project", "--cop", "5", "--plane", "0", "--point", "A=1,2,-3",
    ]);
    let f3 = &d[0].panels[0];
    let proj = segments(f3, Pen::Tried);
    assert!(
        near(proj[0].0, cabinet([0.0, 0.0, 5.0])) && near(proj[0].1, cabinet([1.0, 2.0, -3.0]))
    );
    assert!(on_segment(
        cabinet([0.625, 1.25, 0.0]),
        proj[0].0,
        proj[0].1
    ));
    has_label(&d[0].panels[2], "A'' = (5/8, 5/4) = (0.625, 1.25)");
    let svg = svg_of(
        "project.svg",
        &[
            "project", "--cop", "5", "--plane", "0", "--point", "A=1,2,-3",
        ],
    );
    let texts = check_svg(&svg);
    assert!(
        texts.iter().any(|t| t == "yp/(zprp − zvp) = y/(zprp − z)"),
        "{texts:?}"
    );
}

// ---- window ----

/// fovy = 90°, aspect 2, near 1, far 3, viewport 200×100, A = (0.5, 0.5).
/// By hand: top = near·tan(45°) = 1, right = aspect·top = 2, so the near
/// window's corners are (±2, ±1, −1); far_top = 3·tan 45° = 3, far_right =
/// 6, corners (±6, ±3, −3) (far/near = 3: drawn to scale). A's pixel:
/// px = (0.5 − (−2))/4·200 = 125, py = (0.5 − (−1))/2·100 = 75.
#[test]
fn window_frustum_side_view_and_viewport() {
    let d = drawn(&[
        "window",
        "--fovy",
        "90",
        "--aspect",
        "2",
        "--near",
        "1",
        "--far",
        "3",
        "--viewport",
        "200x100",
        "--point",
        "A=0.5,0.5",
    ]);
    let p = &d[0].panels;
    assert_eq!(p.len(), 4, "frustum, side view, near window, viewport");
    let polygon = |f: &Figure, pen: Pen| -> Vec<Vec<[f64; 2]>> {
        f.items
            .iter()
            .filter_map(|i| match i {
                Item::Polygon { pts, pen: q } if *q == pen => Some(pts.clone()),
                _ => None,
            })
            .collect()
    };
    let corners = |r: f64, t: f64, z: f64| -> Vec<[f64; 2]> {
        vec![
            cabinet([-r, -t, z]),
            cabinet([r, -t, z]),
            cabinet([r, t, z]),
            cabinet([-r, t, z]),
        ]
    };
    assert_eq!(polygon(&p[0], Pen::Kept), vec![corners(2.0, 1.0, -1.0)]);
    assert_eq!(polygon(&p[0], Pen::Given), vec![corners(6.0, 3.0, -3.0)]);
    // The edges run from the eye to the far corners.
    let edges = segments(&p[0], Pen::Frame);
    assert_eq!(edges.len(), 4);
    for (e, c) in edges.iter().zip(corners(6.0, 3.0, -3.0)) {
        assert!(near(e.0, [0.0, 0.0]) && near(e.1, c));
    }
    has_label(&p[0], "top = 1");
    has_label(&p[0], "right = 2");
    has_label(&p[0], "far = 3, far_top = 3");
    // Side view: the near window from (1, −1) to (1, 1); the fovy arc ends
    // on the lines y = ±x (half of 90° each side).
    assert_eq!(segments(&p[1], Pen::Kept), vec![([1.0, -1.0], [1.0, 1.0])]);
    let arc = p[1]
        .items
        .iter()
        .find_map(|i| match i {
            Item::Path { pts, .. } => Some(pts.clone()),
            _ => None,
        })
        .expect("the fovy arc");
    let (a, b) = (arc[0], arc[arc.len() - 1]);
    assert!((a[1] + a[0]).abs() < 1e-12 && (b[1] - b[0]).abs() < 1e-12 && a[0] > 0.0);
    has_label(&p[1], "fovy = 90°");
    has_label(&p[1], "top = near·tan(fovy/2) = 1");
    // The window on the near plane, and the viewport.
    assert_eq!(dots(&p[2], Pen::Frame), vec![[0.5, 0.5]]);
    assert_eq!(dots(&p[3], Pen::Kept), vec![[125.0, 75.0]]);
    has_label(&p[3], "A = (125, 75)");
    same_marks_in_tikz(&d[0]);
}

// ---- shade ----

/// L = (0, 0, 1), N = (0, 1, 1)/√2, V = (0, 0, 1). By hand:
/// cos α = L·N = √2/2 (α = 45°); R = 2(L·N)N − L = √2·(0, √2/2, √2/2) −
/// (0, 0, 1) = (0, 1, 0); cos β = R·V = 0 (β = 90°). Every vector is
/// drawn 1.5 long from the surface point; Blinn adds H = norm(L + V) =
/// (0, 0, 1).
#[test]
fn shade_vectors_and_angles() {
    let base = [
        "shade", "--light", "0,0,1", "--normal", "0,1,1", "--view", "0,0,1", "--color", "1,1,0",
    ];
    let f = only(&base);
    let o = [0.0, 0.0];
    let n = arrows(&f, Pen::Frame);
    let h = 2f64.sqrt() / 2.0 * 1.5;
    assert_eq!(n, vec![(o, cabinet([0.0, h, h]))]);
    assert_eq!(arrows(&f, Pen::Given), vec![(o, cabinet([0.0, 0.0, 1.5]))]);
    // V = L: both drawn, V beside L, moved 0.075 perpendicular on the page
    // (L's page direction is (−k, −k)/(√2·k) with k = 1/(2√2), so the
    // perpendicular is (1, −1)/√2).
    let s = 0.075 / 2f64.sqrt();
    let v = arrows(&f, Pen::Vector);
    assert_eq!(v.len(), 1);
    let l = cabinet([0.0, 0.0, 1.5]);
    assert!(
        near(v[0].0, [s, -s]) && near(v[0].1, [l[0] + s, l[1] - s]),
        "{v:?}"
    );
    has_label(&f, "L = V = (0, 0, 1)");
    has_label(&f, "L, V: coincide; drawn side by side");
    assert_eq!(arrows(&f, Pen::Other), vec![(o, cabinet([0.0, 1.5, 0.0]))]);
    assert!(arrows(&f, Pen::Tried).is_empty(), "no H for Phong");
    for want in [
        "N = (0, √2/2, √2/2)",
        "R = (0, 1, 0)",
        "α: cos α = √2/2 ≈ 0.7071 (α = 45°)",
        "β: cos β = 0 (β = 90°)",
    ] {
        has_label(&f, want);
    }
    // The α arc runs from along L to along N (radius 0.45·1.5).
    let arcs: Vec<Vec<[f64; 2]>> = f
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Path { pts, .. } => Some(pts.clone()),
            _ => None,
        })
        .collect();
    assert_eq!(arcs.len(), 2);
    let r = 0.45 * 1.5;
    assert!(near(arcs[0][0], cabinet([0.0, 0.0, r])));
    let s = r * 2f64.sqrt() / 2.0;
    assert!(near(*arcs[0].last().unwrap(), cabinet([0.0, s, s])));
    let blinn = only(&[&base[..], &["--model", "blinn"]].concat());
    // H = L = V here too: the third of them, moved twice as far.
    let h = arrows(&blinn, Pen::Tried);
    assert!(
        h.len() == 1 && near(h[0].0, [0.15 / 2f64.sqrt(), -0.15 / 2f64.sqrt()]),
        "{h:?}"
    );
    has_label(&blinn, "L = V = H = (0, 0, 1)");
    let svg = svg_of("shade.svg", &[&base[..], &["--model", "blinn"]].concat());
    let texts = check_svg(&svg);
    assert!(
        texts.iter().any(|t| t == "L = V = H = (0, 0, 1)"),
        "{texts:?}"
    );
    same_marks_in_tikz(&drawn(&base)[0]);
}

/// The text's triangle window: top = 0.1·tan 22.5° = (√2 − 1)/10, right =
/// 2·top = (√2 − 1)/5; far = 10 is 100 times near, so the far window is
/// not drawn to scale (the label says so) and the edges run on dashed.
#[test]
fn window_labels_of_the_triangle_example() {
    let d = drawn(&["solve", "problems/text-triangle.toml"]);
    let parts: Vec<&str> = d.iter().map(|x| x.part.as_str()).collect();
    assert_eq!(parts, ["view", "project", "window"]);
    let f = &d[2].panels[0];
    has_label(f, "top = (√2−1)/10 ≈ 0.04142");
    has_label(f, "right = (√2−1)/5 ≈ 0.08284");
    has_label(f, "far = 10, far_top = 10√2−10 ≈ 4.142");
    has_label(f, "(far window not to scale)");
    assert_eq!(segments(f, Pen::Cut).len(), 4);
    // The viewport part's pixels: B'' = (1/50, −√2/50) on a window of
    // width 2(√2−1)/5 gives px = (1/50 + (√2−1)/5)/(2(√2−1)/5)·200
    // = 100 + 10/(√2−1) = 110 + 10√2.
    let vp = d[2].panels.last().unwrap();
    assert!(
        labels(vp).iter().any(|l| l.starts_with("B = (110+10√2, ")),
        "{:?}",
        labels(vp)
    );
}

/// The labels of the figures README shows (the text's three worked
/// examples, in both languages) do not overlap one another and stay on the
/// 600 px page.
#[test]
fn labels_of_the_worked_examples_do_not_overlap() {
    use grafika::report::figure::layout::lay_out;
    for lang in [Lang::En, Lang::Id] {
        for file in ["camera", "triangle", "clip"] {
            let path = format!("problems/text-{file}.toml");
            for d in drawn_in(lang, &["solve", &path]) {
                for (k, f) in d.panels.iter().enumerate() {
                    let boxes: Vec<_> = lay_out(f)
                        .labels
                        .iter()
                        .map(|p| (p.bounds(), p.text.clone()))
                        .collect();
                    for (i, (a, ta)) in boxes.iter().enumerate() {
                        assert!(
                            a.0 >= 0.0 && a.1 <= 600.0,
                            "{file} {} panel {k}: {ta:?} leaves the page",
                            d.part
                        );
                        for (b, tb) in &boxes[..i] {
                            let apart = a.1 <= b.0 || a.0 >= b.1 || a.3 <= b.2 || a.2 >= b.3;
                            assert!(apart, "{file} {} panel {k}: {ta:?} overlaps {tb:?}", d.part);
                        }
                    }
                }
            }
        }
    }
}

/// Two lights (problems/shade-two-lights.toml): a directional light along
/// (0, 0, 1) and a point light at (0, 3, 4) seen from the surface point at
/// the origin, so its L = (0, 3, 4)/5 = (0, 3/5, 4/5), drawn as L2.
#[test]
fn shade_with_two_lights_draws_each_l() {
    let d = drawn(&["solve", "problems/shade-two-lights.toml"]);
    let f = &d[0].panels[0];
    // N, L and V coincide (all (0, 0, 1)): one label, three arrows.
    has_label(f, "N = L = V = (0, 0, 1)");
    has_label(f, "N, L, V: coincide; drawn side by side");
    has_label(f, "L2 = (0, 3/5, 4/5)");
    let given = arrows(f, Pen::Given);
    assert!(given
        .iter()
        .any(|(a, b)| near(*a, [0.0, 0.0]) && near(*b, cabinet([0.0, 0.9, 1.2]))));
}

/// The orthographic projection: A = (1, 2, −3) goes to (1, 2, 0) along a
/// projector parallel to z (no centre of projection).
#[test]
fn project_orthographic_projector_is_parallel_to_z() {
    let d = drawn(&["project", "--ortho", "--point", "A=1,2,-3"]);
    let f3 = &d[0].panels[0];
    assert_eq!(
        segments(f3, Pen::Tried),
        vec![(cabinet([1.0, 2.0, -3.0]), cabinet([1.0, 2.0, 0.0]))]
    );
    has_label(&d[0].panels[1], "yp = y");
}

// ---- solve ----

/// `solve --figure T.svg` writes one file per part, T-1-view.svg, …, and
/// none at all when one of them exists.
#[test]
fn solve_writes_one_figure_per_part_and_never_overwrites() {
    let dir = std::env::temp_dir().join(format!("grafika-solvefig-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let t = dir.join("t.svg");
    let run = || {
        let mut c = Command::cargo_bin("grafika").unwrap();
        c.args(["solve", "problems/text-triangle.toml", "--figure"])
            .arg(&t);
        c
    };
    run().assert().success();
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["t-1-view.svg", "t-2-project.svg", "t-3-window.svg"]);
    for n in &names {
        check_svg(&std::fs::read_to_string(dir.join(n)).unwrap());
    }
    std::fs::remove_file(dir.join("t-1-view.svg")).unwrap();
    let err = run().assert().code(2);
    let err = String::from_utf8_lossy(&err.get_output().stderr).to_string();
    assert!(err.contains("t-2-project.svg already exists"), "{err}");
    assert!(
        !dir.join("t-1-view.svg").exists(),
        "nothing is written when one exists"
    );
    // The clip example: one part.
    let c = dir.join("c.svg");
    Command::cargo_bin("grafika")
        .unwrap()
        .args(["solve", "problems/text-clip.toml", "--figure"])
        .arg(&c)
        .assert()
        .success();
    assert!(dir.join("c-1-clip.svg").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The figures README shows are what README's commands write today
/// (docs/images/, byte for byte).
#[test]
fn readme_figures_are_what_the_commands_write() {
    let dir = std::env::temp_dir().join(format!("grafika-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let run = |args: &[&str], file: &str| {
        Command::cargo_bin("grafika")
            .unwrap()
            .env_remove("GRAFIKA_LANG")
            .env_remove("LC_ALL")
            .env_remove("LC_MESSAGES")
            .env("LANG", "C")
            .args(args)
            .arg("--figure")
            .arg(dir.join(file))
            .assert()
            .success();
    };
    run(
        &[
            "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
        ],
        "clip.svg",
    );
    run(&["solve", "problems/text-camera.toml"], "camera.svg");
    run(&["solve", "problems/text-triangle.toml"], "triangle.svg");
    for f in [
        "clip.svg",
        "camera-1-view.svg",
        "triangle-1-view.svg",
        "triangle-2-project.svg",
        "triangle-3-window.svg",
    ] {
        let now = std::fs::read_to_string(dir.join(f)).unwrap();
        let shown = std::fs::read_to_string(format!("docs/images/{f}")).unwrap();
        assert!(
            now == shown,
            "docs/images/{f} is stale: rerun README's command"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
