//! A generated problem's title and statement in English.

use super::En;
use crate::msg::{DrawnTitle, Number, ShadeAsked, StatedCamera, Statement, Triple};
use crate::report::lang::NumStyle;
use crate::report::words::drawn::{self, number, numbers, triple};
use crate::report::words::DrawnWords;

impl DrawnWords for En {
    fn drawn_title(&self, t: DrawnTitle) -> &'static str {
        match t {
            DrawnTitle::Basis => "Camera basis",
            DrawnTitle::EyeCoordinates => "Eye coordinates",
            DrawnTitle::Projection => "Projection onto the near plane",
            DrawnTitle::Pipeline => "The viewing pipeline",
            DrawnTitle::Window => "The viewing window",
            DrawnTitle::Clipping => "Line clipping",
            DrawnTitle::Lighting => "Lighting at a point",
        }
    }

    /// A word table: long on purpose.
    fn statement(&self, s: &Statement, nums: NumStyle) -> String {
        let n = |x: &Number| number(*x, nums);
        let t = |v: &Triple| triple(*v, nums);
        let camera = |c: &StatedCamera| {
            format!(
                "A camera at Pe = {} looks at Pr = {} with up vector Vup = {}.",
                t(&c.eye),
                t(&c.look),
                t(&c.up)
            )
        };
        match s {
            Statement::Basis(c) => format!("{} Find the camera axes n, u and v.", camera(c)),
            Statement::View(c, pts) => format!(
                "{} Find the camera axes n, u, v and the eye coordinates of the points {}.",
                camera(c),
                drawn::points(pts, nums)
            ),
            Statement::Project(c, pts, near) => format!(
                "{} With near = {}, project the points {} onto the near plane z = d = −near (centre of projection at the eye); give (xp{s}yp{s}zp).",
                camera(c),
                n(near),
                drawn::points(pts, nums),
                s = nums.sep
            ),
            Statement::Pipeline {
                camera: c,
                points,
                near,
                fovy,
                aspect,
                viewport,
            } => format!(
                "{} The perspective set-up is near = {}, fovy = {fovy}°, aspect = {}, viewport {}x{} pixels. For the points {}: (1) find n, u, v and the eye coordinates; (2) project them onto the near plane z = −near; (3) find the viewing window (top, bottom, left, right, height, width); (4) find the pixel coordinates of the projected points.",
                camera(c),
                n(near),
                n(aspect),
                viewport.0,
                viewport.1,
                drawn::points(points, nums)
            ),
            Statement::Window(fovy, aspect, near) => format!(
                "A perspective camera has fovy = {fovy}°, aspect ratio {} and near = {}. Find the viewing window on the near plane: top, bottom, left, right, height and width.",
                n(aspect),
                n(near)
            ),
            Statement::Clip(min, max, p0, p1) => format!(
                "The view volume is the box with corners {} and {}. For the segment P0{} P1{}: (a) give the region codes of P0 and P1 (6 bits, bit 1 rightmost: left, right, bottom, top, front, back); (b) is the segment accepted, rejected or clipped, and what is left of it?",
                t(min),
                t(max),
                t(p0),
                t(p1)
            ),
            Statement::Shade {
                normal,
                color,
                light,
                view,
                model,
                constants,
                asked,
            } => format!(
                "A surface point with normal N = {} and color Cs = {} is lit by one white directional light from L = {} and seen from V = {}. With the {} model ({}), find {} and the color (each channel clamped to [0{}1]).",
                t(normal),
                numbers(*color, nums),
                t(light),
                t(view),
                crate::report::words::report::model_name(model),
                drawn::constants(constants, nums),
                shade_asked(*asked),
                nums.sep
            ),
        }
    }
}

/// What a lighting problem asks for.
fn shade_asked(a: ShadeAsked) -> &'static str {
    match a {
        ShadeAsked::Ambient => "the ambient term",
        ShadeAsked::Diffuse => "cos α = L·N, the diffuse term",
        ShadeAsked::Specular => "cos α = L·N, R = 2N(L·N) − L, cos β = R·V, the specular term",
        ShadeAsked::Lambert => "cos α = L·N, the ambient and diffuse terms",
        ShadeAsked::Blinn => "cos α = L·N, the half vector H = norm(L + V) and N·H, the ambient, diffuse and specular terms",
        ShadeAsked::Phong => "cos α = L·N, R = 2N(L·N) − L, cos β = R·V, the ambient, diffuse and specular terms",
    }
}
