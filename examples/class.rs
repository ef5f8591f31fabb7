//! Writes the class of problems/answers/class/: 24 students' answer files
//! to the triangle ABC example (problems/text-triangle.toml), with
//! mistakes drawn from a seed at the rates stated in
//! tests/common/class.rs (`seeded_class`). The class in the repository was
//! made with
//!
//!     cargo run --example class -- 2026 problems/answers/class
//!
//! and a test checks that the files are still what this writes. An
//! existing file is never overwritten.

#[path = "../tests/common/class.rs"]
mod class;

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(seed), Some(out)) = (
        args.first().and_then(|s| s.parse::<u64>().ok()),
        args.get(1),
    ) else {
        eprintln!("usage: cargo run --example class -- SEED OUT_DIR");
        return ExitCode::from(2);
    };
    let out = std::path::Path::new(out);
    if let Err(e) = std::fs::create_dir_all(out) {
        eprintln!("error: {}: {e}", out.display());
        return ExitCode::from(2);
    }
    for s in class::seeded_class(seed) {
        let path = out.join(class::file_name(&s));
        let written = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
            .and_then(|mut f| std::io::Write::write_all(&mut f, class::answer_file(&s).as_bytes()));
        if let Err(e) = written {
            eprintln!("error: {}: {e}", path.display());
            return ExitCode::from(2);
        }
        println!("{}", path.display());
    }
    ExitCode::SUCCESS
}
