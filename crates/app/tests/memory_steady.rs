//! The lab's heap stays flat over hours of use (issue 7 item 3, the native
//! half of the browser soak): cycling presets, engines, modes, methods, gaits
//! and side-by-side comparisons, every pass after the warm-up pass (the
//! first: lazily built caches) leaves exactly as many bytes allocated as the
//! second. A counting global allocator measures the
//! live bytes; the browser soak (tests/e2e/soak.test.mjs) measures the wasm
//! memory and JS heap of the whole page.
//! Native only: in the browser build the app installs its own counting
//! allocator (`gaitlab_app::memory`), and there can be only one.
#![cfg(not(target_arch = "wasm32"))]
#![allow(unsafe_code)] // the counting allocator forwards to the system allocator

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicIsize, Ordering};

use gaitlab_app::{App, Settings};

struct Counting;

static LIVE_BYTES: AtomicIsize = AtomicIsize::new(0);

// SAFETY: every call forwards to `System` with the caller's layout unchanged.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        LIVE_BYTES.fetch_add(layout.size() as isize, Ordering::Relaxed);
        // SAFETY: the caller upholds `GlobalAlloc::alloc`'s contract.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE_BYTES.fetch_sub(layout.size() as isize, Ordering::Relaxed);
        // SAFETY: `ptr` came from `alloc` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The soak's switches, as commands.
fn cycle() -> Vec<String> {
    let mut commands = Vec::new();
    for preset in ["human", "ik-quadruped"] {
        for mode in ["walk", "run", "wounded-walk", "wounded-run"] {
            for method in ["transpose", "pinv", "dls", "sdls", "ccd"] {
                commands.push(format!(
                    r#"{{"compare": false, "preset": "{preset}", "mode": "{mode}", "method": "{method}"}}"#
                ));
            }
        }
        commands.push(format!(
            r#"{{"preset": "{preset}", "compare": {{"views": ["transpose", "pinv", "dls-ns", "ccd"], "scenario": "singularity"}}}}"#
        ));
    }
    for (preset, gaits) in [
        ("poda-quadruped", &["walk", "trot", "rotary_gallop"][..]),
        ("hexapod", &["tripod", "wave"][..]),
        ("raibert-biped", &["run", "gallop"][..]),
        ("raibert-quadruped", &["trot", "bound"][..]),
        ("raibert-kangaroo", &["hop"][..]),
    ] {
        for gait in gaits {
            commands.push(format!(
                r#"{{"compare": false, "preset": "{preset}", "gait": "{gait}"}}"#
            ));
        }
    }
    commands
}

#[test]
fn repeated_passes_over_every_switch_leave_the_heap_as_it_was_after_warm_up() {
    let commands = cycle();
    let mut lab = App::new(Settings::default());
    let mut live = Vec::new();
    for _pass in 0..4 {
        for command in &commands {
            if let Err(error) = lab.command(command) {
                panic!("{command}: {error}");
            }
            for _ in 0..40 {
                lab.advance(1.0 / 60.0);
            }
            assert!(
                lab.last_error().is_none(),
                "{command}: {:?}",
                lab.last_error()
            );
            drop(lab.state_json());
        }
        live.push(LIVE_BYTES.load(Ordering::Relaxed));
    }
    println!("live heap after each pass: {live:?} bytes");
    assert!(live[0] > 0);
    assert_eq!(live[2], live[1], "the third pass grew the heap: {live:?}");
    assert_eq!(live[3], live[1], "the fourth pass grew the heap: {live:?}");
}
