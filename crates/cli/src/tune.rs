//! `gaitlab tune PRESET --gait G [--objective …] [--budget N] [--seed S]
//! --out FILE`: CMA-ES over a physics gait's tunable gains (the tuner
//! crate), every generation's runs on every core (rayon), a line per
//! generation with the objective, and the preset written back with the
//! tuned gains in `scenario.physics.controller_by_gait.GAIT`.

use std::io::IsTerminal as _;
use std::time::Instant;

use clap::Args;
use gaitlab_tuner::{Generation, Objective, Problem, TuneOptions, Tuned, tune as run_tune};
use rayon::prelude::*;

use crate::fail::Failure;
use crate::load;
use crate::stdout::outln;

/// `gaitlab tune` arguments.
#[derive(Args, Debug)]
pub struct TuneArgs {
    /// A physics preset: a bundled name or a file.
    pub preset: String,
    /// The gait to tune (default: the preset's).
    #[arg(long)]
    pub gait: Option<String>,
    /// Desired speed of the tuned runs, m/s at scale 1 (default: the preset's).
    #[arg(long)]
    pub speed: Option<f64>,
    /// Weighted terms to minimise: fall, speed, table2, table2_out, energy, jump, steps, switch, pairs, friction (`fall=10,speed=1,table2=1,energy=0.5`).
    #[arg(long, default_value = "fall=10,speed=1")]
    pub objective: String,
    /// Further desired speeds every candidate also runs at, m/s at scale 1
    /// (`2,3.5`): fall, speed and energy are averaged over every speed,
    /// table2 stays the tuned speed's.
    #[arg(long, value_delimiter = ',')]
    pub also_at: Vec<f64>,
    /// Further controller parameters to tune beyond the gait's gains
    /// (`landing_rest_m,thrust_m`: the keys of `scenario.physics.controller`),
    /// each scaled from the preset's value (so none may start at 0).
    #[arg(long, value_delimiter = ',')]
    pub vary: Vec<String>,
    /// The gait the `switch` term's runs begin in, switched to the tuned
    /// gait halfway (`--switch-from trot`); needed by that term.
    #[arg(long)]
    pub switch_from: Option<String>,
    /// A gait the `switch` term's runs also change to, begun in the tuned
    /// gait and switched halfway (`--switch-to trot`); with `--switch-from`
    /// both ways are run.
    #[arg(long)]
    pub switch_to: Option<String>,
    /// Candidates evaluated in all (the start's included): one simulated run
    /// each, more with `--also-at` and the `jump`, `steps` and `switch` terms.
    #[arg(long, default_value_t = 200)]
    pub budget: usize,
    /// Random seed: the same seed gives the same tuned preset.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Simulated seconds of each run.
    #[arg(long, default_value_t = 20.0)]
    pub seconds: f64,
    /// Initial step size in log space (0.3: gains move by about 30 %).
    #[arg(long, default_value_t = 0.3)]
    pub sigma: f64,
    /// Threads (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Where to write the tuned preset.
    #[arg(long)]
    pub out: String,
}

/// Run `gaitlab tune`.
pub fn tune(args: &TuneArgs) -> Result<(), Failure> {
    let objective = Objective::parse(&args.objective).map_err(Failure::input)?;
    if !(args.sigma.is_finite() && args.sigma > 0.0 && args.sigma <= 3.0) {
        return Err(Failure::input("sigma: must be in (0, 3]"));
    }
    if args.budget == 0 || args.budget > 1_000_000 {
        return Err(Failure::input("budget: must be 1 to 1000000 runs"));
    }
    let mut creature = load::creature(&args.preset)?;
    let physics = creature.scenario.physics.as_mut().ok_or_else(|| {
        Failure::input(format!("{}: the tuner tunes physics presets", args.preset))
    })?;
    if let Some(speed) = args.speed {
        gaitlab_core::preset::physics::check_speed_mps("speed", speed).map_err(Failure::input)?;
        physics.speed_mps = speed;
    }
    let gait = args
        .gait
        .clone()
        .or_else(|| physics.gait.clone())
        .unwrap_or_default();
    let mut problem =
        Problem::new(&creature, &gait, args.seconds, objective).map_err(Failure::input)?;
    for (i, &speed) in args.also_at.iter().enumerate() {
        gaitlab_core::preset::physics::check_speed_mps(&format!("also_at[{i}]"), speed)
            .map_err(Failure::input)?;
    }
    if args.also_at.len() > 8 {
        return Err(Failure::input("also_at: at most 8 speeds"));
    }
    problem.also_at_mps.clone_from(&args.also_at);
    problem.vary(&args.vary).map_err(Failure::input)?;
    if let Some(from) = &args.switch_from {
        problem.set_switch_from(from).map_err(Failure::input)?;
    }
    if let Some(to) = &args.switch_to {
        problem.set_switch_to(to).map_err(Failure::input)?;
    }
    if objective.switch > 0.0 && args.switch_from.is_none() && args.switch_to.is_none() {
        return Err(Failure::input(
            "objective.switch: name the gait its runs begin in with --switch-from or change to with --switch-to",
        ));
    }
    let threads = args
        .threads
        .unwrap_or_else(rayon::current_num_threads)
        .max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Failure::input(format!("threads: {e}")))?;
    let also = if args.also_at.is_empty() {
        String::new()
    } else {
        let speeds: Vec<String> = args.also_at.iter().map(f64::to_string).collect();
        format!(" · also at {} m/s", speeds.join(", "))
    };
    let also = match problem.switch_from() {
        Some(from) if objective.switch > 0.0 => format!("{also} · switch runs from {from}"),
        _ => also,
    };
    let also = match problem.switch_to() {
        Some(to) if objective.switch > 0.0 => format!("{also} · switch runs to {to}"),
        _ => also,
    };
    let per = problem.runs_per_candidate();
    let budget_of = if per > 1 {
        format!("candidates of {per} runs")
    } else {
        "runs".to_owned()
    };
    outln!(
        "tuning {} · gait {gait} · {} gains and parameters ({}) · objective {}{also} · budget {} {budget_of} of {} s · seed {} · {threads} threads",
        args.preset,
        problem.names().len(),
        problem.names().join(", "),
        args.objective,
        args.budget,
        args.seconds,
        args.seed
    );
    let options = TuneOptions {
        budget: args.budget,
        seed: args.seed,
        sigma: args.sigma,
    };
    let started = Instant::now();
    let tty = std::io::stderr().is_terminal();
    let mut batch = |points: &[Vec<f64>]| -> Vec<f64> {
        pool.install(|| {
            points
                .par_iter()
                .map(|x| problem.evaluate(x).cost)
                .collect()
        })
    };
    let budget = args.budget;
    let unit = if per > 1 { "candidates" } else { "runs" };
    let mut progress = |g: &Generation| {
        outln!(
            "generation {:>3} · {:>5} {unit} · best {:.5} · best so far {:.5} · σ {:.3}",
            g.index,
            g.evaluations,
            g.best_cost,
            g.best_so_far,
            g.sigma
        );
        if tty {
            let filled = (30 * g.evaluations / budget.max(1)).min(30);
            eprint!(
                "\r[{}{}] {}/{budget} {unit}",
                "#".repeat(filled),
                ".".repeat(30 - filled),
                g.evaluations
            );
        }
    };
    let tuned = run_tune(&problem, &options, &mut batch, &mut progress);
    if tty {
        eprintln!();
    }
    let wall_s = started.elapsed().as_secs_f64();
    report(&problem, &tuned, wall_s, threads);
    write_preset(args, &gait, &problem, &tuned)
}

fn report(problem: &Problem, tuned: &Tuned, wall_s: f64, threads: usize) {
    for ((name, start), value) in problem
        .names()
        .iter()
        .zip(problem.start())
        .zip(&tuned.values)
    {
        outln!("  {name:<20} {start:>12.5} → {value:>12.5}");
    }
    let factor = if tuned.cost > 0.0 {
        format!("{:.2}×", tuned.start_cost / tuned.cost)
    } else {
        "to 0".to_owned()
    };
    let per = problem.runs_per_candidate();
    let runs = if per > 1 {
        format!("{} candidates of {per} runs", tuned.evaluations)
    } else {
        format!("{} runs", tuned.evaluations)
    };
    outln!(
        "objective {:.5} → {:.5} (lowered {factor}) · {runs} in {wall_s:.1} s on {threads} threads",
        tuned.start_cost,
        tuned.cost,
    );
}

/// The preset's JSON with the gait, speed and tuned gains written in.
fn write_preset(
    args: &TuneArgs,
    gait: &str,
    problem: &Problem,
    tuned: &Tuned,
) -> Result<(), Failure> {
    let text = load::preset_text(&args.preset)?;
    let mut preset: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| Failure::input(format!("{}: not JSON ({e})", args.preset)))?;
    let physics = preset
        .pointer_mut("/scenario/physics")
        .and_then(serde_json::Value::as_object_mut)
        .ok_or_else(|| Failure::input(format!("{}: no scenario.physics", args.preset)))?;
    physics.insert("gait".into(), gait.into());
    if let Some(speed) = args.speed {
        physics.insert("speed_mps".into(), speed.into());
    }
    // The gait's own parameters: the creature's other gaits keep theirs.
    let by_gait = physics
        .entry("controller_by_gait")
        .or_insert_with(|| serde_json::json!({}));
    let own = by_gait
        .as_object_mut()
        .map(|m| m.entry(gait).or_insert_with(|| serde_json::json!({})));
    if let Some(map) = own.and_then(serde_json::Value::as_object_mut) {
        for (name, value) in problem.names().iter().zip(&tuned.values) {
            map.insert(name.clone(), (*value).into());
        }
    }
    if let Some(d) = preset.get_mut("description") {
        let before = d.as_str().unwrap_or_default().to_owned();
        *d = format!(
            "{before} Gains of its {gait} tuned by `gaitlab tune` (objective {}{}, seed {}, {} runs).",
            args.objective,
            if args.also_at.is_empty() { "" } else { ", also at other speeds" },
            args.seed,
            tuned.evaluations
        )
        .into();
    }
    let json = serde_json::to_string_pretty(&preset)
        .map_err(|e| Failure::input(format!("tuned preset: {e}")))?;
    std::fs::write(&args.out, json + "\n").map_err(|e| Failure::io(&args.out, e))?;
    outln!("wrote {}", args.out);
    Ok(())
}
