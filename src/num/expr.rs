//! The input-number parser (docs/spec.md §2): integers, exact decimals (`0.1` is
//! 1/10, `2.5e-7`), `pi`, `sqrt(...)`, `+ - * / ^` and parentheses, parsed
//! once into an [`Expr`] and evaluated at any precision. A student's own
//! notation is accepted too: `√2`, `π`, the minus sign `−`, and a number
//! written directly before `sqrt`, `pi` or `(` (`5sqrt(2)` = 5·√2).

use super::{Real, Scalar};
use crate::msg::{NumErr, Want};
use std::fmt;

/// A parsed number expression.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Expr {
    /// A decimal literal as written (`12`, `0.1`, `2.5e-7`).
    Lit(String),
    /// π.
    Pi,
    /// √x.
    Sqrt(Box<Expr>),
    /// −x.
    Neg(Box<Expr>),
    /// x + y.
    Add(Box<Expr>, Box<Expr>),
    /// x − y.
    Sub(Box<Expr>, Box<Expr>),
    /// x · y.
    Mul(Box<Expr>, Box<Expr>),
    /// x / y.
    Div(Box<Expr>, Box<Expr>),
    /// xⁿ, n an integer.
    Pow(Box<Expr>, Box<Expr>),
}

impl Expr {
    /// This expression divided by π, when π is a factor of it written out:
    /// `pi/4` → `1/4`, `3*pi/2` → `3/2`, `pi/6 + pi/12` → `1/6 + 1/12`.
    pub fn over_pi(&self) -> Option<Expr> {
        let b = Box::new;
        match self {
            Expr::Pi => Some(Expr::Lit("1".into())),
            Expr::Neg(a) => Some(Expr::Neg(b(a.over_pi()?))),
            Expr::Add(x, y) => Some(Expr::Add(b(x.over_pi()?), b(y.over_pi()?))),
            Expr::Sub(x, y) => Some(Expr::Sub(b(x.over_pi()?), b(y.over_pi()?))),
            Expr::Mul(x, y) => match (x.over_pi(), y.over_pi()) {
                (Some(q), None) => Some(Expr::Mul(b(q), y.clone())),
                (None, Some(q)) => Some(Expr::Mul(x.clone(), b(q))),
                _ => None,
            },
            Expr::Div(x, y) => Some(Expr::Div(b(x.over_pi()?), y.clone())),
            _ => None,
        }
    }

    /// The value of the expression at precision `T`; an error message when a
    /// divisor is zero, a square root's argument negative, an exponent not a
    /// whole number, or the value not finite at that precision.
    pub fn eval<T: Scalar>(&self) -> Result<T, NumErr> {
        let v = self.eval_inner::<T>()?;
        // Exact values must also fit an f64, or nothing could show them.
        if v.is_finite() && v.to_f64().is_finite() {
            Ok(v)
        } else {
            let precision = T::PRECISION.name().to_string();
            Err(NumErr::NotFinite(self.to_string(), precision))
        }
    }

    fn eval_inner<T: Scalar>(&self) -> Result<T, NumErr> {
        Ok(match self {
            Expr::Lit(s) => {
                let r = Real::from_decimal(s).ok_or_else(|| NumErr::NotANumber(s.clone()))?;
                T::from_real(&r)
            }
            Expr::Pi => T::pi(),
            Expr::Sqrt(x) => {
                let v = x.eval_inner::<T>()?;
                if v < T::zero() {
                    return Err(NumErr::NegativeRoot(x.to_string()));
                }
                v.sqrt()
            }
            Expr::Neg(x) => -x.eval_inner::<T>()?,
            Expr::Add(a, b) => a.eval_inner::<T>()? + b.eval_inner::<T>()?,
            Expr::Sub(a, b) => a.eval_inner::<T>()? - b.eval_inner::<T>()?,
            Expr::Mul(a, b) => a.eval_inner::<T>()? * b.eval_inner::<T>()?,
            Expr::Div(a, b) => {
                let d = b.eval_inner::<T>()?;
                if d.is_zero_value() {
                    return Err(NumErr::DivZero(self.to_string()));
                }
                a.eval_inner::<T>()? / d
            }
            Expr::Pow(a, b) => {
                let base = a.eval_inner::<T>()?;
                let e = b.eval_inner::<f64>()?;
                if e.fract() != 0.0 || e.abs() > 1024.0 {
                    return Err(NumErr::Exponent(self.to_string()));
                }
                // |base|^e beyond 2^±8192 cannot lead to a value an f64 can
                // show, and exact powers that large would take long to form.
                if !base.is_zero_value() && (base.to_f64().abs().log2() * e).abs() > 8192.0 {
                    return Err(NumErr::PowerRange(self.to_string()));
                }
                let p = base.powi(e.abs() as u32);
                if e < 0.0 {
                    if p.is_zero_value() {
                        return Err(NumErr::DivZero(self.to_string()));
                    }
                    T::one() / p
                } else {
                    p
                }
            }
        })
    }
}

/// An expression written so that [`parse_expr`] reads it back to the same
/// value: each operand in parentheses where the reader would otherwise
/// group it another way. A sum or a sign under a product or a power; a
/// product or quotient after `/` (`a/(b*c)`, not `a/b*c`, which is
/// (a/b)·c); anything but a number, `pi` or a root as the base of a power
/// (`(2*3)^2`, not `2*3^2`). Where the grouping cannot change the value
/// (`a*b*c`, `a+b-c`) none is added.
impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use Wrap::{Base, Divisor, Factor, Left};
        match self {
            Expr::Lit(s) => write!(f, "{s}"),
            Expr::Pi => write!(f, "pi"),
            Expr::Sqrt(x) => write!(f, "sqrt({x})"),
            Expr::Neg(x) => write!(f, "-{}", Paren(x, Factor)),
            Expr::Add(a, b) => write!(f, "{a}+{b}"),
            Expr::Sub(a, b) => write!(f, "{a}-{}", Paren(b, Factor)),
            Expr::Mul(a, b) => write!(f, "{}*{}", Paren(a, Left), Paren(b, Factor)),
            Expr::Div(a, b) => write!(f, "{}/{}", Paren(a, Left), Paren(b, Divisor)),
            Expr::Pow(a, b) => write!(f, "{}^{}", Paren(a, Base), Paren(b, Divisor)),
        }
    }
}

/// Where an operand stands, which says what must be wrapped in
/// parentheses there.
#[derive(Clone, Copy)]
enum Wrap {
    /// The first operand of a product or quotient: sums (a sign is read
    /// first, `-a*b` is (−a)·b).
    Left,
    /// A factor after `*`, a negated term or a subtrahend: sums and
    /// what starts with a sign.
    Factor,
    /// After `/`, or an exponent: sums, signs, products and quotients.
    Divisor,
    /// The base of a power: everything but a number, `pi` and a root.
    Base,
}

/// Whether an expression is written starting with a sign: a negation,
/// or a product or quotient whose first operand is one (`-a*b`).
fn signed(e: &Expr) -> bool {
    match e {
        Expr::Neg(_) => true,
        Expr::Mul(a, _) | Expr::Div(a, _) => signed(a),
        _ => false,
    }
}

/// Writes an operand, in parentheses where [`Wrap`] says it needs them.
struct Paren<'a>(&'a Expr, Wrap);
impl fmt::Display for Paren<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sum = matches!(self.0, Expr::Add(..) | Expr::Sub(..)) || signed(self.0);
        let product = matches!(self.0, Expr::Mul(..) | Expr::Div(..));
        let wrap = match self.1 {
            Wrap::Left => matches!(self.0, Expr::Add(..) | Expr::Sub(..)),
            Wrap::Factor => sum,
            Wrap::Divisor => sum || product,
            Wrap::Base => sum || product || matches!(self.0, Expr::Pow(..)),
        };
        if wrap {
            write!(f, "({})", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

#[cfg(test)]
thread_local! {
    /// How many texts [`parse_expr`] has read on this thread: the tests
    /// count how often an answer is parsed.
    pub(crate) static PARSED: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// Parses one number expression; the error says what was expected and at
/// which character (1-based column).
pub fn parse_expr(text: &str) -> Result<Expr, NumErr> {
    #[cfg(test)]
    PARSED.with(|n| n.set(n.get() + 1));
    let chars: Vec<char> = text.chars().collect();
    if chars.len() > MAX_CHARS {
        return Err(NumErr::TooLong(chars.len(), MAX_CHARS));
    }
    let mut p = Parser {
        s: &chars,
        i: 0,
        depth: 0,
        ops: 0,
    };
    p.skip_ws();
    if p.at_end() {
        return Err(NumErr::Empty);
    }
    let e = p.sum()?;
    p.skip_ws();
    if !p.at_end() {
        return Err(p.err(Want::OperatorOrEnd));
    }
    Ok(e)
}

/// `text` without one pair of parentheses or brackets around all of it
/// (`(3,1,3)` → `3,1,3`, as answer files write points); `(1+2)*3` and
/// `(1),(2),(3)` are left as they are.
pub fn strip_outer(text: &str) -> &str {
    let t = text.trim();
    let (open, close) = match t.chars().next() {
        Some('(') => ('(', ')'),
        Some('[') => ('[', ']'),
        _ => return t,
    };
    let mut depth = 0i32;
    for (i, c) in t.char_indices() {
        if c == open {
            depth += 1;
        } else if c == close {
            depth -= 1;
            if depth == 0 {
                return if i + c.len_utf8() == t.len() {
                    &t[1..i]
                } else {
                    t
                };
            }
        }
    }
    t
}

/// Parses `x,y,z` (or `(x,y,z)`, `[x,y,z]`, or `x; y; z` with decimal
/// commas) into three expressions ([`components`]). A vector whose only
/// fault is its missing last `)` (`(3, 1, 3`) is told so: `)` expected at
/// the end.
pub fn parse_vec3(text: &str) -> Result<[Expr; 3], NumErr> {
    vec3_parts(text).map_err(|e| match missing_close(text) {
        Some(at) if vec3_parts(&format!("{text})")).is_ok() => {
            NumErr::Expected(Want::Close, at, None)
        }
        _ => e,
    })
}

/// Where a `)` is missing at the end of `text`: the column after its last
/// character, when exactly one `(` is left open there and no bracket
/// closes what it did not open.
pub fn missing_close(text: &str) -> Option<usize> {
    let mut open = Vec::new();
    for c in text.chars() {
        match c {
            '(' | '[' => open.push(c),
            ')' if open.pop() != Some('(') => return None,
            ']' if open.pop() != Some('[') => return None,
            _ => {}
        }
    }
    (open == ['(']).then(|| text.trim_end().chars().count() + 1)
}

fn vec3_parts(text: &str) -> Result<[Expr; 3], NumErr> {
    let parts = components(text);
    if parts.len() != 3 {
        return Err(NumErr::Count(parts.len(), text.to_string()));
    }
    let mut out = Vec::with_capacity(3);
    for part in &parts {
        let e = parse_expr(part.text)
            .map_err(|m| NumErr::Component(out.len(), part.text.trim().to_string(), Box::new(m)))?;
        out.push(e);
    }
    let [x, y, z]: [Expr; 3] = out
        .try_into()
        .map_err(|v: Vec<Expr>| NumErr::Count(v.len(), text.to_string()))?;
    Ok([x, y, z])
}

/// One part of a list as written, and where it starts in the whole text
/// (in characters, so that a reader's column can name the whole text's).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Part<'a> {
    /// The part's text (not trimmed).
    pub text: &'a str,
    /// How many characters of the whole text come before it.
    pub at: usize,
}

/// The parts of a list as people write it, in one pass: one pair of
/// parentheses or brackets around all of it is dropped ([`strip_outer`]);
/// then, when a `;` stands outside every parenthesis, the parts are
/// separated by `;` (and a comma inside a part is a decimal mark:
/// `(0,7071; 0; 0,7071)`, or a matrix's rows `1, 0; 0, 1`); otherwise by
/// the commas outside parentheses (`1/sqrt(2), 0, -1/sqrt(2)`).
pub fn components(text: &str) -> Vec<Part<'_>> {
    let inner = strip_outer(text);
    // where `inner` starts in `text`, in characters
    let lead = text[..text.len() - text.trim_start().len()].chars().count()
        + usize::from(inner.len() < text.trim().len());
    let sep = if split_at(inner, ';').len() > 1 {
        ';'
    } else {
        ','
    };
    split_at(inner, sep)
        .into_iter()
        .map(|p| Part {
            text: p.text,
            at: lead + p.at,
        })
        .collect()
}

/// Splits on `sep` outside parentheses and brackets, keeping where each part
/// starts (in characters).
pub fn split_at(text: &str, sep: char) -> Vec<Part<'_>> {
    let mut parts = Vec::new();
    let mut depth = 0i32;
    let (mut start, mut start_chars) = (0, 0);
    for (n, (i, c)) in text.char_indices().enumerate() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            c if c == sep && depth == 0 => {
                parts.push(Part {
                    text: &text[start..i],
                    at: start_chars,
                });
                start = i + c.len_utf8();
                start_chars = n + 1;
            }
            _ => {}
        }
    }
    parts.push(Part {
        text: &text[start..],
        at: start_chars,
    });
    parts
}

/// The unit an angle is written in (degrees unless `rad` follows it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngleUnit {
    /// Degrees (the default).
    Deg,
    /// Radians (written `0.785rad`).
    Rad,
}

/// An angle as typed: a number expression and its unit.
#[derive(Clone, Debug, PartialEq)]
pub struct Angle {
    /// The number.
    pub value: Expr,
    /// Its unit.
    pub unit: AngleUnit,
}

impl Angle {
    /// Parses `45`, `45deg`, `45°`, `pi/4 rad`, `0.785rad`.
    pub fn parse(text: &str) -> Result<Angle, NumErr> {
        let t = text.trim();
        let (body, unit) = if let Some(b) = t.strip_suffix("rad") {
            (b, AngleUnit::Rad)
        } else if let Some(b) = t.strip_suffix("deg").or_else(|| t.strip_suffix('°')) {
            (b, AngleUnit::Deg)
        } else {
            (t, AngleUnit::Deg)
        };
        Ok(Angle {
            value: parse_expr(body)?,
            unit,
        })
    }

    /// The angle in degrees at precision `T`. Radians written as a multiple
    /// of π (`pi/4 rad`) become q·180° exactly, so exact forms survive, as
    /// for `45`; other radians are converted with 180/π, which makes the
    /// value approximate.
    pub fn degrees<T: Scalar>(&self) -> Result<T, NumErr> {
        if self.unit == AngleUnit::Rad {
            if let Some(q) = self.value.over_pi() {
                return Ok(q.eval::<T>()? * T::from_i64(180));
            }
        }
        let v = self.value.eval::<T>()?;
        Ok(match self.unit {
            AngleUnit::Deg => v,
            AngleUnit::Rad => v * T::from_i64(180) / T::pi(),
        })
    }
}

impl fmt::Display for Angle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.unit {
            AngleUnit::Deg => write!(f, "{}°", self.value),
            AngleUnit::Rad => write!(f, "{} rad", self.value),
        }
    }
}

/// Parentheses, roots and signs nested deeper than this are refused (the
/// parser and the evaluator recurse once per level).
pub const MAX_DEPTH: usize = 100;

/// A number written with more characters than this is refused before it is
/// parsed (a 100,000-digit decimal would take seconds of exact arithmetic).
pub const MAX_CHARS: usize = 4000;

/// An expression with more operations than this is refused (evaluation
/// recurses once per operation of a chain like `1+1+…+1`).
pub const MAX_OPERATIONS: usize = 500;

struct Parser<'a> {
    s: &'a [char],
    i: usize,
    depth: usize,
    ops: usize,
}

impl Parser<'_> {
    fn at_end(&self) -> bool {
        self.i >= self.s.len()
    }
    fn peek(&self) -> Option<char> {
        self.s.get(self.i).copied()
    }
    fn skip_ws(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.i += 1;
        }
    }
    fn err(&self, expected: Want) -> NumErr {
        NumErr::Expected(expected, self.i + 1, self.peek())
    }
    fn eat(&mut self, c: char) -> bool {
        self.skip_ws();
        if self.peek() == Some(c) {
            self.i += 1;
            true
        } else {
            false
        }
    }
    /// `sqrt` written against a digit (`sqrt2`): eaten, the digit left.
    fn eat_sqrt_digits(&mut self) -> bool {
        let at = self.i + 4;
        let word = self
            .s
            .get(self.i..at)
            .is_some_and(|w| w.iter().copied().eq("sqrt".chars()));
        if word && self.s.get(at).is_some_and(char::is_ascii_digit) {
            self.i = at;
            true
        } else {
            false
        }
    }

    fn eat_word(&mut self, w: &str) -> bool {
        self.skip_ws();
        let n = w.chars().count();
        if self.s.len() >= self.i + n
            && self.s[self.i..self.i + n].iter().copied().eq(w.chars())
            && !self
                .s
                .get(self.i + n)
                .is_some_and(|c| c.is_ascii_alphanumeric())
        {
            self.i += n;
            true
        } else {
            false
        }
    }

    /// Enters one more level of nesting, or refuses too deep a nesting.
    fn enter(&mut self) -> Result<(), NumErr> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(NumErr::TooDeep(MAX_DEPTH, self.i + 1));
        }
        Ok(())
    }

    /// Counts one operation, or refuses too long an expression.
    fn op(&mut self) -> Result<(), NumErr> {
        self.ops += 1;
        if self.ops > MAX_OPERATIONS {
            return Err(NumErr::TooManyOps(MAX_OPERATIONS, self.i + 1));
        }
        Ok(())
    }

    /// sum := product (('+' | '-') product)*
    fn sum(&mut self) -> Result<Expr, NumErr> {
        let mut e = self.product()?;
        loop {
            if self.eat('+') {
                self.op()?;
                e = Expr::Add(Box::new(e), Box::new(self.product()?));
            } else if self.eat('-') || self.eat('−') {
                self.op()?;
                e = Expr::Sub(Box::new(e), Box::new(self.product()?));
            } else {
                return Ok(e);
            }
        }
    }

    /// product := unary (('*' | '/' | implicit) unary)*
    fn product(&mut self) -> Result<Expr, NumErr> {
        let mut e = self.unary()?;
        loop {
            if self.eat('*') || self.eat('×') || self.eat('·') {
                self.op()?;
                e = Expr::Mul(Box::new(e), Box::new(self.unary()?));
            } else if self.eat('/') {
                self.op()?;
                e = Expr::Div(Box::new(e), Box::new(self.unary()?));
            } else if self.implicit_factor_follows() {
                self.op()?;
                e = Expr::Mul(Box::new(e), Box::new(self.power()?));
            } else {
                return Ok(e);
            }
        }
    }

    /// A factor written directly after another: `5sqrt(2)`, `2pi`, `3(1+x)`, `2√3`.
    fn implicit_factor_follows(&mut self) -> bool {
        self.skip_ws();
        match self.peek() {
            Some('(' | '√' | 'π') => true,
            Some('s' | 'p') => {
                let rest: String = self.s[self.i..].iter().take(4).collect();
                rest.starts_with("sqrt") || rest.starts_with("pi")
            }
            _ => false,
        }
    }

    /// unary := ('-' | '+') unary | power
    fn unary(&mut self) -> Result<Expr, NumErr> {
        if self.eat('-') || self.eat('−') {
            self.op()?;
            self.enter()?;
            let e = self.unary();
            self.depth -= 1;
            Ok(Expr::Neg(Box::new(e?)))
        } else if self.eat('+') {
            self.enter()?;
            let e = self.unary();
            self.depth -= 1;
            e
        } else {
            self.power()
        }
    }

    /// power := atom ('^' unary)?
    fn power(&mut self) -> Result<Expr, NumErr> {
        let base = self.atom()?;
        if self.eat('^') {
            self.op()?;
            Ok(Expr::Pow(Box::new(base), Box::new(self.unary()?)))
        } else {
            Ok(base)
        }
    }

    /// atom := number | 'pi' | 'π' | 'sqrt' '(' sum ')' | '√' atom | '(' sum ')'
    fn atom(&mut self) -> Result<Expr, NumErr> {
        self.enter()?;
        let e = self.atom_inner();
        self.depth -= 1;
        e
    }

    fn atom_inner(&mut self) -> Result<Expr, NumErr> {
        self.skip_ws();
        if self.eat('(') {
            let e = self.sum()?;
            if !self.eat(')') {
                return Err(self.err(Want::Close));
            }
            return Ok(e);
        }
        if self.eat_word("pi") || self.eat('π') {
            return Ok(Expr::Pi);
        }
        if self.eat_sqrt_digits() {
            // `sqrt2` as people write √2: the root of the number that follows
            return Ok(Expr::Sqrt(Box::new(self.number()?)));
        }
        if self.eat_word("sqrt") {
            if !self.eat('(') {
                return Err(self.err(Want::OpenAfterSqrt));
            }
            self.op()?;
            let e = self.sum()?;
            if !self.eat(')') {
                return Err(self.err(Want::Close));
            }
            return Ok(Expr::Sqrt(Box::new(e)));
        }
        if self.eat('√') {
            self.op()?;
            return Ok(Expr::Sqrt(Box::new(self.power()?)));
        }
        self.number()
    }

    /// number := digits ('.' digits)? (('e' | 'E') ('+' | '-')? digits)?
    fn number(&mut self) -> Result<Expr, NumErr> {
        self.skip_ws();
        let start = self.i;
        let digits = |p: &mut Self| {
            let s = p.i;
            while p.peek().is_some_and(|c| c.is_ascii_digit()) {
                p.i += 1;
            }
            p.i - s
        };
        let mut n = digits(self);
        // The decimal mark: a point, or a comma between digits (`0,1`, as
        // Indonesian writes it); a comma anywhere else is no part of a number.
        let comma = self.peek() == Some(',')
            && n > 0
            && self.s.get(self.i + 1).is_some_and(|c| c.is_ascii_digit());
        if self.peek() == Some('.') || comma {
            self.i += 1;
            n += digits(self);
        }
        if n == 0 {
            self.i = start;
            return Err(self.err(Want::Number));
        }
        if matches!(self.peek(), Some('e' | 'E')) {
            let save = self.i;
            self.i += 1;
            if matches!(self.peek(), Some('+' | '-')) {
                self.i += 1;
            }
            if digits(self) == 0 {
                self.i = save;
            }
        }
        let lit = self.s[start..self.i].iter();
        Ok(Expr::Lit(
            lit.map(|&c| if c == ',' { '.' } else { c }).collect(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f(s: &str) -> f64 {
        parse_expr(s)
            .and_then(|e| e.eval::<f64>())
            .unwrap_or(f64::NAN)
    }

    #[test]
    fn arithmetic_and_precedence() {
        assert_eq!(f("1+2*3"), 7.0);
        assert_eq!(f("(1+2)*3"), 9.0);
        assert_eq!(f("-2^2"), -4.0);
        assert_eq!(f("2^-1"), 0.5);
        assert_eq!(f("2^3^2"), 512.0);
        assert_eq!(f("1/4"), 0.25);
        assert_eq!(f("-5*sqrt(4)/2"), -5.0);
        assert_eq!(f("5sqrt(4)"), 10.0);
        assert_eq!(f("√4+−1"), 1.0);
        assert_eq!(f("2.5e-1"), 0.25);
        assert_eq!(f(".5"), 0.5);
        assert!((f("pi/2") - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        // `sqrt2` as people write √2 (the root of the number only)
        assert_eq!(parse_expr("sqrt2/2"), parse_expr("√2/2"));
        assert_eq!(parse_expr("3sqrt2"), parse_expr("3√2"));
        assert_eq!(f("sqrt16^2"), 16.0);
        assert!(parse_expr("sqrtx").is_err());
    }

    #[test]
    fn a_number_longer_than_max_chars_is_refused_before_parsing() {
        let long = "1".repeat(100_000);
        let e = parse_expr(&long).unwrap_err();
        assert_eq!(e, NumErr::TooLong(100_000, MAX_CHARS));
        assert!(matches!(
            parse_expr(&"(".repeat(10_000)),
            Err(NumErr::TooLong(10_000, _))
        ));
        assert!(parse_expr(&"1".repeat(MAX_CHARS)).is_ok());
    }

    #[test]
    fn fovy_in_radians_as_a_multiple_of_pi_stays_exact() {
        let deg = |t: &str| Angle::parse(t).unwrap().degrees::<Real>().unwrap();
        assert_eq!(deg("pi/4 rad"), Real::from_i64(45));
        assert!(deg("pi/4 rad").is_exact());
        assert_eq!(deg("3*pi/2 rad"), Real::from_i64(270));
        assert_eq!(deg("pi/6 + pi/12 rad"), Real::from_i64(45));
        assert!(!deg("0.785 rad").is_exact());
    }

    #[test]
    fn a_parenthesized_vector_is_read_like_a_bare_one() {
        assert_eq!(strip_outer("(3,1,3)"), "3,1,3");
        assert_eq!(strip_outer(" [3, 1, 3] "), "3, 1, 3");
        assert_eq!(strip_outer("(1+2)*3"), "(1+2)*3");
        assert_eq!(strip_outer("(1),(2),(3)"), "(1),(2),(3)");
        assert_eq!(parse_vec3("(3,1,3)").unwrap(), parse_vec3("3,1,3").unwrap());
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_stack_overflow() {
        // 1,500 opening parentheses: refused at level MAX_DEPTH + 1 (10,000
        // are refused before parsing, as longer than MAX_CHARS).
        let deep = "(".repeat(1_500) + "1" + &")".repeat(1_500);
        let e = parse_expr(&deep).unwrap_err();
        // The 101st parenthesis is column 101.
        assert_eq!(e, NumErr::TooDeep(100, 101));
        let signs = "-".repeat(3_000) + "1";
        assert!(matches!(parse_expr(&signs), Err(NumErr::TooDeep(100, _))));
        let roots = "√".repeat(10_000) + "4";
        assert!(parse_expr(&roots).is_err());
        // A 1,500-term chain: too many operations.
        let chain = vec!["1"; 1_500].join("+");
        assert!(matches!(
            parse_expr(&chain),
            Err(NumErr::TooManyOps(500, _))
        ));
        // Within the limits: 100 levels of parentheses and 500 operations.
        let ok = "(".repeat(99) + "2" + &")".repeat(99);
        assert_eq!(f(&ok), 2.0);
        assert_eq!(f(&vec!["1"; 501].join("+")), 501.0);
    }

    #[test]
    fn errors_name_the_column() {
        let e = parse_expr("1+*2").unwrap_err();
        assert_eq!(e, NumErr::Expected(Want::Number, 3, Some('*')));
        assert_eq!(
            parse_expr("sqrt(2").unwrap_err(),
            NumErr::Expected(Want::Close, 7, None)
        );
        assert!(parse_expr("").is_err());
        assert!(parse_expr("1 2").is_err());
        let div = parse_expr("1/(2-2)").map(|e| e.eval::<f64>());
        assert!(matches!(div, Ok(Err(NumErr::DivZero(_)))));
        assert!(parse_expr("sqrt(-1)").unwrap().eval::<f64>().is_err());
        assert!(parse_expr("2^0.5").unwrap().eval::<f64>().is_err());
        assert!(parse_expr("1e999").unwrap().eval::<f64>().is_err());
    }

    /// Random expressions of small integers, `pi`, roots, signs and the
    /// five operators, nested up to four levels (the exponent a small
    /// whole number, so that every power can be evaluated).
    fn any_expr() -> impl proptest::strategy::Strategy<Value = Expr> {
        use proptest::prelude::*;
        let leaf = prop_oneof![
            (0u32..40).prop_map(|n| Expr::Lit(n.to_string())),
            Just(Expr::Lit("0.5".into())),
            Just(Expr::Pi),
        ];
        leaf.prop_recursive(4, 24, 2, |inner| {
            let b = Box::new;
            prop_oneof![
                inner.clone().prop_map(move |x| Expr::Sqrt(b(x))),
                inner.clone().prop_map(move |x| Expr::Neg(b(x))),
                (inner.clone(), inner.clone()).prop_map(move |(x, y)| Expr::Add(b(x), b(y))),
                (inner.clone(), inner.clone()).prop_map(move |(x, y)| Expr::Sub(b(x), b(y))),
                (inner.clone(), inner.clone()).prop_map(move |(x, y)| Expr::Mul(b(x), b(y))),
                (inner.clone(), inner.clone()).prop_map(move |(x, y)| Expr::Div(b(x), b(y))),
                (inner, 0u32..4)
                    .prop_map(move |(x, k)| Expr::Pow(b(x), b(Expr::Lit(k.to_string())))),
            ]
        })
    }

    proptest::proptest! {
        /// An expression written out reads back to the same value: exactly
        /// where it is exact (`-17/(17*sqrt(17))` was written
        /// `-17/17*sqrt(17)`, which is −√17, before), within rounding where
        /// π or a root without an exact form makes it approximate; an
        /// expression that cannot be evaluated (a zero divisor, a negative
        /// root) cannot be after reading either. Read and written again, it
        /// keeps its text.
        #[test]
        fn an_expression_written_out_reads_back_to_its_value(e in any_expr()) {
            let text = e.to_string();
            let back = parse_expr(&text).map_err(|err| format!("{text}: {err:?}"));
            proptest::prop_assert!(back.is_ok(), "{:?}", back);
            let back = back.unwrap_or(Expr::Pi);
            // once read, it is written the same way ever after
            let again = back.to_string();
            let third = parse_expr(&again).map(|x| x.to_string());
            proptest::prop_assert_eq!(third, Ok(again));
            match (e.eval::<Real>(), back.eval::<Real>()) {
                (Ok(x), Ok(y)) if x.is_exact() && y.is_exact() => {
                    proptest::prop_assert!(x == y, "{}: {:?} then {:?}", text, x, y);
                }
                (Ok(x), Ok(y)) => {
                    let (x, y) = (x.to_f64(), y.to_f64());
                    proptest::prop_assert!(
                        (x - y).abs() <= 1e-9 * x.abs().max(1.0),
                        "{}: {} then {}", text, x, y
                    );
                }
                (x, y) => proptest::prop_assert_eq!(x.is_ok(), y.is_ok(), "{}", text),
            }
        }
    }

    #[test]
    fn a_quotient_by_a_product_is_written_with_its_parentheses() {
        let e = parse_expr("-17/(17*sqrt(17))").unwrap();
        assert_eq!(e.to_string(), "-17/(17*sqrt(17))");
        let e = parse_expr("(2*3)^2").unwrap();
        assert_eq!(e.to_string(), "(2*3)^2");
        assert_eq!(f(&e.to_string()), 36.0);
        // a*b*c and a*b/c need none: the grouping cannot change the value
        assert_eq!(parse_expr("2*(3*4)").unwrap().to_string(), "2*3*4");
    }

    #[test]
    fn vectors_and_angles() {
        let v = parse_vec3("-2, 6, sqrt(2)/2").unwrap();
        assert_eq!(v[0].eval::<f64>(), Ok(-2.0));
        assert!(parse_vec3("1,2").is_err());
        let a = Angle::parse("pi/2rad").unwrap();
        assert!((a.degrees::<f64>().unwrap() - 90.0).abs() < 1e-12);
        assert_eq!(Angle::parse("45").unwrap().unit, AngleUnit::Deg);
    }
}
