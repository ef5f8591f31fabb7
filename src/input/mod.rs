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
pub mod part;
pub mod problem;
pub mod scene;
pub mod values;

pub use values::*;

use crate::error::{Error, Result};
use crate::msg::{ErrMsg, IoWhy};
use std::path::Path;

/// The text of a file the user named, `-` being standard input; an error
/// names `field`.
pub fn read_text(field: &str, path: &Path) -> Result<String> {
    if path.as_os_str() == "-" {
        let mut text = String::new();
        std::io::Read::read_to_string(&mut std::io::stdin(), &mut text)
            .map_err(|e| Error::why(field, ErrMsg::CannotReadStdin(IoWhy::of(&e))))?;
        return Ok(text);
    }
    std::fs::read_to_string(path).map_err(|e| {
        Error::said(
            field,
            crate::msg::Msg::ErrCannotRead(path.display().to_string(), IoWhy::of(&e)),
        )
    })
}
