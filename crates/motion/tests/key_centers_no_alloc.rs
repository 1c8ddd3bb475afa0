//! Key leg positions with centre angles keep PODA's per-frame hot path free
//! of allocations (DESIGN.md "Hot loops allocate nothing per frame"): the
//! key-centres stage evaluates its splines in a scratch buffer the driver
//! owns. A counting global allocator watches the bundled quadruped step with
//! every knee given a centre on the middle key.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use gaitlab_core::driver::Driver;
use gaitlab_core::preset::load_bundled;
use gaitlab_core::preset::poda::KeyCenters;
use gaitlab_motion::PodaDriver;

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

#[test]
fn stepping_with_key_centres_allocates_nothing() {
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
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    for _ in 0..240 {
        driver.step(1.0 / 60.0);
    }
    let count = ALLOCATIONS.load(Ordering::Relaxed) - before;
    assert_eq!(count, 0, "{count} allocations in 240 frames");
}
