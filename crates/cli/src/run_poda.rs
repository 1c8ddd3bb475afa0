//! `gaitlab run` for PODA presets (Girard & Maciejewski 1985): `--gait`
//! picks a named gait, `--path FILE` a body path (`{"kind": "catmull_rom",
//! "points": [[x, z], …], "closed": false}`), and `--json` prints DESIGN.md's
//! gait metrics as measured from the motion: foot slip, each leg's duty factor
//! and relative phase, stride length and body speed.

use gaitlab_core::preset::{Creature, MAX_PRESET_BYTES, PathSpec};
use gaitlab_motion::PodaDriver;
use gaitlab_motion::poda::gait_names;
use serde_json::{Value, json};

use crate::fail::Failure;
use crate::load::read_limited;
use crate::report::{self, Measured};
use crate::run::{RunArgs, timing};

/// Runs a PODA creature headless and prints its gait metrics.
pub fn run(creature: &Creature, args: &RunArgs) -> Result<(), Failure> {
    if args.mode.is_some() || args.method.is_some() {
        return Err(Failure::input(
            "--mode and --method belong to engine ik; engine poda takes --gait and --path",
        ));
    }
    let mut params = creature.scenario.poda_params();
    if let Some(gait) = &args.gait {
        params.gait = Some(gait.clone());
    }
    if let Some(file) = &args.path {
        let text = read_limited(file, MAX_PRESET_BYTES, "path")?;
        let spec: PathSpec = serde_json::from_str(&text)
            .map_err(|e| Failure::input(format!("--path {file}: {e}")))?;
        params.path = Some(spec);
    }
    let mut driver = PodaDriver::with_params(creature, params).map_err(|e| {
        if e.path == "scenario.poda.gait" {
            Failure::input(format!("--gait: {}", e.reason))
        } else {
            Failure::input(e)
        }
    })?;
    let (fps, frames) = timing(args.fps, creature.scenario.fps, args.seconds)?;
    let measured = report::drive(&mut driver, frames, fps, &args.outputs)?;
    let mut metrics = gait_json(&creature.name, &driver, &measured);
    metrics["fps"] = fps.into();
    report::print_gait(&metrics, args.outputs.json);
    Ok(())
}

/// DESIGN.md's `always` and `gait` metric keys, plus the gait's parameters
/// beside what was measured.
pub fn gait_json(preset: &str, driver: &PodaDriver, measured: &Measured) -> Value {
    let metrics = driver.metrics();
    let gait = driver.gait();
    let period = metrics.period_s();
    let legs: Vec<Value> = metrics
        .legs
        .iter()
        .zip(gait.phases())
        .map(|(leg, &phase)| {
            json!({
                "name": leg.name,
                "duty_factor": leg.duty_factor(),
                "relative_phase": period.and_then(|p| leg.relative_phase(p)),
                "duty_factor_set": gait.duty_factor(),
                "relative_phase_set": phase,
                "slip_max_m": leg.slip_max_m,
            })
        })
        .collect();
    let speed = metrics.body_speed_mps();
    let (low, high) = metrics.body_height_range_m;
    json!({
        "preset": preset,
        "engine": "poda",
        "frames": metrics.frames,
        "sim_seconds": metrics.sim_seconds,
        "wall_ms": measured.wall_ms,
        "us_per_frame": if measured.frames > 0 { measured.step_ms * 1e3 / measured.frames as f64 } else { 0.0 },
        "gait": driver.gait_name(),
        "gaits_available": gait_names(gait.leg_count()).collect::<Vec<_>>(),
        "foot_slip_max_m": metrics.foot_slip_max_m(),
        "legs": legs,
        "period_s": period,
        "period_s_set": gait.period_s(),
        "stride_length_m": period.map(|p| p * speed),
        "body_speed_mps": speed,
        "speed_mps_set": gait.speed_mps(),
        "stroke_m": gait.stroke_m(),
        "body_height_range_m": [low, high],
        "flight_duration_max_s": metrics.flight_max_s,
        "within_limits": measured.within_limits,
    })
}
