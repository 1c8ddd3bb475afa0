//! Writes docs/physics.md's Table-2 comparison: every gait of every bundled
//! physics creature run through the driver at the paper's speed, its figures
//! beside Raibert & Hodgins 1991's animation column.
//! `cargo run --release -p gaitlab-physics --example table2_doc`
use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::PhysicsDriver;
use gaitlab_physics::control::gait_controller::gait_names;
use gaitlab_physics::engine::table2::{measured, paper_rows, paper_speed_mps};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    for preset_name in ["raibert-biped", "raibert-quadruped", "raibert-kangaroo"] {
        let preset = load_bundled(preset_name).ok_or("no preset")??;
        let species = PhysicsDriver::new(&preset)?.sim().creature.species;
        for gait in gait_names(species) {
            let mut params = preset.scenario.physics.clone().ok_or("no physics")?;
            params.gait = Some((*gait).to_owned());
            let speed = paper_speed_mps(gait).unwrap_or(params.speed_mps);
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
            let legs: Vec<String> = driver
                .sim()
                .creature
                .legs
                .iter()
                .map(|l| l.name.clone())
                .collect();
            let legs: Vec<&str> = legs.iter().map(String::as_str).collect();
            println!("### {preset_name} · {gait} at {speed} m/s\n");
            println!(
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
                s.peak_vertical_accel_g
            );
            let rows = paper_rows(gait);
            if rows.is_empty() {
                println!("Table 2 has no column for this gait.\n");
                continue;
            }
            println!("| quantity | paper (animation) | gaitlab | difference |");
            println!("|---|---:|---:|---:|");
            for row in rows {
                match measured(&s, row.quantity, &legs) {
                    Some(v) => {
                        let d = (v / row.animation - 1.0) * 100.0;
                        let mark = if d.abs() <= 35.0 { "" } else { " ✗" };
                        println!(
                            "| {} | {} | {:.3} | {:+.0} %{mark} |",
                            row.label, row.animation, v, d
                        );
                    }
                    None => println!("| {} | {} | — | |", row.label, row.animation),
                }
            }
            println!();
        }
    }
    Ok(())
}
