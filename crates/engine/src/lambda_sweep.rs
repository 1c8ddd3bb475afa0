//! She 2006 §4.4.3's damping trade-off, measured: the same thesis motion run
//! with DLS at several λ, each run's error on the targets within reach beside
//! the oscillation and jitter of the limbs whose targets are out of reach
//! (docs/she-2006.md "Choosing λ"; docs/ik-metrics.md for the figures). The
//! page's Method panel draws it; `tools/she2006_lambda_sweep.py` prints the
//! same figures through the CLI.

use gaitlab_core::driver::{Driver, IkMetrics};
use gaitlab_core::ik::Method;
use gaitlab_motion::ThesisDriver;
use serde::Serialize;

/// The λ values of the docs' 1-2-5 sweep, metres.
pub const SWEEP_LAMBDAS_M: [f64; 7] = [0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0];

/// Seconds each λ runs for (the docs' tables use 10).
pub const SWEEP_SECONDS: f64 = 10.0;

/// A target counts as within reach for the sweep when it was in at least
/// this share of the frames (the thesis' feet walking: 100 %; hands: 0 %).
const MOSTLY_REACHABLE: f64 = 0.5;

/// One λ's figures.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LambdaPoint {
    /// The damping λ, metres.
    pub lambda_m: f64,
    /// Mean error of the effectors whose targets were mostly within reach,
    /// over their reachable frames, metres (`None`: no such effector).
    pub reachable_error_m: Option<f64>,
    /// Mean error of the effectors whose targets were mostly out of reach,
    /// over their unreachable frames, metres (`None`: no such effector).
    pub unreachable_error_m: Option<f64>,
    /// Mean oscillation of the out-of-reach effectors' limbs, Hz.
    pub unreachable_oscillation_hz: Option<f64>,
    /// Mean jitter |Δ²θ| of the out-of-reach effectors' limbs, rad/frame².
    pub unreachable_jitter_rad: Option<f64>,
}

/// Runs `driver`'s motion from its reset with DLS at each of `lambdas`
/// (metres) for `seconds` at `fps` frames per second; the other solver
/// options, the parameters, the motion and the origin are the driver's.
/// `driver` itself is not changed.
#[must_use]
pub fn lambda_sweep(
    driver: &ThesisDriver,
    lambdas: &[f64],
    seconds: f64,
    fps: f64,
) -> Vec<LambdaPoint> {
    let frames = (seconds.max(0.0) * fps).round() as usize;
    let dt = 1.0 / fps.max(1.0);
    lambdas
        .iter()
        .map(|&lambda_m| {
            let mut run = driver.clone();
            let mut options = run.options().clone();
            options.method = Method::Dls;
            options.lambda = lambda_m;
            run.set_options(options);
            run.reset();
            for _ in 0..frames {
                run.step(dt);
            }
            match run.ik_metrics() {
                Some(metrics) => point(lambda_m, metrics),
                None => point(lambda_m, &IkMetrics::default()),
            }
        })
        .collect()
}

/// As [`lambda_sweep`] for whatever driver runs: the thesis' motions only.
///
/// # Errors
/// `measure_lambda_tradeoff: …` when `driver` is not a thesis motion (engine
/// `ik` with its script: PODA, physics and a recording have no λ trade-off
/// to measure).
pub fn lambda_sweep_of(
    driver: &crate::AnyDriver,
    lambdas: &[f64],
    seconds: f64,
    fps: f64,
) -> Result<Vec<LambdaPoint>, String> {
    match driver {
        crate::AnyDriver::Thesis(thesis) => Ok(lambda_sweep(thesis, lambdas, seconds, fps)),
        _ => Err(
            "measure_lambda_tradeoff: the λ trade-off is measured on a thesis motion (engine ik)"
                .to_owned(),
        ),
    }
}

fn mean(values: impl Iterator<Item = Option<f64>>) -> Option<f64> {
    let (sum, count) = values
        .flatten()
        .fold((0.0, 0_u32), |(sum, count), v| (sum + v, count + 1));
    (count > 0).then(|| sum / f64::from(count))
}

fn point(lambda_m: f64, metrics: &IkMetrics) -> LambdaPoint {
    let effectors = 0..metrics.effector_count();
    let within = |e: &usize| metrics.reachable(*e).unwrap_or(0.0) >= MOSTLY_REACHABLE;
    let reachable: Vec<usize> = effectors.clone().filter(within).collect();
    let unreachable: Vec<usize> = effectors.filter(|e| !within(e)).collect();
    LambdaPoint {
        lambda_m,
        reachable_error_m: mean(reachable.iter().map(|&e| metrics.mean_error_reachable_m(e))),
        unreachable_error_m: mean(
            unreachable
                .iter()
                .map(|&e| metrics.mean_error_unreachable_m(e)),
        ),
        unreachable_oscillation_hz: mean(unreachable.iter().map(|&e| metrics.oscillation_hz(e))),
        unreachable_jitter_rad: mean(unreachable.iter().map(|&e| metrics.jitter_rad(e))),
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::preset::load_bundled;
    use gaitlab_core::preset::thesis::ThesisMode;

    use super::*;

    fn she_2006(mode: ThesisMode) -> ThesisDriver {
        let Some(Ok(mut creature)) = load_bundled("she-2006") else {
            panic!("she-2006")
        };
        creature.scenario.mode = mode;
        match ThesisDriver::for_creature(&creature) {
            Ok(driver) => driver,
            Err(error) => panic!("{error}"),
        }
    }

    /// §4.4.3's trade-off on the thesis' walk: a larger λ misses the
    /// reachable feet by more and calms the unreachable hands, and λ = 0.2 m
    /// gives the docs' figures (2.0 mm, 0.27 mrad/frame²).
    #[test]
    fn a_larger_lambda_lags_the_reachable_feet_and_calms_the_stretched_arms() {
        let driver = she_2006(ThesisMode::Walk);
        let points = lambda_sweep(&driver, &[0.05, 0.2, 1.0], SWEEP_SECONDS, 60.0);
        let error = |i: usize| points[i].reachable_error_m.unwrap_or(f64::NAN);
        let jitter = |i: usize| points[i].unreachable_jitter_rad.unwrap_or(f64::NAN);
        assert!(error(0) < error(1) && error(1) < error(2), "{points:?}");
        assert!(jitter(1) * 100.0 < jitter(0), "{points:?}");
        assert!((error(1) - 0.0020).abs() < 0.0002, "{points:?}");
        assert!((jitter(1) - 0.000_27).abs() < 0.000_02, "{points:?}");
        // The driver it was measured on is left as it was.
        assert_eq!(driver.options().method, Method::Sdls);
        assert_eq!(driver.time(), 0.0);
    }

    /// Running, no target is within reach: every effector counts as out of reach.
    #[test]
    fn running_has_no_reachable_error() {
        let points = lambda_sweep(&she_2006(ThesisMode::Run), &[0.2], 2.0, 60.0);
        assert_eq!(points[0].reachable_error_m, None);
        assert!(points[0].unreachable_error_m.is_some_and(|e| e > 0.1));
    }
}
