//! Quadruped trotting (Raibert & Hodgins 1991, "Gaits", Table 2): the trot
//! runs without falling and holds its speed; the Table-2 figures side by
//! side with the paper's animation. (The bound and gallop are tested in
//! `quadruped_bound.rs`.)
//!
//! Tests marked `ignore` state acceptance targets the controller does not
//! meet yet; run them with `cargo test -p gaitlab-physics -- --ignored`.

use gaitlab_physics::control::additions::Additions;
use gaitlab_physics::control::gaits::trot;
use gaitlab_physics::control::gaits::trot::{QuadrupedRun, QuadrupedRunParams, quadruped_ground};
use gaitlab_physics::creatures::quadruped;
use gaitlab_physics::engine::metrics::{GaitRecorder, GaitSummary};
use gaitlab_physics::{Sim, SimOptions};

/// Trot at `speed` for `seconds`.
fn run(speed: f64, seconds: f64) -> (GaitSummary, Option<String>) {
    let creature = quadruped(1.0).expect("quadruped builds");
    let mut sim = Sim::new(creature, quadruped_ground(1.0), SimOptions::default());
    trot::start::start(&mut sim, speed, Additions::NONE);
    sim.commands.speed_mps = speed;
    let mut ctl = QuadrupedRun::new(QuadrupedRunParams::default(), &sim.creature);
    let mut rec = GaitRecorder::new(4, speed, 0.0, 3.0);
    while sim.time < seconds {
        if let Err(e) = sim.step(&mut ctl) {
            return (rec.summary(), Some(e.to_string()));
        }
        rec.record(&sim);
    }
    (rec.summary(), None)
}

fn check_runs(speeds: &[f64]) {
    for &v in speeds {
        let (s, err) = run(v, 60.0);
        assert!(err.is_none(), "trot at {v}: {err:?}");
        assert!(!s.fell, "trot at {v} fell");
        let rel = (s.speed_mean_mps - v).abs() / v;
        assert!(
            rel < 0.10,
            "trot at {v}: mean speed {:.3} m/s",
            s.speed_mean_mps
        );
    }
}

#[test]
fn trot_runs_a_minute_at_its_speed() {
    check_runs(&[1.5, 2.3]);
}

#[test]
#[ignore = "trot at 3 m/s: a hip-roll joint spins up in stance (torque mode) after 20-45 s"]
fn trot_runs_a_minute_at_3_mps() {
    check_runs(&[3.0]);
}

fn within(name: &str, paper: f64, ours: f64, misses: &mut Vec<String>) {
    let ok = (ours - paper).abs() <= 0.35 * paper.abs();
    println!(
        "{name:<40} {paper:>8.3} {ours:>8.3} {}",
        if ok { "yes" } else { "NO" }
    );
    if !ok {
        misses.push(name.to_owned());
    }
}

/// Table 2, trot rows: paper's animation column against ours (±35 %).
#[test]
fn table2_trot_side_by_side() {
    let (s, err) = run(2.3, 20.0);
    assert!(err.is_none() && !s.fell);
    let mut misses = Vec::new();
    println!("Quadruped trot: quantity, paper, ours, within ±35 %");
    within(
        "pitch magnitude (deg)",
        6.2,
        s.pitch_magnitude_deg,
        &mut misses,
    );
    within("stride length (m)", 1.49, s.stride_length_m, &mut misses);
    within(
        "stride duration (s)",
        0.54,
        s.stride_duration_s,
        &mut misses,
    );
    within(
        "flight duration (s)",
        0.18,
        s.flight_duration_s,
        &mut misses,
    );
    within(
        "stance duration (s)",
        0.09,
        s.stance_duration_s,
        &mut misses,
    );
    within(
        "leg length change (m)",
        0.03,
        s.leg_length_change_m,
        &mut misses,
    );
    within("running speed (m/s)", 2.3, s.speed_mean_mps, &mut misses);
    // Known misses with the controller's own gains: the trunk pitches less
    // than the paper's (2.6° against 6.2°), so only the figures the
    // controller regulates are held here. The bundled preset's trot gains
    // meet every row (`trot_bundled.rs`).
    for held in [
        "stride length (m)",
        "stride duration (s)",
        "flight duration (s)",
    ] {
        assert!(!misses.iter().any(|m| m == held), "{held} off: {misses:?}");
    }
}

/// The hop-height input reaches the trot (issue 20: it ignored it). With
/// the lab's hop integrator the trot regulates each pair's flight, so a hop
/// height h asks for the flight √(8h/g) whose apex it is, and the measured
/// flight follows it: with the bundled trot's gains (2026-12-06: tuned with
/// the paper's friction) within 5.6 % at 0.02, 0.05, 0.08 and 0.1 m (on the
/// pitching bound's body; it falls at 0.15 m). By eq. 2 alone, as the
/// bundled trot runs, h is the rise eq. 2 is asked for: the flight grows
/// with it, and its apex stays below h (eq. 2 takes the damped legs as
/// lossless): 0.067, 0.133 and 0.204 s at 0.02, 0.05 and 0.11 m.
#[test]
fn the_trot_takes_the_hop_height_as_its_flight() {
    use gaitlab_core::driver::Driver;
    use gaitlab_physics::control::laws::hop_height::{flight_for_height, height_for_flight};
    let preset = gaitlab_core::preset::load_bundled("raibert-quadruped")
        .expect("bundled")
        .expect("valid");
    let flight = |height: f64, integrator: bool| {
        let mut params = preset.scenario.physics.clone().expect("physics");
        params.gait = Some("trot".into());
        params.speed_mps = 1.9;
        params.hop_height_m = Some(height);
        params
            .lab_additions_by_gait
            .entry("trot".to_owned())
            .or_default()
            .hop_integrator = Some(integrator);
        let mut driver =
            gaitlab_physics::PhysicsDriver::with_params(&preset, params).expect("driver");
        assert!((driver.hop_height_m().unwrap_or(0.0) - height).abs() < 1e-12);
        for _ in 0..(20 * 60) {
            driver.step(1.0 / 60.0);
        }
        let s = driver.summary();
        assert!(!s.fell, "hop {height} m, integrator {integrator}: fell");
        s.flight_duration_s
    };
    for height in [0.02, 0.05, 0.08, 0.1] {
        let got = flight(height, true);
        let want = flight_for_height(height);
        assert!(
            (got / want - 1.0).abs() < 0.06,
            "hop {height} m: flight {got} s, want {want} s"
        );
    }
    let mut last = 0.0;
    for height in [0.02, 0.05, 0.11] {
        let got = flight(height, false);
        assert!(
            got > last + 0.03 && height_for_flight(got) < height,
            "eq. 2 asked {height} m: flight {got} s after {last} s"
        );
        last = got;
    }
}
