//! The app: the [`Lab`] (one figure and its parts) with the features beside it
//! — the side-by-side comparison ([`crate::compare`]), the hand that grabs
//! targets ([`crate::grab`]), the Jacobian panel's figures
//! ([`crate::jacobian`]), the λ trade-off ([`crate::lambda_tradeoff`]) and
//! the history scrubber ([`rewind`]) — each holding its own state. The app
//! is what front ends drive (eframe on the web, egui_kittest natively call
//! [`App::ui`] once per frame; the JS API calls [`App::command`] and
//! [`App::state_json`]), and the one place that keeps the figures on screen
//! in step: a comparison replaces the single view's figure, so stepping,
//! resetting, redrawing and rewinding go through here.
//!
//! `App` dereferences to its [`Lab`], so panels and callers read the lab's
//! parts (settings, creature, playback, take…) directly; every operation
//! that concerns the figures on screen is an `App` method, and the lab has
//! none of the same name.

use std::ops::{Deref, DerefMut};

use crate::compare::Comparison;
use crate::grab::Grab;
use crate::jacobian::Jacobian;
use crate::lab::Lab;
use crate::lambda_tradeoff::LambdaTradeoff;
use crate::settings::Settings;

mod compare;
mod editor;
mod figures;
mod gait;
mod grab;
mod iteration;
mod lambda_tradeoff;
mod lesson;
mod paper_alone;
pub mod rewind;
mod terrain;
mod track;

/// The lab and its features, each with its own state.
pub struct App {
    /// The figure, its session, playback, plots, take and the rest of the lab's parts.
    pub(crate) lab: Lab,
    /// The side-by-side IK comparison, when one runs (it replaces the single view).
    pub(crate) compare: Option<Comparison>,
    /// The history scrubber's stored poses and keyframes.
    pub(crate) rewind: rewind::Rewind,
    /// The hand in the 3-D view: grab and pull of IK targets.
    pub(crate) grab: Grab,
    /// The Jacobian panel's figures (singular values, gains, traces).
    pub(crate) jacobian: Jacobian,
    /// The last measured λ trade-off (the Method panel's).
    pub(crate) lambda_tradeoff: Option<LambdaTradeoff>,
}

impl App {
    /// An app with `settings`; an unknown preset falls back to the default one
    /// and leaves a message.
    #[must_use]
    pub fn new(settings: Settings) -> Self {
        let mut app = Self {
            lab: Lab::new(settings),
            compare: None,
            rewind: rewind::Rewind::default(),
            grab: Grab::default(),
            jacobian: Jacobian::default(),
            lambda_tradeoff: None,
        };
        app.after_reset();
        app
    }
}

impl Deref for App {
    type Target = Lab;

    fn deref(&self) -> &Lab {
        &self.lab
    }
}

impl DerefMut for App {
    fn deref_mut(&mut self) -> &mut Lab {
        &mut self.lab
    }
}
