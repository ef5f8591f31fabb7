//! The messages' own words in Bahasa Indonesia ([`Msg`]): one exhaustive match over
//! every key, the helpers' words (what is asked, how a printed answer
//! compares, the terms and the steps of a light) and the Indonesian number
//! style, `0,5` and `(0,5; 2; 3)`.

use super::Id;
use crate::input::ask::Part;
use crate::msg::{Erratum, Implausible, LightPart, Msg, Printed, SpotZone, Term, Trivial};
use crate::report::lang::NumStyle;
use crate::report::words::errors::ErrorWords;
use crate::report::words::keys::KeyWords;
use crate::report::words::msg::{self, MsgWords};
use crate::report::words::{DrawnWords, FigureWords, PixelWords, SaidWords};
use crate::tutor::key::Plane;

impl MsgWords for Id {
    /// A word table: long on purpose.
    fn msg_in(&self, m: &Msg, nums: NumStyle) -> String {
        match m {
            Msg::Math(s) => s.clone(),
            Msg::Written(en, ind) => ind.clone().unwrap_or_else(|| en.clone()),
            Msg::Erratum(kind, why) => msg::erratum(self, *kind, why),
            Msg::Printed(p) => self.printed(*p).into(),
            Msg::Asked(parts) => msg::asked(self, parts),
            Msg::DrawnTitle(t) => self.drawn_title(*t).into(),
            Msg::Pixel(p) => self.pixel(p),
            Msg::Statement(s) => self.statement(s, nums),
            Msg::Figure(f) => self.figure(f),
            Msg::At(place, m) => msg::at(self, place, m),
            Msg::Err(e) => self.error(e),
            Msg::Said(s) => self.said(s, nums),
            Msg::SecModeling => "Tahap 1: transformasi pemodelan".into(),
            Msg::SecViewing => "Tahap 2: transformasi sistem pandang (koordinat dunia → koordinat kamera)".into(),
            Msg::SecProjection => "Tahap 3: proyeksi terhadap near clipping plane".into(),
            Msg::SecWindowClip => "Tahap 4: viewing window dan clipping".into(),
            Msg::SecWindow => "Tahap 4: viewing window".into(),
            Msg::SecViewport => "Pemetaan viewport (viewing window → piksel)".into(),
            Msg::SecLineClip(None) => "Clipping garis".into(),
            Msg::SecLineClip(Some(i)) => format!("Clipping garis, segmen {i}"),
            Msg::SecLighting => "Pencahayaan".into(),
            Msg::SecPixel(x, y) => format!("Piksel ({x}; {y})"),
            Msg::SecLightFace => "Pencahayaan face (lighting::shade)".into(),
            Msg::SecLightVertex(n) => format!("Pencahayaan verteks {n} (lighting::shade)"),
            Msg::SecLightPixel => "Pencahayaan piksel (lighting::shade)".into(),
            Msg::CamAxisN => "Sumbu kamera n (dari Pref kembali ke Peye)".into(),
            Msg::CamAxisU => "Sumbu kamera u (ke kanan)".into(),
            Msg::CamAxisV => "Sumbu kamera v (ke atas pada gambar)".into(),
            Msg::CamCheck => "Pemeriksaan: u, v, n ortonormal dan membentuk sistem tangan kanan".into(),
            Msg::CamMatrix => "Matriks transformasi kamera Mcam (koordinat kamera ke koordinat dunia)".into(),
            Msg::ViewMatrix => "Matriks transformasi pandang V = Mcam⁻¹, invers Mcam (koordinat dunia ke koordinat kamera): rotasi (baris u, v, n) kali translasi sejauh −Pe".into(),
            Msg::EyeCoords(n) => format!("Koordinat kamera titik {n}"),
            Msg::OrthoProj(n) => format!("Proyeksi orthographic titik {n}"),
            Msg::PerspProj(n) => format!("Proyeksi perspektif titik {n}"),
            // the text's h is the near window's half-height; the far one has no name there
            Msg::WindowTop(l) if l == "near" => format!("Setengah tinggi viewing window pada {l} plane (h dalam teks)"),
            Msg::WindowTop(l) => format!("Setengah tinggi viewing window pada {l} plane"),
            Msg::WindowEdges(l) => format!("Tepi dan ukuran viewing window pada {l} plane"),
            Msg::ViewportOf(n) => format!("Koordinat viewport titik {n}"),
            Msg::OutcodeOf(n) => format!("Region code titik {n}"),
            Msg::TrivialTests => "Uji trivial dengan operasi logika AND".into(),
            Msg::Intersection(i, plane) => format!("Titik potong dengan bidang {} {plane}", self.plane(Plane::ALL[*i % 6])),
            Msg::ClippedSegment => "Segmen garis hasil clipping".into(),
            Msg::LiangBarsky => "Pemeriksaan silang dengan Liang–Barsky".into(),
            Msg::MethodsAgree => "Apakah kedua metode sama hasilnya?".into(),
            Msg::NothingToDo => "Tidak ada yang perlu dikerjakan".into(),
            Msg::ProjPlane => "Bidang proyeksi".into(),
            Msg::InsideVolume(n) => format!("Apakah {n}'' di dalam view volume?"),
            Msg::UnitVector(n) => format!("Vektor satuan {n}"),
            Msg::ViewerLocal => "Arah pengamat (pengamat lokal)".into(),
            Msg::Material => "Material dan model".into(),
            Msg::Light((i, n), part) => match *n > 1 {
                true => format!("Sumber cahaya {}: {}", i + 1, self.light_part(*part)),
                false => msg::capitalised(self.light_part(*part)),
            },
            Msg::TermStep(t) => format!("Komponen {}, per kanal warna", self.term(*t)),
            Msg::SumOfTerms => "Jumlah komponen".into(),
            Msg::Clamp => "Batasi tiap kanal ke [0, 1]".into(),
            Msg::WhichTriangle => "Segitiga mana yang menutupi piksel".into(),
            Msg::Depth => "Kedalaman pada piksel (z-buffer)".into(),
            Msg::Barycentric => "Koordinat barisentrik".into(),
            Msg::FlatShading => "Flat shading: satu warna per face".into(),
            Msg::Gouraud => "Gouraud: interpolasi warna verteks".into(),
            Msg::PhongShading => "Phong shading: interpolasi normal, posisi dan warna".into(),
            Msg::PixelColour => "Warna piksel".into(),
            Msg::FOutOfRange => "d² = |Pl − P|² > range²  ⇒  cahaya tidak dihitung".into(),
            Msg::FIncidence => "cos α = Lx·Nx + Ly·Ny + Lz·Nz,  lalu max(cos α, 0)".into(),
            Msg::FCamMatrix => "Mcam = T(Pe) · [u v n]   (kolom u, v, n, Pe)".into(),
            Msg::FViewMatrix => "V = R · T(−Pe),  R = [uᵀ; vᵀ; nᵀ],  kolom terakhir (−u·Pe; −v·Pe; −n·Pe)".into(),
            Msg::FTrivial => "kedua region code 000000 → diterima;  code0 AND code1 ≠ 000000 → ditolak;  selain itu → clipping".into(),
            Msg::FOutcode => "bit 1 x<xmin (kiri) · bit 2 x>xmax (kanan) · bit 3 y<ymin (bawah) · bit 4 y>ymax (atas) · bit 5 z<zmin (depan) · bit 6 z>zmax (belakang); region code ditulis bit 6 … bit 1 (bit 1 paling kanan)".into(),
            Msg::FSegment => "dari titik yang dipertahankan dengan t terkecil ke titik dengan t terbesar (ujung di dalam dihitung t = 0 dan t = 1)".into(),
            Msg::FMethods => "clipping dengan region code dibandingkan dengan Liang–Barsky".into(),
            Msg::FProjPlane => "z = d,  d = −near (kamera memandang ke arah −z dalam koordinat kamera)".into(),
            Msg::FPixelCentre => "pusat piksel (x + ½; y + ½) di dalam segitiga, yang terdekat menang".into(),
            Msg::FEdges => "fungsi tepi E₀, E₁, E₂ ≥ 0 di pusat piksel (aturan kiri-atas pada tepi); kedalaman terdekat menang".into(),
            Msg::FDepth => "z = λ₀z₀ + λ₁z₁ + λ₂z₂ (z/w linear di layar); makin kecil makin dekat".into(),
            Msg::FBarycentric => "λₖ = Eₖ(pusat)/luas di layar;  koreksi perspektif μₖ = (λₖ/wₖ) / Σ λₘ/wₘ".into(),
            Msg::FFlat => "warna = lighting::shade(normal face N; pusat face)".into(),
            Msg::FWindowEdges => "right = aspect·top,  bottom = −top,  left = −right,  tinggi = 2·top,  lebar = 2·right".into(),
            Msg::FLiangBarsky => "p = −Δx, Δx, −Δy, Δy, −Δz, Δz dan q = x0 − xmin, xmax − x0, y0 − ymin, ymax − y0, z0 − zmin, zmax − z0 pada bidang x = xmin … z = zmax;  t0 = max(0, q/p untuk p < 0) (bidang yang dimasuki),  t1 = min(1, q/p untuk p > 0) (bidang yang ditinggalkan);  p = 0 dengan q < 0: di luar;  terlihat bila t0 ≤ t1, dari P0 + t0·Δ sampai P0 + t1·Δ".into(),
            Msg::FInside => "left ≤ xp ≤ right,  bottom ≤ yp ≤ top,  dan −far ≤ z' ≤ −near".into(),
            Msg::FSpot => "ρ = (−L)·axis;  Spot = 1 bila ρ ≥ cos(θ/2), 0 bila ρ ≤ cos(φ/2), selain itu ((ρ − cos(φ/2))/(cos(θ/2) − cos(φ/2)))^falloff".into(),
            Msg::FClamp => "warna = min(max(C; 0); 1)".into(),
            Msg::FByte => "nilai 8-bit = round(255 · clamp(C; 0; 1))".into(),
            Msg::AlreadyUnit => "sudah merupakan vektor satuan".into(),
            Msg::Saturates => "sebuah kanal melewati 1 (atau di bawah 0) dan dibatasi: sorotan (highlight) menjadi jenuh".into(),
            Msg::InRange => "setiap kanal sudah berada di [0, 1]".into(),
            Msg::NoTermInModel(model, t) => {
                let model = crate::report::words::report::model_name(model);
                format!("model {model} tidak memiliki komponen {}", self.term(*t))
            }
            Msg::TextSetting => "satu sumber cahaya putih seperti di teks dan tanpa ambient global: jumlahnya 1·(faktor dalam teks)".into(),
            Msg::TextTerm(Term::Ambient) => "Ia = Is·ka pada teks, dengan intensitas sumber cahaya Is = 1 (satu sumber cahaya putih), dikalikan warna permukaan Cs".into(),
            Msg::TextTerm(Term::Diffuse) => "Id = Is·kd·MAX(cos α, 0) pada teks, dengan Is = 1, dikalikan warna permukaan Cs".into(),
            Msg::TextTerm(Term::Specular) => "Isp = Is·ksp·MAX(cosⁿ β, 0) pada teks (ksp adalah ks), dengan Is = 1, dikalikan warna specular putih Cwhite".into(),
            Msg::SummedInRange => "dijumlahkan atas semua sumber cahaya dalam jangkauan".into(),
            Msg::SpecularSkipped => "komponen specular dilewati (ks = 0 atau --specular off)".into(),
            Msg::BeyondRange => "di luar jangkauannya sumber cahaya tidak menyumbang apa pun, ambient pun tidak".into(),
            Msg::WithinRange => "dalam jangkauan".into(),
            Msg::NoRange => "tanpa batas jangkauan".into(),
            Msg::Behind(true) => "cos α < 0: sumber cahaya di belakang permukaan — tanpa diffuse, dan (--specular-requires-lit) tanpa specular".into(),
            Msg::Behind(false) => "cos α < 0: sumber cahaya di belakang permukaan — tanpa diffuse; kode dalam teks tetap menghitung R dan menambahkan komponen specular (gunakan --specular-requires-lit untuk aturan yang lazim)".into(),
            Msg::LocalViewer => "pengamat lokal (D3DRS_LOCALVIEWER = TRUE): V menunjuk dari verteks ke kamera".into(),
            Msg::NoLocalViewer => "tanpa pengamat lokal: halaman Direct3D menulis (0,0,1) untuk pengamat. Itu benar di ruang kamera grafika yang tangan kanan, tempat pengamat berada di arah +z; ruang kamera Direct3D sendiri tangan kiri dan menempatkan pengamat di arah −z, jadi bacalah (0,0,1) di halaman itu sebagai \"menuju pengamat\". grafika memakai V Anda (bawaan (0; 0; 1))".into(),
            Msg::ShininessZero => "n = 0: x⁰ = 1 untuk setiap arah (0⁰ dianggap 1) — sorotan (highlight) menutupi seluruh permukaan".into(),
            Msg::SpecularOff => "komponen specular tidak aktif untuk model / pengaturan ini (ks = 0, --specular off, atau model tanpa specular)".into(),
            Msg::NoHighlightBehind => "cos α ≤ 0 dan --specular-requires-lit: tidak ada sorotan (highlight) dari sumber cahaya di belakang permukaan".into(),
            Msg::SpotIn(SpotZone::Inner) => "di dalam kerucut dalam (ρ ≥ cos(θ/2)): cahaya penuh".into(),
            Msg::SpotIn(SpotZone::Outer) => "di luar kerucut luar (ρ ≤ cos(φ/2)): tanpa cahaya".into(),
            Msg::SpotIn(SpotZone::Penumbra) => "di penumbra: di antara kedua kerucut".into(),
            Msg::BehindCentre => "di belakang pusat proyeksi: tetap diproyeksikan, tetapi terbalik dan tidak terlihat".into(),
            Msg::TextH => "h dalam teks adalah setengah tinggi ini; tinggi penuh viewing window adalah 2·top".into(),
            Msg::Orthonormal(true) => "ortonormal dan membentuk sistem tangan kanan".into(),
            Msg::Orthonormal(false) => "TIDAK ortonormal: periksa masukan".into(),
            Msg::TrivialNote(Trivial::Accept) => "kedua ujung di dalam: diterima seluruhnya".into(),
            Msg::TrivialNote(Trivial::Reject) => "kedua ujung di luar bidang yang sama: ditolak".into(),
            Msg::TrivialNote(Trivial::Clip) => "tidak ada uji yang memutuskan: cari titik potong dengan bidang yang dilanggar ujung-ujungnya".into(),
            Msg::Kept(true) => "region code 000000: dipertahankan".into(),
            Msg::Kept(false) => "region code bukan 000000: di luar view volume, dibuang".into(),
            Msg::TouchesPoint => "segmen garis menyentuh view volume di satu titik".into(),
            Msg::InsidePart => "bagian P0P1 di dalam view volume".into(),
            Msg::Misses => "tidak ada titik potong di dalam view volume: segmen garis tidak mengenainya (ditolak)".into(),
            Msg::DefaultView => "tidak diberikan: viewVector dari teks (0; 0; 1), pengamat jauh di arah +z".into(),
            Msg::MaterialD3d => "material Direct3D: warnanya sudah memuat koefisien, jadi ka = kd = ks = 1".into(),
            Msg::MaterialText => format!("konstanta dari teks bila tidak diberikan: {}", msg::material_text(nums, " (ksp dalam teks)", "specular putih (Cwhite)")),
            Msg::NoTriangle => "tidak ada segitiga yang menutupi pusat piksel: warnanya tetap warna latar".into(),
            Msg::Nearest => "yang terdekat dari semua segitiga yang menutupi piksel ini".into(),
            Msg::Agree(true) => "kedua metode menghasilkan segmen garis yang sama".into(),
            Msg::Agree(false) => "kedua metode berbeda hasilnya: mohon laporkan masukan ini".into(),
            Msg::AlreadyWorld => "objek sudah diberikan dalam sistem koordinat dunia".into(),
            Msg::Inside(true, true) => "di dalam: tidak di-clip".into(),
            Msg::Inside(false, _) => "di luar viewing window: di-clip".into(),
            Msg::Inside(true, false) => "di luar near/far plane: di-clip".into(),
            Msg::ErrSamePoint(p) => format!("posisi mata Peye dan titik referensi Pref adalah titik yang sama {}", nums.shortest3(*p)),
            Msg::ErrUpZero => "vektor Vup adalah vektor nol".into(),
            Msg::ErrUpParallel(up, d) => format!("vektor Vup = {} sejajar dengan arah pandang Peye − Pref = {}, sehingga Vup × n = 0 dan u tidak terdefinisi", nums.shortest3(*up), nums.shortest3(*d)),
            Msg::ErrFovy(v) => format!("harus di antara 0° dan 180° (tidak termasuk keduanya), diberikan {}°", nums.shortest(*v)),
            Msg::ErrAspect(v) => format!("harus positif (lebar/tinggi), diberikan {}", msg::given(*v, nums)),
            Msg::ErrNear(v) => format!("harus positif (jarak di depan mata), diberikan {}", msg::given(*v, nums)),
            Msg::ErrCopPlane(p, None) => format!("{p} memiliki z = 0: titik itu terletak pada bidang pusat proyeksi dan tidak memiliki bayangan"),
            Msg::ErrCopPlane(p, Some(z)) => format!("{p} memiliki z = zprp = {}: titik itu terletak pada bidang pusat proyeksi dan tidak memiliki bayangan", nums.shortest(*z)),
            Msg::ErrUnknownPoint(p, None) => format!("titik `{p}` tidak dikenal: soal ini tidak memiliki [points]"),
            Msg::ErrUnknownPoint(p, Some(known)) => format!("titik `{p}` tidak dikenal; titik-titiknya adalah {known}"),
            Msg::ErrBoxInverted(a, lo, hi) => format!("{a}min = {} lebih besar daripada {a}max = {}", nums.shortest(*lo), nums.shortest(*hi)),
            Msg::ErrCannotRead(path, why) => format!("tidak dapat membaca {path}: {}", self.io_why(why)),
            Msg::ErrZeroUnit(v) => format!("{v} adalah vektor nol (0; 0; 0): tidak memiliki arah, sehingga tidak dapat dijadikan vektor satuan"),
            Msg::ErrNamedPoint(t) => format!("`{t}`: seharusnya NAMA=X,Y,Z, misalnya A=0,0,0"),
            Msg::ErrPointName(t) => format!("`{t}` bukan nama titik (huruf, angka, _ dan ')"),
            Msg::ErrPointTwice(t) => format!("titik {t} diberikan dua kali"),
            Msg::ErrNamedPair(t) => format!("`{t}`: seharusnya NAMA=X,Y (dua bilangan)"),
            Msg::ErrSize(t) => format!("`{t}`: seharusnya LEBARxTINGGI, misalnya 200x100"),
            Msg::ErrCopNeedsPlane => "--cop memerlukan --plane (bidang pandang z = ZVP)".into(),
            Msg::ErrPlaneNeedsCop => "--plane memerlukan --cop (pusat proyeksi z = ZPRP)".into(),
            Msg::ErrChooseProjection => "pilih satu proyeksi: --d D, atau --cop ZPRP --plane ZVP, atau --ortho".into(),
            Msg::ErrPointNeedsViewport => "--point memerlukan --viewport WxH untuk memetakan titik ke piksel".into(),
            Msg::ExpectOne => "seharusnya satu bilangan".into(),
            Msg::ExpectList(n) => format!("seharusnya daftar berisi {n} nilai"),
            Msg::CountMismatch(n, k) => format!("seharusnya {n} nilai, diberikan {k}"),
            Msg::ExpectedNone => "seharusnya tidak ada (tidak ada yang tersisa)".into(),
            Msg::ExpectedBool(b) => format!("seharusnya {}", if *b { "ya" } else { "tidak" }),
            Msg::SeveralAnswers => "kunci ini memuat beberapa jawaban: berikan satu per satu".into(),
            Msg::EmptyAnswer => "jawaban kosong".into(),
            Msg::NoAnswer => "tidak ada jawaban".into(),
            Msg::AnswerTooLong(n, max) => format!("jawaban ini memuat {n} karakter; paling banyak {max} yang dibaca"),
            Msg::WithinPixel => "dalam setengah piksel".into(),
            Msg::NotAnOutcode(t) => format!("`{t}` bukan region code: tulis enam digit biner, bit 1 paling kanan (001000)"),
            Msg::NotAStatus(t) => format!("`{t}` bukan status: tulis diterima, ditolak atau di-clip (accepted, rejected, clipped)"),
            Msg::NotYesOrNo(t) => format!("`{t}` bukan ya atau tidak: tulis ya atau tidak (yes, no)"),
            Msg::AmbiguousCommas => "koma di sini dipakai sebagai tanda desimal sekaligus pemisah, sehingga bilangannya tidak dapat dibedakan: tulis 0,7071; 0; 0,7071 (koma desimal, bagian dipisahkan ;) atau 0.7071, 0, 0.7071".into(),
            Msg::FollowThrough => "benar menurut jawaban sebelumnya (benar lanjutan)".into(),
            Msg::NoFollowFrom(a, why, b) => {
                let name = |k: &str| crate::report::words::keys::name_of(self, k);
                let (a, b) = (name(a), name(b));
                let not = match why {
                    Implausible::NotUnit => format!("{a} bukan vektor satuan"),
                    Implausible::NotPerpendicular(o) => format!("{a} tidak tegak lurus {}", name(o)),
                    Implausible::OffSegment => format!("{a} tidak terletak pada segmen garis P0P1"),
                    Implausible::NotACosine => format!("{a} bukan nilai cosinus (di luar −1 sampai 1)"),
                    Implausible::NotAColour => format!("{a} bukan warna (ada kanal di luar 0 sampai 1)"),
                    Implausible::Negative => format!("{a} negatif"),
                    Implausible::NotPositive => format!("{a} tidak positif"),
                    Implausible::NotNegative => format!("{a} tidak negatif"),
                };
                format!("{not}, sehingga {b} tidak dapat dinilai menurut nilai itu")
            }
            Msg::Exact => "tepat".into(),
            Msg::Rounded(s) => format!("dibulatkan ke {s} angka penting"),
            Msg::RoundedCoarse(s, need) => format!("dibulatkan ke {s} angka penting, paling sedikit {need} diperlukan"),
            Msg::UpParallel(a) => format!(
                "vektor up (Vup) hampir sejajar dengan arah pandang (sudut {} rad): u dan v sangat peka terhadap masukan",
                msg::exponent(nums, *a)
            ),
            Msg::BehindWarn(n) => format!("{n} berada di belakang pusat proyeksi: bayangannya terbalik dan tidak terlihat"),
            Msg::NoFigure => "tidak ada gambar yang ditulis: tidak ada bagian yang ditanyakan yang punya gambar sendiri (piksel `viewport` digambar pada gambar window: tanyakan `window` juga)".into(),
            Msg::ExactTooLarge(n) => format!("nilai eksak yang akan memuat lebih dari {n} suku (banyak akar kuadrat yang berbeda) dihitung dengan f64 dan ditandai ≈, begitu pula yang diturunkan darinya"),
            Msg::ErrFewDistinct { topic, level, problem, found, asked, all } => format!(
                "soal {problem} ({topic}, {level}) hanya dapat dibuat dalam {found} varian berbeda{}, bukan {asked} seperti diminta (tidak ada soal yang dinyatakan dua kali dalam satu ujian): minta lebih sedikit (--variants, --count) atau tingkat lain (--difficulty)",
                if *all { " (semua soal jenis ini sudah dicoba)" } else { " (ditemukan dalam 200.000 percobaan)" }
            ),
            Msg::ExactTooLong(bits) => format!("nilai eksak yang pembilang atau penyebutnya akan melebihi {bits} bit (pangkat yang tinggi, seperti shininess yang besar) dihitung dengan f64 dan ditandai ≈, begitu pula yang diturunkan darinya"),
            Msg::StaleTempRemoved(p, pid) => format!("{p} dihapus: berkas sementara yang ditinggalkan proses grafika {pid}, yang sudah tidak berjalan (dihentikan sebelum sempat membersihkan)"),
            Msg::ErrHtmlCommand => "menulis penyelesaian basis, view, project, window, clip, shade, solve dan render; untuk ujian gunakan generate --format html".into(),
            Msg::Parts(parts) => msg::parts(self, parts),
            Msg::Expected(v) => format!("seharusnya {}", nums.expect(v)),
            Msg::Unreadable(why) => format!("tidak dapat dibaca: {}", self.number(why)),
            Msg::WithinPct(p) => format!("dalam batas {}%", nums.dec(*p, 3)),
        }
    }

    fn nums(&self) -> NumStyle {
        NumStyle::COMMA
    }

    fn printed(&self, p: Printed) -> &'static str {
        match p {
            Printed::Agrees => "sesuai",
            Printed::Differs(None) => "jawaban yang tercetak salah",
            Printed::Differs(Some(Erratum::Misprint)) => "salah cetak di teks",
            Printed::Differs(Some(Erratum::Convention)) => "teks memakai konvensi lain",
            Printed::Differs(Some(Erratum::Rounding)) => "kesalahan pembulatan di teks",
            Printed::NotAsked => "tidak dihitung (tidak ditanyakan dalam soal ini)",
            Printed::NotComparable => "tidak dapat dibandingkan",
        }
    }

    fn asked_heading(&self) -> &'static str {
        "Ditanyakan"
    }

    fn asked_part(&self, part: Part) -> &'static str {
        match part {
            Part::View => "basis kamera u, v, n, matriks transformasi pandang, dan posisi titik-titik dalam koordinat kamera",
            Part::Project => "hasil proyeksinya terhadap near clipping plane",
            Part::Window => "viewing window pada near clipping plane (tepi-tepinya, lebar dan tinggi) dan titik hasil proyeksi mana yang berada di dalam view volume",
            Part::Viewport => "posisi piksel tiap titik pada viewport",
            Part::Clip => "region code kedua ujung dan hasil clipping segmen garis",
            Part::Shade => "warna hasil pencahayaan pada titik itu, komponen demi komponen",
        }
    }

    fn cut(&self, n: usize) -> String {
        format!("({n} karakter dipotong)")
    }

    fn term(&self, t: Term) -> &'static str {
        match t {
            Term::Ambient => "ambient",
            Term::Diffuse => "diffuse",
            Term::Specular => "specular",
        }
    }

    fn light_part(&self, p: LightPart) -> &'static str {
        match p {
            LightPart::OutOfRange => "di luar jangkauan",
            LightPart::Direction => "arah ke sumber cahaya",
            LightPart::Attenuation => "redaman (Att)",
            LightPart::Incidence => "sudut datang: cos α = L·N",
            LightPart::Reflection => "vektor pantulan R dan cos β",
            LightPart::HalfVector => "vektor setengah jalan H dan N·H (Blinn)",
            LightPart::Highlight => "sorotan specular (highlight)",
            LightPart::Spot => "faktor sorotan (Spot)",
        }
    }
}
