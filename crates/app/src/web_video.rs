//! Video recording of the 3-D view (wasm32 only), the browser's form of She
//! 2006 §6.2's recording panel ("record each frame of animation and create a
//! movie file … at the frame size they want"). Each displayed frame, the view's
//! rectangle of the app canvas is drawn, fitted and centred, into an offscreen
//! canvas of the chosen size; `captureStream` + `MediaRecorder` encode it as
//! WebM, offered as a download when the recording stops.
//!
//! The copy runs in its own `requestAnimationFrame` callback, first scheduled
//! from a microtask after eframe's frame callback has queued the next one, so
//! within every frame it runs after eframe has painted and before the browser
//! composites (the drawing buffer still holds the new frame on both WebGL2
//! and WebGPU).

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::web_download::offer_blob;

/// Container and codec choices, best first.
const MIME_TYPES: [&str; 4] = [
    "video/webm;codecs=vp9",
    "video/webm;codecs=vp8",
    "video/webm",
    "video/mp4",
];

/// Encoder bit rate, bits per second.
const BITS_PER_SECOND: u32 = 8_000_000;

/// Background of the letterbox around a view whose aspect differs from the frame's.
const LETTERBOX: &str = "#15171c";

type FrameLoop = Rc<RefCell<Option<Closure<dyn FnMut()>>>>;

/// A recording in progress.
pub struct VideoRecorder {
    recorder: web_sys::MediaRecorder,
    /// The view rectangle on the app canvas, physical pixels `[x, y, w, h]`.
    rect: Rc<Cell<[f32; 4]>>,
    running: Rc<Cell<bool>>,
    frames: Rc<Cell<u64>>,
    /// Keeps the frame loop's closure alive (and lets it re-arm itself).
    _frame_loop: FrameLoop,
}

fn even(x: f32) -> u32 {
    // Encoders want even sizes; at least 2 × 2.
    ((x.max(2.0) as u32) / 2) * 2
}

fn context_2d(
    canvas: &web_sys::HtmlCanvasElement,
) -> Result<web_sys::CanvasRenderingContext2d, JsValue> {
    canvas
        .get_context("2d")?
        .ok_or("the browser gave no 2-D canvas context")?
        .dyn_into::<web_sys::CanvasRenderingContext2d>()
        .map_err(|_| JsValue::from_str("unexpected 2-D context type"))
}

/// Draws the view rectangle of `source` into `target`, fitted and centred.
fn copy_view(
    source: &web_sys::HtmlCanvasElement,
    target: &web_sys::HtmlCanvasElement,
    context: &web_sys::CanvasRenderingContext2d,
    rect: [f32; 4],
) {
    let [x, y, w, h] = rect.map(f64::from);
    if !(w >= 1.0 && h >= 1.0) {
        return;
    }
    let (tw, th) = (f64::from(target.width()), f64::from(target.height()));
    let scale = (tw / w).min(th / h);
    let (dw, dh) = (w * scale, h * scale);
    context.set_fill_style_str(LETTERBOX);
    context.fill_rect(0.0, 0.0, tw, th);
    let _ = context.draw_image_with_html_canvas_element_and_sw_and_sh_and_dx_and_dy_and_dw_and_dh(
        source,
        x,
        y,
        w,
        h,
        (tw - dw) / 2.0,
        (th - dh) / 2.0,
        dw,
        dh,
    );
}

impl VideoRecorder {
    /// Starts recording the view rectangle `rect` of `source` at `size`
    /// (pixels; `None`: the rectangle's own size). The file is offered as
    /// `file_name` (its extension follows the container the browser picked).
    ///
    /// # Errors
    /// If the browser cannot capture canvases or has no WebM/MP4 encoder.
    pub fn start(
        source: web_sys::HtmlCanvasElement,
        rect: [f32; 4],
        size: Option<(u32, u32)>,
        file_name: String,
    ) -> Result<Self, String> {
        let describe = |e: JsValue| e.as_string().unwrap_or_else(|| format!("{e:?}"));
        let document = web_sys::window()
            .and_then(|w| w.document())
            .ok_or("no document")?;
        let (width, height) = size.unwrap_or((even(rect[2]), even(rect[3])));
        let target = document
            .create_element("canvas")
            .map_err(describe)?
            .dyn_into::<web_sys::HtmlCanvasElement>()
            .map_err(|_| "could not create a canvas".to_owned())?;
        target.set_width(width);
        target.set_height(height);
        let context = context_2d(&target).map_err(describe)?;

        let mime = MIME_TYPES
            .into_iter()
            .find(|m| web_sys::MediaRecorder::is_type_supported(m))
            .ok_or("this browser cannot encode video (no WebM or MP4 MediaRecorder)")?;
        let stream = target.capture_stream().map_err(describe)?;
        let options = web_sys::MediaRecorderOptions::new();
        options.set_mime_type(mime);
        options.set_video_bits_per_second(BITS_PER_SECOND);
        let recorder = web_sys::MediaRecorder::new_with_media_stream_and_media_recorder_options(
            &stream, &options,
        )
        .map_err(describe)?;

        let chunks = js_sys::Array::new();
        let on_data = {
            let chunks = chunks.clone();
            Closure::<dyn FnMut(web_sys::BlobEvent)>::new(move |event: web_sys::BlobEvent| {
                if let Some(blob) = event.data()
                    && blob.size() > 0.0
                {
                    chunks.push(&blob);
                }
            })
        };
        recorder.set_ondataavailable(Some(on_data.as_ref().unchecked_ref()));
        on_data.forget();
        let extension = if mime.starts_with("video/mp4") {
            "mp4"
        } else {
            "webm"
        };
        let file_name = format!("{file_name}.{extension}");
        let container = mime.split(';').next().unwrap_or(mime).to_owned();
        let on_stop = Closure::once_into_js(move || {
            let options = web_sys::BlobPropertyBag::new();
            options.set_type(&container);
            match web_sys::Blob::new_with_blob_sequence_and_options(&chunks, &options) {
                Ok(blob) => {
                    if let Err(e) = offer_blob(&blob, &file_name) {
                        web_sys::console::error_1(&e);
                    }
                }
                Err(e) => web_sys::console::error_1(&e),
            }
        });
        recorder.set_onstop(Some(on_stop.unchecked_ref()));
        recorder.start_with_time_slice(1000).map_err(describe)?;

        let rect = Rc::new(Cell::new(rect));
        let running = Rc::new(Cell::new(true));
        let frames = Rc::new(Cell::new(0));
        let frame_loop: FrameLoop = Rc::new(RefCell::new(None));
        {
            let rect = Rc::clone(&rect);
            let running = Rc::clone(&running);
            let frames = Rc::clone(&frames);
            let again = Rc::clone(&frame_loop);
            *frame_loop.borrow_mut() = Some(Closure::<dyn FnMut()>::new(move || {
                if !running.get() {
                    // Break the closure's cycle so it can be dropped.
                    again.borrow_mut().take();
                    return;
                }
                copy_view(&source, &target, &context, rect.get());
                frames.set(frames.get() + 1);
                request_frame(&again);
            }));
        }
        // First arm from a microtask: after eframe's frame callback has queued its own next frame.
        let first = Rc::clone(&frame_loop);
        let arm = Closure::once_into_js(move || request_frame(&first));
        if let Some(window) = web_sys::window() {
            window.queue_microtask(arm.unchecked_ref());
        }
        Ok(Self {
            recorder,
            rect,
            running,
            frames,
            _frame_loop: frame_loop,
        })
    }

    /// Follows the view when it moves or resizes.
    pub fn set_rect(&self, rect: [f32; 4]) {
        self.rect.set(rect);
    }

    /// Frames copied so far.
    #[must_use]
    pub fn frames(&self) -> u64 {
        self.frames.get()
    }

    /// Stops; the file is offered once the encoder has flushed.
    pub fn stop(self) {
        self.running.set(false);
        if self.recorder.state() != web_sys::RecordingState::Inactive {
            let _ = self.recorder.stop();
        }
    }
}

fn request_frame(frame_loop: &FrameLoop) {
    let Some(window) = web_sys::window() else {
        return;
    };
    if let Some(callback) = frame_loop.borrow().as_ref() {
        let _ = window.request_animation_frame(callback.as_ref().unchecked_ref());
    }
}
