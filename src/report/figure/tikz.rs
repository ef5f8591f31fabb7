//! A [`Figure`] as a TikZ picture (for the LaTeX keys): the same marks,
//! in page units scaled to about 10 cm wide.

use super::{Figure, Item, Pen};
use std::fmt::Write;

/// The `tikzpicture` of a figure (needs `\usepackage{tikz}` and
/// `\definecolor`s from [`preamble`]).
pub fn to_tikz(f: &Figure) -> String {
    let [x0, _, x1, _] = f.bounds();
    let s = 10.0 / (x1 - x0).max(1e-9);
    let mut o = format!("\\begin{{tikzpicture}}[x={s:.4}cm,y={s:.4}cm,>=stealth]\n");
    let pt = |p: &[f64; 2]| format!("({:.4},{:.4})", p[0], p[1]);
    for it in &f.items {
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
            Item::Dot { at, pen } => writeln!(o, "\\fill[{}] {} circle (2pt);", name(*pen), pt(at)),
            Item::Label { at, text } => writeln!(
                o,
                "\\node[above right,font=\\small] at {} {{{}}};",
                pt(at),
                crate::report::doc::latex_text(text)
            ),
        };
    }
    o.push_str("\\end{tikzpicture}\n");
    o
}

/// The colour definitions the pictures use (Okabe–Ito).
pub fn preamble() -> String {
    [Pen::Frame, Pen::Kept, Pen::Cut, Pen::Tried, Pen::Vector]
        .iter()
        .map(|p| {
            format!(
                "\\definecolor{{{}}}{{HTML}}{{{}}}\n",
                name(*p),
                &p.colour()[1..]
            )
        })
        .collect()
}

fn name(p: Pen) -> &'static str {
    match p {
        Pen::Frame => "gfFrame",
        Pen::Kept => "gfKept",
        Pen::Cut => "gfCut",
        Pen::Tried => "gfTried",
        Pen::Vector => "gfVector",
    }
}

fn opts(p: Pen) -> String {
    let pattern = if p.dashed() {
        ",dashed"
    } else if p.dotted() {
        ",dotted"
    } else {
        ""
    };
    format!("{},line width={}pt{pattern}", name(p), p.width() * 0.5)
}
