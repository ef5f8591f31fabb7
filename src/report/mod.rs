//! Reports: the one place where steps and results become words for people
//! and files for programs. `style` writes numbers and values in the
//! text's notation; `text` writes a worked solution as text, `json` as
//! docs/spec.md §3's JSON, and the other modules the other formats.

pub mod bench;
pub mod blueprint;
pub mod check;
pub mod class;
pub mod csv;
pub mod doc;
pub mod escape;
pub mod figure;
pub mod gift;
pub mod html;
pub mod json;
pub mod lang;
pub mod latex;
pub mod mathml;
pub mod mistakes;
pub mod moodle;
pub mod moodle_grades;
pub mod page;
pub mod practice;
pub mod quizfile;
pub mod render;
pub mod sheets;
pub mod style;
pub mod text;
pub mod words;
pub mod writer;

use crate::msg::{DocWord, Msg, Printed};
use crate::stages::trace::Val;
use crate::tutor::solution::{Asked, Compared, Report};
use lang::Lang;

pub use crate::num::format::fmt_dec;
pub use style::Style;

impl Report {
    /// The named results the answer shows, keyed as the JSON keys them: a
    /// render's summary, else the results.
    pub fn answer(&self) -> std::borrow::Cow<'_, [(String, Val)]> {
        match &self.asked {
            Asked::Render(run) => std::borrow::Cow::Owned(
                render::summary(run)
                    .into_iter()
                    .map(|(k, v)| (k.key(), v))
                    .collect(),
            ),
            _ => std::borrow::Cow::Owned(self.result.tree()),
        }
    }

    /// The heading of the answer in `lang`: a render's summary is headed
    /// as a render, it answers nothing.
    pub fn answer_heading(&self, lang: Lang) -> String {
        match &self.asked {
            Asked::Render(_) => words::of(lang).render_heading().to_string(),
            _ => words::of(lang).doc(&DocWord::Answer),
        }
    }

    /// A render's summary as the text names it in `lang`: (key, words,
    /// value); a solution's results are named by their typed names.
    pub fn answer_named(&self, lang: Lang) -> Vec<(String, String, Val)> {
        match &self.asked {
            Asked::Render(run) => render::summary(run)
                .into_iter()
                .map(|(k, v)| (k.key(), words::of(lang).summary(k), v))
                .collect(),
            _ => vec![],
        }
    }

    /// The problem `solve` worked, as its file gives it in the language it
    /// was read in: the title, the statement, and what is asked (the
    /// parts answered).
    pub fn posed(&self) -> Option<(String, Option<String>, Msg)> {
        let Asked::File(p) = &self.asked else {
            return None;
        };
        let statement = p.statement.as_ref().map(|s| s.trim().to_string());
        let parts = (self.result.parts.iter()).map(|p| p.part().key()).collect();
        Some((p.title.clone(), statement, Msg::Asked(parts)))
    }
}

impl Compared {
    /// How the printed answer compares: agrees, differs (of the kind the
    /// problem file says), not asked, not comparable.
    pub fn verdict(&self) -> Printed {
        match (&self.computed, self.agrees) {
            (None, _) => Printed::NotAsked,
            (Some(_), Some(true)) => Printed::Agrees,
            (Some(_), Some(false)) => Printed::Differs(self.kind),
            (Some(_), None) => Printed::NotComparable,
        }
    }
}

/// Keys (answer keys, a class report's keys) in a line, each in its one
/// spelling, separated by `, `.
pub fn joined<T: std::fmt::Display>(keys: impl IntoIterator<Item = T>) -> String {
    let spelled: Vec<String> = keys.into_iter().map(|k| k.to_string()).collect();
    spelled.join(", ")
}

/// Whether a list holds maps only (and at least one): each is an answer of
/// its own (one clipped segment), written as a numbered block.
pub fn is_list_of_maps(items: &[Val]) -> bool {
    !items.is_empty() && items.iter().all(|v| matches!(v, Val::Map(_)))
}
