//! The language of everything grafika prints for people: English or Bahasa
//! Indonesia (the course's own). JSON keys, codes and numbers never depend on
//! it; only the words, and the decimal mark of numbers in text, do.
//!
//! The language itself, [`Lang`], lives in `msg` (below every layer).

pub use crate::msg::Lang;
use crate::msg::{Expect, Fixed, Shown};
use crate::num::format;

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

    /// x with `digits` significant digits: `0.5`, `0,5`, `1.5e-3`.
    pub fn dec(self, x: f64, digits: usize) -> String {
        format::fmt_dec_in(x, digits, self.mark)
    }

    /// x with exactly `places` decimals: `12.35`, `12,35`.
    pub fn fixed(self, x: f64, places: usize) -> String {
        format::fixed(x, places, self.mark)
    }

    /// A number said in a message with its decimals fixed.
    pub fn fixed_of(self, f: Fixed) -> String {
        self.fixed(f.0, f.1)
    }

    /// x in exponent notation, `places` decimals of mantissa: `1.000e-9`.
    pub fn exponent(self, x: f64, places: usize) -> String {
        format::exponent(x, places, self.mark)
    }

    /// A value given back as it was read, its shortest decimal: `0.1`,
    /// `0,1` ([`format::shortest`]).
    pub fn shortest(self, x: f64) -> String {
        format::shortest(x, self.mark)
    }

    /// Three values given back as they were read: `(1, 0.5, 0)`,
    /// `(1; 0,5; 0)`.
    pub fn shortest3(self, v: [f64; 3]) -> String {
        self.tuple(&v.map(|x| self.shortest(x)))
    }

    /// A number for people with `digits` significant digits, its exact
    /// form beside its decimal: `−√2/60 ≈ −0,02357`, `1/50 = 0,02`
    /// ([`format::shown`]).
    pub fn shown(self, s: &Shown, digits: usize, exact_mode: bool) -> String {
        format::shown(s, digits, exact_mode, self.mark)
    }

    /// An exact form (`−√2/60`, `0,5`).
    pub fn form(self, p: &str) -> String {
        format::form(p, self.mark)
    }

    /// A number in a comparison as short as it reads: its exact form, else
    /// its decimal with 6 digits (`3`, `√2/2`, `0,3333`).
    pub fn short(self, s: &Shown) -> String {
        match &s.pretty {
            Some(p) => self.form(p),
            None => self.dec(s.value, 6).replace('-', "−"),
        }
    }

    /// Items in parentheses between this style's separators: `(a, b)` or
    /// `(a; b)`.
    pub fn tuple<S: AsRef<str>>(self, items: &[S]) -> String {
        let items: Vec<&str> = items.iter().map(AsRef::as_ref).collect();
        format!("({})", items.join(self.sep))
    }

    /// A value expected of an answer: a number with its exact form and 6
    /// digits, words as written, a list in parentheses.
    pub fn expect(self, e: &Expect) -> String {
        match e {
            Expect::Num(s) => self.shown(s, 6, true),
            Expect::Text(t) => t.clone(),
            Expect::List(items) => {
                self.tuple(&items.iter().map(|x| self.expect(x)).collect::<Vec<_>>())
            }
            Expect::Nothing => String::new(),
        }
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
        let (p, c) = (NumStyle::POINT, NumStyle::COMMA);
        assert_eq!(p.dec(1.5, 4), "1.5");
        assert_eq!(c.dec(1.5, 4), "1,5");
        assert_eq!(c.fixed(0.25, 2), "0,25");
        // an expected vector (1/2, 2/3): 2/3 = 0.666666…, 6 digits 0.666667
        let half = Shown {
            value: 0.5,
            exact: Some("1/2".into()),
            pretty: Some("1/2".into()),
            beyond: None,
        };
        let two_thirds = Shown {
            value: 2.0 / 3.0,
            exact: Some("2/3".into()),
            pretty: Some("2/3".into()),
            beyond: None,
        };
        let v = Expect::List(vec![Expect::Num(half), Expect::Num(two_thirds)]);
        assert_eq!(p.expect(&v), "(1/2 = 0.5, 2/3 ≈ 0.666667)");
        assert_eq!(c.expect(&v), "(1/2 = 0,5; 2/3 ≈ 0,666667)");
        // words as written: a code is not a number
        assert_eq!(c.expect(&Expect::Text("1.2.3".into())), "1.2.3");
    }
}
