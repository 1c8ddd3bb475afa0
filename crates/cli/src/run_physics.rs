//! `gaitlab run` for physics presets (Raibert & Hodgins 1991): `--gait`
//! picks the gait, `--speed` the desired speed, and `--json` prints
//! DESIGN.md's physics metrics — whether it fell, desired and mean speed,
//! stride, flight and stance, pitch and roll, the friction the motion needed,
//! and how fast the simulation ran — plus the rest of Table 2's quantities.

use gaitlab_core::preset::Creature;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gait_controller::gait_names;
use serde_json::{Value, json};

use crate::fail::Failure;
use crate::report;
use crate::run::{RunArgs, timing};

/// Runs a physics creature headless and prints its Table-2 figures.
pub fn run(creature: &Creature, args: &RunArgs) -> Result<(), Failure> {
    if args.mode.is_some() || args.method.is_some() || args.path.is_some() {
        return Err(Failure::input(
            "--mode, --method and --path belong to other engines; engine physics takes --gait and --speed",
        ));
    }
    let Some(mut params) = creature.scenario.physics.clone() else {
        return Err(Failure::input(
            "scenario.physics: engine \"physics\" needs the creature's physical model",
        ));
    };
    if let Some(gait) = &args.gait {
        params.gait = Some(gait.clone());
    }
    if let Some(speed) = args.speed {
        let max = gaitlab_core::preset::physics::MAX_PHYSICS_SPEED_MPS;
        if !(speed.is_finite() && speed.abs() <= max) {
            return Err(Failure::input(format!(
                "--speed: must be within ±{max} m/s"
            )));
        }
        params.speed_mps = speed;
    }
    let mut driver = PhysicsDriver::with_params(creature, params).map_err(|e| {
        if e.path == "scenario.physics.gait" {
            Failure::input(format!("--gait: {}", e.reason))
        } else {
            Failure::input(e)
        }
    })?;
    driver.reset_after_fall = false;
    let (fps, frames) = timing(args.fps, creature.scenario.fps, args.seconds)?;
    let measured = report::drive(&mut driver, frames, fps, &args.outputs)?;
    let metrics = physics_json(&creature.name, &driver, &measured);
    if args.outputs.json {
        println!("{metrics}");
    } else {
        let get = |k: &str| metrics.get(k).and_then(Value::as_f64).unwrap_or(f64::NAN);
        println!(
            "{} · engine physics · gait {} · {:.1} s simulated · fell {} · speed {:.2} of {:.2} m/s · stride {:.2} m in {:.2} s · flight {:.3} s · stance {:.3} s · pitch {:.1}° · roll {:.1}° · friction needed {:.2} · {:.0} steps/s ({:.0}× real time)",
            creature.name,
            driver.gait(),
            get("sim_seconds"),
            metrics["fell"],
            get("speed_mean_mps"),
            get("speed_desired_mps"),
            get("stride_length_m"),
            get("stride_duration_s"),
            get("flight_duration_s"),
            get("stance_duration_s"),
            get("pitch_magnitude_deg"),
            get("roll_magnitude_deg"),
            get("friction_needed_max"),
            get("steps_per_second"),
            get("realtime_factor"),
        );
    }
    Ok(())
}

/// DESIGN.md's `always` and `physics` metric keys plus Table 2's extras.
pub fn physics_json(preset: &str, driver: &PhysicsDriver, measured: &report::Measured) -> Value {
    let s = driver.summary();
    let sim = driver.sim();
    let step_s = measured.step_ms / 1e3;
    let steps = sim.steps as f64;
    let names: Vec<&str> = sim.creature.legs.iter().map(|l| l.name.as_str()).collect();
    json!({
        "preset": preset,
        "engine": "physics",
        "frames": measured.frames,
        "sim_seconds": sim.time,
        "wall_ms": measured.wall_ms,
        "gait": driver.gait(),
        "gaits_available": gait_names(sim.creature.species),
        "scale": driver.params().scale,
        "fell": s.fell || driver.resets() > 0,
        "blow_up": driver.message(),
        "speed_desired_mps": s.speed_desired_mps,
        "speed_mean_mps": s.speed_mean_mps,
        "stride_length_m": s.stride_length_m,
        "stride_duration_s": s.stride_duration_s,
        "flight_duration_s": s.flight_duration_s,
        "stance_duration_s": s.stance_duration_s,
        "legs": names.iter().zip(&s.leg_stance_s).map(|(n, t)| json!({"name": n, "stance_duration_s": t})).collect::<Vec<_>>(),
        "leg_length_change_m": s.leg_length_change_m,
        "pitch_magnitude_deg": s.pitch_magnitude_deg,
        "roll_magnitude_deg": s.roll_magnitude_deg,
        "peak_vertical_accel_g": s.peak_vertical_accel_g,
        "friction_needed_max": s.friction_needed_max,
        "steps": sim.steps,
        "steps_per_second": if step_s > 0.0 { steps / step_s } else { 0.0 },
        "realtime_factor": if step_s > 0.0 { sim.time / step_s } else { 0.0 },
    })
}
