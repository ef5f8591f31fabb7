//! The class's score distribution drawn: an SVG bar chart for the HTML
//! report, bars of text for Markdown.

use crate::msg::ClassWord as C;
use crate::report::figure::xml_escape;
use crate::report::lang::Lang;
use crate::report::words;
use crate::tutor::class::stats::Bin;

/// Width and height of the chart, in px.
const W: f64 = 600.0;
const H: f64 = 260.0;
/// Margins: left (the count axis), top, bottom (the bins' labels).
const LEFT: f64 = 44.0;
const TOP: f64 = 24.0;
const BOTTOM: f64 = 56.0;
/// Okabe–Ito blue, as the figures use.
const BLUE: &str = "#0072B2";

/// A bin's label: `30–40`.
fn label(b: &Bin) -> String {
    format!("{}–{}", b.from, b.to)
}

/// The bar chart as an SVG element (a title and a description first, each
/// bar with its count above it and its range below).
pub fn svg(bins: &[Bin], lang: Lang) -> String {
    let most = bins.iter().map(|b| b.count).max().unwrap_or(0).max(1) as f64;
    let plot_h = H - TOP - BOTTOM;
    let slot = (W - LEFT - 8.0) / bins.len().max(1) as f64;
    let w = |k: C| words::of(lang).class(&k);
    let students = w(C::Students);
    let title = w(C::Distribution);
    let desc: Vec<String> = bins
        .iter()
        .map(|b| format!("{} %: {} {students}", label(b), b.count))
        .collect();
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {W} {H}\" width=\"{W}\" height=\"{H}\" role=\"img\" aria-labelledby=\"hist-title hist-desc\" font-family=\"system-ui,sans-serif\" font-size=\"13\">\n\
         <title id=\"hist-title\">{}</title>\n<desc id=\"hist-desc\">{}</desc>\n",
        xml_escape(&title),
        xml_escape(&desc.join("; "))
    );
    let base = H - BOTTOM;
    out.push_str(&format!(
        "<line x1=\"{LEFT}\" y1=\"{base}\" x2=\"{}\" y2=\"{base}\" stroke=\"#333\"/>\n",
        W - 8.0
    ));
    for (i, b) in bins.iter().enumerate() {
        let h = plot_h * b.count as f64 / most;
        let x = LEFT + slot * i as f64 + 3.0;
        let mid = x + (slot - 6.0) / 2.0;
        out.push_str(&format!(
            "<rect x=\"{x:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{h:.1}\" fill=\"{BLUE}\"><title>{} %: {} {students}</title></rect>\n\
             <text x=\"{mid:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>\n\
             <text x=\"{mid:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>\n",
            base - h,
            slot - 6.0,
            label(b),
            b.count,
            base - h - 5.0,
            b.count,
            base + 18.0,
            label(b),
        ));
    }
    out.push_str(&format!(
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>\n\
         <text x=\"14\" y=\"{:.1}\" text-anchor=\"middle\" transform=\"rotate(-90 14 {:.1})\">{students}</text>\n</svg>\n",
        LEFT + (W - LEFT) / 2.0,
        H - 12.0,
        xml_escape(&w(C::ScoreAxis)),
        TOP + plot_h / 2.0,
        TOP + plot_h / 2.0,
    ));
    out
}

/// The bars as text, one line per bin (`30–40 %  ██████ 6`).
pub fn text(bins: &[Bin]) -> String {
    bins.iter()
        .map(|b| format!("{:>7} %  {} {}\n", label(b), "█".repeat(b.count), b.count))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bins(counts: &[usize]) -> Vec<Bin> {
        counts
            .iter()
            .enumerate()
            .map(|(i, &count)| Bin {
                from: 10 * i as u32,
                to: 10 * i as u32 + 10,
                count,
            })
            .collect()
    }

    #[test]
    fn the_tallest_bar_fills_the_plot_and_an_empty_bin_has_no_height() {
        let s = svg(&bins(&[0, 0, 1, 0, 0, 2, 0, 0, 4, 0]), Lang::En);
        // plot height 260 − 24 − 56 = 180 for 4 students, 45 for 1
        assert!(s.contains("height=\"180.0\""), "{s}");
        assert!(s.contains("height=\"45.0\""), "{s}");
        assert!(s.contains("height=\"0.0\""), "{s}");
        assert!(s.contains("80–90 %: 4 students"), "{s}");
        assert!(roxmltree::Document::parse(&s).is_ok(), "{s}");
    }

    #[test]
    fn text_bars() {
        assert_eq!(text(&bins(&[0, 3])), "   0–10 %   0\n  10–20 %  ███ 3\n");
    }
}
