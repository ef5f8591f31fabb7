//! The same student handed in twice (`adi.toml` and `adi (1).toml`): each
//! student is counted once.
//!
//! Two answer files are the same student, unless both give a `nim` and
//! the two differ (two students of the same name), when
//! - their names are the same, compared without case and with runs of
//!   spaces as one: the file's `student`, or when it has none the file's
//!   name without a copy's ending (` (1)`, ` - Copy`, ` - Salinan`);
//! - or both give a `nim` and it is the same (spaces ignored);
//! - or their answers are the same as typed (every value, `variant`
//!   included) and at least one of them names no `student` (its name is
//!   only its file's): a file saved again under another name.
//!
//! Of each group one file is kept: a marked file before one that could not
//! be marked, then the one modified last, then (same time, or no time) the
//! last in name order; the others are listed with the file kept and are
//! not counted.

use super::Sheet;
use std::path::Path;
use std::time::SystemTime;

/// Why two files are taken for the same student.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Same {
    /// The same name.
    Name,
    /// The same NIM.
    Nim,
    /// The same answers, one file naming no student.
    Answers,
    /// Another attempt of the same student at a Moodle quiz (the one with
    /// the highest grade is kept, as the gradebook's grade is).
    Attempt,
}

impl Same {
    /// The code JSON writes.
    pub fn code(self) -> &'static str {
        match self {
            Same::Name => "name",
            Same::Nim => "nim",
            Same::Answers => "answers",
            Same::Attempt => "attempt",
        }
    }
}

/// Who a sheet says it is, as read from its file.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Identity {
    /// The name compared: the `student`'s, else the file's without a copy's
    /// ending, lower case, runs of spaces as one.
    pub name: String,
    /// Whether the name is the file's `student` (not only its file name).
    pub declared: bool,
    /// The `nim`, spaces removed.
    pub nim: Option<String>,
    /// The answers as typed, sorted (empty for a file with none or one not
    /// read).
    pub answers: String,
}

/// A name as compared: lower case, trimmed, runs of white space as one.
pub fn name_key(s: &str) -> String {
    s.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .to_lowercase()
}

/// A file's name without the ending a copy gets (`adi (1)`, `adi (12)`,
/// `adi - Copy`, `adi - Salinan`, `adi - Copy (2)`).
pub fn without_copy(stem: &str) -> &str {
    let mut s = stem.trim_end();
    loop {
        let before = s;
        if let Some(open) = s.strip_suffix(')').and_then(|x| x.rfind('(')) {
            let inside = &s[open + 1..s.len() - 1];
            if !inside.is_empty() && inside.chars().all(|c| c.is_ascii_digit()) {
                s = s[..open].trim_end();
            }
        }
        let lower = s.to_lowercase();
        for end in [" - copy", " - salinan", " copy"] {
            if lower.ends_with(end) && s.len() > end.len() {
                s = s[..s.len() - end.len()].trim_end();
                break;
            }
        }
        if s == before {
            return s;
        }
    }
}

/// Whether two sheets are the same student, and why (the first reason of
/// the module's list that holds).
pub fn same(a: &Identity, b: &Identity) -> Option<Same> {
    // two NIMs that differ are two students, whatever their names
    if a.nim.is_some() && b.nim.is_some() && a.nim != b.nim {
        return None;
    }
    if !a.name.is_empty() && a.name == b.name {
        return Some(Same::Name);
    }
    if a.nim.is_some() && a.nim == b.nim {
        return Some(Same::Nim);
    }
    let undeclared = !a.declared || !b.declared;
    (undeclared && !a.answers.is_empty() && a.answers == b.answers).then_some(Same::Answers)
}

/// Marks the duplicates of a class: each sheet that is the same student as
/// a kept one gets `duplicate` (the file kept, and why).
pub fn mark_duplicates(sheets: &mut [Sheet]) {
    let n = sheets.len();
    // the groups: each sheet's group is its lowest-numbered member
    let mut group: Vec<usize> = (0..n).collect();
    for i in 0..n {
        for j in 0..i {
            if same(&sheets[i].identity, &sheets[j].identity).is_some() {
                let (gi, gj) = (group[i], group[j]);
                let low = gi.min(gj);
                for g in group.iter_mut() {
                    if *g == gi || *g == gj {
                        *g = low;
                    }
                }
            }
        }
    }
    let times: Vec<Option<SystemTime>> = sheets.iter().map(|s| modified(&s.file)).collect();
    for g in 0..n {
        let members: Vec<usize> = (0..n).filter(|&i| group[i] == g).collect();
        if members.len() < 2 {
            continue;
        }
        // marked first, then the newest, then the last by name (the
        // sheets are in name order)
        let rank = |i: usize| (sheets[i].outcome.is_ok(), times[i], i);
        let Some(kept) = members.iter().copied().max_by_key(|&i| rank(i)) else {
            continue;
        };
        for &i in &members {
            if i == kept {
                continue;
            }
            let why = same(&sheets[i].identity, &sheets[kept].identity)
                .or_else(|| {
                    (members.iter()).find_map(|&j| {
                        (j != i)
                            .then(|| same(&sheets[i].identity, &sheets[j].identity))
                            .flatten()
                    })
                })
                .unwrap_or(Same::Name);
            sheets[i].duplicate = Some((sheets[kept].file.clone(), why));
        }
    }
}

fn modified(f: &Path) -> Option<SystemTime> {
    std::fs::metadata(f).and_then(|m| m.modified()).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_copys_ending_is_left_out_of_the_name() {
        assert_eq!(without_copy("adi (1)"), "adi");
        assert_eq!(without_copy("adi (12)"), "adi");
        assert_eq!(without_copy("Adi - Copy"), "Adi");
        assert_eq!(without_copy("adi - Salinan (2)"), "adi");
        assert_eq!(without_copy("adi copy"), "adi");
        // not a copy's ending
        assert_eq!(without_copy("adi (b)"), "adi (b)");
        assert_eq!(without_copy("adi"), "adi");
        assert_eq!(without_copy("(1)"), "");
        assert_eq!(name_key("  Adi   Nugroho "), "adi nugroho");
    }

    fn id(name: &str, declared: bool, nim: Option<&str>, answers: &str) -> Identity {
        Identity {
            name: name_key(name),
            declared,
            nim: nim.map(String::from),
            answers: answers.into(),
        }
    }

    #[test]
    fn the_same_student_by_name_nim_or_answers() {
        let a = id("Adi", true, None, "x=1");
        assert_eq!(same(&a, &id("adi", false, None, "x=2")), Some(Same::Name));
        assert_eq!(
            same(
                &id("Adi", true, Some("123"), "x"),
                &id("Adi N", true, Some("123"), "y")
            ),
            Some(Same::Nim)
        );
        // the same answers: the same student only when one names no one
        assert_eq!(
            same(&a, &id("adi2", false, None, "x=1")),
            Some(Same::Answers)
        );
        assert_eq!(same(&a, &id("Budi", true, None, "x=1")), None);
        // two empty files are two students who handed nothing in
        assert_eq!(
            same(&id("a", false, None, ""), &id("b", false, None, "")),
            None
        );
        // different NIMs: two students, even of the same name
        assert_eq!(
            same(
                &id("Adi", true, Some("1"), "x"),
                &id("Adi", true, Some("2"), "x")
            ),
            None
        );
    }
}
