//! The parts of Raibert & Hodgins 1991's control and model that every gait
//! composes, one per equation: [`scale`] Table 1's dynamic scaling,
//! [`leg_spring`] eq. 1's leg spring, [`hop_height`] eq. 2's hop height
//! (with [`lift_share`], the share of a pair's work that lifts the body),
//! [`placement`] eq. 3's foot placement, [`posture`] and [`pair_posture`]
//! eq. 4's posture servo (one leg; a virtual leg's pair), [`hip_servo`]
//! eq. 5's joint servos, [`ground`] eq. 6's ground springs, [`phase`] Figure
//! 4's states; [`attitude`] and [`body_plan`] are what those laws read of
//! the trunk and the legs.

pub mod attitude;
pub mod body_plan;
pub mod ground;
pub mod hip_servo;
pub mod hop_height;
pub mod leg_spring;
pub mod lift_share;
pub mod pair_posture;
pub mod phase;
pub mod placement;
pub mod posture;
pub mod scale;
