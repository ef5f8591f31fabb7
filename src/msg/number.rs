//! Numbers said to people, as data: a message carries the number itself
//! and the words write it once, in the language's number style
//! (`report::lang::NumStyle`: its decimal mark and separator), never a
//! number already written in English and rewritten afterwards.

/// A number shown to the user: its value (at the precision it was computed)
/// and, where known, an exact form.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(Default))]
pub struct Shown {
    /// The value; for f32 results, the f64 nearest the f32's shortest decimal,
    /// so that it prints as the f32 does and reads back to the same f32.
    pub value: f64,
    /// ASCII exact form (`-sqrt(2)/60`), `None` when the value is not exact.
    pub exact: Option<String>,
    /// Unicode exact form (`−√2/60`) for people.
    pub pretty: Option<String>,
    /// An exact value beyond the doubles (1/10^400, whose nearest double
    /// is 0): its decimal as a mantissa in [1, 10) and a power of ten, so
    /// that it is shown as `≈ 1e−400`, never as 0.
    pub beyond: Option<(f64, i64)>,
}

/// A number written with a fixed number of decimals (`12.35` ms with 2):
/// the value, the decimals.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(test, derive(Default))]
pub struct Fixed(pub f64, pub usize);

/// A value expected of an answer, as the words write it after "expected":
/// a number in its exact and decimal form, words as written, or a list of
/// these in parentheses.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(Default))]
pub enum Expect {
    /// A number (its exact form beside its decimal, 6 digits).
    Num(Shown),
    /// Words or a code as written (`accepted`, `010000`).
    Text(String),
    /// Values in parentheses, between the style's separators.
    List(Vec<Expect>),
    /// Nothing to say.
    #[cfg_attr(test, default)]
    Nothing,
}

/// An outcode bit's comparison with its values: the left side, the
/// operator (`>` or `<`), the right side (`4 > 3`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(Default))]
pub struct Compared(pub Shown, pub &'static str, pub Shown);

/// A value given that must be positive, as the check saw it: its double,
/// or the 0 that a tiny positive number written (1e-400) is at a float
/// precision: the precision's name and about the least positive number
/// it holds (`f64`, `5e-324`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Given {
    /// The value.
    Value(f64),
    /// 0 at this precision, below about this least positive number.
    ZeroAt(&'static str, &'static str),
}

/// For the tests' iteration over the message keys (`strum::EnumIter`
/// fills a variant's fields with their defaults).
#[cfg(test)]
impl Default for Given {
    fn default() -> Given {
        Given::Value(0.0)
    }
}
