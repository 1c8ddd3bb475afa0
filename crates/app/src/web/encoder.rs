//! What the two video encoders share (wasm32 only): the bit rate they are asked for, and JS
//! errors as text.

use wasm_bindgen::prelude::*;

/// Bit rate asked of either encoder, bits per second.
pub(crate) const BITS_PER_SECOND: u32 = 8_000_000;

/// A thrown JS value as text: itself if a string, else its `message` (an
/// `Error`, a `DOMException`), else its debug form.
pub(crate) fn describe(error: &JsValue) -> String {
    error
        .as_string()
        .or_else(|| {
            js_sys::Reflect::get(error, &"message".into())
                .ok()
                .and_then(|m| m.as_string())
        })
        .unwrap_or_else(|| format!("{error:?}"))
}
