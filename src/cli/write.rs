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
//! a folder is not a file name; the same file is not given to two flags.
//! Several files of one output are written all or none.
//!
//! Only regular files are replaced: a character device (`-o /dev/null`) is
//! written directly, as `cat > /dev/null` does, and any other file that is
//! not a regular file (a FIFO, a socket, a disk) is refused, never
//! replaced, `--force` or not. A replaced file keeps its permissions (and
//! its owner and group, where the system lets the user keep them).
//!
//! A temporary file is named `.grafika-tmp-PID-START-…` (the process and
//! its start time); one left by a process that no longer runs (stopped by
//! SIGKILL) is removed by the next write into its folder, which says so
//! ([`stale_temps`]).

use super::signals;
use crate::error::{Error, Result};
use crate::msg::{ErrMsg, FileKind, IoWhy, Msg};
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
    /// The files this command has written, with the flag of each.
    written: RefCell<Vec<(FileId, String)>>,
}

/// A file's bytes, produced into the writer given.
pub type Body<'a> = &'a mut dyn FnMut(&mut dyn Write) -> std::io::Result<()>;

impl Outputs {
    /// Outputs of a command run with or without `--force`.
    pub fn new(force: bool) -> Outputs {
        Outputs {
            force,
            inputs: RefCell::new(Vec::new()),
            written: RefCell::new(Vec::new()),
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
    /// symbolic link, not an input nor a file this command has written,
    /// a regular file (replaced only with `--force`) or a character device
    /// (written directly), or new. `field` is the flag the error names.
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
        let id = id_of(path);
        let same = |(w, _): &&(FileId, String)| id.as_ref() == Some(w);
        if let Some((_, other)) = self.written.borrow().iter().find(same) {
            return err(ErrMsg::SameOutput(shown, other.clone()));
        }
        if id.is_some_and(|id| self.inputs.borrow().contains(&id)) {
            return err(ErrMsg::IsInput(shown));
        }
        match FileKind::of(&meta) {
            _ if meta.is_file() => {}
            FileKind::CharDevice => return Ok(()),
            kind => return err(ErrMsg::OutputNotRegular(shown, kind)),
        }
        if !self.force {
            return err(ErrMsg::ExistsForce(shown));
        }
        Ok(())
    }

    /// Writes one file with the bytes `body` produces (see the module).
    pub fn write_with(&self, path: &Path, field: &str, body: Body<'_>) -> Result<()> {
        self.check(path, field)?;
        if is_device(path) {
            return write_device(path, field, body);
        }
        note_stale(folder_of(path));
        let temp = Temp::new(path, field)?;
        temp.fill(body)?;
        signals::locked(|| temp.put(self.force))?;
        self.wrote(path, field);
        Ok(())
    }

    /// Notes a file this command wrote: it is not written again, nor read.
    fn wrote(&self, path: &Path, field: &str) {
        if let Some(id) = id_of(path) {
            self.written.borrow_mut().push((id, field.to_string()));
        }
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
            if files[..i].iter().any(|(q, _)| same_path(q, p)) {
                return Err(Error::why(
                    field,
                    ErrMsg::SameOutput(p.display().to_string(), field.to_string()),
                ));
            }
        }
        let (devices, files): (Vec<_>, Vec<_>) = files.iter().partition(|(p, _)| is_device(p));
        for (p, text) in devices {
            write_device(p, field, &mut |w| w.write_all(text.as_bytes()))?;
        }
        let mut temps = Vec::new();
        for (p, text) in &files {
            note_stale(folder_of(p));
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
        files.iter().for_each(|(p, _)| self.wrote(p, field));
        Ok(())
    }
}

/// Whether `path` is a character device (`/dev/null`, a terminal): written
/// directly, never replaced.
pub fn is_device(path: &Path) -> bool {
    std::fs::symlink_metadata(path).is_ok_and(|m| FileKind::of(&m) == FileKind::CharDevice)
}

/// Writes the body straight into a character device (no temporary file:
/// a device cannot be renamed over, and there is nothing to keep).
fn write_device(path: &Path, field: &str, body: Body<'_>) -> Result<()> {
    let fail = |e: std::io::Error| cannot_write(field, path, &e);
    let f = std::fs::OpenOptions::new()
        .write(true)
        .open(path)
        .map_err(fail)?;
    let mut w = std::io::BufWriter::new(f);
    body(&mut w).map_err(fail)?;
    w.flush().map_err(fail)
}

/// Whether two output paths name the same file: the same file by any name
/// when it exists (links and hard links followed), else the same name in
/// the same folder (`same.csv` and `./same.csv`, `a/../same.csv`).
pub fn same_path(a: &Path, b: &Path) -> bool {
    match (id_of(a), id_of(b)) {
        (Some(x), Some(y)) => x == y,
        _ => normal(a) == normal(b),
    }
}

/// A path's folder, made absolute and its links resolved, and its name.
fn normal(p: &Path) -> (PathBuf, Option<std::ffi::OsString>) {
    let dir = folder_of(p);
    let dir = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf());
    (dir, p.file_name().map(|n| n.to_os_string()))
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
            keep_mode(file.path(), &target);
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

/// Gives the new file `temp` the permissions of the file it replaces,
/// `target` (not the set-user-ID, set-group-ID or sticky bits), and its
/// owner and group where the system lets this user (root may; others keep
/// their own). Nothing to do when there is no such file.
fn keep_mode(temp: &Path, target: &Path) {
    let Ok(old) = std::fs::symlink_metadata(target) else {
        return;
    };
    if !old.is_file() {
        return;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::{MetadataExt, PermissionsExt};
        let mode = old.permissions().mode() & 0o777;
        let _ = std::fs::set_permissions(temp, std::fs::Permissions::from_mode(mode));
        let _ = std::os::unix::fs::chown(temp, Some(old.uid()), Some(old.gid()));
    }
    #[cfg(not(unix))]
    let _ = std::fs::set_permissions(temp, old.permissions());
}

/// The start of every temporary name: `.grafika-tmp-`.
const TEMP: &str = ".grafika-tmp-";

/// This process's temporary names start `.grafika-tmp-PID-START-`: its
/// id and start time ([`started`]), so that a later run can tell whether
/// the process that made one still runs.
fn temp_prefix() -> &'static str {
    static PREFIX: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    PREFIX.get_or_init(|| {
        let pid = std::process::id();
        match started(pid) {
            Some(start) => format!("{TEMP}{pid}-{start}-"),
            None => TEMP.to_string(),
        }
    })
}

/// Temporary files and folders: hidden, named `.grafika-tmp-PID-START-…`,
/// with the permissions a new file or folder gets (`mode`, 0o666 or 0o777,
/// less the umask; not tempfile's 0600).
pub fn temp_builder(mode: u32) -> tempfile::Builder<'static, 'static> {
    let mut b = tempfile::Builder::new();
    b.prefix(temp_prefix());
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        b.permissions(std::fs::Permissions::from_mode(mode));
    }
    #[cfg(not(unix))]
    let _ = mode;
    b
}

/// When process `pid` started, in clock ticks after the boot (Linux: field
/// 22 of `/proc/PID/stat`); `None` when there is no such process (or no
/// way to know).
fn started(pid: u32) -> Option<u64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // after the command's name, which is in parentheses and may hold spaces
    let rest = &stat[stat.rfind(')')? + 1..];
    rest.split_whitespace().nth(19)?.parse().ok()
}

/// How long a temporary file or folder must have been left untouched
/// before it may be taken as stale: a process of another PID namespace (a
/// container sharing the folder) is not in this one's `/proc`, but it
/// writes into what it is building.
const STALE_AFTER: std::time::Duration = std::time::Duration::from_secs(60);

/// The temporary files and folders in `dir` left by grafika processes that
/// no longer run: named `.grafika-tmp-PID-START-…` where no process PID
/// started at START runs now, untouched for [`STALE_AFTER`] (Linux;
/// elsewhere none is known to be stale). A name without both numbers (an
/// older grafika's) is left alone.
pub fn stale_temps(dir: &Path) -> Vec<(PathBuf, u32)> {
    if !cfg!(target_os = "linux") || std::fs::symlink_metadata("/proc/self/stat").is_err() {
        return Vec::new();
    }
    let Ok(rd) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    rd.filter_map(|e| {
        let e = e.ok()?;
        let name = e.file_name();
        let mut parts = name.to_str()?.strip_prefix(TEMP)?.splitn(3, '-');
        let pid: u32 = parts.next()?.parse().ok()?;
        let start: u64 = parts.next()?.parse().ok()?;
        parts.next()?;
        let idle = e.metadata().ok()?.modified().ok()?.elapsed().ok()? >= STALE_AFTER;
        (idle && started(pid) != Some(start)).then(|| (e.path(), pid))
    })
    .collect()
}

/// Removes the stale temporary files and folders of `dir` ([`stale_temps`])
/// and notes each for a warning ([`take_notes`]). A folder is removed with
/// what is in it; a link by that name, only the link.
pub fn note_stale(dir: &Path) {
    for (p, pid) in stale_temps(dir) {
        let Ok(meta) = std::fs::symlink_metadata(&p) else {
            continue;
        };
        let gone = if meta.is_dir() {
            std::fs::remove_dir_all(&p)
        } else {
            std::fs::remove_file(&p)
        };
        if gone.is_ok() {
            let msg = Msg::StaleTempRemoved(p.display().to_string(), pid);
            NOTES.lock().unwrap_or_else(|e| e.into_inner()).push(msg);
        }
    }
}

/// What the writers have to say besides their output (the stale temporary
/// files they removed), for the warnings printed at the end.
static NOTES: std::sync::Mutex<Vec<Msg>> = std::sync::Mutex::new(Vec::new());

/// The writers' notes since the last call ([`note_stale`]).
pub fn take_notes() -> Vec<Msg> {
    std::mem::take(&mut *NOTES.lock().unwrap_or_else(|e| e.into_inner()))
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
