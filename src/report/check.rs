//! A marking as text (a table, the diagnosis, the score) or as JSON for
//! autograders.

use crate::report::lang::Lang;
use crate::report::words::words;
use crate::report::{exact_json, value_json, Style};
use crate::tutor::check::{Marking, Verdict};
use serde_json::{json, Value};

/// The marking as JSON for autograders.
pub fn to_json(m: &Marking, lang: Lang) -> Value {
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
                "note": words(&a.note, lang),
                "diagnosis": a.diagnosis,
                "why": a.why.as_ref().map(|w| words(w, lang)),
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
            "code": d.mistake.code, "mistake": crate::report::mistakes::mistake_text(d.mistake, lang), "keys": d.keys,
            "also": d.also.iter().map(|a| a.code).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "unknown_keys": m.unknown,
    })
}

/// A verdict's words.
fn verdict_words(v: Verdict, lang: Lang) -> String {
    match (v, lang) {
        (_, Lang::En) => v.as_str().replace('_', " "),
        (Verdict::Correct, Lang::Id) => "benar".into(),
        (Verdict::TooCoarse, Lang::Id) => "terlalu kasar".into(),
        (Verdict::Wrong, Lang::Id) => "salah".into(),
        (Verdict::Missing, Lang::Id) => "tidak dijawab".into(),
        (Verdict::Unparseable, Lang::Id) => "tidak terbaca".into(),
    }
}

/// The marking as text: a table of answers, the mistakes found, the score.
pub fn to_text(m: &Marking, style: &Style) -> String {
    use comfy_table::{presets, ContentArrangement, Table};
    let t_ = |en, id| style.tr(en, id);
    let mut t = Table::new();
    t.load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_width(120)
        .set_header(vec![
            t_("answer", "jawaban"),
            t_("verdict", "penilaian"),
            t_("given", "diberikan"),
            t_("expected", "seharusnya"),
            t_("note", "catatan"),
        ]);
    for a in &m.answers {
        t.add_row(vec![
            a.key.clone(),
            verdict_words(a.verdict, style.lang),
            a.given.clone().unwrap_or_else(|| "—".into()),
            a.expected
                .as_ref()
                .map(|e| style.val_inline(e))
                .unwrap_or_default(),
            style.w(&a.note),
        ]);
    }
    let of = t_("answers of", "jawaban dari");
    let mut out = format!("{} — {of} {}\n{t}\n", m.title, m.who);
    let whys: Vec<String> = m
        .answers
        .iter()
        .filter_map(|a| (a.why.as_ref()).map(|w| format!("  • {}: {}\n", a.key, style.w(w))))
        .collect();
    if !whys.is_empty() {
        out.push_str(t_(
            "\nWhy the printed answers differ (the problem file's errata):\n",
            "\nMengapa jawaban yang tercetak berbeda (errata dalam berkas soal):\n",
        ));
        out.push_str(&whys.concat());
    }
    out.push_str(&diagnoses_text(m, style));
    out.push_str(&score_text(m, style));
    out
}

/// The mistakes found, the wrong answers no mistake explains, the unknown keys.
fn diagnoses_text(m: &Marking, style: &Style) -> String {
    let t_ = |en, id| style.tr(en, id);
    let mut out = String::new();
    if !m.diagnoses.is_empty() {
        out.push_str(t_("\nDiagnosis:\n", "\nDiagnosis:\n"));
        for d in &m.diagnoses {
            out.push_str(&format!(
                "  • {} [{}]\n    {}: {}\n",
                crate::report::mistakes::mistake_text(d.mistake, style.lang),
                d.mistake.code,
                t_("reproduces", "menghasilkan ulang"),
                d.keys.join(", ")
            ));
            for a in &d.also {
                out.push_str(&format!(
                    "    ({}: {} [{}])\n",
                    t_(
                        "some of these also follow from",
                        "sebagian juga dapat berasal dari"
                    ),
                    crate::report::mistakes::mistake_text(a, style.lang),
                    a.code
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
            "\n{} {}\n",
            t_(
                "No known mistake explains",
                "Tidak ada kesalahan yang dikenal yang menjelaskan"
            ),
            undiagnosed.join(", "),
        ));
    }
    if !m.unknown.is_empty() {
        out.push_str(&format!(
            "\n{}: {}\n",
            t_(
                "Not answers to this problem (ignored)",
                "Bukan jawaban untuk soal ini (diabaikan)"
            ),
            m.unknown.join(", ")
        ));
    }
    out
}

/// The score line.
fn score_text(m: &Marking, style: &Style) -> String {
    let c = |v| m.count(v);
    let score = style.dec(crate::report::fmt_dec(m.score(), 4));
    let verdicts = [
        Verdict::Correct,
        Verdict::TooCoarse,
        Verdict::Wrong,
        Verdict::Missing,
        Verdict::Unparseable,
    ];
    let words = match style.lang {
        Lang::En => ["correct", "too coarse", "wrong", "missing", "unparseable"],
        Lang::Id => [
            "benar",
            "terlalu kasar",
            "salah",
            "tidak dijawab",
            "tidak terbaca",
        ],
    };
    let counts: Vec<String> = (verdicts.iter().zip(words))
        .map(|(v, w)| format!("{} {w}", c(*v)))
        .collect();
    let score = format!(
        "\n{}: {score}/{} ({})\n",
        style.tr("Score", "Nilai"),
        m.total(),
        counts.join(", ")
    );
    let n = m.follow_through();
    match (n, style.lang) {
        (0, _) => score,
        (_, Lang::En) => score + &format!("({n} of the correct answers by follow-through: right given the student's own earlier answers)\n"),
        (_, Lang::Id) => score + &format!("({n} jawaban benar karena follow-through: benar menurut jawaban mahasiswa sendiri sebelumnya)\n"),
    }
}
