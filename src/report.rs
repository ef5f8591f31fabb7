//! Reports: the one place where steps and results become text (with tables
//! for matrices) or JSON (SPEC §3). Stages only produce data.

use crate::num::{Precision, Shown};
use crate::trace::{Step, Val};
use comfy_table::{presets, Table};
use serde_json::{json, Map, Value};

/// Everything a command produced.
#[derive(Clone, Debug)]
pub struct Report {
    /// The subcommand.
    pub command: String,
    /// The parsed inputs, as JSON.
    pub input: Value,
    /// The named results.
    pub result: Vec<(String, Val)>,
    /// The worked steps.
    pub steps: Vec<Step>,
    /// Warnings (also on stderr).
    pub warnings: Vec<String>,
    /// Extra lines printed after the answer in text mode (e.g. comparison
    /// with the text's printed answers), and given as `"notes"` in JSON.
    pub notes: Vec<String>,
    /// The precision used.
    pub precision: Precision,
    /// Further top-level JSON keys (e.g. `comparison` with the printed answers).
    pub extra: Map<String, Value>,
}

/// How numbers are written in text output.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    /// Significant digits of decimals.
    pub digits: usize,
    /// Whether the run was exact (approximate values are then marked ≈).
    pub exact_mode: bool,
}

/// A decimal with `digits` significant digits, trailing zeros trimmed,
/// scientific notation for very large or small magnitudes.
pub fn fmt_dec(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let digits = digits.clamp(1, 17);
    let mag = x.abs().log10().floor() as i32;
    if !(-5..=9).contains(&mag) {
        let s = format!("{:.*e}", digits - 1, x);
        // trim zeros in the mantissa
        if let Some((m, e)) = s.split_once('e') {
            let m = if m.contains('.') {
                m.trim_end_matches('0').trim_end_matches('.')
            } else {
                m
            };
            return format!("{m}e{e}");
        }
        return s;
    }
    let decimals = (digits as i32 - 1 - mag).max(0) as usize;
    let s = format!("{:.*}", decimals, x);
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

impl Style {
    /// One number: `−√2/60 ≈ −0.02357`, `1/50 = 0.02`, `5`, `≈ 0.4142`, `0.4142`.
    pub fn num(&self, s: &Shown) -> String {
        let dec = fmt_dec(s.value, self.digits);
        match &s.pretty {
            Some(p) if is_plain_decimal(p) => p.replace('-', "−"),
            Some(p) => {
                let sep = if dec.parse::<f64>().ok() == Some(s.value) {
                    "="
                } else {
                    "≈"
                };
                format!("{p} {sep} {}", dec.replace('-', "−"))
            }
            None if self.exact_mode && dec.parse::<f64>().ok() != Some(s.value) => {
                format!("≈ {}", dec.replace('-', "−"))
            }
            None => dec.replace('-', "−"),
        }
    }

    /// A vector or list: `(√2/2, 0, √2/2) ≈ (0.7071, 0, 0.7071)`.
    pub fn list(&self, items: &[Val]) -> String {
        let nums: Option<Vec<&Shown>> = items
            .iter()
            .map(|v| if let Val::Num(s) = v { Some(s) } else { None })
            .collect();
        match nums {
            Some(ns) => {
                let has_form = ns
                    .iter()
                    .any(|s| s.pretty.as_deref().is_some_and(|p| !is_plain_decimal(p)));
                let decs: Vec<String> = ns
                    .iter()
                    .map(|s| fmt_dec(s.value, self.digits).replace('-', "−"))
                    .collect();
                let approx = ns
                    .iter()
                    .any(|s| fmt_dec(s.value, self.digits).parse::<f64>().ok() != Some(s.value));
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
            Val::Bool(b) => if *b { "yes" } else { "no" }.into(),
            Val::Null => "none".into(),
        }
    }

    /// A matrix as a table; exact forms in the cells when there are any.
    pub fn matrix(&self, rows: &[Val]) -> String {
        let mut t = Table::new();
        t.load_preset(presets::UTF8_FULL_CONDENSED);
        for r in rows {
            if let Val::List(cells) = r {
                t.add_row(cells.iter().map(|c| match c {
                    Val::Num(s) => match &s.pretty {
                        Some(p) => p.replace('-', "−"),
                        None => fmt_dec(s.value, self.digits).replace('-', "−"),
                    },
                    other => self.val_inline(other),
                }));
            }
        }
        t.to_string()
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
            format!("{indent}{name} = {}", self.val_inline(v))
        }
    }
}

/// Whether an exact form is just a terminating decimal or integer (so the
/// decimal adds nothing).
fn is_plain_decimal(p: &str) -> bool {
    let p = p.trim_start_matches(['-', '−']);
    !p.is_empty() && p.chars().all(|c| c.is_ascii_digit() || c == '.')
}

impl Report {
    /// The worked solution and answer as text.
    pub fn to_text(&self, style: &Style) -> String {
        let mut out = String::new();
        let mut section: Option<&str> = None;
        for (i, s) in self.steps.iter().enumerate() {
            if s.section.as_deref() != section {
                section = s.section.as_deref();
                if let Some(sec) = section {
                    out.push_str(&format!("\n== {sec} ==\n"));
                }
            }
            out.push_str(&format!("\nStep {}. {}\n", i + 1, s.title));
            if !s.formula.is_empty() {
                out.push_str(&format!("    {}\n", s.formula));
            }
            for (k, v) in &s.values {
                out.push_str(&style.named("    ", k, v));
                out.push('\n');
            }
            for (k, v) in &s.result {
                out.push_str(&style.named("  ⇒ ", k, v));
                out.push('\n');
            }
            if let Some(n) = &s.note {
                out.push_str(&format!("    ({n})\n"));
            }
        }
        out.push_str("\nAnswer\n");
        for (k, v) in &self.result {
            push_answer(&mut out, style, "  ", k, v);
        }
        for n in &self.notes {
            out.push_str(&format!("\n{n}\n"));
        }
        for w in &self.warnings {
            out.push_str(&format!("\nwarning: {w}\n"));
        }
        out
    }

    /// The SPEC §3 JSON object.
    pub fn to_json(&self) -> Value {
        let result = Value::Object(
            self.result
                .iter()
                .map(|(k, v)| (k.clone(), value_json(v)))
                .collect(),
        );
        let exact = Value::Object(
            self.result
                .iter()
                .map(|(k, v)| (k.clone(), exact_json(v)))
                .collect(),
        );
        let steps: Vec<Value> = self.steps.iter().map(step_json).collect();
        let mut obj = json!({
            "command": self.command,
            "precision": self.precision,
            "input": self.input,
            "result": result,
            "exact": exact,
            "steps": steps,
            "warnings": self.warnings,
        });
        if !self.notes.is_empty() {
            obj["notes"] = json!(self.notes);
        }
        for (k, v) in &self.extra {
            obj[k] = v.clone();
        }
        obj
    }
}

/// Writes one answer, opening maps (e.g. points) into one line per entry.
fn push_answer(out: &mut String, style: &Style, indent: &str, k: &str, v: &Val) {
    match v {
        Val::Map(kv) => {
            out.push_str(&format!("{indent}{k}:\n"));
            for (k2, v2) in kv {
                push_answer(out, style, &format!("{indent}  "), k2, v2);
            }
        }
        _ => {
            out.push_str(&style.named(indent, k, v));
            out.push('\n');
        }
    }
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
        Val::Bool(b) => Value::Bool(*b),
        Val::Null => Value::Null,
    }
}

fn step_json(s: &Step) -> Value {
    let obj = |kv: &[(String, Val)], f: fn(&Val) -> Value| {
        Value::Object(kv.iter().map(|(k, v)| (k.clone(), f(v))).collect())
    };
    let mut o = json!({
        "title": s.title,
        "formula": s.formula,
        "values": obj(&s.values, value_json),
        "result": obj(&s.result, value_json),
        "exact": { "values": obj(&s.values, exact_json), "result": obj(&s.result, exact_json) },
    });
    if let Some(sec) = &s.section {
        o["section"] = json!(sec);
    }
    if let Some(n) = &s.note {
        o["note"] = json!(n);
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
        let st = Style {
            digits: 4,
            exact_mode: true,
        };
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
}
