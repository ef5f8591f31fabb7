//! The class report as a document for people, HTML or Markdown
//! ([`crate::report::doc::Doc`]): the summary, the key table with the
//! definitions of its indices, per problem and variant, the mistakes, the
//! wrong answers no mistake explains, the students with the histogram.

use super::histogram;
use crate::msg::{CheckWord, ClassWord as C, DocWord};
use crate::report::doc::Doc;
use crate::report::lang::Lang;
use crate::report::mistakes::mistake_text;
use crate::report::words;
use crate::report::words::report::dec;
use crate::report::Style;
use crate::tutor::check::Settings;
use crate::tutor::check::Verdict;
use crate::tutor::class::stats::{compare, Gap, MistakeStats, Stats, StepRef, VariantProblem};
use crate::tutor::class::Class;

/// A share or an index with two decimals, in the language's decimal mark,
/// a negative one with the minus sign.
fn num(x: Option<f64>, lang: Lang) -> String {
    x.map_or("—".to_string(), |x| {
        // −0.001 is written 0.00, not −0.00
        let x = if x.abs() < 0.005 { 0.0 } else { x };
        crate::report::words::of(lang)
            .nums()
            .fixed(x, 2)
            .replacen('-', "−", 1)
    })
}

/// The class report's word `w` in `lang`.
fn w(lang: Lang, w: C) -> String {
    words::of(lang).class(&w)
}

/// The column of an exam's variant, escaped.
fn variant(doc: Doc, lang: Lang) -> String {
    esc(doc, &words::of(lang).doc(&DocWord::Variant))
}

/// The cells of a table's header, escaped.
fn header(doc: Doc, lang: Lang, keys: impl IntoIterator<Item = C>) -> Vec<String> {
    keys.into_iter().map(|k| esc(doc, &w(lang, k))).collect()
}

/// Text for a cell of either document: escaped; a line break (in a name)
/// becomes a space, so a Markdown table row stays one line.
fn esc(doc: Doc, s: &str) -> String {
    let one_line: String = s
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    match doc {
        Doc::Markdown => doc.text(&one_line).replace('<', "&lt;"),
        _ => doc.text(&one_line),
    }
}

fn para(doc: Doc, s: &str) -> String {
    match doc {
        Doc::Html => format!("<p>{s}</p>\n"),
        _ => format!("{s}\n\n"),
    }
}

/// A table; the cells already escaped.
fn table(doc: Doc, header: &[String], rows: &[Vec<String>]) -> String {
    match doc {
        Doc::Html => {
            let th: String = header.iter().map(|h| format!("<th>{h}</th>")).collect();
            let body: String = rows
                .iter()
                .map(|r| {
                    format!(
                        "<tr>{}</tr>\n",
                        r.iter()
                            .map(|c| format!("<td>{c}</td>"))
                            .collect::<String>()
                    )
                })
                .collect();
            format!("<table class=\"class\">\n<thead><tr>{th}</tr></thead>\n<tbody>\n{body}</tbody>\n</table>\n")
        }
        _ => {
            let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
            let rule = vec!["---".to_string(); header.len()];
            let mut out = line(header) + &line(&rule);
            for r in rows {
                out.push_str(&line(r));
            }
            out + "\n"
        }
    }
}

fn list(doc: Doc, items: &[String]) -> String {
    match doc {
        Doc::Html => format!(
            "<ul>\n{}</ul>\n",
            items
                .iter()
                .map(|i| format!("<li>{i}</li>\n"))
                .collect::<String>()
        ),
        _ => items.iter().map(|i| format!("- {i}\n")).collect::<String>() + "\n",
    }
}

/// The style of the report's tables: small enough that the key table
/// (12 columns) fits the width of A4 in print.
const CSS: &str = "<style>body{max-width:60rem}table.class{border-collapse:collapse;margin:.5rem 0;font-size:.9rem}\
table.class th,table.class td{border:1px solid #999;padding:.15rem .4rem;text-align:left;vertical-align:top}\
table.class td{white-space:nowrap}table.class td:last-child{white-space:normal}\
table.class td.n{text-align:right}.flag{color:#D55E00;font-weight:bold}\
@media print{body{font-size:10pt}h2,h3{break-after:avoid}table.class{font-size:8pt;break-inside:auto}table.class tr{break-inside:avoid}}</style>\n";

/// The whole document: summary, keys, problems and variants, mistakes,
/// unexplained wrong answers, students.
pub(crate) fn document(
    doc: Doc,
    class: &Class,
    s: &Stats,
    settings: &Settings,
    st: &Style,
) -> String {
    let lang = st.lang;
    let title = format!("{}: {}", w(lang, C::ClassReport), class.title);
    let mut body = if doc == Doc::Html {
        CSS.to_string()
    } else {
        String::new()
    };
    body.push_str(&summary(doc, class, s, settings, lang));
    body.push_str(&roster_section(doc, class, lang));
    body.push_str(&duplicates_section(doc, class, lang));
    body.push_str(&fits_section(doc, class, lang));
    body.push_str(&keys_section(doc, s, lang));
    body.push_str(&exam_section(doc, s, lang));
    body.push_str(&mistakes_section(doc, s, st));
    body.push_str(&wrong_section(doc, s, st));
    body.push_str(&students_section(doc, class, s, lang));
    doc.document(&title, &body, lang)
}

fn summary(doc: Doc, class: &Class, s: &Stats, settings: &Settings, lang: Lang) -> String {
    let said = C::Summary {
        students: s.students,
        tolerance_pct: settings.tolerance * 100.0,
        sig_figs: settings.sig_figs,
        follow_through: settings.follow_through,
    };
    let mut out = para(doc, &esc(doc, &w(lang, said)));
    let failed: Vec<String> = class
        .sheets
        .iter()
        .filter_map(|sh| {
            let e = sh.outcome.as_ref().err()?;
            Some(esc(
                doc,
                &format!(
                    "{} ({}): {}",
                    sh.who,
                    sh.file.display(),
                    super::said(e, lang)
                ),
            ))
        })
        .collect();
    if !failed.is_empty() {
        out.push_str(&para(doc, &esc(doc, &w(lang, C::NotMarked))));
        out.push_str(&list(doc, &failed));
    }
    out
}

/// The class list against the files, with `--roster`.
fn roster_section(doc: Doc, class: &Class, lang: Lang) -> String {
    let lists = super::roster_lists(class, lang);
    if lists.is_empty() {
        return String::new();
    }
    let mut out = doc.heading(1, &w(lang, C::RosterHeading));
    for (head, names) in lists {
        out.push_str(&para(doc, &esc(doc, &head)));
        if !names.is_empty() {
            let items: Vec<String> = names.iter().map(|n| esc(doc, n)).collect();
            out.push_str(&list(doc, &items));
        }
    }
    out
}

/// A section of items under its heading, the note after them; nothing
/// when there are no items.
fn listed(doc: Doc, items: &[String], (heading, note): (C, C), lang: Lang) -> String {
    if items.is_empty() {
        return String::new();
    }
    let mut out = doc.heading(1, &w(lang, heading));
    out.push_str(&list(doc, items));
    out + &para(doc, &esc(doc, &w(lang, note)))
}

/// The files that are the same student as another, when there are any:
/// the rule, and each with the file kept.
fn duplicates_section(doc: Doc, class: &Class, lang: Lang) -> String {
    let items: Vec<String> = (class.sheets.iter())
        .filter_map(|sh| {
            let said = super::duplicate_words(sh, lang)?;
            Some(esc(
                doc,
                &format!("{} ({}): {said}", sh.who, sh.file.display()),
            ))
        })
        .collect();
    listed(doc, &items, (C::DuplicatesHeading, C::DuplicatesNote), lang)
}

/// The sheets whose answers fit another variant's key, when there are any.
fn fits_section(doc: Doc, class: &Class, lang: Lang) -> String {
    let items: Vec<String> = (class.sheets.iter())
        .filter(|sh| sh.duplicate.is_none())
        .filter_map(|sh| {
            let said = super::fits_words(sh, lang)?;
            let v = sh.variant.map_or(String::new(), |v| {
                format!(", {} {v}", words::of(lang).doc(&DocWord::Variant))
            });
            Some(esc(
                doc,
                &format!("{} ({}{v}): {said}", sh.who, sh.file.display()),
            ))
        })
        .collect();
    listed(doc, &items, (C::FitsHeading, C::FitsNote), lang)
}

/// The key table and the definitions of its indices.
fn keys_section(doc: Doc, s: &Stats, lang: Lang) -> String {
    let mut out = doc.heading(1, &w(lang, C::AnswerKeys));
    let verdict = |v: Verdict| esc(doc, words::of(lang).verdict(v));
    let mut head = header(doc, lang, [C::Key]);
    // correct (and how), follow-through, then the other verdict words
    let words = Verdict::words();
    head.push(verdict(Verdict::Exact));
    head.extend(header(doc, lang, [C::FollowThrough]));
    head.extend(words[1..].iter().map(|v| verdict(*v)));
    // the indices' letters are the same in every language
    head.extend(["p", "D", "r"].map(String::from));
    head.push(esc(doc, &w(lang, C::Flag)));
    let rows: Vec<Vec<String>> = s
        .keys
        .iter()
        .map(|k| {
            let c = |v: Verdict| k.count(v);
            let right = c(Verdict::Exact) + c(Verdict::Rounded) + c(Verdict::Tolerance);
            let flags: Vec<&str> = k.flags.iter().map(|f| words::of(lang).flag(*f)).collect();
            let flag = if flags.is_empty() {
                String::new()
            } else if doc == Doc::Html {
                format!(
                    "<span class=\"flag\">{}</span>",
                    esc(doc, &flags.join("; "))
                )
            } else {
                format!("**{}**", esc(doc, &flags.join("; ")))
            };
            let mut row = vec![
                esc(doc, &k.key.to_string()),
                format!(
                    "{right} ({}/{}/{})",
                    c(Verdict::Exact),
                    c(Verdict::Rounded),
                    c(Verdict::Tolerance)
                ),
                c(Verdict::FollowThrough).to_string(),
            ];
            row.extend(words[1..].iter().map(|v| c(*v).to_string()));
            row.extend([
                num(Some(k.facility), lang),
                num(k.discrimination, lang),
                num(k.point_biserial, lang),
                flag,
            ]);
            row
        })
        .collect();
    out.push_str(&table(doc, &head, &rows));
    out.push_str(&para(doc, &esc(doc, &w(lang, C::Definitions))));
    out
}

/// Per problem and per variant (an exam only).
fn exam_section(doc: Doc, s: &Stats, lang: Lang) -> String {
    if s.variants.is_empty() && s.problems.iter().all(|p| p.name.is_empty()) {
        return String::new();
    }
    let mut out = doc.heading(1, &w(lang, C::Problems));
    let head = header(doc, lang, [C::Problem, C::Title, C::Students, C::Facility]);
    let rows: Vec<Vec<String>> = s
        .problems
        .iter()
        .map(|p| {
            vec![
                esc(doc, &p.name),
                esc(doc, &p.title),
                p.students.to_string(),
                num(p.facility, lang),
            ]
        })
        .collect();
    out.push_str(&table(doc, &head, &rows));
    if s.variants.is_empty() {
        return out;
    }
    out.push_str(&doc.heading(1, &w(lang, C::Variants)));
    if let Some((min, max)) = s.too_few_per_variant() {
        let need = compare::MIN_STUDENTS;
        out.push_str(&para(
            doc,
            &esc(doc, &w(lang, C::TooFewPerVariant { min, max, need })),
        ));
    }
    let mut head = vec![variant(doc, lang), "n".to_string()];
    head.extend(header(doc, lang, [C::WholeExam]));
    head.extend(s.problems.iter().map(|p| esc(doc, &p.name)));
    let rows: Vec<Vec<String>> = s
        .variants
        .iter()
        .map(|v| {
            let mut row = vec![
                v.variant.to_string(),
                v.students.to_string(),
                num(v.facility, lang),
            ];
            row.extend(v.problems.iter().map(|c| variant_cell(doc, c, lang)));
            row
        })
        .collect();
    out.push_str(&table(doc, &head, &rows));
    out.push_str(&para(doc, &esc(doc, &w(lang, C::VariantsNote))));
    if s.drawn {
        out.push_str(&para(doc, &esc(doc, &w(lang, C::DrawnNote))));
    }
    out
}

/// A variant's facility on a problem, and when flagged, which way and the
/// corrected p: `0.20 ▼ harder (p = 0.003)`.
fn variant_cell(doc: Doc, c: &VariantProblem, lang: Lang) -> String {
    let mark = match (c.gap, c.p_value) {
        (Some(g), Some(p)) => {
            let (arrow, word) = match g {
                Gap::Harder => ("▼", C::Harder),
                Gap::Easier => ("▲", C::Easier),
            };
            format!(" {arrow} {} ({})", w(lang, word), p_words(p, lang))
        }
        _ => String::new(),
    };
    format!("{}{}", num(c.facility, lang), esc(doc, &mark))
}

/// A p-value as a report writes it: `p = 0.012`, or `p < 0.001`, in the
/// language's decimal mark.
fn p_words(p: f64, lang: Lang) -> String {
    let nums = crate::report::words::of(lang).nums();
    if p < 0.001 {
        format!("p < {}", nums.fixed(0.001, 3))
    } else {
        format!("p = {}", nums.fixed(p, 3))
    }
}

/// `step 16 of the worked solution: Window edges …` (an exam's:
/// `problem-02, step 3 …`), so a lecturer can reopen it with `grafika solve`.
fn step_words(step: &StepRef, st: &Style) -> String {
    let part = if step.part.is_empty() {
        String::new()
    } else {
        format!("{}, ", step.part)
    };
    let said = C::StepOf {
        part,
        number: step.number,
        title: st.w(&step.title),
    };
    w(st.lang, said)
}

/// Each mistake with its students, keys and step, the most students first.
fn mistakes_section(doc: Doc, s: &Stats, st: &Style) -> String {
    let lang = st.lang;
    let mut out = doc.heading(1, &w(lang, C::MistakesHeading));
    if s.mistakes.is_empty() {
        return out + &para(doc, &esc(doc, &w(lang, C::NoMistake)));
    }
    let items: Vec<String> = s
        .mistakes
        .iter()
        .map(|m| mistake_item(doc, m, st))
        .collect();
    out.push_str(&list(doc, &items));
    out
}

fn mistake_item(doc: Doc, m: &MistakeStats, st: &Style) -> String {
    let lang = st.lang;
    let n = m.students.len();
    let who = w(lang, C::StudentCount(n));
    let strong = |s: String| {
        if doc == Doc::Html {
            format!("<strong>{s}</strong>")
        } else {
            format!("**{s}**")
        }
    };
    let mut out = format!(
        "{} [{}] — {n} {who}: {}. {}: {}.",
        strong(esc(doc, mistake_text(m.mistake, lang))),
        esc(doc, m.mistake.as_str()),
        esc(doc, &m.students.join(", ")),
        esc(doc, &w(lang, C::Explains)),
        esc(doc, &crate::report::joined(&m.keys)),
    );
    if let Some(step) = &m.step {
        out.push_str(&format!(
            " {}: {}.",
            esc(doc, &w(lang, C::TeachAgain)),
            esc(doc, &step_words(step, st))
        ));
    }
    if !m.also.is_empty() {
        let codes: Vec<&str> = m.also.iter().map(|a| a.as_str()).collect();
        out.push_str(&format!(
            " ({}: {})",
            esc(doc, &words::of(lang).check(&CheckWord::AlsoFollow)),
            esc(doc, &codes.join(", "))
        ));
    }
    out
}

/// The wrong answers no mistake explains, per key.
fn wrong_section(doc: Doc, s: &Stats, st: &Style) -> String {
    let lang = st.lang;
    let mut out = doc.heading(1, &w(lang, C::WrongHeading));
    if s.wrong_answers.is_empty() {
        return out + &para(doc, &esc(doc, &w(lang, C::NoneFound)));
    }
    out.push_str(&para(doc, &esc(doc, &w(lang, C::WrongNote))));
    let check = |k: CheckWord| esc(doc, &words::of(lang).check(&k));
    let mut head = header(doc, lang, [C::Key]);
    head.extend([check(CheckWord::Expected), check(CheckWord::Given)]);
    head.extend(header(doc, lang, [C::Students]));
    let mut rows = Vec::new();
    for wa in &s.wrong_answers {
        let key = match wa.variant {
            Some(v) => format!(
                "{} ({} {v})",
                wa.key,
                words::of(lang).doc(&DocWord::Variant)
            ),
            None => wa.key.to_string(),
        };
        let expected = wa
            .expected
            .as_ref()
            .map(|e| st.val_inline(e))
            .unwrap_or_default();
        for (i, v) in wa.values.iter().enumerate() {
            let (k, e) = if i == 0 {
                (esc(doc, &key), esc(doc, &expected))
            } else {
                (String::new(), String::new())
            };
            rows.push(vec![
                k,
                e,
                esc(doc, &v.value),
                esc(
                    doc,
                    &format!("{} ({})", v.students.len(), v.students.join(", ")),
                ),
            ]);
        }
    }
    out.push_str(&table(doc, &head, &rows));
    out
}

/// The histogram, and the students grouped by the mistake they share.
fn students_section(doc: Doc, class: &Class, s: &Stats, lang: Lang) -> String {
    let mut out = doc.heading(1, &w(lang, C::StudentsHeading));
    out.push_str(&match doc {
        Doc::Html => crate::report::html::figure(
            &histogram::svg(&s.histogram, lang),
            &w(lang, C::DistributionPct),
        ),
        _ => format!("```\n{}```\n\n", histogram::text(&s.histogram)),
    });
    if !s.mistakes.is_empty() {
        out.push_str(&doc.heading(2, &w(lang, C::WhoWhich)));
        let head = header(doc, lang, [C::Mistake, C::Students]);
        let rows: Vec<Vec<String>> = s
            .mistakes
            .iter()
            .map(|m| {
                vec![
                    esc(doc, m.mistake.as_str()),
                    esc(doc, &m.students.join(", ")),
                ]
            })
            .collect();
        out.push_str(&table(doc, &head, &rows));
    }
    out.push_str(&doc.heading(2, &w(lang, C::Scores)));
    let mut head = header(doc, lang, [C::Student]);
    if class.exam {
        head.push(variant(doc, lang));
    }
    head.extend(header(doc, lang, [C::Score, C::Mistakes]));
    let rows: Vec<Vec<String>> = class
        .marked()
        .map(|sh| {
            let mut row = vec![esc(doc, &sh.who)];
            if class.exam {
                row.push(sh.variant_label());
            }
            let score = dec(sh.score().unwrap_or(0.0), 4, words::of(lang).nums());
            row.push(format!("{score}/{}", sh.total().unwrap_or(0)));
            let mut codes: Vec<String> = s
                .mistakes
                .iter()
                .filter(|m| m.students.contains(&sh.who))
                .map(|m| m.mistake.as_str().to_string())
                .collect();
            codes.extend(super::fits_words(sh, lang));
            row.push(esc(doc, &codes.join(" ")));
            row
        })
        .collect();
    out.push_str(&table(doc, &head, &rows));
    out
}
