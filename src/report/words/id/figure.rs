//! The figures' words in Bahasa Indonesia (the course text's terms, docs/glossary.md): panel titles and
//! descriptions (captions and screen readers) and the words inside the
//! figures.

use super::Id;
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::words::keys::KeyWords;
use crate::report::words::{figure, FigureWords};
use crate::tutor::key::Plane;

impl FigureWords for Id {
    fn figure(&self, m: &FigureMsg) -> String {
        match m {
            FigureMsg::Title(Panel::ShadeLight(k)) => format!(
                "Sumber cahaya {k}: bidang N dan {}",
                figure::light_name(*k)
            ),
            FigureMsg::Title(p) => title(*p).into(),
            FigureMsg::Desc(p) => desc(*p).into(),
            FigureMsg::Word(w) => word(*w).into(),
            FigureMsg::View { from, az, el } => format!(
                "Tampak aksonometri (ortografik), dilihat dari arah {from} (azimut {az}°, elevasi {el}°), y ke atas."
            ),
            FigureMsg::OffPlane(name, deg) => format!(
                "{name} tidak terletak pada bidang ini (menyimpang {deg}°): digambar pada bidangnya sendiri di bawah"
            ),
            FigureMsg::Plane(bit, eq) => {
                let name = self.plane(Plane::ALL[(*bit).min(5)]);
                match eq {
                    Some(eq) => format!("{eq} {name}"),
                    None => name.into(),
                }
            }
            FigureMsg::OutOfRange(k) => format!(
                "sumber cahaya {k} di luar jangkauan: tidak menyinari titik ini dan tidak digambar"
            ),
            FigureMsg::Rejected(and) => format!(
                "code0 AND code1 = {and} ≠ 000000: segmen garis di luar, ditolak tanpa mencari titik potong"
            ),
        }
    }
}

/// A panel's title. A word table: long on purpose.
fn title(p: Panel) -> &'static str {
    match p {
        Panel::Camera => "Kamera dalam sistem koordinat dunia",
        Panel::Projection => "Proyeksi ke bidang pandang",
        Panel::ProjectionSide => "Tampak samping (y–z): kesamaan segitiga",
        Panel::ViewPlane => "Bayangan pada bidang pandang (x–y)",
        Panel::Frustum => "View volume, dilihat dari luar",
        Panel::WindowSide => "Tampak samping (y–z): fovy dan top",
        Panel::NearWindow => "Viewing window pada near plane",
        Panel::Viewport => "Viewport (piksel, titik asal kiri bawah)",
        Panel::Clip => "Clipping segmen garis P0P1 terhadap view volume",
        Panel::ClipAlong => "Sepanjang segmen garis: P(t) = P0 + t·(P1 − P0)",
        Panel::Shade | Panel::ShadeLight(_) => "Pencahayaan pada bidang datang (bidang N dan L)",
        Panel::ShadeRV => "Bidang R dan V (β)",
        Panel::ShadeNH => "Bidang N dan H (N·H)",
    }
}

/// A panel's description. A word table: long on purpose.
fn desc(p: Panel) -> &'static str {
    match p {
        Panel::Camera => "Panah hitam: sumbu dunia x, y, z. Titik biru: Peye dan Pref, dihubungkan garis pandang bertitik. Panah biru muda: Vup, digambar di Pref. Sumbu kamera u, v, n di Peye: panah hijau tegas, ungu garis-titik dan merah jingga putus-putus, digambar dua kali panjang Vup (catatan di bawah gambar menyebut panjangnya); arah pandang dipilih agar ketiganya berselisih paling sedikit 15° dan tidak ada yang tergambar lebih pendek dari 40 % yang terpanjang. Titik hitam: titik-titik bernama; catatan memberi koordinat kameranya.",
        Panel::Projection => "Koordinat kamera; pada tampak ini pusat proyeksi berada di luar bidang pandang. Persegi biru muda: bidang pandang. Garis jingga bertitik: proyektor dari pusat proyeksi (sejajar sumbu z pada proyeksi ortografik) melalui tiap titik (titik hitam) ke bayangannya (titik biru).",
        Panel::ProjectionSide => "Tampak samping: −z ke kanan, y ke atas. Garis biru muda adalah bidang pandang; tiap proyektor (bertitik) berjalan dari pusat proyeksi melalui titik ke bayangannya. Sisi hitam y dari titik dan sisi biru yp dari bayangan membentuk dua segitiga dengan sumbu z yang sebentuk (kesamaan segitiga).",
        Panel::ViewPlane => "Bidang pandang dilihat dari depan: xp ke kanan, yp ke atas; tiap titik biru adalah bayangan sebuah titik.",
        Panel::Frustum => "Ruang kamera, mata di titik asal memandang ke arah −z, dilihat dari luar: mata adalah puncak view volume, di luar window-nya. Persegi biru: viewing window pada near plane (left..right × bottom..top di z = −near); persegi biru muda: window pada far plane; garis hitam: rusuk view volume. Window digambar sesuai skala; bila far tidak diberikan atau lebih dari 10 kali near, window pada far plane tidak digambar: rusuknya berlanjut putus-putus merah jingga sampai dua kali near.",
        Panel::WindowSide => "Tampak samping: −z ke kanan, y ke atas. Mata di titik asal; busur ungu adalah sudut fovy; garis biru adalah viewing window pada near plane, dari bottom sampai top, pada jarak near.",
        Panel::NearWindow => "Viewing window pada near plane: x ke kanan, y ke atas; titik hitam adalah titik-titik hasil proyeksi.",
        Panel::Viewport => "Viewport W × H dalam piksel, titik asal di kiri bawah; tiap titik biru adalah sebuah titik pada posisi pikselnya.",
        Panel::Clip => "Digambar seperti buku membaca bidang-bidang balok: x ke kanan, y ke atas dan z menjauhi pembaca, sehingga bidang depan (z = zmin) menghadap pembaca dan bidang belakang (z = zmax) membelakanginya (bayangan cermin dari sumbu tangan kanan, dilihat dari sisi −z yang disebut di atas). Balok, rusuk tersembunyinya putus-putus, dengan enam bidangnya diberi persamaan dan nama dari buku (kiri x = xmin, kanan x = xmax, bawah y = ymin, atas y = ymax, depan z = zmin, belakang z = zmax, menurut bit buku); P0 dan P1 dengan region code-nya. Bagian yang dipertahankan biru tegas, bagian yang dibuang putus-putus merah jingga; tiap titik potong yang dicoba adalah titik yang diberi nama bidangnya (biru bila membatasi bagian yang dipertahankan, dengan koordinatnya; jingga bila di luar balok).",
        Panel::ClipAlong => "Ruas garis digambar lurus, t dari 0 (P0, atas) sampai 1 (P1, bawah): tiap titik potong yang dicoba pada nilai t-nya, dengan bidangnya, titik P(t) dan region code-nya; bagian yang dipertahankan biru tegas, bagian yang dibuang putus-putus merah jingga.",
        Panel::Shade | Panel::ShadeLight(_) => "Diagram datar pada bidang N dan L (bidang datang), dengan sudut sebenarnya: permukaan berupa garis (diarsir di sisi benda) dengan N tegak ke atas, L ke arah sumber cahaya di kiri, R pencerminannya terhadap N, serta V ke arah pengamat dan H vektor setengah jalan (Blinn) bila terletak pada bidang ini; semua vektor satuan sama panjang. Busur menandai α antara L dan N dan β antara R dan V dengan ukuran sebenarnya. N hitam, L biru muda, R ungu garis-titik, V hijau, H jingga bertitik.",
        Panel::ShadeRV => "V keluar dari bidang datang, sehingga R dan V digambar pada bidangnya sendiri, R tegak ke atas, dengan sudut β sebenarnya.",
        Panel::ShadeNH => "H keluar dari bidang datang, sehingga N dan H digambar pada bidangnya sendiri, N tegak ke atas, dengan sudut sebenarnya (N·H adalah kosinusnya).",
    }
}

/// A word inside a figure.
fn word(w: FigWord) -> &'static str {
    match w {
        FigWord::Cop => "pusat proyeksi",
        FigWord::Eye => "mata",
        FigWord::NotToScale => "window pada far plane tidak digambar: terlalu jauh untuk skala ini",
        FigWord::Surface => "permukaan",
        FigWord::CameraAxes => "u hijau, v ungu garis-titik, n merah jingga putus-putus; panjang",
        FigWord::Zoomed => "sisipan: bidang pandang di dekat pusat proyeksi, diperbesar",
        FigWord::Coincide => "berimpit; digambar berdampingan",
        FigWord::Outcode => "region code",
        FigWord::Kept => "dipertahankan",
        FigWord::CutOff => "dibuang",
        FigWord::AngleNH => "sudut(N, H)",
        FigWord::Accepted => "kedua region code 000000: segmen garis di dalam, diterima utuh",
        FigWord::Missed => {
            "tidak ada titik potong di dalam balok: segmen garis melewatinya, ditolak"
        }
    }
}
