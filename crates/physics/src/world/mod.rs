//! The world a creature runs in: its actuators, the ground, and the
//! fixed-step loop that joins them to the dynamics (Raibert & Hodgins 1991,
//! "Modeling" and Figure 2).
//!
//! [`actuator`]s (the spring-damper of eq. 1, the servo of eq. 5, joint
//! stops); [`ground`] contact (springs, the kangaroo's paw pad, terrain);
//! the [`ground_view`] a controller gets of the terrain; the
//! [`commands`] a person gives (speed, heading, hop height); the
//! [`sim`] loop `kinematics → contacts → control → actuators → dynamics →
//! integrate`, ending each step in the blow-up guard.

pub mod actuator;
pub mod commands;
pub mod ground;
pub mod ground_view;
pub mod sim;
