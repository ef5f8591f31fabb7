//! The report writers' own words in English: the class report's headings,
//! columns and sentences, the notes on answer files, … (one exhaustive
//! match per key enum; a word table, long on purpose).

use super::En;
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
use crate::tutor::check::Verdict;
use crate::tutor::class::same::Same;
use crate::tutor::class::stats::Flag;
use crate::tutor::class::{Note, Skip};
use crate::tutor::diagnose::Code;
use crate::tutor::practice::Summary;

impl ReportWords for En {
    fn class(&self, w: &C) -> String {
        match w {
            C::ClassReport => "Class report".into(),
            C::Student => "student".into(),
            C::Students => "students".into(),
            C::Score => "score".into(),
            C::FollowThrough => "follow-through".into(),
            C::Mistakes => "mistakes".into(),
            C::Mistake => "mistake".into(),
            C::Key => "key".into(),
            C::Flag => "flag".into(),
            C::Problem => "problem".into(),
            C::Title => "title".into(),
            C::Facility => "facility p".into(),
            C::WholeExam => "whole exam".into(),
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
                dec(*tolerance_pct, 4, self.nums()),
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
            C::VariantsNote => "Each cell is the variant's facility on the problem; n is the number of students who answered the variant. \
                 A variant is compared with the rest of the class only when both have at least 5 students: a two-proportion z-test of its facility \
                 against the rest's, the p-values of one problem's variants corrected together by Holm's method; ▼ harder (▲ easier) marks a corrected p below 0.05.".into(),
            C::DrawnNote => "In the Moodle quiz each problem's variant was drawn by itself, so a student's variant is written per problem \
                 (2/1/2: problem 1 of variant 2, problem 2 of variant 1, …). A problem's cell counts the students who had that problem \
                 of that variant, n those who had any problem of it, and the whole exam is no one variant's.".into(),
            C::RosterHeading => "Class list".into(),
            C::RosterMissing(n) => format!("On the class list, no answer file ({n}):"),
            C::RosterNotListed(n) => format!("Answer files of no one on the class list ({n}):"),
            C::RosterAll(n) => format!("Each of the {n} students on the class list handed in one answer file, and every file is theirs."),
            C::DuplicatesHeading => "The same student twice".into(),
            C::DuplicatesNote => "Two files are the same student when their names are the same (the file's student, else its file name without a copy's ending such as \" (1)\"; case and spaces ignored), \
                 or both give the same NIM, or their answers are the same as typed and one of them names no student; two different NIMs are two students. \
                 Of each group the marked file modified last is kept (the same time: the last by name); the others are not counted.".into(),
            C::DuplicateOf { kept, why } => format!("the same student as {kept} ({why}): not counted"),
            C::FitsHeading => "Answers that fit another variant's key".into(),
            C::FitsNote => "Each sheet that scores half the marks or less is marked again against every other variant of the exam; \
                 when another variant's key gives it at least half the marks more, the answers fit that key: copied from a student of that variant, or the file says the wrong variant. \
                 The score counted is still the one against its own variant.".into(),
            C::Fits { variant, there, own } => format!(
                "these answers fit variant {variant}'s key ({} % of the marks there, {} % on its own variant)",
                there.round(),
                own.round()
            ),
            C::TooFewPerVariant { min, max, need } => {
                let n = if min == max { min.to_string() } else { format!("{min}–{max}") };
                format!("Too few students per variant to compare variants: n = {n} (at least {need} per variant are needed), so no variant is flagged harder or easier.")
            }
            C::NoMistake => "No known mistake explains a wrong answer.".into(),
            C::WrongNote => "Values equal within the tolerance are counted together; the most common first. A value many students share may be a mistake the catalog does not know yet, or a wrong key.".into(),
            C::NoneFound => "None.".into(),
            C::StudentCount(1) => "student".into(),
            C::StudentCount(_) => "students".into(),
            C::Explains => "Explains".into(),
            C::TeachAgain => "Teach again".into(),
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

    fn same(&self, s: Same) -> &'static str {
        match s {
            Same::Name => "same name",
            Same::Nim => "same NIM",
            Same::Answers => "same answers, one file naming no student",
            Same::Attempt => "another attempt at the quiz; the highest grade is kept",
        }
    }

    fn flag(&self, f: Flag) -> &'static str {
        match f {
            Flag::VeryEasy => "very easy",
            Flag::VeryHard => "very hard",
            Flag::Negative => "negative",
        }
    }

    fn verdict(&self, v: Verdict) -> &'static str {
        match v {
            Verdict::Exact | Verdict::Rounded | Verdict::Tolerance | Verdict::FollowThrough => {
                "correct"
            }
            Verdict::TooCoarse => "too coarse",
            Verdict::Wrong => "wrong",
            Verdict::Missing => "missing",
            Verdict::Unparseable => "unparseable",
        }
    }

    fn check(&self, w: &K) -> String {
        match w {
            K::Answer => "answer".into(),
            K::Verdict => "verdict".into(),
            K::Given => "given".into(),
            K::Expected => "expected".into(),
            K::Note => "note".into(),
            K::AnswersOf => "answers of".into(),
            K::Errata => "Why the printed answers differ (the problem file's errata):".into(),
            K::Diagnosis => "Diagnosis:".into(),
            K::Reproduces => "reproduces".into(),
            K::AlsoFollow => "some of these also follow from".into(),
            K::NoMistakeExplains => "No known mistake explains".into(),
            K::NotAnswers => "Not answers to this problem (ignored)".into(),
            K::Score => "Score".into(),
            K::FollowThroughCount(n) => format!("({n} of the correct answers by follow-through: right given the student's own earlier answers)"),
            K::Marks => "marks".into(),
            K::Working => "working".into(),
            K::WorkingCount(n, right) => format!("Working shown, not counted in the total: {n} answers, {right} of them right"),
            K::MethodMarks => "Marks for the working (method marks), where the value itself is not right:".into(),
            K::MethodEarned(e, of) => format!("{e} of {of} marks, for"),
        }
    }

    fn doc(&self, w: &D) -> String {
        match w {
            D::Step => "Step".into(),
            D::Answer => "Answer".into(),
            D::Answers => "Answers".into(),
            D::Figures => "Figures".into(),
            D::WorkedSolution => "Worked solution".into(),
            D::Problem => "Problem".into(),
            D::Variant => "variant".into(),
            D::Error => "error".into(),
            D::MoodleMarked(n, of) => format!("re-marked {n} of {of} attempts"),
            D::MoodleUnfinished(who, state) => format!("not finished, not marked: {who} ({state})"),
            D::MoodleForeign(slot, head) => format!("question {slot} is not a problem of this exam, skipped: {head}…"),
            D::MoodleUnreadable(who, key, t) if t.is_empty() => format!("{who}: {key} left empty"),
            D::MoodleUnreadable(who, key, t) => format!("{who}: {key} cannot be read as typed: \"{t}\""),
            D::Warning => "warning".into(),
            D::NotesOnSource => "Notes on the source".into(),
            D::Yes => "yes".into(),
            D::No => "no".into(),
            D::NoValue => "none".into(),
            D::ComparedWith => "Compared with the answers printed in".into(),
            D::TheSource => "the source".into(),
            D::Printed => "printed".into(),
            D::CorrectValue => "correct".into(),
            D::Computed => "computed".into(),
            D::Value => "value".into(),
            D::Why => "why".into(),
            D::ExamTitle {
                topics,
                difficulty,
                seed,
                variant,
            } => exam_title("grafika exam", (topics, difficulty), *seed, variant.map(|v| (self.doc(&D::Variant), v))),
            D::KeyTitle(title) => format!("{title} — answer key"),
            D::Marks(n) => format!("({n} mark{})", plural(*n as usize)),
            D::AnswerKey => "Answer key".into(),
            D::Wrote {
                files,
                variants,
                count,
                topics,
                seed,
                out,
            } => format!(
                "wrote {files} file{} ({variants} variant{} of {count} {topics} problem{}, seed {seed}) to {out}",
                plural(*files),
                plural(*variants as usize),
                plural(*count as usize),
            ),
            D::More(n) => format!("… and {n} more"),
            D::SheetTitle { difficulty, variant } => format!(
                "Computer graphics exam — {} level{}",
                match difficulty.as_str() {
                    "easy" => "easy",
                    "hard" => "hard",
                    _ => "medium",
                },
                variant.map(|v| format!(", variant {v}")).unwrap_or_default()
            ),
            D::NameLine => "Name: ______________________________   Student number (NIM): ________________".into(),
            D::TotalMarks(n) => format!("Total: {n} mark{}", plural(*n as usize)),
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
                    Decimal::Point => "a decimal point (0.5, not 0,5)",
                    Decimal::Comma => "a decimal comma (0,5)",
                };
                let pixel = match pixels {
                    true => "; a pixel position within half a pixel, so a whole pixel is right",
                    false => "",
                };
                format!("Type each number as a decimal with at least {figures} significant figures, not as an exact form such as (√2−1)/2, and with {mark} (a number within {pct} % of the key's is right{pixel}).")
            }
            Q::TypeOutcodes => "Type outcodes as six bits, bit 1 rightmost (e.g. 000010).".into(),
            Q::TypeStatus => "Type the clipping status as accepted, rejected or clipped, and the segment that is left as none when there is none.".into(),
            Q::KnownMistake => "Known mistake: ".into(),
            Q::OrMistake => "; or: ".into(),
            Q::Part => "Part".into(),
            Q::FiguresInMoodle => "GIFT carries no files: the figures of the worked solutions are in the Moodle XML of the same exam only (--format moodle).".into(),
            Q::Word(code) => code.clone(),
            Q::Component => "component".into(),
            Q::Point => "point".into(),
        }
    }

    fn cli(&self, w: L) -> &'static str {
        match w {
            L::WorkedSolution => "worked solution",
            L::Measuring => "measuring",
            L::Frames => "frames",
            L::Problems => "problems",
            L::Arguments => "arguments",
            L::TheText => "the text",
        }
    }

    fn stat(&self, w: S) -> String {
        match w {
            S::Heading => "Stats".into(),
            S::TrianglesIn => "triangles in".into(),
            S::Culled => "back faces culled (closed meshes)".into(),
            S::Rejected => "rejected by outcodes".into(),
            S::Clipped => "clipped (crossing a plane)".into(),
            S::Drawn => "set up and rasterized".into(),
            S::NoPixels => "covering no pixel centre".into(),
            S::ObjectsRejected => "objects rejected whole (bounding box)".into(),
            S::ObjectsInside => "objects inside whole (no clip tests)".into(),
            S::PixelsShaded => "pixels shaded".into(),
            S::LightingEvals => "lighting evaluations".into(),
            S::PerPixel => "per-pixel lighting".into(),
            S::LightsSkipped => "lights skipped (out of range)".into(),
            S::SpecularSkipped => "objects without specular work".into(),
            S::Geometry { runs: 0 | 1 } => "time: geometry".into(),
            S::Geometry { runs } => format!("time: geometry (median of {runs})"),
            S::Binning => "time: binning".into(),
            S::Bands => "time: bands (raster + shading)".into(),
            S::Raster => "thread time: raster".into(),
            S::Shading => "thread time: shading".into(),
            S::Frame => "time: frame".into(),
            S::Png => "time: PNG encoding".into(),
        }
    }

    fn plan(&self, w: &N) -> String {
        let s = |n: usize| if n == 1 { "" } else { "s" };
        match w {
            N::Title => "Exam blueprint".into(),
            N::Heading { variants, total } => format!(
                "Blueprint: {variants} variant{}, each worth {total} mark{}; every variant of a problem asks the same case, number class and marks",
                s(*variants),
                s(*total as usize)
            ),
            N::Topic => "Topic".into(),
            N::Case => "Case".into(),
            N::Numbers => "Numbers".into(),
            N::Marks => "Marks".into(),
            N::Statements => "Statements".into(),
            N::Points(n) => format!("{n} point{}", s(*n)),
            N::Model(m) => format!("{} model", model_name(m)),
            N::Clip { status, bits, tried, kept } => format!(
                "{status}: P0 beyond {} plane{}, P1 beyond {}; {tried} intersection{} tried, {kept} kept",
                bits[0],
                s(bits[0] as usize),
                bits[1],
                s(*tried as usize)
            ),
            N::Class(c) => match c.as_str() {
                "rational" => "rational",
                "one_surd" => "one surd",
                "several_surds" => "several surds",
                _ => "no closed form",
            }
            .into(),
            N::OfVariants(k, n) if k == n => format!("all {n}"),
            N::OfVariants(k, n) => format!("{k} of {n}"),
            N::MarksVary => "not the same in every variant".into(),
            N::Distinct(k, n) => format!("{k} different of {n}"),
            N::Spread => "Range of each answer's numbers over the variants".into(),
        }
    }

    fn bench(&self, w: B) -> &'static str {
        match w {
            B::Stage => "stage",
            B::Precision => "precision",
            B::Cases => "cases",
            B::TimePerOp => "time/op (median)",
            B::MaxUlpsInt => "max ulps (int ≤ 2^20)",
            B::MedianUlpsInt => "median ulps (int ≤ 2^20)",
            B::MaxUlpsWide => "max ulps (1e-30…1e30)",
            B::Target => "target ≤ 4 ulps",
            B::Exact => "exact",
            B::NoTarget => "(no target)",
            B::Met => "met",
            B::NotMet => "NOT met",
            B::UlpsNote => "ulps: of the exact value (of 1 for the unit vectors u, v, n), at the row's precision;\n\
                 the exact path's results are the reference (correctly rounded to f64 first).\n",
            B::Disagreements => "cases where a float run failed but the exact one did not, or the reverse (an overflow at f32 is an error)",
            B::Unreferenced => "components without an exact reference (a square root `Real` cannot factor; not counted)",
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
            } => format!("Practice: {title} ({values} values, seed {s})"),
            P::Title {
                title,
                values,
                seed: None,
            } => format!("Practice: {title} ({values} values)"),
            P::HowToAnswer => "Answer each value when asked. Numbers: 0.8, 4/5, sqrt(2)/2; points: \
                 (x, y, z). With decimal commas, separate the parts by ; (0,8; 0,6; 0). \
                 Commands: hint, show, skip, back, quit.".into(),
            P::Answer => "Answer".into(),
            P::Skipped => "Skipped.".into(),
            P::AgainEmpty => "Type an answer, or a command: hint, show, skip, back, quit.".into(),
            P::FirstValue => "This is the first value: there is nothing to go back to.".into(),
            P::NoMoreHints => "No more hints: type show to see the step worked out.".into(),
            P::Exact => "✓ correct".into(),
            P::Tolerance => "✓ correct (within the tolerance)".into(),
            P::Rounded => "✓ correct (rounded)".into(),
            P::FollowThrough => "✓ correct given your earlier answers (follow-through)".into(),
            P::TooCoarse => "½ right, but rounded too coarsely: write more significant figures".into(),
            P::Wrong => "✗ wrong".into(),
            P::Unreadable { why, how } => {
                format!("✗ cannot read this answer:{why} write {how}, or a command")
            }
            P::ReadAs => "read as".into(),
            P::SecondTry => "(a second try: shown, and counted apart; the first verdict stands for the score)".into(),
            P::ShownBefore => "(this value was shown already: the answer is judged and counted apart; the value counts as revealed)".into(),
            P::AlsoShown(keys) => format!("(this also shows {keys}: they count as revealed)"),
            P::LikelyMistake => "Likely mistake".into(),
            P::SourceWrong => "The source printed this, and it is wrong".into(),
            P::NoMistakeTip => "No known mistake explains this answer. Type back to try this value again (hint and show help there).".into(),
            P::NoHint => "No hint for this value.".into(),
            P::Hint1(title) => format!("Hint 1: {title}"),
            P::Hint2 => "Hint 2: the values to substitute (the last step is yours)".into(),
            P::NoValues => "(every value of this step would give the answer away: substitute the problem's own numbers, or type show)".into(),
            P::MistakesMade => "Mistakes made:".into(),
            P::PractiseNext => "Practise next".into(),
            P::SegmentShape => "(x0, y0, z0); (x1, y1, z1), or none".into(),
            P::BitsShape => "6 bits, bit 1 rightmost".into(),
            P::MatrixShape => "4 rows (a, b, c, d); (…); …".into(),
            P::NumberShape => "a number".into(),
            P::YesNoShape => "yes | no".into(),
            P::ValuesShape(n) => format!("({n} values)"),
        }
    }

    fn practice_summary(&self, s: &Summary) -> String {
        let pts = dec(s.points, 4, self.nums());
        let pct = dec(percent(s.points, s.total), 4, self.nums());
        let mut out = format!(
            "Summary: {pts}/{} marks = {pct}% (the values the problem asks; {} steps)\n  correct {} ({} by follow-through), too coarse {}, wrong {},\n  skipped {}, revealed {}, not reached {}; hints used {}\n",
            s.total, s.steps, s.correct, s.follow_through, s.too_coarse, s.wrong, s.skipped, s.revealed, s.unanswered, s.hints
        );
        if s.retries > 0 {
            out.push_str(&format!(
                "  second tries {} ({} right), not in the score\n",
                s.retries, s.retries_correct
            ));
        }
        out
    }
}

/// The English plural's `s`: none for one.
fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}
