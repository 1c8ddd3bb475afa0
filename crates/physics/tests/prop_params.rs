//! Property tests of the physics driver (Raibert & Hodgins 1991) with random
//! parameters inside the ranges preset validation accepts
//! (`PhysicsParams::check`): gait, desired speed (±15 m/s), hop height
//! (0–2 m), dynamic scale factor L (0.05–20, Table 1), integration step
//! (1e-5–2e-3 s), waypoints and obstacles, plus the tunable controller gains
//! (any finite value ≥ 0: from 0 up to 1000 times the default) and a live
//! gait, speed, hop-height and heading change half way.
//!
//! The contract, checked after every frame on the three bundled Raibert
//! creatures: the simulated state, the pose, the effector positions and the
//! plot probe are finite. A state that would turn non-finite must be caught by
//! the blow-up guard (`Sim::step` → `BlowUp`), which puts the creature back at
//! the start and says so: every reset the driver counts carries a message that
//! names a blow-up or a fall. The Table-2 summary is finite at the end.
//!
//! The seed is fixed for repeatable CI; `PROPTEST_RNG_SEED=<u64>` picks another
//! and `GAITLAB_PROP_SCALE=<k>` multiplies the case counts (docs/property-tests.md).

use gaitlab_core::driver::Driver;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::{Creature as PresetCreature, ObstacleSpec, PhysicsParams, load_bundled};
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gaits::table::gait_names;
use gaitlab_testkit::prop_config as config;
use proptest::prelude::*;

const PRESETS: [&str; 3] = ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"];

/// Frames per second of the display loop the driver is stepped by.
const FPS: f64 = 60.0;

/// Most integration steps one case may take per creature (keeps the test
/// fast when a tiny step asks for hundreds of steps per frame).
const STEP_BUDGET: f64 = 6000.0;

fn preset(name: &str) -> PresetCreature {
    match load_bundled(name) {
        Some(Ok(creature)) => creature,
        Some(Err(error)) => panic!("{name}: {error}"),
        None => panic!("no bundled preset {name}"),
    }
}

/// `10^e` for `e` uniform in `[lo, hi]`, capped at `max` (rounding may overshoot).
fn log_uniform(lo: f64, hi: f64, max: f64) -> impl Strategy<Value = f64> {
    (lo..=hi).prop_map(move |e| 10.0_f64.ppowf(e).min(max))
}

/// The drawn values; gait and gain choices are taken modulo the creature's
/// counts (plain numbers, so a regression test can write a case out).
#[derive(Clone, Debug)]
struct Draw {
    gait: Option<usize>,
    speed_mps: f64,
    hop_height_m: Option<f64>,
    scale: f64,
    dt_s: f64,
    waypoints: Vec<[f64; 2]>,
    obstacles: Vec<ObstacleSpec>,
    /// `(which gain, factor on its default)`; a factor of 0 zeroes it.
    gains: Vec<(usize, f64)>,
    live: Live,
}

/// The changes made half way.
#[derive(Clone, Debug)]
struct Live {
    gait: Option<usize>,
    speed_mps: f64,
    hop_height_m: Option<f64>,
    heading_rad: Option<f64>,
}

fn obstacle() -> impl Strategy<Value = ObstacleSpec> {
    (
        prop_oneof![3 => 0.5..=10.0_f64, 1 => -1e3..=1e3_f64],
        log_uniform(-2.0, 3.0, 1e3),
        log_uniform(-3.0, 3.0, 1e3),
    )
        .prop_map(|(at_m, depth_m, height_m)| ObstacleSpec {
            at_m,
            depth_m,
            height_m,
        })
}

fn draw() -> impl Strategy<Value = Draw> {
    let live = (
        prop::option::of(0..8_usize),
        -15.0..=15.0_f64,
        prop::option::of(0.0..=2.0_f64),
        prop::option::of(-std::f64::consts::PI..=std::f64::consts::PI),
    )
        .prop_map(|(gait, speed_mps, hop_height_m, heading_rad)| Live {
            gait,
            speed_mps,
            hop_height_m,
            heading_rad,
        });
    let gain = (
        0..16_usize,
        prop_oneof![1 => Just(0.0), 6 => log_uniform(-3.0, 3.0, 1e3)],
    );
    (
        prop::option::of(0..8_usize),
        prop_oneof![2 => -3.0..=6.0_f64, 1 => -15.0..=15.0_f64],
        prop::option::weighted(0.5, 0.0..=2.0_f64),
        prop_oneof![2 => Just(1.0), 1 => log_uniform(-1.3, 1.3, 20.0).prop_map(|l| l.max(0.05))],
        prop_oneof![2 => Just(0.0004), 1 => log_uniform(-5.0, -2.7, 2e-3).prop_map(|dt| dt.max(1e-5))],
        prop::collection::vec((-50.0..=50.0_f64, -50.0..=50.0_f64).prop_map(|(x, z)| [x, z]), 0..=4),
        prop::collection::vec(obstacle(), 0..=3),
        prop::collection::vec(gain, 0..=4),
        live,
    )
        .prop_map(
            |(gait, speed_mps, hop_height_m, scale, dt_s, waypoints, obstacles, gains, live)| Draw {
                gait,
                speed_mps,
                hop_height_m,
                scale,
                dt_s,
                waypoints,
                obstacles,
                gains,
                live,
            },
        )
}

/// The preset's physics section with the drawn values in place.
fn params(preset: &PresetCreature, gaits: &[&str], draw: &Draw) -> Option<PhysicsParams> {
    let base = preset.scenario.physics.clone()?;
    Some(PhysicsParams {
        gait: draw
            .gait
            .as_ref()
            .map(|i| gaits[i % gaits.len()].to_owned())
            .or(base.gait.clone()),
        speed_mps: draw.speed_mps,
        hop_height_m: draw.hop_height_m,
        scale: draw.scale,
        dt_s: draw.dt_s,
        waypoints: draw.waypoints.clone(),
        obstacles: draw.obstacles.clone(),
        ..base
    })
}

/// The first non-finite output of the driver's frame, if any.
fn frame_problem(driver: &PhysicsDriver) -> Option<String> {
    if !driver.sim().data.is_finite() {
        return Some("the simulated state is not finite".into());
    }
    let pose = driver.pose();
    if !(pose.root.position.is_finite() && pose.root.rotation.is_finite()) {
        return Some(format!("root {:?}", pose.root));
    }
    if let Some((k, v)) = pose.joints.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Some(format!("joint {k} = {v}"));
    }
    if let Some(p) = driver.effector_positions().iter().find(|p| !p.is_finite()) {
        return Some(format!("effector at {p}"));
    }
    let probe = driver.probe();
    let figures = [
        probe.height_m,
        probe.pitch_deg,
        probe.roll_deg,
        probe.leg_length_m,
        probe.ground_force_bw,
        probe.speed_mps,
    ];
    if figures.iter().any(|x| !x.is_finite()) {
        return Some(format!("probe {probe:?}"));
    }
    None
}

/// Runs one creature with the drawn values; returns the first problem.
fn run(name: &str, draw: &Draw) -> Result<(), String> {
    let preset = preset(name);
    let species = PhysicsDriver::new(&preset)
        .map_err(|e| format!("bundled preset refused: {e}"))?
        .sim()
        .creature
        .species;
    let gaits = gait_names(species);
    let params = params(&preset, gaits, draw).ok_or("no physics section")?;
    let known = |n: &str| preset.skeleton.joint_index(n).is_some();
    params
        .check("scenario.physics", &known)
        .map_err(|e| format!("generated parameters out of range: {e}"))?;
    let mut driver = match PhysicsDriver::with_params(&preset, params.clone()) {
        Ok(driver) => driver,
        // A box drawn under the creature puts its feet inside it: refused
        // with the foot named (engine/consistency.rs), a clean outcome.
        Err(e)
            if e.path.starts_with("scenario.physics.legs[")
                && e.reason.contains("below the ground") =>
        {
            return Ok(());
        }
        Err(e) => return Err(format!("refused: {e}")),
    };
    let gains = driver.gains();
    for (index, factor) in draw.gains.iter().filter(|_| !gains.is_empty()) {
        let gain = gains[index % gains.len()];
        let value = gain.default * factor;
        driver
            .set_gain(gain.name, value)
            .map_err(|e| format!("gain {} = {value}: {e}", gain.name))?;
    }
    if let Some(problem) = frame_problem(&driver) {
        return Err(format!("at the start: {problem}"));
    }
    let step_s = driver.sim().options.dt;
    let steps_per_frame = ((1.0 / FPS) / step_s).ceil().min(400.0);
    let frames = (STEP_BUDGET / steps_per_frame).clamp(30.0, 2.0 * FPS) as usize;
    let mut resets = 0;
    for frame in 0..frames {
        if frame == frames / 2 {
            let live = &draw.live;
            if let Some(index) = live.gait {
                driver
                    .set_gait(gaits[index % gaits.len()])
                    .map_err(|e| format!("set_gait: {e}"))?;
            }
            driver
                .set_speed(live.speed_mps)
                .map_err(|e| format!("set_speed: {e}"))?;
            if let Some(height) = live.hop_height_m {
                driver
                    .set_hop_height(height)
                    .map_err(|e| format!("set_hop_height: {e}"))?;
            }
            if let Some(heading) = live.heading_rad {
                driver.set_heading(heading);
            }
        }
        driver.step(1.0 / FPS);
        if let Some(problem) = frame_problem(&driver) {
            return Err(format!(
                "frame {frame} (t = {:.3} s, {} resets): {problem}",
                driver.time(),
                driver.resets()
            ));
        }
        if driver.resets() != resets {
            resets = driver.resets();
            let message = driver.message().unwrap_or_default();
            if !(message.contains("blew up") || message.contains("fell")) {
                return Err(format!(
                    "frame {frame}: reset without a reason: {message:?}"
                ));
            }
        }
    }
    let summary = driver.summary();
    let figures = [
        summary.speed_desired_mps,
        summary.speed_mean_mps,
        summary.stride_duration_s,
        summary.stride_length_m,
        summary.flight_duration_s,
        summary.stance_duration_s,
        summary.leg_length_change_m,
        summary.pitch_magnitude_deg,
        summary.roll_magnitude_deg,
        summary.peak_vertical_accel_g,
        summary.friction_needed_max,
        summary.tail_wag_deg.unwrap_or(0.0),
    ];
    if figures
        .iter()
        .chain(&summary.leg_stance_s)
        .any(|x| !x.is_finite())
    {
        return Err(format!("summary not finite: {summary:?}"));
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(32))]

    /// The biped, the quadruped and the kangaroo with the same drawn values.
    #[test]
    fn physics_parameters_in_range_never_leave_a_non_finite_state_unguarded(draw in draw()) {
        for name in PRESETS {
            prop_assert_eq!(run(name, &draw), Ok(()), "{}", name);
        }
    }
}

/// Regression, shrunk from a failure of the property above (seed 2 at 10×
/// the cases): the small quadruped (L ≈ 0.21) standing against an 11 m wall,
/// switched to the bound half way, had a leg driven past its stop; the
/// bound controller's pitch-torque limit, proportional to the leg's length,
/// went negative and `f64::clamp(-lim, lim)` panicked. (The trot controller
/// computes the same limit and got the same fix; this case does not reach it.)
///
/// Since the start check (engine/consistency.rs) that 11 m box under the
/// creature is refused, naming the foot inside it; the same wall just ahead
/// of the front feet runs.
#[test]
fn a_quadruped_leg_driven_past_its_stop_does_not_panic_the_controller() {
    let mut draw = Draw {
        gait: None,
        speed_mps: 0.0,
        hop_height_m: None,
        scale: 0.206_813_664_869_386_32,
        dt_s: 0.0004,
        waypoints: Vec::new(),
        obstacles: vec![ObstacleSpec {
            at_m: 0.0,
            depth_m: 1.0,
            height_m: 11.067_001_918_472_181,
        }],
        gains: Vec::new(),
        live: Live {
            gait: Some(1),
            speed_mps: 0.0,
            hop_height_m: None,
            heading_rad: None,
        },
    };
    let preset = preset("raibert-quadruped");
    let gaits = gait_names(gaitlab_physics::creatures::Species::Quadruped);
    let Some(params) = params(&preset, gaits, &draw) else {
        panic!("a physics section")
    };
    match PhysicsDriver::with_params(&preset, params) {
        Err(e) => assert!(
            e.path == "scenario.physics.legs[0].foot_point_m"
                && e.reason.contains("below the ground"),
            "{e}"
        ),
        Ok(_) => panic!("a creature inside a box starts"),
    }
    draw.obstacles[0].at_m = 0.5;
    assert_eq!(run("raibert-quadruped", &draw), Ok(()));
}
