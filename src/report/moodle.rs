//! Exams as Moodle XML: one Cloze (`multianswer`) question per problem and
//! variant, the variants of problem NN in the category
//! `$course$/grafika/<topic>/<NN>` (written before its questions), so that a
//! quiz can draw one variant per student ("Add a random question").
//!
//! The writer only writes: the blanks (values, tolerances, mistaken values)
//! are the tutor's ([`crate::tutor::generate::quiz`]), the figures the
//! figure module's (`report::figure`). Each number is a NUMERICAL blank
//! `{1:NUMERICAL:=x:t#…~%0%w:t'#feedback}`, each 0 % answer's feedback
//! naming the catalog mistakes that give it; outcodes and the clipping
//! status are SHORTANSWER blanks. The instruction line says how to type:
//! significant figures, the decimal mark ([`Decimal`]: Moodle reads a
//! typed number by its interface language's mark), half a pixel for pixel
//! positions. The general feedback holds the answers, the problem's
//! figures (SVG files embedded as Moodle exports them, `<file
//! encoding="base64">` referred to as `@@PLUGINFILE@@/name`) and the worked
//! solution, its lines wrapped to [`WIDTH`] characters.
//!
//! Escaping, in the order Moodle undoes it: text is HTML-escaped (`&`, `<`,
//! `>`); inside a blank, Moodle decodes HTML entities once before storing the
//! feedback as HTML, so the feedback is escaped twice, and the characters
//! that end a part of a blank (`}`, `~`, `#`, and `{`, `\`) are written as
//! numeric entities (`&#125;` …), which the decoding turns back; the question
//! text and general feedback go into CDATA sections, a `]]>` inside split
//! across two sections.

use crate::msg::{DocWord as D, Msg, QuizWord as Q};
use crate::report::figure::{drawings::drawings, svg::to_svg};
use crate::report::lang::{Lang, NumStyle};
use crate::report::mistakes::mistake_text;
use crate::report::words::{self as said, words};
use crate::report::Style;
use crate::stages::trace::Val;
use crate::tutor::generate::quiz::{Blank, Question, Quiz, Typed, Typing, Wrong};
use crate::tutor::generate::{topics_name, Generated};
use base64::Engine as _;
use std::fmt::Write as _;

/// The widest line of the worked solution, in characters: a question in
/// review fits a 1100-px window with the course's side panels open.
pub const WIDTH: usize = 72;

pub use crate::msg::Decimal;

impl Decimal {
    /// How the quiz writes its numbers for students: with the mark they
    /// are told to type.
    pub fn nums(self) -> NumStyle {
        match self {
            Decimal::Point => NumStyle::POINT,
            Decimal::Comma => NumStyle::COMMA,
        }
    }
}

/// How a quiz is written: the words' style and the decimal mark to type.
#[derive(Clone, Debug)]
pub struct Written<'a> {
    /// Language, digits of the worked solution.
    pub style: &'a Style,
    /// The mark the instruction line tells students to type.
    pub decimal: Decimal,
}

/// The category of problem i (from 0): `$course$/grafika/<topic>/<NN>`.
pub fn category(q: &Quiz, i: usize) -> String {
    format!(
        "$course$/grafika/{}/{:02}",
        topics_name(&[q.topic(i)]),
        i + 1
    )
}

/// The whole Moodle XML file.
pub fn moodle_xml(q: &Quiz, w: &Written) -> String {
    let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n");
    for i in 0..q.count() {
        let _ = write!(
            s,
            "  <question type=\"category\">\n    <category>\n      <text>{}</text>\n    </category>\n    <info format=\"html\">\n      <text></text>\n    </info>\n  </question>\n",
            xml_text(&category(q, i))
        );
        for (v, exam) in q.variants.iter().enumerate() {
            if let Some(question) = exam.get(i) {
                s.push_str(&cloze_question(question, (i, v), q, w));
            }
        }
    }
    s.push_str("</quiz>\n");
    s
}

/// One Cloze question: problem i of variant v.
fn cloze_question(question: &Question, (i, v): (usize, usize), q: &Quiz, w: &Written) -> String {
    let lang = w.style.lang;
    let mut text = intro_html(question, q, w);
    for a in &question.asked {
        let mut next = a.blanks.iter().map(|b| cloze_blank(b, lang));
        let shape = shape_html(&a.value, &mut || next.next().unwrap_or_default());
        let _ = write!(text, "<p>{} = {shape}</p>", esc_text(&a.key.to_string()));
    }
    let (figures, files) = embedded_figures(&question.problem, w.style);
    format!(
        "  <question type=\"cloze\">\n    <name>\n      <text>{}</text>\n    </name>\n    <questiontext format=\"html\">\n      <text>{}</text>\n    </questiontext>\n    <generalfeedback format=\"html\">\n      <text>{}</text>\n{files}    </generalfeedback>\n    <penalty>0.3333333</penalty>\n    <hidden>0</hidden>\n  </question>\n",
        xml_text(&question_name(&question.problem, i, v, lang)),
        cdata(&text),
        cdata(&solution_html(question, &figures, w.style)),
    )
}

/// The problem's figures as images of files in the question (`<img
/// src="@@PLUGINFILE@@/figure-1-view.svg">`, named as `solve --figure`
/// names its files), and the `<file>` elements that carry those files.
fn embedded_figures(g: &Generated, st: &Style) -> (String, String) {
    let mut html = String::new();
    let mut files = String::new();
    for (k, d) in drawings(&g.report, st).iter().enumerate() {
        let name = format!("figure-{}-{}.svg", k + 1, d.part);
        let title = esc(&d.title());
        let _ = write!(
            html,
            "<p><img src=\"@@PLUGINFILE@@/{name}\" alt=\"{}\" style=\"max-width: 100%; height: auto;\"></p><p><i>{title}</i></p>",
            title.replace('"', "&quot;")
        );
        let b64 = base64::engine::general_purpose::STANDARD.encode(to_svg(d));
        let _ = writeln!(
            files,
            "      <file name=\"{name}\" path=\"/\" encoding=\"base64\">{b64}</file>"
        );
    }
    let heading = said::of(st.lang).doc(&D::Figures);
    let html = if html.is_empty() {
        html
    } else {
        format!("<h3>{heading}</h3>{html}")
    };
    (html, files)
}

/// The question's name: `Problem 01, variant 03: <title>`.
pub fn question_name(g: &Generated, i: usize, v: usize, lang: Lang) -> String {
    let w = |k: D| said::of(lang).doc(&k);
    format!(
        "{} {:02}, {} {:02}: {}",
        w(D::Problem),
        i + 1,
        w(D::Variant),
        v + 1,
        words(&g.title, lang)
    )
}

/// The statement and how to type the answers, as HTML.
pub fn intro_html(question: &Question, q: &Quiz, w: &Written) -> String {
    let lang = w.style.lang;
    let statement = match &question.problem.statement {
        Msg::Statement(s) => crate::report::words::of(lang).statement(s, w.decimal.nums()),
        other => words(other, lang),
    };
    format!(
        "<p>{}</p><p><i>{}</i></p>",
        esc_text(statement.trim()),
        esc(&instructions(&question.typing, q, lang, w.decimal))
    )
}

/// How to type the answers: decimals (never exact forms) with the
/// significant figures of the tolerance and the decimal mark of the site,
/// half a pixel for pixel positions; outcodes and the clipping status where
/// the question asks for them.
pub fn instructions(kinds: &Typing, q: &Quiz, lang: Lang, mark: Decimal) -> String {
    let w = |k: Q| said::of(lang).quiz(&k);
    let mut s = w(Q::Instructions {
        figures: q.figures,
        // the tolerance as students type numbers
        pct: mark.nums().number(&number(q.rel * 100.0)),
        mark,
        pixels: kinds.pixels,
    });
    if kinds.outcodes {
        s.push(' ');
        s.push_str(&w(Q::TypeOutcodes));
    }
    if kinds.status {
        s.push(' ');
        s.push_str(&w(Q::TypeStatus));
    }
    s
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
    let names: Vec<&str> = w.mistakes.iter().map(|m| mistake_text(*m, lang)).collect();
    let w = |k: Q| said::of(lang).quiz(&k);
    format!("{}{}", w(Q::KnownMistake), names.join(&w(Q::OrMistake)))
}

/// The general feedback: the answers, the figures (HTML given), then the
/// worked solution, its sections numbered from 1 within the question and
/// its lines wrapped to [`WIDTH`] characters.
pub fn solution_html(question: &Question, figures: &str, st: &Style) -> String {
    let w = |k: D| said::of(st.lang).doc(&k);
    let mut s = format!("<h3>{}</h3><ul>", w(D::Answers));
    for a in &question.asked {
        // one line flows in the list; a matrix keeps its lines
        let line = esc(&st.named("", &a.key.to_string(), &a.value));
        if line.contains('\n') {
            let _ = write!(s, "<li><pre>{line}</pre></li>");
        } else {
            let _ = write!(s, "<li>{line}</li>");
        }
    }
    let _ = write!(s, "</ul>{figures}<h3>{}</h3>", w(D::WorkedSolution));
    let mut section: Option<&crate::msg::Msg> = None;
    let mut parts = 0;
    for (k, step) in question.problem.report.steps.iter().enumerate() {
        if step.section.as_ref() != section {
            section = step.section.as_ref();
            if let Some(sec) = section {
                parts += 1;
                let _ = write!(
                    s,
                    "<h4>{}</h4>",
                    esc(&part_heading(parts, &st.w(sec), st.lang))
                );
            }
        }
        let _ = write!(
            s,
            "<p><b>{} {}. {}</b></p><pre>{}</pre>",
            w(D::Step),
            k + 1,
            esc(&st.w(&step.title)),
            esc(&wrap(st.step_body(step).trim_end()))
        );
    }
    s
}

/// A section of the worked solution as a part of the question, numbered
/// from 1: `Part 1: window and clipping` for `Step 4: window and clipping`
/// (the pipeline's step in the text means nothing in a question that asks
/// only for the window).
pub fn part_heading(k: usize, section: &str, lang: Lang) -> String {
    // "Step 4: …", "Tahap 4: …": a word and a number before the colon
    let name = section
        .split_once(": ")
        .filter(|(head, _)| {
            let mut w = head.split(' ');
            let (word, num, rest) = (w.next(), w.next(), w.next());
            word.is_some() && num.is_some_and(|n| n.parse::<u32>().is_ok()) && rest.is_none()
        })
        .map_or(section, |(_, name)| name);
    format!("{} {k}: {name}", said::of(lang).quiz(&Q::Part))
}

/// Text wrapped to [`WIDTH`] characters, each wrapped line's continuation
/// indented by two spaces more than the line.
pub fn wrap(text: &str) -> String {
    let mut out: Vec<String> = Vec::new();
    for line in text.lines() {
        let indent = " ".repeat(line.len() - line.trim_start().len() + 2);
        let opts = textwrap::Options::new(WIDTH).subsequent_indent(&indent);
        out.extend(
            textwrap::wrap(line, opts)
                .into_iter()
                .map(|l| l.into_owned()),
        );
    }
    out.join("\n")
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

/// A tolerance t as a plain decimal rounded up to three significant
/// figures (at most 1 % over t), so that it is never below t (but for
/// rounding noise of 1e-9 relative) and never 0 for t > 0.
pub fn tolerance_text(t: f64) -> String {
    if !(t > 0.0 && t.is_finite()) {
        return "0".into();
    }
    let (digits, exp) = sci(t, 2);
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
        // 2.3570e-5 rounds to 2.36e-5 (up)
        assert_eq!(tolerance_text(2.3570226e-5), "0.0000236");
        // 1.2341e-3 would round down to 1.23e-3: written 1.24e-3
        assert_eq!(tolerance_text(1.2341e-3), "0.00124");
        assert_eq!(tolerance_text(9.996e-3), "0.01");
        assert_eq!(tolerance_text(1e-30), format!("0.{}1", "0".repeat(29)));
        // 0.64 computed as 0.6400000000000001: 0.00064, not 0.000641
        assert_eq!(tolerance_text(1e-3 * (0.8 * 0.8)), "0.00064");
        // half a pixel widened by a rounding of 0.003 px
        assert_eq!(tolerance_text(0.503), "0.503");
    }

    #[test]
    fn sections_are_parts_numbered_within_the_question() {
        let en = part_heading(1, "Step 4: window and clipping", Lang::En);
        assert_eq!(en, "Part 1: window and clipping");
        let id = part_heading(2, "Tahap 4: bidang pandang dan clipping", Lang::Id);
        assert_eq!(id, "Bagian 2: bidang pandang dan clipping");
        // a section without a step number keeps its whole name
        let light = part_heading(3, "Lighting: Phong", Lang::En);
        assert_eq!(light, "Part 3: Lighting: Phong");
    }

    #[test]
    fn long_lines_wrap_with_a_hanging_indent() {
        let legend = "bit 1 x<xmin (left) · bit 2 x>xmax (right) · bit 3 y<ymin (bottom) · bit 4 y>ymax (top) · bit 5 z<zmin (front) · bit 6 z>zmax (back)";
        let w = wrap(&format!("short\n{legend}"));
        let lines: Vec<&str> = w.lines().collect();
        assert_eq!(lines[0], "short");
        assert!(lines.len() >= 3, "{w}");
        assert!(lines.iter().all(|l| l.chars().count() <= WIDTH), "{w}");
        assert!(
            lines[2].starts_with("  ") && !lines[2].starts_with("   "),
            "{w}"
        );
        // no word is lost or split
        let words = |s: &str| s.split_whitespace().map(String::from).collect::<Vec<_>>();
        assert_eq!(words(&w)[1..], words(legend)[..]);
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
