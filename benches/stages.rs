//! Divan benchmarks of the pipeline stages at f32, f64 and exact, with the
//! steps not recorded (`NoTrace`), over the fixed input set of
//! `grafika::bench::accuracy` (a pass over every case of the stage per iteration;
//! divide by the case count for a time per operation).

use grafika::bench::accuracy::{inputs, Inputs, Prepared, Stage};
use grafika::num::{Real, Scalar};
use std::sync::OnceLock;

fn main() {
    divan::main();
}

/// Cases per stage: 8 random plus 8 adversarial.
const CASES: usize = 8;

fn set() -> &'static Inputs {
    static SET: OnceLock<Inputs> = OnceLock::new();
    SET.get_or_init(|| inputs(CASES))
}

fn run<T: Scalar>(b: divan::Bencher, s: Stage) {
    let inp = set();
    let prep = Prepared::<T>::new(inp);
    let n = inp.len(s);
    b.counter(divan::counter::ItemsCount::new(n)).bench(|| {
        for i in 0..n {
            divan::black_box(prep.eval(divan::black_box(s), i));
        }
    });
}

macro_rules! stage {
    ($name:ident, $stage:expr) => {
        #[divan::bench(types = [f32, f64, Real], sample_count = 20)]
        fn $name<T: Scalar>(b: divan::Bencher) {
            run::<T>(b, $stage);
        }
    };
}

stage!(basis, Stage::Basis);
stage!(view, Stage::View);
stage!(project, Stage::Project);
stage!(window, Stage::Window);
stage!(clip, Stage::Clip);
