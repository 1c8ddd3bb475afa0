//! The phone layout's touch-target audit (issue 21 item 7): after a frame,
//! every interactive widget egui registered (buttons, sliders, checkboxes,
//! menus, drag values: anything that senses a click or a drag) is measured
//! against [`super::TOUCH_TARGET_PT`]; the ones smaller go to
//! `state().layout.small_touch_targets_pt` for the browser test. Areas that
//! take gestures over a whole region (the 3-D view, plots, scroll areas,
//! panels) are not buttons and are left out by size.

use super::TOUCH_TARGET_PT;

/// A region wider and taller than this, points, is an area, not a target.
const AREA_PT: f32 = 200.0;

/// Counts the interactive widgets of this frame and writes the rectangles
/// (points, `[x, y, w, h]`) of those under [`TOUCH_TARGET_PT`] in either
/// direction, or reaching past the screen's left or right edge (cut off;
/// below the screen is a scroll area's business), into `small`; returns how
/// many were checked.
pub(crate) fn audit(ctx: &egui::Context, small: &mut Vec<[f32; 4]>) -> usize {
    small.clear();
    let screen = ctx.content_rect();
    ctx.viewport(|viewport| {
        let mut checked = 0;
        for (_, widgets) in viewport.this_pass.widgets.layers() {
            for widget in widgets {
                let sense = widget.sense;
                if !widget.enabled || !(sense.senses_click() || sense.senses_drag()) {
                    continue;
                }
                // Its whole size, not the part a scroll area's edge leaves
                // (widgets scrolled out of view count too: they are laid out).
                let r = widget.rect;
                if r.width() > AREA_PT && r.height() > AREA_PT {
                    continue;
                }
                checked += 1;
                // Half a point of slack for layout rounding.
                let cut_off = r.min.x < screen.min.x - 0.5 || r.max.x > screen.max.x + 0.5;
                if cut_off
                    || r.width() < TOUCH_TARGET_PT - 0.5
                    || r.height() < TOUCH_TARGET_PT - 0.5
                {
                    small.push([r.min.x, r.min.y, r.width(), r.height()]);
                }
            }
        }
        checked
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_and_cut_off_targets_are_reported_and_a_big_one_and_a_label_are_not() {
        let ctx = egui::Context::default();
        let mut small = Vec::new();
        let mut checked = 0;
        let mut output = ctx.run_ui(egui::RawInput::default(), |ui| {
            ui.add_sized([100.0, 20.0], egui::Button::new("small"));
            ui.add_sized([100.0, 48.0], egui::Button::new("big"));
            // Past the screen's right edge (the default screen is wide).
            let beyond = egui::Rect::from_min_size(
                egui::pos2(ui.ctx().content_rect().max.x - 20.0, 0.0),
                egui::vec2(60.0, 60.0),
            );
            ui.interact(beyond, ui.scope_id().with("beyond"), egui::Sense::click());
            ui.add(egui::Label::new("words").selectable(false));
            // A region, not a target.
            ui.allocate_exact_size(egui::vec2(300.0, 300.0), egui::Sense::drag());
            checked = audit(ui.ctx(), &mut small);
        });
        output.textures_delta.clear();
        assert_eq!(checked, 3, "{small:?}");
        assert_eq!(small.len(), 2, "{small:?}");
        assert!((small[0][3] - 20.0).abs() < 0.5, "{small:?}");
        assert!(
            (small[1][2] - 60.0).abs() < 0.5,
            "the cut-off one: {small:?}"
        );
    }
}
