//! A folder of outputs written whole or not at all: `generate --out DIR`
//! (issues 28 and 37; docs/spec.md §4).
//!
//! One `generate` at a time writes into DIR: it holds a lock on
//! `DIR/.grafika-lock` (`flock`, released by the system however the
//! process ends) from its first look at DIR to its last move; a second run
//! is refused at once. Every entry the output will have in DIR
//! (`variant-01/`, `key.md`, `quiz.xml`, …) is checked before anything is
//! written; the files are then built in a temporary folder inside DIR
//! (`.grafika-tmp-…`, removed on an error or a stop) and moved into place
//! together at the end.
//!
//! What is generate's own: DIR's `.grafika-generated` lists every file
//! generate wrote there with its SHA-256 ([`List`]). The list itself must
//! be generate's: a regular file of this user, in the format generate
//! writes, naming only names generate writes; any other is refused and
//! nothing it names is touched. Without `--force` neither the list nor any
//! entry may exist yet. With `--force` an existing entry is replaced only
//! if it is generate's own (a listed file whose content is still the one
//! listed, or a folder holding only such files, none of them a link); every
//! own entry the new output does not have is removed (no stale files);
//! anything else (a lecturer's `notes.md`) is left alone, and an entry of
//! the new output that is not generate's own is refused. At the end each
//! replaced or removed entry is checked again after it is moved aside, so
//! a file put there meanwhile is never deleted: the folder is put back as
//! it was, and the run refused.

use super::signals::{self, Registered};
use super::write::{cannot_write, note_stale, temp_builder};
use crate::error::{Error, Result};
use crate::msg::{ErrMsg, IoWhy, ListWhy};
use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};

/// The list of generate's own files in an output folder.
pub const MARKER: &str = ".grafika-generated";

/// The lock one `generate` holds on an output folder while it writes.
pub const LOCK: &str = ".grafika-lock";

/// The first words of a list generate writes (its format's version).
const HEADING: &str = "grafika-generated 2";

/// The largest list read: 250,000 problems with their keys and sheets.
const MAX_LIST: u64 = 64 << 20;

/// The largest file taken as generate's own (its files are far smaller).
const MAX_OWN: u64 = 64 << 20;

/// The files of a list, by name (`key.md`, `variant-01/key.md`), each
/// with the SHA-256 of the content generate wrote, in hex.
type List = BTreeMap<String, String>;

/// An output folder being built (see the module).
pub struct Stage {
    out: PathBuf,
    force: bool,
    entries: Vec<String>,
    /// The run, as the list's first line says it.
    run: String,
    /// Own entries of an earlier run that the new output does not have.
    stale: Vec<String>,
    /// The earlier run's list (with `--force`).
    listed: List,
    /// The files written, with the SHA-256 of each.
    written: List,
    dir: Option<tempfile::TempDir>,
    registered: Option<Registered>,
    created: Option<Registered>,
    lock: Option<Lock>,
}

impl Stage {
    /// Takes DIR (created if need be) for this run, `run` describing it
    /// (its seed, topics, …): locks it, checks the list and each of
    /// `entries` (top-level names), and makes the temporary folder.
    pub fn begin(out: &Path, entries: Vec<String>, force: bool, run: String) -> Result<Stage> {
        let mut stage = Stage {
            out: out.to_path_buf(),
            force,
            entries,
            run,
            stale: Vec::new(),
            listed: List::new(),
            written: List::new(),
            dir: None,
            registered: None,
            created: create_out(out)?,
            lock: None,
        };
        stage.lock = Some(Lock::take(out)?);
        note_stale(out);
        let dir = temp_builder(0o777).tempdir_in(out).map_err(|e| {
            Error::why(
                "out",
                ErrMsg::CannotCreate(out.display().to_string(), IoWhy::of(&e)),
            )
        })?;
        stage.registered = Some(signals::folder(dir.path()));
        let me = owner(dir.path());
        stage.dir = Some(dir);
        if !force && std::fs::symlink_metadata(out.join(MARKER)).is_ok() {
            return Err(Error::why(
                "out",
                ErrMsg::ListExists(out.join(MARKER).display().to_string()),
            ));
        }
        stage.listed = read_list(out, me)?;
        stage.check_entries()?;
        Ok(stage)
    }

    /// Checks the entries the output will have and the stale ones (see the
    /// module).
    fn check_entries(&mut self) -> Result<()> {
        let out = &self.out;
        let exists = |e: &str| std::fs::symlink_metadata(out.join(e)).is_ok();
        for e in self.entries.iter().filter(|e| exists(e)) {
            if !self.force {
                let shown = out.join(e).display().to_string();
                return Err(Error::why("out", ErrMsg::ExistsForce(shown)));
            }
            own(out, e, &self.listed)?;
        }
        self.stale = top_level(&self.listed)
            .into_iter()
            .filter(|e| self.force && !self.entries.contains(e) && exists(e))
            .collect();
        for e in &self.stale {
            own(out, e, &self.listed)?;
        }
        Ok(())
    }

    fn staging(&self) -> &Path {
        self.dir.as_ref().map_or(Path::new(""), |d| d.path())
    }

    /// Writes `text` as `rel` (`key.md`, `variant-01/key.md`) in the
    /// temporary folder; returns the path it will have in DIR.
    pub fn write(&mut self, rel: &str, text: &str) -> Result<PathBuf> {
        let at = self.staging().join(rel);
        let fail = |e: std::io::Error| cannot_write("out", &self.out.join(rel), &e);
        signals::locked(|| -> std::io::Result<()> {
            if let Some(p) = at.parent() {
                std::fs::create_dir_all(p)?;
            }
            let f = std::fs::File::create(&at)?;
            std::io::Write::write_all(&mut std::io::BufWriter::new(&f), text.as_bytes())?;
            super::write::hooks::sync(&f)
        })
        .map_err(fail)?;
        self.written
            .insert(rel.to_string(), sha256(text.as_bytes()));
        Ok(self.out.join(rel))
    }

    /// Moves the new entries into DIR (an own earlier entry replaced, own
    /// stale entries removed) and writes the list of this run's files; on a
    /// failure DIR is put back as it was.
    pub fn commit(mut self) -> Result<()> {
        let list = list_text(&self.run, &self.written);
        let staged = self.staging().to_path_buf();
        let fail = |e: std::io::Error| cannot_write("out", &self.out, &e);
        std::fs::write(staged.join(MARKER), list).map_err(fail)?;
        signals::locked(|| self.swap(&staged))?;
        self.created = None;
        Ok(())
    }

    /// The moves of [`Stage::commit`], undone on a failure: each earlier
    /// entry (and the earlier list) aside into `.old` and checked again
    /// there, then the new entries and the list into DIR.
    fn swap(&self, staged: &Path) -> Result<()> {
        let old = staged.join(".old");
        let io = |e: std::io::Error| cannot_write("out", &self.out, &e);
        std::fs::create_dir(&old).map_err(io)?;
        let mut undo: Vec<(PathBuf, PathBuf)> = Vec::new();
        let back = |undo: &[(PathBuf, PathBuf)]| {
            for (a, b) in undo.iter().rev() {
                let _ = std::fs::rename(b, a);
            }
        };
        let replaced = (self.entries.iter().chain(&self.stale))
            .map(String::as_str)
            .chain(self.force.then_some(MARKER))
            .filter(|e| std::fs::symlink_metadata(self.out.join(e)).is_ok());
        for e in replaced {
            let (from, to) = (self.out.join(e), old.join(e));
            if let Err(err) = std::fs::rename(&from, &to) {
                back(&undo);
                return Err(io(err));
            }
            undo.push((from, to));
            // Checked where it now is: nothing added meanwhile is removed.
            if e != MARKER {
                if let Err(err) = own_at(&old, e, &self.listed, &self.out) {
                    back(&undo);
                    return Err(err);
                }
            }
        }
        let new = (self.entries.iter().map(String::as_str)).chain([MARKER]);
        for e in new {
            let (from, to) = (staged.join(e), self.out.join(e));
            let r = match std::fs::symlink_metadata(&to) {
                Ok(_) => Err(std::io::Error::from(std::io::ErrorKind::AlreadyExists)),
                Err(_) => std::fs::rename(&from, &to),
            };
            if let Err(err) = r {
                back(&undo);
                return Err(io(err));
            }
            undo.push((from, to));
        }
        Ok(())
    }
}

impl Drop for Stage {
    /// An output not committed: its temporary folder goes, and DIR too if
    /// this run created it and it is empty. The lock goes last but one.
    fn drop(&mut self) {
        drop(self.dir.take());
        drop(self.registered.take());
        drop(self.lock.take());
        if self.created.take().is_some() {
            let _ = std::fs::remove_dir(&self.out);
        }
    }
}

/// The lock a run holds on DIR: `DIR/.grafika-lock`, locked with `flock`
/// (the system releases it however the process ends, SIGKILL too, so a
/// lock is never left behind by a stopped run; the file may be, and is
/// reused). Removed when the run ends, while still held.
struct Lock {
    path: PathBuf,
    _file: std::fs::File,
    _registered: Registered,
}

impl Lock {
    /// Locks DIR, or refuses at once when another run holds it.
    fn take(out: &Path) -> Result<Lock> {
        let path = out.join(LOCK);
        let shown = || out.display().to_string();
        let fail =
            |e: std::io::Error| Error::why("out", ErrMsg::CannotCreate(shown(), IoWhy::of(&e)));
        // The holder removes the file before it lets go: a lock taken on a
        // file no longer at its name is taken again on the new one.
        for _ in 0..8 {
            let file = open_lock(&path).map_err(fail)?;
            match file.try_lock() {
                Ok(()) => {}
                Err(std::fs::TryLockError::WouldBlock) => {
                    let lock = path.display().to_string();
                    return Err(Error::why("out", ErrMsg::Locked(shown(), lock)));
                }
                Err(std::fs::TryLockError::Error(e)) => return Err(fail(e)),
            }
            if same_file(&file, &path) {
                let registered = signals::file(&path);
                return Ok(Lock {
                    path,
                    _file: file,
                    _registered: registered,
                });
            }
        }
        let lock = path.display().to_string();
        Err(Error::why("out", ErrMsg::Locked(shown(), lock)))
    }
}

impl Drop for Lock {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// Opens (or creates) the lock file, never through a link.
fn open_lock(path: &Path) -> std::io::Result<std::fs::File> {
    let mut o = std::fs::OpenOptions::new();
    o.read(true).write(true).create(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        o.custom_flags(libc::O_NOFOLLOW);
    }
    o.open(path)
}

/// Whether the open `file` is the one now at `path`.
fn same_file(file: &std::fs::File, path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (file.metadata(), std::fs::symlink_metadata(path)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        let _ = file;
        path.exists()
    }
}

/// Creates DIR (and its parents) if it does not exist: the registration of
/// a folder to remove again if the output is not made.
fn create_out(out: &Path) -> Result<Option<Registered>> {
    match std::fs::symlink_metadata(out) {
        Ok(_) if out.is_dir() => Ok(None),
        Ok(_) => Err(Error::why(
            "out",
            ErrMsg::NotDirectory(out.display().to_string()),
        )),
        Err(_) => {
            std::fs::create_dir_all(out).map_err(|e| {
                Error::why(
                    "out",
                    ErrMsg::CannotCreate(out.display().to_string(), IoWhy::of(&e)),
                )
            })?;
            Ok(Some(signals::created(out)))
        }
    }
}

/// The owner of a file this process made (unix; elsewhere none).
fn owner(p: &Path) -> Option<u32> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        std::fs::symlink_metadata(p).ok().map(|m| m.uid())
    }
    #[cfg(not(unix))]
    {
        let _ = p;
        None
    }
}

/// The list of DIR (empty when there is none), refused unless generate
/// wrote it: a regular file of user `me` (when known), at most
/// [`MAX_LIST`] bytes, starting with [`HEADING`], every other line a
/// comment or `SHA-256  NAME` with a name generate writes.
fn read_list(out: &Path, me: Option<u32>) -> Result<List> {
    let path = out.join(MARKER);
    let refuse =
        |why: ListWhy| Error::why("out", ErrMsg::NotOwnList(path.display().to_string(), why));
    let meta = match std::fs::symlink_metadata(&path) {
        Ok(m) => m,
        Err(_) => return Ok(List::new()),
    };
    if !meta.is_file() {
        return Err(refuse(ListWhy::NotAFile));
    }
    if meta.len() > MAX_LIST {
        return Err(refuse(ListWhy::TooLarge));
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if me.is_some_and(|me| me != meta.uid()) {
            return Err(refuse(ListWhy::Owner));
        }
    }
    let _ = me;
    let text = std::fs::read_to_string(&path).map_err(|e| cannot_write("out", &path, &e))?;
    parse_list(&text).map_err(refuse)
}

/// A list's text read (see [`read_list`]).
fn parse_list(text: &str) -> std::result::Result<List, ListWhy> {
    let mut lines = text.lines();
    let first = lines.next().unwrap_or_default();
    if first != HEADING && !first.starts_with(&format!("{HEADING} ")) {
        return Err(ListWhy::Heading);
    }
    let mut list = List::new();
    for (n, l) in lines.enumerate().map(|(i, l)| (i + 2, l)) {
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        let (hash, name) = l.split_once("  ").ok_or(ListWhy::Line(n))?;
        let hex = |c: char| c.is_ascii_digit() || ('a'..='f').contains(&c);
        if hash.len() != 64 || !hash.chars().all(hex) {
            return Err(ListWhy::Line(n));
        }
        if !generated_name(name) {
            return Err(ListWhy::Name(n, name.to_string()));
        }
        list.insert(name.to_string(), hash.to_string());
    }
    Ok(list)
}

/// Whether generate ever writes a file by this name in DIR: `quiz.xml`,
/// `quiz.gift` (or their parts under `--split-mb`, `quiz-NN.xml`), or an exam's file (`problem-NN.toml`,
/// `problem-NN.key.toml`, `questions.EXT`, `key.EXT`, `exam.json`) at the
/// top or in a `variant-NN/` folder.
pub fn generated_name(name: &str) -> bool {
    let parts: Vec<Component> = Path::new(name).components().collect();
    let text = |c: &Component| c.as_os_str().to_str().map(str::to_string);
    let numbered = |s: &str, head: &str| {
        s.strip_prefix(head)
            .is_some_and(|n| n.len() >= 2 && n.chars().all(|c| c.is_ascii_digit()))
    };
    let exam_file = |f: &str| {
        let sheet = ["md", "tex", "html"]
            .iter()
            .any(|e| f == format!("questions.{e}") || f == format!("key.{e}"));
        let problem = f
            .strip_suffix(".key.toml")
            .or_else(|| f.strip_suffix(".toml"))
            .is_some_and(|p| numbered(p, "problem-"));
        sheet || problem || f == "exam.json" || f == "blueprint.md" || f == "blueprint.json"
    };
    match parts.as_slice() {
        [a] => text(a).is_some_and(|f| exam_file(&f) || quiz_file(&f, &numbered)),
        [v, f] => {
            text(v).is_some_and(|v| numbered(&v, "variant-"))
                && text(f).is_some_and(|f| exam_file(&f))
        }
        _ => false,
    }
}

/// Whether `f` is a quiz file: `quiz.EXT` or `quiz-NN.EXT`, EXT `xml` or
/// `gift`.
fn quiz_file(f: &str, numbered: &dyn Fn(&str, &str) -> bool) -> bool {
    let stem = f.strip_suffix(".xml").or_else(|| f.strip_suffix(".gift"));
    stem.is_some_and(|s| s == "quiz" || numbered(s, "quiz-"))
}

/// The list's text: its heading with the run, then each file's SHA-256 and
/// name, as `sha256sum` writes them.
fn list_text(run: &str, files: &List) -> String {
    let mut t = format!(
        "{HEADING} {run}\n\
         # The files grafika generate wrote in this folder, each after its SHA-256\n\
         # (`sha256sum -c` checks them). generate --force replaces or removes a\n\
         # listed file only while its content is still the one listed, and nothing else.\n"
    );
    for (name, hash) in files {
        t.push_str(&format!("{hash}  {name}\n"));
    }
    t
}

/// The SHA-256 of `bytes`, in lowercase hex.
fn sha256(bytes: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The top-level entries of the listed files (`variant-01`, `key.md`).
fn top_level(listed: &List) -> Vec<String> {
    let mut top: Vec<String> = listed
        .keys()
        .filter_map(|l| Path::new(l).components().next())
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    top.dedup();
    top
}

/// Refuses DIR/entry unless it is generate's own ([`own_at`]).
fn own(out: &Path, entry: &str, listed: &List) -> Result<()> {
    own_at(out, entry, listed, out)
}

/// Whether `base/entry` is generate's own: a listed regular file whose
/// SHA-256 is the listed one, or a real folder whose every entry is such
/// a file. The error names the entry as it is in `shown` (DIR).
fn own_at(base: &Path, entry: &str, listed: &List, shown: &Path) -> Result<()> {
    let not_own = |e: &str| {
        let p = shown.join(e).display().to_string();
        Error::why("out", ErrMsg::NotOwn(p, MARKER.into()))
    };
    let file = |rel: &str| -> Result<()> {
        let Some(want) = listed.get(rel) else {
            return Err(not_own(rel));
        };
        let path = base.join(rel);
        let meta = std::fs::symlink_metadata(&path).map_err(|_| not_own(rel))?;
        if !meta.is_file() || meta.len() > MAX_OWN {
            return Err(not_own(rel));
        }
        let bytes = std::fs::read(&path).map_err(|_| not_own(rel))?;
        if &sha256(&bytes) != want {
            let p = shown.join(rel).display().to_string();
            return Err(Error::why("out", ErrMsg::ChangedSince(p)));
        }
        Ok(())
    };
    let path = base.join(entry);
    let meta = std::fs::symlink_metadata(&path).map_err(|_| not_own(entry))?;
    if meta.is_file() {
        return file(entry);
    }
    if !meta.is_dir() {
        return Err(not_own(entry));
    }
    let rd = std::fs::read_dir(&path).map_err(|_| not_own(entry))?;
    for e in rd {
        let e = e.map_err(|_| not_own(entry))?;
        let rel = format!("{entry}/{}", e.file_name().to_string_lossy());
        file(&rel)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_list_names_only_what_generate_writes() {
        for ok in [
            "key.md",
            "questions.tex",
            "problem-01.toml",
            "problem-123.key.toml",
            "exam.json",
            "quiz.xml",
            "quiz.gift",
            "quiz-01.xml",
            "quiz-12.gift",
            "variant-07/key.html",
            "variant-07/problem-02.key.toml",
        ] {
            assert!(generated_name(ok), "{ok}");
        }
        for bad in [
            "notes.txt",
            "grades",
            "grades/a.csv",
            "../key.md",
            "/etc/passwd",
            "variant-01",
            "variant-1/key.md",
            "variant-01/quiz.xml",
            "quiz-1.xml",
            "quiz-01.txt",
            "variant-01/variant-02/key.md",
            "problem-01.csv",
            "problem-x1.toml",
            ".grafika-generated",
            "key.md/x",
        ] {
            assert!(!generated_name(bad), "{bad}");
        }
    }

    #[test]
    fn a_planted_list_is_refused_and_names_the_line() {
        let hash = sha256(b"x");
        let planted = "# Written by grafika generate\nnotes.txt\ngrades/\n";
        assert_eq!(parse_list(planted), Err(ListWhy::Heading));
        let named = format!("{HEADING} (seed 1)\n{hash}  notes.txt\n");
        assert_eq!(
            parse_list(&named),
            Err(ListWhy::Name(2, "notes.txt".into()))
        );
        let bare = format!("{HEADING}\n# a comment\nkey.md\n");
        assert_eq!(parse_list(&bare), Err(ListWhy::Line(3)));
        let good = format!("{HEADING} (seed 1)\n{hash}  key.md\n");
        assert_eq!(parse_list(&good).map(|l| l.len()), Ok(1));
    }

    #[test]
    fn sha256_is_the_standard_one() {
        // FIPS 180-2, appendix B.1: SHA-256("abc").
        assert_eq!(
            sha256(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn an_own_file_is_one_unchanged_since_it_was_listed() {
        let d = tempfile::tempdir().unwrap();
        std::fs::write(d.path().join("key.md"), "generated").unwrap();
        let mut list = List::new();
        list.insert("key.md".into(), sha256(b"generated"));
        assert!(own(d.path(), "key.md", &list).is_ok());
        std::fs::write(d.path().join("key.md"), "edited by the lecturer").unwrap();
        let e = own(d.path(), "key.md", &list).unwrap_err();
        assert!(
            matches!(e.message, crate::msg::Msg::Err(ErrMsg::ChangedSince(_))),
            "{e}"
        );
        // A folder with a file the list does not name is not own.
        std::fs::create_dir(d.path().join("variant-01")).unwrap();
        std::fs::write(d.path().join("variant-01/key.md"), "generated").unwrap();
        list.insert("variant-01/key.md".into(), sha256(b"generated"));
        assert!(own(d.path(), "variant-01", &list).is_ok());
        std::fs::write(d.path().join("variant-01/notes.md"), "mine").unwrap();
        assert!(own(d.path(), "variant-01", &list).is_err());
    }
}
