//! The random numbers behind `grafika generate`: SplitMix64 (Steele, Lea and
//! Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014; the
//! `splitmix64.c` reference by S. Vigna), written out here so that a seed gives
//! the same exam on every platform and in every future version of grafika.
//! The algorithm and the derived helpers below are fixed: changing any of
//! them changes every generated exam, so do not.
//!
//! One step: `state += 0x9e3779b97f4a7c15`, then the output is `state`
//! mixed by `z = (z ^ z>>30)·0xbf58476d1ce4e5b9`, `z = (z ^ z>>27)·0x94d049bb133111eb`,
//! `z ^ z>>31` (wrapping arithmetic mod 2⁶⁴).

/// A SplitMix64 generator.
#[derive(Clone, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// A generator whose first output is the reference output for `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64 { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in 0..n (n > 0): the high 64 bits of `next_u64() · n`
    /// (Lemire's multiply-shift; the bias is below n/2⁶⁴, invisible here).
    pub fn below(&mut self, n: u64) -> u64 {
        ((self.next_u64() as u128 * n.max(1) as u128) >> 64) as u64
    }

    /// An integer in lo..=hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }

    /// One of the items (the slice must not be empty).
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len() as u64) as usize]
    }

    /// True with probability 1/2.
    pub fn coin(&mut self) -> bool {
        self.next_u64() >> 63 == 1
    }

    /// An independent generator for the `k`-th part (a problem, a variant):
    /// seeded by mixing `k` into this generator's seed, so part k does not
    /// depend on how many numbers the other parts drew.
    pub fn fork(seed: u64, k: u64) -> SplitMix64 {
        let mut g = SplitMix64::new(seed ^ k.wrapping_mul(0xd1b5_4a32_d192_ed03));
        SplitMix64::new(g.next_u64())
    }
}

/// The six orderings of three things (the permutations of 0, 1, 2).
pub const PERMUTATIONS_OF_3: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_outputs_of_splitmix64() {
        // The published outputs of splitmix64.c for seed 0 (also those of
        // java.util.SplittableRandom's mixer on the golden-gamma sequence).
        let mut g = SplitMix64::new(0);
        assert_eq!(g.next_u64(), 0xe220_a839_7b1d_cdaf);
        assert_eq!(g.next_u64(), 0x6e78_9e6a_a1b9_65f4);
        assert_eq!(g.next_u64(), 0x06c4_5d18_8009_454f);
    }

    #[test]
    fn ranges_stay_in_range_and_cover_it() {
        let mut g = SplitMix64::new(7);
        let mut seen = [false; 5];
        for _ in 0..200 {
            let x = g.range(-2, 2);
            assert!((-2..=2).contains(&x));
            seen[(x + 2) as usize] = true;
        }
        assert!(seen.iter().all(|&s| s));
    }
}
