//! The lab's windows (help, the lesson's note, the preset editor). On a wide
//! screen egui's own window (title bar, close and collapse buttons, drag and
//! resize). On a phone (issue 21 item 7) that window's small parts are not
//! touch targets: it sits fixed in the middle of the screen with no title
//! bar and nothing to drag or resize, its title and a Close button of full
//! touch size heading its content.

/// Whether scroll areas show their bar: not on a phone (the content scrolls
/// by dragging; a thin bar is no touch target).
#[must_use]
pub(crate) fn scroll_bars(narrow: bool) -> egui::scroll_area::ScrollBarVisibility {
    if narrow {
        egui::scroll_area::ScrollBarVisibility::AlwaysHidden
    } else {
        egui::scroll_area::ScrollBarVisibility::VisibleWhenNeeded
    }
}

/// How a window sits on a wide screen, and whether its content scrolls.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Placement {
    /// Width to start at, points (at most the screen's less 16).
    pub width_pt: f32,
    /// Height to start at, points (`None`: as tall as the content).
    pub height_pt: Option<f32>,
    /// Tallest share of the screen it may take.
    pub height_share: f32,
    /// Whether it opens in the middle of the screen (else egui's place).
    pub centred: bool,
    /// Whether its content scrolls vertically (in a scroll area of its own).
    pub scrolls: bool,
}

/// Shows the window `title` while `open`, placed as `placement` says on a
/// wide screen; `contents` fills it. Closing clears `open`.
pub(crate) fn show(
    ctx: &egui::Context,
    title: &'static str,
    narrow: bool,
    open: &mut bool,
    placement: Placement,
    contents: impl FnOnce(&mut egui::Ui),
) {
    let screen = ctx.content_rect();
    let body = |ui: &mut egui::Ui| {
        if placement.scrolls {
            egui::ScrollArea::vertical()
                .scroll_bar_visibility(scroll_bars(narrow))
                .show(ui, contents);
        } else {
            contents(ui);
        }
    };
    if !narrow {
        let mut window = egui::Window::new(title)
            .open(open)
            .collapsible(false)
            .default_width(placement.width_pt.min(screen.width() - 16.0))
            .max_width(screen.width() - 16.0)
            .max_height(screen.height() * placement.height_share)
            .vscroll(false);
        if let Some(height) = placement.height_pt {
            window = window.default_height(height.min(screen.height() * placement.height_share));
        }
        if placement.centred {
            window = window
                .pivot(egui::Align2::CENTER_CENTER)
                .default_pos(screen.center())
                .constrain(true);
        }
        window.show(ctx, body);
        return;
    }
    egui::Window::new(title)
        .title_bar(false)
        .resizable(false)
        .movable(false)
        .collapsible(false)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .default_width(screen.width() - 16.0)
        .max_width(screen.width() - 16.0)
        .max_height(screen.height() * 0.85)
        .show(ctx, |ui| {
            ui.horizontal(|ui| {
                ui.heading(title);
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                    if ui.button("Close").clicked() {
                        *open = false;
                    }
                });
            });
            ui.separator();
            body(ui);
        });
}
