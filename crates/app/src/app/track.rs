//! Following a target CSV in the lab (issue 21 item 5): the `gaitlab track`
//! format (header `t`, then `x,y,z` per effector in effector order, world
//! metres), picked or dropped, replaces the figure's own motion with the
//! recording, followed by the chosen IK method — or by every method of a
//! comparison, side by side. The recording stays until another preset or
//! file comes, or the person stops following it. Links do not carry it (a
//! recording can be megabytes): a link made while following one restores
//! the preset's own motion.

use gaitlab_core::export::{MAX_TARGET_CSV_BYTES, parse_target_csv};

use super::App;
use crate::lab::Effect;
use crate::lab::session::{self, LoadedTrack};
use crate::stage::Stage;

impl App {
    /// Loads a file picked or dropped: a `.csv` is a target recording to
    /// follow, anything else a preset ([`App::load_preset_file`]).
    ///
    /// # Errors
    /// `file NAME: reason`; the running figure stays.
    pub fn load_file(&mut self, name: &str, bytes: &[u8]) -> Result<(), String> {
        if name.to_ascii_lowercase().ends_with(".csv") {
            let result = self.load_targets_file(name, bytes);
            if let Err(error) = &result {
                self.report_error(error.clone());
            }
            result
        } else {
            self.load_preset_file(name, bytes)
        }
    }

    /// Follows the target CSV `bytes` (file `name`) with the running creature.
    ///
    /// # Errors
    /// `file NAME: reason` for a file too big, not text, not the format (the
    /// line and column named) or with another effector count than the
    /// creature's; the running figure stays.
    pub fn load_targets_file(&mut self, name: &str, bytes: &[u8]) -> Result<(), String> {
        if bytes.len() > MAX_TARGET_CSV_BYTES {
            return Err(format!(
                "file {name}: {} bytes, more than the {} MiB target-file limit",
                bytes.len(),
                MAX_TARGET_CSV_BYTES / (1024 * 1024)
            ));
        }
        let text =
            std::str::from_utf8(bytes).map_err(|_| format!("file {name}: not UTF-8 text"))?;
        let effectors = self.session.creature.skeleton.effector_count();
        let targets = parse_target_csv(text, effectors).map_err(|e| format!("file {name}: {e}"))?;
        let loaded = LoadedTrack {
            name: name.to_owned(),
            targets,
        };
        self.rebuild_driver(Some(loaded))
            .map_err(|e| format!("file {name}: {e}"))
    }

    /// Back to the creature's own motion.
    ///
    /// # Errors
    /// When the creature's own driver cannot be built (it ran before, so
    /// only after a setting changed); the recording stays then.
    pub fn stop_tracking(&mut self) -> Result<(), String> {
        if self.session.track.is_none() {
            return Ok(());
        }
        self.rebuild_driver(None)
    }

    /// The recording the figure follows, if any.
    #[must_use]
    pub fn tracking(&self) -> Option<&LoadedTrack> {
        self.session.track.as_ref()
    }

    /// A new driver for the running creature following `track` (or its own
    /// motion), from time 0; a comparison restarts on it.
    fn rebuild_driver(&mut self, track: Option<LoadedTrack>) -> Result<(), String> {
        let driver = session::driver_with(
            &self.session.creature,
            &self.session.settings,
            track.as_ref().map(|t| &t.targets),
        )?;
        self.stage = Stage::on_ground(driver);
        self.session.track = track;
        self.take.clear();
        self.camera.framed = false;
        self.outbox.push(Effect::LinkChanged);
        self.after_reset();
        self.rebuild_compare();
        Ok(())
    }
}
