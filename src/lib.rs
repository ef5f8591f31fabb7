//! grafika: a step-by-step tutor and calculator for the 3D viewing pipeline
//! and shading of the course text.
//!
//! The folders are layers, and a module imports only from the layers below
//! its own (no import runs upward or in a circle):
//!
//! | layer | what it holds |
//! |---|---|
//! | [`cli`] | the command line: clap arguments, flags read into the typed problem, dispatch, printing, exit codes |
//! | [`report`] | the one place where words for people are made: a report written as text, JSON, Markdown, LaTeX, HTML and figures, in every language, each format one type of [`report::writer`] implementing the traits of what it writes; each language is one module of [`report::words`] implementing its [`report::words::Words`] (one trait per family of keys, every method an exhaustive match), so a third language is one more module the compiler checks (docs/contributing.md) |
//! | [`tutor`] | the one solver (a problem's parts run through the stages, one module per part, [`tutor::parts`]), the report as data ([`tutor::solution`]), mark answers (check), the mistake catalog, generate exams |
//! | [`bench`](mod@bench) | run time against error of the float stages |
//! | [`render`] | the renderer: geometry, rasterization, shading, drawn with the stages |
//! | [`input`] | the typed problem ([`input::part::Problem`]: the parts asked, each with its inputs, given or taken from an earlier part, whether from a problem file or a calculator command's flags; the parts a file asks, [`input::ask::Part`], named once), scene, lights and mesh files, and flag values, read and validated |
//! | [`stages`] | the math the text teaches: camera, projection, window, clip, lighting; each writes its steps to a [`stages::trace::Trace`] |
//! | [`num`] | numbers: the `Scalar` trait, the exact type, floats, lanes, vectors, expressions, formatting |
//! | [`msg`] | message keys: what is said to a person, as data (`report::words` gives the words); the language, [`msg::Lang`], passed as itself to every layer |
//! | [`error`] | the error value every layer returns |
//!
//! Data flows one way: command-line flags or a problem file become one
//! typed problem; the one solver ([`tutor::solve::solve_problem`]) evaluates
//! it at the chosen precision and runs each part, by one match over the
//! typed part, through its part's module ([`tutor::parts`]), which write
//! their steps to a trace; it returns a typed report
//! ([`tutor::solution::Report`]: what was asked, what each part was given,
//! the named results, the steps), and [`report`] writes that as text, JSON,
//! HTML or figures.

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
