//! The gait controller a physics driver runs (Raibert & Hodgins 1991,
//! "Gaits"): one of the paper's state machines, built by its row of the gait
//! table ([`crate::control::gaits::table`]), with the lab's additions it was
//! built with.

use std::fmt;

use crate::control::additions::Additions;
use crate::control::gaits::gait::{Gait, Handover};
use crate::control::gaits::origins::ControllerParam;
use crate::control::gaits::table::GaitRow;
use crate::world::sim::{ControlInput, Controller, Drive, Gain, Sim};

/// The controller of the gait running: its table row, the lab's additions
/// it runs with and its state machine.
pub struct GaitController {
    row: &'static GaitRow,
    additions: Additions,
    inner: Box<dyn Gait>,
}

impl Clone for GaitController {
    fn clone(&self) -> Self {
        Self {
            row: self.row,
            additions: self.additions,
            inner: self.inner.clone_box(),
        }
    }
}

impl fmt::Debug for GaitController {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("GaitController")
            .field("species", &self.row.species)
            .field("gait", &self.row.gait)
            .field("additions", &self.additions)
            .field("inner", &self.inner)
            .finish()
    }
}

impl GaitController {
    /// `inner`, the state machine of `row`'s gait, running with `additions`.
    #[must_use]
    pub fn new(row: &'static GaitRow, additions: Additions, inner: Box<dyn Gait>) -> Self {
        Self {
            row,
            additions,
            inner,
        }
    }

    /// The same gait and additions driven by `inner` (a copy of this one's
    /// state machine in another state).
    #[must_use]
    pub fn with_inner(&self, inner: Box<dyn Gait>) -> Self {
        Self::new(self.row, self.additions, inner)
    }

    /// Its row of the gait table.
    #[must_use]
    pub fn row(&self) -> &'static GaitRow {
        self.row
    }

    /// The gait's name (`trot`, `hop`, …).
    #[must_use]
    pub fn gait(&self) -> &'static str {
        self.row.gait
    }

    /// The lab's additions this controller runs with (resolved when it was
    /// made from its row's offer and the preset).
    #[must_use]
    pub fn additions(&self) -> Additions {
        self.additions
    }

    /// The virtual legs whose legs this gait means to act together, as
    /// indices into the creature's legs, the leg meant to land first
    /// first (its row's).
    #[must_use]
    pub fn virtual_legs(&self) -> &'static [[usize; 2]] {
        self.row.virtual_legs
    }

    /// Where each of its named parameters comes from.
    #[must_use]
    pub fn parameter_origins(&self) -> &'static [ControllerParam] {
        self.inner.origins()
    }

    /// The state machine as its concrete type, if it is a `T`.
    #[must_use]
    pub fn get<T: 'static>(&self) -> Option<&T> {
        self.inner.as_any().downcast_ref()
    }

    /// The state machine as its concrete type, if it is a `T`.
    pub fn get_mut<T: 'static>(&mut self) -> Option<&mut T> {
        self.inner.as_any_mut().downcast_mut()
    }

    /// What it hands a gait taking over from it ([`Gait::handover`]).
    #[must_use]
    pub fn handover(&self) -> Handover {
        self.inner.handover()
    }

    /// Whether, waiting to take over, it can start in the flight `input`
    /// sees ([`Gait::can_take_over`]).
    #[must_use]
    pub fn can_take_over(&self, input: &ControlInput<'_>) -> bool {
        self.inner.can_take_over(input)
    }

    /// Start from the state `input` sees and what the running gait handed
    /// over ([`Gait::take_over_from`]).
    pub fn take_over_from(&mut self, input: &ControlInput<'_>, found: &Handover) {
        self.inner.take_over_from(input, found);
    }

    /// Put `sim` in this gait's own start at `speed_mps` (m/s at scale 1)
    /// where its row has one; otherwise `sim` keeps the preset's rest pose.
    pub fn start(&self, sim: &mut Sim, speed_mps: f64) {
        if let Some(start) = self.row.start {
            start(sim, speed_mps, self.additions);
        }
    }
}

impl Controller for GaitController {
    fn control(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.inner.control(input, drives);
    }

    fn servo(&mut self, input: &ControlInput<'_>, drives: &mut [Drive]) {
        self.inner.servo(input, drives);
    }

    fn phase_name(&self) -> &'static str {
        self.inner.phase_name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        self.inner.leg_phase_name(leg)
    }

    fn hop_height_m(&self) -> Option<f64> {
        self.inner.hop_height_m()
    }

    fn gains(&self) -> Vec<Gain> {
        self.inner.gains()
    }

    fn set_gain(&mut self, name: &str, value: f64) -> bool {
        self.inner.set_gain(name, value)
    }

    fn parameter(&self, name: &str) -> Option<f64> {
        self.inner.parameter(name)
    }

    fn parameter_names(&self) -> &'static [&'static str] {
        self.inner.parameter_names()
    }
}
