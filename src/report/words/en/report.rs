//! The report writers' own words in English: the class report's headings,
//! columns and sentences, the notes on answer files, … (one exhaustive
//! match per key enum; a word table, long on purpose).

use super::En;
use crate::msg::ClassWord as C;
use crate::report::lang::NumStyle;
use crate::report::words::report::{dec, ReportWords};
use crate::tutor::class::stats::Flag;
use crate::tutor::class::{Note, Skip};

impl ReportWords for En {
    fn class(&self, w: &C) -> String {
        match w {
            C::ClassReport => "Class report".into(),
            C::Student => "student".into(),
            C::Students => "students".into(),
            C::Score => "score".into(),
            C::Correct => "correct".into(),
            C::FollowThrough => "follow-through".into(),
            C::TooCoarse => "too coarse".into(),
            C::Wrong => "wrong".into(),
            C::Missing => "missing".into(),
            C::Unparseable => "unparseable".into(),
            C::Mistakes => "mistakes".into(),
            C::Mistake => "mistake".into(),
            C::Variant => "variant".into(),
            C::Error => "error".into(),
            C::Key => "key".into(),
            C::Flag => "flag".into(),
            C::Problem => "problem".into(),
            C::Title => "title".into(),
            C::Facility => "facility p".into(),
            C::WholeExam => "whole exam".into(),
            C::Expected => "expected".into(),
            C::Given => "given".into(),
            C::Harder => "harder".into(),
            C::Easier => "easier".into(),
            C::AnswerKeys => "Answer keys".into(),
            C::Problems => "Problems".into(),
            C::Variants => "Variants".into(),
            C::MistakesHeading => "Mistakes".into(),
            C::WrongHeading => "Wrong answers no mistake explains".into(),
            C::StudentsHeading => "Students".into(),
            C::WhoWhich => "Who made which mistake".into(),
            C::Scores => "Scores".into(),
            C::Summary {
                students,
                tolerance_pct,
                sig_figs,
                follow_through,
            } => format!(
                "{students} students marked; tolerance {} %, at least {sig_figs} significant figures, follow-through {}.",
                dec(*tolerance_pct, 4, NumStyle::POINT),
                if *follow_through { "on" } else { "off" }
            ),
            C::NotMarked => "Not marked (not counted below):".into(),
            C::Definitions => "Correct: how many, and in brackets how many exact / correctly rounded / within the tolerance. \
                 A key's mark is 1 when correct, ½ when too coarse, 0 otherwise; a student's score is the sum of the marks. \
                 Facility p: the mean mark, the share of full marks (very easy above 0.90, very hard below 0.20). \
                 Discrimination D: the mean mark of the upper 27 % of the class by score minus that of the lower 27 % \
                 (students tied at a group's edge share its places); from −1 to 1. \
                 Point-biserial r: the correlation of the key's mark with the rest of the score (the score without this key); \
                 — when everyone has the same mark. A key with D or r below 0 discriminates negatively (flag: negative): \
                 the weaker students do better on it, so check its key or its question.".into(),
            C::VariantsNote => "Each cell is the variant's facility on the problem; ▼ marks a variant more than 0.20 below the median of its siblings on that problem (▲ above).".into(),
            C::NoMistake => "No known mistake explains a wrong answer.".into(),
            C::WrongNote => "Values equal within the tolerance are counted together; the most common first. A value many students share may be a mistake the catalog does not know yet, or a wrong key.".into(),
            C::NoneFound => "None.".into(),
            C::StudentCount(1) => "student".into(),
            C::StudentCount(_) => "students".into(),
            C::Explains => "Explains".into(),
            C::TeachAgain => "Teach again".into(),
            C::AlsoFollow => "some of these also follow from".into(),
            C::StepOf {
                part,
                number,
                title,
            } => format!("{part}step {number} of the worked solution: {title}"),
            C::DistributionPct => "Score distribution (% of the marks)".into(),
            C::Distribution => "Score distribution".into(),
            C::ScoreAxis => "score, % of the marks".into(),
        }
    }

    fn note(&self, n: Note) -> &'static str {
        match n {
            Note::Empty => "holds no answers: marked with every answer missing",
            Note::NotMarked => {
                "not marked: the file is not a valid answer file (see the error in its row)"
            }
        }
    }

    fn skip(&self, s: Skip) -> &'static str {
        match s {
            Skip::Subdirectory => "skipped: a subdirectory (its files are not read)",
            Skip::NotToml => "skipped: not a .toml file",
        }
    }

    fn flag(&self, f: Flag) -> &'static str {
        match f {
            Flag::VeryEasy => "very easy",
            Flag::VeryHard => "very hard",
            Flag::Negative => "negative",
        }
    }
}
