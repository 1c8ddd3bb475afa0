//! The bundled biped's two gallops by the paper's laws alone (the preset
//! turns the speed trim off), with the gains it carries for each
//! (`controller_by_gait.gallop` and `.gallop_alternate`, tuned over three
//! speeds; docs/physics.md, "The gallops by the paper's laws"): a minute at
//! each of the three speeds within 10 % of the desired one, and the
//! paper's contrast — the together-swing gallop pitches the trunk more than
//! the alternate-swing one ("pitching of the body in response to swinging
//! of the legs is greatly reduced in the second form").

mod common;

use common::{bundled, paper_only_run, speed_error};
use gaitlab_physics::engine::metrics::GaitSummary;

/// The bundled biped's `gait` at `speed` (m/s) for 60 s of simulated time.
fn gallop(gait: &str, speed: f64) -> GaitSummary {
    paper_only_run(&bundled("raibert-biped"), Some(gait), speed, 60.0).0
}

#[test]
fn both_gallops_hold_their_speed_a_minute_by_the_papers_laws() {
    let mut pitch = [0.0; 2];
    for (k, gait) in ["gallop", "gallop_alternate"].into_iter().enumerate() {
        for speed in [1.0, 1.5, 2.0] {
            let s = gallop(gait, speed);
            let off = speed_error(&s, gait, speed);
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
