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
        FigureMsg::Title(Panel::ShadeLight(k)) => {
            let l = if *k == 1 { "L".to_string() } else { format!("L{k}") };
            pick(
                &format!("Light {k}: the plane of N and {l}"),
                &format!("Sumber cahaya {k}: bidang N dan {l}"),
            )
        }
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
        FigureMsg::View { from, az, el } => pick(
            &format!("Axonometric view (orthographic), seen from the direction {from} (azimuth {az}°, elevation {el}°), y up."),
            &format!("Tampak aksonometri (ortografik), dilihat dari arah {from} (azimut {az}°, elevasi {el}°), y ke atas."),
        ),
        FigureMsg::OffPlane(name, deg) => pick(
            &format!("{name} is not in this plane (it leaves it by {deg}°): drawn in its own plane below"),
            &format!("{name} tidak terletak pada bidang ini (menyimpang {deg}°): digambar pada bidangnya sendiri di bawah"),
        ),
        FigureMsg::Plane(bit, eq) => {
            let (en, ind) = super::PLANE_NAMES[(*bit).min(5)];
            match eq {
                Some(eq) => pick(&format!("{eq} ({en})"), &format!("{eq} {ind}")),
                None => pick(en, ind),
            }
        }
        FigureMsg::OutOfRange(k) => pick(
            &format!("light {k} is out of range: it does not light the point and is not drawn"),
            &format!("sumber cahaya {k} di luar jangkauan: tidak menyinari titik ini dan tidak digambar"),
        ),
        FigureMsg::Rejected(and) => pick(
            &format!("code0 AND code1 = {and} ≠ 000000: the segment lies outside, rejected with no intersection tried"),
            &format!("code0 AND code1 = {and} ≠ 000000: segmen garis di luar, ditolak tanpa mencari titik potong"),
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
            "Proyeksi ke bidang pandang",
        ),
        Panel::ProjectionSide => (
            "Side view (y–z): similar triangles",
            "Tampak samping (y–z): kesamaan segitiga",
        ),
        Panel::ViewPlane => (
            "The images on the view plane (x–y)",
            "Bayangan pada bidang pandang (x–y)",
        ),
        Panel::Frustum => (
            "The view volume, seen from outside",
            "View volume, dilihat dari luar",
        ),
        Panel::WindowSide => (
            "Side view (y–z): fovy and top",
            "Tampak samping (y–z): fovy dan top",
        ),
        Panel::NearWindow => (
            "The viewing window on the near plane",
            "Viewing window pada near plane",
        ),
        Panel::Viewport => (
            "The viewport (pixels, origin bottom left)",
            "Viewport (piksel, titik asal kiri bawah)",
        ),
        Panel::Clip => (
            "Clipping P0P1 against the box",
            "Clipping segmen garis P0P1 terhadap view volume",
        ),
        Panel::ClipAlong => (
            "Along the segment: P(t) = P0 + t·(P1 − P0)",
            "Sepanjang segmen garis: P(t) = P0 + t·(P1 − P0)",
        ),
        Panel::Shade | Panel::ShadeLight(_) => (
            "Lighting in the plane of incidence (the plane of N and L)",
            "Pencahayaan pada bidang datang (bidang N dan L)",
        ),
        Panel::ShadeRV => ("The plane of R and V (β)", "Bidang R dan V (β)"),
        Panel::ShadeNH => ("The plane of N and H (N·H)", "Bidang N dan H (N·H)"),
    }
}

fn desc(p: Panel) -> (&'static str, &'static str) {
    match p {
        Panel::Camera => (
            "Black arrows: the world axes x, y, z. Blue dots: Peye and Pref, joined by the dotted line of sight. Sky-blue arrow: Vup, drawn at Pref. The camera axes u, v, n at Peye: green solid, purple dash-dot and vermillion dashed arrows, drawn twice the length of Vup (the note under the drawing states the length); the view is chosen so that they are at least 15° apart and none is drawn shorter than 40 % of the longest. Black dots: the named points; the notes give their eye coordinates.",
            "Panah hitam: sumbu dunia x, y, z. Titik biru: Peye dan Pref, dihubungkan garis pandang bertitik. Panah biru muda: Vup, digambar di Pref. Sumbu kamera u, v, n di Peye: panah hijau tegas, ungu garis-titik dan merah jingga putus-putus, digambar dua kali panjang Vup (catatan di bawah gambar menyebut panjangnya); arah pandang dipilih agar ketiganya berselisih paling sedikit 15° dan tidak ada yang tergambar lebih pendek dari 40 % yang terpanjang. Titik hitam: titik-titik bernama; catatan memberi koordinat kameranya.",
        ),
        Panel::Projection => (
            "Eye coordinates; the centre of projection is outside the view plane in this view. Sky-blue rectangle: the view plane. Dotted orange lines: the projectors from the centre of projection (parallel to z when orthographic) through each point (black dot) to its image (blue dot).",
            "Koordinat kamera; pada tampak ini pusat proyeksi berada di luar bidang pandang. Persegi biru muda: bidang pandang. Garis jingga bertitik: proyektor dari pusat proyeksi (sejajar sumbu z pada proyeksi ortografik) melalui tiap titik (titik hitam) ke bayangannya (titik biru).",
        ),
        Panel::ProjectionSide => (
            "Side view: −z to the right, y up. The sky-blue line is the view plane; each projector (dotted) runs from the centre of projection through the point to its image. The black leg y of the point and the blue leg yp of the image make two similar triangles with the z axis.",
            "Tampak samping: −z ke kanan, y ke atas. Garis biru muda adalah bidang pandang; tiap proyektor (bertitik) berjalan dari pusat proyeksi melalui titik ke bayangannya. Sisi hitam y dari titik dan sisi biru yp dari bayangan membentuk dua segitiga dengan sumbu z yang sebentuk (kesamaan segitiga).",
        ),
        Panel::ViewPlane => (
            "The view plane seen from the front: xp to the right, yp up; each blue dot is a point's image.",
            "Bidang pandang dilihat dari depan: xp ke kanan, yp ke atas; tiap titik biru adalah bayangan sebuah titik.",
        ),
        Panel::Frustum => (
            "Eye space, the eye at the origin looking along −z, seen from outside: the eye is the apex of the view volume, outside its windows. Blue rectangle: the near window (left..right × bottom..top at z = −near); sky-blue rectangle: the far window; black lines: the edges of the view volume. The windows are drawn to scale; when far is not given or more than 10 times near, the far window is not drawn: the edges run on, dashed vermillion, to twice near.",
            "Ruang kamera, mata di titik asal memandang ke arah −z, dilihat dari luar: mata adalah puncak view volume, di luar window-nya. Persegi biru: viewing window pada near plane (left..right × bottom..top di z = −near); persegi biru muda: window pada far plane; garis hitam: rusuk view volume. Window digambar sesuai skala; bila far tidak diberikan atau lebih dari 10 kali near, window pada far plane tidak digambar: rusuknya berlanjut putus-putus merah jingga sampai dua kali near.",
        ),
        Panel::WindowSide => (
            "Side view: −z to the right, y up. The eye at the origin; the purple arc is the angle fovy; the blue line is the near window from bottom to top, at distance near.",
            "Tampak samping: −z ke kanan, y ke atas. Mata di titik asal; busur ungu adalah sudut fovy; garis biru adalah viewing window pada near plane, dari bottom sampai top, pada jarak near.",
        ),
        Panel::NearWindow => (
            "The viewing window on the near plane: x to the right, y up; the black dots are the projected points.",
            "Viewing window pada near plane: x ke kanan, y ke atas; titik hitam adalah titik-titik hasil proyeksi.",
        ),
        Panel::Viewport => (
            "The viewport W × H in pixels, origin at the bottom left; each blue dot is a point at its pixel position.",
            "Viewport W × H dalam piksel, titik asal di kiri bawah; tiap titik biru adalah sebuah titik pada posisi pikselnya.",
        ),
        Panel::Clip => (
            "The box, its hidden edges dashed, with its six planes named by their equations and the text's words (left x = xmin, right x = xmax, bottom y = ymin, top y = ymax, front z = zmin, back z = zmax, as the text's bits count them); P0 and P1 with their outcodes. The kept part is solid blue, the cut-off parts dashed vermillion; each intersection tried is a dot named by its plane (blue when it bounds the kept part, with its coordinates; orange when it lies outside the box).",
            "Balok, rusuk tersembunyinya putus-putus, dengan enam bidangnya diberi persamaan dan nama dari buku (kiri x = xmin, kanan x = xmax, bawah y = ymin, atas y = ymax, depan z = zmin, belakang z = zmax, menurut bit buku); P0 dan P1 dengan region code-nya. Bagian yang dipertahankan biru tegas, bagian yang dibuang putus-putus merah jingga; tiap titik potong yang dicoba adalah titik yang diberi nama bidangnya (biru bila membatasi bagian yang dipertahankan, dengan koordinatnya; jingga bila di luar balok).",
        ),
        Panel::ClipAlong => (
            "The segment drawn straight, t from 0 (P0, top) to 1 (P1, bottom): each intersection tried at its t, with its plane, its point P(t) and its outcode; the kept part solid blue, the cut-off parts dashed vermillion.",
            "Ruas garis digambar lurus, t dari 0 (P0, atas) sampai 1 (P1, bawah): tiap titik potong yang dicoba pada nilai t-nya, dengan bidangnya, titik P(t) dan region code-nya; bagian yang dipertahankan biru tegas, bagian yang dibuang putus-putus merah jingga.",
        ),
        Panel::Shade | Panel::ShadeLight(_) => (
            "A flat diagram in the plane of N and L (the plane of incidence), at true angles: the surface is a line (hatched on the object's side) with N straight up, L toward the light on the left, R its mirror image about N, and V toward the viewer and H the half vector (Blinn) where they lie in this plane; every unit vector drawn with one length. Arcs mark α between L and N and β between R and V at their true size. N black, L sky blue, R purple dash-dot, V green, H orange dotted.",
            "Diagram datar pada bidang N dan L (bidang datang), dengan sudut sebenarnya: permukaan berupa garis (diarsir di sisi benda) dengan N tegak ke atas, L ke arah sumber cahaya di kiri, R pencerminannya terhadap N, serta V ke arah pengamat dan H vektor setengah jalan (Blinn) bila terletak pada bidang ini; semua vektor satuan sama panjang. Busur menandai α antara L dan N dan β antara R dan V dengan ukuran sebenarnya. N hitam, L biru muda, R ungu garis-titik, V hijau, H jingga bertitik.",
        ),
        Panel::ShadeRV => (
            "V leaves the plane of incidence, so R and V are drawn in their own plane, R straight up, at their true angle β.",
            "V keluar dari bidang datang, sehingga R dan V digambar pada bidangnya sendiri, R tegak ke atas, dengan sudut β sebenarnya.",
        ),
        Panel::ShadeNH => (
            "H leaves the plane of incidence, so N and H are drawn in their own plane, N straight up, at their true angle (N·H is its cosine).",
            "H keluar dari bidang datang, sehingga N dan H digambar pada bidangnya sendiri, N tegak ke atas, dengan sudut sebenarnya (N·H adalah kosinusnya).",
        ),
    }
}

fn word(w: FigWord) -> (&'static str, &'static str) {
    match w {
        FigWord::Cop => ("centre of projection", "pusat proyeksi"),
        FigWord::Eye => ("eye", "mata"),
        FigWord::NotToScale => (
            "far window too far to draw to scale",
            "window pada far plane tidak digambar: terlalu jauh untuk skala ini",
        ),
        FigWord::Surface => ("surface", "permukaan"),
        FigWord::CameraAxes => (
            "u green, v purple dash-dot, n vermillion dashed; length",
            "u hijau, v ungu garis-titik, n merah jingga putus-putus; panjang",
        ),
        FigWord::Zoomed => (
            "inset: the view plane near the centre of projection, enlarged",
            "sisipan: bidang pandang di dekat pusat proyeksi, diperbesar",
        ),
        FigWord::Coincide => (
            "coincide; drawn side by side",
            "berimpit; digambar berdampingan",
        ),
        FigWord::Outcode => ("outcode", "region code"),
        FigWord::Kept => ("kept", "dipertahankan"),
        FigWord::CutOff => ("cut off", "dibuang"),
        FigWord::AngleNH => ("angle(N, H)", "sudut(N, H)"),
        FigWord::Accepted => (
            "both codes are 000000: the segment lies inside, accepted whole",
            "kedua code 000000: segmen garis di dalam, diterima utuh",
        ),
        FigWord::Missed => (
            "no intersection tried is in the box: the segment misses it, rejected",
            "tidak ada titik potong di dalam balok: segmen garis melewatinya, ditolak",
        ),
    }
}
