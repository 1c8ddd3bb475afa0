//! The Jacobian panel's probe: each figure's [`Spectrum`] and the traces of
//! the first figure's conditioning and iterations, kept between frames.

use std::collections::VecDeque;

use gaitlab_core::driver::Driver;
use gaitlab_core::ik::Spectrum;
use gaitlab_engine::AnyDriver;

/// Seconds of history the traces keep.
pub const TRACE_S: f64 = 5.0;

/// Most iterations the iteration trace keeps.
pub const MAX_TRACED_ITERATIONS: usize = 2000;

/// One frame's conditioning, for the traces over time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FramePoint {
    /// Simulated time, seconds.
    pub time_s: f64,
    /// The smallest singular value (0 when J is rank deficient), m/rad.
    pub sigma_min: f64,
    /// σ_max / σ_min (infinite when J is rank deficient).
    pub condition: f64,
}

/// One IK iteration, for the iteration trace.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IterationPoint {
    /// Simulated time of the frame it belongs to, seconds.
    pub time_s: f64,
    /// ‖Δθ‖ of its step.
    pub step_norm: f64,
    /// The largest effector error before it, metres.
    pub error_before_m: f64,
    /// The largest effector error after it (before the next iteration, or
    /// at the frame's end for its last), metres.
    pub error_after_m: f64,
}

/// The panel's figures, kept between frames.
#[derive(Clone, Debug, Default)]
pub struct JacobianProbe {
    spectra: Vec<Spectrum>,
    /// Per view, per direction: the gain the last iteration actually gave
    /// it, (vᵢ·Δθ)/(uᵢ·e); `None` where the error had no part along uᵢ.
    actual: Vec<Vec<Option<f64>>>,
    /// Whether each spectrum holds this frame's figures.
    valid: Vec<bool>,
    frames: VecDeque<FramePoint>,
    iterations: VecDeque<IterationPoint>,
    /// The time of the last frame traced (a reset shows as time going back).
    last_time_s: Option<f64>,
}

impl JacobianProbe {
    /// Reads this frame's figures from `drivers` (the single view, or each
    /// view of a comparison, in order). Drivers without a Jacobian (PODA,
    /// physics, a recording, CCD) leave their slot empty.
    pub fn update<'a>(&mut self, drivers: impl IntoIterator<Item = &'a AnyDriver>) {
        let mut count = 0;
        let mut first: Option<&AnyDriver> = None;
        for (i, driver) in drivers.into_iter().enumerate() {
            if i == 0 {
                first = Some(driver);
            }
            if self.spectra.len() <= i {
                self.spectra.push(Spectrum::default());
                self.actual.push(Vec::new());
                self.valid.push(false);
            }
            self.valid[i] = driver.ik_solver().is_some_and(|solver| {
                let size = solver.error().iter().map(|x| x * x).sum::<f64>().sqrt();
                // Before the first iteration J is all zeros: nothing to show yet.
                let valid = solver.spectrum(size, &mut self.spectra[i]).is_ok()
                    && self.spectra[i].law().is_some()
                    && !self.spectra[i].directions().is_empty();
                if valid {
                    actual_gains(
                        &self.spectra[i],
                        solver.error(),
                        solver.last_step(),
                        &mut self.actual[i],
                    );
                }
                valid
            });
            count = i + 1;
        }
        self.valid[count..].fill(false);
        if let Some(driver) = first {
            self.trace(driver, 0);
        }
    }

    /// Adds view `i`'s frame to the traces.
    fn trace(&mut self, driver: &AnyDriver, i: usize) {
        let time_s = driver.time();
        if self.last_time_s.is_some_and(|t| time_s < t) {
            self.frames.clear();
            self.iterations.clear();
        }
        let Some(spectrum) = self.spectrum(i) else {
            return;
        };
        let (sigma_min, condition) = (
            if spectrum.zero_count() > 0 {
                0.0
            } else {
                spectrum.directions().last().map_or(0.0, |d| d.sigma)
            },
            spectrum.condition().unwrap_or(f64::INFINITY),
        );
        let point = FramePoint {
            time_s,
            sigma_min,
            condition,
        };
        if self.last_time_s == Some(time_s) {
            // Another iteration of the same frame: replace, do not repeat.
            self.frames.pop_back();
        }
        self.last_time_s = Some(time_s);
        push_bounded(&mut self.frames, point, usize::MAX);
        while self
            .frames
            .front()
            .is_some_and(|p| p.time_s < time_s - TRACE_S)
        {
            self.frames.pop_front();
        }
        // The frame's iterations: replace any of this frame already traced.
        while self.iterations.back().is_some_and(|p| p.time_s == time_s) {
            self.iterations.pop_back();
        }
        let log = driver.iteration_log();
        let end = driver.ik_report().map_or(f64::NAN, |r| r.max_error_m);
        for (k, record) in log.iter().enumerate() {
            let after = log.get(k + 1).map_or(end, |next| next.error_before_m);
            push_bounded(
                &mut self.iterations,
                IterationPoint {
                    time_s,
                    step_norm: record.step_norm,
                    error_before_m: record.error_before_m,
                    error_after_m: after,
                },
                MAX_TRACED_ITERATIONS,
            );
        }
        while self
            .iterations
            .front()
            .is_some_and(|p| p.time_s < time_s - TRACE_S)
        {
            self.iterations.pop_front();
        }
    }

    /// View `i`'s spectrum this frame, when it has a Jacobian.
    #[must_use]
    pub fn spectrum(&self, i: usize) -> Option<&Spectrum> {
        (*self.valid.get(i)?).then(|| &self.spectra[i])
    }

    /// The gain the last iteration of view `i` actually gave each direction,
    /// (vᵢ·Δθ)/(uᵢ·e), in [`Spectrum::directions`]' order (`None` where the
    /// error had no part along uᵢ).
    #[must_use]
    pub fn actual_gains(&self, i: usize) -> Option<&[Option<f64>]> {
        self.spectrum(i)?;
        self.actual.get(i).map(Vec::as_slice)
    }

    /// The smallest σ and the condition number, frame by frame, oldest first.
    pub fn frames(&self) -> impl ExactSizeIterator<Item = &FramePoint> {
        self.frames.iter()
    }

    /// Each iteration's ‖Δθ‖ and errors, oldest first.
    pub fn iterations(&self) -> impl ExactSizeIterator<Item = &IterationPoint> {
        self.iterations.iter()
    }

    /// Forgets the traces (a new preset or a reset).
    pub fn clear(&mut self) {
        self.frames.clear();
        self.iterations.clear();
        self.valid.fill(false);
        self.last_time_s = None;
    }
}

/// Each direction's measured gain: the step's part along vᵢ over the
/// error's part along uᵢ, where the error has a part along uᵢ (above 1e-6 of
/// its length).
fn actual_gains(spectrum: &Spectrum, error: &[f64], step: &[f64], out: &mut Vec<Option<f64>>) {
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let size = dot(error, error).sqrt();
    out.clear();
    for k in 0..spectrum.directions().len() {
        let (Some(u), Some(v)) = (spectrum.u(k), spectrum.v(k)) else {
            out.push(None);
            continue;
        };
        let along = dot(u, error);
        out.push((along.abs() > 1e-6 * size && size > 0.0).then(|| dot(v, step) / along));
    }
}

/// Appends `point`, dropping the oldest beyond `most`.
fn push_bounded<T>(queue: &mut VecDeque<T>, point: T, most: usize) {
    if queue.len() >= most {
        queue.pop_front();
    }
    queue.push_back(point);
}
