//! Development aid: run the kangaroo and print a trace and the Table-2 figures.
//! `cargo run --release -p gaitlab-physics --example kangaroo_trial -- SPEED SECONDS [trace] [JUMP_AT_M] [L]`
//!
//! Environment: `START` start speed (m/s, default 2 or SPEED if slower; the
//! controller ramps to SPEED), `SETTLE` seconds ignored by the figures
//! (default 3), `P="name=value,…"` parameter overrides.
use gaitlab_physics::control::attitude::com_velocity;
use gaitlab_physics::control::kangaroo_hop::{
    KangarooHop, KangarooHopParams, kangaroo_ground, kangaroo_start,
};
use gaitlab_physics::creatures::kangaroo;
use gaitlab_physics::engine::metrics::GaitRecorder;
use gaitlab_physics::world::ground::Obstacle;
use gaitlab_physics::{Sim, SimOptions};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let speed: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(5.0);
    let secs: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(10.0);
    let trace = args.get(3).is_some_and(|s| s == "trace");
    let jump: Option<f64> = args.get(4).and_then(|s| s.parse().ok());
    let l: f64 = args.get(5).and_then(|s| s.parse().ok()).unwrap_or(1.0);
    let options = SimOptions {
        dt: 0.0004 * l.sqrt(),
        ..Default::default()
    };
    let mut sim = Sim::new(kangaroo(l)?, kangaroo_ground().scaled(l), options);
    let mut params = KangarooHopParams {
        speed_mps: speed,
        jump_at_m: jump.map(|j| j * l),
        ..Default::default()
    };
    // Overrides for tuning: P="name=value,name=value".
    if let Ok(list) = std::env::var("P") {
        for kv in list.split(',').filter(|s| !s.is_empty()) {
            let (k, v) = kv.split_once('=').ok_or("P: name=value")?;
            let v: f64 = v.parse()?;
            let slot = match k {
                "hop_rise_m" => &mut params.hop_rise_m,
                "hop_gain" => &mut params.hop_gain,
                "ankle_stiffness" => &mut params.ankle_stiffness,
                "ankle_damping" => &mut params.ankle_damping,
                "ankle_rest_rad" => &mut params.ankle_rest_rad,
                "max_thrust_rad" => &mut params.max_thrust_rad,
                "placement_gain_s" => &mut params.placement_gain_s,
                "landing_leg_m" => &mut params.landing_leg_m,
                "flight_retract_m" => &mut params.flight_retract_m,
                "hip_kp" => &mut params.hip_kp,
                "hip_kv" => &mut params.hip_kv,
                "stance_hip_kp" => &mut params.stance_hip_kp,
                "stance_hip_kv" => &mut params.stance_hip_kv,
                "knee_kp" => &mut params.knee_kp,
                "knee_kv" => &mut params.knee_kv,
                "posture_kp" => &mut params.posture_kp,
                "posture_kv" => &mut params.posture_kv,
                "pitch_rad" => &mut params.pitch_rad,
                "tail_stiffness" => &mut params.tail_stiffness,
                "tail_damping" => &mut params.tail_damping,
                "tail_mean_rad" => &mut params.tail_mean_rad,
                "tail_step_rad" => &mut params.tail_step_rad,
                "tail_pitch_gain" => &mut params.tail_pitch_gain,
                "tail_rate_gain_s" => &mut params.tail_rate_gain_s,
                "neck_kp" => &mut params.neck_kp,
                "speed_ramp_mps2" => &mut params.speed_ramp_mps2,
                "speed_integral_gain" => &mut params.speed_integral_gain,
                _ => return Err(format!("unknown parameter {k}").into()),
            };
            *slot = v;
        }
    }
    if let Some(at) = params.jump_at_m {
        sim.terrain.obstacles.push(Obstacle {
            min_xz: [-1.0, at],
            max_xz: [1.0, at + params.obstacle_depth_m * l],
            height_m: params.obstacle_height_m * l,
        });
    }
    let start = std::env::var("START")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .unwrap_or(speed.min(2.0));
    kangaroo_start(&mut sim, start);
    let mut ctl = KangarooHop::new(params);
    let settle = std::env::var("SETTLE")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .unwrap_or(3.0);
    let mut rec = GaitRecorder::new(1, speed * l.sqrt(), 0.0, settle * l.sqrt());
    let mut last_print = -1.0;
    let (mut tail_lo, mut tail_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut wags = Vec::new();
    let mut was_touching = false;
    while sim.time < secs * l.sqrt() {
        sim.step(&mut ctl)?;
        rec.record(&sim);
        let q6 = sim.data.q[6];
        tail_lo = tail_lo.min(q6);
        tail_hi = tail_hi.max(q6);
        let touching = sim.contacts[0].touching;
        if touching && !was_touching {
            if sim.time > settle * l.sqrt() {
                wags.push((tail_hi - tail_lo).to_degrees());
            }
            tail_lo = f64::INFINITY;
            tail_hi = f64::NEG_INFINITY;
        }
        was_touching = touching;
        if trace && sim.time - last_print >= 0.01 * l.sqrt() {
            last_print = sim.time;
            let v = com_velocity(&sim.creature, &sim.data);
            let q = &sim.data.q;
            println!(
                "t {:.3} {:11} {:?} z {:.3} y {:.3} vz {:+.2} vy {:+.2} pitch {:+.1} hip {:+.2} knee {:+.2} ankle {:+.2} rest {:+.2} tail {:+.2} toe {:.3},{:.3} F {:.0}",
                sim.time,
                ctl.phase.name(),
                ctl.jump,
                q[0],
                q[1],
                v.z,
                v.y,
                q[2].to_degrees(),
                q[3],
                q[4],
                q[5],
                ctl.ankle_rest,
                q[6],
                sim.contacts[0].position.z,
                sim.contacts[0].position.y,
                sim.contacts[0].force.y,
            );
        }
    }
    let s = rec.summary();
    let wag = if wags.is_empty() {
        0.0
    } else {
        wags.iter().sum::<f64>() / wags.len() as f64
    };
    println!(
        "fell {} speed {:.3}/{:.2} stride {:.3} m {:.3} s flight {:.3} stance {:.3} pitch {:.1} tail {:.1} accel {:.2} g friction {:.2} legΔ {:.3}",
        s.fell,
        s.speed_mean_mps,
        s.speed_desired_mps,
        s.stride_length_m,
        s.stride_duration_s,
        s.flight_duration_s,
        s.stance_duration_s,
        s.pitch_magnitude_deg,
        wag,
        s.peak_vertical_accel_g,
        s.friction_needed_max,
        s.leg_length_change_m
    );
    Ok(())
}
