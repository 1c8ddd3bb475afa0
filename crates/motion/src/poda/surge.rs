//! The body's fore-aft surge (Girard & Maciejewski 1985, "Horizontal
//! Control": "an additional backward acceleration during the restore
//! duration and forward acceleration during the push duration … to simulate
//! the effects of foot position with respect to the body at foot placement
//! and foot liftoff").
//!
//! The paper gives no magnitude; the lab derives it from the same leg force
//! as eq. 12–13. A supporting leg pushes along itself, from the foot to the
//! hip. With the foot under the hip at mid-stance and the body moving at `v`,
//! the foot is `v·τ` behind the hip `τ` seconds after mid-stance, so the
//! push's horizontal part is the vertical force times `v·τ / h` (`h` the
//! hip's height): backward before mid-stance (the restore), forward after
//! (the push). Leg `i` carries its share of the weight with the vertical
//! acceleration `F/m = a + g_n = g_n·P/S` (eq. 12–13, `g_n = g/n`), so its
//! fore-aft acceleration is
//!
//! `a_x(τ) = c·τ` for `|τ| ≤ S/2`, 0 in transfer, with `c = g_n·(P/S)·v/h`.
//!
//! Over a support `a_x` sums to zero, so the leg gives back the speed it took;
//! the body's mean speed stays the gait's (eq. 14–15's horizontal control
//! keeps it), and what remains is a periodic lag and catch-up. Its
//! displacement, with the mean speed and the mean position removed, is
//! [`surge_offset_m`]; the body's surge is the sum over its legs, as the
//! vertical motion is (eq. 12–13's superposition).

use super::gait::GaitParams;

/// One leg's fore-aft surge coefficient `c = g_n·(P/S)·v/h`, m/s³ (module
/// docs); 0 for non-finite or non-positive inputs.
#[must_use]
pub fn surge_coefficient(gait: &GaitParams, g_n: f64, hip_height_m: f64) -> f64 {
    let (period, support) = (gait.period_s(), gait.support_s());
    let c = g_n * period / support * gait.speed_mps() / hip_height_m;
    let ok = support > 0.0 && hip_height_m > 0.0 && g_n > 0.0;
    if ok && c.is_finite() { c } else { 0.0 }
}

/// One leg's fore-aft displacement at `tau_s` after its mid-stance, metres
/// forward (periodic in `S + T`): the double integral of `a_x = c·τ` over
/// the support `|τ| ≤ S/2` (0 in transfer), less its mean velocity and its
/// mean position over the period. With `h = S/2` and `P = S + T`:
/// velocity change in support `c·(τ² − h²)/2`, its period mean
/// `ū = −(2/3)·c·h³/P`, and the displacement
/// `X(τ) = c·[(τ³ + h³)/3 − h²·(τ + h)]/2 − ū·(τ + h) + c·h³·T/(3P)`
/// (the stance integral held at `−(2/3)·c·h³` through the transfer).
/// Returns 0 for non-finite input, `support_s ≤ 0` or `transfer_s < 0`.
#[must_use]
pub fn surge_offset_m(support_s: f64, transfer_s: f64, c: f64, tau_s: f64) -> f64 {
    let ok = support_s.is_finite()
        && support_s > 0.0
        && transfer_s.is_finite()
        && transfer_s >= 0.0
        && c.is_finite()
        && tau_s.is_finite();
    if !ok {
        return 0.0;
    }
    let (h, t) = (0.5 * support_s, transfer_s);
    let period = support_s + transfer_s;
    // τ into [−h, P − h).
    let x = (tau_s + h).rem_euclid(period) - h;
    let mean_velocity = -(2.0 / 3.0) * c * h * h * h / period;
    let stance = if x <= h {
        0.5 * c * ((x * x * x + h * h * h) / 3.0 - h * h * (x + h))
    } else {
        -(2.0 / 3.0) * c * h * h * h
    };
    stance - mean_velocity * (x + h) + c * h * h * h * t / (3.0 * period)
}

/// The body's fore-aft surge at `t_s`, metres forward: the sum of every
/// leg's [`surge_offset_m`] at its eq. 9 time since mid-stance, each with
/// the coefficient of [`surge_coefficient`] (no allocation).
#[must_use]
pub fn surge_superposition_m(gait: &GaitParams, t_s: f64, g_mps2: f64, hip_height_m: f64) -> f64 {
    let (support, transfer) = (gait.support_s(), gait.transfer_s());
    let c = surge_coefficient(gait, gait.gravity_share_mps2(g_mps2), hip_height_m);
    if c == 0.0 {
        return 0.0;
    }
    (0..gait.leg_count())
        .filter_map(|leg| gait.leg_phase(leg, t_s))
        .map(|p| surge_offset_m(support, transfer, c, p.state_s - 0.5 * support))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The displacement by integrating `a_x` numerically (midpoint rule) from
    /// the start of a support, with the mean velocity and position removed
    /// from the samples themselves: an independent computation.
    fn numeric(support_s: f64, transfer_s: f64, c: f64, samples: usize) -> Vec<(f64, f64)> {
        let h = 0.5 * support_s;
        let period = support_s + transfer_s;
        #[expect(clippy::cast_precision_loss, reason = "sample counts are small")]
        let dt = period / samples as f64;
        let mut v = Vec::with_capacity(samples);
        let mut speed = 0.0;
        for k in 0..samples {
            #[expect(clippy::cast_precision_loss, reason = "sample counts are small")]
            let tau = -h + (k as f64 + 0.5) * dt;
            let a = if tau <= h { c * tau } else { 0.0 };
            speed += a * dt;
            v.push((tau, speed - 0.5 * a * dt));
        }
        #[expect(clippy::cast_precision_loss, reason = "sample counts are small")]
        let n = samples as f64;
        let mean_v = v.iter().map(|s| s.1).sum::<f64>() / n;
        let mut x = 0.0;
        let mut out: Vec<(f64, f64)> = v
            .iter()
            .map(|&(tau, vel)| {
                x += (vel - mean_v) * dt;
                (tau, x - 0.5 * (vel - mean_v) * dt)
            })
            .collect();
        let mean_x = out.iter().map(|s| s.1).sum::<f64>() / n;
        for s in &mut out {
            s.1 -= mean_x;
        }
        out
    }

    #[test]
    fn the_closed_form_matches_numerical_integration() {
        for (support, transfer, c) in [(0.45, 0.15, 5.0), (0.3, 0.3, 12.0), (0.2, 0.6, 30.0)] {
            let worst = numeric(support, transfer, c, 20_000)
                .iter()
                .map(|&(tau, x)| (surge_offset_m(support, transfer, c, tau) - x).abs())
                .fold(0.0, f64::max);
            let scale = c * support.powi(3);
            assert!(worst < 1e-6 * scale, "{support} {transfer}: {worst}");
        }
    }

    #[test]
    fn the_surge_is_periodic_continuous_and_centred() {
        let (support, transfer, c) = (0.4, 0.2, 8.0);
        let period = support + transfer;
        let h = 0.5 * support;
        for tau in [-h, 0.0, h, 0.35] {
            let a = surge_offset_m(support, transfer, c, tau);
            let b = surge_offset_m(support, transfer, c, tau + period);
            assert!((a - b).abs() < 1e-12);
        }
        let (before, after) = (
            surge_offset_m(support, transfer, c, h - 1e-9),
            surge_offset_m(support, transfer, c, h + 1e-9),
        );
        assert!((before - after).abs() < 1e-9);
        let n = 10_000;
        let mean = (0..n)
            .map(|k| {
                surge_offset_m(
                    support,
                    transfer,
                    c,
                    -h + period * (f64::from(k) + 0.5) / f64::from(n),
                )
            })
            .sum::<f64>()
            / f64::from(n);
        assert!(mean.abs() < 1e-9, "{mean}");
        // The restore brakes and the push gives the speed back, so the leg's
        // body runs slowest at mid-stance and lags through the whole support;
        // it catches up while the leg is in transfer.
        let at = |tau: f64| surge_offset_m(support, transfer, c, tau);
        assert!(at(0.0) < at(-h) && at(h) < at(0.0));
        assert!(at(h + 0.5 * transfer) > at(h) && at(period - h) > at(h + 0.5 * transfer));
    }

    #[test]
    fn bad_inputs_give_no_surge() {
        assert_eq!(surge_offset_m(0.0, 0.2, 1.0, 0.1), 0.0);
        assert_eq!(surge_offset_m(0.3, -0.1, 1.0, 0.1), 0.0);
        assert_eq!(surge_offset_m(0.3, 0.2, f64::NAN, 0.1), 0.0);
        assert_eq!(surge_offset_m(0.3, 0.2, 1.0, f64::INFINITY), 0.0);
    }
}
