//! The family of the messages' own words ([`Msg`]): the trait each language
//! implements (en/msg.rs, id/msg.rs) and the language-neutral ways the
//! words of a message are put together (a located message, a list of
//! parts, a capital first letter), written once for every language.

use crate::input::ask::Part;
use crate::msg::{Erratum, Given, LightPart, Msg, Printed, Term};
use crate::report::lang::{NumStyle, MAX_MESSAGE};

/// The words of the messages themselves ([`Msg`]) and the number style
/// they are written in.
pub trait MsgWords {
    /// The words of `m`, its numbers in this language's style.
    fn msg(&self, m: &Msg) -> String {
        self.msg_in(m, self.nums())
    }
    /// The words of `m` with its numbers in the style `nums` (the
    /// language's own, or a quiz's `--decimal`): one exhaustive match over
    /// every key.
    fn msg_in(&self, m: &Msg, nums: NumStyle) -> String;
    /// How this language writes numbers: its decimal mark and the
    /// separator between a vector's components.
    fn nums(&self) -> NumStyle;
    /// How a printed answer compares, worded as what it is: a misprint,
    /// another convention, a rounding (docs/spec.md §5).
    fn printed(&self, p: Printed) -> &'static str;
    /// `Asked`, the heading of what a problem asks.
    fn asked_heading(&self) -> &'static str;
    /// What one part of a problem asks (an exhaustive match: a new part
    /// says what it asks).
    fn asked_part(&self, part: Part) -> &'static str;
    /// A term of the lighting sum.
    fn term(&self, t: Term) -> &'static str;
    /// One light's step of the lighting sum.
    fn light_part(&self, p: LightPart) -> &'static str;
    /// What a message cut in its middle says in the cut: `(412
    /// characters cut)`.
    fn cut(&self, n: usize) -> String;
}

/// The words of one message as `place: words` (`p.toml:3:7: …`).
pub fn at<W: MsgWords + ?Sized>(w: &W, place: &str, m: &Msg) -> String {
    format!("{place}: {}", w.msg(m))
}

/// A printed answer that differs, and why: `a misprint in the text: …`.
pub fn erratum<W: MsgWords + ?Sized>(w: &W, kind: Option<Erratum>, why: &Msg) -> String {
    format!("{}: {}", w.printed(Printed::Differs(kind)), w.msg(why))
}

/// The verdict on each part of an answer, `x: exact; y: …`.
pub fn parts<W: MsgWords + ?Sized>(w: &W, parts: &[(String, Msg)]) -> String {
    parts
        .iter()
        .map(|(l, m)| format!("{l}: {}", w.msg(m)))
        .collect::<Vec<_>>()
        .join("; ")
}

/// What a problem asks, part by part: `Asked: …; ….`
pub fn asked<W: MsgWords + ?Sized>(w: &W, parts: &[String]) -> String {
    let list: Vec<&str> = (parts.iter())
        .filter_map(|p| Part::named(p))
        .map(|p| w.asked_part(p))
        .collect();
    format!("{}: {}.", w.asked_heading(), list.join("; "))
}

/// `s` with its first letter a capital (`attenuation` → `Attenuation`).
pub fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|a| a.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

/// A value given that must be positive, in the style `nums` (`0,5`); the
/// 0 that a tiny positive number is at a float precision says so, in
/// English in every language as it always has (its Indonesian words are
/// still to be written).
pub fn given(g: Given, nums: NumStyle) -> String {
    match g {
        Given::Value(v) => nums.shortest(v),
        Given::ZeroAt(p, least) => {
            format!("0 (at {p} precision: a positive number below about {least} is 0 too)")
        }
    }
}

/// The text's constants (ka = 0.4, kd = 0.6, ks = 0.7, n = 4, white
/// specular) in the style `nums`: `ks_note` after ks's value, the
/// specular colour said as `white`.
pub fn material_text(nums: NumStyle, ks_note: &str, white: &str) -> String {
    let (s, d) = (nums.sep, |x: f64| nums.dec(x, 4));
    format!(
        "ka = {}{s}kd = {}{s}ks = {}{ks_note}{s}n = 4{s}{white}",
        d(0.4),
        d(0.6),
        d(0.7)
    )
}

/// A small angle in radians with three decimals of exponent notation
/// (`1.000e-9`), in the style `nums`.
pub fn exponent(nums: NumStyle, a: f64) -> String {
    nums.exponent(a, 3)
}

/// `message` cut to [`MAX_MESSAGE`] characters, its middle replaced by the
/// number of characters left out (`head … (412 characters cut) … tail`).
pub fn cut_message<W: MsgWords + ?Sized>(w: &W, message: &str) -> String {
    let n = message.chars().count();
    if n <= MAX_MESSAGE {
        return message.to_string();
    }
    let keep = MAX_MESSAGE / 2;
    let head: String = message.chars().take(keep).collect();
    let tail: String = message.chars().skip(n - keep).collect();
    format!("{head} … {} … {tail}", w.cut(n - 2 * keep))
}
