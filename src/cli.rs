//! The command line (SPEC §4): clap definitions, dispatch by precision, and
//! the single place where a report or an error is printed.

use crate::commands;
use crate::error::{Error, Result};
use crate::num::Precision;
use crate::report::{Report, Style};
use clap::{Args, Parser, Subcommand};
use std::ffi::OsString;
use std::path::PathBuf;

/// grafika — worked solutions for the 3D viewing pipeline and shading.
#[derive(Parser, Debug)]
#[command(name = "grafika", version, about, long_about = None, propagate_version = true)]
pub struct Cli {
    /// Output and precision options.
    #[command(flatten)]
    pub common: Common,
    /// What to compute.
    #[command(subcommand)]
    pub command: Command,
}

/// Options every calculator command takes.
#[derive(Args, Debug, Clone)]
pub struct Common {
    /// Arithmetic: exact (sums of surds, with decimals), f64 or f32.
    #[arg(long, value_enum, default_value_t = Precision::Exact, global = true)]
    pub precision: Precision,
    /// Significant digits of the decimals shown.
    #[arg(long, default_value_t = 4, global = true, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// Print one JSON object (SPEC §3) instead of the worked solution.
    #[arg(long, global = true)]
    pub json: bool,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Camera basis u, v, n from eye, look-at point and up vector.
    Basis(CameraArgs),
    /// View matrix and eye coordinates of world points.
    View {
        #[command(flatten)]
        camera: CameraArgs,
        /// A world point NAME=X,Y,Z (repeatable).
        #[arg(long = "point", value_name = "NAME=X,Y,Z", allow_hyphen_values = true)]
        points: Vec<String>,
    },
    /// Perspective or orthographic projection of eye-coordinate points.
    Project(ProjectArgs),
    /// Viewing window from fovy/aspect/near, and the viewport mapping.
    Window(WindowArgs),
    /// 3D line clipping with 6-bit outcodes (cross-checked by Liang–Barsky).
    Clip(ClipArgs),
    /// Lighting at one surface point: the text's models and Direct3D 9 Blinn–Phong.
    Shade(ShadeArgs),
    /// Run time against error: time per operation and error in ulps
    /// against the exact path, per stage and precision.
    Bench {
        /// A few cases and passes only (seconds, for tests).
        #[arg(long)]
        quick: bool,
        /// Random cases per stage (each stage adds about as many adversarial
        /// ones); default 60, or 6 with --quick.
        #[arg(long, value_parser = clap::value_parser!(u16).range(2..=5000))]
        cases: Option<u16>,
    },
    /// A whole problem from a TOML file.
    Solve {
        /// The problem file.
        file: PathBuf,
    },
    /// Mark a student's answers to a problem, and diagnose the mistakes.
    Check(crate::check_cmd::CheckArgs),
    /// Generate problems, question sheets and answer keys.
    Generate(crate::generate::GenerateArgs),
    /// Render a scene file (TOML) to a PNG: flat, Gouraud or Phong shading.
    Render(crate::render_cmd::RenderArgs),
}

/// The camera flags.
#[derive(Args, Debug)]
pub struct CameraArgs {
    /// Eye position Pe, X,Y,Z.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub eye: String,
    /// Look-at (reference) point Pr, X,Y,Z.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub look: String,
    /// Up vector Vup, X,Y,Z.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub up: String,
}

/// The projection flags.
#[derive(Args, Debug)]
pub struct ProjectArgs {
    /// Centre of projection at the origin, view plane z = D.
    #[arg(long, allow_hyphen_values = true, value_name = "D")]
    pub d: Option<String>,
    /// Centre of projection at z = ZPRP on the z axis (general form, with --plane).
    #[arg(long, allow_hyphen_values = true, value_name = "ZPRP")]
    pub cop: Option<String>,
    /// View plane z = ZVP (general form, with --cop).
    #[arg(long, allow_hyphen_values = true, value_name = "ZVP")]
    pub plane: Option<String>,
    /// Orthographic projection (xp = x, yp = y, zp = 0).
    #[arg(long)]
    pub ortho: bool,
    /// An eye-coordinate point NAME=X,Y,Z (repeatable).
    #[arg(long = "point", value_name = "NAME=X,Y,Z", allow_hyphen_values = true)]
    pub points: Vec<String>,
}

/// The window flags.
#[derive(Args, Debug)]
pub struct WindowArgs {
    /// Vertical field of view (degrees; append `rad` for radians).
    #[arg(long, allow_hyphen_values = true)]
    pub fovy: String,
    /// Aspect ratio width/height.
    #[arg(long, allow_hyphen_values = true)]
    pub aspect: String,
    /// Distance to the near plane.
    #[arg(long, allow_hyphen_values = true)]
    pub near: String,
    /// Distance to the far plane (adds the far-plane window).
    #[arg(long, allow_hyphen_values = true)]
    pub far: Option<String>,
    /// Viewport size in pixels, WxH.
    #[arg(long, value_name = "WxH")]
    pub viewport: Option<String>,
    /// A projected point NAME=X,Y on the near plane (repeatable; needs --viewport).
    #[arg(long = "point", value_name = "NAME=X,Y", allow_hyphen_values = true)]
    pub points: Vec<String>,
}

/// The clipping flags.
#[derive(Args, Debug)]
pub struct ClipArgs {
    /// Box corner (xmin, ymin, zmin).
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub min: String,
    /// Box corner (xmax, ymax, zmax).
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub max: String,
    /// Segment start P0.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub from: String,
    /// Segment end P1.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub to: String,
}

/// On or off (`--specular off`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum OnOff {
    /// On.
    #[default]
    On,
    /// Off.
    Off,
}

/// The lighting flags (SPEC §4 and the Direct3D extras).
#[derive(Args, Debug, Default)]
pub struct ShadeArgs {
    /// L, toward the light (one white directional light), X,Y,Z.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub light: Option<String>,
    /// N, the surface normal.
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub normal: Option<String>,
    /// V, toward the viewer (default 0,0,1, the text's viewVector).
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub view: Option<String>,
    /// Cs, the surface color, R,G,B in [0, 1].
    #[arg(long, allow_hyphen_values = true, value_name = "R,G,B")]
    pub color: Option<String>,
    /// Ambient coefficient (default 0.4).
    #[arg(long, allow_hyphen_values = true)]
    pub ka: Option<String>,
    /// Diffuse coefficient (default 0.6).
    #[arg(long, allow_hyphen_values = true)]
    pub kd: Option<String>,
    /// Specular coefficient (default 0.7).
    #[arg(long, allow_hyphen_values = true)]
    pub ks: Option<String>,
    /// Specular exponent n (default 4).
    #[arg(long, allow_hyphen_values = true)]
    pub shininess: Option<String>,
    /// Lighting model (default phong).
    #[arg(long, value_enum)]
    pub model: Option<crate::lighting::Model>,
    /// Camera position Cp: local viewer, V = norm(Cp − Vp).
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub camera: Option<String>,
    /// Surface point Vp in eye space (default the origin).
    #[arg(long, allow_hyphen_values = true, value_name = "X,Y,Z")]
    pub position: Option<String>,
    /// Specular term on or off (Direct3D's D3DRS_SPECULARENABLE).
    #[arg(long, value_enum, default_value_t = OnOff::On)]
    pub specular: OnOff,
    /// No specular when the light is behind the surface (cos α ≤ 0); the text's code adds it.
    #[arg(long)]
    pub specular_requires_lit: bool,
    /// Global ambient light Ga, R,G,B.
    #[arg(long, allow_hyphen_values = true, value_name = "R,G,B")]
    pub global_ambient: Option<String>,
    /// Lights (and a Direct3D material) from a TOML file.
    #[arg(long, value_name = "FILE.toml")]
    pub lights: Option<PathBuf>,
}

/// Runs a generic command at the precision asked for.
macro_rules! at_precision {
    ($p:expr, $f:ident ( $($arg:expr),* )) => {
        match $p {
            Precision::Exact => $f::<crate::num::Real>($($arg),*),
            Precision::F64 => $f::<f64>($($arg),*),
            Precision::F32 => $f::<f32>($($arg),*),
        }
    };
}

/// Runs one parsed command line.
pub fn run(cli: &Cli) -> Result<Report> {
    let p = cli.common.precision;
    match &cli.command {
        Command::Basis(c) => at_precision!(p, basis(c)),
        Command::View { camera, points } => at_precision!(p, view(camera, points)),
        Command::Project(a) => at_precision!(p, project(a)),
        Command::Window(a) => at_precision!(p, window(a)),
        Command::Clip(a) => at_precision!(p, clip(a)),
        Command::Shade(a) => at_precision!(p, shade(a)),
        Command::Solve { file } => at_precision!(p, solve(file)),
        Command::Check(_) | Command::Generate(_) | Command::Bench { .. } => Err(Error::new(
            "command",
            "check, generate and bench print their own output: use main_with_args",
        )),
        // The renderer computes at f32 (the calculator's precisions are for explaining).
        Command::Render(a) => crate::render_cmd::run(a),
    }
}

fn basis<T: crate::num::Scalar>(c: &CameraArgs) -> Result<Report> {
    commands::basis::<T>(c)
}
fn view<T: crate::num::Scalar>(c: &CameraArgs, pts: &[String]) -> Result<Report> {
    commands::view::<T>(c, pts)
}
fn project<T: crate::num::Scalar>(a: &ProjectArgs) -> Result<Report> {
    commands::project::<T>(a)
}
fn window<T: crate::num::Scalar>(a: &WindowArgs) -> Result<Report> {
    commands::window::<T>(a)
}
fn clip<T: crate::num::Scalar>(a: &ClipArgs) -> Result<Report> {
    commands::clip::<T>(a)
}
fn shade<T: crate::num::Scalar>(a: &ShadeArgs) -> Result<Report> {
    commands::shade::<T>(a)
}
fn solve<T: crate::num::Scalar>(file: &std::path::Path) -> Result<Report> {
    crate::solve::solve_file::<T>(file)
}

/// Parses the arguments, runs, prints; returns the exit status (0, or 2 for
/// any error).
pub fn main_with_args(args: Vec<OsString>) -> i32 {
    let wants_json = args.iter().any(|a| a == "--json");
    let cli = match Cli::try_parse_from(&args) {
        Ok(c) => c,
        Err(e) => {
            use clap::error::{ContextKind, ErrorKind};
            if matches!(
                e.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = e.print();
                return if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                    2
                } else {
                    0
                };
            }
            let field = e
                .get(ContextKind::InvalidArg)
                .map(|v| v.to_string())
                .unwrap_or_else(|| "arguments".to_string());
            let message = e.kind().to_string();
            return report_error(
                &Error::new(field, message),
                wants_json,
                Some(e.render().to_string()),
            );
        }
    };
    if let Command::Bench { quick, cases } = cli.command {
        let mut set = if quick {
            crate::bench::Settings::quick()
        } else {
            crate::bench::Settings::full()
        };
        if let Some(n) = cases {
            set.cases = n as usize;
        }
        let (inp, rows) = crate::bench::measure(&set);
        if cli.common.json {
            println!(
                "{}",
                serde_json::to_string_pretty(&crate::bench::to_json(&inp, &rows))
                    .unwrap_or_default()
            );
        } else {
            print!("{}", crate::bench::table(&inp, &rows));
        }
        return 0;
    }
    let own_output = match &cli.command {
        Command::Check(a) => Some(crate::check_cmd::run(
            a,
            cli.common.json,
            cli.common.digits as usize,
        )),
        Command::Generate(a) => Some(crate::generate::run(
            a,
            cli.common.json,
            cli.common.digits as usize,
        )),
        _ => None,
    };
    if let Some(out) = own_output {
        return match out {
            Ok(text) => {
                print!("{text}");
                0
            }
            Err(e) => report_error(&e, cli.common.json, None),
        };
    }
    match run(&cli) {
        Ok(report) => {
            for w in &report.warnings {
                eprintln!("warning: {w}");
            }
            if cli.common.json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&report.to_json()).unwrap_or_default()
                );
            } else {
                let style = Style {
                    digits: cli.common.digits as usize,
                    exact_mode: cli.common.precision == Precision::Exact,
                };
                print!("{}", report.to_text(&style));
            }
            0
        }
        Err(e) => report_error(&e, cli.common.json, None),
    }
}

/// Prints an error (stderr; and JSON on stdout with `--json`), returns 2.
fn report_error(e: &Error, json: bool, long: Option<String>) -> i32 {
    match long {
        Some(text) => eprint!("{text}"),
        None => eprintln!("error: {e}"),
    }
    if json {
        println!(
            "{}",
            serde_json::json!({ "error": { "field": e.field, "message": e.message } })
        );
    }
    2
}
