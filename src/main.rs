//! The `grafika` binary: parse, run, print; errors exit with status 2.

fn main() {
    std::process::exit(grafika::cli::main_with_args(std::env::args_os().collect()));
}
