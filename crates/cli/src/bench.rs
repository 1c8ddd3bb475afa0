//! `gaitlab bench [--json]`: the performance figures. For each preset and IK
//! method it reports the µs one IK iteration takes (forward kinematics,
//! Jacobian, solve and update; She 2006 §4.4), measured over the targets of
//! the preset's own thesis walk, and the µs per animation frame of the whole
//! driver. For each PODA preset (Girard & Maciejewski 1985) it reports the µs
//! per frame of the gait engine: leg states, footholds, foot targets and the
//! IK of every leg.

use std::hint::black_box;
use std::time::Instant;

use clap::Args;
use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkSolver, Method, Targets};
use gaitlab_core::preset::Engine;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::{Creature, RootTransform};
use gaitlab_motion::ThesisDriver;
use gaitlab_motion::frame_bench::{self, FrameBenchOptions, median_and_best};
use gaitlab_physics::step_bench::{StepBenchOptions, time_steps};
use serde_json::{Value, json};

use crate::fail::Failure;
use crate::load;

/// Arguments of `gaitlab bench`.
#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Print one JSON object instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Presets to measure (default: human and ik-quadruped, and every PODA preset).
    #[arg(long = "preset")]
    pub presets: Vec<String>,
    /// Methods to measure (default: all five).
    #[arg(long = "method")]
    pub methods: Vec<String>,
    /// Timed repetitions of each case; the median (and the best) is reported.
    #[arg(long, default_value_t = 15)]
    pub repeats: usize,
}

/// Targets the issue sets for this machine, µs per iteration: (preset, method, budget).
const BUDGETS: [(&str, Method, f64); 3] = [
    ("human", Method::Sdls, 10.0),
    ("human", Method::Dls, 3.0),
    ("ik-quadruped", Method::Sdls, 65.0),
];

/// PODA frame budgets, µs per frame: (preset, budget). The issue asks ≤ 1 ms
/// for the 63-joint animal.
const PODA_BUDGETS: [(&str, f64); 1] = [("poda-quadruped", 1000.0)];

/// Physics budgets: (preset, steps per second, real-time factor). The issue
/// asks ≥ 200 000 steps/s and ≥ 80× real time for the biped with contact.
const PHYSICS_BUDGETS: [(&str, f64, f64); 1] = [("raibert-biped", 200_000.0, 80.0)];

/// Default physics presets measured.
const PHYSICS_PRESETS: [&str; 3] = ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"];

/// Default PODA presets measured.
const PODA_PRESETS: [&str; 4] = ["poda-quadruped", "poda-biped", "hexapod", "insect-14"];

/// One frame of recorded targets.
struct Frame {
    root: RootTransform,
    targets: Targets,
}

/// Records 10 s of the preset's thesis walk (60 fps) as a target sequence.
fn record(creature: &Creature) -> Result<Vec<Frame>, Failure> {
    let scenario = &creature.scenario;
    let mut driver = ThesisDriver::new(
        creature.skeleton.clone(),
        scenario.thesis.clone(),
        ThesisMode::Walk,
        scenario.ik_options(),
    )
    .map_err(|e| Failure::input(format!("{}: scenario.thesis.{e}", creature.name)))?;
    let mut frames = Vec::with_capacity(600);
    for _ in 0..600 {
        driver.step(1.0 / 60.0);
        if let Some(targets) = driver.targets() {
            frames.push(Frame {
                root: driver.pose().root,
                targets: targets.clone(),
            });
        }
    }
    Ok(frames)
}

/// Median and minimum of the timed samples.
#[derive(Clone, Copy)]
struct Timing {
    median: f64,
    best: f64,
}

fn summarize(mut values: Vec<f64>) -> Timing {
    let (median, best) = median_and_best(&mut values);
    Timing { median, best }
}

/// µs per IK iteration of `method` over `frames`, `iterations` per frame.
fn time_iterations(
    creature: &Creature,
    frames: &[Frame],
    method: Method,
    iterations: usize,
    repeats: usize,
) -> Timing {
    let mut options = creature.scenario.ik_options();
    options.method = method;
    let skeleton = &creature.skeleton;
    let mut solver = IkSolver::new(skeleton, options);
    let mut values = skeleton.rest_values();
    // Warm up (and reach the steady tracking state).
    for frame in frames.iter().take(60) {
        for _ in 0..iterations {
            black_box(solver.iterate(skeleton, &frame.root, &mut values, &frame.targets));
        }
    }
    let samples = (0..repeats.max(1))
        .map(|_| {
            let start = Instant::now();
            for frame in frames {
                for _ in 0..iterations {
                    black_box(solver.iterate(skeleton, &frame.root, &mut values, &frame.targets));
                }
            }
            start.elapsed().as_secs_f64() * 1e6 / (frames.len() * iterations) as f64
        })
        .collect();
    summarize(samples)
}

/// µs per frame of the creature's driver (thesis: script + IK iterations;
/// PODA: gait, footholds and leg IK), timed by the same routine the browser's
/// `window.gaitlab.bench()` runs.
fn time_frames(creature: &Creature, method: Method, repeats: usize) -> Result<Timing, Failure> {
    let options = FrameBenchOptions {
        method,
        repeats: repeats.max(1),
        ..FrameBenchOptions::default()
    };
    let epoch = Instant::now();
    let mut clock = || epoch.elapsed().as_secs_f64() * 1e3;
    let timing = frame_bench::time_frames(creature, &options, &mut clock)
        .map_err(|e| Failure::input(format!("{}: {e}", creature.name)))?;
    Ok(Timing {
        median: timing.median_us,
        best: timing.best_us,
    })
}

/// `gaitlab bench`.
pub fn bench(args: &BenchArgs) -> Result<(), Failure> {
    let presets = if args.presets.is_empty() {
        ["human", "ik-quadruped"]
            .into_iter()
            .chain(PODA_PRESETS)
            .chain(PHYSICS_PRESETS)
            .map(str::to_owned)
            .collect()
    } else {
        args.presets.clone()
    };
    let methods = if args.methods.is_empty() {
        Method::ALL.to_vec()
    } else {
        args.methods
            .iter()
            .map(|m| crate::run::method(Some(m), Method::Sdls))
            .collect::<Result<Vec<_>, _>>()?
    };
    let mut rows = Vec::new();
    let mut poda_rows = Vec::new();
    let mut physics_rows = Vec::new();
    for name in &presets {
        let creature = load::creature(name)?;
        if creature.scenario.engine == Engine::Physics {
            let epoch = Instant::now();
            let mut clock = || epoch.elapsed().as_secs_f64() * 1e3;
            let options = StepBenchOptions {
                repeats: args.repeats,
                ..StepBenchOptions::default()
            };
            let timing = match time_steps(&creature, &options, &mut clock) {
                Ok(t) => t,
                // A gait not yet available is reported, not fatal.
                Err(e) if e.path == "scenario.physics.gait" => {
                    physics_rows.push(json!({"preset": creature.name, "error": e.to_string()}));
                    continue;
                }
                Err(e) => return Err(Failure::input(e)),
            };
            let budget = PHYSICS_BUDGETS.iter().find(|(p, _, _)| p == name);
            physics_rows.push(json!({
                "preset": creature.name,
                "joints": creature.skeleton.joint_count(),
                "dt_s": timing.dt_s,
                "steps_per_second": timing.steps_per_second,
                "steps_per_second_best": timing.steps_per_second_best,
                "realtime_factor": timing.realtime_factor,
                "budget_steps_per_second": budget.map(|b| b.1),
                "budget_realtime_factor": budget.map(|b| b.2),
                "within_budget": budget.map(|b| timing.steps_per_second >= b.1 && timing.realtime_factor >= b.2),
            }));
            continue;
        }
        if creature.scenario.engine == Engine::Poda {
            // The same per-frame routine as the browser's bench; the method is unused.
            let timing = time_frames(&creature, Method::Sdls, args.repeats)?;
            let budget = PODA_BUDGETS
                .iter()
                .find(|(p, _)| p == name)
                .map(|(_, b)| *b);
            poda_rows.push(json!({
                "preset": creature.name,
                "joints": creature.skeleton.joint_count(),
                "legs": creature.scenario.poda_params().legs.len(),
                "us_per_frame": timing.median,
                "us_per_frame_best": timing.best,
                "budget_us_per_frame": budget,
                "within_budget": budget.map(|b| timing.median <= b),
            }));
            continue;
        }
        let frames = record(&creature)?;
        let iterations = creature.scenario.thesis.iterations_per_frame;
        for &method in &methods {
            let us_per_iteration =
                time_iterations(&creature, &frames, method, iterations, args.repeats);
            let us_per_frame = time_frames(&creature, method, args.repeats)?;
            let budget = BUDGETS
                .iter()
                .find(|(p, m, _)| p == name && *m == method)
                .map(|(_, _, b)| *b);
            rows.push(json!({
                "preset": creature.name,
                "joints": creature.skeleton.joint_count(),
                "effectors": creature.skeleton.effector_count(),
                "method": method.name(),
                "us_per_iteration": us_per_iteration.median,
                "us_per_iteration_best": us_per_iteration.best,
                "iterations_per_frame": iterations,
                "us_per_frame": us_per_frame.median,
                "us_per_frame_best": us_per_frame.best,
                "budget_us_per_iteration": budget,
                "within_budget": budget.map(|b| us_per_iteration.median <= b),
            }));
        }
    }
    let report = json!({
        "ik": rows,
        "poda": poda_rows,
        "physics": physics_rows,
        "cpus": std::thread::available_parallelism().map_or(1, |n| n.get()),
    });
    if args.json {
        println!("{report}");
    } else {
        print_table(&report);
    }
    Ok(())
}

/// `≤B ok` / `≤B MISS` for a row with a budget under `key`, else empty.
fn budget_text(row: &Value, key: &str) -> String {
    match (row[key].as_f64(), row["within_budget"].as_bool()) {
        (Some(b), Some(true)) => format!("≤{b} ok"),
        (Some(b), _) => format!("≤{b} MISS"),
        _ => String::new(),
    }
}

fn print_table(report: &Value) {
    print_ik_table(report);
    print_physics_table(report);
    let poda = report["poda"].as_array().into_iter().flatten();
    println!();
    println!(
        "{:<14} {:>6} {:>4} {:>12} {:>10} {:>12}",
        "PODA preset", "joints", "legs", "µs/frame", "best", "budget"
    );
    for row in poda {
        let budget = budget_text(row, "budget_us_per_frame");
        println!(
            "{:<14} {:>6} {:>4} {:>12.2} {:>10.2} {:>12}",
            row["preset"].as_str().unwrap_or("?"),
            row["joints"],
            row["legs"],
            row["us_per_frame"].as_f64().unwrap_or(f64::NAN),
            row["us_per_frame_best"].as_f64().unwrap_or(f64::NAN),
            budget
        );
    }
}

fn print_physics_table(report: &Value) {
    println!();
    println!(
        "{:<18} {:>6} {:>12} {:>12} {:>10} {:>16}",
        "physics preset", "joints", "steps/s", "best", "× real", "budget"
    );
    for row in report["physics"].as_array().into_iter().flatten() {
        if let Some(e) = row["error"].as_str() {
            println!("{:<18} {e}", row["preset"].as_str().unwrap_or("?"));
            continue;
        }
        let budget = match (
            row["budget_steps_per_second"].as_f64(),
            row["within_budget"].as_bool(),
        ) {
            (Some(b), Some(ok)) => format!("≥{b:.0} {}", if ok { "ok" } else { "MISS" }),
            _ => String::new(),
        };
        println!(
            "{:<18} {:>6} {:>12.0} {:>12.0} {:>10.1} {:>16}",
            row["preset"].as_str().unwrap_or("?"),
            row["joints"],
            row["steps_per_second"].as_f64().unwrap_or(f64::NAN),
            row["steps_per_second_best"].as_f64().unwrap_or(f64::NAN),
            row["realtime_factor"].as_f64().unwrap_or(f64::NAN),
            budget
        );
    }
}

fn print_ik_table(report: &Value) {
    println!(
        "{:<14} {:>6} {:>4} {:<10} {:>12} {:>10} {:>12} {:>10}",
        "preset", "joints", "eff", "method", "µs/iter", "best", "µs/frame", "budget"
    );
    for row in report["ik"].as_array().into_iter().flatten() {
        let budget = budget_text(row, "budget_us_per_iteration");
        println!(
            "{:<14} {:>6} {:>4} {:<10} {:>12.2} {:>10.2} {:>12.2} {:>10}",
            row["preset"].as_str().unwrap_or("?"),
            row["joints"],
            row["effectors"],
            row["method"].as_str().unwrap_or("?"),
            row["us_per_iteration"].as_f64().unwrap_or(f64::NAN),
            row["us_per_iteration_best"].as_f64().unwrap_or(f64::NAN),
            row["us_per_frame"].as_f64().unwrap_or(f64::NAN),
            budget
        );
    }
}
