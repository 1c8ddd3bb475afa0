//! gaitlab-app: the browser lab (DESIGN.md "Layout"): a wgpu 3-D view and egui
//! panels over the gaitlab drivers, with links, a JS state API and persisted
//! settings. The logic builds and tests natively; the eframe/web glue is wasm-only.

pub mod render;
pub mod view;

pub mod api;
pub mod bench;
pub mod compare;
pub mod editor;
pub mod history;
pub mod lab;
mod lab_compare;
mod lab_editor;
pub mod link;
pub mod link_state;
pub mod memory;
mod panels;
mod panels_compare;
mod panels_editor;
mod panels_gait;
mod panels_path;
mod panels_physics;
pub mod settings;
pub mod theme;
mod ui;
#[cfg(target_arch = "wasm32")]
mod web;
#[cfg(target_arch = "wasm32")]
mod web_codecs;
#[cfg(target_arch = "wasm32")]
mod web_download;
#[cfg(target_arch = "wasm32")]
mod web_encoder;
#[cfg(target_arch = "wasm32")]
mod web_file;
#[cfg(target_arch = "wasm32")]
mod web_media_recorder;
#[cfg(target_arch = "wasm32")]
mod web_video;
pub mod webm;

pub use lab::Lab;
pub use settings::Settings;
