//! Side-by-side comparison of IK methods (She 2006 §4.4: transpose, pinv,
//! DLS, SDLS; PODA eq. 6's null-space centering; CCD as a non-Jacobian
//! contrast): 2 or 4 views, each its own thesis driver with its own solver
//! configuration, on the same creature, mode and parameters, advanced in lock
//! step (same `dt`, same frame), so every view sees the same targets. Per view:
//! tracking error (She 2006 §5.3's `d`), wall time per IK iteration, joint
//! velocity jitter and limit hits; per effector, how far its target is out of
//! its limb's reach, the errors over reachable and unreachable frames and the
//! limb's oscillation (docs/ik-metrics.md). The "singularity" scenario pulls every limb
//! target to about its full reach ([`gaitlab_engine::StretchOptions`]). Each view is a
//! [`Stage`] over its own driver, as the lab's single view is.
//!
//! # The `compare` command and state (DESIGN.md "Browser")
//! `{"compare": {"views": [NAME, …], "scenario": "script" | "singularity",
//! "overlay": BOOL, "options": [{"lambda", "gamma_max", "max_step", "rank_tolerance",
//! "null_space_gain"}, …]}}` starts (or reconfigures) a comparison; `views`
//! holds 2 or 4 of [`CompareMethod::ALL`]'s names, `scenario` and `options`
//! (one object per view, each key optional) may be left out. `{"compare":
//! false}` leaves it. `state().compare` is that same object plus a
//! `metrics` array, the plots' shared `plot_error_max_mm` and the scenario's
//! "what to notice" lines, `notice` (all ignored by the command), so passing it back verbatim
//! restores the configuration; it is `null` when no comparison runs.

use gaitlab_core::driver::{Driver, IkMetrics};
use gaitlab_core::ik::IkOptions;
use gaitlab_engine::metrics::EffectorMetrics;
use gaitlab_engine::{AnyDriver, EngineCommand, StretchOptions};
use serde::Serialize;
use serde_json::{Value, json};

use crate::history::History;
use crate::lab::Stage;
use crate::plot_scale::round_step;
use crate::render::Scene;
use crate::view::ViewOptions;

mod colours;
mod config;
mod method;
mod metrics;
mod notice;

pub use colours::{VIEW_COLOURS, view_colour, view_colour_srgb};
pub use config::{CompareConfig, CompareScenario, DEFAULT_VIEWS};
pub use method::{CompareMethod, DEFAULT_NULL_SPACE_GAIN, Parameter};
pub use metrics::{JITTER_WINDOW_FRAMES, ViewMetrics};
pub use notice::{NoticeLine, notice};

/// One view: its configuration, its stage (driver, scene, and as history the
/// largest effector error per frame, one series in metres) and its figures.
pub struct CompareView {
    /// The configuration.
    pub method: CompareMethod,
    pub(crate) stage: Stage<AnyDriver>,
    pub(crate) metrics: ViewMetrics,
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
}

/// A running comparison.
pub struct Comparison {
    /// What runs.
    pub config: CompareConfig,
    pub(crate) views: Vec<CompareView>,
    /// Every view's figure in its colour, in one scene (filled while
    /// `config.overlay` is on).
    overlay: Scene,
}

impl Comparison {
    /// Builds one driver per view from `template` (the lab's IK driver: the
    /// thesis driver with its skeleton, parameters, mode and origin, or a
    /// recording's), reset to time 0. The singularity scenario stretches
    /// the thesis targets; a recording's stay as recorded.
    #[must_use]
    pub fn new(config: CompareConfig, template: &AnyDriver, view: &ViewOptions) -> Self {
        let views = config
            .views
            .iter()
            .zip(&config.options)
            .map(|(&method, options)| {
                let mut driver = template.clone();
                driver.set_ik_options(options.clone());
                // Only the thesis' script has targets to stretch.
                drop(driver.apply(EngineCommand::Stretch(
                    (config.scenario == CompareScenario::Singularity).then(StretchOptions::default),
                )));
                driver.reset();
                let mut view_state = CompareView {
                    method,
                    metrics: ViewMetrics::new(driver.skeleton().joint_count()),
                    stage: Stage::new(
                        driver,
                        History::new(vec![format!("{} max error (mm)", method.name())]),
                    ),
                };
                view_state.stage.refresh_scene(view);
                view_state
            })
            .collect();
        let mut comparison = Self {
            config,
            views,
            overlay: Scene::default(),
        };
        comparison.refresh_overlay();
        comparison
    }

    /// Whether the views follow a recording (not the thesis script).
    #[must_use]
    pub fn recorded(&self) -> bool {
        self.views
            .first()
            .is_some_and(|v| v.driver().is_recording())
    }

    /// The overlay's scene: every view's figure in its colour (empty while
    /// the overlay is off).
    #[must_use]
    pub fn overlay(&self) -> &Scene {
        &self.overlay
    }

    /// Draws the views overlaid (`true`) or one pane each, keeping the run.
    pub fn set_overlay(&mut self, on: bool) {
        self.config.overlay = on;
        self.refresh_overlay();
    }

    /// Refills the overlay from the views' scenes when it is on.
    fn refresh_overlay(&mut self) {
        if self.config.overlay {
            self.overlay.fill_overlay(
                self.views
                    .iter()
                    .enumerate()
                    .map(|(i, v)| (&v.stage.scene, view_colour_srgb(i))),
            );
        }
    }

    /// The views.
    #[must_use]
    pub fn views(&self) -> &[CompareView] {
        &self.views
    }

    /// Sets view `index`'s options live (the configuration keeps them).
    pub fn set_options(&mut self, index: usize, options: IkOptions) {
        if let (Some(view), Some(slot)) = (
            self.views.get_mut(index),
            self.config.options.get_mut(index),
        ) {
            view.stage.driver.set_ik_options(options.clone());
            *slot = options;
        }
    }

    /// Advances every view one frame of `dt` seconds, timing each with `clock`
    /// (milliseconds) when there is one.
    pub fn step(&mut self, dt: f64, clock: Option<&dyn Fn() -> f64>) {
        for view in &mut self.views {
            let started = clock.map(|c| c());
            view.stage.step(dt);
            if let (Some(started), Some(clock)) = (started, clock) {
                view.metrics.wall_us += (clock() - started) * 1e3;
            }
            let stage = &mut view.stage;
            view.metrics.iterations += stage.driver.ik_report().map_or(0, |r| r.iterations as u64);
            let skeleton = stage.driver.skeleton();
            view.metrics.record(skeleton, &stage.driver.pose().joints);
            let error = stage.driver.ik_report().map_or(0.0, |r| r.max_error_m);
            stage
                .history
                .push(stage.driver.time(), std::iter::once(error));
        }
    }

    /// Back to time 0 with cleared figures.
    pub fn reset(&mut self) {
        for view in &mut self.views {
            view.stage.reset();
            view.metrics = ViewMetrics::new(view.stage.driver.skeleton().joint_count());
        }
    }

    /// Sets the thesis motion of every view.
    pub fn set_mode(&mut self, mode: gaitlab_core::preset::thesis::ThesisMode) {
        for view in &mut self.views {
            // A recording's views have no thesis motion to change.
            drop(view.stage.driver.apply(EngineCommand::Mode(mode)));
        }
    }

    /// Rebuilds every view's scene from its pose.
    pub fn refresh_scenes(&mut self, view: &ViewOptions) {
        for v in &mut self.views {
            v.stage.refresh_scene(view);
        }
        self.refresh_overlay();
    }

    /// The top of the y range every card's error plot shares (mm): the
    /// largest error any view shows, rounded up to 1, 2 or 5 × 10ⁿ, at least
    /// 1 mm — so the cards compare by eye (issue 21 item 1).
    #[must_use]
    pub fn plot_error_max_mm(&self) -> f64 {
        let largest = self
            .views
            .iter()
            .filter_map(|v| v.stage.history.max_value(0))
            .fold(0.0, f64::max)
            * 1e3;
        round_step(largest.max(1.0))
    }

    /// The state's `compare` object: the configuration plus per-view metrics.
    #[must_use]
    pub fn state(&self) -> Value {
        let mut value = self.config.to_json();
        let metrics: Vec<Value> = self
            .views
            .iter()
            .map(|v| {
                json!({
                    "method": v.method.name(),
                    "mean_error_m": v.mean_error_m(),
                    "max_error_m": v.max_error_m(),
                    "us_per_iteration": v.metrics.us_per_iteration(),
                    "jitter_rad": v.metrics.jitter_rad(),
                    "limit_hits": v.metrics.limit_hits,
                    "frame": v.metrics.frames,
                    "time_s": v.stage.driver.time(),
                    "oscillation_hz": v.oscillation_hz(),
                    "reachable": v.reachable(),
                    "mean_error_reachable_m": v.mean_error_reachable_m(),
                    "mean_error_unreachable_m": v.mean_error_unreachable_m(),
                    "effectors": v.effectors(),
                })
            })
            .collect();
        if let Some(object) = value.as_object_mut() {
            object.insert("metrics".to_owned(), Value::Array(metrics));
            object.insert(
                "plot_error_max_mm".to_owned(),
                json!(self.plot_error_max_mm()),
            );
            let lines: Vec<String> = notice(self.config.scenario, self.recorded())
                .iter()
                .map(|l| format!("{} ({})", l.text, l.source))
                .collect();
            object.insert("notice".to_owned(), json!(lines));
        }
        value
    }
}
