//! Figures: what each figure shows, read back from the SVG it writes (the
//! named marks: `data-name`, `data-kind`, `data-for`), checked against
//! values worked by hand (derivations in the comments): the shading
//! diagram at true angles, camera axes that read, the eye outside the near
//! window, a complete clip box, every label beside its own mark in both
//! languages; the description's other facts (projectors, windows); the
//! TikZ picture carries the same marks; files are never overwritten.

use assert_cmd::Command;
use clap::Parser;
use grafika::cli::args::Cli;
use grafika::report::figure::layout::{text_width, ASCENT, DESCENT};
use grafika::report::figure::{
    drawings::drawings, svg::to_svg, tikz::to_tikz, Drawing, Figure, Item, Kind, Mark, Pen, Shape,
};
use grafika::report::lang::Lang;
use grafika::report::Style;
use grafika::tutor::generate::{self, Difficulty, Topic};
use proptest::prelude::*;

// ---- reading a figure back ----

/// The shipped problem files (`problems/*.toml`) whose name starts with
/// `prefix`, sorted, as paths from the repository.
fn shipped(prefix: &str) -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir("problems")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(prefix))
        })
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    files.sort();
    files
}

/// The drawings of a command line (`grafika` is prepended), with exact
/// forms, as the command line writes them.
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

/// One mark read back from the SVG, in px of the whole picture (y down).
#[derive(Debug, Clone)]
struct M {
    name: String,
    kind: String,
    /// Its points: a line's tail then tip, a polygon's corners, a dot's
    /// centre; the box's edges two by two.
    pts: Vec<(f64, f64)>,
    /// The box's edges that are dashed (hidden), by index.
    dashed: Vec<bool>,
    /// Whether it is drawn (a face of the box is not).
    stroked: bool,
    /// Whether it is a line with a head at its tip (`marker-end`).
    head: bool,
}

/// One text read back: its kind (`label`, `note`, `title`), the mark it
/// names, the text and its estimated box (left, right, top, bottom).
#[derive(Debug, Clone)]
struct T {
    kind: String,
    of: String,
    text: String,
    bx: (f64, f64, f64, f64),
}

/// One panel read back.
#[derive(Debug, Default)]
struct P {
    title: String,
    desc: String,
    marks: Vec<M>,
    texts: Vec<T>,
}

impl P {
    fn mark(&self, name: &str) -> &M {
        self.marks
            .iter()
            .find(|m| m.name == name)
            .unwrap_or_else(|| panic!("no mark {name:?} in {:?}", self.title))
    }
    fn has(&self, name: &str) -> bool {
        self.marks.iter().any(|m| m.name == name)
    }
    /// The page direction (y up) of an arrow, tail to tip.
    fn dir(&self, name: &str) -> (f64, f64) {
        let p = &self.mark(name).pts;
        (p[1].0 - p[0].0, p[0].1 - p[1].1)
    }
    fn label(&self, of: &str) -> Option<&str> {
        self.texts
            .iter()
            .find(|t| t.kind == "label" && t.of == of)
            .map(|t| t.text.as_str())
    }
    /// The notes' lines joined by spaces (a long note is broken into
    /// lines between words).
    fn notes(&self) -> String {
        let n = self.texts.iter().filter(|t| t.kind == "note");
        n.map(|t| t.text.as_str()).collect::<Vec<_>>().join(" ")
    }
}

fn nums(s: &str) -> Vec<f64> {
    s.split([' ', ','])
        .filter(|x| !x.is_empty())
        .map(|x| x.parse().expect("a number"))
        .collect()
}

/// The panels of an SVG, read back from its named marks and texts.
fn read_svg(svg: &str) -> Vec<P> {
    let doc = roxmltree::Document::parse(svg).expect("SVG parses as XML");
    let num = |n: roxmltree::Node, a: &str| -> f64 { n.attribute(a).expect(a).parse().expect(a) };
    let mut out = Vec::new();
    for g in doc
        .root_element()
        .children()
        .filter(|n| n.has_tag_name("g"))
    {
        let dy = nums(
            g.attribute("transform")
                .unwrap_or("translate(0,0)")
                .trim_start_matches("translate(")
                .trim_end_matches(')'),
        )[1];
        let child_text = |tag: &str| {
            g.children()
                .find(|c| c.has_tag_name(tag))
                .and_then(|c| c.text())
                .unwrap_or("")
                .to_string()
        };
        let mut p = P {
            title: child_text("title"),
            desc: child_text("desc"),
            ..P::default()
        };
        let line = |n: roxmltree::Node| {
            vec![
                (num(n, "x1"), num(n, "y1") + dy),
                (num(n, "x2"), num(n, "y2") + dy),
            ]
        };
        for n in g.children().filter(|n| n.is_element()) {
            let Some(kind) = n.attribute("data-kind") else {
                continue;
            };
            if n.has_tag_name("text") {
                let (x, y, text) = (
                    num(n, "x"),
                    num(n, "y") + dy,
                    n.text().unwrap_or("").to_string(),
                );
                let w = text_width(&text);
                let l = match n.attribute("text-anchor") {
                    Some("middle") => x - w / 2.0,
                    Some("end") => x - w,
                    _ => x,
                };
                let of = n.attribute("data-for").unwrap_or("").to_string();
                let bx = (l, l + w, y - ASCENT, y + DESCENT);
                p.texts.push(T {
                    kind: kind.into(),
                    of,
                    text,
                    bx,
                });
                continue;
            }
            let name = n
                .attribute("data-name")
                .expect("every mark has a data-name")
                .to_string();
            let (mut pts, mut dashed) = (Vec::new(), Vec::new());
            match n.tag_name().name() {
                "line" => pts = line(n),
                "circle" => pts = vec![(num(n, "cx"), num(n, "cy") + dy)],
                "polygon" | "polyline" => {
                    let v = nums(n.attribute("points").unwrap_or(""));
                    pts = v.chunks(2).map(|c| (c[0], c[1] + dy)).collect();
                }
                "g" => {
                    for e in n.children().filter(|e| e.has_tag_name("line")) {
                        pts.extend(line(e));
                        dashed.push(e.attribute("stroke-dasharray").is_some());
                    }
                }
                t => panic!("unexpected mark element {t}"),
            }
            let stroked = n.attribute("stroke") != Some("none");
            let head = n.attribute("marker-end").is_some();
            p.marks.push(M {
                name,
                kind: kind.into(),
                pts,
                dashed,
                stroked,
                head,
            });
        }
        out.push(p);
    }
    out
}

/// The panels of a command's (only) drawing, read back from its SVG.
fn svg_panels(lang: Lang, args: &[&str]) -> Vec<P> {
    let d = drawn_in(lang, args);
    assert_eq!(d.len(), 1, "{args:?}: one drawing");
    read_svg(&to_svg(&d[0]))
}

/// The angle between two page directions, degrees.
fn angle(a: (f64, f64), b: (f64, f64)) -> f64 {
    let c = (a.0 * b.0 + a.1 * b.1) / (a.0.hypot(a.1) * b.0.hypot(b.1));
    c.clamp(-1.0, 1.0).acos().to_degrees()
}

/// The angle between two 3D vectors, degrees.
fn angle3(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = |p: [f64; 3], q: [f64; 3]| p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    (d(a, b) / (d(a, a) * d(b, b)).sqrt())
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

/// The angle an arc spans about `centre`, from its first point to its
/// last, degrees.
fn arc_angle(p: &P, arc: &str, centre: (f64, f64)) -> f64 {
    let pts = &p.mark(arc).pts;
    let (a, b) = (pts[0], pts[pts.len() - 1]);
    angle(
        (a.0 - centre.0, centre.1 - a.1),
        (b.0 - centre.0, centre.1 - b.1),
    )
}

// ---- the marks are named (docs/spec.md §4) ----

/// Every mark of every figure of the text's examples is an element with
/// a `data-name` and one of the kinds; every label names a mark of its
/// panel; an arrow's line runs from its tail to its tip (the head is at
/// x2, y2: `marker-end`).
#[test]
fn every_mark_is_named_and_every_label_names_a_mark() {
    const KINDS: [&str; 8] = [
        "arrow", "point", "segment", "plane", "box", "arc", "axis", "window",
    ];
    for file in [
        "text-camera",
        "text-triangle",
        "text-clip",
        "shade-blinn-local",
    ] {
        for d in drawn(&["solve", &format!("problems/{file}.toml")]) {
            let svg = to_svg(&d);
            for p in read_svg(&svg) {
                for m in &p.marks {
                    assert!(KINDS.contains(&m.kind.as_str()), "{file}: kind {}", m.kind);
                }
                let names: Vec<&str> = p.marks.iter().map(|m| m.name.as_str()).collect();
                for (i, n) in names.iter().enumerate() {
                    assert!(!names[..i].contains(n), "{file}: two marks named {n}");
                }
                for t in p.texts.iter().filter(|t| t.kind == "label") {
                    assert!(
                        names.contains(&t.of.as_str()),
                        "{file}: {t:?} names no mark"
                    );
                }
            }
            for line in svg.lines().filter(|l| l.contains(r#"data-kind="arrow""#)) {
                assert!(
                    line.starts_with("<line ") && line.contains("marker-end"),
                    "{line}"
                );
            }
        }
    }
}

// ---- shading as the text draws it ----

/// README's example: L = (0, 0, 1), N = (0, 1, 1)/√2, V = (0, 0, 1). By
/// hand: cos α = L·N = √2/2, α = 45°; R = 2(L·N)N − L = (0, 1, 0), at 45°
/// from N on the other side; cos β = R·V = 0, β = 90°. All four lie in
/// the plane x = 0, so the diagram is that plane: N straight up, L 45° to
/// its left, R 45° to its right, V along L (drawn beside it, parallel).
#[test]
fn shading_diagram_of_the_readme_example_at_true_angles() {
    let args = [
        "shade", "--light", "0,0,1", "--normal", "0,1,1", "--view", "0,0,1", "--color", "1,1,0",
    ];
    for lang in [Lang::En, Lang::Id] {
        let p = &svg_panels(lang, &args)[0];
        let (n, l, r, v) = (p.dir("N"), p.dir("L"), p.dir("R"), p.dir("V"));
        assert!(n.0.abs() < 0.05 && n.1 > 0.0, "N straight up: {n:?}");
        assert!(l.0 < 0.0 && r.0 > 0.0, "L on the left, R on the right");
        for (a, b, want) in [
            (l, n, 45.0),
            (r, n, 45.0),
            (l, r, 90.0),
            (r, v, 90.0),
            (l, v, 0.0),
        ] {
            assert!((angle(a, b) - want).abs() < 1.5, "{a:?} {b:?}: {want}");
        }
        // The surface is a line across, perpendicular to N.
        let s = &p.mark("surface").pts;
        assert!((s[0].1 - s[1].1).abs() < 0.05 && (s[1].0 - s[0].0).abs() > 100.0);
        // The arcs at true size, about the surface point.
        let o = p.mark("surface point").pts[0];
        assert!((arc_angle(p, "α", o) - 45.0).abs() < 1.5);
        assert!((arc_angle(p, "β", o) - 90.0).abs() < 1.5);
        let (alpha, beta) = (p.label("α").unwrap(), p.label("β").unwrap());
        assert_eq!((alpha, beta), ("α = 45°", "β = 90°"));
        let notes = p.notes();
        let id = lang == Lang::Id;
        let coincide = if id {
            "L, V: berimpit; digambar berdampingan"
        } else {
            "L, V: coincide; drawn side by side"
        };
        assert!(notes.contains(coincide), "{notes:?}");
        let cos = if id {
            "cos α = √2/2 ≈ 0,7071"
        } else {
            "cos α = √2/2 ≈ 0.7071"
        };
        assert!(notes.contains(cos), "{notes:?}");
    }
}

/// The vectors N, L and V of the steps (the first of each name).
fn step_vec(args: &[&str], name: &str) -> Option<[f64; 3]> {
    let mut all = vec!["grafika"];
    all.extend_from_slice(args);
    let report = grafika::cli::run(&Cli::try_parse_from(all).unwrap()).unwrap();
    let json = serde_json::to_value(report.to_json(Lang::En)).unwrap();
    json["steps"].as_array()?.iter().find_map(|s| {
        let v = s["result"][name].as_array()?;
        Some([
            v.first()?.as_f64()?,
            v.get(1)?.as_f64()?,
            v.get(2)?.as_f64()?,
        ])
    })
}

/// The angles between the vectors drawn in a plane-of-incidence panel
/// agree with their true angles within 1.5°, R = 2(L·N)N − L and
/// H = norm(L + V) worked here; V and H are drawn there only when they lie
/// in the plane of N and L.
fn true_angles(p: &P, n: [f64; 3], l: [f64; 3], v: Option<[f64; 3]>, what: &str) {
    let d = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let u = |a: [f64; 3]| a.map(|c| c / d(a, a).sqrt());
    let (n, l) = (u(n), u(l));
    let r = [0, 1, 2].map(|k| 2.0 * d(l, n) * n[k] - l[k]);
    let mut truth = vec![("N", n), ("L", l), ("R", r)];
    if let Some(v) = v.map(u) {
        let m = [
            n[1] * l[2] - n[2] * l[1],
            n[2] * l[0] - n[0] * l[2],
            n[0] * l[1] - n[1] * l[0],
        ];
        let off = d(v, m).abs() / d(m, m).sqrt().max(1e-300);
        let in_plane = d(m, m) < 1e-18 || off < 1e-9;
        assert_eq!(
            p.has("V"),
            in_plane,
            "{what}: V drawn in the plane iff it lies in it"
        );
        if in_plane {
            truth.push(("V", v));
            if p.has("H") {
                truth.push(("H", u([0, 1, 2].map(|k| l[k] + v[k]))));
            }
        }
    }
    for (i, (a, va)) in truth.iter().enumerate() {
        for (b, vb) in &truth[..i] {
            let (want, got) = (angle3(*va, *vb), angle(p.dir(a), p.dir(b)));
            assert!(
                (want - got).abs() < 1.5,
                "{what}: {a}–{b} drawn {got}°, true {want}°"
            );
        }
    }
}

/// Every shipped lighting problem: each light's panel shows its N, L, R
/// (and V, H in the plane) at their true angles.
#[test]
fn shading_diagrams_of_the_shipped_problems_at_true_angles() {
    let files = shipped("shade-");
    assert!(files.len() >= 12);
    for f in files {
        let args = ["solve", f.as_str()];
        let (n, v) = (step_vec(&args, "N").unwrap(), step_vec(&args, "V"));
        let panels = read_svg(&to_svg(&drawn(&args)[0]));
        let first = panels
            .iter()
            .find(|p| p.has("surface"))
            .expect("a plane of incidence");
        true_angles(first, n, step_vec(&args, "L").unwrap(), v, &f);
    }
}

/// The angles a report's steps name, in the figure's names: each step
/// whose result holds `cos α` names α (α2, α3, … for the second, third
/// light: the steps are in the lights' order), `cos β` names β, and
/// Blinn's `N·H` names N·H.
fn angles_named(report: &grafika::tutor::solution::Report) -> Vec<String> {
    let json = serde_json::to_value(report.to_json(Lang::En)).unwrap();
    let mut steps = Vec::new();
    fn walk<'a>(v: &'a serde_json::Value, out: &mut Vec<&'a serde_json::Value>) {
        match v {
            serde_json::Value::Object(m) => {
                if let Some(serde_json::Value::Array(s)) = m.get("steps") {
                    out.extend(s.iter());
                }
                m.values().for_each(|x| walk(x, out));
            }
            serde_json::Value::Array(a) => a.iter().for_each(|x| walk(x, out)),
            _ => {}
        }
    }
    walk(&json, &mut steps);
    let (mut a, mut b) = (0, 0);
    let mut out = Vec::new();
    let tag = |k: usize| if k == 1 { String::new() } else { k.to_string() };
    for s in steps {
        let r = &s["result"];
        if !r["cos α"].is_null() {
            a += 1;
            out.push(format!("α{}", tag(a)));
        }
        if !r["cos β"].is_null() {
            b += 1;
            out.push(format!("β{}", tag(b)));
        }
        if !r["N·H"].is_null() {
            out.push("N·H".into());
        }
    }
    out
}

/// Every angle the steps name has its arc in the figure: the shipped
/// lighting problems (shade-blinn-local's α = 0°, L along N, drawn as a
/// short arc across the two arrows side by side), the shading command
/// lines above and generated lighting exams at every difficulty.
#[test]
fn every_angle_the_steps_name_has_its_arc() {
    let files = shipped("shade-");
    let mut reports: Vec<(String, grafika::tutor::solution::Report)> = Vec::new();
    let mut runs: Vec<Vec<String>> = files
        .iter()
        .map(|f| vec!["solve".into(), f.clone()])
        .collect();
    runs.extend(
        COMMANDS
            .iter()
            .filter(|c| c[0] == "shade")
            .map(|c| c.iter().map(|a| a.to_string()).collect()),
    );
    for args in runs {
        let mut all = vec!["grafika".to_string()];
        all.extend(args.iter().cloned());
        let cli = Cli::try_parse_from(all).expect("arguments parse");
        reports.push((format!("{args:?}"), grafika::cli::run(&cli).unwrap()));
    }
    for level in Difficulty::ALL {
        for (k, g) in generate::exam(&[Topic::Shade], level, 4, 11)
            .unwrap()
            .into_iter()
            .enumerate()
        {
            reports.push((format!("{level:?} #{k}"), g.report));
        }
    }
    let mut arcs = 0;
    for (what, report) in &reports {
        let named = angles_named(report);
        assert!(!named.is_empty(), "{what}: no angle named");
        for lang in [Lang::En, Lang::Id] {
            let drawn: Vec<String> = drawings(report, &Style::new(4, true, lang))
                .iter()
                .flat_map(|d| read_svg(&to_svg(d)))
                .flat_map(|p| p.marks)
                .filter(|m| m.kind == "arc")
                .map(|m| m.name)
                .collect();
            for a in &named {
                assert!(drawn.contains(a), "{what} {lang:?}: no arc {a}: {drawn:?}");
                arcs += 1;
            }
        }
    }
    assert!(arcs > 60, "{arcs} arcs");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]
    /// Random N and L, with V in their plane (V = a·N + b·L): the diagram
    /// draws N, L, R and V at their true angles.
    #[test]
    fn random_shading_in_the_plane_at_true_angles(
        n in prop::array::uniform3(-4i32..=4),
        l in prop::array::uniform3(-4i32..=4),
        (a, b) in (-3i32..=3, -3i32..=3),
    ) {
        let (nf, lf) = (n.map(f64::from), l.map(f64::from));
        let v = [0, 1, 2].map(|k| f64::from(a) * nf[k] + f64::from(b) * lf[k]);
        let d = |p: [f64; 3], q: [f64; 3]| p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
        prop_assume!(d(nf, nf) > 0.0 && d(lf, lf) > 0.0 && d(v, v) > 0.0);
        let s = |x: [f64; 3]| format!("{},{},{}", x[0], x[1], x[2]);
        let (sn, sl, sv) = (s(nf), s(lf), s(v));
        let args = ["shade", "--normal", &sn, "--light", &sl, "--view", &sv, "--color", "1,1,1"];
        let p = &svg_panels(Lang::En, &args)[0];
        true_angles(p, nf, lf, Some(v), &format!("{args:?}"));
    }
}

/// V out of the plane of N and L: N = (0, 0, 1), L = (1, 0, 1)/√2 (the
/// plane y = 0), V = (0, 1, 1)/√2 leaves it by asin(V·(0, 1, 0)) = 45°.
/// It is not drawn there (a note says so); a second panel draws R and V in
/// their own plane at the true β: R = (−1, 0, 1)/√2, cos β = R·V = 1/2,
/// β = 60°.
#[test]
fn a_view_vector_out_of_the_plane_gets_its_own_panel() {
    let args = [
        "shade", "--normal", "0,0,1", "--light", "1,0,1", "--view", "0,1,1", "--color", "1,1,1",
    ];
    let p = svg_panels(Lang::En, &args);
    assert_eq!(p.len(), 2);
    assert!(!p[0].has("V"));
    let note = "V is not in this plane (it leaves it by 45°): drawn in its own plane below";
    assert!(p[0].notes().contains(note), "{:?}", p[0].notes());
    assert_eq!(p[1].title, "The plane of R and V (β)");
    assert!((angle(p[1].dir("R"), p[1].dir("V")) - 60.0).abs() < 1.5);
    let o = p[1].mark("surface point").pts[0];
    assert!((arc_angle(&p[1], "β", o) - 60.0).abs() < 1.5);
    let id = svg_panels(Lang::Id, &args);
    let catatan = "V tidak terletak pada bidang ini (menyimpang 45°): digambar pada bidangnya sendiri di bawah";
    assert!(id[0].notes().contains(catatan), "{:?}", id[0].notes());
}

// ---- camera axes that read ----

/// The page direction of a 3D direction in the view the description
/// states: azimuth az and elevation el give w = (cos el sin az, sin el,
/// cos el cos az), right = (cos az, 0, −sin az), up = w × right; y up.
fn stated(desc: &str, d: [f64; 3]) -> (f64, f64) {
    let grab = |key: &str| -> f64 {
        let at = desc
            .find(key)
            .unwrap_or_else(|| panic!("{key} not in {desc}"))
            + key.len();
        let n: String = desc[at..].chars().take_while(|c| *c != '°').collect();
        n.replace('−', "-")
            .replace(',', ".")
            .trim()
            .parse()
            .unwrap()
    };
    let (az, el) = match desc.contains("azimuth") {
        true => (grab("azimuth "), grab("elevation ")),
        false => (grab("azimut "), grab("elevasi ")),
    };
    let (az, el) = (az.to_radians(), el.to_radians());
    let (sa, ca, se, ce) = (az.sin(), az.cos(), el.sin(), el.cos());
    let right = [ca, 0.0, -sa];
    let up = [-se * sa, ce, -se * ca];
    let dot = |p: [f64; 3]| p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
    (dot(right), dot(up))
}

/// u, v, n at least 15° apart on the page and none shorter than 40 % of
/// the longest, each drawn along the direction the stated view gives.
fn axes_read(p: &P, uvn: [[f64; 3]; 3], what: &str) {
    let ds = ["u", "v", "n"].map(|k| p.dir(k));
    let len = ds.map(|d| d.0.hypot(d.1));
    let longest = len.iter().cloned().fold(0.0, f64::max);
    for i in 0..3 {
        assert!(
            len[i] >= 0.4 * longest,
            "{what}: {} is {} of {longest}",
            ["u", "v", "n"][i],
            len[i]
        );
        assert!(
            angle(ds[i], stated(&p.desc, uvn[i])) < 1.0,
            "{what}: not as the stated view"
        );
        for j in 0..i {
            assert!(
                angle(ds[i], ds[j]) >= 15.0,
                "{what}: {i}, {j} only {}° apart",
                angle(ds[i], ds[j])
            );
        }
    }
}

/// The text's two cameras. Example 6.1 (by hand in the worked solution):
/// u = (0, 0, −1), v = (−3/5, 4/5, 0), n = (4/5, 3/5, 0); the triangle's
/// camera: n = (1, 0, 1)/√2, u = Vup × n = (1, 0, −1)/√2, v = (0, 1, 0).
#[test]
fn camera_axes_of_the_text_read() {
    let r = 0.5f64.sqrt();
    for (file, uvn) in [
        (
            "text-camera",
            [[0.0, 0.0, -1.0], [-0.6, 0.8, 0.0], [0.8, 0.6, 0.0]],
        ),
        (
            "text-triangle",
            [[r, 0.0, -r], [0.0, 1.0, 0.0], [r, 0.0, r]],
        ),
    ] {
        for lang in [Lang::En, Lang::Id] {
            let d = drawn_in(lang, &["solve", &format!("problems/{file}.toml")]);
            let p = &read_svg(&to_svg(&d[0]))[0];
            axes_read(p, uvn, file);
            assert!(p.desc.contains(if lang == Lang::En {
                "Axonometric view"
            } else {
                "Tampak aksonometri"
            }));
        }
    }
    let p = &svg_panels(
        Lang::En,
        &["view", "--eye", "4,4,4", "--look", "0,1,4", "--up", "0,1,0"],
    )[0];
    assert_eq!(p.label("u"), Some("u = (0, 0, −1)"));
    assert_eq!(p.label("n"), Some("n = (4/5, 3/5, 0)"));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]
    /// Random cameras: n = (Pe − Pr)/|Pe − Pr|, u = Vup × n normalized,
    /// v = n × u (worked here), drawn readable.
    #[test]
    fn random_camera_axes_read(
        pe in prop::array::uniform3(-6i32..=6),
        pr in prop::array::uniform3(-6i32..=6),
        up in prop::array::uniform3(-2i32..=2),
    ) {
        let f = |a: [i32; 3]| a.map(f64::from);
        let (pe, pr, up) = (f(pe), f(pr), f(up));
        let cross = |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        let unit = |a: [f64; 3]| { let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt(); a.map(|c| c / l) };
        let back = [0, 1, 2].map(|k| pe[k] - pr[k]);
        let side = cross(up, back);
        prop_assume!(back.iter().any(|c| *c != 0.0) && side.iter().any(|c| *c != 0.0));
        let n = unit(back);
        let u = unit(side);
        let v = cross(n, u);
        let s = |x: [f64; 3]| format!("{},{},{}", x[0], x[1], x[2]);
        let (a, b, c) = (s(pe), s(pr), s(up));
        let p = &svg_panels(Lang::En, &["basis", "--eye", &a, "--look", &b, "--up", &c])[0];
        axes_read(p, [u, v, n], &format!("{a} {b} {c}"));
    }
}

// ---- the view volume seen from outside ----

/// Whether a point lies inside a convex polygon (or on it).
fn inside(p: (f64, f64), poly: &[(f64, f64)]) -> bool {
    let mut sign = 0.0;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let c = (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0);
        if c != 0.0 && sign != 0.0 && c.signum() != sign {
            return false;
        }
        if c != 0.0 {
            sign = c.signum();
        }
    }
    true
}

/// The eye, the apex of the view volume, is outside the near window (and
/// the far one), every edge runs from it: the text's triangle (far 100
/// times near: the far window not drawn), fovy 90° with far = 3·near (to
/// scale) and random set-ups.
#[test]
fn the_eye_is_outside_the_near_window() {
    let mut cases = vec![
        vec![
            "window", "--fovy", "45", "--aspect", "2", "--near", "0.1", "--far", "10",
        ],
        vec![
            "window", "--fovy", "90", "--aspect", "2", "--near", "1", "--far", "3",
        ],
    ];
    let extra: Vec<[String; 3]> = (1..=8)
        .map(|k| {
            [
                format!("{}", 10 * k + 15),
                format!("{}", 0.5 + 0.25 * k as f64),
                format!("{}", k + 1),
            ]
        })
        .collect();
    for [fovy, aspect, far] in &extra {
        cases.push(vec![
            "window", "--fovy", fovy, "--aspect", aspect, "--near", "1", "--far", far,
        ]);
    }
    for args in cases {
        let p = &svg_panels(Lang::En, &args)[0];
        let eye = p.mark("eye").pts[0];
        for w in ["near window", "far window"] {
            if p.has(w) {
                assert!(
                    !inside(eye, &p.mark(w).pts),
                    "{args:?}: the eye inside the {w}"
                );
            }
        }
        for k in 1..=4 {
            let e = &p.mark(&format!("edge {k}")).pts;
            assert!(
                (e[0].0 - eye.0).hypot(e[0].1 - eye.1) < 0.2,
                "{args:?}: edge {k}"
            );
        }
    }
}

// ---- a clip box a student can follow ----

/// The text's example: box 0 ≤ x ≤ 3, 0 ≤ y ≤ 4, 0 ≤ z ≤ 3, P0(4, 2, 2),
/// P1(−2, 6, 1). By hand: code(P0) = 000010 (x > 3), code(P1) = 001001
/// (x < 0, y > 4); AND = 0, so each plane crossed is tried:
/// left x = 0: t = (0 − 4)/(−6) = 2/3, P = (0, 14/3, 4/3), code 001000
/// (y > 4): cut off; right x = 3: t = 1/6, P = (3, 8/3, 11/6), 000000;
/// top y = 4: t = (4 − 2)/4 = 1/2, P = (1, 4, 3/2), 000000. The kept part
/// runs from t = 1/6 to 1/2.
#[test]
fn the_clip_box_names_its_planes_codes_and_intersections() {
    let args = ["solve", "problems/text-clip.toml"];
    for (lang, words) in [
        (
            Lang::En,
            [
                "x = 0 (left)",
                "x = 3 (right)",
                "y = 0 (bottom)",
                "y = 4 (top)",
                "z = 0 (front)",
                "z = 3 (back)",
            ],
        ),
        (
            Lang::Id,
            [
                "x = 0 kiri",
                "x = 3 kanan",
                "y = 0 bawah",
                "y = 4 atas",
                "z = 0 depan",
                "z = 3 belakang",
            ],
        ),
    ] {
        let p = read_svg(&to_svg(&drawn_in(lang, &args)[0]));
        let (box3, along) = (&p[0], &p[1]);
        for a in ["x", "y", "z"] {
            assert_eq!(box3.mark(a).kind, "axis");
        }
        for (plane, want) in [
            "x = xmin", "x = xmax", "y = ymin", "y = ymax", "z = zmin", "z = zmax",
        ]
        .iter()
        .zip(words)
        {
            assert_eq!(box3.mark(plane).kind, "plane");
            assert_eq!(box3.label(plane), Some(want));
        }
        // Twelve edges; the three at the corner away from the viewer dashed.
        let b = box3.mark("box");
        assert_eq!(
            (b.pts.len(), b.dashed.iter().filter(|d| **d).count()),
            (24, 3)
        );
        assert_eq!(box3.label("P0"), Some("P0: 000010"));
        assert_eq!(box3.label("P1"), Some("P1: 001001"));
        let (kept, cut) = match lang {
            Lang::En => ("kept", "cut off"),
            Lang::Id => ("dipertahankan", "dibuang"),
        };
        let sep = if lang == Lang::En { ", " } else { "; " };
        let pt = |x: [&str; 3]| format!("({})", x.join(sep));
        let want = [
            (
                "left",
                format!(
                    "t = 2/3: {} → {}, 001000, {cut}",
                    words[0],
                    pt(["0", "14/3", "4/3"])
                ),
            ),
            (
                "right",
                format!(
                    "t = 1/6: {} → {}, 000000, {kept}",
                    words[1],
                    pt(["3", "8/3", "11/6"])
                ),
            ),
            (
                "top",
                format!(
                    "t = 1/2: {} → {}, 000000, {kept}",
                    words[3],
                    pt(["1", "4", "3/2"])
                ),
            ),
        ];
        for (key, text) in want {
            assert_eq!(along.label(key), Some(text.as_str()));
        }
        // Along the segment, t = 0 at the top and 1 at the bottom: the kept
        // part from t = 1/6 to 1/2 (a sixth and a half of the way down).
        let (top, bottom) = (along.mark("P0").pts[0].1, along.mark("P1").pts[0].1);
        let k = &along.mark("kept part").pts;
        let t = |y: f64| (y - top) / (bottom - top);
        assert!(
            (t(k[0].1) - 1.0 / 6.0).abs() < 0.01 && (t(k[1].1) - 0.5).abs() < 0.01,
            "{k:?}"
        );
    }
}

// ---- every label beside its own mark ----

/// The centre of a face of the clip box on the page (px, y down).
fn centre(m: &M) -> (f64, f64) {
    let n = m.pts.len() as f64;
    let (x, y) = m.pts.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
    (x / n, y / n)
}

/// The clip box of one panel drawn as the text's region codes read it
/// (bit 1 left x < xmin, bit 2 right x > xmax, bit 3 bottom y < ymin, bit 4
/// top y > ymax, bit 5 front z < zmin, bit 6 back z > zmax; spec §1): the
/// front face z = zmin toward the reader, the back face z = zmax away.
/// Read from the SVG alone: the corner where the three dashed (hidden)
/// edges meet is the box's corner farthest from the reader, so it is a
/// corner of the back face and not one of the front face; the right
/// face's centre lies right of the left face's on the page, the top
/// face's above the bottom face's; and the words on the faces say so.
fn clip_faces_read(p: &P, lang: Lang, what: &str) {
    let b = p.mark("box");
    let hidden: Vec<((f64, f64), (f64, f64))> = (0..12)
        .filter(|i| b.dashed[*i])
        .map(|i| (b.pts[2 * i], b.pts[2 * i + 1]))
        .collect();
    assert_eq!(hidden.len(), 3, "{what}: three hidden edges");
    let near = |a: (f64, f64), c: (f64, f64)| (a.0 - c.0).hypot(a.1 - c.1) < 0.5;
    let corner = [hidden[0].0, hidden[0].1]
        .into_iter()
        .find(|c| hidden.iter().all(|(a, e)| near(*a, *c) || near(*e, *c)))
        .unwrap_or_else(|| panic!("{what}: the hidden edges meet at no corner"));
    let has = |face: &str| p.mark(face).pts.iter().any(|q| near(*q, corner));
    assert!(
        has("z = zmax"),
        "{what}: the back face is not away from the reader"
    );
    assert!(
        !has("z = zmin"),
        "{what}: the front face is not toward the reader"
    );
    let (l, r) = (centre(p.mark("x = xmin")), centre(p.mark("x = xmax")));
    assert!(r.0 > l.0, "{what}: x = xmax is not right of x = xmin");
    let (bt, tp) = (centre(p.mark("y = ymin")), centre(p.mark("y = ymax")));
    assert!(tp.1 < bt.1, "{what}: y = ymax is not above y = ymin");
    let words = match lang {
        Lang::En => [
            "(left)", "(right)", "(bottom)", "(top)", "(front)", "(back)",
        ],
        Lang::Id => ["kiri", "kanan", "bawah", "atas", "depan", "belakang"],
    };
    let planes = [
        "x = xmin", "x = xmax", "y = ymin", "y = ymax", "z = zmin", "z = zmax",
    ];
    for (plane, word) in planes.iter().zip(words) {
        // A face's label may be written short, its text in a note.
        let text = p.label(plane).map_or_else(|| p.notes(), str::to_string);
        assert!(
            text.contains(word),
            "{what}: {plane} is not {word}: {text:?}"
        );
    }
}

/// Every clip box grafika draws (the shipped problems, README's command
/// and a segment along x, generated exams at every difficulty, both
/// languages) has its face words where the drawing puts those faces
/// ([`clip_faces_read`]).
#[test]
fn the_clip_boxs_face_words_agree_with_the_drawing() {
    let files = shipped("");
    let mut runs: Vec<Vec<String>> = files
        .iter()
        .map(|f| vec!["solve".into(), f.clone()])
        .collect();
    runs.extend(
        COMMANDS
            .iter()
            .filter(|c| c[0] == "clip")
            .map(|c| c.iter().map(|a| a.to_string()).collect()),
    );
    let mut boxes = 0;
    let mut check = |lang: Lang, what: &str, d: &Drawing| {
        for p in read_svg(&to_svg(d)).iter().filter(|p| p.has("box")) {
            clip_faces_read(p, lang, what);
            boxes += 1;
        }
    };
    for lang in [Lang::En, Lang::Id] {
        for args in &runs {
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            for d in drawn_in(lang, &args) {
                check(lang, &format!("{args:?}"), &d);
            }
        }
        for level in Difficulty::ALL {
            for (k, g) in generate::exam(&[Topic::Clip], level, 4, 7)
                .unwrap()
                .iter()
                .enumerate()
            {
                for d in drawings(&g.report, &Style::new(4, true, lang)) {
                    check(lang, &format!("{level:?} #{k}"), &d);
                }
            }
        }
    }
    assert!(boxes >= 30, "{boxes} boxes checked");
}

/// The distance from a box to a segment (0 when it crosses).
fn box_to_segment(b: (f64, f64, f64, f64), p: (f64, f64), q: (f64, f64)) -> f64 {
    if crosses(b, p, q) {
        return 0.0;
    }
    let to_point = |c: (f64, f64)| {
        let dx = (b.0 - c.0).max(c.0 - b.1).max(0.0);
        let dy = (b.2 - c.1).max(c.1 - b.3).max(0.0);
        dx.hypot(dy)
    };
    let seg = |c: (f64, f64)| {
        let (ux, uy) = (q.0 - p.0, q.1 - p.1);
        let l2 = (ux * ux + uy * uy).max(1e-300);
        let t = (((c.0 - p.0) * ux + (c.1 - p.1) * uy) / l2).clamp(0.0, 1.0);
        (c.0 - p.0 - t * ux).hypot(c.1 - p.1 - t * uy)
    };
    let corners = [(b.0, b.2), (b.1, b.2), (b.1, b.3), (b.0, b.3)];
    corners
        .iter()
        .map(|c| seg(*c))
        .fold(to_point(p).min(to_point(q)), f64::min)
}

/// Whether the segment p–q crosses the box (Liang–Barsky).
fn crosses(b: (f64, f64, f64, f64), p: (f64, f64), q: (f64, f64)) -> bool {
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (a, c) in [
        (-dx, p.0 - b.0),
        (dx, b.1 - p.0),
        (-dy, p.1 - b.2),
        (dy, b.3 - p.1),
    ] {
        if a == 0.0 {
            if c < 0.0 {
                return false;
            }
        } else if a < 0.0 {
            t0 = t0.max(c / a);
        } else {
            t1 = t1.min(c / a);
        }
    }
    t0 <= t1
}

/// The lines of a mark, two by two.
fn lines(m: &M) -> Vec<((f64, f64), (f64, f64))> {
    match m.kind.as_str() {
        "box" => m.pts.chunks(2).map(|c| (c[0], c[1])).collect(),
        _ if m.pts.len() == 1 => vec![],
        "window" | "plane" if m.pts.len() > 2 => (0..m.pts.len())
            .map(|i| (m.pts[i], m.pts[(i + 1) % m.pts.len()]))
            .collect(),
        _ => m.pts.windows(2).map(|w| (w[0], w[1])).collect(),
    }
}

/// How far a label's box is from its mark: an arrow or axis by its tip, a
/// dot by its centre, a face by its region, else by its lines.
fn distance(t: &T, m: &M) -> f64 {
    let tip = match (m.kind.as_str(), m.pts.len()) {
        ("arrow" | "axis", 2) | (_, 1) => Some(m.pts[m.pts.len() - 1]),
        _ => None,
    };
    if let Some(p) = tip {
        return box_to_segment(t.bx, p, p);
    }
    let centre = ((t.bx.0 + t.bx.1) / 2.0, (t.bx.2 + t.bx.3) / 2.0);
    if !m.stroked && inside(centre, &m.pts) {
        return 0.0;
    }
    let ls = if m.stroked {
        lines(m)
    } else {
        (0..m.pts.len())
            .map(|i| (m.pts[i], m.pts[(i + 1) % m.pts.len()]))
            .collect()
    };
    ls.iter()
        .map(|(p, q)| box_to_segment(t.bx, *p, *q))
        .fold(f64::MAX, f64::min)
}

/// The points a label may name: a dot's centre, the tip of a line with a
/// head (an arrow, an axis).
fn spots(m: &M) -> Vec<(f64, f64)> {
    match (m.kind.as_str(), m.head) {
        ("point", _) => m.pts.clone(),
        (_, true) => vec![m.pts[1]],
        _ => vec![],
    }
}

/// The ends of a mark's lines: both ends of a line (each of the box's
/// edges), an arc's first and last point, an outline's corners.
fn ends(m: &M) -> Vec<(f64, f64)> {
    match m.kind.as_str() {
        _ if !m.stroked || m.pts.len() < 2 => vec![],
        "arc" => vec![m.pts[0], m.pts[m.pts.len() - 1]],
        _ => m.pts.clone(),
    }
}

/// The distance from a box to a point.
fn box_to_point(b: (f64, f64, f64, f64), p: (f64, f64)) -> f64 {
    box_to_segment(b, p, p)
}

/// The marks a label names: its own (`data-for`) and those its text
/// names, the pieces between ` = ` and ` ≈ ` but the last that are marks'
/// names (`N = V = (0, 0, 1)` names N and V).
fn named_by<'a>(t: &'a T, p: &P) -> Vec<&'a str> {
    let mut pieces: Vec<&str> = t.text.split(" = ").flat_map(|x| x.split(" ≈ ")).collect();
    pieces.pop();
    let mut out = vec![t.of.as_str()];
    out.extend(pieces.into_iter().filter(|x| p.has(x)));
    out
}

/// What is wrong with the labels of one drawing's SVG, measured from its
/// own geometry (text extents estimated as the layout estimates them, for
/// DejaVu Sans, the widest common sans-serif font; the SVG's coordinates
/// are rounded to 0.1 px, so each bound is taken 0.5 to 1 px looser than
/// the layout's own): each label
/// - within 40 px of its own mark (a dot's centre, an arrow's or axis's
///   tip, a segment, an arc, an outline, a face);
/// - nearer its own mark than any other mark's dot or tip, by 2 px at
///   least (the marks its text names excepted: `N = V = …`, and a mark
///   drawn on its own point, which is the same place);
/// - over no dot, no line and no line's end (1.5 px clear of it);
/// - 9 px clear of every other label side by side, or 1.5 px above or
///   below (closer, `fovy = 60°` and `near = 1` read as one phrase);
///
/// and no two texts (labels, notes) overlap or leave the 600 px page.
fn label_faults(svg: &str) -> Vec<String> {
    let mut faults = Vec::new();
    let all = read_svg(svg);
    let texts: Vec<&T> = all.iter().flat_map(|p| &p.texts).collect();
    for (i, a) in texts.iter().enumerate() {
        if a.bx.0 < 0.0 || a.bx.1 > 600.0 {
            faults.push(format!("{:?} leaves the page", a.text));
        }
        for b in &texts[..i] {
            let (gx, gy) = match (a.kind.as_str(), b.kind.as_str()) {
                ("label", "label") => (9.0, 1.5),
                _ => (0.0, 0.0),
            };
            let apart = a.bx.1 + gx <= b.bx.0
                || b.bx.1 + gx <= a.bx.0
                || a.bx.3 + gy <= b.bx.2
                || b.bx.3 + gy <= a.bx.2;
            if !apart {
                faults.push(format!("{:?} runs into {:?}", a.text, b.text));
            }
        }
    }
    for p in &all {
        for t in p.texts.iter().filter(|t| t.kind == "label") {
            let m = p.mark(&t.of);
            let own = distance(t, m);
            if own > 40.0 {
                faults.push(format!("{:?} is {own:.1} px from {:?}", t.text, t.of));
            }
            let names = named_by(t, p);
            // A dot or tip drawn on the label's own point (within 1 px:
            // Pref and a point Q both at the origin) is the same place.
            let here = spots(m);
            let same_place =
                |s: (f64, f64)| here.iter().any(|q| (q.0 - s.0).hypot(q.1 - s.1) <= 1.0);
            for o in &p.marks {
                for s in spots(o) {
                    let d = box_to_point(t.bx, s);
                    if !names.contains(&o.name.as_str()) && !same_place(s) && d < own + 2.0 {
                        faults.push(format!(
                            "{:?} is {d:.1} px from {:?}, {own:.1} from its own {:?}",
                            t.text, o.name, t.of
                        ));
                    }
                }
                for e in ends(o) {
                    if box_to_point(t.bx, e) < 1.5 {
                        faults.push(format!("{:?} is over an end of {:?}", t.text, o.name));
                    }
                }
                if o.name == m.name || !o.stroked {
                    continue;
                }
                let inner = (t.bx.0 + 1.0, t.bx.1 - 1.0, t.bx.2 + 1.0, t.bx.3 - 1.0);
                if lines(o).iter().any(|(a, b)| crosses(inner, *a, *b)) {
                    faults.push(format!("{:?} crosses {:?}", o.name, t.text));
                }
            }
        }
    }
    faults
}

/// A few command lines of every calculator command with a figure, as
/// README and students write them: README's examples, the other
/// projections and lighting models, a far plane, and a student's own
/// camera with a point near Pref.
const COMMANDS: &[&[&str]] = &[
    &[
        "basis", "--eye", "3,1,3", "--look", "2,1,2", "--up", "0,1,0",
    ],
    &[
        "view",
        "--eye",
        "4,4,4",
        "--look",
        "0,1,4",
        "--up",
        "0,1,0",
        "--point",
        "Pref=0,1,4",
    ],
    &[
        "view",
        "--eye",
        "(0, 0, 5)",
        "--look",
        "0,0,0",
        "--up",
        "0,1,0",
        "--point",
        "P=0.3,0.2,0",
    ],
    &[
        "project",
        "--d",
        "-0.1",
        "--point",
        "A=0,-1,-6/sqrt(2)",
        "--point",
        "B=1/sqrt(2),-1,-5/sqrt(2)",
    ],
    &[
        "project", "--cop", "5", "--plane", "0", "--point", "A=1,2,-3",
    ],
    &[
        "project",
        "--ortho",
        "--point",
        "A=1,2,-3",
        "--point",
        "B=−1,0,−2",
    ],
    &[
        "window",
        "--fovy",
        "45",
        "--aspect",
        "2",
        "--near",
        "0,1",
        "--viewport",
        "200x100",
        "--point",
        "A=0,-sqrt(2)/60",
    ],
    &[
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
    ],
    &[
        "clip", "--min", "0,0,0", "--max", "3,4,3", "--from", "4,2,2", "--to", "-2,6,1",
    ],
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
    &[
        "shade", "--light", "0,0,1", "--normal", "0,1,1", "--view", "0,0,1", "--color", "1,1,0",
    ],
    &[
        "shade", "--model", "blinn", "--light", "1,1,1", "--normal", "0,1,0", "--view", "0,0,1",
        "--color", "1,0.5,0",
    ],
    &[
        "shade", "--normal", "0,0,1", "--light", "1,0,1", "--view", "0,1,1", "--color", "1,1,1",
    ],
];

/// Every figure grafika draws from the shipped problems (`solve`), from
/// the calculator commands above and from generated exams (every topic at
/// every difficulty, two seeds), in both languages: no label fault
/// ([`label_faults`]).
#[test]
fn labels_stand_on_their_own_marks_in_every_figure() {
    let files = shipped("");
    let mut runs: Vec<Vec<String>> = files
        .iter()
        .map(|f| vec!["solve".into(), f.clone()])
        .collect();
    runs.extend(
        COMMANDS
            .iter()
            .map(|c| c.iter().map(|a| a.to_string()).collect()),
    );
    let mut faults = Vec::new();
    let mut labels = 0;
    let mut check = |what: &str, d: &Drawing| {
        let svg = to_svg(d);
        labels += svg.matches(r#"data-kind="label""#).count();
        faults.extend(
            label_faults(&svg)
                .into_iter()
                .map(|f| format!("{what}: {f}")),
        );
    };
    for lang in [Lang::En, Lang::Id] {
        for args in &runs {
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            for d in drawn_in(lang, &args) {
                check(&format!("{lang:?} {args:?} {}", d.part), &d);
            }
        }
        for topic in Topic::ALL {
            for level in Difficulty::ALL {
                for seed in [3, 2026] {
                    for (k, g) in generate::exam(&[topic], level, 2, seed)
                        .unwrap()
                        .iter()
                        .enumerate()
                    {
                        for d in drawings(&g.report, &Style::new(4, true, lang)) {
                            check(&format!("{lang:?} {topic:?} {level:?} {seed} #{k}"), &d);
                        }
                    }
                }
            }
        }
    }
    assert!(
        faults.is_empty(),
        "{} faults:\n{}",
        faults.len(),
        faults.join("\n")
    );
    assert!(labels > 2000, "{labels} labels checked");
}

/// Every dot that a figure of a shipped problem labels keeps its label on
/// the picture, in both languages: a label that cannot stand whole is
/// written short (its mark's name), and never left out with only a note,
/// so no dot is unnamed (the inset's C″ of text-triangle, Pref and Q both
/// at the origin in view-axis-aligned, Pref at the origin among the axes
/// of view-surds, the two intersections at one corner of the box in
/// clip-cases were); and no note is only a mark's name, which says
/// nothing.
#[test]
fn every_labelled_dot_of_the_shipped_problems_keeps_its_label() {
    let files = shipped("");
    let mut faults = Vec::new();
    let mut dots = 0;
    for lang in [Lang::En, Lang::Id] {
        for f in &files {
            for d in drawn_in(lang, &["solve", f]) {
                let svg = to_svg(&d);
                let read = read_svg(&svg);
                assert_eq!(read.len(), d.panels.len(), "{f} {}", d.part);
                for (fig, p) in d.panels.iter().zip(&read) {
                    for l in fig.labels() {
                        let dot = fig
                            .marks()
                            .any(|m| m.name == l.of && matches!(m.shape, Shape::Dot(_)));
                        if !dot || l.short.as_deref() == Some("") {
                            continue;
                        }
                        dots += 1;
                        if p.label(&l.of).is_none() {
                            faults
                                .push(format!("{lang:?} {f} {:?}: {:?} unlabelled", p.title, l.of));
                        }
                    }
                    for t in p.texts.iter().filter(|t| t.kind == "note") {
                        if p.has(&t.text) {
                            faults.push(format!(
                                "{lang:?} {f} {:?}: bare note {:?}",
                                p.title, t.text
                            ));
                        }
                    }
                }
            }
        }
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
    assert!(dots > 100, "{dots} labelled dots");
}

// ---- words ----

/// Every word on a figure in the chosen language: the Indonesian figures
/// of the text's examples hold none of the English words of the figures,
/// and "clipping" is the text's word (never "Klipping").
#[test]
fn indonesian_figures_speak_indonesian() {
    let english = [
        "outcode",
        "kept",
        "cut off",
        "surface",
        "eye",
        "centre",
        "view plane",
        "coincide",
        "inset",
        "(left)",
        "(right)",
        "(top)",
        "(back)",
        "not to scale",
        "length",
        "Along",
        "against",
        "Klipping",
        "plane of",
    ];
    for file in [
        "text-camera",
        "text-triangle",
        "text-clip",
        "shade-phong",
        "shade-two-lights",
    ] {
        for d in drawn_in(Lang::Id, &["solve", &format!("problems/{file}.toml")]) {
            let p = read_svg(&to_svg(&d));
            let words = p.iter().flat_map(|p| {
                p.texts
                    .iter()
                    .map(|t| t.text.clone())
                    .chain([p.title.clone()])
            });
            for w in words {
                // Whole words (or phrases), so that Peye is no "eye".
                let padded = format!(
                    " {} ",
                    w.replace(|c: char| !c.is_alphanumeric() && c != '(' && c != ')', " ")
                );
                for e in english {
                    assert!(
                        !padded.contains(&format!(" {e} ")),
                        "{file}: {e:?} in {w:?}"
                    );
                }
            }
        }
    }
    let d = drawn_in(Lang::Id, &["solve", "problems/text-triangle.toml"]);
    let titles: Vec<String> = d
        .iter()
        .flat_map(|d| d.panels.iter().map(|p| p.title.clone()))
        .collect();
    assert!(
        titles.contains(&"Proyeksi ke bidang pandang".to_string()),
        "{titles:?}"
    );
    assert!(
        titles.contains(&"Viewing window pada near plane".to_string()),
        "{titles:?}"
    );
}

// ---- the description's other facts ----

fn segments(f: &Figure, pen: Pen) -> Vec<([f64; 2], [f64; 2])> {
    f.marks()
        .filter(|m| m.pen == pen)
        .filter_map(|m| match m.shape {
            Shape::Line { a, b, head: false } => Some((a, b)),
            _ => None,
        })
        .collect()
}

fn mark<'a>(f: &'a Figure, name: &str) -> &'a Mark {
    f.mark(name).unwrap_or_else(|| panic!("no mark {name}"))
}

fn line_of(m: &Mark) -> ([f64; 2], [f64; 2]) {
    match m.shape {
        Shape::Line { a, b, .. } => (a, b),
        _ => panic!("{} is not a line", m.name),
    }
}

fn dot_of(m: &Mark) -> [f64; 2] {
    match m.shape {
        Shape::Dot(p) => p,
        _ => panic!("{} is not a dot", m.name),
    }
}

fn texts(f: &Figure) -> Vec<String> {
    f.items
        .iter()
        .filter_map(|it| match it {
            Item::Label(l) => Some(l.text.clone()),
            Item::Note(t) => Some(t.clone()),
            Item::Mark(_) => None,
        })
        .collect()
}

fn has_text(f: &Figure, want: &str) {
    let l = texts(f);
    assert!(l.iter().any(|t| t == want), "no text {want:?} in {l:?}");
}

/// Whether c lies on the segment a–b (collinear, between the ends).
fn on_segment(c: [f64; 2], a: [f64; 2], b: [f64; 2]) -> bool {
    let (ux, uy) = (b[0] - a[0], b[1] - a[1]);
    let (wx, wy) = (c[0] - a[0], c[1] - a[1]);
    let len2 = ux * ux + uy * uy;
    let t = (ux * wx + uy * wy) / len2;
    (ux * wy - uy * wx).abs() <= 1e-9 * len2.max(1.0) && (-1e-9..=1.0 + 1e-9).contains(&t)
}

/// The text's triangle, A' = (0, −1, −3√2) projected onto z = d = −0.1
/// from the origin: yp = d·y/z = (−0.1)(−1)/(−3√2) = −√2/60, so the image
/// (0, −√2/60, −0.1) lies on the projector from the centre to A', in 3D and
/// in the side view (−z, y), where the legs y = −1 (at −z = 3√2) and
/// yp (at 0.1, in the inset enlarged ×20: the plane is under an eighth of
/// the scene away) make the similar triangles.
#[test]
fn the_projector_passes_through_the_point_and_its_image() {
    let d = drawn(&["project", "--d", "-0.1", "--point", "A=0,-1,-6/sqrt(2)"]);
    assert_eq!(d[0].panels.len(), 3, "3D, side view, view plane");
    let (f3, side, plane) = (&d[0].panels[0], &d[0].panels[1], &d[0].panels[2]);
    let (c, a) = line_of(mark(f3, "projector A"));
    assert_eq!(c, dot_of(mark(f3, "COP")));
    assert_eq!(a, dot_of(mark(f3, "A")));
    let (c, a) = line_of(mark(side, "projector A"));
    let z = 3.0 * 2f64.sqrt();
    assert!(c == [0.0, 0.0] && (a[0] - z).abs() < 1e-12 && (a[1] + 1.0).abs() < 1e-12);
    assert!(on_segment([0.1, -(2f64.sqrt()) / 60.0], c, a));
    let (foot, top) = line_of(mark(side, "yp A''"));
    let yp = -(2f64.sqrt()) / 60.0;
    assert!((foot[0] - top[0]).abs() < 1e-12 && (top[1] - foot[1] - 20.0 * yp).abs() < 1e-9);
    has_text(side, "z = d = −0.1 (×20)");
    has_text(side, "A'': yp = −√2/60 ≈ −0.02357");
    has_text(side, "yp/d = y/z  ⇒  yp = d·y/z");
    let img = dot_of(mark(plane, "A''"));
    assert!(img[0] == 0.0 && (img[1] - yp).abs() < 1e-15);
    has_text(plane, "A'' = (0, −√2/60)");
    same_marks_in_tikz(&d[0]);
}

/// The general form: centre (0, 0, 5), plane z = 0, A = (1, 2, −3):
/// xp = 1·5/8 = 5/8, yp = 2·5/8 = 5/4; orthographic: A goes to (1, 2, 0)
/// along z.
#[test]
fn general_and_orthographic_projections() {
    let d = drawn(&[
        "project", "--cop", "5", "--plane", "0", "--point", "A=1,2,-3",
    ]);
    has_text(&d[0].panels[2], "A'' = (5/8, 5/4) = (0.625, 1.25)");
    has_text(&d[0].panels[1], "yp/(zprp − zvp) = y/(zprp − z)");
    let o = drawn(&["project", "--ortho", "--point", "A=1,2,-3"]);
    let (a, b) = line_of(mark(&o[0].panels[0], "projector A"));
    assert_eq!(
        (a, b),
        (
            dot_of(mark(&o[0].panels[0], "A")),
            dot_of(mark(&o[0].panels[0], "A''"))
        )
    );
    has_text(&o[0].panels[1], "yp = y");
}

/// fovy = 90°, aspect 2, near 1, far 3, viewport 200×100, A = (0.5, 0.5).
/// By hand: top = tan 45° = 1, right = 2; far_top = 3, far_right = 6 (to
/// scale: far = 3·near); A's pixel: ((0.5 + 2)/4·200, (0.5 + 1)/2·100) =
/// (125, 75). The side view: the near window from (1, −1) to (1, 1), the
/// fovy arc from −45° to 45°.
#[test]
fn window_panels() {
    let args = [
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
    ];
    let d = drawn(&args);
    let p = &d[0].panels;
    assert_eq!(p.len(), 4, "view volume, side view, near window, viewport");
    assert!(p[0].mark("far window").is_some());
    has_text(&p[0], "top = 1");
    has_text(&p[0], "right = 2");
    has_text(&p[0], "far = 3, far_top = 3");
    assert_eq!(
        line_of(mark(&p[1], "near window")),
        ([1.0, -1.0], [1.0, 1.0])
    );
    let Shape::Path(arc) = &mark(&p[1], "fovy").shape else {
        panic!("the fovy arc")
    };
    let (a, b) = (arc[0], arc[arc.len() - 1]);
    assert!((a[1] + a[0]).abs() < 1e-12 && (b[1] - b[0]).abs() < 1e-12 && a[0] > 0.0);
    assert_eq!(dot_of(mark(&p[2], "A")), [0.5, 0.5]);
    assert_eq!(dot_of(mark(&p[3], "A")), [125.0, 75.0]);
    has_text(&p[3], "A = (125, 75)");
    same_marks_in_tikz(&d[0]);
    // The triangle's far = 10 is 100 times near: no far window, a note.
    let t = drawn(&["solve", "problems/text-triangle.toml"]);
    let f = &t[2].panels[0];
    assert!(f.mark("far window").is_none());
    has_text(
        f,
        "far = 10, far_top = 10√2−10 ≈ 4.142: far window too far to draw to scale",
    );
    assert_eq!(segments(f, Pen::Cut).len(), 4);
}

// ---- the writers ----

/// The same description written as TikZ has the same marks: one `\draw`
/// per line, arrow, polygon and path (one per edge of the box), one
/// `\fill` per dot, one `\node` per label and note line; the SVG one
/// element per mark.
fn same_marks_in_tikz(d: &Drawing) {
    let t = to_tikz(d);
    let svg = to_svg(d);
    let marks: Vec<&Mark> = d.panels.iter().flat_map(|p| p.marks()).collect();
    let draws: usize = marks
        .iter()
        .map(|m| match &m.shape {
            Shape::Edges(e) => e.len(),
            Shape::Dot(_) | Shape::Face(_) => 0,
            _ => 1,
        })
        .sum();
    let heads = marks
        .iter()
        .filter(|m| matches!(m.shape, Shape::Line { head: true, .. }))
        .count();
    let dots = marks.iter().filter(|m| m.kind == Kind::Point).count();
    assert_eq!(t.matches("\\draw[").count(), draws);
    assert_eq!(t.matches("\\draw[->").count(), heads);
    assert_eq!(t.matches("\\fill[").count(), dots);
    assert_eq!(t.matches("\\node[").count(), svg.matches("<text").count());
    assert_eq!(t.matches("\\begin{tikzpicture}").count(), d.panels.len());
    assert_eq!(svg.matches("marker-end").count(), heads);
    assert_eq!(svg.matches("data-name=").count(), marks.len());
}

#[test]
fn tikz_has_the_same_marks() {
    for args in [
        vec![
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
        vec!["solve", "problems/text-camera.toml"],
        vec!["solve", "problems/shade-blinn-local.toml"],
    ] {
        for d in drawn(&args) {
            same_marks_in_tikz(&d);
        }
    }
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

/// `--figure` writes an SVG 600 px wide with `<title>` and `<desc>` first
/// (the drawing's and each panel's), and never overwrites a file.
#[test]
fn figure_flag_writes_svg_that_parses_and_never_overwrites() {
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
    let doc = roxmltree::Document::parse(&svg).expect("SVG parses as XML");
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
    }
    let p = read_svg(&svg);
    // By hand: the unit box is entered at x = 0 (t = 1/3) and left at
    // x = 1 (t = 2/3).
    assert_eq!(
        p[1].label("left"),
        Some("t = 1/3: x = 0 (left) → (0, 1/2, 1/2), 000000, kept")
    );
    assert_eq!(
        p[1].label("right"),
        Some("t = 2/3: x = 1 (right) → (1, 1/2, 1/2), 000000, kept")
    );
}

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
    std::fs::remove_file(dir.join("t-1-view.svg")).unwrap();
    let err = run().assert().code(2);
    let err = String::from_utf8_lossy(&err.get_output().stderr).to_string();
    assert!(err.contains("t-2-project.svg already exists"), "{err}");
    assert!(
        !dir.join("t-1-view.svg").exists(),
        "nothing is written when one exists"
    );
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
    run(
        &[
            "shade", "--light", "0,0,1", "--normal", "0,1,1", "--view", "0,0,1", "--color", "1,1,0",
        ],
        "shade.svg",
    );
    run(&["solve", "problems/text-camera.toml"], "camera.svg");
    run(&["solve", "problems/text-triangle.toml"], "triangle.svg");
    for f in [
        "clip.svg",
        "shade.svg",
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

/// A segment decided without a kept intersection says why under its
/// panel along t: clip-cases' second segment, P0(1, 5, 1) and P1(2, 6, 2),
/// both above the box (y > 4): 001000 AND 001000 = 001000 ≠ 000000; its
/// first, both ends inside: accepted whole. A light out of range has no
/// plane of its own; the first panel says so (shade-out-of-range's
/// second light).
#[test]
fn decided_segments_and_dark_lights_are_said() {
    let d = drawn(&["solve", "problems/clip-cases.toml"]);
    let notes = |k: usize| read_svg(&to_svg(&d[k]))[1].notes();
    assert!(notes(0).contains("both codes are 000000: the segment lies inside, accepted whole"));
    assert!(notes(1).contains("code0 AND code1 = 001000 ≠ 000000: the segment lies outside"));
    let s = drawn_in(Lang::Id, &["solve", "problems/shade-out-of-range.toml"]);
    let p = read_svg(&to_svg(&s[0]));
    assert_eq!(p.len(), 1, "one light in range, one panel");
    assert!(
        p[0].notes().contains("sumber cahaya 2 di luar jangkauan"),
        "{}",
        p[0].notes()
    );
}

/// A problem file that gives d (not near) is projected onto z = d, and the
/// projection figure is drawn from what the part was given: with the eye
/// at the origin looking down −z, F' = F = (0.5, 0.5, −4) and F'' =
/// d·(x/z, y/z) = −2·(0.5/−4, 0.5/−4) = (0.25, 0.25) on the plane z = −2.
/// (The figure once looked d up among the steps' results and was lost
/// when the step came to show d as a value.)
#[test]
fn a_problem_that_gives_d_draws_its_projection_on_z_equals_d() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("d.toml");
    let problem = "title = \"d\"\nask = [\"project\"]\n\
                   [camera]\neye = [0, 0, 0]\nlook = [0, 0, -1]\nup = [0, 1, 0]\n\
                   [perspective]\nd = -2\n[points]\nF = [0.5, 0.5, -4]\n";
    std::fs::write(&file, problem).unwrap();
    let args = ["solve", file.to_str().unwrap()];
    let parts: Vec<String> = drawn(&args).iter().map(|d| d.part.clone()).collect();
    assert_eq!(parts, ["project"]);
    let panels = svg_panels(Lang::En, &args);
    assert!(panels.iter().any(|p| p.has("view plane")));
    let images: Vec<&str> = panels.iter().filter_map(|p| p.label("F''")).collect();
    assert!(
        images.contains(&"F'' = (1/4, 1/4) = (0.25, 0.25)"),
        "{images:?}"
    );
    let svg = to_svg(&drawn(&args)[0]);
    assert!(svg.contains("z = d = −2"), "the plane is named by d");
}

/// `--figure` on a problem whose parts have no figure of their own (the
/// viewport asked alone: its pixels are drawn on the window's figure)
/// writes no file and says so on stderr, in the language asked, instead
/// of finishing silently; the solution is still printed (exit 0).
#[test]
fn a_figure_of_nothing_drawable_is_said_not_silent() {
    let dir = std::env::temp_dir().join(format!("grafika-nofig-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let triangle = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/text-triangle.toml"),
    )
    .unwrap();
    let problem = dir.join("viewport.toml");
    std::fs::write(&problem, format!("ask = [\"viewport\"]\n{triangle}")).unwrap();
    // A's pixel: x = 200·(0 + r)/(2r) = 100, y = (100−25√2)/3 ≈ 21.55
    for (lang, said, pixel) in [
        ("en", "warning: no figure was written", "(100, 21.55)"),
        (
            "id",
            "peringatan: tidak ada gambar yang ditulis",
            "(100; 21,55)",
        ),
    ] {
        let out = Command::cargo_bin("grafika")
            .unwrap()
            .args(["--lang", lang, "solve"])
            .arg(&problem)
            .arg("--figure")
            .arg(dir.join("vp.svg"))
            .assert()
            .success();
        let err = String::from_utf8_lossy(&out.get_output().stderr).to_string();
        assert!(err.starts_with(said), "{lang}: {err}");
        assert!(err.contains("`window`"), "{lang}: {err}");
        let stdout = String::from_utf8_lossy(&out.get_output().stdout).to_string();
        assert!(stdout.contains(pixel), "{lang}: {stdout}");
    }
    let svgs = std::fs::read_dir(&dir).unwrap().filter(|e| {
        e.as_ref()
            .is_ok_and(|e| e.path().extension().is_some_and(|x| x == "svg"))
    });
    assert_eq!(svgs.count(), 0, "no figure file");
    std::fs::remove_dir_all(&dir).unwrap();
}
