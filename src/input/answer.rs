//! An answer as a student writes it, read once for `check`'s answer files
//! and `practice`'s prompts alike: a number, a vector, a matrix, a segment,
//! an outcode or a clipping status, in every form the text and its students
//! use.
//!
//! - A number is an expression of docs/spec.md §2: `-6/sqrt(2)`, `3√2`,
//!   `(1/2)sqrt(2)`, `−0.7071`, a decimal comma `0,0414`.
//! - A vector is a TOML array, or text: `(a, b, c)`, `[a, b, c]`, bare
//!   `a, b, c`; with decimal commas its parts are separated by `;`
//!   (`(0,7071; 0; 0,7071)`). A part may end in any bracket
//!   (`1/sqrt(2), 0, -1/sqrt(2)`).
//! - A matrix or a segment is a list of vectors: a TOML array of rows, or
//!   text with the rows (ends) separated by `;` (`1, 0; 0, 1`,
//!   `(3, 8/3, 11/6); (1, 4, 3/2)`) or each in brackets
//!   (`(3, 8/3, 11/6), (1, 4, 3/2)`); `none` when nothing is left.
//! - An outcode is up to six binary digits, spaces ignored (`001 000`).
//! - A status is a word in either language, any case: `clipped`, `di-clip`,
//!   `accepted`, `diterima`, `rejected`, `ditolak` (or grafika's own
//!   `clipped (di-clip)`).
//! - Yes or no (whether an intersection is kept, a light in range): `yes`,
//!   `no`, `ya`, `tidak`, `true`, `false` (a TOML boolean too), `kept`,
//!   `dipertahankan`, `dibuang`, any case.
//! - A point may carry its name, as the text writes it: `A(3; 8/3; 11/6)`.
//!   A vector may be written times or over a number, as grafika prints it:
//!   `(1, 0, 1)/√2`, `−(4, 3, 0)/5`, `√2/2·(1, 0, 1)`.
//! - A row of numbers may be separated by spaces: a matrix as
//!   `0 0 -1 4; -0,6 0,8 0 -0,8; …`.
//! - Decimal commas and comma separators together (`0,7071, 0, 0,7071`)
//!   cannot be told apart: such an answer is not read, and the note says
//!   how to write it.
//!
//! The shape expected (a value like grafika's answer) says how deep the
//! lists go, so that `;` separates a vector's parts but a matrix's rows.
//! Reading is one pass over the text, linear in its length. An answer that
//! cannot be read gets the part at fault, the column in the whole answer
//! and what was expected there.

use crate::msg::{Msg, NumErr, Want};
use crate::num::expr::{components, missing_close, split_at, strip_outer, Part};
use crate::num::{parse_expr, Expr};
use crate::stages::trace::Val;
use std::borrow::Cow;

/// An answer as read.
#[derive(Clone, Debug, PartialEq)]
pub enum Read {
    /// A number.
    Num(Number),
    /// A vector, a matrix (rows), a segment (its ends).
    List(Vec<Read>),
    /// An outcode (six binary digits) or a status (`accepted`, `rejected`,
    /// `clipped`), in grafika's spelling.
    Word(String),
    /// Nothing is left (`none`, `[]`): the answer for a rejected segment.
    None,
}

impl Read {
    /// The answer as a value (numbers as doubles), to set beside grafika's.
    pub fn value(&self) -> Val {
        match self {
            Read::Num(n) => Val::num(&n.value),
            Read::List(items) => Val::List(items.iter().map(Read::value).collect()),
            Read::Word(w) => Val::text(w.clone()),
            Read::None => Val::Null,
        }
    }
}

/// One number as read.
#[derive(Clone, Debug, PartialEq)]
pub struct Number {
    /// The expression.
    pub expr: Expr,
    /// Its value as a double.
    pub value: f64,
    /// For a plain decimal or whole number (`0.041`, `-124`): the exponent
    /// of its last written digit (−3 for 0.041, 0 for 124); None for an
    /// expression, which is taken as exact.
    pub last_digit: Option<i32>,
}

impl Number {
    /// Whether it is written as a decimal with a point (or comma): its
    /// tolerance is its precision.
    pub fn is_decimal(&self) -> bool {
        self.last_digit.is_some_and(|d| d < 0)
    }
}

/// Reads an answer (a TOML value of an answer file, or a line typed, as a
/// string) against a value shaped like `like`: a number, a list (of lists),
/// a code or status word, or none. The error is the note for the student:
/// which part, at which column, and what was expected there.
pub fn read(given: &toml::Value, like: &Val) -> Result<Read, Msg> {
    Given::of(given).read(like)
}

/// What is read: a text (a string of the file, a line typed, or one part
/// of a list written as text, read from the text itself) or another TOML
/// value (an array, a number, a boolean).
#[derive(Clone, Copy, Debug)]
pub enum Given<'a> {
    /// A text: a line typed, or a string of an answer file.
    Text(&'a str),
    /// Any other TOML value of an answer file.
    Toml(&'a toml::Value),
}

impl<'a> Given<'a> {
    /// A TOML value as read: a string is its text.
    pub fn of(v: &'a toml::Value) -> Given<'a> {
        match v {
            toml::Value::String(s) => Given::Text(s),
            other => Given::Toml(other),
        }
    }

    /// Whether it is a text of nothing but white space (an answer left
    /// empty).
    pub fn is_blank(self) -> bool {
        matches!(self, Given::Text(s) if s.trim().is_empty())
    }

    /// Reads the answer against a value shaped like `like` ([`read`]): a
    /// text may start with its name (`n = …`).
    pub fn read(self, like: &Val) -> Result<Read, Msg> {
        match self {
            Given::Text(t) => match named(t) {
                Some((value, at)) => read_at(Given::Text(value), like, at),
                None => read_at(Given::Text(t), like, 0),
            },
            other => read_at(other, like, 0),
        }
    }
}

/// An answer written after its name, as on paper (`n = (√2/2, 0, √2/2)`,
/// `A'' = (0, −√2/60)`, `top = 0,0414`): the value after the `=`, and how
/// many characters come before it. A name starts with a letter and holds
/// letters, digits, primes, `_`, `.` and spaces, at most 24 characters.
fn named(t: &str) -> Option<(&str, usize)> {
    let (name, value) = t.split_once('=')?;
    let name = name.trim();
    let is_name = name.chars().next().is_some_and(char::is_alphabetic)
        && name.chars().count() <= 24
        && (name.chars()).all(|c| c.is_alphanumeric() || " _.'′″".contains(c));
    let skipped = t.len() - value.trim_start().len();
    is_name.then(|| (value.trim_start(), t[..skipped].chars().count()))
}

/// How deep lists of `like` go (0 for a number or a word).
fn depth(like: &Val) -> usize {
    match like {
        Val::List(items) => 1 + items.iter().map(depth).max().unwrap_or(0),
        _ => 0,
    }
}

fn read_at(given: Given, like: &Val, offset: usize) -> Result<Read, Msg> {
    let text = || scalar_text(given).unwrap_or_default();
    match like {
        Val::Num(_) => number_value(given, offset).map(Read::Num),
        Val::Text(t) if is_code(t) => code(&text()),
        Val::Text(_) => status(&text()),
        Val::Null => match given {
            Given::Toml(toml::Value::Array(a)) if a.is_empty() => Ok(Read::None),
            _ if is_none(given) => Ok(Read::None),
            // a segment where none is left: read as a segment, to be wrong
            _ => {
                let end = Val::List(vec![Val::num(&0.0); 3]);
                list(given, &Val::List(vec![end.clone(), end]), offset)
            }
        },
        Val::List(items) if is_none(given) && items.iter().all(|x| depth(x) >= 1) => Ok(Read::None),
        Val::List(_) => list(given, like, offset),
        Val::Bool(_) => yes_no(&text()),
        Val::Map(_) | Val::Said(_) => Err(Msg::SeveralAnswers),
    }
}

/// Whether a text value is an outcode (six binary digits).
fn is_code(t: &str) -> bool {
    t.len() == 6 && t.chars().all(|c| c == '0' || c == '1')
}

fn is_none(given: Given) -> bool {
    matches!(given, Given::Text(s)
        if matches!(s.trim().to_lowercase().as_str(), "none" | "null" | "tidak ada" | "-" | "—"))
}

/// The text of a scalar: a text as it is, a TOML number or boolean as
/// TOML writes it.
fn scalar_text(given: Given) -> Option<Cow<str>> {
    match given {
        Given::Text(s) => Some(Cow::Borrowed(s)),
        Given::Toml(toml::Value::String(s)) => Some(Cow::Borrowed(s)),
        Given::Toml(toml::Value::Integer(i)) => Some(Cow::Owned(i.to_string())),
        Given::Toml(toml::Value::Float(f)) => Some(Cow::Owned(format!("{f}"))),
        Given::Toml(toml::Value::Boolean(b)) => Some(Cow::Owned(b.to_string())),
        Given::Toml(_) => None,
    }
}

/// A number from a scalar; `offset` is where its text starts in the
/// whole answer (for the column of an error).
fn number_value(given: Given, offset: usize) -> Result<Number, Msg> {
    match scalar_text(given) {
        Some(t) => number_at(&t, offset),
        None => Err(Msg::ExpectOne),
    }
}

/// A number from its text, which starts at `offset` in the whole answer.
fn number_at(text: &str, offset: usize) -> Result<Number, Msg> {
    number(text).map_err(|e| Msg::Unreadable(shift(e, offset)))
}

/// Reads one number: an expression with an optional decimal comma.
pub fn number(text: &str) -> Result<Number, NumErr> {
    let expr = parse_expr(text)?;
    let value = expr.eval::<f64>()?;
    Ok(Number {
        last_digit: last_digit(&expr),
        expr,
        value,
    })
}

/// The exponent of the last written digit of a plain decimal or whole
/// number (`0.041` → −3, `1.50e2` → 0, `124` → 0), through one sign.
fn last_digit(e: &Expr) -> Option<i32> {
    match e {
        Expr::Neg(x) => last_digit(x),
        Expr::Lit(s) => {
            let (mant, exp) = match s.find(['e', 'E']) {
                Some(i) => (&s[..i], s[i + 1..].parse::<i32>().ok()?),
                None => (s.as_str(), 0),
            };
            let decimals = mant.split_once('.').map_or(0, |(_, f)| f.len() as i32);
            Some(exp - decimals)
        }
        _ => None,
    }
}

/// Moves the column of a reader's error by `by` characters (the part's
/// place in the whole answer).
fn shift(e: NumErr, by: usize) -> NumErr {
    match e {
        NumErr::Expected(w, col, found) => NumErr::Expected(w, col + by, found),
        NumErr::TooDeep(max, col) => NumErr::TooDeep(max, col + by),
        NumErr::TooManyOps(max, col) => NumErr::TooManyOps(max, col + by),
        other => other,
    }
}

/// A list against `like` (a list): a TOML array element by element, or
/// text split into its parts ([`components`]); each part read against the
/// element of `like` it stands for. A wrong count is left to the judge
/// (the parts are still read, so that junk in one is named); at most
/// [`MAX_BAD_PARTS`] unreadable parts are named, so a line of thousands of
/// commas gets a short note.
const MAX_BAD_PARTS: usize = 3;

fn list(given: Given, like: &Val, offset: usize) -> Result<Read, Msg> {
    let items: &[Val] = match like {
        Val::List(items) => items,
        _ => &[],
    };
    let element = |i: usize| items.get(i).or(items.last()).unwrap_or(&Val::Null);
    let parts: Vec<(Given, usize)> = match given {
        Given::Toml(toml::Value::Array(a)) => a.iter().map(|v| (Given::of(v), offset)).collect(),
        Given::Text(t) => {
            let (t, offset) = unnamed(t, offset);
            if depth(like) == 1 {
                if let Some(read) = vector_numbers(t, like, offset) {
                    return read;
                }
            }
            text_parts(t, items)
                .into_iter()
                .map(|p| (Given::Text(p.text), offset + p.at))
                .collect()
        }
        _ => return Err(Msg::ExpectList(items.len())),
    };
    let mut read = Vec::with_capacity(parts.len());
    let mut bad = Vec::new();
    for (i, &(part, at)) in parts.iter().enumerate() {
        let like_i = element(i);
        let r = if depth(like_i) == 0 && matches!(part, Given::Text(s) if s.trim().is_empty()) {
            Err(Msg::Unreadable(NumErr::Empty))
        } else {
            read_at(part, like_i, at)
        };
        match r {
            Ok(x) => read.push(x),
            Err(m) => bad.push((label(i, items.len(), depth(like) > 1), m)),
        }
        if bad.len() == MAX_BAD_PARTS {
            break;
        }
    }
    if bad.is_empty() {
        Ok(Read::List(read))
    } else {
        Err(unclosed(given, like, offset).unwrap_or(Msg::Parts(bad)))
    }
}

/// A point written with its name before its coordinates, as the text
/// writes it (`A(3; 8/3; 11/6)`, `P1 (1, 4, 3/2)`): the coordinates, and
/// where they start. A name starts with a letter and holds letters,
/// digits, primes and `_` (not `sqrt` or `pi`, which take a bracket as
/// numbers do); the brackets after it hold the rest of the text.
fn unnamed(t: &str, offset: usize) -> (&str, usize) {
    let lead = t.len() - t.trim_start().len();
    let rest = &t[lead..];
    let name_len: usize = rest
        .char_indices()
        .take_while(|(i, c)| {
            if *i == 0 {
                c.is_alphabetic() && *c != 'π'
            } else {
                c.is_alphanumeric() || "_'′″".contains(*c)
            }
        })
        .map(|(_, c)| c.len_utf8())
        .sum();
    let (name, after) = rest.split_at(name_len);
    let coords = after.trim_start();
    let bracketed = coords.starts_with(['(', '[']) && strip_outer(coords).len() < coords.len();
    if name_len == 0 || matches!(name, "sqrt" | "pi") || !bracketed {
        return (t, offset);
    }
    let skipped = t[..t.len() - coords.len()].chars().count();
    (coords, offset + skipped)
}

/// A vector's numbers, each read once: its parts separated by commas or
/// `;` when each is a number (`1/sqrt(2), 0, -1/sqrt(2)`), or its numbers
/// written otherwise: times or over a number (`(1, 0, 1)/√2`), or
/// separated by spaces (`0 0 -1 4`, `-0,6 0,8 0 -0,8`). None when the text
/// is no such vector (then it is read part by part); commas that may be
/// decimal marks and separators alike, with a count unlike the vector's
/// (`0,7071, 0, 0,7071` for three numbers), are an error that says how to
/// write them.
fn vector_numbers(t: &str, like: &Val, offset: usize) -> Option<Result<Read, Msg>> {
    let Val::List(items) = like else {
        return None;
    };
    let n = items.len();
    if let Some(parts) = scaled(t) {
        return Some(numbers(&parts, offset));
    }
    let split = components(t);
    if split.len() == n {
        if let Some(read) = all_numbers(split.iter().map(|p| p.text)) {
            // read as parts; as numbers here when each part is one
            let each_a_number = (items.iter()).all(|x| matches!(x, Val::Num(_)));
            return each_a_number.then_some(Ok(read));
        }
    }
    if let Some(parts) = spaced(t).filter(|p| p.len() == n) {
        if let Some(read) = all_numbers(parts.iter().map(|(p, _)| p.as_str())) {
            return Some(Ok(read));
        }
    }
    if split.len() != n && split_at(strip_outer(t), ';').len() == 1 && mixed_commas(t) {
        return Some(Err(Msg::AmbiguousCommas));
    }
    None
}

/// A list of numbers, each part one (where it starts in its text; the
/// text starts at `offset` in the whole answer); an unreadable one is
/// named as a list's part is.
fn numbers(parts: &[(String, usize)], offset: usize) -> Result<Read, Msg> {
    let mut read = Vec::with_capacity(parts.len());
    let mut bad = Vec::new();
    for (i, (p, at)) in parts.iter().enumerate() {
        match number_at(p, offset + at) {
            Ok(x) => read.push(Read::Num(x)),
            Err(m) => bad.push((label(i, parts.len(), false), m)),
        }
    }
    if bad.is_empty() {
        Ok(Read::List(read))
    } else {
        Err(Msg::Parts(bad))
    }
}

/// A list of numbers when every text is one, each read once; None at the
/// first that is not.
fn all_numbers<'a>(texts: impl Iterator<Item = &'a str>) -> Option<Read> {
    let read: Option<Vec<Read>> = texts.map(|t| number(t).ok().map(Read::Num)).collect();
    read.map(Read::List)
}

/// Whether commas are written two ways: one between two digits (a
/// decimal mark, or a separator without a space: `0,7071`) and one that is
/// not (a separator: `, `).
fn mixed_commas(t: &str) -> bool {
    let c: Vec<char> = t.chars().collect();
    let between = |i: usize| {
        i > 0 && c[i - 1].is_ascii_digit() && c.get(i + 1).is_some_and(char::is_ascii_digit)
    };
    let commas: Vec<bool> = (0..c.len()).filter(|&i| c[i] == ',').map(between).collect();
    commas.contains(&true) && commas.contains(&false)
}

/// The numbers of a vector separated by spaces outside brackets (`0 0 -1
/// 4`, `(0,8 0,6 0)`), each with where it starts; None when there are no
/// spaces between numbers.
fn spaced(t: &str) -> Option<Vec<(String, usize)>> {
    let inner = strip_outer(t);
    let lead = t[..t.len() - t.trim_start().len()].chars().count()
        + usize::from(inner.len() < t.trim().len());
    let mut parts = Vec::new();
    let mut depth = 0i32;
    let mut cur = String::new();
    let mut at = 0;
    for (n, c) in inner.chars().enumerate() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            _ => {}
        }
        if c.is_whitespace() && depth == 0 {
            if !cur.is_empty() {
                parts.push((std::mem::take(&mut cur), lead + at));
            }
            continue;
        }
        if cur.is_empty() {
            at = n;
        }
        cur.push(c);
    }
    if !cur.is_empty() {
        parts.push((cur, lead + at));
    }
    (parts.len() > 1).then_some(parts)
}

/// A vector times or over a number, as grafika prints one: `(1, 0, 1)/√2`,
/// `−(4, 3, 0)/5`, `√2/2·(1, 0, 1)`, `1/√2 (1, 0, 1)`, `2*(1; 0,5; 0)`:
/// each component as an expression with the number (`(1)/(√2)`), and
/// where the component starts. The vector is the one bracketed group of
/// the text whose parts are separated by commas or `;`; what stands before
/// it multiplies it (a sign, a factor with or without `*`, `·`, `×`), what
/// follows divides or multiplies it (`/`, `*`, `·`, `×` and a number).
fn scaled(t: &str) -> Option<Vec<(String, usize)>> {
    let (open, close) = vector_group(t)?;
    let (before, inner, after) = (&t[..open], &t[open + 1..close], &t[close + 1..]);
    let (before, after) = (before.trim(), after.trim());
    if before.is_empty() && after.is_empty() {
        return None;
    }
    let lead = match before {
        "" => String::new(),
        "-" | "−" => "-".to_string(),
        "+" => String::new(),
        b => format!("({})*", b.trim_end_matches(['*', '·', '×']).trim()),
    };
    let tail = match after.chars().next() {
        None => String::new(),
        Some('/') => format!("/({})", &after[1..]),
        Some(c @ ('*' | '·' | '×')) => format!("*({})", &after[c.len_utf8()..]),
        Some(_) => return None,
    };
    // a column in a component's error counts from the written part
    let start = t[..open + 1].chars().count();
    let written_from = |at: usize| (start + at).saturating_sub(lead.chars().count() + 1);
    let parts = components(inner);
    (parts.len() > 1).then(|| {
        parts
            .iter()
            .map(|p| (format!("{lead}({}){tail}", p.text), written_from(p.at)))
            .collect()
    })
}

/// The bracketed group of `t` (its bracket's byte positions) that holds a
/// comma or `;` of its own, when there is exactly one and nothing outside
/// it does.
fn vector_group(t: &str) -> Option<(usize, usize)> {
    let mut found = None;
    let mut depth = 0i32;
    let mut open = 0;
    let mut holds = false;
    for (i, c) in t.char_indices() {
        match c {
            '(' | '[' => {
                if depth == 0 {
                    open = i;
                    holds = false;
                }
                depth += 1;
            }
            ')' | ']' => {
                depth -= 1;
                if depth == 0 && holds {
                    if found.is_some() {
                        return None;
                    }
                    found = Some((open, i));
                }
            }
            ',' | ';' if depth == 0 => return None,
            ',' | ';' if depth == 1 => holds = true,
            _ => {}
        }
    }
    found
}

/// A list written as text whose only fault is its missing last `)`
/// (`(1/sqrt(2), 0, 1/sqrt(2)`): the reader's words say so (`)` expected
/// at the end), not what the first part lacks once the `(` swallowed it.
fn unclosed(given: Given, like: &Val, offset: usize) -> Option<Msg> {
    let Given::Text(t) = given else {
        return None;
    };
    let at = missing_close(t)?;
    let closed = format!("{t})");
    list(Given::Text(&closed), like, offset).ok()?;
    Some(Msg::Unreadable(NumErr::Expected(
        Want::Close,
        offset + at,
        None,
    )))
}

/// The parts of a list written as text ([`components`]). A matrix or a
/// segment written flat, its numbers in a row without `;` or brackets
/// around its rows, is cut into rows of the length expected.
fn text_parts<'a>(t: &'a str, items: &[Val]) -> Vec<Part<'a>> {
    let parts = components(t);
    let row = match items.first() {
        Some(Val::List(r))
            if items
                .iter()
                .all(|x| matches!(x, Val::List(y) if y.len() == r.len())) =>
        {
            r.len()
        }
        _ => return parts,
    };
    if row == 0 || parts.len() != items.len() * row || parts.len() == items.len() {
        return parts;
    }
    parts
        .chunks(row)
        .map(|c| {
            let (first, last) = (c[0], c[c.len() - 1]);
            let start = first.text.as_ptr() as usize - t.as_ptr() as usize;
            let end = last.text.as_ptr() as usize - t.as_ptr() as usize + last.text.len();
            Part {
                text: &t[start..end],
                at: first.at,
            }
        })
        .collect()
}

/// A part's name in a note: x, y, z of a point; its number otherwise
/// (`2.z` is the z of the second point of a segment or row).
fn label(i: usize, n: usize, nested: bool) -> String {
    if !nested && n <= 3 {
        ["x", "y", "z"][i.min(2)].to_string()
    } else {
        format!("{}", i + 1)
    }
}

/// An outcode: up to six binary digits, spaces ignored, padded on the left.
fn code(text: &str) -> Result<Read, Msg> {
    let digits: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let binary = !digits.is_empty() && digits.chars().all(|c| c == '0' || c == '1');
    if binary && digits.len() <= 6 {
        Ok(Read::Word(format!("{digits:0>6}")))
    } else {
        Err(Msg::NotAnOutcode(text.trim().to_string()))
    }
}

/// A clipping status in either language, any case: `clipped (di-clip)`
/// names one status twice and is read as it.
fn status(text: &str) -> Result<Read, Msg> {
    let t = text.trim().to_lowercase();
    let words: Vec<&str> = t
        .split(|c: char| c.is_whitespace() || matches!(c, '(' | ')' | ',' | '/' | '.'))
        .filter(|w| !w.is_empty())
        .collect();
    let named: Vec<&str> = words.iter().filter_map(|w| status_word(w)).collect();
    match named.first() {
        Some(first) if named.iter().all(|s| s == first) && named.len() == words.len() => {
            Ok(Read::Word(first.to_string()))
        }
        _ => Err(Msg::NotAStatus(text.trim().to_string())),
    }
}

/// A status word, English or Indonesian, as grafika spells the status.
fn status_word(w: &str) -> Option<&'static str> {
    Some(match w {
        "accepted" | "accept" | "diterima" | "terima" => "accepted",
        "rejected" | "reject" | "ditolak" | "tolak" => "rejected",
        "clipped" | "clip" | "di-clip" | "diclip" | "dikliping" | "dipotong" | "terpotong" => {
            "clipped"
        }
        _ => return None,
    })
}

/// Yes or no in either language, any case, as grafika's `true` or
/// `false`: `yes`, `ya`, `iya`, `true`, `kept`, `dipertahankan`; `no`,
/// `tidak`, `false`, `dibuang`, `discarded` (and TOML's booleans).
fn yes_no(text: &str) -> Result<Read, Msg> {
    let t = text.trim().to_lowercase();
    let b = match t.as_str() {
        "yes" | "y" | "ya" | "iya" | "true" | "kept" | "dipertahankan" => true,
        "no" | "n" | "tidak" | "false" | "discarded" | "dibuang" => false,
        _ => return Err(Msg::NotYesOrNo(text.trim().to_string())),
    };
    Ok(Read::Word(b.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(x: f64) -> Val {
        Val::num(&x)
    }
    fn vec3() -> Val {
        Val::List(vec![num(1.0), num(0.0), num(1.0)])
    }
    fn values(r: &Read) -> Vec<f64> {
        match r {
            Read::Num(n) => vec![n.value],
            Read::List(items) => items.iter().flat_map(values).collect(),
            _ => vec![],
        }
    }
    fn text(s: &str) -> toml::Value {
        toml::Value::String(s.into())
    }
    fn en(m: &Msg) -> String {
        crate::report::words::words(m, crate::report::lang::Lang::En)
    }

    #[test]
    fn every_written_form_of_a_vector() {
        // 1/√2 = 0.70710678…, written as the text and its students write it
        let r = std::f64::consts::FRAC_1_SQRT_2;
        for t in [
            "(1/sqrt(2), 0, 1/sqrt(2))",
            "1/sqrt(2), 0, 1/sqrt(2)",
            "[1/sqrt(2), 0, 1/sqrt(2)]",
            "(√2/2, 0, √2/2)",
            "((1/2)sqrt(2), 0, (1/2)√2)",
            "(0,70710678118654752; 0; 0,70710678118654752)",
        ] {
            let got = values(&read(&text(t), &vec3()).unwrap());
            assert_eq!(got.len(), 3, "{t}");
            assert!((got[0] - r).abs() < 1e-15 && got[1] == 0.0, "{t}: {got:?}");
            assert!((got[2] - r).abs() < 1e-15, "{t}: {got:?}");
        }
        // the text's A′ = (0, −1, −6/√2) = (0, −1, −3√2), with a unicode minus
        let got = values(&read(&text("0, −1, −6/√2"), &vec3()).unwrap());
        assert!((got[2] + 3.0 * 2f64.sqrt()).abs() < 1e-14, "{got:?}");
        // implicit products: 3√2 and 2sqrt(2)
        let got = values(&read(&text("3√2, 2sqrt(2), -3*sqrt(2)"), &vec3()).unwrap());
        assert!((got[0] - got[1] - 2f64.sqrt()).abs() < 1e-14 && got[2] < -4.24);
    }

    proptest::proptest! {
        /// A vector reads as the same three numbers in every container and
        /// with either decimal mark: (a, b, c), [a, b, c], bare a, b, c,
        /// a TOML array, and a; b; c with decimal commas.
        #[test]
        fn a_vector_reads_the_same_in_every_form(
            parts in proptest::collection::vec((-9999i32..9999, 0u32..4), 3),
            form in 0usize..6,
        ) {
            let want: Vec<f64> = parts.iter().map(|(n, d)| *n as f64 / 10f64.powi(*d as i32)).collect();
            let dec = |(n, d): &(i32, u32), mark: char| {
                let s = format!("{:.*}", *d as usize, *n as f64 / 10f64.powi(*d as i32));
                s.replace('.', &mark.to_string())
            };
            let point: Vec<String> = parts.iter().map(|p| dec(p, '.')).collect();
            let comma: Vec<String> = parts.iter().map(|p| dec(p, ',')).collect();
            let given = match form {
                0 => text(&format!("({})", point.join(", "))),
                1 => text(&format!("[{}]", point.join(","))),
                2 => text(&point.join(" , ")),
                3 => toml::Value::Array(point.iter().map(|p| text(p)).collect()),
                4 => text(&format!("({})", comma.join("; "))),
                _ => text(&comma.join(";")),
            };
            let got = values(&read(&given, &vec3()).unwrap());
            proptest::prop_assert_eq!(got.len(), 3);
            for (g, w) in got.iter().zip(&want) {
                proptest::prop_assert!((g - w).abs() <= 1e-12 * w.abs().max(1.0), "{:?} {:?}", got, want);
            }
        }
    }

    #[test]
    fn a_matrix_by_rows_and_a_segment_by_ends() {
        let row = |xs: [f64; 4]| Val::List(xs.iter().map(|x| num(*x)).collect());
        let m = Val::List(vec![
            row([1.0; 4]),
            row([2.0; 4]),
            row([3.0; 4]),
            row([4.0; 4]),
        ]);
        let t = "1, 0, 0, -3*sqrt(2); 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1";
        let got = values(&read(&text(t), &m).unwrap());
        assert_eq!(got.len(), 16);
        assert!((got[3] + 3.0 * 2f64.sqrt()).abs() < 1e-14);
        let seg = Val::List(vec![vec3(), vec3()]);
        for t in [
            "(3, 8/3, 11/6); (1, 4, 3/2)",
            "(3, 8/3, 11/6), (1, 4, 3/2)",
            "[(3; 2,5; 1); (1; 4; 1,5)]",
        ] {
            let r = read(&text(t), &seg).unwrap();
            assert!(
                matches!(&r, Read::List(ends) if ends.len() == 2),
                "{t}: {r:?}"
            );
        }
        assert_eq!(read(&text("none"), &seg).unwrap(), Read::None);
        assert_eq!(read(&text("None"), &Val::Null).unwrap(), Read::None);
    }

    #[test]
    fn codes_and_statuses_in_either_language() {
        let code = Val::text("001000");
        assert_eq!(
            read(&text("001 000"), &code).unwrap(),
            Read::Word("001000".into())
        );
        assert_eq!(
            read(&text("1000"), &code).unwrap(),
            Read::Word("001000".into())
        );
        assert!(read(&text("0012"), &code).is_err());
        let st = Val::text("clipped");
        for (t, w) in [
            ("di-clip", "clipped"),
            ("Clipped (di-clip)", "clipped"),
            ("DITOLAK", "rejected"),
            ("diterima", "accepted"),
            ("rejected", "rejected"),
        ] {
            assert_eq!(read(&text(t), &st).unwrap(), Read::Word(w.into()), "{t}");
        }
        assert!(read(&text("clipped (ditolak)"), &st).is_err());
        assert!(read(&text("maybe"), &st).is_err());
    }

    #[test]
    fn yes_and_no_in_either_language() {
        let kept = Val::Bool(true);
        let word = |b: bool| Read::Word(b.to_string());
        for (t, b) in [
            ("ya", true),
            ("Tidak", false),
            ("yes", true),
            ("NO", false),
            ("true", true),
            ("false", false),
            ("dipertahankan", true),
            ("dibuang", false),
        ] {
            assert_eq!(read(&text(t), &kept).unwrap(), word(b), "{t}");
        }
        assert_eq!(
            read(&toml::Value::Boolean(false), &kept).unwrap(),
            word(false)
        );
        let e = read(&text("mungkin"), &kept).unwrap_err();
        assert_eq!(e, Msg::NotYesOrNo("mungkin".into()));
        assert!(en(&e).contains("yes or no"), "{}", en(&e));
    }

    /// Each number of a list read exactly, as an exact value.
    fn exact(r: &Read) -> Vec<crate::num::Real> {
        match r {
            Read::Num(n) => vec![n.expr.eval::<crate::num::Real>().unwrap()],
            Read::List(items) => items.iter().flat_map(exact).collect(),
            _ => vec![],
        }
    }
    fn real(t: &str) -> crate::num::Real {
        parse_expr(t).unwrap().eval().unwrap()
    }

    #[test]
    fn a_point_with_its_name_and_a_vector_times_a_number() {
        // the text's intersection A(3; 8/3; 11/6), and a segment of two
        let a = read(&text("A(3; 8/3; 11/6)"), &vec3()).unwrap();
        assert_eq!(exact(&a), [real("3"), real("8/3"), real("11/6")]);
        let seg = Val::List(vec![vec3(), vec3()]);
        for t in [
            "A(3; 8/3; 11/6), B(1; 4; 3/2)",
            "A(3, 8/3, 11/6); B(1, 4, 3/2)",
            "P′ (3, 8/3, 11/6), P″ [1, 4, 3/2]",
        ] {
            let r = read(&text(t), &seg).unwrap();
            assert_eq!(exact(&r).len(), 6, "{t}");
            assert_eq!(exact(&r)[3], real("1"), "{t}");
        }
        // (1, 0, 1)/√2 = (√2/2, 0, √2/2), exactly, in every way it is written
        let half = real("sqrt(2)/2");
        for t in [
            "(1, 0, 1)/√2",
            "(1; 0; 1)/sqrt(2)",
            "1/√2 (1, 0, 1)",
            "√2/2·(1, 0, 1)",
            "sqrt(2)/2 * [1, 0, 1]",
            "(2, 0, 2)*(√2/4)",
            "n = (1, 0, 1)/√2",
        ] {
            let r = read(&text(t), &vec3()).unwrap();
            assert_eq!(exact(&r), [half.clone(), real("0"), half.clone()], "{t}");
        }
        // −(4, 3, 0)/5 = (−4/5, −3/5, 0); decimal commas inside
        let r = read(&text("−(4, 3, 0)/5"), &vec3()).unwrap();
        assert_eq!(exact(&r), [real("-4/5"), real("-3/5"), real("0")]);
        let r = read(&text("2·(0,5; 0; 0,25)"), &vec3()).unwrap();
        assert_eq!(exact(&r), [real("1"), real("0"), real("1/2")]);
        // sqrt and pi before a bracket are numbers, not names
        assert!(read(&text("sqrt(2)"), &vec3()).is_ok());
        let e = read(&text("(1, x, 1)/√2"), &vec3()).unwrap_err();
        assert!(en(&e).starts_with("y: "), "{}", en(&e));
    }

    #[test]
    fn rows_of_numbers_separated_by_spaces() {
        // the text's example 6.1: V = [0 0 −1 4; −3/5 4/5 0 −4/5; 4/5 3/5 0 −28/5; 0 0 0 1]
        let row = Val::List(vec![num(1.0); 4]);
        let m = Val::List(vec![row; 4]);
        let t = "0 0 -1 4; -0,6 0,8 0 -0,8; 0,8 0,6 0 -5,6; 0 0 0 1";
        let got = values(&read(&text(t), &m).unwrap());
        assert_eq!(
            got,
            [0.0, 0.0, -1.0, 4.0, -0.6, 0.8, 0.0, -0.8, 0.8, 0.6, 0.0, -5.6, 0.0, 0.0, 0.0, 1.0]
        );
        let got = values(&read(&text("(0,8 0,6 0)"), &vec3()).unwrap());
        assert_eq!(got, [0.8, 0.6, 0.0]);
        // an expression with spaces is still one number of a list
        let got = values(&read(&text("1 - 2, 3, 4"), &vec3()).unwrap());
        assert_eq!(got, [-1.0, 3.0, 4.0]);
    }

    /// The number of texts parsed while `f` runs.
    pub(crate) fn parses<T>(f: impl FnOnce() -> T) -> (T, usize) {
        let parsed = || crate::num::expr::PARSED.with(std::cell::Cell::get);
        let before = parsed();
        let out = f();
        (out, parsed() - before)
    }

    #[test]
    fn each_number_of_an_answer_is_parsed_once() {
        // (1/√2, 0, −1/√2) has three numbers, in each of these forms
        for t in [
            "(1/sqrt(2), 0, -1/sqrt(2))",
            "u = (1/sqrt(2), 0, -1/sqrt(2))",
            "(1, 0, -1)/√2",
            "0,7071; 0; -0,7071",
            "[√2/2, 0, −√2/2]",
        ] {
            let (r, n) = parses(|| read(&text(t), &vec3()));
            assert_eq!(values(&r.unwrap()).len(), 3, "{t}");
            assert_eq!(n, 3, "{t}");
        }
        let array = toml::Value::Array(vec![text("0.7071"), text("0"), text("-0.7071")]);
        assert_eq!(parses(|| read(&array, &vec3())).1, 3);
        // a matrix's sixteen numbers, by rows
        let row = Val::List(vec![num(1.0); 4]);
        let m = Val::List(vec![row; 4]);
        let t = "1, 0, 0, -3*sqrt(2); 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1";
        assert_eq!(parses(|| read(&text(t), &m)).1, 16);
    }

    #[test]
    fn decimal_commas_beside_comma_separators_are_not_read() {
        let e = read(&text("0,7071, 0, 0,7071"), &vec3()).unwrap_err();
        assert_eq!(e, Msg::AmbiguousCommas);
        let words = en(&e);
        assert!(
            words.contains("0,7071; 0; 0,7071") && words.contains("0.7071, 0, 0.7071"),
            "{words}"
        );
        let id = crate::report::words::words(&e, crate::report::lang::Lang::Id);
        assert!(id.contains("0,7071; 0; 0,7071"), "{id}");
        // one way each: read
        for t in [
            "0,7071; 0; 0,7071",
            "0.7071, 0, 0.7071",
            "3,1,3",
            "(0,5;1;2)",
        ] {
            assert_eq!(values(&read(&text(t), &vec3()).unwrap()).len(), 3, "{t}");
        }
        // xp, yp of a projected point without zp: two numbers, not ambiguous
        assert_eq!(values(&read(&text("1,5"), &vec3()).unwrap()).len(), 2);
    }

    #[test]
    fn an_unreadable_part_is_named_with_its_column_in_the_whole_answer() {
        // `1/sqrt(2, 0, 1`: the x part `1/sqrt(2` lacks its `)`; the part
        // starts at column 2 of the answer, the `)` is missing at its column
        // 9, which is column 10 of the whole answer.
        let e = read(&text("(1/sqrt(2, 0, 1)"), &vec3()).unwrap_err();
        let words = en(&e);
        assert!(
            words.starts_with("x: ") && words.contains("column 10"),
            "{words}"
        );
        // `(1/sqrt(2), 0, 1/sqrt(2)`: only the list's `)` is missing, after
        // its 24 characters; `(3, 1, 3` likewise after 8.
        let e = read(&text("(1/sqrt(2), 0, 1/sqrt(2)"), &vec3()).unwrap_err();
        assert_eq!(e, Msg::Unreadable(NumErr::Expected(Want::Close, 25, None)));
        assert_eq!(
            crate::num::expr::parse_vec3("(3, 1, 3").unwrap_err(),
            NumErr::Expected(Want::Close, 9, None)
        );
        // written after its name, as on paper: the column counts the name
        let n = read(&text("n = (1/sqrt(2), 0, 1/sqrt(2))"), &vec3()).unwrap();
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let got = values(&n);
        assert!((got[0] - r).abs() < 1e-15 && got[1] == 0.0 && (got[2] - r).abs() < 1e-15);
        let e = read(&text("A'' = (0, x, 1)"), &vec3()).unwrap_err();
        assert!(
            en(&e).contains("y: ") && en(&e).contains("column 11"),
            "{}",
            en(&e)
        );
        assert!(read(&text("1 = 1"), &vec3()).is_err());
        let e = read(&text("1, banana, 0"), &vec3()).unwrap_err();
        assert!(en(&e).starts_with("y: "), "{}", en(&e));
        // a decimal number with a comma is one number
        let n = number("0,0414").unwrap();
        assert_eq!((n.value, n.last_digit), (0.0414, Some(-4)));
        assert!(number("1, 5").is_err());
    }
}
