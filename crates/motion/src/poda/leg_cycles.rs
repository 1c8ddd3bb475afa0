//! Leg-by-leg gait changes (Girard & Maciejewski 1985, "Vertical Control":
//! changes of the gait's parameters are taken on "by adjusting the related
//! dynamic parameters for each leg's contribution independently at the
//! beginning of its upward pushing phase", and legs shift phase "by varying
//! the distribution of vertical pushing forces among them").
//!
//! Each leg runs cycles from one mid-stance to the next: it pushes for
//! `push_s` (the second half of its support), falls for `transfer_s`, and
//! restores for `restore_s` (the first half of its next support). At a
//! mid-stance the leg reads the gait's present values and fixes its next
//! cycle:
//! - the half support of its next support (both halves: every support is
//!   centred on its mid-stance, so a planted foot lifts when eq. 11 planned):
//!   `β·P/2`, lengthened by at most [`RATE`] of the last one (shortened at
//!   once: a shorter support never outreaches the legs);
//! - its nominal transfer, moving toward `(1 − β)·P` by at most [`RATE`];
//! - its phase correction: the transfer is lengthened by how far the leg is
//!   ahead of the other legs (each leg `j` puts the gait's phase at
//!   `β/2 − R_j` plus the part of its cycle elapsed; their circular mean),
//!   within [`CORRECTION`] of the nominal transfer.
//!
//! Only phases relative to each other are corrected, so a new period alone
//! shifts no leg. The rates are the lab's: eq. 12–13's legs cancel each
//! other's push only in a steady gait, and the faster legs leave it, the
//! further the superposition swings (the sweep in docs/poda.md measured
//! them). In a steady gait the cycles are eq. 9's.
//!
//! The vertical motion of a cycle (eq. 12–13): the push accelerates the
//! body from rest to `u₁`, it flies under `g_n` for the transfer and lands at
//! `−u₂`, and the restore brings it to rest at the next mid-stance. The
//! flight ties `u₁ + u₂ = g_n·T`; asking the cycle to end at the height it
//! started gives `u₁ = g_n·T·(T + h₂)/(h₁ + 2T + h₂)` (push `h₁`, restore
//! `h₂`). For `h₁ = h₂ = S/2` this is eq. 13's `a = g_n·T/S`.

use super::gait::{GaitParams, LegPhase};
use super::surge::surge_offset_m;
use gaitlab_core::portable::Portable;

/// Largest change of a leg's nominal transfer, and largest lengthening of its
/// half support, from one cycle to the next, as a fraction of the last.
pub const RATE: f64 = 0.2;
/// Largest phase correction of a transfer, as a fraction of its nominal length.
pub const CORRECTION: f64 = 0.5;
/// Below this mean resultant length the legs' phases have no circular mean
/// to correct toward.
const MIN_RESULTANT: f64 = 0.25;
/// A cycle matches the gait within this, seconds.
const STEADY_S: f64 = 1e-6;
/// Most cycles a query walks ahead of the stored ones.
const MAX_AHEAD: usize = 64;

/// One leg's cycle from a mid-stance to the next; times absolute, seconds.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LegCycle {
    /// The mid-stance that starts the cycle.
    pub mid_s: f64,
    /// Push: mid-stance to lift-off (half the current support).
    pub push_s: f64,
    /// Transfer: lift-off to touchdown.
    pub transfer_s: f64,
    /// Restore: touchdown to the next mid-stance (half the next support).
    pub restore_s: f64,
    /// The transfer before the phase correction (its flight's share of the
    /// change from one gait to the next), seconds.
    pub nominal_s: f64,
}

impl LegCycle {
    /// Lift-off.
    #[must_use]
    pub fn liftoff_s(&self) -> f64 {
        self.mid_s + self.push_s
    }

    /// Touchdown.
    #[must_use]
    pub fn touchdown_s(&self) -> f64 {
        self.liftoff_s() + self.transfer_s
    }

    /// The next mid-stance, where the cycle ends.
    #[must_use]
    pub fn end_s(&self) -> f64 {
        self.touchdown_s() + self.restore_s
    }

    /// Lift-off and landing speeds `(u₁, u₂)` of the leg's contribution,
    /// m/s, that close the cycle (module docs).
    fn speeds(&self, g_n: f64) -> (f64, f64) {
        let (h1, t, h2) = (self.push_s, self.transfer_s, self.restore_s);
        let d = h1 + 2.0 * t + h2;
        if !(t > 0.0 && d > 0.0) {
            return (0.0, 0.0);
        }
        let u1 = g_n * t * (t + h2) / d;
        (u1, g_n * t - u1)
    }

    /// The leg's vertical contribution at `t_s` in this cycle, metres above
    /// its mid-stance level (0 at both mid-stances; eq. 12–13).
    #[must_use]
    pub fn vertical_m(&self, g_n: f64, t_s: f64) -> f64 {
        let (u1, u2) = self.speeds(g_n);
        let tau = (t_s - self.mid_s).clamp(0.0, self.end_s() - self.mid_s);
        if tau <= self.push_s {
            if self.push_s > 0.0 {
                0.5 * u1 / self.push_s * tau * tau
            } else {
                0.0
            }
        } else if tau <= self.push_s + self.transfer_s {
            let f = tau - self.push_s;
            0.5 * u1 * self.push_s + u1 * f - 0.5 * g_n * f * f
        } else {
            let r = self.end_s() - t_s;
            if self.restore_s > 0.0 {
                0.5 * u2 / self.restore_s * r * r
            } else {
                0.0
            }
        }
    }

    /// Whether the cycle is a steady cycle of `gait`.
    fn is_steady(&self, gait: &GaitParams) -> bool {
        let half = 0.5 * gait.support_s();
        (self.push_s - half).abs() < STEADY_S
            && (self.restore_s - half).abs() < STEADY_S
            && (self.transfer_s - gait.transfer_s()).abs() < STEADY_S
            && (self.nominal_s - gait.transfer_s()).abs() < STEADY_S
    }
}

/// `x` wrapped into `[−½, ½)`; 0 when not finite.
fn wrap_half(x: f64) -> f64 {
    let r = (x + 0.5).rem_euclid(1.0) - 0.5;
    if r.is_finite() { r } else { 0.0 }
}

/// Every leg's cycles and the gait's phase (module docs).
#[derive(Clone, Debug, Default)]
pub struct LegCycles {
    previous: Vec<LegCycle>,
    current: Vec<LegCycle>,
    /// Each leg's next cycle as the gait's values at the last
    /// [`LegCycles::advance_to`] predict it.
    next: Vec<LegCycle>,
}

impl LegCycles {
    /// Cycles taking over from eq. 9 at `t_s`: each leg's steady cycle
    /// holding `t_s` and the one before it, with `φ(t) = t/P`.
    pub fn start(&mut self, gait: &GaitParams, t_s: f64) {
        let period = gait.period_s();
        let half = 0.5 * gait.support_s();
        self.previous.clear();
        self.current.clear();
        self.next.clear();
        for leg in 0..gait.leg_count() {
            let since_mid = gait
                .leg_phase(leg, t_s)
                .map_or(0.0, |p| (p.state_s - half).rem_euclid(period));
            let cycle = LegCycle {
                mid_s: t_s - since_mid,
                push_s: half,
                transfer_s: gait.transfer_s(),
                restore_s: half,
                nominal_s: gait.transfer_s(),
            };
            self.current.push(cycle);
            self.previous.push(LegCycle {
                mid_s: cycle.mid_s - period,
                ..cycle
            });
            self.next.push(LegCycle {
                mid_s: cycle.mid_s + period,
                ..cycle
            });
        }
    }

    /// The cycle `leg` starts where `cycle` ends, with the gait's values.
    fn next_cycle(&self, leg: usize, cycle: &LegCycle, gait: &GaitParams) -> LegCycle {
        let mid = cycle.end_s();
        let period = gait.period_s();
        let push = cycle.restore_s;
        let (low, high) = (1.0 - RATE, 1.0 + RATE);
        // A support may shorten at once (a shorter support never outreaches
        // the legs), lengthen by `RATE` a cycle.
        let half = (0.5 * gait.support_s()).min(push * high);
        let nominal = gait
            .transfer_s()
            .clamp(cycle.nominal_s * low, cycle.nominal_s * high);
        let lead = self.phase_lead(leg, mid, gait);
        let transfer = (nominal + lead * period)
            .clamp((1.0 - CORRECTION) * nominal, (1.0 + CORRECTION) * nominal);
        LegCycle {
            mid_s: mid,
            push_s: push,
            transfer_s: transfer,
            restore_s: half,
            nominal_s: nominal,
        }
    }

    /// How far `leg`, at its mid-stance `t_s`, is ahead of the other legs'
    /// phase, cycles in `[−½, ½)`: each leg `j` puts the gait's phase at
    /// `β/2 − R_j` plus the fraction of its stored cycle elapsed at `t_s`
    /// (extrapolated past its end), and the legs' phase is the circular
    /// mean. Only the legs' phases relative to each other are corrected, so a
    /// change of period alone shifts no leg.
    fn phase_lead(&self, leg: usize, t_s: f64, gait: &GaitParams) -> f64 {
        let duty = gait.duty_factor();
        let implied = |j: usize| {
            let c = self.current[j];
            let r = gait.phases().get(j).copied().unwrap_or(0.0);
            let length = c.end_s() - c.mid_s;
            let elapsed = if length > 0.0 {
                (t_s - c.mid_s) / length
            } else {
                0.0
            };
            0.5 * duty - r + elapsed
        };
        let own = 0.5 * duty - gait.phases().get(leg).copied().unwrap_or(0.0);
        let (mut sin, mut cos) = (0.0, 0.0);
        for j in 0..self.current.len() {
            let (s, c) = (std::f64::consts::TAU * (implied(j) - own)).psin_cos();
            sin += s;
            cos += c;
        }
        #[expect(clippy::cast_precision_loss, reason = "leg count ≤ 32")]
        let n = self.current.len().max(1) as f64;
        if sin.phypot(cos) < MIN_RESULTANT * n {
            // The legs' phases spread evenly round the circle (a trot's pairs
            // half a cycle from where a pace wants them): no mean to go by;
            // the first leg sets the phase.
            if self.current.is_empty() {
                return 0.0;
            }
            return wrap_half(own - implied(0));
        }
        // The mean of the others relative to this leg; this leg leads by its negative.
        wrap_half(-sin.patan2(cos) / std::f64::consts::TAU)
    }

    /// Moves every leg to its cycle holding `t_s`, fixing each cycle at its
    /// mid-stance with the gait's values then.
    pub fn advance_to(&mut self, t_s: f64, gait: &GaitParams) {
        if !t_s.is_finite() {
            return;
        }
        for leg in 0..self.current.len() {
            let mut steps = 0;
            while self.current[leg].end_s() <= t_s && steps < MAX_AHEAD {
                let next = self.next_cycle(leg, &self.current[leg], gait);
                self.previous[leg] = self.current[leg];
                self.current[leg] = next;
                steps += 1;
            }
        }
        for leg in 0..self.current.len() {
            self.next[leg] = self.next_cycle(leg, &self.current[leg], gait);
        }
    }

    /// `leg`'s cycle holding `t_s`: the stored ones, later ones predicted
    /// with the gait's present values (no allocation).
    #[must_use]
    pub fn cycle_at(&self, leg: usize, t_s: f64, gait: &GaitParams) -> Option<LegCycle> {
        let current = *self.current.get(leg)?;
        if t_s < current.mid_s {
            return self.previous.get(leg).copied();
        }
        if t_s < current.end_s() {
            return Some(current);
        }
        let mut cycle = *self.next.get(leg)?;
        let mut steps = 0;
        while cycle.end_s() <= t_s && steps < MAX_AHEAD {
            cycle = self.next_cycle(leg, &cycle, gait);
            steps += 1;
        }
        Some(cycle)
    }

    /// `leg`'s state at `t_s` (after [`LegCycles::advance_to`] `t_s`), in
    /// eq. 9's terms; `state_s` is the time since the last touchdown.
    #[must_use]
    pub fn leg_phase(&self, leg: usize, t_s: f64, gait: &GaitParams) -> Option<LegPhase> {
        let c = self.cycle_at(leg, t_s, gait)?;
        let before = self.cycle_before(leg, &c);
        let fraction = |elapsed: f64, length: f64| {
            if length > 0.0 {
                (elapsed / length).clamp(0.0, 1.0 - f64::EPSILON)
            } else {
                0.0
            }
        };
        let after_liftoff = c.end_s() + c.restore_s;
        let phase = if t_s < c.liftoff_s() {
            let touchdown = c.mid_s - c.push_s;
            LegPhase {
                support: true,
                state_s: t_s - touchdown,
                fraction: fraction(t_s - touchdown, 2.0 * c.push_s),
                last_touchdown_s: touchdown,
                last_liftoff_s: before.map_or(touchdown - c.transfer_s, |b| b.liftoff_s()),
                next_touchdown_s: c.touchdown_s(),
                next_liftoff_s: c.liftoff_s(),
            }
        } else if t_s < c.touchdown_s() {
            let touchdown = c.mid_s - c.push_s;
            LegPhase {
                support: false,
                state_s: t_s - touchdown,
                fraction: fraction(t_s - c.liftoff_s(), c.transfer_s),
                last_touchdown_s: touchdown,
                last_liftoff_s: c.liftoff_s(),
                next_touchdown_s: c.touchdown_s(),
                next_liftoff_s: after_liftoff,
            }
        } else {
            let next = match self.current.get(leg) {
                Some(current) if *current == c => self.next.get(leg).copied().unwrap_or(c),
                _ => self.next_cycle(leg, &c, gait),
            };
            LegPhase {
                support: true,
                state_s: t_s - c.touchdown_s(),
                fraction: fraction(t_s - c.touchdown_s(), 2.0 * c.restore_s),
                last_touchdown_s: c.touchdown_s(),
                last_liftoff_s: c.liftoff_s(),
                next_touchdown_s: next.touchdown_s(),
                next_liftoff_s: after_liftoff,
            }
        };
        Some(phase)
    }

    /// The stored cycle before `c`, if `c` is a stored one.
    fn cycle_before(&self, leg: usize, c: &LegCycle) -> Option<LegCycle> {
        let current = self.current.get(leg)?;
        if c == current {
            self.previous.get(leg).copied()
        } else {
            None
        }
    }

    /// `leg`'s vertical contribution at `t_s`, metres (module docs).
    #[must_use]
    pub fn vertical_m(&self, leg: usize, t_s: f64, gait: &GaitParams, g_n: f64) -> f64 {
        self.cycle_at(leg, t_s, gait)
            .map_or(0.0, |c| c.vertical_m(g_n, t_s))
    }

    /// The legs' vertical contributions at `t_s` summed, and summed with
    /// `weights` (the body's pitch slope; eq. 12–13's superposition).
    #[must_use]
    pub fn vertical_sums_m(
        &self,
        t_s: f64,
        gait: &GaitParams,
        g_n: f64,
        weights: &[f64],
    ) -> (f64, f64) {
        let (mut sum, mut weighted) = (0.0, 0.0);
        for leg in 0..self.current.len() {
            let y = self.vertical_m(leg, t_s, gait, g_n);
            sum += y;
            weighted += weights.get(leg).copied().unwrap_or(0.0) * y;
        }
        (sum, weighted)
    }

    /// The mean of the summed vertical contributions over the legs'
    /// supports in `[t_s, t_s + P)`, sampled `samples` times: the constant
    /// that stands the body at its standing height while its feet are down.
    #[must_use]
    pub fn vertical_centre_m(&self, t_s: f64, gait: &GaitParams, g_n: f64, samples: u32) -> f64 {
        let period = gait.period_s();
        let (mut sum, mut count) = (0.0, 0u32);
        for k in 0..samples {
            let t = t_s + period * (f64::from(k) + 0.5) / f64::from(samples);
            let (height, _) = self.vertical_sums_m(t, gait, g_n, &[]);
            for leg in 0..self.current.len() {
                if self.leg_phase(leg, t, gait).is_some_and(|p| p.support) {
                    sum += height;
                    count += 1;
                }
            }
        }
        if count > 0 {
            sum / f64::from(count)
        } else {
            0.0
        }
    }

    /// The legs' fore-aft surge at `t_s` summed, metres
    /// ([`super::surge::surge_offset_m`] over each leg's own cycle, with
    /// coefficient `c`): exact in a steady gait, within a cycle's change
    /// while one is being taken on.
    #[must_use]
    pub fn surge_m(&self, t_s: f64, gait: &GaitParams, c: f64) -> f64 {
        (0..self.current.len())
            .filter_map(|leg| self.cycle_at(leg, t_s, gait))
            .map(|cycle| {
                let support = cycle.push_s + cycle.restore_s;
                surge_offset_m(support, cycle.transfer_s, c, t_s - cycle.mid_s)
            })
            .sum()
    }

    /// `leg`'s latest mid-stance at or before `t_s`, seconds.
    #[must_use]
    pub fn mid_stance_s(&self, leg: usize, t_s: f64, gait: &GaitParams) -> Option<f64> {
        self.cycle_at(leg, t_s, gait).map(|c| c.mid_s)
    }

    /// Whether every leg's cycle holding `t_s` and its next are the gait's
    /// steady ones on eq. 9's phase (a change has been taken on).
    #[must_use]
    pub fn is_steady(&self, t_s: f64, gait: &GaitParams) -> bool {
        (0..self.current.len()).all(|leg| {
            self.cycle_at(leg, t_s, gait).is_some_and(|c| {
                let next = self.next_cycle(leg, &c, gait);
                c.is_steady(gait) && next.is_steady(gait)
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poda::gait::vertical_offset_m;
    use crate::poda::gaits::named_gait;

    fn gait(name: &str, period_s: f64) -> GaitParams {
        let (phases, duty) = named_gait(name, 4).expect("gait");
        GaitParams::new(period_s, duty, phases, 1.0).expect("valid")
    }

    #[test]
    fn steady_cycles_are_eq_9() {
        let g = gait("walk", 1.2);
        let mut cycles = LegCycles::default();
        cycles.start(&g, 0.37);
        for k in 0..600 {
            let t = 0.37 + f64::from(k) * 0.013;
            cycles.advance_to(t, &g);
            for leg in 0..4 {
                let s = cycles.leg_phase(leg, t, &g).expect("leg");
                let p = g.leg_phase(leg, t).expect("leg");
                let at_edge = [
                    p.last_touchdown_s,
                    p.last_liftoff_s,
                    p.next_touchdown_s,
                    p.next_liftoff_s,
                ]
                .iter()
                .any(|e| (t - e).abs() < 1e-9);
                if at_edge {
                    continue;
                }
                assert_eq!(s.support, p.support, "leg {leg} at {t}");
                assert!((s.last_touchdown_s - p.last_touchdown_s).abs() < 1e-9);
                assert!((s.last_liftoff_s - p.last_liftoff_s).abs() < 1e-9);
                assert!((s.fraction - p.fraction).abs() < 1e-9);
                let expected = vertical_offset_m(
                    g.support_s(),
                    g.transfer_s(),
                    2.0,
                    p.state_s - 0.5 * g.support_s(),
                );
                assert!((cycles.vertical_m(leg, t, &g, 2.0) - expected).abs() < 1e-9);
            }
            assert!(cycles.is_steady(t, &g));
        }
    }

    #[test]
    fn an_uneven_cycle_closes_with_continuous_height() {
        let c = LegCycle {
            mid_s: 1.0,
            push_s: 0.1,
            transfer_s: 0.5,
            restore_s: 0.3,
            nominal_s: 0.5,
        };
        let g_n = 2.45;
        assert!(c.vertical_m(g_n, c.mid_s).abs() < 1e-15);
        assert!(c.vertical_m(g_n, c.end_s()).abs() < 1e-12);
        for t in [c.liftoff_s(), c.touchdown_s()] {
            let (a, b) = (c.vertical_m(g_n, t - 1e-9), c.vertical_m(g_n, t + 1e-9));
            assert!((a - b).abs() < 1e-8, "{t}: {a} {b}");
        }
        // The flight's speeds add to g_n·T.
        let (u1, u2) = c.speeds(g_n);
        assert!((u1 + u2 - g_n * 0.5).abs() < 1e-12);
    }

    #[test]
    fn a_switch_is_taken_on_at_each_legs_mid_stance_and_supports_keep_their_length() {
        let mut g = gait("transverse_gallop", 0.6);
        let mut cycles = LegCycles::default();
        cycles.start(&g, 2.0);
        let before: Vec<LegCycle> = (0..4)
            .map(|leg| cycles.cycle_at(leg, 2.0, &g).expect("leg"))
            .collect();
        let old_duty = g.duty_factor();
        let (phases, duty) = named_gait("walk", 4).expect("walk");
        g.set_shape(&phases, duty).expect("walk fits");
        for (leg, cycle) in before.iter().enumerate() {
            assert_eq!(
                cycles.cycle_at(leg, 2.0, &g),
                Some(*cycle),
                "cycles under way stay"
            );
        }
        let mut t = 2.0;
        while t < 12.0 {
            t += 1.0 / 120.0;
            cycles.advance_to(t, &g);
            for leg in 0..4 {
                let c = cycles.cycle_at(leg, t, &g).expect("leg");
                // A support is centred on its mid-stance; its half moves
                // from the gallop's to the walk's by at most `rate` a cycle.
                let old_half = 0.5 * 0.6 * old_duty;
                let new_half = 0.5 * g.support_s();
                assert!(c.push_s >= old_half - 1e-12 && c.push_s <= new_half + 1e-12);
                assert!(c.restore_s <= c.push_s * (1.0 + RATE) + 1e-12);
            }
        }
        assert!(cycles.is_steady(t, &g));
        // The walk's phases, relative to leg 0's mid-stance.
        let mid0 = cycles.cycle_at(0, t, &g).expect("leg").mid_s;
        for leg in 1..4 {
            let mid = cycles.cycle_at(leg, t, &g).expect("leg").mid_s;
            let relative = wrap_half((mid - mid0) / g.period_s() + phases[leg] - phases[0]);
            assert!(relative.abs() < 1e-6, "leg {leg}: {relative}");
        }
    }

    #[test]
    fn a_new_period_alone_shifts_no_leg() {
        let mut g = gait("trot", 1.0);
        let mut cycles = LegCycles::default();
        cycles.start(&g, 2.3);
        g.set_period(0.7).expect("faster");
        let mut t = 2.3;
        while t < 12.0 {
            t += 0.01;
            cycles.advance_to(t, &g);
            // The diagonal pairs stay together all the way.
            for (a, b) in [(0, 3), (1, 2)] {
                let (ca, cb) = (
                    cycles.cycle_at(a, t, &g).expect("leg"),
                    cycles.cycle_at(b, t, &g).expect("leg"),
                );
                assert!((ca.mid_s - cb.mid_s).abs() < 1e-9);
                assert!((ca.transfer_s - cb.transfer_s).abs() < 1e-9);
            }
        }
        assert!(cycles.is_steady(t, &g));
    }
}
