//! Errors as values: the field at fault and the reason. One place (`main`)
//! turns them into a message on stderr, a JSON object with `--json`, and exit
//! status 2.

use std::fmt;

/// A user-facing error: which input was wrong and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Error {
    /// The input at fault, as the user named it (`--up`, `camera.eye`, `points.A`).
    pub field: String,
    /// Why, with the offending values.
    pub message: String,
}

impl Error {
    /// An error about `field`.
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Error {
        Error {
            field: field.into(),
            message: message.into(),
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
        write!(f, "{}: {}", self.field, self.message)
    }
}

impl std::error::Error for Error {}

/// Results of the stages and commands.
pub type Result<T> = std::result::Result<T, Error>;
