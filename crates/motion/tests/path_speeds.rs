//! A body path that carries a desired speed per control point (issue 41 item
//! 4; Girard & Maciejewski 1985, "Horizontal Control": "given the desired
//! body speed along different parts of the curve, PODA may calculate the
//! desired positions and velocities along it using a numerical arclength
//! calculation"). The lab's reading (docs/poda.md, "Speeds along the path"):
//! the desired speed is linear in arc length between the control points'
//! places on the curve; the body follows it within eq. 14's force bound; the
//! gait takes each speed on as a speed edit does (stroke kept, period
//! derived), so the planted feet stay.

use gaitlab_core::driver::Driver;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::{Creature, PathKindSpec, PathSpec, bundled_json, load_bundled};
use gaitlab_motion::PodaDriver;
use gaitlab_motion::poda::path::BodyPath;
use glam::DVec2;

const FPS: f64 = 60.0;

/// A ground position `(x, z)`, metres, after each frame, with its time.
type Frames = Vec<(f64, DVec2)>;

fn bundled(name: &str) -> Creature {
    load_bundled(name)
        .expect("bundled preset")
        .expect("valid preset")
}

/// The root's ground position `(x, z)`, metres, at the start.
fn start(creature: &Creature) -> DVec2 {
    let root = creature.rest_pose().root.position;
    DVec2::new(root.x, root.z)
}

/// A driver for `creature` on `path`.
fn driver(creature: &Creature, path: PathSpec) -> PodaDriver {
    let mut params = creature.scenario.poda_params();
    params.path = Some(path);
    PodaDriver::with_params(creature, params).expect("driver")
}

/// The root's ground position `(x, z)` after each frame of `seconds`.
fn run(driver: &mut PodaDriver, seconds: f64) -> Frames {
    run_both(driver, seconds).0
}

/// After each frame of `seconds`: the root's ground position `(x, z)`, and
/// the body's ground position as eq. 14–15 plan it (the root without its
/// fore-aft surge, which swings it a centimetre or so about that position
/// within each gait cycle).
fn run_both(driver: &mut PodaDriver, seconds: f64) -> (Frames, Frames) {
    let frames = (seconds * FPS).round() as usize;
    (0..frames)
        .map(|_| {
            driver.step(1.0 / FPS);
            let (t, root) = (driver.time(), driver.pose().root.position);
            (
                (t, DVec2::new(root.x, root.z)),
                (t, driver.ground_pose(t).position),
            )
        })
        .unzip()
}

/// When the root's place along `path` (its closest point's arc length) first
/// reaches `s_m`, seconds, interpolated between frames.
fn crossing_s(path: &BodyPath, frames: &[(f64, DVec2)], s_m: f64) -> f64 {
    let along: Vec<(f64, f64)> = frames
        .iter()
        .map(|&(t, p)| (t, path.closest_distance(p)))
        .collect();
    let k = along
        .iter()
        .position(|&(_, s)| s >= s_m)
        .expect("the body gets there");
    let ((t0, s0), (t1, s1)) = (along[k - 1], along[k]);
    t0 + (t1 - t0) * (s_m - s0) / (s1 - s0)
}

/// Per segment between control points: `(asked, measured)` mean speeds, m/s,
/// over the middle half of the segment (a quarter of its length in from each
/// control point, away from the ramps eq. 14 and the legs' cycles put at a
/// change of slope). Both are that stretch's length over a time: measured,
/// the time the root took from one end to the other; asked, the time the
/// interpolated speed asks for, `∫ ds / v(s)` (for a speed linear in arc
/// length `(v₂ − v₁) / ln(v₂ / v₁)`, the logarithmic mean of the stretch's end
/// speeds: the body spends longer where it is slow, so the arithmetic mean
/// would ask 4 % too much on a 0.3 → 0.6 m/s segment).
fn segment_speeds(path: &BodyPath, frames: &[(f64, DVec2)]) -> Vec<(f64, f64)> {
    let knots = path.knots_m();
    knots
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0] + 0.25 * (w[1] - w[0]), w[1] - 0.25 * (w[1] - w[0]));
            let speed = |s: f64| path.desired_speed_mps(s).expect("speeds");
            let (va, vb) = (speed(a), speed(b));
            let asked = if (vb - va).abs() < 1e-12 {
                va
            } else {
                (vb - va) / (vb / va).pln()
            };
            let measured = (b - a) / (crossing_s(path, frames, b) - crossing_s(path, frames, a));
            (asked, measured)
        })
        .collect()
}

/// The quadruped (trot, stroke 0.24 m) on a straight line of four points
/// 2.5 m apart at 0.3, 0.6, 0.4 and 0.4 m/s, and the hexapod (tripod, stroke
/// 0.08 m) on a gentle B-spline curve of three points at 0.1, 0.25 and
/// 0.15 m/s: each segment's mean speed within 5 % of what the interpolation
/// asks ([`segment_speeds`]), measured on the root and on the body's planned
/// ground motion (the root less its fore-aft surge, whose phase at the ends
/// of a stretch shifts the root's crossing times by up to a centimetre); no
/// planted foot slips more than 1 mm; the gait ends at the last speed with
/// its stroke kept (eq. 7–8: `P = stroke / (v·β)`).
#[test]
fn the_body_keeps_the_speeds_asked_between_control_points() {
    let quadruped = bundled("poda-quadruped");
    let o = start(&quadruped);
    let line = PathSpec {
        kind: PathKindSpec::CatmullRom,
        points: (0..4).map(|k| [o.x, o.y + 2.5 * f64::from(k)]).collect(),
        closed: false,
        speeds_mps: Some(vec![0.3, 0.6, 0.4, 0.4]),
    };
    let hexapod = bundled("hexapod");
    let o = start(&hexapod);
    let curve = PathSpec {
        kind: PathKindSpec::BSpline,
        points: vec![[o.x, o.y], [o.x + 0.4, o.y + 1.5], [o.x + 0.2, o.y + 3.0]],
        closed: false,
        speeds_mps: Some(vec![0.1, 0.25, 0.15]),
    };
    let mut report = Vec::new();
    for (label, creature, spec, seconds) in [
        ("poda-quadruped", &quadruped, line, 26.0),
        ("hexapod", &hexapod, curve, 24.0),
    ] {
        let path = BodyPath::try_from(&spec).expect("path");
        let mut driver = driver(creature, spec.clone());
        let stroke = driver.gait().stroke_m();
        let (root, ground) = run_both(&mut driver, seconds);
        let by_root = segment_speeds(&path, &root);
        let by_ground = segment_speeds(&path, &ground);
        for (i, ((asked, root), (_, ground))) in by_root.into_iter().zip(by_ground).enumerate() {
            let off = |measured: f64| 100.0 * (measured / asked - 1.0);
            report.push(format!(
                "{label} segment {i}: asked {asked:.4} m/s; root {root:.4} m/s ({:+.2} %), \
                 planned ground motion {ground:.4} m/s ({:+.2} %)",
                off(root),
                off(ground)
            ));
            for measured in [root, ground] {
                assert!(
                    off(measured).abs() < 5.0,
                    "{label} segment {i}: {measured} m/s, asked {asked} m/s"
                );
            }
        }
        let slip = driver.metrics().foot_slip_max_m();
        report.push(format!("{label}: slip {:.4} mm", slip * 1e3));
        assert!(slip <= 1e-3, "{label}: slip {} mm", slip * 1e3);
        let gait = driver.gait();
        let last = *spec.speeds_mps.as_ref().and_then(|v| v.last()).expect("v");
        assert_eq!(gait.speed_mps(), last, "{label}");
        assert!((gait.stroke_m() - stroke).abs() < 1e-12, "{label}");
        let period = stroke / (last * gait.duty_factor());
        assert!((gait.period_s() - period).abs() < 1e-9, "{label}");
    }
    println!("{}", report.join("\n"));
}

/// A path whose speeds are all `scenario.poda.speed_mps` moves the body
/// exactly as the same path without speeds: every frame's root position and
/// every foot within 1e-9 m (they are bit-identical).
#[test]
fn speeds_all_at_the_presets_speed_change_nothing() {
    for (name, seconds) in [("poda-quadruped", 8.0), ("hexapod", 6.0)] {
        let creature = bundled(name);
        let o = start(&creature);
        let speed = creature.scenario.poda_params().speed_mps;
        let plain = PathSpec {
            kind: PathKindSpec::CatmullRom,
            points: vec![[o.x, o.y], [o.x + 0.5, o.y + 2.0], [o.x, o.y + 4.0]],
            closed: false,
            speeds_mps: None,
        };
        let with_speeds = PathSpec {
            speeds_mps: Some(vec![speed; 3]),
            ..plain.clone()
        };
        let (mut a, mut b) = (driver(&creature, plain), driver(&creature, with_speeds));
        for _ in 0..(seconds * FPS).round() as usize {
            a.step(1.0 / FPS);
            b.step(1.0 / FPS);
            let gap = a.pose().root.position.distance(b.pose().root.position);
            assert!(gap <= 1e-9, "{name} at {} s: root {gap} m apart", a.time());
            for (p, q) in a.effector_positions().iter().zip(b.effector_positions()) {
                assert!(p.distance(*q) <= 1e-9, "{name} at {} s: foot", a.time());
            }
        }
        assert_eq!(a.gait().period_s(), b.gait().period_s(), "{name}");
    }
}

/// The path command with speeds, mid-run: the body and the gait take the new
/// path's speeds on from where the body joins it, the feet stay planted, and
/// a speed edit is refused while the path sets the speed.
#[test]
fn a_live_path_with_speeds_is_taken_on() {
    let creature = bundled("poda-quadruped");
    let mut driver = PodaDriver::new(&creature).expect("driver");
    run(&mut driver, 3.0);
    let here = driver.ground_pose(driver.time()).position;
    let spec = PathSpec {
        kind: PathKindSpec::CatmullRom,
        points: vec![
            [here.x, here.y],
            [here.x, here.y + 3.0],
            [here.x, here.y + 6.0],
        ],
        closed: false,
        speeds_mps: Some(vec![0.5, 0.5, 0.5]),
    };
    driver.set_path(&spec).expect("path with speeds");
    let path = BodyPath::try_from(&spec).expect("path");
    let frames = run(&mut driver, 8.0);
    assert_eq!(driver.gait().speed_mps(), 0.5);
    let (t0, t1) = (
        crossing_s(&path, &frames, 1.5),
        crossing_s(&path, &frames, 3.0),
    );
    let measured = 1.5 / (t1 - t0);
    assert!((measured - 0.5).abs() < 0.025, "{measured} m/s");
    let slip = driver.metrics().foot_slip_max_m();
    assert!(slip <= 1e-3, "slip {} mm", slip * 1e3);
    let refused = driver.set_speed(0.7).expect_err("the path sets the speed");
    assert_eq!(refused.path, "speed_mps");
    // A path without speeds: the body keeps the speed it has, and speed
    // edits are taken again.
    let plain = PathSpec {
        speeds_mps: None,
        ..spec
    };
    driver.set_path(&plain).expect("path");
    run(&mut driver, 1.0);
    assert_eq!(driver.gait().speed_mps(), 0.5);
    driver.set_speed(0.7).expect("speed edit");
}

/// Bad speeds are refused naming the field: in a preset, when the driver is
/// built, and by the path command.
#[test]
fn bad_speeds_name_the_field() {
    let creature = bundled("poda-quadruped");
    let three = |speeds: Vec<f64>| PathSpec {
        kind: PathKindSpec::CatmullRom,
        points: vec![[0.0, 0.0], [0.0, 1.0], [0.0, 2.0]],
        closed: false,
        speeds_mps: Some(speeds),
    };
    // The preset file.
    let preset = |path: &PathSpec| {
        let mut json: serde_json::Value =
            serde_json::from_str(bundled_json("poda-quadruped").expect("json")).expect("json");
        json["scenario"]["poda"]["path"] = serde_json::to_value(path).expect("path");
        Creature::from_json(&json.to_string())
            .map(|_| ())
            .expect_err("bad speeds")
            .to_string()
    };
    assert_eq!(
        preset(&three(vec![0.3, 0.6])),
        "scenario.poda.path.speeds_mps: needs one speed per point (3 points, 2 speeds)"
    );
    for bad in [0.0, -0.5, 25.0] {
        let message = preset(&three(vec![0.3, bad, 0.4]));
        assert!(
            message
                .starts_with("scenario.poda.path.speeds_mps[1]: must be between 0.01 and 20 m/s"),
            "{message}"
        );
    }
    // The driver (parameters that skipped the preset's checks).
    let built = |path: PathSpec| {
        let mut params = creature.scenario.poda_params();
        params.path = Some(path);
        PodaDriver::with_params(&creature, params)
            .map(|_| ())
            .expect_err("bad speeds")
    };
    assert_eq!(
        built(three(vec![0.3; 4])).to_string(),
        "scenario.poda.path.speeds_mps: needs one speed per point (3 points, 4 speeds)"
    );
    assert_eq!(
        built(three(vec![0.3, f64::NAN, 0.4])).path,
        "scenario.poda.path.speeds_mps[1]"
    );
    // In range, but at 0.015 m/s the trot's 0.24 m stroke needs a 32 s period.
    let slow = built(three(vec![0.3, 0.4, 0.015]));
    assert_eq!(slow.path, "scenario.poda.path.speeds_mps[2]", "{slow}");
    assert!(slow.reason.contains("period_s"), "{slow}");
    // The path command.
    let mut driver = PodaDriver::new(&creature).expect("driver");
    run(&mut driver, 0.5);
    let before = driver.path().to_spec();
    let live = driver
        .set_path(&three(vec![0.3, 21.0, 0.4]))
        .expect_err("bad");
    assert_eq!(live.path, "path.speeds_mps[1]");
    let live = driver.set_path(&three(vec![0.3])).expect_err("bad");
    assert_eq!(
        live.to_string(),
        "path.speeds_mps: needs one speed per point (3 points, 1 speeds)"
    );
    let live = driver
        .set_path(&three(vec![0.3, 0.3, 0.015]))
        .expect_err("bad");
    assert_eq!(live.path, "path.speeds_mps[2]");
    assert_eq!(driver.path().to_spec(), before, "nothing changes");
}
