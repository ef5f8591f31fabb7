//! Reports: the one place where steps and results become text (with tables
//! for matrices) or JSON (docs/spec.md §3). Stages only produce data.

pub mod bench;
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
pub mod page;
pub mod practice;
pub mod render;
pub mod sheets;
pub mod words;

use crate::msg::Msg;
use crate::num::Shown;
use crate::stages::trace::{Step, Val};
use crate::tutor::solution::{Asked, Compared, Comparison, Report};
use comfy_table::{presets, Table};
use lang::{tr, Lang};
use serde_json::{json, Map, Value};

/// How numbers are written in text output.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    /// Significant digits of decimals.
    pub digits: usize,
    /// Whether the run was exact (approximate values are then marked ≈).
    pub exact_mode: bool,
    /// The language of the words (and the decimal mark).
    pub lang: Lang,
}

impl Style {
    /// `digits` significant digits, approximate values marked ≈ when `exact_mode`, in `lang`.
    pub fn new(digits: usize, exact_mode: bool, lang: Lang) -> Style {
        Style {
            digits,
            exact_mode,
            lang,
        }
    }
}

pub use crate::num::format::fmt_dec;

impl Style {
    /// The words of a message key in this style's language.
    pub fn w(&self, m: &Msg) -> String {
        words::words(m, self.lang)
    }
    /// English or Indonesian, by this style's language.
    pub fn tr<'a>(&self, en: &'a str, id: &'a str) -> &'a str {
        tr(self.lang, en, id)
    }
    /// Decimal numbers in this style's language: `0.5` → `0,5` and list
    /// separators `, ` → `; ` in Indonesian (so `(0,8; 0,6; 0)` reads
    /// unambiguously); English text is unchanged.
    pub fn dec(&self, s: String) -> String {
        match self.lang {
            Lang::En => s,
            Lang::Id => s.replace(", ", "; ").replace('.', ","),
        }
    }
}

impl Style {
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
                    .map(|s| fmt_dec(s.value, self.digits).replace('-', "−"))
                    .collect();
                let approx = ns
                    .iter()
                    .any(|s| fmt_dec(s.value, self.digits).parse::<f64>().ok() != Some(s.value));
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
            None => format!(
                "({})",
                items
                    .iter()
                    .map(|v| self.val_inline(v))
                    .collect::<Vec<_>>()
                    .join(", ")
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
            Val::Bool(b) => if *b {
                self.tr("yes", "ya")
            } else {
                self.tr("no", "tidak")
            }
            .into(),
            Val::Null => self.tr("none", "tidak ada").into(),
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
                        None => fmt_dec(s.value, self.digits).replace('-', "−"),
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
        let name = |k: &str| words::labels::label(k, self.lang);
        for (k, v) in &s.values {
            out.push_str(&self.named("    ", &name(k), v));
            out.push('\n');
        }
        for (k, v) in &s.result {
            out.push_str(&self.named("  ⇒ ", &name(k), v));
            out.push('\n');
        }
        if let Some(n) = &s.note {
            out.push_str(&format!("    ({})\n", self.w(n)));
        }
        out
    }

    /// `name = value`, with a matrix on its own lines.
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
    /// The named results the answer shows: a render's summary, else the
    /// results.
    pub fn answer(&self) -> std::borrow::Cow<'_, [(String, Val)]> {
        match &self.asked {
            Asked::Render(run) => std::borrow::Cow::Owned(render::summary(run)),
            _ => std::borrow::Cow::Borrowed(&self.result),
        }
    }

    /// The worked solution and answer as text.
    pub fn to_text(&self, style: &Style) -> String {
        let mut out = String::new();
        let mut section: Option<&Msg> = None;
        let step_word = style.tr("Step", "Langkah");
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
        out.push_str(&format!("\n{}\n", style.tr("Answer", "Jawaban")));
        for (k, v) in self.answer().iter() {
            let k = match &self.asked {
                Asked::Render(_) => render::label(k, style.lang),
                _ => k.clone(),
            };
            push_answer(&mut out, style, "  ", &k, v);
        }
        for n in self.all_notes(style) {
            out.push_str(&format!("\n{n}\n"));
        }
        for w in &self.warnings {
            let label = style.tr("warning", "peringatan");
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

    /// The notes after the answer: the report's own, the comparison with
    /// the printed answers, the notes on the source.
    fn all_notes(&self, style: &Style) -> Vec<String> {
        let mut notes = Vec::new();
        if let Asked::Render(run) = &self.asked {
            notes.extend(run.stats_asked.then(|| render::stats_text(run, style.lang)));
        }
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
            let head = style.tr("Notes on the source", "Catatan tentang sumber");
            notes.push(format!("{head}:\n{}", lines.join("\n")));
        }
        notes
    }
}

/// The comparison with the printed answers, one line per answer.
fn comparison_text(c: &Comparison, lang: Lang) -> String {
    let style = Style::new(4, true, lang);
    let t = |en, id| tr(lang, en, id);
    let src = c.source.as_deref().unwrap_or(t("the source", "sumber"));
    let head = t(
        "Compared with the answers printed in",
        "Dibandingkan dengan jawaban yang tercetak di",
    );
    let mut lines = vec![format!("{head} {src}:")];
    let printed = t("printed", "tercetak");
    for r in &c.rows {
        let (key, shown) = (&r.key, &r.printed);
        let why = (r.why.as_ref())
            .map(|w| format!(": {}", style.w(w)))
            .unwrap_or_default();
        lines.push(match (&r.computed, r.agrees) {
            (None, _) => format!(
                "  {key}: {printed} {shown} — {}",
                t(
                    "not computed in this run (not asked for)",
                    "tidak dihitung pada jalannya program ini (tidak diminta)"
                )
            ),
            (Some(_), Some(true)) => {
                format!("  {key}: {printed} {shown} — {}", t("agrees", "sesuai"))
            }
            (Some(v), Some(false)) => format!(
                "  {key}: {printed} {shown}, {} {} — {}{why}",
                t("correct", "yang benar"),
                style.val_inline(v),
                t("the text is WRONG here", "teks SALAH di sini")
            ),
            (Some(v), None) => format!(
                "  {key}: {printed} {shown}, {} {} — {}",
                t("computed", "hasil hitung"),
                style.val_inline(v),
                t("cannot be compared", "tidak dapat dibandingkan")
            ),
        });
    }
    lines.join("\n")
}

/// One compared answer as JSON.
fn compared_json(r: &Compared, lang: Lang) -> Value {
    json!({
        "key": r.key,
        "printed": r.printed,
        "computed": r.computed.as_ref().map(value_json),
        "agrees": r.agrees,
        "why": r.why.as_ref().map(|w| crate::report::words::words(w, lang)),
    })
}

/// Writes one answer, opening maps (e.g. points) into one line per entry
/// and a list of maps (the segments of a clip) into one numbered block per
/// map, `clip[1]:`, `clip[2]:`, …; an empty map is `none`.
fn push_answer(out: &mut String, style: &Style, indent: &str, k: &str, v: &Val) {
    match v {
        Val::Map(kv) if kv.is_empty() => {
            out.push_str(&style.named(indent, k, &Val::Null));
            out.push('\n');
        }
        Val::List(items) if is_list_of_maps(items) => {
            for (i, item) in items.iter().enumerate() {
                push_answer(out, style, indent, &format!("{k}[{}]", i + 1), item);
            }
        }
        Val::Map(kv) => {
            out.push_str(&format!("{indent}{k}:\n"));
            for (k2, v2) in kv {
                push_answer(out, style, &format!("{indent}  "), k2, v2);
            }
        }
        // A clipping status is a code (check compares it); the text
        // glosses it in the chosen language.
        Val::Text(t) if k == "status" => {
            let said = Val::said(crate::msg::Said::Status(t.clone()));
            out.push_str(&style.named(indent, k, &said));
            out.push('\n');
        }
        _ => {
            out.push_str(&style.named(indent, k, v));
            out.push('\n');
        }
    }
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
    let obj = |kv: &[(String, Val)], f: fn(&Val) -> Value| {
        Value::Object(kv.iter().map(|(k, v)| (k.clone(), f(v))).collect())
    };
    let mut o = json!({
        "title": w(&s.title),
        "formula": w(&s.formula),
        "values": obj(&s.values, value_json),
        "result": obj(&s.result, value_json),
        "exact": { "values": obj(&s.values, exact_json), "result": obj(&s.result, exact_json) },
    });
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
        };
        assert_eq!(st.num(&s), "−√2/60 ≈ −0.02357");
        let fifty = Shown {
            value: 0.02,
            exact: Some("1/50".into()),
            pretty: Some("1/50".into()),
        };
        assert_eq!(st.num(&fifty), "1/50 = 0.02");
        let approx = Shown {
            value: 0.41421356,
            exact: None,
            pretty: None,
        };
        assert_eq!(st.num(&approx), "≈ 0.4142");
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
            })
        };
        let v = [n(0.0, "1/1000"), n(0.0, "0")];
        assert_eq!(st.list(&v), "(1/1000, 0)");
    }
}
