//! Spatial (6-D) vector algebra for rigid-body dynamics, after Featherstone's
//! *Rigid Body Dynamics Algorithms* (2008) ch. 2 — the notation the
//! articulated-body algorithm of [`crate::dynamics::aba`] is written in.
//!
//! Conventions: a spatial vector is `[angular; linear]`. A [`Motion`] is a
//! velocity or acceleration (`ω` in rad/s, `v` the velocity of the point at the
//! frame's origin in m/s); a [`Force`] is a moment about the origin (N·m) and
//! a force (N). A [`ParentLink`] places a child frame in its parent's:
//! `p_parent = rot · p_child + pos`.

use glam::{DMat3, DVec3};

/// The matrix `[r]×` with `skew(r) · x = r × x`.
#[must_use]
pub fn skew(r: DVec3) -> DMat3 {
    DMat3::from_cols(
        DVec3::new(0.0, r.z, -r.y),
        DVec3::new(-r.z, 0.0, r.x),
        DVec3::new(r.y, -r.x, 0.0),
    )
}

/// A spatial motion vector: angular velocity and the linear velocity of the
/// point at the frame's origin (or their time derivatives).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    /// Angular part (rad/s or rad/s²).
    pub angular: DVec3,
    /// Linear part (m/s or m/s²).
    pub linear: DVec3,
}

/// A spatial force vector: a moment about the frame's origin and a force.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Force {
    /// Moment about the origin (N·m).
    pub moment: DVec3,
    /// Force (N).
    pub force: DVec3,
}

impl Motion {
    /// The zero motion.
    pub const ZERO: Self = Self {
        angular: DVec3::ZERO,
        linear: DVec3::ZERO,
    };

    /// A motion from its parts.
    #[must_use]
    pub const fn new(angular: DVec3, linear: DVec3) -> Self {
        Self { angular, linear }
    }

    /// `self × m`: the spatial cross product of two motions.
    #[must_use]
    pub fn cross_motion(self, m: Motion) -> Motion {
        Motion {
            angular: self.angular.cross(m.angular),
            linear: self.angular.cross(m.linear) + self.linear.cross(m.angular),
        }
    }

    /// `self ×* f`: the spatial cross product of a motion with a force.
    #[must_use]
    pub fn cross_force(self, f: Force) -> Force {
        Force {
            moment: self.angular.cross(f.moment) + self.linear.cross(f.force),
            force: self.angular.cross(f.force),
        }
    }

    /// The power `m · f` of a force on this motion (W when a velocity).
    #[must_use]
    pub fn dot(self, f: Force) -> f64 {
        self.angular.dot(f.moment) + self.linear.dot(f.force)
    }

    /// Scale both parts.
    #[must_use]
    pub fn scale(self, s: f64) -> Motion {
        Motion {
            angular: self.angular * s,
            linear: self.linear * s,
        }
    }

    /// Whether both parts are finite.
    #[must_use]
    pub fn is_finite(self) -> bool {
        self.angular.is_finite() && self.linear.is_finite()
    }
}

impl std::ops::Add for Motion {
    type Output = Motion;
    fn add(self, o: Motion) -> Motion {
        Motion {
            angular: self.angular + o.angular,
            linear: self.linear + o.linear,
        }
    }
}

impl std::ops::Sub for Motion {
    type Output = Motion;
    fn sub(self, o: Motion) -> Motion {
        Motion {
            angular: self.angular - o.angular,
            linear: self.linear - o.linear,
        }
    }
}

impl Force {
    /// The zero force.
    pub const ZERO: Self = Self {
        moment: DVec3::ZERO,
        force: DVec3::ZERO,
    };

    /// A force from its parts.
    #[must_use]
    pub const fn new(moment: DVec3, force: DVec3) -> Self {
        Self { moment, force }
    }

    /// A pure force `f` acting at point `p` (both in this frame).
    #[must_use]
    pub fn at_point(p: DVec3, f: DVec3) -> Self {
        Self {
            moment: p.cross(f),
            force: f,
        }
    }

    /// Scale both parts.
    #[must_use]
    pub fn scale(self, s: f64) -> Force {
        Force {
            moment: self.moment * s,
            force: self.force * s,
        }
    }
}

impl std::ops::Add for Force {
    type Output = Force;
    fn add(self, o: Force) -> Force {
        Force {
            moment: self.moment + o.moment,
            force: self.force + o.force,
        }
    }
}

impl std::ops::AddAssign for Force {
    fn add_assign(&mut self, o: Force) {
        self.moment += o.moment;
        self.force += o.force;
    }
}

impl std::ops::Sub for Force {
    type Output = Force;
    fn sub(self, o: Force) -> Force {
        Force {
            moment: self.moment - o.moment,
            force: self.force - o.force,
        }
    }
}

/// Where a child frame sits in its parent: `p_parent = rot · p_child + pos`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParentLink {
    /// The child's axes in parent coordinates.
    pub rot: DMat3,
    /// The child's origin in parent coordinates (m).
    pub pos: DVec3,
}

impl Default for ParentLink {
    fn default() -> Self {
        Self {
            rot: DMat3::IDENTITY,
            pos: DVec3::ZERO,
        }
    }
}

impl ParentLink {
    /// A parent-frame motion expressed in the child frame (Featherstone's `X m`).
    #[must_use]
    pub fn motion_to_child(&self, m: Motion) -> Motion {
        let rt = self.rot.transpose();
        Motion {
            angular: rt * m.angular,
            linear: rt * (m.linear + m.angular.cross(self.pos)),
        }
    }

    /// A child-frame force expressed in the parent frame (Featherstone's `Xᵀ f`).
    #[must_use]
    pub fn force_to_parent(&self, f: Force) -> Force {
        let force = self.rot * f.force;
        Force {
            moment: self.rot * f.moment + self.pos.cross(force),
            force,
        }
    }

    /// A child-frame inertia expressed in the parent frame (`Xᵀ I X`).
    #[must_use]
    pub fn inertia_to_parent(&self, i: &Inertia) -> Inertia {
        let (a, b, c) = if self.rot == DMat3::IDENTITY {
            (i.a, i.b, i.c)
        } else {
            let r = self.rot;
            let rt = r.transpose();
            (r * i.a * rt, r * i.b * rt, r * i.c * rt)
        };
        if self.pos == DVec3::ZERO {
            // A joint at the parent's origin (a gimbal's inner axis): rotation only.
            return Inertia { a, b, c };
        }
        let rx = skew(self.pos);
        let b_rx = b * rx;
        Inertia {
            a: a - b_rx - b_rx.transpose() - rx * c * rx,
            b: b + rx * c,
            c,
        }
    }

    /// The composition `self ∘ child`: where `child`'s frame sits in this link's parent.
    #[must_use]
    pub fn then(&self, child: &ParentLink) -> ParentLink {
        ParentLink {
            rot: self.rot * child.rot,
            pos: self.rot * child.pos + self.pos,
        }
    }
}

/// A spatial inertia `[[a, b], [bᵀ, c]]` (a rigid body's, or an articulated
/// body's), with `a` and `c` symmetric. Units: kg·m², kg·m, kg.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia {
    /// Rotational block about the origin (kg·m²).
    pub a: DMat3,
    /// Coupling block (kg·m).
    pub b: DMat3,
    /// Translational block (kg).
    pub c: DMat3,
}

impl Default for Inertia {
    fn default() -> Self {
        Self::ZERO
    }
}

impl Inertia {
    /// The zero inertia.
    pub const ZERO: Self = Self {
        a: DMat3::ZERO,
        b: DMat3::ZERO,
        c: DMat3::ZERO,
    };

    /// A rigid body of `mass` (kg) with its centre of mass at `com` (m) and
    /// rotational inertia `inertia_com` about the centre of mass (kg·m²).
    #[must_use]
    pub fn rigid(mass: f64, com: DVec3, inertia_com: DMat3) -> Self {
        let cx = skew(com);
        Self {
            a: inertia_com - cx * cx * mass,
            b: cx * mass,
            c: DMat3::IDENTITY * mass,
        }
    }

    /// `I · m`: the momentum of a velocity, or the force of an acceleration.
    #[must_use]
    #[inline(always)]
    pub fn mul(&self, m: Motion) -> Force {
        Force {
            moment: self.a * m.angular + self.b * m.linear,
            force: self.bt_mul(m.angular) + self.c * m.linear,
        }
    }

    /// `bᵀ · w` without forming the transpose.
    #[inline]
    fn bt_mul(&self, w: DVec3) -> DVec3 {
        DVec3::new(
            self.b.x_axis.dot(w),
            self.b.y_axis.dot(w),
            self.b.z_axis.dot(w),
        )
    }

    /// `I · (axis, 0)`: the force of a unit rotation about `axis` (a revolute
    /// joint's `U = I S`).
    #[must_use]
    pub fn mul_angular(&self, axis: DVec3) -> Force {
        Force {
            moment: self.a * axis,
            force: self.bt_mul(axis),
        }
    }

    /// `I · (0, axis)`: the force of a unit translation along `axis` (a
    /// prismatic joint's `U = I S`).
    #[must_use]
    pub fn mul_linear(&self, axis: DVec3) -> Force {
        Force {
            moment: self.b * axis,
            force: self.c * axis,
        }
    }

    /// Make this `x + y`, block by block (the same bits as `*self = x` then
    /// `*self += y`, without the copy).
    #[inline(always)]
    pub fn set_sum(&mut self, x: &Inertia, y: &Inertia) {
        for (out, (x, y)) in [&mut self.a, &mut self.b, &mut self.c].into_iter().zip([
            (&x.a, &y.a),
            (&x.b, &y.b),
            (&x.c, &y.c),
        ]) {
            out.x_axis = x.x_axis + y.x_axis;
            out.y_axis = x.y_axis + y.y_axis;
            out.z_axis = x.z_axis + y.z_axis;
        }
    }

    /// `self − u uᵀ / d` for a force-like `u` (the articulated-body update).
    /// Entry `(i, j)` of each block is `self_ij − x_i · (y_j / d)`, written
    /// column by column into the result.
    #[must_use]
    pub fn minus_outer(&self, u: Force, d: f64) -> Inertia {
        let (m, f) = (u.moment, u.force);
        let (m_d, f_d) = (m / d, f / d);
        let block = |s: &DMat3, x: DVec3, y_d: DVec3| DMat3 {
            x_axis: s.x_axis - x * y_d.x,
            y_axis: s.y_axis - x * y_d.y,
            z_axis: s.z_axis - x * y_d.z,
        };
        Inertia {
            a: block(&self.a, m, m_d),
            b: block(&self.b, m, f_d),
            c: block(&self.c, f, f_d),
        }
    }

    /// The 6×6 matrix, rows and columns ordered `[angular; linear]`.
    #[must_use]
    pub fn to_array(&self) -> [[f64; 6]; 6] {
        let mut m = [[0.0; 6]; 6];
        let bt = self.b.transpose();
        for row in 0..3 {
            for col in 0..3 {
                m[row][col] = self.a.col(col)[row];
                m[row][col + 3] = self.b.col(col)[row];
                m[row + 3][col] = bt.col(col)[row];
                m[row + 3][col + 3] = self.c.col(col)[row];
            }
        }
        m
    }
}

impl std::ops::Add for Inertia {
    type Output = Inertia;
    fn add(self, o: Inertia) -> Inertia {
        Inertia {
            a: self.a + o.a,
            b: self.b + o.b,
            c: self.c + o.c,
        }
    }
}

impl std::ops::AddAssign for Inertia {
    fn add_assign(&mut self, o: Inertia) {
        self.a += o.a;
        self.b += o.b;
        self.c += o.c;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    fn mat6_motion_transform(l: &ParentLink) -> [[f64; 6]; 6] {
        // Columns: the child-frame images of the parent-frame unit motions.
        let mut x = [[0.0; 6]; 6];
        for col in 0..6 {
            let mut e = [0.0; 6];
            e[col] = 1.0;
            let m = l.motion_to_child(Motion::new(
                DVec3::new(e[0], e[1], e[2]),
                DVec3::new(e[3], e[4], e[5]),
            ));
            let v = [
                m.angular.x,
                m.angular.y,
                m.angular.z,
                m.linear.x,
                m.linear.y,
                m.linear.z,
            ];
            for row in 0..6 {
                x[row][col] = v[row];
            }
        }
        x
    }

    fn link() -> ParentLink {
        ParentLink {
            rot: DMat3::from_quat(DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 0.7)),
            pos: DVec3::new(0.2, -0.5, 1.3),
        }
    }

    #[test]
    fn inertia_transform_equals_xt_i_x() {
        let l = link();
        let i = Inertia::rigid(
            2.5,
            DVec3::new(0.1, 0.3, -0.2),
            DMat3::from_diagonal(DVec3::new(0.4, 0.2, 0.3)),
        );
        let x = mat6_motion_transform(&l);
        let im = i.to_array();
        let got = l.inertia_to_parent(&i).to_array();
        for r in 0..6 {
            for c in 0..6 {
                let mut s = 0.0;
                for k in 0..6 {
                    for m in 0..6 {
                        s += x[k][r] * im[k][m] * x[m][c];
                    }
                }
                assert!(
                    (s - got[r][c]).abs() < 1e-12,
                    "({r},{c}) {s} vs {}",
                    got[r][c]
                );
            }
        }
    }

    #[test]
    fn force_transform_is_dual_of_motion_transform() {
        // Power is frame-independent: (X m) · f_child == m · (Xᵀ f_child).
        let l = link();
        let m = Motion::new(DVec3::new(0.3, -0.2, 0.9), DVec3::new(1.0, 2.0, -0.5));
        let f = Force::new(DVec3::new(-0.4, 0.1, 0.2), DVec3::new(3.0, -1.0, 0.5));
        let lhs = l.motion_to_child(m).dot(f);
        let rhs = m.dot(l.force_to_parent(f));
        assert!((lhs - rhs).abs() < 1e-12);
    }

    #[test]
    fn rigid_momentum_matches_particle_sum() {
        // A body with its mass concentrated at the centre of mass: momentum
        // m·(v + ω × c), angular momentum about the origin c × that.
        let com = DVec3::new(0.2, -0.1, 0.4);
        let i = Inertia::rigid(3.0, com, DMat3::ZERO);
        let v = Motion::new(DVec3::new(0.5, 1.0, -0.3), DVec3::new(0.1, 0.0, 2.0));
        let h = i.mul(v);
        let p = (v.linear + v.angular.cross(com)) * 3.0;
        assert!((h.force - p).length() < 1e-12);
        assert!((h.moment - com.cross(p)).length() < 1e-12);
    }
}
