//! A sample of the physics panel's tested bands (issue 21 item 3;
//! `tools/physics_band_sweep.py` runs the whole sweep, 60 s a value): each
//! gait at the middle of its tested speeds and the top of its tested scale
//! band runs 10 s without falling, the mean speed within 10 % of desired.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gaits::table::{tested_scales, tested_speeds_mps};

#[test]
fn every_gait_holds_at_the_top_of_its_tested_scale_band() {
    // The middle speeds of tools/physics_speed_sweep.py, which the band sweep runs at.
    for (name, gait, speed) in [
        ("raibert-biped", "run", 1.6),
        ("raibert-biped", "gallop", 1.5),
        ("raibert-quadruped", "trot", 1.9),
        ("raibert-quadruped", "bound", 2.3),
        ("raibert-kangaroo", "hop", 3.5),
    ] {
        let Some(Ok(preset)) = load_bundled(name) else {
            panic!("{name} is bundled")
        };
        let species = match PhysicsDriver::new(&preset) {
            Ok(driver) => driver.sim().creature.species,
            Err(error) => panic!("{error}"),
        };
        let Some((low, high)) = tested_scales(species, gait) else {
            panic!("{name} {gait}: a band")
        };
        assert!(tested_speeds_mps(species, gait).is_some_and(|(a, b)| a <= speed && speed <= b));
        assert!(
            low <= 1.0 && 1.0 < high,
            "{name} {gait}: L = 1 inside [{low}, {high})"
        );
        let Some(mut params) = preset.scenario.physics.clone() else {
            panic!("{name}: physics")
        };
        params.gait = Some(gait.to_owned());
        params.speed_mps = speed;
        params.scale = high;
        let mut driver = match PhysicsDriver::with_params(&preset, params) {
            Ok(driver) => driver,
            Err(error) => panic!("{name} {gait}: {error}"),
        };
        // 10 s of the scaled creature's time.
        let seconds = 10.0 * high.sqrt();
        while driver.time() < seconds && driver.resets() == 0 {
            driver.step(1.0 / 60.0);
        }
        let s = driver.summary();
        let off = (s.speed_mean_mps - s.speed_desired_mps) / s.speed_desired_mps;
        println!(
            "{name} {gait} at L = {high}: mean {:.3} of {:.3} m/s ({:+.1} %), fell {}",
            s.speed_mean_mps,
            s.speed_desired_mps,
            100.0 * off,
            s.fell
        );
        assert!(
            !s.fell && driver.resets() == 0,
            "{name} {gait} fell at L = {high}"
        );
        assert!(
            off.abs() < 0.10,
            "{name} {gait} at L = {high}: {:+.1} %",
            100.0 * off
        );
    }
}
