//! Every error key with sample parameters, and the tests that each has
//! words in every language; the crates' messages read into keys and said
//! again in English are the crates' messages.

use super::*;
use crate::msg::{FileKind, ListWhy};
use crate::report::lang::Lang;
use crate::report::words::of;
use proptest::prelude::*;

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
        ErrMsg::Channel(Channel::Red, s("1.5")),
        ErrMsg::Channel(Channel::Green, s("1.5")),
        ErrMsg::Channel(Channel::Blue, s("-0.5")),
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
        ErrMsg::ExactBeyondF64,
        ErrMsg::ExistsForce(s("out/problem-01.toml")),
        ErrMsg::StdoutClosed,
        ErrMsg::NamesFolder(s("figs/")),
        ErrMsg::IsLink(s("a.png")),
        ErrMsg::IsInput(s("scene.toml")),
        ErrMsg::NotOwn(s("exam/key.md"), s(".grafika-generated")),
        ErrMsg::NotDirectory(s("out")),
        ErrMsg::NotMarked(1, 4, s("class/broken.toml")),
        ErrMsg::FileTooLarge(s("a.toml"), Some(2_000_000), 1 << 20),
        ErrMsg::FileTooLarge(s("-"), None, 1 << 20),
        ErrMsg::TomlTooManyValues(100_000),
        ErrMsg::TomlTooDeep(32),
        ErrMsg::StdinClosed,
        ErrMsg::SameOutput(s("same.csv"), s("csv")),
        ErrMsg::ChangedSince(s("exam/key.md")),
        ErrMsg::ListExists(s("exam/.grafika-generated")),
        ErrMsg::Locked(s("exam"), s("exam/.grafika-lock")),
        ErrMsg::RenderWork(6_710, 1, 4_000),
        ErrMsg::FormulaWork(1_988_100, 961, 7_643, 4_000),
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
        ErrMsg::NoProblemDrawn,
        ErrMsg::StdinHoldsAnswers,
        ErrMsg::GiveProblem,
        ErrMsg::TooManyProblems(3000, 1000, 3, 48, 2000),
        ErrMsg::SplitNotQuiz,
        ErrMsg::QuestionTooLarge(
            s("Problem 01, variant 02: Eye coordinates"),
            s("0.031"),
            s("0.01"),
        ),
        ErrMsg::BothStdin,
        ErrMsg::NoPrinted(s("p.toml")),
        ErrMsg::CsvAndJson,
        ErrMsg::NoAnswerFiles(s("class")),
        ErrMsg::NoExam(s("exam")),
        ErrMsg::NoVariant(4),
        ErrMsg::NotAVariant(s("7"), 4),
        ErrMsg::MarksNotAKey(s("view.bogus")),
        ErrMsg::MarksUnknownField(s("weight")),
        ErrMsg::MarksMissing,
        ErrMsg::MarksNotWhole(s("1.5"), 100),
        ErrMsg::MarksMethodTable,
        ErrMsg::MarksMethodOver(5, 4),
        ErrMsg::MarksMethodAsked(s("shade.diffuse")),
        ErrMsg::NotAProblemOfExam(s("view.n"), s("problem-01, problem-02")),
        ErrMsg::ReportFormat(s("class.txt")),
        ErrMsg::NotResponses(s("no column Response 1")),
        ErrMsg::NoQuestionText,
        ErrMsg::ReportNeedsClass,
        ErrMsg::RosterNeedsClass,
        ErrMsg::EmptyRoster(s("kelas.txt")),
        ErrMsg::RosterRow(3, s("found record with 2 fields")),
        ErrMsg::AnswersFolder(s("nosuchdir"), crate::msg::IoWhy::NotFound),
        ErrMsg::PixelOutside(10, 20, 8, 8),
        ErrMsg::PixelText(s("a,b")),
        ErrMsg::NothingRendered,
        ErrMsg::Threads(s("why")),
        ErrMsg::RenderPrecision,
        ErrMsg::NotTaken(s("check")),
        ErrMsg::OwnOutput,
        ErrMsg::Man(s("why")),
    ]);
    for k in [
        FileKind::Fifo,
        FileKind::Socket,
        FileKind::CharDevice,
        FileKind::BlockDevice,
        FileKind::Folder,
        FileKind::Other,
    ] {
        v.push(ErrMsg::InputNotRegular(s("p.toml"), k));
        v.push(ErrMsg::OutputNotRegular(s("a.png"), k));
    }
    for w in [
        ListWhy::NotAFile,
        ListWhy::Heading,
        ListWhy::Line(3),
        ListWhy::Name(3, s("notes.txt")),
        ListWhy::Owner,
        ListWhy::TooLarge,
    ] {
        v.push(ErrMsg::NotOwnList(s("exam/.grafika-generated"), w));
    }
    v.extend(
        every_obj()
            .into_iter()
            .map(|w| ErrMsg::ObjInvalid(s("m.obj"), w)),
    );
    v
}

fn every_obj() -> Vec<ObjWhy> {
    use ObjWhy::*;
    vec![
        OpenFileFailed,
        ReadError,
        UnrecognizedCharacter,
        PositionParse,
        ScalingByZero,
        ColorParse,
        NormalParse,
        TexcoordParse,
        FaceParse,
        MaterialParse,
        InvalidObjectName,
        InvalidPolygon,
        FaceVertexOutOfBounds,
        FaceTexCoordOutOfBounds,
        FaceNormalOutOfBounds,
        FaceColorOutOfBounds,
        LoadOptions,
        Generic,
    ]
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
        TomlErr::InvalidValue(s("integer `-5`"), s("u32")),
        TomlErr::Num(NumErr::DivZero(s("1/0"))),
        TomlErr::MustBe(Bound::Positive, s("-1.5")),
        TomlErr::WholeRange(3, 4096, s("2")),
        TomlErr::Colour(s("[1.5, 0, 0]")),
        TomlErr::Syntax(s("invalid number")),
        TomlErr::Syntax(s("missing comma between array elements, expected `,`")),
        TomlErr::Syntax(s("invalid string, expected basic string, `\\`")),
        TomlErr::Syntax(s("unexpected content, expected nothing")),
        TomlErr::Syntax(s("unexpected Whitespace, expected value")),
    ]
}

fn every_clap() -> Vec<ClapErr> {
    let s = |x: &str| x.to_string();
    vec![
        ClapErr::InvalidValue(s("foo"), s("exact, f64, f32")),
        ClapErr::InvalidValue(s("foo"), String::new()),
        ClapErr::BadValue(s("abc"), s("invalid digit found in string")),
        ClapErr::BadValue(s("99"), s("99 is not in 1..=17")),
        ClapErr::BadValue(s("-"), s("cannot parse integer from empty string")),
        ClapErr::BadValue(s("x"), s("invalid float literal")),
        ClapErr::BadValue(s("x"), s("the value parser's own words")),
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
        NotADirectory,
        ReadOnly,
        Full,
        TooLarge,
        BadName,
        Other("device not configured".into()),
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
        | E::ExactBeyondF64
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
        | E::FileTooLarge(..)
        | E::TomlTooManyValues(_)
        | E::TomlTooDeep(_)
        | E::StdinClosed
        | E::InputNotRegular(..)
        | E::OutputNotRegular(..)
        | E::SameOutput(..)
        | E::ChangedSince(_)
        | E::NotOwnList(..)
        | E::ListExists(_)
        | E::Locked(..)
        | E::RenderWork(..)
        | E::FormulaWork(..)
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
        | E::NoProblemDrawn
        | E::StdinHoldsAnswers
        | E::GiveProblem
        | E::TooManyProblems(..)
        | E::SplitNotQuiz
        | E::QuestionTooLarge(..)
        | E::BothStdin
        | E::NoPrinted(_)
        | E::CsvAndJson
        | E::NoAnswerFiles(_)
        | E::NoExam(_)
        | E::NoVariant(_)
        | E::NotAVariant(..)
        | E::MarksNotAKey(_)
        | E::MarksUnknownField(_)
        | E::MarksMissing
        | E::MarksNotWhole(..)
        | E::MarksMethodTable
        | E::MarksMethodOver(..)
        | E::MarksMethodAsked(_)
        | E::NotAProblemOfExam(..)
        | E::ReportFormat(_)
        | E::NotResponses(_)
        | E::NoQuestionText
        | E::ReportNeedsClass
        | E::RosterNeedsClass
        | E::EmptyRoster(_)
        | E::RosterRow(..)
        | E::AnswersFolder(..)
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
        | TomlErr::InvalidValue(..)
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
        | IoWhy::NotADirectory
        | IoWhy::ReadOnly
        | IoWhy::Full
        | IoWhy::TooLarge
        | IoWhy::BadName
        | IoWhy::Other(_) => {}
    }
}

/// Fails to compile when an OBJ reason is added without being listed in
/// [`every_obj`].
#[allow(dead_code)]
fn obj_listed(o: &ObjWhy) {
    use ObjWhy::*;
    match o {
        OpenFileFailed
        | ReadError
        | UnrecognizedCharacter
        | PositionParse
        | ScalingByZero
        | ColorParse
        | NormalParse
        | TexcoordParse
        | FaceParse
        | MaterialParse
        | InvalidObjectName
        | InvalidPolygon
        | FaceVertexOutOfBounds
        | FaceTexCoordOutOfBounds
        | FaceNormalOutOfBounds
        | FaceColorOutOfBounds
        | LoadOptions
        | Generic => {}
    }
}

#[test]
fn every_error_has_words_in_both_languages_and_they_differ() {
    let all = every_error();
    assert!(all.len() > 150, "{}", all.len());
    for e in &all {
        let (en, id) = (of(Lang::En).error(e), of(Lang::Id).error(e));
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
        of(Lang::Id).error(&e),
        "harus lebih besar daripada near = 0,5, diberikan -0,5"
    );
    assert_eq!(
        of(Lang::En).error(&e),
        "must be greater than near = 0.5, got -0.5"
    );
    let e = ErrMsg::Attenuation("0.5".into(), "-1".into(), "0".into());
    assert!(of(Lang::Id).error(&e).ends_with("diberikan (0,5; -1; 0)"));
    let e = TomlErr::InvalidType("string \"a\"".into(), "an integer".into());
    assert_eq!(
        of(Lang::Id).toml(&e),
        "jenis nilai salah: string \"a\", seharusnya bilangan bulat"
    );
    let e = ErrMsg::CannotRead("p.toml".into(), IoWhy::NotFound);
    assert_eq!(
        of(Lang::Id).error(&e),
        "tidak dapat membaca p.toml: berkas atau direktori tidak ada"
    );
}

/// Messages as the TOML reader writes them (`description[, expected …]`):
/// every description known, with each form of what it expected (nothing
/// said, `nothing`, literals, words), and descriptions of shapes not known.
fn toml_messages() -> Vec<String> {
    let mut v = Vec::new();
    for w in SyntaxWhat::ALL {
        let d = syntax_text(w);
        v.push(d.to_string());
        v.push(format!("{d}, expected nothing"));
        v.push(format!("{d}, expected `,`, `]`"));
    }
    for w in ExpectWord::ALL {
        v.push(format!("invalid key, expected {}, `=`", expect_text(w)));
    }
    v.push("unexpected Whitespace, expected digits, `+`".into());
    v.push("a message of a newer TOML reader".into());
    v
}

#[test]
fn the_crates_messages_read_as_keys_are_said_in_english_as_the_crates_wrote_them() {
    let en = of(Lang::En);
    for m in toml_messages() {
        assert_eq!(en.toml(&TomlErr::Syntax(m.clone())), m);
    }
    for w in ParseWhy::ALL {
        assert_eq!(value_why(parse_text(w)), ValueWhy::Parse(w));
        assert_eq!(en.value_why(&value_why(parse_text(w))), parse_text(w));
    }
    for w in SerdeWord::ALL {
        assert_eq!(serde_pieces(serde_text(w)), vec![Shape::Known(w)]);
    }
    let e = TomlErr::InvalidType("string \"a\"".into(), "an integer".into());
    assert_eq!(
        en.toml(&e),
        "invalid type: string \"a\", expected an integer"
    );
}

#[test]
fn the_crates_messages_are_read_into_their_shapes() {
    let s = |x: &str| Shape::<SerdeWord>::AsWritten(x.to_string());
    // `an integer` whole, not `an` + `integer`; the value as written
    assert_eq!(
        serde_pieces("an integer"),
        vec![Shape::Known(SerdeWord::AnInteger)]
    );
    assert_eq!(
        serde_pieces("string \"a\""),
        vec![Shape::Known(SerdeWord::String), s(" \"a\"")]
    );
    assert_eq!(
        syntax("missing comma between array elements, expected `,`"),
        Syntax {
            what: Shape::Known(SyntaxWhat::MissingCommaInArray),
            expected: Some(Expected::OneOf(vec![Shape::AsWritten("`,`".into())])),
        }
    );
    assert_eq!(
        syntax("unexpected content, expected nothing").expected,
        Some(Expected::Nothing)
    );
    assert_eq!(
        value_why("99 is not in 1..=17"),
        ValueWhy::NotInRange("99".into(), "1..=17".into())
    );
    assert_eq!(value_why("no idea"), ValueWhy::AsWritten("no idea".into()));
}

#[test]
fn the_crates_messages_are_said_in_indonesian_from_their_keys() {
    let id = of(Lang::Id);
    let syntax = |m: &str| id.toml(&TomlErr::Syntax(m.into()));
    assert_eq!(
        syntax("missing comma between array elements, expected `,`"),
        "sintaks TOML tidak sah: koma tidak ada di antara elemen array, seharusnya `,`"
    );
    // "expected nothing": the line should have ended; not said
    assert_eq!(
        syntax("unexpected content, expected nothing"),
        "sintaks TOML tidak sah: isi yang tidak diharapkan"
    );
    // a description not known is quoted as the reader wrote it
    assert_eq!(
        syntax("unexpected Whitespace, expected digits, `+`"),
        "sintaks TOML tidak sah: unexpected Whitespace, seharusnya angka, `+`"
    );
    let e = TomlErr::InvalidLength("2".into(), "an array of length 3".into());
    assert_eq!(
        id.toml(&e),
        "panjang salah: 2, seharusnya array dengan panjang 3"
    );
    let bad = |why: &str| ErrMsg::Clap(ClapErr::BadValue("-".into(), why.into()), String::new());
    assert_eq!(
        id.error(&bad("cannot parse integer from empty string")),
        "nilai '-' tidak sah: kosong (lihat --help)"
    );
    assert_eq!(
        id.error(&bad("-1 is not in 1..=17")),
        "nilai '-' tidak sah: -1 tidak berada dalam rentang 1..=17 (lihat --help)"
    );
    let obj = ErrMsg::ObjInvalid("m.obj".into(), ObjWhy::FaceParse);
    assert_eq!(
        id.error(&obj),
        "m.obj bukan berkas OBJ yang sah: sebuah bidang (face) tidak dapat dibaca"
    );
    assert_eq!(
        of(Lang::En).error(&obj),
        "m.obj is not a valid OBJ file: face parse error"
    );
}

#[test]
fn every_phrase_of_the_crates_has_words_in_every_language() {
    let (en, id) = (of(Lang::En), of(Lang::Id));
    for w in [en, id] {
        assert!(SerdeWord::ALL.iter().all(|x| !w.serde_word(*x).is_empty()));
    }
    // descriptions and reasons are sentences: each is translated
    for x in SyntaxWhat::ALL {
        assert_ne!(en.syntax_what(x), id.syntax_what(x), "{x:?}");
        assert!(!id.syntax_what(x).is_empty());
    }
    for x in ExpectWord::ALL {
        assert_ne!(en.expect_word(x), id.expect_word(x), "{x:?}");
    }
    for x in ParseWhy::ALL {
        assert_ne!(en.parse_why(x), id.parse_why(x), "{x:?}");
    }
}

#[test]
fn the_readers_tables_are_whole_and_read_the_longest_phrase_first() {
    let distinct = |texts: Vec<&str>| {
        let n = texts.len();
        let set: std::collections::BTreeSet<&str> = texts.into_iter().collect();
        set.len() == n
    };
    assert!(distinct(SyntaxWhat::ALL.map(syntax_text).to_vec()));
    assert!(distinct(ExpectWord::ALL.map(expect_text).to_vec()));
    assert!(distinct(ParseWhy::ALL.map(parse_text).to_vec()));
    let lengths = SerdeWord::ALL.map(|w| serde_text(w).len());
    assert!(distinct(SerdeWord::ALL.map(serde_text).to_vec()));
    assert!(lengths.windows(2).all(|l| l[0] >= l[1]), "{lengths:?}");
}

/// Text made of serde's phrases and other characters.
fn serde_like() -> impl Strategy<Value = String> {
    let phrase =
        prop::sample::select(SerdeWord::ALL.map(serde_text).to_vec()).prop_map(String::from);
    let other = "[a-z `\"0-9,\\[\\]:é]{0,6}";
    prop::collection::vec(prop_oneof![phrase, other], 0..6).prop_map(|v| v.concat())
}

/// Text made of the TOML reader's descriptions and what it expects.
fn toml_like() -> impl Strategy<Value = String> {
    let desc = prop_oneof![
        prop::sample::select(SyntaxWhat::ALL.map(syntax_text).to_vec()).prop_map(String::from),
        "[a-z `=,]{0,12}",
    ];
    let item = prop_oneof![
        prop::sample::select(ExpectWord::ALL.map(expect_text).to_vec()).prop_map(String::from),
        "[a-z `=,]{0,6}",
    ];
    let expected = prop::collection::vec(item, 0..4);
    (desc, prop::option::of(expected)).prop_map(|(d, e)| match e {
        Some(items) => format!("{d}, expected {}", items.join(", ")),
        None => d,
    })
}

proptest! {
    #[test]
    fn serde_text_read_as_phrases_is_written_back_as_it_was(s in serde_like()) {
        prop_assert_eq!(serde_words(&s, serde_text), s);
    }

    #[test]
    fn a_toml_message_read_as_a_key_is_said_in_english_as_written(s in toml_like()) {
        prop_assert_eq!(of(Lang::En).toml(&TomlErr::Syntax(s.clone())), s.clone());
        // and in Indonesian it is framed, never empty
        prop_assert!(of(Lang::Id).toml(&TomlErr::Syntax(s)).starts_with("sintaks TOML tidak sah: "));
    }

    #[test]
    fn a_value_reason_read_as_a_key_is_said_in_english_as_written(s in "[ -~]{0,30}") {
        prop_assert_eq!(of(Lang::En).value_why(&value_why(&s)), s);
    }
}
