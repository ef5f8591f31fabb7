//! `grafika practice`: a problem worked one value at a time, in the order of
//! the text's solution (n, u, v, the view matrix, eye coordinates, projected
//! points, window, pixels; outcodes, each t, intersection and its outcode,
//! the clipped segment, the status; unit L and N, cos α, R, cos β, the
//! terms, their sum, the colour). Each answer is read as `check` reads it
//! (and echoed as read) and gets `check`'s verdict at once ([`Marker`]); a
//! wrong one that is right given the student's own earlier answers is
//! credited as `correct.follow_through` ([`Marker::carried`]); otherwise the
//! mistakes of the catalog that reproduce it and that the earlier answers
//! allow are named.
//!
//! The score is honest: the first verdict on each value counts, and a value
//! revealed with `show` stays revealed; so does every value a `show` or a
//! hint prints, whichever step printed it (`show` on the window's bottom
//! prints its right, left, height and width too); an answer given again
//! after `back`, or to a value already shown, is judged and shown, and
//! counted apart as a retry.
//!
//! Plain functions over plain data: [`plan`] solves the problem, a
//! [`Session`] takes one [`Input`] at a time and returns the [`Event`]s it
//! causes; [`run`] drives a session from any source of lines. The words for
//! people are made in `report::practice`.

use crate::error::Result;
use crate::input::answer::{Given, Read};
use crate::input::problem::ProblemIn;
use crate::msg::{Msg, Said};
use crate::stages::trace::{Name, Step, Val};
use crate::tutor::check::Follow;
use crate::tutor::check::{Marker, Settings, Verdict};
use crate::tutor::diagnose::Code;
use crate::tutor::generate::{Difficulty, Topic};
use crate::tutor::key::{Edge, Field, Key, Part, Shading, Value};

/// One value the student is asked for.
#[derive(Clone, Debug)]
pub struct Item {
    /// The answer key, as in `check` (`view.n`, `project.points.A`).
    pub key: Key,
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
    /// The topic and difficulty, when the problem was generated.
    pub drawn: Option<(Topic, Difficulty)>,
    /// The judge, with grafika's results and the catalog's.
    marker: Marker,
    /// The numbers the problem states (its inputs), which a hint may show.
    stated: Vec<f64>,
}

impl Plan {
    /// How answers are marked.
    pub fn settings(&self) -> &Settings {
        &self.marker.settings
    }
}

/// Solves the problem exactly and lays out the values to ask for: the
/// problem's `[check] keys` when it lists them (and L, N of a lighting
/// problem), else every key of the solution in the text's order.
pub fn plan(p: &ProblemIn, settings: Settings, drawn: Option<(Topic, Difficulty)>) -> Result<Plan> {
    let marker = Marker::new(p, settings)?;
    // `[check] keys`, read as keys (`clip[0].status` is `clip.0.status`)
    let wanted = p
        .check
        .as_ref()
        .and_then(|c| c.keys.as_ref())
        .map(|_| marker.scheme.keys().cloned().collect::<Vec<Key>>());
    let items = marker
        .order
        .iter()
        .filter(|k| {
            let unit = matches!(
                (k.part, &k.value),
                (
                    Some(Part::Shade),
                    Value::Field(Field::Shading(Shading::L | Shading::N))
                )
            );
            // a `[check] key` that is no key of the solution asks
            // nothing, as `check` reports it unknown
            unit || wanted.as_ref().is_none_or(|w| w.contains(k))
        })
        .filter_map(|key| {
            Some(Item {
                key: key.clone(),
                expected: marker.result.get(key)?.into_owned(),
                step: step_for(key, &marker.steps),
            })
        })
        .collect();
    let stated = p.stated_numbers();
    Ok(Plan {
        title: p.title.clone(),
        statement: p.statement.clone(),
        items,
        drawn,
        marker,
        stated,
    })
}

/// The worked step that computes a key: the step whose result bears the
/// key's name (the eye point `A'` for `view.points.A`, `cos α` for
/// `shade.cos_alpha`, …). An exhaustive match, so a new field or value
/// is given its step name (or none) as soon as it compiles.
pub(crate) fn step_for(key: &Key, steps: &[Step]) -> Option<Step> {
    if key.part? == Part::Clip {
        return clip_step(key.segment.unwrap_or(0), &key.value, steps);
    }
    let name = step_name(key)?;
    steps
        .iter()
        .find(|s| s.result.iter().any(|(n, _)| *n == name))
        .cloned()
}

/// The name a key's value bears in the worked steps (`A'` for
/// `view.points.A`, `cos α` for `shade.cos_alpha`), where it has one of its
/// own: a clipping's values (t, code, P(t) of each plane) share theirs.
fn step_name(key: &Key) -> Option<Name> {
    use Shading as S;
    Some(match (key.part?, &key.value) {
        (Part::Clip, _) => return None,
        (Part::View, Value::Point(p)) => Name::Eye(p.clone()),
        (Part::Project, Value::Point(p)) => Name::Image(p.clone()),
        (Part::Viewport, Value::Pixel(p)) => Name::Pixel(p.clone()),
        (_, Value::Field(f)) => match f {
            Field::Matrix => Name::math("V"),
            Field::Shading(S::CosAlpha) => Name::math("cos α"),
            Field::Shading(S::CosBeta) => Name::math("cos β"),
            Field::Shading(S::NDotH) => Name::math("N·H"),
            Field::Shading(S::Color) => Name::Color,
            Field::Shading(S::Unclamped) => Name::Unclamped,
            Field::Edge(Edge::Height, false) => Name::Height,
            Field::Edge(Edge::Width, false) => Name::Width,
            // the step's name is the key's notation (`n`, `top`, `ambient`,
            // `R`); the far window's edges and the emissive term have no
            // step of their own, so none is found
            Field::Axis(_)
            | Field::Edge(..)
            | Field::Shading(
                S::L | S::N | S::R | S::H | S::Ambient | S::Diffuse | S::Specular | S::Emissive,
            ) => Name::math(f.key()),
            Field::Points
            | Field::Pixels
            | Field::Lights
            | Field::Code0
            | Field::Code1
            | Field::Status
            | Field::Segment
            | Field::Intersections => return None,
        },
        (_, Value::Point(_) | Value::Pixel(_)) => return None,
        (
            _,
            Value::Whole | Value::Plane(_) | Value::Cut(..) | Value::Light(_) | Value::Factor(..),
        ) => return None,
    })
}

/// The clipping step of a key in segment `run`: steps are split into one
/// run per segment at each outcode step of P0.
fn clip_step(run: usize, value: &Value, steps: &[Step]) -> Option<Step> {
    let code = Name::RegionCode;
    let starts = |s: &Step| {
        s.result.iter().any(|(n, _)| *n == code)
            && s.values
                .first()
                .is_some_and(|(n, _)| *n == Name::math("P0"))
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
    let has = |s: &&Step, n: &Name| s.result.iter().any(|(x, _)| x == n);
    let found = match value {
        Value::Field(f @ (Field::Code0 | Field::Code1)) => {
            let point = Name::math(if *f == Field::Code0 { "P0" } else { "P1" });
            run.iter()
                .find(|s| has(s, &code) && s.values.first().is_some_and(|(n, _)| *n == point))
        }
        Value::Cut(plane, _) => {
            // the intersections are recorded in the order of the result's map
            let tried = run.iter().filter(|s| has(s, &Name::math("P(t)")));
            tried
                .clone()
                .find(|s| matches!(s.title, Msg::Intersection(i, _) if i == plane.bit()))
                .or_else(|| tried.clone().next())
        }
        Value::Field(Field::Segment) => run
            .iter()
            .find(|s| has(s, &Name::From) && has(s, &Name::To)),
        Value::Field(Field::Status) => run.iter().find(|s| has(s, &Name::math("code0 AND code1"))),
        Value::Whole
        | Value::Field(_)
        | Value::Point(_)
        | Value::Pixel(_)
        | Value::Plane(_)
        | Value::Light(_)
        | Value::Factor(..) => None,
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

/// Why a value is asked again (its JSON: `empty`, `nothing_before`, …).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
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

/// How a value was left without an answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unanswered {
    /// `skip`: it has no verdict yet, and may still be answered.
    Skipped,
    /// `show`, or shown by another value's step or hint: it counts as not
    /// answered.
    Revealed,
}

/// How one answer (or `show`, `skip`) ended.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The key.
    pub key: Key,
    /// The answer as typed (None when skipped or revealed).
    pub given: Option<String>,
    /// The answer as read (None when it could not be read, or none given).
    pub read: Option<Read>,
    /// The verdict (`check`'s, or follow-through; `Missing` when skipped
    /// or revealed).
    pub verdict: Verdict,
    /// How the value was left without an answer (None when answered).
    pub unanswered: Option<Unanswered>,
    /// How it was judged (check's note).
    pub note: Msg,
    /// grafika's value.
    pub expected: Val,
    /// The value computed from the student's own earlier answers, when
    /// the answer was credited by follow-through.
    pub follow_through: Option<Val>,
    /// The mistakes of the catalog that reproduce a wrong answer.
    pub mistakes: Vec<Code>,
    /// Why the source's printed value is wrong, when the answer is that
    /// misprint (`copied_misprint`).
    pub why: Option<Msg>,
    /// An answer given again after `back`, or to a value already shown:
    /// shown, counted apart (the value's first verdict, or its revealing,
    /// stands for the score).
    pub retry: bool,
    /// The value had been shown (by `show` or a hint, of this step or
    /// another) before this answer: it counts as revealed.
    pub shown: bool,
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
        key: Key,
        /// grafika's value (for its shape: a number, a point, a matrix).
        expected: Val,
        /// Why it is asked again.
        again: Option<Again>,
    },
    /// An answer judged (also an unreadable one, which is asked again).
    Verdict(Outcome),
    /// A hint: level 1 the idea and the formula, level 2 the values
    /// substituted, a step short of the value ([`hint_step`]).
    Hint {
        /// The key.
        key: Key,
        /// 1 or 2.
        level: u8,
        /// The hint's step: the step's title and formula, and at level 2
        /// the values that do not give the answer away.
        step: Option<Step>,
        /// The other values the hint prints, now counted as revealed.
        also: Vec<Key>,
    },
    /// The step worked out and the value (counted as revealed).
    Show {
        /// The key.
        key: Key,
        /// grafika's value.
        expected: Val,
        /// The step.
        step: Option<Step>,
        /// The other values the step prints, now counted as revealed.
        also: Vec<Key>,
    },
    /// A value skipped.
    Skip {
        /// The key.
        key: Key,
    },
    /// The end: the summary.
    Summary(Summary),
}

/// The end of a session.
#[derive(Clone, Debug)]
pub struct Summary {
    /// Marks earned by the marking scheme (`check`'s), from each value's
    /// first verdict: the values the problem asks earn their marks (½ too
    /// coarse), or method marks from their working; the steps between earn
    /// none of their own.
    pub points: f64,
    /// The marks of the values the problem asks that the session asks.
    pub total: u32,
    /// Values asked in the session (every step).
    pub steps: usize,
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
    /// Answers given again after `back` (not scored).
    pub retries: usize,
    /// Of those, right.
    pub retries_correct: usize,
    /// Each mistake made, with the keys it explains.
    pub mistakes: Vec<(Code, Vec<Key>)>,
    /// What to practise next.
    pub next: (Topic, Difficulty),
}

/// A session in progress.
pub struct Session<'a> {
    plan: &'a Plan,
    pos: usize,
    /// What counts for the score: each value's first verdict, or its
    /// revealing (a skip is replaced by a later answer).
    scored: Vec<Option<Outcome>>,
    /// The student's latest answer to each value (what later values
    /// follow through from).
    latest: Vec<Option<Outcome>>,
    /// Answers given again after `back`.
    retries: Vec<Outcome>,
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
            scored: vec![None; n],
            latest: vec![None; n],
            retries: vec![],
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

    /// Whether the value at the current position has a verdict that counts
    /// (an answer or a revealing; a skip does not count).
    fn scored_here(&self) -> bool {
        self.scored[self.pos]
            .as_ref()
            .is_some_and(|o| o.unanswered != Some(Unanswered::Skipped))
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
                vec![self.ask(None)]
            }
            Input::Hint if self.hints[self.pos] >= 2 => vec![self.ask(Some(Again::NoMoreHints))],
            Input::Hint => {
                self.hints[self.pos] += 1;
                let level = self.hints[self.pos];
                let own = self.own_step(item);
                let from = own.as_ref().or(item.step.as_ref());
                let step = hint_step(from, &item.expected, level, &self.plan.stated);
                let also = step.as_ref().map_or(vec![], |s| self.reveal(s, false));
                vec![Event::Hint {
                    key,
                    level,
                    step,
                    also,
                }]
            }
            Input::Show | Input::Skip => {
                let show = input == Input::Show;
                if !self.scored_here() {
                    let how = match show {
                        true => Unanswered::Revealed,
                        false => Unanswered::Skipped,
                    };
                    self.scored[self.pos] = Some(unanswered(item, Some(how)));
                }
                let ev = if show {
                    let also = item.step.as_ref().map_or(vec![], |s| self.reveal(s, true));
                    Event::Show {
                        key,
                        expected: item.expected.clone(),
                        step: item.step.clone(),
                        also,
                    }
                } else {
                    Event::Skip { key }
                };
                self.advance(vec![ev])
            }
            Input::Answer(text) => {
                let mut outcome = self.judge(item, &text);
                if matches!(outcome.verdict, Verdict::Unparseable | Verdict::Missing) {
                    return vec![Event::Verdict(outcome), self.ask(Some(Again::Unreadable))];
                }
                if self.scored_here() {
                    outcome.retry = true;
                    outcome.shown = self.scored[self.pos]
                        .as_ref()
                        .is_some_and(|o| o.unanswered == Some(Unanswered::Revealed));
                    self.retries.push(outcome.clone());
                } else {
                    self.scored[self.pos] = Some(outcome.clone());
                }
                self.latest[self.pos] = Some(outcome.clone());
                self.advance(vec![Event::Verdict(outcome)])
            }
        }
    }

    /// Counts as revealed every other value that `printed` shows and that
    /// has no verdict yet (a skip is none): a value the step computes
    /// (`whole`: its results are printed), or one it prints under the
    /// value's own name (`top` in the window's edges, `n` and `u` beside
    /// v). Returns their keys, in the order asked.
    fn reveal(&mut self, printed: &Step, whole: bool) -> Vec<Key> {
        let mut also = Vec::new();
        for (i, item) in self.plan.items.iter().enumerate() {
            let open = self.scored[i]
                .as_ref()
                .is_none_or(|o| o.unanswered == Some(Unanswered::Skipped));
            if i == self.pos || !open || !prints(printed, item, whole) {
                continue;
            }
            self.scored[i] = Some(unanswered(item, Some(Unanswered::Revealed)));
            also.push(item.key.clone());
        }
        also
    }

    /// The item's step worked from the student's own earlier values where
    /// they were wrong (None when none was): a hint goes on from them.
    fn own_step(&self, item: &Item) -> Option<Step> {
        let earlier = &self.plan.items[..self.pos];
        let own: Vec<(Key, Read)> = (earlier.iter())
            .filter_map(|i| Some((i.key.clone(), self.own(&i.key)?)))
            .collect();
        if own.is_empty() {
            return None;
        }
        step_for(&item.key, &self.plan.marker.steps_given(&own)?)
    }

    /// The student's latest answer to an earlier key, where it was wrong
    /// (credited by follow-through or not): what follow-through goes on
    /// from; a right answer, maybe rounded, carries grafika's value.
    fn own(&self, key: &Key) -> Option<Read> {
        self.latest
            .iter()
            .flatten()
            .find(|o| o.key == *key && matches!(o.verdict, Verdict::Wrong | Verdict::FollowThrough))
            .and_then(|o| o.read.clone())
    }

    /// Judges an answer as `check` does; a wrong count of parts is asked
    /// again; a wrong answer is credited by follow-through when it is right
    /// given the student's own earlier answers, else it names the mistakes
    /// that reproduce it and that the earlier right answers allow.
    fn judge(&self, item: &Item, text: &str) -> Outcome {
        let m = &self.plan.marker;
        let key = &item.key;
        let j = m.judge(key, &item.expected, Given::Text(text));
        let mut out = Outcome {
            given: Some(text.to_string()),
            read: j.read,
            verdict: j.verdict,
            note: j.note,
            ..unanswered(item, None)
        };
        if out.verdict == Verdict::Wrong && matches!(out.note, Msg::CountMismatch(..)) {
            out.verdict = Verdict::Unparseable;
            return out;
        }
        let Some(read) = out.read.clone().filter(|_| out.verdict == Verdict::Wrong) else {
            return out;
        };
        let own = |k: &Key| self.own(k);
        if !j.mistakes.contains(&Code::CopiedMisprint) {
            match m.follow(key, &read, &own) {
                Follow::Credited(ft) => {
                    out.verdict = Verdict::FollowThrough;
                    out.note = Msg::FollowThrough;
                    out.follow_through = Some(ft);
                    return out;
                }
                Follow::Blocked(why) => out.note = why,
                Follow::Not => {}
            }
        }
        let agreed: Vec<(&Key, &Read)> = self
            .latest
            .iter()
            .flatten()
            .filter(|o| o.verdict.agrees())
            .filter_map(|o| Some((&o.key, o.read.as_ref()?)))
            .collect();
        out.mistakes = m.fitting(key, &read, &j.mistakes, &agreed);
        if out.mistakes.contains(&Code::CopiedMisprint) {
            out.why = m.erratum(key);
        }
        out
    }

    /// The summary so far: each value's first verdict (or its revealing),
    /// and the retries apart.
    pub fn summary(&self) -> Summary {
        let done: Vec<&Outcome> = self.scored.iter().flatten().collect();
        let count = |f: &dyn Fn(&Outcome) -> bool| done.iter().filter(|o| f(o)).count();
        let mut mistakes: Vec<(Code, Vec<Key>)> = Vec::new();
        for o in &done {
            for m in &o.mistakes {
                match mistakes.iter_mut().find(|(x, _)| x == m) {
                    Some((_, keys)) => keys.push(o.key.clone()),
                    None => mistakes.push((*m, vec![o.key.clone()])),
                }
            }
        }
        let (points, total) = self.marks(&done);
        Summary {
            points,
            total,
            steps: self.plan.items.len(),
            correct: count(&|o| o.verdict.is_correct()),
            follow_through: count(&|o| o.verdict == Verdict::FollowThrough),
            too_coarse: count(&|o| o.verdict == Verdict::TooCoarse),
            wrong: count(&|o| o.verdict == Verdict::Wrong),
            skipped: count(&|o| o.unanswered == Some(Unanswered::Skipped)),
            revealed: count(&|o| o.unanswered == Some(Unanswered::Revealed)),
            unanswered: self.plan.items.len() - done.len(),
            hints: self.hints.iter().map(|&h| h as usize).sum(),
            retries: self.retries.len(),
            retries_correct: (self.retries.iter())
                .filter(|o| o.verdict.is_correct())
                .count(),
            next: self.next(points, &done),
            mistakes,
        }
    }

    /// The marks earned and possible by the scheme, over the values it asks
    /// that the session asks (all of them, when the session asks none).
    fn marks(&self, done: &[&Outcome]) -> (f64, u32) {
        let verdict = |k: &Key| done.iter().find(|o| o.key == *k).map(|o| o.verdict);
        let scheme = &self.plan.marker.scheme;
        let asked = |k: &Key| self.plan.items.iter().any(|i| i.key == *k);
        let items: Vec<_> = match scheme.items.iter().any(|i| asked(&i.key)) {
            true => scheme.items.iter().filter(|i| asked(&i.key)).collect(),
            false => scheme.items.iter().collect(),
        };
        // from +0: an empty f64 sum is −0, which would print as -0
        let points = items.iter().fold(0.0, |s, i| {
            s + i
                .earned(verdict(&i.key).unwrap_or(Verdict::Missing), &verdict)
                .0
        });
        (points, items.iter().map(|i| i.marks).sum())
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
        let total = f64::from(self.marks(done).1.max(1));
        match weakest {
            None if done.len() == self.plan.items.len() => (topic, harder(diff)),
            None => (topic, diff),
            Some(t) if points / total < 0.5 => (t, easier(diff)),
            Some(t) => (t, diff),
        }
    }
}

/// A value with no answer: revealed or skipped (and, with None, the
/// outcome a judged answer starts from).
fn unanswered(item: &Item, how: Option<Unanswered>) -> Outcome {
    Outcome {
        key: item.key.clone(),
        given: None,
        read: None,
        verdict: Verdict::Missing,
        unanswered: how,
        note: Msg::default(),
        expected: item.expected.clone(),
        follow_through: None,
        mistakes: vec![],
        why: None,
        retry: false,
        shown: false,
    }
}

/// Whether a printed step shows an item's value: it is the item's own
/// step and its results are printed (`whole`), or it holds the value under
/// the value's own name.
fn prints(printed: &Step, item: &Item, whole: bool) -> bool {
    if whole && item.step.as_ref() == Some(printed) {
        return true;
    }
    let Some(name) = step_name(&item.key) else {
        return false;
    };
    let named = |(n, v): &(Name, Val)| *n == name && *v == item.expected;
    printed.values.iter().any(named) || (whole && printed.result.iter().any(named))
}

/// The step of a hint: level 1 the idea (the step's title) and the
/// formula; level 2 also the values substituted, but a step short of the
/// answer: a value that would give it away ([`leaks`]) is left out, and an
/// outcode's bit tests are asked, not answered.
pub fn hint_step(step: Option<&Step>, expected: &Val, level: u8, stated: &[f64]) -> Option<Step> {
    let s = step?;
    let mut h = Step::new(s.title.clone(), s.formula.clone());
    // the step's own results (from the student's values, they may differ
    // from grafika's) are kept back too
    let results: Vec<&Val> = s.result.iter().map(|(_, v)| v).collect();
    if level >= 2 {
        h.values = s
            .values
            .iter()
            .filter(|(_, v)| {
                !leaks(v, expected, stated) && !results.iter().any(|r| leaks(v, r, stated))
            })
            .map(|(k, v)| (k.clone(), asked_not_answered(v)))
            .collect();
    }
    Some(h)
}

/// An outcode bit's test as a question (its truth is the answer).
fn asked_not_answered(v: &Val) -> Val {
    match v {
        Val::Said(Msg::Said(Said::BitTest(_, test, values))) => {
            Val::said(Said::BitQuestion(test.clone(), values.clone()))
        }
        other => other.clone(),
    }
}

/// Whether a value shown in a hint gives the asked value away: it is the
/// asked value itself, or it holds one of the asked value's numbers (up to
/// sign) that has three or more significant figures and is none of 0, ±1
/// and the numbers the problem states.
pub fn leaks(shown: &Val, asked: &Val, stated: &[f64]) -> bool {
    let same = |a: f64, b: f64| (a.abs() - b.abs()).abs() <= 1e-9 * a.abs().max(b.abs());
    if shown == asked
        || matches!((shown, asked), (Val::List(_), Val::List(_)) if {
            let (a, b) = (shown.numbers(), asked.numbers());
            a.len() == b.len() && a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1e-12 * x.abs().max(1.0))
        })
    {
        return true;
    }
    let (own, its) = (asked.numbers(), shown.numbers());
    own.iter()
        .filter(|x| figures(**x) >= 3 && !stated.iter().any(|s| same(*s, **x)))
        .any(|x| its.iter().any(|y| same(*x, *y)))
}

/// How many significant figures a number's shortest decimal has.
fn figures(x: f64) -> usize {
    let s = format!("{:e}", x.abs());
    let mantissa = s.split('e').next().unwrap_or_default();
    mantissa.chars().filter(|c| c.is_ascii_digit()).count()
}

/// The topic a key belongs to (its part's module says which:
/// [`crate::tutor::parts::Solves::topic`]; a calculator command's key:
/// the pipeline).
pub fn topic_of(k: &Key) -> Topic {
    match k.part {
        Some(part) => (crate::tutor::parts::of(part).topic)(&k.value),
        None => Topic::Pipeline,
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

    /// The text's example 6.1 without its point: n = (4/5, 3/5, 0),
    /// u = (0, 0, −1), v = (−3/5, 4/5, 0).
    fn camera_plan() -> Plan {
        let p = ProblemIn::parse(
            "title = 't'\nask = ['view']\n[camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n",
            "t",
        )
        .unwrap();
        plan(&p, Settings::default(), None).unwrap()
    }

    fn verdict(events: &[Event]) -> &Outcome {
        events
            .iter()
            .find_map(|e| match e {
                Event::Verdict(o) => Some(o),
                _ => None,
            })
            .unwrap()
    }

    /// A line typed is judged as the text it is: its numbers are parsed
    /// once (grafika's exact forms are read at the first answer, and kept).
    #[test]
    fn a_typed_answer_is_parsed_once() {
        let plan = camera_plan();
        let mut s = Session::new(&plan);
        s.start();
        s.handle(Input::Answer("4/5, 3/5, 0".into()));
        s.handle(Input::Back);
        let parsed = || crate::num::expr::PARSED.with(std::cell::Cell::get);
        let before = parsed();
        // n = (4/5, 3/5, 0): three numbers, with the decimal comma
        let again = s.handle(Input::Answer("n = (0,8; 0,6; 0)".into()));
        assert_eq!(verdict(&again).verdict, Verdict::Exact);
        assert_eq!(parsed() - before, 3);
    }

    #[test]
    fn the_first_verdict_counts_and_a_revealed_value_stays_revealed() {
        let plan = camera_plan();
        let mut s = Session::new(&plan);
        s.start();
        // n = Pe − Pr = (4, 3, 0) not divided by |Pe − Pr| = 5: wrong
        assert_eq!(
            verdict(&s.handle(Input::Answer("4, 3, 0".into()))).verdict,
            Verdict::Wrong
        );
        s.handle(Input::Back);
        // right the second time: shown, counted apart
        let again = s.handle(Input::Answer("4/5, 3/5, 0".into()));
        assert!(verdict(&again).retry && verdict(&again).verdict.is_correct());
        // u revealed, then back and answered: still revealed
        s.handle(Input::Show);
        s.handle(Input::Back);
        let after_show = s.handle(Input::Answer("0, 0, -1".into()));
        assert!(verdict(&after_show).retry);
        // v skipped, then back and answered: a skip is no verdict
        s.handle(Input::Skip);
        s.handle(Input::Back);
        assert!(!verdict(&s.handle(Input::Answer("-3/5, 4/5, 0".into()))).retry);
        let sum = s.summary();
        assert_eq!(
            (sum.points, sum.wrong, sum.revealed, sum.correct),
            (1.0, 1, 1, 1)
        );
        assert_eq!((sum.retries, sum.retries_correct, sum.skipped), (2, 2, 0));
    }

    #[test]
    fn a_value_a_show_printed_counts_as_revealed() {
        // near 0.1, fovy 45°, aspect 2: top = 0.1·tan 22.5° = (√2 − 1)/10;
        // the step of bottom = −top prints right, left, height and width too
        let p = ProblemIn::parse(
            "title = 't'\nask = ['window']\n[perspective]\nnear = 0.1\nfovy = 45\naspect = 2\n",
            "t",
        )
        .unwrap();
        let plan = plan(&p, Settings::default(), None).unwrap();
        let keys: Vec<String> = plan.items.iter().map(|i| i.key.to_string()).collect();
        assert_eq!(keys[..2], ["window.top", "window.bottom"]);
        let mut s = Session::new(&plan);
        s.start();
        assert_eq!(
            verdict(&s.handle(Input::Answer("0.0414".into()))).verdict,
            Verdict::Tolerance // 0.0414 is 0.05 % off (√2 − 1)/10 = 0.041421
        );
        let shown = s.handle(Input::Show);
        let also = shown.iter().find_map(|e| match e {
            Event::Show { also, .. } => Some(also.iter().map(Key::to_string).collect::<Vec<_>>()),
            _ => None,
        });
        let mut others = keys[2..].to_vec();
        others.sort();
        let mut got = also.unwrap();
        got.sort();
        assert_eq!(got, others);
        // right, left, height, width typed next: judged, not scored
        for t in ["-0.0828", "0.0828", "0.0828", "0.1657"] {
            let o = s.handle(Input::Answer(t.into()));
            let o = verdict(&o);
            assert!(o.verdict.is_correct() && o.retry && o.shown, "{t}: {o:?}");
        }
        let sum = s.summary();
        assert_eq!((sum.points, sum.correct, sum.revealed), (1.0, 1, 5));
    }

    #[test]
    fn a_value_a_hint_printed_counts_as_revealed() {
        // the hint on v = n × u, at level 2, prints n = (4/5, 3/5, 0) and
        // u = (0, 0, −1): both skipped, both now revealed
        let plan = camera_plan();
        let mut s = Session::new(&plan);
        s.start();
        s.handle(Input::Skip);
        s.handle(Input::Skip);
        s.handle(Input::Hint);
        let hint = s.handle(Input::Hint);
        let also = hint.iter().find_map(|e| match e {
            Event::Hint { also, level: 2, .. } => Some(also.clone()),
            _ => None,
        });
        assert_eq!(also, Some(vec![key("view.n"), key("view.u")]));
        s.handle(Input::Answer("-3/5, 4/5, 0".into()));
        let sum = s.summary();
        assert_eq!((sum.correct, sum.revealed, sum.skipped), (1, 2, 0));
    }

    #[test]
    fn a_hint_leaves_out_what_gives_the_answer_away() {
        let num = |x: f64| Val::num(&x);
        let r = std::f64::consts::FRAC_1_SQRT_2;
        // u = (√2/2, 0, −√2/2); Vup × n = u itself, and n = (√2/2, 0, √2/2)
        // holds its numbers up to sign
        let u = Val::List(vec![num(r), num(0.0), num(-r)]);
        assert!(leaks(&u, &u, &[]));
        assert!(leaks(&Val::List(vec![num(r), num(0.0), num(r)]), &u, &[]));
        // Vup = (0, 1, 0) and |Vup × n| = 1 hold no figure of it
        assert!(!leaks(
            &Val::List(vec![num(0.0), num(1.0), num(0.0)]),
            &u,
            &[]
        ));
        assert!(!leaks(&num(1.0), &u, &[]));
        // d/z = √2/60 is yp = −√2/60 up to sign; 0.02 has one figure
        let a2 = Val::List(vec![num(0.0), num(-(2f64.sqrt()) / 60.0), num(-0.1)]);
        assert!(leaks(&num(2f64.sqrt() / 60.0), &a2, &[]));
        // 0.02 has one figure: shown beside (0.02, 0.5) as part of it, no leak
        assert!(!leaks(
            &num(0.02),
            &Val::List(vec![num(0.02), num(0.5)]),
            &[]
        ));
        // a number the problem states may be shown whatever it equals
        assert!(!leaks(
            &num(2.5),
            &Val::List(vec![num(2.5), num(1.75)]),
            &[2.5]
        ));
    }

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn the_topic_of_a_key() {
        assert_eq!(topic_of(&key("view.n")), Topic::Basis);
        assert_eq!(topic_of(&key("view.points.A")), Topic::View);
        assert_eq!(topic_of(&key("viewport.pixels.A")), Topic::Pipeline);
        assert_eq!(topic_of(&key("clip.0.status")), Topic::Clip);
    }
}
