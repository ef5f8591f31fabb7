//! The report writers' own words as typed keys, one enum per writer: the
//! headings, column names and sentences the writers (class report,
//! practice, check, Moodle, GIFT, …) put around the steps and values. Their
//! words are in report/words/{en,id}/report.rs; numbers travel as numbers
//! and are written through `NumStyle` there.

/// A word of the class report (`check --answers DIR`, `--report`): the
/// text table's columns, the lecturer's document's headings, columns and
/// sentences, the histogram's labels.
#[derive(Clone, Debug, PartialEq)]
pub enum ClassWord {
    /// The report's title, before the class's title.
    ClassReport,
    /// Column: one student.
    Student,
    /// Column: several students (also the histogram's count axis).
    Students,
    /// Column: a student's score.
    Score,
    /// Column: answers marked by follow-through.
    FollowThrough,
    /// Column: the mistakes' codes.
    Mistakes,
    /// Column: one mistake.
    Mistake,
    /// Column: an exam's variant.
    Variant,
    /// Before a sheet's error in its row.
    Error,
    /// Column: an answer key.
    Key,
    /// Column: the flags of a key.
    Flag,
    /// Column: an exam's problem.
    Problem,
    /// Column: a problem's title.
    Title,
    /// Column: a problem's facility.
    Facility,
    /// Column: a variant's facility over the whole exam.
    WholeExam,
    /// A variant below its siblings.
    Harder,
    /// A variant above its siblings.
    Easier,
    /// Heading: the key table.
    AnswerKeys,
    /// Heading: per problem.
    Problems,
    /// Heading: per variant.
    Variants,
    /// Heading: the mistakes.
    MistakesHeading,
    /// Heading: the wrong answers no mistake explains.
    WrongHeading,
    /// Heading: the students.
    StudentsHeading,
    /// Heading: who made which mistake.
    WhoWhich,
    /// Heading: the scores.
    Scores,
    /// The summary's sentence.
    Summary {
        /// Students marked.
        students: usize,
        /// The tolerance, in per cent.
        tolerance_pct: f64,
        /// The least number of significant figures.
        sig_figs: u32,
        /// Whether follow-through marks are given.
        follow_through: bool,
    },
    /// Before the list of the sheets not marked.
    NotMarked,
    /// The definitions of the key table's columns and indices.
    Definitions,
    /// What a variant table's cell holds.
    VariantsNote,
    /// No mistake explains a wrong answer.
    NoMistake,
    /// How the wrong answers are counted.
    WrongNote,
    /// An empty section.
    NoneFound,
    /// `n student(s)`'s word.
    StudentCount(usize),
    /// Before the keys a mistake explains.
    Explains,
    /// Before the step to teach again.
    TeachAgain,
    /// `problem-02, step 3 of the worked solution: Title`.
    StepOf {
        /// The problem's name and `, `, or nothing.
        part: String,
        /// The step's number.
        number: usize,
        /// The step's title, in words.
        title: String,
    },
    /// The histogram's caption in the HTML report.
    DistributionPct,
    /// The histogram's title.
    Distribution,
    /// The histogram's horizontal axis.
    ScoreAxis,
}

/// A word of `grafika practice` for people: the session's heading, the
/// verdicts, hints, the shape of an answer, the summary's headings.
#[derive(Clone, Debug, PartialEq)]
pub enum PracticeWord {
    /// The session's first line.
    Title {
        /// The problem's title.
        title: String,
        /// How many values are asked.
        values: usize,
        /// The seed of a drawn problem.
        seed: Option<u64>,
    },
    /// How to answer, and the commands.
    HowToAnswer,
    /// Before the answer shown.
    Answer,
    /// A value skipped.
    Skipped,
    /// An empty line was typed.
    AgainEmpty,
    /// `back` on the first value.
    FirstValue,
    /// `hint` after the last hint.
    NoMoreHints,
    /// Verdict: exactly right.
    Exact,
    /// Verdict: right within the tolerance.
    Tolerance,
    /// Verdict: right, rounded.
    Rounded,
    /// Verdict: right given the earlier answers.
    FollowThrough,
    /// Verdict: rounded too coarsely.
    TooCoarse,
    /// Verdict: wrong.
    Wrong,
    /// Verdict: the answer could not be read.
    Unreadable {
        /// Why, with its leading space and `;`, or nothing.
        why: String,
        /// The shape to write.
        how: String,
    },
    /// Before how an answer was read.
    ReadAs,
    /// A second try, counted apart.
    SecondTry,
    /// Before a mistake that explains the answer.
    LikelyMistake,
    /// Before why the source's printed value is wrong.
    SourceWrong,
    /// No mistake explains a wrong answer.
    NoMistakeTip,
    /// A value without a hint.
    NoHint,
    /// The first hint: the step's title.
    Hint1(String),
    /// The second hint's heading.
    Hint2,
    /// The second hint of a step without values.
    NoValues,
    /// The summary's mistakes' heading.
    MistakesMade,
    /// Before the command to practise next.
    PractiseNext,
    /// The shape of a clipped segment.
    SegmentShape,
    /// The shape of an outcode.
    BitsShape,
    /// The shape of a matrix.
    MatrixShape,
    /// The shape of a number.
    NumberShape,
    /// The shape of a list of `n` values.
    ValuesShape(usize),
}

/// A word of a marked answer file (`grafika check --answers FILE`) as
/// text; the class report shares its columns and notes.
#[derive(Clone, Debug, PartialEq)]
pub enum CheckWord {
    /// Column: the answer's key.
    Answer,
    /// Column: the verdict.
    Verdict,
    /// Column: the value given.
    Given,
    /// Column: the value expected.
    Expected,
    /// Column: the note on the verdict.
    Note,
    /// Between the title and the student: `Title — answers of budi`.
    AnswersOf,
    /// Heading: why the source's printed answers differ.
    Errata,
    /// Heading: the mistakes found.
    Diagnosis,
    /// Before the keys a mistake reproduces.
    Reproduces,
    /// Before the other mistakes giving the same values.
    AlsoFollow,
    /// Before the wrong answers no mistake explains.
    NoMistakeExplains,
    /// Before the keys that are not this problem's.
    NotAnswers,
    /// Before the score.
    Score,
    /// How many correct answers were credited by follow-through.
    FollowThroughCount(usize),
}
