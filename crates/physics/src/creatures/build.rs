//! Shared construction helpers for the creature models: scaled bodies and the
//! mapping from the paper's axes (x forward, y left, z up) to gaitlab's
//! (x left, y up, z forward — a cyclic permutation, so handedness is kept).

use glam::{DMat3, DVec3};

use crate::dynamics::model::{Body, Joint};
use crate::dynamics::spatial::ParentLink;

/// A paper-frame vector `(forward, left, up)` in gaitlab axes.
#[must_use]
pub fn paper(forward: f64, left: f64, up: f64) -> DVec3 {
    DVec3::new(left, up, forward)
}

/// A diagonal inertia given in the paper's `[x y z]` order, in gaitlab axes.
#[must_use]
pub fn paper_inertia(ixx: f64, iyy: f64, izz: f64) -> DMat3 {
    DMat3::from_diagonal(DVec3::new(iyy, izz, ixx))
}

/// Incremental model builder applying the scale factor `l`.
pub struct Builder {
    pub bodies: Vec<Body>,
    pub l: f64,
}

impl Builder {
    pub fn new(l: f64) -> Self {
        Self {
            bodies: Vec::new(),
            l,
        }
    }

    /// Add a body; `at`, `com` in metres and `mass`, `inertia` at scale 1.
    #[expect(
        clippy::too_many_arguments,
        reason = "one call per row of Table 3 reads best flat"
    )]
    pub fn body(
        &mut self,
        name: &str,
        parent: Option<usize>,
        joint: Joint,
        at: DVec3,
        mass: f64,
        com: DVec3,
        inertia: DMat3,
    ) -> usize {
        let l = self.l;
        self.bodies.push(Body {
            name: name.to_owned(),
            parent,
            joint,
            placement: ParentLink {
                rot: DMat3::IDENTITY,
                pos: at * l,
            },
            mass: mass * l.powi(3),
            com: com * l,
            inertia_com: inertia * l.powi(5),
        });
        self.bodies.len() - 1
    }

    /// A massless link of a multi-DOF joint.
    pub fn link(&mut self, name: &str, parent: Option<usize>, joint: Joint, at: DVec3) -> usize {
        self.body(name, parent, joint, at, 0.0, DVec3::ZERO, DMat3::ZERO)
    }
}
