//! The class report as a document for people, HTML or Markdown
//! ([`crate::report::doc::Doc`]): the summary, the key table with the
//! definitions of its indices, per problem and variant, the mistakes, the
//! wrong answers no mistake explains, the students with the histogram.

use super::histogram;
use crate::report::doc::Doc;
use crate::report::lang::{tr, Lang};
use crate::report::mistakes::mistake_text;
use crate::report::Style;
use crate::tutor::check::Settings;
use crate::tutor::class::stats::{Flag, Gap, MistakeStats, Stats, StepRef};
use crate::tutor::class::Class;

/// A share or an index with two decimals, in the language's decimal mark,
/// a negative one with the minus sign.
fn num(x: Option<f64>, lang: Lang) -> String {
    x.map_or("—".to_string(), |x| {
        // −0.001 is written 0.00, not −0.00
        let x = if x.abs() < 0.005 { 0.0 } else { x };
        crate::report::words::of(lang)
            .nums()
            .number(&format!("{x:.2}"))
            .replacen('-', "−", 1)
    })
}

fn flag_words(f: Flag, lang: Lang) -> &'static str {
    match f {
        Flag::VeryEasy => tr(lang, "very easy", "sangat mudah"),
        Flag::VeryHard => tr(lang, "very hard", "sangat sulit"),
        Flag::Negative => tr(lang, "negative", "negatif"),
    }
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
pub(super) fn document(
    doc: Doc,
    class: &Class,
    s: &Stats,
    settings: &Settings,
    st: &Style,
) -> String {
    let lang = st.lang;
    let title = format!(
        "{}: {}",
        tr(lang, "Class report", "Laporan kelas"),
        class.title
    );
    let mut body = if doc == Doc::Html {
        CSS.to_string()
    } else {
        String::new()
    };
    body.push_str(&summary(doc, class, s, settings, lang));
    body.push_str(&keys_section(doc, s, lang));
    body.push_str(&exam_section(doc, s, lang));
    body.push_str(&mistakes_section(doc, s, st));
    body.push_str(&wrong_section(doc, s, st));
    body.push_str(&students_section(doc, class, s, lang));
    doc.document(&title, &body, lang)
}

fn summary(doc: Doc, class: &Class, s: &Stats, settings: &Settings, lang: Lang) -> String {
    let tol = crate::report::words::of(lang)
        .nums()
        .number(&crate::report::fmt_dec(settings.tolerance * 100.0, 4));
    let ft = if settings.follow_through {
        tr(lang, "on", "aktif")
    } else {
        tr(lang, "off", "tidak aktif")
    };
    let mut out = para(
        doc,
        &esc(doc, &match lang {
            Lang::En => format!(
                "{} students marked; tolerance {tol} %, at least {} significant figures, follow-through {ft}.",
                s.students, settings.sig_figs
            ),
            Lang::Id => format!(
                "{} mahasiswa dinilai; toleransi {tol} %, paling sedikit {} angka penting, follow-through {ft}.",
                s.students, settings.sig_figs
            ),
        }),
    );
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
        out.push_str(&para(
            doc,
            &esc(
                doc,
                tr(
                    lang,
                    "Not marked (not counted below):",
                    "Tidak dinilai (tidak dihitung di bawah):",
                ),
            ),
        ));
        out.push_str(&list(doc, &failed));
    }
    out
}

/// The key table and the definitions of its indices.
fn keys_section(doc: Doc, s: &Stats, lang: Lang) -> String {
    let mut out = doc.heading(1, tr(lang, "Answer keys", "Kunci jawaban"));
    let header: Vec<String> = match lang {
        Lang::En => [
            "key",
            "correct",
            "follow-through",
            "too coarse",
            "wrong",
            "missing",
            "unparseable",
            "p",
            "D",
            "r",
            "flag",
        ],
        Lang::Id => [
            "kunci",
            "benar",
            "follow-through",
            "terlalu kasar",
            "salah",
            "tidak dijawab",
            "tidak terbaca",
            "p",
            "D",
            "r",
            "tanda",
        ],
    }
    .iter()
    .map(|h| esc(doc, h))
    .collect();
    let rows: Vec<Vec<String>> = s
        .keys
        .iter()
        .map(|k| {
            let c = |code: &str| k.count(code);
            let right = c("correct.exact") + c("correct.rounded") + c("correct.tolerance");
            let flags: Vec<&str> = k.flags.iter().map(|f| flag_words(*f, lang)).collect();
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
            vec![
                esc(doc, &k.key),
                format!(
                    "{right} ({}/{}/{})",
                    c("correct.exact"),
                    c("correct.rounded"),
                    c("correct.tolerance")
                ),
                c("correct.follow_through").to_string(),
                c("too_coarse").to_string(),
                c("wrong").to_string(),
                c("missing").to_string(),
                c("unparseable").to_string(),
                num(Some(k.facility), lang),
                num(k.discrimination, lang),
                num(k.point_biserial, lang),
                flag,
            ]
        })
        .collect();
    out.push_str(&table(doc, &header, &rows));
    out.push_str(&para(doc, &esc(doc, definitions(lang))));
    out
}

/// The definitions of p, D and r, as the report states them.
fn definitions(lang: Lang) -> &'static str {
    tr(
        lang,
        "Correct: how many, and in brackets how many exact / correctly rounded / within the tolerance. \
         A key's mark is 1 when correct, ½ when too coarse, 0 otherwise; a student's score is the sum of the marks. \
         Facility p: the mean mark, the share of full marks (very easy above 0.90, very hard below 0.20). \
         Discrimination D: the mean mark of the upper 27 % of the class by score minus that of the lower 27 % \
         (students tied at a group's edge share its places); from −1 to 1. \
         Point-biserial r: the correlation of the key's mark with the rest of the score (the score without this key); \
         — when everyone has the same mark. A key with D or r below 0 discriminates negatively (flag: negative): \
         the weaker students do better on it, so check its key or its question.",
        "Benar: jumlahnya, dan dalam kurung berapa yang eksak / dibulatkan dengan benar / dalam batas toleransi. \
         Nilai sebuah kunci 1 bila benar, ½ bila terlalu kasar, 0 bila tidak; nilai mahasiswa adalah jumlahnya. \
         Tingkat kemudahan p: rata-rata nilai kunci, bagian dari nilai penuh (sangat mudah di atas 0,90, sangat sulit di bawah 0,20). \
         Daya beda D: rata-rata nilai 27 % kelas teratas menurut nilai dikurangi rata-rata 27 % terbawah \
         (mahasiswa dengan nilai sama di batas kelompok berbagi tempatnya); dari −1 sampai 1. \
         Point-biserial r: korelasi nilai kunci dengan sisa nilai (nilai tanpa kunci ini); \
         — bila semua mendapat nilai yang sama. Kunci dengan D atau r di bawah 0 memiliki daya beda negatif (tanda: negatif): \
         mahasiswa yang lebih lemah justru lebih baik, jadi periksa kunci atau soalnya.",
    )
}

/// Per problem and per variant (an exam only).
fn exam_section(doc: Doc, s: &Stats, lang: Lang) -> String {
    if s.variants.is_empty() && s.problems.iter().all(|p| p.name.is_empty()) {
        return String::new();
    }
    let mut out = doc.heading(1, tr(lang, "Problems", "Soal"));
    let header: Vec<String> = [
        tr(lang, "problem", "soal"),
        tr(lang, "title", "judul"),
        tr(lang, "students", "mahasiswa"),
        tr(lang, "facility p", "tingkat kemudahan p"),
    ]
    .iter()
    .map(|h| esc(doc, h))
    .collect();
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
    out.push_str(&table(doc, &header, &rows));
    if s.variants.is_empty() {
        return out;
    }
    out.push_str(&doc.heading(1, tr(lang, "Variants", "Varian")));
    let mut header: Vec<String> = vec![
        esc(doc, tr(lang, "variant", "varian")),
        esc(doc, tr(lang, "students", "mahasiswa")),
        esc(doc, tr(lang, "whole exam", "seluruh ujian")),
    ];
    header.extend(s.problems.iter().map(|p| esc(doc, &p.name)));
    let rows: Vec<Vec<String>> = s
        .variants
        .iter()
        .map(|v| {
            let mut row = vec![
                v.variant.to_string(),
                v.students.to_string(),
                num(v.facility, lang),
            ];
            row.extend(v.problems.iter().map(|(_, f, gap)| {
                let mark = match gap {
                    Some(Gap::Harder) => format!(" ▼ {}", tr(lang, "harder", "lebih sulit")),
                    Some(Gap::Easier) => format!(" ▲ {}", tr(lang, "easier", "lebih mudah")),
                    None => String::new(),
                };
                format!("{}{}", num(*f, lang), esc(doc, &mark))
            }));
            row
        })
        .collect();
    out.push_str(&table(doc, &header, &rows));
    out.push_str(&para(doc, &esc(doc, tr(lang,
        "Each cell is the variant's facility on the problem; ▼ marks a variant more than 0.20 below the median of its siblings on that problem (▲ above).",
        "Setiap sel adalah tingkat kemudahan varian pada soal itu; ▼ menandai varian yang lebih dari 0,20 di bawah median varian lainnya pada soal itu (▲ di atasnya)."))));
    out
}

/// `step 16 of the worked solution: Window edges …` (an exam's:
/// `problem-02, step 3 …`), so a lecturer can reopen it with `grafika solve`.
fn step_words(step: &StepRef, st: &Style) -> String {
    let part = if step.part.is_empty() {
        String::new()
    } else {
        format!("{}, ", step.part)
    };
    let n = step.number;
    let title = st.w(&step.title);
    match st.lang {
        Lang::En => format!("{part}step {n} of the worked solution: {title}"),
        Lang::Id => format!("{part}langkah {n} dari penyelesaian: {title}"),
    }
}

/// Each mistake with its students, keys and step, the most students first.
fn mistakes_section(doc: Doc, s: &Stats, st: &Style) -> String {
    let lang = st.lang;
    let mut out = doc.heading(1, tr(lang, "Mistakes", "Kesalahan konsep"));
    if s.mistakes.is_empty() {
        return out
            + &para(
                doc,
                &esc(
                    doc,
                    tr(
                        lang,
                        "No known mistake explains a wrong answer.",
                        "Tidak ada kesalahan yang dikenal yang menjelaskan jawaban salah.",
                    ),
                ),
            );
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
    let who = match n {
        1 => tr(lang, "student", "mahasiswa"),
        _ => tr(lang, "students", "mahasiswa"),
    };
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
        esc(doc, m.mistake.code),
        esc(doc, &m.students.join(", ")),
        esc(doc, tr(lang, "Explains", "Menjelaskan")),
        esc(doc, &m.keys.join(", ")),
    );
    if let Some(step) = &m.step {
        out.push_str(&format!(
            " {}: {}.",
            esc(doc, tr(lang, "Teach again", "Ajarkan lagi")),
            esc(doc, &step_words(step, st))
        ));
    }
    if !m.also.is_empty() {
        let codes: Vec<&str> = m.also.iter().map(|a| a.code).collect();
        out.push_str(&format!(
            " ({}: {})",
            esc(
                doc,
                tr(
                    lang,
                    "some of these also follow from",
                    "sebagian juga dapat berasal dari"
                )
            ),
            esc(doc, &codes.join(", "))
        ));
    }
    out
}

/// The wrong answers no mistake explains, per key.
fn wrong_section(doc: Doc, s: &Stats, st: &Style) -> String {
    let lang = st.lang;
    let mut out = doc.heading(
        1,
        tr(
            lang,
            "Wrong answers no mistake explains",
            "Jawaban salah yang tidak dijelaskan kesalahan yang dikenal",
        ),
    );
    if s.wrong_answers.is_empty() {
        return out + &para(doc, &esc(doc, tr(lang, "None.", "Tidak ada.")));
    }
    out.push_str(&para(doc, &esc(doc, tr(lang,
        "Values equal within the tolerance are counted together; the most common first. A value many students share may be a mistake the catalog does not know yet, or a wrong key.",
        "Nilai yang sama dalam batas toleransi dihitung bersama; yang paling sering lebih dulu. Nilai yang sama pada banyak mahasiswa bisa jadi kesalahan yang belum dikenal katalog, atau kunci yang salah."))));
    let header: Vec<String> = [
        tr(lang, "key", "kunci"),
        tr(lang, "expected", "seharusnya"),
        tr(lang, "given", "diberikan"),
        tr(lang, "students", "mahasiswa"),
    ]
    .iter()
    .map(|h| esc(doc, h))
    .collect();
    let mut rows = Vec::new();
    for w in &s.wrong_answers {
        let key = match w.variant {
            Some(v) => format!("{} ({} {v})", w.key, tr(lang, "variant", "varian")),
            None => w.key.clone(),
        };
        let expected = w
            .expected
            .as_ref()
            .map(|e| st.val_inline(e))
            .unwrap_or_default();
        for (i, v) in w.values.iter().enumerate() {
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
    out.push_str(&table(doc, &header, &rows));
    out
}

/// The histogram, and the students grouped by the mistake they share.
fn students_section(doc: Doc, class: &Class, s: &Stats, lang: Lang) -> String {
    let mut out = doc.heading(1, tr(lang, "Students", "Mahasiswa"));
    out.push_str(&match doc {
        Doc::Html => crate::report::html::figure(
            &histogram::svg(&s.histogram, lang),
            tr(
                lang,
                "Score distribution (% of the marks)",
                "Sebaran nilai (% dari nilai penuh)",
            ),
        ),
        _ => format!("```\n{}```\n\n", histogram::text(&s.histogram)),
    });
    if !s.mistakes.is_empty() {
        out.push_str(&doc.heading(
            2,
            tr(
                lang,
                "Who made which mistake",
                "Siapa membuat kesalahan apa",
            ),
        ));
        let header: Vec<String> = [
            tr(lang, "mistake", "kesalahan"),
            tr(lang, "students", "mahasiswa"),
        ]
        .iter()
        .map(|h| esc(doc, h))
        .collect();
        let rows: Vec<Vec<String>> = s
            .mistakes
            .iter()
            .map(|m| vec![esc(doc, m.mistake.code), esc(doc, &m.students.join(", "))])
            .collect();
        out.push_str(&table(doc, &header, &rows));
    }
    out.push_str(&doc.heading(2, tr(lang, "Scores", "Nilai")));
    let mut header: Vec<String> = vec![esc(doc, tr(lang, "student", "mahasiswa"))];
    if class.exam {
        header.push(esc(doc, tr(lang, "variant", "varian")));
    }
    header.extend([
        esc(doc, tr(lang, "score", "nilai")),
        esc(doc, tr(lang, "mistakes", "kesalahan konsep")),
    ]);
    let rows: Vec<Vec<String>> = class
        .marked()
        .map(|sh| {
            let mut row = vec![esc(doc, &sh.who)];
            if class.exam {
                row.push(sh.variant.map(|v| v.to_string()).unwrap_or_default());
            }
            let score = crate::report::words::of(lang)
                .nums()
                .number(&crate::report::fmt_dec(sh.score().unwrap_or(0.0), 4));
            row.push(format!("{score}/{}", sh.total().unwrap_or(0)));
            let codes: Vec<&str> = s
                .mistakes
                .iter()
                .filter(|m| m.students.contains(&sh.who))
                .map(|m| m.mistake.code)
                .collect();
            row.push(esc(doc, &codes.join(" ")));
            row
        })
        .collect();
    out.push_str(&table(doc, &header, &rows));
    out
}
