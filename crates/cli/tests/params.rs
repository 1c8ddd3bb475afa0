//! `gaitlab params`: the parameter table of every bundled preset, as JSON and
//! as text; a `--set` gait switches the physics controller's rows; the
//! values in force are the preset's; a bad `--set` exits 2 naming the key.

mod common;

use common::{bundled_names, gaitlab, gaitlab_ok, json_of};
use serde_json::Value;

fn table(args: &[&str]) -> Vec<Value> {
    let mut all = vec!["params"];
    all.extend_from_slice(args);
    all.push("--json");
    let report = json_of(&gaitlab_ok(&all));
    report["parameters"].as_array().expect("parameters").clone()
}

fn row<'a>(table: &'a [Value], key: &str) -> &'a Value {
    table
        .iter()
        .find(|p| p["key"] == key)
        .unwrap_or_else(|| panic!("no row {key}"))
}

#[test]
fn every_bundled_preset_has_a_table_with_origins() {
    for name in bundled_names() {
        let rows = table(&[&name]);
        assert!(rows.len() >= 5, "{name}: {} rows", rows.len());
        for p in &rows {
            let origin = p["origin"].as_str().expect("origin");
            assert!(["paper", "open", "lab"].contains(&origin), "{name}: {p}");
            assert!(
                !p["why"].as_str().unwrap_or("").is_empty()
                    && !p["reference"].as_str().unwrap_or("").is_empty(),
                "{name}: {p}"
            );
        }
        let text = String::from_utf8(gaitlab_ok(&["params", &name]).stdout).expect("utf-8");
        assert!(
            text.lines().count() == rows.len() + 1,
            "{name}: a header and one line per row"
        );
    }
}

#[test]
fn values_in_force_and_a_gait_set_first() {
    let she = table(&["she-2006"]);
    assert_eq!(row(&she, "scenario.ik.lambda")["value"], 0.2);
    assert_eq!(row(&she, "scenario.ik.lambda")["origin"], "open");
    assert_eq!(row(&she, "scenario.ik.clamp_every_method")["origin"], "lab");
    assert_eq!(row(&she, "scenario.thesis.script")["value"], "listing");
    let lambda = table(&["she-2006", "--set", "scenario.ik.lambda=0.5"]);
    assert_eq!(row(&lambda, "scenario.ik.lambda")["value"], 0.5);

    let trot = table(&["raibert-quadruped"]);
    assert_eq!(row(&trot, "scenario.physics.gait")["value"], "trot");
    assert!(
        trot.iter()
            .all(|p| p["key"] != "scenario.physics.controller.sweep_s")
    );
    let bound = table(&["raibert-quadruped", "--set", "scenario.physics.gait=bound"]);
    assert_eq!(row(&bound, "scenario.physics.gait")["value"], "bound");
    let sweep = row(&bound, "scenario.physics.controller.sweep_s");
    assert_eq!(sweep["origin"], "lab");
    assert!(sweep["value"].is_number());
    let stiffness = row(&bound, "scenario.physics.controller.leg_stiffness");
    assert_eq!(stiffness["live"], true);
    assert_eq!(stiffness["command"], "gain.leg_stiffness");

    let hexapod = table(&["hexapod"]);
    let period = row(&hexapod, "scenario.poda.period_s");
    assert_eq!(period["command"], "period_s");
    assert_eq!(period["domain"]["kind"], "real");
    assert_eq!(period["range"], "[0.1, 10]");
    assert!(row(&hexapod, "stroke_m")["value"].as_f64().expect("stroke") > 0.0);
}

#[test]
fn a_bad_set_exits_2_naming_the_key() {
    let out = gaitlab(&[
        "params",
        "she-2006",
        "--set",
        "scenario.ik.lambda=-1",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("scenario.ik.lambda"), "{err}");
    let out = gaitlab(&["params", "raibert-biped", "--set", "leg_stiffness=1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("scenario.physics.controller.leg_stiffness")
    );
}
