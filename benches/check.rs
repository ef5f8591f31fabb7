//! Divan benchmark of marking a class: 1,000 answer sheets of the text's
//! triangle example (Budi, Siti and Tono of problems/answers/triangle, in
//! turn), marked as `grafika check --answers DIR` marks a directory: the
//! problem solved, and the catalog's mistakes run, once; then every sheet
//! read and judged.

use grafika::input::problem::ProblemIn;
use grafika::tutor::check::{self, Answers, Marker, Settings};

fn main() {
    divan::main();
}

/// Sheets in the class.
const SHEETS: usize = 1000;

fn class() -> (ProblemIn, Vec<Answers>) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let p = ProblemIn::read(&root.join("problems/text-triangle.toml")).expect("the problem");
    let students: Vec<Answers> = ["budi", "siti", "tono"]
        .iter()
        .map(|s| {
            let f = root.join(format!("problems/answers/triangle/{s}.toml"));
            check::read_answers(&f).expect("an answer file").1
        })
        .collect();
    let sheets = (0..SHEETS).map(|i| students[i % 3].clone()).collect();
    (p, sheets)
}

#[divan::bench(sample_count = 10)]
fn mark_a_class_of_1000(b: divan::Bencher) {
    let (p, sheets) = class();
    b.counter(divan::counter::ItemsCount::new(SHEETS))
        .bench(|| {
            let marker = Marker::new(&p, Settings::default()).expect("solves");
            for s in &sheets {
                divan::black_box(marker.mark("student", divan::black_box(s), false));
            }
        });
}
