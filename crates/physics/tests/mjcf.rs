//! The MuJoCo export read back by an independent XML reader (roxmltree): every
//! body mass and inertia, every joint and its axis, the leg springs and hip
//! motors are there, for every bundled physics creature. (tools/mujoco_check.py
//! goes further and loads the files in MuJoCo itself; see docs/physics.md.)

use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::dynamics::model::Joint;

fn numbers(s: &str) -> Vec<f64> {
    s.split_whitespace()
        .map(|x| x.parse().expect("number"))
        .collect()
}

#[test]
fn every_physics_creature_exports_a_complete_mjcf() {
    for name in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
        let preset = load_bundled(name).expect("bundled").expect("valid");
        let driver = PhysicsDriver::new(&preset).expect("driver");
        let xml = driver.mjcf(name);
        let doc = roxmltree::Document::parse(&xml).unwrap_or_else(|e| panic!("{name}: {e}"));
        let root = doc.root_element();
        assert_eq!(root.tag_name().name(), "mujoco");
        assert_eq!(root.attribute("model"), Some(name));
        let model = &driver.sim().creature.model;
        // Mass: every inertial element sums to the model's mass.
        let inertials: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("inertial"))
            .collect();
        let mass: f64 = inertials
            .iter()
            .map(|n| {
                n.attribute("mass")
                    .expect("mass")
                    .parse::<f64>()
                    .expect("number")
            })
            .sum();
        assert!(
            (mass - model.total_mass()).abs() < 1e-6,
            "{name}: mass {mass} vs {}",
            model.total_mass()
        );
        assert_eq!(
            inertials.len(),
            model.bodies().iter().filter(|b| b.mass > 0.0).count(),
            "{name}"
        );
        // Joints: one per coordinate with its axis, plus the free joint.
        let joints: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("joint"))
            .collect();
        assert_eq!(joints.len(), model.joint_count(), "{name}");
        assert_eq!(
            doc.descendants()
                .filter(|n| n.has_tag_name("freejoint"))
                .count(),
            usize::from(model.free_base())
        );
        for body in model.bodies() {
            let axis = match body.joint {
                Joint::Revolute(a) | Joint::Prismatic(a) => a,
                Joint::Free => continue,
            };
            let j = joints
                .iter()
                .find(|n| n.attribute("name") == Some(body.name.as_str()))
                .unwrap_or_else(|| panic!("{name}: joint {}", body.name));
            let got = numbers(j.attribute("axis").expect("axis"));
            assert!(
                (glam::DVec3::new(got[0], got[1], got[2]) - axis).length() < 1e-9,
                "{name} {}",
                body.name
            );
            let kind = if matches!(body.joint, Joint::Revolute(_)) {
                "hinge"
            } else {
                "slide"
            };
            assert_eq!(j.attribute("type"), Some(kind), "{name} {}", body.name);
        }
        // Springs on every leg spring, motors on every hip joint, feet that collide.
        let creature = &driver.sim().creature;
        let springs = joints
            .iter()
            .filter(|n| n.attribute("stiffness").is_some())
            .count();
        assert!(springs >= creature.legs.len(), "{name}: {springs} springs");
        let motors = doc
            .descendants()
            .filter(|n| n.has_tag_name("motor"))
            .count();
        assert_eq!(
            motors,
            creature.legs.iter().map(|l| l.hip.len()).sum::<usize>(),
            "{name}"
        );
        let feet = doc
            .descendants()
            .filter(|n| {
                n.has_tag_name("geom") && n.attribute("name").is_some_and(|s| s.ends_with("-foot"))
            })
            .count();
        assert_eq!(feet, creature.legs.len(), "{name}");
        let gravity = numbers(
            doc.descendants()
                .find(|n| n.has_tag_name("option"))
                .and_then(|n| n.attribute("gravity"))
                .expect("gravity"),
        );
        assert_eq!(gravity, vec![0.0, -9.81, 0.0]);
    }
}
