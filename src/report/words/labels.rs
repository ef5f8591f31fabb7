//! The names of an answer's keys in the text, in the chosen language. The
//! keys are also the keys of the results, so they stay as the tutor writes
//! them there; only the text shows these words. Notation (`cos α`, `code0`,
//! `top`) is the same in every language. (A step's value names are
//! [`super::names`].)

use crate::report::lang::Lang;
use crate::stages::trace::Name;

/// The six planes of the clipping box as the text names them (kiri, …),
/// or in English.
fn plane(p: &str, lang: Lang) -> String {
    let at = crate::report::words::PLANE_NAMES
        .iter()
        .find(|(en, _)| *en == p);
    match (at, lang) {
        (Some((_, id)), Lang::Id) => id.to_string(),
        _ => p.to_string(),
    }
}

/// The words of a key of a worked solution's answer in Indonesian (a part,
/// a group, a value named in words: `view` → `transformasi pandang`,
/// `points` → `titik`, `kept` → `dipertahankan`; `left` under
/// `intersections` → `kiri`); English keeps the keys, which are also the
/// keys of an answer file. `under` is the key this one belongs to.
pub fn answer_key(key: &str, under: Option<&str>, lang: Lang) -> String {
    if lang == Lang::En {
        return key.to_string();
    }
    let id = match (under, key) {
        (None, "view") => "transformasi pandang",
        (None, "project") => "proyeksi",
        (None, "window") => "viewing window",
        (None, "clip") => "clipping",
        (None, "shade") => "pencahayaan",
        (Some("intersections"), p) => return plane(p, lang),
        (_, "matrix") => "matriks pandang V",
        (_, "points") => "titik",
        (_, "pixels") => "piksel",
        (_, "segment") => "segmen garis hasil clipping",
        (_, "intersections") => "titik potong",
        (_, "point") => "titik potong",
        (_, "kept") => "dipertahankan",
        (_, "color") => "warna",
        (_, "unclamped") => "sebelum dibatasi",
        (_, "lights") => "sumber cahaya",
        (_, "in_range") => "dalam jangkauan",
        (_, "distance") => "jarak d",
        (_, "attenuation") => "Att",
        (_, "spot") => "Spot",
        (_, "cos_alpha") => "cos α",
        (_, "cos_beta") => "cos β",
        (_, "N_dot_H") => "N·H",
        _ => key,
    };
    id.to_string()
}

/// An answer key split into its parts: `clip.2.intersections.left.t` and
/// `clip[2].intersections.left.t` are `clip`, the segment 2, and
/// `intersections.left.t` (`None` when the part has one segment).
fn parts(key: &str) -> (Vec<String>, Option<usize>) {
    let mut parts = Vec::new();
    let mut index = None;
    for p in key.split('.') {
        match p.split_once('[') {
            Some((name, i)) => {
                parts.push(name.to_string());
                index = i.trim_end_matches(']').parse().ok();
            }
            None => match p.parse::<usize>() {
                Ok(i) => index = Some(i),
                Err(_) => parts.push(p.to_string()),
            },
        }
    }
    (parts, index)
}

/// The name the worked steps give the value of an answer key (`view.n` →
/// `n`, `view.points.A` → `A'`, `project.points.A` → `A''`,
/// `viewport.pixels.A` → `piksel A`, `view.matrix` → `V`,
/// `clip.intersections.left.t` → `t (kiri)`): the answer table of a page.
pub fn answer_name(key: &str, lang: Lang) -> String {
    let (parts, index) = parts(key);
    let p: Vec<&str> = parts.iter().map(String::as_str).collect();
    let t = |en: &str, id: &str| crate::report::lang::tr(lang, en, id).to_string();
    let name = match p[..] {
        ["view", "matrix"] => "V".to_string(),
        ["view", "points", n] => format!("{n}'"),
        ["project", "points", n] => format!("{n}''"),
        ["viewport", "pixels", n] => super::of(lang).name(&Name::Pixel(n.to_string())),
        ["window", k] => match k.strip_prefix("far_") {
            Some(edge) => format!("{edge} (far plane)"),
            None => k.to_string(),
        },
        ["clip", "segment"] => t("clipped segment", "segmen garis hasil clipping"),
        ["clip", "intersections", pl, what] => {
            let what = match what {
                "point" => "P(t)".to_string(),
                other => answer_key(other, Some(pl), lang),
            };
            format!("{what} ({})", plane(pl, lang))
        }
        ["shade", "lights", k] => {
            let i = index.map(|i| format!(" {i}")).unwrap_or_default();
            let light = t("light", "cahaya");
            return format!("{} ({light}{i})", answer_key(k, Some("lights"), lang));
        }
        [_, k] => answer_key(k, Some(p[0]), lang),
        _ => key.to_string(),
    };
    match index {
        Some(i) => format!("{}{i}: {name}", t("segment ", "segmen ")),
        None => name,
    }
}

/// An edge or size of the window in words (`top` → `batas atas viewing
/// window (top)`; with `far_`, on the far plane).
fn window_words(k: &str, lang: Lang) -> String {
    if lang == Lang::En {
        return format!("window {k}");
    }
    let (far, edge) = match k.strip_prefix("far_") {
        Some(e) => (" pada far plane", e),
        None => ("", k),
    };
    let what = match edge {
        "top" => "batas atas",
        "bottom" => "batas bawah",
        "left" => "batas kiri",
        "right" => "batas kanan",
        "height" => "tinggi",
        _ => "lebar",
    };
    format!("{what} viewing window{far} ({k})")
}

/// What an answer key asks for, in a few words (`view.points.A` → `koordinat
/// kamera A'`): the prompt of a practice session.
pub fn answer_words(key: &str, lang: Lang) -> String {
    let (parts, _) = parts(key);
    let p: Vec<&str> = parts.iter().map(String::as_str).collect();
    let t = |en: &str, id: &str| crate::report::lang::tr(lang, en, id).to_string();
    match p[..] {
        ["view", a @ ("n" | "u" | "v")] => format!("{} {a}", t("camera axis", "sumbu kamera")),
        ["view", "matrix"] => t("the view matrix V", "matriks transformasi pandang V"),
        ["view", "points", n] => format!("{} {n}'", t("eye coordinates", "koordinat kamera")),
        ["project", "points", n] => format!("{} {n}''", t("projected point", "hasil proyeksi")),
        ["window", k] => window_words(k, lang),
        ["viewport", "pixels", n] => {
            format!("{} {n}", t("pixel coordinates of", "koordinat piksel"))
        }
        ["shade", "L"] => t("unit vector L", "vektor satuan L"),
        ["shade", "N"] => t("unit vector N", "vektor satuan N"),
        ["shade", "R"] => t("reflection vector R", "vektor pantulan R"),
        ["shade", "H"] => t("half-way vector H", "vektor setengah jalan H"),
        ["shade", "cos_alpha"] => "cos α = L·N".to_string(),
        ["shade", "cos_beta"] => "cos β = R·V".to_string(),
        ["shade", "N_dot_H"] => "N·H".to_string(),
        ["shade", "color"] => t("the colour, clamped to [0, 1]", "warna, dibatasi ke [0, 1]"),
        ["shade", k] => format!("{} {k}", t("term", "komponen")),
        ["clip", "code0"] => t("outcode of P0", "region code P0"),
        ["clip", "code1"] => t("outcode of P1", "region code P1"),
        ["clip", "intersections", pl, "t"] => {
            format!("t {} {}", t("at the plane", "pada bidang"), plane(pl, lang))
        }
        ["clip", "intersections", pl, "point"] => format!(
            "{} {}",
            t("intersection with the plane", "titik potong dengan bidang"),
            plane(pl, lang)
        ),
        ["clip", "intersections", pl, "code"] => format!(
            "{} {}",
            t(
                "outcode of the intersection with the plane",
                "region code titik potong dengan bidang"
            ),
            plane(pl, lang)
        ),
        ["clip", "segment"] => t("the clipped segment", "segmen garis hasil clipping"),
        ["clip", "status"] => t("the status", "status"),
        _ => key.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_are_named_as_the_steps_name_them() {
        let (en, id) = (|k| answer_name(k, Lang::En), |k| answer_name(k, Lang::Id));
        assert_eq!(en("view.n"), "n");
        assert_eq!(en("view.matrix"), "V");
        assert_eq!(en("view.points.A"), "A'");
        assert_eq!(en("project.points.A"), "A''");
        assert_eq!(en("viewport.pixels.A"), "A pixel");
        assert_eq!(id("viewport.pixels.A"), "piksel A");
        assert_eq!(id("window.top"), "top");
        assert_eq!(id("window.far_top"), "top (far plane)");
        assert_eq!(id("clip.intersections.left.point"), "P(t) (kiri)");
        assert_eq!(
            id("clip[2].intersections.top.kept"),
            "segmen 2: dipertahankan (atas)"
        );
        assert_eq!(id("clip.2.status"), "segmen 2: status");
        assert_eq!(id("shade.color"), "warna");
        assert_eq!(id("shade.cos_alpha"), "cos α");
        assert_eq!(id("shade.lights[1].attenuation"), "Att (cahaya 1)");
    }

    #[test]
    fn practice_asks_in_the_texts_words() {
        let id = |k| answer_words(k, Lang::Id);
        assert_eq!(id("window.top"), "batas atas viewing window (top)");
        assert_eq!(
            id("window.far_width"),
            "lebar viewing window pada far plane (far_width)"
        );
        assert_eq!(id("view.points.A"), "koordinat kamera A'");
        assert_eq!(id("clip.1.segment"), "segmen garis hasil clipping");
        assert_eq!(answer_words("window.top", Lang::En), "window top");
    }
}
