//! Values given as words, in English.

use super::En;
use crate::msg::{Compared, Fixed, Said};
use crate::report::lang::NumStyle;
use crate::report::words::said::compared;
use crate::report::words::SaidWords;

impl SaidWords for En {
    fn said(&self, s: &Said, nums: NumStyle) -> String {
        let n = |x: &Compared| compared(x, nums);
        let f = |x: &Fixed| nums.fixed_of(*x);
        match s {
            Said::BitTest(true, test, values) => format!("1 — {test}: {} is true", n(values)),
            Said::BitTest(false, test, values) => format!("0 — {test}: {} is false", n(values)),
            Said::BitQuestion(test, values) => format!("{test}: is {} true?", n(values)),
            Said::FrameTime(ms, mpix, png) => {
                format!(
                    "{} ms ({} Mpixels/s); PNG encoding {} ms",
                    f(ms),
                    f(mpix),
                    f(png)
                )
            }
            Said::Status(code) => code.clone(),
        }
    }
}
