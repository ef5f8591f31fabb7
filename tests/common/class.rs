//! Answer files of students of the triangle ABC example
//! (problems/text-triangle.toml) with chosen mistakes: the right values and
//! each mistake's values derived by hand below, written in the forms
//! students type (exact forms, rounded decimals, decimal commas, `√`, `−`,
//! vectors as one string). Used by tests/class.rs (a class of 60 with
//! mistakes at known rates) and by examples/class.rs (the class of
//! problems/answers/class/, from a seed).
#![allow(dead_code)]

/// What one student does. A mistake of the catalog is carried through
/// every later key that depends on it, as a student carries it: the
/// values below follow from the mistaken one by the text's own formulas.
#[derive(Clone, Debug, Default)]
pub struct Student {
    /// The name in the file (`student = "…"`).
    pub name: String,
    /// Which of the written forms of the answers: 0 exact (ASCII),
    /// 1 rounded decimals with decimal commas, 2 vectors as one string with
    /// `√` and `−`, 3 four-figure decimals.
    pub form: usize,
    /// `cross_order`, u = n × Vup: u, v, the eye coordinates, the
    /// projections and the pixels of every point change ([`CROSS_ORDER_KEYS`]).
    pub cross_order: bool,
    /// `fovy_not_halved`, tan(fovy) for tan(fovy/2): the window and the
    /// pixels change ([`FOVY_KEYS`]).
    pub fovy_not_halved: bool,
    /// `height_is_half_extent`: the half extent h = top given as the
    /// height and aspect·h = right as the width; the edges and the pixels
    /// stay right ([`HALF_EXTENT_KEYS`]).
    pub height_is_half_extent: bool,
    /// `n_not_normalized`, n = Pe − Pr = (1, 0, 1) not divided by √2: n,
    /// v, the eye coordinates, the projections and pixels of B and C change
    /// ([`N_NOT_NORMALIZED_KEYS`]).
    pub n_not_normalized: bool,
    /// n to one significant figure, (0.7, 0, 0.7): too coarse, no mistake.
    pub n_too_coarse: bool,
    /// v written in words (the v the student's mistakes give): unparseable.
    pub v_in_words: bool,
    /// The viewport part left out (three pixels missing), whatever the
    /// student's mistakes.
    pub no_pixels: bool,
    /// The window's width as written, whatever the student's mistakes
    /// (None: the width the student's mistakes give, or the right one).
    pub width: Option<String>,
    /// A slip no mistake of the catalog explains: pixel B's x written
    /// 142.14 for 124.14 (digits swapped). For a student whose pixel B is
    /// otherwise right (a mistake that changes B comes first).
    pub pixel_slip: bool,
}

/// `(a, b, c)` in the student's form: one TOML array, or one string.
fn vector(form: usize, parts: &[&str]) -> String {
    match form {
        2 => format!("\"({})\"", parts.join(", ")),
        1 => format!("\"({})\"", parts.join("; ")),
        _ => format!(
            "[{}]",
            parts
                .iter()
                .map(|p| format!("\"{p}\""))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// The right value of each key in four forms (0 exact ASCII, 1 decimal
/// commas, 2 unicode exact, 3 decimals), derived by hand:
/// n = (1,0,1)/√2, u = Vup × n = (1,0,−1)/√2, v = (0,1,0); with Pe = (3,1,3),
/// A' = (u·(A−Pe), v·(A−Pe), n·(A−Pe)) = (0, −1, −3√2),
/// B' = (√2/2, −1, −5√2/2), C' = (−√2/2, −1, −5√2/2); d = −0.1 and
/// P'' = (d·x/z, d·y/z): A'' = (0, −√2/60), B'' = (1/50, −√2/50),
/// C'' = (−1/50, −√2/50); top = 0.1·tan 22.5° = (√2−1)/10, right =
/// 2·top; the viewport 200×100: px = 100 + x''·100/right,
/// py = 50 + y''·50/top: A = (100, 21.55), B = (124.14, 15.86),
/// C = (75.86, 15.86).
fn right(key: &str, form: usize) -> Vec<&'static str> {
    let pick = |f: [&'static [&'static str]; 4]| f[form % 4].to_vec();
    match key {
        "view.n" => pick([
            &["sqrt(2)/2", "0", "sqrt(2)/2"],
            &["0,7071", "0", "0,7071"],
            &["√2/2", "0", "√2/2"],
            &["0.7071", "0", "0.7071"],
        ]),
        "view.u" => pick([
            &["1/sqrt(2)", "0", "-1/sqrt(2)"],
            &["0,7071", "0", "−0,7071"],
            &["√2/2", "0", "−√2/2"],
            &["0.7071", "0", "-0.7071"],
        ]),
        "view.v" => pick([&["0", "1", "0"]; 4]),
        "view.points.A" => pick([
            &["0", "-1", "-6/sqrt(2)"],
            &["0", "−1", "−4,243"],
            &["0", "−1", "−3√2"],
            &["0", "-1", "-4.243"],
        ]),
        "view.points.B" => pick([
            &["sqrt(2)/2", "-1", "-5*sqrt(2)/2"],
            &["0,7071", "−1", "−3,536"],
            &["√2/2", "−1", "−5√2/2"],
            &["0.7071", "-1", "-3.536"],
        ]),
        "view.points.C" => pick([
            &["-sqrt(2)/2", "-1", "-5*sqrt(2)/2"],
            &["−0,7071", "−1", "−3,536"],
            &["−√2/2", "−1", "−5√2/2"],
            &["-0.7071", "-1", "-3.536"],
        ]),
        "project.points.A" => pick([
            &["0", "-sqrt(2)/60"],
            &["0", "−0,02357"],
            &["0", "−√2/60"],
            &["0", "-0.02357"],
        ]),
        "project.points.B" => pick([
            &["1/50", "-sqrt(2)/50"],
            &["0,02", "−0,02828"],
            &["1/50", "−√2/50"],
            &["0.02", "-0.02828"],
        ]),
        "project.points.C" => pick([
            &["-1/50", "-sqrt(2)/50"],
            &["−0,02", "−0,02828"],
            &["−1/50", "−√2/50"],
            &["-0.02", "-0.02828"],
        ]),
        "window.top" => pick([
            &["(sqrt(2)-1)/10"],
            &["0,04142"],
            &["(√2−1)/10"],
            &["0.04142"],
        ]),
        "window.bottom" => pick([
            &["(1-sqrt(2))/10"],
            &["−0,04142"],
            &["(1−√2)/10"],
            &["-0.04142"],
        ]),
        "window.left" => pick([
            &["(1-sqrt(2))/5"],
            &["−0,08284"],
            &["(1−√2)/5"],
            &["-0.08284"],
        ]),
        "window.right" => pick([
            &["(sqrt(2)-1)/5"],
            &["0,08284"],
            &["(√2−1)/5"],
            &["0.08284"],
        ]),
        "window.height" => pick([
            &["(sqrt(2)-1)/5"],
            &["0,08284"],
            &["(√2−1)/5"],
            &["0.08284"],
        ]),
        "window.width" => pick([
            &["(2*sqrt(2)-2)/5"],
            &["0,1657"],
            &["(2√2−2)/5"],
            &["0.1657"],
        ]),
        "viewport.pixels.A" => pick([
            &["100", "(100-25*sqrt(2))/3"],
            &["100", "21,55"],
            &["100", "(100−25√2)/3"],
            &["100", "21.55"],
        ]),
        "viewport.pixels.B" => pick([
            &["110+10*sqrt(2)", "30-10*sqrt(2)"],
            &["124,14", "15,86"],
            &["110+10√2", "30−10√2"],
            &["124.14", "15.86"],
        ]),
        "viewport.pixels.C" => pick([
            &["90-10*sqrt(2)", "30-10*sqrt(2)"],
            &["75,86", "15,86"],
            &["90−10√2", "30−10√2"],
            &["75.86", "15.86"],
        ]),
        _ => vec![],
    }
}

/// The keys of the example, in the order of its solution.
pub const KEYS: [&str; 18] = [
    "view.n",
    "view.u",
    "view.v",
    "view.points.A",
    "view.points.B",
    "view.points.C",
    "project.points.A",
    "project.points.B",
    "project.points.C",
    "window.top",
    "window.bottom",
    "window.left",
    "window.right",
    "window.height",
    "window.width",
    "viewport.pixels.A",
    "viewport.pixels.B",
    "viewport.pixels.C",
];

/// The keys each mistake changes, as the catalog makes it (derived below).
pub const CROSS_ORDER_KEYS: [&str; 11] = [
    "view.u",
    "view.v",
    "view.points.A",
    "view.points.B",
    "view.points.C",
    "project.points.A",
    "project.points.B",
    "project.points.C",
    "viewport.pixels.A",
    "viewport.pixels.B",
    "viewport.pixels.C",
];
pub const FOVY_KEYS: [&str; 9] = [
    "window.top",
    "window.bottom",
    "window.left",
    "window.right",
    "window.height",
    "window.width",
    "viewport.pixels.A",
    "viewport.pixels.B",
    "viewport.pixels.C",
];
pub const HALF_EXTENT_KEYS: [&str; 2] = ["window.height", "window.width"];
pub const N_NOT_NORMALIZED_KEYS: [&str; 9] = [
    "view.n",
    "view.v",
    "view.points.A",
    "view.points.B",
    "view.points.C",
    "project.points.B",
    "project.points.C",
    "viewport.pixels.B",
    "viewport.pixels.C",
];

/// A value in the four forms of [`Student::form`].
type Forms = [&'static [&'static str]; 4];

/// What a mistake (or a slip) makes a student write for a key, where it
/// changes the key.
type Writes = fn(&str) -> Option<Forms>;

/// u = n × Vup = (−√2/2, 0, √2/2) instead of (√2/2, 0, −√2/2); then
/// v = n × u = (0, −1, 0), and every x′ = u·(P − Pe) and y′ = v·(P − Pe)
/// changes sign: A′ = (0, 1, −3√2), B′ = (−√2/2, 1, −5√2/2), C′ = (√2/2, 1,
/// −5√2/2); so do xp = d·x′/z′ and yp = d·y′/z′: A″ = (0, √2/60),
/// B″ = (−1/50, √2/50), C″ = (1/50, √2/50); and each pixel mirrors about
/// the viewport's centre (100, 50): px = 200 − px, py = 100 − py, so
/// A = (100, 100 − (100 − 25√2)/3) = (100, (200 + 25√2)/3) ≈ (100, 78.45),
/// B = (90 − 10√2, 70 + 10√2) ≈ (75.86, 84.14), C = (110 + 10√2, 70 + 10√2)
/// ≈ (124.14, 84.14). The window does not change.
fn cross_order(key: &str) -> Option<Forms> {
    Some(match key {
        "view.u" => [
            &["-1/sqrt(2)", "0", "1/sqrt(2)"],
            &["−0,7071", "0", "0,7071"],
            &["−√2/2", "0", "√2/2"],
            &["-0.7071", "0", "0.7071"],
        ],
        "view.v" => [
            &["0", "-1", "0"],
            &["0", "−1", "0"],
            &["0", "−1", "0"],
            &["0", "-1", "0"],
        ],
        "view.points.A" => [
            &["0", "1", "-6/sqrt(2)"],
            &["0", "1", "−4,243"],
            &["0", "1", "−3√2"],
            &["0", "1", "-4.243"],
        ],
        "view.points.B" => [
            &["-sqrt(2)/2", "1", "-5*sqrt(2)/2"],
            &["−0,7071", "1", "−3,536"],
            &["−√2/2", "1", "−5√2/2"],
            &["-0.7071", "1", "-3.536"],
        ],
        "view.points.C" => [
            &["sqrt(2)/2", "1", "-5*sqrt(2)/2"],
            &["0,7071", "1", "−3,536"],
            &["√2/2", "1", "−5√2/2"],
            &["0.7071", "1", "-3.536"],
        ],
        "project.points.A" => [
            &["0", "sqrt(2)/60"],
            &["0", "0,02357"],
            &["0", "√2/60"],
            &["0", "0.02357"],
        ],
        "project.points.B" => [
            &["-1/50", "sqrt(2)/50"],
            &["−0,02", "0,02828"],
            &["−1/50", "√2/50"],
            &["-0.02", "0.02828"],
        ],
        "project.points.C" => [
            &["1/50", "sqrt(2)/50"],
            &["0,02", "0,02828"],
            &["1/50", "√2/50"],
            &["0.02", "0.02828"],
        ],
        "viewport.pixels.A" => [
            &["100", "(200+25*sqrt(2))/3"],
            &["100", "78,45"],
            &["100", "(200+25√2)/3"],
            &["100", "78.45"],
        ],
        "viewport.pixels.B" => [
            &["90-10*sqrt(2)", "70+10*sqrt(2)"],
            &["75,86", "84,14"],
            &["90−10√2", "70+10√2"],
            &["75.86", "84.14"],
        ],
        "viewport.pixels.C" => [
            &["110+10*sqrt(2)", "70+10*sqrt(2)"],
            &["124,14", "84,14"],
            &["110+10√2", "70+10√2"],
            &["124.14", "84.14"],
        ],
        _ => return None,
    })
}

/// top = near·tan(fovy) = 0.1·tan 45° = 0.1 instead of 0.1·tan 22.5°:
/// bottom = −0.1, right = aspect·top = 0.2, left = −0.2, height 0.2,
/// width 0.4. The pixels follow from this window: px = 100 + x″·100/0.2 =
/// 100 + 500x″ and py = 50 + y″·50/0.1 = 50 + 500y″, so A = (100, 50 −
/// 500√2/60) = (100, (150 − 25√2)/3) ≈ (100, 38.22), B = (100 + 10,
/// 50 − 10√2) ≈ (110, 35.86), C = (90, 50 − 10√2). The eye coordinates and
/// projections do not change.
fn fovy_not_halved(key: &str) -> Option<Forms> {
    Some(match key {
        "window.top" => [&["1/10"], &["0,1"], &["0.1"], &["0.1"]],
        "window.bottom" => [&["-1/10"], &["−0,1"], &["−0.1"], &["-0.1"]],
        "window.left" => [&["-1/5"], &["−0,2"], &["−0.2"], &["-0.2"]],
        "window.right" => [&["1/5"], &["0,2"], &["0.2"], &["0.2"]],
        "window.height" => [&["1/5"], &["0,2"], &["0.2"], &["0.2"]],
        "window.width" => [&["2/5"], &["0,4"], &["0.4"], &["0.4"]],
        "viewport.pixels.A" => [
            &["100", "(150-25*sqrt(2))/3"],
            &["100", "38,22"],
            &["100", "(150−25√2)/3"],
            &["100", "38.22"],
        ],
        "viewport.pixels.B" => [
            &["110", "50-10*sqrt(2)"],
            &["110", "35,86"],
            &["110", "50−10√2"],
            &["110", "35.86"],
        ],
        "viewport.pixels.C" => [
            &["90", "50-10*sqrt(2)"],
            &["90", "35,86"],
            &["90", "50−10√2"],
            &["90", "35.86"],
        ],
        _ => return None,
    })
}

/// The half extent h = 0.1·tan 22.5° = (√2 − 1)/10 ≈ 0.0414 (the
/// window's top) written as the height, and aspect·h = (√2 − 1)/5 ≈ 0.0828
/// (its right edge) as the width. Only these two: the edges, and the pixels
/// computed from them, stay right.
fn height_is_half_extent(key: &str) -> Option<Forms> {
    Some(match key {
        "window.height" => [
            &["(sqrt(2)-1)/10"],
            &["0,0414"],
            &["(√2−1)/10"],
            &["0.0414"],
        ],
        "window.width" => [&["(sqrt(2)-1)/5"], &["0,0828"], &["(√2−1)/5"], &["0.0828"]],
        _ => return None,
    })
}

/// n = Pe − Pr = (1, 0, 1), not divided by |Pe − Pr| = √2. u = Vup × n
/// normalised keeps its direction, (√2/2, 0, −√2/2); v = n × u = (1, 0, 1) ×
/// (1, 0, −1)/√2 = (0, 2, 0)/√2 = (0, √2, 0). With P − Pe = (−3, −1, −3),
/// (−2, −1, −3), (−3, −1, −2) for A, B, C: x′ = u·(P − Pe) = 0, √2/2,
/// −√2/2; y′ = v·(P − Pe) = −√2; z′ = n·(P − Pe) = −6, −5, −5. So
/// A′ = (0, −√2, −6), B′ = (√2/2, −√2, −5), C′ = (−√2/2, −√2, −5). With
/// d = −0.1: A″ = (0, −0.1·(−√2)/(−6)) = (0, −√2/60), right (y′ and z′
/// both grew by √2); B″ = (−0.1·(√2/2)/(−5), −0.1·(−√2)/(−5)) = (√2/100,
/// −√2/50), C″ = (−√2/100, −√2/50). The pixels with the right window:
/// px = 100 + x″·100/right = 100 + x″·500(√2 + 1), so B's px = 100 +
/// 5√2(√2 + 1) = 110 + 5√2 ≈ 117.07 and C's 90 − 5√2 ≈ 82.93; py and A stay.
fn n_not_normalized(key: &str) -> Option<Forms> {
    Some(match key {
        // a bare 1 is the mistake's value, never "0.7071 rounded to the units"
        "view.n" => [
            &["1", "0", "1"],
            &["1,0", "0", "1,0"],
            &["1", "0", "1"],
            &["1.0", "0", "1.0"],
        ],
        "view.v" => [
            &["0", "sqrt(2)", "0"],
            &["0", "1,414", "0"],
            &["0", "√2", "0"],
            &["0", "1.414", "0"],
        ],
        "view.points.A" => [
            &["0", "-sqrt(2)", "-6"],
            &["0", "−1,414", "−6"],
            &["0", "−√2", "−6"],
            &["0", "-1.414", "-6"],
        ],
        "view.points.B" => [
            &["sqrt(2)/2", "-sqrt(2)", "-5"],
            &["0,7071", "−1,414", "−5"],
            &["√2/2", "−√2", "−5"],
            &["0.7071", "-1.414", "-5"],
        ],
        "view.points.C" => [
            &["-sqrt(2)/2", "-sqrt(2)", "-5"],
            &["−0,7071", "−1,414", "−5"],
            &["−√2/2", "−√2", "−5"],
            &["-0.7071", "-1.414", "-5"],
        ],
        "project.points.B" => [
            &["sqrt(2)/100", "-sqrt(2)/50"],
            &["0,01414", "−0,02828"],
            &["√2/100", "−√2/50"],
            &["0.01414", "-0.02828"],
        ],
        "project.points.C" => [
            &["-sqrt(2)/100", "-sqrt(2)/50"],
            &["−0,01414", "−0,02828"],
            &["−√2/100", "−√2/50"],
            &["-0.01414", "-0.02828"],
        ],
        "viewport.pixels.B" => [
            &["110+5*sqrt(2)", "30-10*sqrt(2)"],
            &["117,07", "15,86"],
            &["110+5√2", "30−10√2"],
            &["117.07", "15.86"],
        ],
        "viewport.pixels.C" => [
            &["90-5*sqrt(2)", "30-10*sqrt(2)"],
            &["82,93", "15,86"],
            &["90−5√2", "30−10√2"],
            &["82.93", "15.86"],
        ],
        _ => return None,
    })
}

/// n to one significant figure: (0.7, 0, 0.7).
fn n_too_coarse(key: &str) -> Option<Forms> {
    (key == "view.n").then_some([
        &["0.7", "0", "0.7"],
        &["0,7", "0", "0,7"],
        &["0.7", "0", "0.7"],
        &["0.7", "0", "0.7"],
    ])
}

/// Pixel B = (110 + 10√2, 30 − 10√2) ≈ (124.14, 15.86) worked out in
/// decimals and its x's digits swapped: 142.14.
fn pixel_slip(key: &str) -> Option<Forms> {
    (key == "viewport.pixels.B").then_some([
        &["142.14", "15.86"],
        &["142,14", "15,86"],
        &["142.14", "15.86"],
        &["142.14", "15.86"],
    ])
}

/// The value the student writes for a key (None: left out).
fn value(s: &Student, key: &str) -> Option<String> {
    if s.no_pixels && key.starts_with("viewport.") {
        return None;
    }
    if s.v_in_words && key == "view.v" {
        let words = match (s.cross_order, s.n_not_normalized) {
            (true, _) => "nol, minus satu, nol",
            (_, true) => "nol, akar dua, nol",
            _ => "nol, satu, nol",
        };
        return Some(format!("\"{words}\""));
    }
    if let (Some(w), "window.width") = (&s.width, key) {
        return Some(format!("\"{w}\""));
    }
    // the student's mistakes, a mistake before a slip
    let made: [(bool, Writes); 6] = [
        (s.cross_order, cross_order),
        (s.fovy_not_halved, fovy_not_halved),
        (s.height_is_half_extent, height_is_half_extent),
        (s.n_not_normalized, n_not_normalized),
        (s.n_too_coarse, n_too_coarse),
        (s.pixel_slip, pixel_slip),
    ];
    let parts = made
        .iter()
        .filter(|(on, _)| *on)
        .find_map(|(_, forms)| forms(key))
        .map(|f| f[s.form % 4].to_vec())
        .unwrap_or_else(|| right(key, s.form));
    Some(if parts.len() == 1 {
        format!("\"{}\"", parts[0])
    } else {
        vector(s.form, &parts)
    })
}

/// The student's answer file.
pub fn answer_file(s: &Student) -> String {
    let mut out = format!(
        "student = \"{}\"\n",
        s.name
            .replace('\\', "\\\\")
            .replace('"', "\\\"")
            .replace('\r', "\\r")
            .replace('\n', "\\n")
    );
    for key in KEYS {
        if let Some(v) = value(s, key) {
            out.push_str(&format!("{key} = {v}\n"));
        }
    }
    out
}

/// The names of the class of problems/answers/class/.
pub const NAMES: [&str; 24] = [
    "Adi", "Ayu", "Bagus", "Bayu", "Citra", "Dewi", "Dimas", "Eka", "Fajar", "Fitri", "Gilang",
    "Hana", "Indah", "Joko", "Kartika", "Lestari", "Made", "Nur", "Putri", "Rizky", "Sari",
    "Wahyu", "Wulan", "Yusuf",
];

/// A class of 24 drawn from a seed (SplitMix64, as `generate` draws): each
/// student's written form and mistakes at these rates, each drawn on its
/// own: u = n × Vup 12 %, tan(fovy) 15 %, the half extent as the height
/// 30 %, n not normalised 10 %, n to one figure 10 %, v in words 4 %, no
/// pixels 8 %, a slip in pixel B 15 %, and the text's printed width 0.082
/// copied 15 %. A draw that meets a mistake drawn before it on the same
/// keys is dropped: u = n × Vup, tan(fovy) and n not normalised each
/// change pixels the others change too (one at most), the half extent
/// changes the height tan(fovy) changes, n to one figure is not n not
/// normalised, the slip is in a pixel B no mistake changed, and the
/// printed width is not with a mistake that gives a width.
pub fn seeded_class(seed: u64) -> Vec<Student> {
    let mut rng = grafika::num::rng::SplitMix64::new(seed);
    let mut chance = |percent: u64| rng.below(100) < percent;
    NAMES
        .iter()
        .map(|name| {
            // every chance is drawn, dropped or not, so that each draw
            // keeps its place in the seed's sequence
            let cross_order = chance(12);
            let fovy_not_halved = chance(15) && !cross_order;
            let height_is_half_extent = chance(30) && !fovy_not_halved;
            let n_not_normalized = chance(10) && !cross_order && !fovy_not_halved;
            let n_too_coarse = chance(10) && !n_not_normalized;
            let v_in_words = chance(4);
            let no_pixels = chance(8);
            let pixel_slip = chance(15) && !cross_order && !fovy_not_halved && !n_not_normalized;
            let printed_width = chance(15) && !fovy_not_halved && !height_is_half_extent;
            let form = (0..4).filter(|_| chance(50)).count() % 4;
            Student {
                name: name.to_string(),
                form,
                cross_order,
                fovy_not_halved,
                height_is_half_extent,
                n_not_normalized,
                n_too_coarse,
                v_in_words,
                no_pixels,
                width: printed_width.then(|| "0.082".to_string()),
                pixel_slip,
            }
        })
        .collect()
}

/// The file name of a student of [`seeded_class`]: `adi.toml`.
pub fn file_name(s: &Student) -> String {
    format!("{}.toml", s.name.to_lowercase())
}
