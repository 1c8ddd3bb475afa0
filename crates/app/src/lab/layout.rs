//! The lab's layout as last drawn: wide or phone layout (and whether a test
//! forced it), the phone drawers, the light or dark visuals and where the 3-D
//! view lies on the canvas (`state().layout`, `view_rect_px`, `dark`).

/// What the last frame's layout was.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Forces the phone layout on or off (`None`: by the screen width).
    pub narrow_override: Option<bool>,
    /// Whether the last frame used the phone layout (controls in a drawer).
    pub narrow: bool,
    /// Whether the phone layout's controls drawer is open.
    pub controls_open: bool,
    /// Whether the help window is open.
    pub help_open: bool,
    /// Whether the lesson's note window is open.
    pub lesson_note_open: bool,
    /// The titles of the control panels the last frame drew, top to bottom.
    pub panels_shown: Vec<&'static str>,
    /// The phone layout's interactive widgets the last frame measured.
    pub touch_targets_checked: usize,
    /// Those under the 44-point touch size, points `[x, y, w, h]`.
    pub small_touch_targets_pt: Vec<[f32; 4]>,
    /// Whether the phone layout's plots drawer is open (never with the
    /// controls drawer).
    pub plots_open: bool,
    /// The phone layout's "Plots" button, points `[x, y, w, h]` (zeros in the
    /// wide layout), for tests that tap it.
    pub plots_button_pt: [f32; 4],
    /// The phone layout's "Controls" button, points (CSS pixels) `[x, y, w, h]`
    /// (zeros in the wide layout), for tests that tap it.
    pub controls_button_pt: [f32; 4],
    /// Whether the last frame was drawn with dark visuals.
    pub dark_mode: bool,
    /// The 3-D view's rectangle on the canvas, physical pixels `[x, y, w, h]`.
    pub view_rect_px: [f32; 4],
    /// The physics creature's trunk on screen, points `[x, y]`: where a drag
    /// grabs it to push it (`None`: no physics creature in the single view).
    pub trunk_pt: Option<[f32; 2]>,
    /// Where the last frame drew the Help button, the playback-rate slider
    /// and the preset combo box, points `[x, y, w, h]` (zeros where not
    /// drawn), for tests that click their drawn centres at every device
    /// scale factor (issue 43 item 6).
    pub widgets_pt: WidgetRects,
    /// Whether a popup (a combo box's list) is open.
    pub popup_open: bool,
    /// Clicks the preset combo box has taken since the page opened.
    pub preset_combo_clicks: u32,
    /// The open preset menu's entries as drawn.
    pub preset_menu_pt: MenuRects,
    /// The single view's figure (its box, the trunk and a box near it
    /// included) on screen, points `[x, y, w, h]` (`None` in a comparison
    /// or where a corner is behind the eye).
    pub figure_pt: Option<[f32; 4]>,
    /// The single 3-D view's rectangle, points `[x, y, w, h]`.
    pub view_pt: [f32; 4],
    /// Each effector's target on screen in the first pane, `[x, y]` points.
    pub target_pt: Vec<Option<[f32; 2]>>,
    /// Each effector of the first figure on screen, `[x, y]` points.
    pub effector_pt: Vec<Option<[f32; 2]>>,
}

/// Rectangles of a few widgets as drawn, points `[x, y, w, h]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct WidgetRects {
    /// The Help button.
    pub help: [f32; 4],
    /// The playback-rate slider (rail and value).
    pub rate_slider: [f32; 4],
    /// The preset combo box.
    pub preset_combo: [f32; 4],
    /// The Terrain panel's header (a click opens or closes it).
    pub terrain_header: [f32; 4],
    /// The Terrain panel's Stairs button (zeros while the panel is closed).
    pub terrain_stairs: [f32; 4],
}

/// The open preset menu's entries, by preset name, points `[x, y, w, h]`
/// (empty while the menu is closed).
pub type MenuRects = std::collections::BTreeMap<&'static str, [f32; 4]>;

/// `rect` as `[x, y, w, h]`.
#[must_use]
pub fn rect_pt(rect: egui::Rect) -> [f32; 4] {
    [rect.min.x, rect.min.y, rect.width(), rect.height()]
}

impl Default for Layout {
    fn default() -> Self {
        Self {
            narrow_override: None,
            narrow: false,
            controls_open: false,
            help_open: false,
            lesson_note_open: false,
            panels_shown: Vec::new(),
            touch_targets_checked: 0,
            small_touch_targets_pt: Vec::new(),
            plots_open: false,
            plots_button_pt: [0.0; 4],
            controls_button_pt: [0.0; 4],
            dark_mode: true,
            view_rect_px: [0.0; 4],
            trunk_pt: None,
            widgets_pt: WidgetRects::default(),
            popup_open: false,
            preset_combo_clicks: 0,
            preset_menu_pt: MenuRects::new(),
            figure_pt: None,
            view_pt: [0.0; 4],
            target_pt: Vec::new(),
            effector_pt: Vec::new(),
        }
    }
}
