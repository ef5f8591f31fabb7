//! The `grafika practice` command line: the problem (a file, or drawn like
//! `generate`'s first problem), then the session on standard input and
//! output. On a terminal a prompt is shown and verdicts are coloured (not
//! with `NO_COLOR`); from a pipe each line is an answer or a command, echoed
//! after `> `; with `--json` each event is one line of JSON.

use crate::cli::args::PracticeArgs;
use crate::cli::check::valid_tolerance;
use crate::cli::print::{self, Kind, Stopped};
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::ErrMsg;
use crate::report::practice::{event_json, event_text, intro, Look, PROMPT};
use crate::report::Style;
use crate::tutor::check;
use crate::tutor::generate::{self, Difficulty, Topic};
use crate::tutor::practice::{self, Event};
use std::cell::RefCell;
use std::io::{BufRead, IsTerminal};

/// A problem to practise, the topic and difficulty it was drawn at, and
/// its seed (both `None` for a file).
type Drawn = (ProblemIn, Option<(Topic, Difficulty)>, Option<u64>);

/// The problem to practise: the file named, or one drawn for `--topic`
/// (with the topic and difficulty it was drawn at, and its seed).
fn problem(a: &PracticeArgs, style: &Style) -> Result<Drawn> {
    match (&a.file, a.topic) {
        (Some(f), _) if f.as_os_str() == "-" => Err(Error::why("file", ErrMsg::StdinHoldsAnswers)),
        (Some(f), _) => Ok((ProblemIn::read(f)?.localized(style.lang), None, None)),
        (None, Some(t)) => {
            let seed = a.seed.unwrap_or_else(clock_seed);
            let mut exam = generate::exam(&[t], a.difficulty, 1, seed)?;
            let g = exam
                .pop()
                .ok_or_else(|| Error::why("topic", ErrMsg::NoProblemDrawn))?;
            let mut p = g.problem;
            p.title = style.w(&g.title);
            p.statement = Some(style.w(&g.statement));
            Ok((p, Some((t, a.difficulty)), Some(seed)))
        }
        (None, None) => Err(Error::why("file", ErrMsg::GiveProblem)),
    }
}

/// Runs `grafika practice`, printing as it goes.
pub fn run(a: &PracticeArgs, json: bool, style: &Style) -> Result<()> {
    valid_tolerance(a.tolerance)?;
    let (p, drawn, seed) = problem(a, style)?;
    let settings = check::settings_for(&p, a.tolerance, a.sig_figs);
    let plan = practice::plan(&p, settings, drawn)?;
    let terminal = std::io::stdin().is_terminal();
    let look = Look {
        style: Style {
            exact_mode: true,
            ..*style
        },
        color: !json
            && std::io::stdout().is_terminal()
            && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
    };
    // The first write error ends the session: the input is then read as
    // ended, and the error is returned (a broken pipe ends quietly).
    let stopped: RefCell<Option<Stopped>> = RefCell::new(None);
    let kind = if json {
        Kind::Json
    } else {
        Kind::Text { colour: look.color }
    };
    let say = |text: &str| {
        if stopped.borrow().is_none() {
            if let Err(e) = print::stdout(text, kind) {
                *stopped.borrow_mut() = Some(e);
            }
        }
    };
    if !json {
        say(&intro(&plan, &look, seed));
    }
    let stdin = std::io::stdin();
    let mut lines = stdin.lock();
    let next_line = || {
        if stopped.borrow().is_some() {
            return None;
        }
        if terminal && !json {
            say(PROMPT);
        }
        let mut buf = Vec::new();
        match read_line(&mut lines, &mut buf) {
            Ok(0) | Err(_) => None,
            Ok(_) => {
                let line = String::from_utf8_lossy(&buf).trim_end().to_string();
                if !terminal && !json {
                    say(&format!("{PROMPT}{line}\n"));
                }
                Some(line)
            }
        }
    };
    let emit = |e: &Event| {
        if json {
            let line = serde_json::to_string(&event_json(e, look.style.lang));
            say(&format!("{}\n", line.unwrap_or_default()));
        } else {
            say(&event_text(e, &look));
        }
    };
    practice::run(&plan, next_line, emit);
    match stopped.into_inner() {
        None | Some(Stopped::Pipe) => Ok(()),
        Some(Stopped::Failed(e)) => Err(e),
    }
}

/// The longest line read as an answer, in bytes: a longer one is cut here
/// and marked `…` (so it is unreadable as any answer and asked again), and
/// reading stays linear and bounded (45 MB of commas took 3.6 GB).
pub const MAX_LINE: usize = 4_096;

/// Reads one line into `buf`, keeping at most [`MAX_LINE`] bytes of it
/// (the rest, up to its newline, is read and dropped; a cut line ends in
/// `…`); the bytes read.
fn read_line(input: &mut impl BufRead, buf: &mut Vec<u8>) -> std::io::Result<usize> {
    let mut total = 0;
    loop {
        let chunk = input.fill_buf()?;
        if chunk.is_empty() {
            break;
        }
        let (take, done) = match chunk.iter().position(|&b| b == b'\n') {
            Some(i) => (i + 1, true),
            None => (chunk.len(), false),
        };
        let room = (MAX_LINE + 1).saturating_sub(buf.len());
        buf.extend_from_slice(&chunk[..take.min(room)]);
        input.consume(take);
        total += take;
        if done {
            break;
        }
    }
    if buf.len() > MAX_LINE {
        buf.truncate(MAX_LINE);
        buf.extend_from_slice("…\n".as_bytes());
    }
    Ok(total)
}

/// A seed from the clock, short enough to type again.
fn clock_seed() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(1, |d| d.as_nanos() as u64 % 1_000_000)
}
