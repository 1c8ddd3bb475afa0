//! What a tune searches: a physics preset's gait, run for a few simulated
//! seconds with its controller's tunable gains set to a candidate's values,
//! and the cost of the run (Raibert & Hodgins 1991 §5's "we adjusted the
//! spring and damping constants … until", as a search). A candidate is a
//! point `x` in log space: gain `i` = start value · e^{x_i}, so one step size
//! moves every gain by the same fraction whatever its unit.

use gaitlab_core::driver::Driver as _;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::physics::PhysicsParams;
use gaitlab_core::{Creature, PresetError};
use gaitlab_physics::PhysicsDriver;

use crate::objective::Objective;

/// The frame step of a candidate's run (s): the page's 60 Hz.
const FRAME_S: f64 = 1.0 / 60.0;

/// A gait to tune: the preset, the gait, the gains, the run and the cost.
#[derive(Clone, Debug)]
pub struct Problem {
    preset: Creature,
    params: PhysicsParams,
    gait: String,
    names: Vec<&'static str>,
    start: Vec<f64>,
    /// Simulated seconds of each candidate's run.
    pub seconds: f64,
    /// What the run's figures cost.
    pub objective: Objective,
}

/// One candidate's run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Evaluation {
    /// The objective's cost (lower is better).
    pub cost: f64,
    /// Whether it fell or blew up.
    pub fell: bool,
    /// Its mean speed after settling (m/s).
    pub speed_mean_mps: f64,
}

impl Problem {
    /// The gait `gait` of the physics preset `preset`, its tunable gains
    /// starting from the values the preset gives them.
    ///
    /// # Errors
    /// `scenario.physics…` when the preset is not a physics creature or the
    /// gait is unknown; `seconds` when not in (0, 600].
    pub fn new(
        preset: &Creature,
        gait: &str,
        seconds: f64,
        objective: Objective,
    ) -> Result<Self, PresetError> {
        if !(seconds.is_finite() && seconds > 0.0 && seconds <= 600.0) {
            return Err(PresetError::new("seconds", "must be in (0, 600]"));
        }
        let mut params =
            preset.scenario.physics.clone().ok_or_else(|| {
                PresetError::new("scenario.engine", "the tuner tunes physics gaits")
            })?;
        params.gait = Some(gait.to_owned());
        let driver = PhysicsDriver::with_params(preset, params.clone())?;
        let gains = driver.gains();
        Ok(Self {
            preset: preset.clone(),
            params,
            gait: gait.to_owned(),
            names: gains.iter().map(|g| g.name).collect(),
            start: gains.iter().map(|g| g.value).collect(),
            seconds,
            objective,
        })
    }

    /// The gains tuned, by name.
    #[must_use]
    pub fn names(&self) -> &[&'static str] {
        &self.names
    }

    /// Their starting values (scale 1, the paper's units).
    #[must_use]
    pub fn start(&self) -> &[f64] {
        &self.start
    }

    /// The gait tuned.
    #[must_use]
    pub fn gait(&self) -> &str {
        &self.gait
    }

    /// The gains' values at the point `x` of the search.
    #[must_use]
    pub fn values(&self, x: &[f64]) -> Vec<f64> {
        self.start
            .iter()
            .zip(x)
            .map(|(s, xi)| s.max(1e-9) * xi.clamp(-20.0, 20.0).pexp())
            .collect()
    }

    /// The physics section with the gains at `values`.
    #[must_use]
    pub fn params_with(&self, values: &[f64]) -> PhysicsParams {
        let mut params = self.params.clone();
        let own = params
            .controller_by_gait
            .entry(self.gait.clone())
            .or_default();
        for (name, v) in self.names.iter().zip(values) {
            own.insert((*name).to_owned(), *v);
        }
        params
    }

    /// Run the candidate at `x` and cost it. A candidate the controller
    /// refuses costs as a fall.
    #[must_use]
    pub fn evaluate(&self, x: &[f64]) -> Evaluation {
        let params = self.params_with(&self.values(x));
        let Ok(mut driver) = PhysicsDriver::with_params(&self.preset, params) else {
            return Evaluation {
                cost: self.objective.fall + self.objective.speed + self.objective.table2,
                fell: true,
                speed_mean_mps: 0.0,
            };
        };
        driver.reset_after_fall = false;
        let frames = (self.seconds / FRAME_S).round() as usize;
        let mut fell = false;
        for frame in 0..frames {
            driver.step(FRAME_S);
            if driver.resets() > 0 || (frame % 60 == 59 && driver.fell()) {
                fell = true;
                break;
            }
        }
        let s = driver.summary();
        let fell = fell || s.fell || driver.resets() > 0;
        let legs: Vec<&str> = driver
            .sim()
            .creature
            .legs
            .iter()
            .map(|l| l.name.as_str())
            .collect();
        Evaluation {
            cost: self.objective.cost(&s, fell, &self.gait, &legs),
            fell,
            speed_mean_mps: s.speed_mean_mps,
        }
    }
}
