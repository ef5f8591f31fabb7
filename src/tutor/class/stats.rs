//! The lecturer's statistics of a class, from the same markings as the
//! students' rows: per answer key, per catalog mistake, the wrong answers no
//! mistake explains, the score distribution, and for an exam per problem
//! and per variant.
//!
//! Definitions (N students marked; the keys are those the marking scheme
//! asks, [`crate::tutor::check::scheme`]; a key's mark x is the share of
//! its m marks earned: 1 for a correct answer, ½ too coarse, 0 otherwise,
//! or its method marks' share; a student's score S is the marks earned of
//! the total T, taken as the share S/T, and the rest of the score as
//! (S − x·m)/(T − m): for a class that answers one problem, all with the
//! same T, these order and correlate exactly as S and S − x·m do, and the
//! variants of an exam, of different totals, compare):
//!
//! - **facility** p = mean of x over the N students: the share of full
//!   marks (Moodle's facility index). Flagged very easy above 0.9, very
//!   hard below 0.2.
//! - **discrimination** D = x̄(upper) − x̄(lower), Kelley's upper-minus-lower
//!   index: the upper group is the g = round(0.27·N) (at least 1) students
//!   of highest S, the lower group the g of lowest S; students tied at a
//!   group's edge share its remaining places equally (each counts with
//!   weight places/tied), so no order among equal scores is invented.
//!   D runs from −1 to 1.
//! - **point-biserial** r = the Pearson correlation of x with the rest of
//!   the score, S − x (the corrected item-total correlation), over the N
//!   students; undefined (None) when x or S − x is the same for everyone.
//! - a key **discriminates negatively** (suspect: the key, or the
//!   question) when D or r is below 0.
//!
//! In an exam every student answers one variant; a key (`problem-01.view.n`)
//! is counted over the students whose variant asks it, S is the student's
//! whole exam, and a variant is flagged harder (or easier) on a problem than
//! the rest of the class only with enough students to tell
//! ([`compare`]: at least 5 students on it and in the rest, a
//! two-proportion z-test of its facility against the rest's, p < 0.05
//! after Holm's correction over the problem's variants).

use super::{Class, ClassKey, Paper, Sheet};
use crate::msg::Msg;
use crate::num::Real;
use crate::stages::trace::{Step, Val};
use crate::tutor::check::{Marked, Settings, Verdict};
use crate::tutor::diagnose::Code;
use crate::tutor::key::Key;
use crate::tutor::keys::ordered_keys;
use crate::tutor::solve;

pub mod compare;
pub mod made;
mod wrong;

/// Above this facility a key is very easy.
pub const VERY_EASY: f64 = 0.9;
/// Below this facility a key is very hard.
pub const VERY_HARD: f64 = 0.2;
/// The share of the class in each of the upper and lower groups.
pub const GROUP_SHARE: f64 = 0.27;
/// The number of bins of the score histogram (10 % of the marks each).
pub const BINS: usize = 10;

/// What is suspect about a key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Flag {
    /// Facility above [`VERY_EASY`].
    VeryEasy,
    /// Facility below [`VERY_HARD`].
    VeryHard,
    /// D or r below 0: the better students do worse on it.
    Negative,
}

/// One answer key over the class.
#[derive(Clone, Debug)]
pub struct KeyStats {
    /// The key (`view.n`; `problem-01.view.n` in an exam).
    pub key: ClassKey,
    /// How many students were asked it.
    pub students: usize,
    /// How many answers got each verdict, in the order of [`Verdict::ALL`].
    pub counts: Vec<(Verdict, usize)>,
    /// Facility p.
    pub facility: f64,
    /// Upper-minus-lower discrimination D (None for fewer than 2 students).
    pub discrimination: Option<f64>,
    /// Point-biserial r of the key with the rest of the score.
    pub point_biserial: Option<f64>,
    /// Very easy, very hard, negative.
    pub flags: Vec<Flag>,
}

impl KeyStats {
    /// How many answers got the verdict `v` (0 when none did).
    pub fn count(&self, v: Verdict) -> usize {
        (self.counts.iter())
            .find(|(c, _)| *c == v)
            .map_or(0, |(_, n)| *n)
    }
}

/// The step of the worked solution a mistake belongs to.
#[derive(Clone, Debug)]
pub struct StepRef {
    /// The problem (`problem-01`; empty for a lone problem).
    pub part: String,
    /// The step's number in `grafika solve`'s output.
    pub number: usize,
    /// Its title.
    pub title: Msg,
}

/// One catalog mistake made in the class.
#[derive(Clone, Debug)]
pub struct MistakeStats {
    /// The mistake.
    pub mistake: Code,
    /// The students who made it, in file order.
    pub students: Vec<String>,
    /// The keys it explains, in the solution's order.
    pub keys: Vec<ClassKey>,
    /// Other mistakes that give the same values for some of these answers.
    pub also: Vec<Code>,
    /// The step where it is made ([`made`]; else the step of its first key).
    pub step: Option<StepRef>,
}

/// A wrong value no mistake explains, with the students who gave it (values
/// equal within the tolerance counted as one).
#[derive(Clone, Debug)]
pub struct WrongValue {
    /// The value as the first student wrote it.
    pub value: String,
    /// The same as marking read it ([`Marked::read`]), as a value: what
    /// the class's other answers are set beside (None when it could not be
    /// read, and then its text is).
    pub read: Option<Val>,
    /// The students who gave it.
    pub students: Vec<String>,
}

/// The unexplained wrong answers to one key (of one variant, in an exam).
#[derive(Clone, Debug)]
pub struct WrongAnswers {
    /// The key.
    pub key: ClassKey,
    /// The variant, in an exam of several.
    pub variant: Option<usize>,
    /// The right value.
    pub expected: Option<Val>,
    /// The values, the most common first.
    pub values: Vec<WrongValue>,
}

/// One bar of the histogram: the students whose score is at least `from`
/// and below `to` percent of the marks (the last bar includes 100).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Bin {
    /// From, in percent.
    pub from: u32,
    /// To, in percent.
    pub to: u32,
    /// Students.
    pub count: usize,
}

/// One problem of the paper over the class.
#[derive(Clone, Debug)]
pub struct ProblemStats {
    /// `problem-01` (empty for a lone problem).
    pub name: String,
    /// Its title (the first variant's).
    pub title: String,
    /// The students marked on it.
    pub students: usize,
    /// The mean share of its marks.
    pub facility: Option<f64>,
}

/// A variant's facility on a problem set against the rest of the class's
/// ([`compare`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Gap {
    /// Significantly below the rest of the class.
    Harder,
    /// Significantly above it.
    Easier,
}

/// One problem of one variant: its facility over the variant's students
/// and the comparison with the rest of the class.
#[derive(Clone, Debug)]
pub struct VariantProblem {
    /// `problem-01`.
    pub problem: String,
    /// The mean share of the problem's marks over the variant's students.
    pub facility: Option<f64>,
    /// The Holm-corrected p-value of the test against the rest of the
    /// class, when the variant was compared (enough students on both sides).
    pub p_value: Option<f64>,
    /// Harder or easier, when the corrected p is below [`compare::LEVEL`].
    pub gap: Option<Gap>,
}

/// One variant of an exam over the students who answered it.
#[derive(Clone, Debug)]
pub struct VariantStats {
    /// The variant (1-based).
    pub variant: usize,
    /// Its students.
    pub students: usize,
    /// The mean share of the whole exam's marks.
    pub facility: Option<f64>,
    /// Per problem: the facility and the comparison with the rest.
    pub problems: Vec<VariantProblem>,
}

/// The whole class.
#[derive(Clone, Debug)]
pub struct Stats {
    /// The students marked (a file that could not be marked is not counted).
    pub students: usize,
    /// Per key, in the solution's order.
    pub keys: Vec<KeyStats>,
    /// Per mistake, the most students first.
    pub mistakes: Vec<MistakeStats>,
    /// Per key, the wrong answers no mistake explains.
    pub wrong_answers: Vec<WrongAnswers>,
    /// The score distribution in [`BINS`] bars of 10 %.
    pub histogram: Vec<Bin>,
    /// Per problem (one for a lone problem).
    pub problems: Vec<ProblemStats>,
    /// Per variant (an exam of several variants only).
    pub variants: Vec<VariantStats>,
    /// Whether each problem's variant was drawn by itself (a Moodle quiz's
    /// random slots, [`Sheet::drawn`]).
    pub drawn: bool,
}

/// One problem of one variant solved once: its keys in the solution's order
/// and its steps.
struct Solved {
    order: Vec<Key>,
    steps: Vec<Step>,
}

/// The statistics of a marked class.
pub fn of(class: &Class, paper: &Paper, settings: &Settings) -> Stats {
    let solved: Vec<Vec<Solved>> = paper
        .variants
        .iter()
        .map(|parts| parts.iter().map(|p| solved(&p.problem)).collect())
        .collect();
    let sheets: Vec<&Sheet> = class.marked().collect();
    let keys = key_order(paper, &solved, &sheets);
    Stats {
        students: sheets.len(),
        keys: keys.iter().map(|k| key_stats(k, &sheets)).collect(),
        mistakes: wrong::mistakes(&sheets, &keys, paper, &solved),
        wrong_answers: wrong::wrong_answers(&sheets, &keys, paper, settings),
        histogram: histogram(&sheets),
        problems: problems(paper, &sheets),
        variants: variants(paper, &sheets),
        drawn: sheets.iter().any(|s| !s.drawn.is_empty()),
    }
}

fn solved(p: &crate::input::problem::ProblemIn) -> Solved {
    match solve::solve::<Real>(p) {
        Ok(r) => Solved {
            order: ordered_keys(&r.result),
            steps: r.steps,
        },
        Err(_) => Solved {
            order: vec![],
            steps: vec![],
        },
    }
}

/// Every key marked in the class, problem by problem, in the solution's
/// order (keys the solution does not list, in the order first marked).
fn key_order(paper: &Paper, solved: &[Vec<Solved>], sheets: &[&Sheet]) -> Vec<ClassKey> {
    let mut seen: Vec<ClassKey> = Vec::new();
    for (i, part) in paper.variants[0].iter().enumerate() {
        let mut marked: Vec<Key> = Vec::new();
        for s in sheets {
            for m in parts_named(s, &part.name) {
                // the keys the scheme asks: working is never counted
                for a in m.asked() {
                    if !marked.contains(&a.key) {
                        marked.push(a.key.clone());
                    }
                }
            }
        }
        let order: Vec<&Key> = solved
            .iter()
            .filter_map(|v| v.get(i))
            .flat_map(|s| &s.order)
            .collect();
        // a key no solution lists (a component, a whole part) comes after
        // them, in the order first marked
        let rank = |k: &Key| (order.iter()).position(|o| *o == k).unwrap_or(usize::MAX);
        let mut ranked: Vec<(usize, usize, Key)> = marked
            .into_iter()
            .enumerate()
            .map(|(first, k)| (rank(&k), first, k))
            .collect();
        ranked.sort_by_key(|(rank, first, _)| (*rank, *first));
        for (_, _, key) in ranked {
            let full = ClassKey {
                problem: paper.problem(i),
                key,
            };
            if !seen.contains(&full) {
                seen.push(full);
            }
        }
    }
    seen
}

/// The markings of a sheet's part of this name.
fn parts_named<'a>(
    s: &'a Sheet,
    name: &'a str,
) -> impl Iterator<Item = &'a crate::tutor::check::Marking> {
    s.outcome
        .iter()
        .flatten()
        .filter(move |(n, _)| n == name)
        .map(|(_, m)| m)
}

/// A sheet's marked answer to a class key (the markings of a sheet are
/// its paper's problems in order).
fn answer<'a>(s: &'a Sheet, key: &ClassKey) -> Option<&'a Marked> {
    let (_, m) = s.outcome.as_ref().ok()?.get(key.problem.unwrap_or(0))?;
    m.answers.iter().find(|a| a.key == key.key)
}

/// Counts, facility, D and r of one key.
fn key_stats(key: &ClassKey, sheets: &[&Sheet]) -> KeyStats {
    let asked: Vec<(&Marked, f64, f64)> = sheets
        .iter()
        .filter_map(|s| Some((answer(s, key)?, s.score()?, f64::from(s.total()?))))
        .filter(|(a, _, _)| a.asked())
        .collect();
    let counts: Vec<(Verdict, usize)> = (Verdict::ALL.into_iter())
        .map(|v| (v, asked.iter().filter(|(a, _, _)| a.verdict == v).count()))
        .collect();
    // the key's mark x: the share of its marks earned
    let worth = |a: &Marked| f64::from(a.worth.unwrap_or(0));
    let x: Vec<f64> = (asked.iter())
        .map(|(a, _, _)| a.earned / worth(a).max(1.0))
        .collect();
    // shares of each student's own marks, so variants of different lengths compare
    let share = |points: f64, of: f64| if of <= 0.0 { 0.0 } else { points / of };
    let score: Vec<f64> = asked.iter().map(|(_, s, t)| share(*s, *t)).collect();
    let rest: Vec<f64> = (asked.iter())
        .map(|(a, s, t)| share(s - a.earned, t - worth(a)))
        .collect();
    let facility = mean(&x).unwrap_or(0.0);
    let discrimination = upper_minus_lower(&x, &score);
    let point_biserial = correlation(&x, &rest);
    let mut flags = Vec::new();
    if !asked.is_empty() && facility > VERY_EASY {
        flags.push(Flag::VeryEasy);
    }
    if !asked.is_empty() && facility < VERY_HARD {
        flags.push(Flag::VeryHard);
    }
    if discrimination.is_some_and(|d| d < -1e-9) || point_biserial.is_some_and(|r| r < -1e-9) {
        flags.push(Flag::Negative);
    }
    KeyStats {
        key: key.clone(),
        students: asked.len(),
        counts,
        facility,
        discrimination,
        point_biserial,
        flags,
    }
}

fn mean(x: &[f64]) -> Option<f64> {
    (!x.is_empty()).then(|| x.iter().sum::<f64>() / x.len() as f64)
}

/// D = x̄(upper 27 %) − x̄(lower 27 %) by total score, ties at a group's
/// edge sharing its places (see the module docs).
pub fn upper_minus_lower(x: &[f64], total: &[f64]) -> Option<f64> {
    let n = x.len();
    if n < 2 {
        return None;
    }
    let g = (GROUP_SHARE * n as f64).round().max(1.0);
    let upper = group_weights(total, g, true);
    let lower = group_weights(total, g, false);
    let sum = |w: &[f64]| w.iter().zip(x).map(|(w, x)| w * x).sum::<f64>();
    Some((sum(&upper) - sum(&lower)) / g)
}

/// The weight of each student in the group of the g highest (or lowest)
/// totals: 1 inside, places/tied for the students tied at the edge, 0 out.
fn group_weights(total: &[f64], g: f64, highest: bool) -> Vec<f64> {
    let mut order: Vec<usize> = (0..total.len()).collect();
    order.sort_by(|&a, &b| {
        let o = total[a].total_cmp(&total[b]);
        if highest {
            o.reverse()
        } else {
            o
        }
    });
    let mut w = vec![0.0; total.len()];
    let (mut left, mut i) = (g, 0);
    while i < order.len() && left > 1e-12 {
        let tied = order[i..]
            .iter()
            .take_while(|&&j| total[j] == total[order[i]])
            .count();
        let share = (left / tied as f64).min(1.0);
        for &j in &order[i..i + tied] {
            w[j] = share;
        }
        left -= share * tied as f64;
        i += tied;
    }
    w
}

/// Pearson's correlation of x and y (None when either is constant).
pub fn correlation(x: &[f64], y: &[f64]) -> Option<f64> {
    let (mx, my) = (mean(x)?, mean(y)?);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    let syy: f64 = y.iter().map(|b| (b - my).powi(2)).sum();
    (sxx > 1e-12 && syy > 1e-12).then(|| sxy / (sxx * syy).sqrt())
}

/// The score distribution: [`BINS`] bars of 10 % of each student's marks.
fn histogram(sheets: &[&Sheet]) -> Vec<Bin> {
    let step = 100 / BINS as u32;
    let mut bins: Vec<Bin> = (0..BINS as u32)
        .map(|b| Bin {
            from: b * step,
            to: (b + 1) * step,
            count: 0,
        })
        .collect();
    for s in sheets {
        let (Some(score), Some(total)) = (s.score(), s.total()) else {
            continue;
        };
        // in halves, so the bar is found in whole numbers: ⌊10·S/T⌋
        let halves = (score * 2.0).round() as usize;
        let b = (halves * BINS)
            .checked_div(2 * total as usize)
            .unwrap_or(BINS);
        bins[b.min(BINS - 1)].count += 1;
    }
    bins
}

/// Per problem: the mean share of its marks over the class.
fn problems(paper: &Paper, sheets: &[&Sheet]) -> Vec<ProblemStats> {
    paper.variants[0]
        .iter()
        .map(|part| {
            let shares: Vec<f64> = sheets
                .iter()
                .flat_map(|s| parts_named(s, &part.name))
                .map(share)
                .collect();
            ProblemStats {
                name: part.name.clone(),
                title: part.problem.title.clone(),
                students: shares.len(),
                facility: mean(&shares),
            }
        })
        .collect()
}

fn share(m: &crate::tutor::check::Marking) -> f64 {
    m.fraction()
}

/// Per variant of an exam: its students, their facility on each problem,
/// and the problems where it is harder or easier than the rest of the
/// class by the test of [`compare`]. A problem's cell of variant v counts
/// the students who had that problem of variant v, also when the sheet's
/// problems were drawn from different variants ([`Sheet::drawn`]); the
/// whole exam's facility is then not one variant's, and is left out.
fn variants(paper: &Paper, sheets: &[&Sheet]) -> Vec<VariantStats> {
    let drawn = sheets.iter().any(|s| !s.drawn.is_empty());
    let count = match drawn {
        true => sheets
            .iter()
            .flat_map(|s| s.drawn.iter().copied())
            .max()
            .unwrap_or(1),
        false => paper.variants.len(),
    };
    if !paper.exam || count < 2 {
        return vec![];
    }
    let problems = paper.variants[0].len();
    let mut out: Vec<VariantStats> = (1..=count)
        .map(|v| {
            let had = |s: &&&Sheet| (0..problems).any(|p| s.variant_of(p) == Some(v));
            let whole: Vec<f64> = (sheets.iter().filter(had))
                .filter_map(|s| Some(s.score()? / f64::from(s.total()?.max(1))))
                .collect();
            VariantStats {
                variant: v,
                students: whole.len(),
                facility: mean(&whole).filter(|_| !drawn),
                problems: vec![],
            }
        })
        .collect();
    for (p, part) in paper.variants[0].iter().enumerate() {
        for (v, cell) in compared(p, &part.name, count, sheets)
            .into_iter()
            .enumerate()
        {
            out[v].problems.push(cell);
        }
    }
    out
}

/// One problem's cells of every variant: each variant's facility, and its
/// test against the rest of the class (the students of the other
/// variants), the p-values of the variants tested corrected together.
fn compared(p: usize, name: &str, count: usize, sheets: &[&Sheet]) -> Vec<VariantProblem> {
    // each student's share of the problem's marks, by variant
    let mut shares: Vec<Vec<f64>> = vec![vec![]; count];
    for s in sheets {
        let Some(v) = s.variant_of(p).filter(|v| (1..=count).contains(v)) else {
            continue;
        };
        shares[v - 1].extend(parts_named(s, name).map(share));
    }
    let all: usize = shares.iter().map(Vec::len).sum();
    let sum: f64 = shares.iter().flatten().sum();
    let tests: Vec<Option<f64>> = (shares.iter())
        .map(|x| {
            let (n, rest) = (x.len(), all - x.len());
            if n < compare::MIN_STUDENTS || rest < compare::MIN_STUDENTS {
                return None;
            }
            let own: f64 = x.iter().sum();
            let p_rest = (sum - own) / rest as f64;
            compare::two_proportion_p(own / n as f64, n, p_rest, rest)
        })
        .collect();
    let tested: Vec<f64> = tests.iter().flatten().copied().collect();
    let mut corrected = compare::holm(&tested).into_iter();
    (shares.iter().zip(&tests))
        .map(|(x, test)| {
            let facility = mean(x);
            let p_value = test.and_then(|_| corrected.next());
            let rest = (all - x.len()).max(1) as f64;
            let p_rest = (sum - x.iter().sum::<f64>()) / rest;
            let gap = match (facility, p_value) {
                (Some(f), Some(p)) if p < compare::LEVEL && f < p_rest => Some(Gap::Harder),
                (Some(_), Some(p)) if p < compare::LEVEL => Some(Gap::Easier),
                _ => None,
            };
            VariantProblem {
                problem: name.to_string(),
                facility,
                p_value,
                gap,
            }
        })
        .collect()
}

impl Stats {
    /// The fewest and the most students on one variant, when no variant
    /// has enough to be compared ([`compare::MIN_STUDENTS`]): then no
    /// variant is flagged, and the report says why.
    pub fn too_few_per_variant(&self) -> Option<(usize, usize)> {
        let n = self.variants.iter().map(|v| v.students);
        let (min, max) = (n.clone().min()?, n.max()?);
        (max < compare::MIN_STUDENTS).then_some((min, max))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn upper_minus_lower_shares_the_places_of_students_tied_at_the_edge() {
        // N = 10, g = round(2.7) = 3. Upper: the 9 (x = 1) and two places
        // shared by the three 8s (x = 1, 0, 0): (1 + ⅔·1)/3 = 5/9. Lower:
        // the two 2s (x = 0, 1) and the 3 (x = 0): 1/3. D = 5/9 − 1/3 = 2/9.
        let total = [9.0, 8.0, 8.0, 8.0, 5.0, 5.0, 4.0, 3.0, 2.0, 2.0];
        let x = [1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0];
        let d = upper_minus_lower(&x, &total).unwrap();
        assert!((d - 2.0 / 9.0).abs() < 1e-12, "{d}");
        // everyone tied: both groups are the whole class, D = 0
        let d = upper_minus_lower(&[1.0, 0.0, 1.0, 0.0], &[3.0; 4]).unwrap();
        assert!(d.abs() < 1e-12, "{d}");
        assert_eq!(upper_minus_lower(&[1.0], &[1.0]), None);
    }

    #[test]
    fn correlation_is_pearsons() {
        let x = [1.0, 0.0, 1.0, 0.0];
        assert!((correlation(&x, &x).unwrap() - 1.0).abs() < 1e-12);
        assert!((correlation(&x, &[0.0, 1.0, 0.0, 1.0]).unwrap() + 1.0).abs() < 1e-12);
        // x = (1, 0, 0), y = (2, 1, 0): Σ(x−x̄)(y−ȳ) = 1, Σ(x−x̄)² = 2/3,
        // Σ(y−ȳ)² = 2, so r = 1/√(4/3) = √3/2
        let r = correlation(&[1.0, 0.0, 0.0], &[2.0, 1.0, 0.0]).unwrap();
        assert!((r - 3f64.sqrt() / 2.0).abs() < 1e-12, "{r}");
        assert_eq!(correlation(&x, &[2.0; 4]), None);
    }
}
