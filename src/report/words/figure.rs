//! The family of the figures' words (`crate::msg::FigureMsg`): panel titles
//! and descriptions (captions and screen readers) and the words inside the
//! figures, each language's in en/figure.rs and id/figure.rs.

use crate::msg::FigureMsg;

/// The words of the figures.
pub trait FigureWords {
    /// The words of a figure message.
    fn figure(&self, m: &FigureMsg) -> String;
}

/// The name of light `k` (from 1) in a figure: `L` for the first, as the
/// text names its one light, then `L2`, `L3`, ….
pub fn light_name(k: usize) -> String {
    if k == 1 {
        "L".to_string()
    } else {
        format!("L{k}")
    }
}
