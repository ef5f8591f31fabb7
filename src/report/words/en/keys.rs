//! The words of the answer keys in English: the keys themselves for the
//! names of the answer tree (they are also the keys of an answer file),
//! the steps' names for the values, and the practice's prompts.

use super::En;
use crate::report::words::keys::{in_segment, KeyWords};
use crate::report::words::names::NameWords;
use crate::stages::trace::Name;
use crate::tutor::key::{Cut, Factor, Field, Key, Node, Part, Plane, Shading, Value};

impl KeyWords for En {
    fn node(&self, n: &Node) -> String {
        n.to_string()
    }

    fn plane(&self, p: Plane) -> &'static str {
        match p {
            Plane::Left => "left",
            Plane::Right => "right",
            Plane::Bottom => "bottom",
            Plane::Top => "top",
            Plane::Front => "front",
            Plane::Back => "back",
        }
    }

    fn answer_name(&self, k: &Key) -> String {
        let name = match &k.value {
            Value::Whole => k
                .part
                .map_or_else(String::new, |p| self.node(&Node::Part(p))),
            Value::Field(Field::Matrix) if k.part == Some(Part::View) => "V".to_string(),
            Value::Point(n) => match k.part {
                Some(Part::View) => self.name(&Name::Eye(n.clone())),
                Some(Part::Project) => self.name(&Name::Image(n.clone())),
                Some(Part::Window | Part::Viewport | Part::Clip | Part::Shade) | None => n.clone(),
            },
            Value::Pixel(n) => self.name(&Name::Pixel(n.clone())),
            Value::Field(Field::Edge(e, true)) => {
                format!(
                    "{} (far plane)",
                    self.node(&Node::Field(Field::Edge(*e, false)))
                )
            }
            Value::Field(Field::Segment) => "clipped segment".to_string(),
            // the steps' notation, not the keys' spelling
            Value::Field(Field::Shading(Shading::CosAlpha)) => "cos α".to_string(),
            Value::Field(Field::Shading(Shading::CosBeta)) => "cos β".to_string(),
            Value::Field(Field::Shading(Shading::NDotH)) => "N·H".to_string(),
            Value::Field(f) => self.node(&Node::Field(*f)),
            Value::Plane(p) => self.plane(*p).to_string(),
            Value::Cut(p, c) => {
                let what = match c {
                    Cut::Point => "P(t)",
                    Cut::T => "t",
                    Cut::Code => "code",
                    Cut::Kept => "kept",
                };
                format!("{what} ({})", self.plane(*p))
            }
            Value::Light(i) => return format!("light {}", i + 1),
            Value::Factor(i, f) => {
                let said = match f {
                    Factor::InRange => "in range",
                    Factor::Distance => "d",
                    Factor::Attenuation => "Att",
                    Factor::Spot => "Spot",
                };
                return format!("{said} (light {})", i + 1);
            }
        };
        in_segment("segment", k, name)
    }

    fn blank_label(&self, k: &Key) -> String {
        let name = match &k.value {
            Value::Field(Field::Code0) => "outcode of P0",
            Value::Field(Field::Code1) => "outcode of P1",
            Value::Field(Field::Shading(s)) => match s {
                Shading::CosAlpha => "cos α",
                Shading::CosBeta => "cos β",
                Shading::NDotH => "N·H",
                Shading::L => "L",
                Shading::N => "N",
                Shading::R => "R",
                Shading::H => "H",
                Shading::Ambient => "ambient term",
                Shading::Diffuse => "diffuse term",
                Shading::Specular => "specular term",
                Shading::Emissive => "emissive term",
                Shading::Unclamped => "color before clamping",
                Shading::Color => "color",
            },
            _ => return self.answer_name(k),
        };
        in_segment("segment", k, name.to_string())
    }

    fn answer_words(&self, k: &Key) -> String {
        let pl = |p: &Plane| self.plane(*p);
        match &k.value {
            Value::Whole => {
                let part = k
                    .part
                    .map_or_else(String::new, |p| self.node(&Node::Part(p)));
                format!("the answers of {part}")
            }
            Value::Field(f) => match f {
                Field::Axis(a) => {
                    format!("camera axis {}", self.node(&Node::Field(Field::Axis(*a))))
                }
                Field::Matrix => "the view matrix V".to_string(),
                Field::Points => "the points".to_string(),
                Field::Pixels => "the pixels".to_string(),
                Field::Edge(..) => format!("window {}", self.node(&Node::Field(*f))),
                Field::Code0 => "outcode of P0".to_string(),
                Field::Code1 => "outcode of P1".to_string(),
                Field::Status => "the status".to_string(),
                Field::Segment => "the clipped segment".to_string(),
                Field::Intersections => "the intersections with the planes".to_string(),
                Field::Shading(s) => shading(*s),
                Field::Lights => "each light's factors".to_string(),
            },
            Value::Point(n) => match k.part {
                Some(Part::View) => format!("eye coordinates {n}'"),
                Some(Part::Project) => format!("projected point {n}''"),
                Some(Part::Window | Part::Viewport | Part::Clip | Part::Shade) | None => {
                    format!("point {n}")
                }
            },
            Value::Pixel(n) => format!("pixel coordinates of {n}"),
            Value::Plane(p) => format!("the intersection with the plane {}", pl(p)),
            Value::Cut(p, Cut::T) => format!("t at the plane {}", pl(p)),
            Value::Cut(p, Cut::Point) => format!("intersection with the plane {}", pl(p)),
            Value::Cut(p, Cut::Code) => {
                format!("outcode of the intersection with the plane {}", pl(p))
            }
            Value::Cut(p, Cut::Kept) => {
                format!("whether the intersection with the plane {} is kept", pl(p))
            }
            Value::Light(i) => format!("the factors of light {}", i + 1),
            Value::Factor(i, f) => format!("{} of light {}", factor(*f), i + 1),
        }
    }
}

/// What a value of the lighting is.
fn shading(s: Shading) -> String {
    let term = |s: Shading| format!("term {}", Node::Field(Field::Shading(s)));
    match s {
        Shading::L => "unit vector L".to_string(),
        Shading::N => "unit vector N".to_string(),
        Shading::R => "reflection vector R".to_string(),
        Shading::H => "half-way vector H".to_string(),
        Shading::CosAlpha => "cos α = L·N".to_string(),
        Shading::CosBeta => "cos β = R·V".to_string(),
        Shading::NDotH => "N·H".to_string(),
        Shading::Color => "the colour, clamped to [0, 1]".to_string(),
        Shading::Ambient
        | Shading::Diffuse
        | Shading::Specular
        | Shading::Emissive
        | Shading::Unclamped => term(s),
    }
}

/// A light's factor in words.
fn factor(f: Factor) -> &'static str {
    match f {
        Factor::InRange => "whether the point is in range",
        Factor::Distance => "the distance d",
        Factor::Attenuation => "the attenuation",
        Factor::Spot => "the spot factor",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn english_names_the_values_as_the_steps_do() {
        let en = |s| En.answer_name(&key(s));
        assert_eq!(en("view.n"), "n");
        assert_eq!(en("view.matrix"), "V");
        assert_eq!(en("view.points.A"), "A'");
        assert_eq!(en("project.points.A"), "A''");
        assert_eq!(en("viewport.pixels.A"), "A pixel");
        assert_eq!(en("window.far_top"), "top (far plane)");
        assert_eq!(en("shade.cos_alpha"), "cos α");
        assert_eq!(en("shade.N_dot_H"), "N·H");
        assert_eq!(en("shade.lights[0].in_range"), "in range (light 1)");
        assert_eq!(
            en("clip[1].intersections.top.point"),
            "segment 2: P(t) (top)"
        );
        assert_eq!(en("shade.lights[0].attenuation"), "Att (light 1)");
    }

    /// A quiz labels its blanks with no JSON key: the steps' names, and
    /// words where the name is notation (code0, cos_alpha).
    #[test]
    fn a_quiz_labels_its_blanks_in_words_not_keys() {
        let en = |s| En.blank_label(&key(s));
        assert_eq!(en("view.n"), "n");
        assert_eq!(en("view.points.A"), "A'");
        assert_eq!(en("project.points.A"), "A''");
        assert_eq!(en("viewport.pixels.A"), "A pixel");
        assert_eq!(en("window.top"), "top");
        assert_eq!(en("clip.code0"), "outcode of P0");
        assert_eq!(en("clip[1].code1"), "segment 2: outcode of P1");
        assert_eq!(en("clip.segment"), "clipped segment");
        assert_eq!(en("shade.cos_alpha"), "cos α");
        assert_eq!(en("shade.N_dot_H"), "N·H");
        assert_eq!(en("shade.specular"), "specular term");
        assert_eq!(en("shade.color"), "color");
    }

    #[test]
    fn english_keeps_the_keys_as_the_names_of_the_tree() {
        for (name, under) in [("view", None), ("matrix", Some(Node::Part(Part::View)))] {
            let n = Node::read(name, under.as_ref()).expect("a name");
            assert_eq!(En.node(&n), name);
        }
        assert_eq!(En.answer_words(&key("window.top")), "window top");
        assert_eq!(
            En.answer_words(&key("window.far_width")),
            "window far_width"
        );
    }
}
