//! The bundled presets: She 2006 §3.1's 20-joint human and the 63-joint IK
//! quadruped load, have the advertised shape, stand on the ground at rest, and
//! follow the documented sign conventions (y up, x to the figure's left, z forward).

use gaitlab_core::Kinematics;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{self, Creature, Engine, Preset};
use glam::DVec3;

fn human() -> Creature {
    preset::load_bundled("human")
        .expect("human is bundled")
        .expect("human.json is valid")
}

fn quadruped() -> Creature {
    preset::load_bundled("ik-quadruped")
        .expect("ik-quadruped is bundled")
        .expect("ik-quadruped.json is valid")
}

/// Effector positions of `creature` at rest with `changes` applied (joint name, value).
fn effectors_with(creature: &Creature, changes: &[(&str, f64)]) -> Vec<DVec3> {
    let mut pose = creature.rest_pose();
    for (name, value) in changes {
        let j = creature.skeleton.joint_index(name).expect("joint exists");
        pose.joints[j] = *value;
    }
    Kinematics::of(&creature.skeleton, &pose).effector_position
}

fn effector(creature: &Creature, positions: &[DVec3], name: &str) -> DVec3 {
    positions[creature
        .skeleton
        .effector_index(name)
        .expect("effector exists")]
}

#[test]
fn every_bundled_preset_builds_and_is_named_after_itself() {
    let names: Vec<&str> = preset::bundled_names().collect();
    assert_eq!(
        names,
        [
            "human",
            "she-2006",
            "ik-quadruped",
            "poda-quadruped",
            "poda-biped",
            "hexapod",
            "insect-14",
            "raibert-biped",
            "raibert-quadruped",
            "raibert-kangaroo"
        ]
    );
    assert_eq!(names[0], preset::DEFAULT_PRESET);
    for (name, json) in preset::bundled() {
        let creature = Creature::from_json(json).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(creature.name, *name);
        assert!(!creature.description.is_empty(), "{name} has a description");
        assert!(json.len() < preset::MAX_PRESET_BYTES);
    }
    assert!(preset::load_bundled("no-such-preset").is_none());
    assert!(preset::bundled_json("Human").is_none(), "names are exact");
}

#[test]
fn human_has_twenty_revolute_joints_and_four_effectors() {
    let human = human();
    let skeleton = &human.skeleton;
    assert_eq!(skeleton.joint_count(), 20);
    let effectors: Vec<&str> = skeleton
        .effectors()
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    assert_eq!(
        effectors,
        ["left_foot", "right_foot", "left_hand", "right_hand"]
    );
    for joint in skeleton.joints() {
        assert_eq!(
            joint.kind,
            gaitlab_core::JointKind::Revolute,
            "{}",
            joint.name
        );
        assert!((joint.axis.length() - 1.0).abs() < 1e-12);
        let (lo, hi) = joint
            .limits
            .unwrap_or_else(|| panic!("{} has limits", joint.name));
        assert!(lo < hi, "{}: limits ordered", joint.name);
        assert!(
            (lo..=hi).contains(&joint.rest),
            "{}: rest inside limits",
            joint.name
        );
        assert_eq!(
            joint.center, joint.rest,
            "{}: center is the rest angle",
            joint.name
        );
        assert!(
            (0.1..=0.5).contains(&joint.gain),
            "{}: modest gain",
            joint.name
        );
        assert!(joint.size > 0.0);
    }
    for side in ["left", "right"] {
        for part in [
            "hip_flex",
            "hip_abduct",
            "knee",
            "ankle",
            "shoulder_flex",
            "shoulder_abduct",
            "elbow",
            "wrist",
        ] {
            assert!(
                skeleton.joint_index(&format!("{side}_{part}")).is_some(),
                "{side}_{part}"
            );
        }
    }
    for name in ["lumbar_flex", "lumbar_bend", "thorax_twist", "neck"] {
        assert!(skeleton.joint_index(name).is_some(), "{name}");
    }
    // Knees and elbows rest slightly bent, in their flexion directions.
    for side in ["left", "right"] {
        let knee = &skeleton.joints()[skeleton.joint_index(&format!("{side}_knee")).expect("knee")];
        let elbow = &skeleton.joints()[skeleton
            .joint_index(&format!("{side}_elbow"))
            .expect("elbow")];
        assert!(
            knee.rest > 0.05 && knee.rest < 0.5,
            "{side} knee rest {}",
            knee.rest
        );
        assert!(
            elbow.rest < -0.05 && elbow.rest > -0.8,
            "{side} elbow rest {}",
            elbow.rest
        );
    }
}

#[test]
fn human_stands_on_the_ground_with_adult_proportions() {
    let human = human();
    assert!((human.root_position - DVec3::new(0.0, 0.98, 0.0)).length() < 1e-12);
    let pose = human.rest_pose();
    let state = Kinematics::of(&human.skeleton, &pose);
    let at = |name: &str| {
        state.effector_position[human.skeleton.effector_index(name).expect("effector")]
    };
    let joint = |name: &str| state.joint_position[human.skeleton.joint_index(name).expect("joint")];
    for foot in ["left_foot", "right_foot"] {
        let p = at(foot);
        assert!(p.y.abs() < 0.02, "{foot} sole at y = {} m", p.y);
        assert!(
            p.z > 0.0 && p.z < 0.2,
            "{foot} ahead of the ankle: z = {}",
            p.z
        );
    }
    assert!(
        at("left_foot").x > 0.05 && at("right_foot").x < -0.05,
        "left is +x"
    );
    assert!(at("left_hand").x > 0.15 && at("right_hand").x < -0.15);
    for hand in ["left_hand", "right_hand"] {
        let y = at(hand).y;
        assert!(
            (0.7..0.95).contains(&y),
            "{hand} hangs at hip height: y = {y}"
        );
    }
    for shoulder in ["left_shoulder_flex", "right_shoulder_flex"] {
        let y = joint(shoulder).y;
        assert!(
            (1.38..1.55).contains(&y),
            "{shoulder} at y = {y} (about 0.82 of 1.75 m)"
        );
    }
    let neck = joint("neck").y;
    assert!((1.45..1.6).contains(&neck), "neck base at y = {neck}");
    let leg = (joint("left_hip_flex") - joint("left_knee")).length()
        + (joint("left_knee") - joint("left_ankle")).length();
    assert!((leg - 0.87).abs() < 1e-9, "thigh + shank = {leg} m");
}

#[test]
fn human_joint_signs_follow_the_documented_conventions() {
    let human = human();
    let rest = effectors_with(&human, &[]);
    let moved = |changes: &[(&str, f64)], name: &str| {
        effector(&human, &effectors_with(&human, changes), name) - effector(&human, &rest, name)
    };
    // Hip flexion is negative and swings the foot forward (+z).
    assert!(moved(&[("left_hip_flex", -0.6)], "left_foot").z > 0.2);
    // Knee flexion is positive and swings the foot backward (-z).
    assert!(moved(&[("left_knee", 1.0)], "left_foot").z < -0.2);
    // Left hip abduction is positive and moves the left foot to the left (+x); right is negative.
    assert!(moved(&[("left_hip_abduct", 0.4)], "left_foot").x > 0.2);
    assert!(moved(&[("right_hip_abduct", -0.4)], "right_foot").x < -0.2);
    // Shoulder and elbow flexion are negative and bring the hand forward.
    assert!(moved(&[("right_shoulder_flex", -0.8)], "right_hand").z > 0.3);
    assert!(moved(&[("left_elbow", -1.2)], "left_hand").z > 0.15);
    // Trunk flexion is positive (the shoulders go forward and down), the legs do not move.
    let mut pose = human.rest_pose();
    let shoulder = human
        .skeleton
        .joint_index("left_shoulder_flex")
        .expect("shoulder");
    let before = Kinematics::of(&human.skeleton, &pose).joint_position[shoulder];
    pose.joints[human.skeleton.joint_index("lumbar_flex").expect("lumbar")] = 0.4;
    let after = Kinematics::of(&human.skeleton, &pose).joint_position[shoulder];
    assert!(after.z - before.z > 0.1 && after.y < before.y);
    assert!(moved(&[("lumbar_flex", 0.4)], "left_foot").length() < 1e-12);
}

#[test]
fn human_default_scenario_is_the_thesis_walk_with_sdls() {
    let human = human();
    let scenario = &human.scenario;
    assert_eq!(scenario.engine, Engine::Ik);
    assert_eq!(scenario.mode, ThesisMode::Walk);
    assert_eq!(scenario.method, Method::Sdls);
    assert_eq!(scenario.ik_options().method, Method::Sdls);
    assert_eq!(scenario.fps, 60);
    let wounded: Vec<(&str, f64)> = scenario
        .thesis
        .wounded
        .iter()
        .map(|w| (w.joint.as_str(), w.multiply))
        .collect();
    assert_eq!(
        wounded,
        [
            ("left_hip_flex", 0.2),
            ("left_knee", 0.2),
            ("right_shoulder_flex", 0.1)
        ]
    );
    for w in &scenario.thesis.wounded {
        assert!(human.skeleton.joint_index(&w.joint).is_some());
    }
    // walk and run are left to the thesis defaults.
    let defaults = gaitlab_core::preset::thesis::ThesisParams::default();
    assert_eq!(scenario.thesis.walk, defaults.walk);
    assert_eq!(scenario.thesis.run, defaults.run);
    assert_eq!(scenario.thesis.roles, defaults.roles);
}

#[test]
fn quadruped_has_63_joints_5_effectors_and_cycles_its_axes() {
    let quadruped = quadruped();
    let skeleton = &quadruped.skeleton;
    assert_eq!(skeleton.joint_count(), 63);
    let effectors: Vec<&str> = skeleton
        .effectors()
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    assert_eq!(
        effectors,
        [
            "left_front_foot",
            "right_front_foot",
            "left_hind_foot",
            "right_hind_foot",
            "head"
        ]
    );
    let count = |prefix: &str| {
        skeleton
            .joints()
            .iter()
            .filter(|j| j.name.starts_with(prefix))
            .count()
    };
    assert_eq!(count("spine_"), 18);
    assert_eq!(count("neck_"), 9);
    for leg in ["left_front", "right_front", "left_hind", "right_hind"] {
        assert_eq!(count(leg), 9, "{leg}");
        // Each leg effector depends on its 9 leg joints (plus spine joints for the front legs).
        let e = skeleton
            .effector_index(&format!("{leg}_foot"))
            .expect("foot");
        let leg_joints = skeleton
            .chain(e)
            .iter()
            .filter(|&&j| skeleton.joints()[j].name.starts_with(leg))
            .count();
        assert_eq!(leg_joints, 9);
    }
    let axes = [DVec3::X, DVec3::Y, DVec3::Z];
    for (i, joint) in skeleton.joints().iter().enumerate().take(27) {
        assert_eq!(joint.axis, axes[i % 3], "{} cycles x, y, z", joint.name);
        assert!(joint.limits.is_some());
    }
    for joint in skeleton.joints() {
        let (lo, hi) = joint.limits.expect("every joint is limited");
        assert!(lo < hi && (lo..=hi).contains(&joint.rest), "{}", joint.name);
    }
}

#[test]
fn quadruped_stands_on_four_feet_a_metre_long() {
    let quadruped = quadruped();
    let state = Kinematics::of(&quadruped.skeleton, &quadruped.rest_pose());
    let at = |name: &str| {
        state.effector_position[quadruped.skeleton.effector_index(name).expect("effector")]
    };
    for foot in [
        "left_front_foot",
        "right_front_foot",
        "left_hind_foot",
        "right_hind_foot",
    ] {
        assert!(
            at(foot).y.abs() < 0.02,
            "{foot} on the ground: y = {}",
            at(foot).y
        );
    }
    let body = at("left_front_foot").z - at("left_hind_foot").z;
    assert!((0.9..1.1).contains(&body), "body length {body} m");
    assert!(at("left_front_foot").x > 0.0 && at("right_front_foot").x < 0.0);
    assert!(
        at("head").y > quadruped.root_position.y + 0.2,
        "head held up"
    );
    assert!(
        at("head").z > at("left_front_foot").z + 0.2,
        "head in front"
    );
    let leg = quadruped.root_position.y - at("left_hind_foot").y;
    assert!((0.55..0.7).contains(&leg), "leg height {leg} m");
}

#[test]
fn quadruped_thesis_roles_and_walk_shape_fit_its_body() {
    let quadruped = quadruped();
    let thesis = &quadruped.scenario.thesis;
    assert_eq!(thesis.roles.left_hand, "left_front_foot");
    assert_eq!(thesis.roles.right_hand, "right_front_foot");
    assert_eq!(thesis.roles.left_foot, "left_hind_foot");
    assert_eq!(thesis.roles.right_foot, "right_hind_foot");
    let state = Kinematics::of(&quadruped.skeleton, &quadruped.rest_pose());
    let at = |name: &str| {
        state.effector_position[quadruped.skeleton.effector_index(name).expect("effector")]
    };
    let root = quadruped.root_position;
    for shape in [&thesis.walk, &thesis.run] {
        // The strokes are centred on where the feet stand, in the body frame.
        let hind_mid = (shape.front_foot + shape.back_foot) / 2.0;
        let front_mid = (shape.front_hand + shape.back_hand) / 2.0;
        assert!((hind_mid.z - (at("left_hind_foot").z - root.z)).abs() < 0.05);
        assert!((front_mid.z - (at("left_front_foot").z - root.z)).abs() < 0.05);
        assert!((hind_mid.x - at("left_hind_foot").x).abs() < 0.03);
        assert!(shape.root_height_m <= root.y && shape.root_height_m > 0.5);
        assert!(shape.front_foot.z > shape.back_foot.z && shape.front_hand.z > shape.back_hand.z);
    }
}

#[test]
fn a_preset_round_trips_through_serde() {
    for (name, json) in preset::bundled() {
        let parsed = Preset::from_json(json).expect("bundled preset parses");
        let written = serde_json::to_string_pretty(&parsed).expect("serialises");
        let again = Preset::from_json(&written)
            .unwrap_or_else(|e| panic!("{name} round trip: {e}\n{written}"));
        assert_eq!(parsed, again, "{name}");
        assert_eq!(
            parsed.build().expect("builds"),
            again.build().expect("builds")
        );
    }
}

#[test]
fn poda_creatures_have_the_papers_leg_and_joint_counts() {
    use gaitlab_core::preset::Engine;
    // (preset, legs, joints): PODA Figure 2's animal has four 9-DOF legs, a
    // 9-DOF neck and an 18-DOF spine; Figure 11's insect has 14 legs.
    let expected = [
        ("poda-quadruped", 4, 63),
        ("poda-biped", 2, 20),
        ("hexapod", 6, 19),
        ("insect-14", 14, 43),
    ];
    for (name, legs, joints) in expected {
        let creature = preset::load_bundled(name)
            .expect("bundled")
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(creature.scenario.engine, Engine::Poda, "{name}");
        assert_eq!(
            creature.scenario.poda_params().legs.len(),
            legs,
            "{name} legs"
        );
        assert_eq!(creature.skeleton.joint_count(), joints, "{name} joints");
    }
}
