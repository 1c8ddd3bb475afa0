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
use crate::world::sim::{Controller, Sim};

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

    /// Take `fresh`'s parameters and run on with its own state, when `fresh`
    /// is the same state machine in another style (the bound and the
    /// gallop); `false` for any other, which then takes over at the next
    /// flight instead.
    fn adopt(&mut self, _fresh: &dyn Gait) -> bool {
        false
    }
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
