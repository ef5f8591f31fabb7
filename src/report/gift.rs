//! Exams as GIFT, Moodle's plain-text question format. GIFT has no
//! multi-part question, so each value a student types is one question
//! (NUMERICAL `{#=x:t#… =%0%w:t'#feedback ####general feedback}` for a
//! number, short answer `{=code =%0%wrong#feedback}` for a code), all of
//! them repeating the problem's statement. The questions of one variant of
//! problem NN share the category `$course$/grafika/<topic>/<NN>/<VV>` (a
//! `$CATEGORY:` line before them): GIFT cannot keep the parts of a variant
//! together when a quiz draws at random, so a lecturer adds one variant's
//! category whole (the Moodle XML export keeps each variant in one question).
//!
//! Escaping: text is HTML (`[html]`, with `&`, `<`, `>` escaped), then every
//! character GIFT reads as syntax, `~ = # { } :` and the backslash, is
//! preceded by a backslash. Each question is one line (a blank line ends a
//! question).

use crate::report::lang::Lang;
use crate::report::moodle::{
    esc, esc_text, feedback, intro_html, leaf_labels, number, question_name, solution_html,
    tolerance_text, Exams,
};
use crate::report::Style;
use crate::tutor::generate::quiz::{blanks, Blank, Typed};
use crate::tutor::generate::Generated;
use std::fmt::Write as _;

/// The whole GIFT file.
pub fn gift(e: &Exams, st: &Style) -> String {
    let mut s = String::new();
    for i in 0..e.count() {
        for (v, exam) in e.exams.iter().enumerate() {
            if let Some(g) = exam.get(i) {
                let _ = write!(s, "$CATEGORY: {}/{:02}\n\n", e.category(i), v + 1);
                s.push_str(&variant_questions(g, i, v, e.rel, st));
            }
        }
    }
    s
}

/// The questions of one variant of one problem: one per blank.
fn variant_questions(g: &Generated, i: usize, v: usize, rel: f64, st: &Style) -> String {
    let asked = blanks(g, rel);
    let general = gift_escape(&solution_html(&g.report, &asked, st));
    let intro = intro_html(g, rel, st.lang);
    let name = question_name(g, i, v, st.lang);
    let mut s = String::new();
    for a in &asked {
        for (label, b) in leaf_labels(&a.key, &a.value).iter().zip(&a.blanks) {
            let text = format!("{intro}<p>{} = ?</p>", esc_text(label));
            let _ = write!(
                s,
                "::{}::[html]{}{{{} ####{}}}\n\n",
                gift_escape(&format!("{name} — {label}")),
                gift_escape(&text),
                answers(b, st.lang),
                general
            );
        }
    }
    s
}

/// The answers of one blank, right first.
fn answers(b: &Blank, lang: Lang) -> String {
    let right = match &b.value {
        Typed::Num(x) => format!("#={}:{}", number(*x), tolerance_text(b.tolerance)),
        Typed::Text(t) => format!("={}", gift_escape(t)),
    };
    let mut s = right;
    for w in &b.wrong {
        let value = match &w.value {
            Typed::Num(x) => format!("{}:{}", number(*x), tolerance_text(w.tolerance)),
            Typed::Text(t) => gift_escape(t),
        };
        let _ = write!(s, " =%0%{value}#{}", gift_escape(&esc(&feedback(w, lang))));
    }
    s
}

/// GIFT text: a backslash before each of `~ = # { } :` and `\`, and line
/// breaks as `\n`.
pub fn gift_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '~' | '=' | '#' | '{' | '}' | ':' | '\\' => {
                out.push('\\');
                out.push(c);
            }
            '\n' => out.push_str("\\n"),
            '\r' => {}
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gift_specials_are_escaped() {
        assert_eq!(
            gift_escape("a~b=c#d{e}f:g\\h"),
            "a\\~b\\=c\\#d\\{e\\}f\\:g\\\\h"
        );
        assert_eq!(gift_escape("one\ntwo"), "one\\ntwo");
    }
}
