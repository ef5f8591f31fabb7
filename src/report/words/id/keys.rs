//! The words of the answer keys in Bahasa Indonesia, with the text's terms
//! (docs/glossary.md): the names of the answer tree (`titik`, `kiri`,
//! `dipertahankan`), the steps' names for the values (`piksel A`), and the
//! practice's prompts (`koordinat kamera A'`). Notation (`u`, `code0`,
//! `top`, `R`) is the same as in English and is written here too.

use super::Id;
use crate::report::words::keys::{in_segment, KeyWords};
use crate::report::words::names::NameWords;
use crate::stages::trace::Name;
use crate::tutor::key::{Axis, Cut, Edge, Factor, Field, Key, Node, Part, Plane, Shading, Value};

impl KeyWords for Id {
    fn node(&self, n: &Node) -> String {
        let said = match n {
            Node::Part(p) => match p {
                Part::View => "transformasi pandang",
                Part::Project => "proyeksi",
                Part::Window => "viewing window",
                Part::Viewport => "viewport",
                Part::Clip => "clipping",
                Part::Shade => "pencahayaan",
            },
            Node::Field(f) => match f {
                Field::Axis(Axis::U) => "u",
                Field::Axis(Axis::V) => "v",
                Field::Axis(Axis::N) => "n",
                Field::Matrix => "matriks pandang V",
                Field::Points => "titik",
                Field::Pixels => "piksel",
                // the text's tinggi h and lebar w; the edges are notation,
                // as the text's (l, b) – (r, t)
                Field::Edge(Edge::Height, _) => "tinggi",
                Field::Edge(Edge::Width, _) => "lebar",
                Field::Edge(e, true) => {
                    return format!("{} (far plane)", Node::Field(Field::Edge(*e, false)))
                }
                Field::Edge(_, false) | Field::Code0 | Field::Code1 | Field::Status => {
                    return n.to_string()
                }
                Field::Segment => "segmen garis hasil clipping",
                Field::Intersections => "titik potong",
                Field::Shading(s) => match s {
                    Shading::Color => "warna",
                    Shading::Unclamped => "sebelum dibatasi",
                    Shading::CosAlpha => "cos α",
                    Shading::CosBeta => "cos β",
                    Shading::NDotH => "N·H",
                    Shading::L
                    | Shading::N
                    | Shading::R
                    | Shading::H
                    | Shading::Ambient
                    | Shading::Diffuse
                    | Shading::Specular
                    | Shading::Emissive => return n.to_string(),
                },
                Field::Lights => "sumber cahaya",
            },
            Node::Point(name) => name,
            Node::Plane(p) => self.plane(*p),
            Node::Cut(c) => match c {
                Cut::T => "t",
                Cut::Point => "titik potong",
                Cut::Code => "region code",
                Cut::Kept => "dipertahankan",
            },
            Node::Factor(f) => match f {
                Factor::InRange => "dalam jangkauan",
                Factor::Distance => "jarak d",
                Factor::Attenuation => "Att",
                Factor::Spot => "Spot",
            },
        };
        said.to_string()
    }

    /// The text's own names.
    fn plane(&self, p: Plane) -> &'static str {
        super::super::keys::text_plane(p)
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
            // the text's own term: far plane
            Value::Field(Field::Edge(e, true)) => {
                format!(
                    "{} (far plane)",
                    self.node(&Node::Field(Field::Edge(*e, false)))
                )
            }
            Value::Field(f) => self.node(&Node::Field(*f)),
            Value::Plane(p) => self.plane(*p).to_string(),
            Value::Cut(p, c) => {
                let what = match c {
                    Cut::Point => "P(t)".to_string(),
                    Cut::T | Cut::Code | Cut::Kept => self.node(&Node::Cut(*c)),
                };
                format!("{what} ({})", self.plane(*p))
            }
            Value::Light(i) => return format!("cahaya {}", i + 1),
            Value::Factor(i, f) => {
                return format!("{} (cahaya {})", self.node(&Node::Factor(*f)), i + 1)
            }
        };
        in_segment("segmen", k, name)
    }

    fn blank_label(&self, k: &Key) -> String {
        let name = match &k.value {
            Value::Field(Field::Code0) => "region code P0".to_string(),
            Value::Field(Field::Code1) => "region code P1".to_string(),
            Value::Field(Field::Edge(e, far)) => {
                let what = match e {
                    Edge::Top => "batas atas (top)",
                    Edge::Bottom => "batas bawah (bottom)",
                    Edge::Left => "batas kiri (left)",
                    Edge::Right => "batas kanan (right)",
                    Edge::Height => "tinggi",
                    Edge::Width => "lebar",
                };
                let far = if *far { " pada far plane" } else { "" };
                format!("{what}{far}")
            }
            Value::Field(Field::Shading(s)) => match s {
                Shading::Ambient | Shading::Diffuse | Shading::Specular | Shading::Emissive => {
                    format!("komponen {}", Node::Field(Field::Shading(*s)))
                }
                Shading::Unclamped => "warna sebelum dibatasi".to_string(),
                Shading::L
                | Shading::N
                | Shading::R
                | Shading::H
                | Shading::CosAlpha
                | Shading::CosBeta
                | Shading::NDotH
                | Shading::Color => return self.answer_name(k),
            },
            _ => return self.answer_name(k),
        };
        in_segment("segmen", k, name)
    }

    fn answer_words(&self, k: &Key) -> String {
        let pl = |p: &Plane| self.plane(*p);
        match &k.value {
            Value::Whole => {
                let part = k
                    .part
                    .map_or_else(String::new, |p| self.node(&Node::Part(p)));
                format!("jawaban bagian {part}")
            }
            Value::Field(f) => match f {
                Field::Axis(a) => {
                    format!("sumbu kamera {}", self.node(&Node::Field(Field::Axis(*a))))
                }
                Field::Matrix => "matriks transformasi pandang V".to_string(),
                Field::Points => "semua titik".to_string(),
                Field::Pixels => "semua piksel".to_string(),
                Field::Edge(e, far) => window(*e, *far),
                Field::Code0 => "region code P0".to_string(),
                Field::Code1 => "region code P1".to_string(),
                Field::Status => "status".to_string(),
                Field::Segment => "segmen garis hasil clipping".to_string(),
                Field::Intersections => "titik potong dengan setiap bidang".to_string(),
                Field::Shading(s) => shading(*s),
                Field::Lights => "faktor setiap sumber cahaya".to_string(),
            },
            Value::Point(n) => match k.part {
                Some(Part::View) => format!("koordinat kamera {n}'"),
                Some(Part::Project) => format!("hasil proyeksi {n}''"),
                Some(Part::Window | Part::Viewport | Part::Clip | Part::Shade) | None => {
                    format!("titik {n}")
                }
            },
            Value::Pixel(n) => format!("koordinat piksel {n}"),
            Value::Plane(p) => format!("perpotongan dengan bidang {}", pl(p)),
            Value::Cut(p, Cut::T) => format!("t pada bidang {}", pl(p)),
            Value::Cut(p, Cut::Point) => format!("titik potong dengan bidang {}", pl(p)),
            Value::Cut(p, Cut::Code) => {
                format!("region code titik potong dengan bidang {}", pl(p))
            }
            Value::Cut(p, Cut::Kept) => {
                format!("apakah titik potong dengan bidang {} dipertahankan", pl(p))
            }
            Value::Light(i) => format!("faktor sumber cahaya {}", i + 1),
            Value::Factor(i, f) => format!("{} sumber cahaya {}", factor(*f), i + 1),
        }
    }
}

/// An edge or size of the window in words (`top` → `batas atas viewing
/// window (top)`; on the far plane, `… pada far plane (top)`; the size as
/// the text says it, `tinggi viewing window`).
fn window(e: Edge, far: bool) -> String {
    let what = match e {
        Edge::Top => "batas atas",
        Edge::Bottom => "batas bawah",
        Edge::Left => "batas kiri",
        Edge::Right => "batas kanan",
        Edge::Height => "tinggi",
        Edge::Width => "lebar",
    };
    let at = if far { " pada far plane" } else { "" };
    match e {
        Edge::Height | Edge::Width => format!("{what} viewing window{at}"),
        Edge::Top | Edge::Bottom | Edge::Left | Edge::Right => {
            let notation = Node::Field(Field::Edge(e, false));
            format!("{what} viewing window{at} ({notation})")
        }
    }
}

/// What a value of the lighting is.
fn shading(s: Shading) -> String {
    let term = |s: Shading| format!("komponen {}", Node::Field(Field::Shading(s)));
    if s == Shading::Unclamped {
        return "jumlah komponen, sebelum dibatasi ke [0, 1]".to_string();
    }
    match s {
        Shading::L => "vektor satuan L".to_string(),
        Shading::N => "vektor satuan N".to_string(),
        Shading::R => "vektor pantulan R".to_string(),
        Shading::H => "vektor setengah jalan H".to_string(),
        Shading::CosAlpha => "cos α = L·N".to_string(),
        Shading::CosBeta => "cos β = R·V".to_string(),
        Shading::NDotH => "N·H".to_string(),
        Shading::Color => "warna, dibatasi ke [0, 1]".to_string(),
        Shading::Ambient
        | Shading::Diffuse
        | Shading::Specular
        | Shading::Emissive
        | Shading::Unclamped => term(s),
    }
}

/// A light's factor in words (docs/glossary.md: redaman, faktor sorotan,
/// jangkauan).
fn factor(f: Factor) -> &'static str {
    match f {
        Factor::InRange => "apakah titik dalam jangkauan (range)",
        Factor::Distance => "jarak d",
        Factor::Attenuation => "redaman (Att)",
        Factor::Spot => "faktor sorotan (Spot)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(s: &str) -> Key {
        s.parse().unwrap_or_else(|_| panic!("{s} is a key"))
    }

    #[test]
    fn answers_are_named_as_the_steps_name_them() {
        let id = |s| Id.answer_name(&key(s));
        assert_eq!(id("view.n"), "n");
        assert_eq!(id("view.matrix"), "V");
        assert_eq!(id("view.points.A"), "A'");
        assert_eq!(id("viewport.pixels.A"), "piksel A");
        assert_eq!(id("window.top"), "top");
        assert_eq!(id("window.far_top"), "top (far plane)");
        assert_eq!(id("window.height"), "tinggi");
        assert_eq!(id("window.width"), "lebar");
        assert_eq!(id("clip.intersections.left.point"), "P(t) (kiri)");
        assert_eq!(
            id("clip[1].intersections.top.kept"),
            "segmen 2: dipertahankan (atas)"
        );
        assert_eq!(id("clip.1.status"), "segmen 2: status");
        assert_eq!(id("shade.color"), "warna");
        assert_eq!(id("shade.cos_alpha"), "cos α");
        assert_eq!(id("shade.lights[0].attenuation"), "Att (cahaya 1)");
    }

    /// An Indonesian quiz labels its blanks in the text's words: no JSON
    /// key, no English word where the text has its own (tinggi, lebar,
    /// region code, komponen).
    #[test]
    fn a_quiz_labels_its_blanks_in_the_texts_words() {
        let id = |s| Id.blank_label(&key(s));
        assert_eq!(id("view.n"), "n");
        assert_eq!(id("view.points.A"), "A'");
        assert_eq!(id("viewport.pixels.A"), "piksel A");
        assert_eq!(id("window.top"), "batas atas (top)");
        assert_eq!(id("window.height"), "tinggi");
        assert_eq!(id("window.far_width"), "lebar pada far plane");
        assert_eq!(id("clip.code0"), "region code P0");
        assert_eq!(id("clip[1].status"), "segmen 2: status");
        assert_eq!(id("clip.segment"), "segmen garis hasil clipping");
        assert_eq!(id("shade.cos_alpha"), "cos α");
        assert_eq!(id("shade.diffuse"), "komponen diffuse");
        assert_eq!(id("shade.unclamped"), "warna sebelum dibatasi");
        assert_eq!(id("shade.color"), "warna");
    }

    #[test]
    fn practice_asks_in_the_texts_words() {
        let id = |s| Id.answer_words(&key(s));
        assert_eq!(id("window.top"), "batas atas viewing window (top)");
        assert_eq!(
            id("window.far_top"),
            "batas atas viewing window pada far plane (top)"
        );
        assert_eq!(id("window.height"), "tinggi viewing window");
        assert_eq!(
            id("shade.unclamped"),
            "jumlah komponen, sebelum dibatasi ke [0, 1]"
        );
        assert_eq!(id("view.points.A"), "koordinat kamera A'");
        assert_eq!(id("project.points.A"), "hasil proyeksi A''");
        assert_eq!(id("clip.1.segment"), "segmen garis hasil clipping");
        assert_eq!(
            id("clip.intersections.back.code"),
            "region code titik potong dengan bidang belakang"
        );
    }

    #[test]
    fn the_tree_is_named_in_the_texts_words() {
        let under_view = Node::Part(Part::View);
        let name = |s, under: Option<&Node>| Id.node(&Node::read(s, under).expect("a name"));
        assert_eq!(name("view", None), "transformasi pandang");
        assert_eq!(name("matrix", Some(&under_view)), "matriks pandang V");
        assert_eq!(name("points", Some(&under_view)), "titik");
        let planes = Node::Field(Field::Intersections);
        assert_eq!(name("left", Some(&planes)), "kiri");
        assert_eq!(
            name("kept", Some(&Node::Plane(Plane::Left))),
            "dipertahankan"
        );
        // a point's own name is its name, whatever it spells
        let points = Node::Field(Field::Points);
        assert_eq!(name("color", Some(&points)), "color");
    }
}
