//! Key leg positions that carry centre angles and gains (Girard &
//! Maciejewski 1985, "Leg Support and Transfer Trajectories": "a key
//! position records the position of the foot … and the center angles and
//! gains that are associated with that position"; eq. 6).
//!
//! On a small trotting quadruped whose legs have four joints (hip flexion
//! and abduction, knee, ankle: a one-dimensional null space in the leg's
//! plane, with room in the joints' limits), the middle of the three default
//! keys gives every knee (the place form `"2"`) a centre far from its own
//! with gain 1; during the transfer the knee follows it — at the key's phase
//! well toward the key's centre, smoothly from frame to frame — while the
//! foot stays on its spline and planted feet stay put. On the bundled
//! `poda-quadruped` (the name form, front and hind knees bending opposite
//! ways) the knee moves the same way but less: its swinging leg works at
//! the shoulder's and wrist's limits. Without key centres the run is the same
//! to the bit; bad entries are refused naming the field.
//!
//! `cargo test -p gaitlab-motion --test key_centers -- --nocapture` prints
//! the figures docs/poda.md quotes.

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::poda::KeyCenters;
use gaitlab_core::preset::{Creature, PodaParams, bundled_json, load_bundled};
use gaitlab_motion::PodaDriver;
use serde_json::json;

const FPS: f64 = 60.0;
const SECONDS: f64 = 6.0;
/// The test quadruped's knee: its legs' third joint (hip x, hip z, knee, ankle).
const TEST_KNEE: usize = 2;
/// The test knee's own centre (its rest, gain 0.2) and the middle key's.
const TEST_KNEE_OWN: f64 = 0.6;
const TEST_KNEE_KEY: f64 = 0.1;
/// The bundled quadruped's knee: the fourth joint (shoulder or hip x, y, z, then the knee's x).
const KNEE: usize = 3;
/// The middle key's knee centres on the bundled quadruped: front knees
/// (elbow_x, limits [−2, 0], own centre −0.6) nearly straight at −0.2,
/// hind knees (knee_x, [0, 2], own 0.6) at 0.2.
const FRONT_KNEE_KEY: f64 = -0.2;
const HIND_KNEE_KEY: f64 = 0.2;

/// A trotting quadruped with four-joint legs: thigh and shank 0.3 m, foot
/// 0.15 m below the ankle, hips 0.55 m above the ground when standing; the
/// knees bend backward (limits [0, 2.4], rest and centre 0.6, gain 0.2), the
/// hips and ankles have room ([−1.5, 1.5], [−2.2, 2.2]; gain 0.1).
fn test_quadruped() -> Creature {
    let (mut joints, mut effectors, mut legs) = (Vec::new(), Vec::new(), Vec::new());
    for (name, x, z) in [
        ("left_front", 0.15, 0.3),
        ("right_front", -0.15, 0.3),
        ("left_hind", 0.15, -0.3),
        ("right_hind", -0.15, -0.3),
    ] {
        let joint = |part: &str| format!("{name}_{part}");
        joints.extend([
            json!({"name": joint("hip_x"), "parent": null, "axis": [1, 0, 0],
                   "offset": [x, -0.05, z], "limits": [-1.5, 1.5], "rest": -0.3, "gain": 0.1}),
            json!({"name": joint("hip_z"), "parent": joint("hip_x"), "axis": [0, 0, 1],
                   "offset": [0, 0, 0], "limits": [-0.4, 0.4], "rest": 0.0, "gain": 0.3}),
            json!({"name": joint("knee"), "parent": joint("hip_z"), "axis": [1, 0, 0],
                   "offset": [0, -0.3, 0], "limits": [0.0, 2.4], "rest": TEST_KNEE_OWN, "gain": 0.2}),
            json!({"name": joint("ankle"), "parent": joint("knee"), "axis": [1, 0, 0],
                   "offset": [0, -0.3, 0], "limits": [-2.2, 2.2], "rest": -0.3, "gain": 0.1}),
        ]);
        effectors
            .push(json!({"name": joint("foot"), "joint": joint("ankle"), "offset": [0, -0.15, 0]}));
        legs.push(json!({"name": name, "effector": joint("foot"), "hip": joint("hip_x")}));
    }
    let preset = json!({
        "format": "gaitlab-preset/1",
        "name": "key-centre-quadruped",
        "skeleton": {"root": {"position": [0, 0.7, 0]}, "joints": joints, "effectors": effectors},
        "scenario": {"engine": "poda", "fps": 60, "poda": {
            "legs": legs, "gait": "trot", "period_s": 0.6, "speed_mps": 0.8,
            "step_height_m": 0.08, "stand_height_m": 0.6, "body_mass_kg": 40.0}}
    });
    Creature::from_json(&preset.to_string()).expect("valid preset")
}

fn quadruped() -> Creature {
    load_bundled("poda-quadruped")
        .expect("bundled preset")
        .expect("valid preset")
}

fn object(entries: &[(&str, [f64; 2])]) -> KeyCenters {
    entries.iter().map(|(k, v)| ((*k).to_owned(), *v)).collect()
}

/// `creature`'s PODA parameters with the middle of its three default keys
/// carrying `middle`.
fn with_middle_key(creature: &Creature, middle: KeyCenters) -> PodaParams {
    let mut params = creature.scenario.poda_params();
    assert_eq!(params.transfer_keys.len(), 3, "the default three keys");
    params.transfer_key_centers = vec![object(&[]), middle, object(&[])];
    params
}

/// What one run measured of each leg's knee (the leg's joint at `knee`).
#[derive(Debug, Default)]
struct Figures {
    /// Per leg, the knee angle at the frames nearest the middle key's phase
    /// (transfer fraction ½), averaged over the transfers after the first
    /// period, radians.
    knee_at_key: Vec<f64>,
    /// Per leg, the knee angle nearest the key's centre between the middle
    /// key's neighbours (transfer fraction ¼ to ¾) over those transfers.
    knee_nearest: Vec<f64>,
    /// Per leg, the knee's own centre.
    own_center: Vec<f64>,
    /// Largest change of a knee angle from one frame to the next while its
    /// leg transfers (lift-off and touchdown frames included), radians.
    max_knee_step: f64,
    /// Largest change of that step from one frame to the next (the knee's
    /// second difference), radians.
    max_knee_step_change: f64,
    /// Largest distance of a transferring foot from its spline target after
    /// the frame's IK, metres.
    max_transfer_error_m: f64,
    /// Planted-foot slip, metres.
    slip_m: f64,
    /// Every frame's joint values and root position, for bit comparisons.
    poses: Vec<Vec<f64>>,
}

fn run(creature: &Creature, params: PodaParams, knee: usize, key: &[f64]) -> Figures {
    let mut driver = PodaDriver::with_params(creature, params).expect("driver");
    let knees: Vec<usize> = driver
        .leg_joints()
        .map(|(_, joints)| joints[knee])
        .collect();
    let effectors: Vec<usize> = creature
        .scenario
        .poda_params()
        .legs
        .iter()
        .map(|l| creature.skeleton.effector_index(&l.effector).expect("foot"))
        .collect();
    let n = knees.len();
    let mut figures = Figures {
        own_center: knees
            .iter()
            .map(|&j| creature.skeleton.joints()[j].center)
            .collect(),
        knee_nearest: vec![f64::NAN; n],
        ..Figures::default()
    };
    let (mut sum, mut count) = (vec![0.0; n], vec![0u32; n]);
    let dt = 1.0 / FPS;
    let half_frame = 0.5 * dt / driver.gait().transfer_s();
    let mut last: Vec<f64> = knees.iter().map(|&j| driver.pose().joints[j]).collect();
    let mut last_step = vec![f64::NAN; n];
    let mut was_transfer = vec![false; n];
    for _ in 0..(SECONDS * FPS).round() as usize {
        driver.step(dt);
        let t = driver.time();
        let pose = driver.pose();
        let mut snapshot = pose.joints.clone();
        snapshot.extend(pose.root.position.to_array());
        figures.poses.push(snapshot);
        let report = driver.ik_report().expect("report");
        for (i, &j) in knees.iter().enumerate() {
            let phase = driver.gait().leg_phase(i, t).expect("leg");
            let angle = pose.joints[j];
            let transfer = !phase.support;
            let step = angle - last[i];
            if transfer || was_transfer[i] {
                figures.max_knee_step = figures.max_knee_step.max(step.abs());
                if last_step[i].is_finite() {
                    figures.max_knee_step_change = figures
                        .max_knee_step_change
                        .max((step - last_step[i]).abs());
                }
            }
            last_step[i] = if transfer { step } else { f64::NAN };
            if transfer {
                figures.max_transfer_error_m = figures
                    .max_transfer_error_m
                    .max(report.effector_error_m[effectors[i]]);
                if t > driver.gait().period_s() {
                    if (phase.fraction - 0.5).abs() <= half_frame {
                        sum[i] += angle;
                        count[i] += 1;
                    }
                    // Between the middle key's neighbours (u in [¼, ¾]).
                    let nearest = figures.knee_nearest[i];
                    if (0.25..=0.75).contains(&phase.fraction)
                        && (nearest.is_nan() || (angle - key[i]).abs() < (nearest - key[i]).abs())
                    {
                        figures.knee_nearest[i] = angle;
                    }
                }
            }
            last[i] = angle;
            was_transfer[i] = transfer;
        }
    }
    figures.knee_at_key = sum
        .iter()
        .zip(&count)
        .map(|(s, &c)| {
            assert!(c > 0, "a frame at the key's phase");
            s / f64::from(c)
        })
        .collect();
    figures.slip_m = driver.metrics().foot_slip_max_m();
    figures
}

/// Prints the figures of a run without and with key centres.
fn print(label: &str, plain: &Figures, keyed: &Figures, key: &[f64]) {
    println!("{label}");
    println!(
        "  leg: own centre | knee at the middle key's phase without → with key centres \
         (key's centre) | nearest the key's centre, fraction ¼ to ¾, without → with, rad"
    );
    for (i, key) in key.iter().enumerate() {
        println!(
            "  {i}: {:+.3} | {:+.3} → {:+.3} ({key:+.2}) | {:+.3} → {:+.3}",
            plain.own_center[i],
            plain.knee_at_key[i],
            keyed.knee_at_key[i],
            plain.knee_nearest[i],
            keyed.knee_nearest[i]
        );
    }
    println!(
        "  largest knee change a frame in transfer: {:.4} rad without, {:.4} rad with; \
         largest change of it: {:.4} / {:.4} rad",
        plain.max_knee_step,
        keyed.max_knee_step,
        plain.max_knee_step_change,
        keyed.max_knee_step_change
    );
    println!(
        "  largest transferring-foot error: {:.2e} m without, {:.2e} m with; \
         planted-foot slip {:.4} / {:.4} mm",
        plain.max_transfer_error_m,
        keyed.max_transfer_error_m,
        1e3 * plain.slip_m,
        1e3 * keyed.slip_m
    );
}

/// How far the knee moved toward the key's centre at the key's phase, radians.
fn toward(plain: &Figures, keyed: &Figures, key: &[f64], i: usize) -> f64 {
    let without = plain.knee_at_key[i];
    (keyed.knee_at_key[i] - without) * (key[i] - without).signum()
}

#[test]
fn the_knee_follows_the_key_centres_through_the_transfer() {
    let creature = test_quadruped();
    let key = [TEST_KNEE_KEY; 4];
    let plain = run(&creature, creature.scenario.poda_params(), TEST_KNEE, &key);
    // The place form: the third joint of every leg.
    let params = with_middle_key(&creature, object(&[("2", [TEST_KNEE_KEY, 1.0])]));
    let keyed = run(&creature, params, TEST_KNEE, &key);
    print(
        "test quadruped, key \"2\": [0.1, 1.0]",
        &plain,
        &keyed,
        &key,
    );
    for i in 0..4 {
        assert_eq!(plain.own_center[i], TEST_KNEE_OWN);
        // Toward the key's centre by a clear margin: at least 0.3 rad and a
        // third of the way from where the knee goes without key centres.
        let moved = toward(&plain, &keyed, &key, i);
        let gap = (key[i] - plain.knee_at_key[i]).abs();
        assert!(
            moved > 0.3 && moved > gap / 3.0,
            "leg {i}: knee {:.3} → {:.3} rad, key centre {}",
            plain.knee_at_key[i],
            keyed.knee_at_key[i],
            key[i]
        );
    }
    // Smooth: no frame's change of the knee in transfer beyond 0.25 rad (the
    // IK's largest step of one iteration), and its change from one frame to
    // the next at most 0.15 rad (the key's centre sweeps 0.5 rad in a
    // quarter of an 18-frame transfer).
    assert!(keyed.max_knee_step < 0.25, "{}", keyed.max_knee_step);
    assert!(
        keyed.max_knee_step_change < 0.15,
        "{}",
        keyed.max_knee_step_change
    );
    // The foot still follows its spline within the solve's tolerance (1 µm),
    // and planted feet stay put.
    let tolerance = creature.scenario.poda_params().tolerance_m;
    assert!(
        keyed.max_transfer_error_m <= tolerance,
        "foot {} m off its spline",
        keyed.max_transfer_error_m
    );
    assert!(keyed.slip_m <= 1e-3, "planted feet slip {} m", keyed.slip_m);
}

#[test]
fn on_the_bundled_quadruped_the_knee_moves_toward_the_key_within_its_legs_limits() {
    let mut creature = quadruped();
    // Positions alone, both ways: a leg with key centres lets its foot's
    // orientation go in the transfer (docs/poda.md, "The foot's
    // orientation"), and one without holds it, which is a different swing
    // to compare the foot's path against.
    if let Some(poda) = creature.scenario.poda.as_mut() {
        poda.foot_orientation = false;
    }
    let key = [FRONT_KNEE_KEY, FRONT_KNEE_KEY, HIND_KNEE_KEY, HIND_KNEE_KEY];
    let plain = run(&creature, creature.scenario.poda_params(), KNEE, &key);
    // The name form: front and hind knees bend opposite ways.
    let params = with_middle_key(
        &creature,
        object(&[
            ("left_front_elbow_x", [FRONT_KNEE_KEY, 1.0]),
            ("right_front_elbow_x", [FRONT_KNEE_KEY, 1.0]),
            ("left_hind_knee_x", [HIND_KNEE_KEY, 1.0]),
            ("right_hind_knee_x", [HIND_KNEE_KEY, 1.0]),
        ]),
    );
    let keyed = run(&creature, params, KNEE, &key);
    print("poda-quadruped, knees by name", &plain, &keyed, &key);
    for i in 0..4 {
        let moved = toward(&plain, &keyed, &key, i);
        assert!(moved > 0.1, "leg {i}: moved {moved:.3} rad toward the key");
    }
    assert!(keyed.max_knee_step < 0.25, "{}", keyed.max_knee_step);
    // The swinging leg reaches its joints' limits with or without key
    // centres; the foot strays from its spline no more than without.
    assert!(
        keyed.max_transfer_error_m <= plain.max_transfer_error_m + 1e-4,
        "{} m against {} m",
        keyed.max_transfer_error_m,
        plain.max_transfer_error_m
    );
    assert!(keyed.slip_m <= 1e-3, "planted feet slip {} m", keyed.slip_m);
}

#[test]
fn without_key_centres_the_run_is_the_same_to_the_bit() {
    let creature = quadruped();
    let key = [0.0; 4];
    let plain = run(&creature, creature.scenario.poda_params(), KNEE, &key);
    // Key positions that name no joint: every joint its own, as without.
    let mut empty = creature.scenario.poda_params();
    empty.transfer_key_centers = vec![KeyCenters::new(); 3];
    let same = run(&creature, empty, KNEE, &key);
    assert_eq!(plain.poses.len(), same.poses.len());
    for (frame, (a, b)) in plain.poses.iter().zip(&same.poses).enumerate() {
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(a), bits(b), "frame {frame}");
    }
    // And the preset as written carries none.
    assert!(
        creature
            .scenario
            .poda_params()
            .transfer_key_centers
            .is_empty()
    );
}

#[test]
fn bad_key_centres_are_refused_naming_the_field() {
    let creature = quadruped();
    let field = "scenario.poda.transfer_key_centers";
    let cases: Vec<(Vec<KeyCenters>, String, &str)> = vec![
        (
            vec![object(&[]), object(&[])],
            field.to_owned(),
            "one object per key position (3 transfer_keys, 2 objects)",
        ),
        (
            vec![
                object(&[]),
                object(&[("left_front_kneee", [0.0, 0.5])]),
                object(&[]),
            ],
            format!("{field}[1].left_front_kneee"),
            "no joint called",
        ),
        (
            vec![
                object(&[]),
                object(&[("spine_03", [0.0, 0.5])]),
                object(&[]),
            ],
            format!("{field}[1].spine_03"),
            "belongs to no leg",
        ),
        (
            vec![object(&[("9", [0.0, 0.5])]), object(&[]), object(&[])],
            format!("{field}[0].9"),
            "no joint at place 9",
        ),
        (
            vec![object(&[]), object(&[]), object(&[("3", [-1.0, 1.5])])],
            format!("{field}[2].3"),
            "gain 1.5 must be between 0 and 1",
        ),
        (
            vec![object(&[]), object(&[("3", [-1.0, -0.1])]), object(&[])],
            format!("{field}[1].3"),
            "between 0 and 1",
        ),
        (
            // A place names the knee of every leg: −1 is outside the hind
            // knees' limits.
            vec![object(&[]), object(&[("3", [-1.0, 1.0])]), object(&[])],
            format!("{field}[1].3"),
            "outside \"left_hind_knee_x\"'s limits [0, 2]",
        ),
        (
            vec![object(&[]), object(&[("3", [f64::NAN, 1.0])]), object(&[])],
            format!("{field}[1].3"),
            "finite",
        ),
    ];
    for (centers, path, words) in cases {
        let mut params = creature.scenario.poda_params();
        params.transfer_key_centers = centers;
        // The preset check (no skeleton needed) where it can, else the driver.
        let error = match params.check_values("scenario.poda") {
            Err(e) => (e.path, e.reason),
            Ok(()) => {
                let e = PodaDriver::with_params(&creature, params).expect_err("refused");
                (e.path, e.reason)
            }
        };
        assert_eq!(error.0, path, "{}", error.1);
        assert!(error.1.contains(words), "{path}: {}", error.1);
    }
    // A preset file is refused when it loads, for what needs no skeleton.
    let mut json: serde_json::Value =
        serde_json::from_str(bundled_json("poda-quadruped").expect("json")).expect("json");
    json["scenario"]["poda"]["transfer_key_centers"] = json!([{}, {"3": [-1.0, 1.5]}, {}]);
    let error = Creature::from_json(&json.to_string()).expect_err("gain 1.5");
    assert_eq!(
        error.to_string(),
        "scenario.poda.transfer_key_centers[1].3: the gain 1.5 must be between 0 and 1"
    );
}

#[test]
fn a_preset_writes_them_as_json_and_the_driver_edits_them_live() {
    // The place form for every leg at once, a name over it for one leg.
    let json = r#"{"transfer_key_centers": [{}, {"3": [1.4, 1.0],
        "left_front_elbow_x": [-1.4, 1.0], "right_front_elbow_x": [-1.4, 1.0]}, {}]}"#;
    let parsed: PodaParams = serde_json::from_str(json).expect("parses");
    assert_eq!(parsed.transfer_key_centers[1].len(), 3);
    parsed.check_values("scenario.poda").expect("valid values");
    let creature = quadruped();
    let mut params = creature.scenario.poda_params();
    params.transfer_key_centers = parsed.transfer_key_centers.clone();
    let mut driver = PodaDriver::with_params(&creature, params).expect("driver");
    // Legs in support pull toward their own centres.
    for _ in 0..120 {
        driver.step(1.0 / FPS);
        for (i, (_, support)) in driver.foot_targets().enumerate() {
            let [center, gain] = driver.leg_center(i, KNEE).expect("knee");
            if support {
                let own = creature.skeleton.joints()
                    [driver.leg_joints().nth(i).expect("leg").1[KNEE]]
                    .center;
                assert_eq!(center, own, "leg {i} in support");
            }
            assert!((0.0..=1.0).contains(&gain));
        }
    }
    // A count of keys that leaves centres behind is refused; none, then any.
    let error = driver
        .set_transfer_keys(&[[0.5, 1.0]])
        .expect_err("centres on three keys");
    assert_eq!(error.path, "transfer_keys");
    let error = driver
        .set_transfer_key_centers(&[object(&[("3", [1.4, 2.0])]), object(&[]), object(&[])])
        .expect_err("gain 2");
    assert_eq!(error.path, "transfer_key_centers[0].3");
    driver.set_transfer_key_centers(&[]).expect("none");
    driver.set_transfer_keys(&[[0.5, 1.0]]).expect("one key");
    driver
        .set_transfer_key_centers(&[object(&[("left_hind_knee_x", [1.2, 0.8])])])
        .expect("one object for one key");
    // The serialised parameters carry them; without, the field is left out.
    let text = serde_json::to_string(driver.params()).expect("json");
    assert!(
        text.contains(r#""transfer_key_centers":[{"left_hind_knee_x":[1.2,0.8]}]"#),
        "{text}"
    );
    let plain = serde_json::to_string(&creature.scenario.poda_params()).expect("json");
    assert!(!plain.contains("transfer_key_centers"));
}
