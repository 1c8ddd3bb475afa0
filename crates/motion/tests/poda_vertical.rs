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

#[test]
fn a_pronk_rises_and_flies_as_eq_12_and_13_say() {
    let mut creature = match load_bundled("poda-quadruped") {
        Some(Ok(creature)) => creature,
        other => panic!("poda-quadruped: {other:?}"),
    };
    if let Some(poda) = creature.scenario.poda.as_mut() {
        poda.gait = Some("pronk".to_owned());
    }
    let mut driver = match PodaDriver::new(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
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
