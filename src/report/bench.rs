//! `grafika bench` for people and scripts: the table of run time against
//! error, and the same measurement as JSON.

use crate::bench::accuracy::{self, Inputs};
use crate::bench::Row;
use crate::num::Precision;
use crate::report::lang::NumStyle;
use comfy_table::{presets, Cell, CellAlignment, Table};
use serde::Serialize;

/// A time for people in the style `nums`: `12.3 ns`, `4.56 µs`, `7,89 ms`.
pub fn fmt_time(ns: f64, nums: NumStyle) -> String {
    if ns < 1e3 {
        format!("{} ns", nums.fixed(ns, 1))
    } else if ns < 1e6 {
        format!("{} µs", nums.fixed(ns / 1e3, 2))
    } else {
        format!("{} ms", nums.fixed(ns / 1e6, 2))
    }
}

/// An error in ulps for people in the style `nums`.
pub fn fmt_ulps(x: f64, nums: NumStyle) -> String {
    if x.is_infinite() {
        "inf".into()
    } else if x >= 1e6 {
        nums.exponent(x, 2)
    } else if x >= 10.0 {
        nums.fixed(x, 0)
    } else {
        nums.fixed(x, 2)
    }
}

/// The table.
pub fn table(inp: &Inputs, rows: &[Row], lang: crate::report::lang::Lang) -> String {
    use crate::msg::BenchWord as B;
    let w = |k: B| crate::report::words::of(lang).bench(k);
    // numbers with the language's decimal mark (`56,99 ms` in Indonesian)
    let nums = crate::report::words::of(lang).nums();
    let mut t = Table::new();
    t.load_preset(presets::UTF8_FULL_CONDENSED);
    t.set_header(
        [
            B::Stage,
            B::Precision,
            B::Cases,
            B::TimePerOp,
            B::MaxUlpsInt,
            B::MedianUlpsInt,
            B::MaxUlpsWide,
            B::Target,
        ]
        .map(w),
    );
    for r in rows {
        let right = |s: String| Cell::new(s).set_alignment(CellAlignment::Right);
        let (tmax, tmed) = r.target_max_median();
        let (wmax, _) = accuracy::max_median(&r.errors.wide);
        let exact = r.precision == Precision::Exact;
        let dash = || right("—".into());
        let verdict = if exact {
            w(B::Exact)
        } else if !r.stage.has_target() {
            w(B::NoTarget)
        } else if tmax <= 4.0 && r.errors.target_disagreements == 0 {
            w(B::Met)
        } else {
            w(B::NotMet)
        };
        t.add_row(vec![
            Cell::new(r.stage.name()),
            Cell::new(r.precision.name()),
            right(inp.len(r.stage).to_string()),
            right(fmt_time(r.ns_per_op, nums)),
            if exact {
                dash()
            } else {
                right(fmt_ulps(tmax, nums))
            },
            if exact {
                dash()
            } else {
                right(fmt_ulps(tmed, nums))
            },
            if exact {
                dash()
            } else {
                right(fmt_ulps(wmax, nums))
            },
            Cell::new(verdict),
        ]);
    }
    let mut out = t.to_string();
    out.push('\n');
    out.push_str(w(B::UlpsNote));
    let dis: usize = rows.iter().map(|r| r.errors.disagreements).sum();
    let unref: usize = rows.iter().map(|r| r.errors.unreferenced).sum();
    let (a, b) = (w(B::Disagreements), w(B::Unreferenced));
    out.push_str(&format!("{a}: {dis}\n{b}: {unref}\n"));
    out
}

/// The measurement as JSON.
#[derive(Serialize)]
pub struct BenchJson {
    command: &'static str,
    seed: u64,
    rows: Vec<RowJson>,
}

/// One stage at one precision: its time and its errors in ulps.
#[derive(Serialize)]
struct RowJson {
    stage: &'static str,
    precision: &'static str,
    cases: usize,
    ns_per_op: f64,
    passes: usize,
    ulps: UlpsJson,
    disagreements: usize,
    unreferenced: usize,
}

/// The errors against the target, the wide reference and all cases.
#[derive(Serialize)]
struct UlpsJson {
    target: Spread,
    wide: Spread,
    all: Spread,
}

/// The largest and the median error (`"inf"` when not finite), and over
/// how many cases (not written for all of them).
#[derive(Serialize)]
struct Spread {
    #[serde(serialize_with = "ulps")]
    max: f64,
    #[serde(serialize_with = "ulps")]
    median: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    count: Option<usize>,
}

/// An error in ulps: a number, or `"inf"`.
fn ulps<S: serde::Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
    match x.is_finite() {
        true => s.serialize_f64(*x),
        false => s.serialize_str("inf"),
    }
}

/// The measurement as JSON.
pub fn to_json(inp: &Inputs, rows: &[Row]) -> BenchJson {
    let spread = |(max, median): (f64, f64), count| Spread { max, median, count };
    let row = |r: &Row| RowJson {
        stage: r.stage.name(),
        precision: r.precision.name(),
        cases: inp.len(r.stage),
        ns_per_op: r.ns_per_op,
        passes: r.passes,
        ulps: UlpsJson {
            target: spread(r.target_max_median(), Some(r.errors.target.len())),
            wide: spread(
                accuracy::max_median(&r.errors.wide),
                Some(r.errors.wide.len()),
            ),
            all: spread(r.all_max_median(), None),
        },
        disagreements: r.errors.disagreements,
        unreferenced: r.errors.unreferenced,
    };
    BenchJson {
        command: "bench",
        seed: accuracy::SEED,
        rows: rows.iter().map(row).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An error in ulps is written as a number while it is finite and as
    /// `"inf"` otherwise (an infinite error, or NaN), and only the target's
    /// and the wide reference's say how many cases they are over.
    #[test]
    fn an_error_that_is_not_finite_is_written_inf() {
        let json = |s: &Spread| serde_json::to_string(s).unwrap();
        let all = Spread {
            max: f64::INFINITY,
            median: 0.5,
            count: None,
        };
        assert_eq!(json(&all), r#"{"max":"inf","median":0.5}"#);
        let target = Spread {
            max: f64::NAN,
            median: 2.0,
            count: Some(3),
        };
        assert_eq!(json(&target), r#"{"max":"inf","median":2.0,"count":3}"#);
    }
}
