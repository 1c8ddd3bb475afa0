//! How nearly the legs of each virtual leg act in unison (Raibert & Hodgins
//! 1991, "Gaits"): in the trot and the bound "the members of each pair
//! strike the ground in unison and leave the ground in unison"; in the
//! gallop they "no longer strike and leave the ground in perfect unison",
//! the stance being single, double, then single support. Measured from the
//! recorded stances: for each stance of a pair's first leg, the second
//! leg's stance that overlaps it, and the gaps between their touchdowns and
//! between their lift-offs (s).

use crate::engine::metrics::Stance;

/// One virtual leg's timing over a run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairTiming {
    /// The pair's legs (indices into the creature's legs).
    pub legs: [usize; 2],
    /// Mean |touchdown of the second − touchdown of the first| over the
    /// stances both legs shared (s).
    pub touchdown_gap_s: f64,
    /// Mean |lift-off of the second − lift-off of the first| (s).
    pub liftoff_gap_s: f64,
    /// Stances of the first leg that a stance of the second overlapped.
    pub shared: usize,
    /// Stances of the first leg the second did not touch down in: the pair
    /// did not act as one leg then.
    pub alone: usize,
}

/// The touchdown gap the paper's gallop asks of a pair, as a share of one
/// leg's stance: "a single support phase, a double support phase, and then
/// a second single support phase", read as three equal parts, so the second
/// leg lands half a leg's stance after the first. (The paper gives no
/// figure; the bundled biped's gallops land 0.36–0.41 of a stance apart.)
pub const GALLOP_GAP_SHARE: f64 = 0.5;

/// How far a run's pairs are from the gait's timing, 0 (as asked) to 1: for
/// each pair, |touchdown gap / mean stance − `target_share`| / 0.5, capped
/// at 1, each stance of the first leg the second did not share counting 1;
/// the mean over the pairs. `leg_stance_s` is each leg's mean stance (s).
/// `None` when there is no pair or no stance to judge.
#[must_use]
pub fn timing_cost(timings: &[PairTiming], leg_stance_s: &[f64], target_share: f64) -> Option<f64> {
    let costs: Vec<f64> = timings
        .iter()
        .filter(|t| t.shared + t.alone > 0)
        .map(|t| {
            let stance = t
                .legs
                .iter()
                .map(|&i| leg_stance_s.get(i).copied().unwrap_or(0.0))
                .sum::<f64>()
                / 2.0;
            let off = if stance > 0.0 {
                ((t.touchdown_gap_s / stance - target_share).abs() / 0.5).min(1.0)
            } else {
                1.0
            };
            (t.shared as f64 * off + t.alone as f64) / (t.shared + t.alone) as f64
        })
        .collect();
    (!costs.is_empty()).then(|| costs.iter().sum::<f64>() / costs.len() as f64)
}

/// The timing of each pair in `pairs` from every leg's stances.
#[must_use]
pub fn pair_timing(stances: &[Vec<Stance>], pairs: &[[usize; 2]]) -> Vec<PairTiming> {
    pairs
        .iter()
        .filter_map(|&[a, b]| {
            let (first, second) = (stances.get(a)?, stances.get(b)?);
            let mut t = PairTiming {
                legs: [a, b],
                ..PairTiming::default()
            };
            for sa in first {
                // The second leg's overlapping stance whose touchdown is nearest.
                let nearest = second
                    .iter()
                    .filter(|sb| sb.start_s < sa.end_s && sb.end_s > sa.start_s)
                    .min_by(|x, y| {
                        let dx = (x.start_s - sa.start_s).abs();
                        let dy = (y.start_s - sa.start_s).abs();
                        dx.total_cmp(&dy)
                    });
                match nearest {
                    Some(sb) => {
                        t.touchdown_gap_s += (sb.start_s - sa.start_s).abs();
                        t.liftoff_gap_s += (sb.end_s - sa.end_s).abs();
                        t.shared += 1;
                    }
                    None => t.alone += 1,
                }
            }
            if t.shared > 0 {
                t.touchdown_gap_s /= t.shared as f64;
                t.liftoff_gap_s /= t.shared as f64;
            }
            Some(t)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stance(start_s: f64, end_s: f64) -> Stance {
        Stance {
            start_s,
            end_s,
            leg_shortening_m: 0.0,
        }
    }

    #[test]
    fn gaps_are_the_mean_distances_between_overlapping_stances() {
        // Leg 0 lands at 0.0 and 1.0; leg 1 lands 20 and 40 ms later and
        // leaves 10 and 30 ms later; leg 2 never overlaps leg 0.
        let stances = vec![
            vec![stance(0.0, 0.1), stance(1.0, 1.1), stance(2.0, 2.1)],
            vec![stance(0.02, 0.11), stance(1.04, 1.13), stance(2.5, 2.6)],
            vec![stance(0.5, 0.6)],
        ];
        let got = pair_timing(&stances, &[[0, 1], [0, 2], [0, 9]]);
        assert_eq!(got.len(), 2, "a pair naming a missing leg is left out");
        assert_eq!((got[0].shared, got[0].alone), (2, 1));
        assert!((got[0].touchdown_gap_s - 0.03).abs() < 1e-12);
        assert!((got[0].liftoff_gap_s - 0.02).abs() < 1e-12);
        assert_eq!((got[1].shared, got[1].alone), (0, 3));
        assert_eq!(got[1].touchdown_gap_s, 0.0);
    }

    #[test]
    fn the_cost_is_the_distance_from_the_gaits_share_of_a_stance() {
        let pair = |gap: f64, shared, alone| PairTiming {
            legs: [0, 1],
            touchdown_gap_s: gap,
            liftoff_gap_s: 0.0,
            shared,
            alone,
        };
        let stance = [0.1, 0.1];
        // In unison: no gap costs 0, a gap of half a stance the whole 1.
        assert_eq!(timing_cost(&[pair(0.0, 10, 0)], &stance, 0.0), Some(0.0));
        let half = timing_cost(&[pair(0.025, 10, 0)], &stance, 0.0).expect("judged");
        assert!((half - 0.5).abs() < 1e-12);
        // The gallop: half a stance apart costs 0; in unison 1; an unshared
        // stance of the first leg counts 1.
        let gallop = GALLOP_GAP_SHARE;
        assert_eq!(
            timing_cost(&[pair(0.05, 10, 0)], &stance, gallop),
            Some(0.0)
        );
        assert_eq!(timing_cost(&[pair(0.0, 10, 0)], &stance, gallop), Some(1.0));
        let some_alone = timing_cost(&[pair(0.05, 3, 1)], &stance, gallop).expect("judged");
        assert!((some_alone - 0.25).abs() < 1e-12);
        // Two pairs: their mean; nothing to judge: None.
        let two = timing_cost(&[pair(0.05, 10, 0), pair(0.0, 10, 0)], &stance, gallop);
        assert_eq!(two, Some(0.5));
        assert_eq!(timing_cost(&[], &stance, gallop), None);
        assert_eq!(timing_cost(&[pair(0.0, 0, 0)], &stance, gallop), None);
    }

    #[test]
    fn of_two_overlapping_stances_the_nearest_touchdown_is_taken() {
        let stances = vec![
            vec![stance(0.0, 0.2)],
            vec![stance(-0.05, 0.01), stance(0.03, 0.19)],
        ];
        let got = pair_timing(&stances, &[[0, 1]]);
        assert!((got[0].touchdown_gap_s - 0.03).abs() < 1e-12);
        assert!((got[0].liftoff_gap_s - 0.01).abs() < 1e-12);
    }
}
