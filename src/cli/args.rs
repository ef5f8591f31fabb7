//! The command-line arguments (docs/spec.md §4): every flag of every command, as
//! clap reads them. The only file besides the dispatch that knows clap; the
//! choices of the layers below (precision, model, shading, ...) get their
//! command-line names here.

use crate::input::scene::{Normals, Shading};
use crate::num::Precision;
use crate::report::lang::Lang;
use crate::report::moodle::Decimal;
use crate::report::writer::{self, ExamWriter};
use crate::stages::lighting::Model;
use crate::tutor::generate::{ClipCase, Difficulty, Topic};
use clap::builder::PossibleValue;
use clap::{
    Arg, ArgAction, ArgMatches, Args, CommandFactory, FromArgMatches, Parser, Subcommand, ValueEnum,
};
use std::path::PathBuf;

/// grafika — worked solutions for the 3D viewing pipeline and shading.
#[derive(Parser, Debug)]
#[command(name = "grafika", version, about, long_about = None, propagate_version = true)]
struct Parsed {
    /// What to compute.
    #[command(subcommand)]
    command: Command,
}

/// A command line: the command, and the options of [`Common`] given after
/// its name or before it (`grafika --lang id basis …`).
#[derive(Debug)]
pub struct Cli {
    /// The options, as the command takes them (defaults where not given).
    pub common: Common,
    /// What to compute.
    pub command: Command,
}

/// The options several commands take ([`TAKES`] says which).
#[derive(Debug, Clone)]
pub struct Common {
    /// Arithmetic: exact, f64 or f32.
    pub precision: Precision,
    /// Significant digits of the decimals shown.
    pub digits: u8,
    /// JSON instead of text.
    pub json: bool,
    /// The language of the words (none: the environment's).
    pub lang: Option<Lang>,
    /// The worked solution as an HTML page, to this new file.
    pub html: Option<std::path::PathBuf>,
    /// Replace output files that exist (never an input, never through a link).
    pub force: bool,
    /// An option given before a command that does not take it, and the
    /// command.
    pub misplaced: Option<(Opt, &'static str)>,
}

/// An option of [`Common`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Opt {
    /// `--precision`.
    Precision,
    /// `--digits`.
    Digits,
    /// `--json`.
    Json,
    /// `--lang`.
    Lang,
    /// `--html`.
    Html,
    /// `--force`.
    Force,
}

impl Opt {
    /// Every option of [`Common`].
    pub const ALL: [Opt; 6] = [
        Opt::Precision,
        Opt::Digits,
        Opt::Json,
        Opt::Lang,
        Opt::Html,
        Opt::Force,
    ];

    /// The flag's name (without `--`).
    pub fn name(self) -> &'static str {
        match self {
            Opt::Precision => "precision",
            Opt::Digits => "digits",
            Opt::Json => "json",
            Opt::Lang => "lang",
            Opt::Html => "html",
            Opt::Force => "force",
        }
    }

    /// The flag as clap reads it; `json` says what `--json` prints.
    fn arg(self, json: &'static str) -> Arg {
        let arg = Arg::new(self.name()).long(self.name());
        match self {
            Opt::Precision => arg
                .value_name("PRECISION")
                .value_parser(clap::value_parser!(Precision))
                .default_value("exact")
                .help("Arithmetic: exact (sums of surds, with decimals), f64 or f32"),
            Opt::Digits => arg
                .value_name("N")
                .value_parser(clap::value_parser!(u8).range(1..=17))
                .default_value("4")
                .help("Significant digits of the decimals shown"),
            Opt::Json => arg.action(ArgAction::SetTrue).help(json),
            Opt::Lang => arg.value_name("LANG").value_parser(clap::value_parser!(Lang)).help(
                "The language of the words: id (Bahasa Indonesia) or en (default: GRAFIKA_LANG, then the locale)",
            ),
            Opt::Html => arg
                .value_name("FILE.html")
                .value_parser(clap::value_parser!(std::path::PathBuf))
                .help("Also write the worked solution as one self-contained HTML page (formulas in MathML, figures inline) to this file (an existing one only with --force)"),
            Opt::Force => arg.action(ArgAction::SetTrue).help(
                "Replace output files that exist (never one of the command's inputs, never through a link)",
            ),
        }
    }
}

const JSON_REPORT: &str = "Print one JSON object (docs/spec.md §3) instead of the worked solution";
const WORKED: &[Opt] = &Opt::ALL;

/// The options of [`Common`] each command takes after its name (its
/// `--help` lists them; it refuses the others), and what its `--json`
/// prints.
pub const TAKES: [(&str, &[Opt], &str); 15] = [
    ("basis", WORKED, JSON_REPORT),
    ("view", WORKED, JSON_REPORT),
    ("project", WORKED, JSON_REPORT),
    ("window", WORKED, JSON_REPORT),
    ("clip", WORKED, JSON_REPORT),
    ("shade", WORKED, JSON_REPORT),
    ("solve", WORKED, JSON_REPORT),
    (
        "render",
        &[Opt::Digits, Opt::Json, Opt::Lang, Opt::Html, Opt::Force],
        "Print one JSON object (docs/spec.md §3) instead of the summary",
    ),
    (
        "check",
        &[Opt::Digits, Opt::Json, Opt::Lang, Opt::Force],
        "Print the marking as one JSON object instead of the report",
    ),
    (
        "practice",
        &[Opt::Digits, Opt::Json, Opt::Lang],
        "Print JSON Lines: one JSON object per event (docs/spec.md, practice protocol)",
    ),
    (
        "generate",
        &[Opt::Digits, Opt::Json, Opt::Lang, Opt::Force],
        "Print the files written as one JSON object",
    ),
    (
        "bench",
        &[Opt::Json, Opt::Lang],
        "Print the measurement as one JSON object instead of the table",
    ),
    ("completions", &[Opt::Lang], ""),
    ("man", &[Opt::Lang], ""),
    ("help", &[], ""),
];

/// A command's name and the options it takes after its name.
pub fn takes(command: &str) -> (&'static str, &'static [Opt]) {
    TAKES
        .iter()
        .find(|(c, ..)| *c == command)
        .map_or(("", &[]), |(c, o, _)| (*c, *o))
}

impl CommandFactory for Cli {
    /// The commands of [`Command`], each with its share of [`Common`];
    /// the options before a command are all of them.
    fn command() -> clap::Command {
        let top = Opt::ALL.map(|o| {
            o.arg("Print JSON instead of text (see the command's --help)")
                .help_heading(
                    "Options before the command (each command's --help lists those it takes)",
                )
        });
        let mut cmd = Parsed::command().args(top);
        for (name, opts, json) in TAKES {
            if name != "help" {
                cmd = cmd.mut_subcommand(name, |c| c.args(opts.iter().map(|o| o.arg(json))));
            }
        }
        cmd.mut_subcommand("generate", |c| {
            c.mut_arg("force", |a| {
                a.help("Replace generate's own earlier output in --out (never a file it did not write), and write more than 2,000 problems")
            })
        })
    }
    fn command_for_update() -> clap::Command {
        Cli::command()
    }
}

impl FromArgMatches for Cli {
    fn from_arg_matches(m: &ArgMatches) -> Result<Cli, clap::Error> {
        let parsed = Parsed::from_arg_matches(m)?;
        let (name, sub) = m.subcommand().unwrap_or(("", m));
        Ok(Cli {
            common: Common::from_matches(m, name, sub),
            command: parsed.command,
        })
    }
    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Cli::from_arg_matches(m)?;
        Ok(())
    }
}

impl Parser for Cli {}

impl Common {
    /// The options of command `name`: each as given after its name (`sub`),
    /// else before it (`top`), else its default.
    fn from_matches(top: &ArgMatches, name: &str, sub: &ArgMatches) -> Common {
        let (name, taken) = takes(name);
        let given = |m: &ArgMatches, o: Opt| {
            m.value_source(o.name()) == Some(clap::parser::ValueSource::CommandLine)
        };
        let from = |o: Opt| match taken.contains(&o) && given(sub, o) {
            true => sub,
            false => top,
        };
        Common {
            precision: from(Opt::Precision)
                .get_one::<Precision>("precision")
                .copied()
                .unwrap_or(Precision::Exact),
            digits: from(Opt::Digits)
                .get_one::<u8>("digits")
                .copied()
                .unwrap_or(4),
            json: from(Opt::Json).get_flag("json"),
            lang: from(Opt::Lang).get_one::<Lang>("lang").copied(),
            html: from(Opt::Html)
                .get_one::<std::path::PathBuf>("html")
                .cloned(),
            force: from(Opt::Force).get_flag("force"),
            misplaced: Opt::ALL
                .into_iter()
                .find(|o| given(top, *o) && !taken.contains(o))
                .map(|o| (o, name)),
        }
    }
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Camera basis u, v, n from eye, look-at point and up vector.
    #[command(
        after_help = "Examples / Contoh:\n  grafika basis --eye 3,1,3 --look 2,1,2 --up 0,1,0\n  grafika basis --eye \"(3,1,3)\" --look 2,1,2 --up 0,1,0 --precision f64"
    )]
    Basis(CameraArgs),
    /// View matrix and eye coordinates of world points.
    #[command(
        after_help = "Examples / Contoh:\n  grafika view --eye 4,4,4 --look 0,1,4 --up 0,1,0 --point Pref=0,1,4"
    )]
    View {
        #[command(flatten)]
        camera: CameraArgs,
        /// A world point NAME=X,Y,Z (repeatable).
        #[arg(long = "point", value_name = "NAME=X,Y,Z", allow_hyphen_values = true)]
        points: Vec<String>,
    },
    /// Perspective or orthographic projection of eye-coordinate points.
    #[command(
        after_help = "Examples / Contoh:\n  grafika project --d -0.1 --point \"A=0,-1,-6/sqrt(2)\"\n  grafika project --cop 5 --plane 0 --point A=1,2,-3\n  grafika project --ortho --point A=1,2,-3"
    )]
    Project(ProjectArgs),
    /// Viewing window from fovy/aspect/near, and the viewport mapping.
    #[command(
        after_help = "Examples / Contoh:\n  grafika window --fovy 45 --aspect 2 --near 0.1 --viewport 200x100 --point \"A=0,-sqrt(2)/60\"\n  grafika window --fovy \"pi/4 rad\" --aspect 2 --near 0.1 --far 10"
    )]
    Window(WindowArgs),
    /// 3D line clipping with 6-bit outcodes (cross-checked by Liang–Barsky).
    #[command(
        after_help = "Examples / Contoh:\n  grafika clip --min 0,0,0 --max 3,4,3 --from 4,2,2 --to -2,6,1"
    )]
    Clip(ClipArgs),
    /// Lighting at one surface point: the text's models and Direct3D 9 Blinn–Phong.
    #[command(
        after_help = "Examples / Contoh:\n  grafika shade --light 0,0,1 --normal 0,1,1 --view 0,0,1 --color 1,1,0\n  grafika shade --light 0,0,1 --normal 0,1,1 --view 0,0,1 --color 1,1,0 --model blinn"
    )]
    Shade(ShadeArgs),
    /// Run time against error: time per operation and error in ulps
    /// against the exact path, per stage and precision.
    #[command(after_help = "Examples / Contoh:\n  grafika bench --quick\n  grafika bench --json")]
    Bench {
        /// A few cases and passes only (seconds, for tests).
        #[arg(long)]
        quick: bool,
        /// Random cases per stage (each stage adds about as many adversarial
        /// ones); default 60, or 6 with --quick.
        #[arg(long, value_parser = clap::value_parser!(u16).range(2..=5000))]
        cases: Option<u16>,
    },
    /// Shell completions for bash, zsh, fish, elvish or PowerShell, on standard output.
    #[command(
        after_help = "Examples / Contoh:\n  grafika completions bash > ~/.local/share/bash-completion/completions/grafika\n  grafika completions zsh > ~/.zfunc/_grafika"
    )]
    Completions {
        /// The shell.
        shell: clap_complete::Shell,
    },
    /// The manual page (roff) on standard output.
    #[command(after_help = "Examples / Contoh:\n  grafika man > grafika.1 && man ./grafika.1")]
    Man,
    /// A whole problem from a TOML file.
    #[command(
        after_help = "Examples / Contoh:\n  grafika solve problems/text-triangle.toml\n  grafika solve problems/text-triangle.toml --figure triangle.svg\n  grafika solve - --precision f64 < problems/text-camera.toml"
    )]
    Solve {
        /// The problem file.
        file: PathBuf,
        /// Also draw one figure per part of the problem, each into an SVG
        /// file named after FILE.svg and the part: FILE-1-view.svg,
        /// FILE-2-project.svg, FILE-3-window.svg, FILE-4-clip.svg,
        /// FILE-5-shade.svg (numbered in the order of the parts drawn; none
        /// is written if any exists, unless --force replaces them).
        #[arg(long, value_name = "FILE.svg")]
        figure: Option<PathBuf>,
    },
    /// Mark a student's answers to a problem, and diagnose the mistakes.
    #[command(
        after_help = "Examples / Contoh:\n  grafika check problems/text-triangle.toml --answers problems/answers/triangle/siti.toml\n  grafika check problems/text-triangle.toml --answers problems/answers/triangle/ --csv marks.csv\n  grafika check problems/text-triangle.toml --answers-from-text"
    )]
    Check(CheckArgs),
    /// Generate problems, question sheets and answer keys.
    #[command(
        after_help = "Examples / Contoh:\n  grafika generate --topic view,window,clip --count 5 --variants 30 --seed 2026 --out exam\n  grafika generate --topic shade --difficulty easy --format latex --out sheet"
    )]
    Generate(GenerateArgs),
    /// Render a scene file (TOML) to a PNG: flat, Gouraud or Phong shading.
    #[command(
        after_help = "Examples / Contoh:\n  grafika render problems/render/cone-flat.toml -o cone.png --stats\n  grafika render problems/render/cone-flat.toml -o cone.png --explain-pixel 330,150"
    )]
    Render(RenderArgs),
    /// Practise a problem one value at a time: verdict, diagnosis, hints,
    /// follow-through (answers and commands from standard input).
    #[command(
        after_help = "Examples / Contoh:\n  grafika practice problems/text-camera.toml\n  grafika practice --topic clip --difficulty easy --seed 3\n  grafika --lang id practice --topic window --difficulty medium"
    )]
    Practice(PracticeArgs),
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
    /// Also draw the figure (world axes, Peye, Pref, Vup, u, v, n at the eye and the points, in an axonometric view where u, v, n read) into this SVG file (an existing one only with --force).
    #[arg(long, value_name = "FILE.svg")]
    pub figure: Option<std::path::PathBuf>,
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
    /// Also draw the figure (centre of projection, view plane and projectors in 3D; the side view y-z with the similar triangles; the images on the view plane) into this SVG file (an existing one only with --force).
    #[arg(long, value_name = "FILE.svg")]
    pub figure: Option<std::path::PathBuf>,
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
    /// Also draw the figure (the view volume seen from outside with the near and far windows; the side view with fovy and top; the points on the window; the viewport with their pixels) into this SVG file (an existing one only with --force).
    #[arg(long, value_name = "FILE.svg")]
    pub figure: Option<std::path::PathBuf>,
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
    /// Also draw the figure (the box with its six planes named, the segment, P0 and P1 with their outcodes; the segment along t with each intersection's t, point and outcode; kept part solid, cut-off parts dashed) into this SVG file (an existing one only with --force).
    #[arg(long, value_name = "FILE.svg")]
    pub figure: Option<std::path::PathBuf>,
}

/// On or off (`--specular off`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, ValueEnum)]
pub enum OnOff {
    /// On.
    #[default]
    On,
    /// Off.
    Off,
}

/// The lighting flags (docs/spec.md §4 and the Direct3D extras).
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
    pub model: Option<Model>,
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
    /// Also draw the figure (a flat diagram in the plane of N and L: the surface, N, L, R, V and H for Blinn at their true angles, with alpha and beta) into this SVG file (an existing one only with --force).
    #[arg(long, value_name = "FILE.svg")]
    pub figure: Option<std::path::PathBuf>,
}

/// The `check` flags.
#[derive(Args, Debug)]
pub struct CheckArgs {
    /// The problem file, or an exam folder written by `grafika generate`
    /// (answer files then say `variant = N` and hold one `[problem-NN]`
    /// table per problem).
    pub file: PathBuf,
    /// The student's answers (TOML keyed like the JSON results), or a
    /// directory of answer files, one per student.
    #[arg(long, value_name = "FILE|DIR")]
    pub answers: Option<PathBuf>,
    /// Check the answers printed in the source (the file's `[printed]` table).
    #[arg(long)]
    pub answers_from_text: bool,
    /// Relative tolerance (default 0.001, i.e. 0.1%).
    #[arg(long, value_name = "R")]
    pub tolerance: Option<f64>,
    /// Minimum significant figures of a rounded decimal answer (default 2).
    #[arg(long, value_name = "N")]
    pub sig_figs: Option<u32>,
    /// With a directory of answers: write a CSV summary to this file (`-` for stdout).
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// With a directory of answers: write the lecturer's report of the
    /// class (per answer key: counts, facility, discrimination; the
    /// mistakes and who made them; wrong answers no mistake explains; the
    /// score histogram) to this file, as .html, .md, .json or .csv by its
    /// extension.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// With a directory of answers: the class list, one name per line or
    /// CSV with a `nama` (or `name`) column and optionally `nim`; the
    /// table and the report list who handed nothing in and the files of
    /// no one on the list.
    #[arg(long, value_name = "FILE")]
    pub roster: Option<PathBuf>,
    /// Credit a wrong answer that is right given the student's own earlier
    /// answers (pixels from their window and projected points, ...) as
    /// correct.follow_through.
    #[arg(long)]
    pub follow_through: bool,
    /// Re-mark a Moodle quiz made from this exam: its Responses report as
    /// downloaded (Quiz → Results → Responses, CSV, JSON, Excel or
    /// OpenDocument; its columns in English or Indonesian), each finished
    /// attempt marked as an answer file of the class.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["answers", "answers_from_text"])]
    pub moodle_responses: Option<PathBuf>,
    /// With --moodle-responses: write the grades for Moodle's gradebook
    /// import (CSV: email, ID number, name, grafika's grade, Moodle's).
    #[arg(long, value_name = "FILE", requires = "moodle_responses")]
    pub grades: Option<PathBuf>,
    /// With --moodle-responses: write each student's marked sheet (text)
    /// into this folder.
    #[arg(long, value_name = "DIR", requires = "moodle_responses")]
    pub sheets: Option<PathBuf>,
}

/// The `practice` flags.
#[derive(Args, Debug)]
pub struct PracticeArgs {
    /// The problem file (or draw one with --topic).
    #[arg(required_unless_present = "topic", conflicts_with = "topic")]
    pub file: Option<PathBuf>,
    /// Draw a problem on this topic (the problem `generate` writes first
    /// for the same topic, difficulty and seed).
    #[arg(long, value_enum)]
    pub topic: Option<Topic>,
    /// How nice the numbers of a drawn problem are.
    #[arg(long, value_enum, default_value_t = Difficulty::Medium)]
    pub difficulty: Difficulty,
    /// The seed of a drawn problem (default: from the clock; it is printed).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Relative tolerance (default 0.001, i.e. 0.1%).
    #[arg(long, value_name = "R")]
    pub tolerance: Option<f64>,
    /// Minimum significant figures of a rounded decimal answer (default 2).
    #[arg(long, value_name = "N")]
    pub sig_figs: Option<u32>,
}

/// The `render` flags.
#[derive(Args, Debug, Clone)]
pub struct RenderArgs {
    /// The scene file (TOML, docs/spec.md §6).
    pub scene: PathBuf,
    /// The PNG to write (`-` for standard output; the summary then goes to stderr).
    #[arg(short = 'o', long = "output", value_name = "IMAGE.png")]
    pub output: PathBuf,
    /// Image width in pixels (default: the scene's).
    #[arg(long)]
    pub width: Option<u32>,
    /// Image height in pixels (default: the scene's).
    #[arg(long)]
    pub height: Option<u32>,
    /// Shading (default: the scene's).
    #[arg(long, value_enum)]
    pub shading: Option<Shading>,
    /// Vertex normals: `average` of the adjacent faces, or `position` as the
    /// text's draw3Dcg does (right only for a sphere at the origin).
    #[arg(long, value_enum)]
    pub normals: Option<Normals>,
    /// Print what was drawn and skipped, and the time of each stage.
    #[arg(long)]
    pub stats: bool,
    /// Explain one pixel: column X from the left, row Y from the top.
    #[arg(long, value_name = "X,Y")]
    pub explain_pixel: Option<String>,
    /// Render N times and report the median frame time.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub repeat: u32,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=256))]
    pub threads: Option<u32>,
    /// The most work allowed, in millions of steps (about a pixel test
    /// each): a render estimated at more, all its frames together, is
    /// refused before it starts (docs/spec.md §7).
    #[arg(long, value_name = "MILLIONS", default_value_t = crate::input::scene::WORK_LIMIT,
          value_parser = clap::value_parser!(u64).range(1..))]
    pub work_limit: u64,
}

/// The format of the question sheet and the key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Only the problem files and the answer-key files (TOML).
    Toml,
    /// questions.md and key.md.
    Md,
    /// questions.tex and key.tex (plain pdflatex).
    Latex,
    /// questions.html and key.html: self-contained pages, formulas in MathML.
    Html,
    /// exam.json (statements, answers, worked steps).
    Json,
    /// quiz.xml: Moodle XML, one Cloze question per problem and variant.
    Moodle,
    /// quiz.gift: GIFT, one question per value asked.
    Gift,
}

impl Format {
    /// The format's writer: the one place `generate` matches on its format
    /// (what differs between formats is a method of the writer).
    pub fn writer(self) -> Box<dyn ExamWriter> {
        match self {
            Format::Toml => Box::new(writer::Toml),
            Format::Md => Box::new(writer::Markdown),
            Format::Latex => Box::new(writer::Latex),
            Format::Html => Box::new(writer::Html),
            Format::Json => Box::new(writer::Json),
            Format::Moodle => Box::new(writer::Moodle),
            Format::Gift => Box::new(writer::Gift),
        }
    }
}

/// The `generate` flags.
#[derive(Args, Debug, Clone)]
pub struct GenerateArgs {
    /// The topic; several, comma-separated, alternate through the exam.
    #[arg(long, value_enum, value_delimiter = ',', required = true)]
    pub topic: Vec<Topic>,
    /// Problems per exam.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=500))]
    pub count: u32,
    /// The seed: the same seed gives the same files, byte for byte.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// How nice the numbers are.
    #[arg(long, value_enum, default_value_t = Difficulty::Medium)]
    pub difficulty: Difficulty,
    /// The format of the question sheet and key.
    #[arg(long, value_enum, default_value_t = Format::Md)]
    pub format: Format,
    /// The output directory (created if needed).
    #[arg(long)]
    pub out: PathBuf,
    /// Versions of the exam (one per student), each with its own key; the
    /// variants of a problem are parallel forms (the same keys, marks,
    /// case and number class).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=500))]
    pub variants: u32,
    /// The case of the clipping problems, the same in every variant.
    #[arg(long, value_enum, default_value_t = ClipCase::Clipped)]
    pub clip: ClipCase,
    /// Relative tolerance of the numbers in Moodle and GIFT (default 0.001, i.e. 0.1%).
    #[arg(long, value_name = "R")]
    pub tolerance: Option<f64>,
    /// The decimal mark students type in Moodle and GIFT quizzes: point for
    /// a Moodle in English, comma for one with the Indonesian language pack.
    #[arg(long, value_enum, default_value_t = Decimal::Point)]
    pub decimal: Decimal,
    /// Split a Moodle or GIFT quiz into files of at most MB megabytes
    /// (10⁶ bytes) each, quiz-01.xml, quiz-02.xml, …: PHP's default upload
    /// limit is 2 MB.
    #[arg(long, value_name = "MB")]
    pub split_mb: Option<f64>,
}

/// Gives a type of a lower layer its command-line choices: each variant
/// with its help; its name as typed is the type's own (`$name`: `name`,
/// or `code` for a language), spelled once beside the type.
macro_rules! choices {
    ($ty:ident, $name:ident { $($variant:ident : $help:literal),* $(,)? }) => {
        impl ValueEnum for $ty {
            fn value_variants<'a>() -> &'a [Self] {
                &[$($ty::$variant),*]
            }
            fn to_possible_value(&self) -> Option<PossibleValue> {
                Some(PossibleValue::new(self.$name()).help(match self {
                    $($ty::$variant => $help),*
                }))
            }
        }
    };
}

choices!(
    Precision,
    name {
        Exact: "Exact sums of surds where the mathematics is exact, marked ≈ otherwise",
        F64: "IEEE double precision with stable formulas",
        F32: "IEEE single precision with stable formulas",
    }
);
choices!(
    Decimal,
    name {
        Point: "0.5: a Moodle in English (a typed comma is a thousands separator there)",
        Comma: "0,5: a Moodle with the Indonesian language pack",
    }
);
choices!(
    Lang,
    code {
        Id: "Bahasa Indonesia",
        En: "English",
    }
);
choices!(
    Model,
    name {
        Ambient: "Ambient only: ka·Cs",
        Diffuse: "Diffuse scattering only: kd·max(cos α, 0)·Cs",
        Specular: "Specular reflection only: ks·max(cos β, 0)ⁿ·white",
        Lambert: "Lambert's law: diffuse + ambient",
        Phong: "The Phong model: diffuse + specular + ambient (the text's default)",
        Blinn: "Blinn–Phong (Direct3D 9): the specular term uses N·H",
    }
);
choices!(
    Shading,
    name {
        Flat: "One lighting evaluation per face, with the face normal",
        Gouraud: "Lighting per vertex, colours interpolated",
        Phong: "Normals interpolated, lighting per pixel",
    }
);
choices!(
    Normals,
    name {
        Average: "The normalised average of the adjacent face normals",
        Position: "The transformed vertex position, normalised, as the text's draw3Dcg",
    }
);
choices!(
    Topic,
    name {
        Basis: "The camera basis u, v, n",
        View: "The basis and eye coordinates of points",
        Project: "Projection onto the near plane",
        Window: "The viewing window from fovy, aspect and near",
        Clip: "Line clipping with outcodes",
        Shade: "Lighting at one point",
        Pipeline: "The whole chain: view, projection, window, viewport",
    }
);
choices!(
    Difficulty,
    name {
        Easy: "Every answer rational (integer norms, fovy 90°)",
        Medium: "Square roots of one radicand (fovy 30°, 45°, 60°, 120°); clipping: two planes cut",
        Hard: "Square roots of several radicands; a fovy whose tangent has no closed form; clipping: both ends outside",
    }
);
choices!(
    ClipCase,
    name {
        Clipped: "Cut by the box: at least one intersection to compute and keep",
        Accepted: "Inside the box: accepted whole",
        Rejected: "Beyond one plane at both ends: rejected by the AND test",
        Mixed: "Clipping problems take clipped, accepted, rejected in turn (each problem's variants alike)",
    }
);
