//! The names of a step's values in Bahasa Indonesia, with the course
//! text's own terms (region code, face, viewing window): one exhaustive
//! match, so a new name without its words does not compile. Notation is
//! written as it is (`u`, `cos α`, `A'`). A word table: long on purpose.

use super::Id;
use crate::stages::trace::Name;

impl super::super::names::NameWords for Id {
    fn name(&self, n: &Name) -> String {
        let word = match n {
            Name::Math(s) => s,
            Name::Eye(p) => return format!("{p}'"),
            Name::Image(p) => return format!("{p}''"),
            Name::EyeZ(p) => return format!("z' dari {p}'"),
            Name::Pixel(p) => return format!("piksel {p}"),
            Name::Bit(bit, _) => {
                let kiri = crate::report::words::PLANE_NAMES[*bit].1;
                return format!("bit {} ({kiri})", bit + 1);
            }
            Name::Vertex(k) => return format!("verteks {k} (X, Y)"),
            Name::InEyeSpace(v) => return format!("{v} (ruang kamera)"),
            Name::Unclamped => "sebelum dibatasi",
            Name::Color => "warna",
            Name::Highlight => "sorotan (highlight)",
            Name::Contributes => "menyumbang",
            Name::HalfFovy => "fovy/2 (derajat)",
            Name::Outcodes => "region code",
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
