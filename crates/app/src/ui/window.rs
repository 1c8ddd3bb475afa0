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

/// Shows the window `title` while `open`; `wide` sets up the wide screen's
/// window (size, place), `contents` fills it. Closing clears `open`.
pub(crate) fn show(
    ctx: &egui::Context,
    title: &'static str,
    narrow: bool,
    open: &mut bool,
    wide: impl for<'w> FnOnce(egui::Window<'w>) -> egui::Window<'w>,
    contents: impl FnOnce(&mut egui::Ui),
) {
    if !narrow {
        wide(egui::Window::new(title).open(open)).show(ctx, contents);
        return;
    }
    let screen = ctx.content_rect();
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
            contents(ui);
        });
}
