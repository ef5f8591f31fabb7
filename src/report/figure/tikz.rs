//! A [`Drawing`] as TikZ pictures (for the LaTeX keys), one per panel so
//! that a page may break between panels: the same marks and labels at the
//! same places as the SVG ([`super::svg::stack`]), at 0.025 cm per px
//! (15 cm wide), y down as in the SVG.

use super::layout::{Anchor, Laid};
use super::svg::stack;
use super::{Drawing, Item, Mark, Pen, Shape};
use std::fmt::Write;

/// The `tikzpicture`s of a drawing, one per panel, separated by a blank
/// line (needs `\usepackage{tikz}` and the `\definecolor`s from
/// [`preamble`]).
pub fn to_tikz(d: &Drawing) -> String {
    let (laid, _) = stack(d);
    let mut o = String::new();
    for (f, (_, l)) in d.panels.iter().zip(&laid) {
        o.push_str("\\begin{tikzpicture}[x=0.025cm,y=-0.025cm,>=stealth]\n");
        if d.panels.len() > 1 {
            let _ = writeln!(
                o,
                "\\node[anchor=base west,inner sep=0,font=\\small\\bfseries] at (8,-7) {{{}}};",
                text(&f.title)
            );
        }
        let mut labels = l.labels.iter();
        for it in &f.items {
            match it {
                Item::Mark(m) => mark(&mut o, m, l),
                Item::Label(_) => labels
                    .next()
                    .into_iter()
                    .flatten()
                    .for_each(|p| node(&mut o, p)),
                Item::Note(_) => {}
            }
        }
        l.notes.iter().for_each(|p| node(&mut o, p));
        o.push_str("\\end{tikzpicture}\n\n");
    }
    o
}

/// A label or note as a node at its place.
fn node(o: &mut String, p: &super::layout::Placed) {
    let anchor = match p.anchor {
        Anchor::Start => "base west",
        Anchor::Middle => "base",
        Anchor::End => "base east",
    };
    let _ = writeln!(
        o,
        "\\node[anchor={anchor},inner sep=0.5pt,fill=white,font=\\small] at ({:.1},{:.1}) {{{}}};",
        p.x,
        p.y,
        text(&p.text)
    );
}

fn text(s: &str) -> String {
    crate::report::latex::latex_text(s)
}

fn mark(o: &mut String, m: &Mark, l: &Laid) {
    let pt = |p: &[f64; 2]| {
        let (x, y) = l.map(p);
        format!("({x:.1},{y:.1})")
    };
    let path = |pts: &[[f64; 2]]| pts.iter().map(pt).collect::<Vec<_>>().join(" -- ");
    // The mark's kind and name as a comment (in LaTeX's ASCII), so the
    // picture reads like the SVG.
    let _ = writeln!(o, "% {} {}", m.kind.word(), text(&m.name));
    let _ = match &m.shape {
        Shape::Line { a, b, head } => {
            let arrow = if *head { "->," } else { "" };
            writeln!(o, "\\draw[{arrow}{}] {} -- {};", opts(m.pen), pt(a), pt(b))
        }
        Shape::Polygon(pts) => writeln!(o, "\\draw[{}] {} -- cycle;", opts(m.pen), path(pts)),
        Shape::Path(pts) => writeln!(o, "\\draw[{}] {};", opts(m.pen), path(pts)),
        Shape::Face(_) => Ok(()),
        Shape::Dot(at) => writeln!(o, "\\fill[{}] {} circle (2pt);", m.pen.name(), pt(at)),
        Shape::Edges(edges) => edges
            .iter()
            .try_for_each(|(a, b, p)| writeln!(o, "\\draw[{}] {} -- {};", opts(*p), pt(a), pt(b))),
    };
}

/// The colour definitions the pictures use (Okabe–Ito).
pub fn preamble() -> String {
    Pen::ALL
        .iter()
        .map(|p| {
            format!(
                "\\definecolor{{{}}}{{HTML}}{{{}}}\n",
                p.name(),
                &p.colour()[1..]
            )
        })
        .collect()
}

fn opts(p: Pen) -> String {
    let pattern = p
        .dashes()
        .map(|(_, tikz)| format!(",{tikz}"))
        .unwrap_or_default();
    format!("{},line width={}pt{pattern}", p.name(), p.width() * 0.5)
}
