//! The command line (docs/spec.md §4): clap definitions, dispatch by precision, and
//! the single place where a report or an error is printed.

pub mod args;
pub mod calc;
pub mod check;
pub mod generate;
pub mod moodle;
pub mod practice;
pub mod print;
mod refused;
pub mod render;
pub mod signals;
pub mod stage;
pub mod write;

use crate::bench::accuracy::Stage;
use crate::error::{Error, Result};
use crate::input::part::Problem;
use crate::input::problem::ProblemIn;
use crate::msg::{CliWord, DocWord, ErrMsg, Msg};
use crate::num::Precision;
use crate::report::lang::Lang;
use crate::report::words;
use crate::report::writer::{self, SolutionWriter};
use crate::report::Style;
use crate::tutor::solution::Report;
use args::{Cli, Command};
use clap::Parser;
use print::{Kind, Stopped};
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use write::Outputs;

/// Runs a generic command at the precision asked for.
macro_rules! at_precision {
    ($p:expr, $f:ident ( $($arg:expr),* )) => {
        match $p {
            Precision::Exact => $f::<crate::num::Real>($($arg),*),
            Precision::F64 => $f::<f64>($($arg),*),
            Precision::F32 => $f::<f32>($($arg),*),
        }
    };
}

/// Runs one parsed command line; a result that is not a finite number is
/// refused (an error naming it), never printed.
pub fn run(cli: &Cli) -> Result<Report> {
    run_writing(cli, &Outputs::new(cli.common.force))
}

/// [`run`], writing `render`'s PNG through `outputs`.
fn run_writing(cli: &Cli, outputs: &Outputs) -> Result<Report> {
    crate::num::real::take_grew_too_large();
    let mut report = run_unchecked(cli, outputs)?;
    let grew = crate::num::real::take_grew_too_large();
    if grew.terms {
        let n = crate::num::real::MAX_EXACT_TERMS;
        report.warnings.push(Msg::ExactTooLarge(n));
    }
    if grew.bits {
        report
            .warnings
            .push(Msg::ExactTooLong(crate::num::real::MAX_EXACT_BITS));
    }
    // A NaN or ∞ in a step is refused as one in the results is.
    let step = || report.non_finite_step_value();
    match report.non_finite_result().or_else(step) {
        Some(key) => Err(Error::why(
            key,
            match cli.common.precision {
                Precision::Exact => ErrMsg::ExactBeyondF64,
                p => ErrMsg::ResultNotFinite(p.name().to_string()),
            },
        )),
        None => Ok(report),
    }
}

fn run_unchecked(cli: &Cli, outputs: &Outputs) -> Result<Report> {
    let p = cli.common.precision;
    let problem = match &cli.command {
        Command::Solve { file, .. } => {
            Problem::of_file(ProblemIn::read(file)?.localized(style_of(cli).lang))?
        }
        // The renderer computes at f32 (the calculator's precisions are for
        // explaining): another --precision is refused, not ignored.
        Command::Render(_) if p != Precision::Exact => {
            return Err(Error::why("precision", ErrMsg::RenderPrecision))
        }
        Command::Render(a) => return crate::cli::render::run(a, style_of(cli).lang, outputs),
        c => match calc::part_of(c) {
            Some(problem) => problem?,
            None => return Err(Error::why("command", ErrMsg::OwnOutput)),
        },
    };
    at_precision!(p, solve(&problem))
}

fn solve<T: crate::num::Scalar>(p: &Problem) -> Result<Report> {
    crate::tutor::solve::solve_problem::<T>(p)
}

/// Parses the arguments, runs, prints; returns the exit status (0, or 2 for
/// any error).
pub fn main_with_args(args: Vec<OsString>) -> i32 {
    let wants_json = args.iter().any(|a| a == "--json");
    let cli = match Cli::try_parse_from(&args) {
        Ok(c) => c,
        Err(e) => {
            let lang = refused::lang_of_args(&args);
            if let Some((opt, command)) = refused::shared_option_after(&e, &args) {
                let lang = lang.unwrap_or_else(|| Lang::from_env(|k| std::env::var(k).ok()));
                return report_error(&misplaced(opt, &command), wants_json, lang);
            }
            return clap_error(e, wants_json, lang);
        }
    };
    let style = style_of(&cli);
    let json = cli.common.json;
    if let Some((opt, command)) = cli.common.misplaced {
        return report_error(&misplaced(opt, command), json, style.lang);
    }
    let outputs = Outputs::new(cli.common.force);
    if let Err(e) = before_any_work(&cli, &outputs) {
        return report_error(&e, json, style.lang);
    }
    let printed = match &cli.command {
        Command::Bench { quick, cases } => Ok((bench(*quick, *cases, json, style.lang), 0)),
        Command::Completions { shell } => Ok((completions(*shell), 0)),
        Command::Man => man().map(|t| (t, 0)),
        Command::Check(a) => check::run(a, json, &style, &outputs),
        Command::Generate(a) => generate::run(a, cli.common.force, json, &style).map(|t| (t, 0)),
        Command::Practice(a) => practice::run(a, json, &style).map(|()| (String::new(), 0)),
        _ => run_writing(&cli, &outputs).and_then(|mut report| {
            if write_figure(&cli.command, &report, &style, &outputs)? == Some(0) {
                report.warnings.push(Msg::NoFigure);
            }
            write_html(&cli, &report, &style, &outputs)?;
            Ok((report_text(&report, json, &style), 0))
        }),
    };
    // `render -o -` writes the PNG on standard output: the summary goes to stderr.
    // What the writers did besides (a stale temporary file removed).
    for note in write::take_notes() {
        print::stderr_line(&format!(
            "{}: {}",
            style.doc(DocWord::Warning),
            style.w(&note)
        ));
    }
    let png_on_stdout = matches!(&cli.command, Command::Render(a) if a.output.as_os_str() == "-");
    match printed {
        Ok((text, status)) if png_on_stdout => {
            text.lines().for_each(print::stderr_line);
            status
        }
        Ok((text, status)) => {
            let kind = if json {
                Kind::Json
            } else {
                Kind::Text { colour: false }
            };
            match print::stdout(&text, kind) {
                Ok(()) => status,
                Err(stopped) => stopped_status(stopped, status, json, style.lang),
            }
        }
        Err(e) => report_error(&e, json, style.lang),
    }
}

/// The exit status after printing stopped: a broken pipe ends quietly
/// (with the command's own status, after removing any temporary file);
/// another write error is an error.
pub fn stopped_status(stopped: Stopped, status: i32, json: bool, lang: Lang) -> i32 {
    match stopped {
        Stopped::Pipe => {
            signals::clean_up();
            status
        }
        Stopped::Failed(e) => report_error(&e, json, lang),
    }
}

/// What is refused before any work is done: a closed standard output, and
/// every output file already known to be refused (an existing file without
/// `--force`, one of the inputs, a link, a folder), so that nothing is
/// computed or written in vain. The command's input files are noted.
fn before_any_work(cli: &Cli, outputs: &Outputs) -> Result<()> {
    print::refuse_closed_stdout()?;
    match &cli.command {
        Command::Solve { file: f, .. } => outputs.reads([f.as_path()]),
        Command::Shade(a) => outputs.reads(a.lights.iter().map(PathBuf::as_path)),
        Command::Render(a) => outputs.reads([a.scene.as_path()]),
        Command::Check(a) => {
            let inputs: Vec<PathBuf> = (a.answers.iter())
                .chain(a.moodle_responses.iter())
                .chain([&a.file])
                .flat_map(check::input_paths)
                .collect();
            outputs.reads([a.file.as_path()]);
            outputs.reads(inputs.iter().map(PathBuf::as_path));
        }
        _ => {}
    }
    let mut planned: Vec<(&Path, &str)> = Vec::new();
    if let Some(h) = &cli.common.html {
        planned.push((h, "html"));
    }
    match &cli.command {
        Command::Render(a) if a.output.as_os_str() != "-" => planned.push((&a.output, "output")),
        Command::Check(a) => {
            let csv = a.csv.iter().filter(|c| c.as_os_str() != "-");
            planned.extend(csv.map(|c| (c.as_path(), "csv")));
            planned.extend(a.report.iter().map(|r| (r.as_path(), "report")));
        }
        Command::Solve {
            figure: Some(f), ..
        } if write::names_a_folder(f) => {
            return Err(Error::why(
                "figure",
                ErrMsg::NamesFolder(f.display().to_string()),
            ))
        }
        c => planned.extend(figure_path(c).map(|f| (f.as_path(), "figure"))),
    }
    // The same file given to two flags (by any name) is refused before
    // anything is written; a device such as /dev/null may take several.
    for (i, (p, field)) in planned.iter().enumerate() {
        let twice = planned[..i].iter().find(|(q, _)| write::same_path(q, p));
        if let Some((_, other)) = twice.filter(|_| !write::is_device(p)) {
            let shown = p.display().to_string();
            return Err(Error::why(
                *field,
                ErrMsg::SameOutput(shown, other.to_string()),
            ));
        }
    }
    for (p, field) in &planned {
        outputs.check(p, field)?;
    }
    Ok(())
}

/// The `--figure` path of a calculator command (not `solve`, whose files
/// are named after its parts).
fn figure_path(cmd: &Command) -> Option<&PathBuf> {
    match cmd {
        Command::Basis(c) | Command::View { camera: c, .. } => c.figure.as_ref(),
        Command::Project(a) => a.figure.as_ref(),
        Command::Window(a) => a.figure.as_ref(),
        Command::Clip(a) => a.figure.as_ref(),
        Command::Shade(a) => a.figure.as_ref(),
        _ => None,
    }
}

/// The shell's completion script for every command and flag.
fn completions(shell: clap_complete::Shell) -> String {
    use clap::CommandFactory;
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "grafika", &mut out);
    String::from_utf8_lossy(&out).into_owned()
}

/// The manual page (roff), one page for the whole program: the global
/// options, then each command with its synopsis, description and every
/// flag it takes (a section per command, its parts as subsections).
fn man() -> Result<String> {
    use clap::CommandFactory;
    let err = |e: std::io::Error| Error::why("man", ErrMsg::Man(e.to_string()));
    let mut cmd = Cli::command();
    cmd.build();
    // The program's own sections, without clap's list of commands (it names
    // pages grafika-basis(1), … that are not written: each command has its
    // section on this page instead).
    let top = clap_mangen::Man::new(cmd.clone());
    let mut out = Vec::new();
    top.render_title(&mut out).map_err(err)?;
    let mut head = Vec::new();
    top.render_name_section(&mut head).map_err(err)?;
    top.render_synopsis_section(&mut head).map_err(err)?;
    top.render_description_section(&mut head).map_err(err)?;
    top.render_options_section(&mut head).map_err(err)?;
    top.render_version_section(&mut head).map_err(err)?;
    out.extend_from_slice(sections(&String::from_utf8_lossy(&head), ".SH ").as_bytes());
    let commands = cmd
        .get_subcommands()
        .filter(|s| !s.is_hide_set() && s.get_name() != "help");
    for sub in commands {
        let name = format!("grafika {}", sub.get_name());
        let page = clap_mangen::Man::new(sub.clone().bin_name(&name));
        let mut part = Vec::new();
        page.render_synopsis_section(&mut part).map_err(err)?;
        page.render_description_section(&mut part).map_err(err)?;
        page.render_options_section(&mut part).map_err(err)?;
        if sub.get_after_help().is_some() || sub.get_after_long_help().is_some() {
            page.render_extra_section(&mut part).map_err(err)?;
        }
        out.extend_from_slice(format!(".SH \"{}\"\n", name.to_uppercase()).as_bytes());
        out.extend_from_slice(sections(&String::from_utf8_lossy(&part), ".SS ").as_bytes());
    }
    Ok(String::from_utf8_lossy(&out).into_owned())
}

/// Rendered sections without roff's preamble (the title wrote it once),
/// each heading as `level` (`.SS` for a command's sections under its own;
/// clap's EXTRA as EXAMPLES).
fn sections(part: &str, level: &str) -> String {
    (part.lines())
        .filter(|l| !l.starts_with(".ie ") && !l.starts_with(".el "))
        .map(|l| match l.strip_prefix(".SH ") {
            Some("EXTRA") => format!("{level}EXAMPLES\n"),
            Some(h) => format!("{level}{h}\n"),
            None => format!("{l}\n"),
        })
        .collect()
}

/// `--figure FILE.svg`: the report's drawing as an SVG file; for
/// `solve`, one file per part, FILE-1-view.svg, FILE-2-project.svg, …
/// (docs/spec.md §4), all or none. How many files were written, if a
/// figure was asked.
fn write_figure(
    cmd: &Command,
    report: &Report,
    style: &Style,
    outputs: &Outputs,
) -> Result<Option<usize>> {
    use crate::report::figure::{drawings::drawings, svg::to_svg};
    let path = match cmd {
        Command::Solve { figure, .. } => figure.as_ref(),
        c => figure_path(c),
    };
    let Some(path) = path else {
        return Ok(None);
    };
    let all = drawings(report, style);
    let files: Vec<(std::path::PathBuf, String)> = match cmd {
        Command::Solve { .. } => all
            .iter()
            .enumerate()
            .map(|(k, d)| (part_file(path, k + 1, &d.part), to_svg(d)))
            .collect(),
        _ => all.iter().map(|d| (path.clone(), to_svg(d))).collect(),
    };
    outputs.write_all(&files, "figure")?;
    Ok(Some(files.len()))
}

/// `solve`'s file for part k: FILE.svg → FILE-k-PART.svg.
pub fn part_file(path: &std::path::Path, k: usize, part: &str) -> std::path::PathBuf {
    let stem = path.file_stem().unwrap_or_default().to_string_lossy();
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().into_owned())
        .unwrap_or_else(|| "svg".into());
    path.with_file_name(format!("{stem}-{k}-{part}.{ext}"))
}

/// An option given before a command that does not take it: `--html`
/// where there is no worked solution, `--precision` before `render` (which
/// always computes at f32), any other.
fn misplaced(opt: args::Opt, command: &str) -> Error {
    match (opt, command) {
        (args::Opt::Html, _) => Error::said("html", Msg::ErrHtmlCommand),
        (args::Opt::Precision, "render") => Error::why("precision", ErrMsg::RenderPrecision),
        _ => Error::why(opt.name(), ErrMsg::NotTaken(command.into())),
    }
}

/// `--html FILE.html`: the worked solution as a self-contained page.
fn write_html(cli: &Cli, report: &Report, style: &Style, outputs: &Outputs) -> Result<()> {
    let Some(path) = &cli.common.html else {
        return Ok(());
    };
    let page = writer::Html.solution(report, style);
    outputs.write(path, "html", page.as_bytes())
}

/// How numbers and words are written: `--digits`, exact or not, `--lang`
/// (else the environment).
fn style_of(cli: &Cli) -> Style {
    let lang = cli
        .common
        .lang
        .unwrap_or_else(|| Lang::from_env(|k| std::env::var(k).ok()));
    let exact = cli.common.precision == Precision::Exact;
    Style::new(cli.common.digits as usize, exact, lang)
}

/// A report as JSON or as the worked solution; its warnings go to stderr.
fn report_text(report: &Report, json: bool, style: &Style) -> String {
    for w in &report.warnings {
        print::stderr_line(&format!("{}: {}", style.doc(DocWord::Warning), style.w(w)));
    }
    let printed: &dyn SolutionWriter = if json { &writer::Json } else { &writer::Text };
    printed.solution(report, style)
}

/// `grafika bench`: the measurement as a table or JSON.
fn bench(quick: bool, cases: Option<u16>, json: bool, lang: Lang) -> String {
    let mut set = if quick {
        crate::bench::Settings::quick()
    } else {
        crate::bench::Settings::full()
    };
    if let Some(n) = cases {
        set.cases = n as usize;
    }
    let bar = terminal_bar(
        Stage::ALL.len() as u64,
        words::of(lang).cli(CliWord::Measuring),
    );
    let (inp, rows) = crate::bench::measure_with(&set, &mut |k, _| {
        if let Some(b) = &bar {
            b.set_position(k as u64);
        }
    });
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if json {
        let j = crate::report::bench::to_json(&inp, &rows);
        serde_json::to_string_pretty(&j).unwrap_or_default() + "\n"
    } else {
        crate::report::bench::table(&inp, &rows, lang)
    }
}

/// A progress bar of `len` steps on standard error when it is a terminal
/// (none in a pipe, so scripts and tests see nothing).
pub fn terminal_bar(len: u64, msg: &str) -> Option<indicatif::ProgressBar> {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let b = indicatif::ProgressBar::new(len);
    if let Ok(s) = indicatif::ProgressStyle::with_template("{msg} {bar:40} {pos}/{len}") {
        b.set_style(s);
    }
    b.set_message(msg.to_string());
    Some(b)
}

/// A command line clap refused: help and version are printed as asked
/// (exit 0); anything else is an error naming the argument (exit 2), in
/// the language of `--lang` if it was given, else the environment's.
fn clap_error(e: clap::Error, wants_json: bool, lang: Option<Lang>) -> i32 {
    use clap::error::{ContextKind, ErrorKind};
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let lang = lang.unwrap_or_else(|| Lang::from_env(|k| std::env::var(k).ok()));
            if let Err(e) = print::refuse_closed_stdout() {
                return report_error(&e, wants_json, lang);
            }
            match print::stdout(&e.render().to_string(), Kind::Text { colour: false }) {
                Ok(()) => 0,
                Err(stopped) => stopped_status(stopped, 0, wants_json, lang),
            }
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            print::stderr_line(e.render().to_string().trim_end());
            2
        }
        kind => {
            let lang = lang.unwrap_or_else(|| Lang::from_env(|k| std::env::var(k).ok()));
            let field = e
                .get(ContextKind::InvalidArg)
                .map(|v| v.to_string())
                .unwrap_or_else(|| words::of(lang).cli(CliWord::Arguments).into());
            let english = clap_message(&e.render().to_string(), &kind.to_string());
            let err = Error::why(field, refused::clap_refused(&e, english));
            report_error(&err, wants_json, lang)
        }
    }
}

/// clap's several-line error as one line: its first paragraph (the
/// missing arguments and the possible values are on the lines after the
/// first) without the `error: ` prefix, then clap's tip, then `(see --help)`.
fn clap_message(rendered: &str, kind: &str) -> String {
    let first: Vec<String> = rendered
        .lines()
        .map(str::trim)
        .skip_while(|l| l.is_empty())
        .take_while(|l| !l.is_empty() && !l.starts_with("Usage:"))
        .map(|l| match l.strip_prefix("[possible values:") {
            Some(rest) => format!("; possible values:{}", rest.trim_end_matches(']')),
            None => l.trim_start_matches("error:").trim().to_string(),
        })
        .collect();
    // the lines after a `…:` line are its items: `<FILE>, --look <X,Y,Z>`
    let first = match first.split_first() {
        None => kind.to_string(),
        Some((head, rest)) if head.ends_with(':') && !rest.is_empty() => {
            format!("{head} {}", rest.join(", "))
        }
        Some(_) => first.concat(),
    };
    let tip = rendered
        .lines()
        .map(str::trim)
        .find_map(|l| l.strip_prefix("tip:"))
        .map(|t| format!("; {}", t.trim()))
        .unwrap_or_default();
    format!("{first}{tip} (see --help)")
}

pub use crate::report::lang::MAX_MESSAGE;
pub use crate::report::words::cut_message;

/// Prints an error on one line (stderr; and JSON on stdout with `--json`),
/// a long echoed input cut; returns 2.
/// The message in `lang`; the field as the flag or key is spelled.
fn report_error(e: &Error, json: bool, lang: Lang) -> i32 {
    let field = cut_message(&e.field, lang);
    let words = crate::report::words::words(&e.message, lang);
    let message = cut_message(&words, lang).replace('\n', " ");
    let label = words::of(lang).doc(&DocWord::Error);
    print::stderr_line(&format!("{label}: {field}: {message}"));
    if json {
        let j = crate::report::json::error(&field, &message);
        // Nothing more can be said if this fails too: the error is on stderr.
        let j = serde_json::to_string(&j).unwrap_or_default();
        let _ = print::stdout(&format!("{j}\n"), Kind::Json);
    }
    2
}
