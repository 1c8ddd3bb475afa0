//! First steps (issue 21 item 4): a one-line introduction at the top of the
//! controls with a Help button, and the help window — what each colour of
//! the 3-D view means, how to move the camera and time, and what each engine
//! is.

use super::panel::Panel;
use crate::app::App;
use crate::render::gait_overlay::{FOOTHOLD_COLOR, FOOTPRINT_COLOR, PATH_COLOR};
use crate::render::physics_overlay::OBSTACLE_COLOR;
use crate::render::scene::{
    CENTRE_COLOR, EFFECTOR_COLOR, ERROR_COLOR, LEFT_COLOR, RIGHT_COLOR, TARGET_COLOR,
    TARGET_OUT_OF_REACH_COLOR, WORLD_AXIS_COLORS,
};
use crate::render::support_overlay::{SUPPORT_COLOR, UNSUPPORTED_COLOR};

/// The introduction line and the Help button.
pub struct IntroPanel;

impl Panel for IntroPanel {
    fn title(&self) -> &'static str {
        "Introduction"
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label(INTRO);
            let help = ui
                .button("Help")
                .on_hover_text("What the colours mean, how to move the view, the three engines");
            lab.layout.widgets_pt.help = crate::lab::layout::rect_pt(help.rect);
            if help.clicked() {
                lab.layout.help_open = !lab.layout.help_open;
            }
        });
    }
}

/// The introduction, one line.
pub const INTRO: &str = "Legged figures animated by three classic papers: pick an engine and a preset, change what you like, compare.";

/// The 3-D view's key: each colour and what it marks.
const KEY: [([f32; 4], &str); 14] = [
    (
        LEFT_COLOR,
        "the figure's left side (left_knee, front-left-foot, PODA's L1…); the plots draw its series in blues",
    ),
    (
        RIGHT_COLOR,
        "its right side (right_…, …-right-…, R1…); the plots draw its series in oranges",
    ),
    (CENTRE_COLOR, "its centre line: trunk, spine, head"),
    (EFFECTOR_COLOR, "end effectors: hands and feet the IK moves"),
    (TARGET_COLOR, "IK targets the effectors follow"),
    (
        TARGET_OUT_OF_REACH_COLOR,
        "a target beyond its limb's reach",
    ),
    (ERROR_COLOR, "the gap from an effector to its target"),
    (FOOTHOLD_COLOR, "PODA: a foot's next foothold"),
    (FOOTPRINT_COLOR, "PODA: where feet stood"),
    (PATH_COLOR, "PODA: the body's path"),
    (
        SUPPORT_COLOR,
        "PODA: the feet's support polygon and the body's centre",
    ),
    (
        UNSUPPORTED_COLOR,
        "the same while the centre is outside it (statically unstable)",
    ),
    (OBSTACLE_COLOR, "physics: a box in the way"),
    (
        WORLD_AXIS_COLORS[0],
        "world axes: x red, y green, z (forward) blue",
    ),
];

/// Width of the key column of "Moving around", points.
const KEY_COLUMN_PT: f32 = 110.0;

/// How to drive the view and the clock.
const CONTROLS: [(&str, &str); 10] = [
    ("Drag", "orbit the camera (one finger on a touch screen)"),
    (
        "Drag a target",
        "IK: pull a target (or a hand or foot) and watch the methods chase it",
    ),
    ("Scroll or pinch", "zoom"),
    (
        "H or double-click",
        "home view: the figure from a three-quarter view above",
    ),
    ("Space", "pause or play"),
    ("R", "reset to time 0"),
    (".", "one frame forward while paused"),
    (
        "I",
        "IK: one solver iteration (the Jacobian panel shows it)",
    ),
    (
        ",",
        "one frame back (the last 10 s are kept; History slider under Playback)",
    ),
    ("Drop a .json", "load it as a preset (or Load file…)"),
];

/// The three engines, one line each.
const ENGINES: [(&str, &str); 3] = [
    (
        "IK (She 2006)",
        "hand and foot targets move on sinusoids; Jacobian IK (transpose, pseudoinverse, DLS, SDLS) makes the 20-joint figure follow. Side by side compares the methods.",
    ),
    (
        "PODA gaits (Girard & Maciejewski 1985)",
        "a gait (period, duty factor, leg phases) places footholds; feet swing on splines and the legs follow by IK. Any number of legs.",
    ),
    (
        "Physics (Raibert & Hodgins 1991)",
        "simulated biped, quadruped and kangaroo: springy legs, hopping, foot placement for speed and hip torque for posture.",
    ),
];

/// The help window, when open.
pub fn help_window(ctx: &egui::Context, lab: &mut App) {
    if !lab.layout.help_open {
        return;
    }
    let mut open = true;
    // Over the 3-D view, clear of the controls and their Help button.
    let placement = crate::ui::window::Placement {
        width_pt: 440.0,
        height_pt: None,
        height_share: 0.85,
        centred: true,
        scrolls: true,
    };
    crate::ui::window::show(ctx, "Help", lab.narrow(), &mut open, placement, |ui| {
        ui.label(INTRO);
        ui.add_space(6.0);
        ui.strong("The 3-D view");
        for (colour, meaning) in KEY {
            ui.horizontal(|ui| {
                swatch(ui, colour);
                ui.add(egui::Label::new(meaning).wrap());
            });
        }
        ui.add_space(6.0);
        ui.strong("Moving around");
        // One row per key: the key in a fixed column, its meaning wrapping
        // in the width left (a grid gives a wrapping column only a word).
        let key_width = KEY_COLUMN_PT.min(ui.available_width() * 0.4);
        for (key, what) in CONTROLS {
            ui.horizontal(|ui| {
                let left = egui::Layout::left_to_right(egui::Align::Min);
                ui.allocate_ui_with_layout(egui::vec2(key_width, 0.0), left, |ui| {
                    ui.set_min_width(key_width);
                    ui.monospace(key);
                });
                ui.add(egui::Label::new(what).wrap());
            });
        }
        ui.add_space(6.0);
        ui.strong("The engines");
        for (name, what) in ENGINES {
            ui.label(egui::RichText::new(name).strong());
            ui.label(what);
        }
        ui.add_space(6.0);
        ui.label(
            "Every control has a tooltip. Copy link shares the whole lab; the preset \
                     editor shows a creature's JSON.",
        );
    });
    if !open {
        lab.layout.help_open = false;
    }
}

/// A small square of `colour` (sRGB, 0–1).
fn swatch(ui: &mut egui::Ui, colour: [f32; 4]) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
    ui.painter()
        .rect_filled(rect, 3.0, crate::render::viewport::color32(colour));
}
