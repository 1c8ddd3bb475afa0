//! The size of the WebAssembly module's linear memory, for `state()` and the
//! browser soak test (issue 7 item 3: wasm memory must not grow by more than
//! 10 % after warm-up). Linear memory only grows, so its size is the high-water
//! mark of the Rust heap. Natively there is none to report.

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
