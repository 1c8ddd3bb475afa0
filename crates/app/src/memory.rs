//! Memory figures for `state()` and the browser soak test (issue 7 item 3:
//! wasm memory must not grow by more than 10 % after warm-up).
//!
//! - The WebAssembly module's linear memory: it only grows, so its size is the
//!   high-water mark of the Rust heap plus the allocator's fragmentation.
//! - The Rust heap itself: in the browser every allocation goes through
//!   `Counting`, which adds up the bytes live now and the most ever live, so a
//!   leak (live bytes climbing) can be told from a one-off peak.
//!
//! Natively there is no linear memory and the system allocator is left alone
//! (`crates/app/tests/memory_steady.rs` counts the native heap its own way).

#[cfg(target_arch = "wasm32")]
mod counting {
    #![allow(unsafe_code)] // a global allocator must implement an unsafe trait

    use std::alloc::{GlobalAlloc, Layout, System};
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Bytes allocated and not yet freed.
    pub static LIVE_BYTES: AtomicUsize = AtomicUsize::new(0);
    /// The most bytes ever live at once.
    pub static PEAK_BYTES: AtomicUsize = AtomicUsize::new(0);

    /// Forwards to the system allocator and keeps [`LIVE_BYTES`] and [`PEAK_BYTES`].
    pub struct Counting;

    fn grew(bytes: usize) {
        let live = LIVE_BYTES.fetch_add(bytes, Ordering::Relaxed) + bytes;
        PEAK_BYTES.fetch_max(live, Ordering::Relaxed);
    }

    // SAFETY: every call forwards to `System` with the caller's layout and
    // pointer unchanged; the counters never affect what is returned.
    unsafe impl GlobalAlloc for Counting {
        unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
            // SAFETY: the caller upholds `GlobalAlloc::alloc`'s contract.
            let ptr = unsafe { System.alloc(layout) };
            if !ptr.is_null() {
                grew(layout.size());
            }
            ptr
        }

        unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
            // SAFETY: as for `alloc`.
            let ptr = unsafe { System.alloc_zeroed(layout) };
            if !ptr.is_null() {
                grew(layout.size());
            }
            ptr
        }

        unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
            LIVE_BYTES.fetch_sub(layout.size(), Ordering::Relaxed);
            // SAFETY: `ptr` came from this allocator with this layout.
            unsafe { System.dealloc(ptr, layout) }
        }

        unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
            // SAFETY: the caller upholds `GlobalAlloc::realloc`'s contract.
            let moved = unsafe { System.realloc(ptr, layout, new_size) };
            if !moved.is_null() {
                LIVE_BYTES.fetch_sub(layout.size(), Ordering::Relaxed);
                grew(new_size);
            }
            moved
        }
    }

    #[global_allocator]
    static ALLOCATOR: Counting = Counting;
}

/// Bytes of linear memory in the browser; `None` natively.
#[must_use]
pub fn wasm_memory_bytes() -> Option<f64> {
    #[cfg(target_arch = "wasm32")]
    {
        use wasm_bindgen::JsCast;
        let memory = wasm_bindgen::memory()
            .dyn_into::<js_sys::WebAssembly::Memory>()
            .ok()?;
        let buffer = memory.buffer().dyn_into::<js_sys::ArrayBuffer>().ok()?;
        Some(f64::from(buffer.byte_length()))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        None
    }
}

/// The Rust heap in the browser, bytes: `(live now, most ever live)`; `None` natively.
#[must_use]
pub fn wasm_heap_bytes() -> Option<(usize, usize)> {
    #[cfg(target_arch = "wasm32")]
    {
        use std::sync::atomic::Ordering;
        Some((
            counting::LIVE_BYTES.load(Ordering::Relaxed),
            counting::PEAK_BYTES.load(Ordering::Relaxed),
        ))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        None
    }
}
