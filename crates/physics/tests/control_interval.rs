//! The control interval (Raibert & Hodgins 1991, Figure 2: the model every
//! 0.4 ms, the control "every control interval, which is usually a few
//! ms"): the state machine runs every `control_every` steps, while the
//! actuators' servos — eq. 1's spring and eq. 4's posture servo — act on
//! the fresh state every step.

use gaitlab_core::portable::Portable;
use gaitlab_physics::control::gaits::biped_run::{BipedRun, BipedRunParams};
use gaitlab_physics::control::gaits::hopper_params::HopperParams;
use gaitlab_physics::creatures::biped;
use gaitlab_physics::world::ground::GroundParams;
use gaitlab_physics::world::sim::{ControlInput, Controller, Drive};
use gaitlab_physics::{Sim, SimOptions};

/// Counts its calls, and sets the first joint's feed-forward torque to the
/// step it was last called at.
#[derive(Default)]
struct Counting {
    control: Vec<f64>,
    servo: usize,
}

impl Controller for Counting {
    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.control.push(input.dt);
        drives[0].torque(0.0);
    }

    fn servo(&mut self, _input: &ControlInput<'_>, _drives: &mut [Drive]) {
        self.servo += 1;
    }
}

fn sim(control_every: u32) -> Sim {
    let mut sim = Sim::new(
        biped(1.0).expect("biped"),
        GroundParams::default(),
        SimOptions {
            control_every,
            ..SimOptions::default()
        },
    );
    sim.data.base_position.y = 0.9;
    sim
}

#[test]
fn the_state_machine_runs_every_interval_and_the_servos_every_step() {
    let mut sim = sim(5);
    let mut c = Counting::default();
    for _ in 0..50 {
        sim.step(&mut c).expect("steps");
    }
    assert_eq!(c.control.len(), 10, "every fifth step");
    assert_eq!(c.servo, 50, "every step");
    // The controller is told the time since its last call: 2 ms.
    assert!(c.control.iter().all(|&dt| (dt - 0.002).abs() < 1e-12));
}

/// The bundled biped's gains at 2.5 m/s with control every 2 ms: it runs
/// 20 s, trunk yaw within 10° of the heading (`yaw_kv` 40; at the
/// controller's own 20 the yaw swings past 100° within a minute).
#[test]
fn the_biped_runs_with_control_every_two_ms() {
    let mut sim = sim(5);
    sim.data.base_velocity.linear.z = 2.5;
    let d = BipedRunParams::default();
    sim.commands.speed_mps = 2.5;
    let params = BipedRunParams {
        hopper: HopperParams {
            yaw_kv: 40.0,
            ..d.hopper
        },
        unloading_posture: false,
        ..d
    };
    let mut c = BipedRun::new(params, &sim.creature);
    let mut worst_yaw: f64 = 0.0;
    while sim.time < 20.0 {
        sim.step(&mut c).expect("no blow-up");
        let rot = sim.data.world[sim.creature.trunk].rot;
        let fwd = rot * glam::DVec3::Z;
        if sim.time > 3.0 {
            worst_yaw = worst_yaw.max(fwd.x.patan2(fwd.z).abs().to_degrees());
        }
        assert!(sim.data.base_position.y > 0.4, "fell at {:.2} s", sim.time);
    }
    eprintln!(
        "worst yaw {worst_yaw:.2}° at {:.1} m/s",
        sim.data.base_position.z / sim.time
    );
    assert!(worst_yaw < 10.0, "yaw reached {worst_yaw:.1}°");
}
