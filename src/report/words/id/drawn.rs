//! A generated problem's title and statement in Bahasa Indonesia (the
//! course text's terms).

use super::Id;
use crate::msg::{DrawnTitle, Number, ShadeAsked, StatedCamera, Statement, Triple};
use crate::report::lang::NumStyle;
use crate::report::words::drawn::{self, number, numbers, triple};
use crate::report::words::DrawnWords;

impl DrawnWords for Id {
    fn drawn_title(&self, t: DrawnTitle) -> &'static str {
        match t {
            DrawnTitle::Basis => "Basis kamera",
            DrawnTitle::EyeCoordinates => "Koordinat kamera",
            DrawnTitle::Projection => "Proyeksi ke near plane",
            DrawnTitle::Pipeline => "Pipeline viewing",
            DrawnTitle::Window => "Viewing window",
            DrawnTitle::Clipping => "Clipping garis",
            DrawnTitle::Lighting => "Pencahayaan di sebuah titik",
        }
    }

    /// A word table: long on purpose.
    fn statement(&self, s: &Statement, nums: NumStyle) -> String {
        let n = |x: &Number| number(*x, nums);
        let t = |v: &Triple| triple(*v, nums);
        let camera = |c: &StatedCamera| {
            format!(
                "Sebuah kamera di posisi mata Peye = {} melihat ke titik referensi Pref = {} dengan vektor Vup = {}.",
                t(&c.eye),
                t(&c.look),
                t(&c.up)
            )
        };
        match s {
            Statement::Basis(c) => format!("{} Tentukan sumbu kamera n, u dan v.", camera(c)),
            Statement::View(c, pts) => format!(
                "{} Tentukan sumbu kamera n, u, v dan koordinat kamera titik-titik {}.",
                camera(c),
                drawn::points(pts, nums)
            ),
            Statement::Project(c, pts, near) => format!(
                "{} Dengan near = {}, proyeksikan titik-titik {} ke near plane z = d = −near (pusat proyeksi di mata); berikan (xp{s}yp{s}zp).",
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
                "{} Pengaturan perspektifnya near = {}, fovy = {fovy}°, aspect = {}, viewport {}x{} piksel. Untuk titik-titik {}: (1) tentukan n, u, v dan koordinat kamera; (2) proyeksikan ke near plane z = −near; (3) tentukan viewing window (top, bottom, left, right, tinggi, lebar); (4) tentukan koordinat piksel titik-titik hasil proyeksi.",
                camera(c),
                n(near),
                n(aspect),
                viewport.0,
                viewport.1,
                drawn::points(points, nums)
            ),
            Statement::Window(fovy, aspect, near) => format!(
                "Sebuah kamera perspektif memiliki fovy = {fovy}°, aspect ratio {} dan near = {}. Tentukan viewing window pada near plane: top, bottom, left, right, tinggi dan lebar.",
                n(aspect),
                n(near)
            ),
            Statement::Clip(min, max, p0, p1) => format!(
                "View volume berupa balok dengan sudut {} dan {}. Untuk segmen garis P0{} P1{}: (a) berikan region code P0 dan P1 (6 bit, bit 1 paling kanan: kiri, kanan, bawah, atas, depan, belakang); (b) apakah segmen garis diterima, ditolak atau di-clip, dan bagian mana yang tersisa?",
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
                "Sebuah titik pada permukaan dengan vektor normal N = {} dan warna Cs = {} disinari satu sumber cahaya putih berarah dari L = {} dan dilihat dari V = {}. Dengan model {} ({}), tentukan {} dan warnanya (tiap kanal dibatasi ke [0{}1]).",
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
        ShadeAsked::Ambient => "komponen ambient",
        ShadeAsked::Diffuse => "cos α = L·N, komponen diffuse",
        ShadeAsked::Specular => "cos α = L·N, vektor pantulan R = 2N(L·N) − L, cos β = R·V, komponen specular",
        ShadeAsked::Lambert => "cos α = L·N, komponen ambient dan diffuse",
        ShadeAsked::Blinn => "cos α = L·N, vektor setengah jalan H = norm(L + V) dan N·H, komponen ambient, diffuse dan specular",
        ShadeAsked::Phong => "cos α = L·N, vektor pantulan R = 2N(L·N) − L, cos β = R·V, komponen ambient, diffuse dan specular",
    }
}
