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
