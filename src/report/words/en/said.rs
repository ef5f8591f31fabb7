//! Values given as words, in English.

use super::En;
use crate::msg::Said;
use crate::report::words::SaidWords;

impl SaidWords for En {
    fn said(&self, s: &Said) -> String {
        match s {
            Said::BitTest(true, test, values) => format!("1 — {test}: {values} is true"),
            Said::BitTest(false, test, values) => format!("0 — {test}: {values} is false"),
            Said::BitQuestion(test, values) => format!("{test}: is {values} true?"),
            Said::FrameTime(ms, mpix, png) => {
                format!("{ms} ms ({mpix} Mpixels/s); PNG encoding {png} ms")
            }
            Said::Status(code) => code.clone(),
        }
    }
}
