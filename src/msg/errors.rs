//! Why an input was refused, as data: every error a person can meet is one
//! of these keys with its parameters (numbers as numbers, written by the
//! words in the language's number style; an expression or a text as it
//! was typed), and each language's module of `report::words` says it
//! (`ErrorWords`, one exhaustive match per key enum). The field at fault is
//! not here: `Error` holds it, as the flag or key is spelled.

use super::Fixed;

/// Why a number expression (a flag, a file value, an answer) or a plane's
/// height formula could not be read or evaluated.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum NumErr {
    /// The text as typed, then why (`` `1+*2`: … ``).
    Quoted(String, Box<NumErr>),
    /// Longer than allowed: characters, the most allowed.
    TooLong(usize, usize),
    /// Nothing where a number should be.
    #[cfg_attr(test, default)]
    Empty,
    /// Expected this at a 1-based column; the character found (none: the end).
    Expected(Want, usize, Option<char>),
    /// Nested deeper than allowed: the most levels, the column.
    TooDeep(usize, usize),
    /// More operations than allowed: the most, the column.
    TooManyOps(usize, usize),
    /// Not three components: how many, the text.
    Count(usize, String),
    /// Component 0, 1 or 2 (x, y, z), its text, why.
    Component(usize, String, Box<NumErr>),
    /// Not finite at a precision: the expression, the precision (`f32`).
    NotFinite(String, String),
    /// A literal that is not a number.
    NotANumber(String),
    /// A TOML float that is not finite (`nan`, `inf`).
    NotFiniteLiteral(String),
    /// sqrt of a negative number: the argument.
    NegativeRoot(String),
    /// Division by zero: the expression.
    DivZero(String),
    /// An exponent that is not whole or beyond ±1024: the expression.
    Exponent(String),
    /// A power beyond 2^±8192: the expression.
    PowerRange(String),
    /// Height formula: an unexpected character at a 1-based position.
    Unexpected(char, usize),
    /// Height formula: `(` missing after a function name.
    OpenAfter(String),
    /// Height formula: an unknown name.
    UnknownName(String),
    /// Height formula: it ends too early.
    EndsEarly,
    /// Height formula: nested deeper than allowed (most, position).
    FormulaDeep(usize, usize),
    /// Height formula: more operations than allowed (most, position).
    FormulaOps(usize, usize),
}

/// What the number reader expected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Want {
    /// An operator or the end of the number.
    #[cfg_attr(test, default)]
    OperatorOrEnd,
    /// `)`.
    Close,
    /// `(` after sqrt.
    OpenAfterSqrt,
    /// A number.
    Number,
}

/// What a path names, when it is not a regular file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum FileKind {
    /// A FIFO (named pipe).
    #[cfg_attr(test, default)]
    Fifo,
    /// A socket.
    Socket,
    /// A character device (`/dev/null`, a terminal).
    CharDevice,
    /// A block device (a disk).
    BlockDevice,
    /// A folder.
    Folder,
    /// Anything else.
    Other,
}

impl FileKind {
    /// What `meta` (of the file itself, links followed) names.
    pub fn of(meta: &std::fs::Metadata) -> FileKind {
        let t = meta.file_type();
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if t.is_fifo() {
                return FileKind::Fifo;
            }
            if t.is_socket() {
                return FileKind::Socket;
            }
            if t.is_char_device() {
                return FileKind::CharDevice;
            }
            if t.is_block_device() {
                return FileKind::BlockDevice;
            }
        }
        if t.is_dir() {
            FileKind::Folder
        } else {
            FileKind::Other
        }
    }
}

/// Why a folder's `.grafika-generated` is not a list `generate` wrote.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum ListWhy {
    /// It is not a regular file (a link, a folder).
    #[cfg_attr(test, default)]
    NotAFile,
    /// Its first line is not the one generate writes.
    Heading,
    /// A line that is not `SHA-256  NAME`: the line number.
    Line(usize),
    /// A name generate never writes: the line number, the name.
    Name(usize, String),
    /// It belongs to another user.
    Owner,
    /// It is larger than any list generate writes.
    TooLarge,
}

/// Why a file could not be read or written (the system's reason, by kind).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum IoWhy {
    /// No such file or directory.
    #[cfg_attr(test, default)]
    NotFound,
    /// Permission denied.
    Denied,
    /// The file already exists.
    Exists,
    /// A directory where a file was expected.
    IsDirectory,
    /// Not UTF-8 text.
    NotText,
    /// A folder on the path is a file.
    NotADirectory,
    /// The file system is mounted read-only.
    ReadOnly,
    /// No space is left on the device.
    Full,
    /// The file is larger than the file system allows.
    TooLarge,
    /// The name is not one the file system accepts.
    BadName,
    /// Another reason, as the system says it (in the system's language).
    Other(String),
}

impl IoWhy {
    /// The reason of an I/O error.
    pub fn of(e: &std::io::Error) -> IoWhy {
        use std::io::ErrorKind as K;
        match e.kind() {
            K::NotFound => IoWhy::NotFound,
            K::PermissionDenied => IoWhy::Denied,
            K::AlreadyExists => IoWhy::Exists,
            K::IsADirectory => IoWhy::IsDirectory,
            K::InvalidData => IoWhy::NotText,
            K::NotADirectory => IoWhy::NotADirectory,
            K::ReadOnlyFilesystem => IoWhy::ReadOnly,
            K::StorageFull | K::QuotaExceeded => IoWhy::Full,
            K::FileTooLarge => IoWhy::TooLarge,
            K::InvalidFilename => IoWhy::BadName,
            _ => IoWhy::Other(e.to_string()),
        }
    }
}

/// A bound a value must keep, for "must be …, got X".
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Bound {
    /// A number ≥ 0 (material constants).
    #[cfg_attr(test, default)]
    NumberAtLeastZero,
    /// ≥ 0.
    AtLeastZero,
    /// > 0.
    AboveZero,
    /// Positive.
    Positive,
    /// Not negative.
    NotNegative,
    /// A finite number ≥ 0.
    FiniteAtLeastZero,
    /// Above 0 and below 1 (a relative tolerance).
    Fraction,
    /// A whole number of pixels.
    WholePixels,
    /// Greater than near (its value).
    AboveNear(f64),
}

/// Something given twice where once is wanted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Twice {
    /// The global ambient, in the lights file and in `[shade]`.
    #[cfg_attr(test, default)]
    GlobalAmbient,
    /// The material, in the lights file and in `[shade]`.
    Material,
    /// color and material.diffuse.
    Color,
    /// shininess and material.power.
    Shininess,
    /// V and the camera position.
    View,
    /// L and `[[light]]` tables.
    Light,
    /// A spot light's axis and its old name, direction.
    Axis,
    /// `[tilt]` and `[camera]`.
    TiltCamera,
    /// color, face_colors, vertex_colors.
    Colors,
    /// --answers and --answers-from-text (or neither).
    Answers,
}

/// A colour channel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum Channel {
    /// Red.
    #[cfg_attr(test, default)]
    Red,
    /// Green.
    Green,
    /// Blue.
    Blue,
}

impl Channel {
    /// The channels in the order of a colour's components (R, G, B).
    pub const RGB: [Channel; 3] = [Channel::Red, Channel::Green, Channel::Blue];
}

/// Why the OBJ reader (the `tobj` crate) refused a file: one case per
/// reason it gives (`input::mesh` maps its error to these).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum ObjWhy {
    /// A file (a material library) could not be opened.
    #[cfg_attr(test, default)]
    OpenFileFailed,
    /// The file could not be read.
    ReadError,
    /// A character it does not know.
    UnrecognizedCharacter,
    /// A vertex position that cannot be read.
    PositionParse,
    /// A vertex scaled by w = 0.
    ScalingByZero,
    /// A vertex colour with too many or too few components.
    ColorParse,
    /// A vertex normal that cannot be read.
    NormalParse,
    /// A texture coordinate that cannot be read.
    TexcoordParse,
    /// A face that cannot be read.
    FaceParse,
    /// A material that cannot be read.
    MaterialParse,
    /// An object name that is not valid.
    InvalidObjectName,
    /// A polygon that is not valid.
    InvalidPolygon,
    /// A face refers to a vertex that does not exist.
    FaceVertexOutOfBounds,
    /// A face refers to a texture coordinate that does not exist.
    FaceTexCoordOutOfBounds,
    /// A face refers to a normal that does not exist.
    FaceNormalOutOfBounds,
    /// A face refers to a vertex colour that does not exist.
    FaceColorOutOfBounds,
    /// Load options that exclude each other.
    LoadOptions,
    /// A failure it does not name.
    Generic,
}

/// What needs a key: a light of a kind, or an object of a type (as spelled
/// in the file: `spot`, `sphere`, `obj`).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Thing {
    /// A light of this kind.
    Light(String),
    /// An object of this type.
    Object(String),
}

/// What clap refused on the command line.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum ClapErr {
    /// A value not among the possible ones: the value, the possible ones.
    InvalidValue(String, String),
    /// A value that could not be read: the value, clap's reason.
    BadValue(String, String),
    /// An argument that does not exist; a suggestion, if any.
    Unknown(String, Option<String>),
    /// A required argument missing: which.
    Missing(String),
    /// A subcommand that does not exist; a suggestion, if any.
    UnknownCommand(String, Option<String>),
    /// Two arguments that cannot be used together.
    Conflict(String, String),
    /// An argument without its value.
    #[cfg_attr(test, default)]
    NoValue,
    /// An argument with more or fewer values than it takes.
    ValueCount(String),
    /// Anything else (clap's line says it).
    Other,
}

/// Why an input was refused.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum ErrMsg {
    /// A number that cannot be read or evaluated.
    Num(NumErr),
    /// "must be …, got X".
    MustBe(Bound, f64),
    /// Given twice.
    Twice(Twice),
    /// A colour channel outside [0, 1]: channel, value.
    Channel(Channel, f64),
    /// Attenuation a0, a1, a2 negative or all 0.
    Attenuation(f64, f64, f64),
    /// Spot cones not 0 ≤ theta ≤ phi ≤ 180°: theta, phi.
    Cones(f64, f64),
    /// The view plane z = 0 through the centre of projection at the origin.
    #[cfg_attr(test, default)]
    PlaneThroughOrigin,
    /// The view plane z = zvp through the centre of projection.
    PlaneThroughCop(f64),
    /// A point's image too large for a precision: point, precision.
    ImageTooLarge(String, String),
    /// The viewport not positive: width, height.
    Viewport(f64, f64),
    /// v = n × u vanished.
    VVanished,
    /// Pe − Pr too large for a precision: Pe − Pr, precision.
    EyeLookTooLarge([f64; 3], String),
    /// The view matrix's translation too large for a precision.
    TranslationTooLarge(String),
    /// A point's eye coordinates too large: point, precision.
    EyeCoordsTooLarge(String, String),
    /// A result not finite at a float precision (`f64`, `f32`).
    ResultNotFinite(String),
    /// An exact result beyond the range of f64 (no decimal to give).
    ExactBeyondF64,
    /// A file that cannot be read: path, why.
    CannotRead(String, IoWhy),
    /// Standard input cannot be read: why.
    CannotReadStdin(IoWhy),
    /// A file that cannot be written: path, why.
    CannotWrite(String, IoWhy),
    /// A directory that cannot be created: path, why.
    CannotCreate(String, IoWhy),
    /// Standard output cannot be written: why.
    CannotWriteStdout(IoWhy),
    /// Standard output is closed (`>&-`).
    StdoutClosed,
    /// Standard input is closed (`<&-`) where `-` asks to read it.
    StdinClosed,
    /// An input that is not a regular file (a FIFO, a device): path, what it is.
    InputNotRegular(String, FileKind),
    /// An output that exists and is neither a regular file nor a device
    /// grafika writes to directly: path, what it is.
    OutputNotRegular(String, FileKind),
    /// The same output file given to two flags: path, the other flag.
    SameOutput(String, String),
    /// A file that exists; --force overwrites: path.
    ExistsForce(String),
    /// An output that names a folder, not a file: path.
    NamesFolder(String),
    /// An output that is a symbolic link: path.
    IsLink(String),
    /// An output that is one of the command's inputs: path.
    IsInput(String),
    /// An entry of generate's output folder it did not write: path, marker.
    NotOwn(String, String),
    /// A file generate wrote whose content has changed since: path.
    ChangedSince(String),
    /// A `.grafika-generated` that is not a list generate wrote: path, why.
    NotOwnList(String, ListWhy),
    /// A `.grafika-generated` already in the folder, without `--force`: path.
    ListExists(String),
    /// Another `generate` is writing into the folder: the folder, the lock file.
    Locked(String, String),
    /// Not a directory: path.
    NotDirectory(String),
    /// A file read as TOML larger than the most read: path, its size (when
    /// known: standard input's is not), the most.
    FileTooLarge(String, Option<u64>, usize),
    /// A TOML file whose arrays hold more values than read: the most.
    TomlTooManyValues(usize),
    /// A TOML file nesting arrays or inline tables deeper than read: the most.
    TomlTooDeep(usize),
    /// Files of a class that could not be marked: how many, of how many, which.
    NotMarked(usize, usize, String),
    /// A lights file without `[[light]]`: path.
    NoLightTable(String),
    /// Cs missing.
    ColorMissing,
    /// N missing.
    NormalMissing,
    /// The camera at the surface point.
    CameraAtPoint,
    /// No light at all.
    NoLight,
    /// A light at the surface point.
    LightAtPoint,
    /// A light or object needs a key.
    Needs(Thing, String),
    /// A key that does not apply to a light of a kind: key, kind.
    NotApplicable(String, String),
    /// An object type without such a key: type, key, its keys.
    NoSuchKey(String, String, String),
    /// Needed to render.
    NeededToRender,
    /// An OBJ file that cannot be read: path, why.
    ObjUnreadable(String, IoWhy),
    /// An OBJ file that is not valid: path, the OBJ reader's reason.
    ObjInvalid(String, ObjWhy),
    /// An OBJ file without faces.
    ObjNoFaces(String),
    /// An OBJ file with a vertex not finite.
    ObjNotFinite(String),
    /// A face refers to a missing vertex.
    FaceVertex,
    /// A height formula that gives a value not finite.
    FormulaNotFinite,
    /// More triangles in a scene than the renderer takes: how many, the most.
    TooManyTriangles(usize, usize),
    /// More lights in a scene than the renderer takes: how many, the most.
    TooManyLights(usize, usize),
    /// A render whose estimated work passes the limit: the estimate, the
    /// frames, the limit (millions of steps).
    RenderWork(u64, u32, u64),
    /// Height formulas whose evaluation passes the work limit: evaluations,
    /// the formula's size, the limit that would allow it, the limit
    /// (millions of steps).
    FormulaWork(u64, usize, u64, u64),
    /// A colour list that is empty.
    NeedsColour,
    /// A scene without objects.
    NoObjects,
    /// A `[camera]` without `[perspective]`.
    CameraNeedsPerspective,
    /// An image size out of 1..=8192: width, height.
    ImageSize(String, String),
    /// An unknown part of `ask`: the part, the parts.
    UnknownPart(String, String),
    /// A point that is not [x, y, z]: the reader's reason.
    ExpectedXyz(TomlErr),
    /// A TOML error.
    Toml(TomlErr),
    /// Nothing to solve.
    NothingToSolve,
    /// The view asked without `[camera]`.
    NoCameraTable,
    /// Projection without near.
    ProjectionNeedsNear,
    /// The window without fovy, aspect, near.
    WindowNeeds,
    /// `[[light]]` without `[shade]`.
    LightsNeedShade,
    /// No topic.
    NoTopic,
    /// No problem drawn (practice).
    NoProblemDrawn,
    /// Standard input holds the answers (practice).
    StdinHoldsAnswers,
    /// Neither a problem file nor --topic.
    GiveProblem,
    /// More problems than written without --force: problems, count,
    /// variants, megabytes, the most.
    TooManyProblems(u64, u64, u64, u64, u64),
    /// `--split-mb` with a format that writes no quiz file.
    SplitNotQuiz,
    /// One question of a quiz larger than `--split-mb` allows: the
    /// question's name, its size and the limit (MB, 3 decimals).
    QuestionTooLarge(String, Fixed, Fixed),
    /// Problem and answers both from standard input.
    BothStdin,
    /// No `[printed]` table: the file.
    NoPrinted(String),
    /// --csv - with --json.
    CsvAndJson,
    /// A directory without answer files.
    NoAnswerFiles(String),
    /// An exam folder (or one of its variant folders) without problem-01.toml: the folder.
    NoExam(String),
    /// An exam's answer file without `variant = N`: the exam's variants.
    NoVariant(usize),
    /// A variant that is not one of the exam's: as given, the exam's variants.
    NotAVariant(String, usize),
    /// A `[marks]` key that is no answer of the problem: the key as written.
    MarksNotAKey(String),
    /// A `[marks]` entry's table with another field than `marks` and `method`.
    MarksUnknownField(String),
    /// A `[marks]` entry's table without `marks`.
    MarksMissing,
    /// Marks that are not a whole number from 0 to the most: as written, the most.
    MarksNotWhole(String, u32),
    /// A `[marks]` entry's `method` that is not a table.
    MarksMethodTable,
    /// Method marks adding up to more than the value's: their sum, its marks.
    MarksMethodOver(u32, u32),
    /// A method key that the scheme asks itself: the key.
    MarksMethodAsked(String),
    /// An answer in an exam's file outside its problems' tables: the key, the problems.
    NotAProblemOfExam(String, String),
    /// `--report` with an unknown extension: the path.
    ReportFormat(String),
    /// A `--moodle-responses` file that is not Moodle's Responses report:
    /// the column missing, or why it cannot be read.
    NotResponses(String),
    /// A Responses report without the question of each slot, for a quiz
    /// whose problems have several variants.
    NoQuestionText,
    /// `--report` without a folder of answers.
    ReportNeedsClass,
    /// `--roster` without a folder of answers.
    RosterNeedsClass,
    /// A class list with no name: the file.
    EmptyRoster(String),
    /// A class list's CSV row that cannot be read: the line, why.
    RosterRow(usize, String),
    /// `--report` or `--roster` with an answers folder that cannot be read:
    /// the path, why.
    AnswersFolder(String, crate::msg::IoWhy),
    /// A pixel outside the image: x, y, width, height.
    PixelOutside(u32, u32, u32, u32),
    /// Not X,Y.
    PixelText(String),
    /// Nothing rendered.
    NothingRendered,
    /// The thread pool could not start: why.
    Threads(String),
    /// Render refuses --precision.
    RenderPrecision,
    /// An option given before a command (named) that does not take it.
    NotTaken(String),
    /// A command that prints its own output run through `run`.
    OwnOutput,
    /// The manual page could not be written: why.
    Man(String),
    /// The command line, as clap refused it: what, and clap's own line
    /// (the English words).
    Clap(ClapErr, String),
}

/// A TOML file's error, by kind (the field and place are beside it).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum TomlErr {
    /// A key the table does not take: the key, the keys it takes.
    UnknownField(String, Option<String>),
    /// A key that is missing.
    MissingField(String),
    /// A key given twice.
    Duplicate(String),
    /// A value not among the allowed ones: the value, the allowed ones.
    UnknownVariant(String, String),
    /// A value of the wrong type: what was found, what was expected.
    InvalidType(String, String),
    /// An array of the wrong length: the length, the one expected.
    InvalidLength(String, String),
    /// A value of the right type out of what the field takes (a negative
    /// width): what was found, what was expected.
    InvalidValue(String, String),
    /// A number that cannot be read.
    Num(NumErr),
    /// A value out of its bound: the bound, the value given.
    MustBe(Bound, f64),
    /// A whole number out of a range: lowest, highest, the value given.
    WholeRange(i64, i64, i64),
    /// A colour component out of [0, 1]: the colour given.
    Colour([f64; 3]),
    /// A syntax error, as the TOML reader says it.
    Syntax(String),
}

impl From<NumErr> for ErrMsg {
    fn from(e: NumErr) -> ErrMsg {
        ErrMsg::Num(e)
    }
}

impl From<TomlErr> for ErrMsg {
    fn from(e: TomlErr) -> ErrMsg {
        ErrMsg::Toml(e)
    }
}

impl From<Twice> for ErrMsg {
    fn from(e: Twice) -> ErrMsg {
        ErrMsg::Twice(e)
    }
}

impl NumErr {
    /// This reason after the text it is about (`` `1+*2`: … ``).
    pub fn quoted(self, text: &str) -> NumErr {
        NumErr::Quoted(text.to_string(), Box::new(self))
    }
}

/// For the tests' iteration over the error keys (`strum::EnumIter`
/// fills a variant's fields with their defaults).
#[cfg(test)]
impl Default for Thing {
    fn default() -> Thing {
        Thing::Light(String::new())
    }
}

/// For the tests' iteration over the error keys.
#[cfg(test)]
impl Default for TomlErr {
    fn default() -> TomlErr {
        TomlErr::MissingField(String::new())
    }
}
