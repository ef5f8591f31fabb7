//! A marking as text (a table, the diagnosis, the score) or as JSON for
//! autograders.

use crate::report::lang::Lang;
use crate::report::{exact_json, value_json, Style};
use crate::tutor::check::{Marking, Verdict};
use serde_json::{json, Value};

/// The marking as JSON for autograders.
pub fn to_json(m: &Marking) -> Value {
    let answers: Vec<Value> = m
        .answers
        .iter()
        .map(|a| {
            json!({
                "key": a.key,
                "verdict": a.verdict.as_str(),
                "code": a.code,
                "given": a.given_value.as_ref().and_then(|g| serde_json::to_value(g).ok()),
                "expected": a.expected.as_ref().map(|e| json!({ "decimal": value_json(e), "exact": exact_json(e) })),
                "note": a.note,
                "diagnosis": a.diagnosis,
                "why": a.why,
            })
        })
        .collect();
    json!({
        "command": "check",
        "title": m.title,
        "who": m.who,
        "settings": { "tolerance": m.settings.tolerance, "sig_figs": m.settings.sig_figs,
                      "follow_through": m.settings.follow_through },
        "score": { "points": m.score(), "total": m.total(),
                   "fraction": if m.total() == 0 { 1.0 } else { m.score() / m.total() as f64 } },
        "counts": {
            "correct": m.count(Verdict::Correct), "too_coarse": m.count(Verdict::TooCoarse),
            "wrong": m.count(Verdict::Wrong), "missing": m.count(Verdict::Missing),
            "unparseable": m.count(Verdict::Unparseable),
            "follow_through": m.follow_through(),
        },
        "answers": answers,
        "diagnosis": m.diagnoses.iter().map(|d| json!({
            "code": d.mistake.code, "mistake": d.mistake.description, "keys": d.keys,
            "also": d.also.iter().map(|a| a.code).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "unknown_keys": m.unknown,
    })
}

/// The marking as text: a table of answers, the mistakes found, the score.
pub fn to_text(m: &Marking, style: &Style) -> String {
    use comfy_table::{presets, ContentArrangement, Table};
    let mut t = Table::new();
    t.load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_width(120)
        .set_header(vec!["answer", "verdict", "given", "expected", "note"]);
    for a in &m.answers {
        t.add_row(vec![
            a.key.clone(),
            a.verdict.as_str().replace('_', " "),
            a.given.clone().unwrap_or_else(|| "—".into()),
            a.expected
                .as_ref()
                .map(|e| style.val_inline(e))
                .unwrap_or_default(),
            a.note.clone(),
        ]);
    }
    let mut out = format!("{} — answers of {}\n{t}\n", m.title, m.who);
    let whys: Vec<String> = m
        .answers
        .iter()
        .filter_map(|a| a.why.as_ref().map(|w| format!("  • {}: {w}\n", a.key)))
        .collect();
    if !whys.is_empty() {
        out.push_str("\nWhy the printed answers are wrong (the problem file's errata):\n");
        out.push_str(&whys.concat());
    }
    if !m.diagnoses.is_empty() {
        out.push_str("\nDiagnosis:\n");
        for d in &m.diagnoses {
            out.push_str(&format!(
                "  • {} [{}]\n    reproduces: {}\n",
                d.mistake.description,
                d.mistake.code,
                d.keys.join(", ")
            ));
            for a in &d.also {
                out.push_str(&format!(
                    "    (some of these also follow from: {} [{}])\n",
                    a.description, a.code
                ));
            }
        }
    }
    let undiagnosed: Vec<&str> = m
        .answers
        .iter()
        .filter(|a| a.verdict == Verdict::Wrong && a.diagnosis.is_empty())
        .map(|a| a.key.as_str())
        .collect();
    if !undiagnosed.is_empty() {
        out.push_str(&format!(
            "\nNo known mistake reproduces: {} (an arithmetic slip?)\n",
            undiagnosed.join(", ")
        ));
    }
    if !m.unknown.is_empty() {
        out.push_str(&format!(
            "\nNot answers to this problem (ignored): {}\n",
            m.unknown.join(", ")
        ));
    }
    out.push_str(&format!(
        "\nScore: {}/{} ({} correct, {} too coarse, {} wrong, {} missing, {} unparseable)\n",
        crate::report::fmt_dec(m.score(), 4),
        m.total(),
        m.count(Verdict::Correct),
        m.count(Verdict::TooCoarse),
        m.count(Verdict::Wrong),
        m.count(Verdict::Missing),
        m.count(Verdict::Unparseable)
    ));
    if m.follow_through() > 0 {
        let n = m.follow_through();
        out.push_str(&match style.lang {
            Lang::En => format!("({n} of the correct answers by follow-through: right given the student's own earlier answers)\n"),
            Lang::Id => format!("({n} jawaban benar karena follow-through: benar menurut jawaban siswa sendiri sebelumnya)\n"),
        });
    }
    out
}
