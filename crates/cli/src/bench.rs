//! `gaitlab bench [--json] [--check BASELINE]`: the performance figures of
//! [`gaitlab_bench::suite`] — µs per IK iteration (She 2006 §4.4) and per
//! animation frame for each thesis preset and method, µs per PODA frame
//! (Girard & Maciejewski 1985), physics steps per second (Raibert & Hodgins
//! 1991) — the same suite `window.gaitlab.bench('{"suite": true}')` runs in the
//! browser. `--check` compares the run with a committed baseline
//! ([`gaitlab_bench::compare()`]) and fails on a case more than 25 % slower.

use std::time::Instant;

use clap::Args;
use gaitlab_bench::compare::DEFAULT_TOLERANCE_PCT;
use gaitlab_bench::{DEFAULT_PRESETS, SuiteOptions, cases_of, compare, run_suite};
use gaitlab_core::ik::Method;
use serde_json::Value;

use crate::fail::Failure;
use crate::load;
use crate::stdout::outln;

/// Longest baseline file read, bytes.
const MAX_BASELINE_BYTES: usize = 1024 * 1024;

/// Arguments of `gaitlab bench`.
#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Print one JSON object instead of a table (write it to bench/baseline.json to make a baseline).
    #[arg(long)]
    pub json: bool,
    /// Compare with a baseline written by `--json` (default bench/baseline.json): prints
    /// current vs baseline per case and exits 3 naming each case more than the tolerance slower.
    #[arg(long, value_name = "BASELINE", num_args = 0..=1, default_missing_value = "bench/baseline.json")]
    pub check: Option<String>,
    /// Slowdown allowed by `--check`, percent.
    #[arg(long, default_value_t = DEFAULT_TOLERANCE_PCT)]
    pub tolerance_pct: f64,
    /// Presets to measure (default: human and ik-quadruped, and every PODA and physics preset).
    #[arg(long = "preset")]
    pub presets: Vec<String>,
    /// Methods to measure (default: all five).
    #[arg(long = "method")]
    pub methods: Vec<String>,
    /// Timed repetitions of each case; the median (and the best) is reported.
    #[arg(long, default_value_t = 15)]
    pub repeats: usize,
}

/// `gaitlab bench`.
pub fn bench(args: &BenchArgs) -> Result<(), Failure> {
    if !(args.tolerance_pct.is_finite() && args.tolerance_pct >= 0.0) {
        return Err(Failure::input("--tolerance-pct: must be a number ≥ 0"));
    }
    // Read the baseline first: a bad path should not cost a whole run.
    let baseline = match &args.check {
        Some(path) => {
            let text = load::read_limited(path, MAX_BASELINE_BYTES, "baseline")?;
            let report: Value = serde_json::from_str(&text)
                .map_err(|e| Failure::input(format!("{path}: not JSON: {e}")))?;
            Some(cases_of(&report).map_err(|e| Failure::input(format!("{path}: {e}")))?)
        }
        None => None,
    };
    let names: Vec<String> = if args.presets.is_empty() {
        DEFAULT_PRESETS.iter().map(|&n| n.to_owned()).collect()
    } else {
        args.presets.clone()
    };
    let creatures = names
        .iter()
        .map(|name| load::creature(name))
        .collect::<Result<Vec<_>, _>>()?;
    let methods = if args.methods.is_empty() {
        Method::ALL.to_vec()
    } else {
        args.methods
            .iter()
            .map(|m| crate::options::method(Some(m), Method::Sdls))
            .collect::<Result<Vec<_>, _>>()?
    };
    let options = SuiteOptions {
        methods,
        repeats: args.repeats,
    };
    let epoch = Instant::now();
    let mut clock = || epoch.elapsed().as_secs_f64() * 1e3;
    let mut report = run_suite(&creatures, &options, &mut clock).map_err(Failure::input)?;
    report["platform"] = "native".into();
    report["cpus"] = std::thread::available_parallelism()
        .map_or(1, std::num::NonZero::get)
        .into();
    if let Some(baseline) = baseline {
        let mut current = cases_of(&report).map_err(Failure::input)?;
        let mut result = compare(&baseline, &current, args.tolerance_pct);
        // Timing noise: a slower case is measured once more before it fails, and
        // keeps its faster median. A real slowdown is slow both times.
        let mut slower: Vec<&str> = result
            .regressions()
            .filter_map(|r| preset_of(&r.case))
            .collect();
        slower.sort_unstable();
        slower.dedup();
        if !slower.is_empty() {
            let again: Vec<_> = creatures
                .iter()
                .filter(|c| slower.contains(&c.name.as_str()))
                .cloned()
                .collect();
            eprintln!(
                "bench: measuring {} again: {}",
                again.len(),
                slower.join(", ")
            );
            let second = run_suite(&again, &options, &mut clock).map_err(Failure::input)?;
            for (case, us) in cases_of(&second).map_err(Failure::input)? {
                current
                    .entry(case)
                    .and_modify(|first| *first = first.min(us))
                    .or_insert(us);
            }
            result = compare(&baseline, &current, args.tolerance_pct);
        }
        outln!("{}", result.table());
        if !result.passed() {
            let slower: Vec<String> = result
                .regressions()
                .map(|r| match r.ratio() {
                    Some(ratio) if ratio.is_finite() => format!("{} ({ratio:.2}×)", r.case),
                    _ => format!("{} (no figure)", r.case),
                })
                .collect();
            return Err(Failure::check(format!(
                "bench: {} case(s) more than {}% slower than the baseline: {}",
                slower.len(),
                args.tolerance_pct,
                slower.join(", ")
            )));
        }
        return Ok(());
    }
    if args.json {
        outln!("{report}");
    } else {
        print_table(&report);
    }
    Ok(())
}

/// The preset of a case name (`ik/human/sdls/iteration` → `human`).
fn preset_of(case: &str) -> Option<&str> {
    case.split('/').nth(1)
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
    outln!();
    outln!(
        "{:<14} {:>6} {:>4} {:>12} {:>10} {:>12}",
        "PODA preset",
        "joints",
        "legs",
        "µs/frame",
        "best",
        "budget"
    );
    for row in poda {
        let budget = budget_text(row, "budget_us_per_frame");
        outln!(
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
    outln!();
    outln!(
        "{:<18} {:>6} {:>12} {:>12} {:>10} {:>16}",
        "physics preset",
        "joints",
        "steps/s",
        "best",
        "× real",
        "budget"
    );
    for row in report["physics"].as_array().into_iter().flatten() {
        if let Some(e) = row["error"].as_str() {
            outln!("{:<18} {e}", row["preset"].as_str().unwrap_or("?"));
            continue;
        }
        let budget = match (
            row["budget_steps_per_second"].as_f64(),
            row["within_budget"].as_bool(),
        ) {
            (Some(b), Some(ok)) => format!("≥{b:.0} {}", if ok { "ok" } else { "MISS" }),
            _ => String::new(),
        };
        outln!(
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
    outln!(
        "{:<14} {:>6} {:>4} {:<10} {:>12} {:>10} {:>12} {:>10}",
        "preset",
        "joints",
        "eff",
        "method",
        "µs/iter",
        "best",
        "µs/frame",
        "budget"
    );
    for row in report["ik"].as_array().into_iter().flatten() {
        let budget = budget_text(row, "budget_us_per_iteration");
        outln!(
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
