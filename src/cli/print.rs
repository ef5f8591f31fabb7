//! Standard output and standard error (issue 28): everything grafika
//! prints goes through here.
//!
//! Text is shown with its control characters escaped
//! ([`crate::report::escape`]); a write error is an error (one line on
//! stderr, exit status 2), never a panic; a broken pipe (`| head -1`) ends
//! the output quietly, as Unix tools do; a closed standard output (`>&-`)
//! is refused before any work is done, since the results would be lost.

use crate::error::{Error, Result};
use crate::msg::{ErrMsg, IoWhy};
use crate::report::escape;
use std::io::Write;

/// What is printed: how it is escaped on the way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Text for people: control characters shown as `\u{XX}` (with
    /// `colour`, grafika's own plain colours kept).
    Text { colour: bool },
    /// JSON: the same escapes as JSON `\uXXXX`, so it reads back the same.
    Json,
}

/// How printing ended, when it did not succeed.
#[derive(Debug)]
pub enum Stopped {
    /// The reader went away (a broken pipe): stop quietly.
    Pipe,
    /// Any other write error.
    Failed(Error),
}

impl From<std::io::Error> for Stopped {
    fn from(e: std::io::Error) -> Stopped {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            Stopped::Pipe
        } else {
            Stopped::Failed(Error::why(
                "stdout",
                ErrMsg::CannotWriteStdout(IoWhy::of(&e)),
            ))
        }
    }
}

/// Prints `text` on standard output, escaped for its kind, and flushes.
pub fn stdout(text: &str, kind: Kind) -> std::result::Result<(), Stopped> {
    let shown = match kind {
        Kind::Text { colour } => escape::terminal(text, colour),
        Kind::Json => escape::json(text),
    };
    let mut out = std::io::stdout().lock();
    out.write_all(shown.as_bytes())?;
    out.flush()?;
    Ok(())
}

/// Writes bytes (a PNG) to standard output as they are.
pub fn stdout_bytes(
    body: &mut dyn FnMut(&mut dyn Write) -> std::io::Result<()>,
) -> std::result::Result<(), Stopped> {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    body(&mut out)?;
    out.flush()?;
    Ok(())
}

/// Prints a line of text on standard error, escaped; an error writing it
/// is ignored (there is nowhere left to say it).
pub fn stderr_line(text: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{}", escape::terminal(text, false));
}

/// Refuses a closed standard output (`>&-`), where every result would
/// vanish without an error. Only a descriptor closed when the process
/// started counts ([`crate::input::streams`]): `> /dev/null` and
/// `1<>/dev/null` discard the output as asked.
pub fn refuse_closed_stdout() -> Result<()> {
    if crate::input::streams::stdout_closed() {
        return Err(Error::why("stdout", ErrMsg::StdoutClosed));
    }
    Ok(())
}
