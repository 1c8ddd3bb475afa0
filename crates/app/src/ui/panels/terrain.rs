//! The Terrain panel (issue 45 item 4): the ground under the figure — the
//! floor, a slope, a flight of stairs or random rough ground from a seed and
//! a difficulty (0 is flat) — built with one click and tuned with sliders;
//! the walk starts again on the new ground and the link carries it. A height
//! field from a preset file shows here as it is.

use gaitlab_core::terrain::{Plane, Rough, Stairs, Terrain};
use gaitlab_engine::DriverKind;

use super::panel::Panel;
use crate::app::App;

/// The Terrain panel.
pub struct TerrainPanel;

impl Panel for TerrainPanel {
    fn title(&self) -> &'static str {
        "Terrain"
    }

    /// PODA and physics creatures (the IK figures walk on the floor only;
    /// ground a physics gait cannot take is refused with the engine's reason).
    fn shown_for(&self, lab: &App) -> bool {
        matches!(lab.driver().kind(), DriverKind::Poda | DriverKind::Physics)
    }

    fn ui(&self, lab: &mut App, ui: &mut egui::Ui) {
        terrain(ui, lab);
    }
}

/// The heading the creatures walk at the start, degrees (+z).
const FORWARD_DEG: f64 = 90.0;

/// The panel's ground of each kind, kept between frames (egui's memory)
/// so a kind comes back as it was last set.
#[derive(Clone, Debug)]
struct Drafts {
    slope: Plane,
    stairs: Stairs,
    rough: Rough,
    /// The running ground the drafts last followed (`None` for a height
    /// field, whose grid is not kept: its kind is enough).
    seen: Option<Terrain>,
}

impl Default for Drafts {
    fn default() -> Self {
        Self {
            slope: Plane {
                slope_deg: 10.0,
                direction_deg: FORWARD_DEG,
            },
            stairs: Stairs {
                rise_m: 0.05,
                run_m: 0.3,
                count: 5,
                direction_deg: FORWARD_DEG,
                start_m: 0.5,
            },
            rough: Rough::new(1, 0.5),
            seen: Some(Terrain::Flat),
        }
    }
}

impl Drafts {
    /// Takes the running ground's values for its kind when it changed
    /// since the last look (a link, a preset, the `terrain` command).
    fn follow(&mut self, running: &Terrain) {
        let same = match (&self.seen, running) {
            (None, Terrain::HeightField(_)) => true,
            (Some(seen), running) => seen == running,
            (None, _) => false,
        };
        if same {
            return;
        }
        self.seen = match running {
            Terrain::HeightField(_) => None,
            other => Some(other.clone()),
        };
        match running {
            Terrain::Plane(plane) => self.slope = plane.clone(),
            Terrain::Stairs(stairs) => self.stairs = stairs.clone(),
            Terrain::Rough(rough) => self.rough = rough.clone(),
            Terrain::Flat | Terrain::HeightField(_) => {}
        }
    }
}

/// One line saying what the ground is.
fn describe(terrain: &Terrain) -> String {
    match terrain {
        Terrain::Flat => "the floor (flat, every paper's ground)".to_owned(),
        Terrain::Plane(p) => format!(
            "a {:.1}° slope rising toward {:.0}°",
            p.slope_deg, p.direction_deg
        ),
        Terrain::Stairs(s) => format!(
            "{} steps of {:.0} mm {}, treads {:.2} m, toward {:.0}°",
            s.count,
            s.rise_m.abs() * 1e3,
            if s.rise_m < 0.0 { "down" } else { "up" },
            s.run_m,
            s.direction_deg
        ),
        Terrain::HeightField(f) => format!(
            "a height field of {} × {} samples, {:.0} mm apart (from the preset)",
            f.cols,
            f.rows,
            f.cell_m * 1e3
        ),
        Terrain::Rough(r) => format!(
            "rough ground, seed {}, difficulty {:.2} (bumps up to {:.0} mm)",
            r.seed,
            r.difficulty,
            r.difficulty * r.max_height_m * 1e3
        ),
    }
}

/// Whether a slider's change should build the ground now: on release, or
/// on a change that was not a drag (a click, the keyboard). The sliders have
/// no step: egui rounds a stepped slider's value every frame it shows, which
/// would count as a change.
fn settled(response: &egui::Response) -> bool {
    response.drag_stopped() || (response.changed() && !response.dragged())
}

fn terrain(ui: &mut egui::Ui, lab: &mut App) {
    let id = egui::Id::unique("gaitlab terrain drafts");
    let mut drafts: Drafts = ui.data(|d| d.get_temp(id)).unwrap_or_default();
    drafts.follow(lab.terrain());
    let (kind, ground) = (lab.terrain().kind_name(), describe(lab.terrain()));
    let mut build: Option<Terrain> = None;
    let panel = ui.collapsing("Terrain", |ui| {
        ui.label(format!("Ground: {ground}"));
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Flat")
                .on_hover_text("The floor, as in every paper")
                .clicked()
            {
                build = Some(Terrain::Flat);
            }
            if ui
                .button("Slope")
                .on_hover_text("A plane sloped toward the walk")
                .clicked()
            {
                build = Some(Terrain::Plane(drafts.slope.clone()));
            }
            let stairs = ui
                .button("Stairs")
                .on_hover_text("A flight of stairs across the walk");
            lab.layout.widgets_pt.terrain_stairs = crate::lab::layout::rect_pt(stairs.rect);
            if stairs.clicked() {
                build = Some(Terrain::Stairs(drafts.stairs.clone()));
            }
            if ui
                .button("Rough")
                .on_hover_text("Random smooth bumps from a seed; the difficulty scales them")
                .clicked()
            {
                build = Some(Terrain::Rough(drafts.rough.clone()));
            }
        });
        match kind {
            "plane" => {
                let plane = &mut drafts.slope;
                let mut now = false;
                now |= settled(
                    &ui.add(
                        egui::Slider::new(&mut plane.slope_deg, -20.0..=20.0)
                            .text("slope")
                            .suffix("°"),
                    ),
                );
                now |= settled(
                    &ui.add(
                        egui::Slider::new(&mut plane.direction_deg, 0.0..=360.0)
                            .text("rises toward")
                            .suffix("°"),
                    ),
                );
                if now {
                    build = Some(Terrain::Plane(plane.clone()));
                }
            }
            "stairs" => {
                let stairs = &mut drafts.stairs;
                let mut now = false;
                now |= settled(
                    &ui.add(
                        egui::Slider::new(&mut stairs.rise_m, -0.15..=0.15)
                            .text("rise (− down)")
                            .suffix(" m"),
                    ),
                );
                now |= settled(
                    &ui.add(
                        egui::Slider::new(&mut stairs.run_m, 0.1..=1.0)
                            .text("tread")
                            .suffix(" m"),
                    ),
                );
                now |= settled(&ui.add(egui::Slider::new(&mut stairs.count, 1..=30).text("steps")));
                now |= settled(
                    &ui.add(
                        egui::Slider::new(&mut stairs.start_m, 0.0..=5.0)
                            .text("first riser ahead")
                            .suffix(" m"),
                    ),
                );
                now |= settled(
                    &ui.add(
                        egui::Slider::new(&mut stairs.direction_deg, 0.0..=360.0)
                            .text("climbs toward")
                            .suffix("°"),
                    ),
                );
                if now {
                    // Whole millimetres (a slider's step would add float dust to the link).
                    let mm = |m: f64| (m * 1e3).round() / 1e3;
                    stairs.rise_m = mm(stairs.rise_m);
                    stairs.run_m = mm(stairs.run_m);
                    stairs.start_m = mm(stairs.start_m);
                    build = Some(Terrain::Stairs(stairs.clone()));
                }
            }
            "rough" => {
                let rough = &mut drafts.rough;
                let mut now = settled(&ui.add(
                    egui::Slider::new(&mut rough.difficulty, 0.0..=1.0).text("difficulty (0 flat)"),
                ));
                ui.horizontal(|ui| {
                    now |= settled(&ui.add(egui::DragValue::new(&mut rough.seed).prefix("seed ")));
                    if ui
                        .button("New seed")
                        .on_hover_text("Other bumps of the same size")
                        .clicked()
                    {
                        rough.seed = rough.seed.wrapping_add(1);
                        now = true;
                    }
                });
                if now {
                    build = Some(Terrain::Rough(Rough::new(rough.seed, rough.difficulty)));
                }
            }
            _ => {}
        }
        if let Some(poda) = lab.driver().poda() {
            ui.label(format!(
                "Footholds moved off uneven spots: {}",
                poda.footholds_moved()
            ))
            .on_hover_text(
                "Where eq. 11's foothold is too steep, too near an edge or under a riser, \
                 the foot goes to the nearest acceptable spot (the lab's addition, \
                 terrain_feet): drawn as a grey cross with a line to the foothold chosen",
            );
        }
        ui.weak("New ground starts the walk again on it; a link carries it.");
    });
    lab.layout.widgets_pt.terrain_header = crate::lab::layout::rect_pt(panel.header_response.rect);
    if let Some(terrain) = build {
        match lab.set_terrain(&terrain) {
            Ok(()) => drafts.follow(lab.terrain()),
            Err(error) => lab.report_error(error),
        }
    }
    ui.data_mut(|d| d.insert_temp(id, drafts));
}
