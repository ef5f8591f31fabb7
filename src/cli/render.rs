//! `grafika render`: scene file and flags → frame(s) → PNG, with `--stats`,
//! `--repeat` timing and `--explain-pixel` (the worked steps for one pixel,
//! lighting included, from the same `lighting::shade` the calculator uses).

use crate::cli::args::RenderArgs;
use crate::cli::print::Stopped;
use crate::cli::write::Outputs;
use crate::error::{Error, Result};
use crate::input::scene::{Scene, Shading};
use crate::msg::ErrMsg;
use crate::render::{self, Frame, Options, Stats};
use crate::report::lang::Lang;
use crate::stages::trace::Recorder;
use crate::tutor::solution::{Asked, RenderRun, Report, Results, Times};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Runs `render`; the PNG is written through `outputs` (the scene's mesh
/// files are among the inputs it never writes over).
pub fn run(a: &RenderArgs, lang: Lang, outputs: &Outputs) -> Result<Report> {
    let mut scene = Scene::read(&a.scene, a.work_limit)?;
    outputs.reads(scene.files.iter().map(|p| p.as_path()));
    if a.output.as_os_str() != "-" {
        outputs.check(&a.output, "output")?;
    }
    let opt = options(a, &scene);
    within_limit(a, &scene, &opt)?;
    render::release_unused(&mut scene, &opt);
    let pixel = a.explain_pixel.as_deref().map(parse_pixel).transpose()?;
    if let Some((x, y)) = pixel {
        if x >= opt.width || y >= opt.height {
            return Err(Error::why(
                "--explain-pixel",
                ErrMsg::PixelOutside(x, y, opt.width, opt.height),
            ));
        }
    }
    let (frame, runs) = frames(a, &scene, &opt, lang)?;
    let t = Instant::now();
    if a.output.as_os_str() == "-" {
        match crate::cli::print::stdout_bytes(&mut |w| encode_png(&frame, w)) {
            Ok(()) => {}
            // The reader went away: nothing more to say (docs/spec.md §7).
            Err(Stopped::Pipe) => std::process::exit(0),
            Err(Stopped::Failed(e)) => return Err(e),
        }
    } else {
        outputs.write_with(&a.output, "output", &mut |w| encode_png(&frame, w))?;
    }
    let encode = t.elapsed();
    let mut rec = Recorder::new();
    if let Some((x, y)) = pixel {
        crate::tutor::pixel::explain(&frame, &scene, &opt, (x, y), &mut rec)?;
    }
    Ok(report(
        a,
        (&scene, &opt),
        (&frame, &runs),
        encode,
        pixel,
        rec,
    ))
}

/// Refuses a render whose estimated work ([`render::work`]), all its
/// `--repeat` frames together, passes `--work-limit`.
fn within_limit(a: &RenderArgs, scene: &Scene, opt: &Options) -> Result<()> {
    let frame = render::work::estimate(scene, opt)?.total();
    let total = frame.saturating_mul(u64::from(a.repeat));
    if total > a.work_limit.saturating_mul(1_000_000) {
        let e = ErrMsg::RenderWork(total.div_ceil(1_000_000), a.repeat, a.work_limit);
        return Err(Error::why("work-limit", e));
    }
    Ok(())
}

/// The scene's settings with the flags' changes.
fn options(a: &RenderArgs, scene: &Scene) -> Options {
    let mut opt = Options::of(scene);
    opt.shading = a.shading.unwrap_or(opt.shading);
    opt.force_shading = a.shading.is_some();
    opt.normals = a.normals.unwrap_or(opt.normals);
    opt.width = a.width.unwrap_or(opt.width);
    opt.height = a.height.unwrap_or(opt.height);
    opt
}

/// Renders `--repeat` frames (on `--threads` threads), each into the last
/// one's buffers: the last frame and every frame's counters and times.
fn frames(a: &RenderArgs, scene: &Scene, opt: &Options, lang: Lang) -> Result<(Frame, Vec<Stats>)> {
    // --repeat shows its progress on a terminal (a big scene × 10,000 runs
    // for minutes); one frame has the renderer's own bar.
    let bar = (a.repeat > 1)
        .then(|| {
            crate::cli::terminal_bar(
                a.repeat as u64,
                crate::report::words::of(lang).cli(crate::msg::CliWord::Frames),
            )
        })
        .flatten();
    let bands = (opt.height as usize).div_ceil(render::raster::BAND) as u64;
    let progress = Progress::new(a.repeat == 1, bands);
    let go = || -> Result<(Frame, Vec<Stats>)> {
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..a.repeat {
            let f = render::render_observed(scene, opt, last.take(), &|| progress.tick())?;
            times.push(f.stats.clone());
            last = Some(f);
            if let Some(b) = &bar {
                b.inc(1);
            }
        }
        if let Some(b) = &bar {
            b.finish_and_clear();
        }
        progress.finish();
        let f = last.ok_or_else(|| Error::why("--repeat", ErrMsg::NothingRendered))?;
        Ok((f, times))
    };
    let Some(n) = a.threads else {
        return go();
    };
    // The global pool with n threads, so that the frame is allocated on
    // this thread as without --threads (in a pool of its own the frame
    // would be allocated from a worker's arena, beside the memory freed
    // here after reading the scene: 20 MB more at the peak on a
    // 1,048,576-triangle sphere); a pool of its own if the global one runs.
    let pool = rayon::ThreadPoolBuilder::new().num_threads(n as usize);
    if pool.build_global().is_ok() {
        return go();
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(n as usize)
        .build()
        .map_err(|e| Error::why("--threads", ErrMsg::Threads(e.to_string())))?
        .install(go)
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

/// The report of a render: the scene and settings, the last frame's
/// counters, the median times, the explained pixel's steps.
fn report(
    a: &RenderArgs,
    (scene, opt): (&Scene, &Options),
    (frame, runs): (&Frame, &[Stats]),
    encode: Duration,
    pixel: Option<(u32, u32)>,
    rec: Recorder,
) -> Report {
    let median = |f: &dyn Fn(&Stats) -> Duration| {
        let mut v: Vec<Duration> = runs.iter().map(f).collect();
        v.sort();
        v[v.len() / 2]
    };
    let ms = |f: &dyn Fn(&Stats) -> Duration| median(f).as_secs_f64() * 1e3;
    let times = Times {
        runs: runs.len(),
        geometry: ms(&|s| s.geometry),
        binning: ms(&|s| s.binning),
        bands: ms(&|s| s.pass),
        raster: ms(&|s| s.raster),
        shading: ms(&|s| s.shading),
        frame: ms(&|s| s.frame()),
        png: encode.as_secs_f64() * 1e3,
    };
    let frame_s = median(&|s| s.frame()).as_secs_f64();
    let mpixels_per_s = (opt.width as f64 * opt.height as f64) / frame_s / 1e6;
    let run = RenderRun {
        scene: a.scene.display().to_string(),
        output: a.output.display().to_string(),
        size: (opt.width, opt.height),
        shadings: shadings_drawn(scene, opt),
        normals: opt.normals.name().to_string(),
        explain_pixel: pixel,
        stats_asked: a.stats,
        stats: frame.stats.clone(),
        times,
        mpixels_per_s,
    };
    let asked = Asked::Render(Box::new(run));
    Report::from_recorder::<f32>(asked, vec![], Results::default(), rec)
}

/// The shadings drawn: the one forced by `--shading`, else each object's
/// own (or the scene's) once, in object order (flat, gouraud).
fn shadings_drawn(scene: &Scene, opt: &Options) -> Vec<Shading> {
    if opt.force_shading || scene.objects.is_empty() {
        return vec![opt.shading];
    }
    let mut seen: Vec<Shading> = Vec::new();
    for o in &scene.objects {
        let s = o.shading.unwrap_or(opt.shading);
        if !seen.contains(&s) {
            seen.push(s);
        }
    }
    seen
}

fn parse_pixel(s: &str) -> Result<(u32, u32)> {
    let bad = || Error::why("--explain-pixel", ErrMsg::PixelText(s.to_string()));
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    Ok((
        x.trim().parse().map_err(|_| bad())?,
        y.trim().parse().map_err(|_| bad())?,
    ))
}

/// The frame as an 8-bit RGB PNG, written to `out` (a file, standard output).
fn encode_png(frame: &Frame, out: &mut dyn std::io::Write) -> std::io::Result<()> {
    let io = |e: png::EncodingError| match e {
        png::EncodingError::IoError(e) => e,
        e => std::io::Error::other(e.to_string()),
    };
    let mut enc = png::Encoder::new(out, frame.width, frame.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let mut wr = enc.write_header().map_err(io)?;
    wr.write_image_data(&frame.rgb).map_err(io)?;
    wr.finish().map_err(io)
}
