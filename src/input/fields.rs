//! What every input file shares: numbers written as TOML numbers or as
//! expressions ([`Num`]), vectors of them, angles in degrees or radians, and
//! TOML errors turned into `file:line:column: message` naming the field.

use crate::error::{Error, Result};
use crate::msg::ErrMsg;
use crate::msg::TomlErr;
use crate::num::{parse_expr, Expr};
use serde::de::{self, Deserializer};
use serde::Deserialize;
use std::cell::RefCell;

/// A number in a file: a TOML integer or float (taken at its written decimal
/// value) or a string holding an expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Num(pub Expr);

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Num, D::Error> {
        struct V;
        impl de::Visitor<'_> for V {
            type Value = Num;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a number or a string with a number expression such as \"sqrt(2)/2\"")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> std::result::Result<Num, E> {
                Ok(Num(Expr::Lit(v.unsigned_abs().to_string()).neg_if(v < 0)))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> std::result::Result<Num, E> {
                Ok(Num(Expr::Lit(v.to_string())))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> std::result::Result<Num, E> {
                if !v.is_finite() {
                    let e = crate::msg::NumErr::NotFiniteLiteral(v.to_string());
                    return Err(value_error(TomlErr::Num(e)));
                }
                // Rust prints the shortest decimal that reads back to v: the
                // value as written in the file.
                let s = format!("{}", v.abs());
                Ok(Num(Expr::Lit(s).neg_if(v.is_sign_negative())))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> std::result::Result<Num, E> {
                parse_expr(v)
                    .map(Num)
                    .map_err(|m| value_error(TomlErr::Num(m.quoted(v))))
            }
        }
        d.deserialize_any(V)
    }
}

impl Expr {
    /// −self when `neg`, else self.
    fn neg_if(self, neg: bool) -> Expr {
        if neg {
            Expr::Neg(Box::new(self))
        } else {
            self
        }
    }
}

/// A vector [x, y, z]: a TOML array of three numbers or expressions, or one
/// string as people write a vector (`"(1/sqrt(2), 0, -6/sqrt(2))"`,
/// `"0; 1; 0"`, `"[3, 1, 3]"`), read by the same reader as a flag's
/// vector ([`crate::num::expr::parse_vec3`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Vec3In(pub [Num; 3]);

impl std::ops::Deref for Vec3In {
    type Target = [Num; 3];
    fn deref(&self) -> &[Num; 3] {
        &self.0
    }
}

impl From<[Num; 3]> for Vec3In {
    fn from(v: [Num; 3]) -> Vec3In {
        Vec3In(v)
    }
}

impl<'de> Deserialize<'de> for Vec3In {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Vec3In, D::Error> {
        struct V;
        impl<'de> de::Visitor<'de> for V {
            type Value = Vec3In;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a vector: an array [x, y, z] or a string \"(x, y, z)\"")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<Vec3In, E> {
                crate::num::expr::parse_vec3(s)
                    .map(|[x, y, z]| Vec3In([Num(x), Num(y), Num(z)]))
                    .map_err(|m| value_error(TomlErr::Num(m.quoted(s))))
            }
            fn visit_seq<A: de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> std::result::Result<Vec3In, A::Error> {
                let mut v = Vec::with_capacity(3);
                while v.len() < 3 {
                    match seq.next_element::<Num>()? {
                        Some(n) => v.push(n),
                        None => break,
                    }
                }
                let mut n = v.len();
                while seq.next_element::<de::IgnoredAny>()?.is_some() {
                    n += 1;
                }
                match v.try_into() {
                    Ok(a) if n == 3 => Ok(Vec3In(a)),
                    _ => Err(de::Error::invalid_length(n, &"an array of length 3")),
                }
            }
        }
        d.deserialize_any(V)
    }
}

/// An angle: a number (degrees) or a string (`"45"`, `"pi/4 rad"`).
#[derive(Clone, Debug, PartialEq)]
pub struct AngleIn(pub crate::num::Angle);

impl<'de> Deserialize<'de> for AngleIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<AngleIn, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Raw {
            S(String),
            N(Num),
        }
        match Raw::deserialize(d)? {
            Raw::S(s) => crate::num::Angle::parse(&s)
                .map(AngleIn)
                .map_err(|m| value_error(TomlErr::Num(m.quoted(&s)))),
            Raw::N(n) => Ok(AngleIn(crate::num::Angle {
                value: n.0,
                unit: crate::num::AngleUnit::Deg,
            })),
        }
    }
}

thread_local! {
    /// The last error a value of a file raised, with the text serde
    /// carries for it: serde's errors are text, so the key travels beside it.
    static VALUE_ERROR: RefCell<Option<(String, TomlErr)>> = const { RefCell::new(None) };
}

/// A serde error for a value that cannot be taken (a number that cannot
/// be read, a value out of its bounds); [`toml_error`] finds its key again.
pub fn value_error<E: de::Error>(e: TomlErr) -> E {
    let text = format!("{e:?}");
    VALUE_ERROR.with(|c| *c.borrow_mut() = Some((text.clone(), e)));
    E::custom(text)
}

/// A TOML error at `origin:line:col`, field = the key at fault if known.
pub fn toml_error(origin: &str, text: &str, e: &toml::de::Error) -> Error {
    let (line, col) = e.span().map(|s| line_col(text, s.start)).unwrap_or((0, 0));
    let msg = e.message().trim().to_string();
    let field = field_of_toml_error(&msg, text, line, col);
    Error::why(field, toml_reason(&msg)).at(format!("{origin}:{line}:{col}"))
}

/// What a TOML reader's message says, as a key: the kinds serde names, the
/// number errors of [`Num`] and [`AngleIn`], else the reader's own words.
pub fn toml_reason(msg: &str) -> TomlErr {
    let value = VALUE_ERROR.with(|c| c.borrow_mut().take());
    if let Some((_, e)) = value.filter(|(t, _)| msg.contains(t.as_str())) {
        return e;
    }
    let ticked = |m: &str| m.split('`').nth(1).unwrap_or_default().to_string();
    let after = |m: &str, w: &str| m.split_once(w).map(|(_, r)| r.trim().to_string());
    if let Some(rest) = msg.strip_prefix("unknown field") {
        return TomlErr::UnknownField(ticked(rest), after(rest, "expected one of"));
    }
    if let Some(rest) = msg.strip_prefix("missing field") {
        return TomlErr::MissingField(ticked(rest));
    }
    if msg.starts_with("duplicate key") || msg.starts_with("duplicate field") {
        return TomlErr::Duplicate(ticked(msg));
    }
    if let Some(rest) = msg.strip_prefix("unknown variant") {
        let allowed = after(rest, "expected one of").or_else(|| after(rest, "expected"));
        return TomlErr::UnknownVariant(ticked(rest), allowed.unwrap_or_default());
    }
    for (head, kind) in [
        (
            "invalid type:",
            TomlErr::InvalidType as fn(String, String) -> TomlErr,
        ),
        ("invalid length", TomlErr::InvalidLength),
        ("invalid value:", TomlErr::InvalidValue),
    ] {
        if let Some((found, expected)) = msg
            .strip_prefix(head)
            .and_then(|r| r.rsplit_once(", expected "))
        {
            return kind(found.trim().to_string(), expected.trim().to_string());
        }
    }
    TomlErr::Syntax(msg.to_string())
}

/// The field a TOML error is about: the name in the message of an unknown,
/// missing or repeated field; else, for an error inside the value of a
/// `key = value` line, that key (`near = 0.1.2` is about `near`); else
/// `file`, never a stray token such as `#` or `=`.
fn field_of_toml_error(msg: &str, text: &str, line: usize, col: usize) -> String {
    let named = [
        "unknown field",
        "missing field",
        "duplicate key",
        "duplicate field",
    ];
    if named.iter().any(|n| msg.starts_with(n)) {
        if let Some(f) = msg.split('`').nth(1) {
            return f.to_string();
        }
    }
    let is_key = |k: &str| {
        !k.is_empty()
            && k.chars()
                .all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '"'))
    };
    text.lines()
        .nth(line.wrapping_sub(1))
        .and_then(|l| l.split_once('='))
        .filter(|(k, _)| col > k.chars().count() + 1)
        .map(|(k, _)| k.trim().trim_matches('"').to_string())
        .filter(|k| is_key(k))
        .unwrap_or_else(|| "file".to_string())
}

/// 1-based line and column of a byte offset.
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before
        .rfind('\n')
        .map(|i| before[i + 1..].chars().count())
        .unwrap_or(before.chars().count())
        + 1;
    (line, col)
}

/// The most values the arrays of one TOML file may hold together (and
/// `[[…]]` tables), counted before the file is read: a problem of 2,000
/// points holds 6,000. Each value read costs the TOML reader about 300
/// bytes, so this bounds its memory (a 20 MB array of 10 million integers
/// took 2.7 GB).
pub const MAX_TOML_VALUES: usize = 100_000;

/// The deepest nesting of arrays and inline tables a TOML file may have
/// (a point is one level, a matrix two).
pub const MAX_TOML_DEPTH: usize = 32;

/// Reads TOML text as `T` after [`toml_bounds`]; errors carry
/// `origin:line:col`.
pub fn parse_toml<T: serde::de::DeserializeOwned>(text: &str, origin: &str) -> Result<T> {
    toml_bounds(text, origin)?;
    toml::from_str(text).map_err(|e| toml_error(origin, text, &e))
}

/// Refuses, before the TOML reader allocates anything, a file whose arrays
/// hold more than [`MAX_TOML_VALUES`] values or nest deeper than
/// [`MAX_TOML_DEPTH`]: one pass over the text that skips strings and
/// comments and counts the commas of arrays (a value follows each) and the
/// arrays and `[[…]]` headers opened. The error is at the place the bound
/// is passed.
pub fn toml_bounds(text: &str, origin: &str) -> Result<()> {
    match scan(text.as_bytes()) {
        Ok(()) => Ok(()),
        Err((at, why)) => {
            let (line, col) = line_col(text, at);
            Err(Error::why("file", why).at(format!("{origin}:{line}:{col}")))
        }
    }
}

/// The pass of [`toml_bounds`]: `Err` with the byte offset and the bound
/// passed.
fn scan(b: &[u8]) -> std::result::Result<(), (usize, ErrMsg)> {
    // `open`: the brackets and braces of values open at this point;
    // `value`: on this line a `=` has started a value (at depth 0).
    let (mut open, mut value, mut count, mut i) = (Vec::new(), false, 0usize, 0usize);
    let mut add = |n: usize, at: usize| {
        count += n;
        if count > MAX_TOML_VALUES {
            return Err((at, ErrMsg::TomlTooManyValues(MAX_TOML_VALUES)));
        }
        Ok(())
    };
    while i < b.len() {
        match b[i] {
            b'"' | b'\'' => i = skip_string(b, i),
            b'#' => {
                i = skip_line(b, i);
                continue;
            }
            b'\n' if open.is_empty() => value = false,
            b'=' if open.is_empty() => value = true,
            // A table header (`[a]`, `[[a]]`): not a value; a `[[…]]` is
            // one more table.
            b'[' if open.is_empty() && !value => {
                if b.get(i + 1) == Some(&b'[') {
                    add(1, i)?;
                }
                i = skip_header(b, i);
                continue;
            }
            c @ (b'[' | b'{') => {
                open.push(c);
                if open.len() > MAX_TOML_DEPTH {
                    return Err((i, ErrMsg::TomlTooDeep(MAX_TOML_DEPTH)));
                }
                if c == b'[' {
                    add(1, i)?;
                }
            }
            b']' | b'}' => {
                open.pop();
            }
            b',' if open.last() == Some(&b'[') => add(1, i)?,
            _ => {}
        }
        i += 1;
    }
    Ok(())
}

/// The index of the newline ending the comment or line at `i` (or the end).
fn skip_line(b: &[u8], i: usize) -> usize {
    b[i..]
        .iter()
        .position(|&c| c == b'\n')
        .map_or(b.len(), |k| i + k)
}

/// The index of the last byte of the string starting at `i` (`"…"` with
/// escapes, `'…'`, and the multi-line `"""…"""` and `'''…'''`); an
/// unterminated string runs to the end (the TOML reader then says why).
fn skip_string(b: &[u8], i: usize) -> usize {
    let q = b[i];
    let triple = b.get(i + 1) == Some(&q) && b.get(i + 2) == Some(&q);
    let (mut k, close) = if triple { (i + 3, 3) } else { (i + 1, 1) };
    while k < b.len() {
        match b[k] {
            b'\\' if q == b'"' => k += 1,
            b'\n' if !triple => return k.saturating_sub(1),
            c if c == q && (close == 1 || b[k..].starts_with(&[q; 3])) => {
                // a closing `"""` may be followed by up to two more quotes
                let mut end = k + close - 1;
                while close == 3 && b.get(end + 1) == Some(&q) && end + 1 < k + 5 {
                    end += 1;
                }
                return end;
            }
            _ => {}
        }
        k += 1;
    }
    b.len()
}

/// The index just past a table header starting at `i` (its closing `]` or
/// `]]`, quoted names skipped), or the line's end.
fn skip_header(b: &[u8], i: usize) -> usize {
    let mut k = i + 1;
    while k < b.len() && b[k] != b'\n' {
        match b[k] {
            b'"' | b'\'' => k = skip_string(b, k),
            b']' => {
                return k + 1 + usize::from(b.get(k + 1) == Some(&b']'));
            }
            _ => {}
        }
        k += 1;
    }
    k
}
