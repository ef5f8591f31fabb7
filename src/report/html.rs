//! Worked solutions as one self-contained HTML page: the same steps as the
//! text and the documents (`doc`), the formulas and values in MathML
//! (`mathml`), exact forms beside decimals, the figures inline as SVG. No
//! script, font or style sheet is fetched; the page prints on A4.

use super::figure::xml_escape;
use super::mathml;
use super::words::{self, keys};
use super::Style;
use crate::msg::{DocWord, Msg};
use crate::stages::trace::{Step, Subst, Val};

/// The page's style: readable on a screen, one column, and A4 in print
/// (steps are not split across pages); a line of a step too long for the
/// column (a cross product of surds) scrolls within its line, and a wide
/// answer table within itself, so the page itself never grows wider than
/// the window.
const CSS: &str = "\
body{font-family:system-ui,sans-serif;line-height:1.5;max-width:48rem;margin:2rem auto;padding:0 1rem;color:#111}\
h1{font-size:1.6rem}h2{font-size:1.3rem;border-bottom:1px solid #999}h3{font-size:1.15rem}\
h4{font-size:1.05rem;margin:1rem 0 .2rem}h5{font-size:1rem;margin:.2rem 0}\
section.step{border-left:3px solid #0072B2;padding:.2rem .8rem;margin:.8rem 0;break-inside:avoid}\
section.step ul{list-style:none;padding-left:.5rem;margin:.2rem 0}\
section.step li{max-width:100%;overflow-x:auto;overflow-y:hidden}\
.note{font-style:italic;color:#333}.warning{border:1px solid #D55E00;padding:.4rem}\
math[display=block]{margin:.3rem 0;padding:.15em 0;max-width:100%;overflow-x:auto;overflow-y:hidden}\
table.answers{border-collapse:collapse;margin:.5rem 0;display:block;max-width:100%;overflow-x:auto}\
table.answers th,table.answers td{border:1px solid #999;padding:.2rem .6rem;text-align:left;vertical-align:top}\
table.comparison{font-size:.9rem}table.comparison tr.differs{background:#fdf1e6}\
p.statement{font-size:1.05rem}\
figure{margin:1rem 0;break-inside:avoid}figure svg{max-width:100%;height:auto}\
@page{size:A4;margin:18mm}\
@media print{body{margin:0;max-width:none}a{color:inherit}}";

/// A whole page around a body.
pub fn page(title: &str, body: &str, lang: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"{lang}\">\n<head>\n<meta charset=\"utf-8\"/>\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n\
         <title>{t}</title>\n<style>{CSS}</style>\n</head>\n<body>\n<h1>{t}</h1>\n{body}</body>\n</html>\n",
        t = xml_escape(title)
    )
}

/// A heading of the given level (1 = a problem, 2 = a section, 3 = a part).
pub fn heading(level: usize, s: &str) -> String {
    let h = (level + 1).min(6);
    format!("<h{h}>{}</h{h}>\n", xml_escape(s))
}

/// One step: its title, the formula (MathML when it is notation, text when
/// the caption has words), the values, the results (⇒) and the note.
pub fn step(k: usize, s: &Step, st: &Style) -> String {
    let mut out = format!(
        "<section class=\"step\">\n<h5>{} {k}. {}</h5>\n",
        st.doc(DocWord::Step),
        xml_escape(&st.w(&s.title))
    );
    match &s.formula {
        Msg::Math(f) if f.is_empty() => {}
        Msg::Math(f) => out.push_str(&mathml::block(f)),
        words => out.push_str(&format!("<p>{}</p>", xml_escape(&st.w(words)))),
    }
    out.push_str("\n<ul>\n");
    let names = words::of(st.lang);
    for (n, v) in &s.values {
        let line = line(st, &names.name(n), s.sub_of(n), v, false);
        out.push_str(&format!("<li>{line}</li>\n"));
    }
    for (n, v) in &s.result {
        let line = line(st, &names.name(n), s.sub_of(n), v, true);
        out.push_str(&format!("<li>{line}</li>\n"));
    }
    out.push_str("</ul>\n");
    if let Some(n) = &s.note {
        out.push_str(&format!(
            "<p class=\"note\">({})</p>\n",
            xml_escape(&st.w(n))
        ));
    }
    out + "</section>\n"
}

/// `name = substitution = value` in MathML when the step shows how the
/// value was worked, else as [`named`]; `name` in the reader's words.
pub fn line(st: &Style, name: &str, sub: Option<&Subst>, v: &Val, arrow: bool) -> String {
    match sub {
        Some(sub) if !v.is_matrix() => {
            let lead = if arrow { "⇒ " } else { "" };
            mathml::inline(&format!("{lead}{}", st.worked(name, sub, v)))
        }
        _ => named(st, name, v, arrow),
    }
}

/// `name = value` in MathML: a matrix as a table, numbers and vectors as
/// notation, words (a status, yes/no) as text.
pub fn named(st: &Style, name: &str, v: &Val, arrow: bool) -> String {
    let lead = if arrow { "⇒ " } else { "" };
    match v {
        Val::List(rows) if v.is_matrix() => format!(
            "<math display=\"block\"><mrow>{}<mo form=\"infix\">=</mo>{}</mrow></math>",
            mathml::row(&format!("{lead}{name}")),
            matrix(st, rows)
        ),
        Val::Num(_) | Val::List(_) => {
            // "top ≈ 0.182", not "top = ≈ 0.182"
            let val = st.val_inline(v);
            let line = match val.strip_prefix("≈ ") {
                Some(rest) => format!("{lead}{name} ≈ {rest}"),
                None => format!("{lead}{name} = {val}"),
            };
            mathml::inline(&line)
        }
        _ => mathml::inline_then_text(&format!("{lead}{name} ="), &st.val_inline(v)),
    }
}

/// A matrix in parentheses (the rows of a `Val`).
fn matrix(st: &Style, rows: &[Val]) -> String {
    let body: String = rows.iter().map(|r| matrix_row(st, r)).collect();
    format!("<mrow><mo>(</mo><mtable>{body}</mtable><mo>)</mo></mrow>")
}

/// One row of a matrix: exact forms where there are any.
fn matrix_row(st: &Style, r: &Val) -> String {
    let Val::List(cells) = r else {
        return String::new();
    };
    let tds: String = cells
        .iter()
        .map(|c| {
            let text = match c {
                Val::Num(s) => match &s.pretty {
                    Some(p) => st.nums.form(p),
                    None => crate::num::format::decimal_in(s, st.digits, st.nums.mark),
                },
                other => st.val_inline(other),
            };
            format!("<mtd>{}</mtd>", mathml::row(&text))
        })
        .collect();
    format!("<mtr>{tds}</mtr>")
}

/// The answers as a table of `name | value` rows, each named as the steps
/// name it (`A'`, `piksel A`, `t (kiri)`; the answer key in its title),
/// maps of points opened and lists of segments numbered.
pub fn answers(st: &Style, items: &[(String, Val)]) -> String {
    let mut rows = Vec::new();
    flatten(items, &mut rows);
    let named: Vec<(String, String, Val)> = rows
        .into_iter()
        .map(|(k, v)| {
            let name = keys::name_of(words::of(st.lang), &k);
            (k, name, v)
        })
        .collect();
    named_answers(st, &named)
}

/// The answer's table from rows already named: (key, words, value); the
/// key is each row's title.
pub fn named_answers(st: &Style, rows: &[(String, String, Val)]) -> String {
    let body: String = rows
        .iter()
        .map(|(k, name, v)| {
            let cell = match v {
                Val::List(m) if v.is_matrix() => {
                    format!("<math display=\"block\">{}</math>", matrix(st, m))
                }
                Val::Num(_) | Val::List(_) => mathml::inline(&st.val_inline(v)),
                Val::Text(t) if k.ends_with("status") => {
                    let said = Val::said(crate::msg::Said::Status(t.clone()));
                    xml_escape(&st.val_inline(&said))
                }
                other => xml_escape(&st.val_inline(other)),
            };
            format!(
                "<tr><th title=\"{}\">{}</th><td>{cell}</td></tr>\n",
                xml_escape(k),
                mathml::inline(name)
            )
        })
        .collect();
    format!("<table class=\"answers\">\n{body}</table>\n")
}

/// `(key, value)` pairs with maps opened: `points` → `points.A`, …, and
/// lists of maps by their index: `clip` → `clip.0.status`, …, the key an
/// answer file writes (the words name the segment from 1); an empty map is
/// left out.
pub fn flatten(items: &[(String, Val)], out: &mut Vec<(String, Val)>) {
    let numbered = |at: &str, i: usize| format!("{at}.{i}");
    for (k, v) in items {
        v.walk(k, &numbered, &mut |at, x| match x {
            Val::Map(_) => true,
            Val::List(maps) if crate::report::is_list_of_maps(maps) => true,
            _ => {
                out.push((at.to_string(), x.clone()));
                false
            }
        });
    }
}

/// A figure inline, with its title as the caption.
pub fn figure(svg: &str, caption: &str) -> String {
    format!(
        "<figure>\n{svg}<figcaption>{}</figcaption>\n</figure>\n",
        xml_escape(caption)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;

    /// Each row of the answer table is titled with the key an answer file
    /// writes for its value: read back, the key finds that very value.
    /// A clip's several segments and a file's several lights count from 0
    /// in a key, as in JSON (`clip.0.status` is the first segment, which
    /// the words call segment 1); a title numbered from 1 (`clip[1]`)
    /// named the next segment's value, and a student who copied it was
    /// marked against the wrong segment.
    #[test]
    fn every_rows_title_is_the_key_of_its_value() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
        let mut rows_seen = 0;
        for name in [
            "clip-cases.toml",
            "shade-two-lights.toml",
            "text-camera.toml",
        ] {
            let p = ProblemIn::read(&root.join(name)).expect("a shipped problem");
            let r = crate::tutor::solve::solve::<crate::num::Real>(&p).expect("it solves");
            let mut rows = Vec::new();
            flatten(&r.answer(), &mut rows);
            for (k, v) in rows {
                let found = r.result.lookup(&k);
                assert_eq!(found.as_deref(), Some(&v), "{k} in {name}");
                rows_seen += 1;
            }
        }
        assert!(rows_seen > 60, "{rows_seen}");
    }
}
