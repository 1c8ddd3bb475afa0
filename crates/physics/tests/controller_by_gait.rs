//! A gait's own controller parameters (`scenario.physics.controller_by_gait`):
//! set after the parameters every gait shares (`controller`), for that gait
//! only, so a tuned trot leaves the quadruped's bound as it was; a gait the
//! model lacks, or a name the gait's controller lacks, is named by its path.

use std::collections::BTreeMap;

use gaitlab_core::preset::load_bundled;
use gaitlab_core::preset::physics::PhysicsParams;
use gaitlab_physics::control::gaits::make::make_controller;
use gaitlab_physics::engine::preset::creature_from_preset;
use gaitlab_physics::world::sim::Controller;

/// The bundled quadruped's physics section, with `shared` for every gait
/// and `own` for the gaits it names.
fn quadruped(shared: &[(&str, f64)], own: &[(&str, &str, f64)]) -> PhysicsParams {
    let preset = load_bundled("raibert-quadruped")
        .expect("bundled")
        .expect("valid");
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.controller = shared.iter().map(|&(n, v)| (n.to_owned(), v)).collect();
    params.controller_by_gait = BTreeMap::new();
    for &(gait, name, value) in own {
        params
            .controller_by_gait
            .entry(gait.to_owned())
            .or_default()
            .insert(name.to_owned(), value);
    }
    params
}

/// The value of gain `name` of `gait` built from `params`.
fn gain(params: &PhysicsParams, gait: &str, name: &str) -> f64 {
    let preset = load_bundled("raibert-quadruped")
        .expect("bundled")
        .expect("valid");
    let creature = creature_from_preset(&preset).expect("creature");
    let controller = make_controller(&creature, gait, params).expect("controller");
    let gains = controller.gains();
    gains.iter().find(|g| g.name == name).expect("gain").value
}

#[test]
fn a_gait_s_own_parameters_reach_that_gait_only() {
    let default_bound = gain(&quadruped(&[], &[]), "bound", "pitch_kp");
    let default_trot = gain(&quadruped(&[], &[]), "trot", "pitch_kp");
    let params = quadruped(&[], &[("trot", "pitch_kp", 777.0)]);
    assert_eq!(gain(&params, "trot", "pitch_kp"), 777.0);
    assert_eq!(gain(&params, "bound", "pitch_kp"), default_bound);
    assert_ne!(default_trot, 777.0);
    // The gait's own value wins over the one every gait shares.
    let params = quadruped(&[("pitch_kp", 500.0)], &[("bound", "pitch_kp", 90.0)]);
    assert_eq!(gain(&params, "bound", "pitch_kp"), 90.0);
    assert_eq!(gain(&params, "trot", "pitch_kp"), 500.0);
}

#[test]
fn a_wrong_gait_or_name_is_named_by_its_path() {
    let preset = load_bundled("raibert-quadruped")
        .expect("bundled")
        .expect("valid");
    let creature = creature_from_preset(&preset).expect("creature");
    let error = |params: &PhysicsParams, gait: &str| {
        make_controller(&creature, gait, params)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default()
    };
    let unknown_gait = error(&quadruped(&[], &[("canter", "pitch_kp", 1.0)]), "trot");
    assert!(
        unknown_gait.contains("scenario.physics.controller_by_gait.canter")
            && unknown_gait.contains("trot, bound, gallop"),
        "{unknown_gait}"
    );
    let unknown_name = error(
        &quadruped(&[], &[("bound", "tail_stiffness", 1.0)]),
        "bound",
    );
    assert!(
        unknown_name.contains("scenario.physics.controller_by_gait.bound.tail_stiffness"),
        "{unknown_name}"
    );
    // The core's range check names the gait's value too.
    let mut params = quadruped(&[], &[("bound", "pitch_kp", f64::INFINITY)]);
    let checked = params
        .check("scenario.physics", &|_| true)
        .err()
        .map(|e| e.to_string());
    assert!(
        checked
            .as_deref()
            .is_some_and(|e| e.contains("scenario.physics.controller_by_gait.bound.pitch_kp")),
        "{checked:?}"
    );
    params.controller_by_gait.clear();
    assert!(params.check("scenario.physics", &|_| true).is_ok());
}
