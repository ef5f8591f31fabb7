//! How numbers and values are written in text: significant digits, exact
//! forms beside their decimals, the language's decimal mark, matrices as
//! tables, a step's substituted values in the text's notation.

use crate::msg::{DocWord, Msg};
use crate::num::Shown;
use crate::report::lang::{Lang, NumStyle};
use crate::report::words;
use crate::stages::trace::{Name, Step, Subst, Val};
use comfy_table::{presets, Table};

/// How numbers are written in text output.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    /// Significant digits of decimals.
    pub digits: usize,
    /// Whether the run was exact (approximate values are then marked ≈).
    pub exact_mode: bool,
    /// The language of the words.
    pub lang: Lang,
    /// How numbers are written: the language's own decimal mark and
    /// separator ([`Style::new`]), or a quiz's `--decimal`
    /// ([`Style::with_nums`]).
    pub nums: NumStyle,
}

impl Style {
    /// `digits` significant digits, approximate values marked ≈ when
    /// `exact_mode`, in `lang` with its own decimal mark.
    pub fn new(digits: usize, exact_mode: bool, lang: Lang) -> Style {
        Style {
            digits,
            exact_mode,
            lang,
            nums: words::of(lang).nums(),
        }
    }

    /// The same style with its numbers written in `nums` (one decimal mark
    /// for a whole quiz, whatever its language: every number of the
    /// solution, its figures and the words that hold numbers).
    pub fn with_nums(self, nums: NumStyle) -> Style {
        Style { nums, ..self }
    }
}

impl Style {
    /// The words of a message key in this style's language, its numbers in
    /// this style's ([`words::words_in`]).
    pub fn w(&self, m: &Msg) -> String {
        words::words_in(m, self.lang, self.nums)
    }
    /// A word the documents share, in this style's language.
    pub fn doc(&self, w: DocWord) -> String {
        words::of(self.lang).doc(&w)
    }
    /// How this style writes numbers.
    pub fn nums(&self) -> NumStyle {
        self.nums
    }
}

impl Style {
    /// A value as a source printed it (a `[printed]` entry of a problem
    /// file), in the text's notation and this style's numbers: `(0, -1,
    /// -6/sqrt(2))` → `(0; −1; −6/√2)` in Indonesian.
    pub fn printed(&self, typed: &str) -> String {
        notation(typed, self.nums)
    }

    /// One number: `−√2/60 ≈ −0.02357`, `1/50 = 0.02`, `5`, `≈ 0.4142`, `0.4142`.
    pub fn num(&self, s: &Shown) -> String {
        self.nums.shown(s, self.digits, self.exact_mode)
    }

    /// A vector or list: `(√2/2, 0, √2/2) ≈ (0.7071, 0, 0.7071)`.
    pub fn list(&self, items: &[Val]) -> String {
        let sep = self.nums.sep;
        let nums: Option<Vec<&Shown>> = items
            .iter()
            .map(|v| if let Val::Num(s) = v { Some(s) } else { None })
            .collect();
        match nums {
            Some(ns) => {
                // An exact value beyond the doubles is shown by its exact form.
                let has_form = ns.iter().any(|s| {
                    s.pretty.as_deref().is_some_and(|p| {
                        !crate::num::format::is_plain_decimal(p) || !s.value.is_finite()
                    })
                });
                let decs: Vec<String> = ns.iter().map(|s| self.decimal(s)).collect();
                let approx = ns
                    .iter()
                    .any(|s| crate::num::format::is_approx(s, self.digits, self.exact_mode));
                let beyond = ns.iter().any(|s| {
                    (s.value == 0.0 && s.pretty.as_deref().is_some_and(|p| p != "0"))
                        || !s.value.is_finite()
                });
                if has_form {
                    let forms: Vec<String> = ns
                        .iter()
                        .zip(&decs)
                        .map(|(s, d)| {
                            s.pretty
                                .as_deref()
                                .map(|p| self.form(p))
                                .unwrap_or_else(|| format!("≈{d}"))
                        })
                        .collect();
                    if beyond {
                        // beyond the doubles: the exact forms alone
                        return format!("({})", forms.join(sep));
                    }
                    format!(
                        "({}) {} ({})",
                        forms.join(sep),
                        if approx { "≈" } else { "=" },
                        decs.join(sep)
                    )
                } else if self.exact_mode && approx && ns.iter().any(|s| s.pretty.is_none()) {
                    format!("≈ ({})", decs.join(sep))
                } else {
                    format!("({})", decs.join(sep))
                }
            }
            // the items are written in this style already: the separator too
            None => format!(
                "({})",
                items
                    .iter()
                    .map(|v| self.val_inline(v))
                    .collect::<Vec<_>>()
                    .join(sep)
            ),
        }
    }

    /// Any value on one line.
    pub fn val_inline(&self, v: &Val) -> String {
        match v {
            Val::Num(s) => self.num(s),
            Val::List(items) => self.list(items),
            Val::Map(kv) => kv
                .iter()
                .map(|(k, v)| format!("{k} = {}", self.val_inline(v)))
                .collect::<Vec<_>>()
                .join(";  "),
            Val::Text(t) => t.clone(),
            Val::Said(m) => self.w(m),
            Val::Bool(b) => self.doc(if *b { DocWord::Yes } else { DocWord::No }),
            Val::Null => self.doc(DocWord::NoValue),
        }
    }

    /// A matrix as a table; exact forms in the cells when there are any.
    pub fn matrix(&self, rows: &[Val]) -> String {
        let mut t = Table::new();
        t.load_preset(presets::UTF8_FULL_CONDENSED);
        for r in rows {
            if let Val::List(cells) = r {
                t.add_row(cells.iter().map(|c| match c {
                    Val::Num(s) => self.cell(s),
                    other => self.val_inline(other),
                }));
            }
        }
        t.to_string()
    }

    /// A matrix cell: its exact form when it has one, else its decimal.
    pub fn cell(&self, s: &Shown) -> String {
        match &s.pretty {
            Some(p) => self.form(p),
            None => self.decimal(s),
        }
    }

    /// A number's decimal with this style's digits and mark, and the
    /// minus sign: `−0,02357`.
    fn decimal(&self, s: &Shown) -> String {
        crate::num::format::decimal_in(s, self.digits, self.nums.mark).replace('-', "−")
    }

    /// An exact form with this style's mark and the minus sign: `−√2/60`.
    fn form(&self, p: &str) -> String {
        self.nums.form(&p.replace('-', "−"))
    }

    /// A step below its title: the formula, the values substituted, the
    /// results (`⇒`) and the note, one per line.
    pub fn step_body(&self, s: &Step) -> String {
        let mut out = String::new();
        if !s.formula.is_empty() {
            out.push_str(&format!("    {}\n", self.w(&s.formula)));
        }
        let name = |k: &Name| words::of(self.lang).name(k);
        for (k, v) in &s.values {
            out.push_str(&self.line("    ", &name(k), s.sub_of(k), v));
            out.push('\n');
        }
        for (k, v) in &s.result {
            out.push_str(&self.line("  ⇒ ", &name(k), s.sub_of(k), v));
            out.push('\n');
        }
        if let Some(n) = &s.note {
            out.push_str(&format!("    ({})\n", self.w(n)));
        }
        out
    }

    /// `name = value` as [`named`](Style::named) writes it, or `name =
    /// substitution = value` when the step shows how it was worked.
    pub fn line(&self, indent: &str, name: &str, sub: Option<&Subst>, v: &Val) -> String {
        match sub {
            Some(sub) if !v.is_matrix() => {
                format!("{indent}{}", self.worked(name, sub, v))
            }
            _ => self.named(indent, name, v),
        }
    }

    /// `name = substitution = value` (`t = (0 − 4)/(−2 − 4) = 2/3 ≈
    /// 0.6667`), `≈` before a value without an exact form; the
    /// substitution is left out when it reads as the value itself, and the
    /// line is then written as [`named`](Style::named) writes it (`bottom ≈
    /// −0.0364` for −top with top ≈ 0.0364, never `bottom = ≈ −0.0364`).
    pub fn worked(&self, name: &str, sub: &Subst, v: &Val) -> String {
        let (val, sub) = (self.val_inline(v), self.subst(sub));
        let shown = |s: &str| s.split([' ']).any(|p| p == sub) || s == sub;
        match val.strip_prefix("≈ ") {
            _ if shown(&val.replace(" ≈ ", " ").replace(" = ", " ")) => self.named("", name, v),
            Some(rest) => format!("{name} = {sub} ≈ {rest}"),
            None => format!("{name} = {sub} = {val}"),
        }
    }

    /// A substitution in this style's language: each value as a short
    /// decimal when that is exact (0.1), else its exact form (√2/2, 2/3),
    /// else its decimal; in parentheses where the operator before it
    /// would otherwise bind wrongly (`4 − (−2)`, `2·(√2−1)`).
    pub fn subst(&self, s: &Subst) -> String {
        let mut out = String::new();
        let pieces: Vec<&str> = s.form.split("{}").collect();
        for (i, piece) in pieces.iter().enumerate() {
            out.push_str(&piece.replace(Subst::SEP, self.nums.sep));
            let Some(a) = s.args.get(i).filter(|_| i + 1 < pieces.len()) else {
                continue;
            };
            let text = self.operand(a);
            // a whole power after `^` is raised: max(0.8, 0)^4 → max(0.8, 0)⁴
            let raised: Option<String> = (out.ends_with('^'))
                .then(|| text.chars().map(superscript).collect())
                .flatten();
            match raised {
                Some(r) => {
                    out.pop();
                    out.push_str(&r);
                }
                None => {
                    let (before, after) =
                        (out.trim_end().chars().last(), pieces[i + 1].chars().next());
                    out.push_str(&parenthesized(&text, before, after));
                }
            }
        }
        out
    }

    /// One value of a substitution (a vector in parentheses).
    fn operand(&self, v: &Val) -> String {
        match v {
            Val::Num(s) => match &s.pretty {
                Some(p)
                    if p.contains('√') || crate::num::format::is_approx(s, self.digits, false) =>
                {
                    self.form(p)
                }
                _ => self.decimal(s),
            },
            Val::List(items) => {
                let parts: Vec<String> = items.iter().map(|x| self.operand(x)).collect();
                format!("({})", parts.join(self.nums().sep))
            }
            other => self.val_inline(other),
        }
    }

    /// `name = value`, with a matrix on its own lines; `name ≈ value` when
    /// the value has no exact form (never `name = ≈ value`).
    pub fn named(&self, indent: &str, name: &str, v: &Val) -> String {
        if v.is_matrix() {
            let table = self.matrix(match v {
                Val::List(rows) => rows,
                _ => &[],
            });
            let pad = " ".repeat(indent.chars().count());
            let body: Vec<String> = table.lines().map(|l| format!("{pad}  {l}")).collect();
            format!("{indent}{name} =\n{}", body.join("\n"))
        } else {
            // "top ≈ 0.04663", not "top = ≈ 0.04663" (no exact form)
            let val = self.val_inline(v);
            match val.strip_prefix("≈ ") {
                Some(rest) => format!("{indent}{name} ≈ {rest}"),
                None => format!("{indent}{name} = {val}"),
            }
        }
    }
}

/// An expression as a file writes it (`-6/sqrt(2)`, `(0.0067, -0.0283)`)
/// in the text's notation, not simplified: `−6/√2`, roots, π, `·` and
/// the minus sign, and the decimal mark and separator of `nums` for the
/// file's `.` and `, ` (`(0,0067; −0,0283)`) ([`Style::printed`]).
pub fn notation(typed: &str, nums: NumStyle) -> String {
    let chars: Vec<char> = typed.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let rest: String = chars[i..].iter().take(4).collect();
        if rest.eq_ignore_ascii_case("sqrt") {
            i += 4;
            if chars.get(i) == Some(&'(') {
                // the root's argument, to its matching parenthesis
                let (mut depth, start) = (0, i);
                while i < chars.len() {
                    depth += match chars[i] {
                        '(' => 1,
                        ')' => -1,
                        _ => 0,
                    };
                    i += 1;
                    if depth == 0 {
                        break;
                    }
                }
                let inner: String = chars[start + 1..i.saturating_sub(1).max(start + 1)]
                    .iter()
                    .collect();
                let inner = notation(&inner, nums);
                if inner.chars().all(|c| c.is_ascii_digit()) && !inner.is_empty() {
                    out.push_str(&format!("√{inner}"));
                } else {
                    out.push_str(&format!("√({inner})"));
                }
            } else {
                out.push('√');
            }
            continue;
        }
        if rest.len() >= 2
            && rest[..2].eq_ignore_ascii_case("pi")
            && !chars.get(i + 2).is_some_and(|c| c.is_alphabetic())
            && !(i > 0 && chars[i - 1].is_alphabetic())
        {
            out.push('π');
            i += 2;
            continue;
        }
        match chars[i] {
            '-' => out.push('−'),
            '*' => out.push('·'),
            '.' => out.push(nums.mark),
            ',' if chars.get(i + 1) == Some(&' ') => {
                out.push_str(nums.sep);
                i += 1;
            }
            c => out.push(c),
        }
        i += 1;
    }
    out
}

/// A digit raised (`4` → `⁴`); `None` for anything else.
fn superscript(c: char) -> Option<char> {
    let i = c.to_digit(10)? as usize;
    "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().nth(i)
}

/// `text` as an operand between `before` and `after` (the characters
/// around it): in parentheses when it is negative after an operator, a sum
/// (or, after `/` and `^`, any expression) after a product or quotient, or
/// anything but a plain number before a power (`(−2)²`).
fn parenthesized(text: &str, before: Option<char>, after: Option<char>) -> String {
    let negative = text.starts_with('−');
    let body = text.strip_prefix('−').unwrap_or(text);
    let mut depth = 0;
    let (mut sum, mut op) = (false, false);
    for c in body.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '−' if depth == 0 => (sum, op) = (true, true),
            '/' | '·' if depth == 0 => op = true,
            _ => {}
        }
    }
    let power = after.is_some_and(|c| "²³ⁿ^".contains(c)) && (negative || op || body.contains('√'));
    let factor = (negative || op) && after.is_some_and(|c| "·×".contains(c));
    let wrap = power
        || factor
        || match before {
            None | Some('(' | '[' | ';' | ',' | '=' | '|' | '≤' | '<' | '>' | '≥') => false,
            Some('+') => negative,
            Some('−' | '·' | '×') => negative || sum,
            Some('/' | '^') => negative || op || (body.contains('√') && !body.starts_with('√')),
            Some(_) => negative,
        };
    if wrap {
        format!("({text})")
    } else {
        text.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::fmt_dec;

    #[test]
    fn decimals() {
        assert_eq!(fmt_dec(-0.023570226, 4), "-0.02357");
        assert_eq!(fmt_dec(0.02, 4), "0.02");
        assert_eq!(fmt_dec(100.0, 4), "100");
        assert_eq!(fmt_dec(21.548, 4), "21.55");
        assert_eq!(fmt_dec(-1e-12, 3), "-1e-12");
        assert_eq!(fmt_dec(-0.00001, 3), "-0.00001");
    }

    #[test]
    fn exact_numbers_show_their_form() {
        let st = Style::new(4, true, Lang::En);
        let s = Shown {
            value: -0.023570226039551584,
            exact: Some("-sqrt(2)/60".into()),
            pretty: Some("−√2/60".into()),
            beyond: None,
        };
        assert_eq!(st.num(&s), "−√2/60 ≈ −0.02357");
        let fifty = Shown {
            value: 0.02,
            exact: Some("1/50".into()),
            pretty: Some("1/50".into()),
            beyond: None,
        };
        assert_eq!(st.num(&fifty), "1/50 = 0.02");
        let approx = Shown {
            value: 0.41421356,
            exact: None,
            pretty: None,
            beyond: None,
        };
        assert_eq!(st.num(&approx), "≈ 0.4142");
    }

    /// bottom = −top with top = 0.1·tan 20° (no exact form in square
    /// roots): the substitution −0.0364 reads as the value itself, so the
    /// line is the value alone, `≈` after the name, and no `= ≈` with an
    /// empty exact form between them.
    #[test]
    fn a_substitution_that_reads_as_its_value_leaves_no_empty_exact_form() {
        let top = 0.1 * 20f64.to_radians().tan();
        let approx = |value: f64| {
            Val::Num(Shown {
                value,
                exact: None,
                pretty: None,
                beyond: None,
            })
        };
        for (lang, want) in [
            (Lang::En, "bottom ≈ −0.0364"),
            (Lang::Id, "bottom ≈ −0,0364"),
        ] {
            let st = Style::new(4, true, lang);
            let sub = Subst::new("−{}", vec![approx(top)]);
            assert_eq!(st.worked("bottom", &sub, &approx(-top)), want);
        }
        // an exact value whose substitution is itself keeps its one `=`
        let st = Style::new(4, true, Lang::En);
        let half = Val::Num(Shown {
            value: 0.5,
            exact: Some("1/2".into()),
            pretty: Some("1/2".into()),
            beyond: None,
        });
        let sub = Subst::new("{}", vec![half.clone()]);
        assert_eq!(st.worked("t", &sub, &half), "t = 1/2 = 0.5");
    }

    #[test]
    fn a_vector_beyond_the_doubles_shows_its_exact_forms_only() {
        // v = (1/10^400, 0): the nearest doubles are (0, 0), which would
        // read "(…) = (0, 0)".
        let st = Style::new(4, true, Lang::En);
        let n = |value: f64, p: &str| {
            Val::Num(Shown {
                value,
                exact: Some(p.into()),
                pretty: Some(p.into()),
                beyond: None,
            })
        };
        let v = [n(0.0, "1/1000"), n(0.0, "0")];
        assert_eq!(st.list(&v), "(1/1000, 0)");
    }
}
