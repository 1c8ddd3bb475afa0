//! Tuning report (ignored by default): every method × mode at the default
//! parameters, 20 s at 60 fps. Run with
//! `cargo test -p gaitlab-motion --release --test tune -- --ignored --nocapture`.

mod common;

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_motion::ThesisDriver;

#[test]
#[ignore = "report, not a check"]
fn report_errors_per_method_and_mode() {
    let skeleton = common::human();
    let seconds = std::env::var("TUNE_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20.0);
    for method in Method::ALL {
        for mode in ThesisMode::ALL {
            let options = IkOptions {
                method,
                ..IkOptions::default()
            };
            let mut driver =
                match ThesisDriver::new(skeleton.clone(), common::human_params(), mode, options) {
                    Ok(d) => d,
                    Err(e) => panic!("{e}"),
                };
            let frames = (seconds * 60.0_f64).round() as usize;
            for _ in 0..frames {
                driver.step(1.0 / 60.0);
            }
            let Some(m) = driver.ik_metrics() else {
                panic!("metrics")
            };
            let mut line = format!("{:>9} {:>12}", method.name(), mode.name());
            for (e, eff) in skeleton.effectors().iter().enumerate() {
                line += &format!(
                    "  {}: {:6.2}/{:6.2} mm",
                    eff.name,
                    1e3 * m.mean_error_m(e).unwrap_or(f64::NAN),
                    1e3 * m.max_error_m(e).unwrap_or(f64::NAN)
                );
            }
            println!("{line}");
        }
    }
}
