//! The class list (`check … --roster FILE`): who should have handed in.
//! The file is one name per line, or CSV (comma, semicolon or tab) whose
//! first line names a `nama` or `name` column and, optionally, a `nim`
//! column. A student on the list is matched to an answer file by NIM when
//! both give one, else by name, compared without case and with runs of
//! spaces as one ([`super::same::name_key`]).

use super::same::{name_key, Identity};
use super::Sheet;
use crate::error::{Error, Result};
use crate::msg::ErrMsg;
use std::path::{Path, PathBuf};

/// One student of the class list.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Listed {
    /// The name as the list writes it.
    pub name: String,
    /// The NIM, when the list has one.
    pub nim: Option<String>,
}

/// The class list set against the answer files.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Roster {
    /// The students on the list, in its order.
    pub listed: Vec<Listed>,
    /// Those with no answer file, in the list's order.
    pub missing: Vec<Listed>,
    /// The answer files (each student once) of no one on the list: the
    /// student as shown and the file.
    pub not_listed: Vec<(String, PathBuf)>,
}

/// Reads a class list.
pub fn read(path: &Path) -> Result<Vec<Listed>> {
    let text = crate::input::read_text("roster", path)?;
    let listed = parse(&text)?;
    if listed.is_empty() {
        return Err(Error::why(
            "roster",
            ErrMsg::EmptyRoster(path.display().to_string()),
        ));
    }
    Ok(listed)
}

/// The students of a class list's text: CSV when its first line has a
/// `nama` or `name` cell, else one name per line (blank lines and lines
/// starting with `#` left out).
pub fn parse(text: &str) -> Result<Vec<Listed>> {
    let text = text.trim_start_matches('\u{feff}');
    let first = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    let delimiter = [b';', b'\t', b',']
        .into_iter()
        .find(|d| first.contains(char::from(*d)));
    let header: Vec<String> = match delimiter {
        Some(d) => first.split(char::from(d)).map(cell_key).collect(),
        None => vec![cell_key(first)],
    };
    let name_col = header.iter().position(|h| h == "nama" || h == "name");
    let Some(name_col) = name_col else {
        return Ok(lines(text));
    };
    let nim_col = header.iter().position(|h| h == "nim");
    let mut reader = csv::ReaderBuilder::new()
        .delimiter(delimiter.unwrap_or(b','))
        .flexible(true)
        .has_headers(true)
        .from_reader(text.as_bytes());
    let mut out = Vec::new();
    for (i, row) in reader.records().enumerate() {
        let row = row.map_err(|e| Error::why("roster", ErrMsg::RosterRow(i + 2, e.to_string())))?;
        let name = row.get(name_col).unwrap_or("").trim().to_string();
        if name.is_empty() {
            continue;
        }
        let nim = nim_col
            .and_then(|c| row.get(c))
            .map(|n| n.split_whitespace().collect::<String>())
            .filter(|n| !n.is_empty());
        out.push(Listed { name, nim });
    }
    Ok(out)
}

/// A header cell as compared: trimmed, without quotes, lower case.
fn cell_key(c: &str) -> String {
    c.trim().trim_matches('"').trim().to_lowercase()
}

fn lines(text: &str) -> Vec<Listed> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| Listed {
            name: l.to_string(),
            nim: None,
        })
        .collect()
}

/// Whether a student of the list is the one of an answer file: the same
/// NIM when both have one, else the same name.
pub fn matches(l: &Listed, id: &Identity) -> bool {
    match (&l.nim, &id.nim) {
        (Some(a), Some(b)) => a == b,
        _ => !id.name.is_empty() && name_key(&l.name) == id.name,
    }
}

/// The list set against the sheets (a duplicate counted once: only the
/// files kept are read).
pub fn against(listed: Vec<Listed>, sheets: &[Sheet]) -> Roster {
    let kept: Vec<&Sheet> = sheets.iter().filter(|s| s.duplicate.is_none()).collect();
    let missing = (listed.iter())
        .filter(|l| !kept.iter().any(|s| matches(l, &s.identity)))
        .cloned()
        .collect();
    let not_listed = (kept.iter())
        .filter(|s| !listed.iter().any(|l| matches(l, &s.identity)))
        .map(|s| (s.who.clone(), s.file.clone()))
        .collect();
    Roster {
        listed,
        missing,
        not_listed,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_list_of_names_or_csv_with_a_name_column() {
        let l = parse("# kelas A\nAdi Nugroho\n\n  Sari  Lestari \n").unwrap();
        assert_eq!(
            l.iter().map(|x| x.name.as_str()).collect::<Vec<_>>(),
            ["Adi Nugroho", "Sari  Lestari"]
        );
        // a spreadsheet's export with semicolons, a BOM, NIM with a space
        let l = parse("\u{feff}No;NIM;Nama\n1;2106 001;Adi Nugroho\n2;;Sari\n").unwrap();
        assert_eq!(l[0].nim.as_deref(), Some("2106001"));
        assert_eq!(l[0].name, "Adi Nugroho");
        assert_eq!(l[1].nim, None);
        let l = parse("name,nim\n\"Nugroho, Adi\",7\n").unwrap();
        assert_eq!(l[0].name, "Nugroho, Adi");
        // no name column: one name per line
        assert_eq!(parse("Adi, Budi\n").unwrap()[0].name, "Adi, Budi");
    }

    #[test]
    fn matched_by_nim_when_both_have_one_else_by_name() {
        let id = |name: &str, nim: Option<&str>| Identity {
            name: name_key(name),
            nim: nim.map(String::from),
            ..Default::default()
        };
        let adi = Listed {
            name: "ADI  nugroho".into(),
            nim: Some("1".into()),
        };
        assert!(matches(&adi, &id("Adi Nugroho", None)));
        assert!(matches(&adi, &id("A. Nugroho", Some("1"))));
        assert!(!matches(&adi, &id("Adi Nugroho", Some("2"))));
    }
}
