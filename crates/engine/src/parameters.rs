//! The engine contract's `parameters()` (DESIGN.md): every settable value of
//! the running engine — key, command, unit, range, live or not, the paper's
//! reference and origin (the paper's, a value it leaves open, the lab's
//! addition) — with the value in force, joined from each engine's table
//! (She 2006 §4.4–5, Girard & Maciejewski 1985, Raibert & Hodgins 1991).

use gaitlab_core::Creature;
use gaitlab_core::ik::IK_PARAMS;
use gaitlab_core::params::{Domain, Origin, ParamSpec, SCENARIO_PARAMS};
use gaitlab_core::preset::physics::MAX_CONTROLLER_VALUE;
use gaitlab_core::preset::{PHYSICS_PARAMS, PODA_PARAMS, THESIS_PARAMS};
use serde::Serialize;
use serde_json::Value;

use crate::AnyDriver;

/// One row of a run's parameter table: an engine table's row with the value
/// in force.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Parameter {
    /// Its path in a preset (`scenario.ik.lambda`), as `--set` takes it; a
    /// value only a running driver has (PODA's stroke) has its command key.
    pub key: String,
    /// The page's command key and `--edit` key, where there is one
    /// (`lambda`; `gain.NAME` for a physics gain, set by the `gain` command).
    pub command: Option<String>,
    /// What it is, in a few words.
    pub label: String,
    /// Unit; empty for a pure number.
    pub unit: String,
    /// The values it may take.
    pub domain: Domain,
    /// The range in words (`(0, 10]`, `between 1 and 16`).
    pub range: String,
    /// Whether it changes while running.
    pub live: bool,
    /// Where the paper speaks of it.
    pub reference: String,
    /// The paper's, a value the paper leaves open, or the lab's addition.
    pub origin: Origin,
    /// Why this value or addition.
    pub why: String,
    /// The value in force (`null` where the preset leaves it to a default
    /// the engine derives).
    pub value: Value,
}

impl Parameter {
    fn of(spec: &ParamSpec, value: Value) -> Self {
        Self {
            key: spec.key.to_owned(),
            command: spec.command.map(str::to_owned),
            label: spec.label.to_owned(),
            unit: spec.unit.to_owned(),
            domain: spec.domain,
            range: spec.domain.describe(),
            live: spec.live,
            reference: spec.reference.to_owned(),
            origin: spec.origin,
            why: spec.why.to_owned(),
            value,
        }
    }
}

/// The value at a dotted `key` (`scenario.ik.lambda`) of `tree`; `null`
/// where there is none.
fn lookup(tree: &Value, key: &str) -> Value {
    key.split('.')
        .try_fold(tree, |node, part| node.get(part))
        .cloned()
        .unwrap_or(Value::Null)
}

/// The scenario in force: the creature's, with the driver's live values
/// (solver options, thesis, PODA and physics parameters) over it.
fn scenario_in_force(creature: &Creature, driver: &AnyDriver) -> Value {
    let mut scenario = serde_json::to_value(&creature.scenario).unwrap_or(Value::Null);
    let mut put = |key: &str, value: Option<Value>| {
        if let (Some(map), Some(value)) = (scenario.as_object_mut(), value) {
            map.insert(key.to_owned(), value);
        }
    };
    put(
        "ik",
        driver
            .ik_options()
            .and_then(|o| serde_json::to_value(o).ok()),
    );
    if let Some(method) = driver.ik_options().map(|o| o.method.name()) {
        put("method", Some(Value::from(method)));
    }
    match driver {
        AnyDriver::Thesis(thesis) => {
            put("thesis", serde_json::to_value(thesis.params()).ok());
            put("mode", serde_json::to_value(thesis.mode()).ok());
        }
        AnyDriver::Poda(poda) => put("poda", serde_json::to_value(poda.params()).ok()),
        AnyDriver::Physics(physics) => {
            put("physics", serde_json::to_value(physics.params()).ok());
        }
        AnyDriver::Track(_) => {}
    }
    serde_json::json!({ "scenario": scenario })
}

/// Every settable value of `driver` (built from `creature`), in table
/// order: the scenario's rows the engine reads, then the engine's own, then
/// (physics) the gait controller's parameters.
#[must_use]
pub fn parameters(creature: &Creature, driver: &AnyDriver) -> Vec<Parameter> {
    let tree = scenario_in_force(creature, driver);
    let mut out = Vec::new();
    let push_table = |table: &[ParamSpec], out: &mut Vec<Parameter>| {
        for spec in table {
            let value = match (spec.key, driver) {
                ("stroke_m", AnyDriver::Poda(poda)) => Value::from(poda.gait().stroke_m()),
                ("leg_force_n", AnyDriver::Poda(poda)) => Value::from(poda.leg_force_n()),
                ("scenario.poda.gait", AnyDriver::Poda(poda)) => Value::from(poda.gait_name()),
                ("scenario.physics.gait", AnyDriver::Physics(physics)) => {
                    Value::from(physics.gait())
                }
                (key, _) => lookup(&tree, key),
            };
            out.push(Parameter::of(spec, value));
        }
    };
    let scenario_rows = |keys: &[&str]| -> Vec<ParamSpec> {
        SCENARIO_PARAMS
            .iter()
            .filter(|p| keys.contains(&p.key))
            .copied()
            .collect()
    };
    match driver {
        AnyDriver::Thesis(_) => {
            push_table(
                &scenario_rows(&[
                    "scenario.mode",
                    "scenario.method",
                    "scenario.fps",
                    "heading_deg",
                ]),
                &mut out,
            );
            push_table(IK_PARAMS, &mut out);
            push_table(THESIS_PARAMS, &mut out);
        }
        AnyDriver::Track(_) => {
            push_table(
                &scenario_rows(&["scenario.method", "scenario.fps"]),
                &mut out,
            );
            push_table(IK_PARAMS, &mut out);
        }
        AnyDriver::Poda(_) => {
            push_table(&scenario_rows(&["scenario.fps"]), &mut out);
            push_table(PODA_PARAMS, &mut out);
        }
        AnyDriver::Physics(physics) => {
            push_table(&scenario_rows(&["scenario.fps", "heading_deg"]), &mut out);
            push_table(PHYSICS_PARAMS, &mut out);
            let gains: Vec<&str> = physics.gains().iter().map(|g| g.name).collect();
            for row in physics.controller_parameters() {
                let live = gains.contains(&row.name);
                let lo = if live { 0.0 } else { -MAX_CONTROLLER_VALUE };
                let domain = Domain::closed(lo, MAX_CONTROLLER_VALUE);
                out.push(Parameter {
                    key: format!("scenario.physics.controller.{}", row.name),
                    command: live.then(|| format!("gain.{}", row.name)),
                    label: row.label.to_owned(),
                    unit: row.unit.to_owned(),
                    domain,
                    range: domain.describe(),
                    live,
                    reference: row.reference.to_owned(),
                    origin: row.origin,
                    why: row.why.to_owned(),
                    value: physics.parameter(row.name).map_or(Value::Null, Value::from),
                });
            }
        }
    }
    out
}
