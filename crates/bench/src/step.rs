//! The physics benchmark shared by `gaitlab bench` (native) and
//! `window.gaitlab.bench()` (wasm): integration steps per second of a
//! creature running under control with ground contact, and the real-time
//! factor that gives at the preset's step (the paper's 0.4 ms: "7 to 10 times
//! slower than real time on a SUN Sparc2").

use gaitlab_core::preset::{Creature as PresetCreature, PresetError};
use gaitlab_engine::{AnyDriver, Overrides, driver_for};
use gaitlab_physics::PhysicsDriver;

/// What to time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepBenchOptions {
    /// Simulated seconds run before timing (the creature gets going).
    pub warmup_s: f64,
    /// Simulated seconds per timed repeat.
    pub seconds: f64,
    /// Timed repeats; the median and the best are reported.
    pub repeats: usize,
}

impl Default for StepBenchOptions {
    fn default() -> Self {
        Self {
            warmup_s: 2.0,
            seconds: 1.0,
            repeats: 15,
        }
    }
}

/// Steps per second and real-time factor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepTiming {
    /// Median steps per second.
    pub steps_per_second: f64,
    /// Best repeat's steps per second.
    pub steps_per_second_best: f64,
    /// Median simulated seconds per wall second.
    pub realtime_factor: f64,
    /// The integration step timed (s).
    pub dt_s: f64,
}

/// The preset's creature at its gait after `warmup_s` simulated seconds
/// (the state [`time_steps`] times from; shared with the criterion benches).
///
/// # Errors
/// The preset does not make a physics driver, or the warm-up blew up
/// (reported at `scenario.physics`).
pub fn warmed_driver(preset: &PresetCreature, warmup_s: f64) -> Result<PhysicsDriver, PresetError> {
    let mut driver = match driver_for(preset, &Overrides::default())? {
        AnyDriver::Physics(driver) => *driver,
        _ => {
            return Err(PresetError::new(
                "scenario.engine",
                "the step benchmark times physics creatures",
            ));
        }
    };
    let dt = driver.sim().options.dt;
    driver.run_steps(steps_in(warmup_s, dt)).map_err(blew_up)?;
    Ok(driver)
}

/// Integration steps of `dt` seconds in `seconds` (at least one).
fn steps_in(seconds: f64, dt: f64) -> u32 {
    (seconds / dt).round().max(1.0) as u32
}

fn blew_up(e: gaitlab_physics::BlowUp) -> PresetError {
    PresetError::new("scenario.physics", e.to_string())
}

/// Time the preset's creature at its gait; `clock_ms` reads a monotonic clock.
///
/// # Errors
/// The preset does not make a physics driver, or the run blew up (reported
/// as an error at `scenario.physics`).
pub fn time_steps(
    preset: &PresetCreature,
    options: &StepBenchOptions,
    clock_ms: &mut dyn FnMut() -> f64,
) -> Result<StepTiming, PresetError> {
    let mut driver = warmed_driver(preset, options.warmup_s)?;
    let dt = driver.sim().options.dt;
    let n = steps_in(options.seconds, dt);
    let mut rates = Vec::with_capacity(options.repeats.max(1));
    for _ in 0..options.repeats.max(1) {
        let start = clock_ms();
        driver.run_steps(n).map_err(blew_up)?;
        let ms = (clock_ms() - start).max(1e-6);
        rates.push(f64::from(n) / (ms / 1e3));
    }
    rates.sort_by(f64::total_cmp);
    let median = rates[rates.len() / 2];
    let best = rates[rates.len() - 1];
    Ok(StepTiming {
        steps_per_second: median,
        steps_per_second_best: best,
        realtime_factor: median * dt,
        dt_s: dt,
    })
}
