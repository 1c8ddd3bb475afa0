//! Named gaits for the PODA gait model (Girard & Maciejewski 1985, "Gait Design in PODA" and
//! "Leg Coordination", eq. 9): relative phases `R_i` and duty factors for the quadruped gait
//! classes of PODA fig. 5, biped walk/run, hexapod tripod/ripple gaits, and the alternating,
//! ripple and metachronal wave gaits for any even number of legs.
//!
//! **Phase convention (eq. 9).** Leg state `(R_i·P + t) mod P` is 0 at touchdown, so a leg with
//! phase `R` touches down at `t ≡ −R·P (mod P)` and is on the ground while
//! `(R + t/P) mod 1 < β` (duty factor `β`, "Gait Design in PODA"). Gaits are written here as
//! touchdown times `τ` (fractions of the cycle, footfall order readable) and converted with
//! `R = (−τ) mod 1`.
//!
//! **Leg order.** Biped `[left, right]`; quadruped `[left_front, right_front, left_hind,
//! right_hind]`; hexapod `[L1, R1, L2, R2, L3, R3]` front to back; any even `n` as pairs front to
//! back, left then right (leg `i` is pair `p = i / 2`, side `s = i % 2`, 0 = left; `k = n / 2`
//! pairs). A preset's legs default to its limbs in limb order, so a pair of legs added behind
//! the last one (limbs `L4`, `R4` after `R3`) keeps this order.
//!
//! **What is the paper's and what is gaitlab's.** The paper classifies the quadruped gaits by
//! their relative phases (fig. 5), separates walking (`β > 0.5`) from running (`β < 0.5`), says
//! that "an animator using PODA may design gaits for figures having any number of legs" ("Leg
//! Coordination") and shows a 14-legged insect "moving in a wave gait, the legs near the rear
//! advance toward their next footholds" (fig. 11). The hexapod tripod and ripple and every
//! formula below for `n` legs are gaitlab's generalisations in that spirit, not the paper's.
//!
//! **Alternating gait** (`alternating`, any even `n ≥ 4`): two groups half a cycle apart; legs
//! alternate along each side and across the body, `τ = ((p + s) mod 2) / 2`, duty factor
//! `β = 0.5`. With `β = 0.5` one group lands as the other lifts, so exactly `n/2` legs are down
//! at every instant, and each group has feet on both sides and in the front and rear pairs (for
//! `n ≥ 6` at least three, a support polygon spanning the body: statically stable). For `n = 6` it is the
//! `tripod` (L1+R2+L3, R1+L2+R3), for `n = 4` the `trot` (LF+RH, RF+LH), phase for phase.
//!
//! **Ripple gait** (`ripple`, any even `n ≥ 6`): on each side a back-to-front wave, the pairs
//! `1/k` of a cycle apart, the right side half a cycle after the left:
//! `τ = (k − 1 − p)/k + s/2`, duty factor `β = min(1 − 1/k, 0.9)`. With `β = 1 − 1/k` each side
//! lifts exactly one leg at a time (its lifts tile the cycle), so `n − 2` legs are down at every
//! instant (hexapod: `β = 2/3`, four down); the 0.9 cap, as for the wave, keeps the transfer from
//! vanishing on long bodies (`n > 20` then lifts up to two legs per side). For `n = 6` the
//! hexapod's `ripple` (table entry, kept as it was). For `n = 4` the formula is the trot, so
//! `ripple` starts at six legs.
//!
//! **Wave gait** (`wave`, any even `n ≥ 4`, PODA fig. 11): on each side the legs touch down back
//! to front, `1/n` of a cycle apart, the right side half a cycle after the left, so the `n`
//! touchdowns are evenly spread: `τ = (k − 1 − p)/n + s/2`. Duty factor `max(0.75, 1 − 1/n)`,
//! capped at 0.9: with `β = 1 − 1/n` exactly one leg is lifted at a time (hexapod: 5/6); the 0.75
//! floor makes the 4-legged wave the lateral-sequence walk, and the 0.9 cap keeps a long body's
//! transfer from vanishing (n > 10 then lifts `⌊n/10⌋` to `⌈n/10⌉` legs at once: two up to 20
//! legs, up to three or four beyond).
//!
//! **Listing order.** [`gait_names`] lists gaits in table order, and a preset without a gait
//! walks in the first one listed for its leg count (walk, tripod, wave); the `n`-leg
//! `alternating` and `ripple` come after `wave` so that default stays what it was.

use super::gait::{GaitError, GaitParams, LEG_COUNT_RANGE, normalise_phase};

/// Which leg counts a named gait applies to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LegCount {
    /// Exactly this many legs.
    Exactly(usize),
    /// Any even number of legs from this one up to the model's maximum.
    EvenFrom(usize),
}

impl LegCount {
    /// Whether `leg_count` is one this gait applies to.
    #[must_use]
    pub fn accepts(self, leg_count: usize) -> bool {
        match self {
            Self::Exactly(n) => leg_count == n,
            Self::EvenFrom(n) => {
                leg_count >= n
                    && leg_count.is_multiple_of(2)
                    && LEG_COUNT_RANGE.contains(&leg_count)
            }
        }
    }
}

/// How a gait's phases and duty factor are produced.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Pattern {
    /// Fixed touchdown times `τ` per leg (cycle fractions) and a duty factor.
    Touchdowns(&'static [f64], f64),
    /// The metachronal wave for any even leg count (see the module docs).
    Wave,
    /// The two-group alternating gait for any even leg count (see the module docs).
    Alternating,
    /// One back-to-front wave per side, sides half a cycle apart (see the module docs).
    Ripple,
}

/// A named gait: a preset of relative phases and a duty factor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NamedGait {
    /// Name used to look the gait up, e.g. `trot`.
    pub name: &'static str,
    /// One-line description of the footfall pattern.
    pub description: &'static str,
    /// Leg counts the gait applies to.
    pub legs: LegCount,
    pattern: Pattern,
}

const fn fixed(
    name: &'static str,
    description: &'static str,
    touchdowns: &'static [f64],
    duty: f64,
) -> NamedGait {
    NamedGait {
        name,
        description,
        legs: LegCount::Exactly(touchdowns.len()),
        pattern: Pattern::Touchdowns(touchdowns, duty),
    }
}

/// Every named gait. Touchdown times `τ` are listed in the leg order of the module docs.
#[rustfmt::skip]
pub const NAMED_GAITS: &[NamedGait] = &[
    // Bipeds, [left, right].
    fixed("walk", "legs in antiphase with double support (duty 0.6 > 0.5)", &[0.0, 0.5], 0.6),
    fixed("run", "legs in antiphase with a flight phase (duty 0.35 < 0.5)", &[0.0, 0.5], 0.35),
    // Quadrupeds, [LF, RF, LH, RH].
    fixed("walk", "lateral sequence LH, LF, RH, RF, a quarter apart", &[0.25, 0.75, 0.0, 0.5], 0.75),
    fixed("trot", "diagonal pairs LF+RH and RF+LH, half a cycle apart", &[0.0, 0.5, 0.5, 0.0], 0.5),
    fixed("pace", "lateral pairs LF+LH and RF+RH, half a cycle apart", &[0.0, 0.5, 0.0, 0.5], 0.5),
    fixed("canter", "3-beat: RH, LH+RF together, LF, then flight", &[0.5, 0.25, 0.25, 0.0], 0.4),
    fixed("transverse_gallop", "LH, RH, LF, RF; 0.1 lead within pairs", &[0.4, 0.5, 0.0, 0.1], 0.3),
    fixed("rotary_gallop", "LH, RH, RF, LF; 0.1 lead within pairs", &[0.5, 0.4, 0.0, 0.1], 0.3),
    fixed("bound", "hind pair, then front pair half a cycle later", &[0.5, 0.5, 0.0, 0.0], 0.35),
    fixed("pronk", "all four legs together", &[0.0, 0.0, 0.0, 0.0], 0.3),
    // Hexapods, [L1, R1, L2, R2, L3, R3].
    fixed("tripod", "tripods L1+R2+L3 and R1+L2+R3, half a cycle apart",
        &[0.0, 0.5, 0.5, 0.0, 0.0, 0.5], 0.5),
    fixed("ripple", "per side a back-to-front wave a third apart; sides half a cycle apart",
        &[2.0 / 3.0, 1.0 / 6.0, 1.0 / 3.0, 5.0 / 6.0, 0.0, 0.5], 2.0 / 3.0),
    // Any even leg count from 4 (see the module docs).
    NamedGait {
        name: "wave",
        description: "back-to-front metachronal wave on each side; sides half a cycle apart",
        legs: LegCount::EvenFrom(4),
        pattern: Pattern::Wave,
    },
    // Any even leg count, listed after the wave so a preset without a gait keeps its default.
    NamedGait {
        name: "alternating",
        description: "two groups half a cycle apart, alternating along and across the body",
        legs: LegCount::EvenFrom(4),
        pattern: Pattern::Alternating,
    },
    // The hexapod's ripple is the table entry above; this is its generalisation from 8 legs.
    NamedGait {
        name: "ripple",
        description: "per side a back-to-front wave, pairs 1/k apart; sides half a cycle apart",
        legs: LegCount::EvenFrom(8),
        pattern: Pattern::Ripple,
    },
];

/// Pair (front to back) and side (0 left, 1 right) of leg `i`, and the pair count, as floats.
#[expect(clippy::cast_precision_loss, reason = "leg counts ≤ 32")]
fn pair_side(i: usize, leg_count: usize) -> (f64, f64, f64) {
    ((i / 2) as f64, (i % 2) as f64, (leg_count / 2) as f64)
}

/// Touchdown time of leg `i` of `leg_count` in the alternating gait: `((p + s) mod 2) / 2`.
fn alternating_touchdown(i: usize, _leg_count: usize) -> f64 {
    if (i / 2 + i % 2).is_multiple_of(2) {
        0.0
    } else {
        0.5
    }
}

/// Touchdown time of leg `i` of `leg_count` in the ripple gait: `(k − 1 − p)/k + s/2`.
fn ripple_touchdown(i: usize, leg_count: usize) -> f64 {
    let (pair, side, pairs) = pair_side(i, leg_count);
    (pairs - 1.0 - pair) / pairs + 0.5 * side
}

/// Duty factor of the ripple gait for `leg_count` legs: `min(1 − 1/k, 0.9)`.
fn ripple_duty(leg_count: usize) -> f64 {
    let (_, _, pairs) = pair_side(0, leg_count);
    (1.0 - 1.0 / pairs).min(0.9)
}

/// Phases from touchdown times `τ(i, n)` for `leg_count` legs.
fn phases_from(leg_count: usize, touchdown: fn(usize, usize) -> f64) -> Vec<f64> {
    (0..leg_count)
        .map(|i| normalise_phase(-touchdown(i, leg_count)))
        .collect()
}

impl NamedGait {
    /// Phases (in `[0, 1)`, one per leg) and duty factor for `leg_count` legs; `None` when the
    /// gait does not apply to that count.
    #[must_use]
    pub fn phases_and_duty(&self, leg_count: usize) -> Option<(Vec<f64>, f64)> {
        if !self.legs.accepts(leg_count) {
            return None;
        }
        match self.pattern {
            Pattern::Touchdowns(touchdowns, duty) => Some((
                touchdowns
                    .iter()
                    .map(|&tau| normalise_phase(-tau))
                    .collect(),
                duty,
            )),
            Pattern::Wave => {
                #[expect(clippy::cast_precision_loss, reason = "leg count ≤ 32")]
                let n = leg_count as f64;
                let pairs = leg_count / 2;
                let phases = (0..leg_count)
                    .map(|i| {
                        #[expect(clippy::cast_precision_loss, reason = "indices ≤ 32")]
                        let (side, behind) = ((i % 2) as f64, (pairs - 1 - i / 2) as f64);
                        normalise_phase(-(0.5 * side + behind / n))
                    })
                    .collect();
                Some((phases, (1.0 - 1.0 / n).clamp(0.75, 0.9)))
            }
            Pattern::Alternating => Some((phases_from(leg_count, alternating_touchdown), 0.5)),
            Pattern::Ripple => Some((
                phases_from(leg_count, ripple_touchdown),
                ripple_duty(leg_count),
            )),
        }
    }
}

/// Names of the gaits available for `leg_count` legs, in table order.
pub fn gait_names(leg_count: usize) -> impl Iterator<Item = &'static str> {
    NAMED_GAITS
        .iter()
        .filter(move |g| g.legs.accepts(leg_count))
        .map(|g| g.name)
}

/// Phases and duty factor of gait `name` for `leg_count` legs.
///
/// # Errors
/// `gait` when no gait of that name applies to `leg_count`; the reason lists those that do.
pub fn named_gait(name: &str, leg_count: usize) -> Result<(Vec<f64>, f64), GaitError> {
    NAMED_GAITS
        .iter()
        .filter(|g| g.name == name)
        .find_map(|g| g.phases_and_duty(leg_count))
        .ok_or_else(|| {
            let available: Vec<&str> = gait_names(leg_count).collect();
            let available = if available.is_empty() {
                "none".to_owned()
            } else {
                available.join(", ")
            };
            GaitError::new(
                "gait",
                format!("no gait \"{name}\" for {leg_count} legs; available: {available}"),
            )
        })
}

/// Gait parameters for gait `name` with the given period and speed (stroke derived, eq. 7).
///
/// # Errors
/// As [`named_gait`], or [`GaitParams::new`] for the period and speed.
pub fn gait_params(
    name: &str,
    leg_count: usize,
    period_s: f64,
    speed_mps: f64,
) -> Result<GaitParams, GaitError> {
    let (phases, duty) = named_gait(name, leg_count)?;
    GaitParams::new(period_s, duty, phases, speed_mps)
}

#[cfg(test)]
#[expect(clippy::float_cmp, reason = "preset phases are exact binary fractions")]
mod tests {
    use super::*;

    /// Touchdown time (cycle fraction) of a leg with phase `r`.
    fn touchdown(r: f64) -> f64 {
        normalise_phase(-r)
    }

    #[test]
    fn every_gait_has_one_phase_per_leg_in_range() {
        for n in 1..=32 {
            for name in gait_names(n) {
                let (phases, duty) = named_gait(name, n).expect("known gait");
                assert_eq!(phases.len(), n, "{name}/{n}");
                assert!(phases.iter().all(|r| (0.0..1.0).contains(r)), "{name}/{n}");
                assert!(
                    gait_params(name, n, 1.0, 1.0).is_ok(),
                    "{name}/{n} duty {duty}"
                );
            }
        }
        assert_eq!(gait_names(4).count(), 10);
        assert_eq!(
            gait_names(6).collect::<Vec<_>>(),
            ["tripod", "ripple", "wave", "alternating"]
        );
        for n in (8..=32).step_by(2) {
            assert_eq!(
                gait_names(n).collect::<Vec<_>>(),
                ["wave", "alternating", "ripple"],
                "{n} legs"
            );
        }
    }

    #[test]
    fn quadruped_pairs_and_orders() {
        let (trot, _) = named_gait("trot", 4).expect("known gait");
        assert!(trot[0] == trot[3] && trot[1] == trot[2] && (trot[0] - trot[1]).abs() == 0.5);
        let (pace, _) = named_gait("pace", 4).expect("known gait");
        assert!(pace[0] == pace[2] && pace[1] == pace[3] && pace[0] != pace[1]);
        let (bound, duty) = named_gait("bound", 4).expect("known gait");
        assert!(bound[0] == bound[1] && bound[2] == bound[3] && (bound[0] - bound[2]).abs() == 0.5);
        assert!((duty - 0.35).abs() < 1e-15);
        let (pronk, _) = named_gait("pronk", 4).expect("known gait");
        assert!(pronk.iter().all(|&r| r == pronk[0]));
        // Footfall orders as touchdown times, legs [LF, RF, LH, RH].
        let order = |name: &str| {
            named_gait(name, 4)
                .expect("known gait")
                .0
                .iter()
                .map(|&r| touchdown(r))
                .collect::<Vec<_>>()
        };
        assert_eq!(order("walk"), [0.25, 0.75, 0.0, 0.5]); // LH, LF, RH, RF
        assert_eq!(named_gait("wave", 4), named_gait("walk", 4));
        let g = order("rotary_gallop");
        assert!(g[2] < g[3] && g[3] < g[1] && g[1] < g[0]); // LH, RH, RF, LF
        let g = order("transverse_gallop");
        assert!(g[2] < g[3] && g[3] < g[0] && g[0] < g[1]); // LH, RH, LF, RF
        let c = order("canter");
        assert!(c[2] == c[1] && c[3] < c[2] && c[2] < c[0]); // RH, LH+RF, LF
    }

    #[test]
    fn hexapod_and_biped_gaits() {
        let (tripod, _) = named_gait("tripod", 6).expect("known gait");
        assert!(tripod[0] == tripod[3] && tripod[3] == tripod[4]);
        assert!(
            tripod[1] == tripod[2]
                && tripod[2] == tripod[5]
                && (tripod[0] - tripod[1]).abs() == 0.5
        );
        let (_, ripple) = named_gait("ripple", 6).expect("known gait");
        assert!((ripple - 2.0 / 3.0).abs() < 1e-15);
        let (wave, duty) = named_gait("wave", 6).expect("known gait");
        assert!((duty - 5.0 / 6.0).abs() < 1e-15);
        let mut t: Vec<f64> = wave.iter().map(|&r| touchdown(r)).collect();
        t.sort_by(f64::total_cmp); // six touchdowns evenly spread: one leg lifted at a time
        assert!(
            t.windows(2)
                .all(|w| (w[1] - w[0] - 1.0 / 6.0).abs() < 1e-12)
        );
        let (walk, walk_duty) = named_gait("walk", 2).expect("known gait");
        let (run, run_duty) = named_gait("run", 2).expect("known gait");
        assert!(walk_duty > 0.5 && run_duty < 0.5);
        assert!((walk[1] - walk[0]).abs() == 0.5 && (run[1] - run[0]).abs() == 0.5);
    }

    #[test]
    fn fourteen_leg_wave_runs_back_to_front() {
        let (phases, duty) = named_gait("wave", 14).expect("known gait");
        assert!((duty - 0.9).abs() < 1e-15);
        for side in 0..2 {
            let rear = touchdown(phases[12 + side]);
            let since_rear: Vec<f64> = (0..7)
                .rev()
                .map(|pair| normalise_phase(touchdown(phases[2 * pair + side]) - rear))
                .collect();
            assert!(
                since_rear
                    .windows(2)
                    .all(|w| (w[1] - w[0] - 1.0 / 14.0).abs() < 1e-12),
                "{since_rear:?}"
            );
        }
        for pair in 0..7 {
            let gap = normalise_phase(phases[2 * pair] - phases[2 * pair + 1]);
            assert!((gap - 0.5).abs() < 1e-12);
        }
    }

    #[test]
    fn wrong_leg_count_lists_the_available_gaits() {
        let e = named_gait("trot", 6).expect_err("rejected");
        assert_eq!(e.path, "gait");
        assert!(
            e.reason
                .ends_with("available: tripod, ripple, wave, alternating"),
            "{e}"
        );
        let e = named_gait("tripod", 8).expect_err("tripod is the 6-leg name");
        assert!(
            e.reason
                .ends_with("no gait \"tripod\" for 8 legs; available: wave, alternating, ripple"),
            "{e}"
        );
        assert!(
            named_gait("wave", 5)
                .expect_err("rejected")
                .reason
                .ends_with("available: none")
        );
        assert!(named_gait("wave", 34).is_err() && named_gait("gallop", 4).is_err());
        assert!(named_gait("ripple", 4).is_err() && named_gait("alternating", 7).is_err());
    }

    /// Legs on the ground at cycle fraction `t`: `(R + t) mod 1 < β` (eq. 9).
    fn legs_down(phases: &[f64], duty: f64, t: f64) -> usize {
        phases
            .iter()
            .filter(|&&r| normalise_phase(r + t) < duty)
            .count()
    }

    /// Fewest and most legs down over a cycle, sampled off every touchdown and lift-off.
    fn legs_down_range(phases: &[f64], duty: f64) -> (usize, usize) {
        (0..4000)
            .map(|j| {
                legs_down(
                    phases,
                    duty,
                    (f64::from(j) + std::f64::consts::FRAC_1_PI) / 4000.0,
                )
            })
            .fold((usize::MAX, 0), |(lo, hi), c| (lo.min(c), hi.max(c)))
    }

    #[test]
    fn alternating_is_the_tripod_and_the_trot_and_keeps_half_the_legs_down() {
        assert_eq!(named_gait("alternating", 6), named_gait("tripod", 6));
        assert_eq!(named_gait("alternating", 4), named_gait("trot", 4));
        for n in (4..=32).step_by(2) {
            let (phases, duty) = named_gait("alternating", n).expect("known gait");
            assert_eq!((phases.len(), duty), (n, 0.5));
            // Two groups half a cycle apart, alternating along each side and across the body.
            for i in 0..n {
                let td = touchdown(phases[i]);
                assert!(td == 0.0 || td == 0.5, "{n} legs, leg {i}: {td}");
                if i + 2 < n {
                    assert_eq!(normalise_phase(td - touchdown(phases[i + 2])), 0.5);
                }
                if i % 2 == 0 {
                    assert_eq!(normalise_phase(td - touchdown(phases[i + 1])), 0.5);
                }
            }
            // Each group reaches both sides and the front and rear pairs.
            for group in [0.0, 0.5] {
                let legs: Vec<usize> = (0..n).filter(|&i| touchdown(phases[i]) == group).collect();
                assert_eq!(legs.len(), n / 2);
                assert!(legs.iter().any(|i| i % 2 == 0) && legs.iter().any(|i| i % 2 == 1));
                assert!(legs.iter().any(|i| i / 2 == 0) && legs.iter().any(|i| i / 2 == n / 2 - 1));
            }
            let (fewest, most) = legs_down_range(&phases, duty);
            assert_eq!((fewest, most), (n / 2, n / 2), "{n} legs");
            assert!(n < 6 || fewest >= 3);
        }
    }

    #[test]
    fn ripple_for_n_legs_runs_back_to_front_per_side_with_n_minus_2_down() {
        let (hexapod, hexapod_duty) = named_gait("ripple", 6).expect("known gait");
        let general = phases_from(6, ripple_touchdown);
        assert!((ripple_duty(6) - hexapod_duty).abs() < 1e-15);
        for (g, h) in general.iter().zip(&hexapod) {
            assert!(phase_gap(*g, *h) < 1e-12, "{general:?} vs {hexapod:?}");
        }
        for n in (6..=32).step_by(2) {
            let k = n / 2;
            let (phases, duty) = named_gait("ripple", n).expect("known gait");
            #[expect(clippy::cast_precision_loss, reason = "leg counts ≤ 32")]
            let kf = k as f64;
            assert!(
                (duty - (1.0 - 1.0 / kf).min(0.9)).abs() < 1e-15,
                "{n}: {duty}"
            );
            for side in 0..2 {
                // From the rear pair forward, each touchdown 1/k after the one behind it.
                for pair in 0..k - 1 {
                    let ahead = touchdown(phases[2 * pair + side]);
                    let behind = touchdown(phases[2 * (pair + 1) + side]);
                    assert!(phase_gap(normalise_phase(ahead - behind), 1.0 / kf) < 1e-12);
                }
            }
            for pair in 0..k {
                let gap = normalise_phase(phases[2 * pair] - phases[2 * pair + 1]);
                assert!((gap - 0.5).abs() < 1e-12, "{n} legs, pair {pair}");
            }
            let (fewest, most) = legs_down_range(&phases, duty);
            if k <= 10 {
                assert_eq!((fewest, most), (n - 2, n - 2), "{n} legs");
            } else {
                assert!(
                    fewest >= n - 4 && most <= n - 2,
                    "{n} legs: {fewest}..{most}"
                );
            }
        }
    }

    #[test]
    fn wave_lifts_one_leg_at_a_time_up_to_ten_legs() {
        for n in (4..=32).step_by(2) {
            let (phases, duty) = named_gait("wave", n).expect("known gait");
            let (fewest, most) = legs_down_range(&phases, duty);
            if n <= 10 {
                assert_eq!((fewest, most), (n - 1, n - 1), "{n} legs");
            } else {
                // β = 0.9: each leg lifted for n/10 of the 1/n touchdown spacings.
                let (lifted_lo, lifted_hi) = (n / 10, n.div_ceil(10));
                assert!(
                    fewest == n - lifted_hi && most == n - lifted_lo,
                    "{n} legs: {fewest}..{most}"
                );
            }
            // Footfalls: every touchdown 1/n after the previous one, left rear first.
            let mut order: Vec<(f64, usize)> = (0..n).map(|i| (touchdown(phases[i]), i)).collect();
            order.sort_by(|a, b| a.0.total_cmp(&b.0));
            assert_eq!(order[0].1, n - 2, "{n} legs: the left rear leg lands first");
            #[expect(clippy::cast_precision_loss, reason = "leg counts ≤ 32")]
            let step = 1.0 / n as f64;
            assert!(
                order
                    .windows(2)
                    .all(|w| (w[1].0 - w[0].0 - step).abs() < 1e-12)
            );
        }
    }

    /// Circular distance between two cycle fractions.
    fn phase_gap(a: f64, b: f64) -> f64 {
        let d = normalise_phase(a - b);
        d.min(1.0 - d)
    }
}
