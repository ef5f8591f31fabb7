//! A [`Drawing`] as a standalone SVG: 600 px wide, `<title>` and `<desc>`
//! first, its panels one below the other (each a group with its own
//! `<title>` and `<desc>`, and its title written above it), every mark an
//! element with `data-name` and `data-kind`, labels as `<text>` (selectable)
//! with `data-for`. Where things go is `layout`'s.

use super::layout::{lay_out, Anchor, Laid, FONT, WIDTH};
use super::{xml_escape, Drawing, Item, Mark, Pen, Shape};
use std::fmt::Write;

/// The height of a panel's heading, px.
pub const HEADING: f64 = 26.0;

/// The panels' layouts and where each starts (px from the top); the
/// total height.
pub fn stack(d: &Drawing) -> (Vec<(f64, Laid)>, f64) {
    let head = if d.panels.len() > 1 { HEADING } else { 0.0 };
    let mut y = 0.0;
    let mut out = Vec::new();
    for f in &d.panels {
        let l = lay_out(f);
        let h = l.height;
        out.push((y + head, l));
        y += head + h;
    }
    (out, y.max(1.0))
}

/// The SVG text of a drawing.
pub fn to_svg(d: &Drawing) -> String {
    let (laid, height) = stack(d);
    let id = ids(d);
    let mut o = String::new();
    let _ = writeln!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0}" viewBox="0 0 {WIDTH} {height:.0}" role="img" font-family="DejaVu Sans, Verdana, sans-serif" font-size="{FONT}">"#
    );
    let _ = writeln!(o, "<title>{}</title>", xml_escape(&d.title()));
    let descs: Vec<&str> = d.panels.iter().map(|f| f.desc.as_str()).collect();
    let _ = writeln!(o, "<desc>{}</desc>", xml_escape(&descs.join(" ")));
    o.push_str("<defs>");
    for p in Pen::ALL {
        let _ = write!(
            o,
            r#"<marker id="{id}-{}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="{}"/></marker>"#,
            p.name(),
            p.colour()
        );
    }
    o.push_str("</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
    for (f, (top, l)) in d.panels.iter().zip(&laid) {
        let _ = writeln!(o, "<g transform=\"translate(0,{top:.1})\">");
        let _ = writeln!(o, "<title>{}</title>", xml_escape(&f.title));
        let _ = writeln!(o, "<desc>{}</desc>", xml_escape(&f.desc));
        if d.panels.len() > 1 {
            let _ = writeln!(
                o,
                r#"<text x="8" y="-7" font-weight="bold" data-kind="title">{}</text>"#,
                xml_escape(&f.title)
            );
        }
        let mut k = 0;
        for it in &f.items {
            match it {
                Item::Mark(m) => mark(&mut o, m, l, &id),
                Item::Label(lb) => {
                    if let Some(p) = &l.labels[k] {
                        let attrs =
                            format!(r#"data-kind="label" data-for="{}""#, xml_escape(&lb.of));
                        text(&mut o, p, &attrs);
                    }
                    k += 1;
                }
                Item::Note(_) => {}
            }
        }
        for n in &l.notes {
            text(&mut o, n, r#"data-kind="note""#);
        }
        o.push_str("</g>\n");
    }
    o.push_str("</svg>\n");
    o
}

/// The marker id prefix of a drawing: its part and a hash (FNV-1a) of its
/// marks, so that ids stay unique when several drawings are inline in one
/// page, and the same drawing always gets the same ids.
fn ids(d: &Drawing) -> String {
    let clean: String = d
        .part
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect();
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in format!("{:?}", d.panels).bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    format!("gf-{clean}-{:08x}", h as u32)
}

/// The stroke attributes of a pen.
fn stroke(p: Pen) -> String {
    let dash = p
        .dashes()
        .map(|(svg, _)| format!(r#" stroke-dasharray="{svg}""#))
        .unwrap_or_default();
    format!(
        r#"stroke="{}" stroke-width="{}" fill="none"{dash}"#,
        p.colour(),
        p.width()
    )
}

fn points(pts: &[[f64; 2]], l: &Laid) -> String {
    let p: Vec<String> = pts
        .iter()
        .map(|q| {
            let (x, y) = l.map(q);
            format!("{x:.1},{y:.1}")
        })
        .collect();
    p.join(" ")
}

/// A line from a to b (tail to tip), with the attributes `attrs`.
fn line(o: &mut String, a: &[f64; 2], b: &[f64; 2], l: &Laid, attrs: &str) {
    let ((ax, ay), (bx, by)) = (l.map(a), l.map(b));
    let _ = writeln!(
        o,
        r#"<line {attrs}x1="{ax:.1}" y1="{ay:.1}" x2="{bx:.1}" y2="{by:.1}"/>"#
    );
}

/// One mark: an element (a `<g>` for the box's edges) with its
/// `data-name` and `data-kind`.
fn mark(o: &mut String, m: &Mark, l: &Laid, id: &str) {
    let named = format!(
        r#"data-name="{}" data-kind="{}" "#,
        xml_escape(&m.name),
        m.kind.word()
    );
    let pen = stroke(m.pen);
    let _ = match &m.shape {
        Shape::Line { a, b, head } => {
            let end = match head {
                true => format!(r#" marker-end="url(#{id}-{})""#, m.pen.name()),
                false => String::new(),
            };
            line(o, a, b, l, &format!("{named}{pen}{end} "));
            Ok(())
        }
        Shape::Polygon(pts) => {
            writeln!(o, r#"<polygon {named}points="{}" {pen}/>"#, points(pts, l))
        }
        Shape::Face(pts) => writeln!(
            o,
            r#"<polygon {named}points="{}" fill="none" stroke="none"/>"#,
            points(pts, l)
        ),
        Shape::Path(pts) => writeln!(o, r#"<polyline {named}points="{}" {pen}/>"#, points(pts, l)),
        Shape::Dot(at) => {
            let (x, y) = l.map(at);
            writeln!(
                o,
                r#"<circle {named}cx="{x:.1}" cy="{y:.1}" r="4.5" fill="{}"/>"#,
                m.pen.colour()
            )
        }
        Shape::Edges(edges) => {
            let _ = writeln!(o, "<g {}>", named.trim_end());
            for (a, b, p) in edges {
                line(o, a, b, l, &format!("{} ", stroke(*p)));
            }
            writeln!(o, "</g>")
        }
    };
}

/// A label or a note, with its attributes.
fn text(o: &mut String, p: &super::layout::Placed, attrs: &str) {
    let anchor = match p.anchor {
        Anchor::Start => "",
        Anchor::Middle => r#" text-anchor="middle""#,
        Anchor::End => r#" text-anchor="end""#,
    };
    let _ = writeln!(
        o,
        r##"<text {attrs} x="{:.1}" y="{:.1}"{anchor} fill="#000000" stroke="#ffffff" stroke-width="3" paint-order="stroke">{}</text>"##,
        p.x,
        p.y,
        xml_escape(&p.text)
    );
}
