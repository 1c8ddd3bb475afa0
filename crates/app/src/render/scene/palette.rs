//! Colours of the figure (sRGB): bones and joints by side — names starting
//! with `left` / `right`, any case, else the centre line — and effectors,
//! targets, error segments and axes by role.

/// Colour of bones and joints on the figure's centre line (sRGB).
pub const CENTRE_COLOR: [f32; 4] = [0.80, 0.81, 0.84, 1.0];
/// Colour of bones and joints whose name starts with `left` (sRGB).
pub const LEFT_COLOR: [f32; 4] = [0.36, 0.60, 0.96, 1.0];
/// Colour of bones and joints whose name starts with `right` (sRGB).
pub const RIGHT_COLOR: [f32; 4] = [0.96, 0.52, 0.34, 1.0];
/// Colour of end effectors (sRGB).
pub const EFFECTOR_COLOR: [f32; 4] = [0.98, 0.80, 0.26, 1.0];
/// Colour of IK targets (sRGB).
pub const TARGET_COLOR: [f32; 4] = [0.93, 0.16, 0.14, 1.0];
/// Colour of an IK target beyond its limb's reach (sRGB): the orange of the
/// readout's "target out of reach by N mm" (She 2006 §5.3's `d > 0`).
pub const TARGET_OUT_OF_REACH_COLOR: [f32; 4] = [0.88, 0.50, 0.25, 1.0];
/// Colour of the segment from an effector to its target (sRGB).
pub const ERROR_COLOR: [f32; 4] = [1.0, 0.33, 0.28, 1.0];
/// Colour of a revolute joint's rotation axis (sRGB).
pub const REVOLUTE_AXIS_COLOR: [f32; 4] = [0.96, 0.86, 0.22, 1.0];
/// Colour of a prismatic joint's sliding axis (sRGB).
pub const PRISMATIC_AXIS_COLOR: [f32; 4] = [0.25, 0.90, 0.90, 1.0];
/// Colours of the world x, y and z axes (sRGB).
pub const WORLD_AXIS_COLORS: [[f32; 4]; 3] = [
    [0.92, 0.22, 0.20, 1.0],
    [0.32, 0.86, 0.32, 1.0],
    [0.26, 0.48, 1.0, 1.0],
];

/// Which side of the figure a joint, bone or effector is on, read from its
/// name — the one rule the 3-D view, the plots and the Help key share
/// (issue 43 item 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The figure's left.
    Left,
    /// The figure's right.
    Right,
    /// Its centre line (trunk, spine, head, tail, a single leg).
    Centre,
}

/// Whether `name` starts with `prefix`, ignoring ASCII case.
fn starts_with_ignore_case(name: &str, prefix: &str) -> bool {
    name.as_bytes()
        .get(..prefix.len())
        .is_some_and(|head| head.eq_ignore_ascii_case(prefix.as_bytes()))
}

/// The side a word of a name marks: `left` / `l` / `l1`, `right` / `r` /
/// `r2` (any case), else none.
fn side_of_word(word: &str) -> Option<Side> {
    let (letters, digits) = word.split_at(
        word.find(|c: char| c.is_ascii_digit())
            .unwrap_or(word.len()),
    );
    if !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let letters = letters.to_ascii_lowercase();
    match letters.as_str() {
        "left" | "l" => Some(Side::Left),
        "right" | "r" => Some(Side::Right),
        _ => None,
    }
}

/// The side `name` is on: a name that starts with `left` / `right` (any case:
/// `left_knee`, `LeftUpLeg`), or has `left` / `right` as one of its words
/// (`front-left-foot`), or a word `L1`, `R3` (PODA's legs: `L1_coxa`).
#[must_use]
pub fn side_of(name: &str) -> Side {
    if starts_with_ignore_case(name, "left") {
        return Side::Left;
    }
    if starts_with_ignore_case(name, "right") {
        return Side::Right;
    }
    name.split(|c: char| !c.is_ascii_alphanumeric())
        .find_map(side_of_word)
        .unwrap_or(Side::Centre)
}

/// Colour by side ([`side_of`]).
pub(super) fn side_color(name: &str) -> [f32; 4] {
    match side_of(name) {
        Side::Left => LEFT_COLOR,
        Side::Right => RIGHT_COLOR,
        Side::Centre => CENTRE_COLOR,
    }
}

/// Plot colours by side: the side's own colour first, then three more of
/// its hue, so a plot's `left_foot` is blue as the figure's left leg is
/// (sRGB bytes). The centre's are Okabe and Ito's green, purple, yellow, grey.
pub const SIDE_SERIES_COLOURS: [[[u8; 3]; 4]; 3] = [
    [
        [92, 153, 245],
        [0x56, 0xB4, 0xE9],
        [0x00, 0x72, 0xB2],
        [0xA8, 0xC8, 0xFF],
    ],
    [
        [245, 133, 87],
        [0xE6, 0x9F, 0x00],
        [0xD5, 0x5E, 0x00],
        [0xFF, 0xC4, 0x9E],
    ],
    [
        [0x00, 0x9E, 0x73],
        [0xCC, 0x79, 0xA7],
        [0xF0, 0xE4, 0x42],
        [0x99, 0x99, 0x99],
    ],
];

/// The colour of a plot series named `name` that is the `nth` (from 0) of
/// its side among the plot's series (sRGB bytes; after four, they repeat).
#[must_use]
pub fn series_colour(name: &str, nth: usize) -> [u8; 3] {
    let family = match side_of(name) {
        Side::Left => 0,
        Side::Right => 1,
        Side::Centre => 2,
    };
    SIDE_SERIES_COLOURS[family][nth % 4]
}

/// `color` with its RGB scaled by `factor` (alpha kept).
pub(super) fn shade(color: [f32; 4], factor: f32) -> [f32; 4] {
    [
        color[0] * factor,
        color[1] * factor,
        color[2] * factor,
        color[3],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn side_from_name() {
        assert_eq!(side_color("left_knee"), LEFT_COLOR);
        assert_eq!(side_color("LeftUpLeg"), LEFT_COLOR);
        assert_eq!(side_color("right_ankle"), RIGHT_COLOR);
        assert_eq!(side_color("spine"), CENTRE_COLOR);
        assert_eq!(side_color("é"), CENTRE_COLOR);
        // PODA's legs and the physics creatures' names.
        assert_eq!(side_color("L1_coxa"), LEFT_COLOR);
        assert_eq!(side_color("R3"), RIGHT_COLOR);
        assert_eq!(side_color("front-left-upper-leg"), LEFT_COLOR);
        assert_eq!(side_color("rear-right-foot"), RIGHT_COLOR);
        assert_eq!(side_color("rear-foot"), CENTRE_COLOR);
        assert_eq!(side_color("leg-foot"), CENTRE_COLOR);
        assert_eq!(side_color("lumbar_bend"), CENTRE_COLOR);
        assert_eq!(side_color("neck_1"), CENTRE_COLOR);
        assert_eq!(side_color("L1x"), CENTRE_COLOR);
    }

    /// The plots' first colour of a side is the 3-D view's colour of it.
    #[test]
    fn a_sides_first_series_colour_is_its_figure_colour() {
        for (name, colour) in [("left_foot", LEFT_COLOR), ("right_hand", RIGHT_COLOR)] {
            let bytes = series_colour(name, 0);
            for (byte, channel) in bytes.iter().zip(colour) {
                assert!((f32::from(*byte) / 255.0 - channel).abs() < 0.003, "{name}");
            }
        }
        assert_ne!(series_colour("left_foot", 1), series_colour("left_hand", 0));
    }
}
