//! The figures' words in English: panel titles and
//! descriptions (captions and screen readers) and the words inside the
//! figures.

use super::En;
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::words::keys::KeyWords;
use crate::report::words::{figure, FigureWords};
use crate::tutor::key::Plane;

impl FigureWords for En {
    fn figure(&self, m: &FigureMsg) -> String {
        match m {
            FigureMsg::Title(Panel::ShadeLight(k)) => format!(
                "Light {k}: the plane of N and {}",
                figure::light_name(*k)
            ),
            FigureMsg::Title(p) => title(*p).into(),
            FigureMsg::Desc(p) => desc(*p).into(),
            FigureMsg::Word(w) => word(*w).into(),
            FigureMsg::View { from, az, el } => format!(
                "Axonometric view (orthographic), seen from the direction {from} (azimuth {az}°, elevation {el}°), y up."
            ),
            FigureMsg::OffPlane(name, deg) => format!(
                "{name} is not in this plane (it leaves it by {deg}°): drawn in its own plane below"
            ),
            FigureMsg::Plane(bit, eq) => {
                let name = self.plane(Plane::ALL[(*bit).min(5)]);
                match eq {
                    Some(eq) => format!("{eq} ({name})"),
                    None => name.into(),
                }
            }
            FigureMsg::OutOfRange(k) => format!(
                "light {k} is out of range: it does not light the point and is not drawn"
            ),
            FigureMsg::Rejected(and) => format!(
                "code0 AND code1 = {and} ≠ 000000: the segment lies outside, rejected with no intersection tried"
            ),
        }
    }
}

/// A panel's title. A word table: long on purpose.
fn title(p: Panel) -> &'static str {
    match p {
        Panel::Camera => "The camera in world coordinates",
        Panel::Projection => "Projection onto the view plane",
        Panel::ProjectionSide => "Side view (y–z): similar triangles",
        Panel::ViewPlane => "The images on the view plane (x–y)",
        Panel::Frustum => "The view volume, seen from outside",
        Panel::WindowSide => "Side view (y–z): fovy and top",
        Panel::NearWindow => "The viewing window on the near plane",
        Panel::Viewport => "The viewport (pixels, origin bottom left)",
        Panel::Clip => "Clipping P0P1 against the box",
        Panel::ClipAlong => "Along the segment: P(t) = P0 + t·(P1 − P0)",
        Panel::Shade | Panel::ShadeLight(_) => {
            "Lighting in the plane of incidence (the plane of N and L)"
        }
        Panel::ShadeRV => "The plane of R and V (β)",
        Panel::ShadeNH => "The plane of N and H (N·H)",
    }
}

/// A panel's description. A word table: long on purpose.
fn desc(p: Panel) -> &'static str {
    match p {
        Panel::Camera => "Black arrows: the world axes x, y, z. Blue dots: Peye and Pref, joined by the dotted line of sight. Sky-blue arrow: Vup, drawn at Pref. The camera axes u, v, n at Peye: green solid, purple dash-dot and vermillion dashed arrows, drawn twice the length of Vup (the note under the drawing states the length); the view is chosen so that they are at least 15° apart and none is drawn shorter than 40 % of the longest. Black dots: the named points; the notes give their eye coordinates.",
        Panel::Projection => "Eye coordinates; the centre of projection is outside the view plane in this view. Sky-blue rectangle: the view plane. Dotted orange lines: the projectors from the centre of projection (parallel to z when orthographic) through each point (black dot) to its image (blue dot).",
        Panel::ProjectionSide => "Side view: −z to the right, y up. The sky-blue line is the view plane; each projector (dotted) runs from the centre of projection through the point to its image. The black leg y of the point and the blue leg yp of the image make two similar triangles with the z axis.",
        Panel::ViewPlane => "The view plane seen from the front: xp to the right, yp up; each blue dot is a point's image.",
        Panel::Frustum => "Eye space, the eye at the origin looking along −z, seen from outside: the eye is the apex of the view volume, outside its windows. Blue rectangle: the near window (left..right × bottom..top at z = −near); sky-blue rectangle: the far window; black lines: the edges of the view volume. The windows are drawn to scale; when far is not given or more than 10 times near, the far window is not drawn: the edges run on, dashed vermillion, to twice near.",
        Panel::WindowSide => "Side view: −z to the right, y up. The eye at the origin; the purple arc is the angle fovy; the blue line is the near window from bottom to top, at distance near.",
        Panel::NearWindow => "The viewing window on the near plane: x to the right, y up; the black dots are the projected points.",
        Panel::Viewport => "The viewport W × H in pixels, origin at the bottom left; each blue dot is a point at its pixel position.",
        Panel::Clip => "Drawn as the text reads the box's planes: x to the right, y up and z away from the reader, so the front face (z = zmin) is toward the reader and the back face (z = zmax) away from them (a mirror image of right-handed axes, seen from the −z side given above). The box, its hidden edges dashed, with its six planes named by their equations and the text's words (left x = xmin, right x = xmax, bottom y = ymin, top y = ymax, front z = zmin, back z = zmax, as the text's bits count them); P0 and P1 with their outcodes. The kept part is solid blue, the cut-off parts dashed vermillion; each intersection tried is a dot named by its plane (blue when it bounds the kept part, with its coordinates; orange when it lies outside the box).",
        Panel::ClipAlong => "The segment drawn straight, t from 0 (P0, top) to 1 (P1, bottom): each intersection tried at its t, with its plane, its point P(t) and its outcode; the kept part solid blue, the cut-off parts dashed vermillion.",
        Panel::Shade | Panel::ShadeLight(_) => "A flat diagram in the plane of N and L (the plane of incidence), at true angles: the surface is a line (hatched on the object's side) with N straight up, L toward the light on the left, R its mirror image about N, and V toward the viewer and H the half vector (Blinn) where they lie in this plane; every unit vector drawn with one length. Arcs mark α between L and N and β between R and V at their true size. N black, L sky blue, R purple dash-dot, V green, H orange dotted.",
        Panel::ShadeRV => "V leaves the plane of incidence, so R and V are drawn in their own plane, R straight up, at their true angle β.",
        Panel::ShadeNH => "H leaves the plane of incidence, so N and H are drawn in their own plane, N straight up, at their true angle (N·H is its cosine).",
    }
}

/// A word inside a figure.
fn word(w: FigWord) -> &'static str {
    match w {
        FigWord::Cop => "centre of projection",
        FigWord::Eye => "eye",
        FigWord::NotToScale => "far window too far to draw to scale",
        FigWord::Surface => "surface",
        FigWord::CameraAxes => "u green, v purple dash-dot, n vermillion dashed; length",
        FigWord::Zoomed => "inset: the view plane near the centre of projection, enlarged",
        FigWord::Coincide => "coincide; drawn side by side",
        FigWord::Outcode => "outcode",
        FigWord::Kept => "kept",
        FigWord::CutOff => "cut off",
        FigWord::AngleNH => "angle(N, H)",
        FigWord::Accepted => "both codes are 000000: the segment lies inside, accepted whole",
        FigWord::Missed => "no intersection tried is in the box: the segment misses it, rejected",
    }
}
