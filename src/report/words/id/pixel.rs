//! The words of `render --explain-pixel`'s geometry steps in Bahasa Indonesia (the course text's terms, docs/glossary.md).

use super::Id;
use crate::msg::PixelMsg;
use crate::report::words::{PixelWords, PLANE_NAMES};

impl PixelWords for Id {
    /// A word table: long on purpose.
    fn pixel(&self, m: &PixelMsg) -> String {
        match m {
            PixelMsg::SecVertex(k) => format!("Titik sudut {k} segitiga: koordinat objek → dunia → kamera → clip"),
            PixelMsg::SecClip => "Clipping segitiga terhadap view volume (Sutherland–Hodgman di ruang clip)".into(),
            PixelMsg::SecMatrices => "Matriks pandang dan matriks proyeksi".into(),
            PixelMsg::SecScreen(k) => format!("Titik sudut {k} segitiga yang digambar: koordinat clip → piksel"),
            PixelMsg::Matrices(n) => format!("Matriks {n}: pemodelan M, V·M dan P·V·M"),
            PixelMsg::World(n) => format!("Koordinat dunia titik {n}"),
            PixelMsg::Eye(n) => format!("Koordinat kamera titik {n} (matriks pandang)"),
            PixelMsg::ProjMatrix => "Matriks proyeksi".into(),
            PixelMsg::Clip(n) => format!("Koordinat clip titik {n}"),
            PixelMsg::Outcode(n) => format!("Region code titik {n} di ruang clip"),
            PixelMsg::ClipPlane(b) => format!(
                "Clipping terhadap bidang {} (bit {})",
                PLANE_NAMES[(*b).min(5)].1,
                b + 1
            ),
            PixelMsg::Divide(n) => format!("Pembagian perspektif titik {n}"),
            PixelMsg::WindowPoint(n) => format!("Titik {n} pada viewing window"),
            PixelMsg::Row(n) => format!("Baris piksel titik {n}, dihitung dari atas"),
            PixelMsg::Snap(n) => format!("Pembulatan {n} ke 1/256 piksel"),
            PixelMsg::SetUp => "Segitiga yang disiapkan untuk rasterizer".into(),
            PixelMsg::FOutcode => "bit 1: x < −w, bit 2: x > w, bit 3: y < −w, bit 4: y > w, bit 5: z < −w, bit 6: z > w".into(),
            PixelMsg::Composed => "renderer mengalikan titik objek dengan hasil kali V·M sekali (matriks yang sama untuk setiap titik objek)".into(),
            PixelMsg::BoxInside => "kotak pembatas objek berada di dalam view volume (kedelapan sudutnya ber-region code 000000), sehingga renderer menganggap region code setiap titik 000000 tanpa uji ini".into(),
            PixelMsg::Outside => "di luar sebuah bidang: titik ini tidak mendapat piksel sendiri; titik-titik poligon hasil clipping yang mendapatkannya".into(),
            PixelMsg::SameAsRaster(true) => "inilah titik-titik sudut yang dipakai rasterizer untuk segitiga piksel ini".into(),
            PixelMsg::SameAsRaster(false) => "titik-titik ini berbeda dari milik rasterizer (sebuah bug: mohon laporkan)".into(),
        }
    }
}
