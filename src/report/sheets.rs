//! Exams for people: the title, the question sheet and the answer key (with
//! the worked solutions) of a generated exam, as Markdown or LaTeX bodies,
//! and the whole exam as JSON.

use crate::msg::DocWord;
use crate::report::blueprint::BlueprintJson;
use crate::report::doc::Doc;
use crate::report::json::{as_map, both, Both, SolutionJson};
use crate::report::lang::Lang;
use crate::report::words::{self, words};
use crate::report::Style;
use crate::stages::trace::Val;
use crate::tutor::generate::{key_lines, problem_name, topics_name, Difficulty, Generated, Topic};
use crate::tutor::key::Key;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// An exam's title: topics, difficulty, the seed (keys only: a question
/// sheet that showed it would let anyone regenerate the key) and variant.
pub fn exam_title(
    topics: &[Topic],
    diff: Difficulty,
    seed: Option<u64>,
    variant: Option<u32>,
    lang: Lang,
) -> String {
    let title = DocWord::ExamTitle {
        topics: topics_name(topics),
        difficulty: diff.name().to_string(),
        seed,
        variant,
    };
    words::of(lang).doc(&title)
}

/// A question sheet's title: the level in words and the variant (no
/// topics' codes, no seed: anyone could regenerate the key from it).
pub fn sheet_title(diff: Difficulty, variant: Option<u32>, lang: Lang) -> String {
    let title = DocWord::SheetTitle {
        difficulty: diff.name().to_string(),
        variant,
    };
    words::of(lang).doc(&title)
}

/// The key's title for an exam title.
pub fn key_title(title: &str, lang: Lang) -> String {
    words::of(lang).doc(&DocWord::KeyTitle(title.to_string()))
}

/// A generated problem's file: its title and statement in `lang`, then
/// what is asked and the data (docs/spec.md §5).
pub fn problem_file(g: &Generated, lang: Lang) -> String {
    let quoted = |m| toml::Value::String(words(m, lang)).to_string();
    format!(
        "title = {}\nstatement = {}\n{}",
        quoted(&g.title),
        quoted(&g.statement),
        g.body
    )
}

/// A generated problem's answer-key file: a comment with its title, then
/// `key = value` lines that `grafika check` reads.
pub fn key_file(g: &Generated, lang: Lang) -> String {
    format!(
        "# {}: {}\n{}",
        words::of(lang).doc(&DocWord::AnswerKey),
        words(&g.title, lang),
        key_lines(g)
    )
}

/// The answers asked for in a problem, with their values.
fn answers(g: &Generated) -> Vec<(String, Val)> {
    g.keys
        .iter()
        .filter_map(|key| Some((key.to_string(), g.report.result.get(key)?.into_owned())))
        .collect()
}

/// The question sheet and the key bodies.
pub fn sheets(doc: Doc, exam: &[Generated], st: &Style) -> (String, String) {
    let total = exam.iter().map(|g| g.scheme.total()).sum();
    let mut q = String::new();
    for line in [DocWord::NameLine, DocWord::TotalMarks(total)] {
        q.push_str(&doc.text(&st.doc(line)));
        q.push_str("\n\n");
    }
    let mut k = String::new();
    for (i, g) in exam.iter().enumerate() {
        let problem = st.doc(DocWord::Problem);
        let marks = st.doc(DocWord::Marks(g.scheme.total()));
        let title = &format!("{problem} {}: {} {marks}", i + 1, st.w(&g.title));
        let statement = st.w(&g.statement);
        for sheet in [&mut q, &mut k] {
            sheet.push_str(&doc.heading(1, title));
            sheet.push_str(&doc.text(&statement));
            sheet.push_str("\n\n");
        }
        k.push_str(&doc.heading(2, &st.doc(DocWord::Answers)));
        k.push_str(&doc.answers(st, &answers(g)));
        let figures = doc.figures(&g.report, st);
        if !figures.is_empty() {
            k.push_str(&doc.heading(2, &st.doc(DocWord::Figures)));
            k.push_str(&figures);
        }
        k.push_str(&doc.heading(2, &st.doc(DocWord::WorkedSolution)));
        k.push_str(&doc.steps(&g.report, st));
    }
    (q, k)
}

/// The whole exam as JSON: statements, answers (decimal and exact) and the
/// worked solutions.
#[derive(Serialize)]
pub struct ExamJson<'a> {
    title: &'a str,
    seed: u64,
    variant: u32,
    problems: Vec<ProblemJson<'a>>,
}

/// One problem of an exam: its file, words, keys and marks, answers and
/// worked solution.
#[derive(Serialize)]
struct ProblemJson<'a> {
    file: String,
    title: String,
    statement: String,
    keys: &'a [Key],
    #[serde(serialize_with = "as_map")]
    marks: Vec<(String, u32)>,
    total: u32,
    #[serde(serialize_with = "as_map")]
    answers: Vec<(String, Both)>,
    solution: SolutionJson<'a>,
}

/// The whole exam as JSON.
pub fn exam_json<'a>(
    title: &'a str,
    seed: u64,
    variant: u32,
    exam: &'a [Generated],
    lang: Lang,
) -> ExamJson<'a> {
    let problem = |(i, g): (usize, &'a Generated)| ProblemJson {
        file: format!("{}.toml", problem_name(i + 1)),
        title: words(&g.title, lang),
        statement: words(&g.statement, lang),
        keys: &g.keys,
        marks: (g.scheme.items.iter())
            .map(|i| (i.key.to_string(), i.marks))
            .collect(),
        total: g.scheme.total(),
        answers: answers(g)
            .iter()
            .map(|(k, v)| (k.clone(), both(v)))
            .collect(),
        solution: g.report.to_json(lang),
    };
    ExamJson {
        title,
        seed,
        variant,
        problems: exam.iter().enumerate().map(problem).collect(),
    }
}

/// What `generate --json` prints: the files written, with the seed and
/// the blueprint.
#[derive(Serialize)]
struct WrittenJson<'a> {
    command: &'static str,
    seed: u64,
    files: Vec<String>,
    blueprint: &'a BlueprintJson,
}

/// What `generate --json` prints: the files written, with the seed.
pub fn written_json(files: &[PathBuf], seed: u64, blueprint: &BlueprintJson) -> String {
    let j = WrittenJson {
        command: "generate",
        seed,
        files: files.iter().map(|f| f.display().to_string()).collect(),
        blueprint,
    };
    serde_json::to_string_pretty(&j).unwrap_or_default() + "\n"
}

/// What `generate` prints: how many files of what went where, and the first
/// twelve of them.
pub fn written_summary(
    files: &[PathBuf],
    variants: u32,
    count: u32,
    topics: &[Topic],
    seed: u64,
    out: (&Path, Lang),
) -> String {
    let (out, lang) = out;
    let wrote = DocWord::Wrote {
        files: files.len(),
        variants,
        count,
        topics: topics_name(topics),
        seed,
        out: out.display().to_string(),
    };
    let mut s = format!("{}\n", words::of(lang).doc(&wrote));
    for f in files.iter().take(12) {
        let _ = writeln!(s, "  {}", f.display());
    }
    if files.len() > 12 {
        let more = words::of(lang).doc(&DocWord::More(files.len() - 12));
        let _ = writeln!(s, "  {more}");
    }
    s
}
