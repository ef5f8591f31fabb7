//! The report writers' own words in Bahasa Indonesia: the class report's
//! headings, columns and sentences, the notes on answer files, … (one
//! exhaustive match per key enum; a word table, long on purpose).

use super::Id;
use crate::msg::BenchWord as B;
use crate::msg::CheckWord as K;
use crate::msg::ClassWord as C;
use crate::msg::CliWord as L;
use crate::msg::PlanWord as N;
use crate::msg::PracticeWord as P;
use crate::msg::StatWord as S;
use crate::msg::{Decimal, DocWord as D, QuizWord as Q};
use crate::report::words::report::{dec, exam_title, model_name, percent, ReportWords};
use crate::report::words::MsgWords;
use crate::stages::clip::Status;
use crate::tutor::check::Verdict;
use crate::tutor::class::same::Same;
use crate::tutor::class::stats::Flag;
use crate::tutor::class::{Note, Skip};
use crate::tutor::diagnose::Code;
use crate::tutor::practice::Summary;

impl ReportWords for Id {
    fn class(&self, w: &C) -> String {
        match w {
            C::ClassReport => "Laporan kelas".into(),
            C::Student => "mahasiswa".into(),
            C::Students => "mahasiswa".into(),
            C::Score => "nilai".into(),
            C::FollowThrough => "benar lanjutan".into(),
            C::Mistakes => "kesalahan konsep".into(),
            C::Mistake => "kesalahan".into(),
            C::Key => "kunci".into(),
            C::Flag => "tanda".into(),
            C::Problem => "soal".into(),
            C::Title => "judul".into(),
            C::Facility => "tingkat kemudahan p".into(),
            C::WholeExam => "seluruh ujian".into(),
            C::Harder => "lebih sulit".into(),
            C::Easier => "lebih mudah".into(),
            C::AnswerKeys => "Kunci jawaban".into(),
            C::Problems => "Soal".into(),
            C::Variants => "Varian".into(),
            C::MistakesHeading => "Kesalahan konsep".into(),
            C::WrongHeading => "Jawaban salah yang tidak dijelaskan kesalahan yang dikenal".into(),
            C::StudentsHeading => "Mahasiswa".into(),
            C::WhoWhich => "Siapa membuat kesalahan apa".into(),
            C::Scores => "Nilai".into(),
            C::Summary {
                students,
                tolerance_pct,
                sig_figs,
                follow_through,
            } => format!(
                "{students} mahasiswa dinilai; toleransi {} %, paling sedikit {sig_figs} angka penting, penilaian lanjutan (benar menurut jawaban sendiri sebelumnya) {}.",
                dec(*tolerance_pct, 4, self.nums()),
                if *follow_through { "aktif" } else { "tidak aktif" }
            ),
            C::NotMarked => "Tidak dinilai (tidak dihitung di bawah):".into(),
            C::Definitions => "Benar: jumlahnya, dan dalam kurung berapa yang eksak / dibulatkan dengan benar / dalam batas toleransi. \
                 Nilai sebuah kunci 1 bila benar, ½ bila terlalu kasar, 0 bila tidak; nilai mahasiswa adalah jumlahnya. \
                 Tingkat kemudahan p: rata-rata nilai kunci, bagian dari nilai penuh (sangat mudah di atas 0,90, sangat sulit di bawah 0,20). \
                 Daya beda D: rata-rata nilai 27 % kelas teratas menurut nilai dikurangi rata-rata 27 % terbawah \
                 (mahasiswa dengan nilai sama di batas kelompok berbagi tempatnya); dari −1 sampai 1. \
                 Point-biserial r: korelasi nilai kunci dengan sisa nilai (nilai tanpa kunci ini); \
                 — bila semua mendapat nilai yang sama. Kunci dengan D atau r di bawah 0 memiliki daya beda negatif (tanda: negatif): \
                 mahasiswa yang lebih lemah justru lebih baik, jadi periksa kunci atau soalnya.".into(),
            C::VariantsNote => "Setiap sel adalah tingkat kemudahan varian pada soal itu; n adalah banyaknya mahasiswa yang mengerjakan varian itu. \
                 Sebuah varian dibandingkan dengan sisa kelas hanya bila keduanya memiliki paling sedikit 5 mahasiswa: uji z dua proporsi untuk tingkat kemudahannya \
                 terhadap tingkat kemudahan sisa kelas, nilai p varian-varian satu soal dikoreksi bersama dengan metode Holm; ▼ lebih sulit (▲ lebih mudah) menandai nilai p terkoreksi di bawah 0,05.".into(),
            C::DrawnNote => "Dalam kuis Moodle varian setiap soal diundi sendiri-sendiri, jadi varian seorang mahasiswa ditulis per soal \
                 (2/1/2: soal 1 dari varian 2, soal 2 dari varian 1, …). Sel sebuah soal menghitung mahasiswa yang mendapat soal itu \
                 dari varian itu, n mereka yang mendapat soal mana pun dari varian itu, dan ujian utuh bukan milik satu varian.".into(),
            C::RosterHeading => "Daftar kelas".into(),
            C::RosterMissing(n) => format!("Ada di daftar kelas, tanpa berkas jawaban ({n}):"),
            C::RosterNotListed(n) => format!("Berkas jawaban yang tidak ada di daftar kelas ({n}):"),
            C::RosterAll(n) => format!("Setiap {n} mahasiswa di daftar kelas mengumpulkan satu berkas jawaban, dan setiap berkas milik mereka."),
            C::DuplicatesHeading => "Mahasiswa yang sama dua kali".into(),
            C::DuplicatesNote => "Dua berkas dianggap mahasiswa yang sama bila namanya sama (student di berkas, atau nama berkas tanpa akhiran salinan seperti \" (1)\"; huruf besar-kecil dan spasi diabaikan), \
                 atau keduanya memberi NIM yang sama, atau jawabannya sama persis seperti diketik dan salah satunya tidak menyebut nama mahasiswa; dua NIM yang berbeda adalah dua mahasiswa. \
                 Dari setiap kelompok, berkas yang dinilai dan terakhir diubah yang dipakai (waktu sama: yang terakhir menurut nama); yang lain tidak dihitung.".into(),
            C::DuplicateOf { kept, why } => format!("mahasiswa yang sama dengan {kept} ({why}): tidak dihitung"),
            C::FitsHeading => "Jawaban yang cocok dengan kunci varian lain".into(),
            C::FitsNote => "Setiap lembar jawaban yang mendapat setengah nilai atau kurang dinilai lagi terhadap setiap varian lain dari ujian ini; \
                 bila kunci varian lain memberinya paling sedikit setengah nilai lebih banyak, jawaban itu cocok dengan kunci tersebut: disalin dari mahasiswa varian itu, atau berkasnya menyebut varian yang salah. \
                 Nilai yang dihitung tetap nilai terhadap variannya sendiri.".into(),
            C::Fits { variant, there, own } => format!(
                "jawaban ini cocok dengan kunci varian {variant} ({} % nilai di sana, {} % pada variannya sendiri)",
                there.round(),
                own.round()
            ),
            C::TooFewPerVariant { min, max, need } => {
                let n = if min == max { min.to_string() } else { format!("{min}–{max}") };
                format!("Terlalu sedikit mahasiswa per varian untuk membandingkan varian: n = {n} (perlu paling sedikit {need} per varian), jadi tidak ada varian yang ditandai lebih sulit atau lebih mudah.")
            }
            C::NoMistake => "Tidak ada kesalahan yang dikenal yang menjelaskan jawaban salah.".into(),
            C::WrongNote => "Nilai yang sama dalam batas toleransi dihitung bersama; yang paling sering lebih dulu. Nilai yang sama pada banyak mahasiswa bisa jadi kesalahan yang belum dikenal katalog, atau kunci yang salah.".into(),
            C::NoneFound => "Tidak ada.".into(),
            C::StudentCount(_) => "mahasiswa".into(),
            C::Explains => "Menjelaskan".into(),
            C::TeachAgain => "Ajarkan lagi".into(),
            C::StepOf {
                part,
                number,
                title,
            } => format!("{part}langkah {number} dari penyelesaian: {title}"),
            C::DistributionPct => "Sebaran nilai (% dari nilai penuh)".into(),
            C::Distribution => "Sebaran nilai".into(),
            C::ScoreAxis => "nilai, % dari nilai penuh".into(),
        }
    }

    fn note(&self, n: Note) -> &'static str {
        match n {
            Note::Empty => "tidak berisi jawaban: dinilai dengan semua jawaban kosong",
            Note::NotMarked => {
                "tidak dinilai: berkas ini bukan berkas jawaban yang sah (lihat galat di barisnya)"
            }
        }
    }

    fn skip(&self, s: Skip) -> &'static str {
        match s {
            Skip::Subdirectory => "dilewati: subdirektori (berkas di dalamnya tidak dibaca)",
            Skip::NotToml => "dilewati: bukan berkas .toml",
        }
    }

    fn same(&self, s: Same) -> &'static str {
        match s {
            Same::Name => "nama sama",
            Same::Nim => "NIM sama",
            Same::Answers => "jawaban sama, satu berkas tanpa nama mahasiswa",
            Same::Attempt => "percobaan lain pada kuis yang sama; nilai tertinggi yang dipakai",
        }
    }

    fn flag(&self, f: Flag) -> &'static str {
        match f {
            Flag::VeryEasy => "sangat mudah",
            Flag::VeryHard => "sangat sulit",
            Flag::Negative => "negatif",
        }
    }

    fn verdict(&self, v: Verdict) -> &'static str {
        match v {
            Verdict::Exact | Verdict::Rounded | Verdict::Tolerance | Verdict::FollowThrough => {
                "benar"
            }
            Verdict::TooCoarse => "terlalu kasar",
            Verdict::Wrong => "salah",
            Verdict::Missing => "tidak dijawab",
            Verdict::Unparseable => "tidak terbaca",
        }
    }

    fn check(&self, w: &K) -> String {
        match w {
            K::Answer => "jawaban".into(),
            K::Verdict => "penilaian".into(),
            K::Given => "diberikan".into(),
            K::Expected => "seharusnya".into(),
            K::Note => "catatan".into(),
            K::AnswersOf => "jawaban dari".into(),
            K::Errata => "Mengapa jawaban yang tercetak berbeda (errata dalam berkas soal):".into(),
            K::Diagnosis => "Diagnosis:".into(),
            K::Reproduces => "menghasilkan ulang".into(),
            K::AlsoFollow => "sebagian juga dapat berasal dari".into(),
            K::NoMistakeExplains => "Tidak ada kesalahan yang dikenal yang menjelaskan".into(),
            K::NotAnswers => "Bukan jawaban untuk soal ini (diabaikan)".into(),
            K::Score => "Nilai".into(),
            K::FollowThroughCount(n) => format!(
                "({n} jawaban benar lanjutan: benar menurut jawaban mahasiswa sendiri sebelumnya)"
            ),
            K::Marks => "poin".into(),
            K::Working => "langkah".into(),
            K::WorkingCount(n, right) => format!("Langkah pengerjaan yang ditulis, tidak dihitung dalam nilai: {n} jawaban, {right} di antaranya benar"),
            K::MethodMarks => "Poin untuk langkah pengerjaan, bila jawabannya sendiri tidak benar:".into(),
            K::MethodEarned(e, of) => format!("{e} dari {of} poin, untuk"),
        }
    }

    fn doc(&self, w: &D) -> String {
        match w {
            D::Step => "Langkah".into(),
            D::Answer => "Jawaban".into(),
            D::Answers => "Jawaban".into(),
            D::Figures => "Gambar".into(),
            D::WorkedSolution => "Penyelesaian".into(),
            D::Problem => "Soal".into(),
            D::Variant => "varian".into(),
            D::Error => "kesalahan".into(),
            D::MoodleMarked(n, of) => format!("{n} dari {of} percobaan dinilai ulang"),
            D::MoodleUnfinished(who, state) => format!("belum selesai, tidak dinilai: {who} ({state})"),
            D::MoodleForeign(slot, head) => format!("soal {slot} bukan soal ujian ini, dilewati: {head}…"),
            D::MoodleUnreadable(who, key, t) if t.is_empty() => format!("{who}: {key} dibiarkan kosong"),
            D::MoodleUnreadable(who, key, t) => format!("{who}: {key} tidak terbaca seperti diketik: \"{t}\""),
            D::Warning => "peringatan".into(),
            D::NotesOnSource => "Catatan tentang sumber".into(),
            D::Yes => "ya".into(),
            D::No => "tidak".into(),
            D::NoValue => "tidak ada".into(),
            D::ComparedWith => "Dibandingkan dengan jawaban yang tercetak di".into(),
            D::TheSource => "sumber".into(),
            D::Printed => "tercetak".into(),
            D::CorrectValue => "yang benar".into(),
            D::Computed => "hasil hitung".into(),
            D::Value => "nilai".into(),
            D::Why => "alasan".into(),
            D::ExamTitle {
                topics,
                difficulty,
                seed,
                variant,
            } => exam_title("ujian grafika", (topics, difficulty), *seed, variant.map(|v| (self.doc(&D::Variant), v))),
            D::KeyTitle(title) => format!("{title} — kunci jawaban"),
            D::Marks(n) => format!("({n} poin)"),
            D::AnswerKey => "Kunci jawaban".into(),
            D::Wrote {
                files,
                variants,
                count,
                topics,
                seed,
                out,
            } => format!(
                "{files} berkas ditulis ({variants} varian dari {count} soal {topics}, seed {seed}) ke {out}"
            ),
            D::More(n) => format!("… dan {n} lagi"),
            D::SheetTitle { difficulty, variant } => format!(
                "Ujian grafika komputer — tingkat {}{}",
                match difficulty.as_str() {
                    "easy" => "mudah",
                    "hard" => "sulit",
                    _ => "sedang",
                },
                variant.map(|v| format!(", varian {v}")).unwrap_or_default()
            ),
            D::NameLine => "Nama: ______________________________   NIM: ________________".into(),
            D::TotalMarks(n) => format!("Jumlah: {n} poin"),
        }
    }

    fn quiz(&self, w: &Q) -> String {
        match w {
            Q::Instructions {
                figures,
                pct,
                mark,
                pixels,
            } => {
                let mark = match mark {
                    Decimal::Point => "titik desimal (0.5, bukan 0,5)",
                    Decimal::Comma => "koma desimal (0,5)",
                };
                let pixel = match pixels {
                    true => "; posisi piksel boleh berselisih setengah piksel, jadi piksel bulat dinilai benar",
                    false => "",
                };
                format!("Tulis setiap bilangan sebagai desimal dengan sedikitnya {figures} angka penting, bukan sebagai bentuk eksak seperti (√2−1)/2, dengan {mark} (bilangan yang berselisih paling banyak {pct} % dari kunci dinilai benar{pixel}).")
            }
            Q::TypeOutcodes => "Tulis outcode sebagai enam bit, bit 1 paling kanan (mis. 000010).".into(),
            Q::TypeStatus => "Tulis status clipping sebagai diterima, ditolak atau di-clip (kata Inggrisnya, accepted, rejected atau clipped, juga dinilai benar), dan segmen garis yang tersisa sebagai tidak ada (atau none) bila tidak ada yang tersisa.".into(),
            Q::KnownMistake => "Kesalahan yang dikenal: ".into(),
            Q::OrMistake => "; atau: ".into(),
            Q::Part => "Bagian".into(),
            Q::FiguresInMoodle => "GIFT tidak dapat membawa berkas: gambar penyelesaian hanya ada di Moodle XML dari ujian yang sama (--format moodle).".into(),
            Q::Word(code) => match crate::report::words::said::status(code) {
                Some(Status::Accepted) => "diterima".into(),
                Some(Status::Rejected) => "ditolak".into(),
                Some(Status::Clipped) => "di-clip".into(),
                None if code == "none" => self.doc(&D::NoValue),
                None => code.clone(),
            },
            Q::Component => "komponen".into(),
            Q::Point => "titik".into(),
        }
    }

    fn cli(&self, w: L) -> &'static str {
        match w {
            L::WorkedSolution => "penyelesaian",
            L::Measuring => "mengukur",
            L::Frames => "bingkai",
            L::Problems => "soal",
            L::Arguments => "argumen",
            L::TheText => "teks",
        }
    }

    fn stat(&self, w: S) -> String {
        match w {
            S::Heading => "Statistik".into(),
            S::TrianglesIn => "segitiga masuk".into(),
            S::Culled => "sisi belakang dibuang (mesh tertutup)".into(),
            S::Rejected => "ditolak oleh region code".into(),
            S::Clipped => "di-clip (memotong bidang)".into(),
            S::Drawn => "disiapkan dan dirasterisasi".into(),
            S::NoPixels => "tidak menutupi pusat piksel".into(),
            S::ObjectsRejected => "objek ditolak utuh (kotak pembatas)".into(),
            S::ObjectsInside => "objek di dalam utuh (tanpa uji clip)".into(),
            S::PixelsShaded => "piksel diwarnai".into(),
            S::LightingEvals => "evaluasi pencahayaan".into(),
            S::PerPixel => "pencahayaan per piksel".into(),
            S::LightsSkipped => "sumber cahaya dilewati (di luar jangkauan)".into(),
            S::SpecularSkipped => "objek tanpa perhitungan specular".into(),
            S::Geometry { runs: 0 | 1 } => "waktu: geometri".into(),
            S::Geometry { runs } => format!("waktu: geometri (median dari {runs})"),
            S::Binning => "waktu: binning".into(),
            S::Bands => "waktu: pita (raster + shading)".into(),
            S::Raster => "waktu thread: raster".into(),
            S::Shading => "waktu thread: shading".into(),
            S::Frame => "waktu: bingkai".into(),
            S::Png => "waktu: encoding PNG".into(),
        }
    }

    fn plan(&self, w: &N) -> String {
        match w {
            N::Title => "Kisi-kisi ujian".into(),
            N::Heading { variants, total } => format!(
                "Kisi-kisi: {variants} varian, masing-masing bernilai {total} poin; setiap varian sebuah soal menanyakan kasus, kelas bilangan dan poin yang sama"
            ),
            N::Topic => "Topik".into(),
            N::Case => "Kasus".into(),
            N::Numbers => "Bilangan".into(),
            N::Marks => "Poin".into(),
            N::Statements => "Teks soal".into(),
            N::Points(n) => format!("{n} titik"),
            N::Model(m) => format!("model {}", model_name(m)),
            N::Clip { status, bits, tried, kept } => format!(
                "{}: P0 di luar {} bidang, P1 di luar {}; {tried} perpotongan dihitung, {kept} dipakai",
                match status.as_str() {
                    "accepted" => "diterima",
                    "rejected" => "ditolak",
                    _ => "di-clip",
                },
                bits[0],
                bits[1]
            ),
            N::Class(c) => match c.as_str() {
                "rational" => "rasional",
                "one_surd" => "satu bentuk akar",
                "several_surds" => "beberapa bentuk akar",
                _ => "tanpa bentuk eksak",
            }
            .into(),
            N::OfVariants(k, n) if k == n => format!("semua {n}"),
            N::OfVariants(k, n) => format!("{k} dari {n}"),
            N::MarksVary => "tidak sama di setiap varian".into(),
            N::Distinct(k, n) => format!("{k} berbeda dari {n}"),
            N::Spread => "Rentang bilangan setiap jawaban pada semua varian".into(),
        }
    }

    fn bench(&self, w: B) -> &'static str {
        match w {
            B::Stage => "tahap",
            B::Precision => "presisi",
            B::Cases => "kasus",
            B::TimePerOp => "waktu/operasi (median)",
            B::MaxUlpsInt => "ulps maks (bulat ≤ 2^20)",
            B::MedianUlpsInt => "ulps median (bulat ≤ 2^20)",
            B::MaxUlpsWide => "ulps maks (1e-30…1e30)",
            B::Target => "target ≤ 4 ulps",
            B::Exact => "eksak",
            B::NoTarget => "(tanpa target)",
            B::Met => "tercapai",
            B::NotMet => "TIDAK tercapai",
            B::UlpsNote => "ulps: dari nilai eksak (dari 1 untuk vektor satuan u, v, n), pada presisi barisnya;\n\
                 hasil jalur eksak adalah acuannya (dibulatkan benar ke f64 lebih dulu).\n",
            B::Disagreements => "kasus ketika jalur float gagal tetapi jalur eksak tidak, atau sebaliknya (overflow pada f32 adalah kesalahan)",
            B::Unreferenced => "komponen tanpa acuan eksak (akar kuadrat yang tidak dapat difaktorkan `Real`; tidak dihitung)",
        }
    }

    fn mistake(&self, c: Code) -> &'static str {
        super::mistakes::mistake(c)
    }

    fn practice(&self, w: &P) -> String {
        match w {
            P::Title {
                title,
                values,
                seed: Some(s),
            } => format!("Latihan: {title} ({values} nilai, seed {s})"),
            P::Title {
                title,
                values,
                seed: None,
            } => format!("Latihan: {title} ({values} nilai)"),
            P::HowToAnswer => "Jawab setiap nilai yang ditanyakan. Angka: 0,8 atau 4/5 atau sqrt(2)/2; titik: \
                 (x, y, z). Dengan koma desimal, pisahkan komponen dengan ; (0,8; 0,6; 0). \
                 Perintah: petunjuk, lihat (langkahnya), lewati, kembali (ke nilai sebelumnya), \
                 keluar.".into(),
            P::Answer => "Jawaban".into(),
            P::Skipped => "Dilewati.".into(),
            P::AgainEmpty => "Ketik jawaban, atau perintah: petunjuk, lihat, lewati, kembali, keluar.".into(),
            P::FirstValue => "Ini nilai pertama: tidak ada langkah sebelumnya.".into(),
            P::NoMoreHints => "Petunjuk sudah habis: ketik lihat untuk melihat langkahnya.".into(),
            P::Exact => "✓ benar".into(),
            P::Tolerance => "✓ benar (dalam toleransi)".into(),
            P::Rounded => "✓ benar (dibulatkan)".into(),
            P::FollowThrough => "✓ benar menurut jawabanmu sebelumnya".into(),
            P::TooCoarse => "½ benar, tetapi pembulatannya terlalu kasar: tulis lebih banyak angka penting".into(),
            P::Wrong => "✗ salah".into(),
            P::Unreadable { why, how } => {
                format!("✗ jawaban ini tidak terbaca:{why} tulis {how}, atau sebuah perintah")
            }
            P::ReadAs => "dibaca sebagai".into(),
            P::SecondTry => "(percobaan kedua: ditampilkan dan dihitung terpisah; penilaian pertama yang dipakai untuk nilai)".into(),
            P::ShownBefore => "(nilai ini sudah ditampilkan: jawabannya dinilai dan dihitung terpisah; nilainya dihitung sebagai dilihat)".into(),
            P::AlsoShown(keys) => format!("(langkah ini juga menampilkan {keys}: nilai-nilai itu dihitung sebagai dilihat)"),
            P::LikelyMistake => "Kemungkinan kesalahan".into(),
            P::SourceWrong => "Sumber mencetak nilai ini, dan nilai itu salah".into(),
            P::NoMistakeTip => "Tidak ada kesalahan yang dikenal yang menjelaskan jawaban ini. Ketik kembali untuk mencoba nilai ini lagi (petunjuk dan lihat membantu di sana).".into(),
            P::NoHint => "Tidak ada petunjuk untuk nilai ini.".into(),
            P::Hint1(title) => format!("Petunjuk 1: {title}"),
            P::Hint2 => "Petunjuk 2: nilai-nilai yang disubstitusikan (langkah terakhir milikmu)".into(),
            P::NoValues => "(setiap nilai langkah ini akan membocorkan jawabannya: substitusikan bilangan dari soal, atau ketik lihat)".into(),
            P::MistakesMade => "Kesalahan yang dibuat:".into(),
            P::PractiseNext => "Latihan berikutnya".into(),
            P::SegmentShape => "(x0, y0, z0); (x1, y1, z1), atau tidak ada".into(),
            P::BitsShape => "6 bit, bit 1 paling kanan".into(),
            P::MatrixShape => "4 baris (a; b; c; d); (…); …".into(),
            P::NumberShape => "sebuah bilangan".into(),
            P::YesNoShape => "ya | tidak".into(),
            P::ValuesShape(n) => format!("({n} nilai)"),
        }
    }

    fn practice_summary(&self, s: &Summary) -> String {
        let pts = dec(s.points, 4, self.nums());
        let pct = dec(percent(s.points, s.total), 4, self.nums());
        let mut out = format!(
            "Ringkasan: {pts}/{} poin = {pct}% (jawaban yang ditanyakan soal; {} langkah)\n  benar {} ({} benar lanjutan), terlalu kasar {}, salah {},\n  dilewati {}, dilihat {}, belum dijawab {}; petunjuk dipakai {}\n",
            s.total, s.steps, s.correct, s.follow_through, s.too_coarse, s.wrong, s.skipped, s.revealed, s.unanswered, s.hints
        );
        if s.retries > 0 {
            out.push_str(&format!(
                "  percobaan kedua {} ({} benar), tidak masuk nilai\n",
                s.retries, s.retries_correct
            ));
        }
        out
    }
}
