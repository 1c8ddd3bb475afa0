//! Native per-frame compute of the side-by-side comparison (the figure the
//! browser test measures as `sim_us_per_frame`): 4 views on the 63-joint
//! `ik-quadruped`, script and singularity scenarios.
//! Run with `cargo run --release -p gaitlab-app --example compare_bench`.

use std::time::Instant;

use gaitlab_app::{App, Settings};

fn main() {
    for scenario in ["script", "singularity"] {
        let mut lab = App::new(Settings::default());
        if let Err(error) = lab.set_preset("ik-quadruped") {
            eprintln!("{error}");
            std::process::exit(1);
        }
        let epoch = Instant::now();
        lab.set_clock(Box::new(move || epoch.elapsed().as_secs_f64() * 1e3));
        let command = format!(
            r#"{{"compare":{{"views":["transpose","pinv","dls","sdls"],"scenario":"{scenario}"}}}}"#
        );
        if let Err(error) = lab.command(&command) {
            eprintln!("{error}");
            std::process::exit(1);
        }
        lab.set_paused(true);
        let frames = 600;
        let started = Instant::now();
        for _ in 0..frames {
            lab.single_step();
            lab.advance(0.0);
        }
        let per_frame_us = started.elapsed().as_secs_f64() * 1e6 / f64::from(frames);
        print!(
            "ik-quadruped, 4 views, {scenario}: {per_frame_us:.0} µs per frame (4 views, {} frames)",
            frames
        );
        if let Some(compare) = lab.comparison() {
            for view in compare.views() {
                print!(
                    "; {} {:.1} µs/iter",
                    view.method.name(),
                    view.metrics().us_per_iteration()
                );
            }
        }
        println!();
    }
}
