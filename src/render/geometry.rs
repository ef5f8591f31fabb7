//! The geometry stage of the renderer: per object, vertices to eye and clip
//! space, whole-object outcode tests, lights in range; per triangle, outcode
//! rejection, back-face culling, flat/Gouraud lighting, clipping in
//! homogeneous space and the viewport, then raster set-up.

use crate::input::scene::{Colors, Normals, Object, Scene, Shading};
use crate::num::Fast32;
use crate::render::raster::{self, ScreenVert, Tri, BAND};
use crate::stages::lighting::{Light, LightKind, Material};
use crate::stages::trace::{NoTrace, Trace};
use crate::stages::window::{self, Window};
use crate::stages::{camera, clip, projection};
use multiversion::multiversion;
use nalgebra::{Matrix3, Matrix4, Vector3, Vector4};
use rayon::prelude::*;
use std::time::Instant;

use super::shade::{light_at, Planes};
use super::{Corner, Options, Stats, ViewSetup};

/// Per-vertex arrays of an object (kept between frames: a repeated render
/// touches no fresh pages), apart so that culling reads only the first.
#[derive(Clone, Debug, Default)]
pub struct VertBufs {
    ec: Vec<EyeCode>,
    /// Depth z/w and 1/w ([`to_screen`]), read only where the code is 0.
    zw: Vec<[f32; 2]>,
    /// The screen position snapped to 1/256 pixel ([`window::snap_pixel`]),
    /// read only where the code is 0: on the image, so within 2²¹.
    snapped: Vec<[i32; 2]>,
    /// Unit eye-space vertex normals (none for flat shading).
    vn: Vec<[f32; 3]>,
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
    fn eye(&self, i: usize) -> Vector3<f32> {
        self.ec[i].e.into()
    }
}

/// Everything the triangle loop needs about one object.
pub(crate) struct Prep<'a> {
    pub(crate) obj: &'a Object,
    /// The per-vertex transforms (clip coordinates are remade where clipped).
    pub(crate) x: VertXf<'a>,
    v: &'a VertBufs,
    /// Gouraud on a closed mesh: the lit colour of each vertex.
    lit: Option<Vec<[f32; 3]>>,
    pub(crate) material: Material<Fast32>,
    pub(crate) lights: Vec<Light<Fast32>>,
    pub(crate) shading: Shading,
}

/// Vertices per parallel block of the per-vertex work.
const VBLOCK: usize = 4096;

/// The surface colour of a corner.
fn surface(obj: &Object, face: u32, vertex: u32) -> [f32; 3] {
    match &obj.colors {
        Colors::One(c) => *c,
        Colors::Faces(v) => v[face as usize % v.len()],
        Colors::Vertices(v) => v[vertex as usize % v.len()],
    }
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
}

/// The positions and codes of an object's vertices, over parallel blocks
/// ([`vertex_block`]). Returns max |e − centre|² (its √ is the largest
/// distance: √ is monotonic and correctly rounded).
fn vertices(pos: &[[f32; 3]], x: &VertXf, bufs: &mut VertBufs) -> f32 {
    let n = pos.len();
    bufs.ec.resize(n, EyeCode::default());
    bufs.zw.resize(n, [0.0; 2]);
    bufs.snapped.resize(n, [0; 2]);
    pos.par_chunks(VBLOCK)
        .zip(bufs.ec.par_chunks_mut(VBLOCK))
        .zip(bufs.zw.par_chunks_mut(VBLOCK))
        .zip(bufs.snapped.par_chunks_mut(VBLOCK))
        .map(|(((ps, ec), zw), sn)| vertex_block(ps, x, ec, zw, sn))
        .reduce(|| 0.0f32, f32::max)
}

/// Per vertex p of a block, e = E·p and the outcode of c = C·p
/// ([`vertex_clip`]), and [`to_screen`]. Returns max |e − centre|².
/// Compiled for AVX2 and FMA too, chosen at run time (the same bits).
#[multiversion(targets("x86_64+avx2+fma"))]
fn vertex_block(
    ps: &[[f32; 3]],
    x: &VertXf,
    ec: &mut [EyeCode],
    zw: &mut [[f32; 2]],
    sn: &mut [[i32; 2]],
) -> f32 {
    let mut far2 = 0.0f32;
    for (k, &p) in ps.iter().enumerate() {
        let (e, c, code) = vertex_clip(x, p, "", &mut NoTrace);
        far2 = far2.max((e - x.centre).norm_squared());
        ec[k] = EyeCode {
            e: e.into(),
            code: code.into(),
        };
        let (v, s) = to_screen(&c, x.win, x.size, "", &mut NoTrace);
        (zw[k], sn[k]) = ([v.z, v.inv_w], s.map(|s| s as i32));
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
    let p = Vector3::from(p);
    let e = camera::eye_by_matrix(&x.e32, name, &p, tr);
    let c = projection::to_clip(&x.c32, name, &p, tr);
    let code = (!x.inside).then(|| clip::outcode_clip(&c, name, tr));
    (e, c, code.unwrap_or(0))
}

/// Clip coordinates to the screen: perspective division ([`projection::divide`]),
/// window point, viewport and row from the top ([`window::to_pixel`]), and
/// the position snapped to 1/256 pixel ([`window::snap_pixel`]).
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

/// Everything the triangle loop needs about one object ([`Prep`]), or `None`
/// when its bounding box is wholly outside one plane of the view volume.
pub(crate) fn prepare<'a>(
    obj: &'a Object,
    vs: &'a ViewSetup,
    lights: &[Light<f32>],
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
    stats.objects_inside += u64::from(or == 0);
    let e32: Matrix4<f32> = eye_from_model.cast();
    // Lights out of range of the whole object are never evaluated for it:
    // its reach is the box's centre and the largest distance from it.
    let [lo, hi] = obj.bounds;
    let mid = Vector3::from_fn(|k, _| (lo[k] + hi[k]) / 2.0);
    let x = VertXf {
        e32,
        c32: clip_from_model.cast(),
        centre: camera::eye_by_matrix(&e32, "", &mid, &mut NoTrace),
        inside: or == 0,
        win: &vs.win,
        size: (opt.width as f32, opt.height as f32),
    };
    let radius = vertices(&obj.mesh.positions, &x, bufs).sqrt();
    let normals = (shading != Shading::Flat).then_some(opt.normals);
    vertex_normals(obj, vs, normals, &eye_from_model, &mut bufs.vn);
    // A point or spot light with a range is out of reach when
    // |pos − centre| − radius > range.
    let far = |l: &&Light<f32>| match (&l.kind, l.range) {
        (LightKind::Point { pos } | LightKind::Spot { pos, .. }, Some(r)) => {
            (pos - x.centre).norm() - radius > r
        }
        _ => false,
    };
    let near: Vec<_> = lights.iter().filter(|l| !far(l)).map(Light::cast).collect();
    stats.lights_skipped += (lights.len() - near.len()) as u64;
    let mut p = Prep {
        obj,
        x,
        v: bufs,
        lit: None,
        material: material_of(obj, stats),
        lights: near,
        shading,
    };
    // Gouraud on a closed mesh without per-face colours: light each vertex once.
    if shading == Shading::Gouraud && obj.closed && !matches!(obj.colors, Colors::Faces(_)) {
        let lit: Vec<[f32; 3]> = (0..obj.mesh.positions.len())
            .into_par_iter()
            .map(|v| {
                let (s, n, e) = (surface(obj, 0, v as u32), p.v.vn[v].into(), p.v.eye(v));
                light_at(&p.material, &p.lights, s, n, e, vs.ortho, &mut NoTrace)
            })
            .collect();
        stats.lighting_evals += lit.len() as u64;
        p.lit = Some(lit);
    }
    Some(p)
}

/// The AND and OR of the outcodes ([`clip::outcode_clip_space`]) of the
/// eight corners of the object's bounding box (made once, when the scene
/// was read): AND ≠ 0, the object is outside a plane; OR = 0, inside.
fn box_codes(obj: &Object, clip_from_model: &Matrix4<f64>) -> (u8, u8) {
    let [lo, hi] = obj.bounds;
    let (mut and, mut or) = (0x3f, 0);
    for k in 0..8 {
        let q = Vector3::from_fn(|a, _| f64::from(if k & (1 << a) == 0 { lo[a] } else { hi[a] }));
        let code = clip::outcode_clip_space(&camera::apply(clip_from_model, &q));
        and &= code;
        or |= code;
    }
    (and, or)
}

/// An object's unit eye-space vertex normals into `vn`: none (flat
/// shading); its model normals by the inverse transpose of the linear part
/// L of V·M, n' = normalize(L⁻ᵀ·n); or the text's draw3Dcg,
/// n = normalize(R·(M·p)), the vertex in the world turned by the view's R.
fn vertex_normals(
    obj: &Object,
    vs: &ViewSetup,
    normals: Option<Normals>,
    eye_from_model: &Matrix4<f64>,
    vn: &mut Vec<[f32; 3]>,
) {
    let lin: Matrix3<f64> = eye_from_model.fixed_view::<3, 3>(0, 0).into();
    let rot: Matrix3<f64> = vs.eye_from_world.fixed_view::<3, 3>(0, 0).into();
    let (ns, ps) = (obj.vnormals.par_iter(), obj.mesh.positions.par_iter());
    match normals {
        None => vn.clear(),
        Some(Normals::Average) => {
            let nmat: Matrix3<f32> = lin.try_inverse().map_or(lin, |m| m.transpose()).cast();
            ns.map(|&n| (nmat * Vector3::from(n)).normalize().into())
                .collect_into_vec(vn);
        }
        Some(Normals::Position) => {
            let (world, rot): (Matrix4<f32>, Matrix3<f32>) = (obj.model.cast(), rot.cast());
            ps.map(|&p| {
                let v = rot * camera::to_world(&world, "", &p.into(), &mut NoTrace);
                (if v.norm() > 0.0 { v.normalize() } else { v }).into()
            })
            .collect_into_vec(vn);
        }
    }
}

/// An object's material at the renderer's precision: its one colour if it has
/// one; no specular work when ks = 0, specular is off or the model has none.
fn material_of(obj: &Object, stats: &mut Stats) -> Material<Fast32> {
    let mut material: Material<Fast32> = obj.material.cast();
    if let Colors::One(c) = obj.colors {
        material.color = c.map(Fast32);
    }
    let (_, _, has_spec) = material.model.terms();
    if material.ks.0 == 0.0 || !material.specular_on || !has_spec {
        material.specular_on = false;
        stats.specular_skipped += 1;
    }
    material
}

/// How an object is shaded: `--shading` when forced, else its own or the
/// scene's.
pub(crate) fn shading_of(obj: &Object, opt: &Options) -> Shading {
    obj.shading
        .filter(|_| !opt.force_shading)
        .unwrap_or(opt.shading)
}

/// Triangles per parallel chunk of the geometry stage.
const CHUNK: usize = 2048;

/// A set-up triangle the first pass found: the object's triangle `i` (a back
/// face of an open mesh when `back`), or the next of the chunk's clipped ones.
#[derive(Clone, Copy, Debug)]
enum Kept {
    Tri { i: u32, back: bool },
    Clipped,
}

/// One chunk's work between the two passes of the triangle stage (kept
/// between frames: a repeated render allocates nothing).
#[derive(Clone, Debug, Default)]
pub struct ChunkBuf {
    /// The set-up triangles the first pass found, in order.
    kept: Vec<Kept>,
    /// The set-up clipped triangles and their corners, in order.
    clipped: Vec<(Tri, [Corner; 3])>,
    /// Working space of [`clipped_polygon`].
    poly: [Vec<ClipVert>; 2],
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
    Vector4::from_column_slice(&v[..4])
}

/// The outcode and facing tests of triangle `idx`: `None` when rejected (all
/// vertices outside one plane) or culled (a back face of a closed mesh); else
/// the planes it crosses and whether it is a back face (of an open mesh).
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
    let [e0, e1, e2] = [a.e, b.e, c.e].map(Vector3::from);
    let n = (e1 - e0).cross(&(e2 - e0));
    let front = if vs.ortho { n.z } else { -n.dot(&e0) } > 0.0;
    if !front && p.obj.closed && cull {
        st.culled += 1;
        return None;
    }
    Some(((a.code | b.code | c.code) as u8, !front && !p.obj.closed))
}

/// The corners of a kept triangle: per vertex the eye-space normal (flipped
/// on a back face), eye position, surface colour and lit colour — flat: once
/// per face, at the centroid; Gouraud: per vertex (from the object's lit
/// vertices if it has them); Phong: none (lit per pixel).
#[inline(always)]
pub(crate) fn corners(
    p: &Prep,
    idx: [usize; 3],
    face: u32,
    back: bool,
    ortho: bool,
    st: &mut Stats,
) -> [Corner; 3] {
    // An open mesh shows its back: light the side that is seen.
    let flip = if back { -1.0 } else { 1.0 };
    // Flat: colour, normal and position of the whole face; the polygon's
    // normal n/|n|, n = Newell's sum over its eye-space vertices (the
    // triangle's own for a triangle; the model's if n = 0).
    let flat = (p.shading == Shading::Flat).then(|| {
        let poly = &p.obj.mesh.faces[face as usize];
        let d = |k: u32| p.v.eye(k as usize) - p.v.eye(poly[0] as usize);
        let n: Vector3<f32> = poly[1..].windows(2).map(|w| d(w[0]).cross(&d(w[1]))).sum();
        let n = (n.norm() > 0.0).then(|| n / n.norm());
        let n = n.unwrap_or_else(|| p.obj.mesh.face_normal(face as usize).into()) * flip;
        let e = idx.map(|i| p.v.eye(i));
        let centre = (e[0] + e[1] + e[2]) / 3.0;
        let s = surface(p.obj, face, idx[0] as u32);
        st.lighting_evals += 1;
        let c = light_at(&p.material, &p.lights, s, n, centre, ortho, &mut NoTrace);
        [c, n.into(), centre.into()]
    });
    let mut out = [[0.0f32; 12]; 3];
    for (o, &v) in out.iter_mut().zip(&idx) {
        let s = surface(p.obj, face, v as u32);
        let [c, n, e] = if let Some(f) = flat {
            f
        } else {
            let (n, e) = (p.v.vn[v].map(|x| x * flip), p.v.ec[v].e);
            let c = match (p.shading, &p.lit) {
                (Shading::Gouraud, Some(l)) => l[v],
                (Shading::Gouraud, None) => {
                    st.lighting_evals += 1;
                    let (n, e) = (n.into(), e.into());
                    light_at(&p.material, &p.lights, s, n, e, ortho, &mut NoTrace)
                }
                // Phong: no lit colour, lit per pixel.
                _ => [0.0; 3],
            };
            [c, n, e]
        };
        *o = [
            c[0], c[1], c[2], n[0], n[1], n[2], e[0], e[1], e[2], s[0], s[1], s[2],
        ];
    }
    out
}

/// The first pass over chunk `c` of an object's triangles: [`test`]; one
/// inside the view volume is kept if it covers a pixel centre
/// ([`raster::snap_box_of`]), one that crosses a plane goes to [`clip_tri`].
/// Compiled for AVX2 and FMA too, chosen at run time (the same bits).
#[multiversion(targets("x86_64+avx2+fma"))]
fn first_pass(
    p: &Prep,
    oi: u32,
    c: usize,
    vs: &ViewSetup,
    cull: bool,
    opt: &Options,
    buf: &mut ChunkBuf,
) {
    let t = &p.obj.tris;
    let r = c * CHUNK..t.tris.len().min((c + 1) * CHUNK);
    buf.kept.clear();
    buf.clipped.clear();
    let mut st = Stats {
        tris_in: r.len() as u64,
        ..Stats::default()
    };
    for i in r {
        let idx = t.tris[i].map(|i| i as usize);
        let Some((or, back)) = test(p, idx, vs, cull, &mut st) else {
            continue;
        };
        let snapped = idx.map(|i| p.v.snapped[i].map(i64::from));
        if or != 0 {
            clip_tri(p, oi, (i, or, back), vs, opt, buf, &mut st);
        } else if raster::snap_box_of(snapped, opt.width, opt.height).is_some() {
            st.drawn += 1;
            buf.kept.push(Kept::Tri { i: i as u32, back });
        } else {
            // Not lit, but counted as by [`corners`] (flat 1, Gouraud 3 or 0
            // from lit vertices, Phong 0), as before raster tests came first.
            st.no_pixels += 1;
            st.lighting_evals += match (p.shading, &p.lit) {
                (Shading::Flat, _) => 1,
                (Shading::Gouraud, None) => 3,
                _ => 0,
            };
        }
    }
    buf.stats = st;
}

/// Triangle `idx` (corners `cs`) clipped against the planes `or` it crosses:
/// clip coordinates ([`projection::to_clip`]) followed by the corners,
/// through [`clip::clip_polygon`], left in `poly`.
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
        let q = p.obj.mesh.positions[idx[k]].into();
        let c = projection::to_clip(&p.x.c32, "", &q, &mut NoTrace);
        std::array::from_fn(|i| if i < 4 { c[i] } else { cs[k][i - 4] })
    }));
    clip::clip_polygon(poly, or, tmp, tr);
}

/// Triangle `i` of object `oi`, crossing the planes `or`: lit, clipped, each
/// fan triangle that covers a pixel centre set up into `buf.clipped`. (Not
/// inlined: rare, and kept out of the culling loop's registers.)
#[inline(never)]
fn clip_tri(
    p: &Prep,
    oi: u32,
    (i, or, back): (usize, u8, bool),
    vs: &ViewSetup,
    opt: &Options,
    buf: &mut ChunkBuf,
    st: &mut Stats,
) {
    st.clipped += 1;
    let idx = p.obj.tris.tris[i].map(|i| i as usize);
    let cs = corners(p, idx, p.obj.tris.face[i], back, vs.ortho, st);
    let [poly, tmp] = &mut buf.poly;
    clipped_polygon(p, idx, &cs, or, (poly, tmp), &mut NoTrace);
    for k in 1..poly.len().saturating_sub(1) {
        let tri = [poly[0], poly[k], poly[k + 1]];
        let sv = tri.map(|v| to_screen(&clip_xyzw(&v), p.x.win, p.x.size, "", &mut NoTrace));
        let Some((mut t, swap)) = raster::setup_of(sv, opt.width, opt.height) else {
            st.no_pixels += 1;
            continue;
        };
        (t.obj, t.src) = (oi, i as u32);
        let [a, b, c] = tri.map(|v| -> Corner { std::array::from_fn(|i| v[i + 4]) });
        buf.clipped
            .push((t, if swap { [a, c, b] } else { [a, b, c] }));
        buf.kept.push(Kept::Clipped);
        st.drawn += 1;
    }
}

/// Where the second pass writes one chunk's set-up triangles: the frame's
/// slices for them (corners or planes empty when the frame keeps none),
/// and the number of the first.
struct Dest<'t> {
    tris: &'t mut [Tri],
    corners: &'t mut [[Corner; 3]],
    planes: &'t mut [Planes],
    first: u32,
}

/// The second pass over one chunk, straight into the frame's arrays: lights
/// and sets up the kept triangles, copies the clipped ones, Phong's planes
/// (default for other shadings), bins (rows y0..=y1 in bands
/// y0/BAND..=y1/BAND). Compiled for AVX2 and FMA too (the same bits).
#[multiversion(targets("x86_64+avx2+fma"))]
fn second_pass(p: &Prep, oi: u32, vs: &ViewSetup, opt: &Options, buf: &mut ChunkBuf, d: Dest) {
    buf.bins
        .resize_with((opt.height as usize).div_ceil(BAND), Vec::new);
    buf.bins.iter_mut().for_each(Vec::clear);
    let t = &p.obj.tris;
    let phong = p.shading == Shading::Phong;
    let mut clipped = buf.clipped.iter();
    // Corners go to the frame only when it keeps them.
    let mut cbuf = [[0.0f32; 12]; 3];
    for (k, kept) in buf.kept.iter().enumerate() {
        let (tri, c) = (&mut d.tris[k], d.corners.get_mut(k).unwrap_or(&mut cbuf));
        match *kept {
            Kept::Clipped => {
                let (t, cs) = clipped.next().expect("one per Kept::Clipped");
                tri.clone_from(t);
                *c = *cs;
            }
            Kept::Tri { i, back } => {
                let idx = t.tris[i as usize].map(|i| i as usize);
                let snapped = idx.map(|i| p.v.snapped[i].map(i64::from));
                let s = raster::snap_box_of(snapped, opt.width, opt.height).expect("first pass");
                let cs = corners(p, idx, t.face[i as usize], back, vs.ortho, &mut buf.stats);
                *c = if s.swap() { [cs[0], cs[2], cs[1]] } else { cs };
                raster::setup_into(&idx.map(|i| p.v.zw[i]), &s, tri);
                (tri.obj, tri.src) = (oi, i);
            }
        }
        match d.planes.get_mut(k) {
            Some(pl) if phong => pl.set(tri, c),
            Some(pl) => *pl = Planes::default(),
            None => {}
        }
        let (b0, b1) = (tri.bbox[2] as usize / BAND, tri.bbox[3] as usize / BAND);
        for bin in &mut buf.bins[b0..=b1] {
            bin.push(d.first + k as u32);
        }
    }
}

/// The first `n` entries of `s` (all when shorter); `s` keeps the rest.
fn take_front<'a, T>(s: &mut &'a mut [T], n: usize) -> &'a mut [T] {
    let all = std::mem::take(s);
    let (a, rest) = all.split_at_mut(n.min(all.len()));
    *s = rest;
    a
}

/// The triangles of one object, in submission order, into `out` from index
/// `first`: two parallel passes over chunks, the first counting each chunk's
/// set-up triangles so the second writes them in place. Returns the number
/// written and the counters (with `binning`: the time of merging the bins).
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
    // Per-chunk buffers from the previous frame (no fresh pages).
    let n = p.obj.tris.tris.len().div_ceil(CHUNK);
    let mut bufs: Vec<ChunkBuf> = (0..n).map(|_| pool.pop().unwrap_or_default()).collect();
    bufs.par_iter_mut()
        .enumerate()
        .for_each(|(c, buf)| first_pass(p, oi, c, vs, scene.cull, opt, buf));
    let end = first + bufs.iter().map(|b| b.kept.len()).sum::<usize>();
    out.tris.resize(out.tris.len().max(end), Tri::default());
    if out.keep[0] {
        out.corners
            .resize(out.corners.len().max(end), [[0.0; 12]; 3]);
    }
    if out.keep[1] {
        out.planes
            .resize(out.planes.len().max(end), Planes::default());
    }
    let mut rest = (
        &mut out.tris[first..end],
        out.corners.get_mut(first..end).unwrap_or_default(),
        out.planes.get_mut(first..end).unwrap_or_default(),
    );
    let dests: Vec<Dest> = (bufs.iter().map(|b| b.kept.len()))
        .map(|n| Dest {
            first: (end - rest.0.len()) as u32,
            tris: take_front(&mut rest.0, n),
            corners: take_front(&mut rest.1, n),
            planes: take_front(&mut rest.2, n),
        })
        .collect();
    bufs.par_iter_mut()
        .zip(dests)
        .for_each(|(buf, d)| second_pass(p, oi, vs, opt, buf, d));
    // Each band's triangles: the chunks' in order.
    let t0 = Instant::now();
    out.bins
        .resize_with((opt.height as usize).div_ceil(BAND), Vec::new);
    out.bins.par_iter_mut().enumerate().for_each(|(b, bin)| {
        for buf in &bufs {
            bin.extend_from_slice(&buf.bins[b]);
        }
    });
    let mut st = Stats::default();
    for b in &bufs {
        st.add(&b.stats);
    }
    st.binning = t0.elapsed();
    pool.extend(bufs);
    (end - first, st)
}

/// The frame's arrays the triangle stage fills: set-up triangles, their
/// corners and Phong planes (indexed alike), and per band the triangles
/// in it, in submission order.
pub(crate) struct Output<'f> {
    pub(crate) tris: &'f mut Vec<Tri>,
    pub(crate) corners: &'f mut Vec<[Corner; 3]>,
    pub(crate) planes: &'f mut Vec<Planes>,
    pub(crate) bins: &'f mut Vec<Vec<u32>>,
    /// Whether corners are kept (some object is shaded flat or Gouraud) and
    /// planes (some object is shaded by Phong).
    pub(crate) keep: [bool; 2],
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phong_corners_are_the_normal_position_and_colour() {
        // Phong's corners (the last branch of `corners`'s match) against
        // their definition: no lit colour, the eye-space vertex normal
        // (flipped on a back face), the eye position, the surface colour.
        let text = include_str!("../../tests/common/mixed.toml");
        let s = Scene::parse(text, "mixed.toml", std::path::Path::new(".")).unwrap();
        let opt = Options::of(&s);
        let vs = crate::stages::view::setup(&s.view, opt.width, opt.height, &mut NoTrace).unwrap();
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
                        let (n, e) = (p.v.vn[v], p.v.ec[v].e);
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
