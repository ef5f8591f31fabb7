//! TEMPORARY SHIM with the lighting contract's signatures, so that the
//! renderer compiles before the real `lighting` module lands on main. It is
//! deleted when main is merged.

use crate::num::Scalar;
use crate::trace::Trace;
use crate::vec::{self, V3};

/// Lighting model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Model {
    /// Ambient only.
    Ambient,
    /// Diffuse only.
    Diffuse,
    /// Specular only.
    Specular,
    /// Ambient + diffuse.
    Lambert,
    /// Ambient + diffuse + specular.
    Phong,
    /// Phong with the half-way vector.
    Blinn,
}

/// RGB.
pub type Rgb<T> = [T; 3];

/// Material.
#[derive(Clone, Debug, PartialEq)]
pub struct Material<T> {
    /// Model.
    pub model: Model,
    /// ka.
    pub ka: T,
    /// kd.
    pub kd: T,
    /// ks.
    pub ks: T,
    /// n.
    pub shininess: T,
    /// Surface colour.
    pub color: Rgb<T>,
    /// Specular colour.
    pub specular: Rgb<T>,
    /// Emissive.
    pub emissive: Rgb<T>,
    /// Specular on.
    pub specular_on: bool,
    /// Specular only where lit.
    pub specular_requires_lit: bool,
}

impl<T: Scalar> Material<T> {
    /// The text's defaults.
    pub fn text_default(color: Rgb<T>) -> Self {
        let f = |x: f64| T::from_f64(x);
        Material {
            model: Model::Phong,
            ka: f(0.4),
            kd: f(0.6),
            ks: f(0.7),
            shininess: f(4.0),
            color,
            specular: [T::one(), T::one(), T::one()],
            emissive: [T::zero(), T::zero(), T::zero()],
            specular_on: true,
            specular_requires_lit: false,
        }
    }
}

/// Light kind.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind<T> {
    /// Directional.
    Directional {
        /// Toward the light.
        dir: V3<T>,
    },
    /// Point.
    Point {
        /// Position.
        pos: V3<T>,
    },
    /// Spot.
    Spot {
        /// Position.
        pos: V3<T>,
        /// Direction.
        dir: V3<T>,
        /// Inner cone.
        theta: T,
        /// Outer cone.
        phi: T,
        /// Falloff.
        falloff: T,
    },
}

/// Light.
#[derive(Clone, Debug, PartialEq)]
pub struct Light<T> {
    /// Kind.
    pub kind: LightKind<T>,
    /// Ambient.
    pub ambient: Rgb<T>,
    /// Diffuse.
    pub diffuse: Rgb<T>,
    /// Specular.
    pub specular: Rgb<T>,
    /// Attenuation.
    pub attenuation: [T; 3],
    /// Range.
    pub range: Option<T>,
}

impl<T: Scalar> Light<T> {
    /// The text's light.
    pub fn text_default() -> Self {
        let w = [T::one(), T::one(), T::one()];
        Light {
            kind: LightKind::Directional {
                dir: vec::v3(T::zero(), T::zero(), T::one()),
            },
            ambient: w.clone(),
            diffuse: w.clone(),
            specular: w,
            attenuation: [T::one(), T::zero(), T::zero()],
            range: None,
        }
    }
}

/// Surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface<T> {
    /// N.
    pub normal: V3<T>,
    /// V.
    pub view: V3<T>,
    /// Position.
    pub position: V3<T>,
    /// Camera position (local viewer).
    pub camera: Option<V3<T>>,
}

/// Shaded.
#[derive(Clone, Debug, PartialEq)]
pub struct Shaded<T> {
    /// Clamped.
    pub color: Rgb<T>,
    /// Unclamped.
    pub unclamped: Rgb<T>,
    /// Ambient.
    pub ambient: Rgb<T>,
    /// Diffuse.
    pub diffuse: Rgb<T>,
    /// Specular.
    pub specular: Rgb<T>,
}

/// Shade (shim).
pub fn shade<T: Scalar>(
    mat: &Material<T>,
    lights: &[Light<T>],
    s: &Surface<T>,
    tr: &mut impl Trace,
) -> Shaded<T> {
    tr.step(|| crate::trace::Step::new("shim lighting", "shim"));
    let z = || [T::zero(), T::zero(), T::zero()];
    let (mut a, mut d, mut sp) = (z(), z(), z());
    let n = vec::normalize(&s.normal)
        .map(|x| x.0)
        .unwrap_or_else(|| s.normal.clone());
    let v = match &s.camera {
        Some(c) => vec::sub(c, &s.position),
        None => s.view.clone(),
    };
    let v = vec::normalize(&v).map(|x| x.0).unwrap_or(v);
    let (amb, dif, spe) = match mat.model {
        Model::Ambient => (true, false, false),
        Model::Diffuse => (false, true, false),
        Model::Specular => (false, false, true),
        Model::Lambert => (true, true, false),
        Model::Phong | Model::Blinn => (true, true, true),
    };
    let shin = mat.shininess.to_f64().round().max(0.0) as u32;
    for l in lights {
        let ld = match &l.kind {
            LightKind::Directional { dir } => dir.clone(),
            LightKind::Point { pos } | LightKind::Spot { pos, .. } => vec::sub(pos, &s.position),
        };
        let ld = vec::normalize(&ld).map(|x| x.0).unwrap_or(ld);
        let nl = vec::dot(&n, &ld);
        let nlp = if nl > T::zero() {
            nl.clone()
        } else {
            T::zero()
        };
        let r = vec::sub(&vec::scale(&n, &(T::from_i64(2) * nl.clone())), &ld);
        let rv = vec::dot(&r, &v);
        let rvp = if rv > T::zero() { rv } else { T::zero() };
        for k in 0..3 {
            if amb {
                a[k] += mat.ka.clone() * mat.color[k].clone() * l.ambient[k].clone();
            }
            if dif {
                d[k] += mat.kd.clone() * nlp.clone() * mat.color[k].clone() * l.diffuse[k].clone();
            }
            if spe && mat.specular_on && !(mat.specular_requires_lit && nlp.is_zero_value()) {
                sp[k] += mat.ks.clone()
                    * rvp.clone().powi(shin)
                    * mat.specular[k].clone()
                    * l.specular[k].clone();
            }
        }
    }
    let un: Rgb<T> =
        [0, 1, 2].map(|k| a[k].clone() + d[k].clone() + sp[k].clone() + mat.emissive[k].clone());
    let color = un.clone().map(|c| {
        if c < T::zero() {
            T::zero()
        } else if c > T::one() {
            T::one()
        } else {
            c
        }
    });
    Shaded {
        color,
        unclamped: un,
        ambient: a,
        diffuse: d,
        specular: sp,
    }
}
