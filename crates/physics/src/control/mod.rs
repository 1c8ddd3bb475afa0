//! Control: the running controllers (Raibert & Hodgins 1991, "Control"):
//! hopping height by the leg spring's rest length and thrust (eq. 2), speed by
//! foot placement about the neutral point (eq. 3), posture by the hip servo of
//! eq. 4, all sequenced by the state machine of Figure 4. The paper's shared
//! parts each have a module ([`scale`] Table 1, [`leg_spring`] eq. 1,
//! [`placement`] eq. 3, [`posture`] and [`pair_posture`] eq. 4, [`hip_servo`]
//! eq. 5, [`phase`] Figure 4's states and its stance cycle, [`commands`] the
//! desired speed, heading and hop height); the gait modules compose them
//! (each gait's state machine, its parameters in `*_params`, its leg cycle in
//! a child module), [`make_controller`] builds the one a preset asks for and
//! [`start`] puts the creature in its starting state.

pub mod additions;
pub mod attitude;
pub mod biped_gallop;
pub mod biped_gallop_params;
pub mod biped_run;
pub mod biped_run_params;
pub mod body_plan;
pub mod commands;
pub mod gains;
pub mod gait_controller;
pub mod gallop_phase;
pub mod ground;
pub mod hip_servo;
pub mod hop_height;
pub mod hopper_params;
pub mod kangaroo_hop;
pub mod kangaroo_hop_params;
pub mod kangaroo_leg;
pub mod leg_spring;
pub mod make_controller;
pub mod pair_posture;
pub mod parameter_origins;
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
pub mod tested_speeds;

pub use parameter_origins::ControllerParam;
pub use phase::Phase;
