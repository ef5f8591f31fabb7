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
//! The writer only writes: the blanks are the tutor's
//! ([`crate::tutor::generate::quiz`]), the words, labels, spellings and
//! decimal mark those of the Moodle XML writer. GIFT carries no files: the
//! general feedback has no figures and says nothing of them (students read
//! it); `generate` tells the lecturer where the figures are.
//!
//! Escaping: text is HTML (`[html]`, with `&`, `<`, `>` escaped), then every
//! character GIFT reads as syntax, `~ = # { } :` and the backslash, is
//! preceded by a backslash. Each question is one line (a blank line ends a
//! question).

use crate::msg::QuizWord as Q;
use crate::report::escape;
use crate::report::lang::Lang;
use crate::report::moodle::{
    category, esc, esc_text, feedback, intro_html, label, number, question_name, solution_html,
    spellings, tolerance_text, Written,
};
use crate::report::quizfile::{pack, Frame, Unit};
use crate::report::words;
use crate::stages::trace::Val;
use crate::tutor::generate::quiz::{Blank, Question, Quiz, Typed};
use crate::tutor::key::{Field, Key, Value};
use std::fmt::Write as _;

/// The frame of a GIFT file: nothing around its questions.
pub const GIFT: Frame = Frame { head: "", foot: "" };

/// The whole GIFT file.
pub fn gift(q: &Quiz, w: &Written) -> String {
    pack(&gift_units(q, w), GIFT, None)
        .unwrap_or_default()
        .concat()
}

/// The questions of a GIFT file, each after its variant's `$CATEGORY:`
/// line ([`crate::report::quizfile`]).
pub fn gift_units(q: &Quiz, w: &Written) -> Vec<Unit> {
    let mut units = Vec::new();
    for i in 0..q.count() {
        for (v, exam) in q.variants.iter().enumerate() {
            if let Some(question) = exam.get(i) {
                let cat = format!("$CATEGORY: {}/{:02}\n\n", category(q, i), v + 1);
                units.extend(variant_questions(question, (i, v), q, w).into_iter().map(
                    |(name, text)| Unit {
                        category: cat.clone(),
                        text,
                        name,
                    },
                ));
            }
        }
    }
    units
}

/// The questions of one variant of one problem, one per blank: (name,
/// text).
fn variant_questions(
    question: &Question,
    (i, v): (usize, usize),
    q: &Quiz,
    w: &Written,
) -> Vec<(String, String)> {
    let lang = w.style.lang;
    let general = gift_escape(&solution_html(question, "", &w.style));
    let intro = intro_html(question, q, w);
    let name = question_name(&question.problem, i, v, lang);
    let mut out = Vec::new();
    for a in &question.asked {
        for (label, b) in leaf_labels(&a.key, &a.value, lang).iter().zip(&a.blanks) {
            let text = format!("{intro}<p>{} = ?</p>", esc_text(label));
            let named = format!("{name} — {label}");
            let q = format!(
                "::{}::[html]{}{{{} ####{}}}\n\n",
                gift_escape(&named),
                gift_escape(&text),
                answers(b, lang),
                general
            );
            out.push((named, q));
        }
    }
    out
}

/// The names of a value's leaves, depth first: the answer's label as the
/// Cloze question labels it ([`label`]: `n`, `A'`, `cos α`), then the
/// component (`n, component y`; `clipped segment, point 2, component z`).
pub fn leaf_labels(key: &Key, v: &Val, lang: Lang) -> Vec<String> {
    let colour = matches!(key.value, Value::Field(Field::Shading(s)) if s.is_colour());
    let name = label(key, lang);
    let mut out = Vec::new();
    labels(&name, v, colour, lang, &mut out);
    out
}

fn labels(name: &str, v: &Val, colour: bool, lang: Lang, out: &mut Vec<String>) {
    match v {
        Val::List(items) if items.iter().all(|x| matches!(x, Val::Num(_))) => {
            let axes: &[&str] = if colour {
                &["r", "g", "b"]
            } else {
                &["x", "y", "z", "w"]
            };
            for (k, _) in items.iter().enumerate() {
                let axis = axes.get(k).map_or((k + 1).to_string(), |a| a.to_string());
                out.push(format!(
                    "{name}, {} {axis}",
                    words::of(lang).quiz(&Q::Component)
                ));
            }
        }
        Val::List(items) => {
            for (k, x) in items.iter().enumerate() {
                let part = format!("{name}, {} {}", words::of(lang).quiz(&Q::Point), k + 1);
                labels(&part, x, colour, lang, out);
            }
        }
        Val::Map(kv) => kv
            .iter()
            .for_each(|(k, x)| labels(&format!("{name}, {k}"), x, colour, lang, out)),
        _ => out.push(name.to_string()),
    }
}

/// The answers of one blank, right first (a word in each of its
/// spellings, [`spellings`]).
fn answers(b: &Blank, lang: Lang) -> String {
    let mut s = match &b.value {
        Typed::Num(x) => format!("#={}:{}", number(*x), tolerance_text(b.tolerance)),
        Typed::Text(t) => (spellings(t, lang).iter())
            .map(|w| format!("={}", gift_escape(w)))
            .collect::<Vec<_>>()
            .join(" "),
    };
    for w in &b.wrong {
        let values = match &w.value {
            Typed::Num(x) => vec![format!("{}:{}", number(*x), tolerance_text(w.tolerance))],
            Typed::Text(t) => spellings(t, lang).iter().map(|x| gift_escape(x)).collect(),
        };
        for value in values {
            let _ = write!(s, " =%0%{value}#{}", gift_escape(&esc(&feedback(w, lang))));
        }
    }
    s
}

/// GIFT text: a backslash before each of `~ = # { } :` and `\`, line
/// breaks as `\n`, and the active characters (control characters,
/// bidirectional overrides) shown as `\u{XX}` as in every other file
/// grafika writes (report/escape.rs), their backslash and braces escaped.
pub fn gift_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => {}
            c if escape::is_active(c) => {
                let mut shown = String::new();
                escape::push_visible(&mut shown, c);
                shown.chars().for_each(|e| push_gift(&mut out, e));
            }
            c => push_gift(&mut out, c),
        }
    }
    out
}

/// `c`, after a backslash when GIFT gives it a meaning.
fn push_gift(out: &mut String, c: char) {
    if matches!(c, '~' | '=' | '#' | '{' | '}' | ':' | '\\') {
        out.push('\\');
    }
    out.push(c);
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
        // ESC would act on a terminal showing the file; U+202E would
        // reorder the line in Moodle's editor.
        assert_eq!(
            gift_escape("a\u{1b}[2J\u{202e}b"),
            "a\\\\u\\{1B\\}[2J\\\\u\\{202E\\}b"
        );
    }

    #[test]
    fn leaves_are_named_as_the_steps_name_them() {
        let key = |s: &str| s.parse::<Key>().expect("a key");
        let num = |x: f64| {
            Val::Num(crate::num::Shown {
                value: x,
                exact: None,
                pretty: None,
                beyond: None,
            })
        };
        let v3 = Val::List(vec![num(0.0), num(1.0), num(0.0)]);
        let id = leaf_labels(&key("view.n"), &v3, Lang::Id);
        assert_eq!(id, ["n, komponen x", "n, komponen y", "n, komponen z"]);
        let c = leaf_labels(&key("shade.color"), &v3, Lang::En);
        assert_eq!(c[2], "color, component b");
        let u = leaf_labels(&key("shade.unclamped"), &v3, Lang::En);
        assert_eq!(u[0], "color before clamping, component r");
        let a = leaf_labels(&key("shade.cos_alpha"), &Val::List(vec![]), Lang::En);
        assert!(a.is_empty());
        let clipped = leaf_labels(&key("clip.1.segment"), &v3, Lang::En);
        assert_eq!(clipped[0], "segment 2: clipped segment, component x");
        let p = leaf_labels(&key("view.points.A"), &v3, Lang::En);
        assert_eq!(p[0], "A', component x");
        let px = leaf_labels(&key("viewport.pixels.A"), &v3, Lang::Id);
        assert_eq!(px[1], "piksel A, komponen y");
        let seg = Val::List(vec![v3.clone(), v3]);
        let s = leaf_labels(&key("clip.segment"), &seg, Lang::Id);
        assert_eq!(s.len(), 6);
        assert_eq!(s[5], "segmen garis hasil clipping, titik 2, komponen z");
        assert_eq!(
            leaf_labels(&key("clip.status"), &Val::Text("clipped".into()), Lang::En),
            ["status"]
        );
        assert_eq!(
            leaf_labels(&key("clip.code0"), &Val::Text("000010".into()), Lang::Id),
            ["region code P0"]
        );
    }
}
