//! The HTML page of one calculator command or `solve`: the worked steps
//! (written by [`Doc::Html`](super::doc::Doc)), each part's figure under
//! its heading, the answer and the notes, put together from the pieces of
//! [`html`](super::html).

use super::doc::Doc;
use super::figure::xml_escape;
use super::html::{answers, figure, heading, named_answers, page};
use super::words::{self, keys};
use super::{mathml, Report, Style};
use crate::msg::{CheckWord, DocWord, Msg, Printed};
use crate::tutor::solution::{Asked, Compared, Comparison};

/// The drawing's part (`view`, `clip-2`, …) a section of `solve` shows.
fn part_of(section: &Msg) -> Option<String> {
    Some(match section {
        Msg::SecViewing => "view".into(),
        Msg::SecProjection => "project".into(),
        Msg::SecWindowClip | Msg::SecWindow => "window".into(),
        Msg::SecLineClip(None) => "clip".into(),
        Msg::SecLineClip(Some(k)) => format!("clip-{k}"),
        Msg::SecLighting => "shade".into(),
        _ => return None,
    })
}

/// The page of one calculator command or `solve`: the steps grouped by
/// part, each part's figure under its heading (figures of a report
/// without parts come first), the answer, notes and warnings. A figure is
/// (part, SVG, caption).
pub fn report_page(
    r: &Report,
    st: &Style,
    title: &str,
    figures: &[(String, String, String)],
) -> String {
    let mut body = String::new();
    if let Some((_, statement, asked)) = r.posed() {
        for p in statement.iter().chain([&st.w(&asked)]) {
            body.push_str(&format!("<p class=\"statement\">{}</p>\n", xml_escape(p)));
        }
    }
    for w in &r.warnings {
        body.push_str(&format!(
            "<p class=\"warning\">{}: {}</p>\n",
            st.doc(DocWord::Warning),
            xml_escape(&st.w(w))
        ));
    }
    let parts: Vec<String> = r
        .steps
        .iter()
        .filter_map(|s| s.section.as_ref().and_then(part_of))
        .collect();
    for (part, svg, caption) in figures {
        if !parts.contains(part) {
            body.push_str(&figure(svg, caption));
        }
    }
    let mut under = |sec: &Msg| -> String {
        let Some(part) = part_of(sec) else {
            return String::new();
        };
        figures
            .iter()
            .filter(|(p, ..)| *p == part)
            .map(|(_, svg, caption)| figure(svg, caption))
            .collect()
    };
    body.push_str(&Doc::Html.steps_with(r, st, &mut under));
    body.push_str(&heading(1, &r.answer_heading(st.lang)));
    body.push_str(&match &r.asked {
        Asked::Render(_) => named_answers(st, &r.answer_named(st.lang)),
        _ => answers(st, &r.answer()),
    });
    for n in r.notes(st) {
        body.push_str(&format!("<p class=\"note\">{}</p>\n", xml_escape(&n)));
    }
    if let Some(c) = &r.comparison {
        body.push_str(&comparison(c, st));
    }
    if !r.source_notes.is_empty() {
        body.push_str(&heading(2, &st.doc(DocWord::NotesOnSource)));
        let items: String = (r.source_notes.iter())
            .map(|n| format!("<li>{}</li>\n", xml_escape(n)))
            .collect();
        body.push_str(&format!("<ul>\n{items}</ul>\n"));
    }
    page(title, &body, st.lang.code())
}

/// The comparison with the answers a source printed, as a table: each
/// value named as the steps name it, what was printed, the correct value
/// and the verdict (agrees, a misprint, another convention, a rounding);
/// why, where the problem file says, in a row of its own beneath, so the
/// table keeps to the page's width.
fn comparison(c: &Comparison, st: &Style) -> String {
    let src = (c.source.clone()).unwrap_or_else(|| st.doc(DocWord::TheSource));
    let head = st.doc(DocWord::ComparedWith);
    let cols = [
        st.doc(DocWord::Value),
        st.doc(DocWord::Printed),
        st.doc(DocWord::CorrectValue),
        words::of(st.lang).check(&CheckWord::Verdict),
    ];
    let th: String = cols.iter().map(|c| format!("<th>{c}</th>")).collect();
    let rows: String = c.rows.iter().map(|row| compared_row(row, st)).collect();
    format!(
        "{}<table class=\"answers comparison\">\n<tr>{th}</tr>\n{rows}</table>\n",
        heading(2, &format!("{head} {src}"))
    )
}

/// One row of the comparison (two when the problem file says why); the
/// value's name is text, which wraps in the narrow first column (MathML
/// would not).
fn compared_row(row: &Compared, st: &Style) -> String {
    let name = keys::name_of(words::of(st.lang), &row.key);
    let correct = match (&row.computed, row.verdict()) {
        (Some(v), Printed::Differs(_) | Printed::NotComparable) => {
            mathml::inline(&st.val_inline(v))
        }
        _ => String::new(),
    };
    let class = if row.agrees == Some(true) {
        "agrees"
    } else {
        "differs"
    };
    let why = row.why.as_ref().map(|w| {
        format!(
            "<tr class=\"{class} why\"><td colspan=\"3\"><em>{}:</em> {}</td></tr>\n",
            st.doc(DocWord::Why),
            xml_escape(&st.w(w))
        )
    });
    format!(
        "<tr class=\"{class}\"><th rowspan=\"{}\" title=\"{}\">{}</th><td><code>{}</code></td><td>{correct}</td><td>{}</td></tr>\n{}",
        if why.is_some() { 2 } else { 1 },
        xml_escape(&row.key),
        xml_escape(&name),
        xml_escape(&st.printed(&row.printed)),
        xml_escape(&st.w(&Msg::Printed(row.verdict()))),
        why.unwrap_or_default()
    )
}
