//! The limbs and reach of the bundled human (She 2006 §3.1's figure, §5.3's
//! reachable targets): each leg hangs from the root at `*_hip_flex` and reaches
//! 0.44 + 0.43 + |(0, −0.06, 0.1)| ≈ 0.987 m; both hands share `thorax_twist`,
//! so each arm starts at `*_shoulder_flex` and reaches 0.3 + 0.26 + 0.08 = 0.64 m.

use gaitlab_core::preset;

#[test]
fn the_human_limbs_start_below_the_shared_root_and_have_their_link_lengths() {
    let creature = preset::load_bundled("human")
        .expect("human is bundled")
        .expect("human.json is valid");
    let skeleton = &creature.skeleton;
    let leg_m = 0.44 + 0.43 + (0.06_f64.powi(2) + 0.1_f64.powi(2)).sqrt();
    for (effector, first, shared_root, length_m) in [
        ("left_foot", "left_hip_flex", None, leg_m),
        ("right_foot", "right_hip_flex", None, leg_m),
        (
            "left_hand",
            "left_shoulder_flex",
            Some("thorax_twist"),
            0.64,
        ),
        (
            "right_hand",
            "right_shoulder_flex",
            Some("thorax_twist"),
            0.64,
        ),
    ] {
        let e = skeleton.effector_index(effector).expect("effector exists");
        let limb = skeleton.limb(e);
        let names: Vec<&str> = limb
            .joints
            .iter()
            .map(|&j| skeleton.joints()[j].name.as_str())
            .collect();
        assert_eq!(names.first().copied(), Some(first), "{effector}: {names:?}");
        assert_eq!(names.len(), 4, "{effector}: {names:?}");
        assert_eq!(
            limb.shared_root.map(|j| skeleton.joints()[j].name.as_str()),
            shared_root,
            "{effector}"
        );
        assert!(
            (limb.length_m - length_m).abs() < 1e-3,
            "{effector}: {} m, want {length_m} m",
            limb.length_m
        );
    }
    assert!((leg_m - 0.987).abs() < 1e-3);
}
