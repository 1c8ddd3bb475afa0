//! The virtual legs' timing (`engine::pair_timing`) against an independent
//! count of touchdowns from the contacts step by step: the bound's pairs
//! strike in unison, the biped gallop's legs tens of milliseconds apart.

use gaitlab_core::preset::{Creature as PresetCreature, load_bundled};
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::pair_timing::pair_timing;

/// The run's pair timing by the module, and each pair's mean touchdown
/// gap counted here from every step's contacts after `settle_s`.
fn both_ways(name: &str, gait: &str, speed: f64, seconds: f64) -> Vec<(f64, f64, [usize; 2])> {
    let preset: PresetCreature = load_bundled(name).expect("bundled").expect("valid");
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.gait = Some(gait.to_owned());
    params.speed_mps = speed;
    let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
    driver.reset_after_fall = false;
    let legs = driver.sim().creature.legs.len();
    let mut touching = vec![false; legs];
    let mut touchdowns: Vec<Vec<f64>> = vec![Vec::new(); legs];
    let settle_s = 3.0;
    while driver.sim().time < seconds {
        driver.step_observed(1.0 / 60.0, |d| {
            let sim = d.sim();
            for (i, c) in sim.contacts.iter().enumerate() {
                if c.touching && !touching[i] {
                    touchdowns[i].push(sim.time);
                }
                touching[i] = c.touching;
            }
        });
    }
    assert_eq!(driver.resets(), 0, "{name} {gait} ran without a put-back");
    let summary = driver.summary();
    pair_timing(&summary.stances, driver.virtual_legs())
        .into_iter()
        .map(|t| {
            let [a, b] = t.legs;
            // Each first-leg touchdown's nearest second-leg touchdown.
            // (First-leg touchdowns after settling; their partner may have
            // landed just before it.)
            let gaps: Vec<f64> = touchdowns[a]
                .iter()
                .filter(|&&ta| ta > settle_s)
                .filter_map(|&ta| {
                    touchdowns[b]
                        .iter()
                        .map(|&tb| (tb - ta).abs())
                        .min_by(f64::total_cmp)
                })
                .collect();
            let counted = gaps.iter().sum::<f64>() / gaps.len().max(1) as f64;
            assert!(
                t.shared > 10,
                "{name} {gait} {:?}: {} shared",
                t.legs,
                t.shared
            );
            (t.touchdown_gap_s, counted, t.legs)
        })
        .collect()
}

#[test]
fn the_bounds_pairs_strike_in_unison() {
    let got = both_ways("raibert-quadruped", "bound", 2.3, 10.0);
    assert_eq!(got.len(), 2);
    for (gap, counted, legs) in got {
        assert!(gap < 1e-3, "{legs:?}: {gap} s");
        assert!(
            (gap - counted).abs() < 2e-3,
            "{legs:?}: {gap} against {counted} s"
        );
    }
}

#[test]
fn the_biped_gallops_legs_land_tens_of_milliseconds_apart() {
    for gait in ["gallop", "gallop_alternate"] {
        let got = both_ways("raibert-biped", gait, 1.5, 10.0);
        assert_eq!(got.len(), 1);
        let (gap, counted, legs) = got[0];
        assert!(gap > 0.03 && gap < 0.07, "{gait} {legs:?}: {gap} s");
        assert!(
            (gap - counted).abs() < 2e-3,
            "{gait}: {gap} against {counted} s"
        );
    }
}
