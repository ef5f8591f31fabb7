//! What a generated problem says: its title and statement as data, its
//! numbers kept as numbers (integers, decimals, fractions);
//! `report::words` writes them in each language, with its decimal mark
//! and separator.

/// The title of a generated problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum DrawnTitle {
    /// The camera basis u, v, n.
    #[cfg_attr(test, default)]
    Basis,
    /// Eye coordinates of points.
    EyeCoordinates,
    /// Projection onto the near plane.
    Projection,
    /// The whole viewing pipeline.
    Pipeline,
    /// The viewing window.
    Window,
    /// Line clipping.
    Clipping,
    /// Lighting at a point.
    Lighting,
}

/// A number a generated problem states, kept as the number it is (never
/// as written text), so each language writes it with its own decimal mark.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Number {
    /// A decimal `units · 10^−places`: `0.25` is `Decimal(25, 2)`, the
    /// integer 3 is `Decimal(3, 0)`.
    Decimal(i64, u32),
    /// A fraction `p/q`, stated as such (`4/3`).
    Fraction(i64, i64),
}

impl Number {
    /// The integer `n`.
    pub const fn int(n: i64) -> Number {
        Number::Decimal(n, 0)
    }

    /// The decimal `units · 10^−places` (`dec(25, 2)` is 0.25).
    pub const fn dec(units: i64, places: u32) -> Number {
        Number::Decimal(units, places)
    }

    /// Written with the decimal mark `mark`: `0.25` (or `0,25`), `3`,
    /// `4/3`. The point writes it as a problem file (TOML) does.
    pub fn written(self, mark: char) -> String {
        match self {
            Number::Decimal(units, 0) => units.to_string(),
            Number::Decimal(units, places) => {
                let scale = 10i64.pow(places);
                let sign = if units < 0 { "-" } else { "" };
                let (whole, part) = (units.abs() / scale, units.abs() % scale);
                let width = places as usize;
                format!("{sign}{whole}{mark}{part:0width$}")
            }
            Number::Fraction(p, q) => format!("{p}/{q}"),
        }
    }
}

/// The number as a problem file (TOML) writes it: with the point.
impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.written('.'))
    }
}

/// A point's integer coordinates `(x, y, z)` as stated.
pub type Triple = [i64; 3];

/// A named point as stated: `A(1, 0, 2)`.
pub type NamedPoint = (String, Triple);

/// A camera as stated: Pe, Pr and Vup.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(Default))]
pub struct StatedCamera {
    /// Pe.
    pub eye: Triple,
    /// Pr.
    pub look: Triple,
    /// Vup.
    pub up: Triple,
}

/// What a lighting problem asks for, by model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter, Default))]
pub enum ShadeAsked {
    /// The ambient term.
    #[cfg_attr(test, default)]
    Ambient,
    /// cos α, the diffuse term.
    Diffuse,
    /// cos α, R and cos β, the specular term.
    Specular,
    /// cos α, the ambient and diffuse terms.
    Lambert,
    /// cos α, H and N·H, the three terms.
    Blinn,
    /// cos α, R and cos β, the three terms.
    Phong,
}

/// The statement of a generated problem.
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(test, derive(strum::EnumIter))]
pub enum Statement {
    /// Find n, u, v.
    Basis(StatedCamera),
    /// Find n, u, v and the eye coordinates of the points.
    View(StatedCamera, Vec<NamedPoint>),
    /// Project the points onto the near plane (near).
    Project(StatedCamera, Vec<NamedPoint>, Number),
    /// The four parts of the pipeline.
    Pipeline {
        /// The camera.
        camera: StatedCamera,
        /// The points.
        points: Vec<NamedPoint>,
        /// near.
        near: Number,
        /// fovy in degrees.
        fovy: i64,
        /// The aspect ratio.
        aspect: Number,
        /// The viewport, width and height in pixels.
        viewport: (i64, i64),
    },
    /// The window from fovy (degrees), aspect and near.
    Window(i64, Number, Number),
    /// Clip the segment P0 P1 against the box with corners min and max:
    /// (min, max, P0, P1).
    Clip(Triple, Triple, Triple, Triple),
    /// Lighting at a point.
    Shade {
        /// N.
        normal: Triple,
        /// Cs, `(r, g, b)`.
        color: [Number; 3],
        /// L.
        light: Triple,
        /// V.
        view: Triple,
        /// phong, blinn or lambert (as in the file).
        model: String,
        /// The constants stated, by their names (`ka`, `kd`, …).
        constants: Vec<(&'static str, Number)>,
        /// What is asked.
        asked: ShadeAsked,
    },
}

/// For the tests' iteration over the message keys (`strum::EnumIter`
/// fills a variant's fields with their defaults).
#[cfg(test)]
impl Default for Number {
    fn default() -> Number {
        Number::int(0)
    }
}

/// For the tests' iteration over the message keys.
#[cfg(test)]
impl Default for Statement {
    fn default() -> Statement {
        Statement::Basis(StatedCamera::default())
    }
}

#[cfg(test)]
mod tests {
    use super::Number;

    #[test]
    fn a_number_is_written_with_the_mark_asked() {
        assert_eq!(Number::dec(25, 2).written('.'), "0.25");
        assert_eq!(Number::dec(25, 2).written(','), "0,25");
        assert_eq!(Number::dec(15, 1).written(','), "1,5");
        assert_eq!(Number::dec(1, 1).written('.'), "0.1");
        assert_eq!(Number::dec(-105, 2).written(','), "-1,05");
        assert_eq!(Number::int(-3).written(','), "-3");
        assert_eq!(Number::Fraction(16, 9).written(','), "16/9");
    }
}
