//! The lab's additions (docs/physics.md, "The lab's additions"): each
//! controller declares which it has and their defaults; a file without
//! `lab_additions` (made before they were optional) gets every one its
//! gait has; a file that names one gets it; a gait without it ignores it.

use gaitlab_core::preset::load_bundled;
use gaitlab_core::preset::physics::LabAdditions;
use gaitlab_physics::control::gaits::make::make_controller;
use gaitlab_physics::engine::preset::creature_from_preset;

/// The additions `gait` of bundled `preset` runs with under `spec`.
fn names(preset: &str, gait: &str, spec: Option<LabAdditions>) -> Vec<&'static str> {
    let preset = load_bundled(preset).expect("bundled").expect("valid");
    let creature = creature_from_preset(&preset).expect("creature");
    let mut params = preset.scenario.physics.clone().expect("physics");
    params.lab_additions = spec;
    params.lab_additions_by_gait.clear();
    let controller = make_controller(&creature, gait, &params).expect("controller");
    controller.additions().names().collect()
}

#[test]
fn each_gait_runs_its_own_additions_by_the_file_s_choice() {
    let default = Some(LabAdditions::default());
    // A file made before they were optional: every addition the gait has.
    assert_eq!(
        names("raibert-biped", "run", None),
        ["speed_trim", "unloading_posture", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-kangaroo", "hop", None),
        [
            "speed_trim",
            "speed_ramp",
            "tail_feedback",
            "hop_integrator"
        ]
    );
    assert_eq!(names("raibert-quadruped", "trot", None), ["hop_integrator"]);
    // `{}`: each controller's defaults.
    assert_eq!(
        names("raibert-biped", "run", default),
        ["unloading_posture", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-biped", "gallop", default),
        ["speed_trim", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-biped", "gallop_alternate", default),
        ["speed_trim", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-quadruped", "bound", default),
        ["speed_trim", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-quadruped", "gallop", default),
        ["speed_trim", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-kangaroo", "hop", default),
        ["speed_ramp", "tail_feedback", "hop_integrator"]
    );
    // Named ones win; a gait without the addition ignores it.
    let asked = Some(LabAdditions {
        speed_trim: Some(true),
        unloading_posture: Some(false),
        ..LabAdditions::default()
    });
    assert_eq!(
        names("raibert-biped", "run", asked),
        ["speed_trim", "hop_integrator"]
    );
    assert_eq!(
        names("raibert-quadruped", "trot", asked),
        ["hop_integrator"]
    );
    assert_eq!(
        names("raibert-quadruped", "pace", asked),
        ["hop_integrator"]
    );
    let off = Some(LabAdditions {
        speed_trim: Some(false),
        speed_ramp: Some(false),
        tail_feedback: Some(false),
        hop_integrator: Some(false),
        ..LabAdditions::default()
    });
    assert!(names("raibert-kangaroo", "hop", off).is_empty());
    assert!(names("raibert-biped", "gallop", off).is_empty());
}

/// `lab_additions_by_gait` names an addition for one gait over the file's
/// choice: the bundled biped runs and gallops by eq. 2 alone (each gait's
/// hop integrator off by name), which a file without those choices keeps
/// on; a gait the model lacks is refused by name.
#[test]
fn one_gait_s_choice_goes_over_the_file_s() {
    let preset = load_bundled("raibert-biped")
        .expect("bundled")
        .expect("valid");
    let creature = creature_from_preset(&preset).expect("creature");
    let params = preset.scenario.physics.clone().expect("physics");
    let on = |gait: &str, params: &gaitlab_core::preset::PhysicsParams| {
        let controller = make_controller(&creature, gait, params).expect("controller");
        controller.additions().names().collect::<Vec<_>>()
    };
    assert!(on("run", &params).is_empty());
    assert!(on("gallop", &params).is_empty());
    let mut other = params.clone();
    other.lab_additions_by_gait.clear();
    assert_eq!(on("run", &other), ["hop_integrator"]);
    assert_eq!(on("gallop", &other), ["hop_integrator"]);
    other.lab_additions_by_gait.insert(
        "gallop".to_owned(),
        LabAdditions {
            hop_integrator: Some(false),
            ..LabAdditions::default()
        },
    );
    assert!(on("gallop", &other).is_empty());
    other
        .lab_additions_by_gait
        .insert("amble".to_owned(), LabAdditions::default());
    let Err(error) = make_controller(&creature, "run", &other) else {
        panic!("an unknown gait is refused")
    };
    assert!(
        error
            .to_string()
            .starts_with("scenario.physics.lab_additions_by_gait.amble: "),
        "{error}"
    );
}
