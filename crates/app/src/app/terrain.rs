//! The ground under the figure (issue 45 item 4): [`App::set_terrain`] puts
//! the running preset on a new `scenario.terrain` — the preset becomes a
//! custom one that carries its ground, so a link reopens the same ground —
//! and the walk starts again on it.

use gaitlab_core::terrain::Terrain;
use serde_json::Value;

use super::App;

impl App {
    /// The ground the running figure stands on.
    #[must_use]
    pub fn terrain(&self) -> &Terrain {
        &self.session.creature.scenario.terrain
    }

    /// Puts the running preset on `terrain` (its `scenario.terrain`) and starts the walk again on it. Nothing changes
    /// when the ground is the one already under the figure.
    ///
    /// # Errors
    /// `terrain.FIELD: reason` for a value the terrain model refuses, or
    /// the preset's `scenario.terrain: reason` when its engine cannot walk
    /// on that ground; the running figure carries on unchanged.
    pub fn set_terrain(&mut self, terrain: &Terrain) -> Result<(), String> {
        terrain.check().map_err(|e| e.to_string())?;
        if terrain == self.terrain() {
            return Ok(());
        }
        let mut preset: Value = serde_json::from_str(&self.preset_text())
            .map_err(|e| format!("terrain: the running preset does not read back: {e}"))?;
        let value = serde_json::to_value(terrain).map_err(|e| format!("terrain: {e}"))?;
        gaitlab_core::preset::set_preset_value(&mut preset, "scenario.terrain", value)
            .map_err(|e| format!("terrain: {e}"))?;
        self.set_custom_preset(&preset.to_string())?;
        self.outbox.push(crate::lab::Effect::LinkChanged);
        Ok(())
    }
}
