//! The words of the report writers' own headings, columns and notes (class
//! report, practice, check, Moodle, GIFT, …): one method per writer's key
//! enum (`crate::msg::report`), and per tutor enum a writer names, each one
//! exhaustive match in every language. The language-neutral parts (a
//! number written in a language's style) are plain functions here.

use crate::msg::{
    BenchWord, CheckWord, ClassWord, CliWord, DocWord, PlanWord, PracticeWord, QuizWord, StatWord,
};
use crate::num::format::fmt_dec;
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
    style.number(&fmt_dec(x, digits))
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
        PracticeWord as P, QuizWord as Q, StatWord as S,
    };
    use crate::report::lang::Lang;
    use crate::report::words::of;
    use crate::tutor::check::Verdict;
    use crate::tutor::class::same::Same;
    use crate::tutor::class::stats::Flag;
    use crate::tutor::class::{Note, Skip};

    /// Every key's words in one language, one string per key (each
    /// enum's keys listed by `listed`, so a key added and not listed here
    /// does not compile).
    fn every_word(lang: Lang) -> Vec<String> {
        let w = of(lang);
        let mut v: Vec<String> = every_class().iter().map(|k| w.class(k)).collect();
        v.extend(every_check().iter().map(|k| w.check(k)));
        v.extend(every_doc().iter().map(|k| w.doc(k)));
        v.extend(every_quiz().iter().map(|k| w.quiz(k)));
        v.extend(every_practice().iter().map(|k| w.practice(k)));
        v.extend(every_stat().map(|k| w.stat(k)));
        v.extend(every_bench().map(|k| w.bench(k).to_string()));
        v.extend(every_plan().iter().map(|k| w.plan(k)));
        v.extend(every_cli().map(|k| w.cli(k).to_string()));
        v.extend(
            Verdict::words()
                .into_iter()
                .map(|k| w.verdict(k).to_string()),
        );
        v.extend([Note::Empty, Note::NotMarked].map(|k| w.note(k).to_string()));
        v.extend([Skip::Subdirectory, Skip::NotToml].map(|k| w.skip(k).to_string()));
        v.extend(
            [Same::Name, Same::Nim, Same::Answers, Same::Attempt].map(|k| w.same(k).to_string()),
        );
        let flags = [Flag::VeryEasy, Flag::VeryHard, Flag::Negative];
        v.extend(flags.map(|k| w.flag(k).to_string()));
        v
    }

    fn every_class() -> Vec<C> {
        let summary = |follow_through| C::Summary {
            students: 3,
            tolerance_pct: 0.5,
            sig_figs: 3,
            follow_through,
        };
        let step = C::StepOf {
            part: "problem-02, ".into(),
            number: 3,
            title: "Unit vector n".into(),
        };
        vec![
            C::ClassReport,
            C::Student,
            C::Students,
            C::Score,
            C::FollowThrough,
            C::Mistakes,
            C::Mistake,
            C::Key,
            C::Flag,
            C::Problem,
            C::Title,
            C::Facility,
            C::WholeExam,
            C::Harder,
            C::Easier,
            C::AnswerKeys,
            C::Problems,
            C::Variants,
            C::MistakesHeading,
            C::WrongHeading,
            C::StudentsHeading,
            C::WhoWhich,
            C::Scores,
            summary(true),
            summary(false),
            C::NotMarked,
            C::Definitions,
            C::VariantsNote,
            C::DrawnNote,
            C::RosterHeading,
            C::RosterMissing(2),
            C::RosterNotListed(1),
            C::RosterAll(40),
            C::DuplicatesHeading,
            C::DuplicatesNote,
            C::DuplicateOf {
                kept: "adi (1).toml".into(),
                why: "same name".into(),
            },
            C::FitsHeading,
            C::FitsNote,
            C::Fits {
                variant: 4,
                there: 95.0,
                own: 4.5,
            },
            C::TooFewPerVariant {
                min: 1,
                max: 1,
                need: 5,
            },
            C::TooFewPerVariant {
                min: 1,
                max: 3,
                need: 5,
            },
            C::NoMistake,
            C::WrongNote,
            C::NoneFound,
            C::StudentCount(1),
            C::StudentCount(2),
            C::Explains,
            C::TeachAgain,
            step,
            C::DistributionPct,
            C::Distribution,
            C::ScoreAxis,
        ]
    }

    fn every_check() -> Vec<K> {
        vec![
            K::Answer,
            K::Verdict,
            K::Given,
            K::Expected,
            K::Note,
            K::AnswersOf,
            K::Errata,
            K::Diagnosis,
            K::Reproduces,
            K::AlsoFollow,
            K::NoMistakeExplains,
            K::NotAnswers,
            K::Score,
            K::FollowThroughCount(2),
            K::Marks,
            K::Working,
            K::WorkingCount(12, 9),
            K::MethodMarks,
            K::MethodEarned("2".into(), 4),
        ]
    }

    fn every_doc() -> Vec<D> {
        let title = |seed, variant| D::ExamTitle {
            topics: "view".into(),
            difficulty: "easy".into(),
            seed,
            variant,
        };
        let wrote = |files| D::Wrote {
            files,
            variants: 1,
            count: 2,
            topics: "view".into(),
            seed: 7,
            out: "exam".into(),
        };
        vec![
            D::Step,
            D::Answer,
            D::Answers,
            D::Figures,
            D::WorkedSolution,
            D::Problem,
            D::Variant,
            D::Warning,
            D::Error,
            D::MoodleMarked(29, 30),
            D::MoodleUnfinished("Eko".into(), "In progress".into()),
            D::MoodleForeign(4, "What is a pixel?".into()),
            D::MoodleUnreadable(
                "Dewi".into(),
                "problem-01.view.u".into(),
                "tidak tahu".into(),
            ),
            D::MoodleUnreadable("Dewi".into(), "problem-01.view.u".into(), String::new()),
            D::NotesOnSource,
            D::Yes,
            D::No,
            D::NoValue,
            D::ComparedWith,
            D::TheSource,
            D::Printed,
            D::CorrectValue,
            D::Computed,
            D::Value,
            D::Why,
            title(None, None),
            title(Some(7), Some(2)),
            D::KeyTitle("grafika exam: view (easy)".into()),
            D::Marks(1),
            D::Marks(3),
            D::AnswerKey,
            wrote(1),
            wrote(14),
            D::More(2),
            D::SheetTitle {
                difficulty: "hard".into(),
                variant: Some(3),
            },
            D::SheetTitle {
                difficulty: "easy".into(),
                variant: None,
            },
            D::NameLine,
            D::TotalMarks(24),
        ]
    }

    fn every_quiz() -> Vec<Q> {
        let mut v = Vec::new();
        for mark in [Decimal::Point, Decimal::Comma] {
            for pixels in [false, true] {
                v.push(Q::Instructions {
                    figures: 3,
                    pct: "0.5".into(),
                    mark,
                    pixels,
                });
            }
        }
        v.extend([
            Q::TypeOutcodes,
            Q::TypeStatus,
            Q::KnownMistake,
            Q::OrMistake,
            Q::Part,
            Q::FiguresInMoodle,
            Q::Component,
            Q::Point,
            Q::Word("clipped".into()),
            Q::Word("none".into()),
        ]);
        v
    }

    fn every_practice() -> Vec<P> {
        let title = |seed| P::Title {
            title: "Camera basis".into(),
            values: 3,
            seed,
        };
        vec![
            title(None),
            title(Some(7)),
            P::HowToAnswer,
            P::Answer,
            P::Skipped,
            P::AgainEmpty,
            P::FirstValue,
            P::NoMoreHints,
            P::Exact,
            P::Tolerance,
            P::Rounded,
            P::FollowThrough,
            P::TooCoarse,
            P::Wrong,
            P::Unreadable {
                why: String::new(),
                how: "a number".into(),
            },
            P::ReadAs,
            P::SecondTry,
            P::ShownBefore,
            P::AlsoShown("window.left, window.right".into()),
            P::LikelyMistake,
            P::SourceWrong,
            P::NoMistakeTip,
            P::NoHint,
            P::Hint1("Unit vector n".into()),
            P::Hint2,
            P::NoValues,
            P::MistakesMade,
            P::PractiseNext,
            P::SegmentShape,
            P::BitsShape,
            P::MatrixShape,
            P::NumberShape,
            P::YesNoShape,
            P::ValuesShape(5),
        ]
    }

    fn every_stat() -> [S; 22] {
        [
            S::Heading,
            S::TrianglesIn,
            S::Culled,
            S::Rejected,
            S::Clipped,
            S::Drawn,
            S::NoPixels,
            S::ObjectsRejected,
            S::ObjectsInside,
            S::PixelsShaded,
            S::LightingEvals,
            S::PerPixel,
            S::LightsSkipped,
            S::SpecularSkipped,
            S::Geometry { runs: 1 },
            S::Geometry { runs: 5 },
            S::Binning,
            S::Bands,
            S::Raster,
            S::Shading,
            S::Frame,
            S::Png,
        ]
    }

    fn every_bench() -> [B; 15] {
        [
            B::Stage,
            B::Precision,
            B::Cases,
            B::TimePerOp,
            B::MaxUlpsInt,
            B::MedianUlpsInt,
            B::MaxUlpsWide,
            B::Target,
            B::Exact,
            B::NoTarget,
            B::Met,
            B::NotMet,
            B::UlpsNote,
            B::Disagreements,
            B::Unreferenced,
        ]
    }

    fn every_plan() -> Vec<crate::msg::PlanWord> {
        use crate::msg::PlanWord as N;
        let clip = |status: &str| N::Clip {
            status: status.into(),
            bits: [0, 2],
            tried: 2,
            kept: 1,
        };
        let mut v = vec![
            N::Title,
            N::Heading {
                variants: 40,
                total: 24,
            },
            N::Topic,
            N::Case,
            N::Numbers,
            N::Marks,
            N::Statements,
            N::Points(2),
            N::Model("blinn".into()),
            clip("clipped"),
            clip("accepted"),
            clip("rejected"),
            N::OfVariants(39, 40),
            N::MarksVary,
            N::Distinct(40, 40),
            N::Spread,
        ];
        let classes = ["rational", "one_surd", "several_surds", "no_closed_form"];
        v.extend(classes.map(|c| N::Class(c.into())));
        for k in &v {
            match k {
                N::Title
                | N::Heading { .. }
                | N::Topic
                | N::Case
                | N::Numbers
                | N::Marks
                | N::Statements
                | N::Points(_)
                | N::Model(_)
                | N::Clip { .. }
                | N::Class(_)
                | N::OfVariants(..)
                | N::MarksVary
                | N::Distinct(..)
                | N::Spread => {}
            }
        }
        v
    }

    fn every_cli() -> [L; 6] {
        [
            L::WorkedSolution,
            L::Measuring,
            L::Frames,
            L::Problems,
            L::Arguments,
            L::TheText,
        ]
    }

    /// Fails to compile when a key is added and not listed above.
    #[allow(dead_code)]
    fn listed(c: &C, k: &K, d: &D, q: &Q, p: &P, (s, b, l): (S, B, L)) {
        use C::*;
        match c {
            ClassReport
            | Student
            | Students
            | Score
            | FollowThrough
            | Mistakes
            | Mistake
            | Key
            | Flag
            | Problem
            | Title
            | Facility
            | WholeExam
            | Harder
            | Easier
            | AnswerKeys
            | Problems
            | Variants
            | MistakesHeading
            | WrongHeading
            | StudentsHeading
            | WhoWhich
            | Scores
            | Summary { .. }
            | NotMarked
            | Definitions
            | VariantsNote
            | DrawnNote
            | TooFewPerVariant { .. }
            | RosterHeading
            | RosterMissing(_)
            | RosterNotListed(_)
            | RosterAll(_)
            | DuplicatesHeading
            | DuplicatesNote
            | DuplicateOf { .. }
            | FitsHeading
            | FitsNote
            | Fits { .. }
            | NoMistake
            | WrongNote
            | NoneFound
            | StudentCount(_)
            | Explains
            | TeachAgain
            | StepOf { .. }
            | DistributionPct
            | Distribution
            | ScoreAxis => {}
        }
        match k {
            K::Answer
            | K::Verdict
            | K::Given
            | K::Expected
            | K::Note
            | K::AnswersOf
            | K::Errata
            | K::Diagnosis
            | K::Reproduces
            | K::AlsoFollow
            | K::NoMistakeExplains
            | K::NotAnswers
            | K::Score
            | K::FollowThroughCount(_)
            | K::Marks
            | K::Working
            | K::WorkingCount(..)
            | K::MethodMarks
            | K::MethodEarned(..) => {}
        }
        match d {
            D::Step
            | D::Answer
            | D::Answers
            | D::Figures
            | D::WorkedSolution
            | D::Problem
            | D::Variant
            | D::Warning
            | D::Error
            | D::MoodleMarked(..)
            | D::MoodleUnfinished(..)
            | D::MoodleForeign(..)
            | D::MoodleUnreadable(..)
            | D::NotesOnSource
            | D::Yes
            | D::No
            | D::NoValue
            | D::ComparedWith
            | D::TheSource
            | D::Printed
            | D::CorrectValue
            | D::Computed
            | D::Value
            | D::Why
            | D::ExamTitle { .. }
            | D::KeyTitle(_)
            | D::Marks(_)
            | D::AnswerKey
            | D::Wrote { .. }
            | D::More(_)
            | D::SheetTitle { .. }
            | D::NameLine
            | D::TotalMarks(_) => {}
        }
        match q {
            Q::Instructions { .. }
            | Q::TypeOutcodes
            | Q::TypeStatus
            | Q::KnownMistake
            | Q::OrMistake
            | Q::Part
            | Q::FiguresInMoodle
            | Q::Component
            | Q::Point
            | Q::Word(_) => {}
        }
        match p {
            P::Title { .. }
            | P::HowToAnswer
            | P::Answer
            | P::Skipped
            | P::AgainEmpty
            | P::FirstValue
            | P::NoMoreHints
            | P::Exact
            | P::Tolerance
            | P::Rounded
            | P::FollowThrough
            | P::TooCoarse
            | P::Wrong
            | P::Unreadable { .. }
            | P::ReadAs
            | P::SecondTry
            | P::ShownBefore
            | P::AlsoShown(_)
            | P::LikelyMistake
            | P::SourceWrong
            | P::NoMistakeTip
            | P::NoHint
            | P::Hint1(_)
            | P::Hint2
            | P::NoValues
            | P::MistakesMade
            | P::PractiseNext
            | P::SegmentShape
            | P::BitsShape
            | P::MatrixShape
            | P::NumberShape
            | P::YesNoShape
            | P::ValuesShape(_) => {}
        }
        match s {
            S::Heading
            | S::TrianglesIn
            | S::Culled
            | S::Rejected
            | S::Clipped
            | S::Drawn
            | S::NoPixels
            | S::ObjectsRejected
            | S::ObjectsInside
            | S::PixelsShaded
            | S::LightingEvals
            | S::PerPixel
            | S::LightsSkipped
            | S::SpecularSkipped
            | S::Geometry { .. }
            | S::Binning
            | S::Bands
            | S::Raster
            | S::Shading
            | S::Frame
            | S::Png => {}
        }
        match b {
            B::Stage
            | B::Precision
            | B::Cases
            | B::TimePerOp
            | B::MaxUlpsInt
            | B::MedianUlpsInt
            | B::MaxUlpsWide
            | B::Target
            | B::Exact
            | B::NoTarget
            | B::Met
            | B::NotMet
            | B::UlpsNote
            | B::Disagreements
            | B::Unreferenced => {}
        }
        match l {
            L::WorkedSolution
            | L::Measuring
            | L::Frames
            | L::Problems
            | L::Arguments
            | L::TheText => {}
        }
    }

    #[test]
    fn every_report_word_is_written_in_both_languages() {
        for lang in Lang::ALL {
            for w in every_word(lang) {
                assert!(!w.trim().is_empty() && w != "?", "{lang:?}: {w:?}");
            }
        }
    }

    #[test]
    fn most_report_words_differ_between_languages() {
        let (en, id) = (every_word(Lang::En), every_word(Lang::Id));
        assert_eq!(en.len(), id.len());
        let same: Vec<&String> = (en.iter().zip(&id))
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
