//! The view a 3D panel is drawn in: an axonometric view (an orthographic
//! projection onto a plane seen from a direction w), with the y axis drawn
//! straight up. Each figure chooses its own direction by a small search
//! ([`Axo::choose`]) so that what it must show reads (the camera axes
//! apart and none foreshortened, the eye outside the near window, …), as
//! near as possible to the usual textbook view (x to the right, z toward
//! the reader down to the left); the panel's description states it.
//!
//! With w = (cos el · sin az, sin el, cos el · cos az) toward the viewer,
//! the page axes are right = norm(y × w) = (cos az, 0, −sin az) and
//! up = w × right, and a point p is drawn at (p·right, p·up).

/// The usual view of world space: azimuth 35°, elevation 25° (degrees):
/// x to the right, z toward the reader down to the left.
pub const USUAL: (f64, f64) = (35.0, 25.0);

/// The usual view of eye space: azimuth 65°, elevation 15°: the eye on
/// the left looking along −z to the right, as the text draws a frustum.
pub const USUAL_EYE: (f64, f64) = (65.0, 15.0);

/// An axonometric view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axo {
    /// Azimuth of w about the y axis from +z toward +x, degrees.
    pub az: f64,
    /// Elevation of w above the x–z plane, degrees.
    pub el: f64,
    right: [f64; 3],
    up: [f64; 3],
    w: [f64; 3],
    /// Whether z is drawn mirrored (away from the viewer where the view
    /// would draw it toward them): the clip box as the text's front
    /// (z < zmin) and back (z > zmax) read.
    mirror: bool,
}

impl Axo {
    /// The view from azimuth `az` and elevation `el` (degrees).
    pub fn new(az: f64, el: f64) -> Axo {
        let (sa, ca) = az.to_radians().sin_cos();
        let (se, ce) = el.to_radians().sin_cos();
        Axo {
            az,
            el,
            right: [ca, 0.0, -sa],
            up: [-se * sa, ce, -se * ca],
            w: [ce * sa, se, ce * ca],
            mirror: false,
        }
    }
    /// The same view of the world mirrored in z (z drawn away from the
    /// viewer): a point p is drawn where the view draws (x, y, −z), and
    /// the viewer stands on the −z side. The text's clipping box reads so:
    /// x to the right, y up, z away, its front face z = zmin toward the
    /// reader (a left-handed drawing, as the text's region codes are).
    pub fn mirrored(self) -> Axo {
        Axo {
            mirror: true,
            ..self
        }
    }
    /// p, mirrored in z when the view is.
    fn seen(&self, p: [f64; 3]) -> [f64; 3] {
        if self.mirror {
            [p[0], p[1], -p[2]]
        } else {
            p
        }
    }
    /// The usual view ([`USUAL`]).
    pub fn usual() -> Axo {
        Axo::new(USUAL.0, USUAL.1)
    }
    /// A 3D point on the page: (p·right, p·up).
    pub fn page(&self, p: [f64; 3]) -> [f64; 2] {
        let p = self.seen(p);
        [dot(p, self.right), dot(p, self.up)]
    }
    /// How near a point is to the viewer (p·w): of two points on one page
    /// spot, the one with the larger depth is in front.
    pub fn depth(&self, p: [f64; 3]) -> f64 {
        dot(self.seen(p), self.w)
    }
    /// The unit direction w from the scene toward the viewer (in world
    /// coordinates: on the −z side for a mirrored view).
    pub fn toward(&self) -> [f64; 3] {
        self.seen(self.w)
    }
    /// Whether z is drawn mirrored ([`Axo::mirrored`]).
    pub fn is_mirrored(&self) -> bool {
        self.mirror
    }
    /// The view of the least cost among azimuths every 5° and elevations
    /// from −30° to 60° every 5°: `quality` is at least 1 for a view that
    /// shows what it must (more is better, up to 1.5), and each degree
    /// away from the view `usual` (azimuth, elevation) costs 0.004.
    pub fn choose(usual: (f64, f64), quality: impl Fn(&Axo) -> f64) -> Axo {
        Axo::choose_in(usual, false, quality)
    }
    /// As [`Axo::choose`], among mirrored views when `mirror`.
    pub fn choose_in(usual: (f64, f64), mirror: bool, quality: impl Fn(&Axo) -> f64) -> Axo {
        let usual = Axo::new(usual.0, usual.1);
        let mut best = (f64::MIN, usual);
        for el in (-6..=12).map(|k| 5.0 * f64::from(k)) {
            for az in (-36..36).map(|k| 5.0 * f64::from(k)) {
                let a = Axo {
                    mirror,
                    ..Axo::new(az, el)
                };
                let away = dot(a.w, usual.w).clamp(-1.0, 1.0).acos().to_degrees();
                let score = quality(&a).min(1.5) - 0.004 * away;
                if score > best.0 + 1e-12 {
                    best = (score, a);
                }
            }
        }
        best.1
    }
    /// How well the directions `ds` read from their common tail: at least
    /// 15° apart on the page and none drawn shorter than 40 % of the
    /// longest give 1 or more (the smaller of angle/15° and ratio/0.4).
    pub fn readable(&self, ds: &[[f64; 3]]) -> f64 {
        let p: Vec<[f64; 2]> = ds.iter().map(|d| self.page(*d)).collect();
        let len = |q: &[f64; 2]| q[0].hypot(q[1]);
        let longest = p.iter().map(len).fold(0.0, f64::max).max(1e-300);
        let shortest = p.iter().map(len).fold(f64::MAX, f64::min);
        let mut q = shortest / longest / 0.4;
        for i in 0..p.iter().len() {
            for j in 0..i {
                q = q.min(page_angle(p[i], p[j]) / 15.0);
            }
        }
        q
    }
}

/// The view of an eye-space panel: the eye (or the centre of projection)
/// `apex`, when there is one, outside each window drawn, by at least 15 %
/// of the window's size on the page; each window seen at no less than
/// 30 % of its area (|w·z| ≥ 0.3) and the depth axis z drawn at no less
/// than 40 % of its length.
pub fn apex_outside(apex: Option<[f64; 3]>, windows: &[Vec<[f64; 3]>]) -> Axo {
    Axo::choose(USUAL_EYE, |a| {
        let wz = a.toward()[2].abs();
        let mut q = (wz / 0.3).min((1.0 - wz * wz).sqrt() / 0.4);
        if let Some(e) = apex {
            for win in windows {
                let poly: Vec<[f64; 2]> = win.iter().map(|c| a.page(*c)).collect();
                let size = diameter(&poly).max(1e-300);
                q = q.min(outside_by(a.page(e), &poly) / size / 0.15);
            }
        }
        q
    })
}

/// The angle between two page directions, degrees (0 to 180).
pub fn page_angle(a: [f64; 2], b: [f64; 2]) -> f64 {
    let c = (a[0] * b[0] + a[1] * b[1]) / (a[0].hypot(a[1]) * b[0].hypot(b[1])).max(1e-300);
    c.clamp(-1.0, 1.0).acos().to_degrees()
}

/// The distance from page point p to the convex polygon `poly` (0 when
/// inside).
pub fn outside_by(p: [f64; 2], poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    let mut inside = n >= 3;
    let mut sign = 0.0;
    let mut d = f64::MAX;
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let c = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        if c != 0.0 {
            if sign != 0.0 && c.signum() != sign {
                inside = false;
            }
            sign = c.signum();
        }
        d = d.min(to_segment(p, a, b));
    }
    if inside {
        0.0
    } else {
        d
    }
}

/// The distance from p to the segment a–b.
pub fn to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (ux, uy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = ux * ux + uy * uy;
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * ux).hypot(p[1] - a[1] - t * uy)
}

/// The largest distance between two points of a polygon (its size).
pub fn diameter(poly: &[[f64; 2]]) -> f64 {
    let mut d: f64 = 0.0;
    for a in poly {
        for b in poly {
            d = d.max((a[0] - b[0]).hypot(a[1] - b[1]));
        }
    }
    d
}

/// a·b (by the one dot product of `num::vec`).
pub(super) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    let v = |a: [f64; 3]| crate::num::vec::V3::new(a[0], a[1], a[2]);
    crate::num::vec::dot(&v(a), &v(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// From the front (az 0, el 0) the page is the x–y plane; right, up and
    /// w are orthonormal for any view.
    #[test]
    fn front_view_and_orthonormal_axes() {
        let f = Axo::new(0.0, 0.0);
        assert_eq!(f.page([1.0, 2.0, 3.0]), [1.0, 2.0]);
        let a = Axo::new(35.0, 25.0);
        for (p, q) in [(a.right, a.up), (a.up, a.w), (a.w, a.right)] {
            assert!(dot(p, q).abs() < 1e-12);
        }
        for v in [a.right, a.up, a.w] {
            assert!((dot(v, v) - 1.0).abs() < 1e-12);
        }
        // y is drawn straight up; z toward the reader, down to the left.
        let y = a.page([0.0, 1.0, 0.0]);
        let z = a.page([0.0, 0.0, 1.0]);
        assert!(y[0].abs() < 1e-12 && y[1] > 0.0 && z[0] < 0.0 && z[1] < 0.0);
    }

    /// The x, y, z axes from the usual view: x at −(sin 25°·sin 35°)/cos 35°
    /// below the horizontal: atan(0.4226·0.5736/0.8192) = 16.5°; z at
    /// atan(0.4226·0.8192/0.5736) = 31.1° below the horizontal to the left.
    /// So x and z are 180 − 16.5 − 31.1 = 132.4° apart, x and y 106.5°.
    #[test]
    fn page_angles_of_the_usual_view() {
        let a = Axo::usual();
        let (x, y, z) = (
            a.page([1.0, 0.0, 0.0]),
            a.page([0.0, 1.0, 0.0]),
            a.page([0.0, 0.0, 1.0]),
        );
        assert!((page_angle(x, z) - 132.4).abs() < 0.1);
        assert!((page_angle(x, y) - 106.5).abs() < 0.1);
        assert!(a.readable(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]) > 1.0);
    }

    #[test]
    fn inside_and_outside_a_polygon() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(outside_by([0.5, 0.5], &sq), 0.0);
        assert!((outside_by([2.0, 0.5], &sq) - 1.0).abs() < 1e-12);
        assert!((diameter(&sq) - 2f64.sqrt()).abs() < 1e-12);
    }
}
