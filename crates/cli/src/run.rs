//! `gaitlab run PRESET_OR_FILE [--mode M] [--method K] [--seconds S] [--fps N]
//! [--bvh FILE] [--csv FILE] [--json]`: the She 2006 motions, headless; PODA
//! presets go to [`crate::run_poda`] (`--gait G`, `--path FILE`).

use clap::Args;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{Engine, MAX_FPS};
use gaitlab_motion::ThesisDriver;

use crate::fail::Failure;
use crate::load;
use crate::report::{self, Outputs};

/// Longest run the CLI accepts, simulated seconds.
pub const MAX_SECONDS: f64 = 3600.0;

/// Arguments of `gaitlab run`.
#[derive(Args, Debug)]
pub struct RunArgs {
    /// A bundled preset name (see `gaitlab presets`) or a preset JSON file.
    pub preset: String,
    /// Motion: walk, run, wounded-walk, wounded-run (default: the preset's).
    #[arg(long)]
    pub mode: Option<String>,
    /// Gait (PODA and physics engines; the IK engine has none).
    #[arg(long)]
    pub gait: Option<String>,
    /// Body path file for PODA: `{"kind": "catmull_rom", "points": [[x, z], …], "closed": false}`.
    #[arg(long)]
    pub path: Option<String>,
    /// Desired speed, m/s (physics engine; default: the preset's).
    #[arg(long)]
    pub speed: Option<f64>,
    /// IK method: transpose, pinv, dls, sdls, ccd (default: the preset's).
    #[arg(long)]
    pub method: Option<String>,
    /// Simulated seconds.
    #[arg(long, default_value_t = 10.0)]
    pub seconds: f64,
    /// Frames per second (default: the preset's).
    #[arg(long)]
    pub fps: Option<u32>,
    /// BVH, CSV and JSON output.
    #[command(flatten)]
    pub outputs: Outputs,
}

/// Parses `--method`.
pub fn method(name: Option<&str>, default: Method) -> Result<Method, Failure> {
    match name {
        None => Ok(default),
        Some(name) => Method::parse(name).ok_or_else(|| {
            Failure::input(format!(
                "--method: unknown method {name:?} (use transpose, pinv, dls, sdls or ccd)"
            ))
        }),
    }
}

/// Checks `--fps` (or the preset's) and `--seconds`, returning (fps, frames).
pub fn timing(fps: Option<u32>, preset_fps: u32, seconds: f64) -> Result<(f64, usize), Failure> {
    let fps = fps.unwrap_or(preset_fps);
    if fps == 0 || fps > MAX_FPS {
        return Err(Failure::input(format!(
            "--fps: must be between 1 and {MAX_FPS}"
        )));
    }
    if !seconds.is_finite() || seconds <= 0.0 || seconds > MAX_SECONDS {
        return Err(Failure::input(format!(
            "--seconds: must be more than 0 and at most {MAX_SECONDS}"
        )));
    }
    Ok((
        f64::from(fps),
        (seconds * f64::from(fps)).round().max(1.0) as usize,
    ))
}

/// `gaitlab run`.
pub fn run(args: &RunArgs) -> Result<(), Failure> {
    let creature = load::creature(&args.preset)?;
    let scenario = &creature.scenario;
    match scenario.engine {
        Engine::Ik => {}
        Engine::Poda => return crate::run_poda::run(&creature, args),
        Engine::Physics => return crate::run_physics::run(&creature, args),
    }
    if args.path.is_some() {
        return Err(Failure::input(format!(
            "--path: engine {} follows its own script; --path is for engine poda",
            scenario.engine.name()
        )));
    }
    if args.speed.is_some() {
        return Err(Failure::input(format!(
            "--speed: engine {} follows its own script; --speed is for engine physics",
            scenario.engine.name()
        )));
    }
    if let Some(gait) = &args.gait {
        return Err(Failure::input(format!(
            "--gait: engine {} has no gaits (asked for {gait:?}); use --mode",
            scenario.engine.name()
        )));
    }
    let mode = match &args.mode {
        None => scenario.mode,
        Some(name) => ThesisMode::parse(name).ok_or_else(|| {
            Failure::input(format!(
                "--mode: unknown mode {name:?} (use walk, run, wounded-walk or wounded-run)"
            ))
        })?,
    };
    let method = method(args.method.as_deref(), scenario.method)?;
    let (fps, frames) = timing(args.fps, scenario.fps, args.seconds)?;
    let mut options = scenario.ik_options();
    options.method = method;
    let mut driver = ThesisDriver::new(
        creature.skeleton.clone(),
        scenario.thesis.clone(),
        mode,
        options,
    )
    .map_err(|e| Failure::input(format!("scenario.thesis.{e}")))?;
    let measured = report::drive(&mut driver, frames, fps, &args.outputs)?;
    let mut metrics = report::ik_json(
        &creature.name,
        scenario.engine.name(),
        method.name(),
        &driver,
        &measured,
    );
    metrics["mode"] = mode.name().into();
    metrics["fps"] = fps.into();
    metrics["speed_mps"] = driver.script().speed_mps().into();
    metrics["distance_m"] = driver.distance_m().into();
    report::print(&metrics, args.outputs.json);
    Ok(())
}
