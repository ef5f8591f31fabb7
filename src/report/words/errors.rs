//! The words of every error key (`crate::msg::ErrMsg`), in English and in
//! Bahasa Indonesia. Field names, keys, flags and paths are printed as they
//! are spelled; numbers in Indonesian take the decimal comma. One exhaustive
//! match per key enum (`ErrMsg`, `NumErr`, `TomlErr`, …), none with a
//! wildcard arm: the compiler checks that every key has its words.

use super::nums;
use crate::msg::{Bound, ClapErr, ErrMsg, IoWhy, NumErr, Thing, TomlErr, Twice, Want};
use crate::report::lang::Lang;

/// The words of the error keys ([`ErrMsg`] and its families).
pub trait ErrorWords {}

/// English or Indonesian, both written.
fn pick(lang: Lang, en: String, id: String) -> String {
    if lang == Lang::Id {
        id
    } else {
        en
    }
}

/// Plain words, both written.
fn say(lang: Lang, en: &str, id: &str) -> String {
    if lang == Lang::Id { id } else { en }.to_string()
}

/// The words of an error key: one exhaustive match over every key (no
/// wildcard arm), so a key without its words does not compile. A word
/// table: long on purpose.
pub fn error(m: &ErrMsg, lang: Lang) -> String {
    let f = |en: String, id: String| pick(lang, en, id);
    let w = |why: &IoWhy| io_why(why, lang);
    let n = |s: &str| nums(s, lang);
    match m {
        ErrMsg::Num(e) => number(e, lang),
        ErrMsg::Toml(e) => toml(e, lang),
        ErrMsg::Clap(e, en) => clap(e, en, lang),
        ErrMsg::MustBe(b, got) => must_be(b, got, lang),
        ErrMsg::Twice(t) => twice(*t, lang),
        ErrMsg::CannotRead(p, why) => f(
            format!("cannot read {p}: {}", w(why)),
            format!("tidak dapat membaca {p}: {}", w(why)),
        ),
        ErrMsg::CannotReadStdin(why) => f(
            format!("cannot read standard input: {}", w(why)),
            format!("tidak dapat membaca masukan standar: {}", w(why)),
        ),
        ErrMsg::CannotWrite(p, why) => f(
            format!("cannot write {p}: {}", w(why)),
            format!("tidak dapat menulis {p}: {}", w(why)),
        ),
        ErrMsg::CannotCreate(p, why) => f(
            format!("cannot create {p}: {}", w(why)),
            format!("tidak dapat membuat {p}: {}", w(why)),
        ),
        ErrMsg::CannotWriteStdout(why) => f(
            format!("cannot write to standard output: {}", w(why)),
            format!("tidak dapat menulis ke keluaran standar: {}", w(why)),
        ),
        ErrMsg::StdoutClosed => f(
            "standard output is closed, so the results would be lost (to discard them, send them to /dev/null)".into(),
            "keluaran standar tertutup, jadi hasilnya akan hilang (untuk membuangnya, arahkan ke /dev/null)".into(),
        ),
        ErrMsg::ExistsForce(p) => f(
            format!("{p} already exists: give --force to replace it, or choose another name"),
            format!("{p} sudah ada: berikan --force untuk menggantinya, atau pilih nama lain"),
        ),
        ErrMsg::NamesFolder(p) => f(
            format!("{p} is a folder, not a file name: name the file to write (such as {}figure.svg)", folder_prefix(p)),
            format!("{p} adalah folder, bukan nama berkas: sebutkan berkas yang akan ditulis (misalnya {}gambar.svg)", folder_prefix(p)),
        ),
        ErrMsg::IsLink(p) => f(
            format!("{p} is a symbolic link: grafika never writes through a link nor replaces one; name the file itself or another name"),
            format!("{p} adalah tautan simbolik: grafika tidak pernah menulis melalui tautan atau menggantinya; sebutkan berkasnya sendiri atau nama lain"),
        ),
        ErrMsg::IsInput(p) => f(
            format!("{p} is one of this command's own inputs (the same file, links followed): it is never overwritten, even with --force"),
            format!("{p} adalah salah satu masukan perintah ini (berkas yang sama, tautan diikuti): tidak pernah ditimpa, juga dengan --force"),
        ),
        ErrMsg::NotOwn(p, marker) => f(
            format!("{p} was not written by grafika generate (it is not listed in {marker}, or holds other files): --force replaces only generate's own earlier output; move it away or choose another --out"),
            format!("{p} tidak ditulis oleh grafika generate (tidak tercantum di {marker}, atau berisi berkas lain): --force hanya mengganti keluaran generate sendiri sebelumnya; pindahkan atau pilih --out yang lain"),
        ),
        ErrMsg::NotDirectory(p) => f(
            format!("{p} exists and is not a directory"),
            format!("{p} sudah ada dan bukan direktori"),
        ),
        ErrMsg::AnswerFileTooLarge(p, n, max) => f(
            format!("{p} has {n} bytes; an answer file may have at most {max} (it is refused before it is read as TOML)"),
            format!("{p} berukuran {n} bita; berkas jawaban paling besar {max} bita (ditolak sebelum dibaca sebagai TOML)"),
        ),
        ErrMsg::NotMarked(n, of, which) => f(
            format!("{n} of the {of} answer files could not be marked (see the error in each one's row): {which}"),
            format!("{n} dari {of} berkas jawaban tidak dapat dinilai (lihat galat di baris masing-masing): {which}"),
        ),
        ErrMsg::Man(why) => f(
            format!("cannot write the manual page: {why}"),
            format!("tidak dapat menulis halaman manual: {why}"),
        ),
        ErrMsg::ObjUnreadable(p, why) => f(
            format!("cannot read the OBJ file {p}: {}", w(why)),
            format!("tidak dapat membaca berkas OBJ {p}: {}", w(why)),
        ),
        ErrMsg::ObjInvalid(p, kind, en) => f(
            format!("{p} is not a valid OBJ file: {en}"),
            format!("{p} bukan berkas OBJ yang sah: {}", obj_reason(kind, en)),
        ),
        ErrMsg::ObjNoFaces(p) => f(format!("{p} has no faces"), format!("{p} tidak memiliki bidang (face)")),
        ErrMsg::ObjNotFinite(p) => f(
            format!("{p} has a vertex that is not a finite number"),
            format!("{p} memiliki verteks yang bukan bilangan berhingga"),
        ),
        ErrMsg::FaceVertex => say(
            lang,
            "a face refers to a vertex that does not exist",
            "sebuah bidang (face) merujuk ke verteks yang tidak ada",
        ),
        ErrMsg::FormulaNotFinite => say(
            lang,
            "the formula gives a value that is not a finite number",
            "rumus menghasilkan nilai yang bukan bilangan berhingga",
        ),
        ErrMsg::TooManyTriangles(n, max) => f(
            format!("the scene's objects have {n} triangles together; the renderer takes at most {max} per scene (refused before any mesh is built)"),
            format!("objek-objek scene ini bersama-sama memiliki {n} segitiga; renderer menerima paling banyak {max} per scene (ditolak sebelum mesh dibuat)"),
        ),
        ErrMsg::TooManyLights(n, max) => f(
            format!("the file has {n} lights; grafika takes at most {max} per file (as Direct3D 9 does)"),
            format!("file ini memiliki {n} cahaya; grafika menerima paling banyak {max} per file (seperti Direct3D 9)"),
        ),
        ErrMsg::NeedsColour => say(lang, "needs at least one colour", "memerlukan paling sedikit satu warna"),
        ErrMsg::NoObjects => say(
            lang,
            "the scene has no objects: add at least one [[object]] table (cone, sphere, cylinder, box, plane or obj)",
            "scene tidak memiliki objek: tambahkan paling sedikit satu tabel [[object]] (cone, sphere, cylinder, box, plane atau obj)",
        ),
        ErrMsg::CameraNeedsPerspective => say(
            lang,
            "a [camera] needs a [perspective] with fovy, near and far",
            "[camera] memerlukan [perspective] dengan fovy, near dan far",
        ),
        ErrMsg::ImageSize(w, h) => f(
            format!("width and height must be from 1 to 8192 pixels, got {w}x{h}"),
            format!("lebar dan tinggi harus 1 sampai 8192 piksel, diberikan {w}x{h}"),
        ),
        ErrMsg::Needs(thing, key) => needs(thing, key, lang),
        ErrMsg::NoSuchKey(t, k, all) => f(
            format!("a {t} has no `{k}` (its fields: {all})"),
            format!("objek {t} tidak memiliki `{k}` (kuncinya: {all})"),
        ),
        ErrMsg::NeededToRender => say(lang, "is needed to render", "diperlukan untuk me-render"),
        ErrMsg::NoLightTable(p) => f(
            format!("{p} has no [[light]] table"),
            format!("{p} tidak memiliki tabel [[light]]"),
        ),
        ErrMsg::ColorMissing => say(
            lang,
            "the surface color Cs is missing (R,G,B in [0, 1])",
            "warna permukaan Cs tidak ada (R,G,B di [0, 1])",
        ),
        ErrMsg::NormalMissing => say(
            lang,
            "the surface normal N is missing",
            "normal permukaan N tidak ada",
        ),
        ErrMsg::CameraAtPoint => say(
            lang,
            "the camera is at the surface point: no direction to the viewer",
            "kamera berada di titik permukaan: tidak ada arah ke pengamat",
        ),
        ErrMsg::NoLight => say(
            lang,
            "no light: give L (toward the light) or a lights file",
            "tidak ada cahaya: berikan L (menuju sumber cahaya) atau berkas cahaya",
        ),
        ErrMsg::LightAtPoint => say(
            lang,
            "the light is at the surface point itself: no direction to it",
            "sumber cahaya berada di titik permukaan itu sendiri: tidak ada arah ke sana",
        ),
        ErrMsg::NotApplicable(k, kind) => f(
            format!("`{k}` does not apply to a {kind} light"),
            format!("`{k}` tidak berlaku untuk sumber cahaya {kind}"),
        ),
        ErrMsg::Channel(ch, v) => {
            let ind = match ch.as_str() {
                "red" => "merah",
                "green" => "hijau",
                _ => "biru",
            };
            f(
                format!("color channels must lie in [0, 1]; {ch} is {v}"),
                format!(
                    "kanal warna harus berada di [0, 1]; {ind} bernilai {}",
                    n(v)
                ),
            )
        }
        ErrMsg::Attenuation(a0, a1, a2) => f(
            format!("a0, a1, a2 must be ≥ 0 and not all 0, got ({a0}, {a1}, {a2})"),
            format!(
                "a0, a1, a2 harus ≥ 0 dan tidak semuanya 0, diberikan ({}; {}; {})",
                n(a0),
                n(a1),
                n(a2)
            ),
        ),
        ErrMsg::Cones(t, p) => f(
            format!("the cone angles need 0 ≤ theta ≤ phi ≤ 180°, got theta = {t}, phi = {p}"),
            format!(
                "sudut kerucut harus 0 ≤ theta ≤ phi ≤ 180°, diberikan theta = {}, phi = {}",
                n(t),
                n(p)
            ),
        ),
        ErrMsg::PlaneThroughOrigin => say(
            lang,
            "the view plane z = 0 passes through the centre of projection at the origin",
            "bidang proyeksi z = 0 melalui pusat proyeksi di titik asal",
        ),
        ErrMsg::PlaneThroughCop(z) => f(
            format!("the view plane z = {z} passes through the centre of projection"),
            format!("bidang proyeksi z = {} melalui pusat proyeksi", n(z)),
        ),
        ErrMsg::ImageTooLarge(p, prec) => f(
            format!("the image of {p} is too large for {prec} precision (the point is too near the plane of the centre of projection)"),
            format!("bayangan {p} terlalu besar untuk presisi {prec} (titik itu terlalu dekat dengan bidang pusat proyeksi)"),
        ),
        ErrMsg::Viewport(w, h) => f(
            format!("width and height must be positive, got {w}x{h}"),
            format!("lebar dan tinggi harus positif, diberikan {}x{}", n(w), n(h)),
        ),
        ErrMsg::VVanished => say(lang, "v = n × u vanished", "v = n × u menjadi nol"),
        ErrMsg::EyeLookTooLarge(d, prec) => f(
            format!("Pe − Pr = {d} is too large for {prec} precision"),
            format!("Peye − Pref = {} terlalu besar untuk presisi {prec}", n(d)),
        ),
        ErrMsg::TranslationTooLarge(prec) => f(
            format!("the view matrix's translation −(u·Pe, v·Pe, n·Pe) is too large for {prec} precision"),
            format!("translasi matriks pandang −(u·Pe; v·Pe; n·Pe) terlalu besar untuk presisi {prec}"),
        ),
        ErrMsg::EyeCoordsTooLarge(p, prec) => f(
            format!("the eye coordinates of {p} are too large for {prec} precision"),
            format!("koordinat kamera titik {p} terlalu besar untuk presisi {prec}"),
        ),
        ErrMsg::ResultNotFinite(prec) if prec == "exact" => f(
            "the result is exact but beyond the range of f64 (about 1.8e308), so it has no decimal or JSON number to give (scale the inputs)".into(),
            "hasilnya eksak tetapi di luar jangkauan f64 (sekitar 1,8e308), jadi tidak ada desimal atau bilangan JSON untuknya (skalakan masukan)".into(),
        ),
        ErrMsg::ResultNotFinite(prec) => f(
            format!("the result is not a finite number at {prec} precision: an input overflows or underflows the floats (scale the inputs, or use --precision exact)"),
            format!("hasilnya bukan bilangan berhingga pada presisi {prec}: sebuah masukan melampaui batas bilangan floating point (skalakan masukan, atau gunakan --precision exact)"),
        ),
        ErrMsg::UnknownPart(a, all) => f(
            format!("unknown part `{a}`; the parts are {all}"),
            format!("bagian `{a}` tidak dikenal; bagian-bagiannya adalah {all}"),
        ),
        ErrMsg::ExpectedXyz(e) => f(
            format!("expected [x, y, z]: {}", toml(e, lang)),
            format!("seharusnya [x, y, z]: {}", toml(e, lang)),
        ),
        ErrMsg::NothingToSolve => say(
            lang,
            "nothing to solve: the file has no part that its data allow (camera + points, perspective, clip, shade)",
            "tidak ada yang dapat diselesaikan: berkas ini tidak memiliki bagian yang datanya lengkap (camera + points, perspective, clip, shade)",
        ),
        ErrMsg::NoCameraTable => say(
            lang,
            "the problem asks for the view but has no [camera] table",
            "soal meminta transformasi pandang tetapi tidak memiliki tabel [camera]",
        ),
        ErrMsg::ProjectionNeedsNear => say(
            lang,
            "projection needs perspective.near (or perspective.d)",
            "proyeksi memerlukan perspective.near (atau perspective.d)",
        ),
        ErrMsg::WindowNeeds => say(
            lang,
            "the window needs perspective.fovy, perspective.aspect and perspective.near",
            "viewing window memerlukan perspective.fovy, perspective.aspect dan perspective.near",
        ),
        ErrMsg::LightsNeedShade => say(
            lang,
            "[[light]] tables need a [shade] table (normal, color, ...)",
            "tabel [[light]] memerlukan tabel [shade] (normal, color, ...)",
        ),
        ErrMsg::NoTopic => say(lang, "give at least one topic", "berikan paling sedikit satu topik"),
        ErrMsg::NoDrawing => say(
            lang,
            "could not draw a non-degenerate problem in 500 tries",
            "tidak dapat membuat soal yang tidak degenerate dalam 500 percobaan",
        ),
        ErrMsg::NoProblemDrawn => say(lang, "no problem drawn", "tidak ada soal yang dibuat"),
        ErrMsg::StdinHoldsAnswers => say(
            lang,
            "standard input holds the answers: give the problem as a file",
            "masukan standar berisi jawaban: berikan soal sebagai berkas",
        ),
        ErrMsg::GiveProblem => say(lang, "give a problem file or --topic", "berikan berkas soal atau --topic"),
        ErrMsg::TooManyProblems(n, c, v, mb, max) => f(
            format!("{n} problems ({c} × {v}, about {mb} MB) is more than the {max} written without --force"),
            format!("{n} soal ({c} × {v}, sekitar {mb} MB) lebih dari {max} yang ditulis tanpa --force"),
        ),
        ErrMsg::BothStdin => say(
            lang,
            "the problem and the answers cannot both come from standard input (-)",
            "soal dan jawaban tidak dapat sama-sama berasal dari masukan standar (-)",
        ),
        ErrMsg::NoPrinted(p) => f(format!("{p} has no [printed] table"), format!("{p} tidak memiliki tabel [printed]")),
        ErrMsg::CsvAndJson => say(
            lang,
            "--csv - and --json would both write to standard output: give --csv a file name",
            "--csv - dan --json sama-sama akan menulis ke keluaran standar: berikan nama berkas untuk --csv",
        ),
        ErrMsg::NoAnswerFiles(d) => f(
            format!("{d} holds no .toml answer files"),
            format!("{d} tidak berisi berkas jawaban .toml"),
        ),
        ErrMsg::NoExam(d) => f(
            format!("{d} holds no problem-01.toml (nor variant-01/): give a problem file or a folder written by grafika generate"),
            format!("{d} tidak berisi problem-01.toml (maupun variant-01/): berikan berkas soal atau folder yang ditulis grafika generate"),
        ),
        ErrMsg::NoVariant(n) => f(
            format!("the exam has {n} variants: say which one these answers are for with `variant = N` at the top of the file"),
            format!("ujian ini memiliki {n} varian: tuliskan varian mana yang dijawab dengan `variant = N` di awal berkas"),
        ),
        ErrMsg::NotAVariant(v, n) => f(
            format!("`{v}` is not a variant of the exam (1 to {n})"),
            format!("`{v}` bukan varian ujian ini (1 sampai {n})"),
        ),
        ErrMsg::NotAProblemOfExam(k, names) => f(
            format!("`{k}` is not in a table of a problem of the exam ([{names}])"),
            format!("`{k}` tidak berada di tabel soal ujian ini ([{names}])"),
        ),
        ErrMsg::ReportFormat(p) => f(
            format!("{p}: the report's format comes from its extension: .html, .md, .json or .csv"),
            format!("{p}: format laporan ditentukan oleh ekstensinya: .html, .md, .json atau .csv"),
        ),
        ErrMsg::ReportNeedsClass => say(
            lang,
            "a class report needs --answers DIR (a folder of answer files)",
            "laporan kelas memerlukan --answers DIR (folder berkas jawaban)",
        ),
        ErrMsg::PixelOutside(x, y, w, h) => f(
            format!("({x}, {y}) is outside the {w}x{h} image"),
            format!("({x}; {y}) berada di luar gambar {w}x{h}"),
        ),
        ErrMsg::PixelText(s) => f(
            format!("expected X,Y (whole pixel numbers), got `{s}`"),
            format!("seharusnya X,Y (nomor piksel bulat), diberikan `{s}`"),
        ),
        ErrMsg::NothingRendered => say(lang, "nothing rendered", "tidak ada yang di-render"),
        ErrMsg::Threads(why) => f(
            format!("cannot start the threads: {why}"),
            format!("tidak dapat memulai thread: {why}"),
        ),
        ErrMsg::RenderPrecision => say(
            lang,
            "render always computes at f32 (--precision is for the calculator's worked steps): leave it out",
            "render selalu menghitung dengan f32 (--precision untuk langkah-langkah kalkulator): hilangkan opsi itu",
        ),
        ErrMsg::NotTaken(c) => f(
            format!("grafika {c} does not take this option (grafika {c} --help lists those it takes)"),
            format!("grafika {c} tidak menerima opsi ini (grafika {c} --help mendaftar opsi yang diterimanya)"),
        ),
        ErrMsg::OwnOutput => say(
            lang,
            "check, generate, bench, practice, completions and man print their own output: use main_with_args",
            "check, generate, bench, practice, completions dan man mencetak keluarannya sendiri: gunakan main_with_args",
        ),
    }
}

/// Why a number (or a height formula) cannot be read or evaluated.
pub fn number(e: &NumErr, lang: Lang) -> String {
    let n = |s: &str| nums(s, lang);
    let f = |en: String, id: String| pick(lang, en, id);
    match e {
        NumErr::Quoted(t, why) => format!("`{t}`: {}", number(why, lang)),
        NumErr::TooLong(len, max) => f(
            format!("the number is {len} characters long, more than the {max} allowed"),
            format!("bilangan ini panjangnya {len} karakter, lebih dari {max} yang diizinkan"),
        ),
        NumErr::Empty => say(lang, "expected a number, found nothing", "seharusnya sebuah bilangan, tetapi tidak ada isinya"),
        NumErr::Expected(w, col, found) => {
            let (wen, wid) = match w {
                Want::OperatorOrEnd => ("an operator or the end of the number", "operator atau akhir bilangan"),
                Want::Close => ("`)`", "`)`"),
                Want::OpenAfterSqrt => ("`(` after sqrt", "`(` setelah sqrt"),
                Want::Number => ("a number", "sebuah bilangan"),
            };
            match found {
                Some(c) => f(
                    format!("expected {wen} at column {col}, found `{c}`"),
                    format!("seharusnya {wid} di kolom {col}, ditemukan `{c}`"),
                ),
                None => f(
                    format!("expected {wen} at column {col}, found the end"),
                    format!("seharusnya {wid} di kolom {col}, ditemukan akhir teks"),
                ),
            }
        }
        NumErr::TooDeep(max, col) => f(
            format!("the number is nested more than {max} levels deep (parentheses, roots or signs) at column {col}"),
            format!("bilangan ini bersarang lebih dari {max} tingkat (kurung, akar atau tanda) di kolom {col}"),
        ),
        NumErr::TooManyOps(max, col) => f(
            format!("the number has more than {max} operations (at column {col})"),
            format!("bilangan ini memiliki lebih dari {max} operasi (di kolom {col})"),
        ),
        NumErr::Count(k, t) => f(
            format!("expected three numbers x,y,z separated by commas, found {k} in `{t}`"),
            format!("seharusnya tiga bilangan x,y,z dipisahkan koma, ditemukan {k} dalam `{t}`"),
        ),
        NumErr::Component(k, t, why) => {
            let c = ["x", "y", "z"][*k % 3];
            f(
                format!("{c} component `{t}`: {}", number(why, lang)),
                format!("komponen {c} `{t}`: {}", number(why, lang)),
            )
        }
        NumErr::NotFinite(x, p) => f(
            format!("`{x}` is not a finite number at {p} precision"),
            format!("`{x}` bukan bilangan berhingga pada presisi {p}"),
        ),
        NumErr::NotANumber(x) => f(format!("`{x}` is not a number"), format!("`{x}` bukan bilangan")),
        NumErr::NotFiniteLiteral(x) => f(format!("{x} is not a finite number"), format!("{} bukan bilangan berhingga", n(x))),
        NumErr::NegativeRoot(x) => f(
            format!("sqrt({x}) takes the square root of a negative number"),
            format!("sqrt({x}) mengambil akar kuadrat dari bilangan negatif"),
        ),
        NumErr::DivZero(x) => f(format!("`{x}` divides by zero"), format!("`{x}` membagi dengan nol")),
        NumErr::Exponent(x) => f(
            format!("the exponent in `{x}` must be a whole number from -1024 to 1024"),
            format!("pangkat dalam `{x}` harus bilangan bulat dari -1024 sampai 1024"),
        ),
        NumErr::PowerRange(x) => f(
            format!("`{x}` is too large or too small a power"),
            format!("`{x}` adalah perpangkatan yang terlalu besar atau terlalu kecil"),
        ),
        NumErr::Unexpected(c, at) => f(
            format!("unexpected `{c}` at character {at}"),
            format!("`{c}` tidak diharapkan di karakter ke-{at}"),
        ),
        NumErr::OpenAfter(name) => f(format!("expected `(` after {name}"), format!("seharusnya `(` setelah {name}")),
        NumErr::UnknownName(name) => f(
            format!("unknown name `{name}` (the formula may use x, z, pi, exp, sqrt, sin, cos, abs)"),
            format!("nama `{name}` tidak dikenal (rumus boleh memakai x, z, pi, exp, sqrt, sin, cos, abs)"),
        ),
        NumErr::EndsEarly => say(lang, "the formula ends too early", "rumus berakhir terlalu cepat"),
        NumErr::FormulaDeep(max, at) => f(
            format!("the formula is nested more than {max} levels deep (parentheses, signs or powers) at character {at}"),
            format!("rumus bersarang lebih dari {max} tingkat (kurung, tanda atau pangkat) di karakter ke-{at}"),
        ),
        NumErr::FormulaOps(max, at) => f(
            format!("the formula has more than {max} operations (at character {at})"),
            format!("rumus memiliki lebih dari {max} operasi (di karakter ke-{at})"),
        ),

    }
}

/// "must be …, got X".
fn must_be(b: &Bound, got: &str, lang: Lang) -> String {
    let n = |s: &str| nums(s, lang);
    let (en, id) = match b {
        Bound::NumberAtLeastZero => (
            "must be a number ≥ 0".to_string(),
            "harus bilangan ≥ 0".to_string(),
        ),
        Bound::AtLeastZero => ("must be ≥ 0".into(), "harus ≥ 0".into()),
        Bound::AboveZero => ("must be > 0".into(), "harus > 0".into()),
        Bound::Positive => ("must be positive".into(), "harus positif".into()),
        Bound::NotNegative => ("must not be negative".into(), "tidak boleh negatif".into()),
        Bound::FiniteAtLeastZero => (
            "must be a finite number ≥ 0".into(),
            "harus bilangan berhingga ≥ 0".into(),
        ),
        Bound::Fraction => (
            "must be a number above 0 and below 1 (0.001 is 0.1%)".into(),
            "harus bilangan di atas 0 dan di bawah 1 (0,001 adalah 0,1%)".into(),
        ),
        Bound::WholePixels => (
            "must be a whole number of pixels".into(),
            "harus bilangan bulat piksel".into(),
        ),
        Bound::AboveNear(near) => (
            format!("must be greater than near = {near}"),
            format!("harus lebih besar daripada near = {}", n(near)),
        ),
    };
    pick(
        lang,
        format!("{en}, got {got}"),
        format!("{id}, diberikan {}", n(got)),
    )
}

/// Something given twice.
fn twice(t: Twice, lang: Lang) -> String {
    let (en, id) = match t {
        Twice::GlobalAmbient => (
            "give the global ambient once, not both in the lights file and here",
            "berikan ambient global sekali saja, tidak di berkas cahaya dan di sini sekaligus",
        ),
        Twice::Material => (
            "give the material once, not both in the lights file and here",
            "berikan material sekali saja, tidak di berkas cahaya dan di sini sekaligus",
        ),
        Twice::Color => (
            "give the surface color once: color or material.diffuse",
            "berikan warna permukaan sekali saja: color atau material.diffuse",
        ),
        Twice::Shininess => (
            "give the exponent once: shininess or material.power",
            "berikan eksponen sekali saja: shininess atau material.power",
        ),
        Twice::View => (
            "give V or the camera position (local viewer), not both",
            "berikan V atau posisi kamera (pengamat lokal), tidak keduanya",
        ),
        Twice::Light => (
            "give one light vector L or [[light]] tables, not both",
            "berikan satu vektor cahaya L atau tabel [[light]], tidak keduanya",
        ),
        Twice::Axis => (
            "give the spot light's axis once: axis (or its old name, direction)",
            "berikan sumbu sumber cahaya spot sekali saja: axis (atau nama lamanya, direction)",
        ),
        Twice::TiltCamera => (
            "give either [tilt] or [camera], not both",
            "berikan [tilt] atau [camera], tidak keduanya",
        ),
        Twice::Colors => (
            "give only one of color, face_colors, vertex_colors",
            "berikan hanya satu dari color, face_colors, vertex_colors",
        ),
        Twice::Answers => (
            "give either --answers FILE|DIR or --answers-from-text",
            "berikan --answers BERKAS|DIREKTORI atau --answers-from-text, salah satu saja",
        ),
    };
    say(lang, en, id)
}

/// The system's reason a file could not be read or written.
pub fn io_why(w: &IoWhy, lang: Lang) -> String {
    match w {
        IoWhy::NotFound => say(
            lang,
            "no such file or directory",
            "berkas atau direktori tidak ada",
        ),
        IoWhy::Denied => say(lang, "permission denied", "izin ditolak"),
        IoWhy::Exists => say(lang, "it already exists", "sudah ada"),
        IoWhy::IsDirectory => say(lang, "it is a directory", "itu sebuah direktori"),
        IoWhy::NotText => say(lang, "it is not UTF-8 text", "isinya bukan teks UTF-8"),
        IoWhy::Other(s) => s.clone(),
    }
}

/// `dir/` for a path that is a folder (`dir/` itself when it ends in `/`),
/// so that the example is a file name inside it.
fn folder_prefix(p: &str) -> String {
    if p.ends_with('/') {
        p.to_string()
    } else {
        format!("{p}/")
    }
}

/// The OBJ reader's reason, by its name; else its own (English) words.
fn obj_reason(kind: &str, en: &str) -> String {
    let id = match kind {
        "PositionParseError" => "posisi verteks tidak dapat dibaca",
        "NormalParseError" => "normal verteks tidak dapat dibaca",
        "TexcoordParseError" => "koordinat tekstur tidak dapat dibaca",
        "FaceParseError" => "sebuah bidang (face) tidak dapat dibaca",
        "InvalidPolygon" => "sebuah poligon tidak sah",
        "FaceVertexOutOfBounds" => "sebuah bidang merujuk ke verteks yang tidak ada",
        "FaceNormalOutOfBounds" => "sebuah bidang merujuk ke normal yang tidak ada",
        "FaceTexCoordOutOfBounds" => "sebuah bidang merujuk ke koordinat tekstur yang tidak ada",
        "UnrecognizedCharacter" => "ada karakter yang tidak dikenal",
        "ReadError" => "berkas tidak dapat dibaca",
        _ => return en.to_string(),
    };
    id.to_string()
}

/// "a spot light needs `axis`", "a sphere needs `r`", "an obj object needs `path`".
fn needs(thing: &Thing, key: &str, lang: Lang) -> String {
    match (thing, lang) {
        (Thing::Light(kind), Lang::En) => format!("a {kind} light needs `{key}`"),
        (Thing::Light(kind), Lang::Id) => format!("sumber cahaya {kind} memerlukan `{key}`"),
        (Thing::Object(t), Lang::En) if t == "obj" => format!("an obj object needs `{key}`"),
        (Thing::Object(t), Lang::En) => format!("a {t} needs `{key}`"),
        (Thing::Object(t), Lang::Id) => format!("objek {t} memerlukan `{key}`"),
    }
}

/// A TOML file's error.
pub fn toml(e: &TomlErr, lang: Lang) -> String {
    let f = |en: String, id: String| pick(lang, en, id);
    match e {
        TomlErr::UnknownField(k, Some(all)) => f(
            format!("unknown field `{k}`, expected one of {all}"),
            format!("kunci `{k}` tidak dikenal, seharusnya salah satu dari {all}"),
        ),
        TomlErr::UnknownField(k, None) => f(
            format!("unknown field `{k}`"),
            format!("kunci `{k}` tidak dikenal"),
        ),
        TomlErr::MissingField(k) => f(
            format!("missing field `{k}`"),
            format!("kunci `{k}` belum diberikan"),
        ),
        TomlErr::Duplicate(k) => f(
            format!("duplicate key `{k}`"),
            format!("kunci `{k}` diberikan dua kali"),
        ),
        TomlErr::UnknownVariant(v, all) => f(
            format!("unknown variant `{v}`, expected one of {all}"),
            format!("nilai `{v}` tidak dikenal, seharusnya salah satu dari {all}"),
        ),
        TomlErr::InvalidType(found, want) => f(
            format!("invalid type: {found}, expected {want}"),
            format!(
                "jenis nilai salah: {}, seharusnya {}",
                serde_words(found),
                serde_words(want)
            ),
        ),
        TomlErr::InvalidLength(found, want) => f(
            format!("invalid length {found}, expected {want}"),
            format!(
                "panjang salah: {}, seharusnya {}",
                serde_words(found),
                serde_words(want)
            ),
        ),
        TomlErr::Num(n) => number(n, lang),
        TomlErr::MustBe(b, got) => must_be(b, got, lang),
        TomlErr::WholeRange(lo, hi, got) => f(
            format!("must be a whole number from {lo} to {hi}, got {got}"),
            format!(
                "harus bilangan bulat dari {lo} sampai {hi}, diberikan {}",
                nums(got, lang)
            ),
        ),
        TomlErr::Colour(c) => f(
            format!("colour components must be from 0 to 1, got {c}"),
            format!(
                "komponen warna harus dari 0 sampai 1, diberikan {}",
                nums(c, lang)
            ),
        ),
        TomlErr::Syntax(s) => f(
            s.clone(),
            format!("sintaks TOML tidak sah: {}", syntax_words(s)),
        ),
    }
}

/// serde's names of kinds of values, in Indonesian.
fn serde_words(s: &str) -> String {
    let names = [
        (
            "a number or a string with a number expression such as",
            "bilangan atau string berisi ekspresi bilangan seperti",
        ),
        (
            "a vector: an array [x, y, z] or a string",
            "sebuah vektor: array [x, y, z] atau string",
        ),
        ("an array of length", "array dengan panjang"),
        ("a sequence", "array"),
        ("sequence", "array"),
        ("a string", "string"),
        ("string", "string"),
        ("integer", "bilangan bulat"),
        ("floating point", "bilangan desimal"),
        ("boolean", "boolean"),
        ("a map", "tabel"),
        ("map", "tabel"),
        ("elements in sequence", "elemen dalam array"),
        ("a number", "bilangan"),
        ("an integer", "bilangan bulat"),
        ("a boolean", "boolean"),
        ("unit variant", "nilai tanpa data"),
        ("elements", "elemen"),
    ];
    // Longer phrases first, so `an integer` is not read as `an` + `integer`.
    let mut names = names.to_vec();
    names.sort_by_key(|(en, _)| std::cmp::Reverse(en.len()));
    names
        .iter()
        .fold(s.to_string(), |t, (en, id)| t.replace(en, id))
}

/// The TOML reader's descriptions of syntax errors, in Indonesian.
const SYNTAX: [(&str, &str); 47] = [
    ("invalid float", "bilangan desimal tidak sah"),
    ("invalid number", "bilangan tidak sah"),
    ("invalid integer number", "bilangan bulat tidak sah"),
    ("invalid string", "string tidak sah"),
    ("invalid boolean", "boolean tidak sah"),
    ("invalid date-time", "tanggal-waktu tidak sah"),
    ("invalid key", "kunci tidak sah"),
    ("invalid table", "tabel tidak sah"),
    ("invalid value", "nilai tidak sah"),
    (
        "invalid inline table element",
        "elemen tabel inline tidak sah",
    ),
    ("invalid key-value pair", "pasangan kunci-nilai tidak sah"),
    ("invalid basic string", "string tidak sah"),
    (
        "invalid multi-line basic string",
        "string multi-baris tidak sah",
    ),
    ("invalid comment character", "karakter komentar tidak sah"),
    ("invalid unquoted key", "kunci tanpa tanda kutip tidak sah"),
    ("key with no value", "kunci tanpa nilai"),
    ("missing value for key", "nilai untuk kunci tidak ada"),
    ("missing value", "nilai tidak ada"),
    (
        "missing assignment between key-value pairs",
        "tanda `=` tidak ada di antara kunci dan nilai",
    ),
    (
        "missing comma between array elements",
        "koma tidak ada di antara elemen array",
    ),
    (
        "missing comma between key-value pairs",
        "koma tidak ada di antara pasangan kunci-nilai",
    ),
    ("missing opening quote", "tanda kutip pembuka tidak ada"),
    ("missing table open", "pembuka tabel `[` tidak ada"),
    ("missing array opening", "pembuka array `[` tidak ada"),
    (
        "missing inline table opening",
        "pembuka tabel inline `{` tidak ada",
    ),
    (
        "missing key for inline table element",
        "kunci elemen tabel inline tidak ada",
    ),
    ("missing escaped value", "nilai escape tidak ada"),
    ("extra `=`", "`=` berlebih"),
    ("extra comma in array", "koma berlebih dalam array"),
    (
        "extra comma in inline table",
        "koma berlebih dalam tabel inline",
    ),
    (
        "extra assignment between key-value pairs",
        "`=` berlebih di antara pasangan kunci-nilai",
    ),
    (
        "string values must be quoted",
        "nilai string harus diberi tanda kutip",
    ),
    ("unclosed array", "array tidak ditutup"),
    ("unclosed array table", "tabel array tidak ditutup"),
    ("unclosed inline table", "tabel inline tidak ditutup"),
    ("unclosed table", "tabel tidak ditutup"),
    ("unexpected content", "isi yang tidak diharapkan"),
    (
        "unexpected content between comment and newline",
        "isi yang tidak diharapkan sebelum akhir baris",
    ),
    (
        "unexpected key or value",
        "kunci atau nilai yang tidak diharapkan",
    ),
    (
        "unexpected leading zero",
        "nol di depan yang tidak diharapkan",
    ),
    ("unexpected sign", "tanda yang tidak diharapkan"),
    (
        "unexpected `=` in array",
        "`=` yang tidak diharapkan dalam array",
    ),
    (
        "`_` may only go between digits",
        "`_` hanya boleh di antara angka",
    ),
    (
        "unquoted keys cannot be empty",
        "kunci tanpa tanda kutip tidak boleh kosong",
    ),
    ("redundant numeric sign", "tanda bilangan berlebih"),
    ("duplicate key", "kunci ganda"),
    (
        "cannot recurse further; max recursion depth met",
        "bersarang terlalu dalam",
    ),
];

/// What the TOML reader expected, in Indonesian (literals stay as written).
const EXPECTED: [(&str, &str); 11] = [
    ("digits", "angka"),
    ("letters", "huruf"),
    ("numbers", "bilangan"),
    ("value", "nilai"),
    ("key", "kunci"),
    ("characters", "karakter"),
    ("printable characters", "karakter yang dapat dicetak"),
    ("basic string", "string"),
    ("literal string", "string literal"),
    ("multi-line basic string", "string multi-baris"),
    ("unicode hexadecimal value", "nilai heksadesimal unicode"),
];

/// The TOML reader's syntax message (`description, expected a, b`) in
/// Indonesian: known descriptions and expectations translated, anything
/// else (a literal such as `` `=` ``) as written.
fn syntax_words(s: &str) -> String {
    let (desc, expected) = match s.split_once(", expected ") {
        Some((d, e)) => (d, Some(e)),
        None => (s, None),
    };
    let find = |table: &[(&str, &'static str)], w: &str| {
        let hit = table.iter().find(|(en, _)| *en == w.trim());
        hit.map_or_else(|| w.trim().to_string(), |(_, id)| id.to_string())
    };
    let mut out = find(&SYNTAX, desc);
    // "expected nothing": nothing more may follow on the line.
    if let Some(e) = expected.filter(|e| *e != "nothing") {
        let items: Vec<String> = e.split(", ").map(|w| find(&EXPECTED, w)).collect();
        out.push_str(&format!(", seharusnya {}", items.join(", ")));
    }
    out
}

/// A command line clap refused: clap's own line in English; built from the
/// argument, the value and the possible values in Indonesian.
fn clap(e: &ClapErr, en: &str, lang: Lang) -> String {
    if lang == Lang::En {
        return en.to_string();
    }
    let id = match e {
        ClapErr::InvalidValue(v, all) if all.is_empty() => format!("nilai '{v}' tidak sah"),
        ClapErr::InvalidValue(v, all) => {
            format!("nilai '{v}' tidak sah; nilai yang mungkin: {all}")
        }
        ClapErr::BadValue(v, why) => format!("nilai '{v}' tidak sah: {}", value_reason(why)),
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
        ClapErr::Other => format!("baris perintah tidak diterima: {en}"),
    };
    format!("{id} (lihat --help)")
}

/// A value parser's reason (Rust's number parsing, clap's ranges), in
/// Indonesian where known.
fn value_reason(why: &str) -> String {
    let known = [
        ("invalid digit found in string", "bukan bilangan bulat"),
        ("cannot parse integer from empty string", "kosong"),
        (
            "number too large to fit in target type",
            "bilangan terlalu besar",
        ),
        (
            "number too small to fit in target type",
            "bilangan terlalu kecil",
        ),
        ("invalid float literal", "bukan bilangan"),
    ];
    if let Some((_, id)) = known.iter().find(|(en, _)| *en == why) {
        return id.to_string();
    }
    match why.split_once(" is not in ") {
        Some((v, range)) => format!("{v} tidak berada dalam rentang {range}"),
        None => why.to_string(),
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Every error key, with sample parameters (each variant of every
    /// part at least once; `listed` below fails to compile when one is
    /// added without being listed here).
    pub fn every_error() -> Vec<ErrMsg> {
        let s = |x: &str| x.to_string();
        let mut v: Vec<ErrMsg> = every_number().into_iter().map(ErrMsg::Num).collect();
        v.extend(every_toml().into_iter().map(ErrMsg::Toml));
        v.extend(
            every_clap()
                .into_iter()
                .map(|c| ErrMsg::Clap(c, s("clap's line"))),
        );
        v.extend(
            every_bound()
                .into_iter()
                .map(|b| ErrMsg::MustBe(b, s("-0.5"))),
        );
        v.extend(every_twice().into_iter().map(ErrMsg::Twice));
        for w in every_io() {
            v.push(ErrMsg::CannotRead(s("a.toml"), w.clone()));
            v.push(ErrMsg::CannotReadStdin(w.clone()));
            v.push(ErrMsg::CannotWrite(s("a.png"), w.clone()));
            v.push(ErrMsg::CannotCreate(s("out"), w.clone()));
            v.push(ErrMsg::CannotWriteStdout(w.clone()));
            v.push(ErrMsg::ObjUnreadable(s("m.obj"), w));
        }
        v.extend([
            ErrMsg::Channel(s("red"), s("1.5")),
            ErrMsg::Channel(s("green"), s("1.5")),
            ErrMsg::Channel(s("blue"), s("-0.5")),
            ErrMsg::Attenuation(s("0"), s("0"), s("0")),
            ErrMsg::Cones(s("60"), s("30.5")),
            ErrMsg::PlaneThroughOrigin,
            ErrMsg::PlaneThroughCop(s("2.5")),
            ErrMsg::ImageTooLarge(s("A"), s("f32")),
            ErrMsg::Viewport(s("0"), s("1.5")),
            ErrMsg::VVanished,
            ErrMsg::EyeLookTooLarge(s("(1e308, 0, 0)"), s("f64")),
            ErrMsg::TranslationTooLarge(s("f32")),
            ErrMsg::EyeCoordsTooLarge(s("A"), s("f32")),
            ErrMsg::ResultNotFinite(s("f32")),
            ErrMsg::ResultNotFinite(s("exact")),
            ErrMsg::ExistsForce(s("out/problem-01.toml")),
            ErrMsg::StdoutClosed,
            ErrMsg::NamesFolder(s("figs/")),
            ErrMsg::IsLink(s("a.png")),
            ErrMsg::IsInput(s("scene.toml")),
            ErrMsg::NotOwn(s("exam/key.md"), s(".grafika-generated")),
            ErrMsg::NotDirectory(s("out")),
            ErrMsg::NotMarked(1, 4, s("class/broken.toml")),
            ErrMsg::AnswerFileTooLarge(s("a.toml"), 2_000_000, 1 << 20),
            ErrMsg::NoLightTable(s("l.toml")),
            ErrMsg::ColorMissing,
            ErrMsg::NormalMissing,
            ErrMsg::CameraAtPoint,
            ErrMsg::NoLight,
            ErrMsg::LightAtPoint,
            ErrMsg::Needs(Thing::Light(s("point")), s("position")),
            ErrMsg::Needs(Thing::Object(s("sphere")), s("r")),
            ErrMsg::Needs(Thing::Object(s("obj")), s("path")),
            ErrMsg::NotApplicable(s("axis"), s("point")),
            ErrMsg::NoSuchKey(s("box"), s("r"), s("size")),
            ErrMsg::NeededToRender,
            ErrMsg::ObjInvalid(s("m.obj"), s("FaceParseError"), s("Failed to parse a face")),
            ErrMsg::ObjInvalid(s("m.obj"), s("Unknown"), s("something")),
            ErrMsg::ObjNoFaces(s("m.obj")),
            ErrMsg::ObjNotFinite(s("m.obj")),
            ErrMsg::FaceVertex,
            ErrMsg::FormulaNotFinite,
            ErrMsg::TooManyTriangles(5_000_000, 4_000_000),
            ErrMsg::TooManyLights(9, 8),
            ErrMsg::NeedsColour,
            ErrMsg::NoObjects,
            ErrMsg::CameraNeedsPerspective,
            ErrMsg::ImageSize(s("0"), s("10")),
            ErrMsg::UnknownPart(s("views"), s("basis, view")),
            ErrMsg::ExpectedXyz(TomlErr::InvalidLength(s("2"), s("3 elements"))),
            ErrMsg::NothingToSolve,
            ErrMsg::NoCameraTable,
            ErrMsg::ProjectionNeedsNear,
            ErrMsg::WindowNeeds,
            ErrMsg::LightsNeedShade,
            ErrMsg::NoTopic,
            ErrMsg::NoDrawing,
            ErrMsg::NoProblemDrawn,
            ErrMsg::StdinHoldsAnswers,
            ErrMsg::GiveProblem,
            ErrMsg::TooManyProblems(3000, 1000, 3, 48, 2000),
            ErrMsg::BothStdin,
            ErrMsg::NoPrinted(s("p.toml")),
            ErrMsg::CsvAndJson,
            ErrMsg::NoAnswerFiles(s("class")),
            ErrMsg::NoExam(s("exam")),
            ErrMsg::NoVariant(4),
            ErrMsg::NotAVariant(s("7"), 4),
            ErrMsg::NotAProblemOfExam(s("view.n"), s("problem-01, problem-02")),
            ErrMsg::ReportFormat(s("class.txt")),
            ErrMsg::ReportNeedsClass,
            ErrMsg::PixelOutside(10, 20, 8, 8),
            ErrMsg::PixelText(s("a,b")),
            ErrMsg::NothingRendered,
            ErrMsg::Threads(s("why")),
            ErrMsg::RenderPrecision,
            ErrMsg::NotTaken(s("check")),
            ErrMsg::OwnOutput,
            ErrMsg::Man(s("why")),
        ]);
        v
    }

    fn every_number() -> Vec<NumErr> {
        let s = |x: &str| x.to_string();
        let mut v = vec![
            NumErr::Quoted(s("1+*2"), Box::new(NumErr::Empty)),
            NumErr::TooLong(5000, 4000),
            NumErr::Empty,
            NumErr::TooDeep(100, 101),
            NumErr::TooManyOps(500, 1001),
            NumErr::Count(2, s("1,2")),
            NumErr::Component(2, s("x"), Box::new(NumErr::NotANumber(s("x")))),
            NumErr::NotFinite(s("1e999"), s("f64")),
            NumErr::NotANumber(s("1.2.3")),
            NumErr::NotFiniteLiteral(s("NaN")),
            NumErr::NegativeRoot(s("-1")),
            NumErr::DivZero(s("1/0")),
            NumErr::Exponent(s("2^0.5")),
            NumErr::PowerRange(s("10^1000")),
            NumErr::Unexpected('#', 3),
            NumErr::OpenAfter(s("sin")),
            NumErr::UnknownName(s("tan")),
            NumErr::EndsEarly,
            NumErr::FormulaDeep(100, 101),
            NumErr::FormulaOps(500, 1001),
        ];
        for w in [
            Want::OperatorOrEnd,
            Want::Close,
            Want::OpenAfterSqrt,
            Want::Number,
        ] {
            v.push(NumErr::Expected(w, 3, Some('*')));
            v.push(NumErr::Expected(w, 3, None));
        }
        v
    }

    fn every_toml() -> Vec<TomlErr> {
        let s = |x: &str| x.to_string();
        vec![
            TomlErr::UnknownField(s("eyes"), Some(s("`eye`, `look`, `up`"))),
            TomlErr::UnknownField(s("eyes"), None),
            TomlErr::MissingField(s("eye")),
            TomlErr::Duplicate(s("eye")),
            TomlErr::UnknownVariant(s("pyramid"), s("`cone`, `sphere`")),
            TomlErr::InvalidType(s("string \"a\""), s("a sequence")),
            TomlErr::InvalidLength(s("2"), s("an array of length 3")),
            TomlErr::Num(NumErr::DivZero(s("1/0"))),
            TomlErr::MustBe(Bound::Positive, s("-1.5")),
            TomlErr::WholeRange(3, 4096, s("2")),
            TomlErr::Colour(s("[1.5, 0, 0]")),
            TomlErr::Syntax(s("invalid number")),
        ]
    }

    fn every_clap() -> Vec<ClapErr> {
        let s = |x: &str| x.to_string();
        vec![
            ClapErr::InvalidValue(s("foo"), s("exact, f64, f32")),
            ClapErr::InvalidValue(s("foo"), String::new()),
            ClapErr::BadValue(s("abc"), s("invalid digit found in string")),
            ClapErr::BadValue(s("99"), s("99 is not in 1..=17")),
            ClapErr::Unknown(s("--eyes"), Some(s("--eye"))),
            ClapErr::Unknown(s("--eyes"), None),
            ClapErr::UnknownCommand(s("bassis"), Some(s("basis"))),
            ClapErr::UnknownCommand(s("bassis"), None),
            ClapErr::Conflict(s("--ortho"), s("--d")),
            ClapErr::Missing(s("--eye")),
            ClapErr::NoValue,
            ClapErr::ValueCount(s("--point")),
            ClapErr::Other,
        ]
    }

    fn every_bound() -> Vec<Bound> {
        vec![
            Bound::NumberAtLeastZero,
            Bound::AtLeastZero,
            Bound::AboveZero,
            Bound::Positive,
            Bound::NotNegative,
            Bound::FiniteAtLeastZero,
            Bound::Fraction,
            Bound::WholePixels,
            Bound::AboveNear("0.5".into()),
        ]
    }

    fn every_twice() -> Vec<Twice> {
        use Twice::*;
        vec![
            GlobalAmbient,
            Material,
            Color,
            Shininess,
            View,
            Light,
            Axis,
            TiltCamera,
            Colors,
            Answers,
        ]
    }

    fn every_io() -> Vec<IoWhy> {
        use IoWhy::*;
        vec![
            NotFound,
            Denied,
            Exists,
            IsDirectory,
            NotText,
            Other("disk full".into()),
        ]
    }

    /// Fails to compile when a key is added to any error enum without
    /// being listed above (no wildcard arm).
    #[allow(dead_code)]
    fn listed(e: &ErrMsg, n: &NumErr, t: &TomlErr, c: &ClapErr, b: &Bound, w: &Want, i: &IoWhy) {
        use ErrMsg as E;
        match e {
            E::Num(_)
            | E::MustBe(..)
            | E::Twice(_)
            | E::Channel(..)
            | E::Attenuation(..)
            | E::Cones(..)
            | E::PlaneThroughOrigin
            | E::PlaneThroughCop(_)
            | E::ImageTooLarge(..)
            | E::Viewport(..)
            | E::VVanished
            | E::EyeLookTooLarge(..)
            | E::TranslationTooLarge(_)
            | E::EyeCoordsTooLarge(..)
            | E::ResultNotFinite(_)
            | E::CannotRead(..)
            | E::CannotReadStdin(_)
            | E::CannotWrite(..)
            | E::CannotCreate(..)
            | E::CannotWriteStdout(_)
            | E::StdoutClosed
            | E::ExistsForce(_)
            | E::NamesFolder(_)
            | E::IsLink(_)
            | E::IsInput(_)
            | E::NotOwn(..)
            | E::NotDirectory(_)
            | E::NotMarked(..)
            | E::AnswerFileTooLarge(..)
            | E::NoLightTable(_)
            | E::ColorMissing
            | E::NormalMissing
            | E::CameraAtPoint
            | E::NoLight
            | E::LightAtPoint
            | E::Needs(..)
            | E::NotApplicable(..)
            | E::NoSuchKey(..)
            | E::NeededToRender
            | E::ObjUnreadable(..)
            | E::ObjInvalid(..)
            | E::ObjNoFaces(_)
            | E::ObjNotFinite(_)
            | E::FaceVertex
            | E::FormulaNotFinite
            | E::TooManyTriangles(..)
            | E::TooManyLights(..)
            | E::NeedsColour
            | E::NoObjects
            | E::CameraNeedsPerspective
            | E::ImageSize(..)
            | E::UnknownPart(..)
            | E::ExpectedXyz(_)
            | E::Toml(_)
            | E::NothingToSolve
            | E::NoCameraTable
            | E::ProjectionNeedsNear
            | E::WindowNeeds
            | E::LightsNeedShade
            | E::NoTopic
            | E::NoDrawing
            | E::NoProblemDrawn
            | E::StdinHoldsAnswers
            | E::GiveProblem
            | E::TooManyProblems(..)
            | E::BothStdin
            | E::NoPrinted(_)
            | E::CsvAndJson
            | E::NoAnswerFiles(_)
            | E::NoExam(_)
            | E::NoVariant(_)
            | E::NotAVariant(..)
            | E::NotAProblemOfExam(..)
            | E::ReportFormat(_)
            | E::ReportNeedsClass
            | E::PixelOutside(..)
            | E::PixelText(_)
            | E::NothingRendered
            | E::Threads(_)
            | E::RenderPrecision
            | E::NotTaken(_)
            | E::OwnOutput
            | E::Man(_)
            | E::Clap(..) => {}
        }
        match n {
            NumErr::Quoted(..)
            | NumErr::TooLong(..)
            | NumErr::Empty
            | NumErr::Expected(..)
            | NumErr::TooDeep(..)
            | NumErr::TooManyOps(..)
            | NumErr::Count(..)
            | NumErr::Component(..)
            | NumErr::NotFinite(..)
            | NumErr::NotANumber(_)
            | NumErr::NotFiniteLiteral(_)
            | NumErr::NegativeRoot(_)
            | NumErr::DivZero(_)
            | NumErr::Exponent(_)
            | NumErr::PowerRange(_)
            | NumErr::Unexpected(..)
            | NumErr::OpenAfter(_)
            | NumErr::UnknownName(_)
            | NumErr::EndsEarly
            | NumErr::FormulaDeep(..)
            | NumErr::FormulaOps(..) => {}
        }
        match t {
            TomlErr::UnknownField(..)
            | TomlErr::MissingField(_)
            | TomlErr::Duplicate(_)
            | TomlErr::UnknownVariant(..)
            | TomlErr::InvalidType(..)
            | TomlErr::InvalidLength(..)
            | TomlErr::Num(_)
            | TomlErr::MustBe(..)
            | TomlErr::WholeRange(..)
            | TomlErr::Colour(_)
            | TomlErr::Syntax(_) => {}
        }
        match c {
            ClapErr::InvalidValue(..)
            | ClapErr::BadValue(..)
            | ClapErr::Unknown(..)
            | ClapErr::UnknownCommand(..)
            | ClapErr::Conflict(..)
            | ClapErr::Missing(_)
            | ClapErr::NoValue
            | ClapErr::ValueCount(_)
            | ClapErr::Other => {}
        }
        match b {
            Bound::NumberAtLeastZero
            | Bound::AtLeastZero
            | Bound::AboveZero
            | Bound::Positive
            | Bound::NotNegative
            | Bound::FiniteAtLeastZero
            | Bound::Fraction
            | Bound::WholePixels
            | Bound::AboveNear(_) => {}
        }
        match w {
            Want::OperatorOrEnd | Want::Close | Want::OpenAfterSqrt | Want::Number => {}
        }
        match i {
            IoWhy::NotFound
            | IoWhy::Denied
            | IoWhy::Exists
            | IoWhy::IsDirectory
            | IoWhy::NotText
            | IoWhy::Other(_) => {}
        }
    }

    #[test]
    fn every_error_has_words_in_both_languages_and_they_differ() {
        let all = every_error();
        assert!(all.len() > 150, "{}", all.len());
        for e in &all {
            let (en, id) = (error(e, Lang::En), error(e, Lang::Id));
            assert!(!en.trim().is_empty(), "{e:?} has no English");
            assert!(!id.trim().is_empty(), "{e:?} has no Indonesian");
            assert_ne!(en, id, "{e:?} is not translated");
        }
    }

    #[test]
    fn indonesian_errors_write_numbers_with_the_decimal_comma() {
        // -0,5 for the value given; 0,5 for near; the path keeps its dot.
        let e = ErrMsg::MustBe(Bound::AboveNear("0.5".into()), "-0.5".into());
        assert_eq!(
            error(&e, Lang::Id),
            "harus lebih besar daripada near = 0,5, diberikan -0,5"
        );
        assert_eq!(
            error(&e, Lang::En),
            "must be greater than near = 0.5, got -0.5"
        );
        let e = ErrMsg::Attenuation("0.5".into(), "-1".into(), "0".into());
        assert!(error(&e, Lang::Id).ends_with("diberikan (0,5; -1; 0)"));
        let e = TomlErr::InvalidType("string \"a\"".into(), "an integer".into());
        assert_eq!(
            toml(&e, Lang::Id),
            "jenis nilai salah: string \"a\", seharusnya bilangan bulat"
        );
        let e = ErrMsg::CannotRead("p.toml".into(), IoWhy::NotFound);
        assert_eq!(
            error(&e, Lang::Id),
            "tidak dapat membaca p.toml: berkas atau direktori tidak ada"
        );
    }
}
