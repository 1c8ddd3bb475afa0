//! The per-frame benchmark shared by `gaitlab bench` (native) and
//! `window.gaitlab.bench()` (wasm): the µs one animation frame of the
//! creature's engine takes — for the thesis driver the §5.2.2 target script
//! plus the frame's IK iterations (She 2006 §4.4's per-frame cost), for a PODA
//! creature the gait, footholds, foot targets and every leg's IK — so the two
//! platforms time the same work and their ratio means something. The clock is supplied by the caller
//! (`Instant` natively, `performance.now()` in the browser).

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::Method;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{Creature, PresetError};
use gaitlab_engine::{AnyDriver, Overrides, driver_for};

/// Longest run one benchmark may ask for, frames per repeat.
pub const MAX_BENCH_FRAMES: usize = 100_000;
/// Most repeats one benchmark may ask for.
pub const MAX_BENCH_REPEATS: usize = 1_000;

/// What to time.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameBenchOptions {
    /// Thesis motion driven.
    pub mode: ThesisMode,
    /// IK method.
    pub method: Method,
    /// Animation frame length, seconds.
    pub frame_s: f64,
    /// Frames advanced before timing starts (to reach steady tracking).
    pub warmup_frames: usize,
    /// Frames per timed repeat.
    pub frames: usize,
    /// Timed repeats; the median and the best are reported.
    pub repeats: usize,
}

impl Default for FrameBenchOptions {
    fn default() -> Self {
        Self {
            mode: ThesisMode::Walk,
            method: Method::Sdls,
            frame_s: 1.0 / 60.0,
            warmup_frames: 60,
            frames: 600,
            repeats: 15,
        }
    }
}

/// The timings, µs per animation frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTiming {
    /// Median over the repeats.
    pub median_us: f64,
    /// Fastest repeat.
    pub best_us: f64,
    /// IK iterations run per frame.
    pub iterations_per_frame: usize,
}

/// Checks `options` against the limits before anything runs.
///
/// # Errors
/// The offending field as `field: reason`.
pub fn check_options(options: &FrameBenchOptions) -> Result<(), PresetError> {
    if !(options.frame_s.is_finite() && options.frame_s > 0.0 && options.frame_s <= 1.0) {
        return Err(PresetError::new("frame_s", "must be in (0, 1] seconds"));
    }
    if options.frames == 0 || options.frames > MAX_BENCH_FRAMES {
        return Err(PresetError::new(
            "frames",
            format!("must be between 1 and {MAX_BENCH_FRAMES}"),
        ));
    }
    if options.repeats == 0 || options.repeats > MAX_BENCH_REPEATS {
        return Err(PresetError::new(
            "repeats",
            format!("must be between 1 and {MAX_BENCH_REPEATS}"),
        ));
    }
    if options.warmup_frames > MAX_BENCH_FRAMES {
        return Err(PresetError::new(
            "warmup_frames",
            format!("must be at most {MAX_BENCH_FRAMES}"),
        ));
    }
    Ok(())
}

/// Median and minimum of `samples` (NaN when empty).
#[must_use]
pub fn median_and_best(samples: &mut [f64]) -> (f64, f64) {
    samples.sort_by(f64::total_cmp);
    (
        samples.get(samples.len() / 2).copied().unwrap_or(f64::NAN),
        samples.first().copied().unwrap_or(f64::NAN),
    )
}

/// The driver [`time_frames`] times for `creature` (its engine's: the thesis
/// driver with `options.mode` and `options.method`, or the PODA engine), and
/// the most IK iterations a frame may run (per leg for PODA). Shared with the
/// criterion benches so they time the same construction.
///
/// # Errors
/// A physics creature (timed by `gaitlab_physics::step_bench`), or thesis
/// parameters that cannot drive the skeleton.
pub fn frame_driver(
    creature: &Creature,
    options: &FrameBenchOptions,
) -> Result<(AnyDriver, usize), PresetError> {
    let overrides = Overrides {
        mode: Some(options.mode),
        method: Some(options.method),
        ..Overrides::default()
    };
    let driver = driver_for(creature, &overrides)?;
    let iterations_per_frame = match &driver {
        AnyDriver::Poda(poda) => poda.params().iterations_per_frame,
        AnyDriver::Physics(_) => {
            return Err(PresetError::new(
                "scenario.engine",
                "physics creatures are timed in steps per second by the step benchmark",
            ));
        }
        AnyDriver::Thesis(_) | AnyDriver::Track(_) => creature.scenario.thesis.iterations_per_frame,
    };
    Ok((driver, iterations_per_frame))
}

/// Times the driver of `creature`'s engine per `options` (`mode` and
/// `method` apply to the thesis driver); `clock_ms` reads a monotonic clock in
/// milliseconds. `iterations_per_frame` is the most IK iterations a frame may
/// run (per leg for PODA).
///
/// # Errors
/// Bad options, or a creature whose thesis parameters cannot drive it.
pub fn time_frames(
    creature: &Creature,
    options: &FrameBenchOptions,
    clock_ms: &mut dyn FnMut() -> f64,
) -> Result<FrameTiming, PresetError> {
    check_options(options)?;
    let (mut driver, iterations_per_frame) = frame_driver(creature, options)?;
    for _ in 0..options.warmup_frames {
        driver.step(options.frame_s);
    }
    let mut samples = Vec::with_capacity(options.repeats);
    for _ in 0..options.repeats {
        let start = clock_ms();
        for _ in 0..options.frames {
            driver.step(options.frame_s);
        }
        samples.push((clock_ms() - start) * 1e3 / options.frames as f64);
    }
    let (median_us, best_us) = median_and_best(&mut samples);
    Ok(FrameTiming {
        median_us,
        best_us,
        iterations_per_frame,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn human() -> Creature {
        crate::test_presets::bundled("human")
    }

    #[test]
    fn a_fake_clock_gives_exact_per_frame_times() {
        // Each clock read advances 3 ms: a repeat spans one read pair = 3 ms over 30 frames.
        let mut now = 0.0;
        let mut clock = || {
            now += 3.0;
            now
        };
        let options = FrameBenchOptions {
            frames: 30,
            repeats: 4,
            warmup_frames: 2,
            ..FrameBenchOptions::default()
        };
        let creature = human();
        let timing = time_frames(&creature, &options, &mut clock).expect("bench runs");
        assert!((timing.median_us - 100.0).abs() < 1e-9, "{timing:?}");
        assert!((timing.best_us - 100.0).abs() < 1e-9, "{timing:?}");
        assert_eq!(
            timing.iterations_per_frame,
            creature.scenario.thesis.iterations_per_frame
        );
    }

    #[test]
    fn absurd_options_name_their_field() {
        let mut clock = || 0.0;
        for (options, field) in [
            (
                FrameBenchOptions {
                    frames: 0,
                    ..FrameBenchOptions::default()
                },
                "frames",
            ),
            (
                FrameBenchOptions {
                    repeats: MAX_BENCH_REPEATS + 1,
                    ..FrameBenchOptions::default()
                },
                "repeats",
            ),
            (
                FrameBenchOptions {
                    frame_s: f64::NAN,
                    ..FrameBenchOptions::default()
                },
                "frame_s",
            ),
        ] {
            let error = time_frames(&human(), &options, &mut clock).expect_err("rejected");
            assert_eq!(error.path, field);
        }
    }

    #[test]
    fn median_and_best_of_odd_and_empty_samples() {
        assert_eq!(median_and_best(&mut [5.0, 1.0, 3.0]), (3.0, 1.0));
        let (m, b) = median_and_best(&mut []);
        assert!(m.is_nan() && b.is_nan());
    }
}
