//! The per-frame hot path allocates nothing (DESIGN.md "Hot loops allocate
//! nothing per frame"): a counting global allocator watches the thesis, track
//! and PODA drivers step after their first frames.

mod common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use gaitlab_core::Kinematics;
use gaitlab_core::driver::Driver;
use gaitlab_core::export::TargetTrack;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_motion::{ThesisDriver, TrackDriver, TrackOptions};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

#[expect(unsafe_code, reason = "counting allocations needs a GlobalAlloc")]
// SAFETY: every call is forwarded unchanged to the system allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations made while `f` runs.
fn allocations_during(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    f();
    ALLOCATIONS.load(Ordering::Relaxed) - before
}

#[test]
fn stepping_the_drivers_allocates_nothing() {
    poda_driver_allocates_nothing();
    key_centres_allocate_nothing();
    let skeleton = common::human();
    for method in Method::ALL {
        for mode in ThesisMode::ALL {
            let options = IkOptions {
                method,
                ..IkOptions::default()
            };
            let mut driver =
                match ThesisDriver::new(skeleton.clone(), common::human_params(), mode, options) {
                    Ok(driver) => driver,
                    Err(error) => panic!("{error}"),
                };
            for _ in 0..5 {
                driver.step(1.0 / 60.0);
            }
            let count = allocations_during(|| {
                for _ in 0..120 {
                    driver.step(1.0 / 60.0);
                }
                driver.set_mode(ThesisMode::Walk);
                driver.step(1.0 / 60.0);
            });
            assert_eq!(
                count,
                0,
                "{} {}: {count} allocations in 121 frames",
                method.name(),
                mode.name()
            );
        }
    }

    // Recorded targets: one row per 0.1 s of the rest pose, slightly raised.
    let rest = Kinematics::of(
        &skeleton,
        &gaitlab_core::Pose {
            root: gaitlab_core::RootTransform::default(),
            joints: skeleton.rest_values(),
        },
    );
    let mut times = Vec::new();
    let mut positions = Vec::new();
    for row in 0..20 {
        times.push(f64::from(row) * 0.1);
        positions.extend(
            rest.effector_position
                .iter()
                .map(|p| *p + glam::DVec3::Y * 0.002 * f64::from(row)),
        );
    }
    let track = match TargetTrack::new(times, positions, skeleton.effector_count()) {
        Ok(track) => track,
        Err(error) => panic!("{error}"),
    };
    let mut tracker = match TrackDriver::new(skeleton.clone(), track, TrackOptions::default()) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    tracker.step(1.0 / 60.0);
    let count = allocations_during(|| {
        for _ in 0..100 {
            tracker.step(1.0 / 60.0);
        }
    });
    assert_eq!(count, 0, "track: {count} allocations in 100 frames");
}

/// The PODA driver's frames, run from the single test above: the counter is
/// global, so a second test (or the harness reporting it) would disturb it.
fn poda_driver_allocates_nothing() {
    use gaitlab_core::preset::load_bundled;
    use gaitlab_motion::PodaDriver;
    for preset in ["poda-quadruped", "poda-biped", "hexapod", "insect-14"] {
        let creature = match load_bundled(preset) {
            Some(Ok(creature)) => creature,
            _ => panic!("{preset} is bundled and valid"),
        };
        let mut driver = match PodaDriver::new(&creature) {
            Ok(driver) => driver,
            Err(error) => panic!("{preset}: {error}"),
        };
        // Warm up over two cycles: the body plan and metrics reach their size.
        for _ in 0..150 {
            driver.step(1.0 / 60.0);
        }
        // The quadruped's 9-joint legs hold their feet's orientation (eq. 2's
        // six rows): its frames cover that path of the IK.
        let holding = driver.metrics().orientation_legs().count();
        assert_eq!(
            holding,
            if preset == "poda-quadruped" { 4 } else { 0 },
            "{preset}"
        );
        let count = allocations_during(|| {
            for _ in 0..240 {
                driver.step(1.0 / 60.0);
            }
        });
        assert_eq!(count, 0, "{preset}: {count} allocations in 240 frames");
        // A gait change allocates once (the named gait's table and the legs' cycles), then the legs taking it on do not.
        if preset == "poda-quadruped" {
            if let Err(error) = driver.set_gait("rotary_gallop") {
                panic!("{error}");
            }
            let count = allocations_during(|| {
                for _ in 0..120 {
                    driver.step(1.0 / 60.0);
                }
            });
            assert_eq!(
                count, 0,
                "{preset}: {count} allocations while the legs take the gait on"
            );
        }
    }
}

/// Key leg positions with centre angles: the key-centres stage evaluates its
/// splines in a scratch buffer the driver owns (the bundled quadruped with
/// every knee given a centre on the middle key).
fn key_centres_allocate_nothing() {
    use gaitlab_core::preset::load_bundled;
    use gaitlab_core::preset::poda::KeyCenters;
    use gaitlab_motion::PodaDriver;
    let Some(Ok(creature)) = load_bundled("poda-quadruped") else {
        panic!("poda-quadruped is bundled and valid");
    };
    let mut params = creature.scenario.poda_params();
    let middle: KeyCenters = [
        ("3", [-1.2, 1.0]),
        ("left_hind_knee_x", [1.2, 1.0]),
        ("right_hind_knee_x", [1.2, 1.0]),
    ]
    .iter()
    .map(|(k, v)| ((*k).to_owned(), *v))
    .collect();
    params.transfer_key_centers = vec![KeyCenters::new(), middle, KeyCenters::new()];
    let mut driver = match PodaDriver::with_params(&creature, params) {
        Ok(driver) => driver,
        Err(error) => panic!("{error}"),
    };
    // Warm up over two cycles: the body plan and metrics reach their size.
    for _ in 0..150 {
        driver.step(1.0 / 60.0);
    }
    let count = allocations_during(|| {
        for _ in 0..240 {
            driver.step(1.0 / 60.0);
        }
    });
    assert_eq!(count, 0, "key centres: {count} allocations in 240 frames");
}
