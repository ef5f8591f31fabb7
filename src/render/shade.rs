//! The shading stage of the renderer: one call of `lighting::shade` at
//! [`Fast32`] per face (flat), vertex (Gouraud) or pixel (Phong), and the
//! colour of a covered pixel.

use crate::lighting::{self, Light, LightKind, Material, Surface};
use crate::num::Fast32;
use crate::raster::Tri;
use crate::scene::Shading;
use crate::trace::{NoTrace, Trace};
use nalgebra::Vector3;

use super::{Corner, Look};

/// One lighting evaluation through the calculator's `lighting::shade`, at
/// [`Fast32`] (plain f32 arithmetic).
#[inline]
pub fn light_at(
    mat: &Material<Fast32>,
    lights: &[Light<Fast32>],
    color: [f32; 3],
    n: Vector3<f32>,
    p: Vector3<f32>,
    ortho: bool,
    tr: &mut impl Trace,
) -> [f32; 3] {
    // A one-colour object's material already holds its colour: no copy.
    let color = color.map(Fast32);
    let recoloured;
    let m = if mat.color == color {
        mat
    } else {
        recoloured = Material {
            color,
            ..mat.clone()
        };
        &recoloured
    };
    lit(m, lights, n, p, ortho, tr)
}

/// The unit normal shade takes, from an interpolated one (shorter than 1).
#[inline(always)]
fn unit_normal(n: Vector3<f32>) -> Vector3<f32> {
    let len = n.norm();
    if len > 0.0 {
        n / len
    } else {
        n
    }
}

/// `lighting::shade` of a material that already holds the surface colour,
/// at the (not necessarily unit) normal `n` and eye-space point `p`.
#[inline(always)]
fn lit<T: Trace>(
    m: &Material<Fast32>,
    lights: &[Light<Fast32>],
    n: Vector3<f32>,
    p: Vector3<f32>,
    ortho: bool,
    tr: &mut T,
) -> [f32; 3] {
    let n = unit_normal(n);
    let f = |v: Vector3<f32>| Vector3::new(Fast32(v.x), Fast32(v.y), Fast32(v.z));
    // The tilt view's viewer is along +z; a camera is a local viewer at the
    // eye-space origin, V = norm(0 − P), which shade computes itself.
    let s = Surface {
        normal: f(n),
        view: f(Vector3::new(0.0, 0.0, 1.0)),
        position: f(p),
        camera: if ortho { None } else { Some(Vector3::zeros()) },
    };
    if T::ON {
        lighting::shade(m, lights, &s, tr).color.map(|c| c.0)
    } else {
        // The same computation, the color alone (nothing is recorded).
        lighting::shade_color(m, lights, &s).map(|c| c.0)
    }
}

/// A triangle's Phong attributes as planes over the pixel grid: lane 0 is
/// 1/w, lanes 1–9 are (normal, eye position, colour)/w, each
/// `c0 + cx·di + cy·dj` with (di, dj) the pixel's offset from the corner
/// (x0, y0) of the triangle's box. Quantities divided by w are affine in
/// screen space, so one division per pixel (by the 1/w lane) gives the
/// perspective-correct attributes: Σ λk·ak/wk / Σ λk/wk = Σ μk·ak.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Planes {
    c0: [f32; 12],
    cx: [f32; 12],
    cy: [f32; 12],
}

impl Planes {
    /// The planes of triangle `t` with corners `c` (from its screen
    /// barycentric planes λ1, λ2 and its 1/w at the vertices).
    pub fn of(t: &Tri, c: &[Corner; 3]) -> Planes {
        let iw = t.inv_w.map(f64::from);
        let (l1, l2) = (t.l1.map(f64::from), t.l2.map(f64::from));
        let mut p = Planes::default();
        for k in 0..10 {
            // Lane k: ak/wk at the three vertices (a = 1 for lane 0).
            let a = |v: usize| if k == 0 { 1.0 } else { f64::from(c[v][k + 2]) };
            let q0 = iw[0] * a(0);
            let (d1, d2) = (iw[1] * a(1) - q0, iw[2] * a(2) - q0);
            // q = q0·λ0 + q1·λ1 + q2·λ2 with λ0 = 1 − λ1 − λ2.
            p.c0[k] = (q0 + l1[0] * d1 + l2[0] * d2) as f32;
            p.cx[k] = (l1[1] * d1 + l2[1] * d2) as f32;
            p.cy[k] = (l1[2] * d1 + l2[2] * d2) as f32;
        }
        p
    }

    /// Unit normal, eye position and colour at pixel (i, j) of triangle `t`,
    /// perspective-correct.
    #[inline(always)]
    fn at(&self, t: &Tri, i: u32, j: u32) -> (Vector3<f32>, Vector3<f32>, [f32; 3]) {
        let (di, dj) = (i as f32 - t.bbox[0] as f32, j as f32 - t.bbox[2] as f32);
        let mut q = [0.0f32; 12];
        for (k, q) in q.iter_mut().enumerate() {
            *q = self.c0[k] + self.cx[k] * di + self.cy[k] * dj;
        }
        // 1/w > 0 inside a clipped triangle; 0 would need w = ∞.
        let r = if q[0] != 0.0 { 1.0 / q[0] } else { 0.0 };
        let n = Vector3::new(q[1] * r, q[2] * r, q[3] * r);
        let p = Vector3::new(q[4] * r, q[5] * r, q[6] * r);
        (n, p, [q[7] * r, q[8] * r, q[9] * r])
    }
}

/// Phong shading of a run of pixels `i0, i0 + 1, …` in row `j`, all covered
/// by triangle `t` with attribute planes `planes` ([`Planes::of`]; `out`
/// holds their 8-bit RGB): per pixel the same interpolation and
/// `lighting::shade` call as [`pixel_color`], with the triangle's data
/// looked up once per run and its material recoloured in place instead of
/// copied.
///
/// `m` is a working copy of the object's material (the caller keeps one per
/// object and band, so no copy is made per run); its colour is overwritten.
#[allow(clippy::too_many_arguments)]
pub fn phong_span(
    t: &Tri,
    planes: &Planes,
    look: &Look,
    m: &mut Material<Fast32>,
    j: u32,
    i0: u32,
    out: &mut [u8],
    ortho: bool,
) {
    for (k, px) in out.chunks_exact_mut(3).enumerate() {
        let (n, p, s) = planes.at(t, i0 + k as u32, j);
        m.color = s.map(Fast32);
        px.copy_from_slice(&to_u8(lit(m, &look.lights, n, p, ortho, &mut NoTrace)));
    }
}

/// A material at [`Fast32`].
pub fn fast_material(m: &Material<f32>) -> Material<Fast32> {
    Material {
        model: m.model,
        ka: Fast32(m.ka),
        kd: Fast32(m.kd),
        ks: Fast32(m.ks),
        shininess: Fast32(m.shininess),
        color: m.color.map(Fast32),
        specular: m.specular.map(Fast32),
        emissive: m.emissive.map(Fast32),
        specular_on: m.specular_on,
        specular_requires_lit: m.specular_requires_lit,
        ambient_color: m.ambient_color.map(|c| c.map(Fast32)),
    }
}

/// A light at [`Fast32`].
pub fn fast_light(l: &Light<f32>) -> Light<Fast32> {
    let v = |a: &Vector3<f32>| a.map(Fast32);
    Light {
        kind: match &l.kind {
            LightKind::Directional { dir } => LightKind::Directional { dir: v(dir) },
            LightKind::Point { pos } => LightKind::Point { pos: v(pos) },
            LightKind::Spot {
                pos,
                dir,
                theta,
                phi,
                falloff,
            } => LightKind::Spot {
                pos: v(pos),
                dir: v(dir),
                theta: Fast32(*theta),
                phi: Fast32(*phi),
                falloff: Fast32(*falloff),
            },
        },
        ambient: l.ambient.map(Fast32),
        diffuse: l.diffuse.map(Fast32),
        specular: l.specular.map(Fast32),
        attenuation: l.attenuation.map(Fast32),
        range: l.range.map(Fast32),
    }
}

/// The colour of pixel (i, j) covered by triangle `t`: flat and Gouraud
/// interpolate stored colours (no lighting here), Phong interpolates the
/// normal, position and surface colour and calls `lighting::shade`.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn pixel_color(
    t: &Tri,
    c: &[Corner; 3],
    i: u32,
    j: u32,
    looks: &[Look],
    ortho: bool,
    tr: &mut impl Trace,
) -> [f32; 3] {
    let look = &looks[t.obj as usize];
    match look.shading {
        Shading::Flat => [c[0][0], c[0][1], c[0][2]],
        Shading::Gouraud => {
            let m = t.mu(i, j);
            [0, 1, 2].map(|k| m[0] * c[0][k] + m[1] * c[1][k] + m[2] * c[2][k])
        }
        Shading::Phong => {
            let (n, p, s) = Planes::of(t, c).at(t, i, j);
            light_at(&look.material, &look.lights, s, n, p, ortho, tr)
        }
    }
}

/// A colour 0…1 as 8-bit: round(255·c), clamped.
#[inline]
pub fn to_u8(c: [f32; 3]) -> [u8; 3] {
    // 0 ≤ 255·c + ½ ≤ 255.5 after the clamp (NaN gives 0 either way), so
    // the cheaper i32 conversion truncates to the same byte.
    c.map(|x| (x.clamp(0.0, 1.0) * 255.0 + 0.5) as i32 as u8)
}
