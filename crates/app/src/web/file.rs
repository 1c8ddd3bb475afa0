//! Preset files and target recordings (`.csv`, issue 21 item 5) into the
//! browser app (wasm32 only; issue 6 item 3): a hidden
//! `<input type=file id="gaitlab-preset-file">` that "Load file…" clicks, and
//! files dropped on the canvas (eframe hands them over as handles whose bytes
//! arrive asynchronously). Files land in an [`Inbox`] the app empties each
//! frame into [`crate::App::load_file`], which checks the size limit
//! before parsing; a file over the limit is refused here before it is read.

use std::cell::RefCell;
use std::rc::Rc;

use gaitlab_core::preset::MAX_PRESET_BYTES;
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

/// Id of the hidden file input (tests set files on it).
pub const INPUT_ID: &str = "gaitlab-preset-file";

/// A file's name and its bytes, or why they could not be read.
pub type Arrived = (String, Result<Vec<u8>, String>);

/// Files read and waiting for the next frame.
pub type Inbox = Rc<RefCell<Vec<Arrived>>>;

/// The size limit for a file named `name`: a target recording's for a
/// `.csv`, else a preset's; bytes and the limit's words.
fn limit_for(name: &str) -> (usize, String) {
    if name.to_ascii_lowercase().ends_with(".csv") {
        let limit = gaitlab_core::export::MAX_TARGET_CSV_BYTES;
        (limit, format!("{} MiB target-file", limit / (1024 * 1024)))
    } else {
        (
            MAX_PRESET_BYTES,
            format!("{} KiB preset", MAX_PRESET_BYTES / 1024),
        )
    }
}

fn too_big(name: &str, size: f64) -> Option<Arrived> {
    let (limit, words) = limit_for(name);
    #[expect(clippy::cast_precision_loss, reason = "64 MiB is exact in f64")]
    let limit = limit as f64;
    (size > limit).then(|| {
        (
            name.to_owned(),
            Err(format!("{size} bytes, more than the {words} limit")),
        )
    })
}

/// Reads `file` into `inbox` (asynchronously), then asks egui for a frame.
fn read_into(file: web_sys::File, inbox: Inbox, ctx: egui::Context) {
    let name = file.name();
    if let Some(refused) = too_big(&name, file.size()) {
        inbox.borrow_mut().push(refused);
        ctx.request_repaint();
        return;
    }
    wasm_bindgen_futures::spawn_local(async move {
        let result = wasm_bindgen_futures::JsFuture::from(file.array_buffer())
            .await
            .map(|buffer| js_sys::Uint8Array::new(&buffer).to_vec())
            .map_err(|e| format!("the browser could not read it ({e:?})"));
        inbox.borrow_mut().push((name, result));
        ctx.request_repaint();
    });
}

/// Creates the hidden file input (once) and returns it.
///
/// # Errors
/// If the page has no document or body.
pub fn install_input(
    inbox: &Inbox,
    ctx: &egui::Context,
) -> Result<web_sys::HtmlInputElement, JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let input = document
        .create_element("input")?
        .dyn_into::<web_sys::HtmlInputElement>()
        .map_err(|_| JsValue::from_str("could not create a file input"))?;
    input.set_type("file");
    input.set_id(INPUT_ID);
    input.set_accept(".json,application/json,.csv,text/csv");
    input.set_attribute("style", "display:none")?;
    input.set_attribute("aria-label", "Load a preset JSON or target CSV file")?;
    let inbox = Rc::clone(inbox);
    let ctx = ctx.clone();
    let target = input.clone();
    let on_change = Closure::<dyn Fn()>::new(move || {
        if let Some(file) = target.files().and_then(|files| files.get(0)) {
            read_into(file, Rc::clone(&inbox), ctx.clone());
        }
        // Picking the same file again must fire `change` again.
        target.set_value("");
    });
    input.add_event_listener_with_callback("change", on_change.as_ref().unchecked_ref())?;
    on_change.forget();
    document.body().ok_or("no body")?.append_child(&input)?;
    Ok(input)
}

/// Reads the files dropped on the canvas this frame into `inbox`.
pub fn take_dropped(ctx: &egui::Context, inbox: &Inbox) {
    let dropped = ctx.input(|i| i.raw.dropped_files.clone());
    for file in dropped {
        let name = file.path().file_name().map_or_else(
            || "dropped file".to_owned(),
            |n| n.to_string_lossy().into_owned(),
        );
        let inbox = Rc::clone(inbox);
        let ctx = ctx.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let result = file.bytes_async().await;
            inbox.borrow_mut().push((name, result));
            ctx.request_repaint();
        });
    }
}
