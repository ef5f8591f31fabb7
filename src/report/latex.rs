//! LaTeX from the steps' notation: text with its special characters
//! escaped and the notation's symbols (−, √, ≈, ·, ×, ⁻¹, °, …) as math, for
//! the Markdown/LaTeX sheets and keys and the TikZ figures alike.

/// One piece of LaTeX output: plain text, or math (set between `$`).
enum Piece {
    Text(String),
    Math(String),
}

/// Text for LaTeX text mode: special characters escaped, symbols as math.
pub fn latex_text(s: &str) -> String {
    let mut out = String::new();
    let mut in_math = false;
    for p in pieces(s) {
        match p {
            Piece::Text(t) => {
                if in_math {
                    out.push('$');
                    in_math = false;
                }
                out.push_str(&t);
            }
            Piece::Math(m) => {
                if !in_math {
                    out.push('$');
                    in_math = true;
                }
                out.push_str(&m);
            }
        }
    }
    if in_math {
        out.push('$');
    }
    out
}

/// Text for LaTeX math mode (matrix cells).
pub fn latex_math(s: &str) -> String {
    pieces(s)
        .into_iter()
        .map(|p| match p {
            Piece::Text(t) | Piece::Math(t) => t,
        })
        .collect()
}

fn pieces(s: &str) -> Vec<Piece> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        i += 1;
        out.push(match c {
            '√' => sqrt_piece(&chars, &mut i),
            '⁻' if chars.get(i) == Some(&'¹') => {
                i += 1;
                Piece::Math("^{-1}".into())
            }
            // a power of several digits is one superscript (`⁴⁰` → `^{40}`)
            c => match raised_digit(c) {
                Some(d) => {
                    let mut digits = String::from(d);
                    while let Some(d) = chars.get(i).and_then(|c| raised_digit(*c)) {
                        digits.push(d);
                        i += 1;
                    }
                    Piece::Math(format!("^{{{digits}}}"))
                }
                None => symbol(c),
            },
        });
    }
    out
}

/// The digit a superscript digit raises (`⁴` → `4`).
fn raised_digit(c: char) -> Option<char> {
    let i = "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().position(|d| d == c)?;
    char::from_digit(i as u32, 10)
}

/// √ applied to what follows at `i`: a parenthesized group, or a number
/// or a name; `i` moves past it.
fn sqrt_piece(chars: &[char], i: &mut usize) -> Piece {
    let start = *i;
    if chars.get(*i) == Some(&'(') {
        let mut depth = 0;
        while *i < chars.len() {
            if chars[*i] == '(' {
                depth += 1;
            } else if chars[*i] == ')' {
                depth -= 1;
                if depth == 0 {
                    *i += 1;
                    break;
                }
            }
            *i += 1;
        }
        let inner: String = chars[start + 1..i.saturating_sub(1)].iter().collect();
        Piece::Math(format!("\\sqrt{{{}}}", latex_math(&inner)))
    } else {
        while *i < chars.len() && (chars[*i].is_ascii_alphanumeric() || chars[*i] == '.') {
            *i += 1;
        }
        let inner: String = chars[start..*i].iter().collect();
        Piece::Math(format!("\\sqrt{{{inner}}}"))
    }
}

/// One character as LaTeX: a symbol in math mode, an escaped special
/// character, itself (ASCII), or its code point.
fn symbol(c: char) -> Piece {
    let math = |m: &str| Piece::Math(m.to_string());
    let text = |t: &str| Piece::Text(t.to_string());
    match c {
        '−' => math("-"),
        '·' => math("\\cdot "),
        '×' => math("\\times "),
        '≈' => math("\\approx "),
        '≤' => math("\\le "),
        '≥' => math("\\ge "),
        '≠' => math("\\ne "),
        '⇒' => math("\\Rightarrow "),
        '→' => math("\\to "),
        '←' => math("\\leftarrow "),
        '∥' => math("\\parallel "),
        '⊥' => math("\\perp "),
        '°' => math("^\\circ "),
        'ᵀ' => math("^{T}"),
        'ⁿ' => math("^{n}"),
        'Σ' => math("\\Sigma "),
        'Δ' => math("\\Delta "),
        '₀' => math("_0"),
        '₁' => math("_1"),
        '₂' => math("_2"),
        'θ' => math("\\theta "),
        'α' => math("\\alpha "),
        'β' => math("\\beta "),
        'π' => math("\\pi "),
        '<' => math("<"),
        '>' => math(">"),
        '|' => math("|"),
        '…' => text("\\ldots{}"),
        '—' => text("---"),
        '–' => text("--"),
        '’' | '′' => text("'"),
        '“' | '”' => text("\""),
        '\\' => text("\\textbackslash{}"),
        '{' => text("\\{"),
        '}' => text("\\}"),
        '$' => text("\\$"),
        '&' => text("\\&"),
        '#' => text("\\#"),
        '%' => text("\\%"),
        '_' => text("\\_"),
        '^' => text("\\^{}"),
        '~' => text("\\~{}"),
        c if c.is_ascii() => Piece::Text(c.to_string()),
        other => Piece::Text(format!("[U+{:04X}]", other as u32)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_maps_symbols_to_ascii_commands() {
        assert_eq!(
            latex_text("−√2/60 ≈ −0.02357"),
            "$-\\sqrt{2}$/60 $\\approx $ $-$0.02357"
        );
        assert_eq!(latex_text("√(a+b)"), "$\\sqrt{a+b}$");
        // The shading steps' sum over the lights and the specular power.
        assert_eq!(latex_text("Σ (N·H)ⁿ"), "$\\Sigma $ (N$\\cdot $H)$^{n}$");
        assert_eq!(latex_text("x_1 50%"), "x\\_1 50\\%");
        assert_eq!(latex_math("−√2/2"), "-\\sqrt{2}/2");
        assert!(latex_text("V = Mcam⁻¹, Rᵀ, 22.5°, u·v, a × b, ⇒").is_ascii());
        // a substituted power: several digits raised are one superscript
        assert_eq!(latex_math("max(0,5; 0)⁴⁰ + 2³"), "max(0,5; 0)^{40} + 2^{3}");
    }
}
