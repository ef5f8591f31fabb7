//! The one writer of every output file (docs/spec.md §7, issue 28): PNG,
//! SVG, HTML, CSV and the folders `generate` fills.
//!
//! A file is written to a temporary file in its own folder, flushed, synced
//! and renamed over its name: a reader sees the old file or the whole new
//! one, never part of it, and on an error or a stop (see
//! [`super::signals`]) the temporary file is removed and the target left as
//! it was. Before anything is written the target is checked: an existing
//! file is refused unless `--force`; one of the command's own inputs (the
//! same file by any name: links and hard links followed) is refused even
//! with `--force`; a symbolic link is never written through nor replaced;
//! a folder is not a file name. Several files of one output are written
//! all or none.

use super::signals;
use crate::error::{Error, Result};
use crate::msg::{ErrMsg, IoWhy};
use std::cell::RefCell;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The identity of an existing file: the same for every name of it.
#[cfg(unix)]
type FileId = (u64, u64);
#[cfg(not(unix))]
type FileId = PathBuf;

#[cfg(unix)]
fn id_of(p: &Path) -> Option<FileId> {
    use std::os::unix::fs::MetadataExt;
    std::fs::metadata(p).ok().map(|m| (m.dev(), m.ino()))
}

#[cfg(not(unix))]
fn id_of(p: &Path) -> Option<FileId> {
    std::fs::canonicalize(p).ok()
}

/// What a command may write over: `--force`, and the files it reads (and
/// has written), which it never writes over.
#[derive(Debug, Default)]
pub struct Outputs {
    force: bool,
    inputs: RefCell<Vec<FileId>>,
}

/// A file's bytes, produced into the writer given.
pub type Body<'a> = &'a mut dyn FnMut(&mut dyn Write) -> std::io::Result<()>;

impl Outputs {
    /// Outputs of a command run with or without `--force`.
    pub fn new(force: bool) -> Outputs {
        Outputs {
            force,
            inputs: RefCell::new(Vec::new()),
        }
    }

    /// Adds files the command reads (standard input, `-`, and files that
    /// do not exist are skipped).
    pub fn reads<'p>(&self, files: impl IntoIterator<Item = &'p Path>) {
        let ids = files
            .into_iter()
            .filter(|p| p.as_os_str() != "-")
            .filter_map(id_of);
        self.inputs.borrow_mut().extend(ids);
    }

    /// Checks that `path` may be written: a file name (not a folder), not a
    /// symbolic link, not an input, and new unless `--force`. `field` is the
    /// flag the error names.
    pub fn check(&self, path: &Path, field: &str) -> Result<()> {
        let shown = path.display().to_string();
        let err = |m: ErrMsg| Err(Error::why(field, m));
        if names_a_folder(path) {
            return err(ErrMsg::NamesFolder(shown));
        }
        let meta = match std::fs::symlink_metadata(path) {
            Ok(m) => m,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
            Err(e) => return err(ErrMsg::CannotWrite(shown, IoWhy::of(&e))),
        };
        if meta.file_type().is_symlink() {
            return err(ErrMsg::IsLink(shown));
        }
        if meta.is_dir() {
            return err(ErrMsg::NamesFolder(shown));
        }
        if id_of(path).is_some_and(|id| self.inputs.borrow().contains(&id)) {
            return err(ErrMsg::IsInput(shown));
        }
        if !self.force {
            return err(ErrMsg::ExistsForce(shown));
        }
        Ok(())
    }

    /// Writes one file with the bytes `body` produces (see the module).
    pub fn write_with(&self, path: &Path, field: &str, body: Body<'_>) -> Result<()> {
        self.check(path, field)?;
        let temp = Temp::new(path, field)?;
        temp.fill(body)?;
        signals::locked(|| temp.put(self.force))?;
        self.reads([path]);
        Ok(())
    }

    /// Writes one file holding `bytes`.
    pub fn write(&self, path: &Path, field: &str, bytes: &[u8]) -> Result<()> {
        self.write_with(path, field, &mut |w| w.write_all(bytes))
    }

    /// Writes several files, all or none: every target is checked and every
    /// temporary file written before the first is put in place; if one
    /// cannot be put in place, the new files already put are removed again.
    pub fn write_all(&self, files: &[(PathBuf, String)], field: &str) -> Result<()> {
        for (i, (p, _)) in files.iter().enumerate() {
            self.check(p, field)?;
            if files[..i].iter().any(|(q, _)| q == p) {
                return Err(Error::why(
                    field,
                    ErrMsg::ExistsForce(p.display().to_string()),
                ));
            }
        }
        let mut temps = Vec::new();
        for (p, text) in files {
            let t = Temp::new(p, field)?;
            t.fill(&mut |w| w.write_all(text.as_bytes()))?;
            temps.push(t);
        }
        signals::locked(|| {
            let mut placed: Vec<PathBuf> = Vec::new();
            for t in temps {
                let target = t.target.clone();
                let new = std::fs::symlink_metadata(&target).is_err();
                if let Err(e) = t.put(self.force) {
                    placed.iter().for_each(|p| drop(std::fs::remove_file(p)));
                    return Err(e);
                }
                if new {
                    placed.push(target);
                }
            }
            Ok(())
        })?;
        self.reads(files.iter().map(|(p, _)| p.as_path()));
        Ok(())
    }
}

/// Whether a path names a folder rather than a file: it ends in `/` (or
/// the platform's separator), or its last part is `.` or `..`, or it has
/// no file name at all.
pub fn names_a_folder(path: &Path) -> bool {
    let s = path.as_os_str().to_string_lossy();
    s.is_empty()
        || s.ends_with(std::path::is_separator)
        || s.ends_with("/.")
        || s == "."
        || path.file_name().is_none()
}

/// The folder a file is written in (`.` for a bare name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// A temporary file beside its target, registered for removal on a stop.
struct Temp {
    file: tempfile::NamedTempFile,
    target: PathBuf,
    field: String,
    _registered: signals::Registered,
}

impl Temp {
    fn new(target: &Path, field: &str) -> Result<Temp> {
        let file = temp_builder(0o666)
            .tempfile_in(folder_of(target))
            .map_err(|e| cannot_write(field, target, &e))?;
        let registered = signals::file(file.path());
        Ok(Temp {
            file,
            target: target.to_path_buf(),
            field: field.to_string(),
            _registered: registered,
        })
    }

    /// Writes the body, flushes and syncs.
    fn fill(&self, body: Body<'_>) -> Result<()> {
        let fail = |e: std::io::Error| cannot_write(&self.field, &self.target, &e);
        let mut w = std::io::BufWriter::new(self.file.as_file());
        body(&mut w).map_err(fail)?;
        w.flush().map_err(fail)?;
        drop(w);
        hooks::sync(self.file.as_file()).map_err(fail)
    }

    /// Renames the temporary file onto the target (over an existing file
    /// only with `force`).
    fn put(self, force: bool) -> Result<()> {
        let Temp {
            file,
            target,
            field,
            _registered,
        } = self;
        let put = if force {
            file.persist(&target)
        } else {
            file.persist_noclobber(&target)
        };
        put.map(drop).map_err(|e| match e.error.kind() {
            std::io::ErrorKind::AlreadyExists => {
                Error::why(&field, ErrMsg::ExistsForce(target.display().to_string()))
            }
            _ => cannot_write(&field, &target, &e.error),
        })
    }
}

/// Temporary files and folders: hidden, named `.grafika-tmp-…`, with the
/// permissions a new file or folder gets (`mode`, 0o666 or 0o777, less the
/// umask; not tempfile's 0600).
pub fn temp_builder(mode: u32) -> tempfile::Builder<'static, 'static> {
    let mut b = tempfile::Builder::new();
    b.prefix(".grafika-tmp-");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        b.permissions(std::fs::Permissions::from_mode(mode));
    }
    #[cfg(not(unix))]
    let _ = mode;
    b
}

/// The error of a file that could not be written.
pub fn cannot_write(field: &str, path: &Path, e: &std::io::Error) -> Error {
    Error::why(
        field,
        ErrMsg::CannotWrite(path.display().to_string(), IoWhy::of(e)),
    )
}

/// Test hook: with `GRAFIKA_TEST_FAIL_SYNC=1` every sync of an output fails
/// as on a full disk, so the tests can check that no partial file is left
/// (every output file is synced here and only here).
pub(crate) mod hooks {
    /// Syncs a written file to the disk.
    pub fn sync(f: &std::fs::File) -> std::io::Result<()> {
        if std::env::var_os("GRAFIKA_TEST_FAIL_SYNC").is_some_and(|v| v == "1") {
            return Err(std::io::Error::new(
                std::io::ErrorKind::StorageFull,
                "no space left on device (GRAFIKA_TEST_FAIL_SYNC)",
            ));
        }
        f.sync_all()
    }
}
