//! What a gait's folder gives the gait table
//! ([`crate::control::gaits::table`]): a state machine that is a [`Gait`]
//! (a [`Controller`] that knows where its parameters come from), a
//! [`Build`] that makes it from a preset and a [`Start`] that puts the
//! creature in the gait's own starting state.

use std::any::Any;
use std::fmt;

use gaitlab_core::preset::PhysicsParams;

use crate::control::additions::Additions;
use crate::control::gaits::builder::Misfit;
use crate::control::gaits::origins::ControllerParam;
use crate::creatures::PhysicalCreature;
use crate::world::sim::{ControlInput, Controller, Sim};

/// Builds a gait's state machine from a preset's physics section and the
/// lab's additions resolved for it.
pub type Build = fn(&PhysicalCreature, &PhysicsParams, Additions) -> Result<Box<dyn Gait>, Misfit>;

/// Puts a simulation in a gait's own start at a desired speed (m/s at scale
/// 1), given the additions the gait runs with.
pub type Start = fn(&mut Sim, f64, Additions);

/// A gait's state machine: a [`Controller`] that can say where its named
/// parameters come from and be cloned and looked at behind the table's
/// uniform type.
pub trait Gait: Controller + GaitBox + fmt::Debug + Send + Sync {
    /// Where each of its named parameters comes from, in its parameters'
    /// [`NamedParameters::NAMES`](crate::control::gaits::parameters::NamedParameters::NAMES)
    /// order.
    fn origins(&self) -> &'static [ControllerParam];

    /// What it hands a gait taking over from it (the paper's take-over at
    /// the next flight). Default: nothing measured.
    fn handover(&self) -> Handover {
        Handover::default()
    }

    /// Whether, waiting to take over, it can start in the flight `input`
    /// sees (the driver asks only in a flight with the trunk falling).
    /// Default: any such flight.
    fn can_take_over(&self, _input: &ControlInput<'_>) -> bool {
        true
    }

    /// Start from the state `input` sees and what the running gait
    /// measured (`found`), instead of from this gait's own start. Default:
    /// as built.
    fn take_over_from(&mut self, _input: &ControlInput<'_>, _found: &Handover) {}
}

/// What a running gait hands the gait taking over from it at the next
/// flight (Raibert & Hodgins 1991, "Gaits": the quadruped "changes gait").
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Handover {
    /// The support period it measured last (s, at the creature's scale):
    /// eq. 3's "the duration of the next support period is predicted to be
    /// the same as the measured duration of the previous support period".
    pub stance_s: Option<f64>,
}

/// What every [`Gait`] gets for being `Clone` and `'static`: a boxed copy
/// and a look at its concrete type.
pub trait GaitBox {
    /// A boxed copy.
    fn clone_box(&self) -> Box<dyn Gait>;
    /// For [`GaitController::get`](crate::control::gaits::controller::GaitController::get).
    fn as_any(&self) -> &dyn Any;
    /// For [`GaitController::get_mut`](crate::control::gaits::controller::GaitController::get_mut).
    fn as_any_mut(&mut self) -> &mut dyn Any;
}

impl<T: Gait + Clone + 'static> GaitBox for T {
    fn clone_box(&self) -> Box<dyn Gait> {
        Box::new(self.clone())
    }

    fn as_any(&self) -> &dyn Any {
        self
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }
}
