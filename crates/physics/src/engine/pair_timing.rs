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
