//! The gaits' controllers (Raibert & Hodgins 1991, "Gaits"): one folder per
//! controller, and [`table`], the one table of (species, gait) rows that
//! says how each is built, where it starts, its virtual legs, the speeds and
//! scales it is tested at and the lab's additions it offers. Adding a gait
//! is a folder here and a row there.

pub mod biped_gallop;
pub mod biped_run;
pub mod bound;
pub mod builder;
pub mod controller;
pub mod gains;
pub mod gait;
pub mod hopper_params;
pub mod kangaroo_hop;
pub mod make;
pub mod origins;
pub mod pace;
pub mod parameters;
pub mod start;
pub mod table;
pub mod trot;
