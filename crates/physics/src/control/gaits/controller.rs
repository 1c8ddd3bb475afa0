//! The gait controllers a physics driver runs: which of Raibert & Hodgins
//! 1991's state machines drives each gait of each model ("Gaits"), how each
//! is built from a preset's physics section, and the state it starts from.

use crate::control::additions::Additions;
use crate::control::gaits::biped_gallop::BipedGallop;
use crate::control::gaits::biped_run::BipedRun;
use crate::control::gaits::bound::{QuadrupedBound, bound_start};
use crate::control::gaits::kangaroo_hop::{KangarooHop, kangaroo_start};
use crate::control::gaits::trot::{QuadrupedRun, quadruped_start};
use crate::creatures::Species;
use crate::world::sim::{Controller, Sim};

/// The gaits of each model, the default first.
#[must_use]
pub fn gait_names(species: Species) -> &'static [&'static str] {
    match species {
        Species::Biped => &["run", "gallop", "gallop_alternate"],
        Species::Quadruped => &["trot", "bound", "gallop"],
        Species::Kangaroo => &["hop"],
    }
}

/// With the lab's speed ramp, the kangaroo starts no faster than this (m/s
/// at scale 1) and its controller ramps to the desired speed: started at
/// 5 m/s it tumbles.
pub const KANGAROO_START_MPS: f64 = 2.0;

/// The controller of the gait running: one of the paper's state machines.
/// (One lives per driver, so the variants' differing sizes do not matter.)
#[derive(Clone, Debug)]
pub enum GaitController {
    /// Biped running (Figure 4).
    BipedRun(Box<BipedRun>),
    /// Biped galloping, either style.
    BipedGallop(Box<BipedGallop>),
    /// Quadruped trot on virtual legs.
    Quadruped(Box<QuadrupedRun>),
    /// Quadruped bound or gallop: front and rear pairs as a planar biped.
    QuadrupedBound(Box<QuadrupedBound>),
    /// The kangaroo's hop.
    Kangaroo(Box<KangarooHop>),
}

impl GaitController {
    /// The lab's additions this controller runs with (its parameters'
    /// flags, resolved when it was made).
    #[must_use]
    pub fn additions(&self) -> Additions {
        let none = Additions::NONE;
        match self {
            GaitController::BipedRun(c) => Additions {
                speed_trim: c.params.speed_trim,
                unloading_posture: c.params.unloading_posture,
                ..none
            },
            GaitController::BipedGallop(c) => Additions {
                speed_trim: c.params.speed_trim,
                ..none
            },
            GaitController::Quadruped(_) => none,
            GaitController::QuadrupedBound(c) => Additions {
                speed_trim: c.params.speed_trim,
                ..none
            },
            GaitController::Kangaroo(c) => Additions {
                speed_trim: c.params.speed_trim,
                speed_ramp: c.params.speed_ramp,
                tail_feedback: c.params.tail_feedback,
                ..none
            },
        }
    }

    /// The virtual legs whose legs this gait means to act together, as
    /// indices into the creature's legs, the leg meant to land first
    /// first: the trot's diagonal pairs, the bound's and gallop's front and
    /// rear pairs, the biped gallop's two legs; none for one-legged
    /// running and hopping.
    #[must_use]
    pub fn virtual_legs(&self) -> &'static [[usize; 2]] {
        match self {
            GaitController::Quadruped(_) => &crate::control::gaits::trot::TROT_PAIRS,
            GaitController::QuadrupedBound(_) => &crate::control::gaits::bound::PAIRS,
            GaitController::BipedGallop(_) => &[[0, 1]],
            GaitController::BipedRun(_) | GaitController::Kangaroo(_) => &[],
        }
    }

    fn inner(&self) -> &dyn Controller {
        match self {
            GaitController::BipedRun(c) => c.as_ref(),
            GaitController::BipedGallop(c) => c.as_ref(),
            GaitController::Quadruped(c) => c.as_ref(),
            GaitController::QuadrupedBound(c) => c.as_ref(),
            GaitController::Kangaroo(c) => c.as_ref(),
        }
    }

    fn inner_mut(&mut self) -> &mut dyn Controller {
        match self {
            GaitController::BipedRun(c) => c.as_mut(),
            GaitController::BipedGallop(c) => c.as_mut(),
            GaitController::Quadruped(c) => c.as_mut(),
            GaitController::QuadrupedBound(c) => c.as_mut(),
            GaitController::Kangaroo(c) => c.as_mut(),
        }
    }
}

impl Controller for GaitController {
    fn control(
        &mut self,
        input: &crate::world::sim::ControlInput<'_>,
        drives: &mut [crate::world::sim::Drive],
    ) {
        self.inner_mut().control(input, drives);
    }

    fn servo(
        &mut self,
        input: &crate::world::sim::ControlInput<'_>,
        drives: &mut [crate::world::sim::Drive],
    ) {
        self.inner_mut().servo(input, drives);
    }

    fn phase_name(&self) -> &'static str {
        self.inner().phase_name()
    }

    fn leg_phase_name(&self, leg: usize) -> Option<&'static str> {
        self.inner().leg_phase_name(leg)
    }

    fn set_speed(&mut self, speed_mps: f64) {
        self.inner_mut().set_speed(speed_mps);
    }

    fn set_heading(&mut self, heading: f64) {
        self.inner_mut().set_heading(heading);
    }

    fn set_hop_height(&mut self, height_m: f64) {
        self.inner_mut().set_hop_height(height_m);
    }

    fn hop_height_m(&self) -> Option<f64> {
        self.inner().hop_height_m()
    }

    fn gains(&self) -> Vec<crate::world::sim::Gain> {
        self.inner().gains()
    }

    fn set_gain(&mut self, name: &str, value: f64) -> bool {
        self.inner_mut().set_gain(name, value)
    }

    fn parameter(&self, name: &str) -> Option<f64> {
        self.inner().parameter(name)
    }

    fn parameter_names(&self) -> &'static [&'static str] {
        self.inner().parameter_names()
    }
}

/// Put `sim` in the starting state of `controller` where it has its own:
/// the quadruped just above standing height, the kangaroo just before a
/// landing at no more than [`KANGAROO_START_MPS`] (its controller ramps to
/// the rest); other creatures keep the preset's rest pose.
pub fn start_state(sim: &mut Sim, controller: &GaitController, speed_mps: f64) {
    match controller {
        GaitController::Quadruped(_) => quadruped_start(sim, speed_mps),
        GaitController::QuadrupedBound(_) => bound_start(sim, speed_mps),
        GaitController::Kangaroo(c) if c.params.speed_ramp => {
            kangaroo_start(sim, speed_mps.clamp(0.0, KANGAROO_START_MPS));
        }
        GaitController::Kangaroo(_) => kangaroo_start(sim, speed_mps),
        GaitController::BipedRun(_) | GaitController::BipedGallop(_) => {}
    }
}
