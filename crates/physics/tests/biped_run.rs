//! Biped running (Raibert & Hodgins 1991, Figure 4) through the bundled
//! preset and the driver: a minute without falling at the three
//! speeds with the mean speed within 10 % of desired after 3 s (the paper's
//! claim), by the paper's laws (no speed trim) and with the lab's additions
//! on, and the Table-2 figures beside the paper's animation column.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_core::preset::physics::LabAdditions;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::engine::table2::{measured, paper_rows};

fn run(speed: f64, seconds: f64) -> PhysicsDriver {
    run_with(speed, seconds, None)
}

/// The bundled biped at `speed`, with `additions` in place of the preset's
/// `lab_additions` when given.
fn run_with(speed: f64, seconds: f64, additions: Option<LabAdditions>) -> PhysicsDriver {
    let preset = load_bundled("raibert-biped")
        .expect("bundled")
        .expect("valid");
    let mut params = preset.scenario.physics.clone().expect("physics section");
    params.speed_mps = speed;
    if let Some(a) = additions {
        params.lab_additions = Some(a);
        params.lab_additions_by_gait.clear();
    }
    let mut driver = PhysicsDriver::with_params(&preset, params).expect("driver");
    driver.reset_after_fall = false;
    let frames = (seconds * 60.0) as usize;
    for _ in 0..frames {
        driver.step(1.0 / 60.0);
    }
    driver
}

fn a_minute_within_ten_percent(additions: Option<LabAdditions>, want: &[&str]) {
    for speed in [1.0, 1.6, 2.5] {
        let driver = run_with(speed, 60.0, additions);
        assert!(driver.lab_additions().eq(want.iter().copied()));
        let s = driver.summary();
        assert!(
            !s.fell && driver.resets() == 0,
            "fell at {speed} m/s: {:?}",
            driver.message()
        );
        let error = (s.speed_mean_mps - speed).abs() / speed;
        eprintln!(
            "biped run {speed} m/s, additions {want:?}: mean {:.3} m/s ({:.1} %)",
            s.speed_mean_mps,
            error * 100.0
        );
        assert!(
            error < 0.10,
            "mean speed {} at desired {speed}",
            s.speed_mean_mps
        );
    }
}

#[test]
fn runs_a_minute_at_three_speeds_within_ten_percent_without_the_speed_trim() {
    // The bundled preset: the paper's laws alone (eq. 3 holds the speed,
    // Unloading's hip torque is zero as in Figure 4), control every 2 ms.
    a_minute_within_ten_percent(None, &[]);
}

#[test]
fn runs_a_minute_at_three_speeds_within_ten_percent_with_the_lab_additions() {
    let on = LabAdditions {
        speed_trim: Some(true),
        unloading_posture: Some(true),
        hop_integrator: Some(true),
        ..LabAdditions::default()
    };
    a_minute_within_ten_percent(
        Some(on),
        &["speed_trim", "unloading_posture", "hop_integrator"],
    );
}

#[test]
fn table_2_figures_beside_the_papers() {
    let driver = run(1.6, 20.0);
    let s = driver.summary();
    let legs = ["left", "right"];
    let mut within = 0;
    // The "error in running speed" row (†) is reported, not judged: the
    // paper does not define it (docs/physics.md, "Table 2, side by side").
    let rows: Vec<_> = paper_rows("run")
        .iter()
        .filter(|r| !r.quantity.is_speed_error())
        .collect();
    for row in &rows {
        let ours = measured(&s, row.quantity, &legs).expect("measured");
        let ratio = ours / row.animation;
        eprintln!(
            "{:40} paper {:7.3} ours {:7.3} ({:+.0} %)",
            row.label,
            row.animation,
            ours,
            (ratio - 1.0) * 100.0
        );
        if (0.65..=1.35).contains(&ratio) {
            within += 1;
        }
    }
    // The figures that must hold: the step's timing (stride duration and
    // stance are the paper's step, not two steps; see docs/physics.md).
    let step_s = s.stride_duration_s / 2.0;
    assert!((step_s - 0.47).abs() / 0.47 < 0.35, "step {step_s} s");
    assert!(
        (s.stance_duration_s - 0.18).abs() / 0.18 < 0.35,
        "stance {} s",
        s.stance_duration_s
    );
    assert!(
        (s.flight_duration_s - 0.29).abs() / 0.29 < 0.35,
        "flight {} s",
        s.flight_duration_s
    );
    assert_eq!(
        within,
        rows.len(),
        "{within} of {} Table-2 rows within ±35 %",
        rows.len()
    );
}
