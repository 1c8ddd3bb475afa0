//! The Jacobian panel's state as the lab holds it (issue 44 item 6: a
//! feature owns its state): the probe's figures and the request to open or
//! close the panel's section at the next frame.

use super::probe::JacobianProbe;

/// The Jacobian feature's state.
#[derive(Clone, Debug, Default)]
pub struct Jacobian {
    /// The figures: singular values, gains, traces.
    pub probe: JacobianProbe,
    /// Open (true) or close the panel's section at the next frame
    /// (`jacobian_panel`, a lesson), then leave it to the person.
    pub open_request: Option<bool>,
}
