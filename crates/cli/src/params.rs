//! `gaitlab params PRESET_OR_FILE [--json] [--set KEY=VALUE]…`: the engine
//! contract's parameter table for a preset — every settable value with its
//! value in force, unit, range, whether it changes live, the paper's
//! reference and its origin (paper, open, lab).

use clap::Args;
use gaitlab_core::params::{Domain, Origin};
use gaitlab_core::preset::Purpose;
use gaitlab_engine::{Overrides, Parameter, driver_for, parameters};
use serde_json::Value;

use crate::fail::Failure;
use crate::load;
use crate::stdout::outln;

/// Arguments of `gaitlab params`.
#[derive(Args, Debug)]
pub struct ParamsArgs {
    /// A bundled preset name or a preset JSON file.
    pub preset: String,
    /// Print the table as one JSON object (`preset`, `engine`, `parameters`).
    #[arg(long)]
    pub json: bool,
    /// Set a preset value first, as `gaitlab run --set` does (a controller's
    /// table follows `scenario.physics.gait=bound`).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// The table with every lab addition off, as `run --paper-alone`.
    #[arg(long)]
    pub paper_alone: bool,
}

/// `gaitlab params`.
pub fn params(args: &ParamsArgs) -> Result<(), Failure> {
    let (paths, gains) = crate::run::settings(&args.set)?;
    if let Some((name, _)) = gains.first() {
        return Err(Failure::input(format!(
            "--set {name}: a preset path such as scenario.physics.controller.{name}"
        )));
    }
    let creature =
        load::creature_edited(&args.preset, Purpose::Scenario, &paths, args.paper_alone)?;
    let driver = driver_for(&creature, &Overrides::default()).map_err(Failure::input)?;
    let table = parameters(&creature, &driver);
    if args.json {
        let report = serde_json::json!({
            "preset": creature.name,
            "engine": creature.scenario.engine.name(),
            "parameters": table,
        });
        outln!("{report:#}");
        return Ok(());
    }
    print_text(&creature.name, creature.scenario.engine.name(), &table);
    Ok(())
}

/// A value as the table prints it: numbers and names plainly, structures
/// shortened.
fn shown(value: &Value) -> String {
    const MOST: usize = 28;
    let text = match value {
        Value::Null => "(default)".to_owned(),
        Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    if text.chars().count() > MOST {
        let cut: String = text.chars().take(MOST - 1).collect();
        format!("{cut}…")
    } else {
        text
    }
}

fn print_text(preset: &str, engine: &str, table: &[Parameter]) {
    let count = |origin| table.iter().filter(|p| p.origin == origin).count();
    outln!(
        "{preset} · engine {engine} · {} parameters ({} the paper's, {} left open by it, {} the lab's)",
        table.len(),
        count(Origin::Paper),
        count(Origin::Open),
        count(Origin::Lab)
    );
    let key_width = table
        .iter()
        .map(|p| p.key.chars().count())
        .max()
        .unwrap_or(0);
    for p in table {
        let unit = if p.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", p.unit)
        };
        let range = match p.domain {
            Domain::Structured { .. } | Domain::Bool => String::new(),
            Domain::Integer { min, max } => format!(" in {min}..{max}"),
            Domain::Choice { options } => format!(" of {}", options.join(", ")),
            Domain::Real { .. } => format!(" in {}", p.range),
        };
        outln!(
            "{:<key_width$}  {:<5} {}  = {}{unit}{range} · {} · {}",
            p.key,
            p.origin.name(),
            if p.live { "live" } else { "    " },
            shown(&p.value),
            p.reference,
            p.why
        );
    }
}
