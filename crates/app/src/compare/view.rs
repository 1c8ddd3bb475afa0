//! One comparison view: its method, its stage (driver, scene, the largest
//! effector error per frame as history) and its figures — She 2006 §5.3's
//! tracking error `d`, oscillation and reach, per view and per effector
//! (docs/ik-metrics.md).

use gaitlab_core::driver::{Driver, IkMetrics};
use gaitlab_engine::AnyDriver;
use gaitlab_engine::metrics::EffectorMetrics;
use serde::Serialize;

use super::method::CompareMethod;
use super::metrics::ViewMetrics;
use crate::stage::Stage;

/// One view: its configuration, its stage (driver, scene, and as history the
/// largest effector error per frame, one series in metres) and its figures.
pub struct CompareView {
    /// The configuration.
    pub method: CompareMethod,
    pub(super) stage: Stage<AnyDriver>,
    pub(super) metrics: ViewMetrics,
}

impl CompareView {
    /// The view's driver.
    #[must_use]
    pub fn driver(&self) -> &AnyDriver {
        &self.stage.driver
    }

    /// The view's stage.
    #[must_use]
    pub fn stage(&self) -> &Stage<AnyDriver> {
        &self.stage
    }

    /// The view's figures.
    #[must_use]
    pub fn metrics(&self) -> &ViewMetrics {
        &self.metrics
    }

    /// After a frame: the view's figures and its error history.
    pub(super) fn record_frame(&mut self) {
        let stage = &mut self.stage;
        self.metrics.iterations += stage.driver.ik_report().map_or(0, |r| r.iterations as u64);
        let skeleton = stage.driver.skeleton();
        self.metrics.record(skeleton, &stage.driver.pose().joints);
        let error = stage.driver.ik_report().map_or(0.0, |r| r.max_error_m);
        stage
            .history
            .push(stage.driver.time(), std::iter::once(error));
    }

    /// Mean over effectors of each effector's mean error since the reset, metres.
    #[must_use]
    pub fn mean_error_m(&self) -> f64 {
        let Some(m) = self.stage.driver.ik_metrics() else {
            return 0.0;
        };
        let k = m.effector_count().max(1);
        (0..k).filter_map(|e| m.mean_error_m(e)).sum::<f64>() / k as f64
    }

    /// Largest effector error since the reset, metres.
    #[must_use]
    pub fn max_error_m(&self) -> f64 {
        let Some(m) = self.stage.driver.ik_metrics() else {
            return 0.0;
        };
        (0..m.effector_count())
            .filter_map(|e| m.max_error_m(e))
            .fold(0.0, f64::max)
    }

    /// Mean over the effectors that have it of a per-effector figure of the
    /// driver's IK metrics (`None` when none has it).
    fn effector_mean(&self, figure: impl Fn(&IkMetrics, usize) -> Option<f64>) -> Option<f64> {
        let m = self.stage.driver.ik_metrics()?;
        let (sum, count) = (0..m.effector_count())
            .filter_map(|e| figure(m, e))
            .fold((0.0, 0_u32), |(sum, count), v| (sum + v, count + 1));
        (count > 0).then(|| sum / f64::from(count))
    }

    /// Oscillation of the limbs' joints since the reset, Hz, averaged over the
    /// effectors ([`IkMetrics::oscillation_hz`]).
    #[must_use]
    pub fn oscillation_hz(&self) -> Option<f64> {
        self.effector_mean(IkMetrics::oscillation_hz)
    }

    /// Fraction of frames with the target within reach since the reset,
    /// averaged over the effectors ([`IkMetrics::reachable`]).
    #[must_use]
    pub fn reachable(&self) -> Option<f64> {
        self.effector_mean(IkMetrics::reachable)
    }

    /// Mean error over the frames each target was reachable, metres, averaged
    /// over the effectors that had such frames.
    #[must_use]
    pub fn mean_error_reachable_m(&self) -> Option<f64> {
        self.effector_mean(IkMetrics::mean_error_reachable_m)
    }

    /// Mean error over the frames each target was out of reach, metres,
    /// averaged over the effectors that had such frames.
    #[must_use]
    pub fn mean_error_unreachable_m(&self) -> Option<f64> {
        self.effector_mean(IkMetrics::mean_error_unreachable_m)
    }

    /// Each effector's reach and oscillation figures: name, how far its target
    /// is out of reach this frame (metres, negative inside), and its figures
    /// since the reset.
    #[must_use]
    pub fn effectors(&self) -> Vec<EffectorFigures> {
        let driver = &self.stage.driver;
        let (Some(metrics), Some(report)) = (driver.ik_metrics(), driver.ik_report()) else {
            return Vec::new();
        };
        let skeleton = driver.skeleton();
        (0..skeleton.effector_count())
            .map(|e| EffectorFigures {
                metrics: EffectorMetrics::of(skeleton, metrics, e),
                out_of_reach_m: report.out_of_reach_m.get(e).copied(),
                error_m: report.effector_error_m.get(e).copied(),
                target_m: driver
                    .targets()
                    .and_then(|t| t.position.get(e))
                    .map(|p| p.to_array()),
            })
            .collect()
    }
}

/// One effector's figures in a comparison view
/// (`state().compare.metrics[i].effectors`): the run's figures since the
/// reset, as `gaitlab run --json` prints them (docs/ik-metrics.md), and how
/// far its target is out of reach this frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EffectorFigures {
    /// Name, errors, reach, oscillation and jitter since the reset.
    #[serde(flatten)]
    pub metrics: EffectorMetrics,
    /// How far the target lies beyond the limb's reach this frame, metres
    /// (negative: inside by that much).
    pub out_of_reach_m: Option<f64>,
    /// This frame's distance from the target, metres.
    pub error_m: Option<f64>,
    /// Where the target is this frame, world metres (a dragged target is the
    /// same in every view).
    pub target_m: Option<[f64; 3]>,
}
