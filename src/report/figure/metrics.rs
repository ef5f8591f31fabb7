//! The page and the text on it: the page width, the labels' font metrics
//! (DejaVu Sans at 15 px), and a text placed by its anchor, with the box it
//! takes; what layout.rs lays out and place.rs places.

/// The page width in px.
pub const WIDTH: f64 = 600.0;
/// The label font size in px.
pub const FONT: f64 = 15.0;
/// How far a label's text reaches above its baseline, px (DejaVu Sans,
/// the widest of the common sans-serif fonts, at 15 px).
pub const ASCENT: f64 = 14.0;
/// How far it reaches below, px (a glyph from a fallback font, such as
/// `√`, reaches lower).
pub const DESCENT: f64 = 5.0;

/// How a label's text is anchored at its x.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at x.
    Start,
    /// The text is centred on x.
    Middle,
    /// The text ends at x.
    End,
}

/// A label or note placed on the page: its baseline's anchor point in px
/// (y down).
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// x in px.
    pub x: f64,
    /// The baseline's y in px.
    pub y: f64,
    /// How the text is anchored at x.
    pub anchor: Anchor,
    /// The text.
    pub text: String,
}

impl Placed {
    /// The box the text takes, px: left, right, top, bottom (the width
    /// estimated by [`text_width`]).
    pub fn bounds(&self) -> (f64, f64, f64, f64) {
        let w = text_width(&self.text);
        let l = match self.anchor {
            Anchor::Start => self.x,
            Anchor::Middle => self.x - w / 2.0,
            Anchor::End => self.x - w,
        };
        (l, l + w, self.y - ASCENT, self.y + DESCENT)
    }
}

/// Advance widths of DejaVu Sans (the widest common sans-serif font; the
/// SVG asks for it first), in thousandths of the font size, for the
/// printable ASCII characters from the space on.
const ASCII_WIDTH: [u16; 95] = [
    318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337, 636, 636, 636,
    636, 636, 636, 636, 636, 636, 636, 337, 337, 838, 838, 838, 531, 1000, 684, 686, 698, 770, 632,
    575, 775, 752, 295, 295, 656, 557, 863, 748, 787, 603, 787, 695, 635, 611, 732, 684, 989, 685,
    611, 685, 390, 337, 390, 838, 500, 500, 613, 635, 550, 635, 615, 352, 635, 634, 278, 278, 579,
    278, 974, 634, 612, 635, 635, 411, 521, 392, 634, 592, 818, 592, 592, 525, 636, 337, 636, 838,
];

/// The width of a text at [`FONT`] px in DejaVu Sans, px (characters
/// beyond ASCII by their DejaVu widths; an unknown one as wide as `−`).
pub fn text_width(t: &str) -> f64 {
    let em: u32 = t
        .chars()
        .map(|c| match c {
            ' '..='~' => u32::from(ASCII_WIDTH[c as usize - 32]),
            '′' => 227,
            '″' => 374,
            '·' => 318,
            '°' | '∥' => 500,
            '√' | 'β' => 637,
            'α' => 659,
            'θ' => 612,
            '…' => 1000,
            _ => 838,
        })
        .sum();
    f64::from(em) * FONT / 1000.0
}
