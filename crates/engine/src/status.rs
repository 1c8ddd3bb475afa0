//! The running engine's state as the page's `state()` shows it (the engine
//! contract's readout, DESIGN.md): the physics controller's figures
//! (Raibert & Hodgins 1991: Figure 4's state, eq. 3's desired speed, eq. 2's
//! hop height, Table 1's scale, Table 2's figures) and the PODA gait's values
//! (Girard & Maciejewski 1985: eq. 7–9, 12–13, the body path, static
//! stability).

use serde::Serialize;

use crate::AnyDriver;

/// `physics`: the Raibert & Hodgins controller's figures (physics engine only).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PhysicsState {
    /// The physical model's name.
    pub model: &'static str,
    /// The model's scale.
    pub scale: f64,
    /// The controller's phase.
    pub phase: &'static str,
    /// Desired speed, m/s.
    pub speed_desired_mps: f64,
    /// Hop height set, metres.
    pub hop_height_m: Option<f64>,
    /// Heading, degrees.
    pub heading_deg: f64,
    /// The path's current waypoint.
    pub waypoint: usize,
    /// The path being followed, `[x, z]` per waypoint, metres at scale 1.
    pub waypoints: Vec<[f64; 2]>,
    /// The centre of mass on the ground, `[x, z]`, metres.
    pub position_m: [f64; 2],
    /// Mean speed, m/s.
    pub speed_mean_mps: f64,
    /// Whether it fell.
    pub fell: bool,
    /// Times it was put back after a fall.
    pub resets: u32,
    /// Its pushes (`push_mps`), each with whether it recovered.
    pub pushes: Vec<crate::metrics::PushEntry>,
    /// Body height, metres.
    pub height_m: f64,
    /// Body pitch, degrees.
    pub pitch_deg: f64,
    /// Body roll, degrees.
    pub roll_deg: f64,
    /// Stride length, metres.
    pub stride_length_m: f64,
    /// Stride duration, seconds.
    pub stride_duration_s: f64,
    /// Flight duration, seconds.
    pub flight_duration_s: f64,
    /// Stance duration, seconds.
    pub stance_duration_s: f64,
    /// Highest friction coefficient needed.
    pub friction_needed_max: f64,
    /// Simulation steps taken.
    pub steps: u64,
    /// Controller gains by name.
    pub gains: std::collections::BTreeMap<String, f64>,
}

/// `poda`: the PODA gait's values (PODA engine only).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct PodaState {
    /// Cycle period P, seconds.
    pub period_s: f64,
    /// Duty factor β.
    pub duty_factor: f64,
    /// Body speed, m/s.
    pub speed_mps: f64,
    /// Stroke, metres.
    pub stroke_m: f64,
    /// Leg force, newtons.
    pub leg_force_n: f64,
    /// Support time, seconds.
    pub support_s: f64,
    /// Transfer time, seconds.
    pub transfer_s: f64,
    /// Leg phases, cycles.
    pub phases: Vec<f64>,
    /// Step height, metres.
    pub step_height_m: f64,
    /// Transfer curve keys, `[[along, height], …]`.
    pub transfer_keys: Vec<[f64; 2]>,
    /// The body path.
    pub path: gaitlab_core::preset::PathSpec,
    /// Whether some leg has not yet taken on the gait (a switch or edit
    /// being taken on leg by leg, at each leg's mid-stance).
    pub blending: bool,
    /// The legs' names.
    pub legs: Vec<String>,
    /// Largest foot slip in support, metres.
    pub foot_slip_max_m: f64,
    /// Largest distance of the body from its path, metres (corners it cut).
    pub path_error_max_m: f64,
    /// What the last gait edit derived.
    pub derived: Vec<&'static str>,
    /// Feet on the ground now.
    pub feet_down: usize,
    /// The body centre's static stability margin over the support polygon
    /// now, metres (negative: outside it); null in flight.
    pub stability_margin_m: Option<f64>,
    /// Share of the last gait period the body stood statically unstable (0–1).
    pub unstable_share: f64,
    /// Whether the gait panel warns that the walk is statically unstable.
    pub stability_warning: bool,
}

impl AnyDriver {
    /// The PODA or physics gait running (`None` for the thesis' motions).
    #[must_use]
    pub fn gait_name(&self) -> Option<&str> {
        match self {
            AnyDriver::Poda(d) => Some(d.gait_name()),
            AnyDriver::Physics(d) => Some(d.gait()),
            AnyDriver::Thesis(_) | AnyDriver::Track(_) => None,
        }
    }

    /// The physics controller's figures; `None` for other engines.
    #[must_use]
    pub fn physics_state(&self) -> Option<PhysicsState> {
        let AnyDriver::Physics(driver) = self else {
            return None;
        };
        let s = driver.summary();
        let probe = driver.probe();
        let com = driver.centre_of_mass();
        Some(PhysicsState {
            model: driver.params().model.name(),
            scale: driver.params().scale,
            phase: driver.phase_name(),
            speed_desired_mps: driver.params().speed_mps,
            hop_height_m: driver.params().hop_height_m,
            heading_deg: driver.heading().to_degrees(),
            waypoint: driver.waypoint(),
            waypoints: driver.waypoints().to_vec(),
            position_m: [com.x, com.z],
            speed_mean_mps: s.speed_mean_mps,
            fell: s.fell,
            resets: driver.resets(),
            pushes: crate::metrics::push_entries(driver),
            height_m: probe.height_m,
            pitch_deg: probe.pitch_deg,
            roll_deg: probe.roll_deg,
            stride_length_m: s.stride_length_m,
            stride_duration_s: s.stride_duration_s,
            flight_duration_s: s.flight_duration_s,
            stance_duration_s: s.stance_duration_s,
            friction_needed_max: s.friction_needed_max,
            steps: driver.sim().steps,
            gains: driver
                .gains()
                .iter()
                .map(|g| (g.name.to_owned(), g.value))
                .collect(),
        })
    }

    /// The PODA gait's values, with what the last edit `derived` and whether
    /// the unstable share passes `warning_share`; `None` for other engines.
    #[must_use]
    pub fn poda_state(&self, derived: &[&'static str], warning_share: f64) -> Option<PodaState> {
        let AnyDriver::Poda(driver) = self else {
            return None;
        };
        let gait = driver.gait();
        let stability = driver.stability();
        Some(PodaState {
            period_s: gait.period_s(),
            duty_factor: gait.duty_factor(),
            speed_mps: gait.speed_mps(),
            stroke_m: gait.stroke_m(),
            leg_force_n: driver.leg_force_n(),
            support_s: gait.support_s(),
            transfer_s: gait.transfer_s(),
            phases: gait.phases().to_vec(),
            step_height_m: driver.params().step_height_m,
            transfer_keys: driver.params().transfer_keys.clone(),
            path: driver.path().to_spec(),
            blending: driver.is_shifting(),
            legs: driver.leg_names().map(str::to_owned).collect(),
            foot_slip_max_m: driver.metrics().foot_slip_max_m(),
            path_error_max_m: driver.path_error_max_m(),
            derived: derived.to_vec(),
            feet_down: stability.feet_down,
            stability_margin_m: stability.margin_m,
            unstable_share: stability.unstable_share,
            stability_warning: stability.unstable_share > warning_share,
        })
    }
}
