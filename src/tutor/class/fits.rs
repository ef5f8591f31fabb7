//! A sheet that fits another variant's key better than its own: answers
//! copied from a student of another variant, or a file that says the wrong
//! `variant = N`. Such a sheet scores near nothing against its own key
//! and says nothing about why; here it is marked again against every
//! other variant of its exam, problem by problem under the same names, and
//! when one gives it at least [`FITS_MARGIN`] of the marks more (as shares
//! of each variant's total), the sheet fits that variant's key.
//!
//! Only a sheet with at most 1 − [`FITS_MARGIN`] of its own marks can be
//! beaten by that margin, so only those are marked again: a class of good
//! sheets costs nothing more.

use super::{Markers, Paper, Sheet};
use crate::tutor::check::{self, Answers};

/// How much more of the marks (as a share of the total) another variant's
/// key must give a sheet before the sheet fits that key: half.
pub const FITS_MARGIN: f64 = 0.5;

/// Another variant whose key a sheet fits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fits {
    /// The variant (1-based).
    pub variant: usize,
    /// The share of the marks against that variant's key.
    pub there: f64,
    /// The share against the sheet's own variant's key.
    pub own: f64,
}

/// Sets `fits` on each marked sheet of an exam of several variants whose
/// answers fit another variant's key (the best such variant; the lowest
/// number among equals).
pub(super) fn mark_fits(paper: &Paper, markers: &Markers, sheets: &mut [Sheet]) {
    if !paper.exam || paper.variants.len() < 2 {
        return;
    }
    for s in sheets.iter_mut() {
        let (Some(own_v), Some(score), Some(total)) = (s.variant, s.score(), s.total()) else {
            continue;
        };
        let own = if total == 0 {
            1.0
        } else {
            score / f64::from(total)
        };
        if own > 1.0 - FITS_MARGIN + 1e-9 {
            continue;
        }
        let Ok((_, answers)) = check::read_answers(&s.file) else {
            continue;
        };
        let mut best: Option<Fits> = None;
        for v in (1..=paper.variants.len()).filter(|&v| v != own_v) {
            let Some(there) = share_against(paper, markers, &answers, v, &s.who) else {
                continue;
            };
            if there - own >= FITS_MARGIN - 1e-9 && best.is_none_or(|b| there > b.there) {
                best = Some(Fits {
                    variant: v,
                    there,
                    own,
                });
            }
        }
        s.fits = best;
    }
}

/// The share of the marks a file's answers earn against variant `v`'s
/// problems (each `[problem-NN]` table against that variant's problem of
/// the same name); None when a problem of `v` cannot be marked.
fn share_against(
    paper: &Paper,
    markers: &Markers,
    answers: &Answers,
    v: usize,
    who: &str,
) -> Option<f64> {
    let parts = super::split_as(paper, answers, v).ok()?;
    let (mut score, mut total) = (0.0, 0u32);
    for (marker, part) in markers[v - 1].iter().zip(&parts) {
        let m = marker.as_ref().ok()?.mark(who, part, false);
        score += m.score();
        total += m.total();
    }
    Some(if total == 0 {
        1.0
    } else {
        score / f64::from(total)
    })
}
