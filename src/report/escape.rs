//! Text from files and flags is data: the characters that would act
//! instead of being read (control characters, bidirectional overrides) are
//! shown as `\u{XX}`, on a terminal and in every XML file written (SVG,
//! HTML, Moodle XML), so a student's name cannot clear the screen, move the
//! cursor, reorder a line or make a figure ill-formed XML (issue 28).
//!
//! Shown escaped: C0 controls but newline and tab (U+0000–U+001F), DEL and
//! the C1 controls (U+007F–U+009F), the bidirectional embeddings, overrides
//! and isolates (U+202A–U+202E, U+2066–U+2069, as in CVE-2021-42574), and
//! the non-characters U+FFFE and U+FFFF (not allowed in XML).

use std::borrow::Cow;
use std::fmt::Write;

/// Whether `c` is shown escaped (see the module's list).
pub fn is_active(c: char) -> bool {
    matches!(c,
        '\u{0}'..='\u{8}' | '\u{B}'..='\u{1F}' | '\u{7F}'..='\u{9F}'
        | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}' | '\u{FFFE}' | '\u{FFFF}')
}

/// `s` with every active character written `\u{XX}` (hex, upper case);
/// borrowed when there is none.
pub fn visible(s: &str) -> Cow<'_, str> {
    if !s.chars().any(is_active) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        push_visible(&mut out, c);
    }
    Cow::Owned(out)
}

/// `c` onto `out`, written `\u{XX}` when it is active.
pub fn push_visible(out: &mut String, c: char) {
    if is_active(c) {
        let _ = write!(out, "\\u{{{:X}}}", c as u32);
    } else {
        out.push(c);
    }
}

/// Text for a terminal: [`visible`], except that a line ending CR LF (a
/// CSV record's, RFC 4180) is kept, and with `colour` the Select Graphic
/// Rendition sequences of plain colours (`ESC [ n m` for n in 0–2 and
/// 30–37, what grafika itself colours with) are kept. A lone CR, which
/// would return the cursor and overwrite the line, is shown escaped.
pub fn terminal(s: &str, colour: bool) -> Cow<'_, str> {
    if !s.chars().any(is_active) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    let mut rest = s;
    while let Some(c) = rest.chars().next() {
        if rest.starts_with("\r\n") {
            out.push_str("\r\n");
            rest = &rest[2..];
            continue;
        }
        if let Some(n) = colour.then(|| plain_colour(rest)).flatten() {
            out.push_str(&rest[..n]);
            rest = &rest[n..];
            continue;
        }
        push_visible(&mut out, c);
        rest = &rest[c.len_utf8()..];
    }
    Cow::Owned(out)
}

/// The length of a plain colour sequence at the start of `s`, if there is one.
fn plain_colour(s: &str) -> Option<usize> {
    let body = s.strip_prefix("\u{1b}[")?;
    let digits = body.bytes().take_while(u8::is_ascii_digit).count();
    let code: u32 = body[..digits].parse().ok()?;
    let plain = digits <= 2 && (code <= 2 || (30..=37).contains(&code));
    (plain && body[digits..].starts_with('m')).then_some(2 + digits + 1)
}

/// Text for XML content and attribute values: `& < > "` as entities and
/// the active characters shown as `\u{XX}`, so the result is well-formed
/// XML 1.0 whatever `s` holds.
pub fn xml(s: &str) -> String {
    xml_with(s, true)
}

/// [`xml`] for element content only: quotes left as they are.
pub fn xml_text(s: &str) -> String {
    xml_with(s, false)
}

fn xml_with(s: &str, quotes: bool) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' if quotes => out.push_str("&quot;"),
            c => push_visible(&mut out, c),
        }
    }
    out
}

/// JSON text (already valid JSON) for a terminal: the active characters
/// that serde_json leaves raw (DEL, C1, the bidirectional controls,
/// U+FFFE/U+FFFF; it escapes C0 itself) as `\uXXXX` escapes, so the JSON
/// reads back to the same value.
pub fn json(s: &str) -> Cow<'_, str> {
    if !s.chars().any(is_active) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if is_active(c) {
            let _ = write!(out, "\\u{:04x}", c as u32);
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controls_are_shown_not_done() {
        assert_eq!(visible("plain √2 ≈ 1,41\tok\n"), "plain √2 ≈ 1,41\tok\n");
        assert_eq!(visible("A\u{1b}[2J\u{7}B"), "A\\u{1B}[2J\\u{7}B");
        assert_eq!(visible("\u{9b}31m\u{202e}kiri"), "\\u{9B}31m\\u{202E}kiri");
        assert_eq!(visible("a\rb\u{8}c\u{c}"), "a\\u{D}b\\u{8}c\\u{C}");
        assert_eq!(
            visible("\u{2067}x\u{2069}\u{ffff}"),
            "\\u{2067}x\\u{2069}\\u{FFFF}"
        );
    }

    #[test]
    fn only_plain_colours_pass_on_a_colour_terminal() {
        let ours = "\u{1b}[32m✓ correct\u{1b}[0m";
        assert_eq!(terminal(ours, true), ours);
        assert_eq!(terminal(ours, false), "\\u{1B}[32m✓ correct\\u{1B}[0m");
        // Cursor moves, screen clearing, titles and concealed text do not.
        assert_eq!(terminal("\u{1b}[2J\u{1b}[8m", true), "\\u{1B}[2J\\u{1B}[8m");
        assert_eq!(
            terminal("\u{1b}[1A\u{1b}]0;t\u{7}", true),
            "\\u{1B}[1A\\u{1B}]0;t\\u{7}"
        );
        assert_eq!(terminal("\u{1b}[312m", true), "\\u{1B}[312m");
    }

    #[test]
    fn a_line_ending_cr_lf_passes_and_a_lone_cr_does_not() {
        // a CSV record ends in CR LF (RFC 4180); a CR alone would return
        // the cursor and let the rest of a name overwrite its row
        assert_eq!(terminal("a,b\r\nc,d\r\n", false), "a,b\r\nc,d\r\n");
        assert_eq!(terminal("\"x\ry\"\r\n", false), "\"x\\u{D}y\"\r\n");
    }

    #[test]
    fn xml_is_well_formed_whatever_the_text() {
        assert_eq!(xml("A<B & \"C\">"), "A&lt;B &amp; &quot;C&quot;&gt;");
        assert_eq!(xml_text("\"q\"\u{8}"), "\"q\"\\u{8}");
        assert_eq!(xml("P\u{8}\u{c}"), "P\\u{8}\\u{C}");
    }

    #[test]
    fn json_stays_json() {
        let j = serde_json::to_string(&serde_json::json!({"n": "A\u{202e}B\u{85}\u{1b}"})).unwrap();
        let shown = json(&j);
        assert!(!shown.chars().any(is_active), "{shown}");
        let back: serde_json::Value = serde_json::from_str(&shown).unwrap();
        assert_eq!(back["n"], "A\u{202e}B\u{85}\u{1b}");
    }
}
