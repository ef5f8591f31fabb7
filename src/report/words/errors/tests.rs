//! Every error key with sample parameters, and the tests that each has
//! words in every language; the crates' messages read into keys and said
//! again in English are the crates' messages.

use super::*;
use crate::msg::{FileKind, ListWhy};
use crate::report::lang::Lang;
use crate::report::words::of;
use proptest::prelude::*;
use strum::IntoEnumIterator;

/// Every error key: every variant (`EnumIter`, its fields at their
/// defaults, so a key added is tested without being listed), a nested
/// key's every variant in its place, and the samples whose words depend
/// on their values.
pub fn every_error() -> Vec<ErrMsg> {
    ErrMsg::iter().flat_map(with_nested).collect()
}

/// `e` once per variant of the key it holds (the reason a file cannot
/// be read, the bound a value breaks, …), else `e` itself.
fn with_nested(e: ErrMsg) -> Vec<ErrMsg> {
    use ErrMsg as E;
    let each = |io: fn(IoWhy) -> ErrMsg| every_io().into_iter().map(io).collect();
    match e {
        E::Num(_) => every_number().into_iter().map(E::Num).collect(),
        E::Toml(_) => every_toml().into_iter().map(E::Toml).collect(),
        // English says clap's own line, so a line to say
        E::Clap(..) => (every_clap().into_iter())
            .map(|c| E::Clap(c, "clap's line".into()))
            .collect(),
        E::MustBe(_, got) => Bound::iter().map(|b| E::MustBe(b, got)).collect(),
        E::Twice(_) => Twice::iter().map(E::Twice).collect(),
        E::Channel(_, got) => Channel::iter().map(|c| E::Channel(c, got)).collect(),
        E::Needs(_, key) => Thing::iter().map(|t| E::Needs(t, key.clone())).collect(),
        E::CannotRead(..) => each(|w| E::CannotRead("a.toml".into(), w)),
        E::CannotReadStdin(_) => each(E::CannotReadStdin),
        E::CannotWrite(..) => each(|w| E::CannotWrite("a.png".into(), w)),
        E::CannotCreate(..) => each(|w| E::CannotCreate("out".into(), w)),
        E::CannotWriteStdout(_) => each(E::CannotWriteStdout),
        E::ObjUnreadable(..) => each(|w| E::ObjUnreadable("m.obj".into(), w)),
        E::AnswersFolder(..) => each(|w| E::AnswersFolder("class".into(), w)),
        E::InputNotRegular(p, _) => FileKind::iter()
            .map(|k| E::InputNotRegular(p.clone(), k))
            .collect(),
        E::OutputNotRegular(p, _) => FileKind::iter()
            .map(|k| E::OutputNotRegular(p.clone(), k))
            .collect(),
        E::NotOwnList(p, _) => ListWhy::iter()
            .map(|w| E::NotOwnList(p.clone(), w))
            .collect(),
        E::ObjInvalid(p, _) => ObjWhy::iter()
            .map(|w| E::ObjInvalid(p.clone(), w))
            .collect(),
        // the file's size when it is known, and when it is not (standard input)
        E::FileTooLarge(..) => vec![
            E::FileTooLarge("a.toml".into(), Some(2_000_000), 1 << 20),
            E::FileTooLarge("-".into(), None, 1 << 20),
        ],
        other => vec![other],
    }
}

/// Every reason of the number reader, and what it expected at a
/// character and at the end.
pub fn every_number() -> Vec<NumErr> {
    let mut v: Vec<NumErr> = NumErr::iter().collect();
    for w in Want::iter() {
        v.push(NumErr::Expected(w, 3, Some('*')));
        v.push(NumErr::Expected(w, 3, None));
    }
    v
}

/// Every TOML error; a syntax error carries the reader's own message
/// (read into its words, none for an empty one), so real messages
/// replace the empty default.
fn every_toml() -> Vec<TomlErr> {
    let s = |x: &str| x.to_string();
    let mut v: Vec<TomlErr> = TomlErr::iter()
        .filter(|t| !matches!(t, TomlErr::Syntax(_)))
        .collect();
    v.extend([
        // the fields it knows, when there are some
        TomlErr::UnknownField(s("eyes"), Some(s("`eye`, `look`, `up`"))),
        TomlErr::Num(NumErr::DivZero(s("1/0"))),
        TomlErr::Syntax(s("invalid number")),
        TomlErr::Syntax(s("missing comma between array elements, expected `,`")),
        TomlErr::Syntax(s("invalid string, expected basic string, `\\`")),
        TomlErr::Syntax(s("unexpected content, expected nothing")),
        TomlErr::Syntax(s("unexpected Whitespace, expected value")),
    ]);
    v
}

/// Every command-line error, and the forms whose words depend on what
/// clap said: the values allowed or none, each reason a value is bad,
/// a suggestion or none.
fn every_clap() -> Vec<ClapErr> {
    let s = |x: &str| x.to_string();
    let mut v: Vec<ClapErr> = ClapErr::iter().collect();
    v.extend([
        ClapErr::InvalidValue(s("foo"), s("exact, f64, f32")),
        ClapErr::BadValue(s("abc"), s("invalid digit found in string")),
        ClapErr::BadValue(s("99"), s("99 is not in 1..=17")),
        ClapErr::BadValue(s("-"), s("cannot parse integer from empty string")),
        ClapErr::BadValue(s("x"), s("invalid float literal")),
        ClapErr::BadValue(s("x"), s("the value parser's own words")),
        ClapErr::Unknown(s("--eyes"), Some(s("--eye"))),
        ClapErr::UnknownCommand(s("bassis"), Some(s("basis"))),
    ]);
    v
}

/// Every reason a file cannot be read or written, the system's own
/// words given.
fn every_io() -> Vec<IoWhy> {
    let mut v: Vec<IoWhy> = IoWhy::iter().collect();
    v.push(IoWhy::Other("device not configured".into()));
    v
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
    let e = ErrMsg::MustBe(Bound::AboveNear(0.5), -0.5);
    assert_eq!(
        of(Lang::Id).error(&e),
        "harus lebih besar daripada near = 0,5, diberikan -0,5"
    );
    assert_eq!(
        of(Lang::En).error(&e),
        "must be greater than near = 0.5, got -0.5"
    );
    let e = ErrMsg::Attenuation(0.5, -1.0, 0.0);
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

/// What a person typed is quoted as typed in every language: the dots of
/// `1.2.3` are not decimal marks, and the numbers said about it are
/// written in the language's style (a column, an aspect ratio given).
#[test]
fn text_typed_is_quoted_as_typed_and_numbers_take_the_style() {
    let e = ErrMsg::Num(NumErr::Expected(Want::OperatorOrEnd, 4, Some('.')).quoted("1.2.3"));
    let id = of(Lang::Id).error(&e);
    assert!(id.starts_with("`1.2.3`: "), "{id}");
    assert!(id.ends_with("ditemukan `.`"), "{id}");
    let m = crate::msg::Msg::ErrNear(crate::msg::Given::Value(-0.5));
    let id = crate::report::words::words(&m, Lang::Id);
    assert!(id.ends_with("diberikan -0,5"), "{id}");
    let en = crate::report::words::words(&m, Lang::En);
    assert!(en.ends_with("got -0.5"), "{en}");
    // [0.5, 1.5, 0] as the colour given, in brackets as the file has it
    let c = TomlErr::Colour([0.5, 1.5, 0.0]);
    assert!(of(Lang::Id).toml(&c).ends_with("diberikan [0,5; 1,5; 0]"));
    assert!(of(Lang::En).toml(&c).ends_with("got [0.5, 1.5, 0]"));
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
