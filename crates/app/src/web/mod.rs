//! The web glue (wasm32 only): starts eframe on a canvas, publishes
//! `window.gaitlab.state()` / `window.gaitlab.command(json)` (DESIGN.md
//! "Browser") and `window.gaitlab.link()` (the full-state link "Copy link"
//! copies, see [`crate::link_state`]), reads the link on load, keeps the URL in
//! step with `history.replaceState` (and `pushState` for preset changes, so
//! Back works), feeds picked and dropped preset files to the lab, persists the
//! settings, and signals the page once the first frame is drawn.

use std::cell::Cell;
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::app::App;
use crate::lab::{Download, Effect};
use crate::link;
use crate::settings::Settings;
use download::offer_text;
use file::Inbox;
use video::{ErrorSlot, VideoRecorder};

mod codecs;
mod download;
mod encoder;
mod file;
mod media_recorder;
mod video;

/// Depth buffer bits requested from eframe (the 3-D view's pass matches it).
const DEPTH_BITS: u8 = 24;

/// Storage key of the persisted settings.
const SETTINGS_KEY: &str = "gaitlab-settings";

fn window() -> Option<web_sys::Window> {
    web_sys::window()
}

/// A `performance.mark` for the start-up breakdown (ignored where unsupported).
fn mark(name: &str) {
    if let Some(performance) = window().and_then(|w| w.performance()) {
        let _ = performance.mark(name);
    }
}

fn now_ms() -> f64 {
    window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}

/// "webgpu" or "webgl2", then the adapter's name and driver as the browser reports them.
fn backend_name(info: &egui_wgpu::wgpu::AdapterInfo) -> String {
    let kind = match info.backend {
        egui_wgpu::wgpu::Backend::BrowserWebGpu => "webgpu",
        egui_wgpu::wgpu::Backend::Gl => "webgl2",
        other => return format!("{other:?}").to_lowercase(),
    };
    let detail = [info.name.as_str(), info.driver.as_str()]
        .into_iter()
        .filter(|s| !s.is_empty())
        .collect::<Vec<_>>()
        .join(", ");
    if detail.is_empty() {
        kind.to_owned()
    } else {
        format!("{kind} ({detail})")
    }
}

/// The eframe app: the lab plus the page plumbing.
struct WebApp {
    lab: App,
    egui_ctx: egui::Context,
    first_frame_done: bool,
    /// Set by the `popstate` listener: the URL changed under us (Back/Forward).
    url_changed: Rc<Cell<bool>>,
    /// The app's canvas (the video recorder copies the 3-D view from it).
    canvas: web_sys::HtmlCanvasElement,
    /// The video recording in progress, if any.
    video: Option<VideoRecorder>,
    /// Errors the video recorder met after its calls returned.
    video_errors: ErrorSlot,
    /// Preset files read and waiting to load.
    files: Inbox,
    /// The hidden file input "Load file…" clicks.
    file_input: Option<web_sys::HtmlInputElement>,
}

impl WebApp {
    fn new(
        cc: &eframe::CreationContext<'_>,
        url_changed: Rc<Cell<bool>>,
        canvas: web_sys::HtmlCanvasElement,
    ) -> Self {
        let settings: Settings = cc
            .storage
            .and_then(|storage| eframe::get_value(storage, SETTINGS_KEY))
            .unwrap_or_default();
        mark("gaitlab-graphics-ready");
        let mut backend = None;
        if let Some(render_state) = cc.wgpu_render_state.as_ref() {
            backend = Some(backend_name(&render_state.adapter.get_info()));
            crate::render::gpu::install(
                &cc.egui_ctx,
                render_state,
                crate::render::gpu::PassFormat::eframe(render_state, DEPTH_BITS),
            );
        }
        mark("gaitlab-pipelines-ready");
        let mut lab = App::new(settings);
        lab.set_clock(Box::new(now_ms));
        lab.backend = backend;
        if let Some(location) = window().map(|w| w.location()) {
            lab.page_url = format!(
                "{}{}",
                location.origin().unwrap_or_default(),
                location.pathname().unwrap_or_default()
            );
        }
        let files = Inbox::default();
        let file_input = match file::install_input(&files, &cc.egui_ctx) {
            Ok(input) => Some(input),
            Err(error) => {
                lab.report_error(format!("file picker: {error:?}"));
                None
            }
        };
        let mut app = Self {
            lab,
            egui_ctx: cc.egui_ctx.clone(),
            first_frame_done: false,
            url_changed,
            canvas,
            video: None,
            video_errors: ErrorSlot::default(),
            files,
            file_input,
        };
        app.apply_url();
        app
    }

    /// Applies the page's `?query` and `#p=` link ([`Lab::open_link`]); a bad
    /// link leaves a message and the default preset.
    fn apply_url(&mut self) {
        let Some(location) = window().map(|w| w.location()) else {
            return;
        };
        let query = location.search().unwrap_or_default();
        let fragment = location.hash().unwrap_or_default();
        self.lab.open_link(&query, &fragment);
    }

    /// Loads preset and target files that were picked or dropped.
    fn load_files(&mut self, ctx: &egui::Context) {
        file::take_dropped(ctx, &self.files);
        let arrived: Vec<file::Arrived> = self.files.borrow_mut().drain(..).collect();
        for (name, bytes) in arrived {
            match bytes {
                // load_file shows its own problems.
                Ok(bytes) => drop(self.lab.load_file(&name, &bytes)),
                Err(error) => self.lab.report_error(format!("file {name}: {error}")),
            }
        }
    }

    /// Carries out what the lab queued in its outbox: downloads, the file
    /// picker, the video recorder, and the address bar (once, pushing a
    /// history entry when the preset changed).
    fn carry_out_effects(&mut self, ctx: &egui::Context) {
        let mut link: Option<bool> = None;
        for effect in self.lab.drain_effects() {
            match effect {
                Effect::Download(download) => self.deliver(&download),
                Effect::PickFile => self.open_picker(),
                Effect::LinkChanged => link = Some(link.unwrap_or(false)),
                Effect::PresetChanged => link = Some(true),
                Effect::StartVideo => self.start_video(ctx),
                Effect::StopVideo => {
                    if let Some(video) = self.video.take() {
                        video.stop();
                    }
                }
            }
        }
        if let Some(push) = link {
            self.update_url(push);
        }
    }

    /// Opens the preset file picker.
    fn open_picker(&mut self) {
        match &self.file_input {
            Some(input) => input.click(),
            None => self
                .lab
                .report_error("file picker: not available on this page"),
        }
    }

    /// Mirrors the lab's state in the address bar: a new history entry when
    /// `push` (the preset changed, so Back returns to the previous one).
    fn update_url(&mut self, push: bool) {
        let Some(history) = window().and_then(|w| w.history().ok()) else {
            return;
        };
        let mut url = self.lab.address_query();
        if let Some(json) = &self.lab.session.custom_preset {
            url.push_str("#p=");
            url.push_str(&link::encode_preset(json));
        }
        let result = if push {
            history.push_state_with_url(&JsValue::NULL, "", Some(&url))
        } else {
            history.replace_state_with_url(&JsValue::NULL, "", Some(&url))
        };
        if result.is_err() {
            self.lab.report_error("could not update the address bar");
        }
    }

    /// Hands a file to the person as a download.
    fn deliver(&mut self, download: &Download) {
        if let Err(error) = offer_text(&download.text, &download.file_name, download.mime) {
            self.lab
                .report_error(format!("save: the browser refused the download: {error:?}"));
        }
    }

    /// Starts the video recorder on the 3-D view.
    fn start_video(&mut self, ctx: &egui::Context) {
        if self.video.is_some() {
            return;
        }
        let settings = self.lab.settings();
        let name = format!(
            "gaitlab-{}-{}-{}",
            self.lab.creature().name,
            settings.mode.name(),
            settings.method.name()
        );
        match VideoRecorder::start(
            self.canvas.clone(),
            self.lab.view_rect_px(),
            settings.video_size.pixels(),
            name,
            Rc::clone(&self.video_errors),
        ) {
            Ok(video) => {
                self.lab.video.frames = 0;
                self.lab.video.skipped = 0;
                self.lab.video.seconds = 0.0;
                self.lab.video.encoder = video.encoder();
                self.video = Some(video);
                ctx.request_repaint();
            }
            Err(error) => {
                self.lab.set_video_recording(false);
                self.lab.report_error(format!("video: {error}"));
            }
        }
    }

    /// Follows the running video recorder: its errors stop it, otherwise it
    /// tracks the 3-D view and reports its figures to the lab.
    fn follow_video(&mut self, ctx: &egui::Context) {
        let failed = self.video_errors.borrow_mut().take();
        if let Some(error) = failed {
            self.lab.report_error(error);
            if let Some(video) = self.video.take() {
                video.stop();
            }
            self.lab.set_video_recording(false);
        }
        if let Some(video) = &self.video {
            video.set_rect(self.lab.view_rect_px());
            let status = &mut self.lab.video;
            status.frames = video.frames();
            status.encoder = video.encoder();
            status.skipped = video.skipped();
            status.seconds = video.seconds();
            // Every frame must be painted for the recording to be smooth.
            ctx.request_repaint();
        }
    }

    /// Tells the page the first frame is on screen: once this `ui` pass has been painted, that is
    /// when eframe's frame callback returns (a zero-delay timeout runs after it), the loader goes
    /// and `window.__gaitlabFirstFrameMs` is set.
    fn signal_first_frame(&mut self) {
        if self.first_frame_done {
            return;
        }
        self.first_frame_done = true;
        let Some(window) = window() else { return };
        let announce = Closure::once_into_js(first_frame_painted);
        if window
            .set_timeout_with_callback(announce.unchecked_ref())
            .is_err()
        {
            first_frame_painted();
        }
    }
}

/// The page side of [`WebApp::signal_first_frame`].
fn first_frame_painted() {
    mark("gaitlab-first-frame");
    let Some(window) = window() else { return };
    if let Some(document) = window.document() {
        if let Some(loading) = document.get_element_by_id("loading") {
            loading.remove();
        }
        if let Some(body) = document.body() {
            let _ = body.dataset().set("ready", "1");
        }
    }
    let _ = js_sys::Reflect::set(
        &window,
        &JsValue::from_str("__gaitlabFirstFrameMs"),
        &JsValue::from_f64(now_ms()),
    );
}

impl eframe::App for WebApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        if self.url_changed.replace(false) {
            self.apply_url();
        }
        let ctx = ui.ctx().clone();
        self.load_files(&ctx);
        self.lab.ui(ui);
        self.carry_out_effects(&ctx);
        self.follow_video(&ctx);
        self.signal_first_frame();
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, SETTINGS_KEY, self.lab.settings());
    }

    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}

/// Publishes `window.gaitlab = { state(), command(json), link(), bench(json) }` over the running app.
fn publish_api(runner: &Rc<eframe::WebRunner>) -> Result<(), JsValue> {
    let window = window().ok_or("no window")?;
    let api = js_sys::Object::new();
    let state_runner = Rc::clone(runner);
    let state =
        Closure::<dyn Fn() -> String>::new(move || match state_runner.app_mut::<WebApp>() {
            Some(app) => app.lab.state_json(),
            None => serde_json::json!({ "last_error": "the app is not running" }).to_string(),
        });
    let command_runner = Rc::clone(runner);
    let command = Closure::<dyn Fn(JsValue) -> String>::new(move |json: JsValue| {
        let Some(json) = json.as_string() else {
            return "command: expected a JSON string".to_owned();
        };
        match command_runner.app_mut::<WebApp>() {
            Some(mut app) => {
                let result = app.lab.command(&json);
                // A command from JS changes the state without any input event: draw it.
                app.egui_ctx.request_repaint();
                match result {
                    Ok(()) => "ok".to_owned(),
                    Err(error) => error,
                }
            }
            None => "the app is not running".to_owned(),
        }
    });
    let link_runner = Rc::clone(runner);
    let link = Closure::<dyn Fn() -> String>::new(move || match link_runner.app_mut::<WebApp>() {
        Some(app) => app.lab.share_link().unwrap_or_else(|error| error),
        None => String::new(),
    });
    // The benchmark runs in the page's main thread and owns its own driver: the
    // running lab is untouched.
    let bench = Closure::<dyn Fn(JsValue) -> String>::new(move |json: JsValue| {
        let json = json.as_string().unwrap_or_default();
        let mut clock = now_ms;
        match crate::bench::run(&json, &mut clock) {
            Ok(result) => result,
            Err(error) => serde_json::json!({ "error": error }).to_string(),
        }
    });
    js_sys::Reflect::set(&api, &"state".into(), state.as_ref().unchecked_ref())?;
    js_sys::Reflect::set(&api, &"bench".into(), bench.as_ref().unchecked_ref())?;
    js_sys::Reflect::set(&api, &"link".into(), link.as_ref().unchecked_ref())?;
    js_sys::Reflect::set(&api, &"command".into(), command.as_ref().unchecked_ref())?;
    js_sys::Reflect::set(&window, &"gaitlab".into(), &api)?;
    // The page lives as long as the app: the closures stay alive with it.
    state.forget();
    command.forget();
    bench.forget();
    link.forget();
    Ok(())
}

/// The wgpu set-up for the page: eframe's default (WebGPU, else WebGL2), or
/// WebGL2 alone when the page already knows there is no WebGPU adapter.
///
/// Asking the browser for an adapter it does not have costs 0.1–1.2 s in
/// Chromium; `index.html` asks while the wasm downloads and compiles, so wgpu
/// need not ask again on the WebGL2 path.
fn wgpu_options(webgpu_adapter: Option<bool>) -> egui_wgpu::WgpuConfiguration {
    let mut config = egui_wgpu::WgpuConfiguration::default();
    if webgpu_adapter == Some(false)
        && let egui_wgpu::WgpuSetup::CreateNew(create_new) = &mut config.wgpu_setup
    {
        create_new.instance_descriptor.backends = egui_wgpu::wgpu::Backends::GL;
    }
    config
}

/// Starts gaitlab on the canvas with id `canvas_id`.
///
/// `webgpu_adapter` is what the page learned from
/// `navigator.gpu.requestAdapter()`: `false` skips wgpu's own WebGPU probe and
/// goes straight to WebGL2; `true` or absent lets wgpu decide.
///
/// # Errors
/// If the page has no such canvas, or eframe cannot start (no WebGPU/WebGL2).
#[wasm_bindgen]
pub async fn start(canvas_id: String, webgpu_adapter: Option<bool>) -> Result<(), JsValue> {
    let window = window().ok_or("no window")?;
    let document = window.document().ok_or("no document")?;
    let canvas = document
        .get_element_by_id(&canvas_id)
        .ok_or_else(|| JsValue::from_str(&format!("no element with id {canvas_id:?}")))?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .map_err(|_| JsValue::from_str(&format!("#{canvas_id} is not a canvas")))?;
    let url_changed = Rc::new(Cell::new(false));
    let flag = Rc::clone(&url_changed);
    let on_popstate = Closure::<dyn Fn()>::new(move || flag.set(true));
    window.add_event_listener_with_callback("popstate", on_popstate.as_ref().unchecked_ref())?;
    on_popstate.forget();

    let app_canvas = canvas.clone();
    let runner = Rc::new(eframe::WebRunner::new());
    let options = eframe::WebOptions {
        depth_buffer: DEPTH_BITS,
        wgpu_options: wgpu_options(webgpu_adapter),
        ..eframe::WebOptions::default()
    };
    runner
        .start(
            canvas,
            options,
            Box::new(move |cc| Ok(Box::new(WebApp::new(cc, url_changed, app_canvas)))),
        )
        .await?;
    publish_api(&runner)?;
    Ok(())
}
