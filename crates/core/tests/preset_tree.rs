//! Building the joint tree from a preset: joints in any order are sorted parents
//! first (She 2006 §3.1's tree), and PODA Denavit–Hartenberg limbs give exactly
//! the same kinematics as the same limb written joint by joint.

use gaitlab_core::portable::Portable;
use std::f64::consts::FRAC_PI_2;

use gaitlab_core::preset::{self, Creature, Preset};
use gaitlab_core::{JointKind, Kinematics, Pose, RootTransform};
use glam::{DMat3, DVec3};
use serde_json::{Value, json};

fn human_value() -> Value {
    serde_json::from_str(preset::bundled_json("human").expect("bundled")).expect("JSON")
}

fn build(value: &Value) -> Creature {
    Creature::from_json(&value.to_string()).unwrap_or_else(|e| panic!("{e}"))
}

#[track_caller]
fn assert_rejected(value: &Value, path: &str, reason: &str) {
    let error = Preset::from_json(&value.to_string()).expect_err("must be rejected");
    assert_eq!(error.path, path, "{error}");
    assert!(
        error.reason.contains(reason),
        "`{error}` should contain {reason:?}"
    );
}

/// A deterministic pseudo-random value in [-1, 1).
fn noise(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    ((*state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

fn pose_for(creature: &Creature, values: Vec<f64>) -> Pose {
    Pose {
        root: RootTransform {
            position: creature.root_position,
            rotation: DMat3::from_rotation_y(0.3),
        },
        joints: values,
    }
}

#[test]
fn joints_in_any_order_are_sorted_parents_first_with_the_same_kinematics() {
    let ordered = human_value();
    let mut reversed = ordered.clone();
    reversed["skeleton"]["joints"]
        .as_array_mut()
        .expect("array")
        .reverse();
    let a = build(&ordered);
    let b = build(&reversed);
    // A file already in order keeps its order.
    let file_order: Vec<&str> = ordered["skeleton"]["joints"]
        .as_array()
        .expect("array")
        .iter()
        .map(|j| j["name"].as_str().expect("name"))
        .collect();
    let built: Vec<&str> = a
        .skeleton
        .joints()
        .iter()
        .map(|j| j.name.as_str())
        .collect();
    assert_eq!(built, file_order);
    // The reversed file builds parents first.
    for (i, joint) in b.skeleton.joints().iter().enumerate() {
        if let Some(p) = joint.parent {
            assert!(p < i, "{} after its parent", joint.name);
        }
    }
    // Same figure: the same joint values by name give the same effector positions.
    let mut state = 7;
    for _ in 0..5 {
        let values_a: Vec<f64> = (0..20).map(|_| noise(&mut state)).collect();
        let values_b: Vec<f64> = b
            .skeleton
            .joints()
            .iter()
            .map(|j| values_a[a.skeleton.joint_index(&j.name).expect("same names")])
            .collect();
        let fk_a = Kinematics::of(&a.skeleton, &pose_for(&a, values_a));
        let fk_b = Kinematics::of(&b.skeleton, &pose_for(&b, values_b));
        for (e, effector) in a.skeleton.effectors().iter().enumerate() {
            let other = b
                .skeleton
                .effector_index(&effector.name)
                .expect("same effectors");
            let gap = (fk_a.effector_position[e] - fk_b.effector_position[other]).length();
            assert!(gap < 1e-12, "{}: {gap}", effector.name);
        }
    }
}

#[test]
fn errors_in_a_shuffled_file_name_the_file_index() {
    let mut value = human_value();
    value["skeleton"]["joints"]
        .as_array_mut()
        .expect("array")
        .reverse();
    // left_knee is at file index 17 once reversed.
    value["skeleton"]["joints"][17]["limits"] = json!([1.0, 0.5]);
    assert_rejected(
        &value,
        "skeleton.joints[17].limits",
        "minimum 1 is greater than maximum 0.5",
    );
}

/// A torso joint and a three-row arm (revolute, revolute, prismatic) with twists,
/// hung from the torso with a rotated base.
const BASE_OFFSET: [f64; 3] = [0.1, 0.2, -0.05];
const BASE_ROTATION: [f64; 3] = [0.0, FRAC_PI_2, 0.3];
const ROWS: [(&str, &str, f64, f64, f64, f64); 3] = [
    // name, type, a, alpha, d, theta
    ("shoulder", "revolute", 0.3, FRAC_PI_2, 0.05, 0.2),
    ("elbow", "revolute", 0.25, 0.0, 0.0, -0.4),
    ("slide", "prismatic", 0.1, -FRAC_PI_2, 0.05, 0.3),
];

fn creature_with(skeleton: Value) -> Creature {
    build(&json!({
        "format": "gaitlab-preset/1",
        "name": "arm",
        "skeleton": skeleton,
        "scenario": {"engine": "ik"}
    }))
}

fn dh_arm() -> Creature {
    let rows: Vec<Value> = ROWS
        .iter()
        .map(|&(name, kind, a, alpha, d, theta)| {
            let limits = if kind == "prismatic" {
                json!([0.0, 0.2])
            } else {
                json!([-2.0, 2.0])
            };
            json!({"name": name, "type": kind, "a": a, "alpha": alpha, "d": d, "theta": theta,
                   "limits": limits, "gain": 0.2})
        })
        .collect();
    creature_with(json!({
        "root": {"position": [0, 1, 0]},
        "joints": [{"name": "torso", "axis": [0, 1, 0], "offset": [0, 0.3, 0]}],
        "limbs": [{"name": "arm", "parent": "torso", "base_offset": BASE_OFFSET,
                   "base_rotation": BASE_ROTATION, "joints": rows, "effector": "tip"}],
        "effectors": [{"name": "chest", "joint": "torso", "offset": [0, 0.2, 0.1]}]
    }))
}

/// The same arm written joint by joint: axis z, each joint placed by the previous
/// row's constant part `TransZ(d)·TransX(a)·RotX(α)` (revolute) or `RotZ(θ)·TransX(a)·RotX(α)`
/// (prismatic), the effector at the last row's constant translation.
fn joint_arm() -> Creature {
    let [r0, r1, r2] = ROWS;
    let tip = DVec3::new(r2.2 * r2.5.pcos(), r2.2 * r2.5.psin(), 0.0);
    creature_with(json!({
        "root": {"position": [0, 1, 0]},
        "joints": [
            {"name": "torso", "axis": [0, 1, 0], "offset": [0, 0.3, 0]},
            {"name": "shoulder", "parent": "torso", "axis": [0, 0, 1], "offset": BASE_OFFSET,
             "frame_rotation": BASE_ROTATION, "limits": [-2.0, 2.0], "rest": r0.5, "gain": 0.2},
            {"name": "elbow", "parent": "shoulder", "axis": [0, 0, 1], "offset": [r0.2, 0, r0.4],
             "frame_rotation": [r0.3, 0, 0], "limits": [-2.0, 2.0], "rest": r1.5, "gain": 0.2},
            {"name": "slide", "parent": "elbow", "type": "prismatic", "axis": [0, 0, 1],
             "offset": [r1.2, 0, r1.4], "frame_rotation": [r1.3, 0, 0], "limits": [0.0, 0.2],
             "rest": r2.4, "gain": 0.2}
        ],
        "effectors": [{"name": "chest", "joint": "torso", "offset": [0, 0.2, 0.1]},
                      {"name": "tip", "joint": "slide", "offset": [tip.x, tip.y, tip.z]}]
    }))
}

#[test]
fn a_dh_limb_equals_the_same_limb_written_as_joints() {
    let dh = dh_arm();
    let joints = joint_arm();
    assert_eq!(dh.skeleton.joint_count(), 4);
    let names = |c: &Creature| {
        c.skeleton
            .joints()
            .iter()
            .map(|j| j.name.clone())
            .collect::<Vec<_>>()
    };
    assert_eq!(names(&dh), names(&joints));
    let effectors = |c: &Creature| {
        c.skeleton
            .effectors()
            .iter()
            .map(|e| e.name.clone())
            .collect::<Vec<_>>()
    };
    assert_eq!(
        effectors(&dh),
        ["chest", "tip"],
        "listed effectors first, then limb effectors"
    );
    assert_eq!(effectors(&dh), effectors(&joints));
    assert_eq!(dh.skeleton.joints()[3].kind, JointKind::Prismatic);
    assert_eq!(dh.skeleton.rest_values(), joints.skeleton.rest_values());
    assert_eq!(
        dh.skeleton.joints()[1].center,
        0.2,
        "center defaults to the rest θ"
    );
    assert_eq!(
        dh.skeleton.joints()[3].center,
        0.05,
        "prismatic center defaults to the rest d"
    );
    let mut state = 11;
    for trial in 0..20 {
        let values: Vec<f64> = if trial == 0 {
            dh.skeleton.rest_values()
        } else {
            (0..4).map(|_| noise(&mut state) * 1.5).collect()
        };
        let a = Kinematics::of(&dh.skeleton, &pose_for(&dh, values.clone()));
        let b = Kinematics::of(&joints.skeleton, &pose_for(&joints, values));
        for j in 0..4 {
            assert!(
                (a.joint_position[j] - b.joint_position[j]).length() < 1e-12,
                "joint {j}"
            );
            assert!(
                (a.joint_axis[j] - b.joint_axis[j]).length() < 1e-12,
                "axis {j}"
            );
        }
        for e in 0..2 {
            let gap = (a.effector_position[e] - b.effector_position[e]).length();
            assert!(gap < 1e-12, "effector {e}: {gap}");
        }
    }
}

#[test]
fn joints_and_limbs_may_hang_from_each_other_in_any_file_order() {
    // The hand is listed first but hangs from the limb's last row; the limb hangs
    // from a joint listed after it.
    let creature = creature_with(json!({
        "root": {"position": [0, 0, 0]},
        "joints": [
            {"name": "hand", "parent": "fl_ankle", "axis": [1, 0, 0], "offset": [0, 0, 0]},
            {"name": "body", "axis": [0, 1, 0], "offset": [0, 0.5, 0]}
        ],
        "limbs": [{"name": "front_left", "parent": "body",
                   "joints": [{"name": "fl_hip", "a": 0.3}, {"name": "fl_ankle", "a": 0.3}],
                   "effector": "paw"}],
        "effectors": [{"name": "finger", "joint": "hand", "offset": [0, 0, 0.05]}]
    }));
    let order: Vec<&str> = creature
        .skeleton
        .joints()
        .iter()
        .map(|j| j.name.as_str())
        .collect();
    assert_eq!(order, ["body", "fl_hip", "fl_ankle", "hand"]);
    let finger = creature.skeleton.effector_index("finger").expect("finger");
    assert_eq!(creature.skeleton.chain(finger), [0, 1, 2, 3]);
    let state = Kinematics::of(&creature.skeleton, &creature.rest_pose());
    let paw = state.effector_position[creature.skeleton.effector_index("paw").expect("paw")];
    assert!(
        (paw - DVec3::new(0.6, 0.5, 0.0)).length() < 1e-12,
        "two 0.3 m links along x: {paw}"
    );
}

#[test]
fn limb_errors_name_the_limb_path() {
    let arm = |limb: Value| {
        json!({
            "format": "gaitlab-preset/1", "name": "arm",
            "skeleton": {"root": {"position": [0, 1, 0]},
                         "joints": [{"name": "torso", "axis": [0, 1, 0], "offset": [0, 0, 0]}],
                         "limbs": [limb],
                         "effectors": [{"name": "chest", "joint": "torso"}]},
            "scenario": {"engine": "ik"}
        })
    };
    assert_rejected(
        &arm(json!({"name": "a", "joints": []})),
        "skeleton.limbs[0].joints",
        "at least one joint",
    );
    assert_rejected(
        &arm(
            json!({"name": "a", "joints": [{"name": "x", "a": 0.1}, {"name": "y", "limits": [1, -1]}]}),
        ),
        "skeleton.limbs[0].joints[1].limits",
        "minimum 1 is greater than maximum -1",
    );
    assert_rejected(
        &arm(
            json!({"name": "a", "joints": [{"name": "x", "type": "prismatic", "d": 0.5, "limits": [0, 0.2]}]}),
        ),
        "skeleton.limbs[0].joints[0].d",
        "0.5 is outside the limits [0, 0.2]",
    );
    assert_rejected(
        &arm(json!({"name": "a", "joints": [{"name": "x", "theta": 2, "limits": [-1, 1]}]})),
        "skeleton.limbs[0].joints[0].theta",
        "outside the limits",
    );
    assert_rejected(
        &arm(json!({"name": "a", "joints": [{"name": "x", "alpha": 90}]})),
        "skeleton.limbs[0].joints[0].alpha",
        "radians",
    );
    assert_rejected(
        &arm(json!({"name": "a", "parent": "neck", "joints": [{"name": "x"}]})),
        "skeleton.limbs[0].parent",
        r#"no joint named "neck""#,
    );
    assert_rejected(
        &arm(json!({"name": "a", "parent": "x", "joints": [{"name": "x"}]})),
        "skeleton.limbs[0].parent",
        r#"limb "a" is its own parent"#,
    );
    assert_rejected(
        &arm(json!({"name": "a", "joints": [{"name": "torso"}]})),
        "skeleton.limbs[0].joints[0].name",
        r#"duplicate joint name "torso" (first at skeleton.joints[0].name)"#,
    );
    assert_rejected(
        &arm(json!({"name": "a", "joints": [{"name": "x"}], "effector": "chest"})),
        "skeleton.limbs[0].effector",
        r#"duplicate effector name "chest" (first at skeleton.effectors[0].name)"#,
    );
    assert_rejected(
        &arm(json!({"name": "a", "joints": [{"name": "x", "length": 1}]})),
        "skeleton.limbs[0].joints[0].length",
        "unknown field `length`",
    );
    // A cycle through a limb and a joint.
    let mut cyclic = arm(json!({"name": "a", "parent": "torso", "joints": [{"name": "x"}]}));
    cyclic["skeleton"]["joints"][0]["parent"] = json!("x");
    assert_rejected(
        &cyclic,
        "skeleton.joints[0].parent",
        r#"parents form a cycle: "torso" → limb "a" → "torso""#,
    );
}
