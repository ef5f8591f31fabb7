//! Clean stops: the temporary files and folders an output is being built in
//! are removed when grafika is stopped by SIGINT, SIGTERM or SIGHUP, so a
//! stop never leaves a partial file (issue 28).
//!
//! Each temporary path is registered while it exists. The first
//! registration starts a thread that waits for those signals (signal-hook:
//! nothing is done in the signal handler itself); on one it takes the
//! commit lock, removes what is registered and ends the process as the
//! signal would have. Moving finished outputs into place happens under the
//! same lock ([`locked`]), so a stop waits for it and never sees half of it.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, Once};

/// What a stop removes.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Temp {
    /// A temporary file.
    File(PathBuf),
    /// A temporary folder and everything in it.
    Folder(PathBuf),
    /// A folder grafika created for an output, removed only if empty.
    Created(PathBuf),
}

static REGISTRY: Mutex<Vec<Temp>> = Mutex::new(Vec::new());
/// Held while outputs are put in place ([`locked`]) and by a stop: a stop
/// waits for a commit, and nothing is added to a temporary folder while a
/// stop removes it. (A lock apart from the registry's, so that a
/// registration can be dropped during a commit.)
static COMMIT: Mutex<()> = Mutex::new(());
static WATCH: Once = Once::new();

fn registry() -> MutexGuard<'static, Vec<Temp>> {
    REGISTRY.lock().unwrap_or_else(|e| e.into_inner())
}

/// A registered temporary path; dropping it unregisters it (the caller
/// removes the path itself, or has moved it into place).
#[derive(Debug)]
pub struct Registered(Temp);

impl Drop for Registered {
    fn drop(&mut self) {
        registry().retain(|t| t != &self.0);
    }
}

fn register(t: Temp) -> Registered {
    WATCH.call_once(watch);
    registry().push(t.clone());
    Registered(t)
}

/// Registers a temporary file.
pub fn file(p: &Path) -> Registered {
    register(Temp::File(p.to_path_buf()))
}

/// Registers a temporary folder (removed whole on a stop).
pub fn folder(p: &Path) -> Registered {
    register(Temp::Folder(p.to_path_buf()))
}

/// Registers a folder created for an output (removed on a stop if empty).
pub fn created(p: &Path) -> Registered {
    register(Temp::Created(p.to_path_buf()))
}

/// Runs `f` (moving finished files into place, adding a file to a
/// registered folder) with the registry locked: a stop during it waits
/// until it is done.
pub fn locked<R>(f: impl FnOnce() -> R) -> R {
    let _held = COMMIT.lock().unwrap_or_else(|e| e.into_inner());
    f()
}

/// Removes every registered path (newest first); with the lock held.
fn remove_all(temps: &mut Vec<Temp>) {
    while let Some(t) = temps.pop() {
        let _ = match &t {
            Temp::File(p) => std::fs::remove_file(p),
            Temp::Folder(p) => std::fs::remove_dir_all(p),
            Temp::Created(p) => std::fs::remove_dir(p),
        };
    }
}

/// Removes what is registered now: for an end that is not a signal (a
/// broken pipe), before the process exits.
pub fn clean_up() {
    remove_all(&mut registry());
}

#[cfg(unix)]
fn watch() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    let _ = std::thread::Builder::new()
        .name("grafika-signals".into())
        .spawn(move || {
            if let Some(sig) = signals.forever().next() {
                let _commit = COMMIT.lock().unwrap_or_else(|e| e.into_inner());
                remove_all(&mut registry());
                // Ends the process as the signal would have (status 128 + sig
                // in a shell); the commit lock is never released.
                let _ = signal_hook::low_level::emulate_default_handler(sig);
                std::process::exit(128 + sig);
            }
        });
}

#[cfg(not(unix))]
fn watch() {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stop_removes_files_folders_and_empty_created_folders() {
        let dir = tempfile::tempdir().unwrap();
        let (f, d, c, full) = (
            dir.path().join("a.tmp"),
            dir.path().join("d"),
            dir.path().join("c"),
            dir.path().join("full"),
        );
        std::fs::write(&f, "x").unwrap();
        std::fs::create_dir(&d).unwrap();
        std::fs::write(d.join("inner"), "y").unwrap();
        std::fs::create_dir(&c).unwrap();
        std::fs::create_dir(&full).unwrap();
        std::fs::write(full.join("mine"), "z").unwrap();
        let mut temps = vec![
            Temp::Created(full.clone()),
            Temp::Created(c.clone()),
            Temp::Folder(d.clone()),
            Temp::File(f.clone()),
        ];
        remove_all(&mut temps);
        assert!(!f.exists() && !d.exists() && !c.exists());
        assert!(
            full.join("mine").exists(),
            "a created folder that is not empty stays"
        );
    }

    #[test]
    fn a_dropped_registration_is_unregistered() {
        let p = PathBuf::from("/nonexistent/grafika-test.tmp");
        {
            let _r = file(&p);
            assert!(registry().contains(&Temp::File(p.clone())));
        }
        assert!(!registry().contains(&Temp::File(p)));
    }
}
