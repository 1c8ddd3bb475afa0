//! gaitlab-app: the browser lab (DESIGN.md "Layout"): a wgpu 3-D view and egui
//! panels over the gaitlab drivers, with links, a JS state API and persisted
//! settings. The logic builds and tests natively; the eframe/web glue is wasm-only.

pub mod render;
pub mod view;

pub mod api;
pub mod app;
pub mod bench;
pub mod compare;
pub mod editor;
pub mod editor_message;
pub mod grab;
pub mod history;
pub mod jacobian;
pub mod lab;
pub mod lambda_tradeoff;
pub mod lesson;
pub mod link;
pub mod link_state;
pub mod memory;
pub mod named;
pub mod off_or;
pub(crate) mod param_widgets;
pub mod plot_scale;
pub mod settings;
pub mod stage;
pub mod theme;
pub mod ui;
#[cfg(target_arch = "wasm32")]
mod web;
pub mod webm;
pub mod words;

pub use app::App;
pub use lab::Lab;
pub use settings::Settings;
