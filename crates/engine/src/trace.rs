//! The per-step trace of a run (`gaitlab run … --trace FILE.csv`): Raibert &
//! Hodgins 1991's state machine and body after every integration step, as the
//! physics engine's [`TraceWriter`] writes it. Only a simulated creature has
//! one; the kinematic engines have no state machine or forces to trace.

use std::fmt;

use gaitlab_core::driver::Driver;
use gaitlab_physics::engine::trace::TraceWriter;

use crate::AnyDriver;

/// A trace being written: [`StepTrace::begin`] writes the header, then
/// [`StepTrace::step`] takes the place of [`Driver::step`].
#[derive(Clone, Debug)]
pub struct StepTrace {
    writer: TraceWriter,
}

impl StepTrace {
    /// Starts a trace of `driver` into `out` (its CSV header).
    ///
    /// # Errors
    /// `Err(None)` when `driver` is not a physics driver (nothing is
    /// written); `Err(Some(error))` for an error of `out`.
    pub fn begin(
        driver: &AnyDriver,
        out: &mut impl fmt::Write,
    ) -> Result<Self, Option<fmt::Error>> {
        let physics = driver.physics().ok_or(None)?;
        let writer = TraceWriter::new(physics);
        writer.header(physics, out).map_err(Some)?;
        Ok(Self { writer })
    }

    /// Steps `driver` by `dt`, writing a row to `out` after every integration
    /// step; allocates nothing.
    ///
    /// # Errors
    /// The first error of `out`; the step itself always completes.
    pub fn step(
        &mut self,
        driver: &mut AnyDriver,
        dt: f64,
        out: &mut impl fmt::Write,
    ) -> fmt::Result {
        match driver.physics_mut() {
            Some(physics) => self.writer.step(physics, dt, out),
            None => {
                driver.step(dt);
                Ok(())
            }
        }
    }
}
