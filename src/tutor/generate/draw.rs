//! Drawing one problem per topic with nice numbers for its difficulty, and
//! screening it: solvable, non-degenerate, the clipping status wanted.

use super::{Difficulty, Generated, Topic};
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::num::rng::SplitMix64;
use crate::num::Real;
use crate::stages::trace::Val;
use crate::tutor::check::default_keys;
use crate::tutor::solve::{self, lookup};
use std::fmt::Write as _;

/// One problem: drawn until it is non-degenerate and solves.
pub fn problem(
    topic: Topic,
    diff: Difficulty,
    index: usize,
    rng: &mut SplitMix64,
) -> Result<Generated> {
    for _ in 0..500 {
        let toml = match topic {
            Topic::Basis | Topic::View | Topic::Project | Topic::Pipeline => {
                camera_problem(topic, diff, rng)
            }
            Topic::Window => window_problem(diff, rng),
            Topic::Clip => clip_problem(diff, index, rng),
            Topic::Shade => shade_problem(diff, rng),
        };
        if let Some(g) = accept(&toml, topic, diff, index) {
            return Ok(g);
        }
    }
    Err(Error::new(
        "seed",
        "could not draw a non-degenerate problem in 500 tries",
    ))
}

/// Parses, solves and screens a drawn problem.
fn accept(toml: &str, topic: Topic, diff: Difficulty, index: usize) -> Option<Generated> {
    let problem = ProblemIn::parse(toml, "generated").ok()?;
    let f64_result = solve::solve::<f64>(&problem).ok()?.result;
    if !screen(&problem, &f64_result, topic, diff, index) {
        return None;
    }
    let report = solve::solve::<Real>(&problem).ok()?;
    if !report.warnings.is_empty() {
        return None;
    }
    let keys = problem
        .check
        .as_ref()
        .and_then(|c| c.keys.clone())
        .unwrap_or_else(|| default_keys(&report.result));
    Some(Generated {
        toml: toml.to_string(),
        problem,
        report,
        keys,
    })
}

/// Non-degeneracy and the clipping status wanted.
fn screen(
    p: &ProblemIn,
    r: &[(String, Val)],
    topic: Topic,
    diff: Difficulty,
    index: usize,
) -> bool {
    let num = |v: &Val| match v {
        Val::Num(s) => Some(s.value),
        _ => None,
    };
    // Points strictly beyond the near plane (never on the projection plane
    // z' = −near, never behind the eye), and not grazing it.
    if let Some(Val::Map(pts)) = lookup(r, "view.points") {
        let near = p
            .perspective
            .as_ref()
            .and_then(|x| x.near.as_ref())
            .and_then(|n| n.0.eval::<f64>().ok())
            .unwrap_or(0.0);
        for (_, e) in pts {
            if let Val::List(c) = e {
                match c.get(2).and_then(num) {
                    Some(z) if z < -(near + 0.5) => {}
                    _ => return false,
                }
            }
        }
    }
    // Projected points inside the window for the pipeline (a clean exam).
    if topic == Topic::Pipeline {
        if let Some(Val::Map(px)) = lookup(r, "viewport.pixels") {
            let vp: Vec<f64> = p
                .perspective
                .as_ref()
                .and_then(|x| x.viewport.as_ref())
                .map(|v| v.iter().filter_map(|n| n.0.eval::<f64>().ok()).collect())
                .unwrap_or_default();
            for (_, q) in px {
                if let Val::List(c) = q {
                    let (x, y) = (c.first().and_then(num), c.get(1).and_then(num));
                    match (x, y, vp.first(), vp.get(1)) {
                        (Some(x), Some(y), Some(w), Some(h))
                            if x > 0.0 && x < *w && y > 0.0 && y < *h => {}
                        _ => return false,
                    }
                }
            }
        }
    }
    // Lighting: the light clearly in front of the surface.
    if topic == Topic::Shade {
        match lookup(r, "shade.cos_alpha").and_then(num) {
            Some(c) if c > 0.05 => {}
            _ => return false,
        }
    }
    if topic == Topic::Clip {
        let want = ["clipped", "accepted", "rejected"][index % 3];
        let ok = matches!(lookup(r, "clip.status"), Some(Val::Text(s)) if s == want);
        if !ok {
            return false;
        }
        if want == "clipped" {
            // a real piece, not a single point
            if let Some(Val::List(seg)) = lookup(r, "clip.segment") {
                if seg.first() == seg.get(1) {
                    return false;
                }
            }
        }
        let _ = diff;
    }
    true
}

/// The first letter in upper case.
fn capitalized(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

/// `[a, b, c]` for a TOML file.
fn arr(v: &[String]) -> String {
    format!("[{}]", v.join(", "))
}

fn ints(v: [i64; 3]) -> String {
    arr(&v.iter().map(|x| x.to_string()).collect::<Vec<_>>())
}

/// A TOML string literal.
fn tstr(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// (x, y, z) for a statement.
fn tuple(v: [i64; 3]) -> String {
    format!("({}, {}, {})", v[0], v[1], v[2])
}

const TRIPLES: [(i64, i64); 6] = [(3, 4), (4, 3), (5, 12), (12, 5), (6, 8), (8, 6)];

/// Pe − Pr and Vup for the difficulty.
fn direction(diff: Difficulty, rng: &mut SplitMix64) -> ([i64; 3], [i64; 3]) {
    let sign = |r: &mut SplitMix64| if r.coin() { 1 } else { -1 };
    match diff {
        Difficulty::Easy => {
            // (a, 0, c) with a² + c² a square, or (3, 12, 4)-like: |d| = 13
            // and |Vup × d| = 5 are both integers.
            if rng.below(3) == 0 {
                let (a, c) = *rng.pick(&[(3, 4), (4, 3)]);
                ([sign(rng) * a, sign(rng) * 12, sign(rng) * c], [0, 1, 0])
            } else {
                let (a, c) = *rng.pick(&TRIPLES[..4]);
                ([sign(rng) * a, 0, sign(rng) * c], [0, 1, 0])
            }
        }
        Difficulty::Medium => {
            if rng.coin() {
                // (a, 0, c): |d| = |Vup × d| = √(a² + c²), one surd
                let a = rng.range(-3, 3);
                let c = rng.range(1, 3) * sign(rng);
                ([a, 0, c], [0, 1, 0])
            } else {
                // a² + c² square, b ≠ 0: u rational, |d| = √(25 + b²)
                let (a, c) = *rng.pick(&TRIPLES[..2]);
                let b = rng.range(1, 3) * sign(rng);
                ([sign(rng) * a, b, sign(rng) * c], [0, 1, 0])
            }
        }
        Difficulty::Hard => {
            let d = [rng.range(-5, 5), rng.range(-5, 5), rng.range(-5, 5)];
            let up = *rng.pick(&[[0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]);
            (d, up)
        }
    }
}

fn camera_problem(topic: Topic, diff: Difficulty, rng: &mut SplitMix64) -> String {
    let (d, up) = direction(diff, rng);
    let look = [rng.range(-2, 2), rng.range(-2, 2), rng.range(-2, 2)];
    let eye = [look[0] + d[0], look[1] + d[1], look[2] + d[2]];
    let pts = camera_points(topic, diff, look, rng);
    let near: &&str = match diff {
        Difficulty::Easy => rng.pick(&["1", "2"]),
        Difficulty::Medium => rng.pick(&["0.5", "1", "2"]),
        Difficulty::Hard => rng.pick(&["0.1", "0.25", "0.5"]),
    };
    let pts_text = pts
        .iter()
        .map(|(n, p)| format!("{n}{}", tuple(*p)))
        .collect::<Vec<_>>()
        .join(", ");
    let cam_text = format!(
        "A camera at Pe = {} looks at Pr = {} with up vector Vup = {}.",
        tuple(eye),
        tuple(look),
        tuple(up)
    );
    let (title, ask, mut statement) = match topic {
        Topic::Basis => (
            "camera basis",
            r#"["view"]"#,
            format!("{cam_text} Find the camera axes n, u and v."),
        ),
        Topic::View => (
            "eye coordinates",
            r#"["view"]"#,
            format!("{cam_text} Find the camera axes n, u, v and the eye coordinates of the points {pts_text}."),
        ),
        Topic::Project => (
            "projection onto the near plane",
            r#"["project"]"#,
            format!("{cam_text} With near = {near}, project the points {pts_text} onto the near plane z = d = −near (centre of projection at the eye); give (xp, yp, zp)."),
        ),
        _ => (
            "the viewing pipeline",
            r#"["view", "project", "window", "viewport"]"#,
            String::new(),
        ),
    };
    let mut per = String::new();
    if topic == Topic::Project {
        let _ = writeln!(per, "[perspective]\nnear = {near}\n");
    }
    if topic == Topic::Pipeline {
        (statement, per) = pipeline_setup(diff, near, &cam_text, &pts_text, rng);
    }
    let mut t = String::new();
    let _ = writeln!(t, "title = {}", tstr(&capitalized(title)));
    let _ = writeln!(t, "statement = {}", tstr(&statement));
    let _ = writeln!(t, "ask = {ask}\n");
    let _ = writeln!(
        t,
        "[camera]\neye = {}\nlook = {}\nup = {}\n",
        ints(eye),
        ints(look),
        ints(up)
    );
    t.push_str(&per);
    if !pts.is_empty() {
        t.push_str("[points]\n");
        for (n, p) in &pts {
            let _ = writeln!(t, "{n} = {}", ints(*p));
        }
        t.push('\n');
    }
    if topic == Topic::Basis {
        t.push_str("[check]\nkeys = [\"view.n\", \"view.u\", \"view.v\"]\n");
    }
    t
}

/// The named points of a camera problem, near the look-at point: none for
/// the basis, three for the pipeline, else two or three.
fn camera_points(
    topic: Topic,
    diff: Difficulty,
    look: [i64; 3],
    rng: &mut SplitMix64,
) -> Vec<(String, [i64; 3])> {
    let npts = match topic {
        Topic::Basis => 0,
        Topic::Pipeline => 3,
        _ => 2 + rng.below(2) as usize,
    };
    let spread = if diff == Difficulty::Hard { 3 } else { 2 };
    ["A", "B", "C"][..npts]
        .iter()
        .map(|n| {
            let p = [
                look[0] + rng.range(-spread, spread),
                look[1] + rng.range(-spread, spread),
                look[2] + rng.range(-spread, spread),
            ];
            (n.to_string(), p)
        })
        .collect()
}

/// A pipeline problem's perspective set-up (fovy, aspect, viewport drawn
/// for the difficulty): its statement and its `[perspective]` table.
fn pipeline_setup(
    diff: Difficulty,
    near: &str,
    cam_text: &str,
    pts_text: &str,
    rng: &mut SplitMix64,
) -> (String, String) {
    let fovy = *rng.pick(match diff {
        Difficulty::Easy => &[90][..],
        Difficulty::Medium => &[45, 60, 90][..],
        Difficulty::Hard => &[40, 50, 70][..],
    });
    let aspect = *rng.pick(&["1", "2", "1.5"]);
    let vp = *rng.pick(&["[200, 100]", "[400, 200]", "[300, 200]"]);
    let statement = format!(
        "{cam_text} The perspective set-up is near = {near}, fovy = {fovy}°, aspect = {aspect}, viewport {} pixels. For the points {pts_text}: (1) find n, u, v and the eye coordinates; (2) project them onto the near plane z = −near; (3) find the viewing window (top, bottom, left, right, height, width); (4) find the pixel coordinates of the projected points.",
        vp.trim_matches(['[', ']']).replace(", ", "x")
    );
    let per = format!(
        "[perspective]\nnear = {near}\nfovy = {fovy}\naspect = {aspect}\nviewport = {vp}\n\n"
    );
    (statement, per)
}

fn window_problem(diff: Difficulty, rng: &mut SplitMix64) -> String {
    let (fovy, aspect, near): (i64, &str, &str) = match diff {
        Difficulty::Easy => (90, *rng.pick(&["1", "2"]), *rng.pick(&["1", "2", "3"])),
        Difficulty::Medium => (
            *rng.pick(&[30, 45, 60, 120]),
            *rng.pick(&["1.5", "2", "4/3"]),
            *rng.pick(&["0.5", "1", "0.1"]),
        ),
        Difficulty::Hard => (
            *rng.pick(&[40, 50, 70, 75]),
            *rng.pick(&["16/9", "1.6", "1.25"]),
            *rng.pick(&["0.1", "0.25", "0.3"]),
        ),
    };
    let aspect_toml = if aspect.contains('/') {
        tstr(aspect)
    } else {
        aspect.to_string()
    };
    format!(
        "title = {}\nstatement = {}\nask = [\"window\"]\n\n[perspective]\nnear = {near}\nfovy = {fovy}\naspect = {aspect_toml}\n",
        tstr("The viewing window"),
        tstr(&format!("A perspective camera has fovy = {fovy}°, aspect ratio {aspect} and near = {near}. Find the viewing window on the near plane: top, bottom, left, right, height and width.")),
    )
}

/// The clipping box (corners) for the difficulty, and how far outside it
/// segment ends may lie.
fn clip_box(diff: Difficulty, rng: &mut SplitMix64) -> ([i64; 3], [i64; 3], i64) {
    match diff {
        Difficulty::Easy => (
            [0, 0, 0],
            [rng.range(2, 4), rng.range(2, 4), rng.range(2, 4)],
            2,
        ),
        Difficulty::Medium => {
            let min = [rng.range(-3, 0), rng.range(-3, 0), rng.range(-3, 0)];
            (
                min,
                [
                    min[0] + rng.range(2, 5),
                    min[1] + rng.range(2, 5),
                    min[2] + rng.range(2, 5),
                ],
                3,
            )
        }
        Difficulty::Hard => {
            let min = [rng.range(-5, 0), rng.range(-5, 0), rng.range(-5, 0)];
            (
                min,
                [
                    min[0] + rng.range(3, 8),
                    min[1] + rng.range(3, 8),
                    min[2] + rng.range(3, 8),
                ],
                4,
            )
        }
    }
}

/// Segment ends off the box planes for the wanted status: 0 clipped (one
/// end inside and the other anywhere, or both anywhere), 1 accepted, 2
/// rejected.
fn clip_ends(
    status: usize,
    (min, max, pad): ([i64; 3], [i64; 3], i64),
    rng: &mut SplitMix64,
) -> ([i64; 3], [i64; 3]) {
    // A coordinate off the box planes: inside (strictly) or outside.
    let inside = |r: &mut SplitMix64, k: usize| r.range(min[k] + 1, max[k] - 1);
    let any = |r: &mut SplitMix64, k: usize| loop {
        let x = r.range(min[k] - pad, max[k] + pad);
        if x != min[k] && x != max[k] {
            return x;
        }
    };
    match status {
        // clipped: one end inside and the other anywhere, or both anywhere
        0 => {
            let a: [i64; 3] = if rng.coin() {
                std::array::from_fn(|k| inside(rng, k))
            } else {
                std::array::from_fn(|k| any(rng, k))
            };
            let b: [i64; 3] = std::array::from_fn(|k| any(rng, k));
            if rng.coin() {
                (a, b)
            } else {
                (b, a)
            }
        }
        // accepted: both ends strictly inside
        1 => (
            std::array::from_fn(|k| inside(rng, k)),
            std::array::from_fn(|k| inside(rng, k)),
        ),
        // rejected: both ends beyond one plane, or anywhere (a segment
        // that passes the box by is rejected only after clipping)
        _ => {
            let mut a: [i64; 3] = std::array::from_fn(|k| any(rng, k));
            let mut b: [i64; 3] = std::array::from_fn(|k| any(rng, k));
            if rng.below(3) != 0 {
                let k = rng.below(3) as usize;
                let (lo, hi) = if rng.coin() {
                    (min[k] - pad, min[k] - 1)
                } else {
                    (max[k] + 1, max[k] + pad)
                };
                a[k] = rng.range(lo, hi);
                b[k] = rng.range(lo, hi);
            }
            (a, b)
        }
    }
}

fn clip_problem(diff: Difficulty, index: usize, rng: &mut SplitMix64) -> String {
    let (min, max, pad) = clip_box(diff, rng);
    let (p0, p1) = clip_ends(index % 3, (min, max, pad), rng);
    if p0 == p1 {
        return String::new(); // rejected by accept()
    }
    format!(
        "title = {}\nstatement = {}\nask = [\"clip\"]\n\n[clip]\nmin = {}\nmax = {}\n\n[[clip.segment]]\nfrom = {}\nto = {}\n",
        tstr("Line clipping"),
        tstr(&format!(
            "The view volume is the box {}min ≤ x ≤ {}max... with corners {} and {}. For the segment P0{} P1{}: (a) give the region codes of P0 and P1 (6 bits, bit 1 rightmost: left, right, bottom, top, front, back); (b) is the segment accepted, rejected or clipped, and what is left of it?",
            "", "", tuple(min), tuple(max), tuple(p0), tuple(p1)
        ).replace(" box min ≤ x ≤ max... with corners", " box with corners")),
        ints(min),
        ints(max),
        ints(p0),
        ints(p1)
    )
}

/// A lighting problem's vectors, model and constants for the difficulty:
/// (N, L, V, model, [ka, kd, ks, n] unless the text's).
type Draw = (
    [i64; 3],
    [i64; 3],
    [i64; 3],
    &'static str,
    Option<[&'static str; 4]>,
);

/// Draws N, L, V, the model and (hard) the constants.
fn shade_draw(diff: Difficulty, rng: &mut SplitMix64) -> Draw {
    match diff {
        Difficulty::Easy => (
            *rng.pick(&[
                [0, 3, 4],
                [3, 0, 4],
                [0, 4, 3],
                [4, 0, 3],
                [0, -3, 4],
                [-3, 0, 4],
            ]),
            [0, 0, 1],
            [0, 0, 1],
            "phong",
            None,
        ),
        Difficulty::Medium => (
            *rng.pick(&[
                [0, 1, 1],
                [1, 0, 1],
                [0, -1, 1],
                [-1, 0, 1],
                [0, 1, 2],
                [1, 0, 2],
            ]),
            [0, 0, 1],
            *rng.pick(&[[0, 0, 1], [0, 1, 1], [1, 0, 1]]),
            *rng.pick(&["phong", "lambert", "blinn"]),
            None,
        ),
        Difficulty::Hard => {
            let vec = |r: &mut SplitMix64| [r.range(-2, 3), r.range(-2, 3), r.range(1, 3)];
            let k = [
                *rng.pick(&["0.2", "0.3", "0.4"]),
                *rng.pick(&["0.5", "0.6", "0.7"]),
                *rng.pick(&["0.5", "0.7", "0.9"]),
                *rng.pick(&["3", "5", "8", "10"]),
            ];
            (
                vec(rng),
                vec(rng),
                vec(rng),
                *rng.pick(&["phong", "blinn", "lambert"]),
                Some(k),
            )
        }
    }
}

/// What a lighting problem asks for, and the answers checked, follow the
/// model: (the constants as stated, what is asked, the check keys).
fn shade_asked(
    model: &str,
    (ka, kd, ks, sh): (&str, &str, &str, &str),
) -> (String, &'static str, &'static str) {
    match model {
    "lambert" => (
        format!("ka = {ka}, kd = {kd}"),
        "cos α = L·N, the ambient and diffuse terms",
        r#"["shade.cos_alpha", "shade.ambient", "shade.diffuse", "shade.color"]"#,
    ),
    "blinn" => (
        format!("ka = {ka}, kd = {kd}, ks = {ks}, n = {sh}"),
        "cos α = L·N, the half vector H = norm(L + V) and N·H, the ambient, diffuse and specular terms",
        r#"["shade.cos_alpha", "shade.H", "shade.N_dot_H", "shade.ambient", "shade.diffuse", "shade.specular", "shade.color"]"#,
    ),
    _ => (
        format!("ka = {ka}, kd = {kd}, ks = {ks}, n = {sh}"),
        "cos α = L·N, R = 2N(L·N) − L, cos β = R·V, the ambient, diffuse and specular terms",
        r#"["shade.cos_alpha", "shade.R", "shade.cos_beta", "shade.ambient", "shade.diffuse", "shade.specular", "shade.color"]"#,
    ),
}
}

/// A lighting problem at one point: white directional light L, viewer V,
/// normal N, surface color Cs. Easy: L = V = (0, 0, 1) (the text's) and a
/// normal with a rational length (3-4-5), so every answer is rational;
/// medium: normals like (0, 1, 1) with one surd, the models phong, lambert
/// and blinn; hard: any small vectors and coefficients. Always lit (N·L > 0).
fn shade_problem(diff: Difficulty, rng: &mut SplitMix64) -> String {
    let colors: [[&str; 3]; 5] = [
        ["1", "1", "0"],
        ["1", "0", "0"],
        ["0", "0.5", "1"],
        ["1", "0.5", "0"],
        ["0.5", "0.5", "0.5"],
    ];
    let color = *rng.pick(&colors);
    let (n, l, v, model, k) = shade_draw(diff, rng);
    let coeffs = k.map_or(String::new(), |k| {
        format!(
            "ka = {}\nkd = {}\nks = {}\nshininess = {}\n",
            k[0], k[1], k[2], k[3]
        )
    });
    let (ka, kd, ks, sh) = k.map_or(("0.4", "0.6", "0.7", "4"), |k| (k[0], k[1], k[2], k[3]));
    let (consts, asked, keys) = shade_asked(model, (ka, kd, ks, sh));
    let statement = format!(
        "A surface point with normal N = {} and color Cs = ({}) is lit by one white directional light from L = {} and seen from V = {}. With the {model} model ({consts}), find {asked} and the color (each channel clamped to [0, 1]).",
        tuple(n),
        color.join(", "),
        tuple(l),
        tuple(v)
    );
    format!(
        "title = {}\nstatement = {}\nask = [\"shade\"]\n\n[shade]\nmodel = \"{model}\"\nlight = {}\nnormal = {}\nview = {}\ncolor = {}\n{coeffs}\n[check]\nkeys = {keys}\n",
        tstr("Lighting at a point"),
        tstr(&statement),
        ints(l),
        ints(n),
        ints(v),
        arr(&color.iter().map(|c| c.to_string()).collect::<Vec<_>>()),
    )
}
