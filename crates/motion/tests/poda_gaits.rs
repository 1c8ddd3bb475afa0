//! PODA on every bundled creature and every named gait (Girard & Maciejewski
//! 1985): planted feet do not slip, and the duty factor and relative phase
//! measured from the feet match the gait's parameters, on a straight and on a
//! curved body path; the body's vertical motion repeats with the gait period
//! and a strong pronk leaves the ground.

mod common;

use std::f64::consts::PI;

use gaitlab_core::driver::Driver;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::{Creature, PathSpec, PodaParams, load_bundled};
use gaitlab_motion::PodaDriver;
use gaitlab_motion::poda::gait_names;

const PODA_PRESETS: [&str; 4] = ["poda-quadruped", "poda-biped", "hexapod", "insect-14"];
const FPS: f64 = 60.0;

fn creature(name: &str) -> Creature {
    load_bundled(name)
        .expect("bundled preset")
        .expect("valid preset")
}

/// A closed circular path of radius `r` through the creature's start point,
/// turning left.
fn circle(r: f64) -> PathSpec {
    let points = (0..16)
        .map(|k| {
            let a = f64::from(k) / 16.0 * std::f64::consts::TAU;
            [r * a.pcos() - r, r * a.psin()]
        })
        .collect();
    PathSpec {
        kind: Default::default(),
        points,
        closed: true,
        speeds_mps: None,
    }
}

/// The tightest radius `creature`'s body turns on (turn_within_reach), metres.
fn turn_radius(creature: &Creature) -> f64 {
    let driver = PodaDriver::new(creature).expect("driver");
    driver.body_track().dynamics().min_turn_radius_m
}

fn run(creature: &Creature, params: PodaParams, seconds: f64) -> PodaDriver {
    let mut driver = PodaDriver::with_params(creature, params).expect("driver");
    let frames = (seconds * FPS).round() as usize;
    for _ in 0..frames {
        driver.step(1.0 / FPS);
    }
    driver
}

#[test]
fn every_gait_of_every_creature_keeps_feet_planted_and_its_timing() {
    let mut checked = 0;
    for preset in PODA_PRESETS {
        let creature = creature(preset);
        let legs = creature.scenario.poda_params().legs.len();
        for gait in gait_names(legs) {
            for curved in [false, true] {
                let mut params = creature.scenario.poda_params();
                params.gait = Some(gait.to_owned());
                // A turn of radius 4 s of travel (2 rad in the 8 s run), or
                // wider where the creature turns no tighter (turn_within_reach).
                let radius = (4.0 * params.speed_mps).max(1.5 * turn_radius(&creature));
                if curved {
                    params.path = Some(circle(radius));
                }
                let driver = run(&creature, params, 8.0);
                let metrics = driver.metrics();
                let label = format!(
                    "{preset} {gait} {}",
                    if curved { "curved" } else { "straight" }
                );
                let slip = metrics.foot_slip_max_m();
                assert!(slip <= 0.001, "{label}: foot slip {:.3} mm", slip * 1e3);
                common::assert_gait_measured_as_set(&label, &driver);
                if curved {
                    // Half the sideways travel of 8 s round the circle, at least.
                    let turned = (8.0 * driver.gait().speed_mps() / radius).min(PI);
                    let expected = -radius * (1.0 - turned.pcos());
                    let end = driver.pose().root.position;
                    assert!(
                        end.x < 0.5 * expected,
                        "{label}: the body turned left (x = {}, expected {expected})",
                        end.x
                    );
                }
                checked += 1;
            }
        }
    }
    // 10 quadruped gaits (with the 4-leg wave and alternating), 2 biped, 4 hexapod (with the
    // 6-leg alternating), 3 insect (wave, alternating, ripple); two paths each.
    assert_eq!(checked, 38);
}

/// Root heights sampled every frame for `seconds` after `settle` seconds.
fn heights(driver: &mut PodaDriver, settle: f64, seconds: f64) -> Vec<f64> {
    for _ in 0..(settle * FPS).round() as usize {
        driver.step(1.0 / FPS);
    }
    (0..(seconds * FPS).round() as usize)
        .map(|_| {
            driver.step(1.0 / FPS);
            driver.pose().root.position.y
        })
        .collect()
}

#[test]
fn vertical_motion_repeats_with_the_gait_period() {
    let creature = creature("poda-quadruped");
    for gait in ["bound", "pronk", "transverse_gallop", "canter"] {
        // A bound's front and hind pairs push half a cycle apart with equal
        // forces: its body bobs twice a cycle (period P/2).
        let fundamental_is_p = gait != "bound";
        let mut params = creature.scenario.poda_params();
        params.gait = Some(gait.to_owned());
        // Eq. 12–13's superposition alone: with Figure 2's pitch the root,
        // off the legs' centre, also rises and falls with the pitch, once a
        // cycle (docs/poda.md, "Body pitch").
        params.body_pitch = false;
        // P = 0.6 s = 36 frames at 60 fps.
        let mut driver = PodaDriver::with_params(&creature, params).expect("driver");
        let y = heights(&mut driver, 1.0, 3.0);
        let lag = 36;
        let amplitude = y.iter().copied().fold(f64::NEG_INFINITY, f64::max)
            - y.iter().copied().fold(f64::INFINITY, f64::min);
        assert!(amplitude > 0.01, "{gait}: the body bobs ({amplitude} m)");
        let repeat = (0..y.len() - lag)
            .map(|k| (y[k + lag] - y[k]).abs())
            .fold(0.0, f64::max);
        assert!(repeat < 1e-9, "{gait}: y(t + P) − y(t) up to {repeat} m");
        // Not periodic in half the period: the fundamental is P itself.
        let half = (0..y.len() - lag / 2)
            .map(|k| (y[k + lag / 2] - y[k]).abs())
            .fold(0.0, f64::max);
        if fundamental_is_p {
            assert!(half > 0.1 * amplitude, "{gait}: y(t + P/2) ≈ y(t)");
        } else {
            assert!(half < 1e-9, "{gait}: y(t + P/2) − y(t) up to {half} m");
        }
    }
}

#[test]
fn a_pronk_with_high_leg_force_flies() {
    let creature = creature("poda-quadruped");
    let mut params = creature.scenario.poda_params();
    params.gait = Some("pronk".into());
    params.duty_factor = Some(0.9);
    let mass = params.body_mass_kg;
    let stand = params.stand_height_m.unwrap_or(0.0);
    // Rise of the body above its standing height and the longest time with
    // every foot off the ground, over 3 s.
    let hop = |driver: &mut PodaDriver| {
        let mut highest = f64::NEG_INFINITY;
        for _ in 0..180 {
            driver.step(1.0 / FPS);
            highest = highest.max(driver.pose().root.position.y);
        }
        (highest - stand, driver.metrics().flight_max_s)
    };
    let mut weak = PodaDriver::with_params(&creature, params.clone()).expect("driver");
    let (weak_rise, weak_flight) = hop(&mut weak);
    // Three times the balance force (eq. 12–13): transfer lengthens, duty drops below 0.5.
    let mut strong = PodaDriver::with_params(&creature, params).expect("driver");
    let force = 3.0 * strong.gait().leg_force_for_balance_n(mass, 9.81);
    strong
        .gait_mut()
        .set_leg_force(force, mass, 9.81)
        .expect("stronger legs");
    let duty = strong.gait().duty_factor();
    assert!(duty < 0.5, "duty {duty}");
    let (strong_rise, strong_flight) = hop(&mut strong);
    assert!(weak_rise < 0.05, "weak pronk rises {weak_rise} m");
    assert!(
        strong_rise > 0.1 && strong_rise > 3.0 * weak_rise,
        "strong pronk rises {strong_rise} m (weak {weak_rise} m)"
    );
    assert!(
        strong_flight > 0.5 * strong.gait().period_s() && strong_flight > 4.0 * weak_flight,
        "flight {strong_flight} s (weak {weak_flight} s)"
    );
}

/// A sample of `tools/poda_change_sweep.py` (docs/poda.md, "The sweep"): a
/// live change at several frames of a cycle, run until the legs have taken
/// it on (`is_shifting` false), with no planted foot slipping more than 1 mm.
#[test]
fn live_changes_are_taken_on_leg_by_leg_without_slipping() {
    type Change = fn(&mut PodaDriver);
    let creature = creature("poda-quadruped");
    let changes: [(&str, Change); 8] = [
        ("trot → transverse_gallop", |d| {
            d.set_gait("transverse_gallop").expect("gallop")
        }),
        ("trot → pronk", |d| d.set_gait("pronk").expect("pronk")),
        ("trot → walk", |d| d.set_gait("walk").expect("walk")),
        ("trot → pace", |d| d.set_gait("pace").expect("pace")),
        ("period ×1.3", |d| {
            let _ = d.gait_mut().set_period(0.78).expect("period");
        }),
        ("speed ×0.7", |d| {
            let _ = d.set_speed(0.56).expect("speed");
        }),
        ("stroke ×1.3", |d| {
            let _ = d.gait_mut().set_stroke(0.312).expect("stroke");
        }),
        ("duty ×1.3", |d| {
            let _ = d.gait_mut().set_duty_factor(0.65).expect("duty");
        }),
    ];
    for start in (0..36).step_by(7) {
        for (name, change) in changes {
            let mut driver = PodaDriver::new(&creature).expect("driver");
            for _ in 0..60 + start {
                driver.step(1.0 / FPS);
            }
            change(&mut driver);
            driver.step(1.0 / FPS);
            assert!(driver.is_shifting(), "{name}: taken on at once");
            let mut frames = 0;
            while driver.is_shifting() && frames < 900 {
                driver.step(1.0 / FPS);
                frames += 1;
            }
            assert!(
                !driver.is_shifting(),
                "{name} at frame {start}: still shifting after 15 s"
            );
            for _ in 0..60 {
                driver.step(1.0 / FPS);
            }
            // The legs stand in the new gait's phases (eq. 9's R_i relative to leg 0).
            let gait = driver.gait();
            let mid = |i: usize| driver.mid_stance_s(i).expect("leg");
            for (i, &r) in gait.phases().iter().enumerate() {
                let relative = (mid(i) - mid(0)) / gait.period_s() + r - gait.phases()[0];
                let off = relative.rem_euclid(1.0).min(1.0 - relative.rem_euclid(1.0));
                assert!(
                    off < 0.01,
                    "{name} at frame {start}: leg {i} off its phase by {off}"
                );
            }
            let slip = driver.metrics().foot_slip_max_m();
            assert!(
                slip <= 0.001,
                "{name} at frame {}: slip {:.3} mm",
                60 + start,
                slip * 1e3
            );
        }
    }
    let mut driver = PodaDriver::new(&creature).expect("driver");
    let error = driver.set_gait("tripod").expect_err("no tripod for 4 legs");
    assert_eq!(error.path, "gait");
    assert!(error.reason.contains("trot"), "{error}");
}
