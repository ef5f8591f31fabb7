//! The renderer: the calculator's stages at scale.
//!
//! model → view (`camera::basis`, `camera::view_matrix`, or the text's tilt)
//! → clip space (`projection::perspective_matrix` / `ortho_matrix` over the
//! window from `window::window`) → homogeneous outcodes
//! (`clip::outcode_clip_space`: trivial accept/reject of objects and
//! triangles) → clipping of the triangles that cross a plane (so no divide by
//! w ≤ 0) → viewport (`window::viewport_xy`) → raster (`raster`: fill rule,
//! z-buffer) → shading (`lighting::shade`, with `NoTrace`, at f32): flat per
//! face, Gouraud per vertex, Phong per pixel.
//!
//! The frame is rendered band by band (32 rows), the bands in parallel:
//! first a band's visibility (the nearest triangle per pixel), then its
//! shading (each visible pixel lit once), so the lighting work does not
//! depend on how many triangles overlap a pixel, and the output does not
//! depend on the number of threads (each band draws its triangles in
//! submission order).

use crate::error::{Error, Result};
use crate::lighting::{self, Light, LightKind, Material, Surface};
use crate::num::Fast32;
use crate::raster::{self, ScreenVert, Tri, BAND, NONE};
use crate::scene::{Colors, Normals, Object, Scene, Shading, View};
use crate::trace::{NoTrace, Trace};
use crate::window::Window;
use nalgebra::{Matrix3, Matrix4, Vector3, Vector4};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Per-corner data of a triangle: lit colour (flat, Gouraud), eye-space
/// normal, eye-space position, surface colour.
pub type Corner = [f32; 12];

/// What to render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Shading mode.
    pub shading: Shading,
    /// Vertex-normal source.
    pub normals: Normals,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Use `shading` for every object, even those that name their own.
    pub force_shading: bool,
    /// Show a progress bar on a terminal for renders over half a second.
    pub progress: bool,
}

impl Options {
    /// The scene's own settings.
    pub fn of(scene: &Scene) -> Options {
        Options {
            shading: scene.shading,
            normals: scene.normals,
            width: scene.width,
            height: scene.height,
            force_shading: false,
            progress: false,
        }
    }
}

/// What was done and what was skipped.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stats {
    /// Triangles in the scene.
    pub tris_in: u64,
    /// Back faces of closed meshes, culled.
    pub culled: u64,
    /// Triangles wholly outside one plane of the view volume (outcodes).
    pub rejected: u64,
    /// Objects whose bounding box is wholly outside one plane.
    pub objects_rejected: u64,
    /// Objects whose bounding box is wholly inside (no per-triangle tests).
    pub objects_inside: u64,
    /// Triangles that crossed a plane and were clipped.
    pub clipped: u64,
    /// Triangles set up for rasterization (after clipping).
    pub drawn: u64,
    /// Triangles that cover no pixel centre.
    pub no_pixels: u64,
    /// Pixels that got a colour from a triangle.
    pub pixels_shaded: u64,
    /// Calls of `lighting::shade`.
    pub lighting_evals: u64,
    /// (object, light) pairs skipped because the object is out of range.
    pub lights_skipped: u64,
    /// Objects drawn without specular work (ks = 0 or specular off).
    pub specular_skipped: u64,
    /// Time: transforms, culling, clipping, setup, per-face/vertex lighting.
    pub geometry: Duration,
    /// Time: binning triangles into bands.
    pub binning: Duration,
    /// Thread time (summed over bands): visibility.
    pub raster: Duration,
    /// Thread time (summed over bands): shading.
    pub shading: Duration,
    /// Wall time of the band pass (visibility and shading, in parallel).
    pub pass: Duration,
}

impl Stats {
    /// Raster + shading time of the frame (everything but file output).
    pub fn frame(&self) -> Duration {
        self.geometry + self.binning + self.pass
    }

    fn add(&mut self, o: &Stats) {
        self.tris_in += o.tris_in;
        self.culled += o.culled;
        self.rejected += o.rejected;
        self.clipped += o.clipped;
        self.drawn += o.drawn;
        self.no_pixels += o.no_pixels;
        self.lighting_evals += o.lighting_evals;
    }
}

/// A rendered frame.
#[derive(Clone, Debug)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGB, 8 bits each, rows from the top.
    pub rgb: Vec<u8>,
    /// The visible triangle per pixel ([`NONE`] for background).
    pub ids: Vec<u32>,
    /// Depth z/w per pixel.
    pub depth: Vec<f32>,
    /// The set-up triangles.
    pub tris: Vec<Tri>,
    /// Their corners.
    pub corners: Vec<[Corner; 3]>,
    /// Per object: how it is shaded.
    pub looks: Vec<Look>,
    /// Whether the view was orthographic (the viewer along +z).
    pub ortho: bool,
    /// Counters and times.
    pub stats: Stats,
}

/// How one object is shaded: its material, the lights that reach it and
/// the shading mode.
#[derive(Clone, Debug)]
pub struct Look {
    /// Material (specular switched off when ks = 0).
    pub material: Material<Fast32>,
    /// The lights within range of the object.
    pub lights: Vec<Light<Fast32>>,
    /// Flat, Gouraud or Phong.
    pub shading: Shading,
}

/// The view transforms of a scene at an image size.
#[derive(Clone, Debug)]
pub struct ViewSetup {
    /// World → eye.
    pub eye_from_world: Matrix4<f64>,
    /// Eye → clip.
    pub clip_from_eye: Matrix4<f64>,
    /// The window on the near plane (or the tilt view's pixel window).
    pub win: Window<f32>,
    /// Orthographic (the text's tilt view): the viewer is along +z.
    pub ortho: bool,
}

/// The view of a scene: the camera's view matrix and the perspective over
/// its window, or the tilt rotation and an orthographic window of W × H
/// units centred on the origin (1 unit = 1 pixel).
pub fn view_setup(scene: &Scene, w: u32, h: u32) -> Result<ViewSetup> {
    let (wf, hf) = (w as f64, h as f64);
    match &scene.view {
        View::Tilt { x, y } => {
            let rot = Matrix4::from_axis_angle(&Vector3::x_axis(), *x)
                * Matrix4::from_axis_angle(&Vector3::y_axis(), *y);
            let win = Window {
                top: hf / 2.0,
                bottom: -hf / 2.0,
                left: -wf / 2.0,
                right: wf / 2.0,
                height: hf,
                width: wf,
            };
            // Depth range ±10⁶ units: nothing the text draws comes near it.
            let clip = crate::projection::ortho_matrix(&win, &-1e6, &1e6);
            Ok(ViewSetup {
                eye_from_world: rot,
                clip_from_eye: clip,
                win: win32(&win),
                ortho: true,
            })
        }
        View::Camera {
            camera,
            fovy,
            aspect,
            near,
            far,
        } => {
            let b = crate::camera::basis(camera, &mut NoTrace)?;
            let v = crate::camera::view_matrix(&b, &camera.pe, &mut NoTrace);
            let aspect = aspect.unwrap_or(wf / hf);
            let win = crate::window::window(fovy, &aspect, near, "near", &mut NoTrace)?;
            let p = crate::projection::perspective_matrix(&win, near, far);
            Ok(ViewSetup {
                eye_from_world: v,
                clip_from_eye: p,
                win: win32(&win),
                ortho: false,
            })
        }
    }
}

fn win32(w: &Window<f64>) -> Window<f32> {
    Window {
        top: w.top as f32,
        bottom: w.bottom as f32,
        left: w.left as f32,
        right: w.right as f32,
        height: w.height as f32,
        width: w.width as f32,
    }
}

/// Everything the triangle loop needs about one object, in eye and clip space.
struct Prep<'a> {
    obj: &'a Object,
    eye: Vec<[f32; 3]>,
    clip: Vec<[f32; 4]>,
    codes: Vec<u8>,
    inside: bool,
    vnormals: Vec<[f32; 3]>,
    lit: Option<Vec<[f32; 3]>>,
    closed: bool,
    material: Material<Fast32>,
    lights: Vec<Light<Fast32>>,
    shading: Shading,
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
    let f = |v: Vector3<f32>| Vector3::new(Fast32(v.x), Fast32(v.y), Fast32(v.z));
    // shade takes a unit N (an interpolated normal is shorter than 1).
    let len = n.norm();
    let n = if len > 0.0 { n / len } else { n };
    // The tilt view's viewer is along +z; a camera is a local viewer at the
    // eye-space origin, V = norm(0 − P), which shade computes itself.
    let s = Surface {
        normal: f(n),
        view: f(Vector3::new(0.0, 0.0, 1.0)),
        position: f(p),
        camera: if ortho { None } else { Some(Vector3::zeros()) },
    };
    lighting::shade(m, lights, &s, tr).color.map(|c| c.0)
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

fn prepare<'a>(
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
/// Gouraud: per corner), clip, set up.
fn triangles(
    p: &Prep,
    oi: u32,
    vs: &ViewSetup,
    scene: &Scene,
    opt: &Options,
) -> (Vec<Tri>, Vec<[Corner; 3]>, Stats) {
    let mesh = &p.obj.mesh;
    let t = &p.obj.tris;
    let (w, h) = (opt.width, opt.height);
    let chunks: Vec<(Vec<Tri>, Vec<[Corner; 3]>, Stats)> = t
        .tris
        .par_chunks(2048)
        .zip(t.face.par_chunks(2048))
        .map(|(tris, faces)| {
            let mut out = Vec::with_capacity(tris.len());
            let mut corners = Vec::with_capacity(tris.len());
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
            (out, corners, st)
        })
        .collect();
    let mut tris = Vec::new();
    let mut corners = Vec::new();
    let mut st = Stats::default();
    for (t, c, s) in chunks {
        tris.extend(t);
        corners.extend(c);
        st.add(&s);
    }
    (tris, corners, st)
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

/// A progress bar that appears on a terminal once a render has taken half a
/// second.
struct Progress {
    bar: Option<indicatif::ProgressBar>,
    start: Instant,
    shown: AtomicBool,
}

impl Progress {
    fn new(on: bool, total: u64) -> Progress {
        use std::io::IsTerminal;
        let bar = (on && std::io::stderr().is_terminal()).then(|| {
            let b = indicatif::ProgressBar::with_draw_target(
                Some(total),
                indicatif::ProgressDrawTarget::hidden(),
            );
            if let Ok(s) =
                indicatif::ProgressStyle::with_template("{msg} {bar:40} {pos}/{len} bands")
            {
                b.set_style(s);
            }
            b.set_message("rendering");
            b
        });
        Progress {
            bar,
            start: Instant::now(),
            shown: AtomicBool::new(false),
        }
    }
    fn tick(&self) {
        if let Some(b) = &self.bar {
            b.inc(1);
            if self.start.elapsed() > Duration::from_millis(500)
                && !self.shown.swap(true, Ordering::Relaxed)
            {
                b.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            }
        }
    }
    fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

/// Renders a scene.
pub fn render(scene: &Scene, opt: &Options) -> Result<Frame> {
    render_reusing(scene, opt, None)
}

/// Renders a scene into the buffers of a previous frame when it has the
/// same size (as a real-time loop would: no fresh allocation per frame).
pub fn render_reusing(scene: &Scene, opt: &Options, prev: Option<Frame>) -> Result<Frame> {
    crate::scene::check_size(opt.width, opt.height)?;
    let t0 = Instant::now();
    let vs = view_setup(scene, opt.width, opt.height)?;
    let n = (opt.width * opt.height) as usize;
    let (mut tris, mut corners, mut depth, mut ids, mut rgb) = match prev {
        Some(f) if f.rgb.len() == 3 * n => (f.tris, f.corners, f.depth, f.ids, f.rgb),
        _ => (
            Vec::new(),
            Vec::new(),
            vec![0.0f32; n],
            vec![0u32; n],
            vec![0u8; 3 * n],
        ),
    };
    tris.clear();
    corners.clear();
    let mut stats = Stats::default();
    // Per object: the material and the lights that reach it.
    let mut looks = Vec::new();
    for (oi, obj) in scene.objects.iter().enumerate() {
        let Some(p) = prepare(obj, &vs, &scene.lights, opt, &mut stats) else {
            looks.push(Look {
                material: fast_material(&obj.material),
                lights: Vec::new(),
                shading: opt.shading,
            });
            continue;
        };
        let (t, c, s) = triangles(&p, oi as u32, &vs, scene, opt);
        tris.extend(t);
        corners.extend(c);
        stats.add(&s);
        looks.push(Look {
            material: p.material,
            lights: p.lights,
            shading: p.shading,
        });
    }
    stats.geometry = t0.elapsed();

    let t1 = Instant::now();
    let bins = raster::bin(&tris, opt.height);
    stats.binning = t1.elapsed();

    let progress = Progress::new(opt.progress, bins.len() as u64);
    let t2 = Instant::now();
    let bg = to_u8(scene.background);
    let w = opt.width as usize;
    // One pass over bands in parallel: the band's visibility (nearest
    // triangle per pixel), then its shading while the band is in cache.
    let (shaded, evals, raster_t, shade_t) = rgb
        .par_chunks_mut(3 * w * BAND)
        .zip(depth.par_chunks_mut(w * BAND))
        .zip(ids.par_chunks_mut(w * BAND))
        .zip(bins.par_iter())
        .enumerate()
        .map(|(band, (((out, dz), id), bin))| {
            let t = Instant::now();
            raster::visibility_band(&tris, bin, (band * BAND) as u32, w, dz, id);
            let raster_t = t.elapsed();
            let t = Instant::now();
            let (mut count, mut evals) = (0u64, 0u64);
            for (r, (orow, irow)) in out
                .chunks_exact_mut(3 * w)
                .zip(id.chunks_exact(w))
                .enumerate()
            {
                let j = (band * BAND + r) as u32;
                for (i, (px, &t)) in orow.chunks_exact_mut(3).zip(irow).enumerate() {
                    let c = if t == NONE {
                        bg
                    } else {
                        count += 1;
                        let tri = &tris[t as usize];
                        if looks[tri.obj as usize].shading == Shading::Phong {
                            evals += 1;
                        }
                        let c = &corners[t as usize];
                        to_u8(pixel_color(
                            tri,
                            c,
                            i as u32,
                            j,
                            &looks,
                            vs.ortho,
                            &mut NoTrace,
                        ))
                    };
                    px[0] = c[0];
                    px[1] = c[1];
                    px[2] = c[2];
                }
            }
            progress.tick();
            (count, evals, raster_t, t.elapsed())
        })
        .reduce(
            || (0, 0, Duration::ZERO, Duration::ZERO),
            |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2, a.3 + b.3),
        );
    progress.finish();
    stats.pixels_shaded = shaded;
    stats.lighting_evals += evals;
    stats.raster = raster_t;
    stats.shading = shade_t;
    stats.pass = t2.elapsed();
    Ok(Frame {
        width: opt.width,
        height: opt.height,
        rgb,
        ids,
        depth,
        tris,
        corners,
        looks,
        ortho: vs.ortho,
        stats,
    })
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
            let m = t.mu(i, j);
            let at = |k: usize| m[0] * c[0][k] + m[1] * c[1][k] + m[2] * c[2][k];
            let n = Vector3::new(at(3), at(4), at(5));
            let p = Vector3::new(at(6), at(7), at(8));
            let s = [at(9), at(10), at(11)];
            light_at(&look.material, &look.lights, s, n, p, ortho, tr)
        }
    }
}

/// A colour 0…1 as 8-bit: round(255·c), clamped.
#[inline]
pub fn to_u8(c: [f32; 3]) -> [u8; 3] {
    c.map(|x| (x.clamp(0.0, 1.0) * 255.0 + 0.5) as u8)
}

/// Writes the frame as an 8-bit RGB PNG.
pub fn write_png(frame: &Frame, path: &std::path::Path) -> Result<()> {
    let err = |e: String| Error::new("output", format!("cannot write {}: {e}", path.display()));
    let file = std::fs::File::create(path).map_err(|e| err(e.to_string()))?;
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), frame.width, frame.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let mut wr = enc.write_header().map_err(|e| err(e.to_string()))?;
    wr.write_image_data(&frame.rgb)
        .map_err(|e| err(e.to_string()))?;
    wr.finish().map_err(|e| err(e.to_string()))
}
