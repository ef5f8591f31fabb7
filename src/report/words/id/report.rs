//! The report writers' own words in Bahasa Indonesia: the class report's
//! headings, columns and sentences, the notes on answer files, … (one
//! exhaustive match per key enum; a word table, long on purpose).

use super::Id;
use crate::msg::ClassWord as C;
use crate::report::lang::NumStyle;
use crate::report::words::report::{dec, ReportWords};
use crate::tutor::class::stats::Flag;
use crate::tutor::class::{Note, Skip};

impl ReportWords for Id {
    fn class(&self, w: &C) -> String {
        match w {
            C::ClassReport => "Laporan kelas".into(),
            C::Student => "mahasiswa".into(),
            C::Students => "mahasiswa".into(),
            C::Score => "nilai".into(),
            C::Correct => "benar".into(),
            C::FollowThrough => "follow-through".into(),
            C::TooCoarse => "terlalu kasar".into(),
            C::Wrong => "salah".into(),
            C::Missing => "tidak dijawab".into(),
            C::Unparseable => "tidak terbaca".into(),
            C::Mistakes => "kesalahan konsep".into(),
            C::Mistake => "kesalahan".into(),
            C::Variant => "varian".into(),
            C::Error => "kesalahan".into(),
            C::Key => "kunci".into(),
            C::Flag => "tanda".into(),
            C::Problem => "soal".into(),
            C::Title => "judul".into(),
            C::Facility => "tingkat kemudahan p".into(),
            C::WholeExam => "seluruh ujian".into(),
            C::Expected => "seharusnya".into(),
            C::Given => "diberikan".into(),
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
                "{students} mahasiswa dinilai; toleransi {} %, paling sedikit {sig_figs} angka penting, follow-through {}.",
                dec(*tolerance_pct, 4, NumStyle::COMMA),
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
            C::VariantsNote => "Setiap sel adalah tingkat kemudahan varian pada soal itu; ▼ menandai varian yang lebih dari 0,20 di bawah median varian lainnya pada soal itu (▲ di atasnya).".into(),
            C::NoMistake => "Tidak ada kesalahan yang dikenal yang menjelaskan jawaban salah.".into(),
            C::WrongNote => "Nilai yang sama dalam batas toleransi dihitung bersama; yang paling sering lebih dulu. Nilai yang sama pada banyak mahasiswa bisa jadi kesalahan yang belum dikenal katalog, atau kunci yang salah.".into(),
            C::NoneFound => "Tidak ada.".into(),
            C::StudentCount(_) => "mahasiswa".into(),
            C::Explains => "Menjelaskan".into(),
            C::TeachAgain => "Ajarkan lagi".into(),
            C::AlsoFollow => "sebagian juga dapat berasal dari".into(),
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

    fn flag(&self, f: Flag) -> &'static str {
        match f {
            Flag::VeryEasy => "sangat mudah",
            Flag::VeryHard => "sangat sulit",
            Flag::Negative => "negatif",
        }
    }
}
