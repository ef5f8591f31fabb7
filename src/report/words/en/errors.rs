//! The error keys' words in English: [`ErrorWords`] for [`En`], one
//! exhaustive match per key enum. The crates' own messages (clap's line,
//! serde's and the TOML reader's phrases, Rust's number parsing) are
//! English already: their words here are the crates' words.

use super::En;
use crate::msg::{
    Bound, Channel, ClapErr, ErrMsg, FileKind, IoWhy, ListWhy, NumErr, ObjWhy, Thing, TomlErr,
    Twice, Want,
};
use crate::report::lang::NumStyle;
use crate::report::words::errors::{
    self, folder_prefix, ErrorWords, ExpectWord, Expected, ParseWhy, SerdeWord, Syntax, SyntaxWhat,
    ValueWhy,
};

/// The number style of English words.
fn nums() -> NumStyle {
    crate::report::words::MsgWords::nums(&En)
}

/// A value given back as it was read (`0.5`).
fn n(x: f64) -> String {
    nums().shortest(x)
}

impl ErrorWords for En {
    fn error(&self, m: &ErrMsg) -> String {
        match m {
            ErrMsg::Num(e) => self.number(e),
            ErrMsg::Toml(e) => self.toml(e),
            ErrMsg::Clap(e, line) => self.clap(e, line),
            ErrMsg::MustBe(b, got) => self.must_be(b, *got),
            ErrMsg::Twice(t) => self.twice(*t).to_string(),
            ErrMsg::CannotRead(p, why) => format!("cannot read {p}: {}", self.io_why(why)),
            ErrMsg::CannotReadStdin(why) => {
                format!("cannot read standard input: {}", self.io_why(why))
            }
            ErrMsg::CannotWrite(p, why) => format!("cannot write {p}: {}", self.io_why(why)),
            ErrMsg::CannotCreate(p, why) => format!("cannot create {p}: {}", self.io_why(why)),
            ErrMsg::CannotWriteStdout(why) => {
                format!("cannot write to standard output: {}", self.io_why(why))
            }
            ErrMsg::StdoutClosed => "standard output is closed, so the results would be lost (to discard them, send them to /dev/null)".into(),
            ErrMsg::ExistsForce(p) => format!("{p} already exists: give --force to replace it, or choose another name"),
            ErrMsg::NamesFolder(p) => format!("{p} is a folder, not a file name: name the file to write (such as {}figure.svg)", folder_prefix(p)),
            ErrMsg::IsLink(p) => format!("{p} is a symbolic link: grafika never writes through a link nor replaces one; name the file itself or another name"),
            ErrMsg::IsInput(p) => format!("{p} is one of this command's own inputs (the same file, links followed): it is never overwritten, even with --force"),
            ErrMsg::NotOwn(p, marker) => format!("{p} was not written by grafika generate (it is not listed in {marker}, or holds other files): --force replaces only generate's own earlier output; move it away or choose another --out"),
            ErrMsg::NotDirectory(p) => format!("{p} exists and is not a directory"),
            ErrMsg::FileTooLarge(p, Some(n), max) => format!("{p} has {n} bytes; a problem, scene, lights or answer file may have at most {max} (it is refused before it is read as TOML)"),
            ErrMsg::FileTooLarge(p, None, max) => format!("{p} has more than {max} bytes; a problem, scene, lights or answer file may have at most {max} (it is refused before it is read as TOML)"),
            ErrMsg::TomlTooManyValues(max) => format!("the file's arrays hold more than {max} values together, more than grafika reads (refused before the file is read as TOML)"),
            ErrMsg::TomlTooDeep(max) => format!("arrays or inline tables nested more than {max} deep (refused before the file is read as TOML)"),
            ErrMsg::StdinClosed => "standard input is closed (<&-), so there is nothing to read: give a file, or send the input with < FILE or a pipe".into(),
            ErrMsg::InputNotRegular(p, k) => format!("{p} is {}, not a regular file: grafika reads only regular files (and standard input, -), so that a read never waits forever", file_kind(*k)),
            ErrMsg::OutputNotRegular(p, k) => format!("{p} is {}: grafika writes only regular files (and character devices such as /dev/null, directly), never replacing anything else; choose another name", file_kind(*k)),
            ErrMsg::SameOutput(p, other) => format!("{p} is also the file of --{other}: one file cannot hold both outputs (nothing was written); give each its own name"),
            ErrMsg::ChangedSince(p) => format!("{p} has changed since grafika generate wrote it (its content is not what grafika wrote): --force replaces only generate's own output as it was written; move it away or choose another --out"),
            ErrMsg::NotOwnList(p, why) => format!("{p} is not a list that grafika generate wrote ({}), so nothing it names is replaced or removed: if this folder holds only an earlier generate's output, remove {p} and give --force, or choose another --out", list_why(why)),
            ErrMsg::ListExists(p) => format!("{p} already exists (an earlier grafika generate wrote into this folder): give --force to replace that output, or choose another --out"),
            ErrMsg::Locked(d, lock) => format!("another grafika generate is writing into {d} now (it holds {lock}): wait until it has finished, or choose another --out"),
            ErrMsg::NotMarked(n, of, which) => format!("{n} of the {of} answer files could not be marked (see the error in each one's row): {which}"),
            ErrMsg::Man(why) => format!("cannot write the manual page: {why}"),
            ErrMsg::ObjUnreadable(p, why) => {
                format!("cannot read the OBJ file {p}: {}", self.io_why(why))
            }
            ErrMsg::ObjInvalid(p, why) => {
                format!("{p} is not a valid OBJ file: {}", self.obj_why(*why))
            }
            ErrMsg::ObjNoFaces(p) => format!("{p} has no faces"),
            ErrMsg::ObjNotFinite(p) => format!("{p} has a vertex that is not a finite number"),
            ErrMsg::FaceVertex => "a face refers to a vertex that does not exist".into(),
            ErrMsg::FormulaNotFinite => "the formula gives a value that is not a finite number".into(),
            ErrMsg::TooManyTriangles(n, max) => format!("the scene's objects have {n} triangles together; the renderer takes at most {max} per scene (refused before any mesh is built)"),
            ErrMsg::TooManyLights(n, max) => format!("the file has {n} lights; grafika takes at most {max} per file (as Direct3D 9 does)"),
            ErrMsg::RenderWork(est, frames, max) => format!("this render is estimated at {est} million steps (the pixels each triangle's box covers, lighting, over {frames} frame(s)), more than the limit of {max} million (about 10 s on 2 cores): give --work-limit {est} to render it anyway, or lower --width, --height or --repeat"),
            ErrMsg::FormulaWork(n, size, need, max) => format!("the height formulas would be evaluated {n} times, {size} operations and numbers each, more than the work limit of {max} million steps (refused before any is evaluated): give render --work-limit {need} to evaluate them anyway, or use fewer grid points (nx, nz) or a shorter formula"),
            ErrMsg::NeedsColour => "needs at least one colour".into(),
            ErrMsg::NoObjects => "the scene has no objects: add at least one [[object]] table (cone, sphere, cylinder, box, plane or obj)".into(),
            ErrMsg::CameraNeedsPerspective => "a [camera] needs a [perspective] with fovy, near and far".into(),
            ErrMsg::ImageSize(w, h) => format!("width and height must be from 1 to 8192 pixels, got {w}x{h}"),
            ErrMsg::Needs(thing, key) => self.needs(thing, key),
            ErrMsg::NoSuchKey(t, k, all) => format!("a {t} has no `{k}` (its fields: {all})"),
            ErrMsg::NeededToRender => "is needed to render".into(),
            ErrMsg::NoLightTable(p) => format!("{p} has no [[light]] table"),
            ErrMsg::ColorMissing => "the surface color Cs is missing (R,G,B in [0, 1])".into(),
            ErrMsg::NormalMissing => "the surface normal N is missing".into(),
            ErrMsg::CameraAtPoint => "the camera is at the surface point: no direction to the viewer".into(),
            ErrMsg::NoLight => "no light: give L (toward the light) or a lights file".into(),
            ErrMsg::LightAtPoint => "the light is at the surface point itself: no direction to it".into(),
            ErrMsg::NotApplicable(k, kind) => format!("`{k}` does not apply to a {kind} light"),
            ErrMsg::Channel(ch, v) => format!(
                "color channels must lie in [0, 1]; {} is {}",
                self.channel(*ch),
                n(*v)
            ),
            ErrMsg::Attenuation(a0, a1, a2) => format!("a0, a1, a2 must be ≥ 0 and not all 0, got {}", nums().shortest3([*a0, *a1, *a2])),
            ErrMsg::Cones(t, p) => format!("the cone angles need 0 ≤ theta ≤ phi ≤ 180°, got theta = {}, phi = {}", n(*t), n(*p)),
            ErrMsg::PlaneThroughOrigin => "the view plane z = 0 passes through the centre of projection at the origin".into(),
            ErrMsg::PlaneThroughCop(z) => format!("the view plane z = {} passes through the centre of projection", n(*z)),
            ErrMsg::ImageTooLarge(p, prec) => format!("the image of {p} is too large for {prec} precision (the point is too near the plane of the centre of projection)"),
            ErrMsg::Viewport(w, h) => format!("width and height must be positive, got {}x{}", n(*w), n(*h)),
            ErrMsg::VVanished => "v = n × u vanished".into(),
            ErrMsg::EyeLookTooLarge(d, prec) => format!("Pe − Pr = {} is too large for {prec} precision", nums().shortest3(*d)),
            ErrMsg::TranslationTooLarge(prec) => format!("the view matrix's translation −(u·Pe, v·Pe, n·Pe) is too large for {prec} precision"),
            ErrMsg::EyeCoordsTooLarge(p, prec) => format!("the eye coordinates of {p} are too large for {prec} precision"),
            ErrMsg::ExactBeyondF64 => "the result is exact but beyond the range of f64 (about 1.8e308), so it has no decimal or JSON number to give (scale the inputs)".into(),
            ErrMsg::ResultNotFinite(prec) => format!("the result is not a finite number at {prec} precision: an input overflows or underflows the floats (scale the inputs, or use --precision exact)"),
            ErrMsg::UnknownPart(a, all) => format!("unknown part `{a}`; the parts are {all}"),
            ErrMsg::ExpectedXyz(e) => format!("expected [x, y, z]: {}", self.toml(e)),
            ErrMsg::NothingToSolve => "nothing to solve: the file has no part that its data allow (camera + points, perspective, clip, shade)".into(),
            ErrMsg::NoCameraTable => "the problem asks for the view but has no [camera] table".into(),
            ErrMsg::ProjectionNeedsNear => "projection needs perspective.near (or perspective.d)".into(),
            ErrMsg::WindowNeeds => "the window needs perspective.fovy, perspective.aspect and perspective.near".into(),
            ErrMsg::LightsNeedShade => "[[light]] tables need a [shade] table (normal, color, ...)".into(),
            ErrMsg::NoTopic => "give at least one topic".into(),
            ErrMsg::NoProblemDrawn => "no problem drawn".into(),
            ErrMsg::StdinHoldsAnswers => "standard input holds the answers: give the problem as a file".into(),
            ErrMsg::GiveProblem => "give a problem file or --topic".into(),
            ErrMsg::TooManyProblems(n, c, v, mb, max) => format!("{n} problems ({c} × {v}, about {mb} MB) is more than the {max} written without --force"),
            ErrMsg::SplitNotQuiz => "splits a quiz file: it is taken with --format moodle or --format gift only".into(),
            ErrMsg::QuestionTooLarge(q, size, limit) => format!("the question \"{q}\" alone takes {} MB, more than the {} MB a file may have: give a larger --split-mb", nums().fixed_of(*size), nums().fixed_of(*limit)),
            ErrMsg::BothStdin => "the problem and the answers cannot both come from standard input (-)".into(),
            ErrMsg::NoPrinted(p) => format!("{p} has no [printed] table"),
            ErrMsg::CsvAndJson => "--csv - and --json would both write to standard output: give --csv a file name".into(),
            ErrMsg::NoAnswerFiles(d) => format!("{d} holds no .toml answer files"),
            ErrMsg::NoExam(d) => format!("{d} holds no problem-01.toml (nor variant-01/): give a problem file or a folder written by grafika generate"),
            ErrMsg::NoVariant(n) => format!("the exam has {n} variants: say which one these answers are for with `variant = N` at the top of the file"),
            ErrMsg::NotAVariant(v, n) => format!("`{v}` is not a variant of the exam (1 to {n})"),
            ErrMsg::MarksNotAKey(k) => format!("`{k}` is not an answer of this problem, so it cannot be worth marks"),
            ErrMsg::MarksUnknownField(f) => format!("unknown field `{f}`: an entry of [marks] is a number of marks, or a table with `marks` and `method`"),
            ErrMsg::MarksMissing => "the table gives no `marks`: write `{ marks = 3, method = { … } }`".to_string(),
            ErrMsg::MarksNotWhole(v, most) => format!("`{v}` is not a number of marks: a whole number from 0 to {most}"),
            ErrMsg::MarksMethodTable => "`method` is a table of working keys, each with its marks: `method = { \"shade.diffuse\" = 1 }`".to_string(),
            ErrMsg::MarksMethodOver(sum, marks) => format!("the method marks add up to {sum}, more than the {marks} the value itself is worth"),
            ErrMsg::MarksMethodAsked(k) => format!("`{k}` is asked for its own marks, so it cannot also earn method marks for another value"),
            ErrMsg::NotAProblemOfExam(k, names) => format!("`{k}` is not in a table of a problem of the exam ([{names}])"),
            ErrMsg::ReportFormat(p) => format!("{p}: the report's format comes from its extension: .html, .md, .json or .csv"),
            ErrMsg::NotResponses(c) => format!("not Moodle's quiz Responses report ({c}): download it from Quiz → Results → Responses, \"Download table data as\" CSV, JSON, Excel or OpenDocument"),
            ErrMsg::NoQuestionText => "the Responses report does not show which question each student drew: tick \"Question text\" in the report's options and download it again".into(),
            ErrMsg::AnswersFolder(d, why) => format!(
                "the folder of answer files {d} cannot be read: {} (a class report needs --answers DIR)",
                self.io_why(why)
            ),
            ErrMsg::RosterNeedsClass => "a class list is set against a class: --roster needs --answers DIR (a folder of answer files)".into(),
            ErrMsg::EmptyRoster(f) => format!("the class list {f} holds no name"),
            ErrMsg::RosterRow(line, why) => format!("line {line} of the class list cannot be read as CSV: {why}"),
            ErrMsg::ReportNeedsClass => "a class report needs --answers DIR (a folder of answer files)".into(),
            ErrMsg::PixelOutside(x, y, w, h) => format!("({x}, {y}) is outside the {w}x{h} image"),
            ErrMsg::PixelText(s) => format!("expected X,Y (whole pixel numbers), got `{s}`"),
            ErrMsg::NothingRendered => "nothing rendered".into(),
            ErrMsg::Threads(why) => format!("cannot start the threads: {why}"),
            ErrMsg::RenderPrecision => "render always computes at f32 (--precision is for the calculator's worked steps): leave it out".into(),
            ErrMsg::NotTaken(c) => format!("grafika {c} does not take this option (grafika {c} --help lists those it takes)"),
            ErrMsg::OwnOutput => "check, generate, bench, practice, completions and man print their own output: use main_with_args".into(),
        }
    }

    fn number(&self, e: &NumErr) -> String {
        match e {
            NumErr::Quoted(t, why) => format!("`{t}`: {}", self.number(why)),
            NumErr::TooLong(len, max) => format!("the number is {len} characters long, more than the {max} allowed"),
            NumErr::Empty => "expected a number, found nothing".into(),
            NumErr::Expected(w, col, Some(c)) => {
                format!("expected {} at column {col}, found `{c}`", self.want(*w))
            }
            NumErr::Expected(w, col, None) => {
                format!("expected {} at column {col}, found the end", self.want(*w))
            }
            NumErr::TooDeep(max, col) => format!("the number is nested more than {max} levels deep (parentheses, roots or signs) at column {col}"),
            NumErr::TooManyOps(max, col) => format!("the number has more than {max} operations (at column {col})"),
            NumErr::Count(k, t) => format!("expected three numbers x,y,z separated by commas, found {k} in `{t}`"),
            NumErr::Component(k, t, why) => {
                format!("{} component `{t}`: {}", errors::component(*k), self.number(why))
            }
            NumErr::NotFinite(x, p) => format!("`{x}` is not a finite number at {p} precision"),
            NumErr::NotANumber(x) => format!("`{x}` is not a number"),
            NumErr::NotFiniteLiteral(x) => format!("{x} is not a finite number"),
            NumErr::NegativeRoot(x) => format!("sqrt({x}) takes the square root of a negative number"),
            NumErr::DivZero(x) => format!("`{x}` divides by zero"),
            NumErr::Exponent(x) => format!("the exponent in `{x}` must be a whole number from -1024 to 1024"),
            NumErr::PowerRange(x) => format!("`{x}` is too large or too small a power"),
            NumErr::Unexpected(c, at) => format!("unexpected `{c}` at character {at}"),
            NumErr::OpenAfter(name) => format!("expected `(` after {name}"),
            NumErr::UnknownName(name) => format!("unknown name `{name}` (the formula may use x, z, pi, exp, sqrt, sin, cos, abs)"),
            NumErr::EndsEarly => "the formula ends too early".into(),
            NumErr::FormulaDeep(max, at) => format!("the formula is nested more than {max} levels deep (parentheses, signs or powers) at character {at}"),
            NumErr::FormulaOps(max, at) => format!("the formula has more than {max} operations (at character {at})"),
        }
    }

    fn want(&self, w: Want) -> &'static str {
        match w {
            Want::OperatorOrEnd => "an operator or the end of the number",
            Want::Close => "`)`",
            Want::OpenAfterSqrt => "`(` after sqrt",
            Want::Number => "a number",
        }
    }

    fn toml(&self, e: &TomlErr) -> String {
        let serde = |s: &str| errors::serde_words(s, |w| self.serde_word(w));
        match e {
            TomlErr::UnknownField(k, Some(all)) => {
                format!("unknown field `{k}`, expected one of {all}")
            }
            TomlErr::UnknownField(k, None) => format!("unknown field `{k}`"),
            TomlErr::MissingField(k) => format!("missing field `{k}`"),
            TomlErr::Duplicate(k) => format!("duplicate key `{k}`"),
            TomlErr::UnknownVariant(v, all) => {
                format!("unknown variant `{v}`, expected one of {all}")
            }
            TomlErr::InvalidType(found, want) => {
                format!("invalid type: {}, expected {}", serde(found), serde(want))
            }
            TomlErr::InvalidLength(found, want) => {
                format!("invalid length {}, expected {}", serde(found), serde(want))
            }
            TomlErr::InvalidValue(found, want) => {
                format!("invalid value: {}, expected {}", serde(found), serde(want))
            }
            TomlErr::Num(n) => self.number(n),
            TomlErr::MustBe(b, got) => self.must_be(b, *got),
            TomlErr::WholeRange(lo, hi, got) => {
                format!("must be a whole number from {lo} to {hi}, got {got}")
            }
            TomlErr::Colour(c) => format!(
                "colour components must be from 0 to 1, got {}",
                errors::bracketed(*c, nums())
            ),
            TomlErr::Syntax(s) => self.syntax(&errors::syntax(s)),
        }
    }

    fn must_be(&self, b: &Bound, got: f64) -> String {
        let bound = match b {
            Bound::NumberAtLeastZero => "must be a number ≥ 0".to_string(),
            Bound::AtLeastZero => "must be ≥ 0".into(),
            Bound::AboveZero => "must be > 0".into(),
            Bound::Positive => "must be positive".into(),
            Bound::NotNegative => "must not be negative".into(),
            Bound::FiniteAtLeastZero => "must be a finite number ≥ 0".into(),
            Bound::Fraction => "must be a number above 0 and below 1 (0.001 is 0.1%)".into(),
            Bound::WholePixels => "must be a whole number of pixels".into(),
            Bound::AboveNear(near) => format!("must be greater than near = {}", n(*near)),
        };
        format!("{bound}, got {}", n(got))
    }

    fn twice(&self, t: Twice) -> &'static str {
        match t {
            Twice::GlobalAmbient => {
                "give the global ambient once, not both in the lights file and here"
            }
            Twice::Material => "give the material once, not both in the lights file and here",
            Twice::Color => "give the surface color once: color or material.diffuse",
            Twice::Shininess => "give the exponent once: shininess or material.power",
            Twice::View => "give V or the camera position (local viewer), not both",
            Twice::Light => "give one light vector L or [[light]] tables, not both",
            Twice::Axis => "give the spot light's axis once: axis (or its old name, direction)",
            Twice::TiltCamera => "give either [tilt] or [camera], not both",
            Twice::Colors => "give only one of color, face_colors, vertex_colors",
            Twice::Answers => "give either --answers FILE|DIR or --answers-from-text",
        }
    }

    fn io_why(&self, w: &IoWhy) -> String {
        match w {
            IoWhy::NotFound => "no such file or directory".into(),
            IoWhy::Denied => "permission denied".into(),
            IoWhy::Exists => "it already exists".into(),
            IoWhy::IsDirectory => "it is a directory".into(),
            IoWhy::NotText => "it is not UTF-8 text".into(),
            IoWhy::NotADirectory => "a folder on its path is a file".into(),
            IoWhy::ReadOnly => "the file system is read-only".into(),
            IoWhy::Full => "no space left on the device".into(),
            IoWhy::TooLarge => "the file is too large for the file system".into(),
            IoWhy::BadName => "the file system does not accept that name".into(),
            IoWhy::Other(s) => s.clone(),
        }
    }

    fn needs(&self, thing: &Thing, key: &str) -> String {
        match thing {
            Thing::Light(kind) => format!("a {kind} light needs `{key}`"),
            Thing::Object(t) if t == "obj" => format!("an obj object needs `{key}`"),
            Thing::Object(t) => format!("a {t} needs `{key}`"),
        }
    }

    fn channel(&self, c: Channel) -> &'static str {
        match c {
            Channel::Red => "red",
            Channel::Green => "green",
            Channel::Blue => "blue",
        }
    }

    /// The OBJ reader's own words.
    fn obj_why(&self, w: ObjWhy) -> &'static str {
        match w {
            ObjWhy::OpenFileFailed => "open file failed",
            ObjWhy::ReadError => "read error",
            ObjWhy::UnrecognizedCharacter => "unrecognized character",
            ObjWhy::PositionParse => "position parse error",
            ObjWhy::ScalingByZero => "scaling (w) by zero",
            ObjWhy::ColorParse => "color parse error (too many or too few components)",
            ObjWhy::NormalParse => "normal parse error",
            ObjWhy::TexcoordParse => "texcoord parse error",
            ObjWhy::FaceParse => "face parse error",
            ObjWhy::MaterialParse => "material parse error",
            ObjWhy::InvalidObjectName => "invalid object name",
            ObjWhy::InvalidPolygon => "invalid polygon",
            ObjWhy::FaceVertexOutOfBounds => "face vertex index out of bounds",
            ObjWhy::FaceTexCoordOutOfBounds => "face texcoord index out of bounds",
            ObjWhy::FaceNormalOutOfBounds => "face normal index out of bounds",
            ObjWhy::FaceColorOutOfBounds => "face vertex color index out of bounds",
            ObjWhy::LoadOptions => "mutually exclusive load options",
            ObjWhy::Generic => "generic failure",
        }
    }

    /// clap's own line, whatever it refused.
    fn clap(&self, e: &ClapErr, line: &str) -> String {
        match e {
            ClapErr::InvalidValue(..)
            | ClapErr::BadValue(..)
            | ClapErr::Unknown(..)
            | ClapErr::UnknownCommand(..)
            | ClapErr::Conflict(..)
            | ClapErr::Missing(_)
            | ClapErr::NoValue
            | ClapErr::ValueCount(_)
            | ClapErr::Other => line.to_string(),
        }
    }

    fn value_why(&self, w: &ValueWhy) -> String {
        match w {
            ValueWhy::Parse(p) => self.parse_why(*p).to_string(),
            ValueWhy::NotInRange(v, range) => format!("{v} is not in {range}"),
            ValueWhy::AsWritten(s) => s.clone(),
        }
    }

    fn parse_why(&self, w: ParseWhy) -> &'static str {
        errors::parse_text(w)
    }

    fn syntax(&self, s: &Syntax) -> String {
        let what = s.what.words(|w| self.syntax_what(w));
        match &s.expected {
            None => what.to_string(),
            Some(Expected::Nothing) => format!("{what}, expected nothing"),
            Some(Expected::OneOf(items)) => format!(
                "{what}, expected {}",
                errors::one_of(items, |w| self.expect_word(w))
            ),
        }
    }

    fn syntax_what(&self, w: SyntaxWhat) -> &'static str {
        errors::syntax_text(w)
    }

    fn expect_word(&self, w: ExpectWord) -> &'static str {
        errors::expect_text(w)
    }

    fn serde_word(&self, w: SerdeWord) -> &'static str {
        use SerdeWord as S;
        match w {
            S::U8 => "a whole number from 0 to 255",
            S::U16 => "a whole number from 0 to 65535",
            S::U32 => "a whole number from 0 to 4294967295",
            S::U64 | S::Usize => "a whole number ≥ 0",
            S::I32 | S::I64 => "a whole number",
            S::F32 | S::F64 => "a number",
            S::NumberOrExpression
            | S::Vector
            | S::ArrayOfLength
            | S::ASequence
            | S::Sequence
            | S::AString
            | S::String
            | S::Integer
            | S::FloatingPoint
            | S::Boolean
            | S::AMap
            | S::Map
            | S::ElementsInSequence
            | S::ANumber
            | S::AnInteger
            | S::ABoolean
            | S::UnitVariant
            | S::Elements => errors::serde_text(w),
        }
    }
}

/// What a path that is not a regular file names, with its article.
fn file_kind(k: FileKind) -> &'static str {
    match k {
        FileKind::Fifo => "a FIFO (named pipe)",
        FileKind::Socket => "a socket",
        FileKind::CharDevice => "a character device",
        FileKind::BlockDevice => "a block device (a disk)",
        FileKind::Folder => "a folder",
        FileKind::Other => "not a file grafika reads or writes",
    }
}

/// Why a `.grafika-generated` is not generate's own list.
fn list_why(w: &ListWhy) -> String {
    match w {
        ListWhy::NotAFile => "it is not a regular file".into(),
        ListWhy::Heading => "its first line is not the one generate writes".into(),
        ListWhy::Line(n) => format!("line {n} is not a SHA-256 and a file name"),
        ListWhy::Name(n, name) => format!("line {n} names {name}, which generate never writes"),
        ListWhy::Owner => "it belongs to another user".into(),
        ListWhy::TooLarge => "it is larger than any list generate writes".into(),
    }
}
