//! The tuning loop: CMA-ES over a [`Problem`]'s gains until the budget of
//! simulated runs is spent, the best candidate kept. Candidates are handed
//! out a generation at a time to a `batch` evaluator, which may run them in
//! parallel (the CLI on every core with rayon, the page in Web Workers): each
//! run is deterministic and the costs come back in order, so a seed gives
//! the same tune however many threads ran it.

use crate::cmaes::Cmaes;
use crate::problem::Problem;

/// How long and from where a tune runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TuneOptions {
    /// Simulated runs in all, the start's included.
    pub budget: usize,
    /// The random seed.
    pub seed: u64,
    /// Initial step size in log space (0.3: gains move by about 30 %).
    pub sigma: f64,
}

impl Default for TuneOptions {
    fn default() -> Self {
        Self {
            budget: 200,
            seed: 1,
            sigma: 0.3,
        }
    }
}

/// One generation's figures, for the progress line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Generation {
    /// 0 for the start, then 1, 2, …
    pub index: u32,
    /// Runs so far.
    pub evaluations: usize,
    /// Lowest cost in this generation.
    pub best_cost: f64,
    /// Lowest cost so far.
    pub best_so_far: f64,
    /// The step size after it.
    pub sigma: f64,
}

/// A tune's outcome.
#[derive(Clone, Debug, PartialEq)]
pub struct Tuned {
    /// The best candidate's gains (in [`Problem::names`] order).
    pub values: Vec<f64>,
    /// Its cost.
    pub cost: f64,
    /// The start's cost.
    pub start_cost: f64,
    /// Every generation.
    pub generations: Vec<Generation>,
    /// Runs made.
    pub evaluations: usize,
}

/// Tune `problem`: `batch` costs a list of points (in order), `progress`
/// hears of each generation.
pub fn tune(
    problem: &Problem,
    options: &TuneOptions,
    batch: &mut dyn FnMut(&[Vec<f64>]) -> Vec<f64>,
    progress: &mut dyn FnMut(&Generation),
) -> Tuned {
    let n = problem.names().len();
    let origin = vec![0.0; n];
    let start_cost = batch(std::slice::from_ref(&origin))
        .first()
        .copied()
        .unwrap_or(f64::INFINITY);
    let mut best = (origin.clone(), start_cost);
    let mut evaluations = 1;
    let first = Generation {
        index: 0,
        evaluations,
        best_cost: start_cost,
        best_so_far: start_cost,
        sigma: options.sigma,
    };
    progress(&first);
    let mut generations = vec![first];
    if n > 0 {
        let mut es = Cmaes::new(&origin, options.sigma, options.seed);
        while evaluations + es.lambda <= options.budget.max(1) {
            let points = es.ask();
            let costs = batch(&points);
            evaluations += points.len();
            let mut gen_best = f64::INFINITY;
            for (p, &c) in points.iter().zip(&costs) {
                gen_best = gen_best.min(c);
                if c < best.1 {
                    best = (p.clone(), c);
                }
            }
            es.tell(&costs);
            let g = Generation {
                index: es.generation(),
                evaluations,
                best_cost: gen_best,
                best_so_far: best.1,
                sigma: es.sigma(),
            };
            progress(&g);
            generations.push(g);
        }
    }
    Tuned {
        values: problem.values(&best.0),
        cost: best.1,
        start_cost,
        generations,
        evaluations,
    }
}
