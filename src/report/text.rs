//! A worked solution as text: the problem, each step below its title,
//! the answer, the notes and the warnings.

use super::{is_list_of_maps, practice, render, words, Style};
use crate::msg::{DocWord, Msg, Printed};
use crate::report::lang::Lang;
use crate::stages::trace::Val;
use crate::tutor::key::{Field, Node};
use crate::tutor::solution::{Asked, Comparison, One, PartResult, Report, Results};

impl Report {
    /// The worked solution and answer as text, after the problem.
    pub fn to_text(&self, style: &Style) -> String {
        let mut out = String::new();
        if let Some((title, statement, asked)) = self.posed() {
            out.push_str(&format!("{title}\n{}\n", "=".repeat(title.chars().count())));
            if let Some(s) = statement {
                out.push_str(&format!("{s}\n"));
            }
            out.push_str(&format!("\n{}\n", practice::wrap(&style.w(&asked), "")));
        }
        let mut section: Option<&Msg> = None;
        let step_word = style.doc(DocWord::Step);
        for (i, s) in self.steps.iter().enumerate() {
            if s.section.as_ref() != section {
                section = s.section.as_ref();
                if let Some(sec) = section {
                    out.push_str(&format!("\n== {} ==\n", style.w(sec)));
                }
            }
            out.push_str(&format!("\n{step_word} {}. {}\n", i + 1, style.w(&s.title)));
            out.push_str(&style.step_body(s));
        }
        out.push_str(&format!("\n{}\n", self.answer_heading(style.lang)));
        match self.asked {
            Asked::Render(_) => {
                for (_, named, v) in self.answer_named(style.lang) {
                    push_answer(&mut out, style, "  ", (None, &named), &v);
                }
            }
            _ => push_results(&mut out, style, &self.result),
        }
        for n in self.all_notes(style) {
            out.push_str(&format!("\n{n}\n"));
        }
        for w in &self.warnings {
            let label = style.doc(DocWord::Warning);
            out.push_str(&format!("\n{label}: {}\n", style.w(w)));
        }
        out
    }

    /// The report's own notes after the answer: a render's `--stats`.
    pub fn notes(&self, style: &Style) -> Vec<String> {
        match &self.asked {
            Asked::Render(run) if run.stats_asked => vec![render::stats_text(run, style.lang)],
            _ => vec![],
        }
    }

    /// The notes after the answer: the report's own, the comparison with
    /// the printed answers, the notes on the source.
    pub(super) fn all_notes(&self, style: &Style) -> Vec<String> {
        let mut notes = self.notes(style);
        notes.extend(
            self.comparison
                .as_ref()
                .map(|c| comparison_text(c, style.lang)),
        );
        if !self.source_notes.is_empty() {
            let lines: Vec<String> = self
                .source_notes
                .iter()
                .map(|n| format!("  - {n}"))
                .collect();
            let head = style.doc(DocWord::NotesOnSource);
            notes.push(format!("{head}:\n{}", lines.join("\n")));
        }
        notes
    }
}

/// The comparison with the printed answers, one line per answer.
fn comparison_text(c: &Comparison, lang: Lang) -> String {
    let style = Style::new(4, true, lang);
    let t = |w: DocWord| style.doc(w);
    let src = (c.source.clone()).unwrap_or_else(|| t(DocWord::TheSource));
    let head = t(DocWord::ComparedWith);
    let mut lines = vec![format!("{head} {src}:")];
    let printed = t(DocWord::Printed);
    for r in &c.rows {
        let name = words::keys::name_of(words::of(lang), &r.key);
        let (key, shown) = (format!("{name} ({})", r.key), style.printed(&r.printed));
        let verdict = style.w(&Msg::Printed(r.verdict()));
        let why = (r.why.as_ref())
            .map(|w| format!(": {}", style.w(w)))
            .unwrap_or_default();
        lines.push(match (&r.computed, r.verdict()) {
            (Some(v), Printed::Differs(_)) => format!(
                "  {key}: {printed} {shown}, {} {} — {verdict}{why}",
                t(DocWord::CorrectValue),
                style.val_inline(v)
            ),
            (Some(v), Printed::NotComparable) => format!(
                "  {key}: {printed} {shown}, {} {} — {verdict}",
                t(DocWord::Computed),
                style.val_inline(v)
            ),
            _ => format!("  {key}: {printed} {shown} — {verdict}"),
        });
    }
    lines.join("\n")
}

/// Writes the results: a problem file's part by part (a clip's several
/// segments numbered from 1 as the solution numbers them, `clip 1:`, …;
/// not `clip[1]`, which an answer file reads as the second segment), each
/// field by its typed name; a command's fields unnested.
fn push_results(out: &mut String, style: &Style, results: &Results) {
    let words = words::of(style.lang);
    for p in &results.parts {
        let part = Node::Part(p.part());
        match (results.nested, p) {
            (false, _) => {
                let fields = p.one(None).map(One::entries).unwrap_or_default();
                push_fields(out, style, "  ", &fields);
            }
            (true, PartResult::Clip(runs)) if runs.len() != 1 => {
                for (i, r) in runs.iter().enumerate() {
                    let numbered = format!("{} {}", words.node(&part), i + 1);
                    push_part(out, style, &numbered, &One::Clip(r).entries());
                }
            }
            (true, _) => {
                let fields = p.one(None).map(One::entries).unwrap_or_default();
                push_part(out, style, &words.node(&part), &fields);
            }
        }
    }
}

/// A part's fields under its name (`none` when it has none).
fn push_part(out: &mut String, style: &Style, shown: &str, fields: &[(Field, &Val)]) {
    if fields.is_empty() {
        out.push_str(&style.named("  ", shown, &Val::Null));
        out.push('\n');
        return;
    }
    out.push_str(&format!("  {shown}:\n"));
    push_fields(out, style, "    ", fields);
}

/// Each field of a part by its typed name.
fn push_fields(out: &mut String, style: &Style, indent: &str, fields: &[(Field, &Val)]) {
    for (f, v) in fields {
        let node = Node::Field(*f);
        let shown = words::of(style.lang).node(&node);
        push_answer(out, style, indent, (Some(&node), &shown), v);
    }
}

/// Writes one answer, opening maps (e.g. points) into one line per entry
/// and a list of maps (a file's lights) into one block per map numbered
/// from 1, `lights 1:`, `lights 2:`, …; an empty map is `none`. `k` is the
/// answer tree's name (none for a render's summary) and the words it is
/// shown with ([`words::keys::KeyWords::node`]).
fn push_answer(out: &mut String, style: &Style, indent: &str, k: (Option<&Node>, &str), v: &Val) {
    let (node, shown) = k;
    match v {
        Val::Map(kv) if kv.is_empty() => {
            out.push_str(&style.named(indent, shown, &Val::Null));
            out.push('\n');
        }
        Val::List(items) if is_list_of_maps(items) => {
            for (i, item) in items.iter().enumerate() {
                let numbered = format!("{shown} {}", i + 1);
                push_answer(out, style, indent, (node, &numbered), item);
            }
        }
        Val::Map(kv) => {
            out.push_str(&format!("{indent}{shown}:\n"));
            for (k2, v2) in kv {
                let (inner, named) = match node {
                    Some(n) => words::keys::node_of(words::of(style.lang), k2, Some(n)),
                    None => (None, k2.clone()),
                };
                push_answer(
                    out,
                    style,
                    &format!("{indent}  "),
                    (inner.as_ref(), &named),
                    v2,
                );
            }
        }
        // A clipping status is a code (check compares it); the text
        // glosses it in the chosen language.
        Val::Text(t) if node == Some(&Node::Field(Field::Status)) => {
            let said = Val::said(crate::msg::Said::Status(t.clone()));
            out.push_str(&style.named(indent, shown, &said));
            out.push('\n');
        }
        _ => {
            out.push_str(&style.named(indent, shown, v));
            out.push('\n');
        }
    }
}
