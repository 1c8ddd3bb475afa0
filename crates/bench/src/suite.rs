//! The benchmark suite: every timed case of the performance budget, run by
//! `gaitlab bench` and by `window.gaitlab.bench('{"suite": true}')` alike.
//! Thesis presets (`engine: ik`): µs per IK iteration per method (She 2006
//! §4.4) and µs per animation frame of the driver; PODA presets: µs per frame
//! of the gait engine (Girard & Maciejewski 1985); physics presets: steps per
//! second and real-time factor (Raibert & Hodgins 1991).
//!
//! The report is JSON with `ik`, `poda` and `physics` rows, plus `cases`: one
//! name → median µs map (lower is better; physics as µs per step) that the
//! regression check ([`crate::compare()`]) reads.

use std::fmt;

use crate::frame::{self as frame_bench, FrameBenchOptions};
use crate::step::{StepBenchOptions, time_steps};
use gaitlab_core::Creature;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::Engine;
use serde_json::{Map, Value, json};

use crate::iteration::{Timing, record_walk, time_iterations};

/// The presets the suite measures by default: the human and the 63-joint
/// quadruped (thesis IK), every PODA preset, every physics preset.
pub const DEFAULT_PRESETS: [&str; 9] = [
    "human",
    "ik-quadruped",
    "poda-quadruped",
    "poda-biped",
    "hexapod",
    "insect-14",
    "raibert-biped",
    "raibert-quadruped",
    "raibert-kangaroo",
];

/// Targets the issue sets, µs per IK iteration: (preset, method, budget).
const IK_BUDGETS: [(&str, Method, f64); 3] = [
    ("human", Method::Sdls, 10.0),
    ("human", Method::Dls, 3.0),
    ("ik-quadruped", Method::Sdls, 65.0),
];

/// PODA frame budgets, µs per frame: ≤ 1 ms for the 63-joint animal.
const PODA_BUDGETS: [(&str, f64); 1] = [("poda-quadruped", 1000.0)];

/// Physics budgets: (preset, steps per second, real-time factor): ≥ 200 000
/// steps/s and ≥ 80× real time for the biped with contact.
const PHYSICS_BUDGETS: [(&str, f64, f64); 1] = [("raibert-biped", 200_000.0, 80.0)];

/// Length of the recorded walk the IK iterations chase: 10 s at 60 fps.
const RECORDED_FRAMES: usize = 600;

/// What the suite runs.
#[derive(Clone, Debug, PartialEq)]
pub struct SuiteOptions {
    /// IK methods timed on each thesis preset (default: all five).
    pub methods: Vec<Method>,
    /// Timed repeats of each case; the median (and the best) is reported.
    pub repeats: usize,
}

impl Default for SuiteOptions {
    fn default() -> Self {
        Self {
            methods: Method::ALL.to_vec(),
            repeats: 15,
        }
    }
}

/// A preset the suite could not time.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BenchError {
    /// The preset's name.
    pub preset: String,
    /// Why, as `path: reason`.
    pub reason: String,
}

impl fmt::Display for BenchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.preset, self.reason)
    }
}

impl std::error::Error for BenchError {}

/// The name of a case in the report's `cases` map, e.g. `ik/human/sdls/iteration`.
#[must_use]
pub fn case_name(engine: &str, preset: &str, detail: &str) -> String {
    format!("{engine}/{preset}/{detail}")
}

/// Runs every case for `creatures` (each by its engine) and returns the
/// report; `clock_ms` reads a monotonic clock in milliseconds.
///
/// # Errors
/// A creature that cannot be driven, or a physics run that blew up. A physics
/// gait the creature does not have yet is reported in its row, not an error.
pub fn run_suite(
    creatures: &[Creature],
    options: &SuiteOptions,
    clock_ms: &mut dyn FnMut() -> f64,
) -> Result<Value, BenchError> {
    let repeats = options.repeats.max(1);
    let mut ik_rows = Vec::new();
    let mut poda_rows = Vec::new();
    let mut physics_rows = Vec::new();
    let mut cases = Map::new();
    for creature in creatures {
        let fail = |reason: String| BenchError {
            preset: creature.name.clone(),
            reason,
        };
        let name = creature.name.as_str();
        match creature.scenario.engine {
            Engine::Physics => {
                let step_options = StepBenchOptions {
                    repeats,
                    ..StepBenchOptions::default()
                };
                let timing = match time_steps(creature, &step_options, clock_ms) {
                    Ok(timing) => timing,
                    Err(e) if e.path == "scenario.physics.gait" => {
                        physics_rows.push(json!({"preset": name, "error": e.to_string()}));
                        continue;
                    }
                    Err(e) => return Err(fail(e.to_string())),
                };
                let budget = PHYSICS_BUDGETS.iter().find(|(p, _, _)| *p == name);
                cases.insert(
                    case_name("physics", name, "step"),
                    json!(1e6 / timing.steps_per_second),
                );
                physics_rows.push(json!({
                    "preset": name,
                    "joints": creature.skeleton.joint_count(),
                    "dt_s": timing.dt_s,
                    "steps_per_second": timing.steps_per_second,
                    "steps_per_second_best": timing.steps_per_second_best,
                    "realtime_factor": timing.realtime_factor,
                    "budget_steps_per_second": budget.map(|b| b.1),
                    "budget_realtime_factor": budget.map(|b| b.2),
                    "within_budget": budget.map(|b| timing.steps_per_second >= b.1 && timing.realtime_factor >= b.2),
                }));
            }
            Engine::Poda => {
                // The method is unused by the PODA engine (its legs' IK is fixed by the preset).
                let timing =
                    time_frames(creature, Method::Sdls, repeats, clock_ms).map_err(fail)?;
                let budget = PODA_BUDGETS
                    .iter()
                    .find(|(p, _)| *p == name)
                    .map(|(_, b)| *b);
                cases.insert(case_name("poda", name, "frame"), json!(timing.median_us));
                poda_rows.push(json!({
                    "preset": name,
                    "joints": creature.skeleton.joint_count(),
                    "legs": creature.scenario.poda_params().legs.len(),
                    "us_per_frame": timing.median_us,
                    "us_per_frame_best": timing.best_us,
                    "budget_us_per_frame": budget,
                    "within_budget": budget.map(|b| timing.median_us <= b),
                }));
            }
            Engine::Ik => {
                let frames = record_walk(creature, RECORDED_FRAMES, 1.0 / 60.0)
                    .map_err(|e| fail(e.to_string()))?;
                let iterations = creature.scenario.thesis.iterations_per_frame;
                for &method in &options.methods {
                    let per_iteration =
                        time_iterations(creature, &frames, method, iterations, repeats, clock_ms);
                    let per_frame =
                        time_frames(creature, method, repeats, clock_ms).map_err(fail)?;
                    let budget = IK_BUDGETS
                        .iter()
                        .find(|(p, m, _)| *p == name && *m == method)
                        .map(|(_, _, b)| *b);
                    let method_name = method.name();
                    cases.insert(
                        case_name("ik", name, &format!("{method_name}/iteration")),
                        json!(per_iteration.median_us),
                    );
                    cases.insert(
                        case_name("ik", name, &format!("{method_name}/frame")),
                        json!(per_frame.median_us),
                    );
                    ik_rows.push(json!({
                        "preset": name,
                        "joints": creature.skeleton.joint_count(),
                        "effectors": creature.skeleton.effector_count(),
                        "method": method_name,
                        "us_per_iteration": per_iteration.median_us,
                        "us_per_iteration_best": per_iteration.best_us,
                        "iterations_per_frame": iterations,
                        "us_per_frame": per_frame.median_us,
                        "us_per_frame_best": per_frame.best_us,
                        "budget_us_per_iteration": budget,
                        "within_budget": budget.map(|b| per_iteration.median_us <= b),
                    }));
                }
            }
        }
    }
    Ok(json!({
        "repeats": repeats,
        "ik": ik_rows,
        "poda": poda_rows,
        "physics": physics_rows,
        "cases": cases,
    }))
}

/// µs per frame of the creature's driver (thesis: script + IK iterations with
/// `method`; PODA: gait, footholds and leg IK), by the per-frame routine of
/// [`frame_bench::time_frames`].
fn time_frames(
    creature: &Creature,
    method: Method,
    repeats: usize,
    clock_ms: &mut dyn FnMut() -> f64,
) -> Result<Timing, String> {
    let options = FrameBenchOptions {
        method,
        repeats,
        ..FrameBenchOptions::default()
    };
    let timing =
        frame_bench::time_frames(creature, &options, clock_ms).map_err(|e| e.to_string())?;
    Ok(Timing {
        median_us: timing.median_us,
        best_us: timing.best_us,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::test_presets::bundled;

    /// A clock that advances 1 ms per read: every timed repeat spans exactly 1 ms.
    fn ticking_clock() -> impl FnMut() -> f64 {
        let mut now = 0.0;
        move || {
            now += 1.0;
            now
        }
    }

    #[test]
    fn one_case_per_engine_row_with_exact_figures_from_a_fake_clock() {
        let creatures = [
            bundled("human"),
            bundled("poda-biped"),
            bundled("raibert-biped"),
        ];
        let options = SuiteOptions {
            methods: vec![Method::Sdls, Method::Ccd],
            repeats: 3,
        };
        let mut clock = ticking_clock();
        let report = run_suite(&creatures, &options, &mut clock).expect("suite runs");
        let cases = report["cases"].as_object().expect("cases");
        let names: Vec<&str> = cases.keys().map(String::as_str).collect();
        assert_eq!(
            names,
            [
                "ik/human/ccd/frame",
                "ik/human/ccd/iteration",
                "ik/human/sdls/frame",
                "ik/human/sdls/iteration",
                "physics/raibert-biped/step",
                "poda/poda-biped/frame",
            ]
        );
        let iterations = creatures[0].scenario.thesis.iterations_per_frame as f64;
        let expect = [
            ("ik/human/sdls/iteration", 1e3 / (600.0 * iterations)),
            ("ik/human/sdls/frame", 1e3 / 600.0),
            ("poda/poda-biped/frame", 1e3 / 600.0),
            // 1 s at the paper's 0.4 ms step = 2500 steps per 1 ms repeat.
            ("physics/raibert-biped/step", 1e3 / 2500.0),
        ];
        for (case, us) in expect {
            let got = cases[case].as_f64().unwrap_or(f64::NAN);
            assert!((got - us).abs() < 1e-9, "{case}: {got} µs, expected {us}");
        }
        assert_eq!(report["ik"].as_array().map(Vec::len), Some(2));
        assert_eq!(report["ik"][0]["method"], "sdls");
        assert_eq!(report["poda"][0]["preset"], "poda-biped");
        assert_eq!(report["physics"][0]["preset"], "raibert-biped");
        assert_eq!(report["repeats"], 3);
    }
}
