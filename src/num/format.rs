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
