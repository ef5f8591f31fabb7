//! Which standard streams were closed when the process started (`<&-`,
//! `>&-`), noted before the Rust runtime opens `/dev/null` on a closed
//! descriptor 0, 1 or 2 (it does, read-write, so that later files never get
//! those numbers). After that a closed standard output and one a script
//! opened read-write on `/dev/null` (`1<>/dev/null`, Python's
//! `subprocess.DEVNULL`) look the same; so the binary's start-up code
//! calls [`note_at_start`] first, and only a descriptor that was truly
//! closed counts as closed.

use std::sync::atomic::{AtomicU8, Ordering};

/// Bit 0: standard input was closed; bit 1: standard output was.
static CLOSED: AtomicU8 = AtomicU8::new(0);

/// Notes which of descriptors 0 and 1 are closed (Linux: a closed
/// descriptor has no entry in `/proc/self/fd`; `lstat` opens nothing, so
/// it cannot take the number it asks about). Elsewhere, or without
/// `/proc`, nothing is noted and no stream counts as closed. Called by the
/// binary before `main`; without that call no stream counts as closed.
pub fn note_at_start() {
    #[cfg(target_os = "linux")]
    {
        if std::fs::symlink_metadata("/proc/self/fd").is_err() {
            return;
        }
        let closed = |fd: u8| std::fs::symlink_metadata(format!("/proc/self/fd/{fd}")).is_err();
        let bits = u8::from(closed(0)) | (u8::from(closed(1)) << 1);
        CLOSED.store(bits, Ordering::Relaxed);
    }
}

/// Whether standard input was closed when the process started.
pub fn stdin_closed() -> bool {
    CLOSED.load(Ordering::Relaxed) & 1 != 0
}

/// Whether standard output was closed when the process started.
pub fn stdout_closed() -> bool {
    CLOSED.load(Ordering::Relaxed) & 2 != 0
}
