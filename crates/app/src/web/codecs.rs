//! Video encoding through WebCodecs (wasm32 only), for She 2006 §6.2's
//! recording panel: each copied frame of the 3-D view becomes a `VideoFrame`
//! stamped with the time it was shown, a `VideoEncoder` turns it into VP9 (or
//! VP8), and [`crate::webm`] muxes the chunks into a file with a duration and
//! cues.
//!
//! Compared with `MediaRecorder`, nothing is lost at the ends of a take: the
//! encoder is ready before the first frame is stamped, and `flush()` waits for
//! every frame before the file is written. A keyframe is asked for each second
//! so the file seeks well; when the encoder falls behind (a starved machine)
//! frames are skipped rather than queued without bound, and the timestamps
//! keep the playback at the speed the animation ran.
//!
//! `VideoEncoder` sits behind web-sys's unstable APIs, so the few members used
//! here are declared directly.

use std::cell::RefCell;
use std::rc::Rc;

use js_sys::{Object, Reflect};
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

use super::encoder::{BITS_PER_SECOND, describe};
use crate::webm::{VideoCodec, WebmMuxer};

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_name = VideoEncoder)]
    type JsVideoEncoder;
    #[wasm_bindgen(constructor, js_class = "VideoEncoder", catch)]
    fn new(init: &Object) -> Result<JsVideoEncoder, JsValue>;
    #[wasm_bindgen(method, js_class = "VideoEncoder", catch)]
    fn configure(this: &JsVideoEncoder, config: &Object) -> Result<(), JsValue>;
    #[wasm_bindgen(method, js_class = "VideoEncoder", catch)]
    fn encode(this: &JsVideoEncoder, frame: &JsVideoFrame, options: &Object)
    -> Result<(), JsValue>;
    #[wasm_bindgen(method, js_class = "VideoEncoder")]
    fn flush(this: &JsVideoEncoder) -> js_sys::Promise;
    #[wasm_bindgen(method, js_class = "VideoEncoder", catch)]
    fn close(this: &JsVideoEncoder) -> Result<(), JsValue>;
    #[wasm_bindgen(method, getter, js_class = "VideoEncoder", js_name = encodeQueueSize)]
    fn encode_queue_size(this: &JsVideoEncoder) -> u32;
    #[wasm_bindgen(static_method_of = JsVideoEncoder, js_class = "VideoEncoder", js_name = isConfigSupported, catch)]
    fn is_config_supported(config: &Object) -> Result<js_sys::Promise, JsValue>;

    #[wasm_bindgen(js_name = VideoFrame)]
    type JsVideoFrame;
    #[wasm_bindgen(constructor, js_class = "VideoFrame", catch)]
    fn new(source: &web_sys::HtmlCanvasElement, init: &Object) -> Result<JsVideoFrame, JsValue>;
    #[wasm_bindgen(method, js_class = "VideoFrame")]
    fn close(this: &JsVideoFrame);

    #[wasm_bindgen(js_name = EncodedVideoChunk)]
    type JsEncodedVideoChunk;
    #[wasm_bindgen(method, getter, js_class = "EncodedVideoChunk", js_name = type)]
    fn kind(this: &JsEncodedVideoChunk) -> String;
    #[wasm_bindgen(method, getter, js_class = "EncodedVideoChunk")]
    fn timestamp(this: &JsEncodedVideoChunk) -> f64;
    #[wasm_bindgen(method, getter, js_class = "EncodedVideoChunk", js_name = byteLength)]
    fn byte_length(this: &JsEncodedVideoChunk) -> u32;
    #[wasm_bindgen(method, js_class = "EncodedVideoChunk", js_name = copyTo)]
    fn copy_to(this: &JsEncodedVideoChunk, destination: &mut [u8]);
}

/// Codecs tried, best first: (WebCodecs codec string, container codec).
/// VP9 profile 0, level 4.1, 8-bit covers every frame size offered (≤ 1080p).
const CODECS: [(&str, VideoCodec); 2] =
    [("vp09.00.41.08", VideoCodec::Vp9), ("vp8", VideoCodec::Vp8)];

/// A keyframe at least this often, µs (each starts a cluster and a cue).
const KEYFRAME_INTERVAL_US: f64 = 1_000_000.0;

/// Frames waiting in the encoder beyond which new frames are skipped.
const MAX_QUEUED_FRAMES: u32 = 4;

fn set(object: &Object, key: &str, value: impl Into<JsValue>) {
    // Setting a property on a plain object cannot fail.
    let _ = Reflect::set(object, &key.into(), &value.into());
}

/// Whether this browser has WebCodecs' `VideoEncoder`.
#[must_use]
pub fn available() -> bool {
    Reflect::has(&js_sys::global(), &"VideoEncoder".into()).unwrap_or(false)
}

/// A WebCodecs encoder feeding a WebM muxer.
pub struct CodecEncoder {
    encoder: JsVideoEncoder,
    codec: VideoCodec,
    muxer: Rc<RefCell<WebmMuxer>>,
    /// The first error the encoder or muxer reported.
    error: Rc<RefCell<Option<String>>>,
    last_key_us: Option<f64>,
    last_us: Option<f64>,
    skipped: u64,
    frame_init: Object,
    key_options: Object,
    delta_options: Object,
    _on_output: Closure<dyn FnMut(JsEncodedVideoChunk)>,
    _on_error: Closure<dyn FnMut(JsValue)>,
}

impl CodecEncoder {
    /// An encoder for `width` × `height` frames with the best codec the
    /// browser supports; `Ok(None)` when it supports none of them.
    ///
    /// # Errors
    /// If the browser refuses to build or configure the encoder.
    pub async fn open(width: u32, height: u32) -> Result<Option<Self>, String> {
        let mut chosen = None;
        for (name, codec) in CODECS {
            let config = Object::new();
            set(&config, "codec", name);
            set(&config, "width", width);
            set(&config, "height", height);
            set(&config, "bitrate", BITS_PER_SECOND);
            set(&config, "framerate", 60);
            set(&config, "latencyMode", "realtime");
            let answer = JsVideoEncoder::is_config_supported(&config).map_err(|e| describe(&e))?;
            let support = JsFuture::from(answer).await.map_err(|e| describe(&e))?;
            let supported = Reflect::get(&support, &"supported".into())
                .ok()
                .and_then(|s| s.as_bool())
                .unwrap_or(false);
            if supported {
                chosen = Some((config, codec));
                break;
            }
        }
        let Some((config, codec)) = chosen else {
            return Ok(None);
        };
        let muxer = Rc::new(RefCell::new(WebmMuxer::new(codec, width, height)));
        let error: Rc<RefCell<Option<String>>> = Rc::new(RefCell::new(None));
        let on_output = {
            let muxer = Rc::clone(&muxer);
            let error = Rc::clone(&error);
            let mut scratch = Vec::new();
            Closure::<dyn FnMut(JsEncodedVideoChunk)>::new(move |chunk: JsEncodedVideoChunk| {
                scratch.resize(chunk.byte_length() as usize, 0);
                chunk.copy_to(&mut scratch);
                let timestamp_us = chunk.timestamp().max(0.0) as u64;
                let key = chunk.kind() == "key";
                if let Err(e) = muxer.borrow_mut().push(timestamp_us, key, &scratch) {
                    error.borrow_mut().get_or_insert(e.to_string());
                }
            })
        };
        let on_error = {
            let error = Rc::clone(&error);
            Closure::<dyn FnMut(JsValue)>::new(move |e: JsValue| {
                error
                    .borrow_mut()
                    .get_or_insert(format!("the video encoder failed: {}", describe(&e)));
            })
        };
        let init = Object::new();
        set(&init, "output", on_output.as_ref());
        set(&init, "error", on_error.as_ref());
        let encoder = JsVideoEncoder::new(&init).map_err(|e| describe(&e))?;
        encoder.configure(&config).map_err(|e| describe(&e))?;
        let key_options = Object::new();
        set(&key_options, "keyFrame", true);
        let delta_options = Object::new();
        set(&delta_options, "keyFrame", false);
        Ok(Some(Self {
            encoder,
            codec,
            muxer,
            error,
            last_key_us: None,
            last_us: None,
            skipped: 0,
            frame_init: Object::new(),
            key_options,
            delta_options,
            _on_output: on_output,
            _on_error: on_error,
        }))
    }

    /// The codec in use, as the state API names it.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self.codec {
            VideoCodec::Vp9 => "webcodecs-vp9",
            VideoCodec::Vp8 => "webcodecs-vp8",
        }
    }

    /// The first error the encoder reported, if any.
    #[must_use]
    pub fn error(&self) -> Option<String> {
        self.error.borrow().clone()
    }

    /// Frames skipped because the encoder had fallen behind.
    #[must_use]
    pub fn skipped(&self) -> u64 {
        self.skipped
    }

    /// Encodes the picture on `canvas` shown at `timestamp_us` (a clock that
    /// only goes forward). `force` encodes it even if the encoder is behind
    /// (the last frame of a take). Returns whether the frame was encoded.
    ///
    /// # Errors
    /// If the browser cannot read the canvas or the encoder refuses the frame.
    pub fn encode(
        &mut self,
        canvas: &web_sys::HtmlCanvasElement,
        timestamp_us: f64,
        force: bool,
    ) -> Result<bool, String> {
        if self.last_us.is_some_and(|last| timestamp_us <= last) {
            return Ok(false);
        }
        if !force && self.encoder.encode_queue_size() > MAX_QUEUED_FRAMES {
            self.skipped += 1;
            return Ok(false);
        }
        set(&self.frame_init, "timestamp", timestamp_us.round());
        let frame = JsVideoFrame::new(canvas, &self.frame_init).map_err(|e| describe(&e))?;
        let key = self
            .last_key_us
            .is_none_or(|last| timestamp_us - last >= KEYFRAME_INTERVAL_US);
        let options = if key {
            &self.key_options
        } else {
            &self.delta_options
        };
        let result = self.encoder.encode(&frame, options);
        frame.close();
        result.map_err(|e| describe(&e))?;
        if key {
            self.last_key_us = Some(timestamp_us);
        }
        self.last_us = Some(timestamp_us);
        Ok(true)
    }

    /// Waits for every frame to be encoded and returns the WebM file.
    ///
    /// # Errors
    /// If the encoder failed on the way.
    pub async fn finish(self) -> Result<Vec<u8>, String> {
        let flushed = JsFuture::from(self.encoder.flush()).await;
        let _ = self.encoder.close();
        if let Some(error) = self.error() {
            return Err(error);
        }
        flushed.map_err(|e| describe(&e))?;
        // The closed encoder calls nothing more: with its output callback gone,
        // this is the muxer's last owner.
        let Self {
            muxer, _on_output, ..
        } = self;
        drop(_on_output);
        let muxer = Rc::try_unwrap(muxer)
            .map_err(|_| "the video muxer is still in use".to_owned())?
            .into_inner();
        Ok(muxer.finish(concat!("gaitlab ", env!("CARGO_PKG_VERSION"))))
    }
}
