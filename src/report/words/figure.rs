//! The words of the figures: panel titles and descriptions (captions and
//! screen readers), words inside the figures, and the errors of the files
//! `--figure` and `--html` write; English and Bahasa Indonesia (the course
//! text's terms, docs/glossary.md).

use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::lang::Lang;

/// The words of a figure message.
pub fn figure(m: &FigureMsg, lang: Lang) -> String {
    let id = lang == Lang::Id;
    let pick = |en: &str, ind: &str| if id { ind } else { en }.to_string();
    match m {
        FigureMsg::Title(p) => {
            let (en, ind) = title(*p);
            pick(en, ind)
        }
        FigureMsg::Desc(p) => {
            let (en, ind) = desc(*p);
            pick(en, ind)
        }
        FigureMsg::Word(w) => {
            let (en, ind) = word(*w);
            pick(en, ind)
        }
        FigureMsg::Exists(path) => pick(
            &format!("{path} exists; remove it or choose another name"),
            &format!("{path} sudah ada; hapus atau pilih nama lain"),
        ),
    }
}

fn title(p: Panel) -> (&'static str, &'static str) {
    match p {
        Panel::Camera => (
            "The camera in world coordinates",
            "Kamera dalam sistem koordinat dunia",
        ),
        Panel::Projection => (
            "Projection onto the view plane",
            "Proyeksi ke bidang proyeksi",
        ),
        Panel::ProjectionSide => (
            "Side view (y–z): similar triangles",
            "Tampak samping (y–z): kesamaan segitiga",
        ),
        Panel::ViewPlane => (
            "The images on the view plane (x–y)",
            "Bayangan pada bidang proyeksi (x–y)",
        ),
        Panel::Frustum => ("The view volume from the eye", "View volume dari mata"),
        Panel::WindowSide => (
            "Side view (y–z): fovy and top",
            "Tampak samping (y–z): fovy dan top",
        ),
        Panel::NearWindow => (
            "The window on the near plane",
            "Viewing window pada near plane",
        ),
        Panel::Viewport => (
            "The viewport (pixels, origin bottom left)",
            "Viewport (piksel, titik asal kiri bawah)",
        ),
        Panel::Clip => (
            "Clipping P0P1 against the box",
            "Clipping P0P1 terhadap view volume",
        ),
        Panel::Shade => (
            "Lighting vectors at the surface point",
            "Vektor pencahayaan di titik permukaan",
        ),
    }
}

fn desc(p: Panel) -> (&'static str, &'static str) {
    match p {
        Panel::Camera => (
            "Cabinet oblique projection (x − z/(2√2), y − z/(2√2)). Black arrows: the world axes x, y, z. Blue dots: Peye and Pref, joined by the dotted line of sight. Sky-blue arrow: Vup, drawn at Pref. The camera axes u, v, n at Peye: green solid, purple dash-dot and vermillion dashed arrows, drawn twice the length of Vup (the note under the drawing states the length). Black dots: the named points, labelled with their eye coordinates.",
            "Proyeksi oblik kabinet (x − z/(2√2), y − z/(2√2)). Panah hitam: sumbu dunia x, y, z. Titik biru: Peye dan Pref, dihubungkan garis pandang bertitik. Panah biru muda: Vup, digambar di Pref. Sumbu kamera u, v, n di Peye: panah hijau tegas, ungu garis-titik dan merah jingga putus-putus, digambar dua kali panjang Vup (catatan di bawah gambar menyebut panjangnya). Titik hitam: titik-titik bernama, diberi label koordinat kameranya.",
        ),
        Panel::Projection => (
            "Cabinet oblique projection (x − z/(2√2), y − z/(2√2)) of eye coordinates. Sky-blue rectangle: the view plane. Dotted orange lines: the projectors from the centre of projection (parallel to z when orthographic) through each point (black dot) to its image (blue dot).",
            "Proyeksi oblik kabinet (x − z/(2√2), y − z/(2√2)) dari koordinat kamera. Persegi biru muda: bidang proyeksi. Garis jingga bertitik: proyektor dari pusat proyeksi (sejajar sumbu z pada proyeksi ortografik) melalui tiap titik (titik hitam) ke bayangannya (titik biru).",
        ),
        Panel::ProjectionSide => (
            "Side view: −z to the right, y up. The sky-blue line is the view plane; each projector (dotted) runs from the centre of projection through the point to its image. The black leg y of the point and the blue leg yp of the image make two similar triangles with the z axis.",
            "Tampak samping: −z ke kanan, y ke atas. Garis biru muda adalah bidang proyeksi; tiap proyektor (bertitik) berjalan dari pusat proyeksi melalui titik ke bayangannya. Sisi hitam y dari titik dan sisi biru yp dari bayangan membentuk dua segitiga yang sebentuk dengan sumbu z (kesamaan segitiga).",
        ),
        Panel::ViewPlane => (
            "The view plane seen from the front: xp to the right, yp up; each blue dot is a point's image.",
            "Bidang proyeksi dilihat dari depan: xp ke kanan, yp ke atas; tiap titik biru adalah bayangan sebuah titik.",
        ),
        Panel::Frustum => (
            "Cabinet oblique projection (x − z/(2√2), y − z/(2√2)) of eye space: the eye at the origin looking along −z. Blue rectangle: the near window (left..right × bottom..top at z = −near); sky-blue rectangle: the far window; black lines: the edges of the view volume. When far is not given or more than 10 times near, the far window is not drawn to scale: the edges run on, dashed vermillion, to twice near.",
            "Proyeksi oblik kabinet (x − z/(2√2), y − z/(2√2)) dari ruang kamera: mata di titik asal memandang ke arah −z. Persegi biru: viewing window pada near plane (left..right × bottom..top di z = −near); persegi biru muda: viewing window pada far plane; garis hitam: rusuk view volume. Bila far tidak diberikan atau lebih dari 10 kali near, viewing window pada far plane tidak digambar sesuai skala: rusuknya berlanjut putus-putus merah jingga sampai dua kali near.",
        ),
        Panel::WindowSide => (
            "Side view: −z to the right, y up. The eye at the origin; the purple arc is the angle fovy; the blue line is the near window from bottom to top, at distance near.",
            "Tampak samping: −z ke kanan, y ke atas. Mata di titik asal; busur ungu adalah sudut fovy; garis biru adalah viewing window pada near plane dari bottom sampai top, pada jarak near.",
        ),
        Panel::NearWindow => (
            "The window on the near plane: x to the right, y up; the blue dots are the projected points.",
            "Viewing window pada near plane: x ke kanan, y ke atas; titik biru adalah titik-titik hasil proyeksi.",
        ),
        Panel::Viewport => (
            "The viewport W × H in pixels, origin at the bottom left; each blue dot is a point at its pixel position.",
            "Viewport W × H dalam piksel, titik asal di kiri bawah; tiap titik biru adalah sebuah titik pada posisi pikselnya.",
        ),
        Panel::Clip => (
            "Cabinet oblique projection (x − z/(2√2), y − z/(2√2)). The kept part is solid blue, the cut-off parts dashed vermillion; each intersection tried is a dot labelled with its plane, t and outcode.",
            "Proyeksi oblik kabinet (x − z/(2√2), y − z/(2√2)). Bagian yang disimpan biru tegas, bagian yang dibuang putus-putus merah jingga; tiap titik potong yang dicoba diberi label bidang, t dan outcode-nya.",
        ),
        Panel::Shade => (
            "Cabinet oblique projection (x − z/(2√2), y − z/(2√2)) of the unit vectors at the surface point, all drawn with one length: the surface patch (black) perpendicular to N (black arrow), L toward the light (sky blue; L2, L3, … for further lights), R the reflection (purple, dash-dot), V toward the viewer (green), H the half vector for Blinn (orange, dotted). Arcs mark the angle α between L and N and the angle β between R and V.",
            "Proyeksi oblik kabinet (x − z/(2√2), y − z/(2√2)) dari vektor satuan di titik permukaan, semua sama panjang: potongan permukaan (hitam) tegak lurus N (panah hitam), L ke arah sumber cahaya (biru muda; L2, L3, … untuk sumber cahaya berikutnya), R vektor pantulan (ungu, garis-titik), V ke arah pengamat (hijau), H vektor setengah jalan untuk Blinn (jingga, bertitik). Busur menandai sudut α antara L dan N dan sudut β antara R dan V.",
        ),
    }
}

fn word(w: FigWord) -> (&'static str, &'static str) {
    match w {
        FigWord::Cop => ("centre of projection", "pusat proyeksi"),
        FigWord::Eye => ("eye", "mata"),
        FigWord::NotToScale => (
            "far window not to scale",
            "viewing window pada far plane tidak sesuai skala",
        ),
        FigWord::Surface => ("surface", "permukaan"),
        FigWord::CameraAxes => (
            "u green, v purple dash-dot, n vermillion dashed; length",
            "u hijau, v ungu garis-titik, n merah jingga putus-putus; panjang",
        ),
        FigWord::Zoomed => (
            "inset: the view plane near the centre of projection, enlarged",
            "sisipan: bidang proyeksi di dekat pusat proyeksi, diperbesar",
        ),
        FigWord::Coincide => (
            "coincide; drawn side by side",
            "berimpit; digambar berdampingan",
        ),
    }
}
