//! The blueprint of a drawn exam: per problem position, what its variants
//! ask alike and how far they differ, measured from the variants
//! themselves (not read back from the form they were drawn to): the case
//! (the form: points, lighting model, clipping case), the number class of
//! each part ([`numbers::classes`]), the marks ([`Generated::scheme`]), how
//! many statements are distinct, and the range of each answer's numbers.
//! A lecturer reads from it that the variants are one exam.

use super::numbers::{self, for_each_num, NumberClass};
use super::{Exams, Form, Generated};
use crate::tutor::key::{Key, Part};
use std::collections::HashSet;

/// The blueprint of an exam: one entry per problem position.
#[derive(Clone, Debug, PartialEq)]
pub struct Blueprint {
    /// How many variants were drawn.
    pub variants: usize,
    /// Each position, in order.
    pub positions: Vec<Position>,
}

/// One problem position across its variants.
#[derive(Clone, Debug, PartialEq)]
pub struct Position {
    /// The form every variant was drawn to.
    pub form: Form,
    /// The keys asked (the first variant's), with their marks.
    pub keys: Vec<(Key, u32)>,
    /// Whether every variant asks the same keys with the same marks.
    pub same_marks: bool,
    /// The number class of each part asked (the first variant's).
    pub classes: Vec<(Part, NumberClass)>,
    /// How many variants have those classes.
    pub same_class: usize,
    /// How many different statements the variants have.
    pub distinct: usize,
    /// Per key asked: the least and greatest number in it over the
    /// variants (none for a key of words, such as a status).
    pub spread: Vec<(Key, Option<(f64, f64)>)>,
}

impl Position {
    /// The marks of one variant of the position.
    pub fn marks(&self) -> u32 {
        self.keys.iter().map(|(_, m)| m).sum()
    }
}

impl Blueprint {
    /// The marks of one variant of the whole exam.
    pub fn total(&self) -> u32 {
        self.positions.iter().map(Position::marks).sum()
    }
}

/// The blueprint of a drawn exam.
pub fn blueprint(exams: &Exams) -> Blueprint {
    let positions = (exams.forms.iter().enumerate())
        .map(|(i, form)| {
            let column: Vec<&Generated> = exams.variants.iter().filter_map(|v| v.get(i)).collect();
            position(*form, &column)
        })
        .collect();
    Blueprint {
        variants: exams.variants.len(),
        positions,
    }
}

/// The marks of each key a variant asks.
fn marks_of(g: &Generated) -> Vec<(Key, u32)> {
    (g.keys.iter())
        .map(|k| (k.clone(), g.scheme.item(k).map_or(0, |i| i.marks)))
        .collect()
}

/// One position from its variants (at least one).
fn position(form: Form, column: &[&Generated]) -> Position {
    let classes_of = |g: &Generated| numbers::classes(&g.report.result, &g.keys);
    let keys = column.first().map(|g| marks_of(g)).unwrap_or_default();
    let classes = column.first().map(|g| classes_of(g)).unwrap_or_default();
    let statements: HashSet<&str> = column.iter().map(|g| g.body.as_str()).collect();
    Position {
        same_marks: column.iter().all(|g| marks_of(g) == keys),
        same_class: column.iter().filter(|g| classes_of(g) == classes).count(),
        distinct: statements.len(),
        spread: keys
            .iter()
            .map(|(k, _)| (k.clone(), range(column, k)))
            .collect(),
        form,
        keys,
        classes,
    }
}

/// The least and greatest number of `key` over the variants.
fn range(column: &[&Generated], key: &Key) -> Option<(f64, f64)> {
    let mut span: Option<(f64, f64)> = None;
    for v in column.iter().filter_map(|g| g.report.result.get(key)) {
        for_each_num(&v, &mut |n| {
            let (lo, hi) = span.unwrap_or((n.value, n.value));
            span = Some((lo.min(n.value), hi.max(n.value)));
        });
    }
    span
}
