//! The parameter tables of the gait controllers (`control/gaits/*/origins.rs`):
//! each names exactly its parameters, in order, each row with words, a unit
//! its name agrees with and a reference; every bundled gait answers for its
//! table.

use std::collections::HashSet;

use gaitlab_core::params::Origin;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::control::gaits::biped_gallop::params::BipedGallopParams;
use gaitlab_physics::control::gaits::biped_run::params::BipedRunParams;
use gaitlab_physics::control::gaits::bound::params::QuadrupedBoundParams;
use gaitlab_physics::control::gaits::gait::Gait;
use gaitlab_physics::control::gaits::kangaroo_hop::params::KangarooHopParams;
use gaitlab_physics::control::gaits::origins::ControllerParam;
use gaitlab_physics::control::gaits::parameters::NamedParameters;
use gaitlab_physics::control::gaits::table::gait_names;
use gaitlab_physics::control::gaits::trot::params::QuadrupedRunParams;
use gaitlab_physics::control::gaits::{biped_gallop, biped_run, bound, kangaroo_hop, trot};
use gaitlab_physics::engine::driver::PhysicsDriver;
use gaitlab_physics::world::sim::Controller;

/// Every table with its parameters type's names.
fn tables() -> [(
    &'static str,
    &'static [ControllerParam],
    &'static [&'static str],
); 5] {
    [
        (
            "BipedRunParams",
            biped_run::origins::ORIGINS,
            BipedRunParams::NAMES,
        ),
        (
            "BipedGallopParams",
            biped_gallop::origins::ORIGINS,
            BipedGallopParams::NAMES,
        ),
        (
            "KangarooHopParams",
            kangaroo_hop::origins::ORIGINS,
            KangarooHopParams::NAMES,
        ),
        (
            "QuadrupedBoundParams",
            bound::origins::ORIGINS,
            QuadrupedBoundParams::NAMES,
        ),
        (
            "QuadrupedRunParams",
            trot::origins::ORIGINS,
            QuadrupedRunParams::NAMES,
        ),
    ]
}

#[test]
fn each_table_names_exactly_its_parameters() {
    for (what, table, names) in tables() {
        let rows: Vec<&str> = table.iter().map(|r| r.name).collect();
        let set: HashSet<&str> = rows.iter().copied().collect();
        assert_eq!(set.len(), rows.len(), "{what}: a name twice");
        let want: HashSet<&str> = names.iter().copied().collect();
        let missing: Vec<_> = want.difference(&set).collect();
        let extra: Vec<_> = set.difference(&want).collect();
        assert!(missing.is_empty(), "{what}: no row for {missing:?}");
        assert!(extra.is_empty(), "{what}: rows for no parameter {extra:?}");
        assert_eq!(rows, names, "{what}: rows in the names' order");
    }
}

#[test]
fn every_row_has_words_and_a_unit_its_name_agrees_with() {
    // The first suffix a name ends with decides its unit.
    let suffixes = [
        ("_mps2", "m/s²"),
        ("_mps", "m/s"),
        ("_rad", "rad"),
        ("_m", "m"),
        ("_s", "s"),
    ];
    for (what, table, _) in tables() {
        for r in table {
            let name = r.name;
            assert!(!r.label.trim().is_empty(), "{what}.{name}: label");
            assert!(!r.why.trim().is_empty(), "{what}.{name}: why");
            assert!(!r.reference.trim().is_empty(), "{what}.{name}: reference");
            if let Some((_, unit)) = suffixes.iter().find(|(s, _)| name.ends_with(s)) {
                assert_eq!(r.unit, *unit, "{what}.{name}: unit");
            }
            if r.origin == Origin::Lab {
                assert!(
                    r.reference.starts_with("docs/"),
                    "{what}.{name}: lab's docs"
                );
            }
        }
    }
}

#[test]
fn a_bundled_drivers_table_is_its_running_controllers() {
    let mut seen: Vec<&'static [ControllerParam]> = Vec::new();
    for name in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
        let preset = load_bundled(name)
            .expect("bundled")
            .expect("a valid preset");
        let base = preset.scenario.physics.clone().expect("a physics section");
        let driver = PhysicsDriver::new(&preset).expect("driver");
        let species = driver.sim().creature.species;
        for gait in gait_names(species) {
            let mut params = base.clone();
            params.gait = Some((*gait).to_owned());
            let driver = PhysicsDriver::with_params(&preset, params).expect("driver");
            let table = driver.controller_parameters();
            assert!(!table.is_empty(), "{name} {gait}: a table");
            seen.push(table);
            assert_eq!(table.len(), driver.parameter_names().len(), "{name} {gait}");
            for row in table {
                assert!(
                    driver.parameter(row.name).is_some(),
                    "{name} {gait}: {} answers",
                    row.name
                );
            }
        }
    }
    for (what, table, _) in tables() {
        assert!(seen.contains(&table), "no bundled gait runs {what}");
    }
}

#[test]
fn each_controller_gives_its_own_table() {
    let params = KangarooHopParams::default();
    let hop = kangaroo_hop::KangarooHop::new(params);
    let names = hop.parameter_names();
    assert_eq!(Gait::origins(&hop), kangaroo_hop::origins::ORIGINS);
    assert_eq!(names, KangarooHopParams::NAMES);
}
