//! Tuning a gait's other parameters beside its gains (`gaitlab tune
//! --vary`, the paper's "we reduced the standing length of the legs"): a
//! varied parameter starts at the preset's value, a candidate's value
//! reaches the run exactly as if the preset had said it, and a name the
//! controller lacks, or one the search could not move, is refused with the
//! field named.

use gaitlab_core::Creature;
use gaitlab_core::portable::Portable;
use gaitlab_core::preset::load_bundled;
use gaitlab_tuner::{Objective, Problem};

const SECONDS: f64 = 5.0;

/// The bundled biped with its run's hop integrator on (`thrust_m` is the
/// integrator's first thrust; by eq. 2 alone it is unused) and, if given,
/// that first thrust.
fn biped(thrust_m: Option<f64>) -> Creature {
    let Some(Ok(mut creature)) = load_bundled("raibert-biped") else {
        panic!("raibert-biped is bundled")
    };
    if let Some(physics) = creature.scenario.physics.as_mut() {
        physics.lab_additions_by_gait.clear();
    }
    if let (Some(physics), Some(t)) = (creature.scenario.physics.as_mut(), thrust_m) {
        physics
            .controller_by_gait
            .entry("run".to_owned())
            .or_default()
            .insert("thrust_m".to_owned(), t);
    }
    creature
}

fn problem(creature: &Creature) -> Problem {
    let objective = match Objective::parse("fall=10,speed=1,table2=1") {
        Ok(o) => o,
        Err(error) => panic!("{error}"),
    };
    match Problem::new(creature, "run", SECONDS, objective) {
        Ok(p) => p,
        Err(error) => panic!("{error}"),
    }
}

fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|&s| s.to_owned()).collect()
}

/// Why `problem` refuses to vary `list` ("" when it accepts them).
fn refusal(problem: &mut Problem, list: &[&str]) -> String {
    problem
        .vary(&names(list))
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default()
}

#[test]
fn a_varied_parameter_starts_at_the_presets_value_and_reaches_the_run() {
    let mut varied = problem(&biped(Some(0.031)));
    let gains = varied.names().len();
    if let Err(error) = varied.vary(&names(&["thrust_m", "leg_stiffness"])) {
        panic!("{error}");
    }
    // The gain already tuned is passed over; the new one is last.
    assert_eq!(varied.names().len(), gains + 1);
    assert_eq!(varied.names()[gains], "thrust_m");
    assert_eq!(varied.start()[gains], 0.031);

    let mut x = vec![0.0; gains + 1];
    x[gains] = 0.2;
    let thrust = 0.031 * 0.2_f64.pexp();
    assert_eq!(varied.values(&x)[gains], thrust);
    let by_vary = varied.evaluate(&x);
    // The same value written in the preset, the gains at their start.
    let written = problem(&biped(Some(thrust))).evaluate(&vec![0.0; gains]);
    assert_eq!(by_vary, written, "the varied value runs as the preset's");
    let unchanged = problem(&biped(Some(0.031))).evaluate(&vec![0.0; gains]);
    assert_ne!(
        by_vary.cost, unchanged.cost,
        "a 22 % larger thrust changes the run"
    );
}

#[test]
fn names_the_search_cannot_use_are_refused_by_field() {
    let mut p = problem(&biped(None));
    let error = refusal(&mut p, &["thrust_m", "no_such_key"]);
    assert!(error.starts_with("vary[1]:"), "{error}");
    assert!(error.contains("no parameter `no_such_key`"), "{error}");
    assert!(error.contains("landing_rest_m"), "lists the keys: {error}");

    let mut creature = biped(None);
    if let Some(physics) = creature.scenario.physics.as_mut() {
        physics
            .controller_by_gait
            .entry("run".to_owned())
            .or_default()
            .insert("thrust_m".to_owned(), 0.0);
    }
    let error = refusal(&mut problem(&creature), &["thrust_m"]);
    assert!(error.starts_with("vary[0]:"), "{error}");
    assert!(error.contains("starts at 0"), "{error}");

    // The bound's flight per stride follows the preset's hop height.
    let Some(Ok(mut quadruped)) = load_bundled("raibert-quadruped") else {
        panic!("raibert-quadruped is bundled")
    };
    if let Some(physics) = quadruped.scenario.physics.as_mut() {
        physics.hop_height_m = Some(0.05);
    }
    let objective = Objective::parse("fall=10").unwrap_or_default();
    let mut bound = match Problem::new(&quadruped, "bound", SECONDS, objective) {
        Ok(p) => p,
        Err(error) => panic!("{error}"),
    };
    let gains = bound.names().len();
    let error = refusal(&mut bound, &["thrust_m", "stride_flight_s"]);
    assert!(error.starts_with("vary[1]: another field"), "{error}");
    assert_eq!(bound.names().len(), gains, "nothing added on an error");

    let error = refusal(&mut p, &["thrust_m"; 17]);
    assert!(error.starts_with("vary:"), "{error}");
}
