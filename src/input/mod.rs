//! What users type, read and validated: flag values ([`values`]), answers
//! ([`answer`]), problem
//! files ([`problem`]), scene files ([`scene`]), lights files and the
//! `[shade]` set-up ([`lights`]) and meshes ([`mesh`]). Every error names the
//! field (and, for files, the line and column).

pub mod answer;
pub mod ask;
pub mod fields;
pub mod lights;
pub mod mesh;
pub mod moodle_responses;
pub mod part;
pub mod problem;
pub mod scene;
pub mod streams;
pub mod values;

pub use values::*;

use crate::error::{Error, Result};
use crate::msg::{ErrMsg, FileKind, IoWhy};
use std::io::Read;
use std::path::Path;

/// The largest problem, scene, lights or answer file read, in bytes: a
/// class's answer files are a few KB, a problem of 2,000 points 51 KB. A
/// longer file is refused before it is read as TOML, so reading stays
/// bounded (standard input too: at most this much of it is read).
pub const MAX_FILE: usize = 1 << 20;

/// The text of a file the user named, `-` being standard input, at most
/// [`MAX_FILE`] bytes; an error names `field`. Only a regular file is read
/// ([`open_regular`]); a closed standard input is an error.
pub fn read_text(field: &str, path: &Path) -> Result<String> {
    if path.as_os_str() == "-" {
        if streams::stdin_closed() {
            return Err(Error::why(field, ErrMsg::StdinClosed));
        }
        let why = |e: std::io::Error| Error::why(field, ErrMsg::CannotReadStdin(IoWhy::of(&e)));
        return bounded(std::io::stdin().lock(), "-", None, field, why);
    }
    let shown = path.display().to_string();
    let why = |e: std::io::Error| {
        Error::said(
            field,
            crate::msg::Msg::ErrCannotRead(shown.clone(), IoWhy::of(&e)),
        )
    };
    let file = match open_regular(path) {
        Ok(f) => f,
        Err(NotOpened::Io(e)) => return Err(why(e)),
        Err(NotOpened::NotRegular(k)) => {
            return Err(Error::why(field, ErrMsg::InputNotRegular(shown, k)))
        }
    };
    let size = file.metadata().ok().map(|m| m.len());
    bounded(file, &shown, size, field, why)
}

/// Reads at most [`MAX_FILE`] bytes of `r` as text; more is an error
/// giving the size (`size`, when known).
fn bounded(
    r: impl Read,
    shown: &str,
    size: Option<u64>,
    field: &str,
    why: impl Fn(std::io::Error) -> Error,
) -> Result<String> {
    let too_large = || Error::why(field, ErrMsg::FileTooLarge(shown.into(), size, MAX_FILE));
    if size.is_some_and(|n| n > MAX_FILE as u64) {
        return Err(too_large());
    }
    let mut text = String::new();
    r.take(MAX_FILE as u64 + 1)
        .read_to_string(&mut text)
        .map_err(why)?;
    if text.len() > MAX_FILE {
        return Err(too_large());
    }
    Ok(text)
}

/// Why a file the user named was not opened.
#[derive(Debug)]
pub enum NotOpened {
    /// The system's error.
    Io(std::io::Error),
    /// It is not a regular file: what it is.
    NotRegular(FileKind),
}

/// Opens a file the user named for reading, refusing anything but a
/// regular file (links followed): a FIFO would wait forever for a writer,
/// a device never end. The file is opened without waiting (`O_NONBLOCK`, so
/// a FIFO put in its place after a look still cannot block) and its kind
/// is taken from the open file itself.
pub fn open_regular(path: &Path) -> std::result::Result<std::fs::File, NotOpened> {
    let mut opts = std::fs::OpenOptions::new();
    opts.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        opts.custom_flags(libc::O_NONBLOCK);
    }
    let file = opts.open(path).map_err(NotOpened::Io)?;
    let meta = file.metadata().map_err(NotOpened::Io)?;
    if !meta.is_file() {
        return Err(NotOpened::NotRegular(FileKind::of(&meta)));
    }
    Ok(file)
}
