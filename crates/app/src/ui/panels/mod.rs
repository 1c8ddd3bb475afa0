//! The control panels and their registry: every panel is a type implementing
//! [`Panel`], listed once in [`REGISTRY`] in the order they show; adding a
//! panel touches its own file and one line here.

mod buttons;
mod compare;
mod gait;
mod ground_view;
mod help;
mod ik;
mod jacobian;
pub(crate) mod lesson;
mod motion;
mod panel;
mod path;
mod physics;
mod preset;
mod readout;
mod recording;
mod separator;
mod share;
mod stability;
mod terrain;
mod track;
mod view;
mod waypoints;

pub use buttons::buttons;
pub(crate) use buttons::history_scrubber;
pub use compare::cards as compare_cards;
pub use help::{INTRO, help_window};
pub use panel::Panel;
pub use share::editor_window;
pub use stability::UNSTABLE_WARNING_SHARE;

/// Every panel of the controls, top to bottom; each shows when its
/// [`Panel::shown_for`] says so.
pub static REGISTRY: &[&dyn Panel] = &[
    &help::IntroPanel,
    &preset::EnginePanel,
    &preset::PresetPanel,
    &share::SharePanel,
    &lesson::LessonPanel,
    &buttons::ButtonsPanel,
    &buttons::RatePanel,
    &separator::Separator,
    &track::TrackPanel,
    &physics::PhysicsPanel,
    &waypoints::WaypointsPanel,
    &gait::GaitPanel,
    &path::PathPanel,
    &terrain::TerrainPanel,
    &compare::SideBySidePanel,
    &ik::MethodPanel,
    &jacobian::JacobianPanel,
    &motion::MotionPanel,
    &motion::SpeedAndTargetsPanel,
    &view::ViewPanel,
    &recording::RecordingPanel,
    &separator::Separator,
    &readout::ReadoutPanel,
];

/// The titles of the control panels a lesson can hide (every panel but the
/// separators and the lesson's own), top to bottom.
#[must_use]
pub fn hideable_titles() -> Vec<&'static str> {
    let mut titles: Vec<&'static str> = REGISTRY
        .iter()
        .map(|p| p.title())
        .filter(|t| *t != "—" && *t != crate::lesson::LESSON_PANEL)
        .collect();
    titles.dedup();
    titles
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{App, Settings};

    /// Which panels show for a preset, by title.
    fn shown(preset: &str) -> Vec<&'static str> {
        let mut lab = App::new(Settings::default());
        lab.set_preset(preset).expect("bundled");
        REGISTRY
            .iter()
            .filter(|p| p.shown_for(&lab))
            .map(|p| p.title())
            .filter(|t| *t != "—")
            .collect()
    }

    #[test]
    fn each_engine_gets_its_panels_from_the_registry() {
        let common = [
            "Introduction",
            "Engine",
            "Preset",
            "Share",
            "Lesson",
            "Reset / Pause / Step",
            "Playback",
        ];
        let tail = ["View", "Recording", "Readout"];
        let with = |middle: &[&'static str]| -> Vec<&'static str> {
            common.iter().chain(middle).chain(&tail).copied().collect()
        };
        assert_eq!(
            shown("human"),
            with(&["Side by side", "Method", "Jacobian", "Motion", "Speed"])
        );
        assert_eq!(
            shown(gaitlab_engine::bundled_for_engine(
                gaitlab_core::preset::Engine::Poda,
                "human"
            )),
            with(&["Gait", "Path", "Terrain"])
        );
        assert_eq!(
            shown(gaitlab_engine::bundled_for_engine(
                gaitlab_core::preset::Engine::Physics,
                "human"
            )),
            with(&["Physics", "Path (waypoints)", "Terrain"])
        );
        // The planar kangaroo cannot turn: no waypoints.
        assert_eq!(shown("raibert-kangaroo"), with(&["Physics", "Terrain"]));
    }
}
