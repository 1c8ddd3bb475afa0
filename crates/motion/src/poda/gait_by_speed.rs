//! Gait by speed: the named gait and stride for a body speed from the Froude
//! number `Fr = v²/(g·h)` (Alexander 1984, PODA's reference 20: animals of
//! every size change from walking to trotting near `Fr ≈ 0.5` and from
//! trotting to galloping near `Fr ≈ 2–3`, and their relative stride length
//! is about `λ/h = 2.3·Fr^0.3`). The lab's option
//! `scenario.poda.gait_by_speed`; the thresholds' reading for other leg
//! counts and the stroke bound are the lab's.

use gaitlab_core::portable::Portable;

/// Froude number where the slowest gait gives way to the middle one.
pub const WALK_TO_TROT_FROUDE: f64 = 0.5;
/// Froude number where the middle gait gives way to the fastest one (the
/// middle of Alexander's 2–3).
pub const TROT_TO_GALLOP_FROUDE: f64 = 2.5;
/// Relative stride length at `Fr = 1` (`λ/h = 2.3·Fr^0.3`).
const STRIDE_AT_FR1: f64 = 2.3;
/// Exponent of the relative stride length in `Fr`.
const STRIDE_EXPONENT: f64 = 0.3;

/// The slow, middle and fast gaits for `legs` legs, by name: a quadruped
/// walks, trots and gallops (rotary); a biped walks and runs (its middle and
/// fast gaits are both `run`); other even counts go from the wave through
/// the ripple to the alternating gait; `None` where the leg count has no
/// such set.
#[must_use]
pub fn speed_gaits(legs: usize) -> Option<[&'static str; 3]> {
    match legs {
        2 => Some(["walk", "run", "run"]),
        4 => Some(["walk", "trot", "rotary_gallop"]),
        n if n >= 6 && n % 2 == 0 => Some(["wave", "ripple", "alternating"]),
        _ => None,
    }
}

/// The Froude number `v²/(g·h)` of speed `speed_mps` at hip height `hip_height_m`.
#[must_use]
pub fn froude(speed_mps: f64, hip_height_m: f64, g_mps2: f64) -> f64 {
    speed_mps * speed_mps / (g_mps2 * hip_height_m)
}

/// Which of [`speed_gaits`] fits the Froude number `fr`: 0 slow, 1 middle, 2 fast.
#[must_use]
pub fn gait_index(fr: f64) -> usize {
    if fr < WALK_TO_TROT_FROUDE {
        0
    } else if fr < TROT_TO_GALLOP_FROUDE {
        1
    } else {
        2
    }
}

/// Alexander's stride length `λ = 2.3·Fr^0.3·h`, metres.
#[must_use]
pub fn stride_length_m(fr: f64, hip_height_m: f64) -> f64 {
    STRIDE_AT_FR1 * fr.max(0.0).ppowf(STRIDE_EXPONENT) * hip_height_m
}

/// The period for speed `speed_mps` in a gait of duty factor `duty`:
/// Alexander's stride over the speed, `P = λ/v`, shortened where the stroke
/// `β·λ` would exceed `max_stroke_m` (`P = max_stroke / (β·v)`).
#[must_use]
pub fn period_s(
    speed_mps: f64,
    hip_height_m: f64,
    g_mps2: f64,
    duty: f64,
    max_stroke_m: f64,
) -> f64 {
    let fr = froude(speed_mps, hip_height_m, g_mps2);
    let stride = stride_length_m(fr, hip_height_m).min(max_stroke_m / duty);
    stride / speed_mps
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quadruped_walks_trots_and_gallops_by_froude_number() {
        let gaits = speed_gaits(4).expect("quadruped");
        let h = 0.5;
        let pick = |v: f64| gaits[gait_index(froude(v, h, 9.81))];
        assert_eq!(pick(0.5), "walk");
        // Fr = 0.5 at v = √(0.5·g·h) = 1.566 m/s.
        assert_eq!(pick(1.55), "walk");
        assert_eq!(pick(1.58), "trot");
        // Fr = 2.5 at 3.502 m/s.
        assert_eq!(pick(3.49), "trot");
        assert_eq!(pick(3.51), "rotary_gallop");
        assert_eq!(speed_gaits(6).map(|g| g[0]), Some("wave"));
        assert_eq!(speed_gaits(5), None);
    }

    #[test]
    fn the_stride_follows_alexander_until_the_stroke_bound() {
        // Fr = 1: λ = 2.3·h.
        let h: f64 = 0.5;
        let v = (9.81 * h).sqrt();
        assert!((stride_length_m(froude(v, h, 9.81), h) - 1.15).abs() < 1e-12);
        let free = period_s(v, h, 9.81, 0.5, 10.0);
        assert!((free - 1.15 / v).abs() < 1e-12);
        // Bound: stroke 0.3 m at β = 0.5 → stride 0.6 m.
        let bound = period_s(v, h, 9.81, 0.5, 0.3);
        assert!((bound - 0.6 / v).abs() < 1e-12);
    }
}
