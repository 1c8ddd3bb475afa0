//! The lab's bounds on the body while legs take a gait change on one by one
//! ([`super::leg_cycles`]): eq. 12–13's legs cancel each other's push only
//! in a steady gait, so while they change the superposition can sink the
//! body onto its feet, lift it off them or pitch it further than either
//! gait does. Until every leg is steady again the body stays between the
//! lower of the two steady gaits' lowest points and the higher of their
//! highest, pitches within their pitch ranges, and stands no higher than
//! every planted foot reaches at [`REACH`] of its straight leg. None of them
//! binds in a steady gait.

use glam::{DMat3, DVec2, DVec3};

use super::gait::GaitParams;

/// Fraction of a straight leg's length a planted foot is kept within.
pub const REACH: f64 = 0.98;
/// Samples per period of the steady gaits' figures.
pub const SAMPLES: u32 = 240;

/// Eq. 9's vertical centre for `gait` from `t_s` on (the mean of the
/// superposition over every leg's support phase, one period sampled
/// [`SAMPLES`] times) and the lowest and highest the centred superposition
/// goes in that period, metres; `g_mps2` is gravity.
#[must_use]
pub fn eq9_centre_and_range_m(gait: &GaitParams, t_s: f64, g_mps2: f64) -> (f64, f64, f64) {
    let period = gait.period_s();
    let (mut sum, mut count) = (0.0, 0u32);
    let (mut lowest, mut highest) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..SAMPLES {
        let t = t_s + period * (f64::from(k) + 0.5) / f64::from(SAMPLES);
        let height = gait.vertical_superposition_m(t, g_mps2);
        lowest = lowest.min(height);
        highest = highest.max(height);
        for i in 0..gait.leg_count() {
            if gait.leg_phase(i, t).is_some_and(|p| p.support) {
                sum += height;
                count += 1;
            }
        }
    }
    let centre = if count > 0 {
        sum / f64::from(count)
    } else {
        0.0
    };
    (centre, lowest - centre, highest - centre)
}

/// The least and greatest pitch slope of eq. 9's `gait` over one period
/// from `t_s` (`Σ w_i·y_i` with the pitch weights `weights`).
#[must_use]
pub fn eq9_slope_range(gait: &GaitParams, t_s: f64, g_mps2: f64, weights: &[f64]) -> (f64, f64) {
    let period = gait.period_s();
    (0..SAMPLES)
        .map(|k| {
            let t = t_s + period * (f64::from(k) + 0.5) / f64::from(SAMPLES);
            gait.vertical_weighted_m(t, g_mps2, weights)
        })
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), w| {
            (lo.min(w), hi.max(w))
        })
}

/// The steady gaits' lowest points and pitch ranges before a change and now.
#[derive(Clone, Debug)]
pub struct TransitionBounds {
    low_before_m: f64,
    high_before_m: f64,
    slope_before: (f64, f64),
    /// The present gait's figures are due: a change started, or the gait
    /// changed again while the legs take one on (a queued edit the driver
    /// took on).
    now_due: bool,
    low_now_m: f64,
    high_now_m: f64,
    slope_now: (f64, f64),
}

impl Default for TransitionBounds {
    fn default() -> Self {
        Self {
            low_before_m: 0.0,
            high_before_m: 0.0,
            slope_before: (0.0, 0.0),
            now_due: true,
            low_now_m: 0.0,
            high_now_m: 0.0,
            slope_now: (0.0, 0.0),
        }
    }
}

impl TransitionBounds {
    /// A change starts at `t_s` from the steady gait `before`; the present
    /// gait's figures follow at the next [`TransitionBounds::refresh`].
    pub fn start(&mut self, before: &GaitParams, t_s: f64, g_mps2: f64, weights: &[f64]) {
        (_, self.low_before_m, self.high_before_m) = eq9_centre_and_range_m(before, t_s, g_mps2);
        self.slope_before = eq9_slope_range(before, t_s, g_mps2, weights);
        self.now_due = true;
    }

    /// The gait's period, duty factor or phases changed while the legs take
    /// a change on: its figures follow at the next [`TransitionBounds::refresh`].
    pub fn gait_changed(&mut self) {
        self.now_due = true;
    }

    /// Brings the present gait's figures up to date at `t_s` when they are
    /// due (a change started, or the gait changed since).
    pub fn refresh(&mut self, gait: &GaitParams, t_s: f64, g_mps2: f64, weights: &[f64]) {
        if std::mem::take(&mut self.now_due) {
            (_, self.low_now_m, self.high_now_m) = eq9_centre_and_range_m(gait, t_s, g_mps2);
            self.slope_now = eq9_slope_range(gait, t_s, g_mps2, weights);
        }
    }

    /// The lowest the body may go, relative to its standing height, metres.
    #[must_use]
    pub fn low_m(&self) -> f64 {
        self.low_before_m.min(self.low_now_m)
    }

    /// The highest the body may go, relative to its standing height, metres.
    #[must_use]
    pub fn high_m(&self) -> f64 {
        self.high_before_m.max(self.high_now_m)
    }

    /// `slope` held within the two steady gaits' pitch slopes.
    #[must_use]
    pub fn pitch_slope(&self, slope: f64) -> f64 {
        let low = self.slope_before.0.min(self.slope_now.0);
        let high = self.slope_before.1.max(self.slope_now.1);
        slope.max(low).min(high)
    }
}

/// One planted foot and the leg that stands on it.
#[derive(Clone, Copy, Debug)]
pub struct PlantedLeg {
    /// The hip joint relative to the root, body frame, metres.
    pub hip_body: DVec3,
    /// The straight leg's length from the hip to the foot, metres.
    pub length_m: f64,
    /// Where the foot stands, world metres.
    pub foot: DVec3,
}

/// The highest the root may stand, with its ground position `root_xz` (y
/// ignored) and orientation `rotation`, for every planted foot to stay
/// within [`REACH`] of its straight leg from the hip; infinite with no foot
/// down.
pub fn reach_ceiling_m(
    root_xz: DVec3,
    rotation: DMat3,
    planted: impl Iterator<Item = PlantedLeg>,
) -> f64 {
    planted.fold(f64::INFINITY, |ceiling, leg| {
        let hip = rotation * leg.hip_body;
        let across = DVec2::new(
            root_xz.x + hip.x - leg.foot.x,
            root_xz.z + hip.z - leg.foot.z,
        );
        let reach = REACH * leg.length_m;
        let up = (reach * reach - across.length_squared()).max(0.0).sqrt();
        ceiling.min(leg.foot.y + up - hip.y)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_planted_foot_under_its_hip_allows_the_hip_at_reach() {
        let leg = PlantedLeg {
            hip_body: DVec3::new(0.1, -0.05, 0.2),
            length_m: 0.5,
            foot: DVec3::new(0.1, 0.0, 0.2),
        };
        let ceiling = reach_ceiling_m(DVec3::ZERO, DMat3::IDENTITY, [leg].into_iter());
        // Hip straight above the foot at 0.98 × 0.5 m: root 0.05 m higher.
        assert!((ceiling - (0.49 + 0.05)).abs() < 1e-12, "{ceiling}");
        // 0.3 m to the side: √(0.49² − 0.3²) up.
        let side = PlantedLeg {
            foot: DVec3::new(0.4, 0.0, 0.2),
            ..leg
        };
        let ceiling = reach_ceiling_m(DVec3::ZERO, DMat3::IDENTITY, [side].into_iter());
        let up = (0.49_f64 * 0.49 - 0.09).sqrt();
        assert!((ceiling - (up + 0.05)).abs() < 1e-12, "{ceiling}");
        assert_eq!(
            reach_ceiling_m(DVec3::ZERO, DMat3::IDENTITY, std::iter::empty()),
            f64::INFINITY
        );
    }

    #[test]
    fn the_pitch_is_held_within_both_gaits() {
        let bounds = TransitionBounds {
            slope_before: (-0.1, 0.05),
            slope_now: (-0.02, 0.2),
            ..TransitionBounds::default()
        };
        assert_eq!(bounds.pitch_slope(0.3), 0.2);
        assert_eq!(bounds.pitch_slope(-0.3), -0.1);
        assert_eq!(bounds.pitch_slope(0.01), 0.01);
    }
}
