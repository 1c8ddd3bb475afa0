//! `gaitlab run --gait` on the hexapod with a pair of legs added (8 legs): the
//! preset's own 6-legged `tripod` is refused with the gaits that 8 legs have,
//! `--gait alternating` (and `ripple`, `wave`) walk it, and the run's
//! `gaits_available` lists them.

mod common;

use common::{bundled_preset, gaitlab, json_of, scratch_arg};

/// The bundled hexapod with a fourth pair of legs, as a user adds it: copies
/// of the `L3`/`R3` limbs renamed `L4`/`R4` and moved 0.2 m back (the pair
/// spacing), appended to `skeleton.limbs`. Written to a scratch file; its path.
fn octopod_file() -> String {
    let hexapod = bundled_preset("hexapod").to_string();
    let path = scratch_arg("hexapod-8-legs.json");
    let octopod = gaitlab_testkit::with_extra_leg_pairs(&hexapod, 3, 1, 0.2);
    std::fs::write(&path, octopod).expect("scratch file");
    path
}

#[test]
fn eight_legs_refuse_the_tripod_and_walk_the_n_legged_gaits() {
    let file = octopod_file();
    let output = gaitlab(&["run", &file, "--seconds", "1", "--json"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("no gait \"tripod\" for 8 legs; available: wave, alternating, ripple"),
        "{stderr}"
    );
    for gait in ["alternating", "ripple", "wave"] {
        let metrics = json_of(&gaitlab(&[
            "run",
            &file,
            "--gait",
            gait,
            "--seconds",
            "10",
            "--json",
        ]));
        assert_eq!(metrics["gait"], gait);
        assert_eq!(
            metrics["gaits_available"],
            serde_json::json!(["wave", "alternating", "ripple"])
        );
        assert_eq!(metrics["legs"].as_array().map(Vec::len), Some(8));
        let slip = metrics["foot_slip_max_m"].as_f64().expect("slip");
        assert!(slip <= 0.001, "{gait}: slip {slip} m");
        let speed = metrics["body_speed_mps"].as_f64().expect("speed");
        assert!((speed - 0.2).abs() <= 0.004, "{gait}: {speed} m/s");
    }
}
