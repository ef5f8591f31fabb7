//! Exams as Moodle XML: one Cloze (`multianswer`) question per problem and
//! variant, the variants of problem NN in the category
//! `$course$/grafika/<topic>/<NN>` (written before its questions), so that a
//! quiz can draw one variant per student ("Add a random question").
//!
//! Each number is a NUMERICAL blank `{1:NUMERICAL:=x:t#…~%0%w:t'#feedback}`
//! with the key's value x, its absolute tolerance t
//! ([`crate::tutor::generate::quiz`]), and a 0 % answer at each value w a
//! catalog mistake gives, whose feedback names the mistake; outcodes and the
//! clipping status are SHORTANSWER blanks. The worked solution is the
//! general feedback (HTML).
//!
//! Escaping, in the order Moodle undoes it: text is HTML-escaped (`&`, `<`,
//! `>`); inside a blank, Moodle decodes HTML entities once before storing the
//! feedback as HTML, so the feedback is escaped twice, and the characters
//! that end a part of a blank (`}`, `~`, `#`, and `{`, `\`) are written as
//! numeric entities (`&#125;` …), which the decoding turns back; the question
//! text and general feedback go into CDATA sections, a `]]>` inside split
//! across two sections.

use crate::report::lang::{tr, Lang};
use crate::report::mistakes::mistake_text;
use crate::report::words::words;
use crate::report::Style;
use crate::stages::trace::{Report, Val};
use crate::tutor::generate::quiz::{blanks, Asked, Blank, Typed, Wrong};
use crate::tutor::generate::{topics_name, Generated, Topic};
use std::fmt::Write as _;

/// The problems of every variant: `exams[v][i]` is problem i of variant v;
/// problem i is on `topics[i % topics.len()]`.
pub struct Exams<'a> {
    /// The variants' problems.
    pub exams: &'a [Vec<Generated>],
    /// The topics, in the order the problems cycle through them.
    pub topics: &'a [Topic],
    /// The relative tolerance r (> 0).
    pub rel: f64,
}

impl Exams<'_> {
    /// The number of problems of each variant.
    pub fn count(&self) -> usize {
        self.exams.first().map_or(0, Vec::len)
    }

    /// The category of problem i (from 0): `$course$/grafika/<topic>/<NN>`.
    pub fn category(&self, i: usize) -> String {
        let topic = self.topics[i % self.topics.len().max(1)];
        format!("$course$/grafika/{}/{:02}", topics_name(&[topic]), i + 1)
    }
}

/// The whole Moodle XML file.
pub fn moodle_xml(e: &Exams, st: &Style) -> String {
    let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n");
    for i in 0..e.count() {
        let _ = write!(
            s,
            "  <question type=\"category\">\n    <category>\n      <text>{}</text>\n    </category>\n    <info format=\"html\">\n      <text></text>\n    </info>\n  </question>\n",
            xml_text(&e.category(i))
        );
        for (v, exam) in e.exams.iter().enumerate() {
            if let Some(g) = exam.get(i) {
                s.push_str(&cloze_question(g, i, v, e.rel, st));
            }
        }
    }
    s.push_str("</quiz>\n");
    s
}

/// One Cloze question.
fn cloze_question(g: &Generated, i: usize, v: usize, rel: f64, st: &Style) -> String {
    let asked = blanks(g, rel);
    let mut text = intro_html(g, rel, st.lang);
    for a in &asked {
        let mut next = a.blanks.iter().map(|b| cloze_blank(b, st.lang));
        let shape = shape_html(&a.value, &mut || next.next().unwrap_or_default());
        let _ = write!(text, "<p>{} = {shape}</p>", esc_text(&a.key));
    }
    format!(
        "  <question type=\"cloze\">\n    <name>\n      <text>{}</text>\n    </name>\n    <questiontext format=\"html\">\n      <text>{}</text>\n    </questiontext>\n    <generalfeedback format=\"html\">\n      <text>{}</text>\n    </generalfeedback>\n    <penalty>0.3333333</penalty>\n    <hidden>0</hidden>\n  </question>\n",
        xml_text(&question_name(g, i, v, st.lang)),
        cdata(&text),
        cdata(&solution_html(&g.report, &asked, st)),
    )
}

/// The question's name: `Problem 01, variant 03: <title>`.
pub fn question_name(g: &Generated, i: usize, v: usize, lang: Lang) -> String {
    format!(
        "{} {:02}, {} {:02}: {}",
        tr(lang, "Problem", "Soal"),
        i + 1,
        tr(lang, "variant", "varian"),
        v + 1,
        words(&g.title, lang)
    )
}

/// The statement and how to type the answers, as HTML.
pub fn intro_html(g: &Generated, rel: f64, lang: Lang) -> String {
    let statement = words(&g.statement, lang);
    format!(
        "<p>{}</p><p><i>{}</i></p>",
        esc_text(statement.trim()),
        esc(&instructions(rel, lang))
    )
}

/// How to type the answers: significant figures for the tolerance, the
/// outcode and status conventions.
pub fn instructions(rel: f64, lang: Lang) -> String {
    let figs = sig_figs(rel);
    let mut pct = number(rel * 100.0);
    if lang == Lang::Id {
        pct = pct.replace('.', ",");
    }
    match lang {
        Lang::En => format!(
            "Type numbers as decimals with at least {figs} significant figures (a number within {pct} % of the key's is right); outcodes as six bits, bit 1 rightmost (e.g. 000010); the clipping status as accepted, rejected or clipped, and the segment that is left as none when there is none."
        ),
        Lang::Id => format!(
            "Tulis bilangan sebagai desimal dengan sedikitnya {figs} angka penting (bilangan yang berselisih paling banyak {pct} % dari kunci dinilai benar); outcode sebagai enam bit, bit 1 paling kanan (mis. 000010); status kliping sebagai accepted, rejected atau clipped, dan sisa segmen sebagai none bila tidak ada."
        ),
    }
}

/// The significant figures that keep a rounded decimal within the relative
/// tolerance r: n figures err by at most 5·10⁻ⁿ relatively, so n = ⌈log₁₀(5/r)⌉.
pub fn sig_figs(rel: f64) -> u32 {
    (5.0 / rel).log10().ceil().clamp(1.0, 17.0) as u32
}

/// A value's shape with its leaves drawn by `leaf`: a number or code, a
/// vector `(a, b, c)`, a matrix as a table, a list of points, named values.
pub fn shape_html(v: &Val, leaf: &mut dyn FnMut() -> String) -> String {
    match v {
        Val::List(rows) if is_square_matrix(rows) => {
            let mut s = String::from("<table>");
            for r in rows {
                s.push_str("<tr>");
                if let Val::List(cells) = r {
                    for c in cells {
                        let _ = write!(s, "<td>{}</td>", shape_html(c, leaf));
                    }
                }
                s.push_str("</tr>");
            }
            s + "</table>"
        }
        Val::List(items) => {
            let parts: Vec<String> = items.iter().map(|x| shape_html(x, leaf)).collect();
            format!("({})", parts.join(", "))
        }
        Val::Map(kv) => {
            let parts: Vec<String> = kv
                .iter()
                .map(|(k, x)| format!("{} = {}", esc(k), shape_html(x, leaf)))
                .collect();
            parts.join("; ")
        }
        _ => leaf(),
    }
}

/// Whether rows are those of a square matrix of numbers (a segment, two
/// points, is a list of points instead).
fn is_square_matrix(rows: &[Val]) -> bool {
    rows.len() > 2
        && rows.iter().all(|r| {
            matches!(r, Val::List(c) if c.len() == rows.len() && c.iter().all(|x| matches!(x, Val::Num(_))))
        })
}

/// The labels of a value's leaves, depth first: `view.u[1]`, `clip.segment[2][3]`.
pub fn leaf_labels(key: &str, v: &Val) -> Vec<String> {
    match v {
        Val::List(items) => items
            .iter()
            .enumerate()
            .flat_map(|(k, x)| leaf_labels(&format!("{key}[{}]", k + 1), x))
            .collect(),
        Val::Map(kv) => kv
            .iter()
            .flat_map(|(k, x)| leaf_labels(&format!("{key}.{k}"), x))
            .collect(),
        _ => vec![key.to_string()],
    }
}

/// One blank in Cloze syntax.
fn cloze_blank(b: &Blank, lang: Lang) -> String {
    let kind = match b.value {
        Typed::Num(_) => "NUMERICAL",
        Typed::Text(_) => "SHORTANSWER",
    };
    let mut s = format!("{{1:{kind}:={}", cloze_answer(&b.value, b.tolerance));
    for w in &b.wrong {
        let _ = write!(
            s,
            "~%0%{}#{}",
            cloze_answer(&w.value, w.tolerance),
            cloze_escape(&esc(&feedback(w, lang)))
        );
    }
    s + "}"
}

/// An answer in a blank: `x:t` for a number, the code for a text.
fn cloze_answer(v: &Typed, t: f64) -> String {
    match v {
        Typed::Num(x) => format!("{}:{}", number(*x), tolerance_text(t)),
        Typed::Text(s) => cloze_escape(s),
    }
}

/// Text inside a blank: escaped once more for the decoding Moodle does, and
/// the characters that end a part of a blank as numeric entities.
pub fn cloze_escape(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '{' => out.push_str("&#123;"),
            '}' => out.push_str("&#125;"),
            '~' => out.push_str("&#126;"),
            '#' => out.push_str("&#35;"),
            '\\' => out.push_str("&#92;"),
            _ => out.push(c),
        }
    }
    out
}

/// The feedback of a wrong value: the mistakes that give it.
pub fn feedback(w: &Wrong, lang: Lang) -> String {
    let names: Vec<&str> = w.mistakes.iter().map(|m| mistake_text(m, lang)).collect();
    format!(
        "{}{}",
        tr(lang, "Known mistake: ", "Kesalahan yang dikenal: "),
        names.join(tr(lang, "; or: ", "; atau: "))
    )
}

/// The general feedback: the answers, then the worked solution, as HTML.
pub fn solution_html(r: &Report, asked: &[Asked], st: &Style) -> String {
    let mut s = format!("<h3>{}</h3><ul>", tr(st.lang, "Answers", "Jawaban"));
    for a in asked {
        let line = esc(&st.named("", &a.key, &a.value));
        if line.contains('\n') {
            let _ = write!(s, "<li><pre>{line}</pre></li>");
        } else {
            let _ = write!(s, "<li>{line}</li>");
        }
    }
    let _ = write!(
        s,
        "</ul><h3>{}</h3>",
        tr(st.lang, "Worked solution", "Penyelesaian")
    );
    let mut section: Option<&crate::msg::Msg> = None;
    for (k, step) in r.steps.iter().enumerate() {
        if step.section.as_ref() != section {
            section = step.section.as_ref();
            if let Some(sec) = section {
                let _ = write!(s, "<h4>{}</h4>", esc(&st.w(sec)));
            }
        }
        let mut lines: Vec<String> = Vec::new();
        if !step.formula.is_empty() {
            lines.push(st.w(&step.formula));
        }
        lines.extend(step.values.iter().map(|(n, v)| st.named("", n, v)));
        lines.extend(step.result.iter().map(|(n, v)| st.named("⇒ ", n, v)));
        if let Some(n) = &step.note {
            lines.push(format!("({})", st.w(n)));
        }
        let _ = write!(
            s,
            "<p><b>{} {}. {}</b></p><pre>{}</pre>",
            tr(st.lang, "Step", "Langkah"),
            k + 1,
            esc(&st.w(&step.title)),
            esc(&lines.join("\n"))
        );
    }
    s
}

/// HTML (and XML) text: `&`, `<`, `>` escaped, control characters shown
/// ([`crate::report::escape::xml_text`]).
pub fn esc(s: &str) -> String {
    crate::report::escape::xml_text(s)
}

/// Question text: HTML-escaped, and braces as entities, so that no text
/// reads as a blank `{1:NUMERICAL:…}`.
pub fn esc_text(s: &str) -> String {
    esc(s).replace('{', "&#123;").replace('}', "&#125;")
}

/// XML element text (the same escapes; quotes need none outside attributes).
fn xml_text(s: &str) -> String {
    esc(s)
}

/// A CDATA section holding `s`; a `]]>` inside is split across two sections.
/// Control characters are shown as `\u{XX}` (XML allows none, CDATA or not).
pub fn cdata(s: &str) -> String {
    let s = crate::report::escape::visible(s);
    format!("<![CDATA[{}]]>", s.replace("]]>", "]]]]><![CDATA[>"))
}

/// A number for Moodle: a plain ASCII decimal (no exponent, `.` as the
/// decimal mark) with 12 significant figures.
pub fn number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let (digits, exp) = sci(x.abs(), 11);
    plain(x < 0.0, &digits, exp)
}

/// A tolerance t as a plain decimal rounded up to two significant figures,
/// so that it is never below t (but for rounding noise of 1e-9 relative) and
/// never 0 for t > 0.
pub fn tolerance_text(t: f64) -> String {
    if !(t > 0.0 && t.is_finite()) {
        return "0".into();
    }
    let (digits, exp) = sci(t, 1);
    let shown: f64 = format!("{digits}e{exp}").parse().unwrap_or(0.0);
    // (rounding noise of the value, a relative 1e-9, does not round up)
    if shown >= t * (1.0 - 1e-9) {
        return plain(false, &digits, exp);
    }
    let up = digits.parse::<u64>().unwrap_or(0) + 1;
    plain(false, &up.to_string(), exp)
}

/// x > 0 as an integer of 1 + `after` digits and the power of ten it is
/// multiplied by: x ≈ digits·10^exp.
fn sci(x: f64, after: usize) -> (String, i32) {
    let s = format!("{x:.after$e}");
    let (mant, e) = s.split_once('e').unwrap_or((&s, "0"));
    let e: i32 = e.parse().unwrap_or(0);
    (mant.replace('.', ""), e - after as i32)
}

/// The plain decimal of ±digits·10^exp, without trailing zeros.
fn plain(neg: bool, digits: &str, exp: i32) -> String {
    let mut s = if exp >= 0 {
        format!("{digits}{}", "0".repeat(exp as usize))
    } else {
        let k = (-exp) as usize;
        let padded = format!(
            "{}{digits}",
            "0".repeat((k + 1).saturating_sub(digits.len()))
        );
        let (int, frac) = padded.split_at(padded.len() - k);
        let frac = frac.trim_end_matches('0');
        if frac.is_empty() {
            int.to_string()
        } else {
            format!("{int}.{frac}")
        }
    };
    if neg && s.chars().any(|c| c != '0' && c != '.') {
        s.insert(0, '-');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_plain_decimals() {
        assert_eq!(number(0.8), "0.8");
        assert_eq!(number(-0.6), "-0.6");
        assert_eq!(number(200.0), "200");
        assert_eq!(number(-2f64.sqrt() / 60.0), "-0.0235702260396");
        assert_eq!(number(1e-20), "0.00000000000000000001");
        assert_eq!(number(0.0), "0");
    }

    #[test]
    fn tolerances_round_up_and_are_never_zero() {
        assert_eq!(tolerance_text(0.0008), "0.0008");
        // 2.357e-5 rounds to 2.4e-5 (up)
        assert_eq!(tolerance_text(2.3570226e-5), "0.000024");
        // 1.234e-3 would round down to 1.2e-3: written 1.3e-3
        assert_eq!(tolerance_text(1.234e-3), "0.0013");
        assert_eq!(tolerance_text(9.96e-3), "0.01");
        assert_eq!(tolerance_text(1e-30), format!("0.{}1", "0".repeat(29)));
        // 0.64 computed as 0.6400000000000001: 0.00064, not 0.00065
        assert_eq!(tolerance_text(1e-3 * (0.8 * 0.8)), "0.00064");
    }

    #[test]
    fn four_figures_for_a_tenth_of_a_percent() {
        assert_eq!(sig_figs(1e-3), 4);
        assert_eq!(sig_figs(1e-2), 3);
        assert_eq!(sig_figs(5e-3), 3);
    }

    #[test]
    fn cdata_splits_its_end_marker() {
        assert_eq!(cdata("a]]>b"), "<![CDATA[a]]]]><![CDATA[>b]]>");
    }

    #[test]
    fn blank_delimiters_become_entities() {
        assert_eq!(
            cloze_escape("a}b~c#d{e\\"),
            "a&#125;b&#126;c&#35;d&#123;e&#92;"
        );
        assert_eq!(cloze_escape("&lt;"), "&amp;lt;");
    }
}
