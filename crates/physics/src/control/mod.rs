//! Control: the running controllers (Raibert & Hodgins 1991, "Control"):
//! hopping height by the leg spring's rest length and thrust (eq. 2), speed by
//! foot placement about the neutral point (eq. 3), posture by the hip servo of
//! eq. 4, all sequenced by the state machine of Figure 4. The
//! [`gait_controller`] picks the state machine of each gait.

pub mod attitude;
pub mod biped_gallop;
pub mod biped_run;
pub mod gains;
pub mod gait_controller;
pub mod hip_servo;
pub mod kangaroo_hop;
pub mod parameters;
pub mod phase;
pub mod placement;
pub mod quadruped_bound;
pub mod quadruped_run;

pub use phase::Phase;
