//! A folder of outputs written whole or not at all: `generate --out DIR`
//! (issue 28; docs/spec.md §4).
//!
//! Every entry the output will have in DIR (`variant-01/`, `key.md`,
//! `quiz.xml`, …) is checked before anything is written; the files are then
//! built in a temporary folder inside DIR (`.grafika-tmp-…`, removed on an
//! error or a stop) and moved into place together at the end.
//!
//! What is generate's own: DIR's `.grafika-generated` lists every file
//! generate wrote there. Without `--force` no entry may exist yet. With
//! `--force` an existing entry is replaced only if it is generate's own (a
//! listed file, or a folder holding only listed files, none of them a
//! link); every own entry the new output does not have is removed (no stale
//! files); anything else (a lecturer's `notes.md`) is left alone, and an
//! entry of the new output that is not generate's own is refused.

use super::signals::{self, Registered};
use super::write::{cannot_write, temp_builder};
use crate::error::{Error, Result};
use crate::msg::{ErrMsg, IoWhy};
use std::collections::BTreeSet;
use std::path::{Component, Path, PathBuf};

/// The list of generate's own files in an output folder.
pub const MARKER: &str = ".grafika-generated";

/// An output folder being built (see the module).
pub struct Stage {
    out: PathBuf,
    force: bool,
    entries: Vec<String>,
    /// Own entries of an earlier run that the new output does not have.
    stale: Vec<String>,
    /// Files listed in the marker (kept without `--force`).
    listed: BTreeSet<String>,
    written: BTreeSet<String>,
    dir: Option<tempfile::TempDir>,
    _registered: Registered,
    created: Option<Registered>,
}

impl Stage {
    /// Checks DIR and each of `entries` (top-level names), then makes the
    /// temporary folder.
    pub fn begin(out: &Path, entries: Vec<String>, force: bool) -> Result<Stage> {
        let listed = read_marker(out);
        let exists = |e: &str| std::fs::symlink_metadata(out.join(e)).is_ok();
        for e in entries.iter().filter(|e| exists(e)) {
            let shown = out.join(e).display().to_string();
            if !force {
                return Err(Error::why("out", ErrMsg::ExistsForce(shown)));
            }
            if !is_own(out, e, &listed) {
                return Err(Error::why("out", ErrMsg::NotOwn(shown, MARKER.into())));
            }
        }
        let stale: Vec<String> = top_level(&listed)
            .into_iter()
            .filter(|e| force && !entries.contains(e) && exists(e))
            .collect();
        if let Some(e) = stale.iter().find(|e| !is_own(out, e, &listed)) {
            let shown = out.join(e).display().to_string();
            return Err(Error::why("out", ErrMsg::NotOwn(shown, MARKER.into())));
        }
        let created = create_out(out)?;
        let dir = temp_builder(0o777).tempdir_in(out).map_err(|e| {
            Error::why(
                "out",
                ErrMsg::CannotCreate(out.display().to_string(), IoWhy::of(&e)),
            )
        })?;
        let registered = signals::folder(dir.path());
        Ok(Stage {
            out: out.to_path_buf(),
            force,
            entries,
            stale,
            listed,
            written: BTreeSet::new(),
            dir: Some(dir),
            _registered: registered,
            created,
        })
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
        self.written.insert(rel.to_string());
        Ok(self.out.join(rel))
    }

    /// Moves the new entries into DIR (an own earlier entry replaced, own
    /// stale entries removed) and writes the marker; on a failure DIR is
    /// put back as it was.
    pub fn commit(mut self) -> Result<()> {
        let mut listed: BTreeSet<String> = if self.force {
            BTreeSet::new()
        } else {
            std::mem::take(&mut self.listed)
        };
        listed.extend(self.written.iter().cloned());
        let marker = marker_text(&listed);
        let staged = self.staging().to_path_buf();
        let fail = |e: std::io::Error| cannot_write("out", &self.out, &e);
        std::fs::write(staged.join(MARKER), marker).map_err(fail)?;
        signals::locked(|| self.swap(&staged)).map_err(fail)?;
        self.created = None;
        Ok(())
    }

    /// The moves of [`Stage::commit`], undone on a failure.
    fn swap(&self, staged: &Path) -> std::io::Result<()> {
        let old = staged.join(".old");
        std::fs::create_dir(&old)?;
        let mut undo: Vec<(PathBuf, PathBuf)> = Vec::new();
        let replaced = self.entries.iter().chain(&self.stale);
        let moves = replaced
            .filter(|e| std::fs::symlink_metadata(self.out.join(e)).is_ok())
            .map(|e| (self.out.join(e), old.join(e)))
            .chain(
                self.entries
                    .iter()
                    .map(|e| (staged.join(e), self.out.join(e))),
            )
            .chain([(staged.join(MARKER), self.out.join(MARKER))]);
        for (from, to) in moves {
            let r = if to.ends_with(MARKER) || std::fs::symlink_metadata(&to).is_err() {
                std::fs::rename(&from, &to)
            } else {
                Err(std::io::Error::from(std::io::ErrorKind::AlreadyExists))
            };
            if let Err(e) = r {
                for (a, b) in undo.iter().rev() {
                    let _ = std::fs::rename(b, a);
                }
                return Err(e);
            }
            undo.push((from, to));
        }
        Ok(())
    }
}

impl Drop for Stage {
    /// An output not committed: its temporary folder goes, and DIR too if
    /// this run created it and it is empty.
    fn drop(&mut self) {
        drop(self.dir.take());
        if self.created.take().is_some() {
            let _ = std::fs::remove_dir(&self.out);
        }
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

/// The files the marker of DIR lists: relative paths of one or two plain
/// parts (`key.md`, `variant-01/key.md`); anything else in it is ignored.
fn read_marker(out: &Path) -> BTreeSet<String> {
    let path = out.join(MARKER);
    let plain = std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file());
    let text = if plain {
        std::fs::read_to_string(&path).unwrap_or_default()
    } else {
        String::new()
    };
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter(|l| {
            let parts: Vec<Component> = Path::new(l).components().collect();
            (1..=2).contains(&parts.len())
                && parts.iter().all(|c| matches!(c, Component::Normal(_)))
        })
        .map(str::to_string)
        .collect()
}

fn marker_text(listed: &BTreeSet<String>) -> String {
    let mut t = String::from(
        "# Written by grafika generate: the files it wrote in this folder.\n\
         # generate --force replaces these (and removes those it no longer writes), nothing else.\n",
    );
    for l in listed {
        t.push_str(l);
        t.push('\n');
    }
    t
}

/// The top-level entries of the listed files (`variant-01`, `key.md`).
fn top_level(listed: &BTreeSet<String>) -> BTreeSet<String> {
    listed
        .iter()
        .filter_map(|l| Path::new(l).components().next())
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect()
}

/// Whether DIR/entry is generate's own: a listed plain file, or a real
/// folder whose every entry is a listed plain file.
fn is_own(out: &Path, entry: &str, listed: &BTreeSet<String>) -> bool {
    let path = out.join(entry);
    let Ok(meta) = std::fs::symlink_metadata(&path) else {
        return false;
    };
    if meta.is_file() {
        return listed.contains(entry);
    }
    if !meta.is_dir() {
        return false;
    }
    let Ok(rd) = std::fs::read_dir(&path) else {
        return false;
    };
    rd.into_iter().all(|e| {
        e.is_ok_and(|e| {
            let name = format!("{entry}/{}", e.file_name().to_string_lossy());
            e.file_type().is_ok_and(|t| t.is_file()) && listed.contains(&name)
        })
    })
}
