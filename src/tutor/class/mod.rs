//! A class: a folder of answer files, one per student, marked against one
//! problem or against a whole exam written by `generate` ([`exam`]), by the
//! same judgement as one answer file ([`crate::tutor::check::Marker`]); and
//! the lecturer's statistics of the class ([`stats`]).
//!
//! A file that cannot be read or marked is a sheet with its error: the
//! others are marked all the same, and the statistics count only the
//! sheets marked.

pub mod exam;
pub mod fits;
pub mod moodle;
pub mod roster;
pub mod same;
pub mod stats;

use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::{ErrMsg, IoWhy, Msg};
use crate::tutor::check::{self, Answers, Marker, Marking, Settings};
use crate::tutor::generate::{problem_name, problem_number};
use crate::tutor::key::{Key, NotAKey};
use std::fmt;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::str::FromStr;

/// What a class answers: one problem, or an exam's variants, each a list of
/// problems named as `generate` names their files (`problem-01`, …).
#[derive(Clone, Debug)]
pub struct Paper {
    /// The title: the problem's, or the exam folder's name.
    pub title: String,
    /// The variants (one for a lone problem), each its problems in order.
    pub variants: Vec<Vec<Part>>,
    /// Whether this is an exam (answer files then hold `variant = N` and
    /// one `[problem-NN]` table per problem).
    pub exam: bool,
}

/// One problem of a paper.
#[derive(Clone, Debug)]
pub struct Part {
    /// `problem-01` in an exam; empty for a lone problem.
    pub name: String,
    /// The problem.
    pub problem: ProblemIn,
}

impl Paper {
    /// A lone problem.
    pub fn one(problem: ProblemIn) -> Paper {
        Paper {
            title: problem.title.clone(),
            variants: vec![vec![Part {
                name: String::new(),
                problem,
            }]],
            exam: false,
        }
    }

    /// The `i`th problem (0-based) as a class key names it: an exam's
    /// problem, none for a lone problem.
    pub fn problem(&self, i: usize) -> Option<usize> {
        self.exam.then_some(i)
    }
}

/// An answer key as the class report names it: `problem-01.view.n` in an
/// exam (the problem's name as `generate` writes its file), `view.n` for a
/// lone problem.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ClassKey {
    /// The problem of an exam, 0-based (`problem-01` is 0); none for a
    /// lone problem.
    pub problem: Option<usize>,
    /// The answer key within the problem.
    pub key: Key,
}

impl ClassKey {
    /// The problem's name (`problem-01`; empty for a lone problem).
    pub fn problem_name(&self) -> String {
        self.problem
            .map_or_else(String::new, |i| problem_name(i + 1))
    }
}

impl fmt::Display for ClassKey {
    /// `problem-01.view.n`, or `view.n` for a lone problem.
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self.problem {
            Some(_) => write!(f, "{}.{}", self.problem_name(), self.key),
            None => write!(f, "{}", self.key),
        }
    }
}

impl serde::Serialize for ClassKey {
    /// JSON writes a class key as its one spelling (its `Display`).
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl FromStr for ClassKey {
    type Err = NotAKey;

    /// Reads `problem-01.view.n` (a problem of an exam) and `view.n`.
    fn from_str(s: &str) -> std::result::Result<ClassKey, NotAKey> {
        let (problem, key) = match of_problem(s) {
            Some((i, rest)) => (Some(i), rest),
            None => (None, s),
        };
        Ok(ClassKey {
            problem,
            key: key.parse()?,
        })
    }
}

/// The problem (0-based) an exam's answer names first (`problem-01.view.n`
/// → 0) and the rest of the name (`view.n`).
fn of_problem(name: &str) -> Option<(usize, &str)> {
    let (head, rest) = name.split_once('.')?;
    Some((problem_number(head)?.checked_sub(1)?, rest))
}

/// The problem (0-based) an exam's answer file names first
/// (`problem-01.view.n` → 0) and the rest of the answer's name (`view.n`).
fn problem_of(name: &check::Name) -> Option<(usize, check::Name)> {
    let (head, rest) = name.split_first()?;
    Some((problem_number(head)?.checked_sub(1)?, rest))
}

/// One answer file of a class.
#[derive(Clone, Debug)]
pub struct Sheet {
    /// The file.
    pub file: PathBuf,
    /// The student: the file's `student`, else the file's name.
    pub who: String,
    /// The variant answered (1-based; 1 for a lone problem), when known.
    pub variant: Option<usize>,
    /// The exam's variant (1-based) of each problem, when the problems
    /// come from different variants: a Moodle quiz's random slots draw
    /// each problem's variant by itself, and `variant` is then the draw.
    /// Empty when the whole sheet is `variant`.
    pub drawn: Vec<usize>,
    /// The marking of each part (named as [`Part::name`]), or why the file
    /// could not be marked.
    pub outcome: Result<Vec<(String, Marking)>>,
    /// What was done with an unusual file.
    pub note: Option<Note>,
    /// Who the file says it is (its name, `nim`, answers as typed), to
    /// find the same student twice ([`same`]).
    pub identity: same::Identity,
    /// The file kept when this one is the same student as another, and
    /// why: then this one is not counted.
    pub duplicate: Option<(PathBuf, same::Same)>,
    /// Another variant whose key the answers fit far better than their
    /// own ([`fits`]).
    pub fits: Option<fits::Fits>,
}

impl Sheet {
    /// Points earned over every part.
    pub fn score(&self) -> Option<f64> {
        let m = self.outcome.as_ref().ok()?;
        Some(m.iter().fold(0.0, |s, (_, m)| s + m.score()))
    }
    /// Marks possible over every part (the schemes' totals).
    pub fn total(&self) -> Option<u32> {
        let m = self.outcome.as_ref().ok()?;
        Some(m.iter().map(|(_, m)| m.total()).sum())
    }
    /// The exam's variant of problem `p` (0-based) as the student had it.
    pub fn variant_of(&self, p: usize) -> Option<usize> {
        match self.drawn.is_empty() {
            true => self.variant,
            false => self.drawn.get(p).copied(),
        }
    }
    /// The exam's variants the student had, once each problem's when they
    /// differ: `3`, or `2/1/2` (problem 1 of variant 2, problem 2 of
    /// variant 1, …).
    pub fn variant_label(&self) -> String {
        match self.drawn.first() {
            Some(first) if self.drawn.iter().all(|d| d == first) => first.to_string(),
            Some(_) => (self.drawn.iter())
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join("/"),
            None => self.variant.map(|v| v.to_string()).unwrap_or_default(),
        }
    }
}

/// What was done with an unusual answer file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Note {
    /// It holds no answers: marked with every answer missing.
    Empty,
    /// It could not be read or marked (its error is in its row).
    NotMarked,
}

/// Why an entry of the answers folder was not read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Skip {
    /// A subdirectory (its files are not read).
    Subdirectory,
    /// Not a `.toml` file.
    NotToml,
}

/// A class marked: every sheet in file-name order, and the entries skipped.
#[derive(Clone, Debug)]
pub struct Class {
    /// The paper's title.
    pub title: String,
    /// Whether the paper is an exam.
    pub exam: bool,
    /// Every answer file, marked or with its error.
    pub sheets: Vec<Sheet>,
    /// Entries of the folder not read, with the reason.
    pub skipped: Skipped,
    /// The class list set against the files (`--roster`).
    pub roster: Option<roster::Roster>,
}

impl Class {
    /// One student's sheet as a class of its own (`check --answers FILE
    /// --csv`: the class's CSV of one row).
    pub fn of_one(sheet: Sheet, exam: bool) -> Class {
        Class {
            title: String::new(),
            exam,
            sheets: vec![sheet],
            skipped: Vec::new(),
            roster: None,
        }
    }

    /// The sheets marked, each student once (the statistics count these).
    pub fn marked(&self) -> impl Iterator<Item = &Sheet> {
        (self.sheets.iter()).filter(|s| s.outcome.is_ok() && s.duplicate.is_none())
    }
}

/// The markers of a paper's problems, by variant: each problem solved, and
/// the mistake catalog run on it, once for the whole class (shared: the
/// variants of a Moodle report's draws are marked by the exam's markers).
type Markers = Vec<Vec<Result<Rc<Marker>>>>;

fn markers(paper: &Paper, settings: Settings) -> Markers {
    (paper.variants.iter())
        .map(|v| {
            v.iter()
                .map(|p| Marker::new(&p.problem, settings).map(Rc::new))
                .collect()
        })
        .collect()
}

/// Marks every `*.toml` file of `dir` against the paper.
pub fn mark_dir(paper: &Paper, dir: &Path, settings: Settings) -> Result<Class> {
    let (files, skipped) = answer_files(dir)?;
    let markers = markers(paper, settings);
    let mut sheets: Vec<Sheet> = files
        .iter()
        .map(|f| mark_with(paper, &markers, f))
        .collect();
    same::mark_duplicates(&mut sheets);
    fits::mark_fits(paper, &markers, &mut sheets);
    Ok(Class {
        title: paper.title.clone(),
        exam: paper.exam,
        sheets,
        skipped,
        roster: None,
    })
}

/// Reads and marks one student's file: for an exam, its variant's problems
/// each against its `[problem-NN]` table.
pub fn mark_file(paper: &Paper, f: &Path, settings: Settings) -> Sheet {
    mark_with(paper, &markers(paper, settings), f)
}

fn mark_with(paper: &Paper, markers: &Markers, f: &Path) -> Sheet {
    let read = check::read_answers(f).map(|(s, answers)| {
        let (nim, answers): (Answers, Answers) =
            answers.into_iter().partition(|(k, _)| k.is("nim"));
        (s, answers, nim.into_iter().next().map(|(_, v)| v))
    });
    let stem = (f.file_stem()).map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let who = match &read {
        Ok((Some(s), _, _)) => s.clone(),
        _ => check::shown_name(&stem),
    };
    let identity = identity(&read, &stem);
    let read = read.map(|(s, answers, _)| (s, answers));
    mark_read(paper, markers, f, (who, identity), read)
}

/// Marks answers given in memory (a Moodle quiz's attempts, [`moodle`]),
/// each named and split as an answer file is, by the paper's markers.
fn mark_given(
    paper: &Paper,
    markers: &Markers,
    given: impl Iterator<Item = (PathBuf, String, Answers)>,
) -> Vec<Sheet> {
    given
        .map(|(f, who, answers)| {
            let who = check::shown_name(&who);
            let read = Ok((Some(who.clone()), answers, None));
            let identity = identity(&read, &who);
            let read = read.map(|(s, answers, _)| (s, answers));
            mark_read(paper, markers, &f, (who, identity), read)
        })
        .collect()
}

/// Marks answers read (from a file or given), for the student `who`
/// with the identity that finds them twice.
fn mark_read(
    paper: &Paper,
    markers: &Markers,
    f: &Path,
    (who, identity): (String, same::Identity),
    read: Result<(Option<String>, Answers)>,
) -> Sheet {
    let empty = matches!(&read, Ok((_, answers)) if answers.is_empty());
    let split = read.and_then(|(_, answers)| split(paper, &answers));
    let note = match &split {
        Err(_) => Some(Note::NotMarked),
        Ok(_) if empty => Some(Note::Empty),
        Ok(_) => None,
    };
    let variant = split.as_ref().ok().map(|(v, _)| *v);
    let outcome = split.and_then(|(v, parts)| {
        let problems = paper.variants[v - 1].iter().zip(&markers[v - 1]);
        problems
            .zip(parts)
            .map(|((part, marker), answers)| {
                let m = marker.as_ref().map_err(Clone::clone)?;
                Ok((part.name.clone(), m.mark(&who, &answers, false)))
            })
            .collect()
    });
    Sheet {
        file: f.to_path_buf(),
        who,
        variant,
        drawn: Vec::new(),
        outcome,
        note,
        identity,
        duplicate: None,
        fits: None,
    }
}

/// Who a file says it is: its `student` (else its file's name without a
/// copy's ending), its `nim`, its answers as typed.
fn identity(
    read: &Result<(Option<String>, Answers, Option<toml::Value>)>,
    stem: &str,
) -> same::Identity {
    let Ok((student, answers, nim)) = read else {
        return same::Identity {
            name: same::name_key(same::without_copy(stem)),
            ..Default::default()
        };
    };
    let nim = nim.as_ref().map(|v| match v {
        toml::Value::String(s) => s.split_whitespace().collect::<String>(),
        other => other.to_string(),
    });
    let mut typed: Vec<String> = answers.iter().map(|(k, v)| format!("{k}={v}")).collect();
    typed.sort();
    same::Identity {
        name: same::name_key(student.as_deref().unwrap_or(same::without_copy(stem))),
        declared: student.is_some(),
        nim: nim.filter(|n| !n.is_empty()),
        answers: typed.join("\n"),
    }
}

/// The variant a file answers and its answers to each problem of that
/// variant: a lone problem takes the whole file; an exam's file says
/// `variant = N` (not needed when there is one variant) and holds each
/// problem's answers in the table of its name.
fn split(paper: &Paper, answers: &Answers) -> Result<(usize, Vec<Answers>)> {
    if !paper.exam {
        return Ok((1, vec![answers.clone()]));
    }
    let v = exam::variant_of(answers, paper.variants.len())?;
    Ok((v, split_as(paper, answers, v)?))
}

/// An exam file's answers to each problem of variant `v` (1-based), by the
/// names of its tables, whatever variant it says.
fn split_as(paper: &Paper, answers: &Answers, v: usize) -> Result<Vec<Answers>> {
    let problems = &paper.variants[v - 1];
    let mut parts: Vec<Answers> = vec![Vec::new(); problems.len()];
    for (k, val) in (answers.iter()).filter(|(k, _)| !k.is("variant") && !k.is("nim")) {
        let Some((i, rest)) = problem_of(k).filter(|(i, _)| *i < problems.len()) else {
            let names: Vec<&str> = problems.iter().map(|p| p.name.as_str()).collect();
            let k = k.to_string();
            return Err(Error::why(
                k.as_str(),
                ErrMsg::NotAProblemOfExam(k.clone(), names.join(", ")),
            ));
        };
        parts[i].push((rest, val.clone()));
    }
    Ok(parts)
}

/// Entries of a folder not read, with the reason.
type Skipped = Vec<(PathBuf, Skip)>;

/// The `*.toml` files of a directory, sorted by name, and every other
/// entry with the reason it is not read.
fn answer_files(dir: &Path) -> Result<(Vec<PathBuf>, Skipped)> {
    let rd = std::fs::read_dir(dir).map_err(|e| {
        Error::said(
            "answers",
            Msg::ErrCannotRead(dir.display().to_string(), IoWhy::of(&e)),
        )
    })?;
    let mut all: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
    all.sort();
    let (files, others): (Vec<PathBuf>, Vec<PathBuf>) = all
        .into_iter()
        .partition(|p| p.is_file() && p.extension().is_some_and(|x| x == "toml"));
    let skipped = others
        .into_iter()
        .map(|p| {
            let why = if p.is_dir() {
                Skip::Subdirectory
            } else {
                Skip::NotToml
            };
            (p, why)
        })
        .collect();
    if files.is_empty() {
        return Err(Error::why(
            "answers",
            ErrMsg::NoAnswerFiles(dir.display().to_string()),
        ));
    }
    Ok((files, skipped))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tutor::key::{Field, Part, Value};

    #[test]
    fn a_class_key_reads_back_from_its_spelling() {
        for s in [
            "problem-01.view.n",
            "problem-12.clip.1.status",
            "problem-100.view.points.A.1",
            "view.n",
            "viewport",
        ] {
            let k: ClassKey = s.parse().unwrap_or_else(|_| panic!("{s}"));
            assert_eq!(k.to_string(), s);
        }
        let n = ClassKey {
            problem: Some(0),
            key: Key::new(
                Part::View,
                Value::Field(Field::Axis(crate::tutor::key::Axis::N)),
            ),
        };
        assert_eq!(n.to_string(), "problem-01.view.n");
        assert_eq!(n.problem_name(), "problem-01");
        let seg: ClassKey = "problem-02.clip[1].status".parse().expect("a key");
        assert_eq!(seg.problem, Some(1));
        assert_eq!(seg.to_string(), "problem-02.clip.1.status");
        // not a problem's name as `generate` writes it, nor a key
        for s in [
            "problem-1.view.n",
            "problem-00.view.n",
            "problem-01",
            "problem-01.top.x",
        ] {
            assert!(s.parse::<ClassKey>().is_err(), "{s}");
        }
    }
}
