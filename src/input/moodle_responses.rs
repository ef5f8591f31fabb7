//! Moodle's quiz Responses report as a lecturer downloads it (Quiz →
//! Results → Responses, "Download table data as" CSV, JSON, Excel or
//! OpenDocument; read as Moodle 5.1 writes them, its column names in
//! English or Indonesian): one row per attempt, the student's name and
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

/// The most bytes the sheets of an Excel or OpenDocument report may
/// unpack to, as the file's own index declares them: 4 × [`MAX_REPORT`]
/// (the XML of a sheet is about 1.3 times its CSV), refused before a byte
/// is unpacked.
pub const MAX_UNPACKED: u64 = 4 * MAX_REPORT;

/// Reads a Responses report by its name's extension: `.json`, `.xlsx`
/// (Excel), `.ods` (OpenDocument), else CSV.
pub fn read(path: &Path) -> Result<Responses> {
    let bytes = read_report(path)?;
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_lowercase())
        .unwrap_or_default();
    let rows = match ext.as_str() {
        "json" => json_rows(&text(&bytes))?,
        "xlsx" | "ods" => sheet_rows(bytes)?,
        _ => csv_rows(&text(&bytes))?,
    };
    of_rows(rows)
}

/// The file's text, without a byte-order mark.
fn text(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    text.trim_start_matches('\u{feff}').to_string()
}

fn read_report(path: &Path) -> Result<Vec<u8>> {
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
    std::fs::read(path).map_err(why)
}

/// The bytes a zip file's entries unpack to, as its central directory
/// declares them.
fn unpacked_size(bytes: &[u8]) -> Result<u64> {
    let bad = |e: zip::result::ZipError| not_responses(&e.to_string());
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).map_err(bad)?;
    let mut total = 0u64;
    for i in 0..zip.len() {
        total = total.saturating_add(zip.by_index_raw(i).map_err(bad)?.size());
    }
    Ok(total)
}

/// The rows of the first sheet of an Excel (`.xlsx`) or OpenDocument
/// (`.ods`) download, each cell as its text (a number as Rust writes it:
/// `100`, `73.33`). Moodle writes a text that begins with `=` (a name
/// such as `=HYPERLINK("x")`) as an Excel formula without a value: its
/// text is read back from the formula. A file whose index declares more than
/// [`MAX_UNPACKED`] bytes is refused unread.
fn sheet_rows(bytes: Vec<u8>) -> Result<Rows> {
    use calamine::Reader;
    let unpacked = unpacked_size(&bytes)?;
    if unpacked > MAX_UNPACKED {
        return Err(not_responses(&format!(
            "its sheets unpack to {unpacked} bytes, more than {MAX_UNPACKED}"
        )));
    }
    let mut book = calamine::open_workbook_auto_from_rs(std::io::Cursor::new(bytes))
        .map_err(|e| not_responses(&e.to_string()))?;
    let name = book
        .sheet_names()
        .first()
        .cloned()
        .ok_or_else(|| not_responses("no sheet"))?;
    let data = (book.worksheet_range(&name)).map_err(|e| not_responses(&e.to_string()))?;
    let formulas = book.worksheet_formula(&name).unwrap_or_default();
    let (top, left) = data.start().unwrap_or((0, 0));
    let mut all = data.rows().enumerate().map(|(r, row)| {
        (row.iter().enumerate())
            .map(|(c, cell)| match cell {
                calamine::Data::Empty => {
                    let at = (top + r as u32, left + c as u32);
                    (formulas.get_value(at)).map_or(String::new(), |f| format!("={f}"))
                }
                other => other.to_string(),
            })
            .collect::<Vec<String>>()
    });
    let header = all.next().ok_or_else(|| not_responses("empty"))?;
    Ok((header, all.collect()))
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

/// The columns' names as Moodle writes them in English and in Indonesian
/// (its language pack: `Nama akhir`, `Alamat surel`, `Keadaan`, `Nilai/`,
/// `Soal N`, `Jawaban N`), compared without regard to case.
const LAST: &[&str] = &["Last name", "Surname", "Nama akhir", "Nama belakang"];
const FIRST: &[&str] = &["First name", "Nama depan"];
const EMAIL: &[&str] = &["Email address", "Alamat surel", "Alamat email"];
const ID_NUMBER: &[&str] = &["ID number", "Nomor ID"];
const STATUS: &[&str] = &["Status", "State", "Keadaan"];
const GRADE: &[&str] = &["Grade/", "Nilai/"];
const QUESTION: &[&str] = &["Question", "Soal"];
const RESPONSE: &[&str] = &["Response", "Jawaban"];

fn columns(header: &[String]) -> Result<Columns> {
    let is = |h: &str, name: &str| h.trim().eq_ignore_ascii_case(name);
    let at = |names: &[&str]| header.iter().position(|h| names.iter().any(|n| is(h, n)));
    let numbered = |words: &[&str], n: usize| {
        let names: Vec<String> = words.iter().map(|w| format!("{w} {n}")).collect();
        at(&names.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let mut slots = Vec::new();
    for n in 1.. {
        let Some(r) = numbered(RESPONSE, n) else {
            break;
        };
        slots.push((numbered(QUESTION, n), r));
    }
    if slots.is_empty() {
        return Err(not_responses("no column Response 1"));
    }
    Ok(Columns {
        last: at(LAST),
        first: at(FIRST),
        email: at(EMAIL),
        id_number: at(ID_NUMBER),
        status: at(STATUS).ok_or_else(|| not_responses("no column Status"))?,
        grade: header.iter().position(|h| grade_max(h).is_some()),
        slots,
    })
}

/// The quiz's maximum grade from the grade column's name, `Grade/100.00`
/// or `Nilai/100,00`; `Some(None)` for `Grade/` with no number after it
/// (the JSON download's), none for another column.
fn grade_max(h: &str) -> Option<Option<f64>> {
    let h = h.trim();
    GRADE.iter().find_map(|g| {
        let head = h.get(..g.len())?;
        head.eq_ignore_ascii_case(g).then(|| decimal(&h[g.len()..]))
    })
}

fn of_rows((header, rows): Rows) -> Result<Responses> {
    let c = columns(&header)?;
    let out_of = c.grade.and_then(|g| grade_max(&header[g]).flatten());
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

    /// A zip of one stored entry whose central directory declares
    /// `size` bytes unpacked (and holds none).
    fn zip_declaring(size: u32) -> Vec<u8> {
        let name = b"xl/worksheets/sheet1.xml";
        let u16s = |v: &[u16]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
        let u32s = |v: &[u32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
        let n = name.len() as u16;
        let mut local = u32s(&[0x0403_4b50]);
        local.extend(u16s(&[20, 0, 0, 0, 0]));
        local.extend(u32s(&[0, 0, size]));
        local.extend(u16s(&[n, 0]));
        local.extend(name);
        let mut central = u32s(&[0x0201_4b50]);
        central.extend(u16s(&[20, 20, 0, 0, 0, 0]));
        central.extend(u32s(&[0, 0, size]));
        central.extend(u16s(&[n, 0, 0, 0, 0]));
        central.extend(u32s(&[0, 0]));
        central.extend(name);
        let mut end = u32s(&[0x0605_4b50]);
        end.extend(u16s(&[0, 0, 1, 1]));
        end.extend(u32s(&[central.len() as u32, local.len() as u32]));
        end.extend(u16s(&[0]));
        [local, central, end].concat()
    }

    #[test]
    fn a_spreadsheet_that_would_unpack_past_the_bound_is_refused_unread() {
        // 4,000,000,000 bytes declared > 4 × 64 MiB = 268,435,456.
        let big = zip_declaring(4_000_000_000);
        assert_eq!(unpacked_size(&big).ok(), Some(4_000_000_000));
        let err = sheet_rows(big).expect_err("refused");
        assert_eq!(err.field, "moodle-responses");
        assert!(
            format!("{:?}", err.message).contains("268435456"),
            "{err:?}"
        );
        // Within the bound, it is read (and is no sheet).
        assert_eq!(unpacked_size(&zip_declaring(10)).ok(), Some(10));
    }
}
