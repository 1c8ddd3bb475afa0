//! Hands a file to the person in the browser (wasm32 only): a Blob, an object
//! URL and a clicked `<a download>`, the standard way a static page saves a file.

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// Offers `blob` as a download named `file_name`.
///
/// # Errors
/// If the page has no document or the browser refuses the object URL.
pub fn offer_blob(blob: &web_sys::Blob, file_name: &str) -> Result<(), JsValue> {
    let window = web_sys::window().ok_or("no window")?;
    let document = window.document().ok_or("no document")?;
    let url = web_sys::Url::create_object_url_with_blob(blob)?;
    let anchor = document
        .create_element("a")?
        .dyn_into::<web_sys::HtmlAnchorElement>()
        .map_err(|_| JsValue::from_str("could not create a link element"))?;
    anchor.set_href(&url);
    anchor.set_download(file_name);
    anchor.click();
    // The click has started the download; the URL can go once this task ends.
    let revoke = Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&url);
    });
    window.set_timeout_with_callback_and_timeout_and_arguments_0(revoke.unchecked_ref(), 1000)?;
    Ok(())
}

/// Offers `text` as a download named `file_name` of type `mime`.
///
/// # Errors
/// As [`offer_blob`].
pub fn offer_text(text: &str, file_name: &str, mime: &str) -> Result<(), JsValue> {
    let parts = js_sys::Array::of1(&JsValue::from_str(text));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &options)?;
    offer_blob(&blob, file_name)
}
