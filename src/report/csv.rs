//! CSV as a spreadsheet opens it safely: one writer for every CSV grafika
//! writes (`check --csv`, `check --report FILE.csv`).
//!
//! - Quoting is RFC 4180's, by the `csv` crate: a cell holding a comma, a
//!   double quote, a carriage return or a line feed is put in double quotes
//!   (a quote inside doubled); records end in CRLF, so a carriage return in
//!   a student's name is quoted too and never starts a new row.
//! - Formulas are neutralised as OWASP advises against CSV injection: a
//!   cell that starts with `=`, `+`, `-`, `@`, a tab or a carriage return
//!   gets a leading `'`, so `=HYPERLINK(…)` in a name is shown as text.
//! - Numbers stay numbers: a cell that is a plain decimal number (an
//!   optional minus, digits, an optional fraction and exponent: `-0.25`,
//!   `7`, `1e-3`) is written as it is, so a spreadsheet still reads a
//!   negative discrimination or a student's `-0.0414` as a number. Such a
//!   cell can hold no formula.

use std::borrow::Cow;

/// A cell as it goes into the file: a plain number as it is, any other
/// text that starts with `=`, `+`, `-`, `@`, tab or CR behind a `'`.
pub fn cell(s: &str) -> Cow<'_, str> {
    let risky = s.starts_with(['=', '+', '-', '@', '\t', '\r']);
    if risky && !is_plain_number(s) {
        Cow::Owned(format!("'{s}"))
    } else {
        Cow::Borrowed(s)
    }
}

/// `-?digits(.digits)?([eE][+-]?digits)?`: what a spreadsheet reads as a
/// number and nothing else.
fn is_plain_number(s: &str) -> bool {
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let s = s.strip_prefix('-').unwrap_or(s);
    let (mantissa, exponent) = match s.split_once(['e', 'E']) {
        Some((m, e)) => (m, Some(e.strip_prefix(['+', '-']).unwrap_or(e))),
        None => (s, None),
    };
    let whole_and_fraction = match mantissa.split_once('.') {
        Some((w, f)) => digits(w) && digits(f),
        None => digits(mantissa),
    };
    whole_and_fraction && exponent.is_none_or(digits)
}

/// The whole file: a header and the rows, every cell through [`cell`],
/// quoted as RFC 4180 requires, each record ended by CRLF.
pub fn write(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut w = csv::WriterBuilder::new()
        .terminator(csv::Terminator::CRLF)
        .flexible(true)
        .from_writer(Vec::new());
    let records = std::iter::once(header.iter().map(|h| h.to_string()).collect::<Vec<_>>())
        .chain(rows.iter().cloned());
    for r in records {
        // writing into a Vec cannot fail
        let _ = w.write_record(r.iter().map(|c| cell(c).into_owned()));
    }
    let bytes = w.into_inner().unwrap_or_default();
    String::from_utf8(bytes).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_are_text_and_numbers_stay_numbers() {
        assert_eq!(
            cell("=HYPERLINK(\"http://x\",\"y\")"),
            "'=HYPERLINK(\"http://x\",\"y\")"
        );
        assert_eq!(cell("+1+1"), "'+1+1");
        assert_eq!(cell("@SUM(A1)"), "'@SUM(A1)");
        assert_eq!(cell("\tx"), "'\tx");
        assert_eq!(cell("\rx"), "'\rx");
        assert_eq!(cell("-2+3"), "'-2+3");
        assert_eq!(cell("-"), "'-");
        assert_eq!(cell("-sqrt(2)/2"), "'-sqrt(2)/2");
        for n in ["-0.25", "7", "-7", "1e-3", "-1.5E+2", "0.0414"] {
            assert_eq!(cell(n), n);
        }
        assert_eq!(cell("Budi"), "Budi");
        assert_eq!(cell(""), "");
    }

    #[test]
    fn cells_are_quoted_as_rfc_4180_requires() {
        let rows = vec![vec![
            "a,b".to_string(),
            "say \"hi\"".to_string(),
            "two\nlines".to_string(),
            "cr\rhere".to_string(),
            "=1+1".to_string(),
            "-3".to_string(),
            String::new(),
        ]];
        let out = write(&["x", "y"], &rows);
        assert_eq!(
            out,
            "x,y\r\n\"a,b\",\"say \"\"hi\"\"\",\"two\nlines\",\"cr\rhere\",'=1+1,-3,\r\n"
        );
    }
}
