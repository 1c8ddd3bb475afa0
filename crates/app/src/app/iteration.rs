//! One IK iteration at a time (issue 44 item 2's "one iteration" step), and
//! the Jacobian panel's figures read after every frame and iteration
//! ([`crate::jacobian::JacobianProbe`]).

use gaitlab_engine::IterationStep;

use super::App;
use crate::jacobian::JacobianProbe;

impl App {
    /// Pauses and runs one IK iteration in the single view or, in lock step,
    /// in every comparison view: the first iteration of the next frame, or
    /// the next of a frame already opened. The iteration that closes a frame
    /// records it as a whole frame would (the plots, the take, the history
    /// scrubber), so stepping a frame's iterations one by one is the same as
    /// stepping the frame.
    ///
    /// # Errors
    /// When the figure is not driven by the thesis' script (PODA, physics, a
    /// recording): there is no iteration to step.
    pub fn step_iteration(&mut self) -> Result<IterationStep, String> {
        const NONE: &str = "one iteration at a time needs the IK engine's thesis script";
        self.set_paused(true);
        let dt = self.frame_seconds();
        let step = if let Some(compare) = self.compare.as_mut() {
            let step = compare.step_iteration(dt).ok_or(NONE)?;
            if step.done >= step.of {
                self.stage.frame += 1;
            }
            step
        } else {
            let step = self.stage.step_iteration(dt).ok_or(NONE)?;
            if step.done >= step.of {
                self.record_frame();
            }
            step
        };
        if step.done >= step.of {
            self.rewind_note();
        }
        self.probe_jacobian();
        self.refresh_scene();
        Ok(step)
    }

    /// Reads the Jacobian panel's figures from the figures on screen.
    pub(crate) fn probe_jacobian(&mut self) {
        match self.compare.as_ref() {
            Some(compare) => self.jacobian.probe.update(compare.drivers()),
            None => self
                .jacobian
                .probe
                .update(std::iter::once(&self.lab.stage.driver)),
        }
    }

    /// The Jacobian panel's figures.
    #[must_use]
    pub fn jacobian(&self) -> &JacobianProbe {
        &self.jacobian.probe
    }
}
