//! The Jacobian panel's figures on the singularity scenario (issue 44): the
//! smallest singular value and the condition number over time as every
//! limb is pulled to its full reach, and the largest gain each method gives
//! a singular direction — pinv's 1/σ against DLS's σ/(σ² + λ²) ≤ 1/(2λ) and
//! SDLS's clamped 1/σ. Prints what docs/app.md quotes.

use gaitlab_app::{App, Settings};
use serde_json::json;

const SECONDS: f64 = 10.0;

#[test]
fn near_the_singularity_pinv_gains_most_and_dls_stays_under_its_bound() {
    let mut lab = App::new(Settings::default());
    if let Err(error) = lab.set_preset("she-2006") {
        panic!("{error}");
    }
    let c = json!({"mode": "walk", "compare": {
        "views": ["transpose", "pinv", "dls", "sdls"], "scenario": "singularity"}});
    if let Err(error) = lab.command(&c.to_string()) {
        panic!("{error}");
    }
    lab.set_paused(true);
    let frames = (SECONDS / lab.frame_seconds()).round() as usize;
    let names = ["transpose", "pinv", "dls", "sdls"];
    // Per view: smallest σ seen, largest condition, largest gain, and the
    // largest gain at the frame of the smallest σ.
    let mut sigma_min = [f64::INFINITY; 4];
    let mut condition_max = [0.0_f64; 4];
    let mut gain_max = [0.0_f64; 4];
    let mut seconds = Vec::new();
    for frame in 0..frames {
        lab.single_step();
        lab.advance(0.0);
        for (i, _) in names.iter().enumerate() {
            let Some(spectrum) = lab.jacobian().spectrum(i) else {
                continue;
            };
            let directions = spectrum.directions();
            let Some(last) = directions.last() else {
                continue;
            };
            sigma_min[i] = sigma_min[i].min(last.sigma);
            condition_max[i] = condition_max[i].max(spectrum.condition().unwrap_or(0.0));
            for (k, d) in directions.iter().enumerate() {
                gain_max[i] = gain_max[i].max(spectrum.gain(k, d.sigma).unwrap_or(0.0));
            }
        }
        if frame % 60 == 59 {
            let trace: Vec<_> = lab.jacobian().frames().collect();
            if let Some(p) = trace.last() {
                seconds.push((p.time_s, p.sigma_min, p.condition));
            }
        }
    }
    println!("second by second (the first view, transpose): t, σmin (m/rad), condition");
    for (t, s, c) in &seconds {
        println!("  {t:5.2} s  {s:.4}  {c:8.1}");
    }
    println!("method      σmin seen  condition max  largest gain (rad/m)");
    for i in 0..4 {
        println!(
            "{:<10} {:>10.4} {:>14.1} {:>12.2}",
            names[i], sigma_min[i], condition_max[i], gain_max[i]
        );
    }
    let lambda = gaitlab_core::ik::IkOptions::default().lambda;
    // The trace shows the stretch: the first figure's smallest σ falls.
    assert!(seconds.len() >= 9);
    // DLS never exceeds 1/(2λ); pinv's largest gain exceeds DLS's and SDLS's.
    assert!(gain_max[2] <= 0.5 / lambda + 1e-9, "dls {}", gain_max[2]);
    assert!(
        gain_max[1] > gain_max[2],
        "pinv {} against dls {}",
        gain_max[1],
        gain_max[2]
    );
    assert!(
        gain_max[1] > gain_max[3],
        "pinv {} against sdls {}",
        gain_max[1],
        gain_max[3]
    );
}
