//! Writes docs/physics.md's Table-2 comparison: every gait of every bundled
//! physics creature run through the driver at the paper's speed, its figures
//! beside Raibert & Hodgins 1991's animation column (the same rows as `gaitlab
//! run --json`'s `table2`, from [`gaitlab_physics::engine::table2::compare`]).
//!
//! `cargo run --release -p gaitlab-physics --example table2_doc` prints it;
//! with `-- --write` it replaces the part of docs/physics.md between the
//! `table2_doc` markers.
use std::fmt::Write as _;

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gaits::table::{gait_names, tested_speeds_mps};
use gaitlab_physics::engine::table2::{BAND_PCT, compare, paper_speed_mps};

const BEGIN: &str = "<!-- table2_doc:begin -->";
const END: &str = "<!-- table2_doc:end -->";

fn tables() -> Result<String, Box<dyn std::error::Error>> {
    let mut out = String::new();
    for preset_name in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
        let preset = load_bundled(preset_name).ok_or("no preset")??;
        let species = PhysicsDriver::new(&preset)?.sim().creature.species;
        for gait in gait_names(species) {
            let mut params = preset.scenario.physics.clone().ok_or("no physics")?;
            params.gait = Some((*gait).to_owned());
            // The paper's speed; for a gait it does not tabulate, the
            // preset's, moved into the gait's tested speeds.
            let tested = tested_speeds_mps(species, gait).unwrap_or((0.0, f64::INFINITY));
            let speed =
                paper_speed_mps(gait).unwrap_or_else(|| params.speed_mps.clamp(tested.0, tested.1));
            params.speed_mps = speed;
            let mut driver = PhysicsDriver::with_params(&preset, params)?;
            driver.reset_after_fall = false;
            // Let the controller reach the speed (the kangaroo ramps from 2 m/s), then measure 30 s.
            let warmup = if *gait == "hop" { 16.0 } else { 5.0 };
            for _ in 0..(warmup * 60.0) as usize {
                driver.step(1.0 / 60.0);
            }
            driver.clear_metrics();
            for _ in 0..(30.0 * 60.0) as usize {
                driver.step(1.0 / 60.0);
            }
            let s = driver.summary();
            let legs: Vec<&str> = driver.leg_names().collect();
            writeln!(out, "### {preset_name} · {gait} at {speed} m/s\n")?;
            writeln!(
                out,
                "fell: {} · mean speed {:.2} m/s · stride {:.2} m in {:.3} s · flight {:.3} s · stance {:.3} s · pitch {:.1}° · roll {:.1}° · friction needed {:.2} · peak vertical force {:.1} × weight\n",
                s.fell || driver.resets() > 0,
                s.speed_mean_mps,
                s.stride_length_m,
                s.stride_duration_s,
                s.flight_duration_s,
                s.stance_duration_s,
                s.pitch_magnitude_deg,
                s.roll_magnitude_deg,
                s.friction_needed_max,
                s.peak_vertical_force_bw
            )?;
            let rows = compare(&s, gait, &legs);
            if rows.is_empty() {
                writeln!(out, "Table 2 has no column for this gait.\n")?;
                continue;
            }
            writeln!(
                out,
                "| quantity | paper (animation) | gaitlab | difference |"
            )?;
            writeln!(out, "|---|---:|---:|---:|")?;
            for c in rows {
                let label = c.row.label;
                let paper = c.row.animation;
                match (c.measured, c.diff_pct()) {
                    (Some(v), _) if c.row.quantity.is_input() => {
                        writeln!(out, "| {label} | {paper} | {v:.3} | input |")?;
                    }
                    (Some(v), Some(d)) => {
                        let speed_error = c.row.quantity.is_speed_error();
                        let mark = if d.abs() <= BAND_PCT || speed_error {
                            ""
                        } else {
                            " ✗"
                        };
                        let note = if speed_error { " (†)" } else { "" };
                        writeln!(
                            out,
                            "| {label}{note} | {paper} | {v:.3} | {d:+.0} %{mark} |"
                        )?;
                    }
                    _ => writeln!(out, "| {label} | {paper} | — | |")?,
                }
            }
            writeln!(out)?;
        }
    }
    Ok(out)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let text = tables()?;
    if !std::env::args().any(|a| a == "--write") {
        print!("{text}");
        return Ok(());
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/physics.md");
    let doc = std::fs::read_to_string(path)?;
    let (Some(a), Some(b)) = (doc.find(BEGIN), doc.find(END)) else {
        return Err(format!("{path}: no {BEGIN} … {END} markers").into());
    };
    let updated = format!("{}{BEGIN}\n\n{text}{}", &doc[..a], &doc[b..]);
    std::fs::write(path, updated)?;
    println!("wrote {path}");
    Ok(())
}
