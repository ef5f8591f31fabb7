//! The verdict on one answer: one type for the judge, the marks, the
//! reports and the class statistics. Each verdict has its stable code
//! ([`Verdict::name`], for autograders) and its word ([`Verdict::word`]:
//! the four ways of being correct share `correct`).

/// The verdict on one answer, with how it was judged.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Verdict {
    /// Right: equal to the exact value (any equivalent form).
    Exact,
    /// Right: the exact value rounded to the digits written.
    Rounded,
    /// Right: within the tolerance.
    Tolerance,
    /// Right given the student's own earlier answers (follow-through).
    FollowThrough,
    /// Right, but rounded to fewer significant figures than required.
    TooCoarse,
    /// Not the expected value.
    Wrong,
    /// Not answered.
    Missing,
    /// Could not be read as a number (or a list of them).
    Unparseable,
}

impl Verdict {
    /// Every verdict, in the order reports list them (docs/spec.md §5); a
    /// verdict added later goes last (§5: its column after `unparseable`).
    pub const ALL: [Verdict; 8] = [
        Verdict::Exact,
        Verdict::Rounded,
        Verdict::Tolerance,
        Verdict::FollowThrough,
        Verdict::TooCoarse,
        Verdict::Wrong,
        Verdict::Missing,
        Verdict::Unparseable,
    ];

    /// The stable code in output and JSON (`correct.exact`).
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Exact => "correct.exact",
            Verdict::Rounded => "correct.rounded",
            Verdict::Tolerance => "correct.tolerance",
            Verdict::FollowThrough => "correct.follow_through",
            Verdict::TooCoarse => "too_coarse",
            Verdict::Wrong => "wrong",
            Verdict::Missing => "missing",
            Verdict::Unparseable => "unparseable",
        }
    }

    /// The verdict's word in output and JSON: `correct` for every way of
    /// being right, else its code.
    pub fn word(self) -> &'static str {
        match self {
            Verdict::Exact | Verdict::Rounded | Verdict::Tolerance | Verdict::FollowThrough => {
                "correct"
            }
            Verdict::TooCoarse | Verdict::Wrong | Verdict::Missing | Verdict::Unparseable => {
                self.name()
            }
        }
    }

    /// Whether the answer is right (follow-through included).
    pub fn is_correct(self) -> bool {
        matches!(
            self,
            Verdict::Exact | Verdict::Rounded | Verdict::Tolerance | Verdict::FollowThrough
        )
    }

    /// Whether the answer agrees with grafika's value itself: correct (not
    /// by follow-through) or too coarse.
    pub fn agrees(self) -> bool {
        matches!(
            self,
            Verdict::Exact | Verdict::Rounded | Verdict::Tolerance | Verdict::TooCoarse
        )
    }

    /// Whether two verdicts have the same word (both correct, or equal).
    pub fn alike(self, other: Verdict) -> bool {
        self == other || (self.is_correct() && other.is_correct())
    }

    /// The verdicts a score line and a class's columns count, one per
    /// word, each the first of [`Verdict::ALL`] with it: `Exact` for every
    /// correct one, then too coarse, wrong, missing, unparseable.
    pub fn words() -> Vec<Verdict> {
        let mut out: Vec<Verdict> = Vec::new();
        for v in Verdict::ALL {
            if !out.iter().any(|u| u.alike(v)) {
                out.push(v);
            }
        }
        out
    }

    /// Marks for the verdict: 1 correct, ½ too coarse, 0 otherwise.
    pub fn points(self) -> f64 {
        match self {
            Verdict::Exact | Verdict::Rounded | Verdict::Tolerance | Verdict::FollowThrough => 1.0,
            Verdict::TooCoarse => 0.5,
            Verdict::Wrong | Verdict::Missing | Verdict::Unparseable => 0.0,
        }
    }

    /// How bad the verdict is, so a list takes its worst component's: a
    /// correct one by how loosely (exact, within the tolerance, rounded),
    /// then too coarse, unparseable, wrong, missing.
    pub(crate) fn badness(self) -> u8 {
        match self {
            Verdict::Exact => 0,
            Verdict::Tolerance => 1,
            Verdict::Rounded => 2,
            Verdict::FollowThrough => 3,
            Verdict::TooCoarse => 4,
            Verdict::Unparseable => 5,
            Verdict::Wrong => 6,
            Verdict::Missing => 7,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Verdict;

    /// Every verdict is listed once and spells a code of its own; the
    /// words are those of docs/spec.md §5's columns, in their order.
    #[test]
    fn every_verdict_has_its_own_code_and_the_words_are_the_columns() {
        let names: Vec<&str> = Verdict::ALL.iter().map(|v| v.name()).collect();
        let mut unique = names.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), names.len(), "{names:?}");
        let words: Vec<&str> = Verdict::words().iter().map(|v| v.word()).collect();
        assert_eq!(
            words,
            ["correct", "too_coarse", "wrong", "missing", "unparseable"]
        );
        for v in Verdict::ALL {
            assert_eq!(v.name().starts_with("correct."), v.is_correct(), "{v:?}");
            assert_eq!(v.points() == 1.0, v.is_correct(), "{v:?}");
        }
    }
}
