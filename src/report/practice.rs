//! `grafika practice` for people (English or Bahasa Indonesia, lines within
//! 80 columns, colour only when asked for) and for scripts (one JSON object
//! per event, JSON Lines, with the keys of `check`).

use crate::input::answer::Read;
use crate::msg::PracticeWord as P;
use crate::msg::{DocWord, Msg};
use crate::num::Real;
use crate::report::json::{both, plain, step_json, value_json, Both, StepJson};
use crate::report::lang::{Lang, NumStyle};
use crate::report::mistakes::mistake_text;
use crate::report::words;
use crate::report::Style;
use crate::stages::trace::{Step, Val};
use crate::tutor::check::Verdict;
use crate::tutor::diagnose::Code;
use crate::tutor::key::{self, Field, Key};
use crate::tutor::practice::{Again, Event, Outcome, Plan, Summary};
use serde::Serialize;
use serde_json::{Map, Value};

/// Lines are wrapped to this many columns.
pub const WIDTH: usize = 78;

/// How the words look: numbers and language, and whether to colour them
/// (only on a terminal, never with `NO_COLOR`).
#[derive(Clone, Copy, Debug)]
pub struct Look {
    /// Numbers and language.
    pub style: Style,
    /// ANSI colours on or off.
    pub color: bool,
}

#[derive(Clone, Copy)]
enum Tone {
    Good,
    Partial,
    Bad,
    Quiet,
}

impl Look {
    fn paint(&self, tone: Tone, text: &str) -> String {
        if !self.color {
            return text.to_string();
        }
        let code = match tone {
            Tone::Good => "32",
            Tone::Partial => "33",
            Tone::Bad => "31",
            Tone::Quiet => "2",
        };
        format!("\x1b[{code}m{text}\x1b[0m")
    }
    /// The words of `w` in this look's language.
    fn w(&self, w: P) -> String {
        words::of(self.style.lang).practice(&w)
    }
}

/// Words wrapped to [`WIDTH`] columns, each line after the first indented.
pub fn wrap(text: &str, indent: &str) -> String {
    wrap_after("", text, indent)
}

/// `lead` and then the words, wrapped to [`WIDTH`] columns, each line after
/// the first indented.
fn wrap_after(lead: &str, text: &str, indent: &str) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut line = lead.to_string();
    let mut fresh = true;
    for word in text.split_whitespace() {
        if !fresh && line.chars().count() + 1 + word.chars().count() > WIDTH {
            lines.push(std::mem::take(&mut line));
            line.push_str(indent);
        } else if !fresh {
            line.push(' ');
        }
        line.push_str(word);
        fresh = false;
    }
    lines.push(line);
    lines.join("\n")
}

/// Each line wrapped to [`WIDTH`] columns, continued with its own indent
/// and two spaces more (a matrix table is left whole).
fn wrap_lines(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        if line.chars().count() <= WIDTH || line.trim_start().starts_with(['│', '┌', '├', '└'])
        {
            out.push_str(line);
        } else {
            let lead: String = line.chars().take_while(|c| *c == ' ').collect();
            let more = format!("{lead}  ");
            out.push_str(&wrap_after(&lead, line.trim_start(), &more));
        }
        out.push('\n');
    }
    out
}

/// The heading of a session: the title, the statement, how to answer.
pub fn intro(plan: &Plan, look: &Look, seed: Option<u64>) -> String {
    let n = plan.items.len();
    let title = P::Title {
        title: plan.title.clone(),
        values: n,
        seed,
    };
    let mut out = format!("{}\n", look.w(title));
    if let Some(st) = &plan.statement {
        out.push_str(&wrap(st, ""));
        out.push('\n');
    }
    let how = look.w(P::HowToAnswer);
    out.push_str(&look.paint(Tone::Quiet, &wrap(&how, "")));
    out.push('\n');
    out
}

/// The prompt printed before a line is read from a terminal.
pub const PROMPT: &str = "> ";

/// One event as text (ends with a newline).
pub fn event_text(ev: &Event, look: &Look) -> String {
    match ev {
        Event::Ask {
            index,
            total,
            key,
            expected,
            again,
        } => {
            let mut out = again
                .as_ref()
                .map(|a| again_text(a, look))
                .unwrap_or_default();
            if again.is_none() || *again == Some(Again::NothingBefore) {
                out.push('\n');
            }
            let head = format!("[{}/{}] {}", index + 1, total, label(key, look.style.lang));
            let shape = shape(key, expected, look.style.lang);
            let line = format!("{head}  {shape}");
            if line.chars().count() <= WIDTH {
                out.push_str(&line);
            } else {
                out.push_str(&format!("{}\n    {shape}", wrap(&head, "    ")));
            }
            out.push('\n');
            out
        }
        Event::Verdict(o) => verdict_text(o, look),
        Event::Hint {
            level, step, also, ..
        } => {
            let mut out = hint_text(*level, step.as_ref(), look);
            out.push_str(&also_text(also, look));
            wrap_lines(&out)
        }
        Event::Show {
            key,
            expected,
            step,
            also,
        } => {
            let mut out = String::new();
            if let Some(s) = step {
                out.push_str(&format!("  {}\n", look.style.w(&s.title)));
                out.push_str(&look.style.step_body(s));
            }
            let answer = look.w(P::Answer);
            let (head, spelled) = (format!("  {answer}: "), key.to_string());
            out.push_str(&look.style.named(&head, &spelled, expected));
            out.push('\n');
            out.push_str(&also_text(also, look));
            wrap_lines(&out)
        }
        Event::Skip { .. } => format!("  {}\n", look.w(P::Skipped)),
        Event::Summary(s) => summary_text(s, look),
    }
}

/// The other values a `show` or a hint printed, which now count as
/// revealed (nothing when there are none).
fn also_text(also: &[Key], look: &Look) -> String {
    if also.is_empty() {
        return String::new();
    }
    let keys = also
        .iter()
        .map(Key::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    let line = look.w(P::AlsoShown(keys));
    format!("{}\n", look.paint(Tone::Quiet, &format!("  {line}")))
}

fn again_text(a: &Again, look: &Look) -> String {
    let t = match a {
        Again::Empty => look.w(P::AgainEmpty),
        Again::Unreadable => return String::new(),
        Again::NothingBefore => look.w(P::FirstValue),
        Again::NoMoreHints => look.w(P::NoMoreHints),
    };
    format!("{}\n", wrap_after("  ", &t, "  "))
}

/// The verdict's first line, and its colour.
fn verdict_head(o: &Outcome, lang: Lang) -> (Tone, String) {
    let (tone, w) = match o.verdict {
        Verdict::Exact => (Tone::Good, P::Exact),
        Verdict::Tolerance => (Tone::Good, P::Tolerance),
        Verdict::Rounded => (Tone::Good, P::Rounded),
        Verdict::FollowThrough => (Tone::Partial, P::FollowThrough),
        Verdict::TooCoarse => (Tone::Partial, P::TooCoarse),
        Verdict::Wrong => (Tone::Bad, P::Wrong),
        // an empty answer is asked again before it is judged, so a
        // missing one is said as one that cannot be read
        Verdict::Unparseable | Verdict::Missing => {
            let why = unread_why(&o.note, lang);
            let why = if why.is_empty() {
                String::new()
            } else {
                format!(" {why};")
            };
            let how = shape(&o.key, &o.expected, lang);
            (Tone::Bad, P::Unreadable { why, how })
        }
    };
    (tone, words::of(lang).practice(&w))
}

/// Why an answer could not be read, without the words "cannot be read"
/// that its line already starts with (each part's reason after its name).
fn unread_why(m: &Msg, lang: Lang) -> String {
    match m {
        Msg::Unreadable(e) => crate::report::words::of(lang).number(e),
        Msg::Parts(parts) => (parts.iter())
            .map(|(part, why)| format!("{part}: {}", unread_why(why, lang)))
            .collect::<Vec<_>>()
            .join("; "),
        m => crate::report::words::words(m, lang),
    }
}

fn verdict_text(o: &Outcome, look: &Look) -> String {
    let lang = look.style.lang;
    let mut out = String::new();
    if let Some(r) = &o.read {
        let read = read_as(r, &look.style);
        if !same_text(&read, o.given.as_deref().unwrap_or_default()) {
            let line = format!("{} {read}", look.w(P::ReadAs));
            out.push_str(&look.paint(Tone::Quiet, &wrap_after("  ", &line, "    ")));
            out.push('\n');
        }
    }
    let (tone, head) = verdict_head(o, lang);
    out.push_str(&look.paint(tone, &wrap_after("  ", &head, "    ")));
    out.push('\n');
    if o.retry {
        let line = look.w(if o.shown {
            P::ShownBefore
        } else {
            P::SecondTry
        });
        out.push_str(&look.paint(Tone::Quiet, &wrap_after("    ", &line, "    ")));
        out.push('\n');
    }
    for m in &o.mistakes {
        let line = format!(
            "{}: {} [{}]",
            look.w(P::LikelyMistake),
            mistake_text(*m, lang),
            m
        );
        out.push_str(&format!("{}\n", wrap_after("    ", &line, "      ")));
    }
    if let Some(why) = &o.why {
        let line = format!("{}: {}", look.w(P::SourceWrong), look.style.w(why));
        out.push_str(&format!("{}\n", wrap_after("    ", &line, "      ")));
    }
    // why it does not follow from the student's own earlier answer
    if let Msg::NoFollowFrom(..) = &o.note {
        let line = look.style.w(&o.note);
        out.push_str(&format!("{}\n", wrap_after("    ", &line, "      ")));
    }
    if o.verdict == Verdict::Wrong && o.mistakes.is_empty() {
        let tip = look.w(P::NoMistakeTip);
        out.push_str(&look.paint(Tone::Quiet, &wrap_after("    ", &tip, "    ")));
        out.push('\n');
    }
    out
}

/// How an answer was read, in the student's language: each number in its
/// exact form (`√2/2` for `1/sqrt(2)`) or as the decimal written, a list
/// in parentheses, a code or status as grafika spells it.
pub fn read_as(r: &Read, style: &Style) -> String {
    // yes or no (read as grafika's true or false) in the student's language
    match r {
        Read::Word(w) if w == "true" => return style.doc(DocWord::Yes),
        Read::Word(w) if w == "false" => return style.doc(DocWord::No),
        // a status and "nothing" in the student's words (`di-clip`, `tidak ada`)
        Read::Word(w) if crate::report::words::said::status(w).is_some() => {
            return style.val_inline(&Val::said(crate::msg::Said::Status(w.clone())));
        }
        Read::None => return style.val_inline(&Val::Null),
        _ => {}
    }
    read_in(r, style.nums)
}

/// An answer read, its numbers in the style `nums`: a decimal as written,
/// another number by its exact form (else `≈` its decimal), a list in
/// parentheses, a code or word as typed.
fn read_in(r: &Read, nums: NumStyle) -> String {
    match r {
        Read::Num(n) if n.last_digit.is_some() => nums.form(&n.expr.to_string().replace('-', "−")),
        Read::Num(n) => match n.expr.eval::<Real>().ok().and_then(|x| x.exact_pretty()) {
            Some(p) => nums.form(&p.replace('-', "−")),
            None => format!("≈ {}", nums.dec(n.value, 6).replace('-', "−")),
        },
        Read::List(items) => {
            nums.tuple(&items.iter().map(|x| read_in(x, nums)).collect::<Vec<_>>())
        }
        Read::Word(w) => w.clone(),
        Read::None => "none".to_string(),
    }
}

/// Whether the reading says nothing the line typed does not: the same
/// characters but for spaces, brackets, the minus sign's form and the
/// list separator.
fn same_text(read: &str, typed: &str) -> bool {
    let bare = |t: &str| -> String {
        t.chars()
            .filter(|c| !c.is_whitespace() && !matches!(c, '(' | ')' | '[' | ']'))
            .map(|c| match c {
                '-' => '−',
                ';' => ',',
                c => c,
            })
            .collect()
    };
    bare(read) == bare(typed)
}

fn hint_text(level: u8, step: Option<&Step>, look: &Look) -> String {
    let Some(s) = step else {
        return format!("  {}\n", look.w(P::NoHint));
    };
    let hint = match level {
        1 => P::Hint1(look.style.w(&s.title)),
        _ => P::Hint2,
    };
    let mut out = format!("  {}\n", look.w(hint));
    if !s.formula.is_empty() {
        out.push_str(&format!("    {}\n", look.style.w(&s.formula)));
    }
    if level >= 2 {
        let names = words::of(look.style.lang);
        for (k, v) in &s.values {
            out.push_str(&look.style.named("    ", &names.name(k), v));
            out.push('\n');
        }
        if s.values.is_empty() {
            let none = look.w(P::NoValues);
            out.push_str(&format!("{}\n", wrap_after("    ", &none, "    ")));
        }
    }
    out
}

fn summary_text(s: &Summary, look: &Look) -> String {
    let lang = look.style.lang;
    let mut out = format!("\n{}", words::of(lang).practice_summary(s));
    if !s.mistakes.is_empty() {
        out.push_str(&format!("  {}\n", look.w(P::MistakesMade)));
        for (m, keys) in &s.mistakes {
            let keys: Vec<String> = keys.iter().map(Key::to_string).collect();
            let line = format!("• {} [{}]: {}", mistake_text(*m, lang), m, keys.join(", "));
            out.push_str(&format!("{}\n", wrap_after("    ", &line, "      ")));
        }
    }
    let (topic, diff) = (s.next.0.name(), s.next.1.name());
    out.push_str(&format!(
        "  {}: grafika practice --topic {topic} --difficulty {diff}\n",
        look.w(P::PractiseNext)
    ));
    out
}

/// What a key asks for, in a few words, and the key.
pub fn label(key: &Key, lang: Lang) -> String {
    format!("{} ({key})", words::of(lang).answer_words(key))
}

/// How to write the answer: its shape.
fn shape(key: &Key, expected: &Val, lang: Lang) -> String {
    let t = |w: P| words::of(lang).practice(&w);
    let field = match key.value {
        key::Value::Field(f) => Some(f),
        _ => None,
    };
    match field {
        Some(Field::Segment) => return t(P::SegmentShape),
        Some(Field::Status) => return "accepted | rejected | clipped".to_string(),
        _ => {}
    }
    match expected {
        Val::Text(_) => t(P::BitsShape),
        Val::Bool(_) => t(P::YesNoShape),
        // with decimal commas `;` separates the numbers, so each row in
        // brackets: (0,6; 0; −0,8; 0); (…)
        v if v.is_matrix() => t(P::MatrixShape),
        Val::List(items)
            if items.len() == 3 && matches!(field, Some(Field::Shading(s)) if s.is_colour()) =>
        {
            "(r, g, b)".to_string()
        }
        Val::List(items) => ["(x)", "(x, y)", "(x, y, z)"]
            .get(items.len().saturating_sub(1))
            .map_or_else(|| t(P::ValuesShape(items.len())), |s| s.to_string()),
        _ => t(P::NumberShape),
    }
}

/// One event as a JSON object (one line of JSON Lines), its kind first.
// one event is made and written at a time: its size costs nothing
#[allow(clippy::large_enum_variant)]
#[derive(Serialize)]
#[serde(tag = "event", rename_all = "snake_case")]
pub enum EventJson<'a> {
    /// A value asked.
    Ask {
        key: &'a Key,
        index: usize,
        total: usize,
        again: &'a Option<Again>,
    },
    /// An answer judged.
    Verdict {
        key: &'a Key,
        given: &'a Option<String>,
        read: Option<Value>,
        verdict: &'static str,
        code: &'static str,
        expected: Both,
        note: String,
        mistakes: &'a [Code],
        why: Option<String>,
        follow_through: Option<Value>,
        retry: bool,
        shown: bool,
    },
    /// A hint: the step's title and formula, at level 2 its values.
    Hint {
        key: &'a Key,
        level: u8,
        revealed: &'a [Key],
        title: Option<String>,
        formula: Option<String>,
        values: Option<Map<String, Value>>,
    },
    /// A value shown, with its step.
    Show {
        key: &'a Key,
        expected: Both,
        revealed: &'a [Key],
        step: Option<StepJson>,
    },
    /// A value skipped.
    Skip { key: &'a Key },
    /// The session's summary.
    Summary(SummaryJson<'a>),
}

/// One event as a JSON object (one line of JSON Lines).
pub fn event_json(ev: &Event, lang: Lang) -> EventJson<'_> {
    let w = |m: &crate::msg::Msg| crate::report::words::words(m, lang);
    match ev {
        Event::Ask {
            index,
            total,
            key,
            again,
            ..
        } => EventJson::Ask {
            key,
            index: index + 1,
            total: *total,
            again,
        },
        Event::Verdict(o) => EventJson::Verdict {
            key: &o.key,
            given: &o.given,
            read: o.read.as_ref().map(|r| value_json(&r.value())),
            verdict: o.verdict.word(),
            code: o.verdict.name(),
            expected: both(&o.expected),
            note: w(&o.note),
            mistakes: &o.mistakes,
            why: o.why.as_ref().map(w),
            follow_through: o.follow_through.as_ref().map(value_json),
            retry: o.retry,
            shown: o.shown,
        },
        Event::Hint {
            key,
            level,
            step,
            also,
        } => EventJson::Hint {
            key,
            level: *level,
            revealed: also,
            title: step.as_ref().map(|s| w(&s.title)),
            formula: step.as_ref().map(|s| w(&s.formula)),
            values: (step.as_ref().filter(|_| *level >= 2)).map(|s| plain(&s.values, value_json)),
        },
        Event::Show {
            key,
            expected,
            step,
            also,
        } => EventJson::Show {
            key,
            expected: both(expected),
            revealed: also,
            step: step.as_ref().map(|s| step_json(s, lang)),
        },
        Event::Skip { key } => EventJson::Skip { key },
        Event::Summary(s) => EventJson::Summary(summary_json(s, lang)),
    }
}

/// A session's summary.
#[derive(Serialize)]
pub struct SummaryJson<'a> {
    score: ScoreJson,
    steps: usize,
    counts: CountsJson,
    hints: usize,
    retries: RetriesJson,
    mistakes: Vec<MistakeJson<'a>>,
    next: NextJson,
}

/// The marks of a session.
#[derive(Serialize)]
struct ScoreJson {
    points: f64,
    total: u32,
    fraction: f64,
}

/// The values of a session by how they ended.
#[derive(Serialize)]
struct CountsJson {
    correct: usize,
    follow_through: usize,
    too_coarse: usize,
    wrong: usize,
    skipped: usize,
    revealed: usize,
    unanswered: usize,
}

/// The second tries, and how many of them were right.
#[derive(Serialize)]
struct RetriesJson {
    answered: usize,
    correct: usize,
}

/// A mistake made in a session, with the values it explains.
#[derive(Serialize)]
struct MistakeJson<'a> {
    code: Code,
    mistake: &'static str,
    keys: &'a [Key],
}

/// What to practise next.
#[derive(Serialize)]
struct NextJson {
    topic: &'static str,
    difficulty: &'static str,
}

fn summary_json(s: &Summary, lang: Lang) -> SummaryJson<'_> {
    SummaryJson {
        score: ScoreJson {
            points: s.points,
            total: s.total,
            fraction: if s.total == 0 {
                1.0
            } else {
                s.points / f64::from(s.total)
            },
        },
        steps: s.steps,
        counts: CountsJson {
            correct: s.correct,
            follow_through: s.follow_through,
            too_coarse: s.too_coarse,
            wrong: s.wrong,
            skipped: s.skipped,
            revealed: s.revealed,
            unanswered: s.unanswered,
        },
        hints: s.hints,
        retries: RetriesJson {
            answered: s.retries,
            correct: s.retries_correct,
        },
        mistakes: (s.mistakes.iter())
            .map(|(m, keys)| MistakeJson {
                code: *m,
                mistake: mistake_text(*m, lang),
                keys,
            })
            .collect(),
        next: NextJson {
            topic: s.next.0.name(),
            difficulty: s.next.1.name(),
        },
    }
}
