//! The words of the report writers' own headings, columns and notes (class
//! report, practice, check, Moodle, GIFT, …): one method per writer's key
//! enum (`crate::msg::report`), and per tutor enum a writer names, each one
//! exhaustive match in every language. The language-neutral parts (a
//! number written in a language's style) are plain functions here.

use crate::msg::{
    BenchWord, CheckWord, ClassWord, CliWord, DocWord, PlanWord, PracticeWord, QuizWord, StatWord,
};
use crate::report::lang::NumStyle;
use crate::tutor::check::Verdict;
use crate::tutor::class::same::Same;
use crate::tutor::class::stats::Flag;
use crate::tutor::class::{Note, Skip};
use crate::tutor::diagnose::Code;
use crate::tutor::practice::Summary;

/// The words of the report writers' own headings, columns and notes.
pub trait ReportWords {
    /// A word of the class report.
    fn class(&self, w: &ClassWord) -> String;
    /// What was done with an unusual answer file.
    fn note(&self, n: Note) -> &'static str;
    /// Why an entry of the answers folder was skipped.
    fn skip(&self, s: Skip) -> &'static str;
    /// A flag on a key of the class report.
    fn flag(&self, f: Flag) -> &'static str;
    /// Why two answer files are the same student.
    fn same(&self, s: Same) -> &'static str;
    /// A verdict's word (every way of being correct has one; also a
    /// column of the class's tables).
    fn verdict(&self, v: Verdict) -> &'static str;
    /// A word of a marked answer file.
    fn check(&self, w: &CheckWord) -> String;
    /// A word the documents share.
    fn doc(&self, w: &DocWord) -> String;
    /// A word of a quiz (Moodle XML, GIFT).
    fn quiz(&self, w: &QuizWord) -> String;
    /// A word of the command line itself.
    fn cli(&self, w: CliWord) -> &'static str;
    /// A line of `render --stats`.
    fn stat(&self, w: StatWord) -> String;
    /// A word of `grafika bench`'s table.
    fn bench(&self, w: BenchWord) -> &'static str;
    /// A word of an exam's blueprint.
    fn plan(&self, w: &PlanWord) -> String;
    /// What the student did, by a mistake of the catalog.
    fn mistake(&self, c: Code) -> &'static str;
    /// A word of `grafika practice`.
    fn practice(&self, w: &PracticeWord) -> String;
    /// A practice session's summary: the points, the counts, the second
    /// tries (each line ends with a newline).
    fn practice_summary(&self, s: &Summary) -> String;
}

/// `x` with at most `digits` decimals, in `style`: `0.5` or `0,5`.
pub fn dec(x: f64, digits: usize, style: NumStyle) -> String {
    style.dec(x, digits)
}

/// A share of a total as a percentage to one decimal (`88.9` for 8 of
/// 9; 100 for a total of 0).
pub fn percent(points: f64, total: u32) -> f64 {
    match total {
        0 => 100.0,
        t => (points / f64::from(t) * 1000.0).round() / 10.0,
    }
}

/// A lighting model's name as the text writes it, by its file name:
/// `Phong`, `Blinn–Phong`, `Lambert`.
pub fn model_name(file: &str) -> &str {
    match file {
        "phong" => "Phong",
        "blinn" => "Blinn–Phong",
        "lambert" => "Lambert",
        "ambient" => "ambient",
        "diffuse" => "diffuse",
        "specular" => "specular",
        other => other,
    }
}

/// An exam's title: `name: topics (difficulty), seed s, variant v`, the
/// variant with its word.
pub fn exam_title(
    name: &str,
    (topics, difficulty): (&str, &str),
    seed: Option<u64>,
    variant: Option<(String, u32)>,
) -> String {
    format!(
        "{name}: {topics} ({difficulty}){}{}",
        seed.map(|s| format!(", seed {s}")).unwrap_or_default(),
        variant
            .map(|(word, v)| format!(", {word} {v}"))
            .unwrap_or_default()
    )
}

#[cfg(test)]
mod tests {
    use crate::msg::{
        BenchWord as B, CheckWord as K, ClassWord as C, CliWord as L, Decimal, DocWord as D,
        PlanWord as N, PracticeWord as P, QuizWord as Q, StatWord as S,
    };
    use crate::report::lang::Lang;
    use crate::report::words::of;
    use crate::stages::clip::Status;
    use crate::tutor::check::Verdict;
    use crate::tutor::class::same::Same;
    use crate::tutor::class::stats::Flag;
    use crate::tutor::class::{Note, Skip};
    use crate::tutor::generate::numbers::NumberClass;
    use strum::IntoEnumIterator;

    /// Every key's words in one language, one string per key (with the
    /// key, to name it): every
    /// variant of each key enum (`EnumIter`, its fields at their
    /// defaults, so a key added is tested without being listed), then
    /// the samples whose words depend on their values.
    fn every_word(lang: Lang) -> Vec<(String, String)> {
        let w = of(lang);
        let mut v = said(C::iter().chain(class_samples()), |k| w.class(k));
        v.extend(said(K::iter(), |k| w.check(k)));
        v.extend(said(D::iter().chain(doc_samples()), |k| w.doc(k)));
        v.extend(said(quiz_keys(), |k| w.quiz(k)));
        v.extend(said(P::iter().chain(practice_samples()), |k| w.practice(k)));
        let runs = [S::Geometry { runs: 1 }, S::Geometry { runs: 5 }];
        v.extend(said(S::iter().chain(runs), |k| w.stat(*k)));
        v.extend(said(B::iter(), |k| w.bench(*k).into()));
        v.extend(said(plan_keys(), |k| w.plan(k)));
        v.extend(said(L::iter(), |k| w.cli(*k).into()));
        v.extend(said(Verdict::words(), |k| w.verdict(*k).into()));
        v.extend(said(Note::iter(), |k| w.note(*k).into()));
        v.extend(said(Skip::iter(), |k| w.skip(*k).into()));
        v.extend(said(Same::iter(), |k| w.same(*k).into()));
        v.extend(said(Flag::iter(), |k| w.flag(*k).into()));
        v
    }

    /// Each key (as `Debug` writes it, to name it in a failure) with its
    /// words.
    fn said<K: std::fmt::Debug>(
        keys: impl IntoIterator<Item = K>,
        words: impl Fn(&K) -> String,
    ) -> Vec<(String, String)> {
        (keys.into_iter())
            .map(|k| (format!("{k:?}"), words(&k)))
            .collect()
    }

    /// The class report's keys whose words depend on their values.
    fn class_samples() -> Vec<C> {
        vec![
            // the summary's last sentence: follow-through on (off is the default)
            C::Summary {
                students: 3,
                tolerance_pct: 0.5,
                sig_figs: 3,
                follow_through: true,
            },
            // a range of students per variant, not one number
            C::TooFewPerVariant {
                min: 1,
                max: 3,
                need: 5,
            },
            // the singular
            C::StudentCount(1),
        ]
    }

    /// The documents' keys whose words depend on their values.
    fn doc_samples() -> Vec<D> {
        let wrote = |files| D::Wrote {
            files,
            variants: 1,
            count: 2,
            topics: "view".into(),
            seed: 7,
            out: "exam".into(),
        };
        vec![
            // the reader's reason, when there is one
            D::MoodleUnreadable("Dewi".into(), "problem-01.view.u".into(), "tidak".into()),
            // a seed and a variant named
            D::ExamTitle {
                topics: "view".into(),
                difficulty: "easy".into(),
                seed: Some(7),
                variant: Some(2),
            },
            // the singulars
            D::Marks(1),
            wrote(1),
            wrote(14),
            // a variant named
            D::SheetTitle {
                difficulty: "hard".into(),
                variant: Some(3),
            },
        ]
    }

    /// Every quiz key: the instructions in each decimal mark, with and
    /// without pixels; `Word` carries a code whose words it gives (its
    /// default, the empty code, has none), so each clipping status and
    /// `none`.
    fn quiz_keys() -> Vec<Q> {
        let mut v: Vec<Q> = Q::iter().filter(|q| !matches!(q, Q::Word(_))).collect();
        for mark in Decimal::iter() {
            for pixels in [false, true] {
                v.push(Q::Instructions {
                    figures: 3,
                    pct: "0.5".into(),
                    mark,
                    pixels,
                });
            }
        }
        let codes = Status::iter().map(Status::as_str).chain(["none"]);
        v.extend(codes.map(|c| Q::Word(c.into())));
        v
    }

    /// The practice keys whose words depend on their values.
    fn practice_samples() -> [P; 1] {
        // a seed named
        [P::Title {
            title: "Camera basis".into(),
            values: 3,
            seed: Some(7),
        }]
    }

    /// Every blueprint key: a clipping status and a number class carry
    /// the code whose words they give, so each real code replaces the
    /// empty default.
    fn plan_keys() -> Vec<N> {
        let coded = |k: &N| matches!(k, N::Clip { .. } | N::Class(_));
        let mut v: Vec<N> = N::iter().filter(|k| !coded(k)).collect();
        v.extend(Status::iter().map(|s| N::Clip {
            status: s.as_str().into(),
            bits: [0, 2],
            tried: 2,
            kept: 1,
        }));
        v.extend(NumberClass::iter().map(|c| N::Class(c.name().into())));
        v
    }

    #[test]
    fn every_report_word_is_written_in_both_languages() {
        for lang in Lang::ALL {
            for (key, w) in every_word(lang) {
                assert!(!w.trim().is_empty() && w != "?", "{key} in {lang:?}: {w:?}");
            }
        }
    }

    #[test]
    fn most_report_words_differ_between_languages() {
        let (en, id) = (every_word(Lang::En), every_word(Lang::Id));
        assert_eq!(en.len(), id.len());
        let same: Vec<&(String, String)> = (en.iter().zip(&id))
            .filter(|(e, i)| e == i)
            .map(|(e, _)| e)
            .collect();
        // the course's own loanwords and notation: follow-through,
        // Diagnosis:, the bench's target in ulps
        assert!(same.len() <= 3, "{same:?}");
    }

    #[test]
    fn sentences_write_their_numbers_in_the_language_style() {
        let summary = C::Summary {
            students: 12,
            tolerance_pct: 0.5,
            sig_figs: 3,
            follow_through: false,
        };
        let en = of(Lang::En).class(&summary);
        let id = of(Lang::Id).class(&summary);
        assert!(
            en.starts_with("12 students marked; tolerance 0.5 %"),
            "{en}"
        );
        assert!(en.ends_with("follow-through off."), "{en}");
        assert!(
            id.starts_with("12 mahasiswa dinilai; toleransi 0,5 %"),
            "{id}"
        );
        assert!(
            id.ends_with(
                "penilaian lanjutan (benar menurut jawaban sendiri sebelumnya) tidak aktif."
            ),
            "{id}"
        );
    }

    #[test]
    fn english_counts_take_their_plural() {
        let wrote = |files, variants, count| D::Wrote {
            files,
            variants,
            count,
            topics: "view".into(),
            seed: 7,
            out: "exam".into(),
        };
        assert_eq!(
            of(Lang::En).doc(&wrote(1, 1, 1)),
            "wrote 1 file (1 variant of 1 view problem, seed 7) to exam"
        );
        assert_eq!(
            of(Lang::En).doc(&wrote(4, 2, 2)),
            "wrote 4 files (2 variants of 2 view problems, seed 7) to exam"
        );
        assert_eq!(
            of(Lang::Id).doc(&wrote(4, 2, 2)),
            "4 berkas ditulis (2 varian dari 2 soal view, seed 7) ke exam"
        );
        assert_eq!(of(Lang::En).class(&C::StudentCount(1)), "student");
        assert_eq!(of(Lang::En).class(&C::StudentCount(0)), "students");
        assert_eq!(of(Lang::Id).class(&C::StudentCount(3)), "mahasiswa");
    }

    #[test]
    fn an_exam_title_names_its_seed_and_variant_in_the_language() {
        let title = D::ExamTitle {
            topics: "view, clip".into(),
            difficulty: "hard".into(),
            seed: Some(42),
            variant: Some(3),
        };
        assert_eq!(
            of(Lang::En).doc(&title),
            "grafika exam: view, clip (hard), seed 42, variant 3"
        );
        assert_eq!(
            of(Lang::Id).doc(&title),
            "ujian grafika: view, clip (hard), seed 42, varian 3"
        );
    }
}
