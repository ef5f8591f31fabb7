//! The messages of the crates grafika reads with (serde and the TOML reader
//! for files, Rust's number parsing under clap for flags) are English text
//! by nature. Here they are read once, each into a typed key of the shapes
//! recognised (with their parameters); each language gives those keys its
//! words. A piece of a shape not recognised is itself a case, quoted as the
//! crate wrote it ([`Shape::AsWritten`]).
//!
//! The crates' own words are written once, in the `*_text` functions: what
//! the readers match, and the English words (English is what the crates
//! write).

/// A typed key for a crate's phrases: the enum, its variants in order as
/// `ALL`, and its text (the crate's own English, which the reader matches
/// and English says), each variant written once.
macro_rules! listed {
    ($(#[$m:meta])* $name:ident, $all:literal, $text:ident, $text_doc:literal,
     $($v:ident => $t:literal,)*) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum $name {
            $($v,)*
        }

        impl $name {
            #[doc = $all]
            pub const ALL: [$name; [$($t),*].len()] = [$($name::$v),*];
        }

        #[doc = $text_doc]
        pub fn $text(w: $name) -> &'static str {
            match w {
                $($name::$v => $t,)*
            }
        }
    };
}

/// A piece of a crate's message: a phrase recognised, or text as written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Shape<K> {
    /// A phrase recognised.
    Known(K),
    /// Text as the crate wrote it (a literal, a value, a phrase not known).
    AsWritten(String),
}

impl<K: Copy> Shape<K> {
    /// This piece in words: a phrase recognised in `word`'s words, text as
    /// written.
    pub fn words(&self, word: impl Fn(K) -> &'static str) -> &str {
        match self {
            Shape::Known(k) => word(*k),
            Shape::AsWritten(t) => t,
        }
    }
}

/// serde's names of kinds of values (and grafika's own `expecting` words),
/// in its messages "invalid type: {found}, expected {wanted}"; for a
/// number field serde names the Rust type (`u32`, `i64`, `f64`), which
/// no student should have to read: every language says what it takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SerdeWord {
    NumberOrExpression,
    Vector,
    ArrayOfLength,
    ASequence,
    Sequence,
    AString,
    String,
    Integer,
    FloatingPoint,
    Boolean,
    AMap,
    Map,
    ElementsInSequence,
    ANumber,
    AnInteger,
    ABoolean,
    UnitVariant,
    Elements,
    U8,
    U16,
    U32,
    U64,
    Usize,
    I32,
    I64,
    F32,
    F64,
}

impl SerdeWord {
    /// Every phrase, longest first (so `an integer` is read whole, not as
    /// `an` + `integer`).
    pub const ALL: [SerdeWord; 27] = [
        SerdeWord::NumberOrExpression,
        SerdeWord::Vector,
        SerdeWord::ElementsInSequence,
        SerdeWord::ArrayOfLength,
        SerdeWord::FloatingPoint,
        SerdeWord::UnitVariant,
        SerdeWord::ASequence,
        SerdeWord::AnInteger,
        SerdeWord::ABoolean,
        SerdeWord::Sequence,
        SerdeWord::AString,
        SerdeWord::ANumber,
        SerdeWord::Elements,
        SerdeWord::Integer,
        SerdeWord::Boolean,
        SerdeWord::String,
        SerdeWord::AMap,
        SerdeWord::Usize,
        SerdeWord::Map,
        SerdeWord::U16,
        SerdeWord::U32,
        SerdeWord::U64,
        SerdeWord::I32,
        SerdeWord::I64,
        SerdeWord::F32,
        SerdeWord::F64,
        SerdeWord::U8,
    ];
}

/// serde's words for `w`.
pub fn serde_text(w: SerdeWord) -> &'static str {
    match w {
        SerdeWord::NumberOrExpression => "a number or a string with a number expression such as",
        SerdeWord::Vector => "a vector: an array [x, y, z] or a string",
        SerdeWord::ArrayOfLength => "an array of length",
        SerdeWord::ASequence => "a sequence",
        SerdeWord::Sequence => "sequence",
        SerdeWord::AString => "a string",
        SerdeWord::String => "string",
        SerdeWord::Integer => "integer",
        SerdeWord::FloatingPoint => "floating point",
        SerdeWord::Boolean => "boolean",
        SerdeWord::AMap => "a map",
        SerdeWord::Map => "map",
        SerdeWord::ElementsInSequence => "elements in sequence",
        SerdeWord::ANumber => "a number",
        SerdeWord::AnInteger => "an integer",
        SerdeWord::ABoolean => "a boolean",
        SerdeWord::UnitVariant => "unit variant",
        SerdeWord::Elements => "elements",
        SerdeWord::U8 => "u8",
        SerdeWord::U16 => "u16",
        SerdeWord::U32 => "u32",
        SerdeWord::U64 => "u64",
        SerdeWord::Usize => "usize",
        SerdeWord::I32 => "i32",
        SerdeWord::I64 => "i64",
        SerdeWord::F32 => "f32",
        SerdeWord::F64 => "f64",
    }
}

/// serde's description of a value or of what was expected (`string "a"`,
/// `an array of length 3`), as phrases and text between them: at each
/// place the longest phrase that starts there.
pub fn serde_pieces(s: &str) -> Vec<Shape<SerdeWord>> {
    let mut out = Vec::new();
    let mut text = String::new();
    let mut rest = s;
    while let Some(c) = rest.chars().next() {
        let hit = (SerdeWord::ALL.iter()).find(|w| rest.starts_with(serde_text(**w)));
        match hit {
            Some(w) => {
                if !text.is_empty() {
                    out.push(Shape::AsWritten(std::mem::take(&mut text)));
                }
                out.push(Shape::Known(*w));
                rest = &rest[serde_text(*w).len()..];
            }
            None => {
                text.push(c);
                rest = &rest[c.len_utf8()..];
            }
        }
    }
    if !text.is_empty() {
        out.push(Shape::AsWritten(text));
    }
    out
}

/// `s` read by [`serde_pieces`] and written back with `word` for each
/// phrase; the text between the phrases as written.
pub fn serde_words(s: &str, word: impl Fn(SerdeWord) -> &'static str) -> String {
    serde_pieces(s).iter().map(|p| p.words(&word)).collect()
}

/// The TOML reader's syntax error: `description[, expected a, b]`
/// (`expected nothing`: nothing more may follow).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Syntax {
    /// What is wrong.
    pub what: Shape<SyntaxWhat>,
    /// What the reader expected there, if it says.
    pub expected: Option<Expected>,
}

/// What the TOML reader expected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expected {
    /// Nothing (the line should have ended).
    Nothing,
    /// One of these (a literal such as `` `=` `` as written).
    OneOf(Vec<Shape<ExpectWord>>),
}

/// The TOML reader's message `s` as a [`Syntax`].
pub fn syntax(s: &str) -> Syntax {
    let (desc, expected) = match s.split_once(", expected ") {
        Some((d, e)) => (d, Some(e)),
        None => (s, None),
    };
    let what = match SyntaxWhat::ALL
        .into_iter()
        .find(|w| syntax_text(*w) == desc)
    {
        Some(w) => Shape::Known(w),
        None => Shape::AsWritten(desc.to_string()),
    };
    let item = |e: &str| match ExpectWord::ALL.into_iter().find(|w| expect_text(*w) == e) {
        Some(w) => Shape::Known(w),
        None => Shape::AsWritten(e.to_string()),
    };
    let expected = expected.map(|e| match e {
        "nothing" => Expected::Nothing,
        _ => Expected::OneOf(e.split(", ").map(item).collect()),
    });
    Syntax { what, expected }
}

listed! {
    /// A description of a syntax error the TOML reader gives.
    SyntaxWhat, "Every description.", syntax_text, "The TOML reader's words for `w`.",
    InvalidFloat => "invalid float",
    InvalidNumber => "invalid number",
    InvalidInteger => "invalid integer number",
    InvalidString => "invalid string",
    InvalidBoolean => "invalid boolean",
    InvalidDateTime => "invalid date-time",
    InvalidKey => "invalid key",
    InvalidTable => "invalid table",
    InvalidValue => "invalid value",
    InvalidInlineTableElement => "invalid inline table element",
    InvalidKeyValuePair => "invalid key-value pair",
    InvalidBasicString => "invalid basic string",
    InvalidMultiLineBasicString => "invalid multi-line basic string",
    InvalidCommentCharacter => "invalid comment character",
    InvalidUnquotedKey => "invalid unquoted key",
    KeyWithNoValue => "key with no value",
    MissingValueForKey => "missing value for key",
    MissingValue => "missing value",
    MissingAssignment => "missing assignment between key-value pairs",
    MissingCommaInArray => "missing comma between array elements",
    MissingCommaBetweenPairs => "missing comma between key-value pairs",
    MissingOpeningQuote => "missing opening quote",
    MissingTableOpen => "missing table open",
    MissingArrayOpening => "missing array opening",
    MissingInlineTableOpening => "missing inline table opening",
    MissingInlineTableKey => "missing key for inline table element",
    MissingEscapedValue => "missing escaped value",
    ExtraEquals => "extra `=`",
    ExtraCommaInArray => "extra comma in array",
    ExtraCommaInInlineTable => "extra comma in inline table",
    ExtraAssignment => "extra assignment between key-value pairs",
    StringsMustBeQuoted => "string values must be quoted",
    UnclosedArray => "unclosed array",
    UnclosedArrayTable => "unclosed array table",
    UnclosedInlineTable => "unclosed inline table",
    UnclosedTable => "unclosed table",
    UnexpectedContent => "unexpected content",
    UnexpectedBeforeNewline => "unexpected content between comment and newline",
    UnexpectedKeyOrValue => "unexpected key or value",
    UnexpectedLeadingZero => "unexpected leading zero",
    UnexpectedSign => "unexpected sign",
    UnexpectedEqualsInArray => "unexpected `=` in array",
    UnderscoreBetweenDigits => "`_` may only go between digits",
    EmptyUnquotedKey => "unquoted keys cannot be empty",
    RedundantSign => "redundant numeric sign",
    DuplicateKey => "duplicate key",
    TooDeep => "cannot recurse further; max recursion depth met",
    CarriageReturn => "carriage return must be followed by newline",
    SignedRadix => "integers with a radix cannot be signed",
    MultiLineBasicKey => "keys cannot be multi-line basic strings",
    MultiLineLiteralKey => "keys cannot be multi-line literal strings",
    MissingCommentStart => "missing comment start",
    RadixLowercase => "radix must be lowercase",
    RedundantPrefix => "redundant integer number prefix",
    FewUnicodeDigits => "too few unicode value digits",
    IntegerOverflow => "integer number overflowed",
    InvalidBinary => "invalid binary number",
    InvalidOctal => "invalid octal number",
    InvalidHex => "invalid hexadecimal number",
    InvalidMantissa => "invalid mantissa",
    InvalidFraction => "invalid fraction",
    InvalidExponent => "invalid exponent",
    InvalidLiteralString => "invalid literal string",
    InvalidMultiLineLiteralString => "invalid multi-line literal string",
    InvalidDatetime => "invalid datetime",
    WantedStringOrTable => "wanted string or table",
}

listed! {
    /// A kind of thing the TOML reader expected (a literal is not one: it is
    /// written as it is).
    ExpectWord, "Every kind.", expect_text, "The TOML reader's words for `w`.",
    Digits => "digits",
    Letters => "letters",
    Numbers => "numbers",
    Value => "value",
    Key => "key",
    Characters => "characters",
    PrintableCharacters => "printable characters",
    BasicString => "basic string",
    LiteralString => "literal string",
    MultiLineBasicString => "multi-line basic string",
    UnicodeHex => "unicode hexadecimal value",
    NonDoubleQuoteVisible => "non-double-quote visible characters",
    NonSingleQuote => "non-single-quote characters",
    NonSingleQuoteVisible => "non-single-quote visible characters",
    Newline => "newline",
}

/// Why a flag's value parser refused a value (Rust's number parsing,
/// clap's ranges).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ValueWhy {
    /// A reason of Rust's number parsing.
    Parse(ParseWhy),
    /// `{value} is not in {range}` (clap's ranges).
    NotInRange(String, String),
    /// A reason not recognised, as written.
    AsWritten(String),
}

listed! {
    /// A reason Rust's number parsing gives.
    ParseWhy, "Every reason.", parse_text, "Rust's words for `w`.",
    InvalidDigit => "invalid digit found in string",
    Empty => "cannot parse integer from empty string",
    TooLarge => "number too large to fit in target type",
    TooSmall => "number too small to fit in target type",
    InvalidFloat => "invalid float literal",
}

/// A value parser's reason `s` as a [`ValueWhy`].
pub fn value_why(s: &str) -> ValueWhy {
    if let Some(w) = ParseWhy::ALL.into_iter().find(|w| parse_text(*w) == s) {
        return ValueWhy::Parse(w);
    }
    match s.split_once(" is not in ") {
        Some((v, range)) => ValueWhy::NotInRange(v.to_string(), range.to_string()),
        None => ValueWhy::AsWritten(s.to_string()),
    }
}
