//! The geometry `render --explain-pixel` shows: the pixel's triangle made
//! again through the very functions the renderer ran (the stages', with
//! their steps recorded this time), from the object's vertices to the
//! set-up triangle, and checked against the one the rasterizer used.

use super::geometry::{self, ClipVert, VertBufs};
use super::raster::{self, ScreenVert};
use super::{Corner, Frame, Options, Stats};
use crate::error::Result;
use crate::input::scene::Scene;
use crate::msg::{Msg, PixelMsg};
use crate::stages::trace::{NoTrace, Recorder, Step, Trace, Val};
use crate::stages::{camera, clip};
use nalgebra::{Matrix4, Vector4};

/// Records the geometry of set-up triangle `id` of `frame` (rendered from
/// `scene` with `opt`): the view (view matrix, window, projection
/// matrix); per vertex of the object's triangle it came from, world, eye
/// and clip coordinates and the outcode; the clipping when the triangle
/// crossed a plane; per vertex of the set-up triangle, the perspective
/// division, window point, viewport, row and snapping; then the set-up
/// triangle, with whether it is the rasterizer's.
pub fn explain_geometry(
    scene: &Scene,
    opt: &Options,
    frame: &Frame,
    id: u32,
    rec: &mut Recorder,
) -> Result<PixelGeometry> {
    let t = &frame.tris[id as usize];
    let obj = &scene.objects[t.obj as usize];
    rec.section(Msg::Pixel(PixelMsg::SecMatrices));
    let vs = super::view_setup_traced(scene, opt.width, opt.height, rec)?;
    let (mut st, mut bufs) = (Stats::default(), VertBufs::default());
    let Some(p) = geometry::prepare(obj, &vs, &scene.lights, opt, &mut st, &mut bufs) else {
        return Ok(PixelGeometry::default());
    };
    let src = t.src as usize;
    let idx = obj.tris.tris[src].map(|i| i as usize);
    let clip = vertex_steps(&p, idx, rec);
    let Some((or, back)) = geometry::test(&p, idx, &vs, scene.cull, &mut st) else {
        return Ok(PixelGeometry::default());
    };
    // The set-up triangles it gave, as clip coordinates and corners:
    // itself, or the fan of its clipped polygon.
    let cs = geometry::corners(&p, idx, obj.tris.face[src], back, vs.ortho, &mut st);
    let fan: Vec<[ClipVert; 3]> = if or == 0 {
        let v = |k: usize| -> ClipVert {
            std::array::from_fn(|i| if i < 4 { clip[k][i] } else { cs[k][i - 4] })
        };
        vec![[v(0), v(1), v(2)]]
    } else {
        rec.section(Msg::Pixel(PixelMsg::SecClip));
        let (mut poly, mut tmp) = (Vec::new(), Vec::new());
        geometry::clipped_polygon(&p, idx, &cs, or, (&mut poly, &mut tmp), rec);
        (1..poly.len().saturating_sub(1))
            .map(|k| [poly[0], poly[k], poly[k + 1]])
            .collect()
    };
    let fan = (or != 0, fan.as_slice());
    Ok(screen_steps(&p, (opt.width, opt.height), fan, t, rec))
}

/// Of the set-up triangles a triangle gave (`fan`, clipped or not), the
/// one the rasterizer used: per vertex its perspective division, window
/// point, viewport, row and snapping (through [`geometry::to_screen`]),
/// then the set-up triangle, found equal to the frame's `t` or not.
fn screen_steps(
    p: &geometry::Prep,
    (w, h): (u32, u32),
    (clipped, fan): (bool, &[[ClipVert; 3]]),
    t: &raster::Tri,
    rec: &mut Recorder,
) -> PixelGeometry {
    let screen = |v: &ClipVert, name: &str, tr: &mut Recorder| {
        geometry::to_screen(&geometry::clip_xyzw(v), p.x.win, p.x.size, name, tr)
    };
    let same = |f: &[ClipVert; 3]| {
        let to = |v: ClipVert| {
            geometry::to_screen(
                &geometry::clip_xyzw(&v),
                p.x.win,
                p.x.size,
                "",
                &mut NoTrace,
            )
        };
        raster::setup_of(f.map(to), w, h).is_some_and(|(mut m, _)| {
            (m.obj, m.src) = (t.obj, t.src);
            m == *t
        })
    };
    let found = fan.iter().position(same);
    let Some(f) = found.or((!fan.is_empty()).then_some(0)) else {
        return PixelGeometry::default();
    };
    let mut sv = [(ScreenVert::default(), [0i64; 2]); 3];
    for (k, v) in sv.iter_mut().enumerate() {
        rec.section(Msg::Pixel(PixelMsg::SecScreen(k)));
        let name = format!("{}{k}", if clipped { "Q" } else { "V" });
        *v = screen(&fan[f][k], &name, rec);
    }
    set_up_step(&sv, found.is_some(), rec);
    let mut verts = sv.map(|v| v.0);
    let mut corners = fan[f].map(|v| -> Corner { std::array::from_fn(|i| v[i + 4]) });
    if raster::setup_of(sv, w, h).is_some_and(|(_, swap)| swap) {
        verts.swap(1, 2);
        corners.swap(1, 2);
    }
    PixelGeometry {
        same: found.is_some(),
        verts,
        corners,
    }
}

/// The object's matrices, then per vertex k of triangle `idx` (named Vk)
/// its world, eye and clip coordinates and its outcode, through
/// [`geometry::vertex_clip`]: returns the clip coordinates.
fn vertex_steps(p: &geometry::Prep, idx: [usize; 3], rec: &mut Recorder) -> [Vector4<f32>; 3] {
    let obj = p.obj;
    let model: Matrix4<f32> = obj.model.cast();
    rec.step(|| {
        Step::new(
            Msg::Pixel(PixelMsg::Matrices(obj.name.clone())),
            "M,  V·M,  P·V·M = P·(V·M)  (f32)",
        )
        .res("M", Val::mat4(&model))
        .res("V·M", Val::mat4(&p.x.e32))
        .res("P·V·M", Val::mat4(&p.x.c32))
    });
    let mut clip = [Vector4::zeros(); 3];
    for (k, c) in clip.iter_mut().enumerate() {
        rec.section(Msg::Pixel(PixelMsg::SecVertex(k)));
        let (name, pos) = (format!("V{k}"), obj.mesh.positions[idx[k]]);
        camera::to_world(&model, &name, &pos.into(), rec);
        let (_, c_k, code) = geometry::vertex_clip(&p.x, pos, &name, rec);
        *c = c_k;
        let note = if p.x.inside {
            // The renderer skipped the test: shown, with the reason.
            clip::outcode_clip(c, &name, rec);
            Some(PixelMsg::BoxInside)
        } else {
            (code != 0).then_some(PixelMsg::Outside)
        };
        if let (Some(s), Some(n)) = (rec.steps.last_mut(), note) {
            s.note = Some(Msg::Pixel(n));
        }
    }
    clip
}

/// What the geometry of a pixel's triangle came to.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelGeometry {
    /// The triangle made again is the one the rasterizer used.
    pub same: bool,
    /// Its screen vertices, in the set-up triangle's order.
    pub verts: [ScreenVert; 3],
    /// Its corners, in that order.
    pub corners: [Corner; 3],
}

/// The step of the set-up triangle: its snapped vertices, and whether it
/// is the one the rasterizer used.
fn set_up_step(sv: &[(ScreenVert, [i64; 2]); 3], same: bool, rec: &mut Recorder) {
    rec.step(|| {
        let mut s = Step::new(
            Msg::Pixel(PixelMsg::SetUp),
            "E_k(X, Y) = a_k·X + b_k·Y + c_k,  X = 256·x,  Y = 256·row",
        );
        for (k, (_, q)) in sv.iter().enumerate() {
            s = s.val(
                format!("vertex {k} (X, Y)"),
                Val::text(format!("({}, {})", q[0], q[1])),
            );
        }
        s.res("same as the rasterizer's", Val::Bool(same))
            .note(Msg::Pixel(PixelMsg::SameAsRaster(same)))
    });
}
