//! Values given as words, in English.

use super::En;
use crate::msg::Said;
use crate::report::lang::NumStyle;
use crate::report::words::SaidWords;

impl SaidWords for En {
    fn said(&self, s: &Said, nums: NumStyle) -> String {
        let n = |x: &str| nums.values(x);
        match s {
            Said::BitTest(true, test, values) => format!("1 — {test}: {} is true", n(values)),
            Said::BitTest(false, test, values) => format!("0 — {test}: {} is false", n(values)),
            Said::BitQuestion(test, values) => format!("{test}: is {} true?", n(values)),
            Said::FrameTime(ms, mpix, png) => {
                format!(
                    "{} ms ({} Mpixels/s); PNG encoding {} ms",
                    n(ms),
                    n(mpix),
                    n(png)
                )
            }
            Said::Status(code) => code.clone(),
        }
    }
}
