//! The form of a problem position: what every variant of that problem
//! asks alike. Drawn once per position from the exam's seed, before any
//! variant: the number of points of a camera problem, the lighting model,
//! the clipping case (the status, how many outcode bits each end has set,
//! how many intersections are tried and kept). Each variant then draws
//! only its numbers, within the form and the number class its difficulty
//! names ([`super::numbers::wanted`]), so the variants of a position are
//! parallel forms: the same keys, marks, case and class.

use super::{ClipCase, Difficulty, Topic};
use crate::num::rng::SplitMix64;
use crate::stages::clip::Status;
use crate::stages::lighting::Model;

/// What every variant of one problem position asks alike.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Form {
    /// The topic.
    pub topic: Topic,
    /// The difficulty: the number class of its variants.
    pub difficulty: Difficulty,
    /// A camera problem's points (none for the basis).
    pub points: usize,
    /// A lighting problem's model.
    pub model: Option<Model>,
    /// A clipping problem's case.
    pub clip: Option<ClipShape>,
}

/// A clipping case: the status, and the work that leads to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClipShape {
    /// The status every variant ends in.
    pub status: Status,
    /// How many bits of code0 and of code1 are set (how many planes each
    /// end lies beyond).
    pub bits: [u32; 2],
    /// How many intersections are tried (0 when the AND test decides).
    pub tried: u32,
    /// How many of them are kept (the ends of the clipped segment that
    /// are not P0 or P1).
    pub kept: u32,
}

impl ClipShape {
    /// The case of a status at a difficulty; `p0_outside_more`: whether
    /// P0 is the end beyond more planes (drawn per position).
    ///
    /// - clipped: easy, one end inside and the other beyond one plane (one
    ///   intersection, kept); medium, beyond two planes (two tried, one
    ///   kept); hard, both ends outside, beyond one and two planes (three
    ///   tried, two kept, the segment crossing the box);
    /// - accepted: both ends inside;
    /// - rejected by the AND test: both ends beyond a common plane; easy
    ///   one plane each, medium one and two, hard two each.
    pub fn of(status: Status, diff: Difficulty, p0_outside_more: bool) -> ClipShape {
        let (bits, tried, kept) = match (status, diff) {
            (Status::Accepted, _) => ([0, 0], 0, 0),
            (Status::Clipped, Difficulty::Easy) => ([0, 1], 1, 1),
            (Status::Clipped, Difficulty::Medium) => ([0, 2], 2, 1),
            (Status::Clipped, Difficulty::Hard) => ([1, 2], 3, 2),
            (Status::Rejected, Difficulty::Easy) => ([1, 1], 0, 0),
            (Status::Rejected, Difficulty::Medium) => ([1, 2], 0, 0),
            (Status::Rejected, Difficulty::Hard) => ([2, 2], 0, 0),
        };
        let bits = if p0_outside_more {
            [bits[1], bits[0]]
        } else {
            bits
        };
        ClipShape {
            status,
            bits,
            tried,
            kept,
        }
    }
}

/// The form of the problem at `position` (0-based) of an exam on `topic`,
/// drawn from `seed`; `clip_k`: the position's index among the exam's
/// clipping problems (for `--clip mixed`).
pub fn form(
    topic: Topic,
    diff: Difficulty,
    case: ClipCase,
    (position, clip_k): (usize, usize),
    seed: u64,
) -> Form {
    let mut rng = SplitMix64::fork(seed, 0x464f_524d_0000_0000 | position as u64); // "FORM"
    let points = match topic {
        Topic::Basis | Topic::Window | Topic::Clip | Topic::Shade => 0,
        Topic::Pipeline => 3,
        Topic::View | Topic::Project => 2 + rng.below(2) as usize,
    };
    let model = (topic == Topic::Shade).then(|| {
        // hard: a Lambert colour ka + kd·cos α has one radicand at most
        // (cos α = N·L/(|N||L|)), so hard asks a model with a specular term
        let models: &[Model] = match diff {
            Difficulty::Easy => &[Model::Phong, Model::Lambert],
            Difficulty::Medium => &[Model::Phong, Model::Lambert, Model::Blinn],
            Difficulty::Hard => &[Model::Phong, Model::Blinn],
        };
        *rng.pick(models)
    });
    let clip = (topic == Topic::Clip).then(|| {
        let status = match case {
            ClipCase::Clipped => Status::Clipped,
            ClipCase::Accepted => Status::Accepted,
            ClipCase::Rejected => Status::Rejected,
            ClipCase::Mixed => [Status::Clipped, Status::Accepted, Status::Rejected]
                [super::clip_order(seed)[clip_k % 3]],
        };
        ClipShape::of(status, diff, rng.coin())
    });
    Form {
        topic,
        difficulty: diff,
        points,
        model,
        clip,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn a_clipped_case_always_has_an_intersection_to_compute() {
        for diff in Difficulty::ALL {
            for more in [false, true] {
                let c = ClipShape::of(Status::Clipped, diff, more);
                assert!(c.tried >= 1 && c.kept >= 1, "{c:?}");
                // each plane an end lies beyond is tried
                assert_eq!(c.tried, c.bits[0] + c.bits[1]);
                let r = ClipShape::of(Status::Rejected, diff, more);
                assert_eq!(r.tried, 0);
                assert!(r.bits[0] >= 1 && r.bits[1] >= 1);
            }
        }
    }

    #[test]
    fn mixed_clipping_takes_each_status_once_in_three_positions() {
        for seed in 0..20 {
            let statuses: Vec<Status> = (0..3)
                .map(|k| {
                    let f = form(
                        Topic::Clip,
                        Difficulty::Medium,
                        ClipCase::Mixed,
                        (k, k),
                        seed,
                    );
                    f.clip.expect("a clipping form").status
                })
                .collect();
            for s in Status::iter() {
                assert!(statuses.contains(&s), "seed {seed}: {statuses:?}");
            }
        }
    }
}
