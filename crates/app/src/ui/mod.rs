//! The lab's layout: controls on the left, live plots at the bottom, the 3-D
//! view in the middle, an error banner on top when something went wrong, and
//! the keyboard shortcuts (space pause, R reset, . single step, comma one step back). Below
//! [`NARROW_WIDTH_PT`] (a phone, issue 6 "Comfort") the controls and the
//! plots become drawers toggled from a slim top bar (one open at a time, the
//! plots one under another), so the 3-D view keeps most of the screen.

use crate::app::App;
use crate::render::viewport;

pub mod fonts;
pub mod panels;
pub(crate) mod plots;
mod touch;
pub(crate) mod window;

/// Below this width (points, i.e. CSS pixels) the lab takes its phone layout:
/// the 3-D view fills the screen under a slim bar, and the controls or the
/// plots open as a drawer over the lower part of the screen.
pub const NARROW_WIDTH_PT: f32 = 600.0;

/// Height of one plot in the phone layout's plots drawer (points).
const PHONE_PLOT_HEIGHT_PT: f32 = 230.0;

/// Share of the screen height the phone layout's drawers take.
const DRAWER_HEIGHT_FRACTION: f32 = 0.45;

impl App {
    /// Shows the whole lab in `ui` and advances the animation by the frame's time.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        self.layout.widgets_pt = crate::lab::layout::WidgetRects::default();
        self.layout.preset_menu_pt.clear();
        self.apply_theme(ui);
        let dt = ui.input(|i| f64::from(i.stable_dt));
        self.note_frame_time(dt);
        self.keyboard(ui);
        #[cfg(not(target_arch = "wasm32"))]
        self.take_dropped_file(ui);
        self.advance(dt);

        self.layout.narrow = self
            .layout
            .narrow_override
            .unwrap_or(ui.available_width() < NARROW_WIDTH_PT);
        touch_spacing(ui.ctx(), self.layout.narrow);
        if self.layout.narrow {
            self.phone_layout(ui);
        } else {
            self.layout.controls_button_pt = [0.0; 4];
            self.layout.plots_button_pt = [0.0; 4];
            // The history scrubber along the window's foot, as wide as the
            // plots (issue 43 item 5: it was 90 px for 600 frames).
            if self.rewind_range().is_some() {
                egui::Panel::bottom("gaitlab-timeline").show(ui, |ui| {
                    panels::history_scrubber(ui, self, ui.available_width());
                });
            }
            egui::Panel::left("gaitlab-controls")
                .resizable(true)
                .default_size(290.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        ui.heading("gaitlab");
                        self.controls(ui);
                    });
                });
            if self.compare.is_some() {
                egui::Panel::bottom("gaitlab-compare")
                    .resizable(true)
                    .default_size(330.0)
                    .show(ui, |ui| panels::compare_cards(ui, self, false));
            } else if self.session.settings.plots || self.lesson_pins_plots() {
                egui::Panel::bottom("gaitlab-plots")
                    .resizable(true)
                    .default_size(170.0)
                    .show(ui, |ui| self.plots_ui(ui));
            }
        }
        self.layout.popup_open = egui::Popup::is_any_open(ui.ctx());
        panels::editor_window(&ui.ctx().clone(), self);
        panels::help_window(&ui.ctx().clone(), self);
        panels::lesson::lesson_window(&ui.ctx().clone(), self);
        egui::CentralPanel::default().show(ui, |ui| {
            if let Some(notice) = self.session.notice.clone() {
                ui.horizontal_wrapped(|ui| {
                    ui.label(format!("Note: {notice}"));
                    if ui
                        .small_button("Dismiss")
                        .on_hover_text("Hide this note")
                        .clicked()
                    {
                        self.clear_notice();
                    }
                });
            }
            if let Some(error) = self.session.last_error.clone() {
                ui.horizontal_wrapped(|ui| {
                    ui.colored_label(crate::theme::PROBLEM_COLOR, format!("Problem: {error}"));
                    if ui
                        .small_button("Dismiss")
                        .on_hover_text("Hide this message")
                        .clicked()
                    {
                        self.clear_error();
                    }
                });
            }
            self.recording_indicator(ui);
            self.offer_grab_points();
            let rect = match &self.compare {
                Some(compare) => {
                    self.lab.layout.trunk_pt = None;
                    self.lab.layout.figure_pt = None;
                    self.lab.layout.view_pt = [0.0; 4];
                    let labels: Vec<String> = compare
                        .views()
                        .iter()
                        .enumerate()
                        .map(|(i, v)| format!("{} · {}", i + 1, v.method.label()))
                        .collect();
                    let key: Vec<_> = labels
                        .iter()
                        .enumerate()
                        .map(|(i, label)| (compare.colour(i), label.as_str()))
                        .collect();
                    let settings = &self.lab.session.settings.view;
                    if compare.config.overlay {
                        viewport::show_overlay(
                            ui,
                            compare.overlay(),
                            &key,
                            &mut self.lab.camera,
                            settings,
                            &mut self.grab,
                        )
                        .rect
                    } else {
                        let panes: Vec<_> = compare
                            .views()
                            .iter()
                            .zip(&key)
                            .map(|(v, (colour, label))| (&v.stage().scene, *label, *colour))
                            .collect();
                        viewport::show_split(
                            ui,
                            &panes,
                            &mut self.lab.camera,
                            settings,
                            &mut self.grab,
                        )
                        .rect
                    }
                }
                None if self.lab.stage.driver.held_targets().is_some() => {
                    let response = viewport::show_with_tool(
                        ui,
                        &self.lab.stage.scene,
                        &mut self.lab.camera,
                        &self.lab.session.settings.view,
                        &mut self.grab,
                    );
                    self.lab.layout.trunk_pt = None;
                    self.note_single_view(response.rect);
                    response.rect
                }
                None => {
                    let grab = self.lab.stage.driver.push_grab();
                    let trunk = grab.map(|(p, sideways)| (p.as_vec3(), sideways));
                    let (response, pushed) = viewport::show_pushable(
                        ui,
                        &self.lab.stage.scene,
                        &mut self.lab.camera,
                        &self.lab.session.settings.view,
                        &mut self.lab.push_drag,
                        trunk,
                    );
                    self.lab.layout.trunk_pt = trunk
                        .and_then(|(p, _)| {
                            viewport::screen_point(&self.lab.camera, response.rect, p)
                        })
                        .map(|at| [at.x, at.y]);
                    self.note_single_view(response.rect);
                    if let Some(dv) = pushed
                        && let Err(error) = self.push(dv)
                    {
                        self.report_error(error);
                    }
                    response.rect
                }
            };
            self.apply_grab();
            self.note_targets_on_screen(rect);
            let ppp = ui.ctx().pixels_per_point();
            self.lab.layout.view_rect_px = [
                rect.min.x * ppp,
                rect.min.y * ppp,
                rect.width() * ppp,
                rect.height() * ppp,
            ];
        });
        if self.lab.layout.narrow {
            self.lab.layout.touch_targets_checked =
                touch::audit(ui.ctx(), &mut self.lab.layout.small_touch_targets_pt);
        } else {
            self.lab.layout.touch_targets_checked = 0;
            self.lab.layout.small_touch_targets_pt.clear();
        }
        if !self.playback.paused {
            ui.ctx().request_repaint();
        }
    }

    /// Every control panel of the registry that shows for the lab, top to
    /// bottom (the wide layout's side panel and the phone layout's drawer).
    fn controls(&mut self, ui: &mut egui::Ui) {
        self.layout.panels_shown.clear();
        for panel in panels::REGISTRY {
            if panel.shown_for(self) && !self.lesson_hides(panel.title()) {
                if panel.title() != "—" {
                    self.layout.panels_shown.push(panel.title());
                }
                panel.ui(self, ui);
            }
        }
    }

    /// The phone layout: a slim bar (controls drawer toggle, Reset, Play,
    /// Step) over a full-width 3-D view; the drawer, when open, takes the
    /// lower [`DRAWER_HEIGHT_FRACTION`] of the screen with bigger touch targets.
    fn phone_layout(&mut self, ui: &mut egui::Ui) {
        egui::Panel::top("gaitlab-phone-bar").show(ui, |ui| {
            // Six 44-point buttons in one row of a 390-point screen: less
            // padding beside the words than the drawers' buttons have.
            let spacing = ui.spacing_mut();
            spacing.button_padding.x = 8.0;
            spacing.item_spacing.x = 6.0;
            ui.horizontal_wrapped(|ui| {
                // Highlighted while open (a longer "Hide controls" pushed
                // Step off a 390-px screen).
                let (clicked, rect) = drawer_button(
                    ui,
                    self.layout.controls_open,
                    "Controls",
                    "Open or close the control panels over the lower part of the screen",
                );
                self.layout.controls_button_pt = rect;
                if clicked {
                    self.layout.controls_open = !self.layout.controls_open;
                    self.layout.plots_open &= !self.layout.controls_open;
                }
                let (clicked, rect) = drawer_button(
                    ui,
                    self.layout.plots_open,
                    "Plots",
                    "Open or close the live plots (side by side: each method's card) over the \
                     lower part of the screen",
                );
                self.layout.plots_button_pt = rect;
                if clicked {
                    self.layout.plots_open = !self.layout.plots_open;
                    self.layout.controls_open &= !self.layout.plots_open;
                }
                panels::buttons(ui, self);
            });
        });
        let height = (ui.available_height() * DRAWER_HEIGHT_FRACTION).max(160.0);
        if self.layout.plots_open {
            egui::Panel::bottom("gaitlab-phone-plots")
                .resizable(false)
                .exact_size(height)
                .show(ui, |ui| {
                    if self.compare.is_some() {
                        // The comparison's cards, one under another.
                        panels::compare_cards(ui, self, true);
                    } else {
                        self.plots_stacked_ui(ui, PHONE_PLOT_HEIGHT_PT);
                    }
                });
            return;
        }
        if !self.layout.controls_open {
            return;
        }
        egui::Panel::bottom("gaitlab-phone-controls")
            .resizable(false)
            .exact_size(height)
            .show(ui, |ui| {
                let spacing = ui.spacing_mut();
                spacing.item_spacing.y = 8.0;
                // Scrolled by dragging the drawer: no thin bar to aim at.
                egui::ScrollArea::vertical()
                    .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysHidden)
                    .show(ui, |ui| {
                        ui.set_width(ui.available_width());
                        self.controls(ui);
                    });
            });
    }

    /// A red dot and what is being recorded, above the 3-D view (outside the
    /// rectangle a video copies), while a take or a video records.
    fn recording_indicator(&self, ui: &mut egui::Ui) {
        let what = match (self.recording(), self.video_recording()) {
            (false, false) => return,
            (true, false) => "Recording motion",
            (false, true) => "Recording video",
            (true, true) => "Recording motion and video",
        };
        let red = egui::Color32::from_rgb(220, 40, 40);
        ui.horizontal(|ui| {
            let (dot, _) = ui.allocate_exact_size(egui::vec2(12.0, 12.0), egui::Sense::hover());
            ui.painter().circle_filled(dot.center(), 6.0, red);
            let frames = self.take().map_or(0, gaitlab_engine::Take::frames);
            let text = if self.recording() {
                format!("{what} · {frames} frames")
            } else {
                what.to_owned()
            };
            ui.colored_label(red, text)
                .on_hover_text("Stop it in the Recording panel");
        });
    }

    /// Applies the chosen theme to egui (it takes effect from the next frame)
    /// and notes whether this frame is dark.
    fn apply_theme(&mut self, ui: &egui::Ui) {
        fonts::ensure(ui.ctx());
        let wanted = self.session.settings.theme.preference();
        if ui.ctx().options(|o| o.theme_preference) != wanted {
            ui.ctx().set_theme(wanted);
            ui.ctx().request_repaint();
        }
        self.layout.dark_mode = ui.visuals().dark_mode;
    }

    /// Whether the last frame used the phone layout.
    #[must_use]
    pub fn narrow(&self) -> bool {
        self.layout.narrow
    }

    /// Whether the phone layout's controls drawer is open.
    #[must_use]
    pub fn controls_open(&self) -> bool {
        self.layout.controls_open
    }

    /// Whether the help window is open.
    #[must_use]
    pub fn help_open(&self) -> bool {
        self.layout.help_open
    }

    /// Whether the phone layout's plots drawer is open.
    #[must_use]
    pub fn plots_open(&self) -> bool {
        self.layout.plots_open
    }

    /// The single view's rectangle and its figure's box on screen, for `state()`.
    fn note_single_view(&mut self, rect: egui::Rect) {
        self.layout.figure_pt = self
            .stage
            .scene
            .bounds()
            .and_then(|b| figure_on_screen(&self.camera, rect, &b));
        self.layout.view_pt = crate::lab::layout::rect_pt(rect);
    }

    /// Where the first figure's targets and effectors are on screen in the view `rect`
    /// (its first pane side by side), for `state()`.
    fn note_targets_on_screen(&mut self, rect: egui::Rect) {
        let (driver, pane) = match &self.compare {
            Some(compare) => {
                let Some(first) = compare.views().first() else {
                    return;
                };
                let pane = if compare.config.overlay {
                    rect
                } else {
                    viewport::split_rects(rect, compare.views().len())[0]
                };
                (first.driver(), pane)
            }
            None => (&self.lab.stage.driver, rect),
        };
        let camera = &self.lab.camera;
        let on_screen = |p: &glam::DVec3| {
            viewport::screen_point(camera, pane, p.as_vec3()).map(|at| [at.x, at.y])
        };
        self.lab.layout.target_pt.clear();
        if let Some(targets) = gaitlab_core::driver::Driver::targets(driver) {
            self.lab
                .layout
                .target_pt
                .extend(targets.position.iter().map(on_screen));
        }
        self.lab.layout.effector_pt.clear();
        self.lab.layout.effector_pt.extend(
            gaitlab_core::driver::Driver::effector_positions(driver)
                .iter()
                .map(on_screen),
        );
    }

    fn keyboard(&mut self, ui: &egui::Ui) {
        if ui.ctx().egui_wants_keyboard_input() {
            return;
        }
        let (space, reset, step, back, home, iterate) = ui.input(|i| {
            (
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::R),
                i.key_pressed(egui::Key::Period),
                i.key_pressed(egui::Key::Comma),
                i.key_pressed(egui::Key::H),
                i.key_pressed(egui::Key::I),
            )
        });
        if iterate && let Err(error) = self.step_iteration() {
            self.report_error(error);
        }
        if home {
            self.camera.home();
        }
        if back && let Err(error) = self.step_back(1) {
            self.report_error(error);
        }
        if space {
            let paused = self.playback.paused;
            self.set_paused(!paused);
        }
        if reset {
            self.reset();
        }
        if step {
            self.set_paused(true);
            self.single_step();
        }
    }
}

/// The screen rectangle, points `[x, y, w, h]`, around the corners of the
/// figure's box `bounds` seen by `camera` in the view `rect` (`None` when a
/// corner is behind the eye).
fn figure_on_screen(
    camera: &crate::render::camera::Camera,
    rect: egui::Rect,
    bounds: &crate::render::scene::Bounds,
) -> Option<[f32; 4]> {
    let mut screen = egui::Rect::NOTHING;
    for i in 0..8 {
        let corner = glam::DVec3::new(
            if i & 1 == 0 {
                bounds.min.x
            } else {
                bounds.max.x
            },
            if i & 2 == 0 {
                bounds.min.y
            } else {
                bounds.max.y
            },
            if i & 4 == 0 {
                bounds.min.z
            } else {
                bounds.max.z
            },
        );
        let at = viewport::screen_point(camera, rect, corner.as_vec3())?;
        screen.extend_with(at);
    }
    Some(crate::lab::layout::rect_pt(screen))
}

/// A phone-bar button that opens a drawer: whether it was clicked, and its
/// rectangle in points `[x, y, w, h]` (for tests that tap it).
fn drawer_button(ui: &mut egui::Ui, open: bool, label: &str, hover: &str) -> (bool, [f32; 4]) {
    // A framed button, so it reads as one (a bare selectable label looked
    // like plain text), highlighted while its drawer is open.
    let response = ui
        .add(egui::Button::new(label).selected(open))
        .on_hover_text(hover);
    let r = response.rect;
    (
        response.clicked(),
        [r.min.x, r.min.y, r.width(), r.height()],
    )
}

/// Height of a touch target in the phone layout, points (CSS pixels): the
/// 44 px that touch guidelines ask for (issue 21 item 7).
pub const TOUCH_TARGET_PT: f32 = 44.0;

/// In the phone layout every button, slider, checkbox and menu row is at
/// least [`TOUCH_TARGET_PT`] tall (the whole context's style, so popups and
/// windows too); the wide layout keeps egui's compact sizes.
fn touch_spacing(ctx: &egui::Context, narrow: bool) {
    let (interact, padding) = if narrow {
        (
            egui::vec2(TOUCH_TARGET_PT, TOUCH_TARGET_PT),
            egui::vec2(12.0, 12.0),
        )
    } else {
        let desk = egui::style::Spacing::default();
        (desk.interact_size, desk.button_padding)
    };
    // Text that selects on a drag fights the drawer's scrolling on a
    // phone (and would be a 15-point-tall target): labels are plain there.
    let selectable = !narrow;
    let style = ctx.global_style();
    if style.spacing.interact_size != interact || style.interaction.selectable_labels != selectable
    {
        ctx.all_styles_mut(|style| {
            style.spacing.interact_size = interact;
            style.spacing.button_padding = padding;
            style.interaction.selectable_labels = selectable;
        });
    }
}
