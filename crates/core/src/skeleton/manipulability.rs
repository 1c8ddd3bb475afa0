//! The manipulability ellipsoid of an effector's limb (issue 44 item 3,
//! after Yoshikawa's measure and She 2006 §4.3's Jacobian): the principal
//! axes and singular values of the 3×3 block `J_ℓ J_ℓᵀ`, where `J_ℓ` holds
//! the position rows of effector ℓ and the columns of its limb's own joints.
//!
//! # Reading: which columns
//! The block of the stacked `J Jᵀ` for effector ℓ sums over every joint on
//! its chain, the spine and pelvis included; seen that way the hand of the
//! she-2006 human stays mobile along a straight arm (the spine moves it), and
//! the ellipsoid never flattens. The limb is the part the reach test uses
//! ([`Limb`](super::Limb): the joints no other effector depends on), so its
//! ellipsoid and its reach shell describe the same chain: it flattens to a
//! disc as the limb straightens, the direction it loses being along the limb.
//! [`Scope::Chain`] gives the whole block.
//!
//! The ellipsoid `{J_ℓ Δθ : ‖Δθ‖ ≤ 1}` has semi-axes σᵢ (metres per radian)
//! along the eigenvectors of `J_ℓ J_ℓᵀ`, whose eigenvalues are σᵢ².

use glam::DVec3;
use nalgebra::{Matrix3, SymmetricEigen};

use super::{JointKind, Skeleton};
use crate::Kinematics;

/// Which joints' columns make the block.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Scope {
    /// The limb's own joints ([`Limb::joints`](super::Limb)).
    #[default]
    Limb,
    /// Every joint on the effector's chain (the block of the stacked J Jᵀ).
    Chain,
}

/// An effector's manipulability ellipsoid.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ellipsoid {
    /// The effector, world metres.
    pub centre: DVec3,
    /// Unit principal axes, world frame, largest σ first.
    pub axes: [DVec3; 3],
    /// The semi-axes σ₁ ≥ σ₂ ≥ σ₃ ≥ 0, metres per radian.
    pub sigma: [f64; 3],
}

impl Ellipsoid {
    /// σ₃/σ₁: 1 for a sphere, 0 for a disc (a limb at a singularity); 0
    /// when every σ is 0.
    #[must_use]
    pub fn roundness(&self) -> f64 {
        if self.sigma[0] > 0.0 {
            self.sigma[2] / self.sigma[0]
        } else {
            0.0
        }
    }
}

impl Skeleton {
    /// The manipulability ellipsoid of effector `e` in the pose whose forward
    /// kinematics is `kin` (it must have run for the pose). `None` for an
    /// effector the skeleton does not have, a kinematics without it, or a
    /// non-finite pose. Allocates nothing.
    #[must_use]
    pub fn manipulability(&self, kin: &Kinematics, e: usize, scope: Scope) -> Option<Ellipsoid> {
        let centre = *kin.effector_position.get(e)?;
        let joints: &[usize] = match scope {
            Scope::Limb => &self.limbs().get(e)?.joints,
            Scope::Chain => self.chain(e),
        };
        let mut block = Matrix3::<f64>::zeros();
        for &j in joints {
            let (Some(joint), Some(&axis), Some(&anchor)) = (
                self.joints().get(j),
                kin.joint_axis.get(j),
                kin.joint_anchor.get(j),
            ) else {
                return None;
            };
            let column = match joint.kind {
                JointKind::Revolute => axis.cross(centre - anchor),
                JointKind::Prismatic => axis,
            };
            let c = nalgebra::Vector3::new(column.x, column.y, column.z);
            block += c * c.transpose();
        }
        if !centre.is_finite() || block.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let eigen = SymmetricEigen::new(block);
        let mut order = [0, 1, 2];
        order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
        let mut out = Ellipsoid {
            centre,
            ..Ellipsoid::default()
        };
        for (k, &i) in order.iter().enumerate() {
            out.sigma[k] = eigen.eigenvalues[i].max(0.0).sqrt();
            let v = eigen.eigenvectors.column(i);
            out.axes[k] = DVec3::new(v[0], v[1], v[2]).normalize_or_zero();
        }
        Some(out)
    }
}
