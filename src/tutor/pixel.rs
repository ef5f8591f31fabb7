//! `render --explain-pixel`: the worked steps for one pixel of a rendered
//! frame. Which triangle covers it; that triangle made again through the
//! very functions the renderer ran (the stages', with their steps recorded
//! this time), from the object's vertices to the set-up triangle, checked
//! against the one the rasterizer used; then its depth, barycentric weights,
//! interpolation, lighting and the pixel's colour.

use crate::error::Result;
use crate::input::scene::{Scene, Shading};
use crate::msg::{Msg, PixelMsg};
use crate::render::geometry::{self, ClipVert, VertBufs};
use crate::render::raster::{self, ScreenVert, Tri};
use crate::render::{self, Corner, Frame, Options, Stats};
use crate::stages::trace::{Name, NoTrace, Recorder, Step, Trace, Val};
use crate::stages::{camera, clip};
use nalgebra::{Matrix4, Vector3, Vector4};

fn v3(c: &[f32], at: usize) -> Vector3<f32> {
    Vector3::new(c[at], c[at + 1], c[at + 2])
}

/// The worked steps for pixel (x, y): which triangle covers it, the
/// geometry that triangle went through ([`explain_geometry`]: the
/// stages' own steps), its depth, barycentric weights, interpolation and
/// lighting, and the pixel's colour.
pub fn explain(
    f: &Frame,
    scene: &Scene,
    opt: &Options,
    (x, y): (u32, u32),
    rec: &mut Recorder,
) -> Result<()> {
    rec.section(Msg::SecPixel(x, y));
    let k = (y * f.width + x) as usize;
    let id = f.ids[k];
    if id == crate::render::raster::NONE {
        rec.step(|| {
            Step::new(Msg::WhichTriangle, Msg::FPixelCentre)
                .res(Name::Triangle, Val::text("none"))
                .note(Msg::NoTriangle)
        });
        return Ok(());
    }
    let t = &f.tris[id as usize];
    let obj = &scene.objects[t.obj as usize];
    rec.step(|| {
        Step::new(Msg::WhichTriangle, Msg::FEdges)
            .val(Name::Object, Val::text(obj.name.clone()))
            .val(
                Name::PolygonFace,
                Val::text(obj.tris.face[t.src as usize].to_string()),
            )
            .val(Name::ObjectTriangle, Val::text(t.src.to_string()))
            .res(Name::Triangle, Val::text(format!("#{id}")))
    });
    let g = explain_geometry(scene, opt, f, id, rec)?;
    rec.section(Msg::SecPixel(x, y));
    let (l, m, z) = (t.lambda(x, y), t.mu(x, y), t.depth(x, y));
    let zs = g.verts.map(|v| v.z);
    rec.step(|| {
        Step::new(Msg::Depth, Msg::FDepth)
            .val(Name::ZAtVertices, Val::vec3(&Vector3::from(zs)))
            .res(Name::math("z"), Val::num(&z))
            .note(Msg::Nearest)
    });
    rec.step(|| {
        Step::new(Msg::Barycentric, Msg::FBarycentric)
            .val(Name::math("λ"), Val::vec3(&Vector3::from(l)))
            .val(Name::math("1/w"), Val::vec3(&Vector3::from(t.inv_w)))
            .res(Name::math("μ"), Val::vec3(&Vector3::from(m)))
    });
    let c = &g.corners;
    shading(f, (t, c), (x, y), m, rec);
    rec.section(Msg::SecPixel(x, y));
    let px = &f.rgb[3 * k..3 * k + 3];
    let col = render::pixel_color(t, c, x, y, &f.looks, f.ortho, &mut NoTrace);
    rec.step(|| {
        Step::new(Msg::PixelColour, Msg::FByte)
            .val(Name::math("C"), Val::vec3(&Vector3::from(col)))
            .res(
                Name::math("RGB"),
                Val::text(format!("({}, {}, {})", px[0], px[1], px[2])),
            )
    });
    Ok(())
}

/// The shading steps of pixel (x, y) of triangle `t` (corners `c`) with perspective
/// weights `m`: flat, the face's lighting; Gouraud, each vertex's and the
/// interpolation; Phong, the interpolated N, P, C and the pixel's lighting.
fn shading(
    f: &Frame,
    (t, c): (&Tri, &[Corner; 3]),
    (x, y): (u32, u32),
    m: [f32; 3],
    rec: &mut Recorder,
) {
    let at = |i: usize| m[0] * c[0][i] + m[1] * c[1][i] + m[2] * c[2][i];
    let look = &f.looks[t.obj as usize];
    let (mat, lights) = (&look.material, &look.lights);
    let light = |corner: &Corner, rec: &mut Recorder| {
        let s = [corner[9], corner[10], corner[11]];
        render::light_at(mat, lights, s, v3(corner, 3), v3(corner, 6), f.ortho, rec);
    };
    match look.shading {
        Shading::Flat => {
            rec.step(|| {
                Step::new(Msg::FlatShading, Msg::FFlat)
                    .val(Name::InEyeSpace("N"), Val::vec3(&v3(&c[0], 3)))
                    .val(Name::FaceCentre, Val::vec3(&v3(&c[0], 6)))
                    .val(Name::SurfaceColour, Val::vec3(&v3(&c[0], 9)))
            });
            rec.section(Msg::SecLightFace);
            light(&c[0], rec);
        }
        Shading::Gouraud => {
            for (n, corner) in c.iter().enumerate() {
                rec.section(Msg::SecLightVertex(n));
                light(corner, rec);
            }
            rec.section(Msg::SecPixel(x, y));
            rec.step(|| {
                Step::new(Msg::Gouraud, "C = μ₀C₀ + μ₁C₁ + μ₂C₂")
                    .val(Name::math("C₀"), Val::vec3(&v3(&c[0], 0)))
                    .val(Name::math("C₁"), Val::vec3(&v3(&c[1], 0)))
                    .val(Name::math("C₂"), Val::vec3(&v3(&c[2], 0)))
                    .res(
                        Name::math("C"),
                        Val::vec3(&Vector3::new(at(0), at(1), at(2))),
                    )
            });
        }
        Shading::Phong => {
            // The values the renderer lights the pixel with: the same sums,
            // evaluated as planes of a/w over the screen divided by 1/w.
            let [n, p, col] = render::phong_attributes(t, c, x, y);
            rec.step(|| {
                Step::new(
                    Msg::PhongShading,
                    "N = Σ μₖNₖ,  P = Σ μₖPₖ,  C = Σ μₖCₖ  (as Σ λₖaₖ/wₖ ÷ Σ λₖ/wₖ)",
                )
                .val(
                    Name::math("N₀, N₁, N₂"),
                    Val::List(c.iter().map(|k| Val::vec3(&v3(k, 3))).collect()),
                )
                .res(Name::math("N"), Val::vec3(&Vector3::from(n)))
                .res(Name::InEyeSpace("P"), Val::vec3(&Vector3::from(p)))
                .res(Name::math("C"), Val::vec3(&Vector3::from(col)))
            });
            rec.section(Msg::SecLightPixel);
            render::pixel_color(t, c, x, y, &f.looks, f.ortho, rec);
        }
    }
}

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
    let vs = crate::stages::view::setup(&scene.view, opt.width, opt.height, rec)?;
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
    let same = |f: &[ClipVert; 3]| {
        let to = |v: ClipVert| screen(p, &v, "", &mut NoTrace);
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
        *v = screen(p, &fan[f][k], &name, rec);
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

/// Clip-space vertex `v` of a set-up triangle to the screen, through
/// [`geometry::to_screen`].
fn screen(
    p: &geometry::Prep,
    v: &ClipVert,
    name: &str,
    tr: &mut impl Trace,
) -> (ScreenVert, [i64; 2]) {
    geometry::to_screen(&geometry::clip_xyzw(v), p.x.win, p.x.size, name, tr)
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
        .res(Name::math("M"), Val::mat4(&model))
        .res(Name::math("V·M"), Val::mat4(&p.x.e32))
        .res(Name::math("P·V·M"), Val::mat4(&p.x.c32))
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
            s = s.val(Name::Vertex(k), Val::text(format!("({}, {})", q[0], q[1])));
        }
        s.res(Name::SameAsRasterizer, Val::Bool(same))
            .note(Msg::Pixel(PixelMsg::SameAsRaster(same)))
    });
}
