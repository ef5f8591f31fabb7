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

/// One number for people: `−√2/60 ≈ −0.02357`, `1/50 = 0.02`, `5`,
/// `≈ 0.4142` (an approximation in an exact run), `0.4142`; decimals with
/// `digits` significant digits.
pub fn shown(s: &Shown, digits: usize, exact_mode: bool) -> String {
    let dec = fmt_dec(s.value, digits);
    match &s.pretty {
        Some(p) if is_plain_decimal(p) => p.replace('-', "−"),
        // Beyond the doubles (1/10^400 is 0 as a double, 10^400 is ∞): the
        // exact form alone, never a decimal that says `= 0`.
        Some(p) if (s.value == 0.0 && p != "0") || !s.value.is_finite() => p.replace('-', "−"),
        Some(p) => {
            let sep = if dec.parse::<f64>().ok() == Some(s.value) {
                "="
            } else {
                "≈"
            };
            format!("{p} {sep} {}", dec.replace('-', "−"))
        }
        None if exact_mode && dec.parse::<f64>().ok() != Some(s.value) => {
            format!("≈ {}", dec.replace('-', "−"))
        }
        None => dec.replace('-', "−"),
    }
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
        };
        assert_eq!(shown(&tiny, 4, true), "√3/30000");
        let zero = Shown {
            value: 0.0,
            exact: Some("0".into()),
            pretty: Some("0".into()),
        };
        assert_eq!(shown(&zero, 4, true), "0");
    }
}
