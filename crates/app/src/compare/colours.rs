//! Each IK method's colour in a comparison (issue 21 items 1 and 7; issue 43
//! item 2): its card's swatch and plot line, its bars and its figure in the
//! overlay — the same colour whichever view it runs in. Okabe and Ito's
//! colour-blind-safe colours, kept apart from the targets' red and the
//! out-of-reach orange-red; CCD, outside the thesis, in brown.

use super::method::CompareMethod;

/// The colour of each method of [`CompareMethod::ALL`], in that order (sRGB bytes).
pub const METHOD_COLOURS: [[u8; 3]; 7] = [
    [0xE6, 0x9F, 0x00], // transpose: orange
    [0x56, 0xB4, 0xE9], // pinv: sky blue
    [0x00, 0x9E, 0x73], // dls: bluish green
    [0xCC, 0x79, 0xA7], // sdls: reddish purple
    [0x00, 0x72, 0xB2], // pinv-ns: blue
    [0xF0, 0xE4, 0x42], // dls-ns: yellow
    [0xA6, 0x76, 0x3C], // ccd: brown
];

/// `method`'s colour (sRGB bytes).
#[must_use]
pub fn method_colour(method: CompareMethod) -> [u8; 3] {
    let k = CompareMethod::ALL
        .iter()
        .position(|&m| m == method)
        .unwrap_or(0);
    METHOD_COLOURS[k]
}

/// The views' colours: each its method's; a method run in a second view
/// (two λ of DLS, say) takes there the first method colour no view uses.
#[must_use]
pub fn colours_for(views: &[CompareMethod]) -> Vec<[u8; 3]> {
    let mut spare = METHOD_COLOURS
        .iter()
        .copied()
        .filter(|c| !views.iter().any(|&m| method_colour(m) == *c));
    views
        .iter()
        .enumerate()
        .map(|(i, &m)| {
            if views[..i].contains(&m) {
                spare.next().unwrap_or(method_colour(m))
            } else {
                method_colour(m)
            }
        })
        .collect()
}

/// sRGB bytes as an egui colour.
#[must_use]
pub fn colour32([r, g, b]: [u8; 3]) -> egui::Color32 {
    egui::Color32::from_rgb(r, g, b)
}

/// sRGB bytes as the scene's colour (0–1, opaque).
#[must_use]
pub fn colour_srgb([r, g, b]: [u8; 3]) -> [f32; 4] {
    [
        f32::from(r) / 255.0,
        f32::from(g) / 255.0,
        f32::from(b) / 255.0,
        1.0,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A method keeps its colour whatever its slot; a repeated method gets a
    /// colour of its own.
    #[test]
    fn a_method_keeps_its_colour_in_any_slot() {
        use CompareMethod::{Dls, Pinv, Sdls, Transpose};
        let four = colours_for(&[Transpose, Pinv, Dls, Sdls]);
        let two = colours_for(&[Pinv, Dls]);
        assert_eq!(two[0], four[1]);
        assert_eq!(two[1], four[2]);
        assert_eq!(colours_for(&[Dls, Pinv]), vec![four[2], four[1]]);
        let twice = colours_for(&[Dls, Dls]);
        assert_eq!(twice[0], method_colour(Dls));
        assert_ne!(twice[1], twice[0]);
        let mut all = METHOD_COLOURS.to_vec();
        all.sort_unstable();
        all.dedup();
        assert_eq!(all.len(), METHOD_COLOURS.len());
    }
}
