//! The steps' notation as MathML, which current browsers render natively:
//! `n = (Pe − Pr) / |Pe − Pr|`, `−√2/60 ≈ −0.02357`, `top = near·tan(fovy/2)`.
//!
//! A small reader of the notation the steps print: names become `<mi>`,
//! numbers `<mn>` (with the Indonesian decimal comma, and `7.07e−309` as
//! 7.07 × 10⁻³⁰⁹), symbols `<mo>`; `√x` and `√(…)` become `<msqrt>`,
//! superscripts (`²`, `ⁿ`, `ᵀ`, `⁻¹`) `<msup>` and subscripts (`₀`)
//! `<msub>` of what precedes them.

use super::figure::xml_escape;

/// Inline MathML for a line of notation.
pub fn inline(s: &str) -> String {
    format!("<math>{}</math>", row(s))
}

/// Inline MathML for a line of notation that ends in words (`⇒ status =`
/// and `di-clip`): the words as `<mtext>` in the same row.
pub fn inline_then_text(notation: &str, text: &str) -> String {
    let r = row(notation);
    let inner = &r["<mrow>".len()..r.len() - "</mrow>".len()];
    format!(
        "<math><mrow>{inner}<mspace width=\"0.3em\"/><mtext>{}</mtext></mrow></math>",
        xml_escape(text)
    )
}

/// Display (block) MathML for a formula.
pub fn block(s: &str) -> String {
    format!("<math display=\"block\">{}</math>", row(s))
}

/// The deepest nesting of roots and scripts set as MathML; a group nested
/// deeper (a point named `√(√(√(…`, 20,000 deep, took 10 GB and overflowed
/// the stack) is set as its text, so a row costs at most this many passes
/// over its characters.
pub const MAX_MATH_DEPTH: usize = 16;

/// The notation as one `<mrow>`.
pub fn row(s: &str) -> String {
    row_at(s, 0)
}

/// [`row`] of a group nested `depth` deep.
fn row_at(s: &str, depth: usize) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut items: Vec<String> = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            // the space between two words or names is kept (`z' dari C'`,
            // `fovy/2 (derajat)`); beside an operator, MathML spaces it
            let before = chars[..i].iter().rev().find(|c| !c.is_whitespace());
            let after = chars[i..].iter().find(|c| !c.is_whitespace());
            if before.is_some_and(|&b| ends_item(b)) && after.is_some_and(|&a| starts_item(a)) {
                items.push(SPACE.to_string());
            }
            while chars.get(i).is_some_and(|c| c.is_whitespace()) {
                i += 1;
            }
        } else if superscript(c).is_some() {
            let (text, next) = run(&chars, i, superscript);
            i = next;
            attach(&mut items, "msup", &script(&text, depth));
        } else if subscript(c).is_some() {
            let (text, next) = run(&chars, i, subscript);
            i = next;
            attach(&mut items, "msub", &script(&text, depth));
        } else if c == '√' {
            let (inner, next) = radicand(&chars, i + 1, depth);
            i = next;
            items.push(format!("<msqrt>{inner}</msqrt>"));
        } else if c.is_ascii_digit() {
            let (num, next) = number(&chars, i);
            i = next;
            items.push(num);
        } else if c.is_alphabetic() {
            let (item, next) = name_or_words(&chars, i);
            i = next;
            items.push(item);
        } else {
            // a sign (not a difference): first, or after a bracket, a
            // separator or another operator: `(−2 − 4)`, `= −√2/60`
            let before = chars[..i].iter().rev().find(|c| !c.is_whitespace());
            let sign = matches!(c, '−' | '-' | '+')
                && before.is_none_or(|b| "([{,;=≈≤≥<>·×/−+⇒".contains(*b));
            i += 1;
            items.push(match sign {
                true => format!("<mo lspace=\"0\" rspace=\"0\">{c}</mo>"),
                false => operator(c),
            });
        }
    }
    format!("<mrow>{}</mrow>", items.concat())
}

/// The space kept between two words or names.
const SPACE: &str = "<mspace width=\"0.3em\"/>";

/// Whether `c` can end an item that a kept space follows: a name, a
/// number, a prime, a script, a closing bracket.
fn ends_item(c: char) -> bool {
    c.is_alphanumeric()
        || matches!(c, '\'' | '′' | ')' | ']')
        || superscript(c).is_some()
        || subscript(c).is_some()
}

/// Whether `c` can start an item that a kept space precedes.
fn starts_item(c: char) -> bool {
    c.is_alphanumeric() || matches!(c, '(' | '[' | '√')
}

/// A name from `i` as `<mi>`, or as `<mtext>` when it is words: a word of
/// two lowercase letters or more beside a space and another name (`z'
/// dari C'`, `piksel A`), or such words one after another (`polygon
/// face`, `object's triangle`, `at the centre`). MathML sets the
/// identifiers of a row side by side, so words must be text for the
/// spaces between them to stay. Returns the item and where it ends.
fn name_or_words(chars: &[char], i: usize) -> (String, usize) {
    let word_end = |mut k: usize| {
        // a name of two joined by a dash is one word (Liang–Barsky)
        let joined = |k: usize| {
            chars[k] == '–'
                && k > 0
                && chars[k - 1].is_alphabetic()
                && chars.get(k + 1).is_some_and(|c| c.is_alphabetic())
        };
        while k < chars.len() && (chars[k].is_alphabetic() || chars[k] == '_' || joined(k)) {
            k += 1;
        }
        k
    };
    let mut end = word_end(i);
    let mut words = end - i >= 2;
    let mut phrase = false;
    while words {
        // The next word: after spaces, or after an apostrophe (object's).
        let mut k = end;
        while k < chars.len() && chars[k] == ' ' {
            k += 1;
        }
        let apostrophe = k == end && matches!(chars.get(k), Some('\'' | '’'));
        let start = if apostrophe { k + 1 } else { k };
        let next = word_end(start);
        words = (k > end || apostrophe) && next > start && (apostrophe || next - start >= 2);
        if words {
            (end, phrase) = (next, true);
        }
    }
    let text: String = chars[i..end].iter().collect();
    let spaced = |k: usize| chars.get(k).is_some_and(|c| *c == ' ');
    let lone_word = text.chars().count() >= 2
        && text.chars().all(char::is_lowercase)
        && ((i > 0 && spaced(i - 1) && i > 1 && ends_item(chars[i - 2]))
            || (spaced(end)
                && chars[end..]
                    .iter()
                    .find(|c| **c != ' ')
                    .is_some_and(|c| c.is_alphanumeric())));
    let tag = if phrase || lone_word { "mtext" } else { "mi" };
    (format!("<{tag}>{}</{tag}>", xml_escape(&text)), end)
}

/// A symbol as `<mo>`; brackets, bars and the slash of an inline fraction
/// are set without the space MathML would give an operator, and without
/// stretching to a root beside them; the separators `;` and `,` are
/// followed by a space, as the text writes them.
fn operator(c: char) -> String {
    match c {
        '(' | ')' | '[' | ']' | '|' => {
            format!("<mo stretchy=\"false\" lspace=\"0\" rspace=\"0\">{c}</mo>")
        }
        '/' => "<mo lspace=\"0\" rspace=\"0\">/</mo>".to_string(),
        // a relation keeps its spaces at either end of a row (`⇒ code0 =`
        // before a word, or first in the line)
        '=' | '≈' => format!("<mo form=\"infix\">{c}</mo>"),
        '⇒' => "<mo lspace=\"0\" rspace=\"0.5em\">⇒</mo>".to_string(),
        ';' | ',' => format!("<mo separator=\"true\" lspace=\"0\" rspace=\"0.35em\">{c}</mo>"),
        _ => format!("<mo>{}</mo>", xml_escape(&c.to_string())),
    }
}

/// The characters from `i` on that `class` maps, mapped; and where they end.
fn run(chars: &[char], mut i: usize, class: fn(char) -> Option<char>) -> (String, usize) {
    let mut out = String::new();
    while let Some(c) = chars.get(i).and_then(|&c| class(c)) {
        out.push(c);
        i += 1;
    }
    (out, i)
}

/// A script's content: a number, a name or a sign and a number.
fn script(t: &str, depth: usize) -> String {
    match t {
        "°" => "<mo>°</mo>".into(),
        _ if t.chars().all(|c| c.is_ascii_digit()) => format!("<mn>{t}</mn>"),
        _ => format!("<mrow>{}</mrow>", row_inner(t, depth + 1)),
    }
}

/// A row's items without the surrounding `<mrow>`, nested `depth` deep:
/// past [`MAX_MATH_DEPTH`], the text itself.
fn row_inner(t: &str, depth: usize) -> String {
    if depth > MAX_MATH_DEPTH {
        return format!("<mtext>{}</mtext>", xml_escape(t));
    }
    let r = row_at(t, depth);
    r["<mrow>".len()..r.len() - "</mrow>".len()].to_string()
}

/// Wraps the last item as the base of a script (`<msup>base x</msup>`).
fn attach(items: &mut Vec<String>, tag: &str, script: &str) {
    let base = items.pop().unwrap_or_else(|| "<mrow></mrow>".into());
    items.push(format!("<{tag}>{base}{script}</{tag}>"));
}

/// What `√` applies to from `i`: a parenthesized group or a number or a
/// name; its MathML and where it ends.
fn radicand(chars: &[char], i: usize, depth: usize) -> (String, usize) {
    if chars.get(i) == Some(&'(') {
        let mut open = 0;
        let mut j = i;
        while j < chars.len() {
            match chars[j] {
                '(' => open += 1,
                ')' => {
                    open -= 1;
                    if open == 0 {
                        break;
                    }
                }
                _ => {}
            }
            j += 1;
        }
        let inner: String = chars[i + 1..j.min(chars.len())].iter().collect();
        (row_inner(&inner, depth + 1), (j + 1).min(chars.len()))
    } else if chars.get(i).is_some_and(|c| c.is_ascii_digit()) {
        number(chars, i)
    } else {
        let mut j = i;
        while j < chars.len() && chars[j].is_alphabetic() {
            j += 1;
        }
        let name: String = chars[i..j].iter().collect();
        (format!("<mi>{}</mi>", xml_escape(&name)), j)
    }
}

/// A number from `i`: digits with a decimal point (or an Indonesian decimal
/// comma between digits) and an exponent `e−309` set as × 10⁻³⁰⁹.
fn number(chars: &[char], mut i: usize) -> (String, usize) {
    let start = i;
    let digit = |k: usize| chars.get(k).is_some_and(|c| c.is_ascii_digit());
    while digit(i) || (matches!(chars.get(i), Some('.') | Some(',')) && digit(i + 1)) {
        i += 1;
    }
    let mantissa: String = chars[start..i].iter().collect();
    let sign = matches!(chars.get(i + 1), Some('-') | Some('−') | Some('+'));
    if chars.get(i) == Some(&'e') && (digit(i + 1) || (sign && digit(i + 2))) {
        let mut j = i + 1 + usize::from(sign);
        while digit(j) {
            j += 1;
        }
        let exp: String = chars[i + 1..j].iter().collect::<String>().replace('-', "−");
        let ten = format!("<msup><mn>10</mn><mn>{exp}</mn></msup>");
        return (format!("<mn>{mantissa}</mn><mo>×</mo>{ten}"), j);
    }
    (format!("<mn>{mantissa}</mn>"), i)
}

/// A superscript character as the character it raises.
fn superscript(c: char) -> Option<char> {
    Some(match c {
        '⁰' => '0',
        '¹' => '1',
        '²' => '2',
        '³' => '3',
        '⁴' => '4',
        '⁵' => '5',
        '⁶' => '6',
        '⁷' => '7',
        '⁸' => '8',
        '⁹' => '9',
        '⁻' => '−',
        'ⁿ' => 'n',
        'ᵀ' => 'T',
        '°' => '°',
        _ => return None,
    })
}

/// A subscript character as the character it lowers.
fn subscript(c: char) -> Option<char> {
    Some(match c {
        '₀' => '0',
        '₁' => '1',
        '₂' => '2',
        '₃' => '3',
        '₄' => '4',
        '₅' => '5',
        '₆' => '6',
        '₇' => '7',
        '₈' => '8',
        '₉' => '9',
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_are_one_text_and_names_stay_identifiers() {
        assert_eq!(
            row("polygon face ="),
            "<mrow><mtext>polygon face</mtext><mo form=\"infix\">=</mo></mrow>"
        );
        assert_eq!(
            row("object's triangle = 17"),
            "<mrow><mtext>object's triangle</mtext><mo form=\"infix\">=</mo><mn>17</mn></mrow>"
        );
        // notation keeps its names: one-letter names, and names apart
        // from words by operators
        assert_eq!(
            row("top = near·tan"),
            "<mrow><mi>top</mi><mo form=\"infix\">=</mo><mi>near</mi><mo>·</mo><mi>tan</mi></mrow>"
        );
        // a space between two names is kept, and a lone word beside a
        // name is text: `z' dari C'`, `piksel A`
        assert_eq!(
            row("a b"),
            "<mrow><mi>a</mi><mspace width=\"0.3em\"/><mi>b</mi></mrow>"
        );
        assert_eq!(
            row("Liang–Barsky ="),
            "<mrow><mi>Liang–Barsky</mi><mo form=\"infix\">=</mo></mrow>"
        );
        assert_eq!(
            row("piksel A"),
            "<mrow><mtext>piksel</mtext><mspace width=\"0.3em\"/><mi>A</mi></mrow>"
        );
        assert_eq!(
            row("z at the vertices"),
            "<mrow><mi>z</mi><mspace width=\"0.3em\"/><mtext>at the vertices</mtext></mrow>"
        );
    }

    #[test]
    fn a_surd_with_its_decimal() {
        assert_eq!(
            row("−√2/60 ≈ −0.02357"),
            "<mrow><mo lspace=\"0\" rspace=\"0\">−</mo><msqrt><mn>2</mn></msqrt><mo lspace=\"0\" rspace=\"0\">/</mo><mn>60</mn>\
             <mo form=\"infix\">≈</mo><mo lspace=\"0\" rspace=\"0\">−</mo><mn>0.02357</mn></mrow>"
        );
    }

    #[test]
    fn a_sign_is_set_close_and_a_difference_apart() {
        // (−2 − 4): the first minus is the sign of 2, the second a difference
        assert_eq!(
            row("(−2 − 4)"),
            "<mrow><mo stretchy=\"false\" lspace=\"0\" rspace=\"0\">(</mo>\
             <mo lspace=\"0\" rspace=\"0\">−</mo><mn>2</mn><mo>−</mo><mn>4</mn>\
             <mo stretchy=\"false\" lspace=\"0\" rspace=\"0\">)</mo></mrow>"
        );
    }

    #[test]
    fn scripts_attach_to_what_precedes_them() {
        assert_eq!(
            row("v₀² + Mcam⁻¹"),
            "<mrow><msup><msub><mi>v</mi><mn>0</mn></msub><mn>2</mn></msup><mo>+</mo>\
             <msup><mi>Mcam</mi><mrow><mo lspace=\"0\" rspace=\"0\">−</mo><mn>1</mn></mrow></msup></mrow>"
        );
    }

    #[test]
    fn a_group_under_the_root_and_numbers_in_both_languages() {
        assert_eq!(
            row("√(a² + 1)"),
            "<mrow><msqrt><msup><mi>a</mi><mn>2</mn></msup><mo>+</mo><mn>1</mn></msqrt></mrow>"
        );
        // the Indonesian decimal comma stays in the number; "; " separates
        assert_eq!(
            row("(0,5; 2)"),
            "<mrow><mo stretchy=\"false\" lspace=\"0\" rspace=\"0\">(</mo><mn>0,5</mn>\
             <mo separator=\"true\" lspace=\"0\" rspace=\"0.35em\">;</mo><mn>2</mn>\
             <mo stretchy=\"false\" lspace=\"0\" rspace=\"0\">)</mo></mrow>"
        );
        assert_eq!(
            row("7.071e−309"),
            "<mrow><mn>7.071</mn><mo>×</mo><msup><mn>10</mn><mn>−309</mn></msup></mrow>"
        );
    }

    #[test]
    fn a_deep_nesting_is_set_as_text_past_the_bound() {
        // √(√(…√(2)…)) 20,000 deep: MAX_MATH_DEPTH + 1 roots as MathML,
        // the rest as one text (it used to nest 20,000 rows: 10 GB, then a
        // stack overflow).
        let n = 20_000;
        let deep = format!("{}2{}", "√(".repeat(n), ")".repeat(n));
        let m = row(&deep);
        assert_eq!(m.matches("<msqrt>").count(), MAX_MATH_DEPTH + 1);
        assert_eq!(m.matches("<mtext>").count(), 1);
        // the size stays linear: the text once, and the roots' markup
        assert!(m.len() < 2 * deep.len() + 1000, "{}", m.len());
        // a shallow root is unchanged
        assert_eq!(
            row("√(√2)"),
            "<mrow><msqrt><msqrt><mn>2</mn></msqrt></msqrt></mrow>"
        );
    }

    #[test]
    fn markup_characters_are_escaped() {
        assert_eq!(
            row("a < b"),
            "<mrow><mi>a</mi><mo>&lt;</mo><mi>b</mi></mrow>"
        );
    }
}
