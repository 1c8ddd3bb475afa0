//! What a tune minimises: named terms of a run's figures, each with a
//! weight (`--objective fall=10,speed=1,table2=0.5`).
//!
//! - `fall`: 1 when the creature fell or the simulation blew up, else 0.
//! - `speed`: |mean speed − desired| / desired (the paper's 10 % claim).
//! - `table2`: the mean |difference| from Raibert & Hodgins 1991's Table 2
//!   (animation column) over the gait's measured rows, as a fraction; a row
//!   the run has no figure for counts 1. Inputs (desired speeds) and the
//!   undefined "error in running speed" rows are left out.
//! - `table2_out`: the share of those rows more than
//!   [`BAND_PCT`] % off (a row with no figure counts as off): what
//!   `table2`'s mean can hide, one row far out while the rest sit close.
//! - `energy`: the cost of transport (positive actuator work over weight ×
//!   distance, [`GaitSummary::cost_of_transport`]), capped at 10.
//! - `jump`: the share of runs with a box in the path ([`JUMP_BOXES`]) that
//!   fell: the kangaroo's jump ("Results": "to make the kangaroo jump over
//!   an obstacle, a number of additional states were added"). Costed by
//!   [`crate::Problem`], which runs them; [`Objective::cost`] leaves it out.
//! - `steps`: the share of runs with a step of the desired speed halfway
//!   ([`SPEED_STEPS`]) that fell: a slider moved while the creature runs.
//!   A gait whose strides are a narrow limit cycle (the pitching bound)
//!   can hold every steady speed and still fall at the first change. Costed
//!   by [`crate::Problem`], like `jump`.
//! - `switch`: the share of runs begun in another gait
//!   ([`crate::Problem::set_switch_from`], `--switch-from`) and switched to
//!   the tuned one halfway that fell, one per speed the candidate runs at:
//!   the app's gait menu used while the creature runs. Costed by
//!   [`crate::Problem`], like `jump`.
//! - `pairs`: how far each virtual leg's two touchdowns are from the gait's
//!   timing ([`timing_cost`]): in unison for the trot and the bound, half a
//!   stance apart for the gallops ([`GALLOP_GAP_SHARE`]); 1 for a run with
//!   no pair to judge. 0 for a one-legged gait.
//! - `friction`: how far the friction the run needed exceeds what the paper
//!   says its motions needed ([`paper_friction_bounds`]): the excess of the
//!   middle of the supports over its bound plus that of their first and
//!   last 10 ms ([`friction_excess`]).

use gaitlab_core::portable::Portable;
use gaitlab_physics::engine::metrics::{GaitSummary, paper_friction_bounds};
use gaitlab_physics::engine::pair_timing::{GALLOP_GAP_SHARE, pair_timing, timing_cost};
use gaitlab_physics::engine::table2::{BAND_PCT, compare};

/// The names [`Objective::parse`] knows.
pub const TERMS: [&str; 10] = [
    "fall",
    "speed",
    "table2",
    "table2_out",
    "energy",
    "jump",
    "steps",
    "switch",
    "pairs",
    "friction",
];

/// The boxes of the `jump` term, one run each: the near face's distance
/// from the start, height and depth (m at scale 1). Met at different speeds
/// on the way up to the desired one. 0.2 m × 0.3 m, the box of
/// `tools/kangaroo_box_sweep.py` and the docs' traces (the app's "Place a
/// box" is the kangaroo's own `obstacle_height_m`, 0.25 m).
pub const JUMP_BOXES: [(f64, f64, f64); 3] = [(4.0, 0.2, 0.3), (10.0, 0.2, 0.3), (16.0, 0.2, 0.3)];

/// The runs of the `steps` term, one each: the desired speed is multiplied
/// by this halfway through a run at the tuned speed (a step outside the
/// speed's range counts as a fall).
pub const SPEED_STEPS: [f64; 2] = [1.1, 0.9];

/// Weighted terms; a weight of 0 leaves a term out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Objective {
    /// Weight of `fall`.
    pub fall: f64,
    /// Weight of `speed`.
    pub speed: f64,
    /// Weight of `table2`.
    pub table2: f64,
    /// Weight of `table2_out`.
    pub table2_out: f64,
    /// Weight of `energy`.
    pub energy: f64,
    /// Weight of `jump`.
    pub jump: f64,
    /// Weight of `steps`.
    pub steps: f64,
    /// Weight of `switch`.
    pub switch: f64,
    /// Weight of `pairs`.
    pub pairs: f64,
    /// Weight of `friction`.
    pub friction: f64,
}

impl Default for Objective {
    /// `fall=10,speed=1`: stay up, then hold the speed.
    fn default() -> Self {
        Self {
            fall: 10.0,
            speed: 1.0,
            table2: 0.0,
            table2_out: 0.0,
            energy: 0.0,
            jump: 0.0,
            steps: 0.0,
            switch: 0.0,
            pairs: 0.0,
            friction: 0.0,
        }
    }
}

impl Objective {
    /// Parse `name=weight,…`; terms not named get weight 0.
    ///
    /// # Errors
    /// `objective: …` naming the unknown term or the bad weight.
    pub fn parse(text: &str) -> Result<Self, String> {
        let mut o = Self {
            fall: 0.0,
            speed: 0.0,
            table2: 0.0,
            table2_out: 0.0,
            energy: 0.0,
            jump: 0.0,
            steps: 0.0,
            switch: 0.0,
            pairs: 0.0,
            friction: 0.0,
        };
        for part in text.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            let (name, weight) = part
                .split_once('=')
                .ok_or_else(|| format!("objective: \"{part}\" is not name=weight"))?;
            let w: f64 = weight
                .trim()
                .parse()
                .ok()
                .filter(|w: &f64| w.is_finite() && *w >= 0.0)
                .ok_or_else(|| {
                    format!("objective.{name}: the weight \"{weight}\" is not a number ≥ 0")
                })?;
            match name.trim() {
                "fall" => o.fall = w,
                "speed" => o.speed = w,
                "table2" => o.table2 = w,
                "table2_out" => o.table2_out = w,
                "energy" => o.energy = w,
                "jump" => o.jump = w,
                "steps" => o.steps = w,
                "switch" => o.switch = w,
                "pairs" => o.pairs = w,
                "friction" => o.friction = w,
                other => {
                    return Err(format!(
                        "objective: unknown term \"{other}\" (terms: {})",
                        TERMS.join(", ")
                    ));
                }
            }
        }
        let total = o.fall
            + o.speed
            + o.table2
            + o.table2_out
            + o.energy
            + o.jump
            + o.steps
            + o.switch
            + o.pairs
            + o.friction;
        if total <= 0.0 {
            return Err("objective: every weight is 0".to_owned());
        }
        Ok(o)
    }

    /// The cost of a run of `gait` with figures `s` (legs named `legs`,
    /// its virtual legs `pairs`); `fell` also counts a blow-up. Every term
    /// but `jump`, `steps` and `switch`.
    #[must_use]
    pub fn cost(
        &self,
        s: &GaitSummary,
        fell: bool,
        gait: &str,
        legs: &[&str],
        pairs: &[[usize; 2]],
    ) -> f64 {
        let mut cost = 0.0;
        if fell {
            cost += self.fall;
        }
        if self.speed > 0.0 {
            let desired = s.speed_desired_mps.abs().max(1e-6);
            cost +=
                self.speed * ((s.speed_mean_mps - s.speed_desired_mps).abs() / desired).min(1.0);
        }
        if self.table2 > 0.0 || self.table2_out > 0.0 {
            let rows: Vec<Option<f64>> = compare(s, gait, legs)
                .iter()
                .filter(|c| !c.row.quantity.is_input() && !c.row.quantity.is_speed_error())
                .map(|c| c.diff_pct().map(f64::abs))
                .collect();
            if !rows.is_empty() {
                let n = rows.len() as f64;
                let mean = rows
                    .iter()
                    .map(|d| d.map_or(1.0, |d| (d / 100.0).min(1.0)))
                    .sum::<f64>()
                    / n;
                let out = rows
                    .iter()
                    .filter(|d| d.is_none_or(|d| d > BAND_PCT))
                    .count() as f64
                    / n;
                cost += self.table2 * mean + self.table2_out * out;
            }
        }
        if self.energy > 0.0 {
            cost += self.energy * s.cost_of_transport.min(10.0);
        }
        if self.pairs > 0.0 && !pairs.is_empty() {
            let target = if gait.contains("gallop") {
                GALLOP_GAP_SHARE
            } else {
                0.0
            };
            let timings = pair_timing(&s.stances, pairs);
            cost += self.pairs * timing_cost(&timings, &s.leg_stance_s, target).unwrap_or(1.0);
        }
        if self.friction > 0.0 {
            cost += self.friction * friction_excess(s, legs.len());
        }
        cost
    }
}

/// The `friction` term of a run of a creature with `legs` legs: each of
/// the middle's and the edges' excess over [`paper_friction_bounds`] as the
/// logarithm of its ratio to the bound (0 within it; capped at 3, 20 times
/// the bound), summed: far over the bound still has a slope to descend. A
/// run that never measured a support (all zero) costs 0 here: `fall`
/// judges it.
#[must_use]
pub fn friction_excess(s: &GaitSummary, legs: usize) -> f64 {
    let (mid, edges) = paper_friction_bounds(legs);
    let over = |value: f64, bound: f64| {
        if value > bound {
            (value / bound).pln().min(3.0)
        } else {
            0.0
        }
    };
    over(s.friction_needed_mid, mid) + over(s.friction_needed_edges, edges)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terms_parse_by_name_and_bad_ones_are_named() {
        let o = Objective::parse("fall=5, table2=0.5").expect("parses");
        assert_eq!((o.fall, o.speed, o.table2), (5.0, 0.0, 0.5));
        assert!(Objective::parse("power=1").is_err_and(|e| e.contains("unknown term \"power\"")));
        assert_eq!(Objective::parse("energy=2").map(|o| o.energy), Ok(2.0));
        assert!(Objective::parse("speed=-1").is_err_and(|e| e.starts_with("objective.speed")));
        assert!(Objective::parse("speed").is_err());
        assert!(Objective::parse("speed=0").is_err());
        assert_eq!(Objective::parse("jump=3").map(|o| o.jump), Ok(3.0));
        assert_eq!(Objective::parse("steps=2").map(|o| o.steps), Ok(2.0));
        assert_eq!(Objective::parse("switch=3").map(|o| o.switch), Ok(3.0));
        assert_eq!(Objective::parse("pairs=2").map(|o| o.pairs), Ok(2.0));
        assert_eq!(
            Objective::parse("table2_out=4").map(|o| o.table2_out),
            Ok(4.0)
        );
    }

    #[test]
    fn the_cost_adds_weighted_terms() {
        let s = GaitSummary {
            speed_desired_mps: 2.0,
            speed_mean_mps: 1.8,
            ..GaitSummary::default()
        };
        let o = Objective::default();
        assert!((o.cost(&s, false, "run", &[], &[]) - 0.1).abs() < 1e-12);
        assert!((o.cost(&s, true, "run", &[], &[]) - 10.1).abs() < 1e-12);
        // No figures at all: every Table-2 row counts 1.
        let t = Objective::parse("table2=1").expect("parses");
        assert!((t.cost(&s, false, "run", &[], &[]) - 1.0).abs() < 1e-12);
        let e = Objective::parse("energy=2").expect("parses");
        let moving = GaitSummary {
            cost_of_transport: 0.4,
            ..s.clone()
        };
        assert!((e.cost(&moving, false, "run", &[], &[]) - 0.8).abs() < 1e-12);
        // `pairs`: no stance to judge costs 1; a one-legged gait 0.
        let p = Objective::parse("pairs=3").expect("parses");
        assert!((p.cost(&s, false, "bound", &[], &[[0, 1]]) - 3.0).abs() < 1e-12);
        assert_eq!(p.cost(&s, false, "run", &[], &[]), 0.0);
    }

    #[test]
    fn table2_out_counts_the_rows_outside_the_band() {
        // The trot's six measured rows: pitch on the paper, stride length
        // +10 %, stride duration +50 %, flight -40 %, stance on the paper,
        // leg-length change missing. Three of six are out.
        let s = GaitSummary {
            speed_desired_mps: 2.3,
            speed_mean_mps: 2.3,
            pitch_magnitude_deg: 6.2,
            stride_length_m: 1.49 * 1.1,
            stride_duration_s: 0.54 * 1.5,
            flight_duration_s: 0.18 * 0.6,
            stance_duration_s: 0.09,
            ..GaitSummary::default()
        };
        let out = Objective::parse("table2_out=2").expect("parses");
        let c = out.cost(&s, false, "trot", &[], &[]);
        assert!((c - 2.0 * 0.5).abs() < 1e-12, "{c}");
        // The mean of the same rows: (0 + 0.1 + 0.5 + 0.4 + 0 + 1) / 6.
        let mean = Objective::parse("table2=1").expect("parses");
        let c = mean.cost(&s, false, "trot", &[], &[]);
        assert!((c - 2.0 / 6.0).abs() < 1e-12, "{c}");
        // Every row in: nothing to pay.
        let inside = GaitSummary {
            stride_duration_s: 0.54 * 1.34,
            flight_duration_s: 0.18 * 0.66,
            leg_length_change_m: 0.03,
            ..s
        };
        assert_eq!(out.cost(&inside, false, "trot", &[], &[]), 0.0);
    }

    /// ln 1.5 and ln 1.25, to 17 digits.
    const LN_1_5: f64 = 0.405_465_108_108_164_4;
    const LN_1_25: f64 = 0.223_143_551_314_209_76;

    #[test]
    fn friction_costs_only_what_exceeds_the_papers_figures() {
        let f = Objective::parse("friction=2").expect("parses");
        let run = |mid, edges| GaitSummary {
            friction_needed_mid: mid,
            friction_needed_edges: edges,
            ..GaitSummary::default()
        };
        let quadruped = ["fl", "fr", "rl", "rr"];
        // Within the quadruped's 0.6 and 2.0: nothing.
        assert_eq!(f.cost(&run(0.55, 1.9), false, "trot", &quadruped, &[]), 0.0);
        // The middle 1.5 times its bound (0.9 of 0.6), the edges 1.25 times (2.5 of 2.0).
        let c = f.cost(&run(0.9, 2.5), false, "trot", &quadruped, &[]);
        assert!((c - 2.0 * (LN_1_5 + LN_1_25)).abs() < 1e-12, "{c}");
        // Each part is capped at 3 (20 times the bound and more).
        assert!((friction_excess(&run(0.6 * 30.0, 2.0 * 40.0), 4) - 6.0).abs() < 1e-12);
        // The biped's bound is 1 everywhere: 1.5 at the edges costs ln 1.5.
        assert!((friction_excess(&run(0.5, 1.5), 2) - LN_1_5).abs() < 1e-12);
    }
}
