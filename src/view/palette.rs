//! The colour-blind-safe categorical palette of the plots and views: Okabe & Ito's eight
//! colours ("Color Universal Design", 2008), told apart with protanopia, deuteranopia and
//! tritanopia. Sequential data (heatmaps, the workspace grid) use the viridis map of
//! [`crate::view::heatmap`].
//!
//! On a white canvas orange, sky blue and yellow are light (contrast under 3:1): they serve
//! wide lines, fills or a second track, never the only mark of a thin line; black, blue,
//! vermilion, bluish green and reddish purple carry thin lines. Where two series meet and their
//! colours are close for some reader anyway, they also differ in mark (dots, squares, rings,
//! dashes) or carry a label.

/// One colour: its CSS hex text and its components.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Colour {
    pub hex: &'static str,
    pub rgb: (u8, u8, u8),
}

impl Colour {
    /// The colour of CSS hex text `hex` and components `rgb`.
    pub const fn new(hex: &'static str, rgb: (u8, u8, u8)) -> Colour {
        Colour { hex, rgb }
    }

    /// `rgba(r,g,b,alpha)` for a canvas style.
    pub fn rgba(self, alpha: f64) -> String {
        let (r, g, b) = self.rgb;
        format!("rgba({r}, {g}, {b}, {alpha})")
    }
}

pub const BLACK: Colour = Colour::new("#000000", (0, 0, 0));
pub const ORANGE: Colour = Colour::new("#E69F00", (230, 159, 0));
pub const SKY_BLUE: Colour = Colour::new("#56B4E9", (86, 180, 233));
pub const BLUISH_GREEN: Colour = Colour::new("#009E73", (0, 158, 115));
pub const YELLOW: Colour = Colour::new("#F0E442", (240, 228, 66));
pub const BLUE: Colour = Colour::new("#0072B2", (0, 114, 178));
pub const VERMILION: Colour = Colour::new("#D55E00", (213, 94, 0));
pub const REDDISH_PURPLE: Colour = Colour::new("#CC79A7", (204, 121, 167));

/// The eight, in Okabe & Ito's order.
pub const OKABE_ITO: [Colour; 8] = [
    BLACK,
    ORANGE,
    SKY_BLUE,
    BLUISH_GREEN,
    YELLOW,
    BLUE,
    VERMILION,
    REDDISH_PURPLE,
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Okabe & Ito (2008), "Color Universal Design", table of the eight colours (RGB 0-255).
    const PUBLISHED: [(&str, (u8, u8, u8)); 8] = [
        ("black", (0, 0, 0)),
        ("orange", (230, 159, 0)),
        ("sky blue", (86, 180, 233)),
        ("bluish green", (0, 158, 115)),
        ("yellow", (240, 228, 66)),
        ("blue", (0, 114, 178)),
        ("vermilion", (213, 94, 0)),
        ("reddish purple", (204, 121, 167)),
    ];

    #[test]
    fn the_palette_is_okabe_ito_and_its_hex_says_its_components() {
        for (colour, (name, rgb)) in OKABE_ITO.iter().zip(PUBLISHED) {
            assert_eq!(colour.rgb, rgb, "{name}");
            let hex = colour.hex.trim_start_matches('#');
            let parsed: Vec<u8> = (0..3)
                .filter_map(|i| u8::from_str_radix(&hex[2 * i..2 * i + 2], 16).ok())
                .collect();
            assert_eq!(parsed, vec![rgb.0, rgb.1, rgb.2], "{name}: {}", colour.hex);
        }
    }

    #[test]
    fn the_colour_blind_safe_axes_use_it() {
        use crate::view::scene3d::AxisPalette;
        let cb = AxisPalette::ColorBlindSafe.colors();
        let oi = [VERMILION, BLUISH_GREEN, BLUE].map(|c| c.hex.to_ascii_lowercase());
        assert_eq!(cb.map(str::to_ascii_lowercase), oi);
        assert_eq!(BLUE.rgba(0.1), "rgba(0, 114, 178, 0.1)");
    }
}
