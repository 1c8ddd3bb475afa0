//! Development aid: run the bounding / galloping quadruped and print a trace
//! and the Table-2 bound figures beside the paper's animation column.
//! `cargo run --release -p gaitlab-physics --example bound_trial -- STYLE SPEED SECONDS [trace]`
//! STYLE is bound or gallop. Overrides: QB="key=value,…" (parameter names).
//! `… bound_trial -- driver` runs trot → bound → gallop through the physics
//! driver with the bundled "raibert-quadruped" preset (default parameters).
use gaitlab_physics::control::attitude::{attitude_error, com_velocity};
use gaitlab_physics::control::quadruped_bound::{
    BoundStyle, FRONT, QuadrupedBound, QuadrupedBoundParams, REAR, bound_start,
};
use gaitlab_physics::control::quadruped_run::quadruped_ground;
use gaitlab_physics::creatures::quadruped;
use gaitlab_physics::engine::metrics::GaitRecorder;
use gaitlab_physics::engine::table2::{measured, paper_rows};
use gaitlab_physics::{Sim, SimOptions};

const LEG_NAMES: [&str; 4] = ["front-left", "front-right", "rear-left", "rear-right"];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("driver") {
        return driver_change();
    }
    let style = match args.get(1).map(String::as_str) {
        Some("gallop") => BoundStyle::Gallop,
        _ => BoundStyle::Bound,
    };
    let speed: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(2.8);
    let secs: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(10.0);
    let trace = args.get(4).is_some();
    let mut sim = Sim::new(
        quadruped(1.0)?,
        quadruped_ground(1.0),
        SimOptions::default(),
    );
    bound_start(&mut sim, speed);
    // A small change of the start (QB_START_DV, m/s) to probe robustness.
    if let Some(dv) = std::env::var("QB_START_DV")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
    {
        sim.data.base_velocity.linear.z += dv;
    }
    let mut p = QuadrupedBoundParams {
        speed_mps: speed,
        style,
        ..Default::default()
    };
    if let Ok(spec) = std::env::var("QB") {
        for kv in spec.split(',').filter(|s| !s.is_empty()) {
            let (k, v) = kv.split_once('=').ok_or("QB: key=value")?;
            let v: f64 = v.parse()?;
            let field = match k {
                "leg_stiffness" => &mut p.leg_stiffness,
                "leg_damping" => &mut p.leg_damping,
                "leg_air_damping" => &mut p.leg_air_damping,
                "landing_rest_m" => &mut p.landing_rest_m,
                "short_rest_m" => &mut p.short_rest_m,
                "thrust_m" => &mut p.thrust_m,
                "rear_extra_thrust_m" => &mut p.rear_extra_thrust_m,
                "max_thrust_m" => &mut p.max_thrust_m,
                "min_thrust_m" => &mut p.min_thrust_m,
                "stride_flight_s" => &mut p.stride_flight_s,
                "flight_gain" => &mut p.flight_gain,
                "gathered_flight_s" => &mut p.gathered_flight_s,
                "extended_flight_s" => &mut p.extended_flight_s,
                "pair_flight_gain" => &mut p.pair_flight_gain,
                "thrust_end" => &mut p.thrust_end,
                "min_short_s" => &mut p.min_short_s,
                "stance_s" => &mut p.stance_s,
                "placement_gain_s" => &mut p.placement_gain_s,
                "speed_integral_gain" => &mut p.speed_integral_gain,
                "speed_bias_cap" => &mut p.speed_bias_cap,
                "min_stride_s" => &mut p.min_stride_s,
                "front_offset_m" => &mut p.front_offset_m,
                "pitch_bias" => &mut p.pitch_bias,
                "pitch_kp" => &mut p.pitch_kp,
                "pitch_kv" => &mut p.pitch_kv,
                "roll_kp" => &mut p.roll_kp,
                "roll_kv" => &mut p.roll_kv,
                "yaw_kp" => &mut p.yaw_kp,
                "yaw_kv" => &mut p.yaw_kv,
                "posture_force_ratio" => &mut p.posture_force_ratio,
                "sweep_s" => &mut p.sweep_s,
                "swing_kp" => &mut p.swing_kp,
                "swing_kv" => &mut p.swing_kv,
                "gallop_shorter_m" => &mut p.gallop_shorter_m,
                "gallop_spread_m" => &mut p.gallop_spread_m,
                "heading" => &mut p.heading,
                _ => return Err(format!("QB: unknown key {k}").into()),
            };
            *field = v;
        }
    }
    let mut ctl = QuadrupedBound::new(p, 1.0);
    let mut rec = GaitRecorder::new(4, speed, p.heading, 3.0);
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
                "t {:.3} F {:11} R {:11} {} y {:.3} vy {:+.2} vz {:+.2} pitch {:+.1} roll {:+.1} yaw {:+.1} thr {:.3} fl {:.3} {:.3} bias {:+.2} q {:+.3} {:+.3} r {:+.3} {:+.3} fy {:4.0} {:4.0} hp {:+.2} {:+.2}",
                sim.time,
                ctl.pair_phase(FRONT).name(),
                ctl.pair_phase(REAR).name(),
                touch,
                sim.data.base_position.y,
                v.y,
                v.z,
                e.x.to_degrees(),
                e.z.to_degrees(),
                e.y.to_degrees(),
                ctl.thrust,
                ctl.flight_s[0],
                ctl.flight_s[1],
                ctl.speed_bias,
                sim.data.q[2],
                sim.data.q[8],
                sim.drives[2].spring.rest,
                sim.drives[8].spring.rest,
                sim.contacts[0].force.y,
                sim.contacts[2].force.y,
                sim.data.q[1],
                sim.data.q[7],
            );
        }
        if rec.fell() && sim.time > 1.0 {
            break;
        }
    }
    let s = rec.summary();
    println!(
        "{} t {:.1} fell {} speed {:.3}/{:.2} pitch {:.1} roll {:.1} friction {:.2} thrust {:.3} trim {:+.3} {:+.3}",
        style.name(),
        sim.time,
        s.fell,
        s.speed_mean_mps,
        s.speed_desired_mps,
        s.pitch_magnitude_deg,
        s.roll_magnitude_deg,
        s.friction_needed_max,
        ctl.thrust,
        ctl.trim[0],
        ctl.trim[1]
    );
    for row in paper_rows("bound") {
        let ours = measured(&s, row.quantity, &LEG_NAMES);
        println!(
            "  {:38} paper {:6.3}  ours {}",
            row.label,
            row.animation,
            ours.map_or("-".to_owned(), |v| format!("{v:6.3}"))
        );
    }
    Ok(())
}

/// Trot 5 s, bound 10 s, gallop 10 s through the driver.
fn driver_change() -> Result<(), Box<dyn std::error::Error>> {
    use gaitlab_core::driver::Driver;
    let preset =
        gaitlab_core::preset::load_bundled("raibert-quadruped").ok_or("no bundled preset")??;
    let mut d = gaitlab_physics::engine::driver::PhysicsDriver::new(&preset)?;
    d.reset_after_fall = false;
    let mut t = 0.0;
    for (until, gait) in [(5.0, "bound"), (15.0, "gallop"), (25.0, "")] {
        while t < until {
            d.step(1.0 / 60.0);
            t += 1.0 / 60.0;
        }
        let s = d.summary();
        println!(
            "driver t {t:.1} gait {} fell {} resets {} speed {:.3}",
            d.gait(),
            s.fell,
            d.resets(),
            s.speed_mean_mps
        );
        if !gait.is_empty() {
            d.set_gait(gait)?;
        }
    }
    Ok(())
}
