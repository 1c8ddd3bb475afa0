//! CMA-ES on the standard test functions of the optimisation literature
//! (Hansen's tutorial, the BBOB suite): it must find their known minima from
//! a distant start, in a number of evaluations of the order the literature
//! reports, and a seed must repeat bit for bit.

use gaitlab_core::portable::Portable;
use gaitlab_tuner::cmaes::Cmaes;

/// Minimise `f` from `start` until `f < target` or `max_evals`; returns the
/// best value and the evaluations used.
fn minimise(
    f: &dyn Fn(&[f64]) -> f64,
    start: &[f64],
    sigma: f64,
    seed: u64,
    target: f64,
    max_evals: usize,
) -> (f64, usize) {
    let mut es = Cmaes::new(start, sigma, seed);
    let mut evals = 0;
    let mut best = f64::INFINITY;
    while evals < max_evals {
        let xs = es.ask();
        let costs: Vec<f64> = xs.iter().map(|x| f(x)).collect();
        evals += xs.len();
        best = costs.iter().copied().fold(best, f64::min);
        es.tell(&costs);
        if best < target {
            break;
        }
    }
    (best, evals)
}

fn sphere(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum()
}

fn rosenbrock(x: &[f64]) -> f64 {
    x.windows(2)
        .map(|w| 100.0 * (w[1] - w[0] * w[0]).powi(2) + (1.0 - w[0]).powi(2))
        .sum()
}

/// The ill-conditioned ellipsoid: axis scales 1 … 10³ (condition 10⁶).
fn ellipsoid(x: &[f64]) -> f64 {
    let n = x.len() as f64;
    x.iter()
        .enumerate()
        .map(|(i, v)| 1e6_f64.ppowf(i as f64 / (n - 1.0)) * v * v)
        .sum()
}

#[test]
fn it_finds_the_sphere_minimum() {
    let (best, evals) = minimise(&sphere, &[3.0; 8], 1.0, 1, 1e-10, 20_000);
    assert!(best < 1e-10, "sphere: {best} after {evals}");
    // Hansen's tutorial: about 1,500 evaluations at n = 8 from this far.
    assert!(evals < 3_000, "sphere took {evals} evaluations");
}

#[test]
fn it_finds_the_rosenbrock_valley_minimum() {
    for seed in 1..=3 {
        let (best, evals) = minimise(&rosenbrock, &[0.0; 5], 0.5, seed, 1e-8, 40_000);
        assert!(best < 1e-8, "rosenbrock seed {seed}: {best} after {evals}");
    }
}

#[test]
fn it_learns_an_ill_conditioned_ellipsoid() {
    let (best, evals) = minimise(&ellipsoid, &[1.0; 6], 1.0, 2, 1e-8, 30_000);
    assert!(best < 1e-8, "ellipsoid: {best} after {evals}");
}

#[test]
fn a_seed_repeats_bit_for_bit_and_another_seed_differs() {
    let run = |seed| {
        let mut es = Cmaes::new(&[1.0, -2.0, 0.5], 0.7, seed);
        for _ in 0..30 {
            let xs = es.ask();
            let costs: Vec<f64> = xs.iter().map(|x| rosenbrock(x)).collect();
            es.tell(&costs);
        }
        (es.mean().to_vec(), es.sigma())
    };
    assert_eq!(run(9), run(9));
    assert_ne!(run(9), run(10));
}
