//! `grafika practice`: a problem worked one value at a time, in the order of
//! the text's solution (n, u, v, the view matrix, eye coordinates, projected
//! points, window, pixels; outcodes, each t and intersection, the clipped
//! segment, the status; unit L and N, cos α, R, cos β, the terms, the
//! colour). Each answer gets `check`'s verdict at once, a wrong one the
//! mistakes of the catalog that reproduce it, and a wrong one that is right
//! given the student's own earlier answers is credited as
//! `correct.follow_through` ([`follow`]).
//!
//! Plain functions over plain data: [`plan`] solves the problem, a
//! [`Session`] takes one [`Input`] at a time and returns the [`Event`]s it
//! causes; [`run`] drives a session from any source of lines. The words for
//! people are made in `report::practice`.

use crate::error::Result;
use crate::input::problem::ProblemIn;
use crate::num::Real;
use crate::stages::trace::{Step, Val};
use crate::tutor::check::{
    self, judge, value_of, written, Judged, Settings, Verdict, FOLLOW_THROUGH,
};
use crate::tutor::diagnose::{self, Mistake};
use crate::tutor::follow::{self, Inputs};
use crate::tutor::generate::{Difficulty, Topic};
use crate::tutor::solve::{self, lookup};

/// A result tree: named values, as `solve` returns them.
pub type Tree = Vec<(String, Val)>;

/// One value the student is asked for.
#[derive(Clone, Debug)]
pub struct Item {
    /// The answer key, as in `check` (`view.n`, `project.points.A`).
    pub key: String,
    /// grafika's exact value.
    pub expected: Val,
    /// The worked step that computes it (formula, values substituted, result).
    pub step: Option<Step>,
}

/// A problem ready to practise.
pub struct Plan {
    /// The problem's title.
    pub title: String,
    /// The statement, as a student reads it.
    pub statement: Option<String>,
    /// The values asked for, in the order of the text's solution.
    pub items: Vec<Item>,
    /// How answers are marked.
    pub settings: Settings,
    /// The topic and difficulty, when the problem was generated.
    pub drawn: Option<(Topic, Difficulty)>,
    /// grafika's results, with the unit vectors L and N of a lighting problem.
    result: Tree,
    inputs: Inputs,
    /// Each applicable mistake of the catalog with the results it gives.
    variants: Vec<(&'static Mistake, Vec<Tree>)>,
}

/// Solves the problem exactly and lays out the values to ask for: the
/// problem's `[check] keys` when it lists them (and L, N of a lighting
/// problem), else every answer `check` expects and the view matrix.
pub fn plan(p: &ProblemIn, settings: Settings, drawn: Option<(Topic, Difficulty)>) -> Result<Plan> {
    let report = solve::solve::<Real>(p)?;
    let mut result = report.result;
    let wanted = p.check.as_ref().and_then(|c| c.keys.clone());
    if let Some(Val::Map(kv)) = result
        .iter_mut()
        .find(|(k, _)| k == "shade")
        .map(|(_, v)| v)
    {
        // the unit vectors are steps of the solution, not results of
        // `solve`; asked when there is one of each (one light)
        for name in ["N", "L"] {
            let mut found = report.steps.iter().filter_map(|s| step_result(s, name));
            if let (Some(v), None) = (found.next(), found.next()) {
                kv.insert(0, (name.to_string(), v));
            }
        }
    }
    let items = ordered_keys(&result)
        .into_iter()
        .filter(|k| {
            wanted
                .as_ref()
                .is_none_or(|w| w.contains(k) || k == "shade.L" || k == "shade.N")
        })
        .filter_map(|key| {
            let expected = lookup(&result, &key)?.clone();
            let step = step_for(&key, &report.steps);
            Some(Item {
                key,
                expected,
                step,
            })
        })
        .collect();
    let variants = diagnose::CATALOG
        .iter()
        .filter_map(|m| Some((m, (m.apply)(p)?)))
        .collect();
    Ok(Plan {
        title: p.title.clone(),
        statement: p.statement.clone(),
        items,
        settings,
        drawn,
        result,
        inputs: follow::inputs(p),
        variants,
    })
}

/// The keys of a result tree in the order of the text's solution.
pub(crate) fn ordered_keys(result: &Tree) -> Vec<String> {
    let mut keys = Vec::new();
    for (part, v) in result {
        match (part.as_str(), v) {
            ("view", Val::Map(kv)) => {
                let order = ["n", "u", "v", "matrix"];
                keys.extend(
                    order
                        .iter()
                        .filter(|k| kv.iter().any(|(x, _)| x == *k))
                        .map(|k| format!("view.{k}")),
                );
                keys.extend(named(kv, "view.points", "points"));
            }
            ("project", Val::Map(kv)) => keys.extend(named(kv, "project.points", "points")),
            ("viewport", Val::Map(kv)) => keys.extend(named(kv, "viewport.pixels", "pixels")),
            ("window", Val::Map(kv)) => keys.extend(
                kv.iter()
                    .filter(|(k, _)| !k.starts_with("far_"))
                    .map(|(k, _)| format!("window.{k}")),
            ),
            ("clip", Val::Map(kv)) => keys.extend(clip_keys("clip", kv)),
            ("clip", Val::List(runs)) => {
                for (i, r) in runs.iter().enumerate() {
                    if let Val::Map(kv) = r {
                        keys.extend(clip_keys(&format!("clip.{i}"), kv));
                    }
                }
            }
            ("shade", Val::Map(kv)) => {
                let order = ["L", "N", "cos_alpha", "R", "H", "N_dot_H", "cos_beta"];
                let terms = ["ambient", "diffuse", "specular", "color"];
                keys.extend(
                    order
                        .iter()
                        .chain(&terms)
                        .filter(|k| kv.iter().any(|(x, _)| x == *k))
                        .map(|k| format!("shade.{k}")),
                );
            }
            _ => {}
        }
    }
    keys
}

/// `prefix.NAME` for each name of the map held at `inner`.
fn named(kv: &[(String, Val)], prefix: &str, inner: &str) -> Vec<String> {
    match kv.iter().find(|(k, _)| k == inner) {
        Some((_, Val::Map(m))) => m.iter().map(|(n, _)| format!("{prefix}.{n}")).collect(),
        _ => vec![],
    }
}

/// The outcodes, each t and intersection tried, the clipped segment, the status.
fn clip_keys(prefix: &str, kv: &[(String, Val)]) -> Vec<String> {
    let mut keys = vec![format!("{prefix}.code0"), format!("{prefix}.code1")];
    if let Some((_, Val::Map(planes))) = kv.iter().find(|(k, _)| k == "intersections") {
        for (pl, _) in planes {
            keys.push(format!("{prefix}.intersections.{pl}.t"));
            keys.push(format!("{prefix}.intersections.{pl}.point"));
        }
    }
    keys.push(format!("{prefix}.segment"));
    keys.push(format!("{prefix}.status"));
    keys
}

/// The step's result of this name.
fn step_result(step: &Step, name: &str) -> Option<Val> {
    step.result
        .iter()
        .find(|(n, _)| n == name)
        .map(|(_, v)| v.clone())
}
/// The worked step that computes a key.
pub(crate) fn step_for(key: &str, steps: &[Step]) -> Option<Step> {
    let parts: Vec<&str> = key.split('.').collect();
    let name = match parts[..] {
        ["view", "matrix"] => "V".to_string(),
        ["view", "points", p] => format!("{p}'"),
        ["project", "points", p] => format!("{p}''"),
        ["viewport", "pixels", p] => format!("{p} pixel"),
        ["shade", "cos_alpha"] => "cos α".to_string(),
        ["shade", "cos_beta"] => "cos β".to_string(),
        ["shade", "N_dot_H"] => "N·H".to_string(),
        ["clip", ..] => return clip_step(&parts[1..], steps),
        [_, k] => k.to_string(),
        _ => return None,
    };
    steps
        .iter()
        .find(|s| s.result.iter().any(|(n, _)| *n == name))
        .cloned()
}

/// The clipping step of a key: steps are split into one run per segment at
/// each outcode step of P0.
fn clip_step(rest: &[&str], steps: &[Step]) -> Option<Step> {
    let (run, rest) = match rest.first()?.parse::<usize>() {
        Ok(i) => (i, &rest[1..]),
        Err(_) => (0, rest),
    };
    let starts = |s: &Step| {
        s.result.iter().any(|(n, _)| n == "code")
            && s.values.first().is_some_and(|(n, _)| n == "P0")
    };
    let begin = steps
        .iter()
        .enumerate()
        .filter(|(_, s)| starts(s))
        .nth(run)?
        .0;
    let end = steps[begin + 1..]
        .iter()
        .position(starts)
        .map_or(steps.len(), |k| begin + 1 + k);
    let run = &steps[begin..end];
    let has = |s: &&Step, n: &str| s.result.iter().any(|(x, _)| x == n);
    let found = match rest {
        [code] if code.starts_with("code") => {
            let point = format!("P{}", &code[4..]);
            run.iter()
                .find(|s| has(s, "code") && s.values.first().is_some_and(|(n, _)| *n == point))
        }
        ["intersections", _, _] => {
            // the intersections are recorded in the order of the result's map
            let planes = ["left", "right", "bottom", "top", "front", "back"];
            let tried = run.iter().filter(|s| has(s, "P(t)"));
            let wanted = planes.iter().position(|p| *p == rest[1])?;
            tried
                .clone()
                .find(|s| matches!(s.title, crate::msg::Msg::Intersection(i, _) if i == wanted))
                .or_else(|| tried.clone().next())
        }
        ["segment"] => run.iter().find(|s| has(s, "from") && has(s, "to")),
        ["status"] => run.iter().find(|s| has(s, "code0 AND code1")),
        _ => None,
    };
    found.cloned()
}

/// What the student typed at a prompt.
#[derive(Clone, Debug, PartialEq)]
pub enum Input {
    /// An answer.
    Answer(String),
    /// `hint` (`petunjuk`): the formula, then the values substituted.
    Hint,
    /// `show` (`lihat`): the step worked out (counted as revealed).
    Show,
    /// `skip` (`lewati`).
    Skip,
    /// `back` (`kembali`): the previous value again.
    Back,
    /// `quit` (`keluar`), or the end of the input.
    Quit,
    /// An empty line.
    Empty,
}

/// Reads one line: a command (English or Indonesian, any case) or an answer.
pub fn read_input(line: &str) -> Input {
    let t = line.trim();
    match t.to_lowercase().as_str() {
        "" => Input::Empty,
        "hint" | "petunjuk" | "?" => Input::Hint,
        "show" | "lihat" => Input::Show,
        "skip" | "lewati" => Input::Skip,
        "back" | "kembali" => Input::Back,
        "quit" | "exit" | "keluar" => Input::Quit,
        _ => Input::Answer(t.to_string()),
    }
}

/// Why a value is asked again.
#[derive(Clone, Debug, PartialEq)]
pub enum Again {
    /// An empty line.
    Empty,
    /// The answer could not be read.
    Unreadable,
    /// `back` at the first value.
    NothingBefore,
    /// Both hints given already.
    NoMoreHints,
}

/// How one value ended.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The key.
    pub key: String,
    /// The answer as typed (None when skipped or revealed).
    pub given: Option<String>,
    /// The verdict (`Missing` when skipped or revealed).
    pub verdict: Verdict,
    /// `check`'s code, `correct.follow_through`, or `skipped` / `revealed`.
    pub code: &'static str,
    /// How it was judged (check's note).
    pub note: crate::msg::Msg,
    /// grafika's value.
    pub expected: Val,
    /// The value computed from the student's own earlier answers, when
    /// the answer was credited by follow-through.
    pub follow_through: Option<Val>,
    /// The mistakes of the catalog that reproduce a wrong answer.
    pub mistakes: Vec<&'static Mistake>,
}

/// What happened, for the report to put into words or JSON.
#[derive(Clone, Debug)]
pub enum Event {
    /// A value is asked for (`again` says why it is asked once more).
    Ask {
        /// 0-based position.
        index: usize,
        /// How many values the problem asks.
        total: usize,
        /// The key.
        key: String,
        /// grafika's value (for its shape: a number, a point, a matrix).
        expected: Val,
        /// Why it is asked again.
        again: Option<Again>,
    },
    /// An answer judged (also an unreadable one, which is asked again).
    Verdict(Outcome),
    /// A hint: level 1 the formula, level 2 the values substituted.
    Hint {
        /// The key.
        key: String,
        /// 1 or 2.
        level: u8,
        /// The step.
        step: Option<Step>,
    },
    /// The step worked out and the value (counted as revealed).
    Show {
        /// The key.
        key: String,
        /// grafika's value.
        expected: Val,
        /// The step.
        step: Option<Step>,
    },
    /// A value skipped.
    Skip {
        /// The key.
        key: String,
    },
    /// The end: the summary.
    Summary(Summary),
}

/// The end of a session.
#[derive(Clone, Debug)]
pub struct Summary {
    /// Points earned: 1 per correct answer (follow-through included), ½ per too coarse.
    pub points: f64,
    /// Values asked.
    pub total: usize,
    /// Correct answers, follow-through included.
    pub correct: usize,
    /// Of those, credited by follow-through.
    pub follow_through: usize,
    /// Right but too coarse.
    pub too_coarse: usize,
    /// Wrong.
    pub wrong: usize,
    /// Skipped.
    pub skipped: usize,
    /// Revealed with `show`.
    pub revealed: usize,
    /// Not reached (the session ended first).
    pub unanswered: usize,
    /// Hints used.
    pub hints: usize,
    /// Each mistake made, with the keys it explains.
    pub mistakes: Vec<(&'static Mistake, Vec<String>)>,
    /// What to practise next.
    pub next: (Topic, Difficulty),
}

/// A session in progress.
pub struct Session<'a> {
    plan: &'a Plan,
    pos: usize,
    outcomes: Vec<Option<Outcome>>,
    hints: Vec<u8>,
    done: bool,
}

impl<'a> Session<'a> {
    /// A session at the first value.
    pub fn new(plan: &'a Plan) -> Session<'a> {
        let n = plan.items.len();
        Session {
            plan,
            pos: 0,
            outcomes: vec![None; n],
            hints: vec![0; n],
            done: n == 0,
        }
    }

    /// Whether the session has ended.
    pub fn done(&self) -> bool {
        self.done
    }

    /// The events of the start: the first question (or the summary of an
    /// empty plan).
    pub fn start(&mut self) -> Vec<Event> {
        if self.done {
            return vec![Event::Summary(self.summary())];
        }
        vec![self.ask(None)]
    }

    fn ask(&self, again: Option<Again>) -> Event {
        let item = &self.plan.items[self.pos];
        Event::Ask {
            index: self.pos,
            total: self.plan.items.len(),
            key: item.key.clone(),
            expected: item.expected.clone(),
            again,
        }
    }

    /// Moves to the next value, or ends with the summary.
    fn advance(&mut self, mut events: Vec<Event>) -> Vec<Event> {
        self.pos += 1;
        if self.pos >= self.plan.items.len() {
            self.done = true;
            events.push(Event::Summary(self.summary()));
        } else {
            events.push(self.ask(None));
        }
        events
    }

    /// Takes one input; returns the events it causes.
    pub fn handle(&mut self, input: Input) -> Vec<Event> {
        if self.done {
            return vec![];
        }
        let item = &self.plan.items[self.pos];
        let key = item.key.clone();
        match input {
            Input::Empty => vec![self.ask(Some(Again::Empty))],
            Input::Quit => {
                self.done = true;
                vec![Event::Summary(self.summary())]
            }
            Input::Back if self.pos == 0 => vec![self.ask(Some(Again::NothingBefore))],
            Input::Back => {
                self.pos -= 1;
                self.outcomes[self.pos] = None;
                vec![self.ask(None)]
            }
            Input::Hint if self.hints[self.pos] >= 2 => vec![self.ask(Some(Again::NoMoreHints))],
            Input::Hint => {
                self.hints[self.pos] += 1;
                let level = self.hints[self.pos];
                vec![Event::Hint {
                    key,
                    level,
                    step: item.step.clone(),
                }]
            }
            Input::Show | Input::Skip => {
                let show = input == Input::Show;
                self.outcomes[self.pos] = Some(Outcome {
                    key: key.clone(),
                    given: None,
                    verdict: Verdict::Missing,
                    code: if show { "revealed" } else { "skipped" },
                    note: crate::msg::Msg::default(),
                    expected: item.expected.clone(),
                    follow_through: None,
                    mistakes: vec![],
                });
                let ev = if show {
                    Event::Show {
                        key,
                        expected: item.expected.clone(),
                        step: item.step.clone(),
                    }
                } else {
                    Event::Skip { key }
                };
                self.advance(vec![ev])
            }
            Input::Answer(text) => {
                let outcome = self.judge(item, &text);
                if matches!(outcome.verdict, Verdict::Unparseable | Verdict::Missing) {
                    return vec![Event::Verdict(outcome), self.ask(Some(Again::Unreadable))];
                }
                self.outcomes[self.pos] = Some(outcome.clone());
                self.advance(vec![Event::Verdict(outcome)])
            }
        }
    }

    /// The student's value of an earlier key when it was wrong (credited by
    /// follow-through or not), else grafika's: a right answer, maybe
    /// rounded, carries grafika's value forward.
    fn own(&self, key: &str) -> Option<Val> {
        let right = lookup(&self.plan.result, key)?;
        let given = self
            .outcomes
            .iter()
            .flatten()
            .find(|o| o.key == key && (o.verdict == Verdict::Wrong || o.code == FOLLOW_THROUGH))
            .and_then(|o| o.given.as_deref());
        given
            .and_then(|g| value_of(&answer_value(g, right), right, key))
            .or_else(|| Some(right.clone()))
    }

    /// Judges an answer: check's verdict; if wrong, follow-through from the
    /// student's earlier answers, else the mistakes that reproduce it.
    fn judge(&self, item: &Item, text: &str) -> Outcome {
        let s = &self.plan.settings;
        let given = answer_value(text, &item.expected);
        let j = match unreadable(&given, &item.expected, &item.key) {
            true => Judged::new(
                Verdict::Unparseable,
                "unparseable",
                crate::msg::Msg::NotShapeAsked,
            ),
            false => judge(&given, &item.expected, s, &item.key, false),
        };
        let mut out = Outcome {
            key: item.key.clone(),
            given: Some(text.to_string()),
            verdict: j.verdict,
            code: j.code,
            note: j.note,
            expected: item.expected.clone(),
            follow_through: None,
            mistakes: vec![],
        };
        if out.verdict != Verdict::Wrong {
            return out;
        }
        let own = |k: &str| self.own(k);
        let ft = follow::recompute(&self.plan.inputs, &item.key, &own, &self.plan.result);
        match ft {
            Some(ft) if check::follows_through(&given, &ft, &item.expected, s, &item.key) => {
                out.verdict = Verdict::Correct;
                out.code = FOLLOW_THROUGH;
                out.note = crate::msg::Msg::FollowThrough;
                out.follow_through = Some(ft);
            }
            _ => {
                out.mistakes = self
                    .plan
                    .variants
                    .iter()
                    .filter(|(_, v)| check::reproduces(v, &item.key, &given, &item.expected, s))
                    .map(|(m, _)| *m)
                    .collect();
            }
        }
        out
    }

    /// The summary so far.
    pub fn summary(&self) -> Summary {
        let done: Vec<&Outcome> = self.outcomes.iter().flatten().collect();
        let count = |f: &dyn Fn(&Outcome) -> bool| done.iter().filter(|o| f(o)).count();
        let mut mistakes: Vec<(&'static Mistake, Vec<String>)> = Vec::new();
        for o in &done {
            for m in &o.mistakes {
                match mistakes.iter_mut().find(|(x, _)| x.code == m.code) {
                    Some((_, keys)) => keys.push(o.key.clone()),
                    None => mistakes.push((m, vec![o.key.clone()])),
                }
            }
        }
        let points: f64 = done.iter().map(|o| o.verdict.points()).sum();
        Summary {
            points,
            total: self.plan.items.len(),
            correct: count(&|o| o.verdict == Verdict::Correct),
            follow_through: count(&|o| o.code == FOLLOW_THROUGH),
            too_coarse: count(&|o| o.verdict == Verdict::TooCoarse),
            wrong: count(&|o| o.verdict == Verdict::Wrong),
            skipped: count(&|o| o.code == "skipped"),
            revealed: count(&|o| o.code == "revealed"),
            unanswered: self.plan.items.len() - done.len(),
            hints: self.hints.iter().map(|&h| h as usize).sum(),
            next: self.next(points, &done),
            mistakes,
        }
    }

    /// What to practise next: the topic of the most values missed (wrong,
    /// skipped, revealed; follow-through is not missed), one level easier
    /// when under half the points were earned; with none missed, the same
    /// topic one level harder.
    fn next(&self, points: f64, done: &[&Outcome]) -> (Topic, Difficulty) {
        let (topic, diff) = self.plan.drawn.unwrap_or_else(|| {
            (
                self.plan
                    .items
                    .last()
                    .map_or(Topic::Pipeline, |i| topic_of(&i.key)),
                Difficulty::Medium,
            )
        });
        let missed: Vec<Topic> = done
            .iter()
            .filter(|o| matches!(o.verdict, Verdict::Wrong | Verdict::Missing))
            .map(|o| topic_of(&o.key))
            .collect();
        let weakest = missed
            .iter()
            .max_by_key(|t| {
                (
                    missed.iter().filter(|x| x == t).count(),
                    std::cmp::Reverse(missed.iter().position(|x| x == *t)),
                )
            })
            .copied();
        let total = self.plan.items.len().max(1) as f64;
        match weakest {
            None if done.len() == self.plan.items.len() => (topic, harder(diff)),
            None => (topic, diff),
            Some(t) if points / total < 0.5 => (t, easier(diff)),
            Some(t) => (t, diff),
        }
    }
}

/// The topic a key belongs to.
pub fn topic_of(key: &str) -> Topic {
    match key.split('.').collect::<Vec<_>>()[..] {
        ["view", "points", ..] => Topic::View,
        ["view", ..] => Topic::Basis,
        ["project", ..] => Topic::Project,
        ["window", ..] => Topic::Window,
        ["clip", ..] => Topic::Clip,
        ["shade", ..] => Topic::Shade,
        _ => Topic::Pipeline,
    }
}

fn harder(d: Difficulty) -> Difficulty {
    match d {
        Difficulty::Easy => Difficulty::Medium,
        _ => Difficulty::Hard,
    }
}

fn easier(d: Difficulty) -> Difficulty {
    match d {
        Difficulty::Hard => Difficulty::Medium,
        _ => Difficulty::Easy,
    }
}

/// Whether an answer to a number, a point or a matrix cannot be read as
/// one: a part that is not a number, or the wrong count of parts (a
/// projected point may leave out zp = d; `none` is an answer to a segment).
fn unreadable(given: &toml::Value, expected: &Val, key: &str) -> bool {
    let none = matches!(given, toml::Value::String(t) if matches!(t.trim().to_lowercase().as_str(), "none" | "null" | "rejected"));
    match expected {
        Val::List(_) if key.ends_with(".segment") && none => false,
        Val::Num(_) | Val::List(_) => value_of(given, expected, key).is_none(),
        Val::Text(_) if key.ends_with(".status") => !matches!(
            written(given).trim().to_lowercase().as_str(),
            "accepted" | "rejected" | "clipped"
        ),
        Val::Text(_) => {
            let t = written(given);
            let t = t.trim();
            t.is_empty() || t.len() > 6 || !t.chars().all(|c| c == '0' || c == '1')
        }
        _ => false,
    }
}

/// A typed line as an answer: with `;` in it, the parts between semicolons
/// (the components of a point written with decimal commas, `0,8; 0,6; 0`,
/// or the rows of a matrix); otherwise the text as `check` reads it.
pub fn answer_value(text: &str, expected: &Val) -> toml::Value {
    let t = text.trim();
    match expected {
        Val::List(_) if t.contains(';') => {
            let inner = t
                .trim_start_matches(['(', '['])
                .trim_end_matches([')', ']']);
            toml::Value::Array(
                inner
                    .split(';')
                    .map(|p| toml::Value::String(p.trim().to_string()))
                    .collect(),
            )
        }
        _ => toml::Value::String(t.to_string()),
    }
}

/// Runs a session: `next_line` gives each line typed (None at the end of
/// the input, which quits), `emit` gets each event. Returns the summary.
pub fn run(
    plan: &Plan,
    mut next_line: impl FnMut() -> Option<String>,
    mut emit: impl FnMut(&Event),
) -> Summary {
    let mut s = Session::new(plan);
    for e in s.start() {
        emit(&e);
    }
    while !s.done() {
        let input = next_line().map_or(Input::Quit, |l| read_input(&l));
        for e in s.handle(input) {
            emit(&e);
        }
    }
    s.summary()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_in_both_languages_and_answers() {
        assert_eq!(read_input(" HINT "), Input::Hint);
        assert_eq!(read_input("petunjuk"), Input::Hint);
        assert_eq!(read_input("lihat"), Input::Show);
        assert_eq!(read_input("lewati"), Input::Skip);
        assert_eq!(read_input("kembali"), Input::Back);
        assert_eq!(read_input("keluar"), Input::Quit);
        assert_eq!(read_input("   "), Input::Empty);
        assert_eq!(read_input(" 4/5 "), Input::Answer("4/5".into()));
    }

    #[test]
    fn semicolons_separate_parts_written_with_decimal_commas() {
        let point = Val::List(vec![Val::num(&0.8), Val::num(&0.6), Val::num(&0.0)]);
        let v = answer_value("(0,8; 0,6; 0)", &point);
        assert_eq!(
            v,
            toml::Value::Array(vec!["0,8".into(), "0,6".into(), "0".into()])
        );
        assert_eq!(answer_value("0.8, 0.6, 0", &point), "0.8, 0.6, 0".into());
    }

    #[test]
    fn the_topic_of_a_key() {
        assert_eq!(topic_of("view.n"), Topic::Basis);
        assert_eq!(topic_of("view.points.A"), Topic::View);
        assert_eq!(topic_of("viewport.pixels.A"), Topic::Pipeline);
        assert_eq!(topic_of("clip.0.status"), Topic::Clip);
    }
}
