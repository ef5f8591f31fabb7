//! Where each mistake of the catalog is made: the step of the worked
//! solution to teach again. A mistake shows first in the key it spoils
//! (`normal_not_normalized` in cos α, `d_sign` in the projected points),
//! but it is made earlier, in the step that computes what the student
//! got wrong (the unit normal N, the projection plane): that step is the
//! one the class report names.

use crate::msg::{LightPart, Msg, Term};
use crate::stages::trace::Step;
use crate::tutor::diagnose::Code;

/// Whether a step's title is the one where a mistake is made.
type Made = fn(&Msg) -> bool;

/// The step where `code` is made, as a test of a step's title; None for a
/// mistake made where it shows (a misprint copied from the source: in the
/// value copied).
pub fn made_in(code: Code) -> Option<Made> {
    use Code as C;
    let made: Made = match code {
        C::CrossOrder | C::UNotNormalized | C::UvSwapped => |m| *m == Msg::CamAxisU,
        C::NReversed | C::NNotNormalized => |m| *m == Msg::CamAxisN,
        C::FovyNotHalved | C::DegreesAsRadians => |m| matches!(m, Msg::WindowTop(_)),
        C::HeightIsHalfExtent | C::HeightAsHalfExtent | C::AspectInverted => {
            |m| matches!(m, Msg::WindowEdges(_))
        }
        C::DSign => |m| *m == Msg::ProjPlane,
        C::MatrixTransposed | C::McamAsView => |m| *m == Msg::ViewMatrix,
        C::EyeNoTranslation => |m| matches!(m, Msg::EyeCoords(_)),
        C::OutcodeReversed => |m| matches!(m, Msg::OutcodeOf(_)),
        C::EndpointKept | C::TFromP1 => |m| matches!(m, Msg::Intersection(..)),
        C::ReflectPlusL => |m| matches!(m, Msg::Light(_, LightPart::Reflection)),
        C::SpecularNoMax => |m| *m == Msg::TermStep(Term::Specular),
        C::PixelYFromTop => |m| matches!(m, Msg::ViewportOf(_)),
        C::LightNotNormalized => |m| matches!(m, Msg::UnitVector(n) if n == "L"),
        C::NormalNotNormalized => |m| matches!(m, Msg::UnitVector(n) if n == "N"),
        C::CosInRadians => |m| matches!(m, Msg::Light(_, LightPart::Spot)),
        C::CopiedMisprint => return None,
    };
    Some(made)
}

/// The step (0-based, of `steps`) where `code` is made: the first whose
/// title is the one of [`made_in`].
pub fn step_made(code: Code, steps: &[Step]) -> Option<usize> {
    let made = made_in(code)?;
    steps.iter().position(|s| made(&s.title))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;
    use crate::num::Real;
    use crate::report::lang::Lang;
    use crate::report::words;

    /// The steps of the problems of the text the catalog is tried on.
    fn steps(file: &str) -> Vec<Step> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("problems")
            .join(file);
        let p = ProblemIn::read(&path).expect("a shipped problem");
        crate::tutor::solve::solve::<Real>(&p)
            .expect("solves")
            .steps
    }

    #[test]
    fn every_mistake_is_taught_at_the_step_where_it_is_made() {
        let problems = [
            "text-triangle.toml",
            "text-clip.toml",
            "shade-phong.toml",
            "shade-spot-inside.toml",
        ];
        let all: Vec<Vec<Step>> = problems.iter().map(|f| steps(f)).collect();
        for code in Code::all() {
            let Some(made) = made_in(code) else {
                assert_eq!(code, Code::CopiedMisprint, "{code:?} names no step");
                continue;
            };
            assert!(
                all.iter().flatten().any(|s| made(&s.title)),
                "{code:?}: no step of the text's problems is where it is made"
            );
        }
        // the two the issue names, by the text's own words
        let title = |code: Code, file: &str| {
            let steps = steps(file);
            let i = step_made(code, &steps).expect("a step");
            words::words(&steps[i].title, Lang::Id)
        };
        assert_eq!(
            title(Code::NormalNotNormalized, "shade-phong.toml"),
            "Vektor satuan N"
        );
        assert_eq!(title(Code::DSign, "text-triangle.toml"), "Bidang proyeksi");
        assert_eq!(
            title(Code::LightNotNormalized, "shade-phong.toml"),
            "Vektor satuan L"
        );
    }
}
