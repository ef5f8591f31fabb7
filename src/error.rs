//! Errors as values: the field at fault and the reason. One place (`main`)
//! turns them into a message on stderr, a JSON object with `--json`, and exit
//! status 2.

use crate::msg::Msg;
use std::fmt;

/// A user-facing error: which input was wrong and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Error {
    /// The input at fault, as the user named it (`--up`, `camera.eye`, `points.A`).
    pub field: String,
    /// Why, with the offending values: a message key (`report::words`
    /// gives its words in every language). There is no way to give
    /// English text instead: an error without both languages does not
    /// compile.
    pub message: Msg,
}

impl Error {
    /// An error about `field`: why it was refused (`msg::ErrMsg`).
    pub fn why(field: impl Into<String>, why: impl Into<crate::msg::ErrMsg>) -> Error {
        Error::said(field, Msg::Err(why.into()))
    }

    /// An error about `field`, said by a message key.
    pub fn said(field: impl Into<String>, message: Msg) -> Error {
        Error {
            field: field.into(),
            message,
        }
    }

    /// The same error with a location (`file:line:col`) before its message.
    pub fn at(self, place: impl Into<String>) -> Error {
        Error {
            message: Msg::At(place.into(), Box::new(self.message)),
            ..self
        }
    }

    /// The same error, reported against another (outer) field name.
    pub fn in_field(self, field: impl Into<String>) -> Error {
        Error {
            field: field.into(),
            ..self
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field, self.message.plain())
    }
}

impl std::error::Error for Error {}

/// Results of the stages and commands.
pub type Result<T> = std::result::Result<T, Error>;
