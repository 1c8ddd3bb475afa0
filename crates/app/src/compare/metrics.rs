//! One comparison view's running figures: joint-velocity jitter (mean
//! |Δ²θ| over a window), limit hits, wall time and IK iterations.
//! Allocation-free per frame.

use gaitlab_core::Skeleton;

/// Frames in the jitter window (4 s at 60 fps).
pub const JITTER_WINDOW_FRAMES: usize = 240;

/// One view's running figures. Allocation-free per frame.
#[derive(Clone, Debug, Default)]
pub struct ViewMetrics {
    /// Joint values one and two frames ago.
    previous: Vec<f64>,
    before_previous: Vec<f64>,
    /// Frames seen since the reset (the first two give no Δ²θ).
    pub(super) frames: u64,
    /// mean_j |Δ²θⱼ| of the recent frames, rad per frame² (ring buffer).
    jitter: Vec<f64>,
    jitter_next: usize,
    /// Whether each joint sat on a limit last frame.
    at_limit: Vec<bool>,
    /// Times a joint arrived at one of its limits since the reset.
    pub limit_hits: u64,
    /// Wall time spent in this view's driver, µs.
    pub wall_us: f64,
    /// IK iterations run.
    pub iterations: u64,
}

impl ViewMetrics {
    pub(super) fn new(joints: usize) -> Self {
        Self {
            previous: vec![0.0; joints],
            before_previous: vec![0.0; joints],
            jitter: Vec::with_capacity(JITTER_WINDOW_FRAMES),
            at_limit: vec![false; joints],
            ..Self::default()
        }
    }

    pub(super) fn record(&mut self, skeleton: &Skeleton, values: &[f64]) {
        if self.frames >= 2 {
            let n = values.len().max(1) as f64;
            let sum: f64 = values
                .iter()
                .zip(&self.previous)
                .zip(&self.before_previous)
                .map(|((x, p), b)| (x - 2.0 * p + b).abs())
                .sum();
            let jitter = sum / n;
            if self.jitter.len() < JITTER_WINDOW_FRAMES {
                self.jitter.push(jitter);
            } else {
                self.jitter[self.jitter_next] = jitter;
            }
            self.jitter_next = (self.jitter_next + 1) % JITTER_WINDOW_FRAMES;
        }
        for ((value, joint), at) in values.iter().zip(skeleton.joints()).zip(&mut self.at_limit) {
            let now = joint
                .limits
                .is_some_and(|(lo, hi)| *value <= lo + 1e-9 || *value >= hi - 1e-9);
            if now && !*at && self.frames > 0 {
                self.limit_hits += 1;
            }
            *at = now;
        }
        self.before_previous.copy_from_slice(&self.previous);
        self.previous.copy_from_slice(values);
        self.frames += 1;
    }

    /// Mean |Δ²θ| over the joints and the last [`JITTER_WINDOW_FRAMES`]
    /// frames, radians per frame² (0 before three frames).
    #[must_use]
    pub fn jitter_rad(&self) -> f64 {
        if self.jitter.is_empty() {
            0.0
        } else {
            self.jitter.iter().sum::<f64>() / self.jitter.len() as f64
        }
    }

    /// Wall time per IK iteration, µs (0 without a clock).
    #[must_use]
    pub fn us_per_iteration(&self) -> f64 {
        if self.iterations == 0 {
            0.0
        } else {
            self.wall_us / self.iterations as f64
        }
    }
}
