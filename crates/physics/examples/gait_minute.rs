//! Writes docs/physics.md's "a minute at several speeds" table: every gait
//! run for 60 s through the driver, fell or not, and the mean speed after
//! settling against the desired speed.
//! `cargo run --release -p gaitlab-physics --example gait_minute`
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let runs: [(&str, &str, &[f64]); 7] = [
        ("raibert-biped", "run", &[1.0, 2.0, 2.5]),
        ("raibert-biped", "gallop", &[1.0, 1.5, 2.0]),
        ("raibert-biped", "gallop_alternate", &[1.0, 1.5, 2.0]),
        ("raibert-quadruped", "trot", &[1.0, 1.5, 1.9, 2.3]),
        ("raibert-quadruped", "bound", &[1.5, 2.3, 2.8]),
        ("raibert-quadruped", "gallop", &[1.5, 2.3, 2.8]),
        ("raibert-kangaroo", "hop", &[2.0, 3.5, 5.0]),
    ];
    println!(
        "| creature | gait | desired (m/s) | 60 s without falling | mean speed (m/s) | error |"
    );
    println!("|---|---|---:|---|---:|---:|");
    for (preset_name, gait, speeds) in runs {
        let preset = load_bundled(preset_name).ok_or("no preset")??;
        for &speed in speeds {
            let mut params = preset.scenario.physics.clone().ok_or("no physics")?;
            params.gait = Some(gait.to_owned());
            params.speed_mps = speed;
            let mut driver = PhysicsDriver::with_params(&preset, params)?;
            driver.reset_after_fall = false;
            // The kangaroo starts at 2 m/s and ramps at 0.25 m/s²: measure after the ramp.
            let ramp = if gait == "hop" {
                (speed - 2.0).max(0.0) / 0.25
            } else {
                0.0
            };
            for _ in 0..((ramp + 3.0) * 60.0) as usize {
                driver.step(1.0 / 60.0);
            }
            driver.clear_metrics();
            for _ in 0..((60.0 - 3.0) * 60.0) as usize {
                driver.step(1.0 / 60.0);
            }
            let s = driver.summary();
            let ok = !s.fell && driver.resets() == 0;
            println!(
                "| {preset_name} | {gait} | {speed} | {} | {:.3} | {:+.1} % |",
                if ok { "yes" } else { "**no**" },
                s.speed_mean_mps,
                (s.speed_mean_mps / speed - 1.0) * 100.0
            );
        }
    }
    Ok(())
}
