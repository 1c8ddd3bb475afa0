//! The fallback video encoder (wasm32 only) for browsers without WebCodecs:
//! `captureStream` on the copy canvas and `MediaRecorder`, saving WebM (or
//! MP4 where that is all the browser encodes).
//!
//! The stream only gets a frame when the canvas changes, and stopping the
//! recorder drops the frames still in its encoder. So stopping redraws the
//! last picture (a hold frame stamped at the moment of stopping) and gives the
//! encoder [`DRAIN_MS`] before the recorder stops: the file then lasts as long
//! as the recording did, unless the machine is too starved to encode in time.
//! The file carries no duration; players find it by reading to the end.

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use super::download::offer_blob;
use super::encoder::{BITS_PER_SECOND, describe};

/// Container and codec choices, best first.
const MIME_TYPES: [&str; 4] = [
    "video/webm;codecs=vp9",
    "video/webm;codecs=vp8",
    "video/webm",
    "video/mp4",
];

/// Time given to the encoder after the hold frame before the recorder stops, ms.
const DRAIN_MS: i32 = 500;

/// A `MediaRecorder` on the copy canvas.
pub struct MediaSink {
    recorder: web_sys::MediaRecorder,
}

impl MediaSink {
    /// Starts recording `canvas`; the file is offered as `file_name` plus the
    /// extension of the container the browser picked.
    ///
    /// # Errors
    /// If the browser cannot capture canvases or has no WebM/MP4 encoder.
    pub fn start(canvas: &web_sys::HtmlCanvasElement, file_name: &str) -> Result<Self, String> {
        let mime = MIME_TYPES
            .into_iter()
            .find(|m| web_sys::MediaRecorder::is_type_supported(m))
            .ok_or("this browser cannot encode video (no WebCodecs, WebM or MP4 MediaRecorder)")?;
        let stream = canvas.capture_stream().map_err(|e| describe(&e))?;
        let options = web_sys::MediaRecorderOptions::new();
        options.set_mime_type(mime);
        options.set_video_bits_per_second(BITS_PER_SECOND);
        let recorder = web_sys::MediaRecorder::new_with_media_stream_and_media_recorder_options(
            &stream, &options,
        )
        .map_err(|e| describe(&e))?;

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
        recorder
            .start_with_time_slice(1000)
            .map_err(|e| describe(&e))?;
        Ok(Self { recorder })
    }

    /// Stops after a hold frame on `canvas` (drawn through `context`); the
    /// file is offered once the recorder has flushed.
    pub fn stop(
        self,
        canvas: &web_sys::HtmlCanvasElement,
        context: &web_sys::CanvasRenderingContext2d,
    ) {
        if self.recorder.state() == web_sys::RecordingState::Inactive {
            return;
        }
        // Redraw the canvas onto itself: the same picture, a new frame for the stream.
        let _ = context.draw_image_with_html_canvas_element(canvas, 0.0, 0.0);
        let recorder = self.recorder;
        let stop = Closure::once_into_js(move || {
            if recorder.state() != web_sys::RecordingState::Inactive {
                let _ = recorder.stop();
            }
        });
        if let Some(window) = web_sys::window() {
            let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(
                stop.unchecked_ref(),
                DRAIN_MS,
            );
        }
    }
}
