//! The PODA driver (Girard & Maciejewski 1985, "Modeling the Kinematics of
//! Legged Locomotion"): a fixed model (`model.rs`: legs, keys, rest pose,
//! stand height, path), a changing state (`state.rs`), and each frame the
//! stages of `stages/` as functions of the two, in order:
//! `body → leg_states → footholds → foot_targets → ik`.
//! - **body**: the ground-plane pose planned ahead by [`BodyTrack`] (eq.
//!   14–15 and yaw), raised by the superposition of each leg's vertical
//!   push / fall / restore (eq. 12–13), pitched (Figure 2) and surged;
//! - **leg_states**: eq. 9 for every leg until the gait changes; from then
//!   each leg's own cycles ([`super::leg_cycles`]), which take a change on at
//!   each leg's mid-stance, with the body kept within
//!   [`super::transition`]'s bounds while they do;
//! - **footholds**: eq. 11 at each lift-off;
//! - **foot_targets**: planted feet (eq. 10) and the transfer spline
//!   through the key leg positions;
//! - **ik**: the key positions' centre angles ([`super::key_centers`]) and
//!   every leg by pseudoinverse with null-space centering (eq. 5–6).
//!
//! Live edits are events (`edits.rs`): a setter queues what it
//! changed and the stage that takes it on consumes it at the next frame.
//! On a path with speeds (`scenario.poda.path.speeds_mps`) the gait takes
//! on the desired speed where the desired point is whenever a leg reaches
//! mid-stance, as a speed edit does (stroke kept, period derived; with gait
//! by speed the gait and stride follow), and the legs take it on one by one
//! (`gait_edit.rs`).

use std::sync::Arc;

use gaitlab_core::driver::{Driver, IkFrameReport};
use gaitlab_core::ik::Targets;
use gaitlab_core::preset::poda::{KeyCenters, check_transfer_key_centers};
use gaitlab_core::preset::{Creature, PathSpec, PodaParams, check_transfer_keys};
use gaitlab_core::{Pose, Skeleton};
use glam::{DVec2, DVec3};

use super::body_track::BodyTrack;
use super::gait::{Derived, GaitError, GaitParams};
use super::gait_edit::{adopt, apply_speed, follow_path_speed, take_on};
use super::gait_metrics::GaitMetrics;
use super::gaits::named_gait;
use super::ground_pose::GroundPose;
use super::key_centers;
use super::measure;
pub use super::model::GRAVITY_MPS2;
use super::model::{PodaModel, spline_keys};
use super::path::BodyPath;
use super::speed_gait::check_path_speeds;
use super::stability::StabilityReport;
use super::stages::{body, footholds, ik, legs, targets};
use super::start::restart;
use super::state::PodaState;
use crate::DriverError;

/// Animates a creature with PODA's gait model, footholds and foot splines.
#[derive(Clone, Debug)]
pub struct PodaDriver {
    /// What the stages read: changed only by the setters.
    model: PodaModel,
    /// What the stages write.
    state: PodaState,
}

impl PodaDriver {
    /// A driver for `creature` with its preset's PODA scenario.
    ///
    /// # Errors
    /// A [`DriverError`] naming the scenario value that cannot be used (an
    /// unknown gait for the leg count, gait values out of range, a bad path).
    pub fn new(creature: &Creature) -> Result<Self, DriverError> {
        Self::with_params(creature, creature.scenario.poda_params())
    }

    /// A driver for `creature` with `params` instead of the preset's.
    ///
    /// # Errors
    /// As [`PodaDriver::new`].
    pub fn with_params(creature: &Creature, params: PodaParams) -> Result<Self, DriverError> {
        let (model, gait_name, gait) = PodaModel::new(creature, params)?;
        let state = PodaState::new(creature, &model, gait_name, gait);
        check_path_speeds(&model, &state, &model.path, "scenario.poda.path.speeds_mps")?;
        let mut driver = Self { model, state };
        driver.reset();
        Ok(driver)
    }

    /// The gait model (period, duty factor, phases, stroke, speed).
    #[must_use]
    pub fn gait(&self) -> &GaitParams {
        &self.state.gait
    }

    /// Mutable gait model: edits keep eq. 7–8 true and take effect at the
    /// next frame (the call queues a gait edit, taken on then).
    pub fn gait_mut(&mut self) -> &mut GaitParams {
        self.state.edits.gait_edited(&self.state.gait);
        &mut self.state.gait
    }

    /// The PODA parameters in use (legs, step height, transfer keys, dynamics).
    #[must_use]
    pub fn params(&self) -> &PodaParams {
        &self.model.params
    }

    /// Each supporting leg's upward force at this gait, newtons: the force
    /// whose average over the cycle carries the body's weight (eq. 12–13 with
    /// the body's mass and [`GRAVITY_MPS2`]).
    #[must_use]
    pub fn leg_force_n(&self) -> f64 {
        self.state
            .gait
            .leg_force_for_balance_n(self.model.params.body_mass_kg, GRAVITY_MPS2)
    }

    /// One leg's share of the body's weight, newtons (`m·g / legs`): a leg
    /// force must exceed it (eq. 12's `a = F/m − g_n` > 0).
    #[must_use]
    pub fn weight_share_n(&self) -> f64 {
        self.state.gait.gravity_share_mps2(GRAVITY_MPS2) * self.model.params.body_mass_kg
    }

    /// Sets the support-phase leg force, newtons (see
    /// [`GaitParams::set_leg_force`]); the gait derives period and duty factor.
    ///
    /// # Errors
    /// `force_n` not above [`PodaDriver::weight_share_n`], or a derived value
    /// would leave its range; nothing changes.
    pub fn set_leg_force_n(&mut self, force_n: f64) -> Result<Derived, GaitError> {
        let mass_kg = self.model.params.body_mass_kg;
        self.gait_mut()
            .set_leg_force(force_n, mass_kg, GRAVITY_MPS2)
    }

    /// Sets the gait period `P`, seconds, as [`GaitParams::set_period`]
    /// does (duty factor and speed kept); the legs take it on one by one.
    ///
    /// # Errors
    /// As [`GaitParams::set_period`]; nothing changes.
    pub fn set_period(&mut self, period_s: f64) -> Result<Derived, GaitError> {
        self.gait_mut().set_period(period_s)
    }

    /// Sets the duty factor `β`, as [`GaitParams::set_duty_factor`] does
    /// (period and speed kept); the legs take it on one by one.
    ///
    /// # Errors
    /// As [`GaitParams::set_duty_factor`]; nothing changes.
    pub fn set_duty_factor(&mut self, duty_factor: f64) -> Result<Derived, GaitError> {
        self.gait_mut().set_duty_factor(duty_factor)
    }

    /// Sets the stroke, metres, as [`GaitParams::set_stroke`] does (speed
    /// and duty factor kept); the body plans its track anew.
    ///
    /// # Errors
    /// As [`GaitParams::set_stroke`]; nothing changes.
    pub fn set_stroke(&mut self, stroke_m: f64) -> Result<Derived, GaitError> {
        self.gait_mut().set_stroke(stroke_m)
    }

    /// Sets leg `leg`'s relative phase `R_i`, as [`GaitParams::set_phase`]
    /// does; the legs take it on one by one.
    ///
    /// # Errors
    /// As [`GaitParams::set_phase`]; nothing changes.
    pub fn set_phase(&mut self, leg: usize, phase: f64) -> Result<Derived, GaitError> {
        self.gait_mut().set_phase(leg, phase)
    }

    /// Sets the body speed, m/s. With `scenario.poda.gait_by_speed` the gait
    /// and its period follow from the Froude number
    /// ([`super::gait_by_speed`]) and the legs take them on one by one;
    /// otherwise as [`GaitParams::set_speed`] (stroke kept, period derived).
    ///
    /// # Errors
    /// The speed, or a value derived from it, out of range; `speed_mps` while
    /// the body path carries its own speeds (`path.speeds_mps`: they set the
    /// speed); nothing changes.
    pub fn set_speed(&mut self, speed_mps: f64) -> Result<Derived, GaitError> {
        if self.model.path.speeds_mps().is_some() {
            return Err(GaitError::new(
                "speed_mps",
                "the body path sets the speed (path.speeds_mps): edit the path's speeds, \
                 or set a path without them",
            ));
        }
        apply_speed(&self.model, &mut self.state, speed_mps)
    }

    /// Sets the highest point of the transfer trajectory above the ground.
    ///
    /// # Errors
    /// `step_height_m` unless it is a number of metres in (0, 5].
    pub fn set_step_height(&mut self, step_height_m: f64) -> Result<(), DriverError> {
        gaitlab_core::params::row(
            gaitlab_core::preset::PODA_PARAMS,
            "scenario.poda.step_height_m",
        )
        .check_real("step_height_m", step_height_m)
        .map_err(|e| DriverError::new("step_height_m", e.reason))?;
        self.model.params.step_height_m = step_height_m;
        Ok(())
    }

    /// Replaces the key leg positions of the transfer trajectory, each
    /// `[along, height]` (step fraction strictly increasing in (0, 1), height
    /// fraction of the step height in [0, 2]). Feet in transfer follow the new
    /// spline from their current progress. Centre angles the key positions
    /// carry ([`PodaDriver::set_transfer_key_centers`]) stay with them, key by
    /// key.
    ///
    /// # Errors
    /// `transfer_keys[i]` naming the first bad key; `transfer_keys` for a new
    /// count of keys while the keys carry centre angles (set
    /// `transfer_key_centers` to none first); nothing changes.
    pub fn set_transfer_keys(&mut self, keys: &[[f64; 2]]) -> Result<(), DriverError> {
        check_transfer_keys("transfer_keys", keys)
            .map_err(|e| DriverError::new(e.path, e.reason))?;
        let carried = self.model.params.transfer_key_centers.len();
        if carried > 0 && keys.len() != carried {
            return Err(DriverError::new(
                "transfer_keys",
                format!(
                    "the {carried} key positions carry centre angles (transfer_key_centers): \
                     give {carried} keys, or set transfer_key_centers to none first"
                ),
            ));
        }
        spline_keys(keys, &mut self.model.keys);
        self.model.params.transfer_keys = keys.to_vec();
        Ok(())
    }

    /// Replaces the centre angles and gains the key leg positions carry: one
    /// [`KeyCenters`] object per transfer key, or none (every joint its own
    /// centre all cycle). Legs in transfer follow them from the next frame.
    ///
    /// # Errors
    /// `transfer_key_centers` for a count that is not the keys';
    /// `transfer_key_centers[i].{key}` for an unknown joint or place, a gain
    /// outside [0, 1] or a centre outside the joint's limits; nothing changes.
    pub fn set_transfer_key_centers(&mut self, centers: &[KeyCenters]) -> Result<(), DriverError> {
        let field = "transfer_key_centers";
        let model = &mut self.model;
        check_transfer_key_centers(field, model.params.transfer_keys.len(), centers)
            .map_err(|e| DriverError::new(e.path, e.reason))?;
        let resolved = key_centers::resolve(
            &model.skeleton,
            model
                .legs
                .iter()
                .map(|l| (l.name.as_str(), l.joints.as_slice())),
            centers,
            field,
        )?;
        for ((leg, ik), key_centers) in model.legs.iter_mut().zip(&mut self.state.ik).zip(resolved)
        {
            leg.key_centers = key_centers;
            ik.clear_center_overrides();
        }
        model.params.transfer_key_centers = centers.to_vec();
        Ok(())
    }

    /// The centre angle and gain eq. 6 pulls leg `leg`'s `place`-th joint
    /// (the hip 0) toward this frame: a key position's while the leg
    /// transfers ([`super::key_centers`]), the joint's own otherwise.
    #[must_use]
    pub fn leg_center(&self, leg: usize, place: usize) -> Option<[f64; 2]> {
        self.state
            .ik
            .get(leg)?
            .center_of(&self.model.skeleton, place)
    }

    /// Sets a leg joint's center angle and gain (eq. 6), by joint name.
    ///
    /// # Errors
    /// `center.joint` for an unknown joint or one that belongs to no leg;
    /// `center.center` / `center.gain` for values out of range.
    pub fn set_center(&mut self, joint: &str, center: f64, gain: f64) -> Result<(), DriverError> {
        let Some(j) = self.model.skeleton.joint_index(joint) else {
            return Err(DriverError::new(
                "center.joint",
                format!("no joint called {joint:?}"),
            ));
        };
        if !self.model.legs.iter().any(|leg| leg.joints.contains(&j)) {
            return Err(DriverError::new(
                "center.joint",
                format!("{joint:?} belongs to no leg"),
            ));
        }
        Arc::make_mut(&mut self.model.skeleton)
            .set_center(j, center, gain)
            .map_err(|e| {
                let field = if e.path.ends_with("gain") {
                    "gain"
                } else {
                    "center"
                };
                DriverError::new(format!("center.{field}"), e.reason)
            })
    }

    /// Each leg's name and joints (skeleton indices, hip first).
    pub fn leg_joints(&self) -> impl Iterator<Item = (&str, &[usize])> {
        self.model
            .legs
            .iter()
            .map(|l| (l.name.as_str(), l.joints.as_slice()))
    }

    /// Replaces the body path; the body joins it at the point closest to
    /// where it is and plans ahead along it (footholds already planned stay).
    /// With `speeds_mps` the body takes on the path's speed from there
    /// (eq. 14's ramp) and the gait at the next frame, then at the legs'
    /// mid-stances; without, the body keeps the speed it has.
    ///
    /// # Errors
    /// `path.…` naming the bad control point, speed or rule (a speed the gait
    /// cannot take on: `path.speeds_mps[i]`); nothing changes.
    pub fn set_path(&mut self, spec: &PathSpec) -> Result<(), DriverError> {
        let path = BodyPath::try_from(spec)
            .map_err(|e| DriverError::new(format!("path.{}", e.path), e.reason))?;
        check_path_speeds(&self.model, &self.state, &path, "path.speeds_mps")?;
        let state = &mut self.state;
        let here = state.track.interpolate(state.time).position;
        let distance = path.closest_distance(here);
        self.model.path = path;
        self.model.params.path = Some(spec.clone());
        state.edits.path_replaced();
        state
            .track
            .follow_new_path(state.time, distance, &self.model.path, &state.gait);
        Ok(())
    }

    /// Name of the named gait in use.
    #[must_use]
    pub fn gait_name(&self) -> &str {
        &self.state.gait_name
    }

    /// Switches to the named gait; each leg takes it on at its next
    /// mid-stance ([`super::leg_cycles`]), `P` and speed stay. Before the
    /// first frame the run simply starts in it.
    ///
    /// # Errors
    /// `gait` when the name is unknown for this leg count, or its stroke at
    /// this period and speed is out of range; nothing changes.
    pub fn set_gait(&mut self, name: &str) -> Result<(), DriverError> {
        let (phases, duty) = named_gait(name, self.model.legs.len())
            .map_err(|e| DriverError::new("gait", e.reason))?;
        let mut next = self.state.gait.clone();
        next.set_shape(&phases, duty)
            .map_err(|e| DriverError::new("gait", e.to_string()))?;
        adopt(&self.model, &mut self.state, name, next);
        Ok(())
    }

    /// Leg `i`'s latest mid-stance at or before now, seconds.
    #[must_use]
    pub fn mid_stance_s(&self, i: usize) -> Option<f64> {
        let state = &self.state;
        state.clock.mid_stance_s(i, state.time, &state.gait)
    }

    /// Whether some leg has not yet taken on the gait's present values.
    #[must_use]
    pub fn is_shifting(&self) -> bool {
        let state = &self.state;
        state.clock.is_shifting(state.time, &state.gait)
    }

    /// The ground the creature walks on (`scenario.terrain`).
    #[must_use]
    pub fn terrain(&self) -> &gaitlab_core::terrain::Terrain {
        &self.model.terrain
    }

    /// Footholds moved off an unacceptable spot since the restart
    /// ([`crate::poda::terrain_feet`]; 0 on the floor).
    #[must_use]
    pub fn footholds_moved(&self) -> u64 {
        self.state.footholds_moved
    }

    /// Frames in which the body eased its gait's height and pitch toward
    /// the ground's so that its legs hold their feet, since the restart, and
    /// the least fraction of them it kept (1 when none;
    /// [`crate::poda::terrain_feet`]; `(0, 1.0)` on the floor).
    #[must_use]
    pub fn body_eased(&self) -> (u64, f64) {
        self.state.eased
    }

    /// The figures measured since the last reset.
    #[must_use]
    pub fn metrics(&self) -> &GaitMetrics {
        &self.state.metrics
    }

    /// Leg names, in leg order.
    pub fn leg_names(&self) -> impl Iterator<Item = &str> {
        self.model.legs.iter().map(|l| l.name.as_str())
    }

    /// The body path.
    #[must_use]
    pub fn path(&self) -> &BodyPath {
        &self.model.path
    }

    /// Each leg's foot target this frame and whether it is supporting.
    pub fn foot_targets(&self) -> impl Iterator<Item = (DVec3, bool)> + '_ {
        self.state.runs.iter().map(|r| (r.target, r.support))
    }

    /// The footholds planned for the feet now in transfer (eq. 11), world metres.
    pub fn footholds(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.state
            .runs
            .iter()
            .filter(|r| !r.support)
            .map(|r| r.foothold_world)
    }

    /// The feet in transfer whose eq. 11 spot was unacceptable: each as
    /// (eq. 11's own spot, the foothold chosen instead), world metres
    /// ([`crate::poda::terrain_feet`]).
    pub fn moved_footholds(&self) -> impl Iterator<Item = (DVec3, DVec3)> + '_ {
        self.state
            .runs
            .iter()
            .filter(|r| !r.support && r.foothold_moved)
            .map(|r| (r.foothold_nominal, r.foothold_world))
    }

    /// Largest distance of the body's ground position from its path since
    /// the last reset, metres: how far it cut corners its legs could not
    /// take (`turn_within_reach`) or lagged behind the path.
    #[must_use]
    pub fn path_error_max_m(&self) -> f64 {
        self.state.path_error_max_m
    }

    /// This frame's fore-aft surge, metres ahead of the body's even motion
    /// along its path (0 when `scenario.poda.fore_aft_surge` is off).
    #[must_use]
    pub fn surge_m(&self) -> f64 {
        self.state.surge_m
    }

    /// This frame's distance of the body's ground position (the root, with
    /// its surge) from its path, metres.
    #[must_use]
    pub fn path_error_m(&self) -> f64 {
        measure::path_error_m(&self.model, &self.state)
    }

    /// Arc length of the desired point on the body path now, metres.
    #[must_use]
    pub fn path_distance_m(&self) -> f64 {
        self.state.track.interpolate(self.state.time).desired_m
    }

    /// The body's planned ground pose at time `t_s` (known about one gait
    /// period ahead of the current time).
    #[must_use]
    pub fn ground_pose(&self, t_s: f64) -> GroundPose {
        self.state.track.ground_pose(t_s)
    }

    /// The planned body motion.
    #[must_use]
    pub fn body_track(&self) -> &BodyTrack {
        &self.state.track
    }

    /// Static stability now: feet down, the margin of the body's centre over
    /// their support polygon, and the share of the last gait period it stood
    /// statically unstable ([`super::stability`]).
    #[must_use]
    pub fn stability(&self) -> StabilityReport {
        self.state.stability.report()
    }

    /// The support polygon of the feet down now (ground x, z), counter-clockwise.
    #[must_use]
    pub fn support_polygon(&self) -> &[DVec2] {
        self.state.stability.polygon()
    }
}

impl Driver for PodaDriver {
    fn step(&mut self, dt: f64) {
        if !(dt.is_finite() && dt > 0.0) {
            return;
        }
        let (model, state) = (&self.model, &mut self.state);
        // The path's speed is an edit like any other, read at mid-stances.
        follow_path_speed(model, state);
        let t_prev = state.time;
        let t = t_prev + dt;
        let change = take_on(model, state, t_prev);
        state.time = t;
        body::advance(model, state, t_prev, t, change.replanned);
        legs::advance(model, state, t_prev, t);
        footholds::plan(model, state);
        targets::place(model, state, t);
        ik::solve(model, state, model.params.iterations_per_frame);
        measure::record(model, state, t_prev, t, false);
        state.path_error_max_m = state
            .path_error_max_m
            .max(measure::path_error_m(model, state));
    }

    fn time(&self) -> f64 {
        self.state.time
    }

    fn reset(&mut self) {
        restart(&self.model, &mut self.state);
    }

    fn skeleton(&self) -> &Skeleton {
        &self.model.skeleton
    }

    fn pose(&self) -> &Pose {
        &self.state.pose
    }

    fn effector_positions(&self) -> &[DVec3] {
        &self.state.effectors
    }

    fn targets(&self) -> Option<&Targets> {
        Some(&self.state.targets)
    }

    fn ik_report(&self) -> Option<&IkFrameReport> {
        Some(&self.state.report)
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::driver::Driver;
    use gaitlab_core::preset::{Creature, load_bundled};

    use crate::poda::driver::PodaDriver;

    const DT: f64 = 1.0 / 60.0;

    fn quadruped() -> Creature {
        match load_bundled("poda-quadruped") {
            Some(Ok(creature)) => creature,
            _ => panic!("poda-quadruped is bundled and valid"),
        }
    }

    fn driver(creature: &Creature) -> PodaDriver {
        PodaDriver::new(creature).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The root and joints, bit for bit.
    fn pose_bits(driver: &PodaDriver) -> Vec<u64> {
        let pose = driver.pose();
        let root = pose.root.position.to_array().into_iter();
        let rotation = pose.root.rotation.to_cols_array().into_iter();
        root.chain(rotation)
            .chain(pose.joints.iter().copied())
            .map(f64::to_bits)
            .collect()
    }

    #[test]
    fn a_gait_edit_is_taken_on_at_the_next_frame() {
        let creature = quadruped();
        let mut driver = driver(&creature);
        for _ in 0..30 {
            driver.step(DT);
        }
        // An edit that changes nothing is dropped.
        let _ = driver.gait_mut();
        driver.step(DT);
        assert!(!driver.is_shifting());
        let period = driver.gait().period_s();
        let _ = driver.set_period(1.2 * period).expect("period");
        assert!(!driver.is_shifting(), "queued, not yet taken on");
        driver.step(DT);
        assert!(driver.is_shifting(), "the legs take it on one by one");
    }

    /// A restart after a gait change and back runs as a new driver does
    /// (the vertical centre is due at every restart, not kept from the
    /// legs' cycles).
    #[test]
    fn a_restart_after_a_change_and_back_runs_as_a_new_driver() {
        let creature = quadruped();
        let mut fresh = driver(&creature);
        let mut changed = driver(&creature);
        let first = changed.gait_name().to_owned();
        for frame in 0..400 {
            match frame {
                100 => changed.set_gait("walk").expect("walk"),
                130 => changed.set_gait(&first).expect("back"),
                _ => {}
            }
            changed.step(DT);
        }
        changed.reset();
        assert_eq!(pose_bits(&changed), pose_bits(&fresh));
        for frame in 0..120 {
            fresh.step(DT);
            changed.step(DT);
            assert_eq!(pose_bits(&changed), pose_bits(&fresh), "frame {frame}");
        }
    }
}
