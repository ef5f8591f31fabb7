//! The HTML page of one calculator command or `solve`: the worked steps
//! (written by [`Doc::Html`](super::doc::Doc)), each part's figure under
//! its heading, the answer and the notes, put together from the pieces of
//! [`html`](super::html).

use super::doc::Doc;
use super::figure::xml_escape;
use super::html::{answers, figure, heading, page};
use super::{Report, Style};
use crate::msg::Msg;

/// The drawing's part (`view`, `clip-2`, …) a section of `solve` shows.
fn part_of(section: &Msg) -> Option<String> {
    Some(match section {
        Msg::SecViewing => "view".into(),
        Msg::SecProjection => "project".into(),
        Msg::SecWindowClip => "window".into(),
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
    for w in &r.warnings {
        body.push_str(&format!(
            "<p class=\"warning\">{}: {}</p>\n",
            st.tr("warning", "peringatan"),
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
    body.push_str(&heading(1, st.tr("Answer", "Jawaban")));
    body.push_str(&answers(st, &r.answer()));
    for n in r.all_notes(st) {
        body.push_str(&format!("<p class=\"note\">{}</p>\n", xml_escape(&n)));
    }
    page(title, &body, st.lang.code())
}
