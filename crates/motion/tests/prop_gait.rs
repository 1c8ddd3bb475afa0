//! Property tests of the kinematic drivers with random parameters inside the
//! ranges that preset validation accepts.
//!
//! PODA (Girard & Maciejewski 1985) on every bundled PODA creature: period,
//! duty factor, relative phases (eq. 7–9), speed, step height, standing
//! height, transfer key positions, body path (Catmull-Rom or B-spline, open
//! or closed, up to ±1e6 m), body mass, leg force, vertical gain (eq. 12–15),
//! IK iterations, tolerance and center gain (eq. 6), with a live gait change
//! and gait edits half way. Every frame's pose (root and joint values), effector
//! positions, foot targets and footholds are finite. A driver may refuse
//! parameters only for the relations preset validation leaves to it — a stroke
//! `v·β·P` outside its range (eq. 7) or a path whose points are too close — and
//! then says so with the field's path.
//!
//! The thesis driver (She 2006 §5.1.1–5.2): cycle shapes, slowdown, speed,
//! iterations per frame, posture gain, start ramp and wounded weights anywhere
//! in [`validate_params`]' ranges, every mode and method, on the bundled human
//! and IK quadruped: every frame's pose is finite and inside the joint limits,
//! and the IK never had to restore a non-finite solve.
//!
//! The seed is fixed for repeatable CI; `PROPTEST_RNG_SEED=<u64>` picks another
//! and `GAITLAB_PROP_SCALE=<k>` multiplies the case counts (docs/property-tests.md).

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::thesis::{CycleShape, ThesisMode, ThesisParams, WoundedJoint};
use gaitlab_core::preset::{Creature, PathKindSpec, PathSpec, PodaParams, load_bundled};
use gaitlab_motion::poda::gait_names;
use gaitlab_motion::{PodaDriver, ThesisDriver, validate_params};
use gaitlab_testkit::prop_config as config;
use glam::DVec3;
use proptest::prelude::*;
use proptest::sample::Index;

const PODA_PRESETS: [&str; 4] = ["poda-quadruped", "poda-biped", "hexapod", "insect-14"];
const THESIS_PRESETS: [&str; 2] = ["human", "ik-quadruped"];

fn creature(name: &str) -> Creature {
    match load_bundled(name) {
        Some(Ok(creature)) => creature,
        Some(Err(error)) => panic!("{name}: {error}"),
        None => panic!("no bundled preset {name}"),
    }
}

/// `10^e` for `e` drawn uniformly in `[lo, hi]`: log-uniform values.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..=hi).prop_map(|e| 10.0_f64.ppowf(e))
}

/// A log-uniform value capped at `max` (rounding of `10^e` may overshoot).
fn log_uniform_to(lo: f64, max: f64) -> impl Strategy<Value = f64> {
    log_uniform(lo, max.pln() / std::f64::consts::LN_10).prop_map(move |v| v.min(max))
}

/// A body path: a random walk of 2–64 points from an origin near the creature
/// or far out (±1e6 m); a step is sometimes zero (a duplicate point, which the
/// path must refuse).
fn path() -> impl Strategy<Value = PathSpec> {
    let step = prop_oneof![
        1 => Just((0.0, 0.0)),
        200 => (log_uniform(-2.0, 1.3), -std::f64::consts::PI..std::f64::consts::PI),
    ];
    (
        prop_oneof![Just(PathKindSpec::CatmullRom), Just(PathKindSpec::BSpline)],
        any::<bool>(),
        prop_oneof![
            4 => Just([0.0, 0.0]),
            1 => (-9.9e5..9.9e5, -9.9e5..9.9e5).prop_map(|(x, z)| [x, z]),
        ],
        prop::collection::vec(step, 1..=63),
    )
        .prop_map(|(kind, closed, origin, steps)| {
            let mut points = vec![origin];
            let mut at = origin;
            for (length, heading) in steps {
                let (sin, cos) = heading.psin_cos();
                at = [at[0] + length * sin, at[1] + length * cos];
                points.push(at);
            }
            PathSpec {
                kind,
                points,
                closed,
                speeds_mps: None,
            }
        })
}

/// Transfer key positions: up to 16, step fractions strictly increasing in (0, 1).
fn transfer_keys() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((1e-6..1.0 - 1e-6, 0.0..=2.0_f64), 0..=16).prop_map(
        |mut keys: Vec<(f64, f64)>| {
            keys.sort_by(|a, b| a.0.total_cmp(&b.0));
            // Strictly increasing: drop a key whose fraction equals the one before.
            keys.dedup_by(|later, earlier| later.0 <= earlier.0);
            keys.into_iter()
                .map(|(along, height)| [along, height])
                .collect()
        },
    )
}

/// Random PODA values; legs, gait name and phases are fitted to the creature later.
#[derive(Clone, Debug)]
struct PodaDraw {
    gait: Option<Index>,
    period_s: f64,
    duty_factor: Option<f64>,
    /// One phase per leg for up to 32 legs (the creature takes its first few).
    phases: Option<Vec<f64>>,
    speed_mps: f64,
    step_height_m: f64,
    stand_height_m: Option<f64>,
    transfer_keys: Vec<[f64; 2]>,
    path: Option<PathSpec>,
    body_mass_kg: f64,
    max_leg_force_n: Option<f64>,
    vertical_gain: f64,
    iterations_per_frame: usize,
    tolerance_m: f64,
    center_gain: f64,
}

fn poda_draw() -> impl Strategy<Value = PodaDraw> {
    (
        (
            prop::option::of(any::<Index>()),
            log_uniform_to(-1.0, 10.0),
            prop::option::of(0.05..=0.95_f64),
            prop::option::weighted(0.4, prop::collection::vec(-3.0..3.0_f64, 32)),
            log_uniform_to(-2.0, 20.0),
            log_uniform_to(-4.0, 5.0),
            prop::option::weighted(0.3, log_uniform_to(-2.0, 100.0)),
        ),
        (
            transfer_keys(),
            prop::option::weighted(0.5, path()),
            log_uniform_to(-3.0, 1e6),
            prop::option::weighted(0.3, log_uniform_to(-3.0, 1e9)),
            0.0..=4.0_f64,
            1..=64_usize,
            log_uniform_to(-9.0, 0.1),
            0.0..=10.0_f64,
        ),
    )
        .prop_map(
            |(
                (gait, period_s, duty_factor, phases, speed_mps, step_height_m, stand_height_m),
                (
                    transfer_keys,
                    path,
                    body_mass_kg,
                    max_leg_force_n,
                    vertical_gain,
                    iterations_per_frame,
                    tolerance_m,
                    center_gain,
                ),
            )| PodaDraw {
                gait,
                period_s,
                duty_factor,
                phases,
                speed_mps,
                step_height_m,
                stand_height_m,
                transfer_keys,
                path,
                body_mass_kg,
                max_leg_force_n,
                vertical_gain,
                iterations_per_frame,
                tolerance_m,
                center_gain,
            },
        )
}

/// The creature's PODA parameters with the drawn values in place.
fn poda_params(creature: &Creature, draw: &PodaDraw) -> PodaParams {
    let base = creature.scenario.poda_params();
    let legs = base.legs.len();
    let names: Vec<&str> = gait_names(legs).collect();
    PodaParams {
        gait: match (&draw.gait, names.is_empty()) {
            (Some(index), false) => Some(names[index.index(names.len())].to_owned()),
            _ => base.gait.clone(),
        },
        period_s: draw.period_s,
        duty_factor: draw.duty_factor,
        phases: draw
            .phases
            .as_ref()
            .map(|phases| phases[..legs.min(phases.len())].to_vec()),
        speed_mps: draw.speed_mps,
        step_height_m: draw.step_height_m,
        stand_height_m: draw.stand_height_m.or(base.stand_height_m),
        transfer_keys: draw.transfer_keys.clone(),
        path: draw.path.clone(),
        body_mass_kg: draw.body_mass_kg,
        max_leg_force_n: draw.max_leg_force_n,
        vertical_gain: draw.vertical_gain,
        iterations_per_frame: draw.iterations_per_frame,
        tolerance_m: draw.tolerance_m,
        center_gain: draw.center_gain,
        ..base
    }
}

/// Edits made half way through a run (each may be refused; none may break the pose).
#[derive(Clone, Debug)]
struct LiveEdit {
    gait: Index,
    speed_mps: f64,
    duty_factor: f64,
    period_s: f64,
    phase: (Index, f64),
    step_height_m: f64,
}

fn live_edit() -> impl Strategy<Value = LiveEdit> {
    (
        any::<Index>(),
        log_uniform_to(-2.0, 20.0),
        0.05..=0.95_f64,
        log_uniform_to(-1.0, 10.0),
        (any::<Index>(), -3.0..3.0_f64),
        log_uniform_to(-4.0, 5.0),
    )
        .prop_map(
            |(gait, speed_mps, duty_factor, period_s, phase, step_height_m)| LiveEdit {
                gait,
                speed_mps,
                duty_factor,
                period_s,
                phase,
                step_height_m,
            },
        )
}

/// The first non-finite value of the driver's current frame, if any.
fn poda_frame_problem(driver: &PodaDriver) -> Option<String> {
    let pose = driver.pose();
    if !(pose.root.position.is_finite() && pose.root.rotation.is_finite()) {
        return Some(format!("root {:?}", pose.root));
    }
    if let Some((j, v)) = pose.joints.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Some(format!(
            "joint {} = {v}",
            driver.skeleton().joints()[j].name
        ));
    }
    if let Some(p) = driver.effector_positions().iter().find(|p| !p.is_finite()) {
        return Some(format!("effector at {p}"));
    }
    if let Some((p, _)) = driver.foot_targets().find(|(p, _)| !p.is_finite()) {
        return Some(format!("foot target {p}"));
    }
    if let Some(p) = driver.footholds().find(|p| !p.is_finite()) {
        return Some(format!("foothold {p}"));
    }
    None
}

/// Runs `creature` with the drawn parameters for `seconds` at `fps`, with `edit`
/// half way; returns the first problem.
fn run_poda(
    creature: &Creature,
    draw: &PodaDraw,
    edit: &LiveEdit,
    seconds: f64,
    fps: f64,
) -> Result<(), String> {
    let params = poda_params(creature, draw);
    if let Err(error) = params.check_values("scenario.poda") {
        return Err(format!("generated parameters out of range: {error}"));
    }
    let mut driver = match PodaDriver::with_params(creature, params.clone()) {
        Ok(driver) => driver,
        Err(error) => {
            let stroke = draw.speed_mps * draw.period_s * params.duty_factor.unwrap_or(0.5);
            let text = error.to_string();
            // The relations validation leaves to the gait model and the path.
            let allowed = text.contains("stroke_m") || text.starts_with("scenario.poda.path");
            return if allowed {
                Ok(())
            } else {
                Err(format!("refused (stroke ≈ {stroke:.3} m): {text}"))
            };
        }
    };
    if let Some(problem) = poda_frame_problem(&driver) {
        return Err(format!("after reset: {problem}"));
    }
    let frames = (seconds * fps).round() as usize;
    for frame in 0..frames {
        if frame == frames / 2 {
            let legs = driver.gait().leg_count();
            let names: Vec<&str> = gait_names(legs).collect();
            if !names.is_empty() {
                // A gait the model cannot take (a stroke out of range) is refused.
                let _ = driver.set_gait(names[edit.gait.index(names.len())]);
            }
            let gait = driver.gait_mut();
            let _ = gait.set_speed(edit.speed_mps);
            let _ = gait.set_duty_factor(edit.duty_factor);
            let _ = gait.set_period(edit.period_s);
            let _ = gait.set_phase(edit.phase.0.index(legs), edit.phase.1);
            let _ = driver.set_step_height(edit.step_height_m);
        }
        driver.step(1.0 / fps);
        if let Some(problem) = poda_frame_problem(&driver) {
            return Err(format!(
                "frame {frame} (t = {:.3} s): {problem}",
                driver.time()
            ));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(64))]

    /// Every bundled PODA creature, 3 s at 60 frames per second with a live
    /// change half way: every frame finite.
    #[test]
    fn poda_gaits_in_range_never_make_a_non_finite_pose(
        draw in poda_draw(),
        edit in live_edit(),
    ) {
        for name in PODA_PRESETS {
            let outcome = run_poda(&creature(name), &draw, &edit, 3.0, 60.0);
            prop_assert_eq!(outcome, Ok(()), "{}", name);
        }
    }
}

/// A cycle shape: feet and hands within ±1.5 m, frequency in (0, 10] Hz,
/// step height, bounce and root height as validation allows (kept to a few metres).
fn cycle() -> impl Strategy<Value = CycleShape> {
    let point = || {
        (-1.5..=1.5_f64, -0.5..=2.0_f64, -1.5..=1.5_f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
    };
    (
        log_uniform_to(-2.0, 10.0),
        point(),
        point(),
        0.0..=1.0_f64,
        point(),
        point(),
        log_uniform_to(-2.0, 3.0),
        0.0..=1.0_f64,
    )
        .prop_map(
            |(
                frequency_hz,
                front_foot,
                back_foot,
                step_height_m,
                front_hand,
                back_hand,
                root_height_m,
                bounce_m,
            )| CycleShape {
                frequency_hz,
                front_foot,
                back_foot,
                step_height_m,
                front_hand,
                back_hand,
                root_height_m,
                bounce_m,
            },
        )
}

/// Random thesis values; wounded joints are fitted to the skeleton later.
#[derive(Clone, Debug)]
struct ThesisDraw {
    /// Keep the preset's cycle shapes (the tuned walk and run) or use drawn ones.
    walk: Option<CycleShape>,
    run: Option<CycleShape>,
    slowdown: f64,
    moving_forward: bool,
    speed_mps: Option<f64>,
    iterations_per_frame: usize,
    posture_gain: f64,
    start_ramp_s: f64,
    wounded: Vec<(Index, f64, f64)>,
    mode: ThesisMode,
    method: Method,
    /// IK options inside `check_ik_options`' ranges: `None` keeps the defaults.
    ik: Option<(f64, f64, f64, f64)>,
}

fn thesis_draw() -> impl Strategy<Value = ThesisDraw> {
    (
        prop::option::of(cycle()),
        prop::option::of(cycle()),
        prop_oneof![3 => Just(1.0), 1 => 1.0..=100.0_f64],
        any::<bool>(),
        prop::option::of(0.0..=20.0_f64),
        prop_oneof![4 => 1..=8_usize, 1 => 9..=100_usize],
        0.0..=1.0_f64,
        0.0..=10.0_f64,
        prop::collection::vec((any::<Index>(), 0.0..=10.0_f64, -0.5..=0.5_f64), 0..=4),
        prop::sample::select(ThesisMode::ALL.to_vec()),
        prop::sample::select(Method::ALL.to_vec()),
        prop::option::of((
            log_uniform_to(-4.0, 10.0),
            1e-3..=std::f64::consts::PI,
            1e-3..=std::f64::consts::PI,
            0.0..=10.0_f64,
        )),
    )
        .prop_map(
            |(
                walk,
                run,
                slowdown,
                moving_forward,
                speed_mps,
                iterations_per_frame,
                posture_gain,
                start_ramp_s,
                wounded,
                mode,
                method,
                ik,
            )| ThesisDraw {
                walk,
                run,
                slowdown,
                moving_forward,
                speed_mps,
                iterations_per_frame,
                posture_gain,
                start_ramp_s,
                wounded,
                mode,
                method,
                ik,
            },
        )
}

fn thesis_params(creature: &Creature, draw: &ThesisDraw) -> ThesisParams {
    let base = creature.scenario.thesis.clone();
    let joints = creature.skeleton.joints();
    let mut wounded: Vec<WoundedJoint> = Vec::new();
    for (index, multiply, add) in &draw.wounded {
        let joint = joints[index.index(joints.len())].name.clone();
        if wounded.iter().all(|w| w.joint != joint) {
            wounded.push(WoundedJoint {
                joint,
                multiply: *multiply,
                add: *add,
            });
        }
    }
    ThesisParams {
        walk: draw.walk.clone().unwrap_or_else(|| base.walk.clone()),
        run: draw.run.clone().unwrap_or_else(|| base.run.clone()),
        slowdown: draw.slowdown,
        moving_forward: draw.moving_forward,
        speed_mps: draw.speed_mps,
        iterations_per_frame: draw.iterations_per_frame,
        posture_gain: draw.posture_gain,
        start_ramp_s: draw.start_ramp_s,
        wounded,
        ..base
    }
}

fn run_thesis(creature: &Creature, draw: &ThesisDraw, seconds: f64) -> Result<(), String> {
    let params = thesis_params(creature, draw);
    validate_params(&params).map_err(|e| format!("generated parameters out of range: {e}"))?;
    let mut options = IkOptions {
        method: draw.method,
        ..creature.scenario.ik_options()
    };
    if let Some((lambda, gamma_max, max_step, null_space_gain)) = draw.ik {
        options.lambda = lambda;
        options.gamma_max = gamma_max;
        options.max_step = max_step;
        options.null_space_gain = null_space_gain;
    }
    gaitlab_core::preset::check_ik_options("ik", &options)
        .map_err(|e| format!("generated options out of range: {e}"))?;
    let mut driver = ThesisDriver::new(creature.skeleton.clone(), params, draw.mode, options)
        .map_err(|e| format!("refused: {e}"))?;
    // The iterations per frame set the cost: keep the total roughly constant.
    let fps = 60.0;
    let frames = ((seconds * fps) as usize * 4 / draw.iterations_per_frame.max(4)).max(12);
    let skeleton = creature.skeleton.clone();
    for frame in 0..frames {
        driver.step(1.0 / fps);
        let pose = driver.pose();
        if !(pose.root.position.is_finite() && pose.root.rotation.is_finite()) {
            return Err(format!("frame {frame}: root {:?}", pose.root));
        }
        for (joint, &value) in skeleton.joints().iter().zip(&pose.joints) {
            let inside = joint
                .limits
                .is_none_or(|(lo, hi)| (lo..=hi).contains(&value));
            if !(value.is_finite() && inside) {
                return Err(format!(
                    "frame {frame}: {} = {value} (limits {:?})",
                    joint.name, joint.limits
                ));
            }
        }
        if let Some(report) = driver.ik_report()
            && report.restored
        {
            return Err(format!(
                "frame {frame}: the solve went non-finite and was undone"
            ));
        }
        if let Some(p) = driver
            .targets()
            .and_then(|t| t.position.iter().find(|p| !p.is_finite()))
        {
            return Err(format!("frame {frame}: target {p}"));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(48))]

    /// The human and the IK quadruped, 2 s of any mode with any method.
    #[test]
    fn thesis_parameters_in_range_never_make_a_non_finite_pose(draw in thesis_draw()) {
        for name in THESIS_PRESETS {
            let outcome = run_thesis(&creature(name), &draw, 2.0);
            prop_assert_eq!(outcome, Ok(()), "{}", name);
        }
    }
}
