//! Control: the running controllers (Raibert & Hodgins 1991, "Control"):
//! hopping height by the leg spring's rest length and thrust (eq. 2), speed by
//! foot placement about the neutral point (eq. 3), posture by the hip servo of
//! eq. 4, all sequenced by the state machine of Figure 4. The paper's shared
//! parts each have a module ([`scale`] Table 1, [`leg_spring`] eq. 1,
//! [`placement`] eq. 3, [`posture`] eq. 4, [`hip_servo`] eq. 5, [`phase`]
//! Figure 4's states); the gait modules compose them, and the
//! [`gait_controller`] picks the state machine of each gait.

pub mod additions;
pub mod attitude;
pub mod biped_gallop;
pub mod biped_gallop_params;
pub mod biped_run;
pub mod biped_run_params;
pub mod gains;
pub mod gait_controller;
pub mod hip_servo;
pub mod hop_height;
pub mod kangaroo_hop;
pub mod kangaroo_hop_params;
pub mod leg_spring;
pub mod pair_posture;
pub mod parameters;
pub mod phase;
pub mod placement;
pub mod posture;
pub mod quadruped_bound;
pub mod quadruped_bound_params;
pub mod quadruped_run;
pub mod quadruped_run_params;
pub mod scale;
pub mod speed_trim;
pub mod start;

pub use phase::Phase;
