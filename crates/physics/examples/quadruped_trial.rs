//! Development aid: run the trotting quadruped and print a trace and the Table-2 figures.
//! `cargo run --release -p gaitlab-physics --example quadruped_trial -- SPEED SECONDS [trace]`
//! (The bound and gallop have `bound_trial`.)
use gaitlab_physics::control::attitude::{attitude_error, com_velocity};
use gaitlab_physics::control::quadruped_run::{
    QuadrupedRun, QuadrupedRunParams, quadruped_ground, quadruped_start,
};
use gaitlab_physics::creatures::quadruped;
use gaitlab_physics::engine::metrics::GaitRecorder;
use gaitlab_physics::{Sim, SimOptions};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let speed: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(2.3);
    let secs: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(10.0);
    let trace = args.get(3).is_some();
    let mut sim = Sim::new(
        quadruped(1.0)?,
        quadruped_ground(1.0),
        SimOptions::default(),
    );
    quadruped_start(&mut sim, speed);
    let mut params = QuadrupedRunParams {
        speed_mps: speed,
        ..Default::default()
    };
    // Tuning overrides for experiments: QT="key=value,key=value" (trot tuning fields).
    if let Ok(spec) = std::env::var("QT") {
        for kv in spec.split(',').filter(|s| !s.is_empty()) {
            let (k, v) = kv.split_once('=').ok_or("QT: key=value")?;
            let v: f64 = v.parse()?;
            let t = &mut params.trot;
            match k {
                "leg_stiffness" => t.leg_stiffness = v,
                "leg_damping" => t.leg_damping = v,
                "landing_rest_m" => t.landing_rest_m = v,
                "thrust_m" => t.thrust_m = v,
                "flight0" => t.flight_s[0] = v,
                "flight1" => t.flight_s[1] = v,
                "stance_s" => t.stance_s = v,
                "placement_gain_s" => t.placement_gain_s = v,
                "pitch_kp" => t.pitch_kp = v,
                "pitch_kv" => t.pitch_kv = v,
                "roll_kp" => t.roll_kp = v,
                "roll_kv" => t.roll_kv = v,
                "pitch_d" => t.pitch_d = v,
                "speed_gain" => t.speed_gain = v,
                "pitch_swing" => t.pitch_swing = v,
                "posture_force_ratio" => t.posture_force_ratio = v,
                "flight_gain" => params.flight_gain = v,
                "swing_kp" => params.swing_kp = v,
                "swing_kv" => params.swing_kv = v,
                _ => return Err(format!("QT: unknown key {k}").into()),
            }
        }
    }
    let mut ctl = QuadrupedRun::new(params, 1.0);
    let mut rec = GaitRecorder::new(4, speed, 0.0, 3.0);
    let mut last_print = -1.0;
    while sim.time < secs {
        sim.step(&mut ctl)?;
        rec.record(&sim);
        if trace && sim.time - last_print >= 0.01 {
            last_print = sim.time;
            let v = com_velocity(&sim.creature, &sim.data);
            let e = attitude_error(&sim.creature, &sim.data, 0.0, 0.0);
            let touch: String = sim
                .contacts
                .iter()
                .map(|c| if c.touching { '#' } else { '.' })
                .collect();
            println!(
                "t {:.3} {:11} act {} {} y {:.3} vy {:+.2} vz {:+.2} vx {:+.2} pitch {:+.1} roll {:+.1} yaw {:+.1} thr {:.3} {:.3} fl {:.3} {:.3} Ts {:.3} {:.3} qs {:+.3} {:+.3} {:+.3} {:+.3}",
                sim.time,
                ctl.phase().name(),
                ctl.active,
                touch,
                sim.data.base_position.y,
                v.y,
                v.z,
                v.x,
                e.x.to_degrees(),
                e.z.to_degrees(),
                e.y.to_degrees(),
                ctl.thrust[0],
                ctl.thrust[1],
                ctl.flight_s[0],
                ctl.flight_s[1],
                ctl.stance_s[0],
                ctl.stance_s[1],
                sim.data.q[2],
                sim.data.q[5],
                sim.data.q[8],
                sim.data.q[11],
            );
        }
    }
    let s = rec.summary();
    println!(
        "trot fell {} speed {:.3}/{:.2} stride {:.3} m {:.3} s flight {:.3} stance {:.3} [{:.3} {:.3} {:.3} {:.3}] legΔ {:.3} pitch {:.1} roll {:.1} accel {:.2} g friction {:.2}",
        s.fell,
        s.speed_mean_mps,
        s.speed_desired_mps,
        s.stride_length_m,
        s.stride_duration_s,
        s.flight_duration_s,
        s.stance_duration_s,
        s.leg_stance_s[0],
        s.leg_stance_s[1],
        s.leg_stance_s[2],
        s.leg_stance_s[3],
        s.leg_length_change_m,
        s.pitch_magnitude_deg,
        s.roll_magnitude_deg,
        s.peak_vertical_accel_g,
        s.friction_needed_max
    );
    Ok(())
}
