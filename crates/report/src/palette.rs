//! The figures' colours: one index, one configuration, in every figure of a study — the categorical palette of
//! Okabe & Ito (2008) without its yellow, or Tableau 10 for ten members told apart by hue — and the grey (black)
//! of reference lines.

use plotters::prelude::*;
use serde::Serialize;

/// The colour index of reference lines, not configurations: grey in the categorical palette, black in
/// [`Palette::Ten`] (whose index 7 is a train's grey, HSLM-A8, which a grey limit line could not be told from).
pub const GREY: usize = usize::MAX;

/// How a figure maps colour indices to colours.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub enum Palette {
    /// One distinct colour per configuration ([`color`]): 0 = no friction, black.
    #[default]
    Categorical,
    /// Ten members told apart by hue (Tableau 10, matplotlib's default cycle; `TEN`), e.g. HSLM-A1 … A10 drawn
    /// together: a sequential map left neighbours alike (A5 … A8) and seven colours made three trains repeat. Indices
    /// from 10 on take the categorical colour of i − 10.
    Ten,
}

impl Palette {
    /// The colour of index `i`.
    pub fn color(self, i: usize) -> RGBColor {
        match self {
            Palette::Categorical if i == GREY => color(7),
            Palette::Ten if i == GREY => BLACK,
            Palette::Categorical => color(i),
            Palette::Ten if i < TEN.len() => {
                let (r, g, b) = TEN[i];
                RGBColor(r, g, b)
            }
            Palette::Ten => color(i - TEN.len()),
        }
    }
}

/// Okabe–Ito colours without yellow: black, orange, sky blue, bluish green, blue, vermillion, reddish purple, grey.
const PALETTE: [(u8, u8, u8); 8] = [
    (0, 0, 0),
    (230, 159, 0),
    (86, 180, 233),
    (0, 158, 115),
    (0, 114, 178),
    (213, 94, 0),
    (204, 121, 167),
    (128, 128, 128),
];

/// Tableau 10: blue, orange, green, red, purple, brown, pink, grey, olive, cyan.
const TEN: [(u8, u8, u8); 10] = [
    (31, 119, 180),
    (255, 127, 14),
    (44, 160, 44),
    (214, 39, 40),
    (148, 103, 189),
    (140, 86, 75),
    (227, 119, 194),
    (127, 127, 127),
    (188, 189, 34),
    (23, 190, 207),
];

/// The colour of index `i` (cycling through the palette).
pub fn color(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}
