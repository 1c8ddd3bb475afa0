//! The lab's persisted settings: what a person chose in the panels, saved across
//! reloads (eframe storage) and mirrored in links.

use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::ThesisMode;
use serde::{Deserialize, Serialize};

use crate::theme::Theme;
use crate::view::ViewOptions;

/// Settings kept across reloads. Unknown or damaged stored settings fall back to
/// [`Settings::default`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    /// Bundled preset name.
    pub preset: String,
    /// Thesis motion.
    pub mode: ThesisMode,
    /// IK method.
    pub method: Method,
    /// IK options (λ, γmax, step clamp, null-space gain, limits); `method` here
    /// mirrors `method`. Default: the default preset's own (`scenario.ik`).
    pub ik: IkOptions,
    /// 3-D view options.
    pub view: ViewOptions,
    /// Figure heading, degrees about the vertical axis (She 2006 §6.2 "Object transformation").
    pub heading_deg: f64,
    /// Show the error and joint-angle plots.
    pub plots: bool,
    /// Joints whose angles are plotted, by name (empty: the hips and knees).
    pub plot_joints: Vec<String>,
    /// Frame size of video recordings of the 3-D view.
    pub video_size: VideoSize,
    /// Seconds at the end of the take that "Save BVH" / "Save CSV" write; 0 writes the whole take.
    pub export_last_s: f64,
    /// Light, dark, or the system's colour scheme.
    pub theme: Theme,
}

/// Frame size of a video recording (She 2006 §6.2: "users can set the frame size").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum VideoSize {
    /// The 3-D view's own size on screen.
    #[default]
    View,
    /// 640 × 360.
    P360,
    /// 1280 × 720.
    P720,
    /// 1920 × 1080.
    P1080,
}

impl VideoSize {
    /// Every size, in menu order.
    pub const ALL: [Self; 4] = [Self::View, Self::P360, Self::P720, Self::P1080];

    /// Width and height in pixels, or `None` for the view's own size.
    #[must_use]
    pub fn pixels(self) -> Option<(u32, u32)> {
        match self {
            Self::View => None,
            Self::P360 => Some((640, 360)),
            Self::P720 => Some((1280, 720)),
            Self::P1080 => Some((1920, 1080)),
        }
    }

    /// Name used in commands and settings.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::View => "view",
            Self::P360 => "p360",
            Self::P720 => "p720",
            Self::P1080 => "p1080",
        }
    }

    /// Menu label.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::View => "View size",
            Self::P360 => "640 × 360",
            Self::P720 => "1280 × 720",
            Self::P1080 => "1920 × 1080",
        }
    }

    /// The size named `name`.
    #[must_use]
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// The default preset's IK options (a `gaitlab-preset/1` file's, so the
/// solver settings it was made with), or the code's defaults should it not
/// load (the core's tests check that it does).
fn default_preset_ik() -> IkOptions {
    gaitlab_core::preset::load_bundled(gaitlab_core::preset::DEFAULT_PRESET)
        .and_then(Result::ok)
        .map_or_else(IkOptions::default, |creature| creature.scenario.ik)
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            preset: gaitlab_core::preset::DEFAULT_PRESET.to_owned(),
            mode: ThesisMode::Walk,
            method: Method::Sdls,
            ik: default_preset_ik(),
            view: ViewOptions::default(),
            heading_deg: 0.0,
            plots: true,
            plot_joints: Vec::new(),
            video_size: VideoSize::View,
            export_last_s: 0.0,
            theme: Theme::System,
        }
    }
}
