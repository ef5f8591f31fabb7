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
    use strum::IntoEnumIterator;

    /// Every key: every variant of `Msg` (`EnumIter`, its fields at
    /// their defaults, so a key added is tested without being listed),
    /// a nested key's every variant in its place, and the samples whose
    /// words depend on their values. `Math` is notation, the same in
    /// every language, and has no words of its own.
    pub fn every_message() -> Vec<Msg> {
        Msg::iter().flat_map(with_nested).collect()
    }

    /// `m` once per variant of the key it holds, else with the values
    /// its words depend on ([`with_values`]).
    fn with_nested(m: Msg) -> Vec<Msg> {
        use crate::msg::{DrawnTitle, Implausible};
        let errata = || std::iter::once(None).chain(Erratum::iter().map(Some));
        match m {
            Msg::Math(_) => vec![],
            Msg::Erratum(..) => errata().map(|k| Msg::Erratum(k, Box::new(why()))).collect(),
            Msg::Printed(_) => (Printed::iter().filter(|p| !matches!(p, Printed::Differs(_))))
                .chain(errata().map(Printed::Differs))
                .map(Msg::Printed)
                .collect(),
            // one light (no number) and the first of two
            Msg::Light(..) => LightPart::iter()
                .flat_map(|p| [Msg::Light((0, 1), p), Msg::Light((1, 2), p)])
                .collect(),
            Msg::TermStep(_) => Term::iter().map(Msg::TermStep).collect(),
            Msg::TextTerm(_) => Term::iter().map(Msg::TextTerm).collect(),
            Msg::NoTermInModel(..) => Term::iter()
                .map(|t| Msg::NoTermInModel("lambert".into(), t))
                .collect(),
            Msg::SpotIn(_) => SpotZone::iter().map(Msg::SpotIn).collect(),
            Msg::TrivialNote(_) => Trivial::iter().map(Msg::TrivialNote).collect(),
            Msg::DrawnTitle(_) => DrawnTitle::iter().map(Msg::DrawnTitle).collect(),
            Msg::Unreadable(_) => errors::tests::every_number()
                .into_iter()
                .map(Msg::Unreadable)
                .collect(),
            Msg::NoFollowFrom(..) => Implausible::iter()
                .map(|i| Msg::NoFollowFrom("view.u".into(), i, "view.v".into()))
                .collect(),
            Msg::Err(_) => errors::tests::every_error()
                .into_iter()
                .map(Msg::Err)
                .collect(),
            Msg::Said(_) => said_messages(),
            Msg::Figure(_) => figure_messages(),
            Msg::Pixel(_) => pixel::every().into_iter().map(Msg::Pixel).collect(),
            Msg::Statement(_) => statements()
                .into_iter()
                .map(|s| Msg::Statement(Box::new(s)))
                .collect(),
            other => with_values(other),
        }
    }

    /// A lecturer's reason for an erratum, in both languages.
    fn why() -> Msg {
        Msg::Written("as for B".into(), Some("seperti B".into()))
    }

    /// `m` with each value its words depend on, else `m` itself.
    fn with_values(m: Msg) -> Vec<Msg> {
        match m {
            // a lecturer's own words are what is said (the empty default says nothing)
            Msg::Written(..) => vec![why()],
            // the parts a problem asks, named in the text's words
            Msg::Asked(_) => {
                let parts = ["view", "project", "window", "viewport", "clip", "shade"];
                vec![Msg::Asked(parts.map(String::from).to_vec())]
            }
            // a segment's number when there are several
            Msg::SecLineClip(_) => vec![Msg::SecLineClip(None), Msg::SecLineClip(Some(2))],
            // each plane of clip::PLANES by its index
            Msg::Intersection(..) => (0..6)
                .map(|i| Msg::Intersection(i, "x = xmin".into()))
                .collect(),
            Msg::Behind(_) => vec![Msg::Behind(true), Msg::Behind(false)],
            Msg::Orthonormal(_) => vec![Msg::Orthonormal(true), Msg::Orthonormal(false)],
            Msg::Kept(_) => vec![Msg::Kept(true), Msg::Kept(false)],
            Msg::Agree(_) => vec![Msg::Agree(true), Msg::Agree(false)],
            Msg::ExpectedBool(_) => vec![Msg::ExpectedBool(true), Msg::ExpectedBool(false)],
            Msg::Inside(..) => vec![
                Msg::Inside(true, true),
                Msg::Inside(false, true),
                Msg::Inside(true, false),
            ],
            // the known points, when there are some
            Msg::ErrCopPlane(p, _) => vec![
                Msg::ErrCopPlane(p.clone(), None),
                Msg::ErrCopPlane(p, Some(2.5)),
            ],
            Msg::ErrUnknownPoint(p, _) => vec![
                Msg::ErrUnknownPoint(p.clone(), None),
                Msg::ErrUnknownPoint(p, Some("A, B".into())),
            ],
            // every problem of its form tried, or the search stopped
            Msg::ErrFewDistinct { .. } => [true, false]
                .map(|all| Msg::ErrFewDistinct {
                    topic: "window".into(),
                    level: "easy".into(),
                    problem: 2,
                    found: 20,
                    asked: 40,
                    all,
                })
                .to_vec(),
            // the notes of a value's components
            Msg::Parts(_) => vec![Msg::Parts(vec![("x".into(), Msg::Exact)])],
            // a location before a message
            Msg::At(..) => vec![Msg::At("p.toml:3:7".into(), Box::new(Msg::ErrUpZero))],
            other => vec![other],
        }
    }

    /// Every value said in words: a bit's test true and false; a
    /// clipping status carries its code, so each real code.
    fn said_messages() -> Vec<Msg> {
        use crate::msg::Said;
        let mut v: Vec<Said> = Said::iter()
            .filter(|s| !matches!(s, Said::Status(_)))
            .collect();
        let n = |value: f64| crate::msg::Shown {
            value,
            ..Default::default()
        };
        let test = crate::msg::Compared(n(4.5), ">", n(3.0));
        v.push(Said::BitTest(true, "x > xmax".into(), Box::new(test)));
        let codes = crate::stages::clip::Status::iter().map(|s| s.as_str());
        v.extend(codes.map(|c| Said::Status(c.into())));
        v.into_iter().map(Msg::Said).collect()
    }

    /// Every figure message, a panel's title and description for every
    /// panel.
    fn figure_messages() -> Vec<Msg> {
        use crate::msg::{FigWord, FigureMsg as F, Panel};
        let mut v: Vec<F> = F::iter()
            .filter(|f| !matches!(f, F::Title(_) | F::Desc(_) | F::Word(_)))
            .collect();
        v.extend(Panel::iter().flat_map(|p| [F::Title(p), F::Desc(p)]));
        v.extend(FigWord::iter().map(F::Word));
        v.into_iter().map(Msg::Figure).collect()
    }

    /// A statement of each kind of generated problem, with numbers whose
    /// decimal mark shows (each kind of `Statement` is among them, and
    /// each lighting question).
    fn statements() -> Vec<crate::msg::Statement> {
        use crate::msg::{Number, StatedCamera, Statement as S};
        let c = || StatedCamera {
            eye: [3, 4, 0],
            look: [0, 0, 0],
            up: [0, 1, 0],
        };
        let p = || vec![("A".to_string(), [1, -2, 2])];
        let half = Number::dec(5, 1);
        let shade = |asked| S::Shade {
            normal: [0, 3, 4],
            color: [Number::int(1), half, Number::int(0)],
            light: [0, 0, 1],
            view: [0, 0, 1],
            model: "phong".into(),
            constants: vec![("ka", Number::dec(4, 1)), ("kd", Number::dec(6, 1))],
            asked,
        };
        let mut v = vec![
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
        ];
        v.extend(crate::msg::ShadeAsked::iter().map(shade));
        let kind = std::mem::discriminant::<S>;
        for s in S::iter() {
            assert!(v.iter().any(|x| kind(x) == kind(&s)), "no sample of {s:?}");
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

    /// Every name and line of the render summary: every variant, the
    /// frame time of one run and the median of five, and the shadings
    /// drawn named when none is per pixel.
    fn render_words(w: &dyn Words) -> Vec<String> {
        use crate::msg::{PerPixel, Summary};
        let runs = [
            Summary::FrameTime { runs: 1 },
            Summary::FrameTime { runs: 5 },
        ];
        let mut v: Vec<String> = Summary::iter().chain(runs).map(|k| w.summary(k)).collect();
        let nowhere = PerPixel::Nowhere(vec!["flat"]);
        let per_pixel = PerPixel::iter().filter(|p| !matches!(p, PerPixel::Nowhere(_)));
        v.extend(per_pixel.chain([nowhere]).map(|p| w.per_pixel(&p)));
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
