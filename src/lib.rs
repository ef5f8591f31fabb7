//! grafika: a step-by-step tutor and calculator for the 3D viewing pipeline
//! and shading of the course text.
//!
//! The folders are layers, and a module imports only from the layers below
//! its own (no import runs upward or in a circle):
//!
//! | layer | what it holds |
//! |---|---|
//! | [`cli`] | the command line: clap arguments, validation into values, dispatch, printing, exit codes |
//! | [`report`] | the one place where words for people are made: text, JSON, Markdown, LaTeX, in every language |
//! | [`tutor`] | solve a problem file, mark answers (check), the mistake catalog, generate exams |
//! | [`bench`] | run time against error of the float stages |
//! | [`render`] | the renderer: geometry, rasterization, shading, drawn with the stages |
//! | [`input`] | problem, scene, lights and mesh files, and flag values, read and validated |
//! | [`stages`] | the math the text teaches: camera, projection, window, clip, lighting; each writes its steps to a [`stages::trace::Trace`] |
//! | [`num`] | numbers: the `Scalar` trait, the exact type, floats, lanes, vectors, expressions, formatting |
//! | [`msg`] | message keys: what is said to a person, as data (`report::words` gives the words); the language, [`msg::Lang`], passed as itself to every layer |
//! | [`error`] | the error value every layer returns |
//!
//! Data flows one way: command-line flags or a problem file are validated
//! into plain values, the stage functions compute with them at the chosen
//! precision while writing their steps to a trace, and a report turns the
//! steps and results into text or JSON.

pub mod bench;
pub mod cli;
pub mod error;
pub mod input;
pub mod msg;
pub mod num;
pub mod render;
pub mod report;
pub mod stages;
pub mod tutor;
