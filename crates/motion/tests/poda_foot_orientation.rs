//! The foot's orientation, eq. 2's last three components (Girard &
//! Maciejewski 1985 eq. 2; `scenario.poda.foot_orientation`): the bundled
//! quadruped's 9-joint legs hold their planted feet level and still, as
//! measured from the motion, where position alone lets them turn; where the
//! joints' limits refuse a level foot (the bound's crouch) the feet stay
//! planted and tilt no farther than position alone tilts them, and a leg
//! whose foot was refused holds its position alone for 1, 2, 4, then 8
//! supports before it tries again (a foot held level snaps to the tilt its
//! limits force, in a few of its supports only); a leg with fewer than six
//! joints holds its position alone and runs exactly as with the flag off;
//! and the six-row solve reaches a position and an orientation on a chain
//! of exactly six joints.

use gaitlab_core::driver::Driver;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::{Creature, load_bundled};
use gaitlab_core::{Effector, Joint, Kinematics, Pose, RootTransform, Skeleton};
use gaitlab_motion::PodaDriver;
use gaitlab_motion::poda::foot_orientation::{
    angle_between_rad, heading_rad, orientation_error_rad, yaw_rotation,
};
use gaitlab_motion::poda::{LegIk, LegIkOptions};
use glam::{DQuat, DVec3};

const FPS: f64 = 60.0;
const SECONDS: f64 = 10.0;
/// The most a planted foot may turn in support where it is held, degrees.
const HELD_DEG: f64 = 0.5;
/// The most a planted foot may slip, metres.
const SLIP_M: f64 = 1e-3;
/// A planted foot that turns more than this in one frame snaps, degrees
/// (position alone turns the bound's feet at most 11.7° a frame).
const SNAP_DEG: f64 = 15.0;

fn bundled(name: &str) -> Creature {
    match load_bundled(name) {
        Some(Ok(creature)) => creature,
        other => panic!("{name}: {other:?}"),
    }
}

/// What a run of 10 s measured.
struct Run {
    /// Largest turn of a planted foot in support, degrees (the driver's metric).
    turn_deg: f64,
    /// Largest slip of a planted foot, metres (the driver's metric).
    slip_m: f64,
    /// Whether every frame's joints were within their limits.
    within_limits: bool,
    /// The legs that hold their foot's orientation.
    legs: Vec<String>,
    /// Largest angle of a foot at touchdown from its rest orientation carried
    /// by the body's ground yaw (level, facing the heading), degrees.
    landing_deg: f64,
    /// Share of the support frames whose foot is within [`HELD_DEG`] of the
    /// orientation it had at the support's first frame.
    held_share: f64,
    /// Largest elevation of a planted foot's forward axis, up or down, degrees.
    pitch_max_deg: f64,
    /// Largest turn of a planted foot in one frame, degrees.
    frame_turn_max_deg: f64,
    /// Per leg, its supports and those in which its foot snapped.
    supports: Vec<(usize, usize)>,
    /// Root and joints of every frame, bit for bit.
    bits: Vec<u64>,
}

fn run(creature: &Creature, gait: &str, foot_orientation: bool) -> Run {
    let mut params = creature.scenario.poda_params();
    params.gait = Some(gait.to_owned());
    params.foot_orientation = foot_orientation;
    let mut driver = PodaDriver::with_params(creature, params).expect("driver");
    let skeleton = creature.skeleton.clone();
    let rest = creature.rest_pose();
    let rest_kin = Kinematics::of(&skeleton, &rest);
    let rest_yaw = yaw_rotation(heading_rad(rest.root.rotation));
    let feet: Vec<usize> = creature
        .scenario
        .poda_params()
        .legs
        .iter()
        .map(|leg| skeleton.effector_index(&leg.effector).expect("foot"))
        .collect();
    let level: Vec<DQuat> = feet
        .iter()
        .map(|&e| rest_yaw.conjugate() * DQuat::from_mat3(&rest_kin.effector_rotation[e]))
        .collect();
    let mut origin: Vec<Option<DQuat>> = vec![None; feet.len()];
    let mut last: Vec<Option<DQuat>> = vec![None; feet.len()];
    let mut frame_turn_max_deg = 0.0_f64;
    let mut support_counts = vec![(0, 0); feet.len()];
    let mut snapped = vec![false; feet.len()];
    let (mut landing_deg, mut pitch_max_deg) = (0.0_f64, 0.0_f64);
    let (mut held, mut support_frames) = (0_usize, 0_usize);
    let mut within_limits = true;
    let mut bits = Vec::new();
    for _ in 0..(SECONDS * FPS) as usize {
        driver.step(1.0 / FPS);
        let pose = driver.pose();
        within_limits &= pose.joints.iter().zip(skeleton.joints()).all(|(v, joint)| {
            v.is_finite() && joint.limits.is_none_or(|(lo, hi)| *v >= lo && *v <= hi)
        });
        bits.extend(pose.root.position.to_array().map(f64::to_bits));
        bits.extend(pose.joints.iter().map(|v| v.to_bits()));
        let kin = Kinematics::of(&skeleton, pose);
        let yaw = yaw_rotation(driver.ground_pose(driver.time()).yaw_rad);
        let supports: Vec<bool> = driver.foot_targets().map(|(_, s)| s).collect();
        for (i, (&foot, &support)) in feet.iter().zip(&supports).enumerate() {
            let rotation = DQuat::from_mat3(&kin.effector_rotation[foot]);
            let before = last[i].replace(rotation);
            if !support {
                origin[i] = None;
                continue;
            }
            if origin[i].is_none() {
                support_counts[i].0 += 1;
                snapped[i] = false;
            }
            if let (Some(before), Some(_)) = (before, origin[i]) {
                let turn_deg = angle_between_rad(before, rotation).to_degrees();
                frame_turn_max_deg = frame_turn_max_deg.max(turn_deg);
                if turn_deg > SNAP_DEG && !snapped[i] {
                    snapped[i] = true;
                    support_counts[i].1 += 1;
                }
            }
            if origin[i].is_none() {
                origin[i] = Some(rotation);
                landing_deg =
                    landing_deg.max(angle_between_rad(yaw * level[i], rotation).to_degrees());
            }
            let start = origin[i].unwrap_or(rotation);
            support_frames += 1;
            if angle_between_rad(start, rotation).to_degrees() < HELD_DEG {
                held += 1;
            }
            let forward = kin.effector_rotation[foot] * DVec3::Z;
            pitch_max_deg =
                pitch_max_deg.max(forward.y.clamp(-1.0, 1.0).pasin().abs().to_degrees());
        }
    }
    let metrics = driver.metrics();
    #[expect(clippy::cast_precision_loss, reason = "frame counts are small")]
    let held_share = held as f64 / support_frames.max(1) as f64;
    Run {
        turn_deg: metrics.foot_turn_max_rad().to_degrees(),
        slip_m: metrics.foot_slip_max_m(),
        within_limits,
        legs: metrics.orientation_legs().map(str::to_owned).collect(),
        landing_deg,
        held_share,
        pitch_max_deg,
        frame_turn_max_deg,
        supports: support_counts,
        bits,
    }
}

fn report(label: &str, run: &Run) {
    println!(
        "{label}: turn in support {:.3}°, slip {:.4} mm, landing {:.3}° from level, \
         {:.0} % of support frames held within {HELD_DEG}°, foot pitch up to {:.1}°, \
         at most {:.2}° in a frame, (supports, snapped) per leg {:?}, legs {:?}",
        run.turn_deg,
        run.slip_m * 1e3,
        run.landing_deg,
        run.held_share * 100.0,
        run.pitch_max_deg,
        run.frame_turn_max_deg,
        run.supports,
        run.legs
    );
}

#[test]
fn the_trotting_quadruped_holds_its_planted_feet_level_and_still() {
    let creature = bundled("poda-quadruped");
    let on = run(&creature, "trot", true);
    let off = run(&creature, "trot", false);
    report("trot, foot_orientation on ", &on);
    report("trot, foot_orientation off", &off);
    assert_eq!(
        on.legs,
        ["left_front", "right_front", "left_hind", "right_hind"]
    );
    assert!(off.legs.is_empty());
    assert!(on.turn_deg < HELD_DEG, "turn {}°", on.turn_deg);
    assert!(on.landing_deg < HELD_DEG, "landing {}°", on.landing_deg);
    assert!(on.slip_m < SLIP_M, "slip {} m", on.slip_m);
    assert!(on.within_limits);
    // Position alone lets the planted feet turn with the legs.
    assert!(off.turn_deg > 10.0, "turn {}° without", off.turn_deg);
    assert!(off.within_limits && off.slip_m < SLIP_M);
}

#[test]
fn the_bounding_quadruped_keeps_its_feet_planted_and_lets_them_tilt_as_its_limits_force() {
    let creature = bundled("poda-quadruped");
    let on = run(&creature, "bound", true);
    let off = run(&creature, "bound", false);
    report("bound, foot_orientation on ", &on);
    report("bound, foot_orientation off", &off);
    assert!(on.slip_m < SLIP_M, "slip {} m", on.slip_m);
    assert!(on.within_limits);
    // At the bound's crouch (the body pitched ±16°) a level foot would need
    // a knee or an elbow past its 2 rad limit: the foot tilts there, no
    // farther than position alone tilts it.
    assert!(
        on.pitch_max_deg <= off.pitch_max_deg + HELD_DEG,
        "foot pitch {}° against {}° without",
        on.pitch_max_deg,
        off.pitch_max_deg
    );
    // A foot held level snaps to that tilt where its limits refuse it; then
    // its leg holds position alone for 1, 2, 4, 8 supports: in 10 s (17
    // supports a leg) it tries again in supports 3, 6 and 11 at most, and
    // snaps in at most 4 of them (it lands at the tilt it lifted off with
    // after a support alone, so a retry need not snap).
    assert!(
        off.frame_turn_max_deg < SNAP_DEG,
        "{}°",
        off.frame_turn_max_deg
    );
    for (leg, &(supports, snapped)) in on.supports.iter().enumerate() {
        assert!(supports >= 16, "leg {leg}: {supports} supports");
        assert!(
            snapped <= 4,
            "leg {leg}: snapped in {snapped} of {supports} supports"
        );
    }
}

#[test]
fn legs_of_three_joints_hold_position_alone_exactly_as_with_the_flag_off() {
    let creature = bundled("hexapod");
    let on = run(&creature, "tripod", true);
    let off = run(&creature, "tripod", false);
    report("hexapod, foot_orientation on", &on);
    assert!(on.legs.is_empty(), "{:?}", on.legs);
    assert!(on.bits == off.bits, "the same motion, bit for bit");
    assert_eq!(on.turn_deg.to_bits(), off.turn_deg.to_bits());
}

/// A leg of exactly six joints (hip yaw, pitch, roll; knee; ankle pitch and
/// roll) and a foot 0.1 m below the ankle.
fn six_joint_leg() -> Skeleton {
    let down = DVec3::new(0.0, -0.4, 0.0);
    let mut joints = vec![
        Joint::revolute("hip_y", None, DVec3::ZERO, DVec3::Y).with_limits(-1.0, 1.0),
        Joint::revolute("hip_x", Some(0), DVec3::ZERO, DVec3::X).with_limits(-1.5, 1.5),
        Joint::revolute("hip_z", Some(1), DVec3::ZERO, DVec3::Z).with_limits(-0.6, 0.6),
        Joint::revolute("knee", Some(2), down, DVec3::X).with_limits(0.0, 2.5),
        Joint::revolute("ankle_x", Some(3), down, DVec3::X).with_limits(-1.2, 1.2),
        Joint::revolute("ankle_z", Some(4), DVec3::ZERO, DVec3::Z).with_limits(-0.6, 0.6),
    ];
    joints[3].rest = 0.6;
    let effectors = vec![Effector {
        name: "foot".into(),
        joint: 5,
        offset: DVec3::new(0.0, -0.1, 0.0),
        orientation: true,
    }];
    Skeleton::new(joints, effectors).expect("valid leg")
}

#[test]
fn six_rows_bring_a_six_joint_chain_to_a_position_and_an_orientation() {
    let skeleton = six_joint_leg();
    let goal = Pose {
        root: RootTransform::default(),
        joints: vec![0.25, -0.35, 0.15, 0.9, -0.3, -0.2],
    };
    let reached = Kinematics::of(&skeleton, &goal);
    let target = reached.effector_position[0];
    let rotation = DQuat::from_mat3(&reached.effector_rotation[0]);
    let mut ik = LegIk::new((0..6).collect(), 0);
    let mut kin = Kinematics::new(&skeleton);
    let mut values = skeleton.rest_values();
    let exact = LegIkOptions {
        center_gain: 0.0,
        ..LegIkOptions::default()
    };
    for _ in 0..30 {
        kin.update(&skeleton, &RootTransform::default(), &values);
        ik.iterate_pose(&skeleton, &kin, &mut values, target, Some(rotation), &exact);
    }
    kin.update(&skeleton, &RootTransform::default(), &values);
    let miss_m = (kin.effector_position[0] - target).length();
    let turn_rad = orientation_error_rad(rotation, kin.effector_rotation[0]).length();
    println!("six joints: {miss_m:.2e} m, {turn_rad:.2e} rad from the target");
    assert!(
        miss_m < 1e-9 && turn_rad < 1e-9,
        "{miss_m} m, {turn_rad} rad"
    );
    // Six joints, six rows: the pose is the one the target was made from.
    for (got, want) in values.iter().zip(&goal.joints) {
        assert!((got - want).abs() < 1e-6, "{got} against {want}");
    }
}
