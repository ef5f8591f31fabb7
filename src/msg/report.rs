//! The report writers' own words as typed keys, one enum per writer: the
//! headings, column names and sentences the writers (class report,
//! practice, check, Moodle, GIFT, …) put around the steps and values. Their
//! words are in report/words/{en,id}/report.rs; numbers travel as numbers
//! and are written through `NumStyle` there.

/// A word of the class report (`check --answers DIR`, `--report`): the
/// text table's columns, the lecturer's document's headings, columns and
/// sentences, the histogram's labels.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
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
    /// What a variant table's cell holds, and the test behind its flags.
    VariantsNote,
    /// How the variants are counted when each problem's was drawn by
    /// itself (a Moodle quiz's random slots).
    DrawnNote,
    /// Heading: the class list.
    RosterHeading,
    /// Before the students of the class list with no answer file: how many.
    RosterMissing(usize),
    /// Before the answer files of no one on the class list: how many.
    RosterNotListed(usize),
    /// Everyone on the class list handed in, and every file is on it.
    RosterAll(usize),
    /// Heading: the same student twice.
    DuplicatesHeading,
    /// How duplicates are found and which file is kept.
    DuplicatesNote,
    /// A file that is the same student as a kept one: the file kept, why
    /// in words.
    DuplicateOf {
        /// The file kept.
        kept: String,
        /// Why the two are the same student, in words.
        why: String,
    },
    /// Heading: sheets that fit another variant's key better.
    FitsHeading,
    /// How "fits another variant's key" is decided.
    FitsNote,
    /// A sheet fits another variant's key: that variant, the share of the
    /// marks there and on its own, in per cent.
    Fits {
        /// The variant whose key the answers fit.
        variant: usize,
        /// The share of the marks against that variant's key, in per cent.
        there: f64,
        /// The share against its own variant's key, in per cent.
        own: f64,
    },
    /// No variant has enough students to be compared with the others.
    TooFewPerVariant {
        /// The fewest students on one variant.
        min: usize,
        /// The most.
        max: usize,
        /// The fewest a variant needs.
        need: usize,
    },
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
#[cfg_attr(test, derive(strum::EnumIter))]
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
    /// An answer to a value already shown, counted apart.
    ShownBefore,
    /// The other values a `show` or a hint printed (their keys, joined),
    /// now counted as revealed.
    AlsoShown(String),
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
    /// The shape of a yes or no.
    YesNoShape,
    /// The shape of a list of `n` values.
    ValuesShape(usize),
}

/// A word of a marked answer file (`grafika check --answers FILE`) as
/// text; the class report shares its columns and notes.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
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
    /// Column: the marks earned of those an answer is worth.
    Marks,
    /// In the marks column: an answer the scheme does not ask (working).
    Working,
    /// The working shown: how many answers, how many right.
    WorkingCount(usize, usize),
    /// Heading: the marks the working earned for values not right.
    MethodMarks,
    /// Before a method mark's keys: the marks earned (as shown), of how many.
    MethodEarned(String, u32),
}

/// A word the documents share (the worked solution as text, HTML,
/// Markdown, LaTeX; the exam's sheets; a Moodle question): headings,
/// labels, the comparison with a source's printed answers.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum DocWord {
    /// Before a step's number.
    Step,
    /// Heading: the answer.
    Answer,
    /// Heading: the answers.
    Answers,
    /// Heading: the figures.
    Figures,
    /// Heading: the worked solution.
    WorkedSolution,
    /// Before a problem's number.
    Problem,
    /// Before a variant's number.
    Variant,
    /// Before a warning.
    Warning,
    /// Before an error (a sheet's in its row, the program's on stderr).
    Error,
    /// `check --moodle-responses`: attempts marked, of the report's attempts.
    MoodleMarked(usize, usize),
    /// An attempt not finished, not marked: the student, Moodle's state.
    MoodleUnfinished(String, String),
    /// A slot holding no question of the exam, skipped: the slot, the
    /// beginning of its text.
    MoodleForeign(usize, String),
    /// A part that cannot be read: the student, the answer key, what was
    /// typed (empty for an empty part).
    MoodleUnreadable(String, String, String),
    /// Heading: the notes on the source.
    NotesOnSource,
    /// A true value.
    Yes,
    /// A false value.
    No,
    /// No value.
    NoValue,
    /// Before the source the answers are compared with.
    ComparedWith,
    /// The source, when the problem file does not name it.
    TheSource,
    /// Before the value the source printed; a column.
    Printed,
    /// Before the correct value; a column.
    CorrectValue,
    /// Before the value computed, when the printed one cannot be compared.
    Computed,
    /// Column: the value's name.
    Value,
    /// Before why the source's value differs.
    Why,
    /// An exam's title.
    ExamTitle {
        /// The topics' names.
        topics: String,
        /// The difficulty's name.
        difficulty: String,
        /// The seed (a key's title only).
        seed: Option<u64>,
        /// The variant, when there are several.
        variant: Option<u32>,
    },
    /// An answer key's title, after the exam's.
    KeyTitle(String),
    /// A question's marks on an exam sheet: `(3 marks)`.
    Marks(u32),
    /// Before an answer-key file's title.
    AnswerKey,
    /// What `generate --out` wrote.
    Wrote {
        /// Files written.
        files: usize,
        /// Variants of each problem.
        variants: u32,
        /// Problems.
        count: u32,
        /// The topics' names.
        topics: String,
        /// The seed.
        seed: u64,
        /// The folder.
        out: String,
    },
    /// `… and n more` files.
    More(usize),
    /// A question sheet's title: the level in words and the variant, no
    /// internal codes and no seed.
    SheetTitle {
        /// The difficulty's name (`medium`).
        difficulty: String,
        /// The variant, when there are several.
        variant: Option<u32>,
    },
    /// The line a student writes their name and student number (NIM) on.
    NameLine,
    /// The marks of the whole sheet: `Total: 24 marks`.
    TotalMarks(u32),
}

/// The decimal mark students type: a Moodle reads a typed number by the
/// mark of its interface language (English: `0,5` is 5, the comma a
/// thousands separator; Indonesian: both `0,5` and `0.5` are 0.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Decimal {
    /// `0.5`: for a Moodle in English (the common case).
    #[default]
    Point,
    /// `0,5`: for a Moodle with the Indonesian language pack.
    Comma,
}

impl Decimal {
    /// Its name as `--decimal` spells it (`point`).
    pub fn name(self) -> &'static str {
        match self {
            Decimal::Point => "point",
            Decimal::Comma => "comma",
        }
    }
}

/// A word of a quiz (Moodle XML, GIFT): how to type the answers, the
/// feedback, the parts of a question, the names of a value's components.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum QuizWord {
    /// How to type the numbers.
    Instructions {
        /// Significant figures asked.
        figures: u32,
        /// The tolerance in per cent, written with the site's mark.
        pct: String,
        /// The mark to type.
        mark: Decimal,
        /// Whether pixel positions are asked.
        pixels: bool,
    },
    /// How to type an outcode.
    TypeOutcodes,
    /// How to type the clipping status and a missing segment.
    TypeStatus,
    /// Before the mistakes that give a wrong value.
    KnownMistake,
    /// Between two such mistakes.
    OrMistake,
    /// Before a part's number.
    Part,
    /// GIFT carries no figures: said to the lecturer when a GIFT file is
    /// written (never in a question, which students read).
    FiguresInMoodle,
    /// A clipping status's code (`clipped`) or `none` as a student of this
    /// language types it (`di-clip`, `tidak ada`); a blank accepts it beside
    /// the code.
    Word(String),
    /// Before a component's axis.
    Component,
    /// Before a point's number.
    Point,
}

/// A word of the command line itself: progress bars, a page's title, the
/// field of an error that names none.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum CliWord {
    /// A page's title after the command: `grafika view — worked solution`.
    WorkedSolution,
    /// The benchmark's progress bar.
    Measuring,
    /// The render's progress bar.
    Frames,
    /// The problems drawn, on an exam's progress bar.
    Problems,
    /// The field of an error in the arguments that names none.
    Arguments,
    /// Whose answers the text's printed ones are, when the file names no
    /// source.
    TheText,
}

/// A line of `render --stats`: a count of the pipeline's work or a stage's
/// median time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum StatWord {
    /// The table's heading.
    Heading,
    /// Triangles read.
    TrianglesIn,
    /// Back faces culled.
    Culled,
    /// Triangles rejected by their outcodes.
    Rejected,
    /// Triangles clipped.
    Clipped,
    /// Triangles set up and rasterized.
    Drawn,
    /// Triangles covering no pixel centre.
    NoPixels,
    /// Objects rejected whole.
    ObjectsRejected,
    /// Objects inside whole.
    ObjectsInside,
    /// Pixels shaded.
    PixelsShaded,
    /// Lighting evaluations.
    LightingEvals,
    /// Whether lighting is per pixel.
    PerPixel,
    /// Lights skipped out of range.
    LightsSkipped,
    /// Objects without specular work.
    SpecularSkipped,
    /// Time: geometry, a median of `runs` frames when more than one.
    Geometry {
        /// Frames rendered.
        runs: usize,
    },
    /// Time: binning.
    Binning,
    /// Time: the bands.
    Bands,
    /// Thread time: raster.
    Raster,
    /// Thread time: shading.
    Shading,
    /// Time: the frame.
    Frame,
    /// Time: PNG encoding.
    Png,
}

/// A word of an exam's blueprint (`generate`): its heading, columns and
/// cells.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum PlanWord {
    /// blueprint.md's title.
    Title,
    /// The table's heading: the variants and the marks of each.
    Heading {
        /// How many variants.
        variants: usize,
        /// The marks of one variant.
        total: u32,
    },
    /// Column: the topic.
    Topic,
    /// Column: the case every variant asks.
    Case,
    /// Column: the number class.
    Numbers,
    /// Column: the marks.
    Marks,
    /// Column: the statements.
    Statements,
    /// A camera problem's points.
    Points(usize),
    /// A lighting model, by its file name (`phong`, `blinn`, `lambert`).
    Model(String),
    /// A clipping case: the status (`clipped`, …), the planes each end is
    /// beyond, the intersections tried and kept.
    Clip {
        /// The status's code.
        status: String,
        /// How many planes P0 and P1 lie beyond.
        bits: [u32; 2],
        /// Intersections tried.
        tried: u32,
        /// Intersections kept.
        kept: u32,
    },
    /// A number class, by its JSON name (`one_surd`).
    Class(String),
    /// k of the n variants.
    OfVariants(usize, usize),
    /// The marks differ between variants.
    MarksVary,
    /// k distinct statements of n.
    Distinct(usize, usize),
    /// The heading of the answers' ranges.
    Spread,
}

/// A word of `grafika bench`'s table: its columns, a row's verdict and
/// the notes below it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum BenchWord {
    /// Column: the stage.
    Stage,
    /// Column: the precision.
    Precision,
    /// Column: the cases measured.
    Cases,
    /// Column: the median time per operation.
    TimePerOp,
    /// Column: the largest error on integer inputs.
    MaxUlpsInt,
    /// Column: the median error on integer inputs.
    MedianUlpsInt,
    /// Column: the largest error on wide inputs.
    MaxUlpsWide,
    /// Column: the target.
    Target,
    /// Verdict: the exact path.
    Exact,
    /// Verdict: a stage without a target.
    NoTarget,
    /// Verdict: the target met.
    Met,
    /// Verdict: the target not met.
    NotMet,
    /// What an ulp is measured against (two lines, each ending with a
    /// newline).
    UlpsNote,
    /// Before the count of runs where float and exact disagree on failing.
    Disagreements,
    /// Before the count of components without an exact reference.
    Unreferenced,
}
