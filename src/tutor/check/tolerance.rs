//! The one tolerance rule, shared by `check`, `practice` and the quiz
//! exports (Moodle XML, GIFT), so a number is marked the same everywhere.
//!
//! A number x of an answer is within tolerance when it lies within the
//! absolute tolerance t of x, where, from the relative tolerance r
//! (`--tolerance`, 0.1 % by default):
//!
//! - t = r·|x| for x ≠ 0;
//! - t = r·m for x = 0, with m the largest magnitude in the same answer (the
//!   other components of the vector, point or matrix), or t = r when the
//!   whole answer is zero; so t is never 0;
//! - a pixel position (a key of the viewport part: `viewport.pixels.A`,
//!   one of its components, all the pixels, the whole part; a calculator's
//!   `pixels.A`) takes at least t = 0.5 px: a whole pixel within half a
//!   pixel names the same pixel.

use crate::stages::trace::Val;
use crate::tutor::key::{Key, Part, Value};

/// The least tolerance of a pixel position, in pixels.
pub const PIXEL: f64 = 0.5;

/// The absolute tolerance of x in an answer whose largest magnitude is
/// `scale`: r·|x|, or r·scale for x = 0, or r when the answer is all zero.
pub fn absolute(x: f64, scale: f64, rel: f64) -> f64 {
    if x != 0.0 {
        rel * x.abs()
    } else if scale > 0.0 {
        rel * scale
    } else {
        rel
    }
}

/// Whether an answer key is a pixel position (`viewport.pixels.A`): an
/// exhaustive match, so a new kind of value is decided as soon as it
/// compiles, and a new field of the viewport part is a pixel position.
pub fn is_pixel(key: &Key) -> bool {
    match &key.value {
        Value::Pixel(_) => true,
        Value::Field(f) => f.in_part(Part::Viewport),
        Value::Whole => key.part == Some(Part::Viewport),
        Value::Point(_)
        | Value::Plane(_)
        | Value::Cut(..)
        | Value::Light(_)
        | Value::Factor(..) => false,
    }
}

/// The absolute tolerance of x in the answer `key` whose largest magnitude
/// is `scale` ([`absolute`], at least [`PIXEL`] for a pixel position).
pub fn for_key(key: &Key, x: f64, scale: f64, rel: f64) -> f64 {
    let t = absolute(x, scale, rel);
    if is_pixel(key) {
        t.max(PIXEL)
    } else {
        t
    }
}

/// The scale of an answer: the largest magnitude among its finite numbers
/// (in its lists and maps; 0 when it has none), by which a zero takes its
/// tolerance ([`absolute`]).
pub fn scale(v: &Val) -> f64 {
    match v {
        Val::Num(s) if s.value.is_finite() => s.value.abs(),
        Val::List(items) => items.iter().map(scale).fold(0.0, f64::max),
        Val::Map(kv) => kv.iter().map(|(_, x)| scale(x)).fold(0.0, f64::max),
        _ => 0.0,
    }
}

/// The numbers of an answer `v` (a number, a vector's, a matrix's, depth
/// first), each with its absolute tolerance in the answer `key` at
/// relative tolerance `rel` ([`for_key`] by the answer's [`scale`]).
pub fn numbers(key: &Key, v: &Val, rel: f64) -> Vec<(f64, f64)> {
    let sc = scale(v);
    let within = |x: f64| (x, for_key(key, x, sc, rel));
    v.numbers().into_iter().map(within).collect()
}

/// Whether two numbers, each with its absolute tolerance, can be told
/// apart: their tolerance intervals [x − t, x + t] do not meet.
pub fn apart(x: f64, tx: f64, y: f64, ty: f64) -> bool {
    (x - y).abs() > tx + ty
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-15
    }

    /// One walk for every user: (0, 4, −3) at 0.1 % has scale 4, so its
    /// zero takes 0.004 and its others 0.1 % of themselves (0.004, 0.003);
    /// a number that is not finite sets no scale (a mistaken tan 90° does
    /// not make every zero of its answer match anything).
    #[test]
    fn an_answers_numbers_take_their_tolerances_by_its_scale() {
        let v = |xs: &[f64]| Val::List(xs.iter().map(Val::num).collect());
        let key: Key = "view.points.A".parse().expect("a key");
        let got = numbers(&key, &v(&[0.0, 4.0, -3.0]), 1e-3);
        let want = [(0.0, 0.004), (4.0, 0.004), (-3.0, 0.003)];
        for ((x, t), (wx, wt)) in got.iter().zip(want) {
            assert!(*x == wx && near(*t, wt), "{got:?}");
        }
        assert_eq!(got.len(), 3);
        assert_eq!(scale(&v(&[0.0, f64::INFINITY, -2.0])), 2.0);
        assert_eq!(scale(&v(&[0.0, 0.0])), 0.0);
        let matrix = Val::List(vec![v(&[1.0, -7.5]), v(&[0.5, 0.0])]);
        assert_eq!(scale(&matrix), 7.5);
    }

    #[test]
    fn a_zero_takes_the_tolerance_of_its_answer() {
        assert!(near(absolute(0.0, 0.1, 1e-3), 1e-4));
        assert!(near(absolute(-0.02, 0.1, 1e-3), 2e-5));
        assert!(near(absolute(0.0, 0.0, 1e-3), 1e-3));
    }

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn a_pixel_takes_half_a_pixel() {
        // 0.1 % of 133.32 is 0.133 px < 0.5 px: a whole pixel 133 is
        // 0.32 px away, and named right
        for k in [
            "viewport.pixels.A",
            "viewport.pixels.A.0",
            "viewport.pixels",
            "viewport",
            "pixels.A",
        ] {
            let k = key(k);
            assert!(is_pixel(&k), "{k}");
            assert!(near(for_key(&k, 133.32, 133.32, 1e-3), 0.5), "{k}");
            assert!((133.0f64 - 133.32).abs() <= for_key(&k, 133.32, 133.32, 1e-3));
        }
        // a large pixel coordinate keeps its relative tolerance
        let px = key("viewport.pixels.A.1");
        assert!(near(for_key(&px, 1000.0, 1000.0, 1e-3), 1.0));
        // not a pixel: the window's top, 133.32 units: 0.1 % is 0.133
        for k in [
            "window.top",
            "view.points.A.0",
            "project.points.A",
            "window",
            "top",
        ] {
            let k = key(k);
            assert!(!is_pixel(&k), "{k}");
            assert!(near(for_key(&k, 133.32, 133.32, 1e-3), 0.13332), "{k}");
        }
        assert!(near(for_key(&key("window.top"), 0.2, 0.2, 1e-3), 2e-4));
    }
}
