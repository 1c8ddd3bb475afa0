//! The app's side of grab and pull ([`crate::grab`]): which points each pane
//! offers the hand, the hand's events applied to every figure on screen (so
//! side by side every view chases the same target), and a paused figure
//! reaching for a moved target.

use std::collections::BTreeMap;

use gaitlab_core::driver::Driver;
use gaitlab_engine::AnyDriver;

use super::App;
use crate::compare::Comparison;
use crate::grab::DragTargetCommand;
use crate::stage::Stage;

/// Runs `f` on every figure: the single view's driver (hidden during a
/// comparison, it keeps the holds for when the comparison ends) and each
/// comparison view's. Takes the two fields, so the hand can be borrowed
/// beside them.
fn each_figure(
    stage: &mut Stage,
    compare: &mut Option<Comparison>,
    mut f: impl FnMut(&mut AnyDriver),
) {
    f(&mut stage.driver);
    if let Some(compare) = compare.as_mut() {
        compare.for_each_driver(&mut f);
    }
}

impl App {
    /// [`each_figure`] on the lab's figures.
    fn each_driver(&mut self, f: impl FnMut(&mut AnyDriver)) {
        each_figure(&mut self.lab.stage, &mut self.compare, f);
    }

    /// Refills the hand's pickable points from the figures on screen
    /// ([`crate::grab::offer_points`]).
    pub(crate) fn offer_grab_points(&mut self) {
        match self.compare.as_ref() {
            Some(compare) => {
                crate::grab::offer_points(&mut self.grab, compare.drivers(), compare.config.overlay)
            }
            None => crate::grab::offer_points(
                &mut self.grab,
                std::iter::once(&self.lab.stage.driver),
                false,
            ),
        }
    }

    /// Applies what the hand did to every figure on screen
    /// ([`crate::grab::apply`]) and redraws when something moved.
    pub(crate) fn apply_grab(&mut self) {
        let paused = self.playback.paused;
        let (stage, compare) = (&mut self.lab.stage, &mut self.compare);
        let applied = crate::grab::apply(&mut self.grab, paused, |f| {
            each_figure(stage, compare, f);
        });
        if applied.moved || applied.settled {
            self.probe_jacobian();
            self.refresh_scene();
        }
    }

    /// `drag_target`: holds, lets go of or pins an effector's target, in
    /// every figure on screen.
    ///
    /// # Errors
    /// The command's `drag_target.…: reason`, or when the figure's targets
    /// cannot be held (PODA, physics, a recording).
    pub fn drag_target(&mut self, c: &DragTargetCommand) -> Result<(), String> {
        if self.stage.driver.held_targets().is_none() {
            return Err(
                "drag_target: only the IK engine's thesis script has targets to hold".to_owned(),
            );
        }
        let skeleton = self.session.creature.skeleton.clone();
        self.grab.command(c, &skeleton)?;
        self.apply_grab();
        Ok(())
    }

    /// The pinned targets of the single view's figure: name → where, in the
    /// root's frame, metres ([`crate::grab::pinned`]).
    #[must_use]
    pub fn pinned_targets(&self) -> BTreeMap<String, [f64; 3]> {
        self.stage
            .driver
            .held_targets()
            .map_or_else(BTreeMap::new, |held| {
                crate::grab::pinned(&self.session.creature.skeleton, held)
            })
    }

    /// `pinned_targets`: every pin at once, each a point in the root's frame
    /// (as `state().pinned_targets` and links carry them); the others let go.
    ///
    /// # Errors
    /// `pinned_targets.NAME: …` ([`crate::grab::resolve`]), or pins on a
    /// figure whose targets cannot be held; nothing changes then.
    pub fn set_pinned_targets(&mut self, pins: &BTreeMap<String, [f64; 3]>) -> Result<(), String> {
        if self.stage.driver.held_targets().is_none() {
            if pins.is_empty() {
                return Ok(());
            }
            return Err(
                "pinned_targets: only the IK engine's thesis script has targets to pin".to_owned(),
            );
        }
        let resolved = crate::grab::resolve(&self.session.creature.skeleton, pins)?;
        self.release_all_targets();
        let root = self.stage.driver.pose().root;
        for (e, body) in resolved {
            let world = root.position + root.rotation * body;
            self.each_driver(|driver| {
                driver.hold_target(e, Some(world));
                driver.pin_target(e, true);
            });
        }
        self.grab.note_moved();
        self.refresh_scene();
        Ok(())
    }

    /// Lets go of and unpins every target (the panel's *Unpin all*).
    pub fn release_all_targets(&mut self) {
        let count = self.session.creature.skeleton.effector_count();
        self.each_driver(|driver| {
            for effector in 0..count {
                driver.pin_target(effector, false);
                driver.hold_target(effector, None);
            }
        });
        self.grab.note_moved();
        self.refresh_scene();
    }
}
