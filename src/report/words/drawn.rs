//! The words of generated problems: titles and statements, in English and
//! in Bahasa Indonesia (the course text's terms, decimal commas).

use crate::msg::{CameraText, DrawnTitle, ShadeAsked, Statement};
use crate::report::lang::{Lang, NumStyle};

/// A generated problem's title.
pub fn title(t: DrawnTitle, lang: Lang) -> String {
    let (en, id) = match t {
        DrawnTitle::Basis => ("Camera basis", "Basis kamera"),
        DrawnTitle::EyeCoordinates => ("Eye coordinates", "Koordinat kamera"),
        DrawnTitle::Projection => ("Projection onto the near plane", "Proyeksi ke near plane"),
        DrawnTitle::Pipeline => ("The viewing pipeline", "Pipeline viewing"),
        DrawnTitle::Window => ("The viewing window", "Viewing window"),
        DrawnTitle::Clipping => ("Line clipping", "Clipping garis"),
        DrawnTitle::Lighting => ("Lighting at a point", "Pencahayaan di sebuah titik"),
    };
    if lang == Lang::Id { id } else { en }.to_string()
}

/// A generated problem's statement, its numbers written in `nums` (the
/// language's own, or a quiz's `--decimal`).
pub fn statement(s: &Statement, lang: Lang, nums: NumStyle) -> String {
    let n = |x: &str| nums.values(x);
    let id = lang == Lang::Id;
    match s {
        Statement::Basis(c) => match id {
            false => format!("{} Find the camera axes n, u and v.", camera(c, lang, nums)),
            true => format!("{} Tentukan sumbu kamera n, u dan v.", camera(c, lang, nums)),
        },
        Statement::View(c, pts) => match id {
            false => format!(
                "{} Find the camera axes n, u, v and the eye coordinates of the points {}.",
                camera(c, lang, nums),
                n(pts)
            ),
            true => format!(
                "{} Tentukan sumbu kamera n, u, v dan koordinat kamera titik-titik {}.",
                camera(c, lang, nums),
                n(pts)
            ),
        },
        Statement::Project(c, pts, near) => match id {
            false => format!(
                "{} With near = {}, project the points {} onto the near plane z = d = −near (centre of projection at the eye); give (xp{s}yp{s}zp).",
                camera(c, lang, nums),
                n(near),
                n(pts),
                s = nums.sep
            ),
            true => format!(
                "{} Dengan near = {}, proyeksikan titik-titik {} ke near plane z = d = −near (pusat proyeksi di mata); berikan (xp{s}yp{s}zp).",
                camera(c, lang, nums),
                n(near),
                n(pts),
                s = nums.sep
            ),
        },
        Statement::Pipeline { .. } => pipeline(s, lang, nums),
        Statement::Window(fovy, aspect, near) => match id {
            false => format!(
                "A perspective camera has fovy = {fovy}°, aspect ratio {} and near = {}. Find the viewing window on the near plane: top, bottom, left, right, height and width.",
                n(aspect),
                n(near)
            ),
            true => format!(
                "Sebuah kamera perspektif memiliki fovy = {fovy}°, aspect ratio {} dan near = {}. Tentukan viewing window pada near plane: top, bottom, left, right, tinggi dan lebar.",
                n(aspect),
                n(near)
            ),
        },
        Statement::Clip(min, max, p0, p1) => match id {
            false => format!(
                "The view volume is the box with corners {} and {}. For the segment P0{} P1{}: (a) give the region codes of P0 and P1 (6 bits, bit 1 rightmost: left, right, bottom, top, front, back); (b) is the segment accepted, rejected or clipped, and what is left of it?",
                n(min),
                n(max),
                n(p0),
                n(p1)
            ),
            true => format!(
                "View volume berupa balok dengan sudut {} dan {}. Untuk segmen garis P0{} P1{}: (a) berikan region code P0 dan P1 (6 bit, bit 1 paling kanan: kiri, kanan, bawah, atas, depan, belakang); (b) apakah segmen garis diterima, ditolak atau di-clip, dan bagian mana yang tersisa?",
                n(min),
                n(max),
                n(p0),
                n(p1)
            ),
        },
        Statement::Shade { .. } => shade(s, lang, nums),
    }
}

/// "A camera at Pe = … looks at Pr = … with up vector Vup = …."
fn camera(c: &CameraText, lang: Lang, nums: NumStyle) -> String {
    match lang {
        Lang::En => format!(
            "A camera at Pe = {} looks at Pr = {} with up vector Vup = {}.",
            nums.values(&c.eye),
            nums.values(&c.look),
            nums.values(&c.up)
        ),
        Lang::Id => format!(
            "Sebuah kamera di posisi mata Peye = {} melihat ke titik referensi Pref = {} dengan vektor Vup = {}.",
            nums.values(&c.eye),
            nums.values(&c.look),
            nums.values(&c.up)
        ),
    }
}

/// The four parts of a pipeline problem.
fn pipeline(s: &Statement, lang: Lang, nums: NumStyle) -> String {
    let Statement::Pipeline {
        camera: c,
        points,
        near,
        fovy,
        aspect,
        viewport,
    } = s
    else {
        return String::new();
    };
    let n = |x: &str| nums.values(x);
    match lang {
        Lang::En => format!(
            "{} The perspective set-up is near = {}, fovy = {fovy}°, aspect = {}, viewport {viewport} pixels. For the points {}: (1) find n, u, v and the eye coordinates; (2) project them onto the near plane z = −near; (3) find the viewing window (top, bottom, left, right, height, width); (4) find the pixel coordinates of the projected points.",
            camera(c, lang, nums),
            n(near),
            n(aspect),
            n(points)
        ),
        Lang::Id => format!(
            "{} Pengaturan perspektifnya near = {}, fovy = {fovy}°, aspect = {}, viewport {viewport} piksel. Untuk titik-titik {}: (1) tentukan n, u, v dan koordinat kamera; (2) proyeksikan ke near plane z = −near; (3) tentukan viewing window (top, bottom, left, right, tinggi, lebar); (4) tentukan koordinat piksel titik-titik hasil proyeksi.",
            camera(c, lang, nums),
            n(near),
            n(aspect),
            n(points)
        ),
    }
}

/// A lighting problem at one point.
fn shade(s: &Statement, lang: Lang, nums: NumStyle) -> String {
    let Statement::Shade {
        normal,
        color,
        light,
        view,
        model,
        constants,
        asked,
    } = s
    else {
        return String::new();
    };
    let n = |x: &str| nums.values(x);
    match lang {
        Lang::En => format!(
            "A surface point with normal N = {} and color Cs = {} is lit by one white directional light from L = {} and seen from V = {}. With the {model} model ({}), find {} and the color (each channel clamped to [0{}1]).",
            n(normal),
            n(color),
            n(light),
            n(view),
            n(constants),
            shade_asked(*asked, lang),
            nums.sep
        ),
        Lang::Id => format!(
            "Sebuah titik pada permukaan dengan vektor normal N = {} dan warna Cs = {} disinari satu sumber cahaya putih berarah dari L = {} dan dilihat dari V = {}. Dengan model {model} ({}), tentukan {} dan warnanya (tiap kanal dibatasi ke [0{}1]).",
            n(normal),
            n(color),
            n(light),
            n(view),
            n(constants),
            shade_asked(*asked, lang),
            nums.sep
        ),
    }
}

/// What a lighting problem asks for.
fn shade_asked(a: ShadeAsked, lang: Lang) -> &'static str {
    match (a, lang) {
        (ShadeAsked::Lambert, Lang::En) => "cos α = L·N, the ambient and diffuse terms",
        (ShadeAsked::Lambert, Lang::Id) => "cos α = L·N, komponen ambient dan diffuse",
        (ShadeAsked::Blinn, Lang::En) => "cos α = L·N, the half vector H = norm(L + V) and N·H, the ambient, diffuse and specular terms",
        (ShadeAsked::Blinn, Lang::Id) => "cos α = L·N, vektor setengah jalan H = norm(L + V) dan N·H, komponen ambient, diffuse dan specular",
        (ShadeAsked::Phong, Lang::En) => "cos α = L·N, R = 2N(L·N) − L, cos β = R·V, the ambient, diffuse and specular terms",
        (ShadeAsked::Phong, Lang::Id) => "cos α = L·N, vektor pantulan R = 2N(L·N) − L, cos β = R·V, komponen ambient, diffuse dan specular",
    }
}
