//! The 3-D view's theme colours (background, ground, grid), chosen to sit
//! well with egui's dark or light theme.

/// Theme colours of the 3-D view (sRGB).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewStyle {
    /// Behind everything; the ground fades into it.
    pub background: [f32; 4],
    /// The ground plane.
    pub ground: [f32; 4],
    /// Grid lines.
    pub grid: [f32; 4],
}

impl ViewStyle {
    /// Colours that sit well with egui's dark or light theme.
    #[must_use]
    pub fn from_visuals(visuals: &egui::Visuals) -> Self {
        if visuals.dark_mode {
            Self {
                background: [0.105, 0.115, 0.135, 1.0],
                ground: [0.165, 0.175, 0.195, 1.0],
                grid: [0.33, 0.35, 0.40, 1.0],
            }
        } else {
            Self {
                background: [0.86, 0.88, 0.91, 1.0],
                ground: [0.79, 0.81, 0.84, 1.0],
                grid: [0.60, 0.63, 0.68, 1.0],
            }
        }
    }
}
