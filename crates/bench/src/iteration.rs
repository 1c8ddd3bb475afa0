//! µs per IK iteration — forward kinematics, Jacobian, solve and update, the
//! unit of She 2006 §4.4's per-frame cost — timed over the targets of the
//! preset's own thesis walk (§5.2.2), so every method chases the same
//! realistic, moving targets from a steady tracking state.

use std::hint::black_box;

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::{IkSolver, Method, Targets};
use gaitlab_core::preset::PresetError;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::{Creature, RootTransform};
use gaitlab_engine::{Overrides, driver_for};

use crate::frame::median_and_best;

/// One frame of recorded targets.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordedFrame {
    /// Root placement in that frame.
    pub root: RootTransform,
    /// Effector targets in that frame.
    pub targets: Targets,
}

/// Median and fastest of the timed repeats, µs per unit of work.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// Median over the repeats, µs.
    pub median_us: f64,
    /// Fastest repeat, µs.
    pub best_us: f64,
}

impl Timing {
    /// The median and best of `samples` (µs each; NaN when empty).
    #[must_use]
    pub fn of(mut samples: Vec<f64>) -> Self {
        let (median_us, best_us) = median_and_best(&mut samples);
        Self { median_us, best_us }
    }
}

/// Records `frames` frames of `frame_s` seconds of the preset's thesis walk as
/// a target sequence.
///
/// # Errors
/// The preset's thesis parameters cannot drive its skeleton (path under
/// `scenario.thesis`).
pub fn record_walk(
    creature: &Creature,
    frames: usize,
    frame_s: f64,
) -> Result<Vec<RecordedFrame>, PresetError> {
    let overrides = Overrides {
        mode: Some(ThesisMode::Walk),
        ..Overrides::default()
    };
    let mut driver = driver_for(creature, &overrides)?;
    let mut recorded = Vec::with_capacity(frames);
    for _ in 0..frames {
        driver.step(frame_s);
        if let Some(targets) = driver.targets() {
            recorded.push(RecordedFrame {
                root: driver.pose().root,
                targets: targets.clone(),
            });
        }
    }
    Ok(recorded)
}

/// µs per IK iteration of `method` over `frames` (`iterations` per frame,
/// `repeats` timed passes after a 60-frame warm-up); `clock_ms` reads a
/// monotonic clock in milliseconds. The solver and joint values carry over
/// from frame to frame, as in the driver.
pub fn time_iterations(
    creature: &Creature,
    frames: &[RecordedFrame],
    method: Method,
    iterations: usize,
    repeats: usize,
    clock_ms: &mut dyn FnMut() -> f64,
) -> Timing {
    let mut options = creature.scenario.ik_options();
    options.method = method;
    let skeleton = &creature.skeleton;
    let mut solver = IkSolver::new(skeleton, options);
    let mut values = skeleton.rest_values();
    let iterations = iterations.max(1);
    for frame in frames.iter().take(60) {
        for _ in 0..iterations {
            black_box(solver.iterate(skeleton, &frame.root, &mut values, &frame.targets));
        }
    }
    let work = (frames.len() * iterations).max(1) as f64;
    let samples = (0..repeats.max(1))
        .map(|_| {
            let start = clock_ms();
            for frame in frames {
                for _ in 0..iterations {
                    black_box(solver.iterate(skeleton, &frame.root, &mut values, &frame.targets));
                }
            }
            (clock_ms() - start) * 1e3 / work
        })
        .collect();
    Timing::of(samples)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn human() -> Creature {
        crate::test_presets::bundled("human")
    }

    #[test]
    fn the_walk_gives_one_target_set_per_frame() {
        let creature = human();
        let frames = record_walk(&creature, 30, 1.0 / 60.0).expect("records");
        assert_eq!(frames.len(), 30);
        assert_eq!(
            frames[0].targets.position.len(),
            creature.skeleton.effector_count()
        );
        // The targets move: the walk is not a still pose.
        assert_ne!(frames[0].targets.position, frames[29].targets.position);
    }

    #[test]
    fn a_fake_clock_gives_exact_per_iteration_times() {
        // Each read advances 2 ms; one repeat spans 2 ms over 20 frames × 4 iterations = 25 µs.
        let mut now = 0.0;
        let mut clock = || {
            now += 2.0;
            now
        };
        let creature = human();
        let frames = record_walk(&creature, 20, 1.0 / 60.0).expect("records");
        let timing = time_iterations(&creature, &frames, Method::Dls, 4, 3, &mut clock);
        assert!((timing.median_us - 25.0).abs() < 1e-9, "{timing:?}");
        assert!((timing.best_us - 25.0).abs() < 1e-9, "{timing:?}");
    }
}
