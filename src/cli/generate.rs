//! `grafika generate`: draws the exams (tutor), has them written as sheets
//! and keys (report), and writes the files.

use crate::cli::args::GenerateArgs;
use crate::cli::stage::Stage;
use crate::error::{Error, Result};
use crate::msg::{Bound, ErrMsg};
use crate::report::moodle::Written;
use crate::report::quizfile::pack;
use crate::report::sheets::{
    exam_title, key_file, problem_file, sheet_title, written_json, written_summary,
};
use crate::report::writer::{ExamPaper, ExamWriter, QuizWriter};
use crate::report::Style;
use crate::tutor::check::DEFAULT_TOLERANCE;
use crate::tutor::generate::blueprint::blueprint;
use crate::tutor::generate::quiz::Quiz;
use crate::tutor::generate::{exams, problem_name, variant_name, Exams, Generated, Spec};
use std::path::PathBuf;

/// Runs `grafika generate`; returns what to print. `force`: `--force`.
pub fn run(a: &GenerateArgs, force: bool, json: bool, style: &Style) -> Result<String> {
    let writer = a.format.writer();
    let (files, plan) = write_exams(a, &*writer, force, style)?;
    Ok(if json {
        written_json(&files, a.seed, &plan.json)
    } else {
        let mut s = written_summary(
            &files,
            a.variants,
            a.count,
            &a.topic,
            a.seed,
            (&a.out, style.lang),
        );
        if let Some(note) = writer.quiz().and_then(|q| q.note()) {
            // said to the lecturer here, never to students in a question
            s.push_str(&crate::report::words::of(style.lang).quiz(&note));
            s.push('\n');
        }
        s.push('\n');
        s.push_str(&plan.table);
        s
    })
}

/// An exam's blueprint as `generate` prints it (the table) and writes it
/// (blueprint.md, blueprint.json).
pub struct Plan {
    /// The Markdown table printed.
    pub table: String,
    /// blueprint.json's value.
    pub json: crate::report::blueprint::BlueprintJson,
    /// blueprint.md.
    pub markdown: String,
}

/// The blueprint of a drawn exam in the user's language.
fn plan(drawn: &Exams, style: &Style) -> Plan {
    let bp = blueprint(drawn);
    let first = drawn.variants.first();
    let titles: Vec<String> = (first.iter().flat_map(|v| v.iter()))
        .map(|g| style.w(&g.title))
        .collect();
    let topics: Vec<&str> = drawn.forms.iter().map(|f| f.topic.name()).collect();
    let table = crate::report::blueprint::table(&bp, &titles, style.lang);
    Plan {
        json: crate::report::blueprint::json(&bp, &topics),
        markdown: crate::report::blueprint::markdown(&bp, &table, style),
        table,
    }
}

/// The blueprint's files, (name, text), written beside the exam.
fn plan_files(plan: &Plan) -> [(String, String); 2] {
    [
        (BLUEPRINT_MD.to_string(), plan.markdown.clone()),
        (
            BLUEPRINT_JSON.to_string(),
            serde_json::to_string_pretty(&plan.json).unwrap_or_default() + "\n",
        ),
    ]
}

/// The blueprint's file names.
pub const BLUEPRINT_MD: &str = "blueprint.md";
/// See [`BLUEPRINT_MD`].
pub const BLUEPRINT_JSON: &str = "blueprint.json";

/// More problems than this (count × variants) are written only with `--force`.
pub const MAX_PROBLEMS: u64 = 2_000;

/// About how many bytes one problem takes on disk (its problem file, key
/// and worked solution), for the size given when refusing.
const BYTES_PER_PROBLEM: u64 = 16_000;

/// Refuses, unless `--force`, more than [`MAX_PROBLEMS`] problems.
fn check_size(a: &GenerateArgs, force: bool) -> Result<()> {
    let n = a.count as u64 * a.variants as u64;
    if n > MAX_PROBLEMS && !force {
        return Err(Error::why(
            "count",
            ErrMsg::TooManyProblems(
                n,
                a.count as u64,
                a.variants as u64,
                n * BYTES_PER_PROBLEM / 1_000_000,
                MAX_PROBLEMS,
            ),
        ));
    }
    Ok(())
}

/// The names the output has in `--out`: `quiz.xml`, `variant-01` …, or one
/// exam's files (a quiz split by `--split-mb`: [`QuizWriter::file_name`]).
fn entries(a: &GenerateArgs, writer: &dyn ExamWriter) -> Vec<String> {
    let mut names = match writer.quiz() {
        Some(q) => return quiz_entries(q),
        None if a.variants == 1 => exam_files(a.count, writer),
        None => (1..=a.variants).map(|v| variant_name(v as usize)).collect(),
    };
    names.extend([BLUEPRINT_MD, BLUEPRINT_JSON].map(String::from));
    names
}

/// The names a quiz (not split) has in `--out`: `quiz.xml` and the
/// blueprint.
fn quiz_entries(q: &dyn QuizWriter) -> Vec<String> {
    let mut names = vec![q.file_name(None)];
    names.extend([BLUEPRINT_MD, BLUEPRINT_JSON].map(String::from));
    names
}

/// The files of one exam: problem and key files, then the sheets.
fn exam_files(count: u32, writer: &dyn ExamWriter) -> Vec<String> {
    let mut names: Vec<String> = (1..=count)
        .flat_map(|i| {
            [
                format!("{}.toml", problem_name(i as usize)),
                format!("{}.key.toml", problem_name(i as usize)),
            ]
        })
        .collect();
    names.extend(writer.sheet_names());
    names
}

/// Generates and writes every variant, the whole output or nothing (see
/// [`Stage`], the blueprint beside it); returns the files written and the
/// blueprint.
pub fn write_exams(
    a: &GenerateArgs,
    writer: &dyn ExamWriter,
    force: bool,
    style: &Style,
) -> Result<(Vec<PathBuf>, Plan)> {
    check_size(a, force)?;
    let limit = split_limit(a, writer)?;
    if let Some(q) = writer.quiz() {
        let rel = quiz_tolerance(a)?;
        // drawn before anything is written: an exam that cannot be made
        // leaves the output directory as it was
        let drawn = draw(a, style)?;
        let plan = plan(&drawn, style);
        let files = write_quiz(a, q, (rel, limit), (drawn, plan_files(&plan)), force, style)?;
        return Ok((files, plan));
    }
    let drawn = draw(a, style)?;
    let plan = plan(&drawn, style);
    let mut stage = Stage::begin(&a.out, entries(a, writer), force, run_of(a))?;
    let mut files = Vec::new();
    for (v, exam) in drawn.variants.iter().enumerate() {
        let dir = if a.variants == 1 {
            String::new()
        } else {
            format!("{}/", variant_name(v + 1))
        };
        let variant = (writer, v as u32 + 1);
        files.extend(write_exam(&mut stage, &dir, a, variant, exam, style)?);
    }
    for (name, text) in plan_files(&plan) {
        files.push(stage.write(&name, &text)?);
    }
    stage.commit()?;
    Ok((files, plan))
}

/// The run, as the list of generate's own files says it: what it was
/// asked, so that the same command writes the same list.
fn run_of(a: &GenerateArgs) -> String {
    use clap::ValueEnum;
    let topics: Vec<&str> = a.topic.iter().map(|t| t.name()).collect();
    let format = a.format.to_possible_value();
    format!(
        "(seed {}, topic {}, difficulty {}, count {}, variants {}, format {})",
        a.seed,
        topics.join(","),
        a.difficulty.name(),
        a.count,
        a.variants,
        format.as_ref().map_or("", |v| v.get_name()),
    )
}

/// The exam the arguments ask for.
fn spec(a: &GenerateArgs) -> Spec {
    Spec {
        topics: a.topic.clone(),
        difficulty: a.difficulty,
        count: a.count,
        variants: a.variants,
        seed: a.seed,
        clip: a.clip,
    }
}

/// Draws every variant of the exam, with a progress bar over its problems
/// on a terminal when there are more than 100 (smaller exams are drawn in
/// well under a second).
fn draw(a: &GenerateArgs, style: &Style) -> Result<Exams> {
    let n = a.count as u64 * a.variants as u64;
    let msg = crate::report::words::of(style.lang).cli(crate::msg::CliWord::Problems);
    let bar = (n > 100).then(|| super::terminal_bar(n, msg)).flatten();
    let drawn = exams(&spec(a), &mut |k| bar.iter().for_each(|b| b.inc(k)));
    bar.iter().for_each(|b| b.finish_and_clear());
    drawn
}

/// Writes one exam's files (into `dir`, `` or `variant-NN/`): the problem
/// and key files, then the sheets the format's writer writes.
fn write_exam(
    stage: &mut Stage,
    dir: &str,
    a: &GenerateArgs,
    (writer, variant): (&dyn ExamWriter, u32),
    exam: &[Generated],
    style: &Style,
) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let mut put = |name: String, text: String| -> Result<()> {
        files.push(stage.write(&format!("{dir}{name}"), &text)?);
        Ok(())
    };
    for (i, g) in exam.iter().enumerate() {
        put(
            format!("{}.toml", problem_name(i + 1)),
            problem_file(g, style.lang),
        )?;
        put(
            format!("{}.key.toml", problem_name(i + 1)),
            key_file(g, style.lang),
        )?;
    }
    let numbered = (a.variants > 1).then_some(variant);
    let paper = ExamPaper {
        title: exam_title(&a.topic, a.difficulty, Some(a.seed), numbered, style.lang),
        // The question sheet does not show the seed (anyone could regenerate the key).
        sheet_title: sheet_title(a.difficulty, numbered, style.lang),
        seed: a.seed,
        variant,
        problems: exam,
    };
    for (name, text) in writer.sheets(&paper, style) {
        put(name, text)?;
    }
    Ok(files)
}

/// The relative tolerance of a quiz: `--tolerance`, else 0.1 %; it must be
/// a number in (0, 1), so that no nonzero key gets a zero tolerance.
fn quiz_tolerance(a: &GenerateArgs) -> Result<f64> {
    let r = a.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    if r.is_finite() && r > 0.0 && r < 1.0 {
        Ok(r)
    } else {
        Err(Error::why("tolerance", ErrMsg::MustBe(Bound::Fraction, r)))
    }
}

/// The bytes a quiz file may have, from `--split-mb` (megabytes of 10⁶
/// bytes, a number above 0), given only with a quiz's format.
fn split_limit(a: &GenerateArgs, writer: &dyn ExamWriter) -> Result<Option<usize>> {
    let Some(mb) = a.split_mb else {
        return Ok(None);
    };
    if writer.quiz().is_none() {
        return Err(Error::why("split-mb", ErrMsg::SplitNotQuiz));
    }
    if !(mb.is_finite() && mb > 0.0) {
        return Err(Error::why("split-mb", ErrMsg::MustBe(Bound::AboveZero, mb)));
    }
    Ok(Some((mb * 1e6).floor().min(usize::MAX as f64) as usize))
}

/// Writes every variant into one Moodle XML or GIFT file in the output
/// directory (quiz.xml or quiz.gift), or, with a `limit` in bytes, into
/// as many files as it takes, none larger (quiz-01.xml, …). An existing
/// entry is refused before the work (the names of a split quiz are known
/// once it is written: any quiz file is refused then, without `--force`).
fn write_quiz(
    a: &GenerateArgs,
    q: &dyn QuizWriter,
    (rel, limit): (f64, Option<usize>),
    (drawn, beside): (Exams, [(String, String); 2]),
    force: bool,
    style: &Style,
) -> Result<Vec<PathBuf>> {
    let early = match limit {
        None => Some(Stage::begin(&a.out, quiz_entries(q), force, run_of(a))?),
        Some(_) => {
            refuse_quiz_files(a, q, force)?;
            None
        }
    };
    let mut texts = quiz_files(a, q, (rel, limit), drawn, style)?;
    texts.extend(beside);
    let mut stage = match early {
        Some(stage) => stage,
        None => Stage::begin(
            &a.out,
            texts.iter().map(|(n, _)| n.clone()).collect(),
            force,
            run_of(a),
        )?,
    };
    let files = (texts.iter())
        .map(|(name, text)| stage.write(name, text))
        .collect::<Result<Vec<_>>>()?;
    stage.commit()?;
    Ok(files)
}

/// Without `--force`, an error naming a quiz file already in `--out`
/// (`quiz.xml` or `quiz-NN.xml`; `.gift`): a split quiz's names are known
/// only once it is written, so any of them is refused before the work.
fn refuse_quiz_files(a: &GenerateArgs, q: &dyn QuizWriter, force: bool) -> Result<()> {
    if force {
        return Ok(());
    }
    let ext = format!(".{}", q.extension());
    let Ok(dir) = std::fs::read_dir(&a.out) else {
        return Ok(());
    };
    let quiz = |name: &String| {
        let numbered = (name.strip_prefix("quiz-"))
            .and_then(|r| r.strip_suffix(&ext))
            .is_some_and(|k| !k.is_empty() && k.chars().all(|c| c.is_ascii_digit()));
        numbered || *name == q.file_name(None)
    };
    let first = (dir.flatten())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(quiz)
        .min();
    match first {
        Some(name) => {
            let shown = a.out.join(&name).display().to_string();
            Err(Error::why("out", ErrMsg::ExistsForce(shown)))
        }
        None => Ok(()),
    }
}

/// The quiz's files, (name, text): one, or split under `limit` bytes.
fn quiz_files(
    a: &GenerateArgs,
    q: &dyn QuizWriter,
    (rel, limit): (f64, Option<usize>),
    drawn: Exams,
    style: &Style,
) -> Result<Vec<(String, String)>> {
    let quiz = Quiz::new(drawn.variants, &a.topic, rel);
    let w = Written::new(style, a.decimal);
    let (units, frame) = (q.units(&quiz, &w), q.frame());
    let texts = pack(&units, frame, limit).map_err(|i| {
        let mb = |bytes: usize| crate::msg::Fixed(bytes as f64 / 1e6, 3);
        let size =
            units[i].text.len() + units[i].category.len() + frame.head.len() + frame.foot.len();
        let limit = mb(limit.unwrap_or(0));
        Error::why(
            "split-mb",
            ErrMsg::QuestionTooLarge(units[i].name.clone(), mb(size), limit),
        )
    })?;
    Ok(match limit {
        None => texts.into_iter().map(|t| (q.file_name(None), t)).collect(),
        Some(_) => (texts.into_iter().enumerate())
            .map(|(k, t)| (q.file_name(Some(k + 1)), t))
            .collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::args::Format;
    use crate::report::lang::Lang;
    use crate::tutor::generate::{ClipCase, Difficulty, Topic};
    use clap::ValueEnum;

    /// Every `--format`'s writer writes one exam's sheets under the names
    /// it gives before anything is written (the output's entries, which
    /// the stage lists), each with the format's extension; a quiz format
    /// writes no sheets of its own.
    #[test]
    fn each_format_writes_the_sheets_it_names() {
        let spec = Spec {
            topics: vec![Topic::View, Topic::Clip],
            difficulty: Difficulty::Easy,
            count: 2,
            variants: 1,
            seed: 7,
            clip: ClipCase::Clipped,
        };
        let drawn = exams(&spec, &mut |_| {}).expect("draws");
        let style = Style::new(4, true, Lang::Id);
        for format in Format::value_variants() {
            let w = format.writer();
            let paper = ExamPaper {
                title: "Ujian".into(),
                sheet_title: "Soal".into(),
                seed: 7,
                variant: 1,
                problems: &drawn.variants[0],
            };
            let sheets = w.sheets(&paper, &style);
            let names: Vec<String> = sheets.iter().map(|(n, _)| n.clone()).collect();
            assert_eq!(names, w.sheet_names(), "{format:?}");
            let ext = format!(".{}", w.extension());
            assert!(
                names.iter().all(|n| n.ends_with(&ext)),
                "{format:?}: {names:?}"
            );
            assert!(
                sheets.iter().all(|(_, text)| !text.is_empty()),
                "{format:?}"
            );
            assert!(w.quiz().is_none() || names.is_empty(), "{format:?}");
        }
    }

    /// A quiz's files (docs/spec.md §4): `quiz.xml`, `quiz.gift`, and the
    /// k-th file of a split quiz `quiz-0k.EXT`.
    #[test]
    fn a_quiz_is_named_by_its_format() {
        let quiz = |f: Format| {
            let w = f.writer();
            let q = w.quiz().map(|q| (q.file_name(None), q.file_name(Some(3))));
            q.expect("a quiz format")
        };
        assert_eq!(
            quiz(Format::Moodle),
            ("quiz.xml".into(), "quiz-03.xml".into())
        );
        assert_eq!(
            quiz(Format::Gift),
            ("quiz.gift".into(), "quiz-03.gift".into())
        );
        assert!(Format::Md.writer().quiz().is_none());
    }
}
