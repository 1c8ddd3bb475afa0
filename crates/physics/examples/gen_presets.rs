//! Writes the bundled physics presets (`presets/raibert-*.json`) from the
//! Table 3 models in `gaitlab_physics::creatures`:
//! `cargo run -p gaitlab-physics --example gen_presets -- presets`
use gaitlab_physics::creatures::{biped, kangaroo, quadruped};
use gaitlab_physics::engine::preset::{PresetMeta, to_preset};
use glam::DVec3;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "presets".into());
    let entries = [
        (
            biped(1.0)?,
            PresetMeta {
                name: "raibert-biped".into(),
                description: "Raibert & Hodgins 1991's biped robot (Table 3): a 23.1 kg trunk on two telescoping legs with ball hips, physically simulated. Gaits: run, gallop, gallop_alternate.".into(),
                root_position: DVec3::new(0.0, 0.9, 0.0),
                rest: vec![0.0, 0.0, 0.0, -0.03, 0.0, 0.0, 0.0, -0.18],
                gait: "run".into(),
                speed_mps: 1.5,
                control_every: 5,
            },
        ),
        (
            quadruped(1.0)?,
            PresetMeta {
                name: "raibert-quadruped".into(),
                description: "Raibert & Hodgins 1991's quadruped robot (Table 3): a 10 kg trunk on four telescoping legs with gimbal hips, physically simulated. Gaits: trot, bound, gallop.".into(),
                root_position: DVec3::new(0.0, 0.75, 0.0),
                rest: vec![0.0, 0.0, -0.1, 0.0, 0.0, -0.1, 0.0, 0.0, -0.1, 0.0, 0.0, -0.1],
                gait: "trot".into(),
                speed_mps: 2.3,
                // The skip bound's 10–27 ms stances fall at 2.8 m/s with
                // its events seen 2 ms late (docs/physics.md).
                control_every: 1,
            },
        ),
        (
            kangaroo(1.0)?,
            PresetMeta {
                name: "raibert-kangaroo".into(),
                description: "Raibert & Hodgins 1991's planar kangaroo (Table 3, Figure 5): trunk, one leg, three-link tail and head, physically simulated. Gait: hop.".into(),
                root_position: DVec3::ZERO,
                rest: vec![0.0, 0.45, 0.0, 0.6, -1.2, 1.2, 0.0, 0.0, 0.0, 0.0],
                gait: "hop".into(),
                speed_mps: 5.0,
                control_every: 5,
            },
        ),
    ];
    for (creature, meta) in entries {
        let preset = to_preset(&creature, &meta);
        let json = serde_json::to_string_pretty(&preset)?;
        let path = format!("{dir}/{}.json", meta.name);
        std::fs::write(&path, json + "\n")?;
        println!("wrote {path}");
    }
    Ok(())
}
