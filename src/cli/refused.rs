//! A command line clap refused, as a message key: clap's own line is the
//! English, and the parts clap names (the argument, the value, the possible
//! values) make the Indonesian.

use crate::cli::args::{Opt, TAKES};
use crate::msg::{ClapErr, ErrMsg};
use crate::report::lang::Lang;
use clap::error::{ContextKind, ContextValue, ErrorKind};
use std::ffi::OsString;

/// What clap refused, with `english` (clap's line) as its English words.
pub fn clap_refused(e: &clap::Error, english: String) -> ErrMsg {
    let text = |k: ContextKind| match e.get(k) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        Some(ContextValue::Strings(v)) => Some(v.join(", ")),
        Some(ContextValue::StyledStr(s)) => Some(s.to_string()),
        Some(ContextValue::StyledStrs(v)) => Some(
            v.iter()
                .map(|s| s.to_string())
                .collect::<Vec<_>>()
                .join(", "),
        ),
        Some(ContextValue::Number(n)) => Some(n.to_string()),
        _ => None,
    };
    let arg = || text(ContextKind::InvalidArg).unwrap_or_default();
    let what = match e.kind() {
        ErrorKind::InvalidValue => match text(ContextKind::InvalidValue) {
            Some(v) if !v.is_empty() => {
                ClapErr::InvalidValue(v, text(ContextKind::ValidValue).unwrap_or_default())
            }
            _ => ClapErr::NoValue,
        },
        ErrorKind::ValueValidation => ClapErr::BadValue(
            text(ContextKind::InvalidValue).unwrap_or_default(),
            reason(e),
        ),
        ErrorKind::UnknownArgument => ClapErr::Unknown(arg(), text(ContextKind::SuggestedArg)),
        ErrorKind::InvalidSubcommand => ClapErr::UnknownCommand(
            text(ContextKind::InvalidSubcommand).unwrap_or_default(),
            text(ContextKind::SuggestedSubcommand),
        ),
        ErrorKind::ArgumentConflict => {
            ClapErr::Conflict(arg(), text(ContextKind::PriorArg).unwrap_or_default())
        }
        ErrorKind::MissingRequiredArgument => ClapErr::Missing(arg()),
        ErrorKind::TooManyValues | ErrorKind::TooFewValues | ErrorKind::WrongNumberOfValues => {
            ClapErr::ValueCount(arg())
        }
        _ => ClapErr::Other,
    };
    ErrMsg::Clap(what, english)
}

/// The value parser's reason, from the error's source.
fn reason(e: &clap::Error) -> String {
    std::error::Error::source(e)
        .map(|s| s.to_string())
        .unwrap_or_default()
}

/// The language a command line asks for with `--lang X` or `--lang=X`
/// (read before clap, whose errors need it too).
pub fn lang_of_args(args: &[OsString]) -> Option<Lang> {
    let args: Vec<String> = args.iter().map(|a| a.to_string_lossy().into()).collect();
    args.iter().enumerate().rev().find_map(|(i, a)| {
        let v = match a.strip_prefix("--lang") {
            Some("") => args.get(i + 1)?.as_str(),
            Some(rest) => rest.strip_prefix('=')?,
            None => return None,
        };
        Lang::from_code(v)
    })
}

/// An option of [`Opt`] written after a command that does not take it
/// (`grafika check … --html x.html`): the option and the command, so the
/// refusal says so, as for the option written before the command, instead
/// of clap's "to pass '--html' as a value, use '-- --html'".
pub fn shared_option_after(e: &clap::Error, args: &[OsString]) -> Option<(Opt, String)> {
    if e.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(arg)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let name = arg.strip_prefix("--")?.split('=').next()?;
    let opt = Opt::ALL.into_iter().find(|o| o.name() == name)?;
    let command = (args.iter().skip(1))
        .map(|a| a.to_string_lossy())
        .find(|a| TAKES.iter().any(|(c, ..)| c == a))?;
    Some((opt, command.into_owned()))
}
