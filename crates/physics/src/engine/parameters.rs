//! The running gait controller's parameter table (Raibert & Hodgins 1991,
//! eqs. 1–5, Figure 4, Table 2): each name the controller takes, with its
//! label, unit, the paper's reference and its origin
//! ([`parameter_origins`](crate::control::gaits::origins)).

use crate::control::gaits::origins::ControllerParam;
use crate::engine::driver::PhysicsDriver;

impl PhysicsDriver {
    /// Where each of the running gait controller's named parameters
    /// ([`PhysicsDriver::parameter_names`]) comes from, in that order: the
    /// table of the controller running now (after a gait change, the new
    /// one's once it has taken over).
    #[must_use]
    pub fn controller_parameters(&self) -> &'static [ControllerParam] {
        self.controller().parameter_origins()
    }
}
