//! The engine as the rest of gaitlab sees it: a preset in, a pose
//! and the paper's figures out (Raibert & Hodgins 1991, Tables 2 and 3).
//!
//! The [`driver`] runs a [`preset`]'s creature under its gait controller for
//! the app and the CLI, steering it ([`steering`]) and showing it ([`probe`]);
//! [`metrics`] measures the Table-2 figures, [`pair_timing`] how nearly
//! each virtual leg's legs act in unison, and
//! [`table2`] holds the paper's; [`mjcf`] exports the creature to MuJoCo;
//! [`trace`] writes its state after every step; [`cycle_start`] starts a
//! run on the gait's cycle, and [`gait_entry`] a switched-to gait at its
//! own start; [`push`] pushes the trunk and judges the recovery.

pub mod consistency;
pub mod cycle_start;
pub mod driver;
pub mod gait_change;
pub mod gait_entry;
pub mod metrics;
pub mod mjcf;
pub mod pair_timing;
pub mod parameters;
pub mod preset;
pub mod probe;
pub mod push;
pub mod steering;
pub mod table2;
pub mod trace;
