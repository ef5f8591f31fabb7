//! The geometry stage of the renderer: per object, vertices to eye and clip
//! space, whole-object outcode tests, lights in range; per triangle, outcode
//! rejection, back-face culling, flat/Gouraud lighting, clipping in
//! homogeneous space and the viewport, then raster set-up.

use crate::input::scene::{Colors, Normals, Object, Scene, Shading};
use crate::num::Fast32;
use crate::render::raster::{self, ScreenVert, Tri, BAND};
use crate::stages::lighting::{self, Light, LightKind, Material};
use crate::stages::trace::{NoTrace, Trace};
use crate::stages::window::{self, Window};
use crate::stages::{camera, clip, projection};
use multiversion::multiversion;
use nalgebra::{Matrix3, Matrix4, Vector3, Vector4};
use rayon::prelude::*;
use std::time::Instant;

use super::shade::{light_as, light_at, material_as, Planes};
use super::{Corner, Options, Stats, ViewSetup};

/// Per-vertex arrays of an object (kept between frames, so a repeated
/// render touches no fresh pages): eye-space position with the outcode,
/// screen position and eye-space normal, apart so that the culling pass
/// reads only the first (one 16-byte load per vertex).
#[derive(Clone, Debug, Default)]
pub struct VertBufs {
    ec: Vec<EyeCode>,
    /// Depth z/w and 1/w ([`to_screen`]) of the vertices whose code is 0
    /// (0 for the others, which only clipped triangles use).
    zw: Vec<[f32; 2]>,
    /// Their screen positions snapped to 1/256 pixel
    /// ([`window::snap_pixel`]), x and y: on the image, so within
    /// 8192·256 = 2²¹.
    snapped: Vec<[i32; 2]>,
    /// Unit eye-space vertex normals (none for flat shading).
    vnormals: Vec<[f32; 3]>,
}

/// A vertex's eye-space position and its outcode in clip space (0 for all
/// when the object's box is inside), side by side for the culling pass.
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(16))]
struct EyeCode {
    e: [f32; 3],
    code: u32,
}

impl VertBufs {
    /// The eye-space position of vertex `i`.
    #[inline]
    fn eye(&self, i: usize) -> Vector3<f32> {
        v3(self.ec[i].e)
    }
}

/// Everything the triangle loop needs about one object.
pub(crate) struct Prep<'a> {
    pub(crate) obj: &'a Object,
    /// The per-vertex transforms (clip-space positions are made again
    /// where a triangle is clipped, rather than kept for every vertex).
    pub(crate) x: VertXf<'a>,
    v: &'a VertBufs,
    lit: Option<Vec<[f32; 3]>>,
    closed: bool,
    pub(crate) material: Material<Fast32>,
    pub(crate) lights: Vec<Light<Fast32>>,
    pub(crate) shading: Shading,
}

/// Vertices per parallel block of the per-vertex work.
const VBLOCK: usize = 4096;

/// Makes `v` n long, filling only the entries it did not have (the caller
/// then writes every entry).
fn size<T: Clone + Default>(v: &mut Vec<T>, n: usize) {
    v.truncate(n);
    v.resize(n, T::default());
}

fn mul4(m: &Matrix4<f32>, p: [f32; 3]) -> [f32; 4] {
    let v = m * Vector4::new(p[0], p[1], p[2], 1.0);
    [v.x, v.y, v.z, v.w]
}

pub(crate) fn v3(a: [f32; 3]) -> Vector3<f32> {
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

/// Where the vertex normals come from.
enum NormalSrc<'a> {
    /// None (flat shading).
    None,
    /// The object's unit model-space normals, one per vertex, to eye space
    /// by the inverse transpose n' = normalize(M⁻ᵀ·n).
    Model(&'a [[f32; 3]], Matrix3<f32>),
    /// The text's draw3Dcg: n = normalize(R·(model·p)), the vertex in the
    /// world rotated by the view's linear part R.
    Position(Matrix4<f32>, Matrix3<f32>),
}

/// The per-vertex transforms of an object.
pub(crate) struct VertXf<'a> {
    /// Model → eye.
    pub(crate) e32: Matrix4<f32>,
    /// Model → clip.
    pub(crate) c32: Matrix4<f32>,
    /// The eye-space centre of the bounding box.
    centre: Vector3<f32>,
    /// The whole object is inside the view volume (all codes 0).
    pub(crate) inside: bool,
    pub(crate) win: &'a Window<f32>,
    /// Image width and height.
    pub(crate) size: (f32, f32),
    normals: NormalSrc<'a>,
}

/// All per-vertex work of an object in one pass over parallel blocks: per
/// vertex p, eye position e = E·p; outcode of c = C·p (0 when the object
/// is inside); screen position ([`to_screen`]) and its snapped coordinates
/// when the code is 0; the eye-space normal. Returns max |e − centre|²
/// (its √ is the largest distance: √ is monotonic and correctly rounded).
fn vertices(pos: &[[f32; 3]], x: &VertXf, bufs: &mut VertBufs) -> f32 {
    let n = pos.len();
    size(&mut bufs.ec, n);
    size(&mut bufs.zw, n);
    size(&mut bufs.snapped, n);
    let vn = &mut bufs.vnormals;
    let blocks = n.div_ceil(VBLOCK);
    let vn: Vec<&mut [[f32; 3]]> = if matches!(x.normals, NormalSrc::None) {
        vn.clear();
        (0..blocks).map(|_| &mut [][..]).collect()
    } else {
        size(vn, n);
        vn.chunks_mut(VBLOCK).collect()
    };
    pos.par_chunks(VBLOCK)
        .zip(bufs.ec.par_chunks_mut(VBLOCK))
        .zip(bufs.zw.par_chunks_mut(VBLOCK))
        .zip(bufs.snapped.par_chunks_mut(VBLOCK))
        .zip(vn)
        .enumerate()
        .map(|(b, ((((ps, ec), ss), sn), vn))| {
            let out = VertOut { ec, ss, sn, vn };
            vertex_block(b * VBLOCK, ps, x, out)
        })
        .reduce(|| 0.0f32, f32::max)
}

/// One block's slices of the per-vertex arrays.
struct VertOut<'a> {
    ec: &'a mut [EyeCode],
    ss: &'a mut [[f32; 2]],
    sn: &'a mut [[i32; 2]],
    /// Empty for no normals.
    vn: &'a mut [[f32; 3]],
}

/// [`vertices`] for the block of vertices `ps`, numbers from `first`: per
/// vertex [`vertex_clip`], and [`to_screen`] when its code is 0; the
/// normals. Compiled for AVX2 and FMA too, chosen at run time (the same
/// bits: no operation is fused or reordered).
#[multiversion(targets("x86_64+avx2+fma"))]
fn vertex_block(first: usize, ps: &[[f32; 3]], x: &VertXf, o: VertOut) -> f32 {
    let mut far2 = 0.0f32;
    for (k, &p) in ps.iter().enumerate() {
        let (e, c, code) = vertex_clip(x, p, "", &mut NoTrace);
        far2 = far2.max((e - x.centre).norm_squared());
        o.ec[k] = EyeCode {
            e: [e.x, e.y, e.z],
            code: code as u32,
        };
        (o.ss[k], o.sn[k]) = if code == 0 {
            let (v, s) = to_screen(&c, x.win, x.size, "", &mut NoTrace);
            ([v.z, v.inv_w], s.map(|s| s as i32))
        } else {
            ([0.0; 2], [0; 2])
        };
    }
    match &x.normals {
        NormalSrc::None => {}
        NormalSrc::Model(ns, nmat) => {
            let ns = ns.get(first..).unwrap_or_default();
            for (&n, o) in ns.iter().zip(o.vn) {
                let v = (nmat * v3(n)).normalize();
                *o = [v.x, v.y, v.z];
            }
        }
        NormalSrc::Position(world, rot) => {
            for (&p, o) in ps.iter().zip(o.vn) {
                let w = mul4(world, p);
                let v = rot * Vector3::new(w[0], w[1], w[2]);
                let v = if v.norm() > 0.0 { v.normalize() } else { v };
                *o = [v.x, v.y, v.z];
            }
        }
    }
    far2
}

/// Object point `p` through the stages up to its outcode: eye coordinates
/// e = (V·M)·p ([`camera::eye_by_matrix`]), clip coordinates
/// c = (P·V·M)·p ([`projection::to_clip`]) and the clip-space outcode
/// ([`clip::outcode_clip`]; 0 untested when the object's box is inside).
#[inline(always)]
pub(crate) fn vertex_clip(
    x: &VertXf,
    p: [f32; 3],
    name: &str,
    tr: &mut impl Trace,
) -> (Vector3<f32>, Vector4<f32>, u8) {
    let p = v3(p);
    let e = camera::eye_by_matrix(&x.e32, name, &p, tr);
    let c = projection::to_clip(&x.c32, name, &p, tr);
    let code = if x.inside {
        0
    } else {
        clip::outcode_clip(&c, name, tr)
    };
    (e, c, code)
}

/// Clip coordinates to the screen: the perspective division
/// ([`projection::divide`]), the window point, viewport and row from the
/// top ([`window::to_pixel`]), and the position snapped to 1/256 pixel
/// ([`window::snap_pixel`]).
#[inline(always)]
pub(crate) fn to_screen(
    c: &Vector4<f32>,
    win: &Window<f32>,
    (w, h): (f32, f32),
    name: &str,
    tr: &mut impl Trace,
) -> (ScreenVert, [i64; 2]) {
    let (n, inv_w) = projection::divide(c, name, tr);
    let (x, y) = window::to_pixel(win, (&w, &h), name, (&n.x, &n.y), tr);
    let s = window::snap_pixel((x, y), name, tr);
    let v = ScreenVert {
        x,
        y,
        z: n.z,
        inv_w,
    };
    (v, s)
}

/// Everything the triangle loop needs about one object, or `None` when
/// its bounding box is wholly outside one plane of the view volume
/// (counted in `stats`): the whole-object outcode tests, the per-vertex
/// work ([`vertices`]), the lights within range, the material, and for
/// Gouraud on a closed mesh the lit vertices.
pub(crate) fn prepare<'a>(
    obj: &'a Object,
    vs: &'a ViewSetup,
    scene_lights: &[Light<f32>],
    opt: &Options,
    stats: &mut Stats,
    bufs: &'a mut VertBufs,
) -> Option<Prep<'a>> {
    let shading = shading_of(obj, opt);
    let eye_from_model = vs.eye_from_world * obj.model;
    let clip_from_model = vs.clip_from_eye * eye_from_model;
    let (and, or) = box_codes(obj, &clip_from_model);
    // Σ (polygon size − 2): the fan triangles made when the scene was read.
    let ntris = obj.tris.tris.len() as u64;
    if and != 0 {
        stats.objects_rejected += 1;
        stats.rejected += ntris;
        stats.tris_in += ntris;
        return None;
    }
    let inside = or == 0;
    stats.objects_inside += u64::from(inside);
    let e32: Matrix4<f32> = eye_from_model.cast();
    // Lights out of range of the whole object are never evaluated for it:
    // its reach is the box's centre and the largest distance from it.
    let [lo, hi] = obj.bounds;
    let centre = mul4(&e32, std::array::from_fn(|k| (lo[k] + hi[k]) / 2.0));
    let x = VertXf {
        e32,
        c32: clip_from_model.cast(),
        centre: Vector3::new(centre[0], centre[1], centre[2]),
        inside,
        win: &vs.win,
        size: (opt.width as f32, opt.height as f32),
        normals: normal_source(obj, vs, opt, shading, &eye_from_model),
    };
    let radius = vertices(&obj.mesh.positions, &x, bufs).sqrt();
    let bufs: &'a VertBufs = bufs;
    let lights = lights_in_range(scene_lights, &x.centre, radius, stats);
    let material = material_of(obj, stats);
    // Gouraud on a closed mesh without per-face colours: light each vertex once.
    let lit =
        (shading == Shading::Gouraud && obj.closed && !matches!(obj.colors, Colors::Faces(_)))
            .then(|| {
                let l: Vec<[f32; 3]> = (0..obj.mesh.positions.len())
                    .into_par_iter()
                    .map(|v| {
                        let (s, n) = (surface(obj, 0, v as u32), v3(bufs.vnormals[v]));
                        light_at(
                            &material,
                            &lights,
                            s,
                            n,
                            bufs.eye(v),
                            vs.ortho,
                            &mut NoTrace,
                        )
                    })
                    .collect();
                stats.lighting_evals += l.len() as u64;
                l
            });
    Some(Prep {
        obj,
        x,
        v: bufs,
        lit,
        closed: obj.closed,
        material,
        lights,
        shading,
    })
}

/// The AND and OR of the outcodes ([`clip::outcode_clip_space`]) of the
/// eight corners of the object's bounding box (made once, when the scene
/// was read): AND ≠ 0, the object is outside a plane; OR = 0, inside.
fn box_codes(obj: &Object, clip_from_model: &Matrix4<f64>) -> (u8, u8) {
    let [lo, hi] = obj.bounds;
    let (mut and, mut or) = (0x3f, 0);
    for k in 0..8 {
        let q: [f64; 3] =
            std::array::from_fn(|a| f64::from(if k & (1 << a) == 0 { lo[a] } else { hi[a] }));
        let code = clip::outcode_clip_space(&camera::apply(clip_from_model, &Vector3::from(q)));
        and &= code;
        or |= code;
    }
    (and, or)
}

/// Where an object's vertex normals come from: none for flat shading; its
/// model normals to eye space by the inverse transpose of the linear part
/// of V·M; or, the text's draw3Dcg, the vertex position in the (tilted)
/// world made a unit vector.
fn normal_source<'a>(
    obj: &'a Object,
    vs: &ViewSetup,
    opt: &Options,
    shading: Shading,
    eye_from_model: &Matrix4<f64>,
) -> NormalSrc<'a> {
    let lin: Matrix3<f64> = eye_from_model.fixed_view::<3, 3>(0, 0).into();
    let nmat: Matrix3<f32> = lin
        .try_inverse()
        .map(|m| m.transpose())
        .unwrap_or(lin)
        .cast();
    let rot = || {
        vs.eye_from_world
            .fixed_view::<3, 3>(0, 0)
            .into_owned()
            .cast()
    };
    match (shading, opt.normals) {
        (Shading::Flat, _) => NormalSrc::None,
        (_, Normals::Average) => NormalSrc::Model(&obj.vnormals, nmat),
        (_, Normals::Position) => NormalSrc::Position(obj.model.cast(), rot()),
    }
}

/// The scene's lights that may reach an object whose vertices lie within
/// `radius` of `centre` (eye space): a point or spot light with a range is
/// out when |pos − centre| − radius > range (counted in `stats`).
fn lights_in_range(
    lights: &[Light<f32>],
    centre: &Vector3<f32>,
    radius: f32,
    stats: &mut Stats,
) -> Vec<Light<Fast32>> {
    let mut out = Vec::new();
    for l in lights {
        let far = match (&l.kind, l.range) {
            (LightKind::Point { pos } | LightKind::Spot { pos, .. }, Some(r)) => {
                (pos - centre).norm() - radius > r
            }
            _ => false,
        };
        if far {
            stats.lights_skipped += 1;
        } else {
            out.push(light_as(l));
        }
    }
    out
}

/// An object's material at the renderer's precision: its one colour when
/// it has one, and no specular work when ks = 0, specular is off or the
/// model has no specular term (counted in `stats`).
fn material_of(obj: &Object, stats: &mut Stats) -> Material<Fast32> {
    let mut material: Material<Fast32> = material_as(&obj.material);
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
    material
}

/// How an object is shaded: `--shading` when forced, else its own or the
/// scene's.
pub(crate) fn shading_of(obj: &Object, opt: &Options) -> Shading {
    if opt.force_shading {
        opt.shading
    } else {
        obj.shading.unwrap_or(opt.shading)
    }
}

/// Triangles per parallel chunk of the geometry stage.
const CHUNK: usize = 2048;

/// A triangle that passed the outcode and facing tests (first pass).
#[derive(Clone, Copy, Debug)]
struct Kept {
    /// Its index in the object's triangle list.
    tri: u32,
    /// How many set-up triangles it gives: 0 (no pixel centre) or 1, or for
    /// a clipped one, its fan's triangles that cover a centre.
    out: u32,
    /// The clip planes it crosses (0: set up in the second pass; otherwise
    /// clipped and set up in the first, into [`ChunkBuf::clipped`]).
    or: u8,
    /// A back face of an open mesh (its normals are flipped).
    back: bool,
}

/// One chunk's work between the two passes of the triangle stage (kept
/// between frames, so a repeated render allocates nothing).
#[derive(Clone, Debug, Default)]
pub struct ChunkBuf {
    /// The triangles that passed the outcode and facing tests, in order.
    kept: Vec<Kept>,
    /// The set-up clipped triangles and their corners, in order.
    clipped: Vec<(Tri, [Corner; 3])>,
    /// Set-up triangles in the chunk: Σ `out` of `kept`.
    count: usize,
    /// Per band: the frame's numbers of the chunk's triangles in it.
    bins: Vec<Vec<u32>>,
    /// The chunk's counters.
    stats: Stats,
}

/// A clip-space vertex (x, y, z, w) followed by its corner data, as
/// [`clip::clip_polygon`] interpolates it.
pub(crate) type ClipVert = [f32; 16];

/// The clip coordinates of a [`ClipVert`].
pub(crate) fn clip_xyzw(v: &ClipVert) -> Vector4<f32> {
    Vector4::new(v[0], v[1], v[2], v[3])
}

/// The outcode and facing tests of triangle `idx` of an object: `None`
/// when it is rejected (all three vertices outside one plane) or culled (a
/// back face of a closed mesh), counted in `st`; else the planes it crosses
/// and whether it is a back face (of an open mesh).
#[inline(always)]
pub(crate) fn test(
    p: &Prep,
    idx: [usize; 3],
    vs: &ViewSetup,
    cull: bool,
    st: &mut Stats,
) -> Option<(u8, bool)> {
    let [a, b, c] = idx.map(|i| p.v.ec[i]);
    if a.code & b.code & c.code != 0 {
        st.rejected += 1;
        return None;
    }
    // Facing: the text's test N·(toward viewer) with N = (v1 − v0) × (v2 − v0).
    let (e0, e1, e2) = (v3(a.e), v3(b.e), v3(c.e));
    let n = (e1 - e0).cross(&(e2 - e0));
    let front = if vs.ortho {
        n.z > 0.0
    } else {
        n.dot(&e0) < 0.0
    };
    if !front && p.closed && cull {
        st.culled += 1;
        return None;
    }
    Some(((a.code | b.code | c.code) as u8, !front && !p.closed))
}

/// The corners of a kept triangle: per vertex the eye-space normal (flipped
/// on a back face), eye position and surface colour, and the lit colour —
/// flat: once per face, at the centroid with the polygon's normal; Gouraud:
/// per vertex (from the object's lit vertices when it has them); Phong:
/// none (lit per pixel). Lighting evaluations are counted in `st`.
pub(crate) fn corners(
    p: &Prep,
    idx: [usize; 3],
    face: u32,
    back: bool,
    ortho: bool,
    st: &mut Stats,
) -> [Corner; 3] {
    let mut cs = [[0.0f32; 12]; 3];
    corners_into(p, idx, face, back, ortho, st, &mut cs, [0, 1, 2]);
    cs
}

/// [`corners`] written straight into `out`: vertex k's corner goes to
/// `out[slot[k]]` (the set-up triangle's vertex order).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn corners_into(
    p: &Prep,
    idx: [usize; 3],
    face: u32,
    back: bool,
    ortho: bool,
    st: &mut Stats,
    out: &mut [Corner; 3],
    slot: [usize; 3],
) {
    // An open mesh shows its back: light the side that is seen.
    let flip = if back { -1.0 } else { 1.0 };
    // Flat: one colour, normal and position for the whole face.
    let flat = (p.shading == Shading::Flat).then(|| {
        // The polygon's normal in eye space: the triangle's own for a
        // triangle, Newell's average for a polygon.
        let fe = face_normal_eye(p, face as usize)
            .unwrap_or_else(|| v3(p.obj.mesh.face_normal(face as usize)))
            * flip;
        let e = idx.map(|i| p.v.eye(i));
        let centre = (e[0] + e[1] + e[2]) / 3.0;
        let s = surface(p.obj, face, idx[0] as u32);
        let c = light_at(&p.material, &p.lights, s, fe, centre, ortho, &mut NoTrace);
        st.lighting_evals += 1;
        (c, [fe.x, fe.y, fe.z], [centre.x, centre.y, centre.z])
    });
    for k in 0..3 {
        let v = idx[k];
        let s = surface(p.obj, face, v as u32);
        let (c, nrm, e) = if let Some(f) = flat {
            f
        } else {
            let nrm =
                p.v.vnormals
                    .get(v)
                    .map_or([0.0; 3], |n| n.map(|x| x * flip));
            let e = p.v.ec[v].e;
            let c = match (p.shading, &p.lit) {
                (Shading::Gouraud, Some(l)) => l[v],
                (Shading::Gouraud, None) => {
                    st.lighting_evals += 1;
                    let (n, e) = (v3(nrm), v3(e));
                    light_at(&p.material, &p.lights, s, n, e, ortho, &mut NoTrace)
                }
                // Phong: no lit colour, lit per pixel.
                _ => [0.0; 3],
            };
            (c, nrm, e)
        };
        out[slot[k]] = [
            c[0], c[1], c[2], nrm[0], nrm[1], nrm[2], e[0], e[1], e[2], s[0], s[1], s[2],
        ];
    }
}

/// The lighting evaluations [`corners`] makes for one triangle: flat 1,
/// Gouraud 3 (0 from the object's lit vertices), Phong 0.
fn corner_evals(p: &Prep) -> u64 {
    match (p.shading, &p.lit) {
        (Shading::Flat, _) => 1,
        (Shading::Gouraud, None) => 3,
        _ => 0,
    }
}

/// The first pass over one chunk of an object's triangles (those from
/// number `first` in its list): outcode and facing tests; for a triangle
/// inside the view volume, whether it covers a pixel centre
/// ([`raster::snap_box_of`]); a triangle that crosses a plane is lit,
/// clipped and set up here (few do).
///
/// On a CPU with AVX2 the same code, compiled a second time with AVX2
/// enabled, is chosen at run time; the results are the same bits.
#[allow(clippy::too_many_arguments)]
#[multiversion(targets("x86_64+avx2+fma"))]
fn first_pass(
    p: &Prep,
    oi: u32,
    first: usize,
    tris: &[[u32; 3]],
    faces: &[u32],
    vs: &ViewSetup,
    cull: bool,
    opt: &Options,
    buf: &mut ChunkBuf,
) {
    let (w, h) = (opt.width, opt.height);
    buf.kept.clear();
    buf.clipped.clear();
    buf.count = 0;
    let mut st = Stats {
        tris_in: tris.len() as u64,
        ..Stats::default()
    };
    let (mut poly, mut tmp) = (Vec::new(), Vec::new());
    for (n, (tri, &face)) in tris.iter().zip(faces).enumerate() {
        let idx = tri.map(|i| i as usize);
        let Some((or, back)) = test(p, idx, vs, cull, &mut st) else {
            continue;
        };
        let out = if or == 0 {
            match raster::snap_box_of(idx.map(|i| p.v.snapped[i].map(i64::from)), w, h) {
                Some(_) => {
                    st.drawn += 1;
                    1
                }
                None => {
                    st.no_pixels += 1;
                    0
                }
            }
        } else {
            let tri = (idx, face, oi, (first + n) as u32);
            clip_tri(
                p,
                tri,
                (or, back),
                vs,
                opt,
                buf,
                &mut st,
                (&mut poly, &mut tmp),
            )
        };
        buf.count += out as usize;
        buf.kept.push(Kept {
            tri: (first + n) as u32,
            out,
            or,
            back,
        });
    }
    buf.stats = st;
}

/// The polygon of triangle `idx` (with corners `cs`) clipped against the
/// planes `or` it crosses: its vertices' clip coordinates
/// ([`projection::to_clip`]) followed by their corners, through
/// [`clip::clip_polygon`], left in `poly`.
pub(crate) fn clipped_polygon(
    p: &Prep,
    idx: [usize; 3],
    cs: &[Corner; 3],
    or: u8,
    (poly, tmp): (&mut Vec<ClipVert>, &mut Vec<ClipVert>),
    tr: &mut impl Trace,
) {
    poly.clear();
    poly.extend((0..3).map(|k| {
        let q = v3(p.obj.mesh.positions[idx[k]]);
        let c = projection::to_clip(&p.x.c32, "", &q, &mut NoTrace);
        std::array::from_fn(|i| if i < 4 { c[i] } else { cs[k][i - 4] })
    }));
    clip::clip_polygon(poly, or, tmp, tr);
}

/// A triangle that crosses the clip planes `or` (vertices `idx` of polygon
/// `face` of object `oi`): lit, clipped, its fan set up into `buf.clipped`.
/// Returns how many of the fan's triangles cover a pixel centre. (Not
/// inlined: rare, and kept out of the culling loop's registers.)
#[allow(clippy::too_many_arguments)]
#[inline(never)]
fn clip_tri(
    p: &Prep,
    (idx, face, oi, src): ([usize; 3], u32, u32, u32),
    (or, back): (u8, bool),
    vs: &ViewSetup,
    opt: &Options,
    buf: &mut ChunkBuf,
    st: &mut Stats,
    (poly, tmp): (&mut Vec<ClipVert>, &mut Vec<ClipVert>),
) -> u32 {
    let (w, h) = (opt.width, opt.height);
    st.clipped += 1;
    let cs = corners(p, idx, face, back, vs.ortho, st);
    let before = buf.clipped.len();
    clipped_polygon(p, idx, &cs, or, (poly, tmp), &mut NoTrace);
    let size = (w as f32, h as f32);
    for k in 1..poly.len().saturating_sub(1) {
        let tri = [poly[0], poly[k], poly[k + 1]];
        let sv = tri.map(|v| to_screen(&clip_xyzw(&v), &vs.win, size, "", &mut NoTrace));
        match raster::setup_of(sv, w, h) {
            Some((mut t, swap)) => {
                t.obj = oi;
                t.src = src;
                let [a, b, c] = tri.map(|v| -> Corner { std::array::from_fn(|i| v[i + 4]) });
                buf.clipped
                    .push((t, if swap { [a, c, b] } else { [a, b, c] }));
                st.drawn += 1;
            }
            None => st.no_pixels += 1,
        }
    }
    (buf.clipped.len() - before) as u32
}

/// Where the second pass writes one chunk's set-up triangles: the frame's
/// slices for them, and the number of the first.
struct Dest<'t> {
    tris: &'t mut [Tri],
    /// Empty when no object needs corners to be shaded.
    corners: &'t mut [[Corner; 3]],
    /// Empty when no object is shaded by Phong.
    planes: &'t mut [Planes],
    first: u32,
}

/// The second pass over one chunk: lights and sets up the triangles the
/// first pass kept inside the view volume, copies the clipped ones, computes
/// Phong's attribute planes (`Planes::of`, for a Phong object; the default
/// otherwise), and bins them by band (rows y0..=y1 are in bands
/// y0/BAND..=y1/BAND), all straight into the frame's arrays.
///
/// On a CPU with AVX2 the same code, compiled a second time with AVX2
/// enabled (wider registers for the f64 planes), is chosen at run time;
/// the results are the same bits (no operation is fused or reordered).
#[multiversion(targets("x86_64+avx2+fma"))]
fn second_pass(p: &Prep, oi: u32, vs: &ViewSetup, opt: &Options, buf: &mut ChunkBuf, d: Dest) {
    let (w, h) = (opt.width, opt.height);
    let bands = (h as usize).div_ceil(BAND);
    buf.bins.resize_with(bands, Vec::new);
    buf.bins.iter_mut().for_each(Vec::clear);
    let t = &p.obj.tris;
    let phong = p.shading == Shading::Phong;
    let mut clipped = buf.clipped.iter();
    // The next output slot (a corner kept only when the frame keeps them),
    // and the frame's number of the next.
    let (mut k, mut cbuf) = (0, [[0.0f32; 12]; 3]);
    let mut st = Stats::default();
    for kept in &buf.kept {
        if kept.or != 0 {
            for (tri, cs) in clipped.by_ref().take(kept.out as usize) {
                let c = d.corners.get_mut(k).unwrap_or(&mut cbuf);
                d.tris[k].clone_from(tri);
                *c = *cs;
                finish(
                    d.first + k as u32,
                    phong,
                    (&d.tris[k], c, d.planes.get_mut(k)),
                    &mut buf.bins,
                );
                k += 1;
            }
            continue;
        }
        // One that covers no centre is not lit, but counted as if it were
        // (as it was before the raster test moved ahead of lighting).
        if kept.out == 0 {
            st.lighting_evals += corner_evals(p);
            continue;
        }
        let i = kept.tri as usize;
        let (idx, face) = (t.tris[i].map(|i| i as usize), t.face[i]);
        let Some(s) = raster::snap_box_of(idx.map(|i| p.v.snapped[i].map(i64::from)), w, h) else {
            continue;
        };
        let (tri, c) = (&mut d.tris[k], d.corners.get_mut(k).unwrap_or(&mut cbuf));
        let slot = if s.swap() { [0, 2, 1] } else { [0, 1, 2] };
        corners_into(p, idx, face, kept.back, vs.ortho, &mut st, c, slot);
        raster::setup_into(&idx.map(|i| p.v.zw[i]), &s, tri);
        tri.obj = oi;
        tri.src = kept.tri;
        finish(
            d.first + k as u32,
            phong,
            (tri, c, d.planes.get_mut(k)),
            &mut buf.bins,
        );
        k += 1;
    }
    buf.stats.lighting_evals += st.lighting_evals;
}

/// Set-up triangle number `n` of the frame is in place with its corners:
/// its Phong planes when the frame keeps planes (the default for another
/// shading) and its bins (rows y0..=y1 are in bands y0/BAND..=y1/BAND).
#[inline(always)]
fn finish(
    n: u32,
    phong: bool,
    (tri, c, pl): (&Tri, &[Corner; 3], Option<&mut Planes>),
    bins: &mut [Vec<u32>],
) {
    match pl {
        Some(pl) if phong => pl.set(tri, c),
        Some(pl) => *pl = Planes::default(),
        None => {}
    }
    let (b0, b1) = (tri.bbox[2] as usize / BAND, tri.bbox[3] as usize / BAND);
    for bin in &mut bins[b0..=b1] {
        bin.push(n);
    }
}

/// [`split_by`] of `v[range]`, or as many empty slices when `v` is not
/// kept (shorter than the range).
fn split_kept<T>(
    v: &mut [T],
    range: std::ops::Range<usize>,
    lens: impl Iterator<Item = usize>,
) -> Vec<&mut [T]> {
    match v.get_mut(range) {
        Some(s) => split_by(s, lens),
        None => lens.map(|_| &mut [][..]).collect(),
    }
}

/// Splits `s` into consecutive slices of the given lengths (the rest is
/// dropped).
fn split_by<T>(mut s: &mut [T], lens: impl Iterator<Item = usize>) -> Vec<&mut [T]> {
    let mut out = Vec::new();
    for n in lens {
        let (a, b) = std::mem::take(&mut s).split_at_mut(n);
        out.push(a);
        s = b;
    }
    out
}

/// The triangles of one object: reject, cull, light (flat: per face,
/// Gouraud: per corner), clip, set up, Phong's planes, binned by band; in
/// submission order. Two parallel passes over chunks: the first finds how
/// many set-up triangles each chunk gives, so the second writes them
/// straight into `tris`, `corners` and `planes` from index `first` (grown
/// as needed; nothing is copied between them). Returns the number written
/// and the counters (with `binning`: the time of merging the bins).
#[allow(clippy::too_many_arguments)]
pub(crate) fn triangles(
    p: &Prep,
    oi: u32,
    vs: &ViewSetup,
    scene: &Scene,
    opt: &Options,
    first: usize,
    out: &mut Output,
    pool: &mut Vec<ChunkBuf>,
) -> (usize, Stats) {
    let t = &p.obj.tris;
    // Per-chunk buffers from the previous frame (no fresh pages).
    let n = t.tris.len().div_ceil(CHUNK);
    let mut bufs: Vec<ChunkBuf> = (0..n).map(|_| pool.pop().unwrap_or_default()).collect();
    t.tris
        .par_chunks(CHUNK)
        .zip(t.face.par_chunks(CHUNK))
        .zip(bufs.par_iter_mut())
        .enumerate()
        .for_each(|(c, ((tris, faces), buf))| {
            first_pass(p, oi, c * CHUNK, tris, faces, vs, scene.cull, opt, buf);
        });
    let total: usize = bufs.iter().map(|b| b.count).sum();
    let end = first + total;
    let [keep_corners, keep_planes] = out.keep;
    if out.tris.len() < end {
        out.tris.resize(end, Tri::default());
    }
    if keep_corners && out.corners.len() < end {
        out.corners.resize(end, [[0.0; 12]; 3]);
    }
    if keep_planes && out.planes.len() < end {
        out.planes.resize(end, Planes::default());
    }
    let lens = || bufs.iter().map(|b| b.count);
    let starts: Vec<u32> = lens()
        .scan(first as u32, |s, n| {
            let a = *s;
            *s += n as u32;
            Some(a)
        })
        .collect();
    let dests: Vec<Dest> = split_by(&mut out.tris[first..end], lens())
        .into_iter()
        .zip(split_kept(out.corners, first..end, lens()))
        .zip(split_kept(out.planes, first..end, lens()))
        .zip(starts)
        .map(|(((tris, corners), planes), first)| Dest {
            tris,
            corners,
            planes,
            first,
        })
        .collect();
    bufs.par_iter_mut()
        .zip(dests)
        .for_each(|(buf, d)| second_pass(p, oi, vs, opt, buf, d));
    // Each band's triangles: the chunks' in order.
    let t0 = Instant::now();
    let bands = (opt.height as usize).div_ceil(BAND);
    out.bins.resize_with(bands, Vec::new);
    out.bins.par_iter_mut().enumerate().for_each(|(b, bin)| {
        for buf in &bufs {
            bin.extend_from_slice(&buf.bins[b]);
        }
    });
    let mut st = Stats {
        binning: t0.elapsed(),
        ..Stats::default()
    };
    for b in &bufs {
        st.add(&b.stats);
    }
    pool.extend(bufs);
    (total, st)
}

/// The frame's arrays the triangle stage fills: set-up triangles, their
/// corners and Phong planes (indexed alike), and per band the triangles
/// in it, in submission order.
pub(crate) struct Output<'f> {
    pub(crate) tris: &'f mut Vec<Tri>,
    pub(crate) corners: &'f mut Vec<[Corner; 3]>,
    pub(crate) planes: &'f mut Vec<Planes>,
    pub(crate) bins: &'f mut Vec<Vec<u32>>,
    /// Whether corners and planes are kept: corners when some object is
    /// shaded flat or Gouraud (they hold its colours), planes when some
    /// object is shaded by Phong (its per-pixel attributes).
    pub(crate) keep: [bool; 2],
}

/// The eye-space normal of polygon `f` (Newell's sum over its eye-space
/// vertices), `None` if degenerate.
fn face_normal_eye(p: &Prep, f: usize) -> Option<Vector3<f32>> {
    let face = &p.obj.mesh.faces[f];
    let p0 = p.v.eye(face[0] as usize);
    let mut n = Vector3::zeros();
    for w in face[1..].windows(2) {
        n += (p.v.eye(w[0] as usize) - p0).cross(&(p.v.eye(w[1] as usize) - p0));
    }
    let l = n.norm();
    (l > 0.0).then(|| n / l)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phong_corners_are_the_normal_position_and_colour() {
        // Phong's corners (the first branch of `corners_into`) against
        // their definition: no lit colour, the eye-space vertex normal
        // (flipped on a back face), the eye position, the surface colour.
        let text = include_str!("../../tests/common/mixed.toml");
        let s = Scene::parse(text, "mixed.toml", std::path::Path::new(".")).unwrap();
        let opt = Options::of(&s);
        let vs = super::super::view_setup(&s, opt.width, opt.height).unwrap();
        let mut checked = 0;
        for obj in &s.objects {
            let (mut stats, mut bufs) = (Stats::default(), VertBufs::default());
            let Some(p) = prepare(obj, &vs, &s.lights, &opt, &mut stats, &mut bufs) else {
                continue;
            };
            assert_eq!(p.shading, Shading::Phong);
            for (t, &face) in obj.tris.tris.iter().zip(&obj.tris.face) {
                let idx = t.map(|i| i as usize);
                for back in [false, true] {
                    let got = corners(&p, idx, face, back, vs.ortho, &mut stats);
                    let flip = if back { -1.0 } else { 1.0 };
                    for (k, &v) in idx.iter().enumerate() {
                        let (n, e) = (p.v.vnormals[v], p.v.ec[v].e);
                        let c = surface(obj, face, v as u32);
                        let want = [
                            0.0,
                            0.0,
                            0.0,
                            n[0] * flip,
                            n[1] * flip,
                            n[2] * flip,
                            e[0],
                            e[1],
                            e[2],
                            c[0],
                            c[1],
                            c[2],
                        ];
                        assert_eq!(got[k].map(f32::to_bits), want.map(f32::to_bits));
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 100, "{checked}");
    }
}
