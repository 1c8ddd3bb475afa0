//! Video recording of the 3-D view (wasm32 only), the browser's form of She
//! 2006 §6.2's recording panel ("record each frame of animation and create a
//! movie file … at the frame size they want"). Each displayed frame, the view's
//! rectangle of the app canvas is drawn, fitted and centred, into an offscreen
//! canvas of the chosen size, and that canvas goes to an encoder: WebCodecs
//! into a WebM with a duration and cues ([`super::codecs`]) where the
//! browser has it, `MediaRecorder` ([`super::media_recorder`]) otherwise.
//! The file is offered as a download when the recording stops.
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

use super::codecs::{self, CodecEncoder};
use super::download::offer_blob;
use super::encoder::describe;
use super::media_recorder::MediaSink;

/// Background of the letterbox around a view whose aspect differs from the frame's.
const LETTERBOX: &str = "#15171c";

type FrameLoop = Rc<RefCell<Option<Closure<dyn FnMut()>>>>;

/// Where the recorder reports errors that happen after its call returned
/// (the encoder failing, the file not being written); the page shows them.
pub type ErrorSlot = Rc<RefCell<Option<String>>>;

/// The encoder the copied frames go to.
enum Sink {
    /// Waiting for the browser to say which codec it can encode.
    Opening,
    Codecs(CodecEncoder),
    Media(MediaSink),
    /// Stopped, or failed to open.
    Closed,
}

impl Sink {
    fn name(&self) -> &'static str {
        match self {
            Self::Opening => "starting",
            Self::Codecs(encoder) => encoder.name(),
            Self::Media(_) => "mediarecorder",
            Self::Closed => "",
        }
    }
}

/// A recording in progress.
pub struct VideoRecorder {
    sink: Rc<RefCell<Sink>>,
    /// The copy canvas, and its 2-D context.
    target: web_sys::HtmlCanvasElement,
    context: web_sys::CanvasRenderingContext2d,
    /// The view rectangle on the app canvas, physical pixels `[x, y, w, h]`.
    rect: Rc<Cell<[f32; 4]>>,
    running: Rc<Cell<bool>>,
    frames: Rc<Cell<u64>>,
    /// When the first frame was recorded, page clock µs.
    first_us: Rc<Cell<Option<f64>>>,
    file_name: String,
    errors: ErrorSlot,
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

/// The page clock, microseconds.
fn now_us() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now() * 1000.0)
}

fn report(errors: &ErrorSlot, message: String) {
    errors.borrow_mut().get_or_insert(message);
}

/// Offers the finished WebM `bytes` as `file_name`.
fn offer_webm(bytes: &[u8], file_name: &str) -> Result<(), JsValue> {
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("video/webm");
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)?;
    offer_blob(&blob, file_name)
}

impl VideoRecorder {
    /// Starts recording the view rectangle `rect` of `source` at `size`
    /// (pixels; `None`: the rectangle's own size). The file is offered as
    /// `file_name` (its extension follows the container). Errors after this
    /// call returns go to `errors`.
    ///
    /// # Errors
    /// If the browser cannot make the copy canvas or has no video encoder.
    pub fn start(
        source: web_sys::HtmlCanvasElement,
        rect: [f32; 4],
        size: Option<(u32, u32)>,
        file_name: String,
        errors: ErrorSlot,
    ) -> Result<Self, String> {
        let document = web_sys::window()
            .and_then(|w| w.document())
            .ok_or("no document")?;
        let (width, height) = size.unwrap_or((even(rect[2]), even(rect[3])));
        let target = document
            .create_element("canvas")
            .map_err(|e| describe(&e))?
            .dyn_into::<web_sys::HtmlCanvasElement>()
            .map_err(|_| "could not create a canvas".to_owned())?;
        target.set_width(width);
        target.set_height(height);
        let context = context_2d(&target).map_err(|e| describe(&e))?;

        let running = Rc::new(Cell::new(true));
        let sink = if codecs::available() {
            let sink = Rc::new(RefCell::new(Sink::Opening));
            let (sink_, running_, errors_) =
                (Rc::clone(&sink), Rc::clone(&running), Rc::clone(&errors));
            let (target_, name_) = (target.clone(), file_name.clone());
            wasm_bindgen_futures::spawn_local(async move {
                let opened = CodecEncoder::open(width, height).await;
                if !running_.get() {
                    return;
                }
                let next = match opened {
                    Ok(Some(encoder)) => Ok(Sink::Codecs(encoder)),
                    // No VP9/VP8 in WebCodecs: MediaRecorder may still encode something.
                    Ok(None) => MediaSink::start(&target_, &name_).map(Sink::Media),
                    Err(e) => Err(format!("video: {e}")),
                };
                *sink_.borrow_mut() = next.unwrap_or_else(|e| {
                    report(&errors_, e);
                    Sink::Closed
                });
            });
            sink
        } else {
            Rc::new(RefCell::new(Sink::Media(MediaSink::start(
                &target, &file_name,
            )?)))
        };

        let rect = Rc::new(Cell::new(rect));
        let frames = Rc::new(Cell::new(0));
        let first_us = Rc::new(Cell::new(None));
        let frame_loop: FrameLoop = Rc::new(RefCell::new(None));
        {
            let rect = Rc::clone(&rect);
            let running = Rc::clone(&running);
            let frames = Rc::clone(&frames);
            let first_us = Rc::clone(&first_us);
            let sink = Rc::clone(&sink);
            let errors = Rc::clone(&errors);
            let again = Rc::clone(&frame_loop);
            let (target, context) = (target.clone(), context.clone());
            *frame_loop.borrow_mut() = Some(Closure::<dyn FnMut()>::new(move || {
                if !running.get() {
                    // Break the closure's cycle so it can be dropped.
                    again.borrow_mut().take();
                    return;
                }
                copy_view(&source, &target, &context, rect.get());
                let now = now_us();
                let recorded = match &mut *sink.borrow_mut() {
                    Sink::Opening | Sink::Closed => Ok(false),
                    Sink::Media(_) => Ok(true),
                    Sink::Codecs(encoder) => encoder.encode(&target, now, false),
                };
                match recorded {
                    Ok(true) => {
                        frames.set(frames.get() + 1);
                        if first_us.get().is_none() {
                            first_us.set(Some(now));
                        }
                    }
                    Ok(false) => {}
                    Err(e) => report(&errors, format!("video: {e}")),
                }
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
            sink,
            target,
            context,
            rect,
            running,
            frames,
            first_us,
            file_name,
            errors,
            _frame_loop: frame_loop,
        })
    }

    /// Follows the view when it moves or resizes.
    pub fn set_rect(&self, rect: [f32; 4]) {
        self.rect.set(rect);
    }

    /// Frames recorded so far.
    #[must_use]
    pub fn frames(&self) -> u64 {
        self.frames.get()
    }

    /// Seconds since the first recorded frame (0 before it).
    #[must_use]
    pub fn seconds(&self) -> f64 {
        self.first_us
            .get()
            .map_or(0.0, |first| (now_us() - first).max(0.0) / 1e6)
    }

    /// Frames the encoder skipped because it had fallen behind.
    #[must_use]
    pub fn skipped(&self) -> u64 {
        match &*self.sink.borrow() {
            Sink::Codecs(encoder) => encoder.skipped(),
            _ => 0,
        }
    }

    /// The encoder in use: `webcodecs-vp9`, `webcodecs-vp8`, `mediarecorder`,
    /// or `starting` while the browser is asked.
    #[must_use]
    pub fn encoder(&self) -> &'static str {
        self.sink.borrow().name()
    }

    /// Stops; the file is offered once the encoder has finished. The last
    /// picture is held until now, so the file lasts as long as the recording.
    pub fn stop(self) {
        self.running.set(false);
        let sink = std::mem::replace(&mut *self.sink.borrow_mut(), Sink::Closed);
        match sink {
            Sink::Codecs(mut encoder) => {
                if let Err(e) = encoder.encode(&self.target, now_us(), true) {
                    report(&self.errors, format!("video: {e}"));
                }
                let (errors, file_name) = (self.errors, format!("{}.webm", self.file_name));
                wasm_bindgen_futures::spawn_local(async move {
                    let written = encoder.finish().await.and_then(|bytes| {
                        offer_webm(&bytes, &file_name)
                            .map_err(|e| format!("the browser refused the download: {e:?}"))
                    });
                    if let Err(e) = written {
                        report(&errors, format!("video: {e}"));
                    }
                });
            }
            Sink::Media(media) => media.stop(&self.target, &self.context),
            Sink::Opening => report(
                &self.errors,
                "video: stopped before the encoder was ready; nothing was recorded".to_owned(),
            ),
            Sink::Closed => {}
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
