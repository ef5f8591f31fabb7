//! The marking scheme: what a problem asks and what each answer is worth,
//! one for `check`, `practice`, the class report and the quizzes.
//!
//! A problem asks its final values: a problem file's `[check] keys`, else
//! [`super::default_keys`] (each part's answers; a lighting problem's
//! colour). Each is worth one mark, unless the file's `[marks]` table says
//! otherwise:
//!
//! ```toml
//! [marks]
//! "view.n" = 2
//! "shade.color" = { marks = 4, method = { "shade.ambient" = 1, "shade.diffuse" = 1, "shade.specular" = 1 } }
//! ```
//!
//! A key of `[marks]` that is not asked already is asked too (after the
//! others, in the order of the text's solution); a key worth 0 is not
//! asked. The total is the sum of the marks asked, whatever a student
//! writes: an answer to a key the scheme does not ask is working, marked
//! and shown, and never counted. A final value's `method` marks are what
//! its working can earn when the value itself is not right: each method key
//! answered right (or by follow-through) earns its marks, a too coarse one
//! half, and the value earns the larger of that sum (at most its own
//! marks) and its own verdict's share.

use super::{answer_key, default_keys, Results, Verdict};
use crate::error::{Error, Result};
use crate::input::problem::ProblemIn;
use crate::msg::ErrMsg;
use crate::tutor::key::Key;

/// The most marks one key may be worth (a Moodle blank's weight is a small
/// whole number).
pub const MAX_MARKS: u32 = 100;

/// One final value asked, and what it is worth.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// The answer key.
    pub key: Key,
    /// Its marks.
    pub marks: u32,
    /// The working that can earn method marks when the value is not right:
    /// each key with its marks (their sum is at most `marks`).
    pub method: Vec<(Key, u32)>,
}

impl Item {
    /// The marks this value earns with the verdict `verdict`: its share of
    /// its marks, or, when it is not right, what its working earns as
    /// method marks (each method key's verdict, from `of`, earning its
    /// share of that key's marks), whichever is more, at most its marks;
    /// with the working keys that earned them when they count.
    pub fn earned(
        &self,
        verdict: Verdict,
        of: &dyn Fn(&Key) -> Option<Verdict>,
    ) -> (f64, Vec<Key>) {
        let own = share(verdict, self.marks);
        if verdict.is_correct() {
            return (own, Vec::new());
        }
        let earning: Vec<(&Key, f64)> = (self.method.iter())
            .filter_map(|(k, marks)| Some((k, share(of(k)?, *marks))))
            .filter(|(_, e)| *e > 0.0)
            .collect();
        let method: f64 = earning.iter().map(|(_, e)| e).sum();
        match method > own {
            true => (
                method.min(f64::from(self.marks)),
                earning.into_iter().map(|(k, _)| k.clone()).collect(),
            ),
            false => (own, Vec::new()),
        }
    }
}

/// What a problem asks, in order, and what each answer is worth.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scheme {
    /// The final values asked, in the order they are marked.
    pub items: Vec<Item>,
}

impl Scheme {
    /// The total: the sum of the marks asked.
    pub fn total(&self) -> u32 {
        self.items.iter().map(|i| i.marks).sum()
    }

    /// The item asking `key`, if the scheme asks it.
    pub fn item(&self, key: &Key) -> Option<&Item> {
        self.items.iter().find(|i| i.key == *key)
    }

    /// The keys asked, in order.
    pub fn keys(&self) -> impl Iterator<Item = &Key> {
        self.items.iter().map(|i| &i.key)
    }

    /// The scheme of a problem whose exact results are `result`, with its
    /// keys in the text's `order`: `[check] keys` (those that are keys of
    /// the results) or the default keys, each one mark, then `[marks]`.
    pub fn of(p: &ProblemIn, result: &Results, order: &[Key]) -> Result<Scheme> {
        let asked: Vec<Key> = match p.check.as_ref().and_then(|c| c.keys.as_ref()) {
            Some(ks) => ks.iter().filter_map(|k| answer_key(k).ok()).collect(),
            None => default_keys(result),
        };
        // a `[check] key` that is no value of the results asks nothing
        // (an answer to it is reported unknown)
        let asked = asked.into_iter().filter(|k| result.get(k).is_some());
        let mut items: Vec<Item> = Vec::new();
        for key in asked {
            if !items.iter().any(|i| i.key == key) {
                items.push(Item {
                    key,
                    marks: 1,
                    method: Vec::new(),
                });
            }
        }
        let mut added = Vec::new();
        for (name, spec) in &p.marks {
            let key = known(&field(name), name, result)?;
            let (marks, method) = read_spec(name, spec, result)?;
            match items.iter_mut().find(|i| i.key == key) {
                Some(i) => (i.marks, i.method) = (marks, method),
                None => added.push(Item { key, marks, method }),
            }
        }
        // keys `[marks]` adds: in the text's order (then as written)
        added.sort_by_key(|i| order.iter().position(|k| *k == i.key).unwrap_or(usize::MAX));
        items.extend(added);
        items.retain(|i| i.marks > 0);
        check_method(&items)?;
        Ok(Scheme { items })
    }
}

/// The field of a `[marks]` entry as errors name it: `marks."view.n"`.
fn field(name: &str) -> String {
    format!("marks.\"{name}\"")
}

/// The key `name` as a key of the results, or the error naming `field`.
fn known(field: &str, name: &str, result: &Results) -> Result<Key> {
    match answer_key(name) {
        Ok(k) if result.get(&k).is_some() => Ok(k),
        _ => Err(Error::why(field, ErrMsg::MarksNotAKey(name.to_string()))),
    }
}

/// A `[marks]` entry: a whole number of marks, or a table with `marks`
/// and `method` (working keys, each with its marks).
fn read_spec(name: &str, spec: &toml::Value, result: &Results) -> Result<(u32, Vec<(Key, u32)>)> {
    let at = field(name);
    match spec {
        toml::Value::Table(t) => {
            if let Some(other) = t
                .keys()
                .find(|k| !["marks", "method"].contains(&k.as_str()))
            {
                return Err(Error::why(
                    format!("{at}.{other}"),
                    ErrMsg::MarksUnknownField(other.clone()),
                ));
            }
            let marks = t
                .get("marks")
                .ok_or_else(|| Error::why(&at, ErrMsg::MarksMissing))?;
            let marks = whole(&format!("{at}.marks"), marks)?;
            let method = match t.get("method") {
                None => Vec::new(),
                Some(toml::Value::Table(m)) => (m.iter())
                    .map(|(k, v)| {
                        let f = format!("{at}.method.\"{k}\"");
                        Ok((known(&f, k, result)?, whole(&f, v)?))
                    })
                    .collect::<Result<_>>()?,
                Some(_) => {
                    return Err(Error::why(format!("{at}.method"), ErrMsg::MarksMethodTable))
                }
            };
            Ok((marks, method))
        }
        other => Ok((whole(&at, other)?, Vec::new())),
    }
}

/// A number of marks: a whole number from 0 to [`MAX_MARKS`].
fn whole(field: &str, v: &toml::Value) -> Result<u32> {
    match v {
        toml::Value::Integer(n) if (0..=i64::from(MAX_MARKS)).contains(n) => Ok(*n as u32),
        other => Err(Error::why(
            field,
            ErrMsg::MarksNotWhole(other.to_string(), MAX_MARKS),
        )),
    }
}

/// Each item's method marks add up to at most its own marks, and a method
/// key is working: not asked itself.
fn check_method(items: &[Item]) -> Result<()> {
    for i in items {
        let at = field(&i.key.to_string());
        let sum: u32 = i.method.iter().map(|(_, m)| m).sum();
        if sum > i.marks {
            return Err(Error::why(
                format!("{at}.method"),
                ErrMsg::MarksMethodOver(sum, i.marks),
            ));
        }
        if let Some((k, _)) = i
            .method
            .iter()
            .find(|(k, _)| items.iter().any(|j| j.key == *k))
        {
            return Err(Error::why(
                format!("{at}.method"),
                ErrMsg::MarksMethodAsked(k.to_string()),
            ));
        }
    }
    Ok(())
}

/// The marks one answer earns of `marks`: all for a right answer, half for
/// a too coarse one, none otherwise.
pub fn share(verdict: Verdict, marks: u32) -> f64 {
    verdict.points() * f64::from(marks)
}
