//! The engine contract's `apply(command)` (DESIGN.md): one typed command for
//! every live change a front end makes to a running driver — the page's
//! commands and panels, the CLI's `--switch` and `--edit` — routed to the
//! engine that takes it: a gait and eq. 7–8's gait values, eq. 9's phases,
//! the transfer trajectory, eq. 6's centres and the body path (Girard &
//! Maciejewski 1985); the desired speed and hop height, a controller gain,
//! waypoints, a box to jump and the heading (Raibert & Hodgins 1991); the
//! motion and the script's parameters (She 2006 §5.1.1). The drivers check
//! their values against the engines' parameter tables; an engine that has no
//! such value says so, naming the key.

use gaitlab_core::RootTransform;
use gaitlab_core::preset::PathSpec;
use gaitlab_core::preset::thesis::{ThesisMode, ThesisParams};
use gaitlab_motion::poda::GaitError;
use gaitlab_motion::stretch::StretchOptions;
use glam::DMat3;

use crate::AnyDriver;

/// One live change of a running driver.
#[derive(Clone, Debug, PartialEq)]
pub enum EngineCommand<'a> {
    /// Switch the PODA or physics gait by name.
    Gait(&'a str),
    /// Set one gait value: PODA's `period_s`, `duty_factor`, `speed_mps`,
    /// `stroke_m`, `leg_force_n`; physics' `speed_mps`, `hop_height_m`.
    Value {
        /// The value's command key.
        key: &'a str,
        /// The new value, in the key's unit.
        value: f64,
    },
    /// Set a physics controller gain by name.
    Gain {
        /// The gain's name (`leg_stiffness`).
        name: &'a str,
        /// Its value, ≥ 0.
        value: f64,
    },
    /// Set a PODA leg's relative phase (eq. 9), in cycles.
    Phase {
        /// The leg's index in gait order.
        leg: usize,
        /// Its phase.
        phase: f64,
    },
    /// Set PODA's step height, metres.
    StepHeight(f64),
    /// Replace PODA's transfer key positions `[along, height]`.
    TransferKeys(&'a [[f64; 2]]),
    /// Replace PODA's body path.
    Path(&'a PathSpec),
    /// Set a PODA leg joint's centre angle and gain (eq. 6).
    Center {
        /// The joint's name.
        joint: &'a str,
        /// Centre angle, radians (metres for a prismatic joint).
        center: f64,
        /// Gain in [0, 1].
        gain: f64,
    },
    /// Have the physics creature follow waypoints `[x, z]`, m at scale 1.
    Waypoints(&'a [[f64; 2]]),
    /// Place a box this far ahead of the kangaroo, which jumps it, m.
    ObstacleAhead(f64),
    /// Face this heading, radians about +y.
    Heading(f64),
    /// Push the physics creature: change its trunk's horizontal velocity
    /// by `[x, z]` m/s (world; z is forward at heading 0).
    Push([f64; 2]),
    /// Run the thesis motion `mode`.
    Mode(ThesisMode),
    /// Replace the thesis script's parameters.
    Thesis(Box<ThesisParams>),
    /// Stretch the thesis figure's targets toward full reach (the side by
    /// side's singularity scenario), or stop (`None`).
    Stretch(Option<StretchOptions>),
}

/// What a command did beyond setting its value.
#[derive(Clone, Debug, PartialEq)]
pub enum Applied {
    /// Set; nothing else follows.
    Done,
    /// Set, and the gait model derived these values (eq. 7–8, 13).
    Derived(Vec<&'static str>),
    /// A box placed this far ahead, metres.
    Obstacle(f64),
    /// Set; the motion starts again to take it (a thesis or PODA heading).
    Restart,
}

/// The engine's name as presets write it (`ik`, `poda`, `physics`).
fn engine_name(driver: &AnyDriver) -> &'static str {
    match driver {
        AnyDriver::Thesis(_) | AnyDriver::Track(_) => "ik",
        AnyDriver::Poda(_) => "poda",
        AnyDriver::Physics(_) => "physics",
    }
}

impl AnyDriver {
    /// Applies one live change (see [`EngineCommand`]).
    ///
    /// # Errors
    /// `key: reason` naming the command's key: the engine has no such value
    /// (`gain: engine poda has no controller gains`), the name is unknown,
    /// or the value (or one derived from it) is out of range; nothing
    /// changes then.
    pub fn apply(&mut self, command: EngineCommand<'_>) -> Result<Applied, String> {
        let engine = engine_name(self);
        match (command, self) {
            (EngineCommand::Gait(name), AnyDriver::Physics(physics)) => physics
                .set_gait(name)
                .map(|()| Applied::Done)
                .map_err(|e| format!("gait: {}", e.reason)),
            (EngineCommand::Gait(name), AnyDriver::Poda(poda)) => poda
                .set_gait(name)
                .map(|()| Applied::Done)
                .map_err(|e| e.to_string()),
            (EngineCommand::Gait(_), _) => {
                Err(format!("gait: engine {engine} has no gaits (use mode)"))
            }
            (EngineCommand::Value { key, value }, driver) => {
                value_edit(driver, key, value).map(Applied::Derived)
            }
            (EngineCommand::Gain { name, value }, AnyDriver::Physics(physics)) => {
                physics.set_gain(name, value).map(|()| Applied::Done)
            }
            (EngineCommand::Gain { .. }, _) => {
                Err(format!("gain: engine {engine} has no controller gains"))
            }
            (EngineCommand::Phase { leg, phase }, AnyDriver::Poda(poda)) => poda
                .gait_mut()
                .set_phase(leg, phase)
                .map(|derived| Applied::Derived(derived.derived.to_vec()))
                .map_err(|e| format!("phases[{leg}]: {}", e.reason)),
            (EngineCommand::StepHeight(height), AnyDriver::Poda(poda)) => poda
                .set_step_height(height)
                .map(|()| Applied::Done)
                .map_err(|e| e.to_string()),
            (EngineCommand::TransferKeys(keys), AnyDriver::Poda(poda)) => poda
                .set_transfer_keys(keys)
                .map(|()| Applied::Done)
                .map_err(|e| e.to_string()),
            (EngineCommand::Phase { .. } | EngineCommand::StepHeight(_), _)
            | (EngineCommand::TransferKeys(_), _) => {
                Err(format!("gait: engine {engine} has no gait"))
            }
            (
                EngineCommand::Center {
                    joint,
                    center,
                    gain,
                },
                AnyDriver::Poda(poda),
            ) => poda
                .set_center(joint, center, gain)
                .map(|()| Applied::Done)
                .map_err(|e| e.to_string()),
            (EngineCommand::Center { .. }, _) => Err(format!(
                "center: engine {engine} sets centers in its IK panel"
            )),
            (EngineCommand::Path(spec), AnyDriver::Poda(poda)) => poda
                .set_path(spec)
                .map(|()| Applied::Done)
                .map_err(|e| e.to_string()),
            (EngineCommand::Path(_), _) => Err(format!("path: engine {engine} has no body path")),
            (EngineCommand::Waypoints(points), AnyDriver::Physics(physics)) => physics
                .set_waypoints(points)
                .map(|()| Applied::Done)
                .map_err(|e| e.to_string()),
            (EngineCommand::Waypoints(_), _) => {
                Err(format!("waypoints: engine {engine} has no waypoints"))
            }
            (EngineCommand::ObstacleAhead(distance), AnyDriver::Physics(physics)) => physics
                .place_obstacle_ahead(distance)
                .map(Applied::Obstacle),
            (EngineCommand::ObstacleAhead(_), _) => {
                Err(format!("obstacle: engine {engine} has no obstacles"))
            }
            (EngineCommand::Heading(radians), AnyDriver::Physics(physics)) => {
                // A running creature turns toward the new heading.
                physics.set_heading(radians);
                Ok(Applied::Done)
            }
            (EngineCommand::Heading(radians), AnyDriver::Thesis(thesis)) => {
                thesis.set_origin(RootTransform {
                    rotation: DMat3::from_rotation_y(radians),
                    ..RootTransform::default()
                });
                Ok(Applied::Restart)
            }
            (EngineCommand::Heading(_), _) => Ok(Applied::Restart),
            (EngineCommand::Push(dv), AnyDriver::Physics(physics)) => {
                physics.push(dv).map(|()| Applied::Done)
            }
            (EngineCommand::Push(_), _) => Err(format!(
                "push: engine {engine} is not simulated; only a physics creature can be pushed"
            )),
            (EngineCommand::Mode(mode), AnyDriver::Thesis(thesis)) => {
                thesis.set_mode(mode);
                Ok(Applied::Done)
            }
            (EngineCommand::Mode(_), _) => Err(format!(
                "mode: engine {engine} has no thesis motions (use gait)"
            )),
            (EngineCommand::Thesis(params), AnyDriver::Thesis(thesis)) => thesis
                .set_params(*params)
                .map(|()| Applied::Done)
                .map_err(|e| format!("scenario.thesis.{e}")),
            (EngineCommand::Stretch(stretch), AnyDriver::Thesis(thesis)) => {
                thesis.set_stretch(stretch);
                Ok(Applied::Done)
            }
            (EngineCommand::Stretch(_), _) => Err(format!(
                "scenario: engine {engine} has no thesis targets to stretch"
            )),
            (EngineCommand::Thesis(_), _) => Err(format!(
                "scenario.thesis: engine {engine} has no thesis parameters"
            )),
        }
    }
}

/// One gait value (see [`EngineCommand::Value`]); the names of the values
/// the gait model derived.
fn value_edit(driver: &mut AnyDriver, key: &str, value: f64) -> Result<Vec<&'static str>, String> {
    let engine = engine_name(driver);
    match driver {
        AnyDriver::Physics(physics) => match key {
            "speed_mps" => physics.set_speed(value).map_err(|e| e.to_string()),
            "hop_height_m" => physics.set_hop_height(value).map_err(|e| e.to_string()),
            _ => Err(format!(
                "{key}: engine physics has no such gait value (speed_mps, hop_height_m)"
            )),
        }
        .map(|()| Vec::new()),
        AnyDriver::Poda(poda) => {
            if key == "speed_mps" {
                return poda
                    .set_speed(value)
                    .map(|derived| derived.derived.to_vec())
                    .map_err(|e| e.to_string());
            }
            if key == "leg_force_n" {
                return poda
                    .set_leg_force_n(value)
                    .map(|derived| derived.derived.to_vec())
                    .map_err(|e| GaitError::new(key, e.reason).to_string());
            }
            let gait = poda.gait_mut();
            match key {
                "period_s" => gait.set_period(value),
                "duty_factor" => gait.set_duty_factor(value),
                "stroke_m" => gait.set_stroke(value),
                _ => {
                    return Err(format!(
                        "{key}: not a gait value (period_s, duty_factor, speed_mps, stroke_m, leg_force_n)"
                    ));
                }
            }
            .map(|derived| derived.derived.to_vec())
            .map_err(|e| e.to_string())
        }
        AnyDriver::Thesis(_) | AnyDriver::Track(_) => {
            Err(format!("{key}: engine {engine} has no gait"))
        }
    }
}
