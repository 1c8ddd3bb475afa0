//! The colour scheme (issue 6 "Comfort": a light/dark theme that follows the
//! system preference by default). The panels take egui's light or dark
//! visuals; the 3-D view picks its background, ground and grid colours from
//! them ([`crate::render::gpu::ViewStyle::from_visuals`]).

use serde::{Deserialize, Serialize};

/// The colour of a problem the lab reports (a refused edit, an error).
pub const PROBLEM_COLOR: egui::Color32 = egui::Color32::from_rgb(230, 90, 70);

/// The colour of a warning (a value outside what was tested, an unstable walk).
pub const WARNING_COLOR: egui::Color32 = egui::Color32::from_rgb(230, 140, 40);

/// The colour of a range known to hold (a slider's tested band): Okabe and
/// Ito's bluish green, apart from the warning's orange for colour-blind eyes.
pub const TESTED_COLOR: egui::Color32 = egui::Color32::from_rgb(0, 158, 115);

/// The colour scheme (issue 6 "Comfort": light/dark theme, following the
/// system preference by default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Theme {
    /// Whatever the system (the browser's `prefers-color-scheme`) says.
    #[default]
    System,
    /// Light panels and a light 3-D view.
    Light,
    /// Dark panels and a dark 3-D view.
    Dark,
}

impl Theme {
    /// Every theme, in menu order.
    pub const ALL: [Self; 3] = [Self::System, Self::Light, Self::Dark];

    /// Name used in commands, state and settings.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::System => "system",
            Self::Light => "light",
            Self::Dark => "dark",
        }
    }

    /// Menu label.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::System => "System",
            Self::Light => "Light",
            Self::Dark => "Dark",
        }
    }

    /// The theme named `name`.
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == name)
    }

    /// egui's preference for this theme.
    #[must_use]
    pub fn preference(self) -> egui::ThemePreference {
        match self {
            Self::System => egui::ThemePreference::System,
            Self::Light => egui::ThemePreference::Light,
            Self::Dark => egui::ThemePreference::Dark,
        }
    }
}
