//! PODA's vertical dynamics (Girard & Maciejewski 1985, eq. 12–13) against a
//! hand computation: the bundled quadruped's pronk, whose four legs push
//! together, moves the body as one hopper.
//!
//! By hand, with the leg force `F` the driver reports, the body's mass `m`,
//! period `P` and duty factor `β`: during support the four legs accelerate
//! the body by `a = 4F/m − g` (eq. 12); eq. 13 ties the flight to it,
//! `T = (a/g)·S` with `S = β·P`, `T = P − S`. From mid-stance (the lowest
//! point, velocity 0) the body rises `a·S²/8` by lift-off, leaves at
//! `v = a·S/2` and climbs `v²/(2g)` more: peak to peak `a·S²/8 + v²/(2g)`.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_motion::PodaDriver;

const G: f64 = 9.81;

/// The bundled PODA quadruped in `gait`.
fn quadruped_in(gait: &str) -> PodaDriver {
    let mut creature = match load_bundled("poda-quadruped") {
        Some(Ok(creature)) => creature,
        other => panic!("poda-quadruped: {other:?}"),
    };
    if let Some(poda) = creature.scenario.poda.as_mut() {
        poda.gait = Some(gait.to_owned());
        // Eq. 12–13's height alone: with Figure 2's pitch the root, off the
        // legs' centre, also rises and falls with the pitch (docs/poda.md).
        poda.body_pitch = false;
    }
    match PodaDriver::new(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    }
}

#[test]
fn a_pronk_rises_and_flies_as_eq_12_and_13_say() {
    let mut driver = quadruped_in("pronk");
    // 600 frames a second, so that the sampled extremes are within 0.1 % of
    // the true ones.
    let fps = 600.0;
    let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
    for frame in 0..(6.0 * fps) as usize {
        driver.step(1.0 / fps);
        if frame as f64 >= 1.0 * fps {
            let y = driver.pose().root.position.y;
            low = low.min(y);
            high = high.max(y);
        }
    }
    let mass = driver.params().body_mass_kg;
    let force = driver.leg_force_n();
    let (period, duty) = (driver.gait().period_s(), driver.gait().duty_factor());
    let support = duty * period;
    let accel = 4.0 * force / mass - G;
    // Eq. 13's flight from eq. 12's acceleration, against the gait's own.
    let transfer = accel / G * support;
    assert!(
        (transfer - (period - support)).abs() < 1e-9,
        "eq. 13: T = {transfer} s, the gait's {} s",
        period - support
    );
    let lift_off = 0.5 * accel * support;
    let by_hand = accel * support * support / 8.0 + lift_off * lift_off / (2.0 * G);
    let measured = high - low;
    println!(
        "pronk: F = {force} N, m = {mass} kg, a = {accel:.3} m/s², S = {support:.3} s, \
         T = {transfer:.3} s; bob by hand {by_hand:.5} m, driver {measured:.5} m"
    );
    assert!(
        (measured - by_hand).abs() <= 0.01 * by_hand,
        "bob {measured} m against {by_hand} m by hand"
    );
    // Its flight, measured from the feet: a foot counts as down within 1 mm
    // of the ground (`CONTACT_HEIGHT_M`), so the flight measures a little
    // under T (0.415 s against 0.42 s at 600 fps); within 2 %.
    let flight = driver.metrics().flight_max_s;
    assert!(
        flight <= transfer && flight >= 0.98 * transfer,
        "flight {flight} s against T = {transfer} s"
    );
}

/// Each leg of a mixed gait by hand: the quadruped's canter (its legs at
/// phases 0.5, 0.75, 0.75 and 0, duty factor 0.4; the walk's evenly spaced
/// legs cancel to a level body). Leg `i` reaches mid-stance where eq. 9's state
/// `(R_i·P + t) mod P` is `S/2`; `τ` after it, its share of the body is
/// `a·τ²/2` in support (`|τ| ≤ S/2`, `a = g_n·T/S`, eq. 12–13 with
/// `g_n = g/4`) and `a·S²/8 + (a·S/2)·f − g_n·f²/2` in flight (`f = τ − S/2`).
/// The four legs' sum, less its mean, is the body's height less its mean.
#[test]
fn each_leg_of_a_canter_moves_the_body_as_eq_12_and_13_say() {
    let mut driver = quadruped_in("canter");
    let (period, support) = (driver.gait().period_s(), driver.gait().support_s());
    let phases = driver.gait().phases().to_vec();
    let transfer = period - support;
    let g_n = G / 4.0;
    let accel = g_n * transfer / support;
    let leg = |phase: f64, t: f64| {
        let state = (phase * period + t).rem_euclid(period);
        // τ from mid-stance, in [−S/2, P − S/2).
        let tau = state - 0.5 * support;
        if tau <= 0.5 * support {
            0.5 * accel * tau * tau
        } else {
            let f = tau - 0.5 * support;
            accel * support * support / 8.0 + 0.5 * accel * support * f - 0.5 * g_n * f * f
        }
    };
    let fps = 600.0;
    let (mut by_hand, mut body) = (Vec::new(), Vec::new());
    for frame in 1..=(3.0 * fps) as usize {
        driver.step(1.0 / fps);
        let t = frame as f64 / fps;
        if t >= 1.0 {
            by_hand.push(phases.iter().map(|&r| leg(r, t)).sum::<f64>());
            body.push(driver.pose().root.position.y);
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (hand_mean, body_mean) = (mean(&by_hand), mean(&body));
    let range = by_hand.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - by_hand.iter().copied().fold(f64::INFINITY, f64::min);
    let worst = by_hand
        .iter()
        .zip(&body)
        .map(|(h, b)| ((h - hand_mean) - (b - body_mean)).abs())
        .fold(0.0, f64::max);
    println!(
        "canter: phases {phases:?}, a = {accel:.4} m/s², S = {support:.3} s, T = {transfer:.3} s; bob by hand \
         {:.3} mm, largest difference from the body {:.6} mm",
        range * 1e3,
        worst * 1e3
    );
    assert!(range > 0.05, "the canter bobs: {range} m");
    assert!(worst <= 0.01 * range, "{worst} m against a {range} m bob");
}
