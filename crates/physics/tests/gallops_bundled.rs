//! The bundled biped's two gallops by the paper's laws alone (the preset
//! turns the speed trim off), with the gains it carries for each
//! (`controller_by_gait.gallop` and `.gallop_alternate`, tuned over three
//! speeds; docs/physics.md, "The gallops by the paper's laws"): a minute at
//! each of the three speeds within 10 % of the desired one, and the
//! paper's contrast — the together-swing gallop pitches the trunk more than
//! the alternate-swing one ("pitching of the body in response to swinging
//! of the legs is greatly reduced in the second form").

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::metrics::GaitSummary;

/// The bundled biped's `gait` at `speed` (m/s) for 60 s of simulated time.
fn gallop(gait: &str, speed: f64) -> GaitSummary {
    let Some(Ok(preset)) = load_bundled("raibert-biped") else {
        panic!("the biped is bundled")
    };
    let Some(mut params) = preset.scenario.physics.clone() else {
        panic!("a physics preset")
    };
    params.gait = Some(gait.to_owned());
    params.speed_mps = speed;
    let mut driver = match PhysicsDriver::with_params(&preset, params) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(driver.lab_additions().count(), 0, "paper-only");
    while driver.time() < 60.0 {
        driver.step(1.0 / 60.0);
    }
    assert_eq!(driver.resets(), 0, "{gait} at {speed} m/s fell");
    driver.summary()
}

#[test]
fn both_gallops_hold_their_speed_a_minute_by_the_papers_laws() {
    let mut pitch = [0.0; 2];
    for (k, gait) in ["gallop", "gallop_alternate"].into_iter().enumerate() {
        for speed in [1.0, 1.5, 2.0] {
            let s = gallop(gait, speed);
            let off = (s.speed_mean_mps - speed) / speed;
            println!(
                "{gait} at {speed} m/s: mean {:.3} ({:+.1} %), pitch {:.1}°",
                s.speed_mean_mps,
                100.0 * off,
                s.pitch_magnitude_deg
            );
            assert!(
                !s.fell && off.abs() < 0.10,
                "{gait} at {speed}: {:+.1} %",
                100.0 * off
            );
            if speed == 1.5 {
                pitch[k] = s.pitch_magnitude_deg;
            }
        }
    }
    assert!(
        pitch[0] > 1.3 * pitch[1],
        "together-swing {:.1}° against alternate {:.1}°",
        pitch[0],
        pitch[1]
    );
}
