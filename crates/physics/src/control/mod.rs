//! Control: the running controllers (Raibert & Hodgins 1991, "Control"):
//! hopping height by the leg spring's rest length and thrust (eq. 2), speed by
//! foot placement about the neutral point (eq. 3), posture by the hip servo of
//! eq. 4, all sequenced by the state machine of Figure 4.
//!
//! Three folders: [`laws`] holds the paper's parts, one per equation (Table
//! 1's scaling, eqs. 1–6, Figure 4's states); [`gaits`] holds one folder per
//! gait's controller (its state machine, its parameters and their origins,
//! its start) and the one table of gaits that builds them; [`additions`]
//! holds what the lab adds to the paper's laws, each named and off by default
//! where a gait runs by the paper's laws alone.

pub mod additions;
pub mod gaits;
pub mod laws;

pub use gaits::origins::ControllerParam;
pub use laws::phase::Phase;
