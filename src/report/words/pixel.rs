//! The words of `render --explain-pixel`'s geometry steps, in English and
//! in Bahasa Indonesia (the course text's terms, docs/glossary.md).

use crate::msg::PixelMsg;
use crate::report::lang::Lang;

/// The words of `m` in `lang`.
pub fn words(m: &PixelMsg, lang: Lang) -> String {
    let (en, id) = pair(m);
    if lang == Lang::Id {
        id
    } else {
        en
    }
}

/// The plane of bit `b` (0…5) as the text names it.
fn plane(b: usize) -> (&'static str, &'static str) {
    const EN: [&str; 6] = ["left", "right", "bottom", "top", "front", "back"];
    const ID: [&str; 6] = ["kiri", "kanan", "bawah", "atas", "depan", "belakang"];
    (EN[b.min(5)], ID[b.min(5)])
}

/// The words of a section title or of a step of a vertex.
fn pair(m: &PixelMsg) -> (String, String) {
    let f = |en: String, id: String| (en, id);
    let s = |en: &str, id: &str| (en.to_string(), id.to_string());
    match m {
        PixelMsg::SecVertex(k) => f(
            format!("Vertex {k} of the triangle: object → world → eye → clip coordinates"),
            format!("Titik sudut {k} segitiga: koordinat objek → dunia → kamera → clip"),
        ),
        PixelMsg::SecClip => s(
            "Clipping the triangle against the view volume (Sutherland–Hodgman in clip space)",
            "Clipping segitiga terhadap view volume (Sutherland–Hodgman di ruang clip)",
        ),
        PixelMsg::SecMatrices => s(
            "The view and projection matrices",
            "Matriks pandang dan matriks proyeksi",
        ),
        PixelMsg::SecScreen(k) => f(
            format!("Vertex {k} of the set-up triangle: clip coordinates → pixel"),
            format!("Titik sudut {k} segitiga yang digambar: koordinat clip → piksel"),
        ),
        PixelMsg::Matrices(n) => f(
            format!("The matrices of {n}: modeling M, V·M and P·V·M"),
            format!("Matriks {n}: pemodelan M, V·M dan P·V·M"),
        ),
        PixelMsg::World(n) => f(
            format!("World coordinates of {n}"),
            format!("Koordinat dunia titik {n}"),
        ),
        PixelMsg::Eye(n) => f(
            format!("Eye coordinates of {n} (view matrix)"),
            format!("Koordinat kamera titik {n} (matriks pandang)"),
        ),
        PixelMsg::ProjMatrix => s("Projection matrix", "Matriks proyeksi"),
        PixelMsg::Clip(n) => f(
            format!("Clip coordinates of {n}"),
            format!("Koordinat clip titik {n}"),
        ),
        PixelMsg::Outcode(n) => f(
            format!("Outcode of {n} in clip space"),
            format!("Region code titik {n} di ruang clip"),
        ),
        PixelMsg::ClipPlane(b) => {
            let (en, id) = plane(*b);
            f(
                format!("Clipping against the {en} plane (bit {})", b + 1),
                format!("Clipping terhadap bidang {id} (bit {})", b + 1),
            )
        }
        PixelMsg::Divide(n) => f(
            format!("Perspective division of {n}"),
            format!("Pembagian perspektif titik {n}"),
        ),
        PixelMsg::WindowPoint(n) => f(
            format!("Window point of {n}"),
            format!("Titik {n} pada viewing window"),
        ),
        PixelMsg::Row(n) => f(
            format!("Pixel row of {n}, counted from the top"),
            format!("Baris piksel titik {n}, dihitung dari atas"),
        ),
        PixelMsg::Snap(n) => f(
            format!("Snapping {n} to 1/256 pixel"),
            format!("Pembulatan {n} ke 1/256 piksel"),
        ),
        PixelMsg::SetUp
        | PixelMsg::FOutcode
        | PixelMsg::Composed
        | PixelMsg::BoxInside
        | PixelMsg::Outside
        | PixelMsg::SameAsRaster(_) => note(m),
    }
}

/// The words of the set-up triangle's step and of the notes under steps
/// (the messages [`pair`] hands on; the last arm is `SameAsRaster(false)`).
fn note(m: &PixelMsg) -> (String, String) {
    let s = |en: &str, id: &str| (en.to_string(), id.to_string());
    match m {
        PixelMsg::SetUp => s(
            "The triangle set up for the rasterizer",
            "Segitiga yang disiapkan untuk rasterizer",
        ),
        PixelMsg::FOutcode => s(
            "bit 1: x < −w, bit 2: x > w, bit 3: y < −w, bit 4: y > w, bit 5: z < −w, bit 6: z > w",
            "bit 1: x < −w, bit 2: x > w, bit 3: y < −w, bit 4: y > w, bit 5: z < −w, bit 6: z > w",
        ),
        PixelMsg::Composed => s(
            "the renderer multiplies the object point by the product V·M once (the same matrix for every vertex of the object)",
            "renderer mengalikan titik objek dengan hasil kali V·M sekali (matriks yang sama untuk setiap titik objek)",
        ),
        PixelMsg::BoxInside => s(
            "the object's bounding box is inside the view volume (all eight corners have code 000000), so the renderer takes every vertex's code as 000000 without this test",
            "kotak pembatas objek berada di dalam view volume (kedelapan sudutnya ber-region code 000000), sehingga renderer menganggap region code setiap titik 000000 tanpa uji ini",
        ),
        PixelMsg::Outside => s(
            "outside a plane: this vertex gets no pixel of its own; the clipped polygon's vertices do",
            "di luar sebuah bidang: titik ini tidak mendapat piksel sendiri; titik-titik poligon hasil clipping yang mendapatkannya",
        ),
        PixelMsg::SameAsRaster(true) => s(
            "these are the vertices the rasterizer used for the pixel's triangle",
            "inilah titik-titik sudut yang dipakai rasterizer untuk segitiga piksel ini",
        ),
        _ => s(
            "these vertices differ from the rasterizer's (a bug: please report it)",
            "titik-titik ini berbeda dari milik rasterizer (sebuah bug: mohon laporkan)",
        ),
    }
}

/// Every message, for the test that each has words in both languages.
#[cfg(test)]
pub fn every() -> Vec<PixelMsg> {
    let n = || "V0".to_string();
    let mut v = vec![
        PixelMsg::SecVertex(0),
        PixelMsg::SecClip,
        PixelMsg::SecMatrices,
        PixelMsg::SecScreen(1),
        PixelMsg::Matrices(n()),
        PixelMsg::World(n()),
        PixelMsg::Eye(n()),
        PixelMsg::ProjMatrix,
        PixelMsg::Clip(n()),
        PixelMsg::Outcode(n()),
        PixelMsg::Divide(n()),
        PixelMsg::WindowPoint(n()),
        PixelMsg::Row(n()),
        PixelMsg::Snap(n()),
        PixelMsg::SetUp,
        PixelMsg::FOutcode,
        PixelMsg::Composed,
        PixelMsg::BoxInside,
        PixelMsg::Outside,
        PixelMsg::SameAsRaster(true),
        PixelMsg::SameAsRaster(false),
    ];
    v.extend((0..6).map(PixelMsg::ClipPlane));
    v
}
