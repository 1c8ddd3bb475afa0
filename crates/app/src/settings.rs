//! The lab's persisted settings: what a person chose in the panels, saved across
//! reloads (eframe storage) and mirrored in links.

use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::ThesisMode;
use serde::{Deserialize, Serialize};

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
    /// IK options (λ, γmax, step clamp, null-space gain, limits); `method` here mirrors `method`.
    pub ik: IkOptions,
    /// 3-D view options.
    pub view: ViewOptions,
    /// Figure heading, degrees about the vertical axis (She 2006 §6.2 "Object transformation").
    pub heading_deg: f64,
    /// Show the error and joint-angle plots.
    pub plots: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            preset: gaitlab_core::preset::DEFAULT_PRESET.to_owned(),
            mode: ThesisMode::Walk,
            method: Method::Sdls,
            ik: IkOptions::default(),
            view: ViewOptions::default(),
            heading_deg: 0.0,
            plots: true,
        }
    }
}
