//! Printing exact numbers in a canonical, CAS-readable form: one integer
//! denominator under a numerator of integer multiples of square roots, e.g.
//! `(sqrt(2)-1)/10` in ASCII and `(√2−1)/10` in Unicode.

use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_traits::{One, Signed};

use super::surd::Surd;

struct Style {
    minus: &'static str,
    unicode: bool,
}

const ASCII: Style = Style {
    minus: "-",
    unicode: false,
};
const UNICODE: Style = Style {
    minus: "\u{2212}",
    unicode: true,
};

/// One term |c|·√r of the numerator, without its sign.
fn term(c: &BigInt, r: &BigUint, style: &Style) -> String {
    let c = c.magnitude();
    if r.is_one() {
        c.to_string()
    } else if style.unicode {
        if c.is_one() {
            format!("√{r}")
        } else {
            format!("{c}√{r}")
        }
    } else if c.is_one() {
        format!("sqrt({r})")
    } else {
        format!("{c}*sqrt({r})")
    }
}

/// The ASCII (`unicode = false`) or Unicode form of a surd.
///
/// Terms go rational part first, then by radicand; a leading negative term is
/// avoided by starting with the first positive one (`√2−1`, not `−1+√2`).
/// When every term is negative and there is a denominator, the minus goes in
/// front: `-(1+sqrt(2))/10`, `-sqrt(2)/60`.
pub(crate) fn format_surd(s: &Surd, unicode: bool) -> String {
    let style = if unicode { &UNICODE } else { &ASCII };
    if s.is_empty() {
        return "0".to_string();
    }
    let mut den = BigInt::one();
    for (_, q) in s.terms() {
        den = den.lcm(q.denom());
    }
    let mut terms: Vec<(BigInt, &BigUint)> = s
        .terms()
        .map(|(r, q)| (q.numer() * (&den / q.denom()), r))
        .collect();
    let all_negative = terms.iter().all(|(c, _)| c.is_negative());
    let pull_minus = all_negative && (terms.len() == 1 || !den.is_one());
    if let Some(first_pos) = terms.iter().position(|(c, _)| c.is_positive()) {
        let t = terms.remove(first_pos);
        terms.insert(0, t);
    }
    let mut body = String::new();
    for (i, (c, r)) in terms.iter().enumerate() {
        if c.is_negative() && !pull_minus {
            body.push_str(style.minus);
        } else if i > 0 {
            body.push('+');
        }
        body.push_str(&term(c, r, style));
    }
    let sign = if pull_minus { style.minus } else { "" };
    if den.is_one() {
        format!("{sign}{body}")
    } else if terms.len() > 1 {
        format!("{sign}({body})/{den}")
    } else {
        format!("{sign}{body}/{den}")
    }
}

impl std::fmt::Debug for Surd {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Surd({})", format_surd(self, false))
    }
}
