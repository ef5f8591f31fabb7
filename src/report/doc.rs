//! Worked solutions as documents: the same steps the text report prints
//! (`report.rs`), rendered as Markdown or as LaTeX that a plain `pdflatex`
//! compiles (ASCII only: every symbol the steps use is mapped to a LaTeX
//! command). Used for exam answer keys.

use crate::msg::DocWord;
use crate::report::html;
use crate::report::lang::Lang;
use crate::report::latex::{latex_math, latex_text};
use crate::report::words;
use crate::report::{Report, Style};
use crate::stages::trace::{Name, Step, Val};

/// The output format of a document.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Doc {
    /// GitHub-flavoured Markdown.
    Markdown,
    /// LaTeX (article class; geometry and, for the figures, TikZ: Debian's
    /// texlive-latex-base and texlive-pictures).
    Latex,
    /// One self-contained HTML page, formulas in MathML (`report::html`).
    Html,
}

impl Doc {
    /// Text as it goes into the document (escaped, symbols mapped).
    pub fn text(self, s: &str) -> String {
        match self {
            Doc::Markdown => s.replace('|', "\\|").replace('*', "\\*"),
            Doc::Latex => latex_text(s),
            Doc::Html => crate::report::figure::xml_escape(s),
        }
    }

    /// A heading of the given level (1 = a problem, 2 = a section).
    pub fn heading(self, level: usize, s: &str) -> String {
        match self {
            Doc::Markdown => format!("{} {}\n\n", "#".repeat(level + 1), self.text(s)),
            Doc::Latex => {
                let cmd = ["section*", "subsection*", "subsubsection*", "paragraph"][level.min(3)];
                format!("\\{cmd}{{{}}}\n\n", latex_text(s))
            }
            Doc::Html => html::heading(level, s),
        }
    }

    /// A formula line.
    fn formula(self, s: &str) -> String {
        match self {
            Doc::Markdown => format!("`{s}`"),
            Doc::Latex => latex_text(s),
            Doc::Html => crate::report::mathml::block(s),
        }
    }

    /// `name = value` (a matrix is set as a matrix), `name` in the
    /// reader's words.
    pub fn named(self, st: &Style, name: &str, v: &Val, arrow: bool) -> String {
        let lead = if arrow { "⇒ " } else { "" };
        match (self, v) {
            (Doc::Html, _) => html::named(st, name, v, arrow),
            (Doc::Markdown, Val::List(rows)) if v.is_matrix() => {
                // A table with an empty header row (Markdown tables need one).
                let width = match rows.first() {
                    Some(Val::List(c)) => c.len(),
                    _ => 0,
                };
                let mut s = format!("{lead}{} =\n\n", self.text(name));
                s.push_str(&format!(
                    "|{}\n|{}\n",
                    "   |".repeat(width),
                    "---|".repeat(width)
                ));
                for r in rows {
                    if let Val::List(cells) = r {
                        let cs: Vec<String> = cells.iter().map(|c| cell(st, c)).collect();
                        s.push_str(&format!("| {} |\n", cs.join(" | ")));
                    }
                }
                s
            }
            (Doc::Latex, Val::List(rows)) if v.is_matrix() => {
                let n = match rows.first() {
                    Some(Val::List(c)) => c.len(),
                    _ => 0,
                };
                let body: Vec<String> = rows
                    .iter()
                    .map(|r| match r {
                        Val::List(cells) => cells
                            .iter()
                            .map(|c| latex_math(&cell(st, c)))
                            .collect::<Vec<_>>()
                            .join(" & "),
                        _ => String::new(),
                    })
                    .collect();
                format!(
                    "{}{} = $\\left(\\begin{{array}}{{{}}}{}\\end{{array}}\\right)$",
                    latex_text(lead),
                    latex_text(name),
                    "r".repeat(n),
                    body.join(" \\\\ ")
                )
            }
            _ => {
                // "top ≈ 0.182", not "top = ≈ 0.182"
                let val = st.val_inline(v);
                let (sign, val) = match val.strip_prefix("≈ ") {
                    Some(rest) => ("≈", rest.to_string()),
                    None => ("=", val),
                };
                format!(
                    "{}{} {} {}",
                    self.text(lead),
                    self.text(name),
                    self.text(sign),
                    self.text(&val)
                )
            }
        }
    }

    /// The worked steps of a report, grouped by section.
    pub fn steps(self, r: &Report, st: &Style) -> String {
        self.steps_with(r, st, &mut |_| String::new())
    }

    /// The worked steps, with what `after_heading` gives for a section
    /// put right under its heading (a part's figure).
    pub fn steps_with(
        self,
        r: &Report,
        st: &Style,
        after_heading: &mut dyn FnMut(&crate::msg::Msg) -> String,
    ) -> String {
        let mut out = String::new();
        let mut section: Option<&crate::msg::Msg> = None;
        for (i, s) in r.steps.iter().enumerate() {
            if s.section.as_ref() != section {
                section = s.section.as_ref();
                if let Some(sec) = section {
                    out.push_str(&self.heading(3, &st.w(sec)));
                    out.push_str(&after_heading(sec));
                }
            }
            out.push_str(&self.step(i + 1, s, st));
        }
        out
    }

    fn step(self, k: usize, s: &Step, st: &Style) -> String {
        if self == Doc::Html {
            return html::step(k, s, st);
        }
        let mut lines: Vec<String> = Vec::new();
        if !s.formula.is_empty() {
            lines.push(self.formula(&st.w(&s.formula)));
        }
        let line = |(n, v): &(Name, Val), arrow| {
            let name = words::of(st.lang).name(n);
            match s.sub_of(n) {
                Some(sub) if !v.is_matrix() => {
                    let lead = if arrow { "⇒ " } else { "" };
                    self.text(&format!("{lead}{}", st.worked(&name, sub, v)))
                }
                _ => self.named(st, &name, v, arrow),
            }
        };
        lines.extend(s.values.iter().map(|nv| line(nv, false)));
        lines.extend(s.result.iter().map(|nv| line(nv, true)));
        if let Some(n) = &s.note {
            let n = &st.w(n);
            lines.push(match self {
                Doc::Markdown => format!("*({})*", self.text(n)),
                _ => format!("\\emph{{({})}}", latex_text(n)),
            });
        }
        match self {
            Doc::Markdown => {
                let step = st.doc(DocWord::Step);
                let mut out = format!("**{step} {k}. {}**\n\n", self.text(&st.w(&s.title)));
                for l in lines {
                    if l.contains('\n') {
                        out.push_str(&format!("\n{l}\n"));
                    } else {
                        out.push_str(&format!("- {l}\n"));
                    }
                }
                out.push('\n');
                out
            }
            _ => {
                let mut out = format!(
                    "\\paragraph{{{} {k}. {}}}\n\\begin{{itemize}}\n",
                    st.doc(DocWord::Step),
                    latex_text(&st.w(&s.title))
                );
                for l in lines {
                    out.push_str(&format!("\\item {l}\n"));
                }
                if s.formula.is_empty()
                    && s.values.is_empty()
                    && s.result.is_empty()
                    && s.note.is_none()
                {
                    out.push_str("\\item ---\n");
                }
                out.push_str("\\end{itemize}\n\n");
                out
            }
        }
    }

    /// A list of `name = value` lines.
    pub fn answers(self, st: &Style, items: &[(String, Val)]) -> String {
        if self == Doc::Html {
            return html::answers(st, items);
        }
        // a list of maps (the segments of a clip) as one line per value
        let mut rows = Vec::new();
        for (k, v) in items {
            match v {
                Val::List(maps) if crate::report::is_list_of_maps(maps) => {
                    html::flatten(&[(k.clone(), v.clone())], &mut rows)
                }
                _ => rows.push((k.clone(), v.clone())),
            }
        }
        let items = &rows[..];
        match self {
            Doc::Html => html::answers(st, items),
            Doc::Markdown => {
                items
                    .iter()
                    .map(|(k, v)| format!("- {}\n", self.named(st, k, v, false)))
                    .collect::<String>()
                    + "\n"
            }
            Doc::Latex => {
                let mut out = String::from("\\begin{itemize}\n");
                for (k, v) in items {
                    out.push_str(&format!("\\item {}\n", self.named(st, k, v, false)));
                }
                out + "\\end{itemize}\n\n"
            }
        }
    }

    /// The figures of a report: TikZ pictures in LaTeX, inline SVG in HTML
    /// (each with its title as the caption); Markdown has none (a key in
    /// Markdown is text only).
    pub fn figures(self, r: &Report, st: &Style) -> String {
        use crate::report::figure::{drawings::drawings, svg::to_svg, tikz::to_tikz};
        let all = drawings(r, st);
        match self {
            Doc::Markdown => String::new(),
            Doc::Html => all
                .iter()
                .map(|d| html::figure(&to_svg(d), &d.title()))
                .collect(),
            Doc::Latex => all
                .iter()
                .map(|d| {
                    format!(
                        "\\begin{{center}}\n{}{{\\small {}}}\n\\end{{center}}\n\n",
                        to_tikz(d),
                        latex_text(&d.title())
                    )
                })
                .collect(),
        }
    }

    /// A whole document around a body.
    pub fn document(self, title: &str, body: &str, lang: Lang) -> String {
        match self {
            Doc::Html => html::page(title, body, lang.code()),
            Doc::Markdown => format!("# {}\n\n{body}", self.text(title)),
            Doc::Latex => format!(
                "\\documentclass[11pt]{{article}}\n\\usepackage[margin=2cm]{{geometry}}\n\\usepackage{{tikz}}\n{}\\setlength{{\\parindent}}{{0pt}}\n\\title{{{}}}\n\\date{{}}\n\\begin{{document}}\n\\maketitle\n\n{body}\\end{{document}}\n",
                crate::report::figure::tikz::preamble(),
                latex_text(title)
            ),
        }
    }
}

/// A matrix cell: the exact form when there is one, else the decimal.
fn cell(st: &Style, c: &Val) -> String {
    match c {
        Val::Num(s) => s
            .pretty
            .clone()
            .unwrap_or_else(|| crate::num::format::decimal(s, st.digits)),
        other => st.val_inline(other),
    }
}
