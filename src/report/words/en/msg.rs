//! The messages' own words in English ([`Msg`]): one exhaustive match over
//! every key, the helpers' words (what is asked, how a printed answer
//! compares, the terms and the steps of a light) and the English number
//! style, `0.5` and `(0.5, 2, 3)`.

use super::En;
use crate::input::ask::Part;
use crate::msg::{Erratum, Implausible, LightPart, Msg, Printed, SpotZone, Term, Trivial};
use crate::report::lang::NumStyle;
use crate::report::words::errors::ErrorWords;
use crate::report::words::keys::{text_plane, KeyWords};
use crate::report::words::msg::{self, MsgWords};
use crate::report::words::{DrawnWords, FigureWords, PixelWords, SaidWords};
use crate::tutor::key::Plane;

impl MsgWords for En {
    /// A word table: long on purpose.
    fn msg_in(&self, m: &Msg, nums: NumStyle) -> String {
        match m {
            Msg::Math(s) => s.clone(),
            Msg::Written(en, _) => en.clone(),
            Msg::Erratum(kind, why) => msg::erratum(self, *kind, why),
            Msg::Printed(p) => self.printed(*p).into(),
            Msg::Asked(parts) => msg::asked(self, parts),
            Msg::DrawnTitle(t) => self.drawn_title(*t).into(),
            Msg::Pixel(p) => self.pixel(p),
            Msg::Statement(s) => self.statement(s, nums),
            Msg::Figure(f) => self.figure(f),
            Msg::At(place, m) => msg::at(self, place, m),
            Msg::Err(e) => self.error(e),
            Msg::Said(s) => self.said(s, nums),
            Msg::SecModeling => "Stage 1: modeling transformation".into(),
            Msg::SecViewing => "Stage 2: viewing transformation (world → eye coordinates)".into(),
            Msg::SecProjection => "Stage 3: projection onto the near plane".into(),
            Msg::SecWindowClip => "Stage 4: window and clipping".into(),
            Msg::SecWindow => "Stage 4: viewing window".into(),
            Msg::SecViewport => "Viewport mapping (window → pixels)".into(),
            Msg::SecLineClip(None) => "Line clipping".into(),
            Msg::SecLineClip(Some(i)) => format!("Line clipping, segment {i}"),
            Msg::SecLighting => "Lighting".into(),
            Msg::SecPixel(x, y) => format!("Pixel ({x}, {y})"),
            Msg::SecLightFace => "Lighting of the face (lighting::shade)".into(),
            Msg::SecLightVertex(n) => format!("Lighting of vertex {n} (lighting::shade)"),
            Msg::SecLightPixel => "Lighting of the pixel (lighting::shade)".into(),
            Msg::CamAxisN => "Camera axis n (points from the look-at point back to the eye)".into(),
            Msg::CamAxisU => "Camera axis u (to the right)".into(),
            Msg::CamAxisV => "Camera axis v (up in the picture)".into(),
            Msg::CamCheck => "Check: u, v, n are orthonormal and right-handed".into(),
            Msg::CamMatrix => "Camera matrix Mcam (camera to world)".into(),
            Msg::ViewMatrix => "View matrix V = Mcam⁻¹ (world to eye): rotation (rows u, v, n) times translation by −Pe".into(),
            Msg::EyeCoords(n) => format!("Eye coordinates of {n}"),
            Msg::OrthoProj(n) => format!("Orthographic projection of {n}"),
            Msg::PerspProj(n) => format!("Perspective projection of {n}"),
            // the text's h is the near window's half-height; the far one has no name there
            Msg::WindowTop(l) if l == "near" => format!("Window half-height on the {l} plane (the text calls it h)"),
            Msg::WindowTop(l) => format!("Window half-height on the {l} plane"),
            Msg::WindowEdges(l) => format!("Window edges and size on the {l} plane"),
            Msg::ViewportOf(n) => format!("Viewport coordinates of {n}"),
            Msg::OutcodeOf(n) => format!("Outcode of {n}"),
            Msg::TrivialTests => "Trivial tests".into(),
            Msg::Intersection(i, plane) => {
                let p = Plane::ALL[*i % 6];
                format!("Intersection with the {} ({}) plane {plane}", text_plane(p), self.plane(p))
            }
            Msg::ClippedSegment => "Clipped segment".into(),
            Msg::LiangBarsky => "Cross-check by Liang–Barsky".into(),
            Msg::MethodsAgree => "Do the two methods agree?".into(),
            Msg::NothingToDo => "Nothing to do".into(),
            Msg::ProjPlane => "Projection plane".into(),
            Msg::InsideVolume(n) => format!("Is {n}'' inside the view volume?"),
            Msg::UnitVector(n) => format!("Unit vector {n}"),
            Msg::ViewerLocal => "Viewer direction (local viewer)".into(),
            Msg::Material => "Material and model".into(),
            Msg::Light((i, n), part) => match *n > 1 {
                true => format!("Light {}: {}", i + 1, self.light_part(*part)),
                false => msg::capitalised(self.light_part(*part)),
            },
            Msg::TermStep(t) => format!("{} term, per channel", msg::capitalised(self.term(*t))),
            Msg::SumOfTerms => "Sum of the terms".into(),
            Msg::Clamp => "Clamp each channel to [0, 1]".into(),
            Msg::WhichTriangle => "Which triangle covers the pixel".into(),
            Msg::Depth => "Depth at the pixel (z-buffer)".into(),
            Msg::Barycentric => "Barycentric coordinates".into(),
            Msg::FlatShading => "Flat shading: one colour per face".into(),
            Msg::Gouraud => "Gouraud: interpolate the vertex colours".into(),
            Msg::PhongShading => "Phong shading: interpolate normal, position and colour".into(),
            Msg::PixelColour => "Pixel colour".into(),
            Msg::FOutOfRange => "d² = |Pl − P|² > range²  ⇒  the light is not evaluated".into(),
            Msg::FIncidence => "cos α = Lx·Nx + Ly·Ny + Lz·Nz,  then max(cos α, 0)".into(),
            Msg::FCamMatrix => "Mcam = T(Pe) · [u v n]   (columns u, v, n, Pe)".into(),
            Msg::FViewMatrix => "V = R · T(−Pe),  R = [uᵀ; vᵀ; nᵀ],  last column (−u·Pe, −v·Pe, −n·Pe)".into(),
            Msg::FTrivial => "both codes 000000 → accept;  code0 AND code1 ≠ 000000 → reject;  otherwise clip".into(),
            Msg::FOutcode => "bit 1 x<xmin (left) · bit 2 x>xmax (right) · bit 3 y<ymin (bottom) · bit 4 y>ymax (top) · bit 5 z<zmin (front) · bit 6 z>zmax (back); the code is written bit 6 … bit 1 (bit 1 rightmost)".into(),
            Msg::FSegment => "from the kept point with the smallest t to the one with the largest t (inside ends count as t = 0 and t = 1)".into(),
            Msg::FMethods => "outcode clipping against Liang–Barsky".into(),
            Msg::FProjPlane => "z = d,  d = −near (the camera looks along −z in eye coordinates)".into(),
            Msg::FPixelCentre => "pixel centre (x + ½, y + ½) inside a triangle, nearest wins".into(),
            Msg::FEdges => "edge functions E₀, E₁, E₂ ≥ 0 at the centre (top-left rule on edges); nearest depth wins".into(),
            Msg::FDepth => "z = λ₀z₀ + λ₁z₁ + λ₂z₂ (z/w is linear on the screen); smaller is nearer".into(),
            Msg::FBarycentric => "λₖ = Eₖ(centre)/area on the screen;  perspective-correct μₖ = (λₖ/wₖ) / Σ λₘ/wₘ".into(),
            Msg::FFlat => "colour = lighting::shade(face normal N, face centre)".into(),
            Msg::FWindowEdges => "right = aspect·top,  bottom = −top,  left = −right,  height = 2·top,  width = 2·right".into(),
            Msg::FLiangBarsky => "p = −Δx, Δx, −Δy, Δy, −Δz, Δz and q = x0 − xmin, xmax − x0, y0 − ymin, ymax − y0, z0 − zmin, zmax − z0 at the planes x = xmin … z = zmax;  t0 = max(0, q/p where p < 0) (planes entered),  t1 = min(1, q/p where p > 0) (planes left);  p = 0 with q < 0: outside;  visible if t0 ≤ t1, from P0 + t0·Δ to P0 + t1·Δ".into(),
            Msg::FInside => "left ≤ xp ≤ right,  bottom ≤ yp ≤ top,  and −far ≤ z' ≤ −near".into(),
            Msg::FSpot => "ρ = (−L)·axis;  Spot = 1 if ρ ≥ cos(θ/2), 0 if ρ ≤ cos(φ/2), else ((ρ − cos(φ/2))/(cos(θ/2) − cos(φ/2)))^falloff".into(),
            Msg::FClamp => "color = min(max(C, 0), 1)".into(),
            Msg::FByte => "8-bit value = round(255 · clamp(C, 0, 1))".into(),
            Msg::AlreadyUnit => "already a unit vector".into(),
            Msg::Saturates => "a channel went past 1 (or below 0) and is clamped: the highlight saturates".into(),
            Msg::InRange => "every channel is already in [0, 1]".into(),
            Msg::NoTermInModel(model, t) => {
                let model = crate::report::words::report::model_name(model);
                format!("the {model} model has no {} term", self.term(*t))
            }
            Msg::TextSetting => "the text's single white light and no global ambient: the sum is 1·(the text's factor)".into(),
            Msg::TextTerm(Term::Ambient) => "the text's Ia = Is·ka, with the light's intensity Is = 1 (its one white light), on the surface colour Cs".into(),
            Msg::TextTerm(Term::Diffuse) => "the text's Id = Is·kd·MAX(cos α, 0), with Is = 1, on the surface colour Cs".into(),
            Msg::TextTerm(Term::Specular) => "the text's Isp = Is·ksp·MAX(cosⁿ β, 0) (its ksp is ks), with Is = 1, in the specular colour Cwhite".into(),
            Msg::SummedInRange => "summed over the lights in range".into(),
            Msg::SpecularSkipped => "the specular term is skipped (ks = 0 or --specular off)".into(),
            Msg::BeyondRange => "beyond its range a light adds nothing, not even ambient".into(),
            Msg::WithinRange => "within range".into(),
            Msg::NoRange => "no range limit".into(),
            Msg::Behind(true) => "cos α < 0: the light is behind the surface — no diffuse, and (--specular-requires-lit) no specular".into(),
            Msg::Behind(false) => "cos α < 0: the light is behind the surface — no diffuse; the text's code still computes R and adds the specular term (use --specular-requires-lit for the usual rule)".into(),
            Msg::LocalViewer => "local viewer (D3DRS_LOCALVIEWER = TRUE): V points from the vertex to the camera".into(),
            Msg::NoLocalViewer => "no local viewer: the Direct3D page writes (0,0,1) for the viewer. That is right in grafika's right-handed eye space, where the viewer lies along +z; Direct3D's own camera space is left-handed and puts the viewer along −z, so read the page's (0,0,1) as \"toward the viewer\". grafika uses your V (default (0,0,1))".into(),
            Msg::ShininessZero => "n = 0: x⁰ = 1 for every direction (0⁰ taken as 1) — the highlight covers the whole surface".into(),
            Msg::SpecularOff => "the specular term is off for this model / setting (ks = 0, --specular off, or a model without it)".into(),
            Msg::NoHighlightBehind => "cos α ≤ 0 and --specular-requires-lit: no highlight from a light behind the surface".into(),
            Msg::SpotIn(SpotZone::Inner) => "inside the inner cone (ρ ≥ cos(θ/2)): full light".into(),
            Msg::SpotIn(SpotZone::Outer) => "outside the outer cone (ρ ≤ cos(φ/2)): no light".into(),
            Msg::SpotIn(SpotZone::Penumbra) => "in the penumbra: between the cones".into(),
            Msg::BehindCentre => "behind the centre of projection: projected, but inverted and not visible".into(),
            Msg::TextH => "the text's h is this half extent; the full window height is 2·top".into(),
            Msg::Orthonormal(true) => "orthonormal and right-handed".into(),
            Msg::Orthonormal(false) => "NOT orthonormal: check the inputs".into(),
            Msg::TrivialNote(Trivial::Accept) => "both ends inside: accepted whole".into(),
            Msg::TrivialNote(Trivial::Reject) => "both ends outside the same plane: rejected".into(),
            Msg::TrivialNote(Trivial::Clip) => "neither test decides: intersect with the planes the ends violate".into(),
            Msg::Kept(true) => "code 000000: kept".into(),
            Msg::Kept(false) => "code not 000000: outside the box, discarded".into(),
            Msg::TouchesPoint => "the segment touches the box in a single point".into(),
            Msg::InsidePart => "the part of P0P1 inside the box".into(),
            Msg::Misses => "no intersection is inside the box: the segment misses it (rejected)".into(),
            Msg::DefaultView => "not given: the text's viewVector (0, 0, 1), a viewer far along +z".into(),
            Msg::MaterialD3d => "Direct3D material: its colors carry the coefficients, so ka = kd = ks = 1".into(),
            Msg::MaterialText => format!("the text's constants unless given: {}", msg::material_text(nums, "", "white specular")),
            Msg::NoTriangle => "no triangle covers the pixel centre: it keeps the background colour".into(),
            Msg::Nearest => "the nearest of all triangles covering this pixel".into(),
            Msg::Agree(true) => "both methods give the same segment".into(),
            Msg::Agree(false) => "the methods disagree: please report this input".into(),
            Msg::AlreadyWorld => "the objects are already given in world coordinates".into(),
            Msg::Inside(true, true) => "inside: not clipped".into(),
            Msg::Inside(false, _) => "outside the window: clipped".into(),
            Msg::Inside(true, false) => "outside the near/far planes: clipped".into(),
            Msg::ErrSamePoint(p) => format!("the eye Pe and the look-at point Pr are the same point {}", nums.shortest3(*p)),
            Msg::ErrUpZero => "the up vector Vup is the zero vector".into(),
            Msg::ErrUpParallel(up, d) => format!("the up vector Vup = {} is parallel to the view direction Pe − Pr = {}, so Vup × n = 0 and u is undefined", nums.shortest3(*up), nums.shortest3(*d)),
            Msg::ErrFovy(v) => format!("must be between 0° and 180° (exclusive), got {}°", nums.shortest(*v)),
            Msg::ErrAspect(v) => format!("must be positive (width/height), got {}", msg::given(*v, nums)),
            Msg::ErrNear(v) => format!("must be positive (a distance in front of the eye), got {}", msg::given(*v, nums)),
            Msg::ErrCopPlane(p, None) => format!("{p} has z = 0: it lies in the plane of the centre of projection and has no image"),
            Msg::ErrCopPlane(p, Some(z)) => format!("{p} has z = zprp = {}: it lies in the plane of the centre of projection and has no image", nums.shortest(*z)),
            Msg::ErrUnknownPoint(p, None) => format!("unknown point `{p}`: the problem has no [points]"),
            Msg::ErrUnknownPoint(p, Some(known)) => format!("unknown point `{p}`; the points are {known}"),
            Msg::ErrBoxInverted(a, lo, hi) => format!("{a}min = {} is greater than {a}max = {}", nums.shortest(*lo), nums.shortest(*hi)),
            Msg::ErrCannotRead(path, why) => format!("cannot read {path}: {}", self.io_why(why)),
            Msg::ErrZeroUnit(v) => format!("{v} is the zero vector (0, 0, 0): it has no direction, so it cannot be made a unit vector"),
            Msg::ErrNamedPoint(t) => format!("`{t}`: expected NAME=X,Y,Z, e.g. A=0,0,0"),
            Msg::ErrPointName(t) => format!("`{t}` is not a point name (letters, digits, _ and ')"),
            Msg::ErrPointTwice(t) => format!("point {t} is given twice"),
            Msg::ErrNamedPair(t) => format!("`{t}`: expected NAME=X,Y (two numbers)"),
            Msg::ErrSize(t) => format!("`{t}`: expected WIDTHxHEIGHT, e.g. 200x100"),
            Msg::ErrCopNeedsPlane => "--cop needs --plane (the view plane z = ZVP)".into(),
            Msg::ErrPlaneNeedsCop => "--plane needs --cop (the centre of projection z = ZPRP)".into(),
            Msg::ErrChooseProjection => "choose one projection: --d D, or --cop ZPRP --plane ZVP, or --ortho".into(),
            Msg::ErrPointNeedsViewport => "--point needs --viewport WxH to map points to pixels".into(),
            Msg::ExpectOne => "expected one number".into(),
            Msg::ExpectList(n) => format!("expected a list of {n} values"),
            Msg::CountMismatch(n, k) => format!("expected {n} values, got {k}"),
            Msg::ExpectedNone => "expected none (nothing is left)".into(),
            Msg::ExpectedBool(b) => format!("expected {}", if *b { "yes" } else { "no" }),
            Msg::SeveralAnswers => "this key holds several answers: give them one by one".into(),
            Msg::EmptyAnswer => "empty answer".into(),
            Msg::NoAnswer => "no answer given".into(),
            Msg::AnswerTooLong(n, max) => format!("the answer has {n} characters; at most {max} are read"),
            Msg::WithinPixel => "within half a pixel".into(),
            Msg::NotAnOutcode(t) => format!("`{t}` is not an outcode: write six binary digits, bit 1 rightmost (001000)"),
            Msg::NotAStatus(t) => format!("`{t}` is not a status: write accepted, rejected or clipped"),
            Msg::NotYesOrNo(t) => format!("`{t}` is not yes or no: write yes or no (ya or tidak)"),
            Msg::AmbiguousCommas => "commas here are both decimal marks and separators, so the numbers cannot be told apart: write 0,7071; 0; 0,7071 (decimal commas, parts separated by ;) or 0.7071, 0, 0.7071".into(),
            Msg::FollowThrough => "right given the earlier answers (follow-through)".into(),
            Msg::NoFollowFrom(a, why, b) => {
                let name = |k: &str| crate::report::words::keys::name_of(self, k);
                let (a, b) = (name(a), name(b));
                let not = match why {
                    Implausible::NotUnit => format!("{a} is not a unit vector"),
                    Implausible::NotPerpendicular(o) => format!("{a} is not perpendicular to {}", name(o)),
                    Implausible::OffSegment => format!("{a} is not on the segment P0P1"),
                    Implausible::NotACosine => format!("{a} is not a cosine (it lies outside −1 to 1)"),
                    Implausible::NotAColour => format!("{a} is not a colour (a channel lies outside 0 to 1)"),
                    Implausible::Negative => format!("{a} is negative"),
                    Implausible::NotPositive => format!("{a} is not positive"),
                    Implausible::NotNegative => format!("{a} is not negative"),
                };
                format!("{not}, so {b} can't follow from it (no follow-through)")
            }
            Msg::Exact => "exact".into(),
            Msg::Rounded(s) => format!("rounded to {s} significant figures"),
            Msg::RoundedCoarse(s, need) => format!(
                "rounded to {s} significant figure{}, at least {need} required",
                if *s == 1 { "" } else { "s" }
            ),
            Msg::UpParallel(a) => format!(
                "the up vector is nearly parallel to the view direction (angle {} rad): u and v are very sensitive to the inputs",
                msg::exponent(nums, *a)
            ),
            Msg::BehindWarn(n) => format!("{n} is behind the centre of projection: its image is inverted and it cannot be seen"),
            Msg::NoFigure => "no figure was written: no part asked has a figure of its own (the pixels of `viewport` are drawn on the window's figure: ask `window` with it)".into(),
            Msg::ExactTooLarge(n) => format!("exact values that would hold more than {n} terms (many different square roots) were computed in f64 and are marked ≈, as is what follows from them"),
            Msg::ErrFewDistinct { topic, level, problem, found, asked, all } => format!(
                "problem {problem} ({topic}, {level}) can have only {found} different variant{}{}, not the {asked} asked (no problem is stated twice in an exam): ask for fewer (--variants, --count) or another --difficulty",
                if *found == 1 { "" } else { "s" },
                if *all { " (every problem of its kind was tried)" } else { " (found in 200,000 tries)" }
            ),
            Msg::ExactTooLong(bits) => format!("exact values whose numerator or denominator would pass {bits} bits (a high power, such as a large shininess) were computed in f64 and are marked ≈, as is what follows from them"),
            Msg::StaleTempRemoved(p, pid) => format!("removed {p}, a temporary file left by grafika process {pid}, which is no longer running (it was stopped before it could clean up)"),
            Msg::ErrHtmlCommand => "writes the worked solution of basis, view, project, window, clip, shade, solve and render; for exams use generate --format html".into(),
            Msg::Parts(parts) => msg::parts(self, parts),
            Msg::Expected(v) => format!("expected {}", nums.expect(v)),
            Msg::Unreadable(why) => format!("cannot be read: {}", self.number(why)),
            Msg::WithinPct(p) => format!("within {}%", nums.dec(*p, 3)),
        }
    }

    fn nums(&self) -> NumStyle {
        NumStyle::POINT
    }

    fn printed(&self, p: Printed) -> &'static str {
        match p {
            Printed::Agrees => "agrees",
            Printed::Differs(None) => "the printed answer is wrong",
            Printed::Differs(Some(Erratum::Misprint)) => "a misprint in the text",
            Printed::Differs(Some(Erratum::Convention)) => "the text uses another convention",
            Printed::Differs(Some(Erratum::Rounding)) => "a rounding error in the text",
            Printed::NotAsked => "not computed in this run (not asked for)",
            Printed::NotComparable => "cannot be compared",
        }
    }

    fn asked_heading(&self) -> &'static str {
        "Asked"
    }

    fn asked_part(&self, part: Part) -> &'static str {
        match part {
            Part::View => "the camera basis u, v, n, the view matrix and the eye coordinates of the points",
            Part::Project => "their projections onto the near plane",
            Part::Window => "the viewing window on the near plane (its edges, width and height) and which projected points lie inside the view volume",
            Part::Viewport => "the pixel of each point in the viewport",
            Part::Clip => "the region codes of the ends and the result of clipping the segment",
            Part::Shade => "the colour at the point, term by term",
        }
    }

    fn cut(&self, n: usize) -> String {
        format!("({n} characters cut)")
    }

    fn term(&self, t: Term) -> &'static str {
        match t {
            Term::Ambient => "ambient",
            Term::Diffuse => "diffuse",
            Term::Specular => "specular",
        }
    }

    fn light_part(&self, p: LightPart) -> &'static str {
        match p {
            LightPart::OutOfRange => "out of range",
            LightPart::Direction => "direction to the light",
            LightPart::Attenuation => "attenuation",
            LightPart::Incidence => "angle of incidence: cos α = L·N",
            LightPart::Reflection => "reflection R and cos β",
            LightPart::HalfVector => "half vector H and N·H (Blinn)",
            LightPart::Highlight => "highlight",
            LightPart::Spot => "spot factor",
        }
    }
}
