//! The error keys' words in Bahasa Indonesia: [`ErrorWords`] for [`Id`],
//! one exhaustive match per key enum. Numbers given in a message take the
//! decimal comma (`NumStyle` of Indonesian); the crates' messages are said
//! from their typed keys, with a phrase not recognised quoted as written.

use super::Id;
use crate::msg::{
    Bound, Channel, ClapErr, ErrMsg, FileKind, IoWhy, ListWhy, NumErr, ObjWhy, Thing, TomlErr,
    Twice, Want,
};
use crate::report::lang::NumStyle;
use crate::report::words::errors::{
    self, folder_prefix, ErrorWords, ExpectWord, Expected, ParseWhy, SerdeWord, Syntax, SyntaxWhat,
    ValueWhy,
};

/// The number style of Indonesian words: the decimal comma.
fn nums() -> NumStyle {
    crate::report::words::MsgWords::nums(&Id)
}

impl ErrorWords for Id {
    fn error(&self, m: &ErrMsg) -> String {
        match m {
            ErrMsg::Num(e) => self.number(e),
            ErrMsg::Toml(e) => self.toml(e),
            ErrMsg::Clap(e, line) => self.clap(e, line),
            ErrMsg::MustBe(b, got) => self.must_be(b, *got),
            ErrMsg::Twice(t) => self.twice(*t).to_string(),
            ErrMsg::CannotRead(p, why) => format!("tidak dapat membaca {p}: {}", self.io_why(why)),
            ErrMsg::CannotReadStdin(why) => {
                format!("tidak dapat membaca masukan standar: {}", self.io_why(why))
            }
            ErrMsg::CannotWrite(p, why) => format!("tidak dapat menulis {p}: {}", self.io_why(why)),
            ErrMsg::CannotCreate(p, why) => format!("tidak dapat membuat {p}: {}", self.io_why(why)),
            ErrMsg::CannotWriteStdout(why) => {
                format!("tidak dapat menulis ke keluaran standar: {}", self.io_why(why))
            }
            ErrMsg::StdoutClosed => "keluaran standar tertutup, jadi hasilnya akan hilang (untuk membuangnya, arahkan ke /dev/null)".into(),
            ErrMsg::ExistsForce(p) => format!("{p} sudah ada: berikan --force untuk menggantinya, atau pilih nama lain"),
            ErrMsg::NamesFolder(p) => format!("{p} adalah folder, bukan nama berkas: sebutkan berkas yang akan ditulis (misalnya {}gambar.svg)", folder_prefix(p)),
            ErrMsg::IsLink(p) => format!("{p} adalah tautan simbolik: grafika tidak pernah menulis melalui tautan atau menggantinya; sebutkan berkasnya sendiri atau nama lain"),
            ErrMsg::IsInput(p) => format!("{p} adalah salah satu masukan perintah ini (berkas yang sama, tautan diikuti): tidak pernah ditimpa, juga dengan --force"),
            ErrMsg::NotOwn(p, marker) => format!("{p} tidak ditulis oleh grafika generate (tidak tercantum di {marker}, atau berisi berkas lain): --force hanya mengganti keluaran generate sendiri sebelumnya; pindahkan atau pilih --out yang lain"),
            ErrMsg::NotDirectory(p) => format!("{p} sudah ada dan bukan direktori"),
            ErrMsg::FileTooLarge(p, Some(n), max) => format!("{p} berukuran {n} bita; berkas soal, scene, cahaya atau jawaban paling besar {max} bita (ditolak sebelum dibaca sebagai TOML)"),
            ErrMsg::FileTooLarge(p, None, max) => format!("{p} berukuran lebih dari {max} bita; berkas soal, scene, cahaya atau jawaban paling besar {max} bita (ditolak sebelum dibaca sebagai TOML)"),
            ErrMsg::TomlTooManyValues(max) => format!("larik-larik (array) dalam berkas ini bersama-sama memuat lebih dari {max} nilai, lebih dari yang dibaca grafika (ditolak sebelum berkas dibaca sebagai TOML)"),
            ErrMsg::TomlTooDeep(max) => format!("larik (array) atau tabel sebaris bersarang lebih dari {max} tingkat (ditolak sebelum berkas dibaca sebagai TOML)"),
            ErrMsg::StdinClosed => "masukan standar tertutup (<&-), jadi tidak ada yang bisa dibaca: berikan sebuah berkas, atau kirim masukan dengan < BERKAS atau pipa".into(),
            ErrMsg::InputNotRegular(p, k) => format!("{p} adalah {}, bukan berkas biasa: grafika hanya membaca berkas biasa (dan masukan standar, -), agar pembacaan tidak pernah menunggu selamanya", file_kind(*k)),
            ErrMsg::OutputNotRegular(p, k) => format!("{p} adalah {}: grafika hanya menulis berkas biasa (dan perangkat karakter seperti /dev/null, secara langsung), tidak pernah mengganti yang lain; pilih nama lain", file_kind(*k)),
            ErrMsg::SameOutput(p, other) => format!("{p} juga berkas untuk --{other}: satu berkas tidak dapat memuat kedua keluaran (tidak ada yang ditulis); berikan nama sendiri untuk masing-masing"),
            ErrMsg::ChangedSince(p) => format!("{p} telah berubah sejak ditulis oleh grafika generate (isinya bukan yang ditulis grafika): --force hanya mengganti keluaran generate sendiri seperti saat ditulis; pindahkan atau pilih --out yang lain"),
            ErrMsg::NotOwnList(p, why) => format!("{p} bukan daftar yang ditulis oleh grafika generate ({}), jadi tidak ada yang disebutnya diganti atau dihapus: jika folder ini hanya berisi keluaran generate sebelumnya, hapus {p} lalu berikan --force, atau pilih --out yang lain", list_why(why)),
            ErrMsg::ListExists(p) => format!("{p} sudah ada (grafika generate sebelumnya menulis ke folder ini): berikan --force untuk mengganti keluaran itu, atau pilih --out yang lain"),
            ErrMsg::Locked(d, lock) => format!("grafika generate lain sedang menulis ke {d} (ia memegang {lock}): tunggu sampai selesai, atau pilih --out yang lain"),
            ErrMsg::NotMarked(n, of, which) => format!("{n} dari {of} berkas jawaban tidak dapat dinilai (lihat galat di baris masing-masing): {which}"),
            ErrMsg::Man(why) => format!("tidak dapat menulis halaman manual: {why}"),
            ErrMsg::ObjUnreadable(p, why) => {
                format!("tidak dapat membaca berkas OBJ {p}: {}", self.io_why(why))
            }
            ErrMsg::ObjInvalid(p, why) => {
                format!("{p} bukan berkas OBJ yang sah: {}", self.obj_why(*why))
            }
            ErrMsg::ObjNoFaces(p) => format!("{p} tidak memiliki bidang (face)"),
            ErrMsg::ObjNotFinite(p) => format!("{p} memiliki verteks yang bukan bilangan berhingga"),
            ErrMsg::FaceVertex => "sebuah bidang (face) merujuk ke verteks yang tidak ada".into(),
            ErrMsg::FormulaNotFinite => "rumus menghasilkan nilai yang bukan bilangan berhingga".into(),
            ErrMsg::TooManyTriangles(n, max) => format!("objek-objek scene ini bersama-sama memiliki {n} segitiga; renderer menerima paling banyak {max} per scene (ditolak sebelum mesh dibuat)"),
            ErrMsg::TooManyLights(n, max) => format!("file ini memiliki {n} cahaya; grafika menerima paling banyak {max} per file (seperti Direct3D 9)"),
            ErrMsg::RenderWork(est, frames, max) => format!("render ini diperkirakan {est} juta langkah (piksel yang dicakup kotak setiap segitiga, pencahayaan, untuk {frames} frame), melebihi batas {max} juta (sekitar 10 detik dengan 2 core): berikan --work-limit {est} untuk tetap me-render, atau kecilkan --width, --height atau --repeat"),
            ErrMsg::FormulaWork(n, size, need, max) => format!("rumus ketinggian akan dievaluasi {n} kali, masing-masing {size} operasi dan bilangan, melebihi batas kerja {max} juta langkah (ditolak sebelum ada yang dievaluasi): berikan render --work-limit {need} untuk tetap mengevaluasinya, atau pakai lebih sedikit titik grid (nx, nz) atau rumus yang lebih pendek"),
            ErrMsg::NeedsColour => "memerlukan paling sedikit satu warna".into(),
            ErrMsg::NoObjects => "scene tidak memiliki objek: tambahkan paling sedikit satu tabel [[object]] (cone, sphere, cylinder, box, plane atau obj)".into(),
            ErrMsg::CameraNeedsPerspective => "[camera] memerlukan [perspective] dengan fovy, near dan far".into(),
            ErrMsg::ImageSize(w, h) => format!("lebar dan tinggi harus 1 sampai 8192 piksel, diberikan {w}x{h}"),
            ErrMsg::Needs(thing, key) => self.needs(thing, key),
            ErrMsg::NoSuchKey(t, k, all) => format!("objek {t} tidak memiliki `{k}` (kuncinya: {all})"),
            ErrMsg::NeededToRender => "diperlukan untuk me-render".into(),
            ErrMsg::NoLightTable(p) => format!("{p} tidak memiliki tabel [[light]]"),
            ErrMsg::ColorMissing => "warna permukaan Cs tidak ada (R,G,B di [0, 1])".into(),
            ErrMsg::NormalMissing => "normal permukaan N tidak ada".into(),
            ErrMsg::CameraAtPoint => "kamera berada di titik permukaan: tidak ada arah ke pengamat".into(),
            ErrMsg::NoLight => "tidak ada cahaya: berikan L (menuju sumber cahaya) atau berkas cahaya".into(),
            ErrMsg::LightAtPoint => "sumber cahaya berada di titik permukaan itu sendiri: tidak ada arah ke sana".into(),
            ErrMsg::NotApplicable(k, kind) => format!("`{k}` tidak berlaku untuk sumber cahaya {kind}"),
            ErrMsg::Channel(ch, v) => format!(
                "kanal warna harus berada di [0, 1]; {} bernilai {}",
                self.channel(*ch),
                nums().shortest(*v)
            ),
            ErrMsg::Attenuation(a0, a1, a2) => format!(
                "a0, a1, a2 harus ≥ 0 dan tidak semuanya 0, diberikan {}",
                nums().shortest3([*a0, *a1, *a2])
            ),
            ErrMsg::Cones(t, p) => format!(
                "sudut kerucut harus 0 ≤ theta ≤ phi ≤ 180°, diberikan theta = {}, phi = {}",
                nums().shortest(*t),
                nums().shortest(*p)
            ),
            ErrMsg::PlaneThroughOrigin => "bidang proyeksi z = 0 melalui pusat proyeksi di titik asal".into(),
            ErrMsg::PlaneThroughCop(z) => format!("bidang proyeksi z = {} melalui pusat proyeksi", nums().shortest(*z)),
            ErrMsg::ImageTooLarge(p, prec) => format!("bayangan {p} terlalu besar untuk presisi {prec} (titik itu terlalu dekat dengan bidang pusat proyeksi)"),
            ErrMsg::Viewport(w, h) => format!("lebar dan tinggi harus positif, diberikan {}x{}", nums().shortest(*w), nums().shortest(*h)),
            ErrMsg::VVanished => "v = n × u menjadi nol".into(),
            ErrMsg::EyeLookTooLarge(d, prec) => format!("Peye − Pref = {} terlalu besar untuk presisi {prec}", nums().shortest3(*d)),
            ErrMsg::TranslationTooLarge(prec) => format!("translasi matriks pandang −(u·Pe; v·Pe; n·Pe) terlalu besar untuk presisi {prec}"),
            ErrMsg::EyeCoordsTooLarge(p, prec) => format!("koordinat kamera titik {p} terlalu besar untuk presisi {prec}"),
            ErrMsg::ExactBeyondF64 => "hasilnya eksak tetapi di luar jangkauan f64 (sekitar 1,8e308), jadi tidak ada desimal atau bilangan JSON untuknya (skalakan masukan)".into(),
            ErrMsg::ResultNotFinite(prec) => format!("hasilnya bukan bilangan berhingga pada presisi {prec}: sebuah masukan melampaui batas bilangan floating point (skalakan masukan, atau gunakan --precision exact)"),
            ErrMsg::UnknownPart(a, all) => format!("bagian `{a}` tidak dikenal; bagian-bagiannya adalah {all}"),
            ErrMsg::ExpectedXyz(e) => format!("seharusnya [x, y, z]: {}", self.toml(e)),
            ErrMsg::NothingToSolve => "tidak ada yang dapat diselesaikan: berkas ini tidak memiliki bagian yang datanya lengkap (camera + points, perspective, clip, shade)".into(),
            ErrMsg::NoCameraTable => "soal meminta transformasi pandang tetapi tidak memiliki tabel [camera]".into(),
            ErrMsg::ProjectionNeedsNear => "proyeksi memerlukan perspective.near (atau perspective.d)".into(),
            ErrMsg::WindowNeeds => "viewing window memerlukan perspective.fovy, perspective.aspect dan perspective.near".into(),
            ErrMsg::LightsNeedShade => "tabel [[light]] memerlukan tabel [shade] (normal, color, ...)".into(),
            ErrMsg::NoTopic => "berikan paling sedikit satu topik".into(),
            ErrMsg::NoProblemDrawn => "tidak ada soal yang dibuat".into(),
            ErrMsg::StdinHoldsAnswers => "masukan standar berisi jawaban: berikan soal sebagai berkas".into(),
            ErrMsg::GiveProblem => "berikan berkas soal atau --topic".into(),
            ErrMsg::TooManyProblems(n, c, v, mb, max) => format!("{n} soal ({c} × {v}, sekitar {mb} MB) lebih dari {max} yang ditulis tanpa --force"),
            ErrMsg::SplitNotQuiz => "memecah berkas kuis: hanya dipakai dengan --format moodle atau --format gift".into(),
            ErrMsg::QuestionTooLarge(q, size, limit) => format!("pertanyaan \"{q}\" sendiri berukuran {} MB, lebih dari {} MB yang boleh dimiliki satu berkas: berikan --split-mb yang lebih besar", nums().fixed_of(*size), nums().fixed_of(*limit)),
            ErrMsg::BothStdin => "soal dan jawaban tidak dapat sama-sama berasal dari masukan standar (-)".into(),
            ErrMsg::NoPrinted(p) => format!("{p} tidak memiliki tabel [printed]"),
            ErrMsg::CsvAndJson => "--csv - dan --json sama-sama akan menulis ke keluaran standar: berikan nama berkas untuk --csv".into(),
            ErrMsg::NoAnswerFiles(d) => format!("{d} tidak berisi berkas jawaban .toml"),
            ErrMsg::NoExam(d) => format!("{d} tidak berisi problem-01.toml (maupun variant-01/): berikan berkas soal atau folder yang ditulis grafika generate"),
            ErrMsg::NoVariant(n) => format!("ujian ini memiliki {n} varian: tuliskan varian mana yang dijawab dengan `variant = N` di awal berkas"),
            ErrMsg::NotAVariant(v, n) => format!("`{v}` bukan varian ujian ini (1 sampai {n})"),
            ErrMsg::MarksNotAKey(k) => format!("`{k}` bukan jawaban soal ini, sehingga tidak dapat diberi poin"),
            ErrMsg::MarksUnknownField(f) => format!("field `{f}` tidak dikenal: isi [marks] adalah banyaknya poin, atau tabel dengan `marks` dan `method`"),
            ErrMsg::MarksMissing => "tabel ini tidak memuat `marks`: tuliskan `{ marks = 3, method = { … } }`".to_string(),
            ErrMsg::MarksNotWhole(v, most) => format!("`{v}` bukan banyaknya poin: bilangan bulat dari 0 sampai {most}"),
            ErrMsg::MarksMethodTable => "`method` adalah tabel kunci langkah pengerjaan, masing-masing dengan poinnya: `method = { \"shade.diffuse\" = 1 }`".to_string(),
            ErrMsg::MarksMethodOver(sum, marks) => format!("jumlah poin langkah pengerjaan {sum}, lebih dari {marks} poin jawaban itu sendiri"),
            ErrMsg::MarksMethodAsked(k) => format!("`{k}` sudah ditanyakan dengan poinnya sendiri, sehingga tidak dapat juga memberi poin langkah untuk jawaban lain"),
            ErrMsg::NotAProblemOfExam(k, names) => format!("`{k}` tidak berada di tabel soal ujian ini ([{names}])"),
            ErrMsg::ReportFormat(p) => format!("{p}: format laporan ditentukan oleh ekstensinya: .html, .md, .json atau .csv"),
            ErrMsg::NotResponses(c) => format!("bukan laporan Jawaban (Responses) kuis Moodle ({c}): unduh dari Kuis → Hasil → Jawaban, \"Unduh data tabel sebagai\" CSV, JSON, Excel atau OpenDocument"),
            ErrMsg::NoQuestionText => "laporan Responses tidak menunjukkan soal yang didapat tiap mahasiswa: centang \"Question text\" di pilihan laporan lalu unduh lagi".into(),
            ErrMsg::AnswersFolder(d, why) => format!(
                "folder berkas jawaban {d} tidak dapat dibaca: {} (laporan kelas memerlukan --answers DIR)",
                self.io_why(why)
            ),
            ErrMsg::RosterNeedsClass => "daftar kelas dicocokkan dengan satu kelas: --roster memerlukan --answers DIR (folder berkas jawaban)".into(),
            ErrMsg::EmptyRoster(f) => format!("daftar kelas {f} tidak berisi nama"),
            ErrMsg::RosterRow(line, why) => format!("baris {line} daftar kelas tidak dapat dibaca sebagai CSV: {why}"),
            ErrMsg::ReportNeedsClass => "laporan kelas memerlukan --answers DIR (folder berkas jawaban)".into(),
            ErrMsg::PixelOutside(x, y, w, h) => format!("({x}; {y}) berada di luar gambar {w}x{h}"),
            ErrMsg::PixelText(s) => format!("seharusnya X,Y (nomor piksel bulat), diberikan `{s}`"),
            ErrMsg::NothingRendered => "tidak ada yang di-render".into(),
            ErrMsg::Threads(why) => format!("tidak dapat memulai thread: {why}"),
            ErrMsg::RenderPrecision => "render selalu menghitung dengan f32 (--precision untuk langkah-langkah kalkulator): hilangkan opsi itu".into(),
            ErrMsg::NotTaken(c) => format!("grafika {c} tidak menerima opsi ini (grafika {c} --help mendaftar opsi yang diterimanya)"),
            ErrMsg::OwnOutput => "check, generate, bench, practice, completions dan man mencetak keluarannya sendiri: gunakan main_with_args".into(),
        }
    }

    fn number(&self, e: &NumErr) -> String {
        match e {
            NumErr::Quoted(t, why) => format!("`{t}`: {}", self.number(why)),
            NumErr::TooLong(len, max) => format!("bilangan ini panjangnya {len} karakter, lebih dari {max} yang diizinkan"),
            NumErr::Empty => "seharusnya sebuah bilangan, tetapi tidak ada isinya".into(),
            NumErr::Expected(w, col, Some(c)) => {
                format!("seharusnya {} di kolom {col}, ditemukan `{c}`", self.want(*w))
            }
            NumErr::Expected(w, col, None) => {
                format!("seharusnya {} di kolom {col}, ditemukan akhir teks", self.want(*w))
            }
            NumErr::TooDeep(max, col) => format!("bilangan ini bersarang lebih dari {max} tingkat (kurung, akar atau tanda) di kolom {col}"),
            NumErr::TooManyOps(max, col) => format!("bilangan ini memiliki lebih dari {max} operasi (di kolom {col})"),
            NumErr::Count(k, t) => format!("seharusnya tiga bilangan x,y,z dipisahkan koma, ditemukan {k} dalam `{t}`"),
            NumErr::Component(k, t, why) => {
                format!("komponen {} `{t}`: {}", errors::component(*k), self.number(why))
            }
            NumErr::NotFinite(x, p) => format!("`{x}` bukan bilangan berhingga pada presisi {p}"),
            NumErr::NotANumber(x) => format!("`{x}` bukan bilangan"),
            NumErr::NotFiniteLiteral(x) => format!("{x} bukan bilangan berhingga"),
            NumErr::NegativeRoot(x) => format!("sqrt({x}) mengambil akar kuadrat dari bilangan negatif"),
            NumErr::DivZero(x) => format!("`{x}` membagi dengan nol"),
            NumErr::Exponent(x) => format!("pangkat dalam `{x}` harus bilangan bulat dari -1024 sampai 1024"),
            NumErr::PowerRange(x) => format!("`{x}` adalah perpangkatan yang terlalu besar atau terlalu kecil"),
            NumErr::Unexpected(c, at) => format!("`{c}` tidak diharapkan di karakter ke-{at}"),
            NumErr::OpenAfter(name) => format!("seharusnya `(` setelah {name}"),
            NumErr::UnknownName(name) => format!("nama `{name}` tidak dikenal (rumus boleh memakai x, z, pi, exp, sqrt, sin, cos, abs)"),
            NumErr::EndsEarly => "rumus berakhir terlalu cepat".into(),
            NumErr::FormulaDeep(max, at) => format!("rumus bersarang lebih dari {max} tingkat (kurung, tanda atau pangkat) di karakter ke-{at}"),
            NumErr::FormulaOps(max, at) => format!("rumus memiliki lebih dari {max} operasi (di karakter ke-{at})"),
        }
    }

    fn want(&self, w: Want) -> &'static str {
        match w {
            Want::OperatorOrEnd => "operator atau akhir bilangan",
            Want::Close => "`)`",
            Want::OpenAfterSqrt => "`(` setelah sqrt",
            Want::Number => "sebuah bilangan",
        }
    }

    fn toml(&self, e: &TomlErr) -> String {
        let serde = |s: &str| errors::serde_words(s, |w| self.serde_word(w));
        match e {
            TomlErr::UnknownField(k, Some(all)) => {
                format!("kunci `{k}` tidak dikenal, seharusnya salah satu dari {all}")
            }
            TomlErr::UnknownField(k, None) => format!("kunci `{k}` tidak dikenal"),
            TomlErr::MissingField(k) => format!("kunci `{k}` belum diberikan"),
            TomlErr::Duplicate(k) => format!("kunci `{k}` diberikan dua kali"),
            TomlErr::UnknownVariant(v, all) => {
                format!("nilai `{v}` tidak dikenal, seharusnya salah satu dari {all}")
            }
            TomlErr::InvalidType(found, want) => {
                format!(
                    "jenis nilai salah: {}, seharusnya {}",
                    serde(found),
                    serde(want)
                )
            }
            TomlErr::InvalidLength(found, want) => {
                format!(
                    "panjang salah: {}, seharusnya {}",
                    serde(found),
                    serde(want)
                )
            }
            TomlErr::InvalidValue(found, want) => {
                format!(
                    "nilai tidak sah: {}, seharusnya {}",
                    serde(found),
                    serde(want)
                )
            }
            TomlErr::Num(e) => self.number(e),
            TomlErr::MustBe(b, got) => self.must_be(b, *got),
            TomlErr::WholeRange(lo, hi, got) => {
                format!("harus bilangan bulat dari {lo} sampai {hi}, diberikan {got}")
            }
            TomlErr::Colour(c) => {
                format!(
                    "komponen warna harus dari 0 sampai 1, diberikan {}",
                    errors::bracketed(*c, nums())
                )
            }
            TomlErr::Syntax(s) => {
                format!(
                    "sintaks TOML tidak sah: {}",
                    self.syntax(&errors::syntax(s))
                )
            }
        }
    }

    fn must_be(&self, b: &Bound, got: f64) -> String {
        let bound = match b {
            Bound::NumberAtLeastZero => "harus bilangan ≥ 0".to_string(),
            Bound::AtLeastZero => "harus ≥ 0".into(),
            Bound::AboveZero => "harus > 0".into(),
            Bound::Positive => "harus positif".into(),
            Bound::NotNegative => "tidak boleh negatif".into(),
            Bound::FiniteAtLeastZero => "harus bilangan berhingga ≥ 0".into(),
            Bound::Fraction => "harus bilangan di atas 0 dan di bawah 1 (0,001 adalah 0,1%)".into(),
            Bound::WholePixels => "harus bilangan bulat piksel".into(),
            Bound::AboveNear(near) => format!(
                "harus lebih besar daripada near = {}",
                nums().shortest(*near)
            ),
        };
        format!("{bound}, diberikan {}", nums().shortest(got))
    }

    fn twice(&self, t: Twice) -> &'static str {
        match t {
            Twice::GlobalAmbient => {
                "berikan ambient global sekali saja, tidak di berkas cahaya dan di sini sekaligus"
            }
            Twice::Material => {
                "berikan material sekali saja, tidak di berkas cahaya dan di sini sekaligus"
            }
            Twice::Color => "berikan warna permukaan sekali saja: color atau material.diffuse",
            Twice::Shininess => "berikan eksponen sekali saja: shininess atau material.power",
            Twice::View => "berikan V atau posisi kamera (pengamat lokal), tidak keduanya",
            Twice::Light => "berikan satu vektor cahaya L atau tabel [[light]], tidak keduanya",
            Twice::Axis => {
                "berikan sumbu sumber cahaya spot sekali saja: axis (atau nama lamanya, direction)"
            }
            Twice::TiltCamera => "berikan [tilt] atau [camera], tidak keduanya",
            Twice::Colors => "berikan hanya satu dari color, face_colors, vertex_colors",
            Twice::Answers => {
                "berikan --answers BERKAS|DIREKTORI atau --answers-from-text, salah satu saja"
            }
        }
    }

    /// The system's reason; one it gives in its own words is quoted as is.
    fn io_why(&self, w: &IoWhy) -> String {
        match w {
            IoWhy::NotFound => "berkas atau direktori tidak ada".into(),
            IoWhy::Denied => "izin ditolak".into(),
            IoWhy::Exists => "sudah ada".into(),
            IoWhy::IsDirectory => "itu sebuah direktori".into(),
            IoWhy::NotText => "isinya bukan teks UTF-8".into(),
            IoWhy::NotADirectory => "sebuah folder pada jalurnya adalah berkas".into(),
            IoWhy::ReadOnly => "sistem berkas hanya bisa dibaca".into(),
            IoWhy::Full => "ruang penyimpanan sudah penuh".into(),
            IoWhy::TooLarge => "berkas terlalu besar untuk sistem berkas".into(),
            IoWhy::BadName => "sistem berkas tidak menerima nama itu".into(),
            // The system's own words (often English): quoted as such.
            IoWhy::Other(s) => format!("pesan sistem: {s}"),
        }
    }

    fn needs(&self, thing: &Thing, key: &str) -> String {
        match thing {
            Thing::Light(kind) => format!("sumber cahaya {kind} memerlukan `{key}`"),
            Thing::Object(t) => format!("objek {t} memerlukan `{key}`"),
        }
    }

    fn channel(&self, c: Channel) -> &'static str {
        match c {
            Channel::Red => "merah",
            Channel::Green => "hijau",
            Channel::Blue => "biru",
        }
    }

    fn obj_why(&self, w: ObjWhy) -> &'static str {
        match w {
            ObjWhy::OpenFileFailed => "berkas tidak dapat dibuka",
            ObjWhy::ReadError => "berkas tidak dapat dibaca",
            ObjWhy::UnrecognizedCharacter => "ada karakter yang tidak dikenal",
            ObjWhy::PositionParse => "posisi verteks tidak dapat dibaca",
            ObjWhy::ScalingByZero => "koordinat w sebuah verteks bernilai nol",
            ObjWhy::ColorParse => {
                "warna verteks tidak dapat dibaca (komponennya terlalu banyak atau terlalu sedikit)"
            }
            ObjWhy::NormalParse => "normal verteks tidak dapat dibaca",
            ObjWhy::TexcoordParse => "koordinat tekstur tidak dapat dibaca",
            ObjWhy::FaceParse => "sebuah bidang (face) tidak dapat dibaca",
            ObjWhy::MaterialParse => "material tidak dapat dibaca",
            ObjWhy::InvalidObjectName => "nama objek tidak sah",
            ObjWhy::InvalidPolygon => "sebuah poligon tidak sah",
            ObjWhy::FaceVertexOutOfBounds => "sebuah bidang merujuk ke verteks yang tidak ada",
            ObjWhy::FaceTexCoordOutOfBounds => {
                "sebuah bidang merujuk ke koordinat tekstur yang tidak ada"
            }
            ObjWhy::FaceNormalOutOfBounds => "sebuah bidang merujuk ke normal yang tidak ada",
            ObjWhy::FaceColorOutOfBounds => "sebuah bidang merujuk ke warna verteks yang tidak ada",
            ObjWhy::LoadOptions => "opsi pembacaan saling meniadakan",
            ObjWhy::Generic => "kegagalan umum",
        }
    }

    /// Built from the argument, the value and the possible values clap
    /// names; a refusal of another kind quotes clap's line.
    fn clap(&self, e: &ClapErr, line: &str) -> String {
        let said = match e {
            ClapErr::InvalidValue(v, all) if all.is_empty() => format!("nilai '{v}' tidak sah"),
            ClapErr::InvalidValue(v, all) => {
                format!("nilai '{v}' tidak sah; nilai yang mungkin: {all}")
            }
            ClapErr::BadValue(v, why) => {
                format!(
                    "nilai '{v}' tidak sah: {}",
                    self.value_why(&errors::value_why(why))
                )
            }
            ClapErr::Unknown(a, Some(s)) => {
                format!("argumen '{a}' tidak dikenal; mungkin maksudnya '{s}'")
            }
            ClapErr::Unknown(a, None) => format!("argumen '{a}' tidak dikenal"),
            ClapErr::UnknownCommand(c, Some(s)) => {
                format!("subperintah '{c}' tidak dikenal; mungkin maksudnya '{s}'")
            }
            ClapErr::UnknownCommand(c, None) => format!("subperintah '{c}' tidak dikenal"),
            ClapErr::Conflict(a, b) => format!("argumen '{a}' tidak dapat dipakai bersama '{b}'"),
            ClapErr::Missing(a) => format!("argumen wajib belum diberikan: {a}"),
            ClapErr::NoValue => "argumen ini memerlukan nilai, tetapi tidak diberikan".to_string(),
            ClapErr::ValueCount(a) => format!("banyaknya nilai untuk '{a}' tidak sesuai"),
            ClapErr::Other => format!("baris perintah tidak diterima: {line}"),
        };
        format!("{said} (lihat --help)")
    }

    fn value_why(&self, w: &ValueWhy) -> String {
        match w {
            ValueWhy::Parse(p) => self.parse_why(*p).to_string(),
            ValueWhy::NotInRange(v, range) => format!("{v} tidak berada dalam rentang {range}"),
            ValueWhy::AsWritten(s) => s.clone(),
        }
    }

    fn parse_why(&self, w: ParseWhy) -> &'static str {
        match w {
            ParseWhy::InvalidDigit => "bukan bilangan bulat",
            ParseWhy::Empty => "kosong",
            ParseWhy::TooLarge => "bilangan terlalu besar",
            ParseWhy::TooSmall => "bilangan terlalu kecil",
            ParseWhy::InvalidFloat => "bukan bilangan",
        }
    }

    /// "expected nothing" (the line should have ended) is left unsaid.
    fn syntax(&self, s: &Syntax) -> String {
        let what = s.what.words(|w| self.syntax_what(w));
        match &s.expected {
            None | Some(Expected::Nothing) => what.to_string(),
            Some(Expected::OneOf(items)) => format!(
                "{what}, seharusnya {}",
                errors::one_of(items, |w| self.expect_word(w))
            ),
        }
    }

    fn syntax_what(&self, w: SyntaxWhat) -> &'static str {
        use SyntaxWhat::*;
        match w {
            InvalidFloat => "bilangan desimal tidak sah",
            InvalidNumber => "bilangan tidak sah",
            InvalidInteger => "bilangan bulat tidak sah",
            InvalidString => "string tidak sah",
            InvalidBoolean => "boolean tidak sah",
            InvalidDateTime => "tanggal-waktu tidak sah",
            InvalidKey => "kunci tidak sah",
            InvalidTable => "tabel tidak sah",
            InvalidValue => "nilai tidak sah",
            InvalidInlineTableElement => "elemen tabel inline tidak sah",
            InvalidKeyValuePair => "pasangan kunci-nilai tidak sah",
            InvalidBasicString => "string tidak sah",
            InvalidMultiLineBasicString => "string multi-baris tidak sah",
            InvalidCommentCharacter => "karakter komentar tidak sah",
            InvalidUnquotedKey => "kunci tanpa tanda kutip tidak sah",
            KeyWithNoValue => "kunci tanpa nilai",
            MissingValueForKey => "nilai untuk kunci tidak ada",
            MissingValue => "nilai tidak ada",
            MissingAssignment => "tanda `=` tidak ada di antara kunci dan nilai",
            MissingCommaInArray => "koma tidak ada di antara elemen array",
            MissingCommaBetweenPairs => "koma tidak ada di antara pasangan kunci-nilai",
            MissingOpeningQuote => "tanda kutip pembuka tidak ada",
            MissingTableOpen => "pembuka tabel `[` tidak ada",
            MissingArrayOpening => "pembuka array `[` tidak ada",
            MissingInlineTableOpening => "pembuka tabel inline `{` tidak ada",
            MissingInlineTableKey => "kunci elemen tabel inline tidak ada",
            MissingEscapedValue => "nilai escape tidak ada",
            ExtraEquals => "`=` berlebih",
            ExtraCommaInArray => "koma berlebih dalam array",
            ExtraCommaInInlineTable => "koma berlebih dalam tabel inline",
            ExtraAssignment => "`=` berlebih di antara pasangan kunci-nilai",
            StringsMustBeQuoted => "nilai string harus diberi tanda kutip",
            UnclosedArray => "array tidak ditutup",
            UnclosedArrayTable => "tabel array tidak ditutup",
            UnclosedInlineTable => "tabel inline tidak ditutup",
            UnclosedTable => "tabel tidak ditutup",
            UnexpectedContent => "isi yang tidak diharapkan",
            UnexpectedBeforeNewline => "isi yang tidak diharapkan sebelum akhir baris",
            UnexpectedKeyOrValue => "kunci atau nilai yang tidak diharapkan",
            UnexpectedLeadingZero => "nol di depan yang tidak diharapkan",
            UnexpectedSign => "tanda yang tidak diharapkan",
            UnexpectedEqualsInArray => "`=` yang tidak diharapkan dalam array",
            UnderscoreBetweenDigits => "`_` hanya boleh di antara angka",
            EmptyUnquotedKey => "kunci tanpa tanda kutip tidak boleh kosong",
            RedundantSign => "tanda bilangan berlebih",
            DuplicateKey => "kunci ganda",
            TooDeep => "bersarang terlalu dalam",
            CarriageReturn => "carriage return harus diikuti akhir baris",
            SignedRadix => "bilangan bulat berbasis (0x, 0o, 0b) tidak boleh bertanda",
            MultiLineBasicKey => "kunci tidak boleh berupa string multi-baris",
            MultiLineLiteralKey => "kunci tidak boleh berupa string literal multi-baris",
            MissingCommentStart => "awal komentar `#` tidak ada",
            RadixLowercase => "awalan basis harus huruf kecil (0x, 0o, 0b)",
            RedundantPrefix => "awalan bilangan bulat berlebih",
            FewUnicodeDigits => "digit nilai unicode terlalu sedikit",
            IntegerOverflow => "bilangan bulat terlalu besar",
            InvalidBinary => "bilangan biner tidak sah",
            InvalidOctal => "bilangan oktal tidak sah",
            InvalidHex => "bilangan heksadesimal tidak sah",
            InvalidMantissa => "mantisa tidak sah",
            InvalidFraction => "bagian pecahan tidak sah",
            InvalidExponent => "eksponen tidak sah",
            InvalidLiteralString => "string literal tidak sah",
            InvalidMultiLineLiteralString => "string literal multi-baris tidak sah",
            InvalidDatetime => "tanggal-waktu tidak sah",
            WantedStringOrTable => "seharusnya string atau tabel",
        }
    }

    fn expect_word(&self, w: ExpectWord) -> &'static str {
        match w {
            ExpectWord::Digits => "angka",
            ExpectWord::Letters => "huruf",
            ExpectWord::Numbers => "bilangan",
            ExpectWord::Value => "nilai",
            ExpectWord::Key => "kunci",
            ExpectWord::Characters => "karakter",
            ExpectWord::PrintableCharacters => "karakter yang dapat dicetak",
            ExpectWord::BasicString => "string",
            ExpectWord::LiteralString => "string literal",
            ExpectWord::MultiLineBasicString => "string multi-baris",
            ExpectWord::UnicodeHex => "nilai heksadesimal unicode",
            ExpectWord::NonDoubleQuoteVisible => "karakter terlihat selain tanda kutip ganda",
            ExpectWord::NonSingleQuote => "karakter selain tanda kutip tunggal",
            ExpectWord::NonSingleQuoteVisible => "karakter terlihat selain tanda kutip tunggal",
            ExpectWord::Newline => "akhir baris",
        }
    }

    fn serde_word(&self, w: SerdeWord) -> &'static str {
        match w {
            SerdeWord::NumberOrExpression => {
                "bilangan atau string berisi ekspresi bilangan seperti"
            }
            SerdeWord::Vector => "sebuah vektor: array [x, y, z] atau string",
            SerdeWord::ArrayOfLength => "array dengan panjang",
            SerdeWord::ASequence => "array",
            SerdeWord::Sequence => "array",
            SerdeWord::AString => "string",
            SerdeWord::String => "string",
            SerdeWord::Integer => "bilangan bulat",
            SerdeWord::FloatingPoint => "bilangan desimal",
            SerdeWord::Boolean => "boolean",
            SerdeWord::AMap => "tabel",
            SerdeWord::Map => "tabel",
            SerdeWord::ElementsInSequence => "elemen dalam array",
            SerdeWord::ANumber => "bilangan",
            SerdeWord::AnInteger => "bilangan bulat",
            SerdeWord::ABoolean => "boolean",
            SerdeWord::UnitVariant => "nilai tanpa data",
            SerdeWord::Elements => "elemen",
            SerdeWord::U8 => "bilangan bulat dari 0 sampai 255",
            SerdeWord::U16 => "bilangan bulat dari 0 sampai 65535",
            SerdeWord::U32 => "bilangan bulat dari 0 sampai 4294967295",
            SerdeWord::U64 | SerdeWord::Usize => "bilangan bulat ≥ 0",
            SerdeWord::I32 | SerdeWord::I64 => "bilangan bulat",
            SerdeWord::F32 | SerdeWord::F64 => "bilangan",
        }
    }
}

/// Apa yang dinamai sebuah jalur yang bukan berkas biasa.
fn file_kind(k: FileKind) -> &'static str {
    match k {
        FileKind::Fifo => "FIFO (pipa bernama)",
        FileKind::Socket => "soket",
        FileKind::CharDevice => "perangkat karakter",
        FileKind::BlockDevice => "perangkat blok (disk)",
        FileKind::Folder => "folder",
        FileKind::Other => "bukan berkas yang dibaca atau ditulis grafika",
    }
}

/// Mengapa sebuah `.grafika-generated` bukan daftar milik generate.
fn list_why(w: &ListWhy) -> String {
    match w {
        ListWhy::NotAFile => "ia bukan berkas biasa".into(),
        ListWhy::Heading => "baris pertamanya bukan yang ditulis generate".into(),
        ListWhy::Line(n) => format!("baris {n} bukan SHA-256 dan nama berkas"),
        ListWhy::Name(n, name) => {
            format!("baris {n} menyebut {name}, yang tidak pernah ditulis generate")
        }
        ListWhy::Owner => "ia milik pengguna lain".into(),
        ListWhy::TooLarge => "ia lebih besar dari daftar mana pun yang ditulis generate".into(),
    }
}
