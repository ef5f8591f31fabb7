//! `grafika bench`: run time against error. For each stage and precision,
//! the time per operation (median over repeated passes over the input set)
//! and the error against the exact path over the fixed input set of
//! [`crate::bench::accuracy`].

pub mod accuracy;

use crate::num::{Precision, Real, Scalar};
use accuracy::{Errors, Inputs, Prepared, Stage};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// How much to run.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Random cases per stage (plus about as many adversarial ones).
    pub cases: usize,
    /// Time spent timing each float stage.
    pub float_budget: Duration,
    /// Time spent timing each exact stage.
    pub exact_budget: Duration,
}

impl Settings {
    /// The full run (about 15 s in release on two cores).
    pub fn full() -> Settings {
        Settings {
            cases: 60,
            float_budget: Duration::from_millis(400),
            exact_budget: Duration::from_millis(1500),
        }
    }

    /// A few cases and passes (for tests).
    pub fn quick() -> Settings {
        Settings {
            cases: 6,
            float_budget: Duration::from_millis(5),
            exact_budget: Duration::from_millis(5),
        }
    }
}

/// One row of the table.
#[derive(Clone, Debug)]
pub struct Row {
    /// The stage.
    pub stage: Stage,
    /// The precision.
    pub precision: Precision,
    /// Median time per operation, nanoseconds.
    pub ns_per_op: f64,
    /// Number of timed passes.
    pub passes: usize,
    /// Errors (empty for exact).
    pub errors: Errors,
}

impl Row {
    pub fn target_max_median(&self) -> (f64, f64) {
        accuracy::max_median(&self.errors.target)
    }
    pub fn all_max_median(&self) -> (f64, f64) {
        accuracy::max_median(&self.errors.all())
    }
}

/// Times passes over every case of stage `s` until `budget` is spent (at
/// least 3 passes); returns the median time per case and the pass count.
fn time_stage<T: Scalar>(prep: &Prepared<T>, n: usize, s: Stage, budget: Duration) -> (f64, usize) {
    let mut per_op = Vec::new();
    let start = Instant::now();
    while per_op.len() < 3 || (start.elapsed() < budget && per_op.len() < 100_000) {
        let t0 = Instant::now();
        for i in 0..n {
            black_box(prep.eval(black_box(s), black_box(i)));
        }
        per_op.push(t0.elapsed().as_nanos() as f64 / n.max(1) as f64);
    }
    let passes = per_op.len();
    (accuracy::max_median(&per_op).1, passes)
}

/// Runs the whole measurement.
pub fn measure(set: &Settings) -> (Inputs, Vec<Row>) {
    measure_with(set, &mut |_, _| {})
}

/// [`measure`], calling `step(k, n)` as the k-th of the n stages starts (a
/// progress bar on a terminal).
pub fn measure_with(set: &Settings, step: &mut dyn FnMut(usize, usize)) -> (Inputs, Vec<Row>) {
    let inp = accuracy::inputs(set.cases);
    let exact = Prepared::<Real>::new(&inp);
    let p64 = Prepared::<f64>::new(&inp);
    let p32 = Prepared::<f32>::new(&inp);
    let mut rows = Vec::new();
    for (k, s) in Stage::ALL.into_iter().enumerate() {
        step(k, Stage::ALL.len());
        let n = inp.len(s);
        let reference = accuracy::exact_results(&exact, &inp, s);
        let (t, k) = time_stage(&exact, n, s, set.exact_budget);
        rows.push(Row {
            stage: s,
            precision: Precision::Exact,
            ns_per_op: t,
            passes: k,
            errors: Errors::default(),
        });
        let (t, k) = time_stage(&p64, n, s, set.float_budget);
        rows.push(Row {
            stage: s,
            precision: Precision::F64,
            ns_per_op: t,
            passes: k,
            errors: accuracy::errors(&inp, &p64, &reference, s),
        });
        let (t, k) = time_stage(&p32, n, s, set.float_budget);
        rows.push(Row {
            stage: s,
            precision: Precision::F32,
            ns_per_op: t,
            passes: k,
            errors: accuracy::errors(&inp, &p32, &reference, s),
        });
    }
    (inp, rows)
}
