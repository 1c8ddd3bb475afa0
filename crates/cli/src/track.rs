//! `gaitlab track PRESET_OR_FILE --targets FILE.csv [--method K] [--fps N]
//! [--json]`: follow recorded effector targets (marker data retargeting) and
//! report the same IK metrics as `run`.

use clap::Args;
use gaitlab_core::export::{MAX_TARGET_CSV_BYTES, parse_target_csv};
use gaitlab_core::preset::Purpose;
use gaitlab_engine::{Overrides, RunMetrics, Tracking, driver_for};
use gaitlab_motion::TargetSource;

use crate::drive::{Outputs, drive};
use crate::fail::Failure;
use crate::load;
use crate::options::{method, timing};
use crate::print::print;
use crate::schedule::Schedule;

/// Arguments of `gaitlab track`.
#[derive(Args, Debug)]
pub struct TrackArgs {
    /// A bundled preset name or a preset JSON file.
    pub preset: String,
    /// CSV of targets: header `t` then `x,y,z` per effector in effector order, world metres.
    #[arg(long)]
    pub targets: String,
    /// IK method: transpose, pinv, dls, sdls, ccd (default: the preset's).
    #[arg(long)]
    pub method: Option<String>,
    /// Frames per second to sample the recording at (default: the preset's).
    #[arg(long)]
    pub fps: Option<u32>,
    /// IK iterations per frame (default: the preset's thesis setting).
    #[arg(long)]
    pub iterations: Option<usize>,
    /// BVH, CSV and JSON output.
    #[command(flatten)]
    pub outputs: Outputs,
}

/// `gaitlab track`. The preset is loaded for tracking: only its skeleton, IK
/// options, method, fps and iterations per frame are used, so its thesis roles
/// (which only the target script reads) are not checked.
pub fn track(args: &TrackArgs) -> Result<(), Failure> {
    let creature = load::creature_for(&args.preset, Purpose::Tracking)?;
    let scenario = &creature.scenario;
    let text = load::read_limited(&args.targets, MAX_TARGET_CSV_BYTES, "target file")?;
    let track = parse_target_csv(&text, creature.skeleton.effector_count())
        .map_err(|e| Failure::input(format!("{}: {e}", args.targets)))?;
    let method = method(args.method.as_deref(), scenario.method)?;
    let duration = track.duration_s();
    let fps = f64::from(args.fps.unwrap_or(scenario.fps));
    let (fps, frames) = timing(Some(fps as u32), scenario.fps, duration.max(1.0 / fps))?;
    let overrides = Overrides {
        method: Some(method),
        tracking: Some(Tracking {
            targets: track,
            iterations_per_frame: args.iterations,
        }),
        ..Overrides::default()
    };
    let mut driver =
        driver_for(&creature, &overrides).map_err(|e| Failure::input(format!("--{e}")))?;
    let measured = drive(
        &mut driver,
        frames,
        fps,
        &args.outputs,
        None,
        &mut Schedule::default(),
    )?;
    let mut metrics = RunMetrics::of(&creature.name, &driver, &measured).with_fps(fps);
    if let RunMetrics::Ik(ik) = &mut metrics {
        ik.targets_file = Some(args.targets.clone());
    }
    print(&metrics, &[], args.outputs.json);
    Ok(())
}
