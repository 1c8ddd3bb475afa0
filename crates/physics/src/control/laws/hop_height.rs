//! Hop height and flight time (Raibert & Hodgins 1991, "Hopping Control",
//! eq. 2): a body that leaves the ground rising and lands at the height it
//! left reaches `h = g·t²/8` above lift-off in a flight of `t` seconds. The
//! gaits that regulate their flight time (the trot, the bound) take the hop
//! height a user asks for through this. Eq. 2 itself — the apex the energy
//! in the springs, the elevation and the vertical speed predict — and the
//! thrust that makes that prediction the target are [`predicted_apex_m`]
//! and [`thrust_for_apex`]: what every creature's thrust is by default.

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

/// Eq. 2: the altitude (m) a body of `mass_kg` hops to from its centre of
/// mass at `com_height_m` rising at `com_vy_mps`, with `strain_j` (J) stored
/// in its leg springs — `h = (PE_strain + PE_elevation + KE)/Mg`, the leg
/// taken as massless and the spring as lossless, as the paper does.
#[must_use]
pub fn predicted_apex_m(strain_j: f64, mass_kg: f64, com_height_m: f64, com_vy_mps: f64) -> f64 {
    let weight = mass_kg * GRAVITY_MPS2;
    (strain_j + weight * com_height_m + 0.5 * mass_kg * com_vy_mps * com_vy_mps) / weight
}

/// One supporting leg's spring for eq. 2: its constant k (N/m, or N·m/rad
/// for the kangaroo's ankle) and how far it is compressed below its rest
/// (m or rad, positive when it pushes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Compressed {
    /// Spring constant k of eq. 1.
    pub stiffness: f64,
    /// `x_r − x`: the rest beyond the spring's length.
    pub compression: f64,
}

impl Compressed {
    /// The strain energy `k·(x_r − x)²/2` (J).
    #[must_use]
    pub fn strain_j(self) -> f64 {
        0.5 * self.stiffness * (self.compression * self.compression)
    }
}

/// A pair's springs for eq. 2 (a virtual leg, "Gaits"): leg `i`'s spring
/// of `stiffness` compressed from `rests[i]` to its length
/// `q[springs[i]]` where it `supports[i]`, none where it does not.
#[must_use]
pub fn pair_springs(
    q: &[f64],
    springs: [usize; 2],
    rests: [f64; 2],
    supports: [bool; 2],
    stiffness: f64,
) -> [Compressed; 2] {
    std::array::from_fn(|i| Compressed {
        stiffness: if supports[i] { stiffness } else { 0.0 },
        compression: if supports[i] {
            rests[i] - q[springs[i]]
        } else {
            0.0
        },
    })
}

/// Eq. 2 solved for the thrust: the step Δ of every supporting spring's
/// rest (m or rad) that makes the predicted apex `target_m`. What the
/// springs must store beyond what they hold, `Mg·(target − predicted)`,
/// gives `Σ k_i (c_i + Δ)²/2 = Σ k_i c_i²/2 + Mg·(target − predicted)`, a
/// quadratic in Δ; its larger root. Where no step stores that little (the
/// body already rises past the target), the step that stores least — the
/// springs let go as far as they can. `springs` empty: no step (0).
#[must_use]
pub fn thrust_for_apex(
    springs: &[Compressed],
    mass_kg: f64,
    com_height_m: f64,
    com_vy_mps: f64,
    target_m: f64,
) -> f64 {
    let k: f64 = springs.iter().map(|s| s.stiffness).sum();
    if k.is_nan() || k <= 0.0 {
        return 0.0;
    }
    // The stiffness-weighted compression now and after the step.
    let mean = springs
        .iter()
        .map(|s| s.stiffness * s.compression)
        .sum::<f64>()
        / k;
    let after = compression_for_apex(
        springs,
        k,
        mean,
        mass_kg,
        com_height_m,
        com_vy_mps,
        target_m,
    );
    after - mean
}

/// Where the stance shortens a leg (Figure 4's Unloading, "active leg
/// spring approaches full length") before its spring has given back the
/// step Δ: the spring is still `of_step·Δ + beyond_m` short of the rest the
/// step moved it to. The trot's pair unloads back at its stance rest
/// (`of_step` 1); a leg unloading once it has extended a share of the
/// step past that rest holds the rest of it (the bound's `thrust_end`,
/// tried and not kept: docs/physics.md "The lift share"); 0 and 0 is a
/// spring spent to its rest, as eq. 2 takes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Release {
    /// The share of the step still held at the release.
    pub of_step: f64,
    /// Compression beyond that (m or rad).
    pub beyond_m: f64,
}

/// Eq. 2 for legs that are shortened before their springs have given back
/// what they hold ([`Release`]): the strain the prediction counts is what
/// the springs return until they are released, the rest being lost when
/// Unloading shortens the leg. With `Δ` the step, `a` and `ε` the release,
/// each spring returns `k_i·((c_i + Δ)² − (aΔ + ε)²)/2`, so
/// `K(1 − a²)/2·Δ² + Σk_i(c_i − aε)·Δ = Mg·(target − predicted) + Kε²/2`,
/// `predicted` eq. 2's apex with the strain as it stands, `K` the springs'
/// total stiffness: its larger root. No step when the springs are already
/// at their release (nothing left to push with) or when the body already
/// rises past the target (the springs let go).
#[must_use]
pub fn thrust_for_apex_released(
    springs: &[Compressed],
    release: Release,
    mass_kg: f64,
    com_height_m: f64,
    com_vy_mps: f64,
    target_m: f64,
) -> f64 {
    let (a, eps) = (release.of_step, release.beyond_m);
    let k: f64 = springs.iter().map(|s| s.stiffness).sum();
    let push: f64 = springs
        .iter()
        .map(|s| s.stiffness * (s.compression - a * eps))
        .sum();
    if k.is_nan() || k <= 0.0 || push.is_nan() || push <= 0.0 {
        return 0.0;
    }
    let strain: f64 = springs.iter().map(|s| s.strain_j()).sum();
    let predicted = predicted_apex_m(strain, mass_kg, com_height_m, com_vy_mps);
    let wanted = (target_m - predicted) * mass_kg * GRAVITY_MPS2 + 0.5 * k * eps * eps;
    let square = 0.5 * k * (1.0 - a * a);
    let step = if square.abs() < 1e-12 * k {
        wanted / push
    } else {
        let disc = push * push + 4.0 * square * wanted;
        if disc < 0.0 {
            return 0.0;
        }
        (disc.sqrt() - push) / (2.0 * square)
    };
    step.max(0.0)
}

/// Eq. 2 for one spring of length `length` (m or rad) compressed as
/// `spring`: the rest that makes the predicted apex `target_m` —
/// [`thrust_for_apex`]'s solve as the rest itself.
#[must_use]
pub fn rest_for_apex(
    length: f64,
    spring: Compressed,
    mass_kg: f64,
    com_height_m: f64,
    com_vy_mps: f64,
    target_m: f64,
) -> f64 {
    let one = [spring];
    let k = spring.stiffness;
    length
        + compression_for_apex(
            &one,
            k,
            spring.compression,
            mass_kg,
            com_height_m,
            com_vy_mps,
            target_m,
        )
}

/// The stiffness-weighted compression (`mean` now, `k` the springs' total)
/// after the step whose predicted apex is `target_m`: with `Δ` the step,
/// `k·mean·Δ + k·Δ²/2` must be `Mg·(target − predicted)`, so the mean after
/// is `√(mean² + 2·Mg·(target − predicted)/k)`; 0 (the springs let go)
/// where no step stores that little.
fn compression_for_apex(
    springs: &[Compressed],
    k: f64,
    mean: f64,
    mass_kg: f64,
    com_height_m: f64,
    com_vy_mps: f64,
    target_m: f64,
) -> f64 {
    let strain: f64 = springs.iter().map(|s| s.strain_j()).sum();
    let predicted = predicted_apex_m(strain, mass_kg, com_height_m, com_vy_mps);
    let wanted = (target_m - predicted) * mass_kg * GRAVITY_MPS2;
    let stored = mean * mean + 2.0 * wanted / k;
    stored.max(0.0).sqrt()
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

    #[test]
    fn the_thrust_stores_what_the_prediction_lacks() {
        // Two springs, a body at 0.8 m falling at 0.1 m/s: the step found
        // makes eq. 2 predict the target, within rounding.
        let springs = [
            Compressed {
                stiffness: 6000.0,
                compression: 0.02,
            },
            Compressed {
                stiffness: 4000.0,
                compression: 0.035,
            },
        ];
        let (m, y, vy, target) = (12.0, 0.8, -0.1, 0.9);
        let step = thrust_for_apex(&springs, m, y, vy, target);
        let stored: f64 = springs
            .iter()
            .map(|s| {
                Compressed {
                    compression: s.compression + step,
                    ..*s
                }
                .strain_j()
            })
            .sum();
        assert!((predicted_apex_m(stored, m, y, vy) - target).abs() < 1e-12);
        assert!(step > 0.0);
        // One spring, energy checked by hand: 0.5·k·d² = Mg·Δh.
        let one = [Compressed {
            stiffness: 2.0 * 9.81 * 10.0,
            compression: 0.0,
        }];
        assert!((thrust_for_apex(&one, 10.0, 0.0, 0.0, 0.25) - 0.5).abs() < 1e-12);
        // Already rising past the target: the springs let go entirely.
        let rising = thrust_for_apex(&springs, m, y, 3.0, target);
        let kc = 6000.0 * 0.02 + 4000.0 * 0.035;
        assert!((rising + kc / 10000.0).abs() < 1e-12);
        assert_eq!(thrust_for_apex(&[], m, y, vy, target), 0.0);
    }

    #[test]
    fn a_released_spring_returns_what_the_target_asks() {
        // Two springs released short of the rest the step moved them to:
        // what they give back from here to there, with the step, is what
        // the target lacks beyond elevation and speed.
        let springs = [
            Compressed {
                stiffness: 6000.0,
                compression: 0.03,
            },
            Compressed {
                stiffness: 4000.0,
                compression: 0.045,
            },
        ];
        let (m, y, vy, target) = (12.0, 0.8, -0.1, 0.9);
        for (a, eps) in [(1.0, 0.01), (0.33, 0.005), (0.0, 0.0)] {
            let release = Release {
                of_step: a,
                beyond_m: eps,
            };
            let step = thrust_for_apex_released(&springs, release, m, y, vy, target);
            let returned: f64 = springs
                .iter()
                .map(|s| {
                    0.5 * s.stiffness * ((s.compression + step).powi(2) - (a * step + eps).powi(2))
                })
                .sum();
            assert!(
                (predicted_apex_m(returned, m, y, vy) - target).abs() < 1e-12,
                "released at {a}·Δ + {eps}"
            );
            assert!(step > 0.0);
        }
        // Spent to the rest: the same step as the whole strain's solve.
        let spent = Release {
            of_step: 0.0,
            beyond_m: 0.0,
        };
        let whole = thrust_for_apex(&springs, m, y, vy, target);
        let same = thrust_for_apex_released(&springs, spent, m, y, vy, target);
        assert!((whole - same).abs() < 1e-12, "{whole} against {same}");
        // At the release already, or rising past the target: no step.
        let at = Release {
            of_step: 1.0,
            beyond_m: 0.05,
        };
        assert_eq!(
            thrust_for_apex_released(&springs, at, m, y, vy, target),
            0.0
        );
        let trot = Release {
            of_step: 1.0,
            beyond_m: 0.01,
        };
        assert_eq!(
            thrust_for_apex_released(&springs, trot, m, y, 3.0, target),
            0.0
        );
    }
}
