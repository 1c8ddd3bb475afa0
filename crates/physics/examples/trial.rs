//! Development aid: run the biped and print a trace and the Table-2 figures.
//! `cargo run --release -p gaitlab-physics --example trial -- SPEED SECONDS [trace]`
use gaitlab_physics::control::attitude::{attitude_error, com_velocity};
use gaitlab_physics::control::biped_run::{BipedRun, BipedRunParams};
use gaitlab_physics::creatures::biped;
use gaitlab_physics::engine::metrics::GaitRecorder;
use gaitlab_physics::world::ground::GroundParams;
use gaitlab_physics::{Sim, SimOptions};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let speed: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1.5);
    let secs: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(5.0);
    let trace = args.get(3).is_some();
    let env = |k: &str, d: f64| {
        std::env::var(k)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(d)
    };
    let g0 = GroundParams::default();
    let ground = GroundParams {
        vertical_damping: env("GVD", g0.vertical_damping),
        tangential_damping: env("GTD", g0.tangential_damping),
        vertical_stiffness: env("GVK", g0.vertical_stiffness),
        tangential_stiffness: env("GTK", g0.tangential_stiffness),
        ..g0
    };
    let mut sim = Sim::new(
        biped(1.0)?,
        ground,
        SimOptions {
            control_every: env("EVERY", 1.0) as u32,
            ..SimOptions::default()
        },
    );
    sim.data.base_position.y = 0.9;
    sim.data.base_velocity.linear.z = speed;
    let d = BipedRunParams::default();
    let params = BipedRunParams {
        speed_mps: speed,
        posture_kp: env("PKP", d.posture_kp),
        posture_kv: env("PKV", d.posture_kv),
        placement_gain_s: env("KG", d.placement_gain_s),
        leg_stiffness: env("LEGK", d.leg_stiffness),
        leg_damping: env("LEGB", d.leg_damping),
        hop_height_m: env("HOP", d.hop_height_m),
        swing_kp: env("SKP", d.swing_kp),
        swing_kv: env("SKV", d.swing_kv),
        ..d
    };
    let mut ctl = BipedRun::new(params, 1.0);
    let mut rec = GaitRecorder::new(2, speed, 0.0, 3.0);
    let mut last_print = -1.0;
    let mut last_phase = ctl.phase;
    let events = std::env::var("EVENTS").is_ok();
    while sim.time < secs {
        sim.step(&mut ctl)?;
        rec.record(&sim);
        if events && ctl.phase != last_phase {
            last_phase = ctl.phase;
            let e = attitude_error(&sim.creature, &sim.data, 0.0, 0.0);
            let w = gaitlab_physics::control::attitude::trunk_rate(&sim.creature, &sim.data);
            let v = com_velocity(&sim.creature, &sim.data);
            let com =
                gaitlab_physics::dynamics::energy::center_of_mass(&sim.creature.model, &sim.data);
            let f = sim.contacts[ctl.active].position;
            println!(
                "{:.3} {:11} act {} roll {:+5.1} rate {:+5.2} pitch {:+5.1} rate {:+5.2} vx {:+.2} vz {:+.2} foot-com x {:+.3} z {:+.3} y {:.3}",
                sim.time,
                ctl.phase.name(),
                ctl.active,
                e.z.to_degrees(),
                w.z,
                e.x.to_degrees(),
                w.x,
                v.x,
                v.z,
                f.x - com.x,
                f.z - com.z,
                com.y
            );
        }
        if trace && sim.time - last_print >= 0.01 {
            last_print = sim.time;
            let v = com_velocity(&sim.creature, &sim.data);
            let e = attitude_error(&sim.creature, &sim.data, 0.0, 0.0);
            println!(
                "t {:.3} {:11} act {} y {:.3} vz {:+.2} vx {:+.2} pitch {:+.1} roll {:+.1} yaw {:+.1} yawq {:+.2} {:+.2} {:+.1} {:+.1} q {:+.2} {:+.2} {:+.2} {:+.2}",
                sim.time,
                ctl.phase.name(),
                ctl.active,
                sim.data.base_position.y,
                v.z,
                v.x,
                e.x.to_degrees(),
                e.z.to_degrees(),
                e.y.to_degrees(),
                sim.data.q[2],
                sim.data.q[6],
                sim.data.qd[2],
                sim.data.qd[6],
                sim.data.q[0],
                sim.data.q[1],
                sim.data.q[4],
                sim.data.q[5]
            );
        }
    }
    let s = rec.summary();
    println!(
        "fell {} speed {:.3}/{:.2} stride {:.3} m {:.3} s flight {:.3} stance {:.3} legΔ {:.3} pitch {:.1} roll {:.1} accel {:.2} g friction {:.2}",
        s.fell,
        s.speed_mean_mps,
        s.speed_desired_mps,
        s.stride_length_m,
        s.stride_duration_s,
        s.flight_duration_s,
        s.stance_duration_s,
        s.leg_length_change_m,
        s.pitch_magnitude_deg,
        s.roll_magnitude_deg,
        s.peak_vertical_accel_g,
        s.friction_needed_max
    );
    Ok(())
}
