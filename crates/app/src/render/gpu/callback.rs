//! One view's frame for egui-wgpu: [`SceneCallback`] carries the primitives
//! (an `Arc`, not a copy), the camera and the drawing options from
//! [`crate::render::viewport::show`] to the renderer's `prepare` and `paint`.

use std::sync::Arc;

use super::style::ViewStyle;
use crate::render::camera::Camera;
use crate::render::scene::SceneFrame;
use crate::view::ViewOptions;

/// One view's frame for egui-wgpu: the primitives (shared, not copied), the
/// camera and the drawing options.
pub struct SceneCallback {
    /// Which view (its egui id): each view keeps its own GPU targets.
    pub view_id: u64,
    /// egui's frame counter, to retire the targets of views no longer shown.
    pub frame_nr: u64,
    /// The view's rectangle, points (the paint callback's rect).
    pub rect: egui::Rect,
    /// The camera for this frame.
    pub camera: Camera,
    /// The primitives to draw.
    pub frame: Arc<SceneFrame>,
    /// Theme colours.
    pub style: ViewStyle,
    /// Draw the ground grid.
    pub grid: bool,
    /// Draw blob shadows and contact marks.
    pub shadow: bool,
}

impl SceneCallback {
    /// The callback for view `view_id` showing `frame` through `camera` with `view`'s options.
    #[must_use]
    pub fn new(
        view_id: u64,
        frame_nr: u64,
        rect: egui::Rect,
        camera: Camera,
        frame: Arc<SceneFrame>,
        view: &ViewOptions,
        style: ViewStyle,
    ) -> Self {
        Self {
            view_id,
            frame_nr,
            rect,
            camera,
            frame,
            style,
            grid: view.grid,
            shadow: view.shadow,
        }
    }
}
