//! The names of a step's values in Bahasa Indonesia, with the course
//! text's own terms (region code, face, viewing window): one exhaustive
//! match, so a new name without its words does not compile. Notation is
//! written as its key spells it (`u`, `cos α`, `A'`). A word table: long
//! on purpose.

use super::Id;
use crate::report::words::keys::KeyWords;
use crate::stages::trace::Name;

impl super::super::names::NameWords for Id {
    fn name(&self, n: &Name) -> String {
        let word = match n {
            // notation, the same in every language: as its key spells it
            Name::Math(_) | Name::Eye(_) | Name::Image(_) => return n.to_string(),
            Name::EyeZ(p) => return format!("z' dari {p}'"),
            Name::Pixel(p) => return format!("piksel {p}"),
            Name::Bit(bit, _) => {
                let kiri = self.plane(crate::tutor::key::Plane::ALL[*bit]);
                return format!("bit {} ({kiri})", bit + 1);
            }
            Name::Vertex(k) => return format!("verteks {k} (X, Y)"),
            Name::InEyeSpace(v) => return format!("{v} (ruang kamera)"),
            Name::Unclamped => "sebelum dibatasi",
            Name::Height => "tinggi",
            Name::Width => "lebar",
            Name::Color => "warna",
            Name::Highlight => "sorotan (highlight)",
            Name::Contributes => "menyumbang",
            Name::HalfFovy => "fovy/2 (derajat)",
            Name::Outcodes => "region code",
            Name::RegionCode => "region code",
            Name::Agree => "sama",
            Name::TKept => "t titik yang dipertahankan",
            Name::From => "ujung awal",
            Name::To => "ujung akhir",
            Name::Segment => "segmen garis",
            Name::Inside => "di dalam",
            Name::Polygon => "poligon (x, y, z, w)",
            Name::ClippedPolygon => "poligon hasil clipping",
            Name::Object => "objek",
            Name::PolygonFace => "face poligon",
            Name::ObjectTriangle => "segitiga pada objek",
            Name::Triangle => "segitiga",
            Name::ZAtVertices => "z di verteks",
            Name::FaceCentre => "pusat face",
            Name::SurfaceColour => "warna permukaan",
            Name::SameAsRasterizer => "sama dengan milik rasterizer",
        };
        word.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::words::names::NameWords;

    #[test]
    fn names_in_the_texts_words() {
        let id = |n: Name| Id.name(&n);
        let a = || "A".to_string();
        assert_eq!(id(Name::EyeZ(a())), "z' dari A'");
        assert_eq!(id(Name::Pixel(a())), "piksel A");
        assert_eq!(id(Name::Bit(0, "kiri (left)")), "bit 1 (kiri)");
        assert_eq!(id(Name::Bit(5, "belakang (back)")), "bit 6 (belakang)");
        assert_eq!(id(Name::Vertex(2)), "verteks 2 (X, Y)");
        assert_eq!(id(Name::InEyeSpace("N")), "N (ruang kamera)");
        assert_eq!(id(Name::FaceCentre), "pusat face");
        assert_eq!(id(Name::From), "ujung awal");
        assert_eq!(id(Name::ClippedPolygon), "poligon hasil clipping");
        // Notation is the same in every language.
        assert_eq!(id(Name::Eye(a())), "A'");
        assert_eq!(id(Name::Image(a())), "A''");
        for same in ["Pe − Pr", "cos α", "code0 AND code1", "top", "n"] {
            assert_eq!(id(Name::math(same)), same);
        }
    }
}
