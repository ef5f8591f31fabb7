//! Judging one answer: exact equality, the tolerance, the rounding to the
//! digits written, significant figures; lists element by element.

use super::{Settings, Verdict, ZERO_TOLERANCE};
use crate::msg::Msg;
use crate::num::{parse_expr, Real, Shown};
use crate::stages::trace::Val;

/// A judged value (a number, or a list judged element by element).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Judged {
    pub verdict: Verdict,
    /// The stable code: `correct.exact`, `correct.tolerance`,
    /// `correct.rounded`, `too_coarse`, `wrong`, `unparseable`, `missing`.
    pub code: &'static str,
    pub note: Msg,
}

impl Judged {
    pub(crate) fn new(verdict: Verdict, code: &'static str, note: Msg) -> Judged {
        Judged {
            verdict,
            code,
            note,
        }
    }
}

/// Judges a given answer against an expected value.
/// `carry`: also accept a decimal within one unit of its last written digit
/// (used when matching mistaken values: students carry rounded intermediate
/// values forward, as the text does with 2 × 0.041 = 0.082).
pub(crate) fn judge(
    given: &toml::Value,
    expected: &Val,
    s: &Settings,
    key: &str,
    carry: bool,
) -> Judged {
    match expected {
        Val::Num(e) => match scalar_text(given) {
            Some(t) => judge_number(&t, e, s, carry),
            None => Judged::new(Verdict::Unparseable, "unparseable", Msg::ExpectOne),
        },
        Val::List(items) => judge_list(given, items, s, key, carry),
        Val::Text(t) => judge_text(given, t),
        Val::Null => judge_none(given),
        Val::Bool(b) => judge_bool(given, *b),
        Val::Map(_) | Val::Said(_) => {
            Judged::new(Verdict::Unparseable, "unparseable", Msg::SeveralAnswers)
        }
    }
}

/// A list answer (a point, a segment): each component judged, the worst
/// verdict kept; a projected point may leave out zp.
fn judge_list(given: &toml::Value, items: &[Val], s: &Settings, key: &str, carry: bool) -> Judged {
    let Some(parts) = list_parts(given) else {
        return Judged::new(
            Verdict::Unparseable,
            "unparseable",
            Msg::ExpectList(items.len()),
        );
    };
    // A projected point may be given as (xp, yp): zp = d is the plane.
    let prefix_ok = key.starts_with("project.") && parts.len() == items.len() - 1;
    if parts.len() != items.len() && !prefix_ok {
        if let Some(junk) = parts
            .iter()
            .filter_map(scalar_text)
            .find(|t| parse_expr(&t.trim().replace(',', ".")).is_err())
        {
            return Judged::new(
                Verdict::Unparseable,
                "unparseable",
                Msg::NotANumber(junk.trim().to_string(), items.len()),
            );
        }
        return Judged::new(
            Verdict::Wrong,
            "wrong",
            Msg::CountMismatch(items.len(), parts.len()),
        );
    }
    let nested = items.iter().any(|x| matches!(x, Val::List(_)));
    let label = |i: usize| {
        if nested {
            format!("point {}", i + 1)
        } else if items.len() <= 3 {
            ["x", "y", "z"][i].to_string()
        } else {
            format!("component {}", i + 1)
        }
    };
    combine(
        parts
            .iter()
            .zip(items)
            .map(|(g, e)| judge(g, e, s, key, carry))
            .collect(),
        label,
    )
}

/// A text answer: an outcode (a short binary number is padded on the left)
/// or a word such as a status, in any case.
fn judge_text(given: &toml::Value, t: &str) -> Judged {
    let g = scalar_text(given).unwrap_or_default();
    let g = g.trim();
    let same = if t.len() == 6 && t.chars().all(|c| c == '0' || c == '1') {
        // an outcode; a short binary number is padded on the left
        g.len() <= 6 && g.chars().all(|c| c == '0' || c == '1') && format!("{g:0>6}") == *t
    } else {
        g.eq_ignore_ascii_case(t)
    };
    if same {
        Judged::new(Verdict::Correct, "correct.exact", Msg::default())
    } else {
        Judged::new(Verdict::Wrong, "wrong", Msg::Expected(t.to_string()))
    }
}

/// The answer to "none" (a rejected segment): empty, `none`, `null` or `rejected`.
fn judge_none(given: &toml::Value) -> Judged {
    let empty = match given {
        toml::Value::Array(a) => a.is_empty(),
        toml::Value::String(s) => {
            matches!(
                s.trim().to_lowercase().as_str(),
                "" | "none" | "null" | "rejected"
            )
        }
        _ => false,
    };
    if empty {
        Judged::new(Verdict::Correct, "correct.exact", Msg::default())
    } else {
        Judged::new(Verdict::Wrong, "wrong", Msg::ExpectedNone)
    }
}

/// A yes/no answer.
fn judge_bool(given: &toml::Value, b: bool) -> Judged {
    let g = scalar_text(given).unwrap_or_default().to_lowercase();
    let gb = matches!(g.as_str(), "true" | "yes" | "1");
    if gb == b {
        Judged::new(Verdict::Correct, "correct.exact", Msg::default())
    } else {
        Judged::new(Verdict::Wrong, "wrong", Msg::ExpectedBool(b))
    }
}

/// The parts of a list answer: a TOML array, or `(a, b, c)` written as text.
fn list_parts(given: &toml::Value) -> Option<Vec<toml::Value>> {
    match given {
        toml::Value::Array(a) => Some(a.clone()),
        toml::Value::String(t) => {
            let inner = t
                .trim()
                .trim_start_matches(['(', '['])
                .trim_end_matches([')', ']']);
            // `(0,8; 0,6; 0)`: with semicolons the commas are decimal marks.
            let items: Vec<&str> = if inner.contains(';') {
                inner.split(';').collect()
            } else {
                crate::num::expr::split_top_level(inner)
            };
            Some(
                items
                    .into_iter()
                    .map(|x| toml::Value::String(x.trim().to_string()))
                    .collect(),
            )
        }
        _ => None,
    }
}

/// The value of an answer to `key`, read the way `judge` reads it against a
/// value shaped like `like` (numbers as f64, a decimal comma as a point; a
/// projected point given as (xp, yp) takes zp = d from `like`); None when it
/// cannot be read. Follow-through computes with it.
pub(crate) fn value_of(given: &toml::Value, like: &Val, key: &str) -> Option<Val> {
    if let (true, Val::List(items), Some(parts)) =
        (key.starts_with("project."), like, list_parts(given))
    {
        if items.len() == 3 && parts.len() == 2 {
            let mut xy = read_value(given, &Val::List(items[..2].to_vec()))?;
            if let Val::List(v) = &mut xy {
                v.push(items[2].clone());
            }
            return Some(xy);
        }
    }
    read_value(given, like)
}

fn read_value(given: &toml::Value, like: &Val) -> Option<Val> {
    match like {
        Val::Num(_) => {
            let t = scalar_text(given)?.trim().replace(',', ".");
            let x = parse_expr(&t).ok()?.eval::<f64>().ok()?;
            Some(Val::num(&x))
        }
        Val::List(items) => {
            let parts = list_parts(given)?;
            (parts.len() == items.len())
                .then(|| {
                    parts
                        .iter()
                        .zip(items)
                        .map(|(g, e)| read_value(g, e))
                        .collect()
                })
                .flatten()
                .map(Val::List)
        }
        Val::Text(t) => {
            let g = scalar_text(given)?.trim().to_string();
            let outcode = t.len() == 6 && g.len() <= 6 && g.chars().all(|c| c == '0' || c == '1');
            Some(Val::Text(if outcode {
                format!("{g:0>6}")
            } else {
                g.to_lowercase()
            }))
        }
        Val::Null | Val::Bool(_) | Val::Map(_) | Val::Said(_) => None,
    }
}

/// The text of a scalar TOML value.
fn scalar_text(v: &toml::Value) -> Option<String> {
    match v {
        toml::Value::String(s) => Some(s.clone()),
        toml::Value::Integer(i) => Some(i.to_string()),
        toml::Value::Float(f) => Some(format!("{f}")),
        toml::Value::Boolean(b) => Some(b.to_string()),
        _ => None,
    }
}

/// The verdict on a list: its worst element; the weakest kind of correct.
fn combine(parts: Vec<Judged>, label: impl Fn(usize) -> String) -> Judged {
    let worst = parts
        .iter()
        .map(|j| j.verdict)
        .max()
        .unwrap_or(Verdict::Correct);
    // A component that cannot be read decides over a wrong one, so that
    // the note names the junk (`sqrt(-1)`, `1/0`) rather than only the rest.
    let unreadable = parts.iter().any(|j| j.verdict == Verdict::Unparseable);
    let worst = if worst == Verdict::Wrong && unreadable {
        Verdict::Unparseable
    } else {
        worst
    };
    let rank = |c: &str| match c {
        "correct.exact" => 0,
        "correct.tolerance" => 1,
        _ => 2,
    };
    let code = if worst == Verdict::Correct {
        parts
            .iter()
            .map(|j| j.code)
            .max_by_key(|c| rank(c))
            .unwrap_or("correct.exact")
    } else {
        parts
            .iter()
            .find(|j| j.verdict == worst)
            .map(|j| j.code)
            .unwrap_or("wrong")
    };
    // The notes of the components that decided the verdict.
    let notes: Vec<(String, Msg)> = parts
        .iter()
        .enumerate()
        .filter(|(_, j)| {
            !j.note.is_empty()
                && if worst == Verdict::Correct {
                    j.code == code
                } else {
                    j.verdict == worst
                }
        })
        .map(|(i, j)| (label(i).to_string(), j.note.clone()))
        .collect();
    // One note when every component says the same.
    let note = if !notes.is_empty()
        && parts.iter().all(|j| j.note == parts[0].note)
        && !parts[0].note.is_empty()
    {
        parts[0].note.clone()
    } else {
        Msg::Parts(notes)
    };
    Judged::new(worst, code, note)
}

/// A plain decimal as written: (significant figures, exponent of the last
/// written digit), e.g. "0.041" → (2, −3), "-1.50e2" → (3, 0). None for
/// integers (taken as exact) and for expressions.
pub fn decimal_places(text: &str) -> Option<(u32, i32)> {
    let t = text.trim().trim_start_matches(['-', '−', '+']);
    let (mant, exp) = match t.find(['e', 'E']) {
        Some(i) => (&t[..i], t[i + 1..].parse::<i32>().ok()?),
        None => (t, 0),
    };
    let (int, frac) = mant.split_once('.')?;
    if !(int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit())) || int.len() + frac.len() == 0
    {
        return None;
    }
    let digits: String = format!("{int}{frac}");
    let sig = digits.trim_start_matches('0').len() as u32;
    Some((sig.max(1), exp - frac.len() as i32))
}

/// A whole number as written, read as a rounding to the units: (significant
/// figures, 0), e.g. "124" → (3, 0), "-4" → (1, 0). None for 0 (no figure
/// of it is significant) and for anything that is not a plain integer.
fn whole_number_places(text: &str) -> Option<(u32, i32)> {
    let t = text.trim().trim_start_matches(['-', '−', '+']);
    if t.is_empty() || !t.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    let sig = t.trim_start_matches('0').len() as u32;
    (sig > 0).then_some((sig, 0))
}

/// Judges one number written by the student against an expected number.
fn judge_number(text: &str, e: &Shown, s: &Settings, carry: bool) -> Judged {
    let t = text.trim();
    if t.is_empty() {
        return Judged::new(Verdict::Missing, "missing", Msg::EmptyAnswer);
    }
    // A decimal comma (0,041) is a decimal point.
    let t = t.replace(',', ".");
    let expr = match parse_expr(&t) {
        Ok(x) => x,
        Err(m) => return Judged::new(Verdict::Unparseable, "unparseable", Msg::Unreadable(m)),
    };
    let g = match expr.eval::<f64>() {
        Ok(v) => v,
        Err(m) => return Judged::new(Verdict::Unparseable, "unparseable", Msg::Unreadable(m)),
    };
    let ev = e.value;
    let places = decimal_places(&t).or_else(|| whole_number_places(&t));
    let expected_txt = || Msg::Expected(crate::num::format::shown(e, 6, true));

    // 1. Exact equality, when both sides are exact.
    let mut decided = false;
    if let Some(ex) = &e.exact {
        if let (Ok(er), Ok(gr)) = (
            parse_expr(ex).and_then(|x| x.eval::<Real>()),
            expr.eval::<Real>(),
        ) {
            if er.is_exact() && gr.is_exact() {
                decided = true;
                if er == gr {
                    return Judged::new(Verdict::Correct, "correct.exact", Msg::Exact);
                }
                if places.is_none() {
                    // an exact form that is not equal: only tolerance can save it
                    return within_tolerance(g, ev, s, places)
                        .unwrap_or_else(|| Judged::new(Verdict::Wrong, "wrong", expected_txt()));
                }
            }
        }
    }
    // Equal to 1e-12 (relative): exact, when exact arithmetic cannot decide
    // (a terminating decimal such as 0.6 = 3/5 is exact, however few digits).
    if !decided && (g - ev).abs() <= ZERO_TOLERANCE * ev.abs().max(1.0) {
        return Judged::new(Verdict::Correct, "correct.exact", Msg::Exact);
    }
    if let Some(j) = within_tolerance(g, ev, s, places) {
        return j;
    }
    // 3. Correctly rounded to the places written.
    if let Some((sig, last)) = places {
        let unit = if carry { 1.0 } else { 0.5 };
        let half = unit * 10f64.powi(last) * (1.0 + 1e-9);
        if (g - ev).abs() <= half {
            return if sig < s.sig_figs {
                Judged::new(
                    Verdict::TooCoarse,
                    "too_coarse",
                    Msg::RoundedCoarse(sig, s.sig_figs),
                )
            } else {
                Judged::new(Verdict::Correct, "correct.rounded", Msg::Rounded(sig))
            };
        }
    }
    Judged::new(Verdict::Wrong, "wrong", expected_txt())
}

/// The tolerance test: relative `s.tolerance` (absolute 1e-12 near zero).
fn within_tolerance(g: f64, ev: f64, s: &Settings, places: Option<(u32, i32)>) -> Option<Judged> {
    let tol = (s.tolerance * ev.abs()).max(ZERO_TOLERANCE);
    if (g - ev).abs() > tol {
        return None;
    }
    Some(match places {
        Some((sig, _)) if sig < s.sig_figs => Judged::new(
            Verdict::TooCoarse,
            "too_coarse",
            Msg::SigCoarse(sig, s.sig_figs),
        ),
        _ => Judged::new(
            Verdict::Correct,
            "correct.tolerance",
            Msg::WithinPct(fmt_pct(s.tolerance)),
        ),
    })
}

fn fmt_pct(t: f64) -> String {
    crate::num::format::fmt_dec(t * 100.0, 3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tutor::check::Settings;

    fn num(v: f64) -> Shown {
        Shown {
            value: v,
            exact: None,
            pretty: None,
        }
    }
    fn j(text: &str, v: f64) -> Judged {
        judge_number(text, &num(v), &Settings::default(), false)
    }

    #[test]
    fn places_written() {
        assert_eq!(decimal_places("0.041"), Some((2, -3)));
        assert_eq!(decimal_places("-0.0283"), Some((3, -4)));
        assert_eq!(decimal_places("1.50e2"), Some((3, 0)));
        assert_eq!(decimal_places("12"), None);
        assert_eq!(decimal_places("-6/sqrt(2)"), None);
    }

    #[test]
    fn junk_inside_a_vector_is_unparseable_and_named() {
        let e = Val::List(vec![Val::num(&0.0), Val::num(&0.0), Val::num(&1.0)]);
        let s = Settings::default();
        let arr = |xs: &[&str]| {
            toml::Value::Array(
                xs.iter()
                    .map(|x| toml::Value::String(x.to_string()))
                    .collect(),
            )
        };
        let j = judge(&arr(&["sqrt(-1)", "0", "1/0"]), &e, &s, "view.n", false);
        let en = |m: &Msg| crate::report::words::words(m, crate::report::lang::Lang::En);
        assert_eq!(j.verdict, Verdict::Unparseable, "{}", en(&j.note));
        assert!(
            en(&j.note).contains("x:") && en(&j.note).contains("z:"),
            "{}",
            en(&j.note)
        );
        let j = judge(
            &toml::Value::String("banana".into()),
            &e,
            &s,
            "view.n",
            false,
        );
        assert_eq!(j.code, "unparseable", "{}", en(&j.note));
        assert!(en(&j.note).contains("banana"), "{}", en(&j.note));
        // A readable wrong answer of the wrong length stays wrong.
        let j = judge(&arr(&["0", "1"]), &e, &s, "view.n", false);
        assert_eq!(j.code, "wrong");
    }

    #[test]
    fn a_whole_number_is_read_as_a_rounding_to_the_units() {
        // 124.14 to the units is 124 (3 figures): correct; −3√2 = −4.243 to
        // the units is −4, one figure: too coarse, as 0.04 is for a decimal.
        assert_eq!(j("124", 124.14).code, "correct.rounded");
        assert_eq!(j("-4", -3.0 * 2f64.sqrt()).code, "too_coarse");
        assert_eq!(j("125", 124.14).verdict, Verdict::Wrong); // 0.86 off, more than half a unit
        assert_eq!(j("0", 0.3).verdict, Verdict::Wrong); // 0 has no significant figure
    }

    #[test]
    fn a_truncated_long_decimal_is_not_exact() {
        // 50 digits of √2 − 1, truncated: close, but not the exact value.
        let t = "0.41421356237309504880168872420969807856967187537694";
        let judged = judge_number(t, &exact_sqrt2_minus_1(), &Settings::default(), false);
        assert_ne!(judged.code, "correct.exact");
        assert_eq!(judged.verdict, Verdict::Correct);
    }

    fn exact_sqrt2_minus_1() -> Shown {
        Shown {
            value: 2f64.sqrt() - 1.0,
            exact: Some("sqrt(2)-1".into()),
            pretty: None,
        }
    }

    #[test]
    fn verdicts_on_numbers() {
        // tan 22.5° = √2 − 1, so 0.1·tan 22.5° = 0.0414213562...
        let top = 0.1 * (2f64.sqrt() - 1.0);
        assert_eq!(j("0.041", top).code, "correct.rounded"); // |0.041 − top| = 0.00042 ≤ 0.0005
        assert_eq!(j("0.0414", top).code, "correct.tolerance"); // 0.05% off
        assert_eq!(j("0.04", top).verdict, Verdict::TooCoarse); // 1 significant figure
        assert_eq!(j("0.042", top).verdict, Verdict::Wrong); // 1.4% off, not the rounding
        assert_eq!(j("0,041", top).code, "correct.rounded"); // decimal comma
                                                             // −6/√2 = −3√2, written either way
        let a = -6.0 / 2f64.sqrt();
        assert_eq!(j("-3*sqrt(2)", a).code, "correct.exact");
        assert_eq!(j("-3√2", a).code, "correct.exact");
        assert_eq!(j("-4.24", a).code, "correct.tolerance"); // 0.06% off
        assert_eq!(j("-4.2", a).code, "correct.rounded");
        assert_eq!(j("1/(", a).verdict, Verdict::Unparseable);
        assert_eq!(j("", a).verdict, Verdict::Missing);
        // near zero: absolute 1e-12
        assert_eq!(j("0", 1e-15).verdict, Verdict::Correct);
        assert_eq!(j("0.001", 0.0).verdict, Verdict::Wrong);
    }

    #[test]
    fn lists_and_codes() {
        let s = Settings::default();
        let e = Val::List(vec![Val::Num(num(0.02)), Val::Num(num(-0.0282842712))]);
        let g: toml::Value = toml::Value::Array(vec!["0.0067".into(), "-0.0283".into()]);
        let r = judge(&g, &e, &s, "project.points.B", false);
        assert_eq!(r.verdict, Verdict::Wrong);
        let ok: toml::Value = "(1/50, -sqrt(2)/50)".into();
        assert_eq!(
            judge(&ok, &e, &s, "project.points.B", false).verdict,
            Verdict::Correct
        );
        let code = Val::text("000010");
        assert_eq!(
            judge(&"10".into(), &code, &s, "clip.code0", false).verdict,
            Verdict::Correct
        );
        assert_eq!(
            judge(&"010000".into(), &code, &s, "clip.code0", false).verdict,
            Verdict::Wrong
        );
    }
}
