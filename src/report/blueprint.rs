//! An exam's blueprint for people and scripts
//! ([`crate::tutor::generate::blueprint`]): a Markdown table, one row per
//! problem position (its case, the number class of its parts, its marks,
//! how many of its statements differ), then the range of each answer's
//! numbers over the variants; and the same as JSON (docs/spec.md §4).

use crate::msg::{DocWord, PlanWord as P};
use crate::report::json::as_map;
use crate::report::lang::Lang;
use crate::report::words;
use crate::report::words::report::dec;
use crate::report::Style;
use crate::tutor::generate::blueprint::{Blueprint, Position};
use crate::tutor::generate::form::Form;
use serde::Serialize;
use std::fmt::Write as _;

/// The words of a plan key in `lang`.
fn w(lang: Lang, k: P) -> String {
    words::of(lang).plan(&k)
}

/// A position's case in words: its points, its lighting model, its
/// clipping case, or a dash.
fn case(f: &Form, lang: Lang) -> String {
    if let Some(c) = f.clip {
        return w(
            lang,
            P::Clip {
                status: c.status.as_str().to_string(),
                bits: c.bits,
                tried: c.tried,
                kept: c.kept,
            },
        );
    }
    if let Some(m) = f.model {
        return w(lang, P::Model(m.name().to_string()));
    }
    match f.points {
        0 => "—".to_string(),
        n => w(lang, P::Points(n)),
    }
}

/// The number classes of a position's parts: `one surd`, or `view: one
/// surd; window: no closed form` when its parts differ.
fn classes(p: &Position, lang: Lang) -> String {
    let said =
        |c: &crate::tutor::generate::numbers::NumberClass| w(lang, P::Class(c.name().to_string()));
    let all_same = p.classes.windows(2).all(|x| x[0].1 == x[1].1);
    match p.classes.as_slice() {
        [] => "—".into(),
        [(_, c), ..] if all_same => said(c),
        many => (many.iter())
            .map(|(part, c)| format!("{}: {}", part.key(), said(c)))
            .collect::<Vec<_>>()
            .join("; "),
    }
}

/// One row of the table: problem, topic, case, numbers, marks,
/// statements.
fn row(i: usize, title: &str, p: &Position, n: usize, lang: Lang) -> [String; 6] {
    let of = |k| w(lang, P::OfVariants(k, n));
    let marks = if p.same_marks {
        format!("{} ({})", p.marks(), of(n))
    } else {
        format!("{} ({})", p.marks(), w(lang, P::MarksVary))
    };
    [
        (i + 1).to_string(),
        title.to_string(),
        case(&p.form, lang),
        format!("{} ({})", classes(p, lang), of(p.same_class)),
        marks,
        w(lang, P::Distinct(p.distinct, n)),
    ]
}

/// The blueprint as a Markdown table (printed by `generate`, and the
/// first part of blueprint.md); `titles`: each position's title.
pub fn table(bp: &Blueprint, titles: &[String], lang: Lang) -> String {
    let head = [
        words::of(lang).doc(&DocWord::Problem),
        w(lang, P::Topic),
        w(lang, P::Case),
        w(lang, P::Numbers),
        w(lang, P::Marks),
        w(lang, P::Statements),
    ];
    let line = |cells: &[String]| {
        let cells: Vec<String> = cells.iter().map(|c| c.replace('|', "\\|")).collect();
        format!("| {} |\n", cells.join(" | "))
    };
    let mut s = format!(
        "{}\n\n",
        w(
            lang,
            P::Heading {
                variants: bp.variants,
                total: bp.total()
            }
        )
    );
    s.push_str(&line(&head));
    s.push_str(&line(&head.map(|_| "---".to_string())));
    for (i, p) in bp.positions.iter().enumerate() {
        let title = titles.get(i).map_or("", String::as_str);
        s.push_str(&line(&row(i, title, p, bp.variants, lang)));
    }
    s
}

/// blueprint.md: the `table` ([`table`]), then per position the range of
/// each answer's numbers over the variants.
pub fn markdown(bp: &Blueprint, table: &str, st: &Style) -> String {
    let lang = st.lang;
    let mut s = format!("# {}\n\n", w(lang, P::Title));
    s.push_str(table);
    let _ = write!(s, "\n## {}\n\n", w(lang, P::Spread));
    for (i, p) in bp.positions.iter().enumerate() {
        let spans: Vec<String> = (p.spread.iter())
            .filter_map(|(k, span)| {
                let (lo, hi) = (*span)?;
                let num = |x: f64| dec(x, 4, st.nums()).replace('-', "−");
                Some(format!("`{k}` {} … {}", num(lo), num(hi)))
            })
            .collect();
        if !spans.is_empty() {
            let _ = writeln!(s, "{}. {}", i + 1, spans.join("; "));
        }
    }
    s
}

/// blueprint.json (docs/spec.md §4).
#[derive(Serialize)]
pub struct BlueprintJson {
    variants: usize,
    total: u32,
    positions: Vec<PositionJson>,
}

/// One position of the exam: its case, the number class of each part,
/// each key's marks, and the range of each answer's numbers.
#[derive(Serialize)]
struct PositionJson {
    problem: usize,
    topic: &'static str,
    case: Option<CaseJson>,
    #[serde(serialize_with = "as_map")]
    classes: Vec<(String, &'static str)>,
    same_class: usize,
    #[serde(serialize_with = "as_map")]
    marks: Vec<(String, u32)>,
    total: u32,
    same_marks: bool,
    distinct: usize,
    #[serde(serialize_with = "as_map")]
    spread: Vec<(String, Option<(f64, f64)>)>,
}

/// A position's case: its clipping case, its lighting model, or its
/// number of points.
#[derive(Serialize)]
#[serde(untagged)]
enum CaseJson {
    Clip {
        status: &'static str,
        bits: [u32; 2],
        tried: u32,
        kept: u32,
    },
    Model {
        model: &'static str,
    },
    Points {
        points: usize,
    },
}

/// blueprint.json; `topics`: each position's topic.
pub fn json(bp: &Blueprint, topics: &[&'static str]) -> BlueprintJson {
    BlueprintJson {
        variants: bp.variants,
        total: bp.total(),
        positions: (bp.positions.iter().enumerate())
            .map(|(i, p)| position_json(i, p, topics.get(i).copied().unwrap_or("")))
            .collect(),
    }
}

/// One position as JSON.
fn position_json(i: usize, p: &Position, topic: &'static str) -> PositionJson {
    let f = &p.form;
    let case = match (f.clip, f.model) {
        (Some(c), _) => Some(CaseJson::Clip {
            status: c.status.as_str(),
            bits: c.bits,
            tried: c.tried,
            kept: c.kept,
        }),
        (None, Some(m)) => Some(CaseJson::Model { model: m.name() }),
        (None, None) if f.points > 0 => Some(CaseJson::Points { points: f.points }),
        _ => None,
    };
    PositionJson {
        problem: i + 1,
        topic,
        case,
        classes: (p.classes.iter())
            .map(|(part, c)| (part.key(), c.name()))
            .collect(),
        same_class: p.same_class,
        marks: p.keys.iter().map(|(k, m)| (k.to_string(), *m)).collect(),
        total: p.marks(),
        same_marks: p.same_marks,
        distinct: p.distinct,
        spread: p.spread.iter().map(|(k, s)| (k.to_string(), *s)).collect(),
    }
}
