//! Raw text inputs (flags) to typed values (expressions, names, angles),
//! and those evaluated at a precision: every failure names the field.

use crate::error::{Error, Result};
use crate::input::fields::{AngleIn, Num, Vec3In};
use crate::msg::Msg;
use crate::num::expr::components;
use crate::num::vec::V3;
use crate::num::{parse_expr, parse_vec3, Angle, Expr, Scalar};

/// A number expression from the field `field`.
pub fn expr(field: &str, text: &str) -> Result<Expr> {
    parse_expr(text).map_err(|m| Error::why(field, m.quoted(text)))
}

/// Three expressions from `x,y,z` text.
pub fn vec3_expr(field: &str, text: &str) -> Result<[Expr; 3]> {
    parse_vec3(text).map_err(|m| Error::why(field, m.quoted(text)))
}

/// A number flag.
pub fn num(field: &str, text: &str) -> Result<Num> {
    expr(field, text).map(Num)
}

/// A vector flag `X,Y,Z`.
pub fn vec3(field: &str, text: &str) -> Result<Vec3In> {
    let [x, y, z] = vec3_expr(field, text)?;
    Ok(Vec3In([Num(x), Num(y), Num(z)]))
}

/// An angle flag (degrees unless `rad` follows).
pub fn angle(field: &str, text: &str) -> Result<AngleIn> {
    Angle::parse(text)
        .map(AngleIn)
        .map_err(|m| Error::why(field, m.quoted(text)))
}

/// Evaluates a number at precision `T`, naming the field on failure.
pub fn eval<T: Scalar>(field: &str, n: &Num) -> Result<T> {
    n.0.eval::<T>().map_err(|m| Error::why(field, m))
}

/// Evaluates a vector.
pub fn eval3<T: Scalar>(field: &str, v: &Vec3In) -> Result<V3<T>> {
    Ok(V3::new(
        eval(field, &v[0])?,
        eval(field, &v[1])?,
        eval(field, &v[2])?,
    ))
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

/// `NAME=X,Y,Z` points of flag `field`, in the order given, names unique.
pub fn points3(field: &str, items: &[String]) -> Result<Vec<(String, Vec3In)>> {
    let mut out: Vec<(String, Vec3In)> = Vec::new();
    for it in items {
        let (name, rest) = named(field, it)?;
        if out.iter().any(|(n, _)| n == name) {
            return Err(Error::said(field, Msg::ErrPointTwice(name.to_string())));
        }
        out.push((name.to_string(), vec3(&point_field(field, name), rest)?));
    }
    Ok(out)
}

/// `NAME=X,Y` points of flag `field` (also `NAME=(X; Y)` with decimal
/// commas, as a vector flag is written).
pub fn points2(field: &str, items: &[String]) -> Result<Vec<(String, [Num; 2])>> {
    let mut out = Vec::new();
    for it in items {
        let (name, rest) = named(field, it)?;
        let parts = components(rest);
        let [x, y] = parts[..] else {
            return Err(Error::said(field, Msg::ErrNamedPair(it.to_string())));
        };
        let f = point_field(field, name);
        out.push((name.to_string(), [num(&f, x.text)?, num(&f, y.text)?]));
    }
    Ok(out)
}

/// The field of point `name` given by flag `field` (`point A`).
pub fn point_field(field: &str, name: &str) -> String {
    format!("{field} {name}")
}

/// `WxH` (a viewport size in pixels).
pub fn size(field: &str, text: &str) -> Result<[Num; 2]> {
    let (w, h) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| Error::said(field, Msg::ErrSize(text.to_string())))?;
    Ok([num(field, w)?, num(field, h)?])
}
