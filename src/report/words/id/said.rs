//! Values given as words, in Bahasa Indonesia (numbers with the decimal
//! comma, a clipping status glossed with the text's word).

use super::Id;
use crate::msg::{Compared, Fixed, Said};
use crate::report::lang::NumStyle;
use crate::report::words::{said, SaidWords};
use crate::stages::clip::Status;

impl SaidWords for Id {
    fn said(&self, s: &Said, nums: NumStyle) -> String {
        let n = |x: &Compared| said::compared(x, nums);
        let f = |x: &Fixed| nums.fixed_of(*x);
        match s {
            Said::BitTest(true, test, values) => format!("1 — {test}: {} benar", n(values)),
            Said::BitTest(false, test, values) => format!("0 — {test}: {} salah", n(values)),
            Said::BitQuestion(test, values) => format!("{test}: apakah {} benar?", n(values)),
            Said::FrameTime(ms, mpix, png) => format!(
                "{} ms ({} Mpiksel/s); encoding PNG {} ms",
                f(ms),
                f(mpix),
                f(png)
            ),
            Said::Status(code) => match said::status(code) {
                Some(Status::Clipped) => "di-clip".to_string(),
                Some(Status::Accepted) => "diterima".to_string(),
                Some(Status::Rejected) => "ditolak".to_string(),
                None => code.clone(),
            },
        }
    }
}
