//! `gaitlab export PRESET_OR_FILE --format mjcf`: a physics creature as a
//! MuJoCo model (bodies, joints, inertias, springs, hip motors, soft foot
//! contact), written to standard output or `--out FILE`.

use clap::Args;
use gaitlab_engine::{Overrides, driver_for};

use crate::fail::Failure;
use crate::load;
use crate::stdout::out;

/// Arguments of `gaitlab export`.
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// A bundled preset name or a preset JSON file (engine physics).
    pub preset: String,
    /// Output format: mjcf.
    #[arg(long)]
    pub format: String,
    /// Write to this file instead of standard output.
    #[arg(long)]
    pub out: Option<String>,
}

/// `gaitlab export`.
pub fn export(args: &ExportArgs) -> Result<(), Failure> {
    if args.format != "mjcf" {
        return Err(Failure::input(format!(
            "--format: unknown format {:?} (use mjcf)",
            args.format
        )));
    }
    let creature = load::creature(&args.preset)?;
    let driver = driver_for(&creature, &Overrides::default()).map_err(Failure::input)?;
    let Some(xml) = driver.mjcf(&creature.name) else {
        return Err(Failure::input(format!(
            "{}: MJCF export is for physics creatures; this preset's engine is {}",
            creature.name,
            creature.scenario.engine.name()
        )));
    };
    match &args.out {
        Some(path) => {
            std::fs::write(path, xml).map_err(|e| Failure::input(format!("--out {path}: {e}")))?
        }
        None => out!("{xml}"),
    }
    Ok(())
}
