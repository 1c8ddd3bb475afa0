//! Rolling per-frame history for the live plots: each effector's tracking error
//! (She 2006 §5.3's distance d) and a few selected joint angles. Fixed capacity,
//! no allocation once full.

/// Frames kept for the plots (10 s at 60 fps).
pub const HISTORY_FRAMES: usize = 600;

/// A ring buffer of samples per series.
#[derive(Clone, Debug, Default)]
pub struct History {
    /// Series names (effector or joint names).
    pub names: Vec<String>,
    /// Simulated time of each kept frame, seconds.
    times: Vec<f64>,
    /// `values[s]` holds series `s`, aligned with `times`.
    values: Vec<Vec<f64>>,
    /// Index of the oldest sample once the buffer is full.
    start: usize,
}

impl History {
    /// Empty history for the named series.
    #[must_use]
    pub fn new(names: Vec<String>) -> Self {
        let values = vec![Vec::with_capacity(HISTORY_FRAMES); names.len()];
        Self {
            names,
            times: Vec::with_capacity(HISTORY_FRAMES),
            values,
            start: 0,
        }
    }

    /// Forgets every sample.
    pub fn clear(&mut self) {
        self.times.clear();
        for series in &mut self.values {
            series.clear();
        }
        self.start = 0;
    }

    /// Appends one frame: `time` and one value per series (missing values are
    /// NaN). A `time` before the newest kept one — the simulation restarted
    /// (a fall's or a blow-up's reset) — first forgets every sample, so a plot
    /// breaks cleanly instead of drawing a line back to the start.
    pub fn push(&mut self, time: f64, sample: impl Iterator<Item = f64>) {
        if self.newest_time().is_some_and(|newest| time < newest) {
            self.clear();
        }
        let mut sample = sample;
        if self.times.len() < HISTORY_FRAMES {
            self.times.push(time);
            for series in &mut self.values {
                series.push(sample.next().unwrap_or(f64::NAN));
            }
        } else {
            let at = self.start;
            self.times[at] = time;
            for series in &mut self.values {
                series[at] = sample.next().unwrap_or(f64::NAN);
            }
            self.start = (self.start + 1) % HISTORY_FRAMES;
        }
    }

    /// The newest sample's time (s).
    fn newest_time(&self) -> Option<f64> {
        let n = self.times.len();
        if n == 0 {
            return None;
        }
        let newest = if n < HISTORY_FRAMES {
            n - 1
        } else {
            (self.start + HISTORY_FRAMES - 1) % HISTORY_FRAMES
        };
        Some(self.times[newest])
    }

    /// The largest finite value of series `s` kept, if any.
    #[must_use]
    pub fn max_value(&self, s: usize) -> Option<f64> {
        self.values
            .get(s)?
            .iter()
            .copied()
            .filter(|v| v.is_finite())
            .reduce(f64::max)
    }

    /// Samples kept.
    #[must_use]
    pub fn len(&self) -> usize {
        self.times.len()
    }

    /// Whether no sample is kept.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.times.is_empty()
    }

    /// Series `s` as `[time, value]` points, oldest first.
    pub fn points(&self, s: usize) -> impl Iterator<Item = [f64; 2]> + '_ {
        let n = self.times.len();
        let start = if n < HISTORY_FRAMES { 0 } else { self.start };
        (0..n).map(move |k| {
            let i = (start + k) % n.max(1);
            [self.times[i], self.values[s][i]]
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_the_latest_frames_in_order() {
        let mut history = History::new(vec!["a".into(), "b".into()]);
        for f in 0..HISTORY_FRAMES + 10 {
            history.push(f as f64, [f as f64, -(f as f64)].into_iter());
        }
        assert_eq!(history.len(), HISTORY_FRAMES);
        let points: Vec<[f64; 2]> = history.points(1).collect();
        assert_eq!(points[0], [10.0, -10.0]);
        assert_eq!(
            points[HISTORY_FRAMES - 1],
            [(HISTORY_FRAMES + 9) as f64, -((HISTORY_FRAMES + 9) as f64)]
        );
        assert!(points.windows(2).all(|w| w[1][0] > w[0][0]));
    }

    #[test]
    fn a_restart_breaks_the_series_cleanly() {
        // Past the ring's wrap too: the newest sample is found where it is.
        for frames in [10, HISTORY_FRAMES + 25] {
            let mut history = History::new(vec!["a".into()]);
            for f in 0..frames {
                history.push(0.01 * f as f64, [1.0].into_iter());
            }
            // Same time again: kept (a paused step does not restart).
            let last = 0.01 * (frames - 1) as f64;
            history.push(last, [2.0].into_iter());
            assert_eq!(history.len(), (frames + 1).min(HISTORY_FRAMES));
            // The driver reset itself after a fall: time 0 again.
            history.push(0.0, [3.0].into_iter());
            history.push(0.01, [4.0].into_iter());
            let points: Vec<[f64; 2]> = history.points(0).collect();
            assert_eq!(points, vec![[0.0, 3.0], [0.01, 4.0]], "{frames} frames");
        }
    }
}
