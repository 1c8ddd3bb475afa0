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
//! With an orientation target ([`LegIk::iterate_pose`]: eq. 2's last three
//! components, [`super::foot_orientation`]) the Jacobian has six rows, the
//! position rows `J_p` and then the angular rows `J_o` (a revolute joint's
//! world axis, 0 for a prismatic one), and the error is the position error
//! and the rotation vector `o` of `R_target · R_currentᵀ`. An iteration's
//! step is the three-row step above (joint limits and all) plus the turn
//! `o′` the six rows ask on top of it (`o` less the three-row step's own
//! turn), made where the foot does not move: `JJᵀ` by its 3×3 blocks, position
//! first, with `A = J_p J_pᵀ`, `B = J_p J_oᵀ` and the Schur complement
//! `T = J_o J_oᵀ − Bᵀ A⁻¹ B` (the angular rows' Gram matrix over the joint
//! motions that leave the foot where it is), `Δθ = J_pᵀ y_p + J_oᵀ y_o`
//! with `y_o = T⁻¹ o'`, `y_p = −A⁻¹ B y_o`. Where the six rows can be met
//! the sum is eq. 5–6's step over the six rows exactly (the pseudoinverse
//! of a full-rank 6×n Jacobian by blocks, and eq. 6's null-space term over
//! the six rows). The foot's position comes first: where a joint's limit
//! refuses the turn its share is shortened, and near a singularity of the
//! position rows over the joints left no turn is made
//! ([`LegIk::turn_refused`]).
//!
//! Near a singularity (smallest singular value of J below
//! [`LegIkOptions::singular_threshold_m`]) the solve blends smoothly into damped
//! least squares, `Jᵀ(JJᵀ + λ²I)⁻¹`, with λ² growing as the leg straightens,
//! so a fully stretched leg neither explodes nor freezes; `T` is damped
//! alike ([`LegIkOptions::singular_threshold_rad`]).

use gaitlab_core::portable::Portable;
use gaitlab_core::{Joint, JointKind, Kinematics, Skeleton};
use glam::{DMat3, DQuat, DVec3};

use super::foot_orientation::orientation_error_rad;

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
    /// Smallest singular value of the angular rows over the joint motions
    /// that leave the foot where it is (radians of foot turn per radian of
    /// joint motion; module docs' `T`) below which their damping starts.
    /// Default 0.1.
    pub singular_threshold_rad: f64,
    /// Damping λ of those rows where they are singular. Default 0.1.
    pub max_damping_rad: f64,
    /// Largest foot turn asked of one iteration, radians. Default 0.5.
    pub max_turn_step_rad: f64,
}

impl Default for LegIkOptions {
    fn default() -> Self {
        Self {
            center_gain: 0.5,
            singular_threshold_m: 0.08,
            max_damping_m: 0.08,
            max_reach_step_m: 0.1,
            max_joint_step: 0.25,
            singular_threshold_rad: 0.1,
            max_damping_rad: 0.1,
            max_turn_step_rad: 0.5,
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
    /// Jacobian column (angular rows, eq. 2's orientation) per leg joint:
    /// filled only by an iteration with an orientation target.
    turns: Vec<DVec3>,
    step: Vec<f64>,
    /// The part of a step that turns the foot (an iteration with an orientation target).
    turn_step: Vec<f64>,
    center_push: Vec<f64>,
    active: Vec<bool>,
    /// Per leg joint, `[center, gain]` in place of the skeleton's (`None`: the skeleton's).
    center_overrides: Vec<Option<[f64; 2]>>,
    /// Whether an iteration since [`LegIk::clear_turn_refused`] found the
    /// foot's turn refused by the joints' limits or by a singular position
    /// Jacobian.
    turn_refused: bool,
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
            turns: vec![DVec3::ZERO; n],
            step: vec![0.0; n],
            turn_step: vec![0.0; n],
            center_push: vec![0.0; n],
            active: vec![true; n],
            center_overrides: vec![None; n],
            turn_refused: false,
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

    /// Whether an iteration with an orientation target since the last
    /// [`LegIk::clear_turn_refused`] gave the foot's turn up, or part of it,
    /// for its position: a joint's limit refused it, or the position rows
    /// were near a singularity over the joints left (module docs).
    #[must_use]
    pub fn turn_refused(&self) -> bool {
        self.turn_refused
    }

    /// Forgets that a turn was refused (call before a frame's iterations).
    pub fn clear_turn_refused(&mut self) {
        self.turn_refused = false;
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
        self.iterate_pose(skeleton, kin, values, target, None, options)
    }

    /// [`LegIk::iterate`] toward `target` and, given `rotation` (the foot's
    /// orientation, from its frame to the world), toward that orientation
    /// too: the six rows of eq. 2 (module docs). `None` is
    /// [`LegIk::iterate`], bit for bit. The step is the position rows' step
    /// of [`LegIk::iterate`] and the turn the six rows ask on top of it,
    /// made without moving the foot; where the turn would carry a joint past
    /// a limit, or the position rows are near a singularity over the joints
    /// left, the turn gives way, in part or whole, and the foot's position
    /// does not ([`LegIk::turn_refused`]). Returns the foot's distance to
    /// `target` before the step, metres.
    pub fn iterate_pose(
        &mut self,
        skeleton: &Skeleton,
        kin: &Kinematics,
        values: &mut [f64],
        target: DVec3,
        rotation: Option<DQuat>,
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
        // Eq. 2's orientation error, world radians, no larger than one
        // iteration's turn.
        let turn = match rotation {
            Some(rotation) => {
                let Some(&current) = kin.effector_rotation.get(self.effector) else {
                    return f64::INFINITY;
                };
                let error_rad = orientation_error_rad(rotation, current);
                let angle_rad = error_rad.length();
                if !angle_rad.is_finite() {
                    return f64::INFINITY;
                }
                Some(if angle_rad > options.max_turn_step_rad {
                    error_rad * (options.max_turn_step_rad / angle_rad)
                } else {
                    error_rad
                })
            }
            None => None,
        };
        let joints = skeleton.joints();
        for (k, &j) in self.joints.iter().enumerate() {
            let axis = kin.joint_axis[j];
            self.columns[k] = match joints[j].kind {
                JointKind::Revolute => axis.cross(foot - kin.joint_anchor[j]),
                JointKind::Prismatic => axis,
            };
            if turn.is_some() {
                self.turns[k] = match joints[j].kind {
                    JointKind::Revolute => axis,
                    JointKind::Prismatic => DVec3::ZERO,
                };
            }
            let joint = &joints[j];
            let (center, gain) = match self.center_overrides[k] {
                Some([center, gain]) => (center, gain),
                None => (joint.center, joint.gain),
            };
            self.center_push[k] = -options.center_gain * 2.0 * gain * (values[j] - center);
        }
        self.position_step(joints, values, reach, options);
        if let Some(turn) = turn {
            self.add_turn_step(joints, values, turn, options);
        }
        for (k, &j) in self.joints.iter().enumerate() {
            values[j] = joints[j].clamp(values[j] + self.step[k]);
        }
        distance
    }

    /// The step of the position rows alone (eq. 5–6 over three rows) toward
    /// `reach`, in `self.step`: a joint that its step would carry past a
    /// limit stops there and the others re-solve for the rest (one extra pass).
    fn position_step(
        &mut self,
        joints: &[Joint],
        values: &[f64],
        reach: DVec3,
        options: &LegIkOptions,
    ) {
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
    }

    /// Adds to the position rows' step (`self.step`, over `self.active`)
    /// the turn that the six rows ask on top of it (eq. 2, module docs):
    /// `turn` less the position step's own turn, made by the joints still
    /// active in the null space of their position rows, `J⁺` of the six rows
    /// by blocks with the position's right-hand side 0. Without a limit in
    /// the way the sum is eq. 5–6's step over the six rows (the position
    /// step's null-space term and the turn's together are eq. 6's over the
    /// six rows). The turn's share is shortened as far as the longest joint
    /// step and the joints' limits need, and none is made where the
    /// position rows over the joints left need damping (their damped
    /// inverse would let the turn move the foot): the foot's position comes
    /// first.
    fn add_turn_step(
        &mut self,
        joints: &[Joint],
        values: &[f64],
        turn: DVec3,
        options: &LegIkOptions,
    ) {
        let mut turned = DVec3::ZERO;
        for (axis, step) in self.turns.iter().zip(&self.step) {
            turned += *axis * *step;
        }
        let Some(solver) = self.turn_solver(options) else {
            self.turn_refused = true;
            return;
        };
        let (y, y_turn) = solver.solve(turn - turned);
        let mut limited = false;
        // The largest share of the turn that keeps every joint's step within
        // the longest step and its limits: |m + s·t| ≤ max, lo ≤ v + m + s·t ≤ hi.
        let mut share: f64 = 1.0;
        for (k, &j) in self.joints.iter().enumerate() {
            if !self.active[k] {
                self.turn_step[k] = 0.0;
                continue;
            }
            let turning = self.columns[k].dot(y) + self.turns[k].dot(y_turn);
            self.turn_step[k] = turning;
            if turning == 0.0 {
                continue;
            }
            let moving = self.step[k];
            let wanted = values[j] + moving;
            let (low, high) = joints[j]
                .limits
                .unwrap_or((f64::NEG_INFINITY, f64::INFINITY));
            // A joint the position's step carried past a limit is clamped
            // there at the end: the turn moves it no farther.
            let (low, high) = (low.min(wanted), high.max(wanted));
            let (room_step, room_limit) = if turning > 0.0 {
                (options.max_joint_step - moving, high - wanted)
            } else {
                (-options.max_joint_step - moving, low - wanted)
            };
            share = share.min(room_step / turning);
            if room_limit / turning < share {
                share = room_limit / turning;
                limited = true;
            }
        }
        if !share.is_finite() {
            return;
        }
        let share = share.clamp(0.0, 1.0);
        if limited && share < 1.0 {
            self.turn_refused = true;
        }
        for (step, turning) in self.step.iter_mut().zip(&self.turn_step) {
            *step += share * turning;
        }
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
        let damping = damping(&jjt, options.singular_threshold_m, options.max_damping_m);
        invert(jjt + DMat3::from_diagonal(DVec3::splat(damping.max(1e-12))))
    }

    /// The solver of the turn over the active columns (module docs): the
    /// position rows' Gram matrix `A = J_p J_pᵀ`, its coupling `B = J_p J_oᵀ`
    /// with the angular rows and the Schur complement `T = J_o J_oᵀ − Bᵀ A⁻¹ B`,
    /// damped by its own smallest singular value (radians). `None` when no
    /// joint is active, a block cannot be inverted, or the position rows are
    /// near a singularity ([`LegIkOptions::singular_threshold_m`]): their
    /// damped inverse would let the turn move the foot.
    fn turn_solver(&self, options: &LegIkOptions) -> Option<TurnSolver> {
        let (mut position, mut coupling, mut angular) = (DMat3::ZERO, DMat3::ZERO, DMat3::ZERO);
        let mut any = false;
        for ((&column, &turn), &active) in self.columns.iter().zip(&self.turns).zip(&self.active) {
            if active {
                position += outer(column, column);
                coupling += outer(column, turn);
                angular += outer(turn, turn);
                any = true;
            }
        }
        if !any
            || damping(
                &position,
                options.singular_threshold_m,
                options.max_damping_m,
            ) > 0.0
        {
            return None;
        }
        let position_inverse = invert(position + DMat3::from_diagonal(DVec3::splat(1e-12)))?;
        let schur = angular - coupling.transpose() * position_inverse * coupling;
        let schur_damping = damping(
            &schur,
            options.singular_threshold_rad,
            options.max_damping_rad,
        );
        let schur_inverse =
            invert(schur + DMat3::from_diagonal(DVec3::splat(schur_damping.max(1e-12))))?;
        Some(TurnSolver {
            position_inverse,
            schur_inverse,
            coupling,
        })
    }
}

/// The six rows' `(JJᵀ + Λ)⁻¹` applied to a turn alone, `[[A, B], [Bᵀ, T']]`
/// by block elimination, position first: `A⁻¹`, the damped Schur
/// complement's inverse `(T + λ²I)⁻¹` and `B` (module docs).
struct TurnSolver {
    position_inverse: DMat3,
    schur_inverse: DMat3,
    coupling: DMat3,
}

impl TurnSolver {
    /// `y_o = (T + λ²I)⁻¹ o`, `y_p = −A⁻¹ B y_o`: the joint step `J_pᵀ y_p +
    /// J_oᵀ y_o` turns the foot by `o` (as far as `T` allows) and moves it
    /// by `A y_p + B y_o = 0`.
    fn solve(&self, turn: DVec3) -> (DVec3, DVec3) {
        let y_turn = self.schur_inverse * turn;
        let y = -(self.position_inverse * (self.coupling * y_turn));
        (y, y_turn)
    }
}

/// λ² of a symmetric positive semi-definite Gram matrix `gram`: 0 while its
/// smallest singular value (square root of the smallest eigenvalue) is at
/// least `threshold`, growing smoothly to `max_damping²` as it falls to 0.
fn damping(gram: &DMat3, threshold: f64, max_damping: f64) -> f64 {
    let sigma_min = smallest_eigenvalue(gram).max(0.0).sqrt();
    if sigma_min < threshold {
        let t = sigma_min / threshold;
        (1.0 - t * t) * max_damping * max_damping
    } else {
        0.0
    }
}

/// The inverse of `m`, `None` when it is (nearly) singular or not finite.
fn invert(m: DMat3) -> Option<DMat3> {
    let det = m.determinant();
    (det.is_finite() && det.abs() > 1e-30).then(|| m.inverse())
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

    /// A seven-joint leg hanging from the root: hip yaw, pitch and roll,
    /// knee, ankle pitch, roll and yaw, and a foot 0.1 m below the ankle.
    fn seven_joint_leg() -> Skeleton {
        let down = DVec3::new(0.0, -0.4, 0.0);
        let mut joints = vec![
            Joint::revolute("hip_y", None, DVec3::ZERO, DVec3::Y).with_limits(-1.0, 1.0),
            Joint::revolute("hip_x", Some(0), DVec3::ZERO, DVec3::X).with_limits(-1.5, 1.5),
            Joint::revolute("hip_z", Some(1), DVec3::ZERO, DVec3::Z).with_limits(-0.6, 0.6),
            Joint::revolute("knee", Some(2), down, DVec3::X).with_limits(0.0, 2.5),
            Joint::revolute("ankle_x", Some(3), down, DVec3::X).with_limits(-1.2, 1.2),
            Joint::revolute("ankle_z", Some(4), DVec3::ZERO, DVec3::Z).with_limits(-0.6, 0.6),
            Joint::revolute("ankle_y", Some(5), DVec3::ZERO, DVec3::Y).with_limits(-0.6, 0.6),
        ];
        joints[3].rest = 0.5;
        joints[3].center = 0.5;
        joints[3].gain = 0.3;
        let effectors = vec![gaitlab_core::Effector {
            name: "foot".into(),
            joint: 6,
            offset: DVec3::new(0.0, -0.1, 0.0),
            orientation: true,
        }];
        Skeleton::new(joints, effectors).expect("valid leg")
    }

    /// Iterates the seven-joint leg toward `target` and `rotation` as the
    /// driver does (centering first, the last three exact); returns the
    /// position error (m), the orientation error (rad) and the IK.
    fn solve_pose(
        skeleton: &Skeleton,
        values: &mut [f64],
        target: DVec3,
        rotation: DQuat,
        iterations: usize,
    ) -> (f64, f64, LegIk) {
        let mut ik = LegIk::new((0..7).collect(), 0);
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
            ik.iterate_pose(skeleton, &kin, values, target, Some(rotation), options);
        }
        kin.update(skeleton, &RootTransform::default(), values);
        let turn = orientation_error_rad(rotation, kin.effector_rotation[0]).length();
        ((kin.effector_position[0] - target).length(), turn, ik)
    }

    #[test]
    fn six_rows_reach_a_position_and_an_orientation() {
        let skeleton = seven_joint_leg();
        // A pose the leg can take, seen from outside the IK: its foot's
        // position and orientation are the target.
        let goal = [0.3, -0.4, 0.2, 1.1, -0.5, -0.15, 0.25];
        let kin = Kinematics::of(
            &skeleton,
            &gaitlab_core::Pose {
                root: RootTransform::default(),
                joints: goal.to_vec(),
            },
        );
        let target = kin.effector_position[0];
        let rotation = DQuat::from_mat3(&kin.effector_rotation[0]);
        let mut values = skeleton.rest_values();
        let (miss_m, turn_rad, ik) = solve_pose(&skeleton, &mut values, target, rotation, 30);
        assert!(miss_m < 1e-9, "position error {miss_m} m");
        assert!(turn_rad < 1e-9, "orientation error {turn_rad} rad");
        assert!(!ik.turn_refused());
        for (value, joint) in values.iter().zip(skeleton.joints()) {
            assert!(
                joint.clamp(*value) == *value,
                "{} within its limits",
                joint.name
            );
        }
        // Three rows alone leave the orientation where the joints put it.
        let mut three = skeleton.rest_values();
        solve(&skeleton, &mut three, target, 30);
        let kin = Kinematics::of(
            &skeleton,
            &gaitlab_core::Pose {
                root: RootTransform::default(),
                joints: three,
            },
        );
        assert!(orientation_error_rad(rotation, kin.effector_rotation[0]).length() > 0.05);
    }

    #[test]
    fn centering_at_a_reached_pose_keeps_the_foots_position_and_orientation() {
        let skeleton = seven_joint_leg();
        let target = DVec3::new(0.05, -0.75, 0.1);
        let rotation = DQuat::from_rotation_y(0.2) * DQuat::from_rotation_x(0.1);
        let mut values = skeleton.rest_values();
        solve_pose(&skeleton, &mut values, target, rotation, 30);
        let before = values.clone();
        // Only eq. 6's null-space term (three joints' worth over six rows) acts.
        let (miss_m, turn_rad, _) = solve_pose(&skeleton, &mut values, target, rotation, 200);
        assert!(miss_m < 1e-9, "position error {miss_m} m");
        assert!(turn_rad < 1e-9, "orientation error {turn_rad} rad");
        let pull = |v: &[f64]| (v[3] - 0.5).abs();
        assert!(
            pull(&values) <= pull(&before) + 1e-9,
            "knee no farther from its center"
        );
    }

    #[test]
    fn a_turn_the_limits_refuse_gives_way_and_the_foot_stays() {
        let skeleton = seven_joint_leg();
        // The foot pitched 2 rad: beyond what the ankle's and the hip's
        // limits allow at this spot.
        let target = DVec3::new(0.0, -0.8, 0.1);
        let rotation = DQuat::from_rotation_x(2.0);
        let mut values = skeleton.rest_values();
        let (miss_m, turn_rad, ik) = solve_pose(&skeleton, &mut values, target, rotation, 40);
        assert!(miss_m < 1e-9, "position error {miss_m} m");
        assert!(turn_rad > 0.1, "the turn is not made: {turn_rad} rad left");
        assert!(ik.turn_refused());
        for (value, joint) in values.iter().zip(skeleton.joints()) {
            assert!(
                joint.clamp(*value) == *value,
                "{} within its limits",
                joint.name
            );
        }
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
