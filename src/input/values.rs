//! Raw text inputs (flags, file values) to validated numbers and vectors:
//! every failure names the field.

use crate::error::{Error, Result};
use crate::msg::Msg;
use crate::num::vec::V3;
use crate::num::{parse_expr, parse_vec3, Angle, Expr, Scalar};

/// A number expression from the field `field`.
pub fn expr(field: &str, text: &str) -> Result<Expr> {
    parse_expr(text).map_err(|m| Error::why(field, m.quoted(text)))
}

/// Evaluates an expression at precision `T`, naming the field on failure.
pub fn eval<T: Scalar>(field: &str, e: &Expr) -> Result<T> {
    e.eval::<T>().map_err(|m| Error::why(field, m))
}

/// A number from text.
pub fn num<T: Scalar>(field: &str, text: &str) -> Result<T> {
    eval(field, &expr(field, text)?)
}

/// Three expressions from `x,y,z` text.
pub fn vec3_expr(field: &str, text: &str) -> Result<[Expr; 3]> {
    parse_vec3(text).map_err(|m| Error::why(field, m.quoted(text)))
}

/// Evaluates three expressions.
pub fn eval3<T: Scalar>(field: &str, e: &[Expr; 3]) -> Result<V3<T>> {
    Ok(V3::new(
        eval(field, &e[0])?,
        eval(field, &e[1])?,
        eval(field, &e[2])?,
    ))
}

/// A vector from `x,y,z` text.
pub fn vec3<T: Scalar>(field: &str, text: &str) -> Result<V3<T>> {
    eval3(field, &vec3_expr(field, text)?)
}

/// An angle (degrees unless `rad` follows) in degrees at precision `T`.
pub fn angle_deg<T: Scalar>(field: &str, text: &str) -> Result<T> {
    let a = Angle::parse(text).map_err(|m| Error::why(field, m.quoted(text)))?;
    a.degrees::<T>().map_err(|m| Error::why(field, m))
}

/// `NAME=rest`, with a name of letters, digits, `_` or `'`.
pub fn named<'a>(field: &str, text: &'a str) -> Result<(&'a str, &'a str)> {
    let (name, rest) = text
        .split_once('=')
        .ok_or_else(|| Error::said(field, Msg::ErrNamedPoint(text.to_string())))?;
    let name = name.trim();
    if name.is_empty()
        || !name
            .chars()
            .all(|c| c.is_alphanumeric() || c == '_' || c == '\'')
    {
        return Err(Error::said(field, Msg::ErrPointName(name.to_string())));
    }
    Ok((name, rest))
}

/// `NAME=X,Y,Z` points, in the order given, names unique.
pub fn points3<T: Scalar>(field: &str, items: &[String]) -> Result<Vec<(String, V3<T>)>> {
    let mut out: Vec<(String, V3<T>)> = Vec::new();
    for it in items {
        let (name, rest) = named(field, it)?;
        if out.iter().any(|(n, _)| n == name) {
            return Err(Error::said(field, Msg::ErrPointTwice(name.to_string())));
        }
        out.push((name.to_string(), vec3(&format!("{field} {name}"), rest)?));
    }
    Ok(out)
}

/// `NAME=X,Y` points.
pub fn points2<T: Scalar>(field: &str, items: &[String]) -> Result<Vec<(String, (T, T))>> {
    let mut out: Vec<(String, (T, T))> = Vec::new();
    for it in items {
        let (name, rest) = named(field, it)?;
        let parts = crate::num::expr::split_top_level(crate::num::expr::strip_outer(rest));
        if parts.len() != 2 {
            return Err(Error::said(field, Msg::ErrNamedPair(it.to_string())));
        }
        let f = format!("{field} {name}");
        out.push((name.to_string(), (num(&f, parts[0])?, num(&f, parts[1])?)));
    }
    Ok(out)
}

/// `WxH` (a viewport size in pixels).
pub fn size<T: Scalar>(field: &str, text: &str) -> Result<(T, T)> {
    let (w, h) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| Error::said(field, Msg::ErrSize(text.to_string())))?;
    Ok((num(field, w)?, num(field, h)?))
}
