//! The mistake catalog's descriptions in English: what the student did,
//! in one line, by the mistake's code. A word table: long on purpose.

use crate::tutor::diagnose::Code;

/// The English description of a mistake.
pub(super) fn mistake(c: Code) -> &'static str {
    match c {
        Code::CrossOrder => "u = n × Vup instead of Vup × n (u, and with it v = n × u, flip sign)",
        Code::NReversed => {
            "n computed from Pr − Pe instead of Pe − Pr (the camera looks the wrong way)"
        }
        Code::NNotNormalized => {
            "n = Pe − Pr not divided by |Pe − Pr| (v = n × u then has the same length)"
        }
        Code::UNotNormalized => {
            "u = Vup × n not divided by |Vup × n| (v = n × u then has the same length)"
        }
        Code::UvSwapped => {
            "u and v swapped: the camera's x axis (right) written as its y axis (up) and the other way round (and the view matrix's rows and the eye coordinates that follow)"
        }
        Code::FovyNotHalved => "tan(fovy) used instead of tan(fovy/2) for the window",
        Code::DegreesAsRadians => "the angle in degrees given to tan as if it were radians",
        Code::HeightIsHalfExtent => {
            "the half extent near·tan(fovy/2) (the text's h) given as the window height (and aspect·h as the width)"
        }
        Code::HeightAsHalfExtent => {
            "near·tan(fovy/2) taken as the full height, so the window edges are at half the right distance"
        }
        Code::DSign => "the wrong sign of d (the projection plane z = +near instead of z = −near)",
        Code::MatrixTransposed => {
            "the view matrix written transposed (the row-vector convention P·M)"
        }
        Code::McamAsView => {
            "Mcam, the camera-to-world matrix (columns u, v, n, Pe), handed in as the view matrix V = Mcam⁻¹ (rows u, v, n and −u·Pe, −v·Pe, −n·Pe)"
        }
        Code::OutcodeReversed => {
            "outcode bits written in the wrong order (bit 1 leftmost instead of rightmost)"
        }
        Code::EndpointKept => {
            "an endpoint outside the box kept instead of the intersection that replaces it"
        }
        Code::TFromP1 => {
            "t measured from P1 instead of P0 (1 − t), and the intersection, its code and the clipped segment that follow from P(t) = P0 + t·(P1 − P0)"
        }
        Code::ReflectPlusL => "R computed as 2N(L·N) + L instead of 2N(L·N) − L",
        Code::SpecularNoMax => {
            "the specular term without max(·, 0): a negative cos β raised to the power n"
        }
        Code::PixelYFromTop => {
            "the pixel's py measured from the top edge (H − py), as an image file counts its rows, instead of from the bottom"
        }
        Code::EyeNoTranslation => {
            "the eye coordinates taken as (u·P, v·P, n·P), Peye not subtracted (the view matrix without its translation, and the projection and pixels that follow)"
        }
        Code::AspectInverted => {
            "the window's right edge taken as top / aspect instead of aspect·top (the width 2·top/aspect, and the pixels that follow)"
        }
        Code::LightNotNormalized => {
            "L not divided by |L|: cos α = L·N with the light vector as given (and R = 2N(L·N) − L, cos β and the terms that follow)"
        }
        Code::NormalNotNormalized => {
            "N not divided by |N|: cos α = L·N with the normal as given (and R, cos β and the terms that follow)"
        }
        Code::CosInRadians => {
            "the cosine of an angle in degrees taken in radian mode (cos 45 read as the cosine of 45 rad): the spot light's cos(θ/2) and cos(φ/2), and the spot factor and the terms that follow"
        }
        Code::CopiedMisprint => {
            "the value the source printed, which its errata say is wrong (see the erratum)"
        }
    }
}
