//! Development aid: gallop the biped and print the Table-2 figures plus the
//! gallop's own (touchdown lag, double support).
//! `cargo run --release -p gaitlab-physics --example gallop_trial -- STYLE SPEED SECONDS`
//! with STYLE 1 (together swing) or 2 (alternate swing); EVENTS=1 prints
//! phase events; parameters by environment variables (see `main`).
use gaitlab_physics::control::attitude::{attitude_error, com_velocity, trunk_rate};
use gaitlab_physics::control::biped_gallop::{BipedGallop, BipedGallopParams, GallopStyle};
use gaitlab_physics::creatures::biped;
use gaitlab_physics::engine::metrics::{GaitRecorder, GaitSummary};
use gaitlab_physics::world::ground::GroundParams;
use gaitlab_physics::{Sim, SimOptions};

/// Per trailing-leg stance: the leading leg's stance that overlaps it, the
/// touchdown lag and the double-support time; means over the run.
fn gallop_figures(s: &GaitSummary, trail: usize) -> (usize, usize, f64, f64) {
    let lead = 1 - trail;
    let (mut strides, mut galloped, mut lag, mut double) = (0, 0, 0.0, 0.0);
    for t in &s.stances[trail] {
        strides += 1;
        if let Some(d) = s.stances[lead]
            .iter()
            .find(|d| d.start_s >= t.start_s && d.start_s < t.end_s)
        {
            galloped += 1;
            lag += d.start_s - t.start_s;
            double += t.end_s.min(d.end_s) - d.start_s;
        }
    }
    let n = galloped.max(1) as f64;
    (strides, galloped, lag / n, double / n)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let style = match args.get(1).map(String::as_str) {
        Some("2") => GallopStyle::AlternateSwing,
        _ => GallopStyle::TogetherSwing,
    };
    let speed: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1.5);
    let secs: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(10.0);
    let env = |k: &str, d: f64| {
        std::env::var(k)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(d)
    };
    let l = env("SCALE", 1.0);
    let mut sim = Sim::new(
        biped(l)?,
        GroundParams::default().scaled(l),
        SimOptions::default(),
    );
    sim.data.base_position.y = 0.9 * l;
    sim.data.base_velocity.linear.z = speed * l.sqrt();
    let d = BipedGallopParams::default();
    let params = BipedGallopParams {
        speed_mps: speed,
        style,
        posture_kp: env("PKP", d.posture_kp),
        posture_kv: env("PKV", d.posture_kv),
        placement_gain_s: env("KG", d.placement_gain_s),
        speed_integral_gain: env("KI", d.speed_integral_gain),
        hop_height_m: env("HOP", d.hop_height_m),
        swing_kp: env("SKP", d.swing_kp),
        swing_kv: env("SKV", d.swing_kv),
        trail_offset_m: env("TOFF", d.trail_offset_m),
        lead_offset_m: env("LOFF", d.lead_offset_m),
        lead_delay_s: env("DELAY", d.lead_delay_s),
        lead_extend_mps: env("EXT", d.lead_extend_mps),
        hop_gain: env("HG", d.hop_gain),
        trail_extend_mps: env("TEXT", d.trail_extend_mps),
        trail_unload_mps: env("UNLOAD", d.trail_unload_mps),
        pitch_feedforward: env("PFF", d.pitch_feedforward),
        lead_retract_m: env("RETRACT", d.lead_retract_m),
        idle_rest_m: env("IDLE", d.idle_rest_m),
        landing_rest_m: env("LAND", d.landing_rest_m),
        leg_rate_mps: env("RATE", d.leg_rate_mps),
        ..d
    };
    let mut ctl = BipedGallop::new(params, l);
    let mut rec = GaitRecorder::new(2, speed * l.sqrt(), 0.0, 3.0 * l.sqrt());
    let mut last_phase = (ctl.legs[0].phase, ctl.legs[1].phase);
    let events = std::env::var("EVENTS").is_ok();
    let turn_at = env("TURN_AT", f64::INFINITY);
    while sim.time < secs * l.sqrt() {
        if sim.time >= turn_at {
            ctl.params.heading = env("TURN", 0.3);
            ctl.params.speed_mps = env("SPEED2", speed);
        }
        sim.step(&mut ctl)?;
        rec.record(&sim);
        if events && (ctl.legs[0].phase, ctl.legs[1].phase) != last_phase {
            last_phase = (ctl.legs[0].phase, ctl.legs[1].phase);
            let e = attitude_error(&sim.creature, &sim.data, 0.0, 0.0);
            let w = trunk_rate(&sim.creature, &sim.data);
            let v = com_velocity(&sim.creature, &sim.data);
            let com =
                gaitlab_physics::dynamics::energy::center_of_mass(&sim.creature.model, &sim.data);
            let f0 = sim.contacts[0].position - com;
            let f1 = sim.contacts[1].position - com;
            println!(
                "{:.3} {:14} L0 {:11} {:+.3} L1 {:11} {:+.3} roll {:+5.1} rate {:+5.2} pitch {:+5.1} rate {:+5.2} vx {:+.2} vz {:+.2} y {:.3} foot0 z {:+.3} foot1 z {:+.3} thrust {:.3}",
                sim.time,
                ctl.phase.name(),
                ctl.legs[0].phase.name(),
                sim.data.q[sim.creature.legs[0].spring],
                ctl.legs[1].phase.name(),
                sim.data.q[sim.creature.legs[1].spring],
                e.z.to_degrees(),
                w.z,
                e.x.to_degrees(),
                w.x,
                v.x,
                v.z,
                com.y,
                f0.z,
                f1.z,
                ctl.thrust_m()
            );
        }
    }
    let s = rec.summary();
    let (strides, galloped, lag, double) = gallop_figures(&s, ctl.trail());
    println!(
        "{} fell {} speed {:.3}/{:.2} stride {:.3} m {:.3} s flight {:.3} stance {:.3} ({:.3}/{:.3}) legΔ {:.3} pitch {:.1} roll {:.1} accel {:.2} g friction {:.2} | strides {} galloped {} lag {:.3} double {:.3}",
        style.name(),
        s.fell,
        s.speed_mean_mps,
        s.speed_desired_mps,
        s.stride_length_m,
        s.stride_duration_s,
        s.flight_duration_s,
        s.stance_duration_s,
        s.leg_stance_s.first().copied().unwrap_or(0.0),
        s.leg_stance_s.get(1).copied().unwrap_or(0.0),
        s.leg_length_change_m,
        s.pitch_magnitude_deg,
        s.roll_magnitude_deg,
        s.peak_vertical_accel_g,
        s.friction_needed_max,
        strides,
        galloped,
        lag,
        double
    );
    Ok(())
}
