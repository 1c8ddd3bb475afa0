//! Hop height and flight time (Raibert & Hodgins 1991, "Hopping Control",
//! eq. 2): a body that leaves the ground rising and lands at the height it
//! left reaches `h = g·t²/8` above lift-off in a flight of `t` seconds. The
//! gaits that regulate their flight time (the trot, the bound) take the hop
//! height a user asks for through this.

use crate::dynamics::model::GRAVITY_MPS2;

/// The flight (s) whose apex is `height_m` (m, ≥ 0) above lift-off.
#[must_use]
pub fn flight_for_height(height_m: f64) -> f64 {
    (8.0 * height_m.max(0.0) / GRAVITY_MPS2).sqrt()
}

/// The apex height (m) above lift-off of a flight of `flight_s` seconds.
#[must_use]
pub fn height_for_flight(flight_s: f64) -> f64 {
    GRAVITY_MPS2 * flight_s * flight_s / 8.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ballistic_flight_and_its_apex_agree() {
        // Half the flight rising at g: v = g·t/2, h = v²/(2g).
        let t = 0.3;
        let v = GRAVITY_MPS2 * t / 2.0;
        assert!((height_for_flight(t) - v * v / (2.0 * GRAVITY_MPS2)).abs() < 1e-15);
        assert!((flight_for_height(height_for_flight(t)) - t).abs() < 1e-15);
        assert_eq!(flight_for_height(-1.0), 0.0);
    }
}
