//! `grafika render`: scene file and flags → frame(s) → PNG, with `--stats`,
//! `--repeat` timing and `--explain-pixel` (the worked steps for one pixel,
//! lighting included, from the same `lighting::shade` the calculator uses).

use crate::cli::args::RenderArgs;
use crate::error::{Error, Result};
use crate::input::scene::{Scene, Shading};
use crate::msg::Msg;
use crate::render::{self, Frame, Options, Stats};
use crate::stages::trace::Report;
use crate::stages::trace::{Recorder, Step, Trace, Val};
use nalgebra::Vector3;
use serde_json::json;
use std::time::{Duration, Instant};

/// Runs `render`.
pub fn run(a: &RenderArgs, lang: crate::report::lang::Lang) -> Result<Report> {
    let scene = Scene::read(&a.scene)?;
    let mut opt = Options::of(&scene);
    opt.shading = a.shading.unwrap_or(opt.shading);
    opt.force_shading = a.shading.is_some();
    opt.normals = a.normals.unwrap_or(opt.normals);
    opt.width = a.width.unwrap_or(opt.width);
    opt.height = a.height.unwrap_or(opt.height);
    opt.progress = a.repeat == 1;
    let pixel = a.explain_pixel.as_deref().map(parse_pixel).transpose()?;
    if let Some((x, y)) = pixel {
        if x >= opt.width || y >= opt.height {
            return Err(Error::why(
                "--explain-pixel",
                crate::msg::ErrMsg::PixelOutside(x, y, opt.width, opt.height),
            ));
        }
    }
    // --repeat shows its progress on a terminal (a big scene × 10,000 runs
    // for minutes); one frame has the renderer's own bar.
    let bar = (a.repeat > 1)
        .then(|| {
            crate::cli::terminal_bar(
                a.repeat as u64,
                crate::report::lang::tr(lang, "frames", "bingkai"),
            )
        })
        .flatten();
    let go = || -> Result<(Frame, Vec<Stats>)> {
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..a.repeat {
            let f = render::render_reusing(&scene, &opt, last.take())?;
            times.push(f.stats.clone());
            last = Some(f);
            if let Some(b) = &bar {
                b.inc(1);
            }
        }
        if let Some(b) = &bar {
            b.finish_and_clear();
        }
        let f = last.ok_or_else(|| Error::why("--repeat", crate::msg::ErrMsg::NothingRendered))?;
        Ok((f, times))
    };
    let (frame, runs) = match a.threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n as usize)
            .build()
            .map_err(|e| Error::why("--threads", crate::msg::ErrMsg::Threads(e.to_string())))?
            .install(go)?,
        None => go()?,
    };
    let t = Instant::now();
    if a.output.as_os_str() == "-" {
        let out = std::io::stdout().lock();
        render::encode_png(&frame, out).map_err(|e| {
            Error::why(
                "output",
                crate::msg::ErrMsg::CannotWriteStdout(crate::msg::IoWhy::Other(e)),
            )
        })?;
    } else {
        render::write_png(&frame, &a.output)?;
    }
    let encode = t.elapsed();

    let median = |f: &dyn Fn(&Stats) -> Duration| {
        let mut v: Vec<Duration> = runs.iter().map(f).collect();
        v.sort();
        v[v.len() / 2]
    };
    let frame_t = median(&|s| s.frame());
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let st = &frame.stats;
    let mpix = (opt.width as f64 * opt.height as f64) / frame_t.as_secs_f64() / 1e6;
    let mut rec = Recorder::new();
    if let Some((x, y)) = pixel {
        explain(&frame, &scene, x, y, &mut rec);
    }
    let shading = shading_summary(&scene, &opt);
    let mut result = vec![
        (
            "image".to_string(),
            Val::text(a.output.display().to_string()),
        ),
        (
            "size".to_string(),
            Val::text(format!("{}x{}", opt.width, opt.height)),
        ),
        ("shading".to_string(), Val::text(shading.clone())),
        (
            "triangles drawn".to_string(),
            Val::Num(crate::num::Scalar::shown(&(st.drawn as f64))),
        ),
        (
            "pixels shaded".to_string(),
            Val::Num(crate::num::Scalar::shown(&(st.pixels_shaded as f64))),
        ),
    ];
    let label = if a.repeat > 1 {
        format!("frame time (median of {})", a.repeat)
    } else {
        "frame time".to_string()
    };
    result.push((
        label,
        Val::said(crate::msg::Said::FrameTime(
            format!("{:.2}", ms(frame_t)),
            format!("{mpix:.1}"),
            format!("{:.2}", ms(encode)),
        )),
    ));
    let mut notes = Vec::new();
    if a.stats {
        notes.push(stats_text(st, &runs, opt.shading, &median, encode, lang));
    }
    let mut extra = serde_json::Map::new();
    extra.insert(
        "stats".into(),
        json!({
            "triangles_in": st.tris_in, "culled": st.culled, "rejected": st.rejected,
            "objects_rejected": st.objects_rejected, "objects_inside": st.objects_inside,
            "clipped": st.clipped, "drawn": st.drawn, "no_pixels": st.no_pixels,
            "pixels_shaded": st.pixels_shaded, "lighting_evaluations": st.lighting_evals,
            "lights_skipped": st.lights_skipped, "specular_skipped": st.specular_skipped,
            "frame_ms": ms(frame_t), "geometry_ms": ms(median(&|s| s.geometry)),
            "binning_ms": ms(median(&|s| s.binning)), "raster_ms": ms(median(&|s| s.raster)),
            "shading_ms": ms(median(&|s| s.shading)), "bands_ms": ms(median(&|s| s.pass)), "png_ms": ms(encode),
            "repeat": a.repeat, "mpixels_per_s": mpix,
        }),
    );
    Ok(Report {
        command: "render".into(),
        input: json!({
            "scene": a.scene.display().to_string(), "output": a.output.display().to_string(),
            "width": opt.width, "height": opt.height, "shading": shading,
            "normals": format!("{:?}", opt.normals).to_lowercase(),
            "explain_pixel": pixel.map(|(x, y)| [x, y]),
        }),
        result,
        steps: rec.steps,
        warnings: rec.warnings,
        notes,
        precision: crate::num::Precision::F32,
        extra,
        comparison: None,
        source_notes: vec![],
    })
}

/// The shadings drawn: the one forced by `--shading`, else each object's
/// own (or the scene's) once, in object order (`flat, gouraud`).
fn shading_summary(scene: &Scene, opt: &Options) -> String {
    let name = |s: Shading| format!("{s:?}").to_lowercase();
    if opt.force_shading || scene.objects.is_empty() {
        return name(opt.shading);
    }
    let mut seen: Vec<String> = Vec::new();
    for o in &scene.objects {
        let n = name(o.shading.unwrap_or(opt.shading));
        if !seen.contains(&n) {
            seen.push(n);
        }
    }
    seen.join(", ")
}

/// The median over the runs of one stage's time.
type Median<'a> = dyn Fn(&dyn Fn(&Stats) -> Duration) -> Duration + 'a;

fn stats_text(
    st: &Stats,
    runs: &[Stats],
    shading: Shading,
    median: &Median<'_>,
    encode: Duration,
    lang: crate::report::lang::Lang,
) -> String {
    let ms = |f: &dyn Fn(&Stats) -> Duration| median(f).as_secs_f64() * 1e3;
    let times = crate::report::render::Times {
        runs: runs.len(),
        geometry: ms(&|s| s.geometry),
        binning: ms(&|s| s.binning),
        bands: ms(&|s| s.pass),
        raster: ms(&|s| s.raster),
        shading: ms(&|s| s.shading),
        frame: ms(&|s| s.frame()),
        png: encode.as_secs_f64() * 1e3,
    };
    crate::report::render::stats_text(st, &times, shading, lang)
}

fn parse_pixel(s: &str) -> Result<(u32, u32)> {
    let bad = || {
        Error::why(
            "--explain-pixel",
            crate::msg::ErrMsg::PixelText(s.to_string()),
        )
    };
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    Ok((
        x.trim().parse().map_err(|_| bad())?,
        y.trim().parse().map_err(|_| bad())?,
    ))
}

fn v3(c: &[f32], at: usize) -> Vector3<f32> {
    Vector3::new(c[at], c[at + 1], c[at + 2])
}

/// The worked steps for pixel (x, y).
pub fn explain(f: &Frame, scene: &Scene, x: u32, y: u32, rec: &mut Recorder) {
    rec.section(Msg::SecPixel(x, y));
    let k = (y * f.width + x) as usize;
    let id = f.ids[k];
    if id == crate::render::raster::NONE {
        rec.step(|| {
            Step::new(Msg::WhichTriangle, Msg::FPixelCentre)
                .res("triangle", Val::text("none"))
                .note(Msg::NoTriangle)
        });
        return;
    }
    let t = &f.tris[id as usize];
    let c = &f.corners[id as usize];
    let obj = &scene.objects[t.obj as usize];
    rec.step(|| {
        let mut s = Step::new(Msg::WhichTriangle, Msg::FEdges)
            .val("object", Val::text(obj.name.clone()))
            .val("polygon face", Val::text(t.face.to_string()));
        for (n, v) in t.verts.iter().enumerate() {
            s = s.val(format!("screen vertex {n} (x, y)"), Val::vec2(&v.x, &v.y));
        }
        s.res("triangle", Val::text(format!("#{id}")))
    });
    let l = t.lambda(x, y);
    let m = t.mu(x, y);
    let z = t.depth(x, y);
    rec.step(|| {
        Step::new(Msg::Depth, Msg::FDepth)
            .val(
                "z at the vertices",
                Val::vec3(&Vector3::new(t.verts[0].z, t.verts[1].z, t.verts[2].z)),
            )
            .res("z", Val::num(&z))
            .note(Msg::Nearest)
    });
    rec.step(|| {
        Step::new(Msg::Barycentric, Msg::FBarycentric)
            .val("λ", Val::vec3(&Vector3::new(l[0], l[1], l[2])))
            .val(
                "1/w",
                Val::vec3(&Vector3::new(t.inv_w[0], t.inv_w[1], t.inv_w[2])),
            )
            .res("μ", Val::vec3(&Vector3::new(m[0], m[1], m[2])))
    });
    let at = |i: usize| m[0] * c[0][i] + m[1] * c[1][i] + m[2] * c[2][i];
    let look = &f.looks[t.obj as usize];
    let (mat, lights) = (&look.material, &look.lights);
    match look.shading {
        Shading::Flat => {
            rec.step(|| {
                Step::new(Msg::FlatShading, Msg::FFlat)
                    .val("N (eye space)", Val::vec3(&v3(&c[0], 3)))
                    .val("face centre", Val::vec3(&v3(&c[0], 6)))
                    .val("surface colour", Val::vec3(&v3(&c[0], 9)))
            });
            rec.section(Msg::SecLightFace);
            render::light_at(
                mat,
                lights,
                [c[0][9], c[0][10], c[0][11]],
                v3(&c[0], 3),
                v3(&c[0], 6),
                f.ortho,
                rec,
            );
        }
        Shading::Gouraud => {
            for (n, corner) in c.iter().enumerate() {
                rec.section(Msg::SecLightVertex(n));
                render::light_at(
                    mat,
                    lights,
                    [corner[9], corner[10], corner[11]],
                    v3(corner, 3),
                    v3(corner, 6),
                    f.ortho,
                    rec,
                );
            }
            rec.section(Msg::SecPixel(x, y));
            rec.step(|| {
                Step::new(Msg::Gouraud, "C = μ₀C₀ + μ₁C₁ + μ₂C₂")
                    .val("C₀", Val::vec3(&v3(&c[0], 0)))
                    .val("C₁", Val::vec3(&v3(&c[1], 0)))
                    .val("C₂", Val::vec3(&v3(&c[2], 0)))
                    .res("C", Val::vec3(&Vector3::new(at(0), at(1), at(2))))
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
                    "N₀, N₁, N₂",
                    Val::List(c.iter().map(|k| Val::vec3(&v3(k, 3))).collect()),
                )
                .res("N", Val::vec3(&Vector3::new(n[0], n[1], n[2])))
                .res("P (eye space)", Val::vec3(&Vector3::new(p[0], p[1], p[2])))
                .res("C", Val::vec3(&Vector3::new(col[0], col[1], col[2])))
            });
            rec.section(Msg::SecLightPixel);
            render::pixel_color(t, c, x, y, &f.looks, f.ortho, rec);
        }
    }
    rec.section(Msg::SecPixel(x, y));
    let px = &f.rgb[3 * k..3 * k + 3];
    let col = render::pixel_color(
        t,
        c,
        x,
        y,
        &f.looks,
        f.ortho,
        &mut crate::stages::trace::NoTrace,
    );
    rec.step(|| {
        Step::new(Msg::PixelColour, Msg::FByte)
            .val("C", Val::vec3(&Vector3::new(col[0], col[1], col[2])))
            .res(
                "RGB",
                Val::text(format!("({}, {}, {})", px[0], px[1], px[2])),
            )
    });
}
