//! The words of every message key (`crate::msg::Msg`), in English and in
//! Bahasa Indonesia, with the course text's own terms (docs/glossary.md).
//!
//! Each language is one module (`en`, `id`) holding one type that
//! implements [`Words`]: one trait per family of keys, each method one
//! exhaustive match over that family in that language, and the language's
//! number style ([`MsgWords::nums`]). A third language is a third module
//! and a `Lang` variant; the compiler names every family and every key it
//! has not yet written. A family's file (`msg.rs`, `drawn.rs`, …) holds its
//! trait and the language-neutral joining its words share.

use super::lang::Lang;
use crate::msg::Msg;

mod drawn;
mod en;
pub mod errors;
mod figure;
mod id;
pub mod keys;
mod msg;
pub mod names;
mod pixel;
pub mod render;
pub mod report;
pub mod said;

pub use drawn::DrawnWords;
pub use figure::FigureWords;
pub use msg::MsgWords;
pub use pixel::PixelWords;
pub use render::RenderWords;
pub use said::SaidWords;

/// Every word of one language: each family's trait, implemented by that
/// language's module.
pub trait Words:
    Sync
    + MsgWords
    + DrawnWords
    + FigureWords
    + PixelWords
    + SaidWords
    + RenderWords
    + errors::ErrorWords
    + names::NameWords
    + keys::KeyWords
    + report::ReportWords
{
}

/// The words of `lang`.
pub fn of(lang: Lang) -> &'static dyn Words {
    match lang {
        Lang::En => &en::En,
        Lang::Id => &id::Id,
    }
}

/// The words of `m` in `lang` ([`MsgWords::msg`]): each language's one
/// exhaustive match over every key, so a key without its words does not
/// compile (no wildcard arm, nothing falls through to "?" or an empty
/// string at run time).
pub fn words(m: &Msg, lang: Lang) -> String {
    of(lang).msg(m)
}

/// The words of `m` in `lang` with its numbers in the style `nums`, which
/// may be another language's: a quiz's `--decimal` (`--lang id --decimal
/// point`) writes the whole exam with one decimal mark
/// ([`MsgWords::msg_in`]).
pub fn words_in(m: &Msg, lang: Lang, nums: super::lang::NumStyle) -> String {
    of(lang).msg_in(m, nums)
}

/// `message` cut to `MAX_MESSAGE` characters in `lang`
/// (`msg::cut_message`).
pub fn cut_message(message: &str, lang: Lang) -> String {
    msg::cut_message(of(lang), message)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msg::{Erratum, LightPart, Printed, SpotZone, Term, Trivial};
    use crate::report::lang::NumStyle;

    /// Every key, once, with sample parameters.
    pub fn every_message() -> Vec<Msg> {
        let s = || "A".to_string();
        let mut v = vec![
            Msg::SecModeling,
            Msg::SecViewing,
            Msg::SecProjection,
            Msg::SecWindowClip,
            Msg::SecWindow,
            Msg::SecViewport,
            Msg::SecLineClip(None),
            Msg::SecLineClip(Some(2)),
            Msg::SecLighting,
            Msg::SecPixel(1, 2),
            Msg::SecLightFace,
            Msg::SecLightVertex(1),
            Msg::SecLightPixel,
            Msg::CamAxisN,
            Msg::CamAxisU,
            Msg::CamAxisV,
            Msg::CamCheck,
            Msg::CamMatrix,
            Msg::ViewMatrix,
            Msg::EyeCoords(s()),
            Msg::OrthoProj(s()),
            Msg::PerspProj(s()),
            Msg::WindowTop(s()),
            Msg::WindowEdges(s()),
            Msg::ViewportOf(s()),
            Msg::OutcodeOf(s()),
            Msg::TrivialTests,
            Msg::ClippedSegment,
            Msg::LiangBarsky,
            Msg::MethodsAgree,
            Msg::NothingToDo,
            Msg::ProjPlane,
            Msg::InsideVolume(s()),
            Msg::UnitVector(s()),
            Msg::ViewerLocal,
            Msg::Material,
            Msg::SumOfTerms,
            Msg::Clamp,
            Msg::WhichTriangle,
            Msg::Depth,
            Msg::Barycentric,
            Msg::FlatShading,
            Msg::Gouraud,
            Msg::PhongShading,
            Msg::PixelColour,
            Msg::FOutOfRange,
            Msg::FIncidence,
            Msg::FCamMatrix,
            Msg::FWindowEdges,
            Msg::FViewMatrix,
            Msg::FTrivial,
            Msg::FOutcode,
            Msg::FSegment,
            Msg::FMethods,
            Msg::FProjPlane,
            Msg::FPixelCentre,
            Msg::FEdges,
            Msg::FDepth,
            Msg::FBarycentric,
            Msg::FFlat,
            Msg::FLiangBarsky,
            Msg::FInside,
            Msg::FSpot,
            Msg::FClamp,
            Msg::FByte,
            Msg::AlreadyUnit,
            Msg::Saturates,
            Msg::InRange,
            Msg::TextSetting,
            Msg::SummedInRange,
            Msg::SpecularSkipped,
            Msg::BeyondRange,
            Msg::WithinRange,
            Msg::NoRange,
            Msg::Behind(true),
            Msg::Behind(false),
            Msg::LocalViewer,
            Msg::NoLocalViewer,
            Msg::ShininessZero,
            Msg::SpecularOff,
            Msg::NoHighlightBehind,
            Msg::BehindCentre,
            Msg::TextH,
            Msg::Orthonormal(true),
            Msg::Orthonormal(false),
            Msg::Kept(true),
            Msg::Kept(false),
            Msg::TouchesPoint,
            Msg::InsidePart,
            Msg::Misses,
            Msg::DefaultView,
            Msg::MaterialD3d,
            Msg::MaterialText,
            Msg::NoTriangle,
            Msg::Nearest,
            Msg::Agree(true),
            Msg::Agree(false),
            Msg::AlreadyWorld,
            Msg::Inside(true, true),
            Msg::Inside(false, true),
            Msg::Inside(true, false),
            Msg::UpParallel(1e-9),
            Msg::BehindWarn(s()),
            Msg::ExactTooLarge(64),
            Msg::ExactTooLong(16_384),
            Msg::StaleTempRemoved("out/.grafika-tmp-123-4567-ab".into(), 123),
            Msg::NoFigure,
            Msg::ExpectOne,
            Msg::ExpectList(3),
            Msg::CountMismatch(3, 2),
            Msg::Expected("0.5".into()),
            Msg::ExpectedNone,
            Msg::ExpectedBool(true),
            Msg::SeveralAnswers,
            Msg::EmptyAnswer,
            Msg::NoAnswer,
            Msg::AnswerTooLong(5000, 4000),
            Msg::Unreadable(crate::msg::NumErr::Empty),
            Msg::Exact,
            Msg::Rounded(4),
            Msg::RoundedCoarse(1, 3),
            Msg::WithinPct("0.5".into()),
            Msg::Parts(vec![("x".into(), Msg::Exact)]),
            Msg::WithinPixel,
            Msg::NotAnOutcode(s()),
            Msg::NotAStatus(s()),
            Msg::NotYesOrNo(s()),
            Msg::AmbiguousCommas,
            Msg::FollowThrough,
            Msg::NoFollowFrom(
                "view.u".into(),
                crate::msg::Implausible::NotUnit,
                "view.v".into(),
            ),
            Msg::NoFollowFrom(
                "view.v".into(),
                crate::msg::Implausible::NotPerpendicular("view.n".into()),
                "view.points.A".into(),
            ),
            Msg::NoFollowFrom(
                "clip.intersections.right.point".into(),
                crate::msg::Implausible::OffSegment,
                "clip.segment".into(),
            ),
            Msg::ErrSamePoint("(1, 2, 3)".into()),
            Msg::ErrUpZero,
            Msg::ErrUpParallel("(0, 1, 0)".into(), "(0, 5, 0)".into()),
            Msg::ErrFovy("180".into()),
            Msg::ErrAspect("0".into()),
            Msg::ErrNear("-1".into()),
            Msg::ErrCopPlane(s(), None),
            Msg::ErrCopPlane(s(), Some("2".into())),
            Msg::ErrUnknownPoint(s(), None),
            Msg::ErrUnknownPoint(s(), Some("A, B".into())),
            Msg::ErrBoxInverted("y".into(), "5".into(), "4".into()),
            Msg::ErrCannotRead("p.toml".into(), crate::msg::IoWhy::NotFound),
            Msg::ErrZeroUnit(s()),
            Msg::ErrNamedPoint(s()),
            Msg::ErrPointName(s()),
            Msg::ErrPointTwice(s()),
            Msg::ErrNamedPair(s()),
            Msg::ErrSize(s()),
            Msg::ErrCopNeedsPlane,
            Msg::ErrPlaneNeedsCop,
            Msg::ErrChooseProjection,
            Msg::ErrPointNeedsViewport,
        ];
        for i in 0..6 {
            v.push(Msg::Intersection(i, "x = xmin".into()));
        }
        for t in [Term::Ambient, Term::Diffuse, Term::Specular] {
            v.push(Msg::TermStep(t));
            v.push(Msg::NoTermInModel("lambert".into(), t));
            v.push(Msg::TextTerm(t));
        }
        for p in [
            LightPart::OutOfRange,
            LightPart::Direction,
            LightPart::Attenuation,
            LightPart::Incidence,
            LightPart::Reflection,
            LightPart::HalfVector,
            LightPart::Highlight,
            LightPart::Spot,
        ] {
            v.push(Msg::Light((0, 1), p));
            v.push(Msg::Light((1, 2), p));
        }
        for z in [SpotZone::Inner, SpotZone::Outer, SpotZone::Penumbra] {
            v.push(Msg::SpotIn(z));
        }
        for t in [Trivial::Accept, Trivial::Reject, Trivial::Clip] {
            v.push(Msg::TrivialNote(t));
        }
        for all in [true, false] {
            v.push(Msg::ErrFewDistinct {
                topic: "window".into(),
                level: "easy".into(),
                problem: 2,
                found: 20,
                asked: 40,
                all,
            });
        }
        v.push(Msg::ErrHtmlCommand);
        v.extend(figure_messages());
        v.extend(drawn_messages());
        v.push(Msg::Unreadable(crate::msg::NumErr::DivZero("1/0".into())));
        v.push(Msg::Written("as for B".into(), Some("seperti B".into())));
        for k in [
            None,
            Some(Erratum::Misprint),
            Some(Erratum::Convention),
            Some(Erratum::Rounding),
        ] {
            v.push(Msg::Printed(Printed::Differs(k)));
            let why = Msg::Written("as for B".into(), Some("seperti B".into()));
            v.push(Msg::Erratum(k, Box::new(why)));
        }
        for p in [Printed::Agrees, Printed::NotAsked, Printed::NotComparable] {
            v.push(Msg::Printed(p));
        }
        let parts = ["view", "project", "window", "viewport", "clip", "shade"];
        v.push(Msg::Asked(parts.map(String::from).to_vec()));
        for s in [
            crate::msg::Said::BitTest(true, "x > xmax".into(), "4.5 > 3".into()),
            crate::msg::Said::BitTest(false, "x < xmin".into(), "4.5 < 0".into()),
            crate::msg::Said::BitQuestion("x < xmin".into(), "4.5 < 0".into()),
            crate::msg::Said::FrameTime("12.30".into(), "25.0".into(), "1.20".into()),
            crate::msg::Said::Status("clipped".into()),
            crate::msg::Said::Status("accepted".into()),
            crate::msg::Said::Status("rejected".into()),
        ] {
            v.push(Msg::Said(s));
        }
        v.push(Msg::At("p.toml:3:7".into(), Box::new(Msg::ErrUpZero)));
        v.extend(errors::tests::every_error().into_iter().map(Msg::Err));
        v.extend(pixel::every().into_iter().map(Msg::Pixel));
        v
    }

    /// Every figure message.
    fn figure_messages() -> Vec<Msg> {
        use crate::msg::{FigWord as W, FigureMsg as F, Panel as P};
        let panels = [
            P::Camera,
            P::Projection,
            P::ProjectionSide,
            P::ViewPlane,
            P::Frustum,
            P::WindowSide,
            P::NearWindow,
            P::Viewport,
            P::Clip,
            P::Shade,
        ];
        let words = [W::Cop, W::Eye, W::NotToScale, W::Surface];
        let mut v: Vec<F> = panels
            .iter()
            .flat_map(|p| [F::Title(*p), F::Desc(*p)])
            .collect();
        v.extend(words.map(F::Word));
        v.into_iter().map(Msg::Figure).collect()
    }

    /// Every title and statement of a generated problem.
    fn drawn_messages() -> Vec<Msg> {
        use crate::msg::{DrawnTitle as T, Number, ShadeAsked, StatedCamera, Statement as S};
        let c = || StatedCamera {
            eye: [3, 4, 0],
            look: [0, 0, 0],
            up: [0, 1, 0],
        };
        let p = || vec![("A".to_string(), [1, -2, 2])];
        let half = Number::dec(5, 1);
        let mut v: Vec<Msg> = [
            T::Basis,
            T::EyeCoordinates,
            T::Projection,
            T::Pipeline,
            T::Window,
            T::Clipping,
            T::Lighting,
        ]
        .into_iter()
        .map(Msg::DrawnTitle)
        .collect();
        let shade = |asked| S::Shade {
            normal: [0, 3, 4],
            color: [Number::int(1), half, Number::int(0)],
            light: [0, 0, 1],
            view: [0, 0, 1],
            model: "phong".into(),
            constants: vec![("ka", Number::dec(4, 1)), ("kd", Number::dec(6, 1))],
            asked,
        };
        for st in [
            S::Basis(c()),
            S::View(c(), p()),
            S::Project(c(), p(), half),
            S::Pipeline {
                camera: c(),
                points: p(),
                near: half,
                fovy: 45,
                aspect: Number::dec(15, 1),
                viewport: (200, 100),
            },
            S::Window(90, Number::Fraction(4, 3), Number::int(2)),
            S::Clip([0, 0, 0], [2, 2, 2], [1, 1, 1], [3, 1, 1]),
            shade(ShadeAsked::Ambient),
            shade(ShadeAsked::Diffuse),
            shade(ShadeAsked::Specular),
            shade(ShadeAsked::Lambert),
            shade(ShadeAsked::Blinn),
            shade(ShadeAsked::Phong),
        ] {
            v.push(Msg::Statement(Box::new(st)));
        }
        v
    }

    #[test]
    fn a_statement_writes_its_numbers_in_the_style_asked() {
        use crate::msg::{Number, ShadeAsked, Statement as S};
        let shade = S::Shade {
            normal: [0, -3, 4],
            color: [Number::int(1), Number::dec(5, 1), Number::int(0)],
            light: [0, 0, 1],
            view: [0, 0, 1],
            model: "lambert".into(),
            constants: vec![("ka", Number::dec(4, 1)), ("kd", Number::dec(6, 1))],
            asked: ShadeAsked::Lambert,
        };
        let id = of(Lang::Id).statement(&shade, NumStyle::COMMA);
        assert!(
            id.contains("N = (0; -3; 4) dan warna Cs = (1; 0,5; 0)"),
            "{id}"
        );
        assert!(id.contains("(ka = 0,4; kd = 0,6)"), "{id}");
        assert!(id.contains("[0; 1]"), "{id}");
        // a quiz with --decimal point in Indonesian, comma in English
        let id_point = of(Lang::Id).statement(&shade, NumStyle::POINT);
        assert!(id_point.contains("Cs = (1, 0.5, 0)") && id_point.contains("ka = 0.4, kd = 0.6"));
        let en_comma = of(Lang::En).statement(&shade, NumStyle::COMMA);
        assert!(en_comma.contains("color Cs = (1; 0,5; 0)"), "{en_comma}");
        let window = S::Window(90, Number::Fraction(16, 9), Number::dec(25, 2));
        let id = of(Lang::Id).statement(&window, NumStyle::COMMA);
        assert!(id.contains("aspect ratio 16/9 dan near = 0,25."), "{id}");
        let pts = S::View(
            crate::msg::StatedCamera {
                eye: [3, 4, 0],
                look: [0, 0, 0],
                up: [0, 1, 0],
            },
            vec![("A".into(), [1, 0, 2]), ("B".into(), [-1, 2, 0])],
        );
        let id = of(Lang::Id).statement(&pts, NumStyle::COMMA);
        assert!(
            id.contains("Pref = (0; 0; 0)") && id.ends_with("titik-titik A(1; 0; 2); B(-1; 2; 0)."),
            "{id}"
        );
    }

    /// Fails to compile when a key is added without being listed above.
    #[allow(dead_code)]
    fn listed(m: &Msg) {
        use Msg::*;
        match m {
            Math(_)
            | Written(..)
            | Erratum(..)
            | Printed(_)
            | Asked(_)
            | SecModeling
            | SecViewing
            | SecProjection
            | SecWindowClip
            | SecWindow
            | SecViewport
            | SecLineClip(_)
            | SecLighting
            | SecPixel(..)
            | SecLightFace
            | SecLightVertex(_)
            | SecLightPixel
            | CamAxisN
            | CamAxisU
            | CamAxisV
            | CamCheck
            | CamMatrix
            | ViewMatrix
            | EyeCoords(_)
            | OrthoProj(_)
            | PerspProj(_)
            | WindowTop(_)
            | WindowEdges(_)
            | ViewportOf(_)
            | OutcodeOf(_)
            | TrivialTests
            | Intersection(..)
            | ClippedSegment
            | LiangBarsky
            | MethodsAgree
            | NothingToDo
            | ProjPlane
            | InsideVolume(_)
            | UnitVector(_)
            | ViewerLocal
            | Material
            | Light(..)
            | TermStep(_)
            | SumOfTerms
            | Clamp
            | WhichTriangle
            | Depth
            | Barycentric
            | FlatShading
            | Gouraud
            | PhongShading
            | PixelColour
            | FOutOfRange
            | FIncidence
            | FCamMatrix
            | FViewMatrix
            | FTrivial
            | FOutcode
            | FSegment
            | FMethods
            | FProjPlane
            | FLiangBarsky
            | FInside
            | FSpot
            | FClamp
            | FWindowEdges
            | FPixelCentre
            | FEdges
            | FDepth
            | FBarycentric
            | FFlat
            | FByte
            | AlreadyUnit
            | Saturates
            | InRange
            | NoTermInModel(..)
            | TextSetting
            | TextTerm(_)
            | SummedInRange
            | SpecularSkipped
            | BeyondRange
            | WithinRange
            | NoRange
            | Behind(_)
            | LocalViewer
            | NoLocalViewer
            | ShininessZero
            | SpecularOff
            | NoHighlightBehind
            | SpotIn(_)
            | BehindCentre
            | TextH
            | Orthonormal(_)
            | TrivialNote(_)
            | Kept(_)
            | TouchesPoint
            | InsidePart
            | Misses
            | DefaultView
            | MaterialD3d
            | MaterialText
            | NoTriangle
            | Nearest
            | Agree(_)
            | AlreadyWorld
            | Inside(..)
            | UpParallel(_)
            | BehindWarn(_)
            | ExactTooLarge(_)
            | ExactTooLong(_)
            | StaleTempRemoved(..)
            | NoFigure
            | ExpectOne
            | ExpectList(_)
            | CountMismatch(..)
            | Expected(_)
            | ExpectedNone
            | ExpectedBool(_)
            | SeveralAnswers
            | EmptyAnswer
            | NoAnswer
            | AnswerTooLong(..)
            | Unreadable(_)
            | Exact
            | Rounded(_)
            | RoundedCoarse(..)
            | WithinPct(_)
            | Parts(_)
            | WithinPixel
            | NotAnOutcode(_)
            | NotAStatus(_)
            | NotYesOrNo(_)
            | AmbiguousCommas
            | FollowThrough
            | NoFollowFrom(..)
            | At(..)
            | Err(_)
            | Said(_)
            | ErrSamePoint(_)
            | ErrUpZero
            | ErrUpParallel(..)
            | ErrFovy(_)
            | ErrAspect(_)
            | ErrNear(_)
            | ErrCopPlane(..)
            | ErrUnknownPoint(..)
            | ErrBoxInverted(..)
            | ErrCannotRead(..)
            | ErrZeroUnit(_)
            | ErrNamedPoint(_)
            | ErrPointName(_)
            | ErrPointTwice(_)
            | ErrNamedPair(_)
            | ErrSize(_)
            | ErrCopNeedsPlane
            | ErrPlaneNeedsCop
            | ErrChooseProjection
            | ErrPointNeedsViewport
            | DrawnTitle(_)
            | Pixel(_)
            | Statement(_)
            | ErrFewDistinct { .. }
            | ErrHtmlCommand
            | Figure(_) => {}
        }
    }

    /// Every name and line of the render summary.
    fn render_words(w: &dyn Words) -> Vec<String> {
        use crate::msg::{PerPixel, Summary};
        let mut v: Vec<String> = [
            Summary::Image,
            Summary::Size,
            Summary::Shading,
            Summary::TrianglesDrawn,
            Summary::PixelsShaded,
            Summary::FrameTime { runs: 1 },
            Summary::FrameTime { runs: 5 },
        ]
        .into_iter()
        .map(|k| w.summary(k))
        .collect();
        for p in [
            PerPixel::Everywhere,
            PerPixel::PhongObjectsOnly,
            PerPixel::Nowhere(vec!["flat"]),
        ] {
            v.push(w.per_pixel(&p));
        }
        v.push(w.render_heading().to_string());
        v
    }

    /// A message whose words are a sentence: three words or more, at
    /// least one of them of four letters or more.
    fn is_sentence(s: &str) -> bool {
        let words: Vec<&str> = s.split_whitespace().collect();
        let long = |w: &&str| w.chars().filter(|c| c.is_alphabetic()).count() >= 4;
        words.len() >= 3 && words.iter().any(long)
    }

    #[test]
    fn every_message_has_words_in_every_language() {
        for lang in Lang::ALL {
            for m in every_message() {
                let w = of(lang).msg(&m);
                assert!(
                    !w.trim().is_empty() && w != "?",
                    "{m:?} has no words in {lang:?}"
                );
                assert_eq!(w, words(&m, lang), "{m:?}: words() is of(lang).msg()");
            }
            for w in render_words(of(lang)) {
                assert!(!w.trim().is_empty(), "a render word is empty in {lang:?}");
            }
        }
    }

    #[test]
    fn no_indonesian_sentence_is_the_english_one() {
        // notation written the same in both: the clip-space outcode bits,
        // the problem file's own text given in one language only
        let same = |m: &Msg| {
            matches!(
                m,
                Msg::Pixel(crate::msg::PixelMsg::FOutcode) | Msg::Written(_, None)
            )
        };
        for m in every_message() {
            let (en, id) = (of(Lang::En).msg(&m), of(Lang::Id).msg(&m));
            if is_sentence(&en) && !same(&m) {
                assert_ne!(en, id, "{m:?} is not translated");
            }
        }
        let (en, id) = (render_words(of(Lang::En)), render_words(of(Lang::Id)));
        for (en, id) in en.iter().zip(&id) {
            if is_sentence(en) {
                assert_ne!(en, id, "a render word is not translated");
            }
        }
    }

    #[test]
    fn each_language_declares_its_numbers() {
        assert_eq!(of(Lang::En).nums(), NumStyle::POINT);
        assert_eq!(of(Lang::Id).nums(), NumStyle::COMMA);
        let up = Msg::UpParallel(1.5e-9);
        assert!(of(Lang::Id).msg(&up).contains("1,500e-9 rad"));
        assert!(of(Lang::En).msg(&up).contains("1.500e-9 rad"));
    }

    #[test]
    fn a_long_message_is_cut_in_its_middle_in_each_language() {
        // 400 characters: 150 kept at each end, 400 − 300 = 100 cut
        let m = format!("{}{}{}", "a".repeat(150), "b".repeat(100), "c".repeat(150));
        let (head, tail) = ("a".repeat(150), "c".repeat(150));
        assert_eq!(
            cut_message(&m, Lang::En),
            format!("{head} … (100 characters cut) … {tail}")
        );
        assert_eq!(
            cut_message(&m, Lang::Id),
            format!("{head} … (100 karakter dipotong) … {tail}")
        );
        let short = "x".repeat(300);
        assert_eq!(cut_message(&short, Lang::Id), short);
    }

    #[test]
    fn the_per_pixel_line_names_every_shading_drawn() {
        use crate::msg::PerPixel;
        let en = |p: PerPixel| of(Lang::En).per_pixel(&p);
        let id = |p: PerPixel| of(Lang::Id).per_pixel(&p);
        assert_eq!(en(PerPixel::Nowhere(vec!["flat"])), "none (flat shading)");
        let both = || PerPixel::Nowhere(vec!["gouraud", "flat"]);
        assert_eq!(en(both()), "none (gouraud and flat shading)");
        assert_eq!(id(both()), "tidak ada (gouraud dan flat shading)");
        assert_eq!(en(PerPixel::Everywhere), "yes (Phong)");
        assert_eq!(en(PerPixel::PhongObjectsOnly), "Phong objects only");
        assert_eq!(id(PerPixel::PhongObjectsOnly), "hanya objek Phong");
    }

    #[test]
    fn a_summary_name_has_its_words_and_its_json_key_in_every_language() {
        use crate::msg::Summary;
        let median = Summary::FrameTime { runs: 5 };
        assert_eq!(median.key(), "frame time (median of 5)");
        assert_eq!(of(Lang::En).summary(median), median.key());
        assert_eq!(
            of(Lang::Id).summary(median),
            "waktu per bingkai (median dari 5)"
        );
        assert_eq!(Summary::FrameTime { runs: 1 }.key(), "frame time");
        assert_eq!(
            of(Lang::Id).summary(Summary::TrianglesDrawn),
            "segitiga digambar"
        );
        assert_eq!(Summary::TrianglesDrawn.key(), "triangles drawn");
    }

    #[test]
    fn a_clipping_status_is_said_in_the_texts_word() {
        use crate::msg::Said;
        use crate::stages::clip::Status;
        // the code is the JSON's; Indonesian text says the text's word alone
        let words = [
            (Status::Accepted, "diterima"),
            (Status::Rejected, "ditolak"),
            (Status::Clipped, "di-clip"),
        ];
        for (s, word) in words {
            let said = Said::Status(s.as_str().into());
            assert_eq!(of(Lang::En).said(&said, NumStyle::POINT), s.as_str());
            assert_eq!(of(Lang::Id).said(&said, NumStyle::COMMA), word);
        }
    }

    #[test]
    fn most_messages_differ_between_languages() {
        let all = every_message();
        let same = all
            .iter()
            .filter(|m| words(m, Lang::En) == words(m, Lang::Id))
            .count();
        // Only notation-like captions (the outcode bits) may coincide.
        assert!(same <= 2, "{same} messages are not translated");
    }
}
