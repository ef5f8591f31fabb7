//! Answer files of students of the triangle ABC example
//! (problems/text-triangle.toml) with chosen mistakes: the right values and
//! each mistake's values derived by hand below, written in the forms
//! students type (exact forms, rounded decimals, decimal commas, `√`, `−`,
//! vectors as one string). Used by tests/class.rs (a class of 60 with
//! mistakes at known rates) and by examples/class.rs (the class of
//! problems/answers/class/, from a seed).
#![allow(dead_code)]

/// What one student does.
#[derive(Clone, Debug, Default)]
pub struct Student {
    /// The name in the file (`student = "…"`).
    pub name: String,
    /// Which of the written forms of the right answers: 0 exact (ASCII),
    /// 1 rounded decimals with decimal commas, 2 vectors as one string with
    /// `√` and `−`, 3 four-figure decimals.
    pub form: usize,
    /// u = n × Vup: u, v, the eye coordinates, the projections and the
    /// pixels of every point change sign in x and y (11 answers).
    pub cross_order: bool,
    /// tan(fovy) for tan(fovy/2): top = 0.1·tan 45° = 0.1, so the window is
    /// ±0.1 by ±0.2, height 0.2 (width written as `width` below).
    pub fovy_not_halved: bool,
    /// The half extent h = 0.1·tan 22.5° = (√2−1)/10 ≈ 0.0414 given as the
    /// height.
    pub height_is_half_extent: bool,
    /// n = Pe − Pr = (1, 0, 1), not divided by |Pe − Pr| = √2 (written 1.0).
    pub n_not_normalized: bool,
    /// n to one significant figure, (0.7, 0, 0.7): too coarse.
    pub n_too_coarse: bool,
    /// v written in words: unparseable.
    pub v_in_words: bool,
    /// The viewport part left out (three pixels missing).
    pub no_pixels: bool,
    /// The window's width as written (None: the right width in the form).
    pub width: Option<String>,
    /// A slip in pixel B's x: 142.14 for 124.14 (digits swapped).
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

/// The keys each mistake changes.
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
pub const FOVY_KEYS: [&str; 5] = [
    "window.top",
    "window.bottom",
    "window.left",
    "window.right",
    "window.height",
];

/// The value the student writes for a key (None: left out).
fn value(s: &Student, key: &str) -> Option<String> {
    let f = s.form;
    let mistaken: Option<Vec<&str>> = match key {
        _ if s.no_pixels && key.starts_with("viewport.") => return None,
        "view.v" if s.v_in_words => return Some("\"nol, satu, nol\"".into()),
        "window.width" if s.width.is_some() => return s.width.as_ref().map(|w| format!("\"{w}\"")),
        // written to one decimal: a bare 1 would read as 0.7071 rounded to
        // the units (too coarse), not as a wrong answer
        "view.n" if s.n_not_normalized => Some(vec!["1.0", "0", "1.0"]),
        "view.n" if s.n_too_coarse => Some(vec!["0.7", "0", "0.7"]),
        // u = n × Vup = (−1, 0, 1)/√2, v = n × u = (0, −1, 0): x', y' flip
        "view.u" if s.cross_order => Some(vec!["-0.7071", "0", "0.7071"]),
        "view.v" if s.cross_order => Some(vec!["0", "-1", "0"]),
        "view.points.A" if s.cross_order => Some(vec!["0", "1", "-3√2"]),
        "view.points.B" if s.cross_order => Some(vec!["-0.7071", "1", "-3.536"]),
        "view.points.C" if s.cross_order => Some(vec!["0.7071", "1", "-3.536"]),
        "project.points.A" if s.cross_order => Some(vec!["0", "0.02357"]),
        "project.points.B" if s.cross_order => Some(vec!["-0.02", "0.02828"]),
        "project.points.C" if s.cross_order => Some(vec!["0.02", "0.02828"]),
        // px = 100 − (px − 100), py = 100 − py
        "viewport.pixels.A" if s.cross_order => Some(vec!["100", "78.45"]),
        "viewport.pixels.B" if s.cross_order => Some(vec!["75.86", "84.14"]),
        "viewport.pixels.C" if s.cross_order => Some(vec!["124.14", "84.14"]),
        "viewport.pixels.B" if s.pixel_slip => Some(vec!["142.14", "15.86"]),
        // top = 0.1·tan 45° = 0.1, right = 2·top
        "window.top" if s.fovy_not_halved => Some(vec!["0.1"]),
        "window.bottom" if s.fovy_not_halved => Some(vec!["-0.1"]),
        "window.left" if s.fovy_not_halved => Some(vec!["-0.2"]),
        "window.right" if s.fovy_not_halved => Some(vec!["0.2"]),
        "window.height" if s.fovy_not_halved => Some(vec!["0.2"]),
        "window.height" if s.height_is_half_extent => Some(vec!["0.0414"]),
        _ => None,
    };
    let parts = mistaken.unwrap_or_else(|| right(key, f));
    Some(if parts.len() == 1 {
        format!("\"{}\"", parts[0])
    } else {
        vector(f, &parts)
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
/// 30 % (with width aspect·h = 0.0828; not with tan(fovy), which changes
/// the height itself), n not normalised 10 %, n to one figure 10 %, v in
/// words 4 %, no pixels 8 %, a slip in pixel B 15 %, and the text's
/// printed width 0.082 copied 15 % (tan(fovy) gives 0.4).
pub fn seeded_class(seed: u64) -> Vec<Student> {
    let mut rng = grafika::num::rng::SplitMix64::new(seed);
    let mut chance = |percent: u64| rng.below(100) < percent;
    NAMES
        .iter()
        .map(|name| {
            let cross_order = chance(12);
            let fovy_not_halved = chance(15);
            let height_is_half_extent = chance(30) && !fovy_not_halved;
            let n_not_normalized = chance(10);
            let n_too_coarse = chance(10) && !n_not_normalized;
            let v_in_words = chance(4);
            let no_pixels = chance(8);
            let pixel_slip = chance(15);
            let printed_width = chance(15);
            let form = (0..4).filter(|_| chance(50)).count() % 4;
            let width = if fovy_not_halved {
                Some("0.4".to_string())
            } else if height_is_half_extent {
                Some("0.0828".to_string())
            } else if printed_width {
                Some("0.082".to_string())
            } else {
                None
            };
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
                width,
                pixel_slip,
            }
        })
        .collect()
}

/// The file name of a student of [`seeded_class`]: `adi.toml`.
pub fn file_name(s: &Student) -> String {
    format!("{}.toml", s.name.to_lowercase())
}
