//! `gaitlab track PRESET_OR_FILE --targets FILE.csv [--method K] [--fps N]
//! [--json]`: follow recorded effector targets (marker data retargeting) and
//! report the same IK metrics as `run`.

use clap::Args;
use gaitlab_core::RootTransform;
use gaitlab_core::export::{MAX_TARGET_CSV_BYTES, parse_target_csv};
use gaitlab_core::preset::Purpose;
use gaitlab_motion::{TargetSource, TrackDriver, TrackOptions};

use crate::fail::Failure;
use crate::load;
use crate::report::{self, Outputs};
use crate::run;

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
    let method = run::method(args.method.as_deref(), scenario.method)?;
    let duration = track.duration_s();
    let fps = f64::from(args.fps.unwrap_or(scenario.fps));
    let (fps, frames) = run::timing(Some(fps as u32), scenario.fps, duration.max(1.0 / fps))?;
    let mut ik = scenario.ik_options();
    ik.method = method;
    let options = TrackOptions {
        ik,
        iterations_per_frame: args
            .iterations
            .unwrap_or(scenario.thesis.iterations_per_frame),
        root: RootTransform {
            position: creature.root_position,
            ..RootTransform::default()
        },
    };
    let mut driver = TrackDriver::new(creature.skeleton.clone(), track, options)
        .map_err(|e| Failure::input(format!("--{e}")))?;
    let measured = report::drive(&mut driver, frames, fps, &args.outputs)?;
    let mut metrics = report::ik_json(&creature.name, "track", method.name(), &driver, &measured);
    metrics["targets_file"] = args.targets.clone().into();
    metrics["fps"] = fps.into();
    report::print(&metrics, args.outputs.json);
    Ok(())
}
