//! One leg's inverse kinematics in PODA ("Controlling Redundant Limbs"): the
//! position rows of the Jacobian of eq. 3 for the leg's own joints, the
//! pseudoinverse of eq. 5 for a full-rank 3×n Jacobian, `J⁺ = Jᵀ(JJᵀ)⁻¹`
//! (a 3×3 solve instead of an explicit inverse), and eq. 6's null-space term
//! `(I − J⁺J)z` with `z = −k∇H`, `H = Σ αᵢ(θᵢ − θcᵢ)²`, which pulls the joints
//! toward their center angles without moving the foot. The centre angles
//! and gains are the skeleton's (`Joint::center`, `Joint::gain`) unless the
//! caller puts others in their place for a joint ([`LegIk::set_center_override`]:
//! the driver's key leg positions while the leg transfers).
//!
//! Near a singularity (smallest singular value of J below
//! [`LegIkOptions::singular_threshold_m`]) the solve blends smoothly into damped
//! least squares, `Jᵀ(JJᵀ + λ²I)⁻¹`, with λ² growing as the leg straightens,
//! so a fully stretched leg neither explodes nor freezes.

use gaitlab_core::portable::Portable;
use gaitlab_core::{JointKind, Kinematics, Skeleton};
use glam::{DMat3, DVec3};

/// Options of [`LegIk`]; every field has a default suited to metre-scale legs.
#[derive(Clone, Debug, PartialEq)]
pub struct LegIkOptions {
    /// Gain k of the null-space term toward the center angles (eq. 6). Default 0.5.
    pub center_gain: f64,
    /// Smallest singular value of J, metres, below which damping starts. Default 0.08.
    pub singular_threshold_m: f64,
    /// Damping λ at a singular Jacobian, metres. Default 0.08.
    pub max_damping_m: f64,
    /// Longest foot displacement asked of one iteration, metres. Default 0.1.
    pub max_reach_step_m: f64,
    /// Largest joint change in one iteration, radians (metres for prismatic joints). Default 0.25.
    pub max_joint_step: f64,
}

impl Default for LegIkOptions {
    fn default() -> Self {
        Self {
            center_gain: 0.5,
            singular_threshold_m: 0.08,
            max_damping_m: 0.08,
            max_reach_step_m: 0.1,
            max_joint_step: 0.25,
        }
    }
}

/// The IK of one leg: its joints (hip first) and its foot effector, with
/// workspace reused between calls (no allocation per iteration).
#[derive(Clone, Debug)]
pub struct LegIk {
    joints: Vec<usize>,
    effector: usize,
    /// Jacobian column (position rows) per leg joint.
    columns: Vec<DVec3>,
    step: Vec<f64>,
    center_push: Vec<f64>,
    active: Vec<bool>,
    /// Per leg joint, `[center, gain]` in place of the skeleton's (`None`: the skeleton's).
    center_overrides: Vec<Option<[f64; 2]>>,
}

impl LegIk {
    /// The IK for the leg made of `joints` (indices into the skeleton, hip
    /// first) ending at effector `effector`.
    #[must_use]
    pub fn new(joints: Vec<usize>, effector: usize) -> Self {
        let n = joints.len();
        Self {
            joints,
            effector,
            columns: vec![DVec3::ZERO; n],
            step: vec![0.0; n],
            center_push: vec![0.0; n],
            active: vec![true; n],
            center_overrides: vec![None; n],
        }
    }

    /// Puts `center_gain` (`[center, gain]`: radians, or metres for a
    /// prismatic joint, and a gain in [0, 1]) in place of the skeleton's
    /// centre angle and gain of the leg's `k`-th joint (hip 0) in eq. 6's
    /// `H`; `None` gives the joint back its own. An index past the leg's
    /// joints is ignored. Values are used as given: the caller checks them.
    pub fn set_center_override(&mut self, k: usize, center_gain: Option<[f64; 2]>) {
        if let Some(slot) = self.center_overrides.get_mut(k) {
            *slot = center_gain;
        }
    }

    /// Gives every joint of the leg back its own (skeleton) centre and gain.
    pub fn clear_center_overrides(&mut self) {
        self.center_overrides.fill(None);
    }

    /// The centre angle and gain eq. 6 uses for the leg's `k`-th joint now:
    /// an override's, or the skeleton's.
    #[must_use]
    pub fn center_of(&self, skeleton: &Skeleton, k: usize) -> Option<[f64; 2]> {
        let joint = skeleton.joints().get(*self.joints.get(k)?)?;
        Some(self.center_overrides[k].unwrap_or([joint.center, joint.gain]))
    }

    /// The leg's joints, hip first.
    #[must_use]
    pub fn joints(&self) -> &[usize] {
        &self.joints
    }

    /// The foot effector.
    #[must_use]
    pub fn effector(&self) -> usize {
        self.effector
    }

    /// One iteration toward `target` (world metres): reads the pose from
    /// `kin` (forward kinematics must be current for `values`), writes the
    /// leg's joints in `values`, clamped to their limits. A joint that its
    /// step would carry past a limit stops there and the others re-solve for
    /// the rest (one extra pass). Returns the foot's distance to the target
    /// before the step, metres.
    ///
    /// The null-space term is first order: with a non-zero center gain the
    /// foot settles a second-order distance (tens of micrometres) from the
    /// target, so finish with an iteration at `center_gain` 0 for exact placement.
    pub fn iterate(
        &mut self,
        skeleton: &Skeleton,
        kin: &Kinematics,
        values: &mut [f64],
        target: DVec3,
        options: &LegIkOptions,
    ) -> f64 {
        let Some(&foot) = kin.effector_position.get(self.effector) else {
            return f64::INFINITY;
        };
        let error = target - foot;
        let distance = error.length();
        if !distance.is_finite() {
            return f64::INFINITY;
        }
        let reach = if distance > options.max_reach_step_m {
            error * (options.max_reach_step_m / distance)
        } else {
            error
        };
        let joints = skeleton.joints();
        for (k, &j) in self.joints.iter().enumerate() {
            let axis = kin.joint_axis[j];
            self.columns[k] = match joints[j].kind {
                JointKind::Revolute => axis.cross(foot - kin.joint_anchor[j]),
                JointKind::Prismatic => axis,
            };
            let joint = &joints[j];
            let (center, gain) = match self.center_overrides[k] {
                Some([center, gain]) => (center, gain),
                None => (joint.center, joint.gain),
            };
            self.center_push[k] = -options.center_gain * 2.0 * gain * (values[j] - center);
        }
        self.active.fill(true);
        self.step.fill(0.0);
        let mut remaining = reach;
        for _pass in 0..2 {
            let Some(solve) = self.damped_solver(options) else {
                break;
            };
            // Δθ = J⁺e + (I − J⁺J)z over the active joints.
            let y = solve * remaining;
            let mut jz = DVec3::ZERO;
            for k in 0..self.joints.len() {
                if self.active[k] {
                    jz += self.columns[k] * self.center_push[k];
                }
            }
            let y_null = solve * jz;
            let mut pass_step_max: f64 = 0.0;
            for k in 0..self.joints.len() {
                if self.active[k] {
                    let delta =
                        self.columns[k].dot(y) + self.center_push[k] - self.columns[k].dot(y_null);
                    self.step[k] = delta;
                    pass_step_max = pass_step_max.max(delta.abs());
                }
            }
            if pass_step_max > options.max_joint_step {
                let scale = options.max_joint_step / pass_step_max;
                for k in 0..self.joints.len() {
                    if self.active[k] {
                        self.step[k] *= scale;
                    }
                }
            }
            // Freeze joints the step would carry past a limit; re-solve once without them.
            let mut froze = false;
            for (k, &j) in self.joints.iter().enumerate() {
                if !self.active[k] {
                    continue;
                }
                let wanted = values[j] + self.step[k];
                let clamped = joints[j].clamp(wanted);
                if clamped != wanted {
                    self.step[k] = clamped - values[j];
                    self.active[k] = false;
                    froze = true;
                }
            }
            if !froze {
                break;
            }
            let mut achieved = DVec3::ZERO;
            for k in 0..self.joints.len() {
                if !self.active[k] {
                    achieved += self.columns[k] * self.step[k];
                }
            }
            remaining = reach - achieved;
        }
        for (k, &j) in self.joints.iter().enumerate() {
            values[j] = joints[j].clamp(values[j] + self.step[k]);
        }
        distance
    }

    /// `(JJᵀ + λ²I)⁻¹` over the active columns, λ = 0 away from singularities;
    /// `None` when no joint is active or the matrix cannot be inverted.
    fn damped_solver(&self, options: &LegIkOptions) -> Option<DMat3> {
        let mut jjt = DMat3::ZERO;
        let mut any = false;
        for (column, &active) in self.columns.iter().zip(&self.active) {
            if active {
                jjt += outer(*column, *column);
                any = true;
            }
        }
        if !any {
            return None;
        }
        let sigma_min = smallest_eigenvalue(&jjt).max(0.0).sqrt();
        let threshold = options.singular_threshold_m;
        let damping = if sigma_min < threshold {
            let t = sigma_min / threshold;
            (1.0 - t * t) * options.max_damping_m * options.max_damping_m
        } else {
            0.0
        };
        let damped = jjt + DMat3::from_diagonal(DVec3::splat(damping.max(1e-12)));
        let det = damped.determinant();
        (det.is_finite() && det.abs() > 1e-30).then(|| damped.inverse())
    }
}

fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// Smallest eigenvalue of a symmetric 3×3 matrix (closed form, trigonometric).
fn smallest_eigenvalue(m: &DMat3) -> f64 {
    let (a, b, c) = (m.x_axis, m.y_axis, m.z_axis);
    let p1 = b.x * b.x + c.x * c.x + c.y * c.y;
    let trace = a.x + b.y + c.z;
    if p1 <= f64::EPSILON * trace.abs().max(1e-300) {
        return a.x.min(b.y).min(c.z);
    }
    let q = trace / 3.0;
    let p2 = (a.x - q).powi(2) + (b.y - q).powi(2) + (c.z - q).powi(2) + 2.0 * p1;
    let p = (p2 / 6.0).sqrt();
    let shifted = (*m - DMat3::from_diagonal(DVec3::splat(q))) * (1.0 / p);
    let r = (shifted.determinant() / 2.0).clamp(-1.0, 1.0);
    let phi = r.pacos() / 3.0;
    // Eigenvalues q + 2p·cos(φ + 2πk/3); the smallest is k = 1.
    q + 2.0 * p * (phi + 2.0 * std::f64::consts::PI / 3.0).pcos()
}

#[cfg(test)]
mod tests {
    use super::*;
    use gaitlab_core::{Joint, RootTransform};

    /// A planar-ish 3-joint leg hanging down from the root: hip (x), knee (x), ankle (x), plus hip yaw.
    fn leg() -> Skeleton {
        let mut joints = vec![
            Joint::revolute("hip_yaw", None, DVec3::ZERO, DVec3::Y),
            Joint::revolute("hip", Some(0), DVec3::ZERO, DVec3::X),
            Joint::revolute("knee", Some(1), DVec3::new(0.0, -0.4, 0.0), DVec3::X)
                .with_limits(0.0, 2.5),
            Joint::revolute("ankle", Some(2), DVec3::new(0.0, -0.4, 0.0), DVec3::X),
        ];
        joints[2].rest = 0.5;
        joints[2].center = 0.5;
        joints[2].gain = 0.3;
        let effectors = vec![gaitlab_core::Effector {
            name: "foot".into(),
            joint: 3,
            offset: DVec3::new(0.0, -0.1, 0.0),
            orientation: false,
        }];
        Skeleton::new(joints, effectors).expect("valid leg")
    }

    fn solve(skeleton: &Skeleton, values: &mut [f64], target: DVec3, iterations: usize) -> f64 {
        let mut ik = LegIk::new(vec![0, 1, 2, 3], 0);
        let mut kin = Kinematics::new(skeleton);
        let centering = LegIkOptions::default();
        let exact = LegIkOptions {
            center_gain: 0.0,
            ..LegIkOptions::default()
        };
        for i in 0..iterations {
            let options = if i + 3 < iterations {
                &centering
            } else {
                &exact
            };
            kin.update(skeleton, &RootTransform::default(), values);
            ik.iterate(skeleton, &kin, values, target, options);
        }
        kin.update(skeleton, &RootTransform::default(), values);
        (kin.effector_position[0] - target).length()
    }

    #[test]
    fn reaches_a_reachable_target_to_a_micrometre() {
        let skeleton = leg();
        let mut values = skeleton.rest_values();
        let target = DVec3::new(0.05, -0.75, 0.15);
        let error = solve(&skeleton, &mut values, target, 20);
        assert!(error < 1e-6, "error {error} m");
        assert!(values[2] >= 0.0, "knee inside its limits");
    }

    #[test]
    fn null_space_moves_joints_toward_center_without_moving_the_foot() {
        let skeleton = leg();
        let mut values = skeleton.rest_values();
        let target = DVec3::new(0.0, -0.8, 0.1);
        solve(&skeleton, &mut values, target, 20);
        let before = values.clone();
        // Many more iterations at the reached target: only the null-space term acts.
        let error = solve(&skeleton, &mut values, target, 200);
        assert!(error < 1e-6, "foot stays on target: {error} m");
        let pull = |v: &[f64]| (v[2] - 0.5).abs();
        assert!(
            pull(&values) <= pull(&before) + 1e-9,
            "knee no farther from its center"
        );
    }

    #[test]
    fn an_override_moves_the_centre_and_none_gives_the_skeletons_back() {
        let skeleton = leg();
        let target = DVec3::new(0.0, -0.8, 0.1);
        let mut ik = LegIk::new(vec![0, 1, 2, 3], 0);
        assert_eq!(ik.center_of(&skeleton, 2), Some([0.5, 0.3]));
        ik.set_center_override(2, Some([1.4, 1.0]));
        ik.set_center_override(9, Some([0.0, 1.0]));
        assert_eq!(ik.center_of(&skeleton, 2), Some([1.4, 1.0]));
        assert_eq!(ik.center_of(&skeleton, 9), None);
        let mut kin = Kinematics::new(&skeleton);
        let mut values = skeleton.rest_values();
        solve(&skeleton, &mut values, target, 20);
        let settled = values[2];
        // Centring iterations with the override pull the knee toward 1.4 at the target.
        for _ in 0..200 {
            kin.update(&skeleton, &RootTransform::default(), &values);
            ik.iterate(
                &skeleton,
                &kin,
                &mut values,
                target,
                &LegIkOptions::default(),
            );
        }
        let error = solve(&skeleton, &mut values, target, 4);
        assert!(error < 1e-6, "foot on target: {error} m");
        assert!(
            values[2] > settled + 0.2,
            "knee {settled} → {} toward 1.4",
            values[2]
        );
        ik.clear_center_overrides();
        assert_eq!(ik.center_of(&skeleton, 2), Some([0.5, 0.3]));
    }

    #[test]
    fn out_of_reach_target_stays_finite_and_stretches_toward_it() {
        let skeleton = leg();
        let mut values = skeleton.rest_values();
        let target = DVec3::new(0.0, -2.0, 0.0);
        let error = solve(&skeleton, &mut values, target, 100);
        assert!(values.iter().all(|v| v.is_finite()));
        // Leg length 0.9 m: the closest reachable point is 1.1 m away.
        assert!((error - 1.1).abs() < 0.01, "error {error} m");
    }

    #[test]
    fn smallest_eigenvalue_matches_a_diagonal_and_a_rotated_matrix() {
        let d = DMat3::from_diagonal(DVec3::new(3.0, 1.0, 2.0));
        assert!((smallest_eigenvalue(&d) - 1.0).abs() < 1e-12);
        let r = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
        let m = r * d * r.transpose();
        assert!((smallest_eigenvalue(&m) - 1.0).abs() < 1e-9);
    }
}
