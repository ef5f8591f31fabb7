//! The language of everything grafika prints for people: English or Bahasa
//! Indonesia (the course's own). JSON keys, codes and numbers never depend on
//! it; only the words, and the decimal mark of numbers in text, do.
//!
//! The language itself, [`Lang`], lives in `msg` (below every layer).

pub use crate::msg::Lang;

/// How numbers are written for people: the decimal mark and the separator
/// between the components of a vector. Each language declares its own
/// (`report::words`' `MsgWords::nums`): English (and a Moodle quiz with
/// `--decimal point`) writes `(0.5, 2, 3)`; Indonesian (and `--decimal
/// comma`) writes `(0,5; 2; 3)`, so a comma never reads both as a decimal
/// mark and as a separator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NumStyle {
    /// The decimal mark: `.` or `,`.
    pub mark: char,
    /// Between a vector's components: `, ` or `; `.
    pub sep: &'static str,
}

impl NumStyle {
    /// `0.5`, `(0.5, 2, 3)`.
    pub const POINT: NumStyle = NumStyle {
        mark: '.',
        sep: ", ",
    };
    /// `0,5`, `(0,5; 2; 3)`.
    pub const COMMA: NumStyle = NumStyle {
        mark: ',',
        sep: "; ",
    };

    /// One number (or a formula of numbers: `−√2/60 ≈ −0.02357`, `1.5e-3`,
    /// `12.35 ms`) that was formatted with the point, written with this mark.
    pub fn number(self, pointed: &str) -> String {
        pointed
            .chars()
            .map(|c| if c == '.' { self.mark } else { c })
            .collect()
    }

    /// Values formatted the English way, with the point and `, ` between
    /// components (`(1.5, 2, 3)`, `ka = 0.2, kd = 0.5`), written in this
    /// style: the separators first, then the marks.
    pub fn values(self, english: &str) -> String {
        self.number(&self.separated(english))
    }

    /// A list or formula written with `, ` between its parts (`max(a, 0)`)
    /// with this style's separator instead; its numbers are not touched.
    pub fn separated(self, english: &str) -> String {
        english.replace(NumStyle::POINT.sep, self.sep)
    }
}

/// At most this many characters of a message are printed: an error about
/// a 100 KB input quotes its start and end, not all of it
/// (`report::words::cut_message`).
pub const MAX_MESSAGE: usize = 300;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_take_the_mark_and_separator_of_their_style() {
        let v = "(1.5, -2, 0.25)";
        assert_eq!(NumStyle::POINT.values(v), "(1.5, -2, 0.25)");
        assert_eq!(NumStyle::COMMA.values(v), "(1,5; -2; 0,25)");
        assert_eq!(
            NumStyle::COMMA.number("−√2/60 ≈ −0.02357"),
            "−√2/60 ≈ −0,02357"
        );
        assert_eq!(NumStyle::POINT.number("0.1"), "0.1");
        // a formula's separators change, its numbers do not
        assert_eq!(NumStyle::COMMA.separated("max(0.8, 0)"), "max(0.8; 0)");
    }
}
