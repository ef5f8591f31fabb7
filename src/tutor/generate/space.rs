//! Every problem a form can draw, numbered: a drawing is a function of
//! the digits of one index in a mixed-radix numbering (each choice a
//! digit, its radix the number of options, the same radices for every
//! index), so the space of a form has a known size, and the variants of a
//! position are its indices visited in an order drawn from the seed (a
//! keyed permutation). No index is visited twice, and when every index has
//! been visited the problems found are all the form has: `generate` can
//! say how many different variants a difficulty can make.

use crate::num::rng::SplitMix64;

/// The choices of one drawing: the digits of its index, least significant
/// first. A drawing must ask the same radices, in the same order, for
/// every index (no choice depends on an earlier one), so that the space's
/// size is the product of the radices.
#[derive(Clone, Debug)]
pub struct Digits {
    rest: u64,
    /// The product of the radices asked so far (saturating).
    size: u128,
}

impl Digits {
    /// The digits of `index`.
    pub fn of(index: u64) -> Digits {
        Digits {
            rest: index,
            size: 1,
        }
    }

    /// The next digit, in 0..n (n ≥ 1).
    pub fn below(&mut self, n: u64) -> u64 {
        let n = n.max(1);
        self.size = self.size.saturating_mul(n as u128);
        let d = self.rest % n;
        self.rest /= n;
        d
    }

    /// One of the items (not empty).
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }

    /// An integer in lo..=hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }

    /// A yes or no.
    pub fn coin(&mut self) -> bool {
        self.below(2) == 1
    }

    /// How many indices the radices asked so far number, at most
    /// [`MAX_SPACE`].
    pub fn size(&self) -> u64 {
        self.size.min(MAX_SPACE as u128) as u64
    }
}

/// The most indices a space numbers: a larger one is numbered only this
/// far (more than any exam visits).
pub const MAX_SPACE: u64 = 1 << 62;

/// A keyed permutation of 0..n: index i of the visit order is
/// `permuted(i, n, key)`. A four-round Feistel network on the smallest
/// even number of bits that holds n, walked until it lands below n
/// (cycle walking), so it is a bijection of 0..n; its round function is
/// SplitMix64 of the key, the round and the half.
pub fn permuted(i: u64, n: u64, key: u64) -> u64 {
    if n <= 1 {
        return 0;
    }
    let bits = (64 - (n - 1).leading_zeros()).max(2);
    let half = bits.div_ceil(2);
    let mask = (1u64 << half) - 1;
    let mut x = i;
    loop {
        let (mut l, mut r) = (x >> half, x & mask);
        for round in 0..4u64 {
            let f = SplitMix64::fork(key ^ round.wrapping_mul(0x9e37_79b9), r).next_u64() & mask;
            (l, r) = (r, l ^ f);
        }
        x = (l << half) | r;
        if x < n {
            return x;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_permutation_visits_every_index_once() {
        for n in [1u64, 2, 3, 7, 20, 100, 257, 1000] {
            for key in [0u64, 1, 4242] {
                let mut seen: Vec<u64> = (0..n).map(|i| permuted(i, n, key)).collect();
                seen.sort();
                assert_eq!(seen, (0..n).collect::<Vec<_>>(), "n {n} key {key}");
            }
        }
        // the keys give different orders
        let a: Vec<u64> = (0..20).map(|i| permuted(i, 100, 1)).collect();
        let b: Vec<u64> = (0..20).map(|i| permuted(i, 100, 2)).collect();
        assert_ne!(a, b);
    }

    #[test]
    fn digits_number_a_mixed_radix_space() {
        // radices 3, 2, 4: index 0..24 reads every triple once
        let mut seen = std::collections::BTreeSet::new();
        for i in 0..24 {
            let mut d = Digits::of(i);
            let t = (d.below(3), d.below(2), d.below(4));
            assert_eq!(d.size(), 24);
            seen.insert(t);
        }
        assert_eq!(seen.len(), 24);
        // 8 mod 5 = 3: the fourth of −2, −1, 0, 1, 2
        assert_eq!(Digits::of(8).range(-2, 2), 1);
    }
}
