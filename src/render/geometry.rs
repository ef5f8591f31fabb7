//! The geometry stage of the renderer: per object, vertices to eye and clip
//! space, whole-object outcode tests, lights in range; per triangle, outcode
//! rejection, back-face culling, flat/Gouraud lighting, clipping in
//! homogeneous space and the viewport, then raster set-up.

use crate::lighting::{self, Light, LightKind, Material};
use crate::num::Fast32;
use crate::raster::{self, ScreenVert, Tri};
use crate::scene::{Colors, Normals, Object, Scene, Shading};
use crate::trace::NoTrace;
use crate::window::Window;
use nalgebra::{Matrix3, Matrix4, Vector3, Vector4};
use rayon::prelude::*;

use super::shade::{fast_light, fast_material, light_at};
use super::{Corner, Options, Stats, ViewSetup};

/// Everything the triangle loop needs about one object, in eye and clip space.
pub(super) struct Prep<'a> {
    obj: &'a Object,
    eye: Vec<[f32; 3]>,
    clip: Vec<[f32; 4]>,
    codes: Vec<u8>,
    inside: bool,
    vnormals: Vec<[f32; 3]>,
    lit: Option<Vec<[f32; 3]>>,
    closed: bool,
    pub(super) material: Material<Fast32>,
    pub(super) lights: Vec<Light<Fast32>>,
    pub(super) shading: Shading,
}

fn mul4(m: &Matrix4<f32>, p: [f32; 3]) -> [f32; 4] {
    let v = m * Vector4::new(p[0], p[1], p[2], 1.0);
    [v.x, v.y, v.z, v.w]
}

fn v3(a: [f32; 3]) -> Vector3<f32> {
    Vector3::new(a[0], a[1], a[2])
}

/// The surface colour of a corner.
fn surface(obj: &Object, face: u32, vertex: u32) -> [f32; 3] {
    match &obj.colors {
        Colors::One(c) => *c,
        Colors::Faces(v) => v[face as usize % v.len()],
        Colors::Vertices(v) => v[vertex as usize % v.len()],
    }
}

pub(super) fn prepare<'a>(
    obj: &'a Object,
    vs: &ViewSetup,
    scene_lights: &[Light<f32>],
    opt: &Options,
    stats: &mut Stats,
) -> Option<Prep<'a>> {
    let mesh = &obj.mesh;
    let shading = if opt.force_shading {
        opt.shading
    } else {
        obj.shading.unwrap_or(opt.shading)
    };
    let eye_from_model = vs.eye_from_world * obj.model;
    let clip_from_model = vs.clip_from_eye * eye_from_model;
    // Bounding box of the model, its corners' outcodes: whole-object tests.
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for p in &mesh.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let mut and = 0x3f;
    let mut or = 0;
    let c64: Matrix4<f64> = clip_from_model;
    for k in 0..8 {
        let q = [
            if k & 1 == 0 { lo[0] } else { hi[0] },
            if k & 2 == 0 { lo[1] } else { hi[1] },
            if k & 4 == 0 { lo[2] } else { hi[2] },
        ];
        let c = c64 * Vector4::new(q[0] as f64, q[1] as f64, q[2] as f64, 1.0);
        let code = crate::clip::outcode_clip_space(&c);
        and &= code;
        or |= code;
    }
    let ntris: u64 = mesh.faces.iter().map(|f| f.len() as u64 - 2).sum();
    if and != 0 {
        stats.objects_rejected += 1;
        stats.rejected += ntris;
        stats.tris_in += ntris;
        return None;
    }
    let inside = or == 0;
    if inside {
        stats.objects_inside += 1;
    }
    let e32: Matrix4<f32> = eye_from_model.cast();
    let c32: Matrix4<f32> = clip_from_model.cast();
    let eye: Vec<[f32; 3]> = mesh
        .positions
        .iter()
        .map(|&p| {
            let v = mul4(&e32, p);
            [v[0], v[1], v[2]]
        })
        .collect();
    let clip: Vec<[f32; 4]> = mesh.positions.iter().map(|&p| mul4(&c32, p)).collect();
    let codes: Vec<u8> = if inside {
        Vec::new()
    } else {
        clip.iter()
            .map(|c| crate::clip::outcode_clip_space(&Vector4::new(c[0], c[1], c[2], c[3])))
            .collect()
    };
    // Normals go to eye space by the inverse transpose of the linear part.
    let lin: Matrix3<f64> = eye_from_model.fixed_view::<3, 3>(0, 0).into();
    let nmat: Matrix3<f32> = lin
        .try_inverse()
        .map(|m| m.transpose())
        .unwrap_or(lin)
        .cast();
    let vnormals: Vec<[f32; 3]> = if shading == Shading::Flat {
        Vec::new()
    } else {
        match opt.normals {
            Normals::Average => obj
                .vnormals
                .iter()
                .map(|&n| {
                    let v = (nmat * v3(n)).normalize();
                    [v.x, v.y, v.z]
                })
                .collect(),
            Normals::Position => {
                // The text's draw3Dcg: the normal is the vertex position in
                // the (tilted) world, made a unit vector.
                let world: Matrix4<f32> = obj.model.cast();
                let rot: Matrix3<f32> = vs
                    .eye_from_world
                    .fixed_view::<3, 3>(0, 0)
                    .into_owned()
                    .cast();
                mesh.positions
                    .iter()
                    .map(|&p| {
                        let w = mul4(&world, p);
                        let v = rot * Vector3::new(w[0], w[1], w[2]);
                        let v = if v.norm() > 0.0 { v.normalize() } else { v };
                        [v.x, v.y, v.z]
                    })
                    .collect()
            }
        }
    };
    // Lights out of range of the whole object are never evaluated for it.
    let centre = mul4(
        &e32,
        [
            (lo[0] + hi[0]) / 2.0,
            (lo[1] + hi[1]) / 2.0,
            (lo[2] + hi[2]) / 2.0,
        ],
    );
    let centre = Vector3::new(centre[0], centre[1], centre[2]);
    let radius = eye
        .iter()
        .map(|p| (v3(*p) - centre).norm())
        .fold(0.0f32, f32::max);
    let mut lights = Vec::new();
    for l in scene_lights {
        let far = match (&l.kind, l.range) {
            (LightKind::Point { pos } | LightKind::Spot { pos, .. }, Some(r)) => {
                (pos - centre).norm() - radius > r
            }
            _ => false,
        };
        if far {
            stats.lights_skipped += 1;
        } else {
            lights.push(fast_light(l));
        }
    }
    let mut material = fast_material(&obj.material);
    if let Colors::One(c) = obj.colors {
        material.color = c.map(Fast32);
    }
    let has_spec = matches!(
        material.model,
        lighting::Model::Phong | lighting::Model::Blinn | lighting::Model::Specular
    );
    if material.ks.0 == 0.0 || !material.specular_on || !has_spec {
        material.specular_on = false;
        stats.specular_skipped += 1;
    }
    let closed = obj.closed;
    // Gouraud on a closed mesh without per-face colours: light each vertex once.
    let lit = if shading == Shading::Gouraud && closed && !matches!(obj.colors, Colors::Faces(_)) {
        let l: Vec<[f32; 3]> = (0..eye.len())
            .into_par_iter()
            .map(|v| {
                light_at(
                    &material,
                    &lights,
                    surface(obj, 0, v as u32),
                    v3(vnormals[v]),
                    v3(eye[v]),
                    vs.ortho,
                    &mut NoTrace,
                )
            })
            .collect();
        stats.lighting_evals += l.len() as u64;
        Some(l)
    } else {
        None
    };
    Some(Prep {
        obj,
        eye,
        clip,
        codes,
        inside,
        vnormals,
        lit,
        closed,
        material,
        lights,
        shading,
    })
}

/// Triangles per parallel chunk of the geometry stage.
const CHUNK: usize = 2048;

/// One chunk's set-up triangles and corners (kept between frames).
pub type ChunkBuf = (Vec<Tri>, Vec<[Corner; 3]>);

/// A clip-space vertex with its corner data.
#[derive(Clone, Copy)]
struct CV {
    c: [f32; 4],
    a: Corner,
}

/// Signed distance to clip plane `bit` (≥ 0 inside): w + x for x ≥ −w, w − x for x ≤ w, …
#[inline]
fn plane_dist(c: &[f32; 4], bit: usize) -> f32 {
    let v = c[bit / 2];
    if bit % 2 == 0 {
        c[3] + v
    } else {
        c[3] - v
    }
}

/// Clips a polygon against the planes whose bits are in `mask`
/// (Sutherland–Hodgman in homogeneous space: the intersection with a plane is
/// at t = d0/(d0 − d1) along the edge, and attributes are interpolated with
/// the same t, which is right because they are linear in clip space).
fn clip_poly(poly: &mut Vec<CV>, mask: u8, tmp: &mut Vec<CV>) {
    for bit in 0..6 {
        if mask & (1 << bit) == 0 {
            continue;
        }
        tmp.clear();
        for k in 0..poly.len() {
            let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
            let (dp, dq) = (plane_dist(&p.c, bit), plane_dist(&q.c, bit));
            if dp >= 0.0 {
                tmp.push(p);
            }
            if (dp >= 0.0) != (dq >= 0.0) {
                let t = dp / (dp - dq);
                let mut r = p;
                for i in 0..4 {
                    r.c[i] = p.c[i] + t * (q.c[i] - p.c[i]);
                }
                for i in 0..12 {
                    r.a[i] = p.a[i] + t * (q.a[i] - p.a[i]);
                }
                tmp.push(r);
            }
        }
        std::mem::swap(poly, tmp);
        if poly.len() < 3 {
            return;
        }
    }
}

/// Clip space → screen (pixels, rows from the top): perspective divide, the
/// window point, and the viewport formula of `window::viewport_xy`.
#[inline]
fn to_screen(c: &[f32; 4], win: &Window<f32>, w: f32, h: f32) -> ScreenVert {
    let inv_w = 1.0 / c[3];
    let (nx, ny, nz) = (c[0] * inv_w, c[1] * inv_w, c[2] * inv_w);
    let xp = win.left + (nx + 1.0) * 0.5 * win.width;
    let yp = win.bottom + (ny + 1.0) * 0.5 * win.height;
    let (px, py) = crate::window::viewport_xy(win, (&w, &h), (&xp, &yp));
    ScreenVert {
        x: px,
        y: h - py,
        z: nz,
        inv_w,
    }
}

/// The triangles of one object: cull, reject, light (flat: per face,
/// Gouraud: per corner), clip, set up; appended to `tris` and `corners` in
/// submission order (one copy from the parallel chunks).
#[allow(clippy::too_many_arguments)]
pub(super) fn triangles(
    p: &Prep,
    oi: u32,
    vs: &ViewSetup,
    scene: &Scene,
    opt: &Options,
    tris: &mut Vec<Tri>,
    corners: &mut Vec<[Corner; 3]>,
    pool: &mut Vec<ChunkBuf>,
) -> Stats {
    let mesh = &p.obj.mesh;
    let t = &p.obj.tris;
    let (w, h) = (opt.width, opt.height);
    // Per-chunk output buffers from the previous frame (no fresh pages).
    let n = t.tris.len().div_ceil(CHUNK);
    let mut bufs: Vec<ChunkBuf> = (0..n).map(|_| pool.pop().unwrap_or_default()).collect();
    let stats: Vec<Stats> = t
        .tris
        .par_chunks(CHUNK)
        .zip(t.face.par_chunks(CHUNK))
        .zip(bufs.par_iter_mut())
        .map(|((tris, faces), (out, corners))| {
            out.clear();
            corners.clear();
            let mut st = Stats::default();
            let (mut poly, mut tmp) = (Vec::with_capacity(9), Vec::with_capacity(9));
            for (tri, &face) in tris.iter().zip(faces) {
                st.tris_in += 1;
                let [i0, i1, i2] = tri.map(|i| i as usize);
                let (mut and, mut or) = (0u8, 0u8);
                if !p.inside {
                    and = p.codes[i0] & p.codes[i1] & p.codes[i2];
                    or = p.codes[i0] | p.codes[i1] | p.codes[i2];
                }
                if and != 0 {
                    st.rejected += 1;
                    continue;
                }
                // Facing: the text's test N·(toward viewer) with N = (v1 − v0) × (v2 − v0).
                let (e0, e1, e2) = (v3(p.eye[i0]), v3(p.eye[i1]), v3(p.eye[i2]));
                let n = (e1 - e0).cross(&(e2 - e0));
                let front = if vs.ortho {
                    n.z > 0.0
                } else {
                    n.dot(&e0) < 0.0
                };
                if !front && p.closed && scene.cull {
                    st.culled += 1;
                    continue;
                }
                // An open mesh shows its back: light the side that is seen.
                let flip = if !front && !p.closed { -1.0 } else { 1.0 };
                let idx = [i0, i1, i2];
                let mut cs = [[0.0f32; 12]; 3];
                for k in 0..3 {
                    let v = idx[k];
                    let s = surface(p.obj, face, v as u32);
                    let nrm = if p.vnormals.is_empty() {
                        [0.0; 3]
                    } else {
                        p.vnormals[v].map(|x| x * flip)
                    };
                    cs[k][3..6].copy_from_slice(&nrm);
                    cs[k][6..9].copy_from_slice(&p.eye[v]);
                    cs[k][9..12].copy_from_slice(&s);
                }
                match p.shading {
                    Shading::Flat => {
                        let fnrm = v3(mesh.face_normal(face as usize));
                        // The polygon's normal in eye space: the triangle's own
                        // for a triangle, Newell's average for a polygon.
                        let fe = face_normal_eye(p, face as usize).unwrap_or(fnrm) * flip;
                        let centre = (e0 + e1 + e2) / 3.0;
                        let c = light_at(
                            &p.material,
                            &p.lights,
                            cs[0][9..12].try_into().unwrap_or([1.0; 3]),
                            fe,
                            centre,
                            vs.ortho,
                            &mut NoTrace,
                        );
                        st.lighting_evals += 1;
                        for corner in &mut cs {
                            corner[0..3].copy_from_slice(&c);
                            corner[3..6].copy_from_slice(&[fe.x, fe.y, fe.z]);
                            corner[6..9].copy_from_slice(&[centre.x, centre.y, centre.z]);
                        }
                    }
                    Shading::Gouraud => {
                        for k in 0..3 {
                            let c = match &p.lit {
                                Some(l) => l[idx[k]],
                                None => {
                                    st.lighting_evals += 1;
                                    let c = &cs[k];
                                    light_at(
                                        &p.material,
                                        &p.lights,
                                        [c[9], c[10], c[11]],
                                        Vector3::new(c[3], c[4], c[5]),
                                        Vector3::new(c[6], c[7], c[8]),
                                        vs.ortho,
                                        &mut NoTrace,
                                    )
                                }
                            };
                            cs[k][0..3].copy_from_slice(&c);
                        }
                    }
                    Shading::Phong => {}
                }
                let cv = |k: usize| CV {
                    c: p.clip[idx[k]],
                    a: cs[k],
                };
                let mut emit = |a: &CV, b: &CV, c: &CV, st: &mut Stats| {
                    let sv = [a, b, c].map(|v| to_screen(&v.c, &vs.win, w as f32, h as f32));
                    match raster::setup(sv, w, h) {
                        Some((mut t, swap)) => {
                            t.obj = oi;
                            t.face = face;
                            out.push(t);
                            corners.push(if swap {
                                [a.a, c.a, b.a]
                            } else {
                                [a.a, b.a, c.a]
                            });
                            st.drawn += 1;
                        }
                        None => st.no_pixels += 1,
                    }
                };
                if or == 0 {
                    emit(&cv(0), &cv(1), &cv(2), &mut st);
                } else {
                    st.clipped += 1;
                    poly.clear();
                    poly.extend([cv(0), cv(1), cv(2)]);
                    clip_poly(&mut poly, or, &mut tmp);
                    for k in 1..poly.len().saturating_sub(1) {
                        let (a, b, c) = (poly[0], poly[k], poly[k + 1]);
                        emit(&a, &b, &c, &mut st);
                    }
                }
            }
            st
        })
        .collect();
    let mut st = Stats::default();
    tris.reserve(bufs.iter().map(|c| c.0.len()).sum());
    corners.reserve(bufs.iter().map(|c| c.1.len()).sum());
    for ((t, c), s) in bufs.iter().zip(&stats) {
        tris.extend_from_slice(t);
        corners.extend_from_slice(c);
        st.add(s);
    }
    pool.extend(bufs);
    st
}

/// The eye-space normal of polygon `f` (Newell's sum over its eye-space
/// vertices), `None` if degenerate.
fn face_normal_eye(p: &Prep, f: usize) -> Option<Vector3<f32>> {
    let face = &p.obj.mesh.faces[f];
    let p0 = v3(p.eye[face[0] as usize]);
    let mut n = Vector3::zeros();
    for w in face[1..].windows(2) {
        n += (v3(p.eye[w[0] as usize]) - p0).cross(&(v3(p.eye[w[1] as usize]) - p0));
    }
    let l = n.norm();
    (l > 0.0).then(|| n / l)
}
