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

/// Whether `name` starts with `prefix`, ignoring ASCII case.
fn starts_with_ignore_case(name: &str, prefix: &str) -> bool {
    name.as_bytes()
        .get(..prefix.len())
        .is_some_and(|head| head.eq_ignore_ascii_case(prefix.as_bytes()))
}

/// Colour by side: names starting with `left` / `right` (any case: `left_knee`,
/// `LeftUpLeg`) are the figure's left / right.
pub(super) fn side_color(name: &str) -> [f32; 4] {
    if starts_with_ignore_case(name, "left") {
        LEFT_COLOR
    } else if starts_with_ignore_case(name, "right") {
        RIGHT_COLOR
    } else {
        CENTRE_COLOR
    }
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
    }
}
