//! PODA's per-frame stages (Girard & Maciejewski 1985), each a function of
//! the fixed [`PodaModel`](super::model::PodaModel) and the changing
//! [`PodaState`](super::state::PodaState), run in this order:
//! 1. [`body`]: the body's planned ground pose (eq. 14–15, yaw) and its
//!    height, pitch and surge from the legs' vertical motion (eq. 12–13,
//!    Figure 2, "Horizontal Control");
//! 2. [`legs`]: each leg's state (eq. 9, or its own cycles after a gait
//!    change) and its lift-off and touchdown since the last frame;
//! 3. [`footholds`]: eq. 11 at each lift-off;
//! 4. [`targets`]: the feet's targets — planted where they landed (eq. 10),
//!    or on the transfer spline through the key leg positions;
//! 5. [`ik`]: the root held within the planted feet's reach, the key
//!    positions' centre angles, and the legs' pseudoinverse IK with
//!    null-space centering (eq. 5–6).
//!
//! Each reads what the earlier ones wrote this frame; none reads the
//! driver, and only the driver's setters change the model.

pub mod body;
pub mod footholds;
pub mod ik;
pub mod legs;
pub mod targets;
