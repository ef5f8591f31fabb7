//! Judging one answer, as read ([`crate::input::answer`]), against one
//! value: grafika's, a mistake's, or the one the student's own earlier
//! answers lead to. A number is, in this order:
//!
//! 1. exact: equal to the value (any equivalent form, decided exactly);
//! 2. within the tolerance ([`tolerance::for_key`]): correct, whatever
//!    figures it is written with (1.0 for 0.99926, 0.074 % off, is right);
//! 3. the value rounded to the digits written (a whole number is rounded to
//!    the units): correct, or too coarse with fewer significant figures
//!    than asked. Figures are counted from the value's own leading digit,
//!    so a rounding past it keeps none (1 for 0.7071 is wrong; 1 for 0.96
//!    and 0.1 for 0.096 keep one figure);
//! 4. wrong.
//!
//! So "too coarse" is a rounding of the value that keeps too few of its
//! figures to come within the tolerance: right as far as it goes, worth
//! half. An expression that is not exactly the value (`7/5` for √2) can
//! only be saved by the tolerance. A list takes its worst component's
//! verdict; a zero component takes the tolerance of its list's largest
//! magnitude. Before step 2, the caller sets the answer beside the
//! catalog's mistaken values ([`matches_closely`]): an answer equal to one
//! is wrong, whatever it rounds.

use super::{tolerance, Settings, Verdict};
use crate::input::answer::{Number, Read};
use crate::msg::{Expect, Msg};
use crate::num::{Expr, Real, Shown};
use crate::stages::trace::Val;
use crate::tutor::key::Key;

/// A judged answer: its verdict (exact, within the tolerance, rounded,
/// too coarse, wrong, unparseable, missing) and note.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Judged {
    pub verdict: Verdict,
    pub note: Msg,
}

impl Judged {
    pub(crate) fn new(verdict: Verdict, note: Msg) -> Judged {
        Judged { verdict, note }
    }
    fn wrong(note: Msg) -> Judged {
        Judged::new(Verdict::Wrong, note)
    }
    /// Whether the answer agrees with the value: correct (not by
    /// follow-through) or too coarse.
    pub(crate) fn agrees(&self) -> bool {
        self.verdict.agrees()
    }
}

/// A value's exact form (its ASCII, as grafika writes it) as an exact
/// number; the caller caches it, since a class is marked against the same
/// values.
pub(crate) type ExactOf<'a> = &'a dyn Fn(&str) -> Option<Real>;

/// An answer's expression, as read, as an exact number; the caller caches
/// it by the expression, since a class writes the same forms.
pub(crate) type ExactExpr<'a> = &'a dyn Fn(&Expr) -> Option<Real>;

/// What a judgment needs besides the answer and the value.
#[derive(Clone, Copy)]
pub(crate) struct Ctx<'a> {
    pub settings: &'a Settings,
    /// The answer key (a pixel position takes half a pixel).
    pub key: &'a Key,
    /// Also accept a decimal within one unit of its last written digit:
    /// students carry rounded values forward (the text's 2 × 0.041 =
    /// 0.082), so a mistaken or carried value is matched this loosely.
    pub carry: bool,
    pub exact: ExactOf<'a>,
    pub given: ExactExpr<'a>,
}

/// Judges an answer against a value.
pub(crate) fn judge(read: &Read, expected: &Val, ctx: &Ctx) -> Judged {
    judge_scaled(read, expected, tolerance::scale(expected), ctx)
}

fn judge_scaled(read: &Read, expected: &Val, sc: f64, ctx: &Ctx) -> Judged {
    match (read, expected) {
        (Read::Num(n), Val::Num(e)) => number(n, e, sc, ctx),
        (Read::List(items), Val::List(es)) if items.len() == es.len() => combine(
            items
                .iter()
                .zip(es)
                .map(|(g, e)| judge_scaled(g, e, sc, ctx))
                .collect(),
            es.len(),
            es.iter().any(|x| matches!(x, Val::List(_))),
        ),
        (Read::List(items), Val::List(es)) => {
            Judged::wrong(Msg::CountMismatch(es.len(), items.len()))
        }
        (Read::Word(w), Val::Text(t)) if w == t => Judged::new(Verdict::Exact, Msg::Exact),
        (Read::Word(w), Val::Bool(b)) if *w == b.to_string() => {
            Judged::new(Verdict::Exact, Msg::Exact)
        }
        (Read::None, Val::Null) => Judged::new(Verdict::Exact, Msg::Exact),
        (_, Val::Null) => Judged::wrong(Msg::ExpectedNone),
        (_, Val::Bool(b)) => Judged::wrong(Msg::ExpectedBool(*b)),
        (_, e) => Judged::wrong(expected_note(e)),
    }
}

/// Whether an answer a source printed (a problem file's `[printed]`)
/// agrees with the value computed: read as a student's answer is read
/// ([`crate::input::answer::read`]), judged by [`judge`] with the
/// problem's settings, and agreeing when the verdict does
/// ([`Judged::agrees`]: correct, or too coarse). A printed (x, y) is
/// judged against the first two of (x, y, z), as a source prints a point
/// on the plane of projection. None when it cannot be read as such a value
/// (not comparable).
pub(crate) fn printed_agrees(
    printed: &toml::Value,
    computed: &Val,
    key: &Key,
    settings: &Settings,
) -> Option<bool> {
    let read = crate::input::answer::read(printed, computed).ok()?;
    let exact = |t: &str| crate::num::parse_expr(t).ok()?.eval::<Real>().ok();
    let ctx = Ctx {
        settings,
        key,
        carry: false,
        exact: &exact,
        given: &|e| e.eval::<Real>().ok(),
    };
    Some(judge(&read, &first_of(computed, &read), &ctx).agrees())
}

/// A value's lists cut to the length of an answer's, at every depth.
fn first_of(v: &Val, read: &Read) -> Val {
    match (v, read) {
        (Val::List(vs), Read::List(rs)) if rs.len() <= vs.len() => {
            Val::List(vs.iter().zip(rs).map(|(v, r)| first_of(v, r)).collect())
        }
        _ => v.clone(),
    }
}

/// "expected …" with the value in exact and decimal form.
pub(crate) fn expected_note(e: &Val) -> Msg {
    Msg::Expected(expect(e))
}

/// A value as "expected …" says it: numbers, words as written, lists.
fn expect(e: &Val) -> Expect {
    match e {
        Val::Num(s) => Expect::Num(s.clone()),
        Val::Text(t) => Expect::Text(t.clone()),
        Val::List(items) => Expect::List(items.iter().map(expect).collect()),
        _ => Expect::Nothing,
    }
}

/// Whether two numbers are equal as doubles can tell (relative 1e-9).
fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
}

/// The exponent of a number's leading digit (−2 for 0.0414), read from
/// its shortest decimal, which a logarithm can miss by one at a power of 10.
fn leading_digit(x: f64) -> i32 {
    let s = format!("{:e}", x.abs());
    s.split_once('e')
        .and_then(|(_, e)| e.parse().ok())
        .unwrap_or(0)
}

/// Judges one number (steps 1 to 4 of the module docs); `sc` is the
/// largest magnitude of the answer it belongs to.
fn number(n: &Number, e: &Shown, sc: f64, ctx: &Ctx) -> Judged {
    let (g, ev) = (n.value, e.value);
    let s = ctx.settings;
    // 1. Exactly equal: decided exactly where both are exact forms (only
    // when the doubles agree: otherwise they cannot be equal), else to 1e-12.
    if same(g, ev) {
        let exact = e.exact.as_deref().and_then(ctx.exact);
        let given = exact.as_ref().and_then(|_| (ctx.given)(&n.expr));
        let exactly = match (exact, given) {
            (Some(x), Some(y)) if x.is_exact() && y.is_exact() => x == y,
            _ => (g - ev).abs() <= 1e-12 * ev.abs().max(1.0),
        };
        if exactly {
            return Judged::new(Verdict::Exact, Msg::Exact);
        }
    }
    let figures = n.last_digit.map(|last| leading_digit(ev) - last + 1);
    let coarse = |k: i32| ev != 0.0 && k < s.sig_figs as i32;
    // 2. Within the tolerance (an expression that is not the value: only
    // this), however many figures are written.
    let off = (g - ev).abs();
    if off <= tolerance::for_key(ctx.key, ev, sc, s.tolerance) {
        let note = if off > tolerance::absolute(ev, sc, s.tolerance) {
            Msg::WithinPixel
        } else {
            Msg::WithinPct(s.tolerance * 100.0)
        };
        return Judged::new(Verdict::Tolerance, note);
    }
    let (Some(last), Some(k)) = (n.last_digit, figures) else {
        return Judged::wrong(expected_note(&Val::Num(e.clone())));
    };
    // 3. The value rounded to the digits written.
    let unit = if ctx.carry { 1.0 } else { 0.5 };
    let within = |exp: i32| off <= unit * 10f64.powi(exp) * (1.0 + 1e-9);
    // a rounding past the value's leading digit keeps one figure only
    // when it is the value's rounding to that digit (0.96 → 1)
    let k = if k <= 0 && within(leading_digit(ev)) {
        1
    } else {
        k
    };
    if within(last) && k >= 1 {
        return if coarse(k) {
            Judged::new(Verdict::TooCoarse, Msg::RoundedCoarse(k as u32, s.sig_figs))
        } else {
            Judged::new(Verdict::Rounded, Msg::Rounded(k as u32))
        };
    }
    Judged::wrong(expected_note(&Val::Num(e.clone())))
}

/// Whether an answer is a mistaken value itself: every number equal to it
/// (as doubles can tell), or, written as a decimal, within its tolerance;
/// every word the same.
pub(crate) fn matches_closely(read: &Read, v: &Val, key: &Key, rel: f64) -> bool {
    let sc = tolerance::scale(v);
    fn go(read: &Read, v: &Val, key: &Key, rel: f64, sc: f64) -> bool {
        match (read, v) {
            (Read::Num(n), Val::Num(m)) => {
                same(n.value, m.value)
                    || (n.is_decimal()
                        && (n.value - m.value).abs() <= tolerance::for_key(key, m.value, sc, rel))
            }
            (Read::List(a), Val::List(b)) => {
                a.len() == b.len() && a.iter().zip(b).all(|(x, y)| go(x, y, key, rel, sc))
            }
            (Read::Word(w), Val::Text(t)) => w == t,
            (Read::None, Val::Null) => true,
            _ => false,
        }
    }
    go(read, v, key, rel, sc)
}

/// Whether two values can be told apart at the tolerance: a number whose
/// tolerance intervals do not meet, a different word, another shape.
pub(crate) fn apart(a: &Val, b: &Val, key: &Key, rel: f64) -> bool {
    let (sa, sb) = (tolerance::scale(a), tolerance::scale(b));
    fn go(a: &Val, b: &Val, key: &Key, rel: f64, s: (f64, f64)) -> bool {
        match (a, b) {
            (Val::Num(x), Val::Num(y)) => tolerance::apart(
                x.value,
                tolerance::for_key(key, x.value, s.0, rel),
                y.value,
                tolerance::for_key(key, y.value, s.1, rel),
            ),
            (Val::List(xs), Val::List(ys)) => {
                xs.len() != ys.len() || xs.iter().zip(ys).any(|(x, y)| go(x, y, key, rel, s))
            }
            _ => a != b,
        }
    }
    go(a, b, key, rel, (sa, sb))
}

/// The verdict on a list: its worst element; the weakest kind of correct.
/// Notes are labelled x, y, z (a point of three) or by position.
fn combine(parts: Vec<Judged>, n: usize, nested: bool) -> Judged {
    let label = |i: usize| {
        if !nested && n <= 3 {
            ["x", "y", "z"][i].to_string()
        } else {
            format!("{}", i + 1)
        }
    };
    let worst = (parts.iter().map(|j| j.verdict))
        .max_by_key(|v| v.badness())
        .unwrap_or(Verdict::Exact);
    // The notes of the components that decided the verdict.
    let notes: Vec<(String, Msg)> = parts
        .iter()
        .enumerate()
        .filter(|(_, j)| !j.note.is_empty() && j.verdict == worst)
        .map(|(i, j)| (label(i), j.note.clone()))
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
    Judged::new(worst, note)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::answer;

    fn exact(t: &str) -> Option<Real> {
        crate::num::parse_expr(t).ok()?.eval::<Real>().ok()
    }
    fn shown(v: f64, exact: Option<&str>) -> Val {
        Val::Num(Shown {
            value: v,
            exact: exact.map(str::to_string),
            pretty: None,
            beyond: None,
        })
    }
    fn j_at(text: &str, e: &Val, key: &str) -> Judged {
        let s = Settings::default();
        let key: Key = key.parse().expect("a key");
        let ctx = Ctx {
            settings: &s,
            key: &key,
            carry: false,
            exact: &exact,
            given: &|e| e.eval::<Real>().ok(),
        };
        let read = answer::read(&toml::Value::String(text.into()), e).unwrap();
        judge(&read, e, &ctx)
    }
    fn j(text: &str, v: f64) -> Judged {
        j_at(text, &shown(v, None), "window.top")
    }

    #[test]
    fn verdicts_on_numbers() {
        // tan 22.5° = √2 − 1, so 0.1·tan 22.5° = 0.0414213562...
        let top = 0.1 * (2f64.sqrt() - 1.0);
        assert_eq!(j("0.041", top).verdict, Verdict::Rounded); // |0.041 − top| = 0.00042 ≤ 0.0005
        assert_eq!(j("0.0414", top).verdict, Verdict::Tolerance); // 0.05% off
        assert_eq!(j("0.04", top).verdict, Verdict::TooCoarse); // 1 significant figure
        assert_eq!(j("0.042", top).verdict, Verdict::Wrong); // 1.4% off, not the rounding
        assert_eq!(j("0,041", top).verdict, Verdict::Rounded); // decimal comma
                                                               // −6/√2 = −3√2, written either way
        let a = shown(-3.0 * 2f64.sqrt(), Some("-3*sqrt(2)"));
        assert_eq!(j_at("-6/sqrt(2)", &a, "top").verdict, Verdict::Exact);
        assert_eq!(j_at("-3√2", &a, "top").verdict, Verdict::Exact);
        assert_eq!(j_at("-4.24", &a, "top").verdict, Verdict::Tolerance); // 0.06% off
        assert_eq!(j_at("-4.2", &a, "top").verdict, Verdict::Rounded);
        // 7/5 is 1% from √2: an expression is not a rounding
        let r2 = shown(2f64.sqrt(), Some("sqrt(2)"));
        assert_eq!(j_at("7/5", &r2, "top").verdict, Verdict::Wrong);
        // 50 digits of √2 − 1, truncated: close, but not the exact value
        let t = "0.41421356237309504880168872420969807856967187537694";
        let v = shown(2f64.sqrt() - 1.0, Some("sqrt(2)-1"));
        assert_eq!(j_at(t, &v, "top").verdict, Verdict::Tolerance);
    }

    /// A value as grafika shows it: its double and its exact form.
    fn exact_value(form: &str) -> Val {
        let x = exact(form).expect("an exact form");
        Val::Num(Shown {
            value: x.to_f64(),
            exact: x.exact_ascii(),
            pretty: None,
            beyond: None,
        })
    }

    #[test]
    fn an_unrationalized_form_is_exact() {
        // −17/(17√17) = −1/√17 = −√17/17; −36652/(187√2618): 36652 =
        // 14·2618, so it is −14·2618/(187√2618) = −14√2618/187
        for (given, value) in [
            ("-17/(17*sqrt(17))", "-sqrt(17)/17"),
            ("−17/(17√17)", "-sqrt(17)/17"),
            ("-36652/(187*sqrt(2618))", "-14*sqrt(2618)/187"),
            ("-4/(13*sqrt(17))", "-4*sqrt(17)/221"),
        ] {
            let got = j_at(given, &exact_value(value), "view.u.2");
            assert_eq!(got.verdict, Verdict::Exact, "{given}: {got:?}");
        }
    }

    proptest::proptest! {
        /// a·√m/b written every way students write it: rationalized or
        /// not, a product of roots for a composite m, a square factor
        /// under the root, a common factor in numerator and denominator,
        /// implicit products, `√` and `−`: each is exact, never "within
        /// the tolerance".
        #[test]
        fn every_form_of_a_surd_is_exact(
            a in 1i64..40,
            negative in proptest::bool::ANY,
            b in 1i64..40,
            k in 2i64..6,
            pq in proptest::sample::select(vec![(1i64, 2i64), (1, 3), (1, 5), (2, 3), (2, 5), (3, 5), (2, 7), (7, 17), (2, 1309), (11, 238)]),
        ) {
            let (p, q) = pq;
            let m = p * q;
            let sign = if negative { "-" } else { "" };
            let value = exact_value(&format!("{sign}{a}*sqrt({m})/{b}"));
            let forms = [
                format!("{sign}{a}*sqrt({m})/{b}"),
                format!("{sign}{}/({b}*sqrt({m}))", a * m),
                format!("{sign}{a}/({b}/sqrt({m}))"),
                format!("{sign}{}*sqrt({m})/({})", a * k, b * k),
                format!("{sign}{a}*sqrt({})/({})", m * k * k, b * k),
                format!("{sign}{a}*sqrt({p})*sqrt({q})/{b}"),
                format!("{sign}{a}/{b}*sqrt({p})*sqrt({q})"),
                format!("{}({a}/{b})sqrt({m})", if negative { "−" } else { "" }),
                format!("{}{a}√{m}/{b}", if negative { "−" } else { "" }),
                format!("{sign}{}/({b}*sqrt({p})*sqrt({q}))", a * m),
                format!("{sign}sqrt({})/{b}", a * a * m),
            ];
            for form in forms {
                let got = j_at(&form, &value, "view.u.0");
                proptest::prop_assert_eq!(got.verdict, Verdict::Exact, "{} for {:?}: {:?}", form, value, got);
            }
        }
    }

    #[test]
    fn figures_are_counted_from_the_values_leading_digit() {
        // 0.7071 to the units is 1, which keeps no figure of it: wrong
        assert_eq!(j("1", 0.5f64.sqrt()).verdict, Verdict::Wrong);
        // 0.96 to one figure is 1; 0.096 to one figure is 0.1: too coarse
        assert_eq!(j("1", 0.96).verdict, Verdict::TooCoarse);
        assert_eq!(j("0.1", 0.096).verdict, Verdict::TooCoarse);
        // 124.14 to the units is 124 (3 figures); −3√2 = −4.243 to the
        // units is −4 (1 figure)
        assert_eq!(j("124", 124.14).verdict, Verdict::Rounded);
        assert_eq!(j("-4", -3.0 * 2f64.sqrt()).verdict, Verdict::TooCoarse);
        assert_eq!(j("125", 124.14).verdict, Verdict::Wrong);
        assert_eq!(j("0", 0.3).verdict, Verdict::Wrong);
        // 0.10 for 0.0957 rounds at the second decimal: one figure of it
        assert_eq!(j("0.10", 0.0957).verdict, Verdict::TooCoarse);
    }

    #[test]
    fn within_the_tolerance_is_correct_whatever_the_figures() {
        // 26/√677 = 0.999261…: 1.0 is 0.074 % off, inside 0.1 %
        let cos = 26.0 / 677f64.sqrt();
        assert_eq!(j("1.0", cos).verdict, Verdict::Tolerance);
        assert_eq!(j("1", cos).verdict, Verdict::Tolerance);
        assert_eq!(j("1,0", cos).verdict, Verdict::Tolerance);
        assert_eq!(j("1.00", cos).verdict, Verdict::Tolerance);
        // 0.99 is no rounding of it (to two decimals it is 1.00), and
        // 0.93 % off: wrong
        assert_eq!(j("0.99", cos).verdict, Verdict::Wrong);
        // (0.9, −0.3) for (3/√10, −1/√10) = (0.9487, −0.3162): each a
        // rounding to one figure, 5 % off: too coarse, not wrong
        let r10 = 10f64.sqrt();
        let v = Val::List(vec![
            shown(3.0 / r10, Some("3*sqrt(10)/10")),
            shown(-1.0 / r10, Some("-sqrt(10)/10")),
        ]);
        for given in ["(0.9, −0.3)", "0,9; −0,3", "[0.9, -0.3]"] {
            let got = j_at(given, &v, "view.u");
            assert_eq!(got.verdict, Verdict::TooCoarse, "{given}: {got:?}");
        }
    }

    #[test]
    fn a_pixel_within_half_a_pixel_names_the_pixel() {
        let px = Val::List(vec![shown(8.2, None), shown(78.45, None)]);
        let got = j_at("8, 78", &px, "viewport.pixels.A");
        assert_eq!(got.verdict, Verdict::Tolerance, "{got:?}");
        assert_eq!(
            j_at("9, 78", &px, "viewport.pixels.A").verdict,
            Verdict::Wrong
        );
    }

    proptest::proptest! {
        /// A value rounded to 2 to 6 significant figures (the default asks
        /// for 2) is correct; rounded to one, it is correct exactly when
        /// that rounding is within the tolerance (0.1 %) of the value, and
        /// too coarse otherwise; moved by two units of its last digit
        /// beyond the tolerance, it is wrong.
        #[test]
        fn a_rounding_is_judged_by_its_figures(
            m in 1.0f64..10.0,
            e in -6i32..6,
            neg in proptest::bool::ANY,
            k in 1usize..7,
        ) {
            let x = if neg { -m } else { m } * 10f64.powi(e);
            let text = format!("{:.*e}", k - 1, x);
            let got = j(&text, x);
            // a rounding that carries into a new leading digit (9.97 to
            // 1.0e1) keeps one figure fewer of the value's own
            let written: i32 = text.split_once('e').unwrap().1.parse().unwrap();
            let figures = k as i32 - i32::from(written > leading_digit(x));
            let within = (text.parse::<f64>().unwrap() - x).abs() <= 1e-3 * x.abs();
            if within {
                proptest::prop_assert!(
                    matches!(got.verdict, Verdict::Tolerance | Verdict::Exact),
                    "{} for {}: {:?}", text, x, got
                );
            } else if figures >= 2 {
                proptest::prop_assert_eq!(got.verdict, Verdict::Rounded, "{} for {}", text, x);
            } else {
                proptest::prop_assert_eq!(got.verdict, Verdict::TooCoarse, "{} for {}", text, x);
            }
            // a unit of the last digit written (9.97 to one figure is 1e1)
            let digits = text.split_once('e').unwrap().0.chars().filter(char::is_ascii_digit).count();
            let last = written - digits as i32 + 1;
            let off = text.parse::<f64>().unwrap() + 2.0 * 10f64.powi(last);
            if (off - x).abs() > 1e-3 * x.abs() {
                // written to the same last digit
                let moved = if last < 0 {
                    format!("{:.*}", (-last) as usize, off)
                } else {
                    format!("{}e{last}", (off / 10f64.powi(last)).round())
                };
                proptest::prop_assert_eq!(j(&moved, x).verdict, Verdict::Wrong, "{} for {}", moved, x);
            }
        }
    }

    #[test]
    fn a_mistaken_value_is_matched_exactly_or_within_the_tolerance_of_a_decimal() {
        let m = Val::List(vec![shown(1.0, None), shown(0.0, None), shown(1.0, None)]);
        let read = |t: &str| answer::read(&toml::Value::String(t.into()), &m).unwrap();
        let n: &Key = &"view.n".parse().unwrap();
        assert!(matches_closely(&read("1, 0, 1"), &m, n, 1e-3));
        assert!(matches_closely(&read("1.0004, 0, 0.9996"), &m, n, 1e-3));
        assert!(!matches_closely(&read("1.01, 0, 1"), &m, n, 1e-3));
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let right = Val::List(vec![shown(r, None), shown(0.0, None), shown(r, None)]);
        assert!(apart(&m, &right, n, 1e-3));
        assert!(!apart(&right, &right, n, 1e-3));
    }
}
