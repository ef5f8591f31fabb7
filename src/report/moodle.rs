//! Exams as Moodle XML: one Cloze (`multianswer`) question per problem and
//! variant, the variants of problem NN in the category
//! `$course$/grafika/<topic>/<NN>` (written before its questions), so that a
//! quiz can draw one variant per student ("Add a random question").
//!
//! The writer only writes: the blanks (values, tolerances, mistaken values)
//! are the tutor's ([`crate::tutor::generate::quiz`]), the figures the
//! figure module's (`report::figure`). Each number is a NUMERICAL blank
//! `{W:NUMERICAL:=x:t#…~%0%w:t'#feedback}`, each 0 % answer's feedback
//! naming the catalog mistakes that give it; outcodes and the clipping
//! status are SHORTANSWER blanks. The instruction line says how to type:
//! significant figures, the decimal mark ([`Decimal`]: Moodle reads a
//! typed number by its interface language's mark), half a pixel for pixel
//! positions. Each answer's blanks are labelled as the steps name its value
//! in the quiz's language ([`blank_label`](crate::report::words::keys::KeyWords::blank_label): `n`, `A'`, `piksel
//! A`, `cos α`), never by a JSON key. A status or a missing segment is
//! right in the quiz language's words and in the English codes (`di-clip`
//! or `clipped`, `tidak ada` or `none`).
//!
//! Marks: the statement ends with the question's marks in the scheme of
//! `check` (`(4 marks)`), and each blank weighs W so that an answer's
//! blanks together weigh its share of those marks ([`Question::weights`]).
//! Moodle reads a Cloze question's default mark as the sum of its blanks'
//! weights (it ignores `<defaultgrade>`), and gives a random question's
//! slot 1 mark: the proportions are the scheme's, the quiz's maximum mark
//! of each slot is the lecturer's to set to the stated marks.
//!
//! One decimal mark for the whole quiz: the statement, the instruction,
//! the answers, the worked solution and the figures write their numbers
//! with the mark of `--decimal` ([`Written::new`] gives the style its
//! [`NumStyle`]), and a comma-decimal quiz separates a vector's blanks
//! with `;` as its statement separates the components.
//!
//! The general feedback holds the answers, the problem's figures (SVG files
//! embedded as Moodle exports them, `<file encoding="base64">` referred to
//! as `@@PLUGINFILE@@/name`) and the worked solution. The writer breaks no
//! line: each line of a step is a block the browser wraps at the width of
//! the question, with its indentation and a hanging indent ([`body_html`]),
//! and a matrix keeps its lines whole in a block that scrolls rather than
//! wraps. Every number in the feedback is one Moodle reads back as written
//! when a student types it: a minus is the ASCII `-` (Moodle reads
//! `−0.5` as no number and `1.6e−10` as 1.6), see [`typeable`].
//!
//! Escaping, in the order Moodle undoes it: text is HTML-escaped (`&`, `<`,
//! `>`); inside a blank, Moodle decodes HTML entities once before storing the
//! feedback as HTML, so the feedback is escaped twice, and the characters
//! that end a part of a blank (`}`, `~`, `#`, and `{`, `\`) are written as
//! numeric entities (`&#125;` …), which the decoding turns back; the question
//! text and general feedback go into CDATA sections, a `]]>` inside split
//! across two sections.

use crate::msg::{DocWord as D, QuizWord as Q};
use crate::report::figure::{drawings::drawings, svg::to_svg};
use crate::report::lang::{Lang, NumStyle};
use crate::report::mistakes::mistake_text;
use crate::report::quizfile::{pack, Frame, Unit};
use crate::report::words::{self as said, words};
use crate::report::Style;
use crate::stages::trace::Val;
use crate::tutor::generate::quiz::{Blank, Question, Quiz, Typed, Typing, Wrong};
use crate::tutor::generate::{topics_name, Generated};
use crate::tutor::key::Key;
use base64::Engine as _;
use std::fmt::Write as _;

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
#[derive(Clone, Copy, Debug)]
pub struct Written {
    /// Language, digits of the worked solution, and the numbers written
    /// with the decimal mark to type.
    pub style: Style,
    /// The mark the instruction line tells students to type.
    pub decimal: Decimal,
}

impl Written {
    /// A quiz in `style`'s language and digits whose every number is
    /// written with the mark `decimal` (one decimal mark for the exam).
    pub fn new(style: &Style, decimal: Decimal) -> Written {
        Written {
            style: style.with_nums(decimal.nums()),
            decimal,
        }
    }
}

/// The label of an answer's blanks in `lang` ([`blank_label`](crate::report::words::keys::KeyWords::blank_label)).
pub fn label(key: &Key, lang: Lang) -> String {
    said::of(lang).blank_label(key)
}

/// The category of problem i (from 0): `$course$/grafika/<topic>/<NN>`.
pub fn category(q: &Quiz, i: usize) -> String {
    format!(
        "$course$/grafika/{}/{:02}",
        topics_name(&[q.topic(i)]),
        i + 1
    )
}

/// The frame of a Moodle XML file.
pub const XML: Frame = Frame {
    head: "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n",
    foot: "</quiz>\n",
};

/// The whole Moodle XML file.
pub fn moodle_xml(q: &Quiz, w: &Written) -> String {
    pack(&moodle_units(q, w), XML, None)
        .unwrap_or_default()
        .concat()
}

/// The questions of a Moodle XML file, each after its problem's category
/// ([`crate::report::quizfile`]).
pub fn moodle_units(q: &Quiz, w: &Written) -> Vec<Unit> {
    let mut units = Vec::new();
    for i in 0..q.count() {
        let cat = format!(
            "  <question type=\"category\">\n    <category>\n      <text>{}</text>\n    </category>\n    <info format=\"html\">\n      <text></text>\n    </info>\n  </question>\n",
            xml_text(&category(q, i))
        );
        for (v, exam) in q.variants.iter().enumerate() {
            if let Some(question) = exam.get(i) {
                units.push(Unit {
                    category: cat.clone(),
                    text: cloze_question(question, (i, v), q, w),
                    name: question_name(&question.problem, i, v, w.style.lang),
                });
            }
        }
    }
    units
}

/// One Cloze question: problem i of variant v.
fn cloze_question(question: &Question, (i, v): (usize, usize), q: &Quiz, w: &Written) -> String {
    let lang = w.style.lang;
    let mut text = intro_html(question, q, w);
    let sep = w.style.nums().sep;
    for (a, weight) in question.asked.iter().zip(question.weights()) {
        let mut next = a.blanks.iter().map(|b| cloze_blank(b, weight, lang));
        let shape = shape_html(&a.value, sep, &mut || next.next().unwrap_or_default());
        let _ = write!(text, "<p>{} = {shape}</p>", esc_text(&label(&a.key, lang)));
    }
    let (figures, files) = embedded_figures(&question.problem, &w.style);
    format!(
        "  <question type=\"cloze\">\n    <name>\n      <text>{}</text>\n    </name>\n    <questiontext format=\"html\">\n      <text>{}</text>\n    </questiontext>\n    <generalfeedback format=\"html\">\n      <text>{}</text>\n{files}    </generalfeedback>\n    <penalty>0.3333333</penalty>\n    <hidden>0</hidden>\n  </question>\n",
        xml_text(&question_name(&question.problem, i, v, lang)),
        cdata(&text),
        cdata(&solution_html(question, &figures, &w.style)),
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

/// The statement with its marks, and how to type the answers, as HTML.
pub fn intro_html(question: &Question, q: &Quiz, w: &Written) -> String {
    let lang = w.style.lang;
    let statement = w.style.w(&question.problem.statement);
    let marks = w.style.doc(D::Marks(question.marks()));
    format!(
        "<p>{} {marks}</p><p><i>{}</i></p>",
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
        pct: number_in(q.rel * 100.0, mark.nums().mark),
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
/// vector `(a, b, c)` (its components parted by `sep`, `, ` or `; ` as the
/// quiz's numbers are written), a matrix as a table, a list of points,
/// named values.
pub fn shape_html(v: &Val, sep: &str, leaf: &mut dyn FnMut() -> String) -> String {
    match v {
        Val::List(rows) if is_square_matrix(rows) => {
            let mut s = String::from("<table>");
            for r in rows {
                s.push_str("<tr>");
                if let Val::List(cells) = r {
                    for c in cells {
                        let _ = write!(s, "<td>{}</td>", shape_html(c, sep, leaf));
                    }
                }
                s.push_str("</tr>");
            }
            s + "</table>"
        }
        Val::List(items) => {
            let parts: Vec<String> = items.iter().map(|x| shape_html(x, sep, leaf)).collect();
            format!("({})", parts.join(sep))
        }
        Val::Map(kv) => {
            let parts: Vec<String> = kv
                .iter()
                .map(|(k, x)| format!("{} = {}", esc(k), shape_html(x, sep, leaf)))
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

/// One blank in Cloze syntax, of `weight` ([`Question::weights`]): the
/// right answers (a word in each of its spellings, [`spellings`]), then
/// each mistaken value at 0 % with its feedback.
fn cloze_blank(b: &Blank, weight: u32, lang: Lang) -> String {
    let kind = match b.value {
        Typed::Num(_) => "NUMERICAL",
        Typed::Text(_) => "SHORTANSWER",
    };
    let right: Vec<String> = cloze_answers(&b.value, b.tolerance, lang)
        .into_iter()
        .map(|a| format!("={a}"))
        .collect();
    let mut s = format!("{{{weight}:{kind}:{}", right.join("~"));
    for w in &b.wrong {
        let fb = cloze_escape(&esc(&feedback(w, lang)));
        for a in cloze_answers(&w.value, w.tolerance, lang) {
            let _ = write!(s, "~%0%{a}#{fb}");
        }
    }
    s + "}"
}

/// A value's answers in a blank: `x:t` for a number, each spelling of a
/// word.
fn cloze_answers(v: &Typed, t: f64, lang: Lang) -> Vec<String> {
    match v {
        Typed::Num(x) => vec![format!("{}:{}", number(*x), tolerance_text(t))],
        Typed::Text(s) => spellings(s, lang).iter().map(|w| cloze_escape(w)).collect(),
    }
}

/// The spellings a blank takes for a word (a status's code, `none`, an
/// outcode): the quiz language's word first (the answer Moodle shows as
/// right), then the code when it differs (`di-clip`, `clipped`).
pub fn spellings(code: &str, lang: Lang) -> Vec<String> {
    let word = said::of(lang).quiz(&Q::Word(code.to_string()));
    if word == code {
        vec![word]
    } else {
        vec![word, code.to_string()]
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

/// The feedback of a wrong value: the mistakes that give it ([`typeable`]).
pub fn feedback(w: &Wrong, lang: Lang) -> String {
    let names: Vec<&str> = w.mistakes.iter().map(|m| mistake_text(*m, lang)).collect();
    let w = |k: Q| said::of(lang).quiz(&k);
    typeable(&format!(
        "{}{}",
        w(Q::KnownMistake),
        names.join(&w(Q::OrMistake))
    ))
}

/// Text a student may copy into a blank, written so that Moodle reads
/// each number in it as it is written: the minus sign `−` (U+2212) as the
/// ASCII `-`. Moodle's number reader takes only `-`: `−0.5` is no number
/// to it, and `1.587e−10` is read as 1.587 (the `e−10` taken for a unit).
pub fn typeable(s: &str) -> String {
    s.replace('\u{2212}', "-")
}

/// The general feedback: the answers, the figures (HTML given), then the
/// worked solution, its sections numbered from 1 within the question and
/// its lines laid out by [`body_html`]; every number [`typeable`].
pub fn solution_html(question: &Question, figures: &str, st: &Style) -> String {
    typeable(&solution(question, figures, st))
}

fn solution(question: &Question, figures: &str, st: &Style) -> String {
    let w = |k: D| said::of(st.lang).doc(&k);
    let mut s = format!("<h3>{}</h3><ul>", w(D::Answers));
    for a in &question.asked {
        // one line flows in the list; a matrix keeps its lines; a word is
        // the quiz language's (`ditolak`), as its blank shows it
        let name = label(&a.key, st.lang);
        let line = esc(&match &a.value {
            Val::Text(code) => format!("{name} = {}", spellings(code, st.lang)[0]),
            v => st.named("", &name, v),
        });
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
            "<p><b>{} {}. {}</b></p>{}",
            w(D::Step),
            k + 1,
            esc(&st.w(&step.title)),
            body_html(st.step_body(step).trim_end())
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

/// A step's lines as HTML that the browser lays out in the width it has,
/// in monospace: each line a block of its own, its indentation kept and,
/// where the browser wraps it, its continuation indented two characters
/// more; a matrix's lines (a table drawn with box characters, ┌ │ ├ └)
/// together in a block that never wraps and scrolls sideways in a narrow
/// window. The writer breaks no line.
pub fn body_html(body: &str) -> String {
    let mut out = String::from("<div style=\"font-family:monospace;white-space:pre-wrap\">");
    let mut table: Vec<&str> = Vec::new();
    let flush = |out: &mut String, table: &mut Vec<&str>| {
        if !table.is_empty() {
            let _ = write!(
                out,
                "<div style=\"white-space:pre;overflow-x:auto\">{}</div>",
                esc(&table.join("\n"))
            );
            table.clear();
        }
    };
    for line in body.lines() {
        let text = line.trim_start();
        if text.starts_with(['┌', '│', '├', '└']) {
            table.push(line);
            continue;
        }
        flush(&mut out, &mut table);
        let indent = line.chars().count() - text.chars().count();
        let _ = write!(
            out,
            "<div style=\"padding-left:{}ch;text-indent:-2ch\">{}</div>",
            indent + 2,
            esc(text)
        );
    }
    flush(&mut out, &mut table);
    out + "</div>"
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
    number_in(x, '.')
}

/// [`number`] with the decimal mark `mark` (a number in a quiz's words).
fn number_in(x: f64, mark: char) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let (digits, exp) = sci(x.abs(), 11);
    plain(x < 0.0, &digits, exp, mark)
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
        return plain(false, &digits, exp, '.');
    }
    let up = digits.parse::<u64>().unwrap_or(0) + 1;
    plain(false, &up.to_string(), exp, '.')
}

/// x > 0 as an integer of 1 + `after` digits and the power of ten it is
/// multiplied by: x ≈ digits·10^exp.
fn sci(x: f64, after: usize) -> (String, i32) {
    let s = format!("{x:.after$e}");
    let (mant, e) = s.split_once('e').unwrap_or((&s, "0"));
    let e: i32 = e.parse().unwrap_or(0);
    (mant.replace('.', ""), e - after as i32)
}

/// The plain decimal of ±digits·10^exp, without trailing zeros, with the
/// decimal mark `mark`.
fn plain(neg: bool, digits: &str, exp: i32, mark: char) -> String {
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
            format!("{int}{mark}{frac}")
        }
    };
    if neg && s.chars().any(|c| c != '0' && c != mark) {
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
    fn a_step_is_laid_out_by_the_browser_and_a_matrix_kept_whole() {
        let legend = "bit 1 x<xmin (left) · bit 2 x>xmax (right) · bit 3 y<ymin (bottom) · bit 4 y>ymax (top) · bit 5 z<zmin (front) · bit 6 z>zmax (back)";
        let body = format!(
            "    {legend}\n  ⇒ V =\n      ┌───┬───┐\n      │ 1 ┆ 0 │\n      └───┴───┘\n    (a < b)"
        );
        let html = body_html(&body);
        // the long line is one block, unbroken, its 4 spaces of indent as
        // padding and a hanging indent of 2 more
        let shown = legend.replace('<', "&lt;").replace('>', "&gt;");
        let line = format!("<div style=\"padding-left:6ch;text-indent:-2ch\">{shown}</div>");
        assert!(html.contains(&line), "{html}");
        assert!(html.contains("padding-left:4ch;text-indent:-2ch\">⇒ V =</div>"));
        // the matrix's three lines together, as drawn, in a block that does
        // not wrap
        assert!(
            html.contains(
                "white-space:pre;overflow-x:auto\">      ┌───┬───┐\n      │ 1 ┆ 0 │\n      └───┴───┘</div>"
            ),
            "{html}"
        );
        assert!(html.contains("(a &lt; b)"));
        assert!(html.starts_with("<div") && html.ends_with("</div></div>"));
    }

    #[test]
    fn typed_back_every_number_reads_as_written() {
        assert_eq!(typeable("x = −0.5 ≈ 1.587e−10"), "x = -0.5 ≈ 1.587e-10");
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
