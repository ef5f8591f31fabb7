//! A [`Figure`] as a standalone SVG: 600 px wide, `<title>` and `<desc>`
//! first, labels as `<text>` (selectable).

use super::{xml_escape, Figure, Item, Pen};
use std::fmt::Write;

/// The drawing's width in px.
pub const WIDTH: f64 = 600.0;
const MARGIN: f64 = 60.0;

/// The SVG text of a figure.
pub fn to_svg(f: &Figure) -> String {
    let [x0, y0, x1, y1] = f.bounds();
    let s = (WIDTH - 2.0 * MARGIN) / (x1 - x0).max(1e-9);
    let height = ((y1 - y0) * s + 2.0 * MARGIN).clamp(200.0, 900.0);
    let s = s.min((height - 2.0 * MARGIN) / (y1 - y0).max(1e-9));
    let map = |p: &[f64; 2]| (MARGIN + (p[0] - x0) * s, height - MARGIN - (p[1] - y0) * s);
    let mut o = String::new();
    let _ = writeln!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0}" viewBox="0 0 {WIDTH} {height:.0}" role="img" font-family="sans-serif" font-size="15">"#
    );
    let _ = writeln!(o, "<title>{}</title>", xml_escape(&f.title));
    let _ = writeln!(o, "<desc>{}</desc>", xml_escape(&f.desc));
    o.push_str(concat!(
        r#"<defs><marker id="head" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="8" markerHeight="8" orient="auto-start-reverse">"#,
        r##"<path d="M0,0 L10,5 L0,10 z" fill="#009E73"/></marker></defs>"##,
        "\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
    ));
    for it in &f.items {
        item(&mut o, it, &map);
    }
    o.push_str("</svg>\n");
    o
}

fn stroke(p: Pen) -> String {
    let dash = if p.dashed() {
        r#" stroke-dasharray="9 6""#
    } else if p.dotted() {
        r#" stroke-dasharray="2 4""#
    } else {
        ""
    };
    format!(
        r#"stroke="{}" stroke-width="{}" fill="none"{dash}"#,
        p.colour(),
        p.width()
    )
}

fn item(o: &mut String, it: &Item, map: &dyn Fn(&[f64; 2]) -> (f64, f64)) {
    match it {
        Item::Segment { a, b, pen } | Item::Arrow { a, b, pen } => {
            let ((ax, ay), (bx, by)) = (map(a), map(b));
            let head = if matches!(it, Item::Arrow { .. }) {
                r#" marker-end="url(#head)""#
            } else {
                ""
            };
            let _ = writeln!(
                o,
                r#"<line x1="{ax:.1}" y1="{ay:.1}" x2="{bx:.1}" y2="{by:.1}" {}{head}/>"#,
                stroke(*pen)
            );
        }
        Item::Polygon { pts, pen } => {
            let p: Vec<String> = pts
                .iter()
                .map(|q| {
                    let (x, y) = map(q);
                    format!("{x:.1},{y:.1}")
                })
                .collect();
            let _ = writeln!(o, r#"<polygon points="{}" {}/>"#, p.join(" "), stroke(*pen));
        }
        Item::Dot { at, pen } => {
            let (x, y) = map(at);
            let _ = writeln!(
                o,
                r#"<circle cx="{x:.1}" cy="{y:.1}" r="4.5" fill="{}"/>"#,
                pen.colour()
            );
        }
        Item::Label { at, text } => {
            let (x, y) = map(at);
            let _ = writeln!(
                o,
                r##"<text x="{:.1}" y="{:.1}" fill="#000000">{}</text>"##,
                x + 6.0,
                y - 6.0,
                xml_escape(text)
            );
        }
    }
}
