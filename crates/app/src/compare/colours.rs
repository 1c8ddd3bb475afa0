//! Each comparison view's colour (issue 21 items 1 and 7): its card's plot
//! line and swatch and its figure in the overlay. Four of Okabe and Ito's
//! colour-blind-safe colours — orange, sky blue, bluish green, reddish purple —
//! chosen to stay apart from the targets' red and out-of-reach orange-red.

/// The views' colours, sRGB bytes, in view order (a fifth view would repeat).
pub const VIEW_COLOURS: [[u8; 3]; 4] = [
    [0xE6, 0x9F, 0x00],
    [0x56, 0xB4, 0xE9],
    [0x00, 0x9E, 0x73],
    [0xCC, 0x79, 0xA7],
];

/// View `i`'s colour for egui.
#[must_use]
pub fn view_colour(i: usize) -> egui::Color32 {
    let [r, g, b] = VIEW_COLOURS[i % VIEW_COLOURS.len()];
    egui::Color32::from_rgb(r, g, b)
}

/// View `i`'s colour for the scene (sRGB, 0–1, opaque).
#[must_use]
pub fn view_colour_srgb(i: usize) -> [f32; 4] {
    let [r, g, b] = VIEW_COLOURS[i % VIEW_COLOURS.len()];
    [
        f32::from(r) / 255.0,
        f32::from(g) / 255.0,
        f32::from(b) / 255.0,
        1.0,
    ]
}
