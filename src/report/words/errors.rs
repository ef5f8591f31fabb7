//! The words of the error keys (`crate::msg::ErrMsg` and its families):
//! the trait [`ErrorWords`] that each language implements (`en/errors.rs`,
//! `id/errors.rs`: one exhaustive match per key enum, no wildcard arm), and
//! the parts every language shares, written once here: the crates' English
//! messages read into typed keys (`crates`), a folder's example prefix,
//! a component's letter. Field names, keys, flags and paths are printed as
//! they are spelled.

mod crates;
pub use crates::{
    expect_text, parse_text, serde_pieces, serde_text, serde_words, syntax, syntax_text, value_why,
    ExpectWord, Expected, ParseWhy, SerdeWord, Shape, Syntax, SyntaxWhat, ValueWhy,
};

use crate::msg::{
    Bound, Channel, ClapErr, ErrMsg, IoWhy, NumErr, ObjWhy, Thing, TomlErr, Twice, Want,
};
use crate::report::lang::NumStyle;

/// The words of the error keys ([`ErrMsg`] and its families), in one
/// language. Each method is one exhaustive match over its key.
pub trait ErrorWords {
    /// Why an input was refused.
    fn error(&self, e: &ErrMsg) -> String;
    /// Why a number (or a height formula) cannot be read or evaluated.
    fn number(&self, e: &NumErr) -> String;
    /// What the number reader expected.
    fn want(&self, w: Want) -> &'static str;
    /// A TOML file's error.
    fn toml(&self, e: &TomlErr) -> String;
    /// "must be …, got X".
    fn must_be(&self, b: &Bound, got: f64) -> String;
    /// Something given twice.
    fn twice(&self, t: Twice) -> &'static str;
    /// The system's reason a file could not be read or written.
    fn io_why(&self, w: &IoWhy) -> String;
    /// "a spot light needs `axis`", "a sphere needs `r`".
    fn needs(&self, thing: &Thing, key: &str) -> String;
    /// A colour channel.
    fn channel(&self, c: Channel) -> &'static str;
    /// The OBJ reader's reason.
    fn obj_why(&self, w: ObjWhy) -> &'static str;
    /// A command line clap refused; `line` is clap's own (English) line.
    fn clap(&self, e: &ClapErr, line: &str) -> String;
    /// A flag value parser's reason.
    fn value_why(&self, w: &ValueWhy) -> String;
    /// A reason of Rust's number parsing.
    fn parse_why(&self, w: ParseWhy) -> &'static str;
    /// The TOML reader's syntax error.
    fn syntax(&self, s: &Syntax) -> String;
    /// A description of a syntax error by the TOML reader.
    fn syntax_what(&self, w: SyntaxWhat) -> &'static str;
    /// A kind of thing the TOML reader expected.
    fn expect_word(&self, w: ExpectWord) -> &'static str;
    /// A phrase of serde's (`a sequence`, `an integer`).
    fn serde_word(&self, w: SerdeWord) -> &'static str;
}

/// Values given back as they were read in brackets, as a TOML array:
/// `[0.5, 1.2, 0]`, `[0,5; 1,2; 0]`.
pub fn bracketed(v: [f64; 3], nums: NumStyle) -> String {
    format!("[{}]", v.map(|x| nums.shortest(x)).join(nums.sep))
}

/// `dir/` for a path that is a folder (`dir/` itself when it ends in `/`),
/// so that the example is a file name inside it.
pub fn folder_prefix(p: &str) -> String {
    if p.ends_with('/') {
        p.to_string()
    } else {
        format!("{p}/")
    }
}

/// The letter of a vector's component 0, 1 or 2.
pub fn component(k: usize) -> &'static str {
    ["x", "y", "z"][k % 3]
}

/// The TOML reader's list of what it expected, each in `word`'s words,
/// joined as the reader joins them (`, `).
pub fn one_of(items: &[Shape<ExpectWord>], word: impl Fn(ExpectWord) -> &'static str) -> String {
    let words: Vec<&str> = items.iter().map(|i| i.words(&word)).collect();
    words.join(", ")
}

#[cfg(test)]
pub(crate) mod tests;
