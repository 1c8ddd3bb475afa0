//! Grab and pull (issue 44 item 1; the lab's addition — She 2006 moves its
//! targets by script only): in the IK engine a press on a target or an
//! effector in the 3-D view picks it (the nearest within a fingertip, with a
//! hover highlight; elsewhere a drag still turns the camera), and dragging
//! moves that effector's target on the plane through it facing the camera.
//! The script lets go of a held target and takes it back, blended, on
//! release (`gaitlab_motion::held`); side by side, every view's figure
//! chases the same target. *Pin* keeps a released target where it was left.
//! The drag only records what the hand did ([`GrabEvent`]); the lab applies
//! it to every figure.

mod command;
mod controls;
mod figures;
mod hand;
mod pick;
mod pins;
mod tool;

pub use command::{DragTargetCommand, MAX_DRAG_M};
pub use controls::controls;
pub use figures::{Applied, apply, offer_points};
pub use hand::{Grab, GrabEvent, SETTLE_FRAMES};
pub use pick::{OVERLAP_PT, PICK_RADIUS_PT, Pickable, nearest, on_drag_plane, ray};
pub use pins::{pinned, resolve};
