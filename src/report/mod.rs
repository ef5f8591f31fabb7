//! Reports: the one place where steps and results become text (with tables
//! for matrices) or JSON (docs/spec.md §3). Stages only produce data.

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
pub mod words;

use crate::msg::{DocWord, Msg, Printed};
use crate::num::Shown;
use crate::stages::trace::{Name, Step, Subst, Val};
use crate::tutor::key::{Field, Node};
use crate::tutor::solution::{Asked, Compared, Comparison, Report};
use comfy_table::{presets, Table};
use lang::{Lang, NumStyle};
use serde_json::{json, Map, Value};

/// How numbers are written in text output.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    /// Significant digits of decimals.
    pub digits: usize,
    /// Whether the run was exact (approximate values are then marked ≈).
    pub exact_mode: bool,
    /// The language of the words.
    pub lang: Lang,
    /// How numbers are written: the language's own decimal mark and
    /// separator ([`Style::new`]), or a quiz's `--decimal`
    /// ([`Style::with_nums`]).
    pub nums: NumStyle,
}

impl Style {
    /// `digits` significant digits, approximate values marked ≈ when
    /// `exact_mode`, in `lang` with its own decimal mark.
    pub fn new(digits: usize, exact_mode: bool, lang: Lang) -> Style {
        Style {
            digits,
            exact_mode,
            lang,
            nums: words::of(lang).nums(),
        }
    }

    /// The same style with its numbers written in `nums` (one decimal mark
    /// for a whole quiz, whatever its language: every number of the
    /// solution, its figures and the words that hold numbers).
    pub fn with_nums(self, nums: NumStyle) -> Style {
        Style { nums, ..self }
    }
}

pub use crate::num::format::fmt_dec;

impl Style {
    /// The words of a message key in this style's language, its numbers in
    /// this style's ([`words::words_in`]).
    pub fn w(&self, m: &Msg) -> String {
        words::words_in(m, self.lang, self.nums)
    }
    /// A word the documents share, in this style's language.
    pub fn doc(&self, w: DocWord) -> String {
        words::of(self.lang).doc(&w)
    }
    /// How this style writes numbers.
    pub fn nums(&self) -> NumStyle {
        self.nums
    }
    /// Values formatted the English way written in this style's language
    /// ([`NumStyle::values`]): `(0.8, 0.6, 0)` → `(0,8; 0,6; 0)` in Indonesian.
    pub fn dec(&self, s: String) -> String {
        self.nums().values(&s)
    }
}

impl Style {
    /// A value as a source printed it (a `[printed]` entry of a problem
    /// file), in the text's notation and this style's numbers: `(0, -1,
    /// -6/sqrt(2))` → `(0; −1; −6/√2)` in Indonesian.
    pub fn printed(&self, typed: &str) -> String {
        self.dec(notation(typed))
    }

    /// One number: `−√2/60 ≈ −0.02357`, `1/50 = 0.02`, `5`, `≈ 0.4142`, `0.4142`.
    pub fn num(&self, s: &Shown) -> String {
        self.dec(crate::num::format::shown(s, self.digits, self.exact_mode))
    }

    /// A vector or list: `(√2/2, 0, √2/2) ≈ (0.7071, 0, 0.7071)`.
    pub fn list(&self, items: &[Val]) -> String {
        match items.iter().all(|v| matches!(v, Val::Num(_))) {
            true => self.dec(self.list_en(items)),
            false => self.list_en(items),
        }
    }

    /// A list written the English way (numbers inside are converted by `dec`).
    fn list_en(&self, items: &[Val]) -> String {
        let nums: Option<Vec<&Shown>> = items
            .iter()
            .map(|v| if let Val::Num(s) = v { Some(s) } else { None })
            .collect();
        match nums {
            Some(ns) => {
                // An exact value beyond the doubles is shown by its exact form.
                let has_form = ns.iter().any(|s| {
                    s.pretty.as_deref().is_some_and(|p| {
                        !crate::num::format::is_plain_decimal(p) || !s.value.is_finite()
                    })
                });
                let decs: Vec<String> = ns
                    .iter()
                    .map(|s| crate::num::format::decimal(s, self.digits).replace('-', "−"))
                    .collect();
                let approx = ns
                    .iter()
                    .any(|s| crate::num::format::is_approx(s, self.digits, self.exact_mode));
                let beyond = ns.iter().any(|s| {
                    (s.value == 0.0 && s.pretty.as_deref().is_some_and(|p| p != "0"))
                        || !s.value.is_finite()
                });
                if has_form {
                    let forms: Vec<String> = ns
                        .iter()
                        .zip(&decs)
                        .map(|(s, d)| {
                            s.pretty
                                .clone()
                                .map(|p| p.replace('-', "−"))
                                .unwrap_or_else(|| format!("≈{d}"))
                        })
                        .collect();
                    if beyond {
                        // beyond the doubles: the exact forms alone
                        return format!("({})", forms.join(", "));
                    }
                    format!(
                        "({}) {} ({})",
                        forms.join(", "),
                        if approx { "≈" } else { "=" },
                        decs.join(", ")
                    )
                } else if self.exact_mode && approx && ns.iter().any(|s| s.pretty.is_none()) {
                    format!("≈ ({})", decs.join(", "))
                } else {
                    format!("({})", decs.join(", "))
                }
            }
            // the items are written in this style already: the separator too
            None => format!(
                "({})",
                items
                    .iter()
                    .map(|v| self.val_inline(v))
                    .collect::<Vec<_>>()
                    .join(self.nums().sep)
            ),
        }
    }

    /// Any value on one line.
    pub fn val_inline(&self, v: &Val) -> String {
        match v {
            Val::Num(s) => self.num(s),
            Val::List(items) => self.list(items),
            Val::Map(kv) => kv
                .iter()
                .map(|(k, v)| format!("{k} = {}", self.val_inline(v)))
                .collect::<Vec<_>>()
                .join(";  "),
            Val::Text(t) => t.clone(),
            Val::Said(m) => self.w(m),
            Val::Bool(b) => self.doc(if *b { DocWord::Yes } else { DocWord::No }),
            Val::Null => self.doc(DocWord::NoValue),
        }
    }

    /// A matrix as a table; exact forms in the cells when there are any.
    pub fn matrix(&self, rows: &[Val]) -> String {
        let mut t = Table::new();
        t.load_preset(presets::UTF8_FULL_CONDENSED);
        for r in rows {
            if let Val::List(cells) = r {
                t.add_row(cells.iter().map(|c| match c {
                    Val::Num(s) => self.dec(match &s.pretty {
                        Some(p) => p.replace('-', "−"),
                        None => crate::num::format::decimal(s, self.digits).replace('-', "−"),
                    }),
                    other => self.val_inline(other),
                }));
            }
        }
        t.to_string()
    }

    /// A step below its title: the formula, the values substituted, the
    /// results (`⇒`) and the note, one per line.
    pub fn step_body(&self, s: &Step) -> String {
        let mut out = String::new();
        if !s.formula.is_empty() {
            out.push_str(&format!("    {}\n", self.w(&s.formula)));
        }
        let name = |k: &Name| words::of(self.lang).name(k);
        for (k, v) in &s.values {
            out.push_str(&self.line("    ", &name(k), s.sub_of(k), v));
            out.push('\n');
        }
        for (k, v) in &s.result {
            out.push_str(&self.line("  ⇒ ", &name(k), s.sub_of(k), v));
            out.push('\n');
        }
        if let Some(n) = &s.note {
            out.push_str(&format!("    ({})\n", self.w(n)));
        }
        out
    }

    /// `name = value` as [`named`](Style::named) writes it, or `name =
    /// substitution = value` when the step shows how it was worked.
    pub fn line(&self, indent: &str, name: &str, sub: Option<&Subst>, v: &Val) -> String {
        match sub {
            Some(sub) if !v.is_matrix() => {
                format!("{indent}{}", self.worked(name, sub, v))
            }
            _ => self.named(indent, name, v),
        }
    }

    /// `name = substitution = value` (`t = (0 − 4)/(−2 − 4) = 2/3 ≈
    /// 0.6667`), `≈` before a value without an exact form; the
    /// substitution is left out when it reads as the value itself, and the
    /// line is then written as [`named`](Style::named) writes it (`bottom ≈
    /// −0.0364` for −top with top ≈ 0.0364, never `bottom = ≈ −0.0364`).
    pub fn worked(&self, name: &str, sub: &Subst, v: &Val) -> String {
        let (val, sub) = (self.val_inline(v), self.subst(sub));
        let shown = |s: &str| s.split([' ']).any(|p| p == sub) || s == sub;
        match val.strip_prefix("≈ ") {
            _ if shown(&val.replace(" ≈ ", " ").replace(" = ", " ")) => self.named("", name, v),
            Some(rest) => format!("{name} = {sub} ≈ {rest}"),
            None => format!("{name} = {sub} = {val}"),
        }
    }

    /// A substitution in this style's language: each value as a short
    /// decimal when that is exact (0.1), else its exact form (√2/2, 2/3),
    /// else its decimal; in parentheses where the operator before it
    /// would otherwise bind wrongly (`4 − (−2)`, `2·(√2−1)`).
    pub fn subst(&self, s: &Subst) -> String {
        let mut out = String::new();
        let pieces: Vec<&str> = s.form.split("{}").collect();
        for (i, piece) in pieces.iter().enumerate() {
            out.push_str(&self.nums().separated(piece));
            let Some(a) = s.args.get(i).filter(|_| i + 1 < pieces.len()) else {
                continue;
            };
            let text = self.operand(a);
            // a whole power after `^` is raised: max(0.8, 0)^4 → max(0.8, 0)⁴
            let raised: Option<String> = (out.ends_with('^'))
                .then(|| text.chars().map(superscript).collect())
                .flatten();
            match raised {
                Some(r) => {
                    out.pop();
                    out.push_str(&r);
                }
                None => {
                    let (before, after) =
                        (out.trim_end().chars().last(), pieces[i + 1].chars().next());
                    out.push_str(&parenthesized(&text, before, after));
                }
            }
        }
        out
    }

    /// One value of a substitution (a vector in parentheses).
    fn operand(&self, v: &Val) -> String {
        match v {
            Val::Num(s) => {
                let dec = crate::num::format::decimal(s, self.digits);
                let text = match &s.pretty {
                    Some(p)
                        if p.contains('√')
                            || crate::num::format::is_approx(s, self.digits, false) =>
                    {
                        p.clone()
                    }
                    _ => dec,
                };
                self.dec(text.replace('-', "−"))
            }
            Val::List(items) => {
                let parts: Vec<String> = items.iter().map(|x| self.operand(x)).collect();
                format!("({})", parts.join(self.nums().sep))
            }
            other => self.val_inline(other),
        }
    }

    /// `name = value`, with a matrix on its own lines; `name ≈ value` when
    /// the value has no exact form (never `name = ≈ value`).
    pub fn named(&self, indent: &str, name: &str, v: &Val) -> String {
        if v.is_matrix() {
            let table = self.matrix(match v {
                Val::List(rows) => rows,
                _ => &[],
            });
            let pad = " ".repeat(indent.chars().count());
            let body: Vec<String> = table.lines().map(|l| format!("{pad}  {l}")).collect();
            format!("{indent}{name} =\n{}", body.join("\n"))
        } else {
            // "top ≈ 0.04663", not "top = ≈ 0.04663" (no exact form)
            let val = self.val_inline(v);
            match val.strip_prefix("≈ ") {
                Some(rest) => format!("{indent}{name} ≈ {rest}"),
                None => format!("{indent}{name} = {val}"),
            }
        }
    }
}

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
            _ => std::borrow::Cow::Borrowed(&self.result),
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

    /// The answer as the text names it in `lang`: (key, words, value).
    pub fn answer_named(&self, lang: Lang) -> Vec<(String, String, Val)> {
        match &self.asked {
            Asked::Render(run) => render::summary(run)
                .into_iter()
                .map(|(k, v)| (k.key(), words::of(lang).summary(k), v))
                .collect(),
            _ => self
                .result
                .iter()
                .map(|(k, v)| {
                    let (_, named) = words::keys::node_of(words::of(lang), k, None);
                    (k.clone(), named, v.clone())
                })
                .collect(),
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
        let parts = self.result.iter().map(|(k, _)| k.clone()).collect();
        Some((p.title.clone(), statement, Msg::Asked(parts)))
    }

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
        let render = matches!(self.asked, Asked::Render(_));
        for (k, named, v) in self.answer_named(style.lang) {
            let node = (!render).then(|| Node::read(&k, None)).flatten();
            push_answer(&mut out, style, "  ", (node.as_ref(), &named), &v);
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

    /// The docs/spec.md §3 JSON object; only its human-readable strings (titles,
    /// notes, warnings) depend on `lang`.
    pub fn to_json(&self, lang: Lang) -> Value {
        let style = Style::new(4, true, lang);
        let answer = self.answer();
        let result = Value::Object(
            answer
                .iter()
                .map(|(k, v)| (k.clone(), value_json(v)))
                .collect(),
        );
        let exact = Value::Object(
            answer
                .iter()
                .map(|(k, v)| (k.clone(), exact_json(v)))
                .collect(),
        );
        let steps: Vec<Value> = self.steps.iter().map(|s| step_json(s, lang)).collect();
        let warnings: Vec<String> = self.warnings.iter().map(|w| style.w(w)).collect();
        let mut obj = json!({
            "command": self.command(),
            "precision": self.precision,
            "input": json::input(self),
            "result": result,
            "exact": exact,
            "steps": steps,
            "warnings": warnings,
        });
        let notes = self.all_notes(&style);
        if !notes.is_empty() {
            obj["notes"] = json!(notes);
        }
        if let Asked::Render(run) = &self.asked {
            obj["stats"] = render::stats_json(run);
        }
        if !self.source_notes.is_empty() {
            obj["source_notes"] = json!(self.source_notes);
        }
        if let Some(c) = &self.comparison {
            obj["comparison"] = c.rows.iter().map(|r| compared_json(r, lang)).collect();
        }
        obj
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
    fn all_notes(&self, style: &Style) -> Vec<String> {
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

/// An expression as a file writes it (`-6/sqrt(2)`, `(0.0067, -0.0283)`)
/// in the text's notation, not simplified: `−6/√2`, roots, π, `·` and
/// the minus sign; the decimal mark and separator are the style's
/// ([`Style::printed`]).
pub fn notation(typed: &str) -> String {
    let chars: Vec<char> = typed.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let rest: String = chars[i..].iter().take(4).collect();
        if rest.eq_ignore_ascii_case("sqrt") {
            i += 4;
            if chars.get(i) == Some(&'(') {
                // the root's argument, to its matching parenthesis
                let (mut depth, start) = (0, i);
                while i < chars.len() {
                    depth += match chars[i] {
                        '(' => 1,
                        ')' => -1,
                        _ => 0,
                    };
                    i += 1;
                    if depth == 0 {
                        break;
                    }
                }
                let inner: String = chars[start + 1..i.saturating_sub(1).max(start + 1)]
                    .iter()
                    .collect();
                let inner = notation(&inner);
                if inner.chars().all(|c| c.is_ascii_digit()) && !inner.is_empty() {
                    out.push_str(&format!("√{inner}"));
                } else {
                    out.push_str(&format!("√({inner})"));
                }
            } else {
                out.push('√');
            }
            continue;
        }
        if rest.len() >= 2
            && rest[..2].eq_ignore_ascii_case("pi")
            && !chars.get(i + 2).is_some_and(|c| c.is_alphabetic())
            && !(i > 0 && chars[i - 1].is_alphabetic())
        {
            out.push('π');
            i += 2;
            continue;
        }
        out.push(match chars[i] {
            '-' => '−',
            '*' => '·',
            c => c,
        });
        i += 1;
    }
    out
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

/// One compared answer as JSON (`kind`: the erratum's, a code).
fn compared_json(r: &Compared, lang: Lang) -> Value {
    json!({
        "key": r.key,
        "printed": r.printed,
        "computed": r.computed.as_ref().map(value_json),
        "agrees": r.agrees,
        "kind": r.kind,
        "why": r.why.as_ref().map(|w| crate::report::words::words(w, lang)),
    })
}

/// Writes one answer, opening maps (e.g. points) into one line per entry
/// and a list of maps (the segments of a clip) into one numbered block per
/// map, `clip[1]:`, `clip[2]:`, …; an empty map is `none`. `k` is the
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
                let numbered = format!("{shown}[{}]", i + 1);
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

/// A digit raised (`4` → `⁴`); `None` for anything else.
fn superscript(c: char) -> Option<char> {
    let i = c.to_digit(10)? as usize;
    "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().nth(i)
}

/// `text` as an operand between `before` and `after` (the characters
/// around it): in parentheses when it is negative after an operator, a sum
/// (or, after `/` and `^`, any expression) after a product or quotient, or
/// anything but a plain number before a power (`(−2)²`).
fn parenthesized(text: &str, before: Option<char>, after: Option<char>) -> String {
    let negative = text.starts_with('−');
    let body = text.strip_prefix('−').unwrap_or(text);
    let mut depth = 0;
    let (mut sum, mut op) = (false, false);
    for c in body.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '−' if depth == 0 => (sum, op) = (true, true),
            '/' | '·' if depth == 0 => op = true,
            _ => {}
        }
    }
    let power = after.is_some_and(|c| "²³ⁿ^".contains(c)) && (negative || op || body.contains('√'));
    let factor = (negative || op) && after.is_some_and(|c| "·×".contains(c));
    let wrap = power
        || factor
        || match before {
            None | Some('(' | '[' | ';' | ',' | '=' | '|' | '≤' | '<' | '>' | '≥') => false,
            Some('+') => negative,
            Some('−' | '·' | '×') => negative || sum,
            Some('/' | '^') => negative || op || (body.contains('√') && !body.starts_with('√')),
            Some(_) => negative,
        };
    if wrap {
        format!("({text})")
    } else {
        text.to_string()
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

/// A value with plain numbers.
pub fn value_json(v: &Val) -> Value {
    match v {
        Val::Num(s) => serde_json::Number::from_f64(s.value)
            .map(Value::Number)
            .unwrap_or(Value::Null),
        Val::List(items) => Value::Array(items.iter().map(value_json).collect()),
        Val::Map(kv) => Value::Object(
            kv.iter()
                .map(|(k, v)| (k.clone(), value_json(v)))
                .collect::<Map<_, _>>(),
        ),
        Val::Text(t) => Value::String(t.clone()),
        Val::Said(m) => Value::String(words::words(m, Lang::En)),
        Val::Bool(b) => Value::Bool(*b),
        Val::Null => Value::Null,
    }
}

/// The same shape with each number as its exact expression string (or null).
pub fn exact_json(v: &Val) -> Value {
    match v {
        Val::Num(s) => s.exact.clone().map(Value::String).unwrap_or(Value::Null),
        Val::List(items) => Value::Array(items.iter().map(exact_json).collect()),
        Val::Map(kv) => Value::Object(
            kv.iter()
                .map(|(k, v)| (k.clone(), exact_json(v)))
                .collect::<Map<_, _>>(),
        ),
        Val::Text(t) => Value::String(t.clone()),
        Val::Said(m) => Value::String(words::words(m, Lang::En)),
        Val::Bool(b) => Value::Bool(*b),
        Val::Null => Value::Null,
    }
}

/// A step as JSON (docs/spec.md §3); its title, formula, section and note in `lang`.
pub fn step_json(s: &Step, lang: Lang) -> Value {
    let w = |m: &Msg| words::words(m, lang);
    let obj = |kv: &[(Name, Val)], f: fn(&Val) -> Value| {
        Value::Object(kv.iter().map(|(k, v)| (k.to_string(), f(v))).collect())
    };
    let mut o = json!({
        "title": w(&s.title),
        "formula": w(&s.formula),
        "values": obj(&s.values, value_json),
        "result": obj(&s.result, value_json),
        "exact": { "values": obj(&s.values, exact_json), "result": obj(&s.result, exact_json) },
    });
    if !s.subs.is_empty() {
        // notation with the numbers written the English way, like `exact`
        let en = Style::new(4, true, Lang::En);
        let subs = s
            .subs
            .iter()
            .map(|(k, x)| (k.to_string(), json!(en.subst(x))));
        o["substituted"] = Value::Object(subs.collect());
    }
    if let Some(sec) = &s.section {
        o["section"] = json!(w(sec));
    }
    if let Some(n) = &s.note {
        o["note"] = json!(w(n));
    }
    o
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals() {
        assert_eq!(fmt_dec(-0.023570226, 4), "-0.02357");
        assert_eq!(fmt_dec(0.02, 4), "0.02");
        assert_eq!(fmt_dec(100.0, 4), "100");
        assert_eq!(fmt_dec(21.548, 4), "21.55");
        assert_eq!(fmt_dec(-1e-12, 3), "-1e-12");
        assert_eq!(fmt_dec(-0.00001, 3), "-0.00001");
    }

    #[test]
    fn exact_numbers_show_their_form() {
        let st = Style::new(4, true, lang::Lang::En);
        let s = Shown {
            value: -0.023570226039551584,
            exact: Some("-sqrt(2)/60".into()),
            pretty: Some("−√2/60".into()),
            beyond: None,
        };
        assert_eq!(st.num(&s), "−√2/60 ≈ −0.02357");
        let fifty = Shown {
            value: 0.02,
            exact: Some("1/50".into()),
            pretty: Some("1/50".into()),
            beyond: None,
        };
        assert_eq!(st.num(&fifty), "1/50 = 0.02");
        let approx = Shown {
            value: 0.41421356,
            exact: None,
            pretty: None,
            beyond: None,
        };
        assert_eq!(st.num(&approx), "≈ 0.4142");
    }

    /// bottom = −top with top = 0.1·tan 20° (no exact form in square
    /// roots): the substitution −0.0364 reads as the value itself, so the
    /// line is the value alone, `≈` after the name, and no `= ≈` with an
    /// empty exact form between them.
    #[test]
    fn a_substitution_that_reads_as_its_value_leaves_no_empty_exact_form() {
        let top = 0.1 * 20f64.to_radians().tan();
        let approx = |value: f64| {
            Val::Num(Shown {
                value,
                exact: None,
                pretty: None,
                beyond: None,
            })
        };
        for (lang, want) in [
            (lang::Lang::En, "bottom ≈ −0.0364"),
            (lang::Lang::Id, "bottom ≈ −0,0364"),
        ] {
            let st = Style::new(4, true, lang);
            let sub = Subst::new("−{}", vec![approx(top)]);
            assert_eq!(st.worked("bottom", &sub, &approx(-top)), want);
        }
        // an exact value whose substitution is itself keeps its one `=`
        let st = Style::new(4, true, lang::Lang::En);
        let half = Val::Num(Shown {
            value: 0.5,
            exact: Some("1/2".into()),
            pretty: Some("1/2".into()),
            beyond: None,
        });
        let sub = Subst::new("{}", vec![half.clone()]);
        assert_eq!(st.worked("t", &sub, &half), "t = 1/2 = 0.5");
    }

    #[test]
    fn a_vector_beyond_the_doubles_shows_its_exact_forms_only() {
        // v = (1/10^400, 0): the nearest doubles are (0, 0), which would
        // read "(…) = (0, 0)".
        let st = Style::new(4, true, lang::Lang::En);
        let n = |value: f64, p: &str| {
            Val::Num(Shown {
                value,
                exact: Some(p.into()),
                pretty: Some(p.into()),
                beyond: None,
            })
        };
        let v = [n(0.0, "1/1000"), n(0.0, "0")];
        assert_eq!(st.list(&v), "(1/1000, 0)");
    }
}
