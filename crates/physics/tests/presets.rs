//! The bundled physics presets rebuild exactly the Table 3 models of
//! `gaitlab_physics::creatures`, at scale 1 and scaled (Table 1).

use gaitlab_core::preset::{Creature as PresetCreature, load_bundled};
use gaitlab_physics::PhysicalCreature;
use gaitlab_physics::creatures::{TRUNK_INERTIA_TENTH_KGM2, biped, kangaroo, quadruped_with_trunk};
use gaitlab_physics::engine::preset::creature_from_preset;

fn assert_same(name: &str, got: &PhysicalCreature, want: &PhysicalCreature) {
    assert_eq!(got.species, want.species, "{name}");
    assert_eq!(got.trunk, want.trunk, "{name} trunk");
    assert_eq!(got.legs, want.legs, "{name} legs");
    assert_eq!(got.tail, want.tail, "{name} tail");
    assert_eq!(got.neck, want.neck, "{name} neck");
    let (a, b) = (got.model.bodies(), want.model.bodies());
    assert_eq!(a.len(), b.len(), "{name} body count");
    for (x, y) in a.iter().zip(b) {
        assert_eq!(x.name, y.name, "{name}");
        assert_eq!(x.parent, y.parent, "{name} {}", x.name);
        assert_eq!(x.joint, y.joint, "{name} {}", x.name);
        let close = |p: f64, q: f64| (p - q).abs() <= 1e-12 * (1.0 + q.abs());
        assert!(close(x.mass, y.mass), "{name} {} mass", x.name);
        assert!((x.com - y.com).length() < 1e-12, "{name} {} com", x.name);
        assert!(
            (x.placement.pos - y.placement.pos).length() < 1e-12,
            "{name} {} placement",
            x.name
        );
        assert!(
            x.placement.rot.abs_diff_eq(y.placement.rot, 1e-12),
            "{name} {} rotation",
            x.name
        );
        assert!(
            x.inertia_com.abs_diff_eq(y.inertia_com, 1e-12),
            "{name} {} inertia",
            x.name
        );
    }
}

type Builder = fn(f64) -> Result<PhysicalCreature, gaitlab_physics::ModelError>;

fn bundled(name: &str) -> PresetCreature {
    load_bundled(name).expect("bundled").expect("valid")
}

#[test]
fn bundled_presets_are_the_table_3_models() {
    // The bundled quadruped reads Table 3's garbled trunk inertia as a
    // tenth of the printed digits (since 2026-12-04).
    let cases: [(&str, Builder); 3] = [
        ("raibert-biped", biped),
        ("raibert-quadruped", |l| {
            quadruped_with_trunk(l, TRUNK_INERTIA_TENTH_KGM2)
        }),
        ("raibert-kangaroo", kangaroo),
    ];
    for (name, build) in cases {
        let preset = bundled(name);
        let got = creature_from_preset(&preset).expect("physics creature");
        assert_same(name, &got, &build(1.0).expect("builder"));
        let mut scaled = preset.clone();
        if let Some(p) = scaled.scenario.physics.as_mut() {
            p.scale = 2.5;
        }
        let got = creature_from_preset(&scaled).expect("scaled creature");
        assert_same(name, &got, &build(2.5).expect("scaled builder"));
    }
}
