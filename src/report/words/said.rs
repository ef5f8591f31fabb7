//! The words of values given as words (`crate::msg::Said`): an outcode
//! bit's test, the render time, a clipping status.

use super::nums;
use crate::msg::Said;
use crate::report::lang::Lang;

/// The words of `s` in `lang`.
pub fn said(s: &Said, lang: Lang) -> String {
    let id = lang == Lang::Id;
    match s {
        Said::BitTest(holds, test, values) => {
            let v = nums(values, lang);
            match (id, holds) {
                (false, true) => format!("1 — {test}: {values} is true"),
                (false, false) => format!("0 — {test}: {values} is false"),
                (true, true) => format!("1 — {test}: {v} benar"),
                (true, false) => format!("0 — {test}: {v} salah"),
            }
        }
        Said::BitQuestion(test, values) => match id {
            false => format!("{test}: is {values} true?"),
            true => format!("{test}: apakah {} benar?", nums(values, lang)),
        },
        Said::FrameTime(ms, mpix, png) => {
            if id {
                format!(
                    "{} ms ({} Mpiksel/s); encoding PNG {} ms",
                    nums(ms, lang),
                    nums(mpix, lang),
                    nums(png, lang)
                )
            } else {
                format!("{ms} ms ({mpix} Mpixels/s); PNG encoding {png} ms")
            }
        }
        Said::Status(code) => match (id, code.as_str()) {
            (true, "clipped") => "clipped (di-clip)".to_string(),
            (true, "accepted") => "accepted (diterima)".to_string(),
            (true, "rejected") => "rejected (ditolak)".to_string(),
            _ => code.clone(),
        },
    }
}
