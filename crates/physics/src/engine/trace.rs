//! The per-step trace of a running simulation (`gaitlab run … --trace
//! FILE.csv`): after every integration step, the state machine's state
//! (Raibert & Hodgins 1991, Figure 4), the trunk and centre of mass, the
//! attitude, each leg's state, length, spring rest, contact and ground force (the
//! "Modeling" section's ground springs), the desired speed and heading, and
//! every joint coordinate — what the old `examples/*trial.rs` printed.
//!
//! One row per integration step (0.4 ms at scale 1), not per frame: the
//! controller runs every step (`SimOptions::control_every` is 1), so every
//! state change is seen when it happens, and the Table-2 recorder
//! ([`crate::engine::metrics`]) sees exactly these states, so its figures can
//! be recomputed from the trace. A [`TraceRow`] is filled in place each step
//! and written as one CSV line: nothing is allocated per step.

use std::fmt::{self, Write};

use gaitlab_core::driver::Driver;
use glam::DVec3;

use crate::control::laws::attitude::{attitude_error, com_state, trunk_rate};
use crate::control::laws::scale::Scale;
use crate::dynamics::model::GRAVITY_MPS2;
use crate::engine::driver::PhysicsDriver;
use crate::engine::probe;

/// One leg in one [`TraceRow`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LegTrace {
    /// The state of the leg's own state machine, where the controller runs
    /// one per leg or per pair of legs; else the controller's state.
    pub state: &'static str,
    /// Whether the foot is on the ground.
    pub touching: bool,
    /// Hip-to-foot length (m).
    pub length_m: f64,
    /// Rest length (or angle, for the kangaroo's ankle) the controller gives
    /// the leg's spring (m or rad).
    pub spring_rest: f64,
    /// The foot's position (world, m).
    pub foot_m: DVec3,
    /// The ground's force on the foot (world, N).
    pub force_n: DVec3,
}

/// The state of a simulation after one step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TraceRow {
    /// Simulated time (s).
    pub time_s: f64,
    /// The state machine's state, as the controller names it.
    pub state: &'static str,
    /// The state's Figure-4 index as the live plots show it (0 flight,
    /// 1 loading, 2 compression, 3 thrust, 4 unloading; 0 for a state outside
    /// Figure 4, such as the kangaroo's jump states).
    pub state_index: usize,
    /// Desired forward speed (m/s, at the creature's scale).
    pub speed_desired_mps: f64,
    /// Desired heading (deg about +y; 0 = +z).
    pub heading_deg: f64,
    /// Trunk origin (world, m).
    pub trunk_m: DVec3,
    /// Trunk origin's velocity (world, m/s).
    pub trunk_velocity_mps: DVec3,
    /// Centre of mass (world, m).
    pub com_m: DVec3,
    /// Centre of mass velocity (world, m/s).
    pub com_velocity_mps: DVec3,
    /// Trunk pitch, roll and yaw (deg; pitch positive nose down).
    pub attitude_deg: [f64; 3],
    /// Trunk pitch, roll and yaw rates (deg/s).
    pub attitude_rate_dps: [f64; 3],
    /// Total vertical ground force over body weight.
    pub ground_force_bw: f64,
    /// One entry per leg.
    pub legs: Vec<LegTrace>,
    /// Every joint coordinate (rad or m), in the skeleton's order.
    pub joints: Vec<f64>,
}

impl TraceRow {
    /// A row sized for `driver`'s creature (filled by [`TraceRow::fill`]).
    #[must_use]
    pub fn for_driver(driver: &PhysicsDriver) -> Self {
        let sim = driver.sim();
        let mut row = Self {
            legs: vec![LegTrace::default(); sim.creature.legs.len()],
            joints: vec![0.0; sim.data.q.len()],
            ..Self::default()
        };
        row.fill(driver);
        row
    }

    /// Reads `driver`'s state now into this row, allocating nothing.
    pub fn fill(&mut self, driver: &PhysicsDriver) {
        let sim = driver.sim();
        let (creature, data) = (&sim.creature, &sim.data);
        let trunk = creature.trunk;
        let (com, com_velocity) = com_state(creature, data);
        let attitude = attitude_error(creature, data, 0.0, 0.0);
        let rate = trunk_rate(creature, data);
        let weight = creature.model.total_mass() * GRAVITY_MPS2;
        let trunk_frame = data.world[trunk];
        self.time_s = sim.time;
        self.state = driver.phase_name();
        self.state_index = probe::phase_index(self.state);
        self.speed_desired_mps =
            driver.params().speed_mps * Scale::new(driver.params().scale).velocity();
        self.heading_deg = driver.heading().to_degrees();
        self.trunk_m = trunk_frame.pos;
        self.trunk_velocity_mps = data.point_velocity_world(trunk, DVec3::ZERO);
        self.com_m = com;
        self.com_velocity_mps = com_velocity;
        self.attitude_deg = [
            attitude.x.to_degrees(),
            attitude.z.to_degrees(),
            attitude.y.to_degrees(),
        ];
        self.attitude_rate_dps = [
            rate.x.to_degrees(),
            rate.z.to_degrees(),
            rate.y.to_degrees(),
        ];
        let mut vertical = 0.0;
        for (i, ((out, leg), contact)) in self
            .legs
            .iter_mut()
            .zip(&creature.legs)
            .zip(&sim.contacts)
            .enumerate()
        {
            let hip = trunk_frame.rot * leg.hip_in_trunk + trunk_frame.pos;
            let foot = data.point_world(leg.foot_body, leg.foot_point);
            *out = LegTrace {
                state: driver.leg_phase_name(i),
                touching: contact.touching,
                length_m: (foot - hip).length(),
                spring_rest: sim.drives.get(leg.spring).map_or(0.0, |d| d.spring.rest),
                foot_m: foot,
                force_n: contact.force,
            };
            vertical += contact.force.y;
        }
        self.ground_force_bw = vertical / weight;
        let n = self.joints.len().min(data.q.len());
        self.joints[..n].copy_from_slice(&data.q[..n]);
    }
}

/// Writes a simulation's trace as CSV: [`TraceWriter::header`] once, then
/// [`TraceWriter::step`] in place of [`Driver::step`].
#[derive(Clone, Debug)]
pub struct TraceWriter {
    row: TraceRow,
}

/// A name safe inside a CSV header (no separators, quotes or line breaks).
fn column_name(name: &str) -> String {
    name.chars()
        .map(|c| {
            if matches!(c, ',' | '"' | '\n' | '\r') {
                '_'
            } else {
                c
            }
        })
        .collect()
}

impl TraceWriter {
    /// A writer for `driver`'s creature.
    #[must_use]
    pub fn new(driver: &PhysicsDriver) -> Self {
        Self {
            row: TraceRow::for_driver(driver),
        }
    }

    /// The row last written (the state after the last step).
    #[must_use]
    pub fn row(&self) -> &TraceRow {
        &self.row
    }

    /// The CSV header: fixed columns, then per leg (by name) and per joint
    /// coordinate (by the skeleton's joint name).
    ///
    /// # Errors
    /// The sink's.
    pub fn header(&self, driver: &PhysicsDriver, out: &mut impl Write) -> fmt::Result {
        out.write_str(
            "time_s,state,state_index,speed_desired_mps,heading_deg,\
             trunk_x_m,trunk_y_m,trunk_z_m,trunk_vx_mps,trunk_vy_mps,trunk_vz_mps,\
             com_x_m,com_y_m,com_z_m,com_vx_mps,com_vy_mps,com_vz_mps,\
             pitch_deg,roll_deg,yaw_deg,pitch_rate_dps,roll_rate_dps,yaw_rate_dps,\
             ground_force_bw",
        )?;
        for leg in &driver.sim().creature.legs {
            let name = column_name(&leg.name);
            for column in [
                "state",
                "touching",
                "length_m",
                "spring_rest",
                "foot_x_m",
                "foot_y_m",
                "foot_z_m",
                "force_x_n",
                "force_y_n",
                "force_z_n",
            ] {
                write!(out, ",{name}.{column}")?;
            }
        }
        let joints = driver.skeleton().joints();
        for k in 0..self.row.joints.len() {
            match joints.get(k) {
                Some(joint) => write!(out, ",q.{}", column_name(&joint.name))?,
                None => write!(out, ",q.{k}")?,
            }
        }
        out.write_char('\n')
    }

    /// [`Driver::step`] with a row written to `out` after every integration
    /// step; the motion is exactly that of an untraced step.
    ///
    /// # Errors
    /// The first error of `out`; the step itself always completes.
    pub fn step(
        &mut self,
        driver: &mut PhysicsDriver,
        dt: f64,
        out: &mut impl Write,
    ) -> fmt::Result {
        let mut written = Ok(());
        driver.step_observed(dt, |driver| {
            if written.is_ok() {
                written = self.write_row(driver, out);
            }
        });
        written
    }

    /// Reads `driver` now and writes one CSV line; allocates nothing.
    ///
    /// # Errors
    /// The sink's.
    pub fn write_row(&mut self, driver: &PhysicsDriver, out: &mut impl Write) -> fmt::Result {
        self.row.fill(driver);
        let r = &self.row;
        write!(
            out,
            "{:.6},{},{},{:.6},{:.4}",
            r.time_s, r.state, r.state_index, r.speed_desired_mps, r.heading_deg
        )?;
        for v in [r.trunk_m, r.trunk_velocity_mps, r.com_m, r.com_velocity_mps] {
            write!(out, ",{:.6},{:.6},{:.6}", v.x, v.y, v.z)?;
        }
        for a in r.attitude_deg.iter().chain(&r.attitude_rate_dps) {
            write!(out, ",{a:.4}")?;
        }
        write!(out, ",{:.5}", r.ground_force_bw)?;
        for leg in &r.legs {
            write!(
                out,
                ",{},{},{:.6},{:.6},{:.6},{:.6},{:.6},{:.3},{:.3},{:.3}",
                leg.state,
                u8::from(leg.touching),
                leg.length_m,
                leg.spring_rest,
                leg.foot_m.x,
                leg.foot_m.y,
                leg.foot_m.z,
                leg.force_n.x,
                leg.force_n.y,
                leg.force_n.z
            )?;
        }
        for q in &r.joints {
            write!(out, ",{q:.6}")?;
        }
        out.write_char('\n')
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::preset::load_bundled;

    use super::*;

    fn driver(name: &str) -> PhysicsDriver {
        let preset = load_bundled(name).expect("bundled").expect("valid preset");
        PhysicsDriver::new(&preset).expect("a physics preset")
    }

    #[test]
    fn one_row_per_step_with_the_header_s_columns() {
        let mut d = driver("raibert-biped");
        let mut writer = TraceWriter::new(&d);
        let mut text = String::new();
        writer.header(&d, &mut text).expect("header");
        writer.step(&mut d, 0.02, &mut text).expect("rows");
        let lines: Vec<&str> = text.lines().collect();
        // 0.02 s at 0.4 ms per step.
        assert_eq!(lines.len(), 1 + 50, "{}", lines.len());
        let columns = lines[0].split(',').count();
        assert!(lines.iter().all(|l| l.split(',').count() == columns));
        assert!(lines[0].starts_with("time_s,state,state_index,"));
        let last: Vec<&str> = lines[50].split(',').collect();
        let time: f64 = last[0].parse().expect("a time");
        assert!((time - d.time()).abs() < 1e-6, "{time} vs {}", d.time());
        assert_eq!(writer.row().time_s, d.time());
    }

    /// The trot runs a state machine per leg: diagonal pairs are seen in
    /// different states.
    #[test]
    fn each_leg_has_its_own_state_where_the_controller_has_one() {
        let mut d = driver("raibert-quadruped");
        let mut writer = TraceWriter::new(&d);
        let mut sink = String::new();
        let mut differ = false;
        for _ in 0..60 {
            writer.step(&mut d, 1.0 / 60.0, &mut sink).expect("rows");
            sink.clear();
            let legs = &writer.row().legs;
            differ |= legs.iter().any(|l| l.state != legs[0].state);
            assert!(legs.iter().all(|l| !l.state.is_empty()));
        }
        assert!(differ, "the four legs always in one state");
    }

    #[test]
    fn a_traced_step_moves_the_creature_exactly_as_an_untraced_one() {
        let mut plain = driver("raibert-quadruped");
        let mut traced = plain.clone();
        let mut writer = TraceWriter::new(&traced);
        let mut sink = String::new();
        for _ in 0..30 {
            plain.step(1.0 / 60.0);
            writer
                .step(&mut traced, 1.0 / 60.0, &mut sink)
                .expect("rows");
            sink.clear();
        }
        assert_eq!(plain.pose(), traced.pose());
        assert_eq!(plain.summary(), traced.summary());
    }
}
