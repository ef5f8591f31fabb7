//! Numbers written for people: decimals with a number of significant
//! digits, and a number with its exact form beside its decimal.

use super::Shown;

/// A decimal with `digits` significant digits, trailing zeros trimmed,
/// scientific notation for very large or small magnitudes.
pub fn fmt_dec(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let digits = digits.clamp(1, 17);
    let mag = x.abs().log10().floor() as i32;
    if !(-5..=9).contains(&mag) {
        let s = format!("{:.*e}", digits - 1, x);
        // trim zeros in the mantissa
        if let Some((m, e)) = s.split_once('e') {
            let m = if m.contains('.') {
                m.trim_end_matches('0').trim_end_matches('.')
            } else {
                m
            };
            return format!("{m}e{e}");
        }
        return s;
    }
    let decimals = (digits as i32 - 1 - mag).max(0) as usize;
    let s = format!("{:.*}", decimals, x);
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// Whether an exact form is just a terminating decimal or integer (so the
/// decimal adds nothing).
pub fn is_plain_decimal(p: &str) -> bool {
    let p = p.trim_start_matches(['-', '−']);
    !p.is_empty() && p.chars().all(|c| c.is_ascii_digit() || c == '.')
}

/// The most digits a number in an exact form shown to people may have.
pub const FORM_DIGITS: usize = 8;

/// Whether an exact form helps a reader: a terminating decimal or an
/// integer always does; a fraction or surd does while none of its numbers
/// has more than [`FORM_DIGITS`] digits (`3486784401/20000000000` is read
/// as 0.1743). The exact form stays in the JSON either way.
pub fn helps(p: &str) -> bool {
    is_plain_decimal(p)
        || p.split(|c: char| !c.is_ascii_digit())
            .all(|run| run.len() <= FORM_DIGITS)
}

/// The decimal of a number shown, with `digits` significant digits: its
/// value's, or for an exact value beyond the doubles ([`Shown::beyond`])
/// the exact value's own (`1e−400` for 1/10^400, whose double is 0).
pub fn decimal(s: &Shown, digits: usize) -> String {
    match s.beyond {
        Some((m, e)) => scientific(m, e, digits),
        None => fmt_dec(s.value, digits),
    }
}

/// Whether the decimal shown of `s` is not its value itself, so that it is
/// marked ≈: a decimal rounded, an exact value beyond the doubles, and in an
/// exact run a value without exact form that is 0 as a double (an
/// approximation that underflowed is not an exact 0).
pub fn is_approx(s: &Shown, digits: usize, exact_mode: bool) -> bool {
    s.beyond.is_some()
        || fmt_dec(s.value, digits).parse::<f64>().ok() != Some(s.value)
        || (exact_mode && s.exact.is_none() && s.value == 0.0)
}

/// m·10^e written `m e E` with `digits` significant digits of m
/// (1 ≤ |m| < 10), trailing zeros trimmed.
fn scientific(m: f64, e: i64, digits: usize) -> String {
    let digits = digits.clamp(1, 17);
    let mut text = format!("{:.*}", digits - 1, m);
    let mut e = e;
    // rounding may carry to 10 (9.99996 with 4 digits)
    if text.trim_start_matches('-').starts_with("10") {
        text = format!("{:.*}", digits - 1, m / 10.0);
        e += 1;
    }
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    };
    format!("{text}e{e}")
}

/// One number for people: `−√2/60 ≈ −0.02357`, `1/50 = 0.02`, `5`,
/// `≈ 0.4142` (an approximation in an exact run), `0.4142`; decimals with
/// `digits` significant digits and the decimal mark `mark` (`0,02`). An
/// exact value is never written `= 0` unless it is 0: beyond the doubles
/// it is its exact form, or, when that is too long to help, `≈` its
/// decimal (`≈ 1.567e−5283`).
pub fn shown(s: &Shown, digits: usize, exact_mode: bool, mark: char) -> String {
    let dec = decimal_in(s, digits, mark).replace('-', "−");
    let approx = is_approx(s, digits, exact_mode);
    match &s.pretty {
        Some(p) if is_plain_decimal(p) => form(&p.replace('-', "−"), mark),
        // Beyond the doubles (1/10^400 is 0 as a double, 10^400 is ∞): the
        // exact form alone, never a decimal that says `= 0`.
        Some(p) if (s.value == 0.0 && p != "0") || !s.value.is_finite() => {
            form(&p.replace('-', "−"), mark)
        }
        Some(p) => {
            let sep = if approx { "≈" } else { "=" };
            format!("{} {sep} {dec}", form(p, mark))
        }
        None if s.beyond.is_some() || (exact_mode && approx) => format!("≈ {dec}"),
        None => dec,
    }
}

/// `text`, a number this module has just written (Rust writes the point),
/// with the decimal mark `mark`.
fn marked(text: String, mark: char) -> String {
    match mark {
        '.' => text,
        _ => text.replace('.', mark.encode_utf8(&mut [0; 4])),
    }
}

/// x as Rust writes a double, its shortest decimal that reads back to it
/// (`0.1`, `1e-7` as `0.0000001`), with the decimal mark `mark`: a value
/// given back as it was read.
pub fn shortest(x: f64, mark: char) -> String {
    marked(x.to_string(), mark)
}

/// [`fmt_dec`] with the decimal mark `mark`: `0.5` or `0,5`.
pub fn fmt_dec_in(x: f64, digits: usize, mark: char) -> String {
    marked(fmt_dec(x, digits), mark)
}

/// [`decimal`] with the decimal mark `mark`.
pub fn decimal_in(s: &Shown, digits: usize, mark: char) -> String {
    marked(decimal(s, digits), mark)
}

/// x with exactly `places` decimals and the decimal mark `mark` (`12.35`
/// or `12,35` for 12.345 with 2).
pub fn fixed(x: f64, places: usize, mark: char) -> String {
    marked(format!("{x:.places$}"), mark)
}

/// x in exponent notation with `places` decimals of its mantissa and the
/// decimal mark `mark` (`1.000e-9`, `1,000e-9`).
pub fn exponent(x: f64, places: usize, mark: char) -> String {
    marked(format!("{x:.places$e}"), mark)
}

/// An exact form for people (`−√2/60`, `0.5` → `0,5`) with the decimal
/// mark `mark` in its decimals.
pub fn form(p: &str, mark: char) -> String {
    marked(p.to_string(), mark)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_rationals_are_not_forms_that_help() {
        // 0.7^4·0.5 = 2401/20000 helps; 0.9^10·0.5 = 3486784401/20000000000
        // (10 and 11 digits) is read as a decimal; integers always help.
        assert!(helps("2401/20000"));
        assert!(helps("(4+3√2)/10"));
        assert!(helps("12345678/3"));
        assert!(!helps("123456789/2"));
        assert!(!helps("3486784401/20000000000"));
        assert!(helps("123456789012"));
    }

    #[test]
    fn an_exact_value_beyond_the_doubles_is_not_written_as_zero() {
        // 1/10^400 is positive; its nearest double is 0.
        let tiny = Shown {
            value: 0.0,
            exact: Some("1/1e400".into()),
            pretty: Some("√3/30000".into()),
            beyond: None,
        };
        assert_eq!(shown(&tiny, 4, true, '.'), "√3/30000");
        let zero = Shown {
            value: 0.0,
            exact: Some("0".into()),
            pretty: Some("0".into()),
            beyond: None,
        };
        assert_eq!(shown(&zero, 4, true, '.'), "0");
    }

    #[test]
    fn an_exact_value_too_long_to_show_is_its_decimal_marked_approximate() {
        // (2/3)^3000 = 2^3000/3^3000: log10 = 3000·log10(2/3) = −528.27…,
        // so 10^−528.27… = 5.3…e−529 (by hand: 10^0.7294 = 5.36).
        let tiny = Shown {
            value: 0.0,
            exact: Some("2^3000/3^3000".into()),
            pretty: None,
            beyond: Some((5.3621, -529)),
        };
        assert_eq!(shown(&tiny, 4, true, '.'), "≈ 5.362e−529");
        // A mantissa that rounds up carries into the exponent.
        assert_eq!(scientific(9.99996, -10, 4), "1e-9");
        assert_eq!(scientific(-2.5, 400, 4), "-2.5e400");
    }

    #[test]
    fn an_approximation_that_underflowed_is_not_an_exact_zero() {
        let under = Shown {
            value: 0.0,
            exact: None,
            pretty: None,
            beyond: None,
        };
        assert_eq!(shown(&under, 4, true, '.'), "≈ 0");
        // At f64 a zero is the double 0.
        assert_eq!(shown(&under, 4, false, '.'), "0");
    }

    #[test]
    fn numbers_are_written_with_the_mark_given() {
        // −√2/60 = −0.0235702…, 4 digits: −0.02357; the exact form keeps
        // its own digits and takes the mark only in a decimal (−0.5).
        let s = Shown {
            value: -(2f64.sqrt()) / 60.0,
            exact: Some("-sqrt(2)/60".into()),
            pretty: Some("−√2/60".into()),
            beyond: None,
        };
        assert_eq!(shown(&s, 4, true, ','), "−√2/60 ≈ −0,02357");
        assert_eq!(shown(&s, 4, true, '.'), "−√2/60 ≈ −0.02357");
        assert_eq!(form("−0.5", ','), "−0,5");
        assert_eq!(fmt_dec_in(1.5e-7, 3, ','), "1,5e-7");
        // 12.3456 to two decimals: 12.35 (the third decimal, 5, rounds up)
        assert_eq!(fixed(12.3456, 2, ','), "12,35");
        assert_eq!(fixed(12.5, 1, '.'), "12.5");
        assert_eq!(exponent(1e-9, 3, ','), "1,000e-9");
    }
}
