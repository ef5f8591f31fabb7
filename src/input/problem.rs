//! Problem files (docs/spec.md §5): the TOML schema, read with line and column in
//! every syntax error, into plain expressions that any precision evaluates.

use crate::error::{Error, Result};
use crate::input::ask::Part;
use crate::input::fields::{toml_reason, AngleIn, Num, Vec3In};
use crate::msg::{ErrMsg, Erratum, Lang, Msg};
use serde::de::{self, Deserializer};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;

/// `[camera]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraIn {
    /// Pe.
    pub eye: Vec3In,
    /// Pr.
    pub look: Vec3In,
    /// Vup.
    pub up: Vec3In,
}

/// `[perspective]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PerspectiveIn {
    /// Near-plane distance.
    pub near: Option<Num>,
    /// Far-plane distance.
    pub far: Option<Num>,
    /// Vertical field of view (degrees; a string ending in `rad` for radians).
    pub fovy: Option<AngleIn>,
    /// width / height.
    pub aspect: Option<Num>,
    /// [W, H] pixels.
    pub viewport: Option<[Num; 2]>,
    /// The projection plane z = d (default −near).
    pub d: Option<Num>,
}

/// A segment end: coordinates `[x, y, z]`, or the name of a point in
/// `[points]` (`from = "A"`).
#[derive(Clone, Debug, PartialEq)]
pub enum PointRef {
    /// Coordinates.
    At(Box<Vec3In>),
    /// A point of the problem, by name.
    Named(String),
}

impl<'de> Deserialize<'de> for PointRef {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<PointRef, D::Error> {
        struct V;
        impl<'de> de::Visitor<'de> for V {
            type Value = PointRef;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("[x, y, z], \"(x, y, z)\" or the name of a point in [points]")
            }
            /// A name, or coordinates written as one string (`"(0, 2, 6)"`):
            /// a name holds no bracket, comma or semicolon.
            fn visit_str<E: de::Error>(self, v: &str) -> std::result::Result<PointRef, E> {
                if v.contains(['(', '[', ',', ';']) {
                    let at: Vec3In = Deserialize::deserialize(de::value::StrDeserializer::new(v))?;
                    return Ok(PointRef::At(Box::new(at)));
                }
                Ok(PointRef::Named(v.to_string()))
            }
            fn visit_seq<A: de::SeqAccess<'de>>(
                self,
                seq: A,
            ) -> std::result::Result<PointRef, A::Error> {
                let v: Vec3In =
                    Deserialize::deserialize(de::value::SeqAccessDeserializer::new(seq))?;
                Ok(PointRef::At(Box::new(v)))
            }
        }
        d.deserialize_any(V)
    }
}

/// One `[[clip.segment]]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SegmentIn {
    /// P0.
    pub from: PointRef,
    /// P1.
    pub to: PointRef,
}

/// `[clip]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClipIn {
    /// (xmin, ymin, zmin).
    pub min: Vec3In,
    /// (xmax, ymax, zmax).
    pub max: Vec3In,
    /// The segments to clip.
    #[serde(default)]
    pub segment: Vec<SegmentIn>,
}

/// One `[[errata]]` entry: where the source's printed answer differs from
/// the right one, what kind of difference it is, and why.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ErratumIn {
    /// The result key (`project.points.B`).
    pub key: String,
    /// A misprint, another convention, or a rounding (none: not said).
    #[serde(default)]
    pub kind: Option<Erratum>,
    /// The reason, in English.
    pub why: String,
    /// The reason in Bahasa Indonesia (shown with `--lang id`).
    #[serde(default)]
    pub why_id: Option<String>,
}

impl ErratumIn {
    /// The reason in both languages the file gives.
    pub fn why(&self) -> Msg {
        Msg::Written(self.why.clone(), self.why_id.clone())
    }

    /// The reason after the words for its kind (`a misprint in the text: …`).
    pub fn reason(&self) -> Msg {
        Msg::Erratum(self.kind, Box::new(self.why()))
    }
}

/// `[check]`: how `grafika check` marks answers to this problem.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CheckIn {
    /// Relative tolerance (default 0.001).
    pub tolerance: Option<f64>,
    /// Minimum significant figures of a rounded decimal answer (default 2).
    pub sig_figs: Option<u32>,
    /// The answer keys expected (default: every answer the problem asks for).
    pub keys: Option<Vec<String>>,
}

/// A whole problem file.
#[derive(Clone, Debug, Deserialize)]
pub struct ProblemIn {
    /// The problem's title.
    pub title: String,
    /// Where it comes from.
    pub source: Option<String>,
    /// Where it comes from, in Bahasa Indonesia (shown with `--lang id`).
    #[serde(default)]
    pub source_id: Option<String>,
    /// The statement, as a student reads it.
    pub statement: Option<String>,
    /// The title in Bahasa Indonesia (shown with `--lang id`).
    #[serde(default)]
    pub title_id: Option<String>,
    /// The statement in Bahasa Indonesia (shown with `--lang id`).
    #[serde(default)]
    pub statement_id: Option<String>,
    /// The parts asked for, in the file's order; default: all the data
    /// allow. Read from the file's names by [`ProblemIn::parse`].
    #[serde(skip)]
    pub ask: Option<Vec<Part>>,
    /// `ask` as the file writes it (names), read into `ask` by `parse`,
    /// which refuses an unknown name.
    #[serde(rename = "ask", default)]
    ask_names: Option<Vec<String>>,
    /// The camera.
    pub camera: Option<CameraIn>,
    /// The perspective set-up.
    pub perspective: Option<PerspectiveIn>,
    /// World points, in file order.
    #[serde(default)]
    pub points: toml::Table,
    /// A clipping box and segments.
    pub clip: Option<ClipIn>,
    /// The lighting problem (see the shade command).
    pub shade: Option<crate::input::lights::ShadeIn>,
    /// Lights for the lighting problem.
    #[serde(default)]
    pub light: Vec<crate::input::lights::LightIn>,
    /// Ga, the global ambient light of the lighting problem.
    pub global_ambient: Option<Vec3In>,
    /// The answers printed in the source, keyed like the JSON results.
    #[serde(default)]
    pub printed: toml::Table,
    /// Where and why the printed answers are wrong.
    #[serde(default)]
    pub errata: Vec<ErratumIn>,
    /// Settings for `grafika check` (tolerance, significant figures, the answers expected).
    pub check: Option<CheckIn>,
    /// The marking scheme's weights: answer key → marks, or `{ marks, method
    /// }` (read by `tutor::check::scheme`, which knows the keys).
    #[serde(default)]
    pub marks: toml::Table,
    /// Remarks on the source beyond single answers (misprinted rules).
    #[serde(default)]
    pub source_notes: Vec<String>,
    /// The remarks in Bahasa Indonesia (shown with `--lang id`).
    #[serde(default)]
    pub source_notes_id: Vec<String>,
    /// Any other key: kept for tools, ignored by solve.
    #[serde(flatten)]
    pub other: BTreeMap<String, toml::Value>,
}

impl ProblemIn {
    /// Parses a problem from TOML text; syntax and type errors carry the line
    /// and column (`file:line:col`).
    pub fn parse(text: &str, origin: &str) -> Result<ProblemIn> {
        let mut p: ProblemIn = crate::input::fields::parse_toml(text, origin)?;
        crate::input::lights::place(&mut p.light, text, origin)?;
        if let Some(names) = p.ask_names.take() {
            p.ask = Some(names.iter().map(|a| part(a)).collect::<Result<_>>()?);
        }
        Ok(p)
    }

    /// The problem as a reader of `lang` sees it: in Bahasa Indonesia
    /// `title_id`, `statement_id`, `source_id` and `source_notes_id` in
    /// place of `title`, `statement`, `source` and `source_notes` where the
    /// file gives them.
    pub fn localized(mut self, lang: Lang) -> ProblemIn {
        if lang == Lang::Id {
            self.title = self.title_id.take().unwrap_or(self.title);
            self.statement = self.statement_id.take().or(self.statement);
            self.source = self.source_id.take().or(self.source);
            if !self.source_notes_id.is_empty() {
                self.source_notes = std::mem::take(&mut self.source_notes_id);
            }
        }
        self
    }

    /// Reads and parses a problem file.
    pub fn read(path: &Path) -> Result<ProblemIn> {
        let text = crate::input::read_text("file", path)?;
        ProblemIn::parse(&text, &path.display().to_string())
    }

    /// The points in file order, each parsed.
    pub fn points(&self) -> Result<Vec<(String, Vec3In)>> {
        self.points
            .iter()
            .map(|(name, v)| {
                let arr: Vec3In = v.clone().try_into().map_err(|e: toml::de::Error| {
                    Error::why(
                        format!("points.{name}"),
                        ErrMsg::ExpectedXyz(toml_reason(e.message())),
                    )
                })?;
                Ok((name.clone(), arr))
            })
            .collect()
    }

    /// Every number the problem states, at f64 (those `solve --json`'s
    /// `input` lists: the camera, the points, the perspective set-up with
    /// fovy in degrees, the box and the segments' coordinates, the `[shade]`
    /// vectors and coefficients, the lights' directions, positions and
    /// axes); a number that does not evaluate is left out.
    pub fn stated_numbers(&self) -> Vec<f64> {
        let mut nums: Vec<&Num> = Vec::new();
        let mut vecs: Vec<&Vec3In> = Vec::new();
        if let Some(c) = &self.camera {
            vecs.extend([&c.eye, &c.look, &c.up]);
        }
        let points = self.points().unwrap_or_default();
        vecs.extend(points.iter().map(|(_, v)| v));
        let mut out: Vec<f64> = Vec::new();
        if let Some(per) = &self.perspective {
            nums.extend(
                [&per.near, &per.far, &per.aspect, &per.d]
                    .into_iter()
                    .flatten(),
            );
            out.extend(per.fovy.as_ref().and_then(|a| a.0.degrees::<f64>().ok()));
            nums.extend(per.viewport.iter().flatten());
        }
        if let Some(c) = &self.clip {
            vecs.extend([&c.min, &c.max]);
            for s in &c.segment {
                for end in [&s.from, &s.to] {
                    if let PointRef::At(v) = end {
                        vecs.push(v);
                    }
                }
            }
        }
        if let Some(sh) = &self.shade {
            let v = [
                &sh.light,
                &sh.normal,
                &sh.view,
                &sh.color,
                &sh.camera,
                &sh.position,
            ];
            vecs.extend(v.into_iter().flatten());
            nums.extend(
                [&sh.ka, &sh.kd, &sh.ks, &sh.shininess]
                    .into_iter()
                    .flatten(),
            );
            for l in &self.light {
                vecs.extend([&l.direction, &l.position, &l.axis].into_iter().flatten());
            }
        }
        nums.extend(vecs.into_iter().flat_map(|v| v.iter()));
        out.extend(nums.iter().filter_map(|n| n.0.eval::<f64>().ok()));
        out
    }

    /// Whether the part is asked for (explicitly, or by default when the data allow it).
    pub fn asks(&self, part: Part) -> bool {
        match &self.ask {
            Some(a) => a.contains(&part),
            None => true,
        }
    }
}

/// The part `ask` names, or the error naming the parts there are.
fn part(name: &str) -> Result<Part> {
    Part::named(name).ok_or_else(|| {
        let all: Vec<&str> = Part::all().into_iter().map(Part::name).collect();
        Error::why("ask", ErrMsg::UnknownPart(name.to_string(), all.join(", ")))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Expr;

    #[test]
    fn numbers_keep_their_written_value() {
        let p = ProblemIn::parse(
            "title='t'\n[perspective]\nnear = 0.1\naspect = \"sqrt(2)/2\"\nfar = -3\n",
            "t",
        )
        .unwrap();
        let per = p.perspective.unwrap();
        assert_eq!(per.near.unwrap().0, Expr::Lit("0.1".into()));
        assert_eq!(
            per.far.unwrap().0,
            Expr::Neg(Box::new(Expr::Lit("3".into())))
        );
        assert!(matches!(per.aspect.unwrap().0, Expr::Div(..)));
    }

    #[test]
    fn errors_have_line_and_column() {
        let e = ProblemIn::parse(
            "title='t'\n[camera]\neye = [1, 2]\nlook=[0,0,0]\nup=[0,1,0]\n",
            "p.toml",
        )
        .unwrap_err();
        assert!(e.message.plain().starts_with("p.toml:3:"), "{e}");
        let e = ProblemIn::parse(
            "title='t'\n[camera]\neye = [1, 2, \"1+\"]\nlook=[0,0,0]\nup=[0,1,0]\n",
            "p.toml",
        )
        .unwrap_err();
        assert!(e.message.plain().contains("p.toml:3:"), "{e}");
        let e = ProblemIn::parse(
            "title='t'\n[camera]\neye=[0,0,1]\nlok=[0,0,0]\nup=[0,1,0]\n",
            "p.toml",
        )
        .unwrap_err();
        assert!(e.message.plain().contains("p.toml:4:"), "{e}");
    }
}
