//! The programmable leg spring of Raibert & Hodgins 1991, eq. 1:
//! `f = k(x − x_r) + b·ẋ` on a leg's springy joint, the controller moving the
//! rest length x_r (lengthen for landing, extend in thrust, shorten the idle
//! leg), with stiff stops at the ends of the leg's travel.

use crate::control::laws::scale::Scale;
use crate::world::actuator::Stops;
use crate::world::sim::Drive;

/// Stiffness of the stops at the ends of a telescoping leg's travel (N/m at
/// scale 1): stiff enough to hold the body's weight within millimetres.
pub const STOP_STIFFNESS: f64 = 2.0e5;

/// Damping of those stops (N·s/m at scale 1).
pub const STOP_DAMPING: f64 = 500.0;

/// A telescoping leg's spring: eq. 1's constants at scale 1 and the leg's
/// travel. Lengths are spring coordinates: metres of extension, 0 = the leg
/// at full length, negative = shorter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegSpring {
    /// Spring constant k (N/m at scale 1).
    pub stiffness: f64,
    /// Damping b (N·s/m at scale 1).
    pub damping: f64,
    /// How far the leg can shorten from full length (m at scale 1, > 0).
    pub travel_m: f64,
}

impl LegSpring {
    /// Eq. 1's `k` (N/m), `b` (N·s/m) and the travel (m), at scale 1.
    #[must_use]
    pub const fn new(stiffness: f64, damping: f64, travel_m: f64) -> Self {
        Self {
            stiffness,
            damping,
            travel_m,
        }
    }

    /// The stops at full length and at `travel_m` shorter.
    #[must_use]
    pub fn stops(&self, s: Scale) -> Stops {
        Stops {
            min: -self.travel_m * s.length(),
            max: 0.0,
            stiffness: STOP_STIFFNESS * s.stiffness(),
            damping: STOP_DAMPING * s.damping(),
        }
    }

    /// Set `drive` to eq. 1 with rest length `rest_m` (already scaled) and
    /// damping `damping` (N·s/m at scale 1; flight and stance may differ).
    pub fn apply_with_damping(&self, drive: &mut Drive, rest_m: f64, damping: f64, s: Scale) {
        drive.stops = Some(self.stops(s));
        drive.spring.stiffness = self.stiffness * s.stiffness();
        drive.spring.damping = damping * s.damping();
        drive.spring.max_force = f64::INFINITY;
        drive.feedforward = 0.0;
        drive.spring.rest = rest_m;
    }

    /// Set `drive` to eq. 1 with rest length `rest_m` (already scaled).
    pub fn apply(&self, drive: &mut Drive, rest_m: f64, s: Scale) {
        self.apply_with_damping(drive, rest_m, self.damping, s);
    }
}

/// Move a rest length toward `target` by at most `rate_mps·dt` (both scaled):
/// a leg snapped short would jerk the trunk through the hips.
#[must_use]
pub fn toward(rest: f64, target: f64, max_step: f64) -> f64 {
    rest + (target - rest).clamp(-max_step, max_step)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq_1_with_its_rest_length_and_stops() {
        let spring = LegSpring {
            stiffness: 1000.0,
            damping: 10.0,
            travel_m: 0.25,
        };
        let mut d = Drive::default();
        spring.apply(&mut d, -0.05, Scale::new(1.0));
        // f = −k(x − x_r) − b·ẋ inside the travel.
        assert!((d.force(-0.10, 0.2) - (1000.0 * 0.05 - 10.0 * 0.2)).abs() < 1e-9);
        // The stop at full length pushes back past it.
        assert!(d.force(0.01, 0.0) < -1000.0);
        // At scale 2: travel ×2, spring k ×4.
        spring.apply(&mut d, 0.0, Scale::new(2.0));
        assert_eq!(d.stops.map(|s| s.min), Some(-0.5));
        assert_eq!(d.spring.stiffness, 4000.0);
        assert_eq!(toward(0.0, 1.0, 0.1), 0.1);
        assert_eq!(toward(0.0, -0.05, 0.1), -0.05);
    }
}
