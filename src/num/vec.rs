//! Small vector helpers over `nalgebra::Vector3<T>` for any [`Scalar`],
//! using the scalar's stable products (nalgebra's own `norm`/`normalize`
//! need `RealField`, which the exact type cannot implement).

use crate::num::Scalar;
use nalgebra::Vector3;

/// A 3-vector of scalars.
pub type V3<T> = Vector3<T>;

/// (x, y, z).
#[inline(always)]
pub fn v3<T: Scalar>(x: T, y: T, z: T) -> V3<T> {
    Vector3::new(x, y, z)
}

/// a − b.
#[inline(always)]
pub fn sub<T: Scalar>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    v3(
        a[0].clone() - b[0].clone(),
        a[1].clone() - b[1].clone(),
        a[2].clone() - b[2].clone(),
    )
}

/// a + b.
#[inline(always)]
pub fn add<T: Scalar>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    v3(
        a[0].clone() + b[0].clone(),
        a[1].clone() + b[1].clone(),
        a[2].clone() + b[2].clone(),
    )
}

/// s·a.
#[inline(always)]
pub fn scale<T: Scalar>(a: &V3<T>, s: &T) -> V3<T> {
    v3(
        a[0].clone() * s.clone(),
        a[1].clone() * s.clone(),
        a[2].clone() * s.clone(),
    )
}

/// a / s (s ≠ 0; the caller checks), by [`Scalar::div3`].
#[inline(always)]
pub fn div<T: Scalar>(a: &V3<T>, s: &T) -> V3<T> {
    let [x, y, z] = T::div3([&a[0], &a[1], &a[2]], s);
    v3(x, y, z)
}

/// a · b = a₀b₀ + a₁b₁ + a₂b₂ (compensated in floats).
#[inline(always)]
pub fn dot<T: Scalar>(a: &V3<T>, b: &V3<T>) -> T {
    T::dot3([&a[0], &a[1], &a[2]], [&b[0], &b[1], &b[2]])
}

/// a × b = (a₁b₂ − a₂b₁, a₂b₀ − a₀b₂, a₀b₁ − a₁b₀), each component a
/// difference of products with one rounding.
#[inline(always)]
pub fn cross<T: Scalar>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    v3(
        T::diff_of_products(&a[1], &b[2], &a[2], &b[1]),
        T::diff_of_products(&a[2], &b[0], &a[0], &b[2]),
        T::diff_of_products(&a[0], &b[1], &a[1], &b[0]),
    )
}

/// |a| = √(a·a), without overflow or underflow in floats.
#[inline(always)]
pub fn norm<T: Scalar>(a: &V3<T>) -> T {
    T::hypot3(&a[0], &a[1], &a[2])
}

/// a / |a|, or `None` when a is the zero vector.
#[inline(always)]
pub fn normalize<T: Scalar>(a: &V3<T>) -> Option<(V3<T>, T)> {
    let m = norm(a);
    if m.is_zero_value() {
        None
    } else {
        Some((div(a, &m), m))
    }
}

/// Whether every component is finite.
pub fn is_finite<T: Scalar>(a: &V3<T>) -> bool {
    a.iter().all(Scalar::is_finite)
}

/// Converts a vector between precisions through exact values.
pub fn to_f64<T: Scalar>(a: &V3<T>) -> [f64; 3] {
    [a[0].to_f64(), a[1].to_f64(), a[2].to_f64()]
}
