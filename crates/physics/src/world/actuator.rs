//! Actuator models (Raibert & Hodgins 1991): the spring-damper with
//! programmable rest length of eq. 1, `f = k(x − x_r) + b·ẋ`, and the linear
//! joint servo of eq. 5, `f = −k_p(θ − θ_d) − k_v·θ̇`, both with a force limit;
//! plus the mechanical stops of a joint's travel.
//!
//! Sign convention: the functions return the generalized force the actuator
//! applies to the joint coordinate (positive drives `q` up), so eq. 1's
//! spring force acting against the stretch is returned negated.

/// A spring-damper with programmable rest length (eq. 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpringDamper {
    /// Stiffness k (N/m or N·m/rad).
    pub stiffness: f64,
    /// Damping b (N·s/m or N·m·s/rad).
    pub damping: f64,
    /// Rest length or angle x_r (m or rad), set by the controller.
    pub rest: f64,
    /// Largest force or torque it can exert (N or N·m).
    pub max_force: f64,
}

impl SpringDamper {
    /// The force on the coordinate at `x` moving at `xd`.
    #[must_use]
    pub fn force(&self, x: f64, xd: f64) -> f64 {
        let f = -(self.stiffness * (x - self.rest) + self.damping * xd);
        f.clamp(-self.max_force, self.max_force)
    }
}

/// A linear servo (eq. 5): the same law as a spring-damper whose rest is the
/// desired value θ_d.
#[must_use]
pub fn servo(kp: f64, kv: f64, theta: f64, theta_d: f64, theta_dot: f64, max: f64) -> f64 {
    (-kp * (theta - theta_d) - kv * theta_dot).clamp(-max, max)
}

/// A joint's travel with stiff stops at both ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stops {
    /// Lowest coordinate (m or rad).
    pub min: f64,
    /// Highest coordinate (m or rad).
    pub max: f64,
    /// Stop stiffness (N/m or N·m/rad).
    pub stiffness: f64,
    /// Stop damping, acting only while in the stop.
    pub damping: f64,
}

impl Stops {
    /// The force the stops exert at `x` moving at `xd` (zero inside the travel).
    #[must_use]
    pub fn force(&self, x: f64, xd: f64) -> f64 {
        if x > self.max {
            (-self.stiffness * (x - self.max) - self.damping * xd).min(0.0)
        } else if x < self.min {
            (-self.stiffness * (x - self.min) - self.damping * xd).max(0.0)
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spring_pushes_back_to_rest_and_limits() {
        let s = SpringDamper {
            stiffness: 1000.0,
            damping: 10.0,
            rest: 0.1,
            max_force: 50.0,
        };
        assert!((s.force(0.08, 0.0) - 20.0).abs() < 1e-12);
        assert!((s.force(0.1, 1.0) + 10.0).abs() < 1e-12);
        assert_eq!(s.force(0.0, 0.0), 50.0);
        assert!((servo(100.0, 5.0, 0.2, 0.0, 1.0, 1e9) + 25.0).abs() < 1e-12);
    }

    #[test]
    fn stops_act_only_outside_the_travel() {
        let st = Stops {
            min: -0.2,
            max: 0.0,
            stiffness: 1e5,
            damping: 100.0,
        };
        assert_eq!(st.force(-0.1, 3.0), 0.0);
        assert!((st.force(0.01, 0.0) + 1000.0).abs() < 1e-9);
        assert!(st.force(-0.21, 0.0) > 0.0);
        // Never pulls the coordinate into the stop.
        assert_eq!(st.force(0.001, -20.0), 0.0);
    }
}
