//! A whole exam written by `grafika generate` as a paper for a class: its
//! folder holds `variant-01/`, `variant-02/`, … each with `problem-01.toml`,
//! `problem-02.toml`, … (or, with one variant, the problem files
//! themselves); the answer keys beside them (`problem-01.key.toml`) are not
//! read: grafika solves each problem again.
//!
//! A student's answer file says which variant it answers and holds one
//! table per problem, named as the problem's file:
//!
//! ```toml
//! student = "Ani"
//! variant = 3
//! [problem-01]
//! view.n = ["0.8", "0.6", "0"]
//! [problem-02]
//! window.top = "0.0414"
//! ```

use super::{Paper, Part};
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::ErrMsg;
use crate::msg::Lang;
use crate::tutor::check::Answers;
use crate::tutor::generate::{problem_name, variant_name};
use std::path::{Path, PathBuf};

/// Reads an exam folder: every variant's problem files, in order, each in
/// the chosen language.
pub fn read(dir: &Path, lang: Lang) -> Result<Paper> {
    let folders: Vec<PathBuf> = if dir.join(variant_name(1)).is_dir() {
        (1..)
            .map(|v| dir.join(variant_name(v)))
            .take_while(|d| d.is_dir())
            .collect()
    } else {
        vec![dir.to_path_buf()]
    };
    let mut variants = Vec::new();
    for folder in &folders {
        let files = (1..)
            .map(|i| {
                (
                    problem_name(i),
                    folder.join(format!("{}.toml", problem_name(i))),
                )
            })
            .take_while(|(_, f)| f.is_file());
        let mut parts = Vec::new();
        for (name, f) in files {
            let problem = ProblemIn::read(&f)?.localized(lang);
            parts.push(Part { name, problem });
        }
        if parts.is_empty() {
            return Err(Error::why(
                "file",
                ErrMsg::NoExam(folder.display().to_string()),
            ));
        }
        variants.push(parts);
    }
    let title = dir
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| dir.display().to_string());
    Ok(Paper {
        title,
        variants,
        exam: true,
    })
}

/// The variant an answer file answers (1-based): its `variant`, which may
/// be left out when the exam has one variant.
pub fn variant_of(answers: &Answers, variants: usize) -> Result<usize> {
    let given = answers
        .iter()
        .find(|(k, _)| k.is("variant"))
        .map(|(_, v)| v);
    let text = match given {
        None if variants == 1 => return Ok(1),
        None => return Err(Error::why("variant", ErrMsg::NoVariant(variants))),
        Some(toml::Value::String(s)) => s.trim().to_string(),
        Some(other) => other.to_string(),
    };
    match text.parse::<usize>() {
        Ok(v) if (1..=variants).contains(&v) => Ok(v),
        _ => Err(Error::why("variant", ErrMsg::NotAVariant(text, variants))),
    }
}
