//! PODA's fore-aft surge ("Horizontal Control": backward acceleration in the
//! restore, forward in the push; `scenario.poda.fore_aft_surge`) against a
//! hand computation, and planted feet that stay planted with it.
//!
//! By hand, for the bundled quadruped's pronk (four legs in phase): each leg
//! brakes and drives the body by `a_x = c·τ` through its support `|τ| ≤ h`,
//! `h = S/2`, with `c = g_n·(P/S)·v/H` (g_n = g/4, `H` the standing height).
//! Less its mean, the body's velocity is `(c/2)(τ² − h²) − ū` in support and
//! `−ū` in transfer, `ū = −(2/3)·c·h³/P`; it is zero at `τ* = ±h·√ρ`,
//! `ρ = 1 − 4h/(3P)`, and the body's lag and lead between those instants
//! differ by `(2/3)·c·h³·ρ^{3/2}` per leg: peak to peak four times that.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::{Creature, load_bundled};
use gaitlab_motion::PodaDriver;

const G: f64 = 9.81;

fn bundled(name: &str) -> Creature {
    match load_bundled(name) {
        Some(Ok(creature)) => creature,
        other => panic!("{name}: {other:?}"),
    }
}

fn driver(creature: &Creature) -> PodaDriver {
    match PodaDriver::new(creature) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    }
}

#[test]
fn a_pronks_surge_is_the_hand_computed_lag_and_lead() {
    let mut creature = bundled("poda-quadruped");
    let poda = creature.scenario.poda.as_mut().expect("a PODA preset");
    assert!(poda.fore_aft_surge, "the bundled quadruped surges");
    poda.gait = Some("pronk".to_owned());
    let mut driver = driver(&creature);
    let fps = 600.0;
    let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut worst_placement = 0.0_f64;
    for frame in 0..(4.0 * fps) as usize {
        driver.step(1.0 / fps);
        let surge = driver.surge_m();
        // The root stands `surge` ahead of the planned ground pose, along the heading.
        let ground = driver.ground_pose(driver.time());
        let ahead = ground.to_body(driver.pose().root.position).z;
        worst_placement = worst_placement.max((ahead - surge).abs());
        if frame as f64 >= fps {
            low = low.min(surge);
            high = high.max(surge);
        }
    }
    let gait = driver.gait();
    let (period, support, speed) = (gait.period_s(), gait.support_s(), gait.speed_mps());
    let stand = driver
        .params()
        .stand_height_m
        .expect("the quadruped sets its height");
    let h = 0.5 * support;
    let c = G / 4.0 * period / support * speed / stand;
    let rho = 1.0 - 4.0 * h / (3.0 * period);
    let by_hand = 4.0 * (2.0 / 3.0) * c * h * h * h * rho * rho.sqrt();
    let measured = high - low;
    println!(
        "pronk surge: c = {c:.3} m/s³, S = {support:.3} s, P = {period:.3} s; \
         peak to peak by hand {:.3} mm, driver {:.3} mm",
        by_hand * 1e3,
        measured * 1e3
    );
    assert!(
        (measured - by_hand).abs() <= 0.01 * by_hand,
        "surge {measured} m against {by_hand} m by hand"
    );
    assert!(
        worst_placement < 1e-9,
        "root off its surge by {worst_placement} m"
    );
    assert!(
        driver.metrics().foot_slip_max_m() < 1e-6,
        "slip {} m",
        driver.metrics().foot_slip_max_m()
    );
}

#[test]
fn every_bundled_gait_keeps_its_feet_planted_while_surging() {
    for name in ["poda-quadruped", "hexapod", "insect-14", "poda-biped"] {
        let creature = bundled(name);
        let gaits: Vec<String> = {
            let probe = driver(&creature);
            gaitlab_motion::poda::gait_names(probe.gait().leg_count())
                .map(str::to_owned)
                .collect()
        };
        for gait in gaits {
            let mut creature = creature.clone();
            let poda = creature.scenario.poda.as_mut().expect("a PODA preset");
            assert!(poda.fore_aft_surge, "{name} surges");
            poda.gait = Some(gait.clone());
            let mut driver = driver(&creature);
            let mut range = (0.0_f64, 0.0_f64);
            for _ in 0..240 {
                driver.step(1.0 / 60.0);
                range = (range.0.min(driver.surge_m()), range.1.max(driver.surge_m()));
            }
            let slip = driver.metrics().foot_slip_max_m();
            assert!(slip < 1e-6, "{name} {gait}: slip {slip} m");
            assert_eq!(driver.metrics().body_surge_range_m, range, "{name} {gait}");
        }
    }
}

#[test]
fn without_the_key_the_body_moves_evenly_as_before() {
    let mut creature = bundled("poda-quadruped");
    let poda = creature.scenario.poda.as_mut().expect("a PODA preset");
    poda.fore_aft_surge = false;
    poda.gait = Some("trot".to_owned());
    let mut driver = driver(&creature);
    for _ in 0..120 {
        driver.step(1.0 / 60.0);
        let ground = driver.ground_pose(driver.time());
        assert!(ground.to_body(driver.pose().root.position).z.abs() < 1e-12);
    }
    assert_eq!(driver.metrics().body_surge_range_m, (0.0, 0.0));
}
