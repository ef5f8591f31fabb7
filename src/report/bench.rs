//! `grafika bench` for people and scripts: the table of run time against
//! error, and the same measurement as JSON.

use crate::bench::accuracy::{self, Inputs};
use crate::bench::Row;
use crate::num::Precision;
use crate::report::lang::NumStyle;
use comfy_table::{presets, Cell, CellAlignment, Table};
use serde_json::{json, Value};

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
pub fn to_json(inp: &Inputs, rows: &[Row]) -> Value {
    let rows: Vec<Value> = rows
        .iter()
        .map(|r| {
            let (tmax, tmed) = r.target_max_median();
            let (amax, amed) = r.all_max_median();
            let (wmax, wmed) = accuracy::max_median(&r.errors.wide);
            let num = |x: f64| if x.is_finite() { json!(x) } else { json!("inf") };
            json!({
                "stage": r.stage.name(),
                "precision": r.precision.name(),
                "cases": inp.len(r.stage),
                "ns_per_op": r.ns_per_op,
                "passes": r.passes,
                "ulps": {
                    "target": {"max": num(tmax), "median": num(tmed), "count": r.errors.target.len()},
                    "wide": {"max": num(wmax), "median": num(wmed), "count": r.errors.wide.len()},
                    "all": {"max": num(amax), "median": num(amed)},
                },
                "disagreements": r.errors.disagreements,
                "unreferenced": r.errors.unreferenced,
            })
        })
        .collect();
    json!({ "command": "bench", "seed": accuracy::SEED, "rows": rows })
}
