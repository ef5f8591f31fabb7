//! A [`Drawing`] as TikZ pictures (for the LaTeX keys), one per panel so
//! that a page may break between panels: the same marks and labels at the
//! same places as the SVG ([`super::svg::stack`]), at 0.025 cm per px
//! (15 cm wide), y down as in the SVG.

use super::layout::{Anchor, Laid};
use super::svg::stack;
use super::{Drawing, Item, Pen};
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
        let mut k = 0;
        for it in &f.items {
            if let Item::Label { .. } | Item::Note { .. } = it {
                let p = &l.labels[k];
                k += 1;
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
            } else {
                mark(&mut o, it, l);
            }
        }
        o.push_str("\\end{tikzpicture}\n\n");
    }
    o
}

fn text(s: &str) -> String {
    crate::report::latex::latex_text(s)
}

fn mark(o: &mut String, it: &Item, l: &Laid) {
    let pt = |p: &[f64; 2]| {
        let (x, y) = l.map(p);
        format!("({x:.1},{y:.1})")
    };
    let _ = match it {
        Item::Segment { a, b, pen } => {
            writeln!(o, "\\draw[{}] {} -- {};", opts(*pen), pt(a), pt(b))
        }
        Item::Arrow { a, b, pen } => {
            writeln!(o, "\\draw[->,{}] {} -- {};", opts(*pen), pt(a), pt(b))
        }
        Item::Polygon { pts, pen } => {
            let p: Vec<String> = pts.iter().map(pt).collect();
            writeln!(o, "\\draw[{}] {} -- cycle;", opts(*pen), p.join(" -- "))
        }
        Item::Path { pts, pen } => {
            let p: Vec<String> = pts.iter().map(pt).collect();
            writeln!(o, "\\draw[{}] {};", opts(*pen), p.join(" -- "))
        }
        Item::Dot { at, pen } => writeln!(o, "\\fill[{}] {} circle (2pt);", pen.name(), pt(at)),
        Item::Label { .. } | Item::Note { .. } => Ok(()),
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
    let pattern = if p.dashed() {
        ",dashed"
    } else if p.dotted() {
        ",dotted"
    } else if p.dash_dotted() {
        ",dash pattern=on 5pt off 2pt on 1pt off 2pt"
    } else {
        ""
    };
    format!("{},line width={}pt{pattern}", p.name(), p.width() * 0.5)
}
