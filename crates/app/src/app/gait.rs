//! The lab's gait controls: the PODA gait (Girard & Maciejewski 1985: gait
//! name, eq. 7–8 gait values, eq. 9 phases, transfer trajectory, eq. 6
//! centers, body path) and the physics controllers' desired speed, hop
//! height and gains (Raibert & Hodgins 1991). Each edit goes to the engine
//! layer's driver, which validates it; the lab only routes and words errors.

use gaitlab_core::preset::Engine;
use gaitlab_engine::{Applied, EngineCommand};

use super::App;
use crate::lab::Effect;
use crate::lab::GaitShapeEdit;

impl App {
    /// Switches the PODA or physics gait (the engine layer's
    /// [`gaitlab_engine::switch_gait`], shared with the CLI's `--switch`).
    ///
    /// # Errors
    /// `gait: reason` when the engine has no gaits or the name is unknown for
    /// the creature's leg count; nothing changes.
    pub fn set_gait(&mut self, name: &str) -> Result<(), String> {
        gaitlab_engine::switch_gait(&mut self.stage.driver, name)?;
        self.outbox.push(Effect::LinkChanged);
        Ok(())
    }

    /// Sets one gait value (`period_s`, `duty_factor`, `speed_mps`,
    /// `stroke_m`, `leg_force_n`, `hop_height_m`) through the engine layer's
    /// [`gaitlab_engine::edit_value`], shared with the CLI's `--edit`; the
    /// gait model derives the others so that eq. 7–8 (and eq. 13 for the
    /// force) stay true, and [`App::gait_derived`] names what it derived.
    ///
    /// # Errors
    /// `key: reason` when the engine has no gait, the key is unknown, or the
    /// value (or a value derived from it) is out of range; nothing changes.
    pub fn edit_gait(&mut self, key: &str, value: f64) -> Result<(), String> {
        let derived = gaitlab_engine::edit_value(&mut self.stage.driver, key, value)?;
        if self.engine() == Engine::Poda {
            self.gait_derived = derived;
        }
        Ok(())
    }

    /// Restarts the physics creature at dynamic scale `scale` (Table 1's L:
    /// lengths ×L, masses ×L³, times ×√L), keeping its gait and desired
    /// speed: the running preset with `scenario.physics.scale` changed.
    ///
    /// # Errors
    /// `scale: …` when the engine is not physics or L is outside
    /// the preset's range; nothing changes.
    pub fn set_physics_scale(&mut self, scale: f64) -> Result<(), String> {
        if self.engine() != Engine::Physics {
            let engine = self.session.engine_name();
            return Err(format!("scale: engine {engine} has no dynamic scale"));
        }
        // The gait and desired speed in force, from the engine's parameter table.
        let table = gaitlab_engine::parameters(&self.session.creature, &self.stage.driver);
        let value = |key: &str| {
            table
                .iter()
                .find(|p| p.key == key)
                .map_or(serde_json::Value::Null, |p| p.value.clone())
        };
        let (gait, speed) = (
            value("scenario.physics.gait"),
            value("scenario.physics.speed_mps"),
        );
        let mut preset: serde_json::Value = serde_json::from_str(&self.session.preset_text())
            .map_err(|e| format!("scale: the running preset is not JSON ({e})"))?;
        let Some(physics) = preset
            .pointer_mut("/scenario/physics")
            .and_then(serde_json::Value::as_object_mut)
        else {
            return Err("scale: the running preset has no scenario.physics".to_owned());
        };
        physics.insert("scale".into(), scale.into());
        physics.insert("gait".into(), gait);
        physics.insert("speed_mps".into(), speed);
        let name = self.session.settings.preset.clone();
        self.set_custom_preset(&preset.to_string())
            .map_err(|e| e.replacen("preset: ", "", 1))?;
        self.session.settings.preset = name;
        Ok(())
    }

    /// Places a box `distance_m` ahead of the kangaroo, which jumps it
    /// (the engine layer's [`EngineCommand::ObstacleAhead`]).
    ///
    /// # Errors
    /// `obstacle: …` when the engine or gait has no jump, or the distance is
    /// out of range; nothing changes.
    pub fn place_obstacle(&mut self, distance_m: f64) -> Result<f64, String> {
        match self
            .stage
            .driver
            .apply(EngineCommand::ObstacleAhead(distance_m))?
        {
            Applied::Obstacle(at_m) => Ok(at_m),
            _ => Ok(distance_m),
        }
    }

    /// Pushes the physics creature: its trunk's horizontal velocity changes
    /// by `dv_mps` = `[x, z]` m/s at once ([`EngineCommand::Push`]), and its
    /// arrow is drawn.
    ///
    /// # Errors
    /// `push: …` when the engine is not physics, the creature is planar
    /// and the push sideways, or a speed is not finite within ±10 m/s;
    /// nothing changes.
    pub fn push(&mut self, dv_mps: [f64; 2]) -> Result<(), String> {
        self.stage.driver.apply(EngineCommand::Push(dv_mps))?;
        // The arrow shows at once, paused or not.
        self.refresh_scene();
        Ok(())
    }

    /// Has the physics creature follow `waypoints` (`[x, z]`, m at scale 1)
    /// from the first ([`EngineCommand::Waypoints`]).
    ///
    /// # Errors
    /// `waypoints: …` when the engine is not physics or a point is out of
    /// range; nothing changes.
    pub fn set_waypoints(&mut self, waypoints: &[[f64; 2]]) -> Result<(), String> {
        self.stage
            .driver
            .apply(EngineCommand::Waypoints(waypoints))
            .map(drop)
    }

    /// Sets a physics controller gain by name (the Gains sliders and the
    /// `gain` command).
    ///
    /// # Errors
    /// `gain: …` when the engine is not physics, `gain.NAME: reason` for an
    /// unknown gain or a negative or non-finite value; nothing changes.
    pub fn set_gain(&mut self, name: &str, value: f64) -> Result<(), String> {
        self.stage
            .driver
            .apply(EngineCommand::Gain { name, value })
            .map(drop)
    }

    /// Sets leg `leg`'s relative phase (eq. 9), the step height or the
    /// transfer key positions of the PODA gait.
    ///
    /// # Errors
    /// `key: reason` when the engine has no gait or the value is out of
    /// range; nothing changes.
    pub fn edit_gait_shape(&mut self, edit: GaitShapeEdit<'_>) -> Result<(), String> {
        let command = match edit {
            GaitShapeEdit::Phase { leg, phase } => EngineCommand::Phase { leg, phase },
            GaitShapeEdit::StepHeight(height) => EngineCommand::StepHeight(height),
            GaitShapeEdit::TransferKeys(keys) => EngineCommand::TransferKeys(keys),
        };
        self.stage.driver.apply(command).map(drop)
    }

    /// Sets a PODA leg joint's center angle (radians, or metres for prismatic
    /// joints) and gain (eq. 6).
    ///
    /// # Errors
    /// `center.…: reason`; nothing changes.
    pub fn set_center(&mut self, joint: &str, center: f64, gain: f64) -> Result<(), String> {
        self.stage
            .driver
            .apply(EngineCommand::Center {
                joint,
                center,
                gain,
            })
            .map(drop)
    }

    /// Replaces the PODA body path (the body joins it where it is closest).
    ///
    /// # Errors
    /// `path.…: reason`; nothing changes.
    pub fn set_path(&mut self, spec: &gaitlab_core::preset::PathSpec) -> Result<(), String> {
        self.stage.driver.apply(EngineCommand::Path(spec))?;
        self.refresh_scene();
        Ok(())
    }

    /// What the last gait edit derived (e.g. `support_s`, `period_s`).
    #[must_use]
    pub fn gait_derived(&self) -> &[&'static str] {
        &self.gait_derived
    }
}
