//! Running any driver headless for a number of frames — timing it, streaming
//! BVH / CSV, and collecting DESIGN.md's metric keys into one JSON object.

use std::time::Instant;

use clap::Args;

use gaitlab_core::driver::Driver;
use gaitlab_core::export::{BvhWriter, PoseCsvColumns, PoseCsvWriter};
use serde_json::{Value, json};

use crate::fail::Failure;
use crate::sink::FileSink;

/// Output options shared by `run` and `track`.
#[derive(Args, Debug, Default)]
pub struct Outputs {
    /// Write the motion as BVH to this file.
    #[arg(long)]
    pub bvh: Option<String>,
    /// Write per-frame joint values, effector positions and targets as CSV to this file.
    #[arg(long)]
    pub csv: Option<String>,
    /// Print one JSON object of metrics.
    #[arg(long)]
    pub json: bool,
    /// Write only the last S seconds of the motion to --bvh and --csv (the
    /// browser's "Save the last S s"; rounded to whole frames, at least one).
    #[arg(long, value_name = "S")]
    pub last: Option<f64>,
}

/// Frames written to the files when `frames` are run at `fps` and only the
/// `last` seconds are wanted: `round(last · fps)`, at least 1, at most `frames`.
pub fn written_frames(last: Option<f64>, frames: usize, fps: f64) -> Result<usize, Failure> {
    let Some(seconds) = last else {
        return Ok(frames);
    };
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= crate::run::MAX_SECONDS) {
        return Err(Failure::input(format!(
            "--last: must be more than 0 and at most {} s",
            crate::run::MAX_SECONDS
        )));
    }
    // At most MAX_SECONDS · MAX_FPS: a small whole number.
    Ok(((seconds * fps).round().max(1.0) as usize).min(frames))
}

/// Figures measured by [`drive`].
pub struct Measured {
    /// Frames stepped.
    pub frames: usize,
    /// Wall time spent inside `Driver::step`, milliseconds.
    pub step_ms: f64,
    /// Whole loop including output, milliseconds.
    pub wall_ms: f64,
    /// Whether every joint value stayed finite and within its limits (1e-9 slack).
    pub within_limits: bool,
}

/// Steps `driver` `frames` times at `1/fps`, writing every frame (including the
/// start pose) to the requested outputs.
pub fn drive(
    driver: &mut dyn Driver,
    frames: usize,
    fps: f64,
    outputs: &Outputs,
) -> Result<Measured, Failure> {
    let dt = 1.0 / fps;
    let written = written_frames(outputs.last, frames, fps)?;
    let first_written = frames - written;
    let skeleton = driver.skeleton().clone();
    let mut bvh = match outputs.bvh.as_deref() {
        Some(path) => {
            let mut sink = FileSink::create(path)?;
            let mut writer = BvhWriter::new(&skeleton, fps).map_err(Failure::input)?;
            writer
                .write_header(&mut sink, written)
                .map_err(|e| sink.fail(e))?;
            Some((sink, writer))
        }
        None => None,
    };
    let columns = PoseCsvColumns {
        effector_positions: true,
        effector_targets: driver.targets().is_some(),
    };
    let csv_writer = PoseCsvWriter::new(&skeleton, columns);
    let mut csv = match outputs.csv.as_deref() {
        Some(path) => {
            let mut sink = FileSink::create(path)?;
            csv_writer
                .write_header(&mut sink)
                .map_err(|e| sink.fail(e))?;
            Some(sink)
        }
        None => None,
    };
    let start = Instant::now();
    let mut step_seconds = 0.0;
    let mut within_limits = true;
    for frame in 0..frames {
        let before = Instant::now();
        driver.step(dt);
        step_seconds += before.elapsed().as_secs_f64();
        let pose = driver.pose();
        for (value, joint) in pose.joints.iter().zip(skeleton.joints()) {
            let inside = joint
                .limits
                .is_none_or(|(lo, hi)| *value >= lo - 1e-9 && *value <= hi + 1e-9);
            within_limits &= value.is_finite() && inside;
        }
        if frame < first_written {
            continue;
        }
        if let Some((sink, writer)) = bvh.as_mut() {
            writer.write_frame(sink, pose).map_err(|e| sink.fail(e))?;
        }
        if let Some(sink) = csv.as_mut() {
            let targets = driver.targets().map_or(&[][..], |t| &t.position[..]);
            csv_writer
                .write_row(
                    sink,
                    driver.time(),
                    pose,
                    driver.effector_positions(),
                    targets,
                )
                .map_err(|e| sink.fail(e))?;
        }
    }
    if let Some((sink, _)) = bvh {
        sink.finish()?;
    }
    if let Some(sink) = csv {
        sink.finish()?;
    }
    Ok(Measured {
        frames,
        step_ms: step_seconds * 1e3,
        wall_ms: start.elapsed().as_secs_f64() * 1e3,
        within_limits,
    })
}

/// The IK metric object: DESIGN.md's `always` and `IK` keys plus a few more.
pub fn ik_json(
    preset: &str,
    engine: &str,
    method: &str,
    driver: &dyn Driver,
    measured: &Measured,
) -> Value {
    let skeleton = driver.skeleton();
    let (iterations, effectors, sim_seconds, restored) = match driver.ik_metrics() {
        Some(metrics) => (
            metrics.iterations,
            skeleton
                .effectors()
                .iter()
                .enumerate()
                .map(|(e, effector)| {
                    json!({
                        "name": effector.name,
                        "mean_error_m": metrics.mean_error_m(e),
                        "max_error_m": metrics.max_error_m(e),
                    })
                })
                .collect::<Vec<_>>(),
            metrics.sim_seconds,
            metrics.restored_frames,
        ),
        None => (0, Vec::new(), driver.time(), 0),
    };
    let us_per_iteration = if iterations > 0 {
        measured.step_ms * 1e3 / iterations as f64
    } else {
        0.0
    };
    json!({
        "preset": preset,
        "engine": engine,
        "method": method,
        "frames": measured.frames,
        "sim_seconds": sim_seconds,
        "wall_ms": measured.wall_ms,
        "iterations": iterations,
        "us_per_iteration": us_per_iteration,
        "us_per_frame": if measured.frames > 0 { measured.step_ms * 1e3 / measured.frames as f64 } else { 0.0 },
        "effectors": effectors,
        "within_limits": measured.within_limits,
        "restored_frames": restored,
    })
}

/// Prints the metrics as one JSON line, or as a short human-readable table.
pub fn print(metrics: &Value, as_json: bool) {
    if as_json {
        println!("{metrics}");
        return;
    }
    let get = |key: &str| metrics.get(key).cloned().unwrap_or(Value::Null);
    println!(
        "{} · engine {} · method {} · {} frames ({:.2} s simulated) in {:.1} ms · {:.2} µs per IK iteration",
        get("preset").as_str().unwrap_or("?"),
        get("engine").as_str().unwrap_or("?"),
        get("method").as_str().unwrap_or("?"),
        get("frames"),
        get("sim_seconds").as_f64().unwrap_or(0.0),
        get("wall_ms").as_f64().unwrap_or(0.0),
        get("us_per_iteration").as_f64().unwrap_or(0.0),
    );
    if let Some(effectors) = metrics.get("effectors").and_then(Value::as_array) {
        println!(
            "  {:<14} {:>12} {:>12}",
            "effector", "mean err mm", "max err mm"
        );
        for effector in effectors {
            let mm = |key: &str| {
                effector
                    .get(key)
                    .and_then(Value::as_f64)
                    .map_or("-".to_owned(), |m| format!("{:.2}", m * 1e3))
            };
            println!(
                "  {:<20} {:>12} {:>12}",
                effector.get("name").and_then(Value::as_str).unwrap_or("?"),
                mm("mean_error_m"),
                mm("max_error_m")
            );
        }
    }
}

/// Prints gait metrics as one JSON line, or as a short table of legs.
pub fn print_gait(metrics: &Value, as_json: bool) {
    if as_json {
        println!("{metrics}");
        return;
    }
    let get = |key: &str| metrics.get(key).cloned().unwrap_or(Value::Null);
    let number = |key: &str| get(key).as_f64().unwrap_or(f64::NAN);
    println!(
        "{} · engine poda · gait {} · {} frames ({:.2} s simulated) in {:.1} ms · {:.1} µs per frame",
        get("preset").as_str().unwrap_or("?"),
        get("gait").as_str().unwrap_or("?"),
        get("frames"),
        number("sim_seconds"),
        number("wall_ms"),
        number("us_per_frame"),
    );
    println!(
        "  foot slip max {:.3} mm · period {:.3} s · stride {:.3} m · body speed {:.3} m/s",
        number("foot_slip_max_m") * 1e3,
        number("period_s"),
        number("stride_length_m"),
        number("body_speed_mps"),
    );
    println!(
        "  {:<14} {:>10} {:>10} {:>10} {:>10}",
        "leg", "duty", "(set)", "phase", "(set)"
    );
    for leg in get("legs").as_array().into_iter().flatten() {
        let value = |key: &str| {
            leg.get(key)
                .and_then(Value::as_f64)
                .map_or("-".to_owned(), |v| format!("{v:.3}"))
        };
        println!(
            "  {:<14} {:>10} {:>10} {:>10} {:>10}",
            leg.get("name").and_then(Value::as_str).unwrap_or("?"),
            value("duty_factor"),
            value("duty_factor_set"),
            value("relative_phase"),
            value("relative_phase_set"),
        );
    }
}
