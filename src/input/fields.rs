//! What every input file shares: numbers written as TOML numbers or as
//! expressions ([`Num`]), vectors of them, angles in degrees or radians, and
//! TOML errors turned into `file:line:column: message` naming the field.

use crate::error::Error;
use crate::num::{parse_expr, Expr};
use serde::de::{self, Deserializer};
use serde::Deserialize;

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
                    return Err(E::custom(format!("{v} is not a finite number")));
                }
                // Rust prints the shortest decimal that reads back to v: the
                // value as written in the file.
                let s = format!("{}", v.abs());
                Ok(Num(Expr::Lit(s).neg_if(v.is_sign_negative())))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> std::result::Result<Num, E> {
                parse_expr(v)
                    .map(Num)
                    .map_err(|m| E::custom(format!("`{v}`: {m}")))
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

/// A vector [x, y, z].
pub type Vec3In = [Num; 3];

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
                .map_err(|m| de::Error::custom(format!("`{s}`: {m}"))),
            Raw::N(n) => Ok(AngleIn(crate::num::Angle {
                value: n.0,
                unit: crate::num::AngleUnit::Deg,
            })),
        }
    }
}

/// A TOML error as `origin:line:col: message`, field = the key at fault if known.
pub fn toml_error(origin: &str, text: &str, e: &toml::de::Error) -> Error {
    let (line, col) = e.span().map(|s| line_col(text, s.start)).unwrap_or((0, 0));
    let msg = e.message().trim().to_string();
    let field = field_of_toml_error(&msg, text, line, col);
    Error::new(field, format!("{origin}:{line}:{col}: {msg}"))
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
