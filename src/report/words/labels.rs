//! The names of a step's values in the text, in the chosen language. The
//! names are also the keys of the step's JSON `values`, so they stay as
//! the stages write them there; only the text shows these words. Notation
//! (`Pe − Pr`, `cos α`, `code0`, `top`) is the same in every language.
//! (An answer's keys have their words in `keys`.)

use crate::report::lang::Lang;

/// Names made of words, and their Indonesian.
const NAMES: [(&str, &str); 23] = [
    ("N (eye space)", "N (ruang kamera)"),
    ("P (eye space)", "P (ruang kamera)"),
    ("agree", "sama"),
    ("color", "warna"),
    ("contributes", "menyumbang"),
    ("face centre", "pusat face"),
    ("fovy/2 (degrees)", "fovy/2 (derajat)"),
    ("from", "ujung awal"),
    ("inside", "di dalam"),
    ("kept", "dipertahankan"),
    ("object", "objek"),
    ("object's triangle", "segitiga pada objek"),
    ("outcodes", "region code"),
    ("polygon face", "face poligon"),
    ("same as the rasterizer's", "sama dengan milik rasterizer"),
    ("segment", "segmen garis"),
    ("surface colour", "warna permukaan"),
    ("t kept", "t titik yang dipertahankan"),
    ("to", "ujung akhir"),
    ("triangle", "segitiga"),
    ("unclamped", "sebelum dibatasi"),
    ("z at the vertices", "z di verteks"),
    ("highlight", "sorotan (highlight)"),
];

/// The text name of a value called `name`, in `lang`.
pub fn label(name: &str, lang: Lang) -> String {
    if lang == Lang::En {
        return name.to_string();
    }
    if let Some((_, id)) = NAMES.iter().find(|(en, _)| *en == name) {
        return id.to_string();
    }
    // `z' of A'`, `A pixel`, `screen vertex 0 (x, y)`, `bit 1 (kiri (left))`.
    if let Some((z, p)) = name.split_once(" of ") {
        return format!("{z} dari {p}");
    }
    if let Some(k) = name.strip_prefix("vertex ") {
        return format!("verteks {k}");
    }
    if let Some(p) = name.strip_suffix(" pixel") {
        return format!("piksel {p}");
    }
    if let Some(n) = name
        .strip_prefix("screen vertex ")
        .and_then(|r| r.strip_suffix(" (x, y)"))
    {
        return format!("verteks layar {n} (x; y)");
    }
    if let Some((bit, side)) = name.strip_prefix("bit ").and_then(|r| r.split_once(" (")) {
        let kiri = side
            .split(" (")
            .next()
            .unwrap_or(side)
            .trim_end_matches(')');
        return format!("bit {bit} ({kiri})");
    }
    name.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_names_in_indonesian() {
        let id = |n| label(n, Lang::Id);
        assert_eq!(id("z' of A'"), "z' dari A'");
        assert_eq!(id("A pixel"), "piksel A");
        assert_eq!(id("screen vertex 2 (x, y)"), "verteks layar 2 (x; y)");
        assert_eq!(id("bit 1 (kiri (left))"), "bit 1 (kiri)");
        assert_eq!(id("face centre"), "pusat face");
        assert_eq!(id("from"), "ujung awal");
        // Notation is the same in every language.
        for same in ["Pe − Pr", "cos α", "code0 AND code1", "top", "n"] {
            assert_eq!(id(same), same);
        }
        assert_eq!(label("z' of A'", Lang::En), "z' of A'");
    }
}
