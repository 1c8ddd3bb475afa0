//! `gaitlab run PRESET_OR_FILE [--mode M] [--method K] [--gait G] [--path FILE]
//! [--speed V] [--seconds S] [--fps N] [--set KEY=VALUE] [--switch T:GAIT]
//! [--edit T:KEY=VALUE] [--push T:VX,VZ] [--trace FILE] [--bvh FILE]
//! [--csv FILE] [--last S] [--json]`: any preset headless. The options each engine
//! takes are checked here; the driver comes from the engine layer's `driver_for`.

use clap::Args;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{Creature, Engine, MAX_PRESET_BYTES, PathSpec, PresetError, Purpose};
use gaitlab_engine::{EngineCommand, Overrides, RunMetrics, driver_for};
use serde_json::Value;

use crate::drive::{Outputs, drive};
use crate::fail::Failure;
use crate::load;
use crate::options::{method, timing};
use crate::print::print;
use crate::schedule::Schedule;

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
    /// Body path file for PODA: `{"kind": "catmull_rom", "points": [[x, z], …], "closed": false}`,
    /// optionally `"speeds_mps": [v, …]`, one desired body speed per point.
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
    /// Change one value, repeatable: a dotted preset path such as
    /// `scenario.physics.speed_mps=2.5` or `skeleton.joints[3].gain=2` (checked
    /// like a preset file), or a physics controller gain by name such as
    /// `k_speed=0.1` (see `state().physics.gains` in the app). VALUE is JSON;
    /// text that is not JSON is taken as a string (`scenario.physics.gait=bound`).
    /// Physics runs also take `scenario.physics.control_every=N`,
    /// `scenario.physics.ground={"vertical_stiffness": …}` and any controller
    /// parameter, `scenario.physics.controller={"thrust_m": 0.05}` (docs/physics.md).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Run the preset as its paper alone: every lab addition of its engine
    /// off (the page's "Run the paper alone"; `--json`'s `lab_additions`
    /// is then `[]`), before `--set`.
    #[arg(long)]
    pub paper_alone: bool,
    /// Switch gait at T simulated seconds, repeatable: `--switch 3:trot`
    /// (engines poda and physics). Applied before the first frame at or
    /// after T; `--json` lists each under `changes`.
    #[arg(long = "switch", value_name = "T:GAIT")]
    pub switch: Vec<String>,
    /// Change a gait value at T simulated seconds, repeatable, as the page's
    /// commands do: `--edit 5:period_s=0.8`; keys period_s, duty_factor,
    /// speed_mps, stroke_m, leg_force_n (poda; the gait model derives the
    /// others, eq. 7–8, 13), speed_mps, hop_height_m (physics). A value the
    /// engine refuses leaves the run unchanged and is listed in `changes`
    /// with the reason.
    #[arg(long = "edit", value_name = "T:KEY=VALUE")]
    pub edit: Vec<String>,
    /// Push the physics creature at T simulated seconds, repeatable:
    /// `--push 8:0,-0.3` changes its trunk's velocity by VX (sideways, world
    /// x) and VZ (forward at heading 0, world z) m/s at once. `--json` lists
    /// each under `pushes` with whether it recovered (no fall, and its
    /// forward speed over the last of the next 5 s within 10 % of the
    /// desired), and `recovered` for all of them
    #[arg(long = "push", value_name = "T:VX,VZ")]
    pub push: Vec<String>,
    /// Write the simulation's state after every integration step (0.4 ms at
    /// scale 1) as CSV to this file: time, the state machine's state, trunk and
    /// centre of mass, attitude, per leg its length, spring rest, contact and
    /// ground force, every joint coordinate (engine physics; see docs/physics.md).
    #[arg(long, value_name = "FILE.csv")]
    pub trace: Option<String>,
    /// BVH, CSV and JSON output.
    #[command(flatten)]
    pub outputs: Outputs,
}

/// `gaitlab run`.
pub fn run(args: &RunArgs) -> Result<(), Failure> {
    let (paths, gains) = settings(&args.set)?;
    let creature =
        load::creature_edited(&args.preset, Purpose::Scenario, &paths, args.paper_alone)?;
    let overrides = overrides(&creature, args)?;
    let mut driver = driver_for(&creature, &overrides).map_err(|e| flag_error(e, args))?;
    // A headless run reports a fall; it does not start over.
    driver.set_reset_after_fall(false);
    if creature.scenario.engine == Engine::Physics {
        for (name, value) in &gains {
            driver
                .apply(EngineCommand::Gain {
                    name,
                    value: *value,
                })
                .map_err(|e| Failure::input(format!("--set {e}")))?;
        }
    } else if let Some((name, _)) = gains.first() {
        return Err(Failure::input(format!(
            "--set {name}: engine {} has no controller gains (a preset value is a dotted path, e.g. scenario.thesis.walk.frequency_hz)",
            creature.scenario.engine.name()
        )));
    }
    let (fps, frames) = timing(args.fps, creature.scenario.fps, args.seconds)?;
    if !args.push.is_empty() && creature.scenario.engine != Engine::Physics {
        return Err(Failure::input(format!(
            "--push: engine {} is not simulated; only a physics creature can be pushed",
            creature.scenario.engine.name()
        )));
    }
    let mut schedule = Schedule::parse(&args.switch, &args.edit, &args.push)?;
    if !schedule.is_empty() && creature.scenario.engine == Engine::Ik {
        return Err(Failure::input(
            "--switch and --edit change gaits: engine ik has none (its motion is --mode)",
        ));
    }
    let measured = drive(
        &mut driver,
        frames,
        fps,
        &args.outputs,
        args.trace.as_deref(),
        &mut schedule,
    )?;
    let metrics = RunMetrics::of(&creature.name, &driver, &measured).with_fps(fps);
    print(&metrics, &schedule.outcomes, args.outputs.json);
    Ok(())
}

/// `--set KEY=VALUE` arguments: dotted preset paths with JSON values, and
/// controller gains by name with numbers.
pub(crate) type Settings = (Vec<(String, Value)>, Vec<(String, f64)>);

pub(crate) fn settings(set: &[String]) -> Result<Settings, Failure> {
    let mut paths = Vec::new();
    let mut gains = Vec::new();
    for item in set {
        let Some((key, text)) = item.split_once('=') else {
            return Err(Failure::input(format!(
                "--set {item}: expected KEY=VALUE (a preset path such as scenario.physics.speed_mps, or a gain name)"
            )));
        };
        let key = key.trim();
        if key.is_empty() {
            return Err(Failure::input(format!("--set {item}: the key is empty")));
        }
        let value = serde_json::from_str(text).unwrap_or_else(|_| Value::from(text));
        if key.contains('.') || key.contains('[') {
            paths.push((key.to_owned(), value));
        } else {
            let number = value.as_f64().ok_or_else(|| {
                Failure::input(format!("--set {key}: a gain is a number, not {text:?}"))
            })?;
            gains.push((key.to_owned(), number));
        }
    }
    Ok((paths, gains))
}

/// The options `args` gives for `creature`'s engine; an option another engine
/// takes is an error that names it.
fn overrides(creature: &Creature, args: &RunArgs) -> Result<Overrides, Failure> {
    let scenario = &creature.scenario;
    let mut overrides = Overrides {
        gait: args.gait.clone(),
        ..Overrides::default()
    };
    match scenario.engine {
        Engine::Ik => {
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
            refuse_trace(scenario.engine, args)?;
            overrides.mode = match &args.mode {
                None => None,
                Some(name) => Some(ThesisMode::parse(name).ok_or_else(|| {
                    Failure::input(format!(
                        "--mode: unknown mode {name:?} (use walk, run, wounded-walk or wounded-run)"
                    ))
                })?),
            };
            overrides.method = Some(method(args.method.as_deref(), scenario.method)?);
        }
        Engine::Poda => {
            if args.mode.is_some() || args.method.is_some() {
                return Err(Failure::input(
                    "--mode and --method belong to engine ik; engine poda takes --gait and --path",
                ));
            }
            refuse_trace(scenario.engine, args)?;
            if let Some(file) = &args.path {
                let text = load::read_limited(file, MAX_PRESET_BYTES, "path")?;
                let spec: PathSpec = serde_json::from_str(&text)
                    .map_err(|e| Failure::input(format!("--path {file}: {e}")))?;
                overrides.path = Some(spec);
            }
        }
        Engine::Physics => {
            if args.mode.is_some() || args.method.is_some() || args.path.is_some() {
                return Err(Failure::input(
                    "--mode, --method and --path belong to other engines; engine physics takes --gait and --speed",
                ));
            }
            overrides.speed_mps = args.speed;
        }
    }
    Ok(overrides)
}

/// `--trace` for an engine without a simulation to trace.
fn refuse_trace(engine: Engine, args: &RunArgs) -> Result<(), Failure> {
    match &args.trace {
        Some(_) => Err(Failure::input(format!(
            "--trace: engine {} has no simulated state machine or ground forces to trace; --trace is for engine physics",
            engine.name()
        ))),
        None => Ok(()),
    }
}

/// An engine error about a value an option set is reported at the option.
fn flag_error(error: PresetError, args: &RunArgs) -> Failure {
    let flag = match error.path.as_str() {
        "scenario.poda.gait" | "scenario.physics.gait" if args.gait.is_some() => "--gait",
        "scenario.physics.speed_mps" if args.speed.is_some() => "--speed",
        _ => return Failure::input(error),
    };
    Failure::input(format!("{flag}: {}", error.reason))
}
