//! A running comparison: its views (each a [`Stage`] over its own thesis
//! driver), their configuration, stepped in lock step, and the figures the
//! panel and `state().compare` read.

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::IkOptions;
use gaitlab_engine::{AnyDriver, EngineCommand, StretchOptions};
use serde_json::{Value, json};

use crate::history::History;
use crate::plot_scale::round_step;
use crate::render::Scene;
use crate::stage::Stage;
use crate::view::ViewOptions;

use super::claim::Checked;
use super::colours::{colour_srgb, colour32, colours_for};
use super::config::{CompareConfig, CompareScenario};
use super::metrics::ViewMetrics;
use super::notice::{NoticeLine, notice};
use super::view::CompareView;

/// A running comparison.
pub struct Comparison {
    /// What runs.
    pub config: CompareConfig,
    pub(super) views: Vec<CompareView>,
    /// Each view's colour: its method's ([`colours_for`]), sRGB bytes.
    colours: Vec<[u8; 3]>,
    /// Every view's figure in its colour, in one scene (filled while
    /// `config.overlay` is on).
    overlay: Scene,
}

impl Comparison {
    /// Every view's driver, in view order.
    pub fn drivers(&self) -> impl ExactSizeIterator<Item = &AnyDriver> {
        self.views.iter().map(|v| &v.stage.driver)
    }

    /// Runs `f` on every view's driver, in view order.
    pub fn for_each_driver(&mut self, mut f: impl FnMut(&mut AnyDriver)) {
        for view in &mut self.views {
            f(&mut view.stage.driver);
        }
    }

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
        let colours = colours_for(&config.views);
        let mut comparison = Self {
            config,
            colours,
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
                    .zip(&self.colours)
                    .map(|(v, &c)| (&v.stage.scene, colour_srgb(c))),
            );
        }
    }

    /// View `i`'s colour for egui: its method's, in every card, bar, plot
    /// and overlay.
    #[must_use]
    pub fn colour(&self, i: usize) -> egui::Color32 {
        colour32(self.colours.get(i).copied().unwrap_or([0x99; 3]))
    }

    /// View `i`'s colour for the scene (sRGB, 0–1, opaque).
    #[must_use]
    pub fn colour_srgb(&self, i: usize) -> [f32; 4] {
        colour_srgb(self.colours.get(i).copied().unwrap_or([0x99; 3]))
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
            view.record_frame();
        }
    }

    /// One IK iteration in every view, in lock step (see
    /// [`gaitlab_engine::AnyDriver::step_iteration`]); a view whose frame the
    /// iteration closes records it as [`Comparison::step`] does. The first
    /// view's step, `None` when the views cannot step by iteration.
    pub fn step_iteration(&mut self, dt: f64) -> Option<gaitlab_engine::IterationStep> {
        let mut first = None;
        for view in &mut self.views {
            let step = view.stage.step_iteration(dt)?;
            if step.done >= step.of {
                view.record_frame();
            }
            first.get_or_insert(step);
        }
        first
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

    /// The scenario's "what to notice" lines, each claim checked against
    /// this run's figures.
    #[must_use]
    pub fn notes(&self) -> Vec<(NoticeLine, Option<Checked>)> {
        notice(self.config.scenario, self.recorded())
            .iter()
            .map(|line| (*line, line.claim.map(|c| c.check(&self.views))))
            .collect()
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
            let notes = self.notes();
            let lines: Vec<String> = notes
                .iter()
                .map(|(l, checked)| match (l.claim, checked) {
                    (Some(claim), Some(checked)) => {
                        format!("{} ({}) {}", l.text, l.source, checked.sentence(&claim))
                    }
                    _ => format!("{} ({})", l.text, l.source),
                })
                .collect();
            object.insert("notice".to_owned(), json!(lines));
            let claims: Vec<Value> = notes
                .iter()
                .enumerate()
                .filter_map(|(i, (l, checked))| {
                    let (claim, checked) = (l.claim?, checked.as_ref()?);
                    Some(json!({
                        "line": i,
                        "figure": claim.figure.key(),
                        "method": claim.method.name(),
                        "rank": claim.rank.name(),
                        "among": claim.among.iter().map(|m| m.name()).collect::<Vec<_>>(),
                        "verdict": checked.verdict.name(),
                    }))
                })
                .collect();
            object.insert("claims".to_owned(), Value::Array(claims));
        }
        value
    }
}
