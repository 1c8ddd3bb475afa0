//! What a tune searches: a physics preset's gait, run for a few simulated
//! seconds with its controller's tunable gains set to a candidate's values,
//! and the cost of the run (Raibert & Hodgins 1991 §5's "we adjusted the
//! spring and damping constants … until", as a search). A candidate is a
//! point `x` in log space: gain `i` = start value · e^{x_i}, so one step size
//! moves every gain by the same fraction whatever its unit. A candidate may
//! also run at further desired speeds ([`Problem::also_at_mps`]), so a tune
//! holds a gait over the speeds it is used at, not only the one tuned at.

use gaitlab_core::driver::Driver as _;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::physics::{ObstacleSpec, PhysicsParams};
use gaitlab_core::{Creature, PresetError};
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gaits::parameters::REPLACED_BY_HOP_HEIGHT;
use gaitlab_physics::creatures::Species;
use gaitlab_physics::engine::metrics::GaitSummary;

use crate::objective::{JUMP_BOXES, Objective, SPEED_STEPS};

/// Most parameters [`Problem::vary`] adds.
pub const MAX_VARY: usize = 16;

/// The frame step of a candidate's run (s): the page's 60 Hz.
const FRAME_S: f64 = 1.0 / 60.0;

/// A gait to tune: the preset, the gait, the gains, the run and the cost.
#[derive(Clone, Debug)]
pub struct Problem {
    preset: Creature,
    params: PhysicsParams,
    gait: String,
    names: Vec<String>,
    start: Vec<f64>,
    /// The creature's legs by name (Table 2's per-pair rows need them).
    legs: Vec<String>,
    /// The gait's virtual legs (the `pairs` term).
    pairs: &'static [[usize; 2]],
    /// Simulated seconds of each candidate's run.
    pub seconds: f64,
    /// What the run's figures cost.
    pub objective: Objective,
    /// Further desired speeds (m/s at scale 1) every candidate also runs at.
    /// The `fall`, `speed` and `energy` terms are then the mean over the
    /// preset's speed and these; `table2` stays the preset speed's (Table 2
    /// gives one speed per gait). Empty: one run, as before.
    pub also_at_mps: Vec<f64>,
    /// The gait the `switch` term's runs begin in
    /// ([`Problem::set_switch_from`]).
    switch_from: Option<String>,
    /// The gait the `switch` term's runs begun in the tuned gait change to
    /// ([`Problem::set_switch_to`]).
    switch_to: Option<String>,
}

/// What changes halfway through a run.
#[derive(Clone, Debug)]
enum Change {
    /// Nothing.
    None,
    /// The desired speed is multiplied by this (the `steps` term).
    Speed(f64),
    /// The run switches to this gait (the `switch` term).
    Gait(String),
}

/// One candidate's run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Evaluation {
    /// The objective's cost (lower is better).
    pub cost: f64,
    /// Whether its run at the tuned speed fell or blew up (the runs at
    /// [`Problem::also_at_mps`] and the jump term's count in `cost` only).
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
    /// gait is unknown; `seconds` when not in (0, 600]; `objective.jump`
    /// for a creature without jump states.
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
        if objective.jump > 0.0 && driver.sim().creature.species != Species::Kangaroo {
            return Err(PresetError::new(
                "objective.jump",
                "only the kangaroo has jump states (Raibert & Hodgins 1991, \"Results\")",
            ));
        }
        let gains = driver.gains();
        Ok(Self {
            preset: preset.clone(),
            params,
            gait: gait.to_owned(),
            names: gains.iter().map(|g| g.name.to_owned()).collect(),
            start: gains.iter().map(|g| g.value).collect(),
            legs: driver.leg_names().map(str::to_owned).collect(),
            pairs: driver.virtual_legs(),
            seconds,
            objective,
            also_at_mps: Vec::new(),
            switch_from: None,
            switch_to: None,
        })
    }

    /// The `switch` term's runs begin in `gait` and switch to the tuned
    /// gait halfway, as the app's gait menu does.
    ///
    /// # Errors
    /// `switch_from: …` when `gait` is the tuned gait or one the creature
    /// does not run; nothing changes then.
    pub fn set_switch_from(&mut self, gait: &str) -> Result<(), PresetError> {
        self.check_other_gait("switch_from", gait, "begin in")?;
        self.switch_from = Some(gait.to_owned());
        Ok(())
    }

    /// The `switch` term's runs also begin in the tuned gait and switch to
    /// `gait` halfway: the tuned gait handing over to another, as
    /// [`Problem::set_switch_from`] has it taking over.
    ///
    /// # Errors
    /// `switch_to: …` when `gait` is the tuned gait or one the creature
    /// does not run; nothing changes then.
    pub fn set_switch_to(&mut self, gait: &str) -> Result<(), PresetError> {
        self.check_other_gait("switch_to", gait, "change to")?;
        self.switch_to = Some(gait.to_owned());
        Ok(())
    }

    /// `Ok` when `gait` is not the tuned gait and the creature runs it.
    fn check_other_gait(&self, field: &str, gait: &str, verb: &str) -> Result<(), PresetError> {
        if gait == self.gait {
            return Err(PresetError::new(
                field,
                format!(
                    "the runs {verb} {gait}, the tuned gait: name another gait the creature runs"
                ),
            ));
        }
        let mut params = self.params.clone();
        params.gait = Some(gait.to_owned());
        PhysicsDriver::with_params(&self.preset, params)
            .map_err(|e| PresetError::new(field, e.to_string()))?;
        Ok(())
    }

    /// The gait the `switch` term's runs begin in, when one is set.
    #[must_use]
    pub fn switch_from(&self) -> Option<&str> {
        self.switch_from.as_deref()
    }

    /// The gait the `switch` term's runs change to from the tuned gait,
    /// when one is set.
    #[must_use]
    pub fn switch_to(&self) -> Option<&str> {
        self.switch_to.as_deref()
    }

    /// The `switch` term's runs: one per speed a candidate runs at for each
    /// of the switch from a gait and the switch to one that is set, when
    /// the term is weighted.
    fn switch_runs(&self) -> usize {
        let ways = usize::from(self.switch_from.is_some()) + usize::from(self.switch_to.is_some());
        if self.objective.switch > 0.0 {
            ways * (1 + self.also_at_mps.len())
        } else {
            0
        }
    }

    /// The gains tuned, by name.
    #[must_use]
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Tune these parameters of the gait's controller too (its `controller`
    /// keys beyond the gains: the paper's "we reduced the standing length of
    /// the legs" is `landing_rest_m`), each from the value the preset gives
    /// it. A name tuned already is passed over. On an error nothing is
    /// added.
    ///
    /// # Errors
    /// `vary[i]: …` for a name the controller does not have, one that
    /// starts at 0 (the search scales each value, so 0 stays 0) or one
    /// another field of the preset sets (the bound's `stride_flight_s`
    /// follows `hop_height_m`); `vary` for more than [`MAX_VARY`] names.
    pub fn vary(&mut self, names: &[String]) -> Result<(), PresetError> {
        if names.len() > MAX_VARY {
            return Err(PresetError::new(
                "vary",
                format!("at most {MAX_VARY} parameters"),
            ));
        }
        let driver = PhysicsDriver::with_params(&self.preset, self.params.clone())?;
        let mut added: Vec<(String, f64)> = Vec::new();
        for (i, name) in names.iter().enumerate() {
            let field = format!("vary[{i}]");
            let Some(start) = driver.parameter(name) else {
                return Err(PresetError::new(
                    &field,
                    format!(
                        "the {} controller has no parameter `{name}` (it has: {})",
                        self.gait,
                        driver.parameter_names().join(", ")
                    ),
                ));
            };
            if self.names.contains(name) || added.iter().any(|(n, _)| n == name) {
                continue;
            }
            if !(start.is_finite() && start != 0.0) {
                return Err(PresetError::new(
                    &field,
                    format!(
                        "`{name}` starts at {start}; the search scales each value, so give it a non-zero start in controller_by_gait.{}",
                        self.gait
                    ),
                ));
            }
            // A value written for the gait must reach its controller.
            let probe = 1.5 * start;
            let mut params = self.params.clone();
            params
                .controller_by_gait
                .entry(self.gait.clone())
                .or_default()
                .insert(name.clone(), probe);
            let reached = PhysicsDriver::with_params(&self.preset, params)
                .ok()
                .and_then(|d| d.parameter(name));
            let commanded = self.params.hop_height_m.is_some()
                && REPLACED_BY_HOP_HEIGHT.contains(&name.as_str());
            if reached != Some(probe) || commanded {
                return Err(PresetError::new(
                    &field,
                    format!(
                        "another field of the preset sets `{name}` (the hop height?), so tuning it would change nothing"
                    ),
                ));
            }
            added.push((name.clone(), start));
        }
        for (name, start) in added {
            self.names.push(name);
            self.start.push(start);
        }
        Ok(())
    }

    /// Their starting values (scale 1, the paper's units).
    #[must_use]
    pub fn start(&self) -> &[f64] {
        &self.start
    }

    /// Simulated runs per candidate: the tuned speed's, one per
    /// [`Problem::also_at_mps`], with the `jump` term one per box, with
    /// the `steps` term one per speed step and with the `switch` term one
    /// per speed.
    #[must_use]
    pub fn runs_per_candidate(&self) -> usize {
        let boxes = if self.objective.jump > 0.0 {
            JUMP_BOXES.len()
        } else {
            0
        };
        let steps = if self.objective.steps > 0.0 {
            SPEED_STEPS.len()
        } else {
            0
        };
        1 + self.also_at_mps.len() + boxes + steps + self.switch_runs()
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
            .map(|(s, xi)| nonzero(*s) * xi.clamp(-20.0, 20.0).pexp())
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
            own.insert(name.clone(), *v);
        }
        params
    }

    /// Run the candidate at `x` and cost it. A candidate the controller
    /// refuses costs as a fall.
    #[must_use]
    pub fn evaluate(&self, x: &[f64]) -> Evaluation {
        let params = self.params_with(&self.values(x));
        let Some((main, fell)) = self.run(params.clone()) else {
            return self.refused();
        };
        let gait = self.gait.as_str();
        let legs: Vec<&str> = self.legs.iter().map(String::as_str).collect();
        let o = &self.objective;
        let mut cost = if self.also_at_mps.is_empty() {
            o.cost(&main, fell, gait, &legs, self.pairs)
        } else {
            // Table 2 from the preset's speed; the other terms averaged over every speed.
            let table2 = Objective {
                fall: 0.0,
                speed: 0.0,
                energy: 0.0,
                pairs: 0.0,
                friction: 0.0,
                ..*o
            };
            let rest = Objective {
                table2: 0.0,
                table2_out: 0.0,
                ..*o
            };
            let mut sum = rest.cost(&main, fell, gait, &legs, self.pairs);
            for &speed in &self.also_at_mps {
                let mut at = params.clone();
                at.speed_mps = speed;
                let Some((s, fell)) = self.run(at) else {
                    return self.refused();
                };
                sum += rest.cost(&s, fell, gait, &legs, self.pairs);
            }
            sum / (1 + self.also_at_mps.len()) as f64
                + table2.cost(&main, fell, gait, &legs, self.pairs)
        };
        if o.jump > 0.0 {
            let boxes = JUMP_BOXES.map(|(at_m, height_m, depth_m)| {
                let mut with_box = params.clone();
                with_box.obstacles.push(ObstacleSpec {
                    at_m,
                    depth_m,
                    height_m,
                });
                (with_box, Change::None)
            });
            cost += o.jump * f64::from(self.fallen(boxes)) / JUMP_BOXES.len() as f64;
        }
        if o.steps > 0.0 {
            let steps = SPEED_STEPS.map(|f| (params.clone(), Change::Speed(f)));
            cost += o.steps * f64::from(self.fallen(steps)) / SPEED_STEPS.len() as f64;
        }
        let switches = self.switch_runs();
        if switches > 0 {
            let speeds = std::iter::once(params.speed_mps).chain(self.also_at_mps.iter().copied());
            let ways = [
                self.switch_from
                    .clone()
                    .map(|from| (from, self.gait.clone())),
                self.switch_to.clone().map(|to| (self.gait.clone(), to)),
            ];
            let runs = ways.into_iter().flatten().flat_map(|(begin, end)| {
                let params = &params;
                speeds.clone().map(move |speed| {
                    let mut begun = params.clone();
                    begun.speed_mps = speed;
                    begun.gait = Some(begin.clone());
                    (begun, Change::Gait(end.clone()))
                })
            });
            cost += o.switch * f64::from(self.fallen(runs)) / switches as f64;
        }
        Evaluation {
            cost,
            fell,
            speed_mean_mps: main.speed_mean_mps,
        }
    }

    /// What a candidate the controller refuses costs: a fall, a missed
    /// speed, every Table-2 row missed, every box and every speed step a
    /// fall, every switch a fall (when the `switch` term has runs).
    fn refused(&self) -> Evaluation {
        let o = &self.objective;
        let switch = if self.switch_runs() > 0 {
            o.switch
        } else {
            0.0
        };
        Evaluation {
            cost: o.fall + o.speed + o.table2 + o.table2_out + o.jump + o.steps + switch,
            fell: true,
            speed_mean_mps: 0.0,
        }
    }

    /// How many of the runs `runs` (each [`Problem::run_with`]'s
    /// arguments) fell or were refused.
    fn fallen(&self, runs: impl IntoIterator<Item = (PhysicsParams, Change)>) -> u32 {
        runs.into_iter()
            .map(|(params, change)| {
                u32::from(self.run_with(params, &change).is_none_or(|(_, fell)| fell))
            })
            .sum()
    }

    /// One run of `seconds` with `params`: its figures and whether it fell
    /// (or blew up); `None` when the controller refuses it.
    fn run(&self, params: PhysicsParams) -> Option<(GaitSummary, bool)> {
        self.run_with(params, &Change::None)
    }

    /// [`Problem::run`], with `change` made halfway through.
    fn run_with(&self, params: PhysicsParams, change: &Change) -> Option<(GaitSummary, bool)> {
        let speed_mps = params.speed_mps;
        let mut driver = PhysicsDriver::with_params(&self.preset, params).ok()?;
        driver.reset_after_fall = false;
        let frames = (self.seconds / FRAME_S).round() as usize;
        let mut fell = false;
        for frame in 0..frames {
            if frame == frames / 2 {
                match change {
                    Change::None => {}
                    Change::Speed(factor) => driver.set_speed(factor * speed_mps).ok()?,
                    Change::Gait(gait) => driver.set_gait(gait).ok()?,
                }
            }
            driver.step(FRAME_S);
            if driver.resets() > 0 || (frame % 60 == 59 && driver.fell()) {
                fell = true;
                break;
            }
        }
        let s = driver.summary();
        let fell = fell || s.fell || driver.resets() > 0;
        Some((s, fell))
    }
}

/// A start value the search can scale: itself, or 1e-9 for a gain that
/// starts at 0 (as before; a signed parameter keeps its sign).
fn nonzero(start: f64) -> f64 {
    if start < 0.0 { start } else { start.max(1e-9) }
}
