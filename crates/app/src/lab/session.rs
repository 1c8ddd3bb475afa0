//! The lab's session: the creature being animated, the person's settings, the
//! preset's JSON when it came from a link or a file rather than the bundle,
//! and the last problem to show; and how a creature and settings become a
//! driver (through the engine layer's one `driver_for`).

use gaitlab_core::preset::{Creature, load_bundled};
use gaitlab_engine::{AnyDriver, Overrides};

use crate::settings::Settings;

/// What a person chose and what runs.
pub struct Session {
    /// What a person chose (persisted).
    pub settings: Settings,
    /// The creature being animated.
    pub creature: Creature,
    /// JSON of a preset loaded from a link or file rather than the bundle.
    pub custom_preset: Option<String>,
    /// The last problem to show (bad link, bad command, bad preset).
    pub last_error: Option<String>,
    /// A note about the running preset: the deprecated values it uses
    /// ([`Creature::deprecations`]), which still run as the preset was made.
    pub notice: Option<String>,
    /// The teacher's lesson the lab runs, if any ([`crate::lesson`]).
    pub lesson: Option<crate::lesson::Lesson>,
    /// The recorded targets the figure follows instead of its own motion, if any.
    pub track: Option<LoadedTrack>,
}

/// A target CSV the lab follows: its file name and its targets.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedTrack {
    /// The file's name, as picked or dropped.
    pub name: String,
    /// The recorded targets (one per effector per row).
    pub targets: gaitlab_core::export::TargetTrack,
}

/// The bundled preset `name`.
///
/// # Errors
/// `no bundled preset named …`, or the bundled file's problem.
pub fn bundled(name: &str) -> Result<Creature, String> {
    match load_bundled(name) {
        Some(Ok(creature)) => Ok(creature),
        Some(Err(error)) => Err(format!("bundled preset {name}: {error}")),
        None => Err(format!("no bundled preset named {name:?}")),
    }
}

fn default_creature() -> Creature {
    match bundled(gaitlab_core::preset::DEFAULT_PRESET) {
        Ok(creature) => creature,
        // The bundled default is checked by the core's tests; this cannot happen.
        Err(error) => unreachable!("{error}"),
    }
}

/// The driver for `creature` with the person's settings, through the engine
/// layer's one `driver_for`.
///
/// # Errors
/// `settings.PATH: reason` for a bad setting, `preset NAME: PATH: reason` for
/// a creature that cannot drive.
pub fn driver_for(creature: &Creature, settings: &Settings) -> Result<AnyDriver, String> {
    driver_with(creature, settings, None)
}

/// As [`driver_for`], following `track`'s recorded targets (or the
/// creature's own motion when `None`).
///
/// # Errors
/// As [`driver_for`]; `preset NAME: targets: …` when the recording does not
/// fit the skeleton.
pub fn driver_with(
    creature: &Creature,
    settings: &Settings,
    track: Option<&gaitlab_core::export::TargetTrack>,
) -> Result<AnyDriver, String> {
    let overrides = Overrides {
        mode: Some(settings.mode),
        method: Some(settings.method),
        ik: Some(settings.ik.clone()),
        heading_deg: Some(settings.heading_deg),
        tracking: track.map(|targets| gaitlab_engine::Tracking {
            targets: targets.clone(),
            iterations_per_frame: None,
        }),
        ..Overrides::default()
    };
    gaitlab_engine::driver_for(creature, &overrides).map_err(|e| {
        if e.path.starts_with("ik") || e.path == "heading_deg" {
            format!("settings.{e}")
        } else {
            format!("preset {}: {e}", creature.name)
        }
    })
}

impl Session {
    /// A session with `settings` and its driver; an unknown preset falls back
    /// to the default one and settings that cannot drive to the defaults, each
    /// leaving a message.
    #[must_use]
    pub fn start(settings: Settings) -> (Self, AnyDriver) {
        let mut settings = settings;
        let mut last_error = None;
        let mut creature = match bundled(&settings.preset) {
            Ok(creature) => creature,
            Err(error) => {
                last_error = Some(error);
                settings.preset = gaitlab_core::preset::DEFAULT_PRESET.to_owned();
                default_creature()
            }
        };
        let driver = match driver_for(&creature, &settings) {
            Ok(driver) => driver,
            Err(error) => {
                last_error = Some(error);
                // Back to the default preset with default settings: the
                // creature and its driver must stay one figure.
                settings = Settings::default();
                creature = default_creature();
                match driver_for(&creature, &settings) {
                    Ok(driver) => driver,
                    Err(error) => unreachable!("the default preset drives: {error}"),
                }
            }
        };
        let session = Self {
            settings,
            creature,
            custom_preset: None,
            last_error,
            notice: None,
            lesson: None,
            track: None,
        };
        (session, driver)
    }

    /// The running preset's JSON: the custom text, or the bundled file.
    #[must_use]
    pub fn preset_text(&self) -> String {
        match &self.custom_preset {
            Some(json) => json.clone(),
            None => gaitlab_core::preset::bundled_json(&self.settings.preset)
                .map(str::to_owned)
                .unwrap_or_default(),
        }
    }

    /// The engine's name, for messages.
    #[must_use]
    pub fn engine_name(&self) -> &'static str {
        self.creature.scenario.engine.name()
    }
}
