//! A class marked by `grafika check --answers DIR`: one row per student as
//! a text table, a CSV summary and JSON (`rows` view), and the lecturer's
//! report of the class ([`lecturer`]: HTML, Markdown, JSON, CSV).

pub mod histogram;
pub mod lecturer;
pub(crate) mod page;

use crate::error::Error;
use crate::msg::ClassWord as C;
use crate::report::check::{problems_json, to_json, MarkingJson};
use crate::report::json::Fault;
use crate::report::lang::Lang;
use crate::report::words;
use crate::report::words::cut_message;
use crate::tutor::check::{Marking, Verdict};
use crate::tutor::class::roster::Listed;
use crate::tutor::class::{Class, Note, Sheet, Skip};
use serde::Serialize;

/// What was done with an unusual answer file, in words.
pub fn note_words(n: Note, lang: Lang) -> &'static str {
    words::of(lang).note(n)
}

/// Why an entry of the answers folder was skipped, in words.
pub fn skip_words(s: Skip, lang: Lang) -> &'static str {
    words::of(lang).skip(s)
}

/// An error as a person reads it: `field: words`, cut when long.
pub fn said(e: &Error, lang: Lang) -> String {
    let words = crate::report::words::words(&e.message, lang);
    cut_message(&format!("{}: {words}", e.field), lang)
}

/// The codes of the mistakes found in a sheet, space-separated.
fn mistakes(ms: &[(String, Marking)]) -> String {
    let mut codes: Vec<&str> = Vec::new();
    for d in ms.iter().flat_map(|(_, m)| &m.diagnoses) {
        if !codes.contains(&d.mistake.as_str()) {
            codes.push(d.mistake.as_str());
        }
    }
    codes.join(" ")
}

/// The width of the class table's column of mistakes, in characters.
const MISTAKES_WIDTH: u16 = 44;

/// The mistakes found in a sheet in words, in `lang` (the table's column;
/// the CSV and JSON keep the codes), one per line.
fn mistakes_said(ms: &[(String, Marking)], lang: Lang) -> String {
    let mut codes = Vec::new();
    for d in ms.iter().flat_map(|(_, m)| &m.diagnoses) {
        if !codes.contains(&d.mistake) {
            codes.push(d.mistake);
        }
    }
    let said: Vec<&str> = codes
        .into_iter()
        .map(|c| crate::report::mistakes::mistake_text(c, lang))
        .collect();
    said.join("\n")
}

/// A sheet's counts over all its parts: score, total, each verdict's (in
/// the order of [`Verdict::words`], the columns'), follow-through.
fn counts(ms: &[(String, Marking)]) -> (f64, usize, [usize; 6]) {
    let sum = |f: &dyn Fn(&Marking) -> usize| ms.iter().map(|(_, m)| f(m)).sum::<usize>();
    let mut n = [0; 6];
    for (i, v) in Verdict::words().into_iter().enumerate() {
        n[i] = sum(&|m: &Marking| m.count(v));
    }
    n[5] = sum(&|m: &Marking| m.follow_through());
    (
        ms.iter().fold(0.0, |s, (_, m)| s + m.score()),
        sum(&|m: &Marking| m.total() as usize),
        n,
    )
}

/// The headings of a class's table (`check --answers DIR`), one per column.
pub fn class_header(lang: Lang) -> Vec<String> {
    let w = words::of(lang);
    let mut header = vec![w.class(&C::Student), w.class(&C::Score)];
    header.extend(
        Verdict::words()
            .into_iter()
            .map(|v| w.verdict(v).to_string()),
    );
    header.extend([C::FollowThrough, C::Mistakes].map(|k| w.class(&k)));
    header
}

/// One row per student, then the notes on unusual files and the entries
/// skipped. An exam's table has the variant after the student.
pub fn table(class: &Class, lang: Lang) -> String {
    use comfy_table::{presets, Table};
    let mut header = class_header(lang);
    if class.exam {
        header.insert(1, words::of(lang).doc(&crate::msg::DocWord::Variant));
    }
    let mut t = Table::new();
    let columns = header.len();
    t.load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(comfy_table::ContentArrangement::Dynamic)
        .set_width(400)
        .set_header(header);
    // the mistakes in words wrap in their column; the counts never do
    if let Some(c) = t.column_mut(columns - 1) {
        c.set_constraint(comfy_table::ColumnConstraint::UpperBoundary(
            comfy_table::Width::Fixed(MISTAKES_WIDTH),
        ));
    }
    for s in &class.sheets {
        let mut cells = vec![s.who.clone()];
        if class.exam {
            cells.push(s.variant_label());
        }
        match &s.outcome {
            Ok(ms) => {
                let (score, total, n) = counts(ms);
                cells.push(format!("{}/{total}", crate::report::fmt_dec(score, 4)));
                cells.extend(n.iter().map(|x| x.to_string()));
                cells.push(mistakes_said(ms, lang));
            }
            Err(e) => {
                cells.push("—".to_string());
                cells.extend(std::iter::repeat_n(String::new(), 6));
                cells.push(format!(
                    "{}: {}",
                    words::of(lang).doc(&crate::msg::DocWord::Error),
                    said(e, lang)
                ));
            }
        }
        t.add_row(cells);
    }
    let mut out = format!("{}\n{t}\n", class.title);
    for s in &class.sheets {
        if let Some(n) = s.note {
            out.push_str(&format!("{}: {}\n", s.file.display(), note_words(n, lang)));
        }
    }
    for s in &class.sheets {
        for said in [duplicate_words(s, lang), fits_words(s, lang)]
            .into_iter()
            .flatten()
        {
            out.push_str(&format!("{}: {said}\n", s.file.display()));
        }
    }
    for (f, why) in &class.skipped {
        out.push_str(&format!("{}: {}\n", f.display(), skip_words(*why, lang)));
    }
    for (head, names) in roster_lists(class, lang) {
        out.push_str(&format!("{head} {}\n", names.join(", ")));
    }
    out
}

/// The class list's two lists, each with its heading, when not empty: who
/// on it handed nothing in (`Adi Nugroho (NIM 2106001)`), and the answer
/// files of no one on it (`Budi (budi.toml)`); or the sentence that
/// everyone handed in, with no list.
pub fn roster_lists(class: &Class, lang: Lang) -> Vec<(String, Vec<String>)> {
    let Some(r) = &class.roster else {
        return vec![];
    };
    let w = words::of(lang);
    if r.missing.is_empty() && r.not_listed.is_empty() {
        return vec![(w.class(&C::RosterAll(r.listed.len())), vec![])];
    }
    let mut out = Vec::new();
    if !r.missing.is_empty() {
        let names = (r.missing.iter())
            .map(|l| match &l.nim {
                Some(n) => format!("{} (NIM {n})", l.name),
                None => l.name.clone(),
            })
            .collect();
        out.push((w.class(&C::RosterMissing(r.missing.len())), names));
    }
    if !r.not_listed.is_empty() {
        let files = (r.not_listed.iter())
            .map(|(who, f)| format!("{who} ({})", f.display()))
            .collect();
        out.push((w.class(&C::RosterNotListed(r.not_listed.len())), files));
    }
    out
}

/// The class list as JSON (`roster`): `listed` (how many), `missing`
/// (`name`, `nim`), `not_listed` (`student`, `file`).
#[derive(Serialize)]
pub struct RosterJson<'a> {
    listed: usize,
    missing: &'a [Listed],
    not_listed: Vec<FileJson<'a>>,
}

/// A student's answer file.
#[derive(Serialize)]
pub struct FileJson<'a> {
    student: &'a str,
    file: String,
}

/// The class list as JSON; null without one.
pub fn roster_json(class: &Class) -> Option<RosterJson<'_>> {
    let r = class.roster.as_ref()?;
    Some(RosterJson {
        listed: r.listed.len(),
        missing: &r.missing,
        not_listed: (r.not_listed.iter())
            .map(|(who, f)| FileJson {
                student: who,
                file: f.display().to_string(),
            })
            .collect(),
    })
}

/// `the same student as adi (1).toml (same name): not counted`, for a
/// sheet that is a duplicate.
pub fn duplicate_words(s: &Sheet, lang: Lang) -> Option<String> {
    let (kept, why) = s.duplicate.as_ref()?;
    let w = words::of(lang);
    let kept = kept.file_name().map_or_else(
        || kept.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    Some(w.class(&C::DuplicateOf {
        kept,
        why: w.same(*why).to_string(),
    }))
}

/// `these answers fit variant 4's key (…)`, for a sheet that does.
pub fn fits_words(s: &Sheet, lang: Lang) -> Option<String> {
    let f = s.fits?;
    Some(words::of(lang).class(&C::Fits {
        variant: f.variant,
        there: f.there * 100.0,
        own: f.own * 100.0,
    }))
}

/// The file a duplicate sheet is a copy of, and why.
#[derive(Serialize)]
struct DuplicateJson {
    file: String,
    same: &'static str,
}

/// The variant whose key a sheet's answers fit, and how well (to 4
/// decimals): there and in its own variant.
#[derive(Serialize)]
struct FitsJson {
    variant: usize,
    there: f64,
    own: f64,
}

pub(super) fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

/// The CSV columns (docs/spec.md §5): the student, the score, each
/// verdict word's count (`correct`, `too_coarse`, …), follow-through, the
/// mistakes and the error; an exam's CSV has `variant` after `file`.
fn csv_header(exam: bool) -> Vec<&'static str> {
    let mut header = vec!["student", "file", "score", "total"];
    if exam {
        header.insert(2, "variant");
    }
    header.extend(Verdict::words().into_iter().map(Verdict::word));
    header.extend(["follow_through", "mistakes", "error"]);
    header
}

/// The CSV summary, one row per sheet (a file that could not be marked:
/// empty counts and its error), safe to open in a spreadsheet
/// ([`crate::report::csv`]).
pub fn csv(sheets: &[Sheet], exam: bool, lang: Lang) -> String {
    let header = csv_header(exam);
    let rows: Vec<Vec<String>> = sheets
        .iter()
        .map(|s| {
            let mut row = vec![s.who.clone(), s.file.display().to_string()];
            if exam {
                row.push(s.variant_label());
            }
            match &s.outcome {
                Ok(ms) => {
                    let (score, total, n) = counts(ms);
                    row.extend([score.to_string(), total.to_string()]);
                    row.extend(n.iter().map(|x| x.to_string()));
                    row.extend([mistakes(ms), String::new()]);
                }
                Err(e) => {
                    row.extend(std::iter::repeat_n(String::new(), 9));
                    row.push(said(e, lang));
                }
            }
            row
        })
        .collect();
    crate::report::csv::write(&header, &rows)
}

/// The class as JSON: each student's marking (an exam's: each problem's,
/// under `problems`), or the error of a file that could not be marked, and
/// the entries skipped.
#[derive(Serialize)]
pub struct ClassJson<'a> {
    command: &'static str,
    title: &'a str,
    students: Vec<SheetJson<'a>>,
    skipped: Vec<SkippedJson>,
    roster: Option<RosterJson<'a>>,
}

/// An entry of the answers folder skipped, and why in words.
#[derive(Serialize)]
struct SkippedJson {
    file: String,
    reason: &'static str,
}

/// The class as JSON.
pub fn json(class: &Class, lang: Lang) -> ClassJson<'_> {
    ClassJson {
        command: "check",
        title: &class.title,
        students: (class.sheets.iter())
            .map(|s| sheet_json(s, class.exam, lang))
            .collect(),
        skipped: (class.skipped.iter())
            .map(|(f, why)| SkippedJson {
                file: f.display().to_string(),
                reason: skip_words(*why, lang),
            })
            .collect(),
        roster: roster_json(class),
    }
}

/// One student's sheet: its marks, then the file it duplicates and the
/// variant its answers fit, when so.
#[derive(Serialize)]
struct SheetJson<'a> {
    #[serde(flatten)]
    marks: SheetMarks<'a>,
    #[serde(skip_serializing_if = "Option::is_none")]
    duplicate_of: Option<DuplicateJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fits: Option<FitsJson>,
}

/// A sheet's marks: a lone problem's marking (with its `file`), an
/// exam's, or the error of a file that could not be marked.
#[derive(Serialize)]
#[serde(untagged)]
enum SheetMarks<'a> {
    One(MarkingJson<'a>),
    Exam {
        student: &'a str,
        file: String,
        variant: VariantJson<'a>,
        score: ScoreJson,
        problems: Vec<MarkingJson<'a>>,
    },
    Failed {
        student: &'a str,
        file: String,
        error: Fault<'a>,
        #[serde(skip_serializing_if = "Option::is_none")]
        variant: Option<VariantJson<'a>>,
    },
}

/// An exam's score over its problems.
#[derive(Serialize)]
struct ScoreJson {
    points: f64,
    total: usize,
}

fn sheet_json(s: &Sheet, exam: bool, lang: Lang) -> SheetJson<'_> {
    SheetJson {
        marks: sheet_marks_json(s, exam, lang),
        duplicate_of: (s.duplicate.as_ref()).map(|(kept, why)| DuplicateJson {
            file: kept.display().to_string(),
            same: why.code(),
        }),
        fits: s.fits.map(|f| FitsJson {
            variant: f.variant,
            there: round4(f.there),
            own: round4(f.own),
        }),
    }
}

fn sheet_marks_json(s: &Sheet, exam: bool, lang: Lang) -> SheetMarks<'_> {
    let file = s.file.display().to_string();
    match (&s.outcome, exam) {
        (Ok(ms), false) if ms.len() == 1 => {
            let mut one = to_json(&ms[0].1, lang);
            one.file = Some(file);
            SheetMarks::One(one)
        }
        (Ok(ms), _) => {
            let (points, total, _) = counts(ms);
            SheetMarks::Exam {
                student: &s.who,
                file,
                variant: variant_json(s),
                score: ScoreJson { points, total },
                problems: problems_json(ms, lang),
            }
        }
        (Err(e), _) => SheetMarks::Failed {
            student: &s.who,
            file,
            error: fault(e, lang),
            variant: exam.then(|| variant_json(s)),
        },
    }
}

/// An error of a file that could not be marked: its field and its words.
pub(super) fn fault(e: &Error, lang: Lang) -> Fault<'_> {
    Fault {
        field: &e.field,
        message: crate::report::words::words(&e.message, lang),
    }
}

/// A sheet's variant in JSON: its number (null when none), or the list of
/// each problem's variant when they were drawn from different variants
/// (`[2, 1, 2]`).
#[derive(Serialize)]
#[serde(untagged)]
pub(super) enum VariantJson<'a> {
    Each(&'a [usize]),
    One(Option<usize>),
}

/// A sheet's variant in JSON.
pub(super) fn variant_json(s: &Sheet) -> VariantJson<'_> {
    match s.drawn.first() {
        Some(first) if s.drawn.iter().any(|d| d != first) => VariantJson::Each(&s.drawn),
        Some(first) => VariantJson::One(Some(*first)),
        None => VariantJson::One(s.variant),
    }
}
