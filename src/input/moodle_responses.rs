//! Moodle's quiz Responses report as a lecturer downloads it (Quiz →
//! Results → Responses, "Download table data as" CSV or JSON; read as
//! Moodle 5.1 writes them): one row per attempt, the student's name and
//! identity fields, the attempt's state and grade, and per slot the
//! question's text ("Question N", when the report shows it) and the
//! response summary ("Response N"). A Cloze question's summary lists its
//! blanks: `part 1: 0.8; part 2: ; part 3: -0.6`, each part's text exactly
//! as the student typed it.

use crate::error::{Error, Result};
use crate::msg::{ErrMsg, FileKind, IoWhy, Msg};
use std::path::Path;

/// The largest Responses report read, in bytes: a 10-problem quiz's row
/// is about 25 KB (the question texts), so 64 MB holds 2,500 attempts.
pub const MAX_REPORT: u64 = 64 << 20;

/// A Responses report.
#[derive(Clone, Debug, PartialEq)]
pub struct Responses {
    /// The quiz's maximum grade (the `Grade/100.00` column), when shown.
    pub out_of: Option<f64>,
    /// Every attempt, in the report's order.
    pub attempts: Vec<Attempt>,
}

/// One attempt (one row of the report).
#[derive(Clone, Debug, PartialEq)]
pub struct Attempt {
    /// The row in the file (1-based, the header being row 1).
    pub row: usize,
    /// `First name Last name`.
    pub name: String,
    /// The email address, when shown.
    pub email: String,
    /// The ID number, when shown.
    pub id_number: String,
    /// The state as Moodle says it (`Finished`, `In progress`, …).
    pub state: String,
    /// Whether the attempt is finished (submitted).
    pub finished: bool,
    /// Moodle's grade, out of [`Responses::out_of`], when given.
    pub grade: Option<f64>,
    /// Each slot's question text (empty when not shown) and response.
    pub slots: Vec<Slot>,
}

/// One slot of an attempt.
#[derive(Clone, Debug, PartialEq)]
pub struct Slot {
    /// The question's text as the report gives it (empty when not shown).
    pub question: String,
    /// The response summary; none when Moodle recorded no response (`-`).
    pub response: Option<String>,
}

/// Reads a Responses report: JSON when its name ends in `.json`, else CSV.
pub fn read(path: &Path) -> Result<Responses> {
    let text = read_report(path)?;
    let json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let rows = if json {
        json_rows(&text)?
    } else {
        csv_rows(&text)?
    };
    of_rows(rows)
}

fn read_report(path: &Path) -> Result<String> {
    let shown = path.display().to_string();
    let field = "moodle-responses";
    let why =
        |e: std::io::Error| Error::said(field, Msg::ErrCannotRead(shown.clone(), IoWhy::of(&e)));
    let meta = std::fs::metadata(path).map_err(why)?;
    if !meta.is_file() {
        return Err(Error::why(
            field,
            ErrMsg::InputNotRegular(shown, FileKind::of(&meta)),
        ));
    }
    if meta.len() > MAX_REPORT {
        let (size, most) = (Some(meta.len()), MAX_REPORT as usize);
        return Err(Error::why(field, ErrMsg::FileTooLarge(shown, size, most)));
    }
    let bytes = std::fs::read(path).map_err(why)?;
    let text = String::from_utf8_lossy(&bytes).into_owned();
    Ok(text.trim_start_matches('\u{feff}').to_string())
}

/// A table: the header, then the rows, each cell by column.
type Rows = (Vec<String>, Vec<Vec<String>>);

/// The rows of a CSV file (RFC 4180: quoted cells, `""` in a quoted cell,
/// line breaks inside quotes).
fn csv_rows(text: &str) -> Result<Rows> {
    let mut r = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(text.as_bytes());
    let mut all = Vec::new();
    for rec in r.records() {
        let rec = rec.map_err(|e| not_responses(&e.to_string()))?;
        all.push(rec.iter().map(str::to_string).collect::<Vec<_>>());
    }
    let mut it = all.into_iter();
    let header = it.next().ok_or_else(|| not_responses("empty"))?;
    Ok((header, it.collect()))
}

/// The rows of the JSON download: `[[{"lastname": …, "response1": …}, …]]`
/// (one array per sheet; the keys are the column names in lower case
/// without spaces). The header is rebuilt as the CSV names its columns.
fn json_rows(text: &str) -> Result<Rows> {
    let v: serde_json::Value =
        serde_json::from_str(text).map_err(|e| not_responses(&e.to_string()))?;
    let objects: Vec<&serde_json::Map<String, serde_json::Value>> = v
        .as_array()
        .into_iter()
        .flatten()
        .flat_map(|sheet| sheet.as_array().into_iter().flatten())
        .filter_map(|o| o.as_object())
        .collect();
    let keys: Vec<String> = objects
        .first()
        .map(|o| o.keys().cloned().collect())
        .unwrap_or_default();
    let header = keys.iter().map(|k| json_column(k)).collect();
    let rows = objects
        .iter()
        .map(|o| {
            keys.iter()
                .map(|k| match o.get(k) {
                    Some(serde_json::Value::String(s)) => s.clone(),
                    Some(serde_json::Value::Null) | None => String::new(),
                    Some(x) => x.to_string(),
                })
                .collect()
        })
        .collect();
    Ok((header, rows))
}

/// A JSON key as the CSV's column: `response3` → `Response 3`,
/// `grade10000` → `Grade/` (its maximum is not recoverable from the key).
fn json_column(k: &str) -> String {
    let digits = k.trim_start_matches(|c: char| c.is_ascii_alphabetic());
    let word = &k[..k.len() - digits.len()];
    match word {
        "lastname" => "Last name".into(),
        "firstname" => "First name".into(),
        "emailaddress" => "Email address".into(),
        "idnumber" => "ID number".into(),
        "status" => "Status".into(),
        "question" => format!("Question {digits}"),
        "response" => format!("Response {digits}"),
        "grade" => "Grade/".into(),
        _ => k.to_string(),
    }
}

fn not_responses(what: &str) -> Error {
    Error::why("moodle-responses", ErrMsg::NotResponses(what.to_string()))
}

/// The columns of the report that are read.
struct Columns {
    last: Option<usize>,
    first: Option<usize>,
    email: Option<usize>,
    id_number: Option<usize>,
    status: usize,
    grade: Option<usize>,
    /// Per slot, its question column (if shown) and its response column.
    slots: Vec<(Option<usize>, usize)>,
}

fn columns(header: &[String]) -> Result<Columns> {
    let at = |name: &str| header.iter().position(|h| h.trim() == name);
    let mut slots = Vec::new();
    for n in 1.. {
        let Some(r) = at(&format!("Response {n}")) else {
            break;
        };
        slots.push((at(&format!("Question {n}")), r));
    }
    if slots.is_empty() {
        return Err(not_responses("no column Response 1"));
    }
    Ok(Columns {
        last: at("Last name").or_else(|| at("Surname")),
        first: at("First name"),
        email: at("Email address"),
        id_number: at("ID number"),
        status: at("Status")
            .or_else(|| at("State"))
            .ok_or_else(|| not_responses("no column Status"))?,
        grade: header.iter().position(|h| h.starts_with("Grade/")),
        slots,
    })
}

fn of_rows((header, rows): Rows) -> Result<Responses> {
    let c = columns(&header)?;
    let out_of = c
        .grade
        .and_then(|g| header[g].trim_start_matches("Grade/").trim().parse().ok());
    let cell = |row: &[String], i: Option<usize>| {
        i.and_then(|i| row.get(i))
            .map_or("", |s| s.trim())
            .to_string()
    };
    let attempts = rows
        .iter()
        .enumerate()
        // Moodle adds an "Overall average" row below the attempts on screen;
        // a row without a status is not an attempt.
        .filter(|(_, row)| !cell(row, Some(c.status)).is_empty())
        .map(|(i, row)| {
            let state = cell(row, Some(c.status));
            let name = [cell(row, c.first), cell(row, c.last)]
                .into_iter()
                .filter(|s| !s.is_empty())
                .collect::<Vec<_>>()
                .join(" ");
            Attempt {
                row: i + 2,
                name,
                email: cell(row, c.email),
                id_number: cell(row, c.id_number),
                finished: is_finished(&state),
                state,
                grade: decimal(&cell(row, c.grade)),
                slots: c
                    .slots
                    .iter()
                    .map(|&(q, r)| {
                        let response = row.get(r).map(String::as_str).unwrap_or("-");
                        Slot {
                            question: cell(row, q),
                            response: (response.trim() != "-").then(|| response.to_string()),
                        }
                    })
                    .collect(),
            }
        })
        .collect();
    Ok(Responses { out_of, attempts })
}

/// Whether a state says the attempt was submitted: `Finished` in
/// English, `Selesai` in Indonesian.
fn is_finished(state: &str) -> bool {
    matches!(state.trim().to_lowercase().as_str(), "finished" | "selesai")
}

/// A grade as Moodle writes it, with a decimal point or comma (`44.00`,
/// `44,00`); none for `-` or an empty cell.
pub fn decimal(s: &str) -> Option<f64> {
    let s = s.trim();
    let s = if s.contains('.') {
        s.to_string()
    } else {
        s.replace(',', ".")
    };
    s.parse::<f64>().ok().filter(|x| x.is_finite())
}

/// The parts of a Cloze response summary, in order: `part 1: 0.8; part 2:
/// ; part 3: -0.6` gives `0.8`, ``, `-0.6` (each as typed; the label is
/// whatever word precedes ` 1: `, so a translated Moodle reads the same).
/// A part's text may itself hold `; `: a part ends only where the next
/// part's label begins. None when the summary is not a list of parts.
pub fn parts(summary: &str) -> Option<Vec<String>> {
    let first = summary.find(" 1: ")?;
    let label = &summary[..first];
    if label.is_empty() || label.contains(';') {
        return None;
    }
    let mut rest = &summary[first + 4..];
    let mut out = Vec::new();
    for n in 2.. {
        let next = format!("; {label} {n}: ");
        match rest.find(&next) {
            Some(i) => {
                out.push(rest[..i].to_string());
                rest = &rest[i + next.len()..];
            }
            None => {
                out.push(rest.to_string());
                break;
            }
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_summary_splits_into_its_parts_as_typed() {
        let p = parts("part 1: 0,8; part 2: ; part 3: tidak tahu; part 4: 1; 2").unwrap();
        assert_eq!(p, vec!["0,8", "", "tidak tahu", "1; 2"]);
        let p = parts("bagian 1: −0.6; bagian 2: none").unwrap();
        assert_eq!(p, vec!["−0.6", "none"]);
        assert_eq!(parts("0.8"), None);
    }

    #[test]
    fn grades_read_with_either_decimal_mark() {
        assert_eq!(decimal("44.00"), Some(44.0));
        assert_eq!(decimal("44,50"), Some(44.5));
        assert_eq!(decimal("-"), None);
    }

    #[test]
    fn quoted_cells_keep_commas_quotes_and_line_breaks() {
        let text = "\"Last name\",\"First name\",Status,Grade/10.00,\"Response 1\"\n\"=HYPERLINK(\"\"x\"\")\",\"Ni \"\"Made\"\", Ayu\",Finished,\"7,50\",\"part 1: a\nb\"\n";
        let r = of_rows(csv_rows(text).unwrap()).unwrap();
        assert_eq!(r.out_of, Some(10.0));
        let a = &r.attempts[0];
        assert_eq!(a.name, "Ni \"Made\", Ayu =HYPERLINK(\"x\")");
        assert_eq!(a.grade, Some(7.5));
        assert!(a.finished);
        assert_eq!(a.slots[0].response.as_deref(), Some("part 1: a\nb"));
    }
}
