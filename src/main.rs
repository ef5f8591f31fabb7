//! The `grafika` binary: parse, run, print; errors exit with status 2.

fn main() {
    std::process::exit(grafika::cli::main_with_args(std::env::args_os().collect()));
}

/// Runs before `main` and before the Rust runtime's start-up, which opens
/// `/dev/null` on a closed standard descriptor: notes which standard
/// streams were truly closed (`grafika::input::streams`), so that a closed
/// standard output is refused and one opened read-write on `/dev/null` is
/// not.
#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static NOTE_STREAMS: extern "C" fn() = note_streams;

#[cfg(target_os = "linux")]
extern "C" fn note_streams() {
    grafika::input::streams::note_at_start();
}
