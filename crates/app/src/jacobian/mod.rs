//! The Jacobian panel's model (issue 44 item 2; She 2006 §4.4 read through the
//! SVD of J, §4.4.4): for each IK figure on screen, the singular values of
//! its stacked Jacobian, the condition number and the running method's gain
//! per singular direction ([`gaitlab_core::ik::Spectrum`]); for the first figure, the smallest
//! σ and the condition number over the last [`TRACE_S`] seconds and each
//! iteration's ‖Δθ‖ with the error before and after it. Refreshed after every
//! frame and every single iteration; allocation-free once its buffers have
//! grown.

mod controls;
mod feature;
mod panel;
mod probe;
mod state;

pub use controls::iteration_row;
pub use feature::Jacobian;
pub use panel::figures;
pub use probe::{FramePoint, IterationPoint, JacobianProbe, MAX_TRACED_ITERATIONS, TRACE_S};
pub use state::{JacobianState, SpectrumState};
