//! The words of every message key (`crate::msg::Msg`), in English and in
//! Bahasa Indonesia, with the course text's own terms (docs/glossary.md).
//! One exhaustive match: a key without both languages does not compile.
//!
//! Each language is one module ([`en`], [`id`]) holding one type that
//! implements [`Words`]: one trait per family of keys, each method one
//! exhaustive match over that family in that language. A third language is
//! a third module and a `Lang` variant; the compiler names every family it
//! has not yet written.

use super::lang::{Lang, NumStyle};
use crate::msg::{Erratum, LightPart, Msg, Printed, SpotZone, Term, Trivial};

mod drawn;
pub use drawn::statement;
mod en;
pub mod errors;
mod figure;
mod id;
pub mod keys;
pub mod labels;
pub mod names;
mod pixel;
pub mod render;
pub mod report;
mod said;

/// Every word of one language: each family's trait, implemented by that
/// language's module.
pub trait Words:
    Sync + MsgWords + errors::ErrorWords + names::NameWords + keys::KeyWords + report::ReportWords
{
}

/// The words of the messages themselves ([`Msg`]).
pub trait MsgWords {}

/// The words of `lang`.
pub fn of(lang: Lang) -> &'static dyn Words {
    match lang {
        Lang::En => &en::En,
        Lang::Id => &id::Id,
    }
}

/// The words of `m` in `lang`: one exhaustive match over every key, so a
/// key without its words does not compile (no wildcard arm, nothing falls
/// through to "?" or an empty string at run time). A word table: long on
/// purpose.
pub fn words(m: &Msg, lang: Lang) -> String {
    let id = lang == Lang::Id;
    let p = |en: &str, ind: &str| pick(lang, en, ind);
    let f = |en: String, ind: String| if id { ind } else { en };
    let n = |s: &str| nums(s, lang);
    match m {
        Msg::Math(s) => s.clone(),
        Msg::Written(en, ind) => match (lang, ind) {
            (Lang::Id, Some(ind)) => ind.clone(),
            _ => en.clone(),
        },
        Msg::Erratum(kind, why) => format!(
            "{}: {}",
            printed(Printed::Differs(*kind), lang),
            words(why, lang)
        ),
        Msg::Printed(p) => printed(*p, lang),
        Msg::Asked(parts) => asked(parts, lang),
        Msg::DrawnTitle(t) => drawn::title(*t, lang),
        Msg::Pixel(p) => pixel::words(p, lang),
        Msg::Statement(s) => drawn::statement(s, lang, NumStyle::of(lang)),
        Msg::Figure(f) => figure::figure(f, lang),
        Msg::At(place, m) => format!("{place}: {}", words(m, lang)),
        Msg::Err(e) => errors::error(e, lang),
        Msg::Said(s) => said::said(s, lang),
        Msg::SecModeling => p(
            "Stage 1: modeling transformation",
            "Tahap 1: transformasi pemodelan",
        ),
        Msg::SecViewing => p(
            "Stage 2: viewing transformation (world → eye coordinates)",
            "Tahap 2: transformasi sistem pandang (koordinat dunia → koordinat kamera)",
        ),
        Msg::SecProjection => p(
            "Stage 3: projection onto the near plane",
            "Tahap 3: proyeksi terhadap near clipping plane",
        ),
        Msg::SecWindowClip => p(
            "Stage 4: window and clipping",
            "Tahap 4: viewing window dan clipping",
        ),
        Msg::SecViewport => p(
            "Viewport mapping (window → pixels)",
            "Pemetaan viewport (viewing window → piksel)",
        ),
        Msg::SecLineClip(None) => p("Line clipping", "Clipping garis"),
        Msg::SecLineClip(Some(i)) => {
            if id {
                format!("Clipping garis, segmen {i}")
            } else {
                format!("Line clipping, segment {i}")
            }
        }
        Msg::SecLighting => p("Lighting", "Pencahayaan"),
        Msg::SecPixel(x, y) => {
            if id {
                format!("Piksel ({x}; {y})")
            } else {
                format!("Pixel ({x}, {y})")
            }
        }
        Msg::SecLightFace => p(
            "Lighting of the face (lighting::shade)",
            "Pencahayaan face (lighting::shade)",
        ),
        Msg::SecLightVertex(n) => {
            if id {
                format!("Pencahayaan verteks {n} (lighting::shade)")
            } else {
                format!("Lighting of vertex {n} (lighting::shade)")
            }
        }
        Msg::SecLightPixel => p(
            "Lighting of the pixel (lighting::shade)",
            "Pencahayaan piksel (lighting::shade)",
        ),
        Msg::CamAxisN => p(
            "Camera axis n (points from the look-at point back to the eye)",
            "Sumbu kamera n (dari Pref kembali ke Peye)",
        ),
        Msg::CamAxisU => p("Camera axis u (to the right)", "Sumbu kamera u (ke kanan)"),
        Msg::CamAxisV => p("Camera axis v (up in the picture)", "Sumbu kamera v (ke atas pada gambar)"),
        Msg::CamCheck => p(
            "Check: u, v, n are orthonormal and right-handed",
            "Pemeriksaan: u, v, n ortonormal dan membentuk sistem tangan kanan",
        ),
        Msg::CamMatrix => p(
            "Camera matrix Mcam (camera to world)",
            "Matriks transformasi kamera Mcam (koordinat kamera ke koordinat dunia)",
        ),
        Msg::ViewMatrix => p(
            "View matrix V = Mcam⁻¹ (world to eye): rotation (rows u, v, n) times translation by −Pe",
            "Matriks transformasi pandang V = Mcam⁻¹, invers Mcam (koordinat dunia ke koordinat kamera): rotasi (baris u, v, n) kali translasi sejauh −Pe",
        ),
        Msg::EyeCoords(n) => f(format!("Eye coordinates of {n}"), format!("Koordinat kamera titik {n}")),
        Msg::OrthoProj(n) => f(format!("Orthographic projection of {n}"), format!("Proyeksi orthographic titik {n}")),
        Msg::PerspProj(n) => f(format!("Perspective projection of {n}"), format!("Proyeksi perspektif titik {n}")),
        // the text's h is the near window's half-height; the far one has no name there
        Msg::WindowTop(l) if l == "near" => f(
            format!("Window half-height on the {l} plane (the text calls it h)"),
            format!("Setengah tinggi viewing window pada {l} plane (h dalam teks)"),
        ),
        Msg::WindowTop(l) => f(
            format!("Window half-height on the {l} plane"),
            format!("Setengah tinggi viewing window pada {l} plane"),
        ),
        Msg::WindowEdges(l) => f(
            format!("Window edges and size on the {l} plane"),
            format!("Tepi dan ukuran viewing window pada {l} plane"),
        ),
        Msg::ViewportOf(n) => f(format!("Viewport coordinates of {n}"), format!("Koordinat viewport titik {n}")),
        Msg::OutcodeOf(n) => f(format!("Outcode of {n}"), format!("Region code titik {n}")),
        Msg::TrivialTests => p("Trivial tests", "Uji trivial dengan operasi logika AND"),
        Msg::Intersection(i, plane) => {
            let (en, ind) = PLANE_NAMES[*i % 6];
            f(
                format!("Intersection with the {ind} ({en}) plane {plane}"),
                format!("Titik potong dengan bidang {ind} {plane}"),
            )
        }
        Msg::ClippedSegment => p("Clipped segment", "Segmen garis hasil clipping"),
        Msg::LiangBarsky => p("Cross-check by Liang–Barsky", "Pemeriksaan silang dengan Liang–Barsky"),
        Msg::MethodsAgree => p("Do the two methods agree?", "Apakah kedua metode sama hasilnya?"),
        Msg::NothingToDo => p("Nothing to do", "Tidak ada yang perlu dikerjakan"),
        Msg::ProjPlane => p("Projection plane", "Bidang proyeksi"),
        Msg::InsideVolume(n) => f(
            format!("Is {n}'' inside the view volume?"),
            format!("Apakah {n}'' di dalam view volume?"),
        ),
        Msg::UnitVector(n) => f(format!("Unit vector {n}"), format!("Vektor satuan {n}")),
        Msg::ViewerLocal => p(
            "Viewer direction (local viewer)",
            "Arah pengamat (pengamat lokal)",
        ),
        Msg::Material => p("Material and model", "Material dan model"),
        Msg::Light((i, n), part) => {
            let w = light_part(*part, lang);
            if *n > 1 {
                format!(
                    "{} {}: {w}",
                    if id { "Sumber cahaya" } else { "Light" },
                    i + 1
                )
            } else {
                let mut c = w.chars();
                c.next()
                    .map(|a| a.to_uppercase().chain(c).collect())
                    .unwrap_or_default()
            }
        }
        Msg::TermStep(t) => {
            let w = term(*t, lang);
            let cap: String = w[..1].to_uppercase() + &w[1..];
            f(
                format!("{cap} term, per channel"),
                format!("Komponen {w}, per kanal warna"),
            )
        }
        Msg::SumOfTerms => p("Sum of the terms", "Jumlah komponen"),
        Msg::Clamp => p(
            "Clamp each channel to [0, 1]",
            "Batasi tiap kanal ke [0, 1]",
        ),
        Msg::WhichTriangle => p(
            "Which triangle covers the pixel",
            "Segitiga mana yang menutupi piksel",
        ),
        Msg::Depth => p(
            "Depth at the pixel (z-buffer)",
            "Kedalaman pada piksel (z-buffer)",
        ),
        Msg::Barycentric => p("Barycentric coordinates", "Koordinat barisentrik"),
        Msg::FlatShading => p(
            "Flat shading: one colour per face",
            "Flat shading: satu warna per face",
        ),
        Msg::Gouraud => p(
            "Gouraud: interpolate the vertex colours",
            "Gouraud: interpolasi warna verteks",
        ),
        Msg::PhongShading => p(
            "Phong shading: interpolate normal, position and colour",
            "Phong shading: interpolasi normal, posisi dan warna",
        ),
        Msg::PixelColour => p("Pixel colour", "Warna piksel"),
        Msg::FOutOfRange => p(
            "d² = |Pl − P|² > range²  ⇒  the light is not evaluated",
            "d² = |Pl − P|² > range²  ⇒  cahaya tidak dihitung",
        ),
        Msg::FIncidence => p(
            "cos α = Lx·Nx + Ly·Ny + Lz·Nz,  then max(cos α, 0)",
            "cos α = Lx·Nx + Ly·Ny + Lz·Nz,  lalu max(cos α, 0)",
        ),
        Msg::FCamMatrix => p(
            "Mcam = T(Pe) · [u v n]   (columns u, v, n, Pe)",
            "Mcam = T(Pe) · [u v n]   (kolom u, v, n, Pe)",
        ),
        Msg::FViewMatrix => p(
            "V = R · T(−Pe),  R = [uᵀ; vᵀ; nᵀ],  last column (−u·Pe, −v·Pe, −n·Pe)",
            "V = R · T(−Pe),  R = [uᵀ; vᵀ; nᵀ],  kolom terakhir (−u·Pe; −v·Pe; −n·Pe)",
        ),
        Msg::FTrivial => p(
            "both codes 000000 → accept;  code0 AND code1 ≠ 000000 → reject;  otherwise clip",
            "kedua region code 000000 → diterima;  code0 AND code1 ≠ 000000 → ditolak;  selain itu → clipping",
        ),
        Msg::FOutcode => p(
            "bit 1 x<xmin (kiri) · bit 2 x>xmax (kanan) · bit 3 y<ymin (bawah) · bit 4 y>ymax (atas) · bit 5 z<zmin (depan) · bit 6 z>zmax (belakang); the code is written bit 6 … bit 1 (bit 1 rightmost)",
            "bit 1 x<xmin (kiri) · bit 2 x>xmax (kanan) · bit 3 y<ymin (bawah) · bit 4 y>ymax (atas) · bit 5 z<zmin (depan) · bit 6 z>zmax (belakang); region code ditulis bit 6 … bit 1 (bit 1 paling kanan)",
        ),
        Msg::FSegment => p(
            "from the kept point with the smallest t to the one with the largest t (inside ends count as t = 0 and t = 1)",
            "dari titik yang dipertahankan dengan t terkecil ke titik dengan t terbesar (ujung di dalam dihitung t = 0 dan t = 1)",
        ),
        Msg::FMethods => p(
            "outcode clipping against Liang–Barsky",
            "clipping dengan region code dibandingkan dengan Liang–Barsky",
        ),
        Msg::FProjPlane => p(
            "z = d,  d = −near (the camera looks along −z in eye coordinates)",
            "z = d,  d = −near (kamera memandang ke arah −z dalam koordinat kamera)",
        ),
        Msg::FPixelCentre => p(
            "pixel centre (x + ½, y + ½) inside a triangle, nearest wins",
            "pusat piksel (x + ½; y + ½) di dalam segitiga, yang terdekat menang",
        ),
        Msg::FEdges => p(
            "edge functions E₀, E₁, E₂ ≥ 0 at the centre (top-left rule on edges); nearest depth wins",
            "fungsi tepi E₀, E₁, E₂ ≥ 0 di pusat piksel (aturan kiri-atas pada tepi); kedalaman terdekat menang",
        ),
        Msg::FDepth => p(
            "z = λ₀z₀ + λ₁z₁ + λ₂z₂ (z/w is linear on the screen); smaller is nearer",
            "z = λ₀z₀ + λ₁z₁ + λ₂z₂ (z/w linear di layar); makin kecil makin dekat",
        ),
        Msg::FBarycentric => p(
            "λₖ = Eₖ(centre)/area on the screen;  perspective-correct μₖ = (λₖ/wₖ) / Σ λₘ/wₘ",
            "λₖ = Eₖ(pusat)/luas di layar;  koreksi perspektif μₖ = (λₖ/wₖ) / Σ λₘ/wₘ",
        ),
        Msg::FFlat => p(
            "colour = lighting::shade(face normal N, face centre)",
            "warna = lighting::shade(normal face N; pusat face)",
        ),
        Msg::FLiangBarsky => p(
            "t0 = max over entering planes of q/p,  t1 = min over leaving planes of q/p,  visible if t0 ≤ t1",
            "t0 = nilai q/p terbesar di antara bidang yang dimasuki,  t1 = nilai q/p terkecil di antara bidang yang ditinggalkan,  terlihat bila t0 ≤ t1",
        ),
        Msg::FInside => p(
            "left ≤ xp ≤ right,  bottom ≤ yp ≤ top,  and −far ≤ z' ≤ −near",
            "left ≤ xp ≤ right,  bottom ≤ yp ≤ top,  dan −far ≤ z' ≤ −near",
        ),
        Msg::FSpot => p(
            "ρ = (−L)·axis;  Spot = 1 if ρ ≥ cos(θ/2), 0 if ρ ≤ cos(φ/2), else ((ρ − cos(φ/2))/(cos(θ/2) − cos(φ/2)))^falloff",
            "ρ = (−L)·axis;  Spot = 1 bila ρ ≥ cos(θ/2), 0 bila ρ ≤ cos(φ/2), selain itu ((ρ − cos(φ/2))/(cos(θ/2) − cos(φ/2)))^falloff",
        ),
        Msg::FClamp => p(
            "color = min(max(C, 0), 1)",
            "warna = min(max(C; 0); 1)",
        ),
        Msg::FByte => p(
            "8-bit value = round(255 · clamp(C, 0, 1))",
            "nilai 8-bit = round(255 · clamp(C; 0; 1))",
        ),
        Msg::AlreadyUnit => p("already a unit vector", "sudah merupakan vektor satuan"),
        Msg::Saturates => p(
            "a channel went past 1 (or below 0) and is clamped: the highlight saturates",
            "sebuah kanal melewati 1 (atau di bawah 0) dan dibatasi: sorotan (highlight) menjadi jenuh",
        ),
        Msg::InRange => p("every channel is already in [0, 1]", "setiap kanal sudah berada di [0, 1]"),
        Msg::NoTermInModel(model, t) => if id {
            format!("model {model} tidak memiliki komponen {}", term(*t, lang))
        } else {
            format!("the {model} model has no {} term", term(*t, lang))
        },
        Msg::TextSetting => p(
            "the text's single white light and no global ambient: the sum is 1·(the text's factor)",
            "satu sumber cahaya putih seperti di teks dan tanpa ambient global: jumlahnya 1·(faktor dalam teks)",
        ),
        Msg::SummedInRange => p(
            "summed over the lights in range",
            "dijumlahkan atas semua sumber cahaya dalam jangkauan",
        ),
        Msg::SpecularSkipped => p(
            "the specular term is skipped (ks = 0 or --specular off)",
            "komponen specular dilewati (ks = 0 atau --specular off)",
        ),
        Msg::BeyondRange => p(
            "beyond its range a light adds nothing, not even ambient",
            "di luar jangkauannya sumber cahaya tidak menyumbang apa pun, ambient pun tidak",
        ),
        Msg::WithinRange => p("within range", "dalam jangkauan"),
        Msg::NoRange => p("no range limit", "tanpa batas jangkauan"),
        Msg::Behind(true) => p(
            "cos α < 0: the light is behind the surface — no diffuse, and (--specular-requires-lit) no specular",
            "cos α < 0: sumber cahaya di belakang permukaan — tanpa diffuse, dan (--specular-requires-lit) tanpa specular",
        ),
        Msg::Behind(false) => p(
            "cos α < 0: the light is behind the surface — no diffuse; the text's code still computes R and adds the specular term (use --specular-requires-lit for the usual rule)",
            "cos α < 0: sumber cahaya di belakang permukaan — tanpa diffuse; kode dalam teks tetap menghitung R dan menambahkan komponen specular (gunakan --specular-requires-lit untuk aturan yang lazim)",
        ),
        Msg::LocalViewer => p(
            "local viewer (D3DRS_LOCALVIEWER = TRUE): V points from the vertex to the camera",
            "pengamat lokal (D3DRS_LOCALVIEWER = TRUE): V menunjuk dari verteks ke kamera",
        ),
        Msg::NoLocalViewer => p(
            "no local viewer: the Direct3D page writes (0,0,1) for the viewer. That is right in grafika's right-handed eye space, where the viewer lies along +z; Direct3D's own camera space is left-handed and puts the viewer along −z, so read the page's (0,0,1) as \"toward the viewer\". grafika uses your V (default (0,0,1))",
            "tanpa pengamat lokal: halaman Direct3D menulis (0,0,1) untuk pengamat. Itu benar di ruang kamera grafika yang tangan kanan, tempat pengamat berada di arah +z; ruang kamera Direct3D sendiri tangan kiri dan menempatkan pengamat di arah −z, jadi bacalah (0,0,1) di halaman itu sebagai \"menuju pengamat\". grafika memakai V Anda (bawaan (0; 0; 1))",
        ),
        Msg::ShininessZero => p(
            "n = 0: x⁰ = 1 for every direction (0⁰ taken as 1) — the highlight covers the whole surface",
            "n = 0: x⁰ = 1 untuk setiap arah (0⁰ dianggap 1) — sorotan (highlight) menutupi seluruh permukaan",
        ),
        Msg::SpecularOff => p(
            "the specular term is off for this model / setting (ks = 0, --specular off, or a model without it)",
            "komponen specular tidak aktif untuk model / pengaturan ini (ks = 0, --specular off, atau model tanpa specular)",
        ),
        Msg::NoHighlightBehind => p(
            "cos α ≤ 0 and --specular-requires-lit: no highlight from a light behind the surface",
            "cos α ≤ 0 dan --specular-requires-lit: tidak ada sorotan (highlight) dari sumber cahaya di belakang permukaan",
        ),
        Msg::SpotIn(SpotZone::Inner) => p(
            "inside the inner cone (ρ ≥ cos(θ/2)): full light",
            "di dalam kerucut dalam (ρ ≥ cos(θ/2)): cahaya penuh",
        ),
        Msg::SpotIn(SpotZone::Outer) => p(
            "outside the outer cone (ρ ≤ cos(φ/2)): no light",
            "di luar kerucut luar (ρ ≤ cos(φ/2)): tanpa cahaya",
        ),
        Msg::SpotIn(SpotZone::Penumbra) => p(
            "in the penumbra: between the cones",
            "di penumbra: di antara kedua kerucut",
        ),
        Msg::BehindCentre => p(
            "behind the centre of projection: projected, but inverted and not visible",
            "di belakang pusat proyeksi: tetap diproyeksikan, tetapi terbalik dan tidak terlihat",
        ),
        Msg::TextH => p(
            "the text's h is this half extent; the full window height is 2·top",
            "h dalam teks adalah setengah tinggi ini; tinggi penuh viewing window adalah 2·top",
        ),
        Msg::Orthonormal(true) => p(
            "orthonormal and right-handed",
            "ortonormal dan membentuk sistem tangan kanan",
        ),
        Msg::Orthonormal(false) => p(
            "NOT orthonormal: check the inputs",
            "TIDAK ortonormal: periksa masukan",
        ),
        Msg::TrivialNote(Trivial::Accept) => p(
            "both ends inside: accepted whole",
            "kedua ujung di dalam: diterima seluruhnya",
        ),
        Msg::TrivialNote(Trivial::Reject) => p(
            "both ends outside the same plane: rejected",
            "kedua ujung di luar bidang yang sama: ditolak",
        ),
        Msg::TrivialNote(Trivial::Clip) => p(
            "neither test decides: intersect with the planes the ends violate",
            "tidak ada uji yang memutuskan: cari titik potong dengan bidang yang dilanggar ujung-ujungnya",
        ),
        Msg::Kept(true) => p("code 000000: kept", "region code 000000: dipertahankan"),
        Msg::Kept(false) => p(
            "code not 000000: outside the box, discarded",
            "region code bukan 000000: di luar view volume, dibuang",
        ),
        Msg::TouchesPoint => p(
            "the segment touches the box in a single point",
            "segmen garis menyentuh view volume di satu titik",
        ),
        Msg::InsidePart => p("the part of P0P1 inside the box", "bagian P0P1 di dalam view volume"),
        Msg::Misses => p(
            "no intersection is inside the box: the segment misses it (rejected)",
            "tidak ada titik potong di dalam view volume: segmen garis tidak mengenainya (ditolak)",
        ),
        Msg::DefaultView => p(
            "not given: the text's viewVector (0, 0, 1), a viewer far along +z",
            "tidak diberikan: viewVector dari teks (0; 0; 1), pengamat jauh di arah +z",
        ),
        Msg::MaterialD3d => p(
            "Direct3D material: its colors carry the coefficients, so ka = kd = ks = 1",
            "material Direct3D: warnanya sudah memuat koefisien, jadi ka = kd = ks = 1",
        ),
        Msg::MaterialText => p(
            "the text's constants unless given: ka = 0.4, kd = 0.6, ks = 0.7, n = 4, white specular",
            "konstanta dari teks bila tidak diberikan: ka = 0,4; kd = 0,6; ks = 0,7 (ksp dalam teks); n = 4; specular putih (Cwhite)",
        ),
        Msg::NoTriangle => p(
            "no triangle covers the pixel centre: it keeps the background colour",
            "tidak ada segitiga yang menutupi pusat piksel: warnanya tetap warna latar",
        ),
        Msg::Nearest => p(
            "the nearest of all triangles covering this pixel",
            "yang terdekat dari semua segitiga yang menutupi piksel ini",
        ),
        Msg::Agree(true) => p("both methods give the same segment", "kedua metode menghasilkan segmen garis yang sama"),
        Msg::Agree(false) => p(
            "the methods disagree: please report this input",
            "kedua metode berbeda hasilnya: mohon laporkan masukan ini",
        ),
        Msg::AlreadyWorld => p(
            "the objects are already given in world coordinates",
            "objek sudah diberikan dalam sistem koordinat dunia",
        ),
        Msg::Inside(true, true) => p("inside: not clipped", "di dalam: tidak di-clip"),
        Msg::Inside(false, _) => p("outside the window: clipped", "di luar viewing window: di-clip"),
        Msg::Inside(true, false) => p(
            "outside the near/far planes: clipped",
            "di luar near/far plane: di-clip",
        ),
        Msg::ErrSamePoint(p) => f(
            format!("the eye Pe and the look-at point Pr are the same point {p}"),
            format!("posisi mata Peye dan titik referensi Pref adalah titik yang sama {}", n(p)),
        ),
        Msg::ErrUpZero => pick(lang, "the up vector Vup is the zero vector", "vektor Vup adalah vektor nol"),
        Msg::ErrUpParallel(up, d) => f(
            format!("the up vector Vup = {up} is parallel to the view direction Pe − Pr = {d}, so Vup × n = 0 and u is undefined"),
            format!("vektor Vup = {} sejajar dengan arah pandang Peye − Pref = {}, sehingga Vup × n = 0 dan u tidak terdefinisi", n(up), n(d)),
        ),
        Msg::ErrFovy(v) => f(
            format!("must be between 0° and 180° (exclusive), got {v}°"),
            format!("harus di antara 0° dan 180° (tidak termasuk keduanya), diberikan {}°", n(v)),
        ),
        Msg::ErrAspect(v) => f(
            format!("must be positive (width/height), got {v}"),
            format!("harus positif (lebar/tinggi), diberikan {}", n(v)),
        ),
        Msg::ErrNear(v) => f(
            format!("must be positive (a distance in front of the eye), got {v}"),
            format!("harus positif (jarak di depan mata), diberikan {}", n(v)),
        ),
        Msg::ErrCopPlane(p, None) => f(
            format!("{p} has z = 0: it lies in the plane of the centre of projection and has no image"),
            format!("{p} memiliki z = 0: titik itu terletak pada bidang pusat proyeksi dan tidak memiliki bayangan"),
        ),
        Msg::ErrCopPlane(p, Some(z)) => f(
            format!("{p} has z = zprp = {z}: it lies in the plane of the centre of projection and has no image"),
            format!("{p} memiliki z = zprp = {}: titik itu terletak pada bidang pusat proyeksi dan tidak memiliki bayangan", n(z)),
        ),
        Msg::ErrUnknownPoint(p, None) => f(
            format!("unknown point `{p}`: the problem has no [points]"),
            format!("titik `{p}` tidak dikenal: soal ini tidak memiliki [points]"),
        ),
        Msg::ErrUnknownPoint(p, Some(known)) => f(
            format!("unknown point `{p}`; the points are {known}"),
            format!("titik `{p}` tidak dikenal; titik-titiknya adalah {known}"),
        ),
        Msg::ErrBoxInverted(a, lo, hi) => f(
            format!("{a}min = {lo} is greater than {a}max = {hi}"),
            format!("{a}min = {} lebih besar daripada {a}max = {}", n(lo), n(hi)),
        ),
        Msg::ErrCannotRead(path, why) => f(
            format!("cannot read {path}: {}", errors::io_why(why, lang)),
            format!("tidak dapat membaca {path}: {}", errors::io_why(why, lang)),
        ),
        Msg::ErrZeroUnit(v) => f(
            format!("{v} is the zero vector (0, 0, 0): it has no direction, so it cannot be made a unit vector"),
            format!("{v} adalah vektor nol (0; 0; 0): tidak memiliki arah, sehingga tidak dapat dijadikan vektor satuan"),
        ),
        Msg::ErrNamedPoint(t) => f(
            format!("`{t}`: expected NAME=X,Y,Z, e.g. A=0,0,0"),
            format!("`{t}`: seharusnya NAMA=X,Y,Z, misalnya A=0,0,0"),
        ),
        Msg::ErrPointName(t) => f(
            format!("`{t}` is not a point name (letters, digits, _ and ')"),
            format!("`{t}` bukan nama titik (huruf, angka, _ dan ')"),
        ),
        Msg::ErrPointTwice(t) => f(
            format!("point {t} is given twice"),
            format!("titik {t} diberikan dua kali"),
        ),
        Msg::ErrNamedPair(t) => f(
            format!("`{t}`: expected NAME=X,Y (two numbers)"),
            format!("`{t}`: seharusnya NAMA=X,Y (dua bilangan)"),
        ),
        Msg::ErrSize(t) => f(
            format!("`{t}`: expected WIDTHxHEIGHT, e.g. 200x100"),
            format!("`{t}`: seharusnya LEBARxTINGGI, misalnya 200x100"),
        ),
        Msg::ErrCopNeedsPlane => pick(
            lang,
            "--cop needs --plane (the view plane z = ZVP)",
            "--cop memerlukan --plane (bidang pandang z = ZVP)",
        ),
        Msg::ErrPlaneNeedsCop => pick(
            lang,
            "--plane needs --cop (the centre of projection z = ZPRP)",
            "--plane memerlukan --cop (pusat proyeksi z = ZPRP)",
        ),
        Msg::ErrChooseProjection => pick(
            lang,
            "choose one projection: --d D, or --cop ZPRP --plane ZVP, or --ortho",
            "pilih satu proyeksi: --d D, atau --cop ZPRP --plane ZVP, atau --ortho",
        ),
        Msg::ErrPointNeedsViewport => pick(
            lang,
            "--point needs --viewport WxH to map points to pixels",
            "--point memerlukan --viewport WxH untuk memetakan titik ke piksel",
        ),
        Msg::ExpectOne => p("expected one number", "seharusnya satu bilangan"),
        Msg::ExpectList(n) => f(
            format!("expected a list of {n} values"),
            format!("seharusnya daftar berisi {n} nilai"),
        ),
        Msg::CountMismatch(n, k) => f(
            format!("expected {n} values, got {k}"),
            format!("seharusnya {n} nilai, diberikan {k}"),
        ),
        Msg::ExpectedNone => p(
            "expected none (nothing is left)",
            "seharusnya tidak ada (tidak ada yang tersisa)",
        ),
        Msg::ExpectedBool(b) => f(
            format!("expected {b}"),
            format!("seharusnya {}", if *b { "ya" } else { "tidak" }),
        ),
        Msg::SeveralAnswers => p(
            "this key holds several answers: give them one by one",
            "kunci ini memuat beberapa jawaban: berikan satu per satu",
        ),
        Msg::EmptyAnswer => p("empty answer", "jawaban kosong"),
        Msg::NoAnswer => p("no answer given", "tidak ada jawaban"),
        Msg::AnswerTooLong(n, max) => f(
            format!("the answer has {n} characters; at most {max} are read"),
            format!("jawaban ini memuat {n} karakter; paling banyak {max} yang dibaca"),
        ),
        Msg::WithinPixel => p("within half a pixel", "dalam setengah piksel"),
        Msg::NotAnOutcode(t) => f(
            format!("`{t}` is not an outcode: write six binary digits, bit 1 rightmost (001000)"),
            format!("`{t}` bukan region code: tulis enam digit biner, bit 1 paling kanan (001000)"),
        ),
        Msg::NotAStatus(t) => f(
            format!("`{t}` is not a status: write accepted, rejected or clipped"),
            format!("`{t}` bukan status: tulis diterima, ditolak atau di-clip (accepted, rejected, clipped)"),
        ),
        Msg::FollowThrough => p(
            "right given the earlier answers (follow-through)",
            "benar menurut jawaban sebelumnya (follow-through)",
        ),
        Msg::Exact => p("exact", "tepat"),
        Msg::Rounded(s) => f(
            format!("rounded to {s} significant figures"),
            format!("dibulatkan ke {s} angka penting"),
        ),
        Msg::RoundedCoarse(s, need) => f(
            format!(
                "rounded to {s} significant figure{}, at least {need} required",
                if *s == 1 { "" } else { "s" }
            ),
            format!("dibulatkan ke {s} angka penting, paling sedikit {need} diperlukan"),
        ),
        Msg::SigCoarse(s, need) => f(
            format!("{s} significant figure(s), at least {need} required"),
            format!("{s} angka penting, paling sedikit {need} diperlukan"),
        ),
        Msg::UpParallel(a) => {
            let a = NumStyle::of(lang).number(&format!("{a:.3e}"));
            if id {
                format!("vektor up (Vup) hampir sejajar dengan arah pandang (sudut {a} rad): u dan v sangat peka terhadap masukan")
            } else {
                format!("the up vector is nearly parallel to the view direction (angle {a} rad): u and v are very sensitive to the inputs")
            }
        }
        Msg::BehindWarn(n) => {
            if id {
                format!("{n} berada di belakang pusat proyeksi: bayangannya terbalik dan tidak terlihat")
            } else {
                format!("{n} is behind the centre of projection: its image is inverted and it cannot be seen")
            }
        }
        Msg::ExactTooLarge(n) => {
            if id {
                format!("nilai eksak yang akan memuat lebih dari {n} suku (banyak akar kuadrat yang berbeda) dihitung dengan f64 dan ditandai ≈, begitu pula yang diturunkan darinya")
            } else {
                format!("exact values that would hold more than {n} terms (many different square roots) were computed in f64 and are marked ≈, as is what follows from them")
            }
        }
        Msg::ErrFewDistinct(topic, level, n) => {
            if id {
                format!("tidak dapat menarik soal {topic} tingkat {level} yang berbeda dari {n} soal sebelumnya: soal yang berbeda di tingkat ini tidak banyak; minta lebih sedikit soal (--count) atau tingkat lain (--difficulty)")
            } else {
                format!("could not draw a {topic} problem at {level} level unlike the {n} before it: there are few different ones at this level; ask for fewer problems (--count) or another --difficulty")
            }
        }
        // Msg::ErrHtmlCommand
        Msg::ErrHtmlCommand => pick(
            lang,
            "writes the worked solution of basis, view, project, window, clip, shade, solve and render; for exams use generate --format html",
            "menulis penyelesaian basis, view, project, window, clip, shade, solve dan render; untuk ujian gunakan generate --format html",
        ),
        Msg::Parts(parts) => parts
            .iter()
            .map(|(l, n)| format!("{l}: {}", words(n, lang)))
            .collect::<Vec<_>>()
            .join("; "),
        Msg::Expected(v) => format!(
            "{} {}",
            pick(lang, "expected", "seharusnya"),
            NumStyle::of(lang).values(v)
        ),
        Msg::Unreadable(why) => format!(
            "{}: {}",
            pick(lang, "cannot be read", "tidak dapat dibaca"),
            errors::number(why, lang)
        ),
        Msg::WithinPct(p) => format!(
            "{} {}%",
            pick(lang, "within", "dalam batas"),
            NumStyle::of(lang).number(p)
        ),
    }
}

/// The words of `lang`, both written.
fn pick(lang: Lang, en: &str, ind: &str) -> String {
    super::lang::tr(lang, en, ind).to_string()
}

/// What a problem asks, part by part (the parts of `input::problem::PARTS`).
fn asked(parts: &[String], lang: Lang) -> String {
    let part = |p: &str| {
        let (en, ind) = match p {
            "view" => (
                "the camera basis u, v, n, the view matrix and the eye coordinates of the points",
                "basis kamera u, v, n, matriks transformasi pandang, dan posisi titik-titik dalam koordinat kamera",
            ),
            "project" => (
                "their projections onto the near plane",
                "hasil proyeksinya terhadap near clipping plane",
            ),
            "window" => (
                "the viewing window on the near plane (its edges, width and height) and which projected points lie inside the view volume",
                "viewing window pada near clipping plane (tepi-tepinya, lebar dan tinggi) dan titik hasil proyeksi mana yang berada di dalam view volume",
            ),
            "viewport" => (
                "the pixel of each point in the viewport",
                "posisi piksel tiap titik pada viewport",
            ),
            "clip" => (
                "the region codes of the ends and the result of clipping the segment",
                "region code kedua ujung dan hasil clipping segmen garis",
            ),
            _ => (
                "the colour at the point, term by term",
                "warna hasil pencahayaan pada titik itu, komponen demi komponen",
            ),
        };
        pick(lang, en, ind)
    };
    let list: Vec<String> = parts.iter().map(|p| part(p)).collect();
    format!(
        "{}: {}.",
        pick(lang, "Asked", "Ditanyakan"),
        list.join("; ")
    )
}

/// How a printed answer compares, worded as what it is: a misprint,
/// another convention, a rounding (docs/spec.md §5).
fn printed(p: Printed, lang: Lang) -> String {
    let p_ = |en: &str, ind: &str| pick(lang, en, ind);
    match p {
        Printed::Agrees => p_("agrees", "sesuai"),
        Printed::Differs(None) => p_("the printed answer is wrong", "jawaban yang tercetak salah"),
        Printed::Differs(Some(Erratum::Misprint)) => {
            p_("a misprint in the text", "salah cetak di teks")
        }
        Printed::Differs(Some(Erratum::Convention)) => p_(
            "the text uses another convention",
            "teks memakai konvensi lain",
        ),
        Printed::Differs(Some(Erratum::Rounding)) => p_(
            "a rounding error in the text",
            "kesalahan pembulatan di teks",
        ),
        Printed::NotAsked => p_(
            "not computed in this run (not asked for)",
            "tidak dihitung (tidak ditanyakan dalam soal ini)",
        ),
        Printed::NotComparable => p_("cannot be compared", "tidak dapat dibandingkan"),
    }
}

fn term(t: Term, lang: Lang) -> &'static str {
    match (t, lang) {
        (Term::Ambient, _) => "ambient",
        (Term::Diffuse, Lang::En) => "diffuse",
        (Term::Diffuse, Lang::Id) => "diffuse",
        (Term::Specular, _) => "specular",
    }
}

fn light_part(p: LightPart, lang: Lang) -> &'static str {
    match (p, lang) {
        (LightPart::OutOfRange, Lang::En) => "out of range",
        (LightPart::OutOfRange, Lang::Id) => "di luar jangkauan",
        (LightPart::Direction, Lang::En) => "direction to the light",
        (LightPart::Direction, Lang::Id) => "arah ke sumber cahaya",
        (LightPart::Attenuation, Lang::En) => "attenuation",
        (LightPart::Attenuation, Lang::Id) => "redaman (Att)",
        (LightPart::Incidence, Lang::En) => "angle of incidence: cos α = L·N",
        (LightPart::Incidence, Lang::Id) => "sudut datang: cos α = L·N",
        (LightPart::Reflection, Lang::En) => "reflection R and cos β",
        (LightPart::Reflection, Lang::Id) => "vektor pantulan R dan cos β",
        (LightPart::HalfVector, Lang::En) => "half vector H and N·H (Blinn)",
        (LightPart::HalfVector, Lang::Id) => "vektor setengah jalan H dan N·H (Blinn)",
        (LightPart::Highlight, Lang::En) => "highlight",
        (LightPart::Highlight, Lang::Id) => "sorotan specular (highlight)",
        (LightPart::Spot, Lang::En) => "spot factor",
        (LightPart::Spot, Lang::Id) => "faktor sorotan (Spot)",
    }
}

/// The planes in `clip::PLANES` order: the English name and the text's.
pub const PLANE_NAMES: [(&str, &str); 6] = [
    ("left", "kiri"),
    ("right", "kanan"),
    ("bottom", "bawah"),
    ("top", "atas"),
    ("front", "depan"),
    ("back", "belakang"),
];

/// Numbers in a message parameter written in `lang` (`(1.5, 2, 3)` →
/// `(1,5; 2; 3)` in Indonesian; [`NumStyle::values`]).
fn nums(s: &str, lang: Lang) -> String {
    NumStyle::of(lang).values(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msg::{Erratum, LightPart, Printed, SpotZone, Term, Trivial};

    /// Every key, once, with sample parameters.
    pub fn every_message() -> Vec<Msg> {
        let s = || "A".to_string();
        let mut v = vec![
            Msg::SecModeling,
            Msg::SecViewing,
            Msg::SecProjection,
            Msg::SecWindowClip,
            Msg::SecViewport,
            Msg::SecLineClip(None),
            Msg::SecLineClip(Some(2)),
            Msg::SecLighting,
            Msg::SecPixel(1, 2),
            Msg::SecLightFace,
            Msg::SecLightVertex(1),
            Msg::SecLightPixel,
            Msg::CamAxisN,
            Msg::CamAxisU,
            Msg::CamAxisV,
            Msg::CamCheck,
            Msg::CamMatrix,
            Msg::ViewMatrix,
            Msg::EyeCoords(s()),
            Msg::OrthoProj(s()),
            Msg::PerspProj(s()),
            Msg::WindowTop(s()),
            Msg::WindowEdges(s()),
            Msg::ViewportOf(s()),
            Msg::OutcodeOf(s()),
            Msg::TrivialTests,
            Msg::ClippedSegment,
            Msg::LiangBarsky,
            Msg::MethodsAgree,
            Msg::NothingToDo,
            Msg::ProjPlane,
            Msg::InsideVolume(s()),
            Msg::UnitVector(s()),
            Msg::ViewerLocal,
            Msg::Material,
            Msg::SumOfTerms,
            Msg::Clamp,
            Msg::WhichTriangle,
            Msg::Depth,
            Msg::Barycentric,
            Msg::FlatShading,
            Msg::Gouraud,
            Msg::PhongShading,
            Msg::PixelColour,
            Msg::FOutOfRange,
            Msg::FIncidence,
            Msg::FCamMatrix,
            Msg::FViewMatrix,
            Msg::FTrivial,
            Msg::FOutcode,
            Msg::FSegment,
            Msg::FMethods,
            Msg::FProjPlane,
            Msg::FPixelCentre,
            Msg::FEdges,
            Msg::FDepth,
            Msg::FBarycentric,
            Msg::FFlat,
            Msg::FLiangBarsky,
            Msg::FInside,
            Msg::FSpot,
            Msg::FClamp,
            Msg::FByte,
            Msg::AlreadyUnit,
            Msg::Saturates,
            Msg::InRange,
            Msg::TextSetting,
            Msg::SummedInRange,
            Msg::SpecularSkipped,
            Msg::BeyondRange,
            Msg::WithinRange,
            Msg::NoRange,
            Msg::Behind(true),
            Msg::Behind(false),
            Msg::LocalViewer,
            Msg::NoLocalViewer,
            Msg::ShininessZero,
            Msg::SpecularOff,
            Msg::NoHighlightBehind,
            Msg::BehindCentre,
            Msg::TextH,
            Msg::Orthonormal(true),
            Msg::Orthonormal(false),
            Msg::Kept(true),
            Msg::Kept(false),
            Msg::TouchesPoint,
            Msg::InsidePart,
            Msg::Misses,
            Msg::DefaultView,
            Msg::MaterialD3d,
            Msg::MaterialText,
            Msg::NoTriangle,
            Msg::Nearest,
            Msg::Agree(true),
            Msg::Agree(false),
            Msg::AlreadyWorld,
            Msg::Inside(true, true),
            Msg::Inside(false, true),
            Msg::Inside(true, false),
            Msg::UpParallel(1e-9),
            Msg::BehindWarn(s()),
            Msg::ExactTooLarge(64),
            Msg::ExpectOne,
            Msg::ExpectList(3),
            Msg::CountMismatch(3, 2),
            Msg::Expected("0.5".into()),
            Msg::ExpectedNone,
            Msg::ExpectedBool(true),
            Msg::SeveralAnswers,
            Msg::EmptyAnswer,
            Msg::NoAnswer,
            Msg::AnswerTooLong(5000, 4000),
            Msg::Unreadable(crate::msg::NumErr::Empty),
            Msg::Exact,
            Msg::Rounded(4),
            Msg::RoundedCoarse(1, 3),
            Msg::SigCoarse(2, 3),
            Msg::WithinPct("0.5".into()),
            Msg::Parts(vec![("x".into(), Msg::Exact)]),
            Msg::WithinPixel,
            Msg::NotAnOutcode(s()),
            Msg::NotAStatus(s()),
            Msg::FollowThrough,
            Msg::ErrSamePoint("(1, 2, 3)".into()),
            Msg::ErrUpZero,
            Msg::ErrUpParallel("(0, 1, 0)".into(), "(0, 5, 0)".into()),
            Msg::ErrFovy("180".into()),
            Msg::ErrAspect("0".into()),
            Msg::ErrNear("-1".into()),
            Msg::ErrCopPlane(s(), None),
            Msg::ErrCopPlane(s(), Some("2".into())),
            Msg::ErrUnknownPoint(s(), None),
            Msg::ErrUnknownPoint(s(), Some("A, B".into())),
            Msg::ErrBoxInverted("y".into(), "5".into(), "4".into()),
            Msg::ErrCannotRead("p.toml".into(), crate::msg::IoWhy::NotFound),
            Msg::ErrZeroUnit(s()),
            Msg::ErrNamedPoint(s()),
            Msg::ErrPointName(s()),
            Msg::ErrPointTwice(s()),
            Msg::ErrNamedPair(s()),
            Msg::ErrSize(s()),
            Msg::ErrCopNeedsPlane,
            Msg::ErrPlaneNeedsCop,
            Msg::ErrChooseProjection,
            Msg::ErrPointNeedsViewport,
        ];
        for i in 0..6 {
            v.push(Msg::Intersection(i, "x = xmin".into()));
        }
        for t in [Term::Ambient, Term::Diffuse, Term::Specular] {
            v.push(Msg::TermStep(t));
            v.push(Msg::NoTermInModel("lambert".into(), t));
        }
        for p in [
            LightPart::OutOfRange,
            LightPart::Direction,
            LightPart::Attenuation,
            LightPart::Incidence,
            LightPart::Reflection,
            LightPart::HalfVector,
            LightPart::Highlight,
            LightPart::Spot,
        ] {
            v.push(Msg::Light((0, 1), p));
            v.push(Msg::Light((1, 2), p));
        }
        for z in [SpotZone::Inner, SpotZone::Outer, SpotZone::Penumbra] {
            v.push(Msg::SpotIn(z));
        }
        for t in [Trivial::Accept, Trivial::Reject, Trivial::Clip] {
            v.push(Msg::TrivialNote(t));
        }
        v.push(Msg::ErrFewDistinct("window".into(), "easy".into(), 20));
        v.push(Msg::ErrHtmlCommand);
        v.extend(figure_messages());
        v.extend(drawn_messages());
        v.push(Msg::Unreadable(crate::msg::NumErr::DivZero("1/0".into())));
        v.push(Msg::Written("as for B".into(), Some("seperti B".into())));
        for k in [
            None,
            Some(Erratum::Misprint),
            Some(Erratum::Convention),
            Some(Erratum::Rounding),
        ] {
            v.push(Msg::Printed(Printed::Differs(k)));
            let why = Msg::Written("as for B".into(), Some("seperti B".into()));
            v.push(Msg::Erratum(k, Box::new(why)));
        }
        for p in [Printed::Agrees, Printed::NotAsked, Printed::NotComparable] {
            v.push(Msg::Printed(p));
        }
        let parts = ["view", "project", "window", "viewport", "clip", "shade"];
        v.push(Msg::Asked(parts.map(String::from).to_vec()));
        for s in [
            crate::msg::Said::BitTest(true, "x > xmax".into(), "4.5 > 3".into()),
            crate::msg::Said::BitTest(false, "x < xmin".into(), "4.5 < 0".into()),
            crate::msg::Said::BitQuestion("x < xmin".into(), "4.5 < 0".into()),
            crate::msg::Said::FrameTime("12.30".into(), "25.0".into(), "1.20".into()),
            crate::msg::Said::Status("clipped".into()),
            crate::msg::Said::Status("accepted".into()),
            crate::msg::Said::Status("rejected".into()),
        ] {
            v.push(Msg::Said(s));
        }
        v.push(Msg::At("p.toml:3:7".into(), Box::new(Msg::ErrUpZero)));
        v.extend(errors::tests::every_error().into_iter().map(Msg::Err));
        v.extend(pixel::every().into_iter().map(Msg::Pixel));
        v
    }

    /// Every figure message.
    fn figure_messages() -> Vec<Msg> {
        use crate::msg::{FigWord as W, FigureMsg as F, Panel as P};
        let panels = [
            P::Camera,
            P::Projection,
            P::ProjectionSide,
            P::ViewPlane,
            P::Frustum,
            P::WindowSide,
            P::NearWindow,
            P::Viewport,
            P::Clip,
            P::Shade,
        ];
        let words = [W::Cop, W::Eye, W::NotToScale, W::Surface];
        let mut v: Vec<F> = panels
            .iter()
            .flat_map(|p| [F::Title(*p), F::Desc(*p)])
            .collect();
        v.extend(words.map(F::Word));
        v.into_iter().map(Msg::Figure).collect()
    }

    /// Every title and statement of a generated problem.
    fn drawn_messages() -> Vec<Msg> {
        use crate::msg::{CameraText, DrawnTitle as T, ShadeAsked, Statement as S};
        let c = || CameraText {
            eye: "(3, 4, 0)".into(),
            look: "(0, 0, 0)".into(),
            up: "(0, 1, 0)".into(),
        };
        let p = || "A(1, 0.5, 2)".to_string();
        let x = |s: &str| s.to_string();
        let mut v: Vec<Msg> = [
            T::Basis,
            T::EyeCoordinates,
            T::Projection,
            T::Pipeline,
            T::Window,
            T::Clipping,
            T::Lighting,
        ]
        .into_iter()
        .map(Msg::DrawnTitle)
        .collect();
        let shade = |asked| S::Shade {
            normal: x("(0, 3, 4)"),
            color: x("(1, 0.5, 0)"),
            light: x("(0, 0, 1)"),
            view: x("(0, 0, 1)"),
            model: x("phong"),
            constants: x("ka = 0.4, kd = 0.6"),
            asked,
        };
        for st in [
            S::Basis(c()),
            S::View(c(), p()),
            S::Project(c(), p(), x("0.5")),
            S::Pipeline {
                camera: c(),
                points: p(),
                near: x("0.5"),
                fovy: x("45"),
                aspect: x("1.5"),
                viewport: x("200x100"),
            },
            S::Window(x("90"), x("1.5"), x("2")),
            S::Clip(
                x("(0, 0, 0)"),
                x("(2, 2, 2)"),
                x("(1, 1, 1)"),
                x("(3, 1, 1)"),
            ),
            shade(ShadeAsked::Lambert),
            shade(ShadeAsked::Blinn),
            shade(ShadeAsked::Phong),
        ] {
            v.push(Msg::Statement(Box::new(st)));
        }
        v
    }

    /// Fails to compile when a key is added without being listed above.
    #[allow(dead_code)]
    fn listed(m: &Msg) {
        use Msg::*;
        match m {
            Math(_)
            | Written(..)
            | Erratum(..)
            | Printed(_)
            | Asked(_)
            | SecModeling
            | SecViewing
            | SecProjection
            | SecWindowClip
            | SecViewport
            | SecLineClip(_)
            | SecLighting
            | SecPixel(..)
            | SecLightFace
            | SecLightVertex(_)
            | SecLightPixel
            | CamAxisN
            | CamAxisU
            | CamAxisV
            | CamCheck
            | CamMatrix
            | ViewMatrix
            | EyeCoords(_)
            | OrthoProj(_)
            | PerspProj(_)
            | WindowTop(_)
            | WindowEdges(_)
            | ViewportOf(_)
            | OutcodeOf(_)
            | TrivialTests
            | Intersection(..)
            | ClippedSegment
            | LiangBarsky
            | MethodsAgree
            | NothingToDo
            | ProjPlane
            | InsideVolume(_)
            | UnitVector(_)
            | ViewerLocal
            | Material
            | Light(..)
            | TermStep(_)
            | SumOfTerms
            | Clamp
            | WhichTriangle
            | Depth
            | Barycentric
            | FlatShading
            | Gouraud
            | PhongShading
            | PixelColour
            | FOutOfRange
            | FIncidence
            | FCamMatrix
            | FViewMatrix
            | FTrivial
            | FOutcode
            | FSegment
            | FMethods
            | FProjPlane
            | FLiangBarsky
            | FInside
            | FSpot
            | FClamp
            | FPixelCentre
            | FEdges
            | FDepth
            | FBarycentric
            | FFlat
            | FByte
            | AlreadyUnit
            | Saturates
            | InRange
            | NoTermInModel(..)
            | TextSetting
            | SummedInRange
            | SpecularSkipped
            | BeyondRange
            | WithinRange
            | NoRange
            | Behind(_)
            | LocalViewer
            | NoLocalViewer
            | ShininessZero
            | SpecularOff
            | NoHighlightBehind
            | SpotIn(_)
            | BehindCentre
            | TextH
            | Orthonormal(_)
            | TrivialNote(_)
            | Kept(_)
            | TouchesPoint
            | InsidePart
            | Misses
            | DefaultView
            | MaterialD3d
            | MaterialText
            | NoTriangle
            | Nearest
            | Agree(_)
            | AlreadyWorld
            | Inside(..)
            | UpParallel(_)
            | BehindWarn(_)
            | ExactTooLarge(_)
            | ExpectOne
            | ExpectList(_)
            | CountMismatch(..)
            | Expected(_)
            | ExpectedNone
            | ExpectedBool(_)
            | SeveralAnswers
            | EmptyAnswer
            | NoAnswer
            | AnswerTooLong(..)
            | Unreadable(_)
            | Exact
            | Rounded(_)
            | RoundedCoarse(..)
            | SigCoarse(..)
            | WithinPct(_)
            | Parts(_)
            | WithinPixel
            | NotAnOutcode(_)
            | NotAStatus(_)
            | FollowThrough
            | At(..)
            | Err(_)
            | Said(_)
            | ErrSamePoint(_)
            | ErrUpZero
            | ErrUpParallel(..)
            | ErrFovy(_)
            | ErrAspect(_)
            | ErrNear(_)
            | ErrCopPlane(..)
            | ErrUnknownPoint(..)
            | ErrBoxInverted(..)
            | ErrCannotRead(..)
            | ErrZeroUnit(_)
            | ErrNamedPoint(_)
            | ErrPointName(_)
            | ErrPointTwice(_)
            | ErrNamedPair(_)
            | ErrSize(_)
            | ErrCopNeedsPlane
            | ErrPlaneNeedsCop
            | ErrChooseProjection
            | ErrPointNeedsViewport
            | DrawnTitle(_)
            | Pixel(_)
            | Statement(_)
            | ErrFewDistinct(..)
            | ErrHtmlCommand
            | Figure(_) => {}
        }
    }

    #[test]
    fn every_message_has_words_in_both_languages() {
        for m in every_message() {
            let (en, id) = (words(&m, Lang::En), words(&m, Lang::Id));
            assert!(!en.is_empty() && en != "?", "{m:?} has no English");
            assert!(!id.is_empty() && id != "?", "{m:?} has no Indonesian");
        }
    }

    #[test]
    fn most_messages_differ_between_languages() {
        let all = every_message();
        let same = all
            .iter()
            .filter(|m| words(m, Lang::En) == words(m, Lang::Id))
            .count();
        // Only notation-like captions (the outcode bits) may coincide.
        assert!(same <= 2, "{same} messages are not translated");
    }
}
