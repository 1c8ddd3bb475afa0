//! PODA gait model (Girard & Maciejewski 1985): period, duty factor, stroke and speed tied by
//! eq. 7–8, each leg's support/transfer state by eq. 9, and per-leg vertical hops by eq. 12–13.
//!
//! [`GaitParams`] keeps three canonical values — period `P`, duty factor `β` and body speed `v` —
//! plus one relative phase `R_i ∈ [0, 1)` per leg. Everything else is derived so the relations
//! always hold: `support_s = β·P`, `transfer_s = P − support_s` (eq. 8) and
//! `stroke_m = v·support_s` (eq. 7). Every edit says which quantities it recomputed
//! ([`Derived`]) and is rejected, leaving the state unchanged, if a derived value would leave
//! its range. Range checks on derived values allow a relative rounding slack of 1e-12.
//!
//! Vertical dynamics (eq. 12–13) treat each leg as a one-legged hopper carrying its share of the
//! weight, `g_n = g / leg_count`; superposing the legs' ballistic contributions gives the body's
//! vertical motion (PODA's "decomposition by leg").

use serde::{Deserialize, Serialize};
use std::ops::RangeInclusive;

use gaitlab_core::preset as table;

/// Allowed gait cycle period `P`, seconds (PODA's parameter table).
pub const PERIOD_RANGE_S: RangeInclusive<f64> = table::PERIOD_RANGE_S.0..=table::PERIOD_RANGE_S.1;
/// Allowed duty factor `β` (fraction of the period a leg is on the ground).
pub const DUTY_FACTOR_RANGE: RangeInclusive<f64> =
    table::DUTY_FACTOR_RANGE.0..=table::DUTY_FACTOR_RANGE.1;
/// Allowed body speed `v`, metres per second.
pub const SPEED_RANGE_MPS: RangeInclusive<f64> =
    table::SPEED_RANGE_MPS.0..=table::SPEED_RANGE_MPS.1;
/// Allowed stroke (body travel during one support duration), metres.
pub const STROKE_RANGE_M: RangeInclusive<f64> = table::STROKE_RANGE_M.0..=table::STROKE_RANGE_M.1;
/// Allowed number of legs.
pub const LEG_COUNT_RANGE: RangeInclusive<usize> = 1..=32;

/// Relative slack for range checks on derived (rounded) values.
const DERIVED_SLACK: f64 = 1e-12;
/// The largest `f64` below 1.
const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;

/// Why a gait value was rejected: the field (`duty_factor`, `phases[2]`) and
/// the reason, shown as `path: reason` (the crate's [`DriverError`](crate::DriverError)).
pub type GaitError = crate::DriverError;

/// What an edit changed: the quantity set and the quantities recomputed from it (field names),
/// so a UI can say which values were derived.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Derived {
    /// The quantity the caller set, e.g. `speed_mps`.
    pub edited: &'static str,
    /// The quantities recomputed to keep eq. 7–8 true, e.g. `["support_s", "period_s"]`.
    pub derived: &'static [&'static str],
}

impl Derived {
    /// What an edit of `edited` derived.
    #[must_use]
    pub const fn new(edited: &'static str, derived: &'static [&'static str]) -> Self {
        Self { edited, derived }
    }

    /// Whether `name` was recomputed by the edit.
    #[must_use]
    pub fn contains(&self, name: &str) -> bool {
        self.derived.contains(&name)
    }
}

/// Wraps a relative phase into `[0, 1)` (non-finite input gives 0).
#[must_use]
pub fn normalise_phase(phase: f64) -> f64 {
    wrap(phase, 1.0)
}

/// `x mod period` in `[0, period)` (`rem_euclid` can round up to `period`); 0 if not finite.
fn wrap(x: f64, period: f64) -> f64 {
    let r = x.rem_euclid(period);
    if r.is_finite() && r < period {
        r + 0.0
    } else {
        0.0
    }
}

/// A candidate `(period_s, duty_factor, speed_mps)`, the canonical state.
type State = (f64, f64, f64);

const SUPPORT_TRANSFER_STROKE: &[&str] = &["support_s", "transfer_s", "stroke_m"];
const SUPPORT_PERIOD_TRANSFER: &[&str] = &["support_s", "period_s", "transfer_s"];
const EDIT_PERIOD: Derived = Derived::new("period_s", SUPPORT_TRANSFER_STROKE);
const EDIT_DUTY: Derived = Derived::new("duty_factor", SUPPORT_TRANSFER_STROKE);
const EDIT_SPEED: Derived = Derived::new("speed_mps", SUPPORT_PERIOD_TRANSFER);
const EDIT_STROKE: Derived = Derived::new("stroke_m", SUPPORT_PERIOD_TRANSFER);
const EDIT_SUPPORT: Derived = Derived::new("support_s", &["duty_factor", "transfer_s", "stroke_m"]);
const EDIT_TRANSFER: Derived = Derived::new("transfer_s", &["period_s", "duty_factor"]);
const EDIT_FORCE: Derived = Derived::new("force_n", &["transfer_s", "period_s", "duty_factor"]);
const EDIT_PHASE: Derived = Derived::new("phases", &[]);

/// The serialised form of [`GaitParams`]; deserialising
/// validates it with [`GaitParams::new`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GaitSpec {
    /// Gait cycle period `P`, seconds.
    pub period_s: f64,
    /// Duty factor `β`.
    pub duty_factor: f64,
    /// Body speed `v`, metres per second.
    pub speed_mps: f64,
    /// Relative phase `R_i` of each leg.
    pub phases: Vec<f64>,
}

/// PODA gait parameters kept consistent with eq. 7–8 (see the module docs).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "GaitSpec", into = "GaitSpec")]
pub struct GaitParams {
    period_s: f64,
    duty_factor: f64,
    speed_mps: f64,
    phases: Vec<f64>,
}

/// Where one leg is in its cycle at a time `t` (eq. 9); all times are absolute, in seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegPhase {
    /// Whether the foot is on the ground (leg state < support duration).
    pub support: bool,
    /// Eq. 9 leg state `(R_i·P + t) mod P`, in `[0, P)`: 0 at touchdown, `support_s` at lift-off.
    pub state_s: f64,
    /// Progress through the current phase (support or transfer), in `[0, 1)`.
    pub fraction: f64,
    /// The latest touchdown at or before `t`.
    pub last_touchdown_s: f64,
    /// The latest lift-off at or before `t`.
    pub last_liftoff_s: f64,
    /// The first touchdown after `t`.
    pub next_touchdown_s: f64,
    /// The first lift-off after `t`.
    pub next_liftoff_s: f64,
}

fn range_text(range: &RangeInclusive<f64>) -> String {
    format!("{}..={}", range.start(), range.end())
}

/// Checks an edited input strictly against its range.
fn check_input(path: &str, value: f64, range: &RangeInclusive<f64>) -> Result<(), GaitError> {
    if value.is_finite() && range.contains(&value) {
        return Ok(());
    }
    let reason = format!("{value} is outside {}", range_text(range));
    Err(GaitError::new(path, reason))
}

/// Checks an edited input that has no range of its own but must be positive and finite.
fn check_positive(path: &str, value: f64) -> Result<(), GaitError> {
    if value.is_finite() && value > 0.0 {
        return Ok(());
    }
    Err(GaitError::new(path, format!("{value} is not positive")))
}

/// Checks that there are `count` phases, all finite.
fn check_phases(phases: &[f64], count: RangeInclusive<usize>) -> Result<(), GaitError> {
    if !count.contains(&phases.len()) {
        let reason = format!("{} phases; expected {count:?}", phases.len());
        return Err(GaitError::new("phases", reason));
    }
    let Some(i) = phases.iter().position(|p| !p.is_finite()) else {
        return Ok(());
    };
    Err(GaitError::new(format!("phases[{i}]"), "not finite"))
}

/// Checks every canonical and derived quantity of a candidate `(P, β, v)`; errors name `edited`.
fn check_candidate(edited: &str, (period_s, duty, speed_mps): State) -> Result<(), GaitError> {
    let values = [
        ("period_s", period_s, PERIOD_RANGE_S),
        ("duty_factor", duty, DUTY_FACTOR_RANGE),
        ("speed_mps", speed_mps, SPEED_RANGE_MPS),
        ("stroke_m", speed_mps * duty * period_s, STROKE_RANGE_M),
    ];
    for (name, value, range) in values {
        let (lo, hi) = (*range.start(), *range.end());
        if !(value >= lo * (1.0 - DERIVED_SLACK) && value <= hi * (1.0 + DERIVED_SLACK)) {
            let shown = (value * 1e9).round() / 1e9;
            let reason = format!("would make {name} {shown}, outside {}", range_text(&range));
            return Err(GaitError::new(edited, reason));
        }
    }
    Ok(())
}

impl GaitParams {
    /// Builds a gait from period, duty factor, one relative phase per leg (normalised into
    /// `[0, 1)`) and body speed; the stroke is derived (eq. 7).
    ///
    /// # Errors
    /// A value out of range or non-finite, a derived stroke out of range, or a leg count
    /// outside [`LEG_COUNT_RANGE`].
    pub fn new(
        period_s: f64,
        duty_factor: f64,
        phases: Vec<f64>,
        speed_mps: f64,
    ) -> Result<Self, GaitError> {
        check_input("period_s", period_s, &PERIOD_RANGE_S)?;
        check_input("duty_factor", duty_factor, &DUTY_FACTOR_RANGE)?;
        check_input("speed_mps", speed_mps, &SPEED_RANGE_MPS)?;
        check_candidate("stroke_m", (period_s, duty_factor, speed_mps))?;
        check_phases(&phases, LEG_COUNT_RANGE)?;
        let phases = phases.into_iter().map(normalise_phase).collect();
        Ok(Self {
            period_s,
            duty_factor,
            speed_mps,
            phases,
        })
    }

    /// Gait cycle period `P`, seconds.
    #[must_use]
    pub fn period_s(&self) -> f64 {
        self.period_s
    }
    /// Duty factor `β = support_s / P`.
    #[must_use]
    pub fn duty_factor(&self) -> f64 {
        self.duty_factor
    }
    /// Support duration `β·P`, seconds.
    #[must_use]
    pub fn support_s(&self) -> f64 {
        self.duty_factor * self.period_s
    }
    /// Transfer duration `P − support_s` (eq. 8), seconds.
    #[must_use]
    pub fn transfer_s(&self) -> f64 {
        self.period_s - self.support_s()
    }
    /// Stroke `v·support_s` (eq. 7), metres.
    #[must_use]
    pub fn stroke_m(&self) -> f64 {
        self.speed_mps * self.support_s()
    }
    /// Body speed `v`, metres per second.
    #[must_use]
    pub fn speed_mps(&self) -> f64 {
        self.speed_mps
    }
    /// Relative phase `R_i ∈ [0, 1)` of each leg.
    #[must_use]
    pub fn phases(&self) -> &[f64] {
        &self.phases
    }
    /// Number of legs.
    #[must_use]
    pub fn leg_count(&self) -> usize {
        self.phases.len()
    }

    /// Validates and stores a candidate state.
    fn commit(&mut self, edit: Derived, next: State) -> Result<Derived, GaitError> {
        check_candidate(edit.edited, next)?;
        (self.period_s, self.duty_factor, self.speed_mps) = next;
        Ok(edit)
    }

    /// Sets `P`, keeping duty factor and speed; support, transfer and stroke are derived.
    ///
    /// # Errors
    /// `period_s` out of range, or a derived value would leave its range.
    pub fn set_period(&mut self, period_s: f64) -> Result<Derived, GaitError> {
        check_input("period_s", period_s, &PERIOD_RANGE_S)?;
        let next = (period_s, self.duty_factor, self.speed_mps);
        self.commit(EDIT_PERIOD, next)
    }

    /// Sets `β`, keeping `P` and speed; support, transfer and stroke are derived.
    ///
    /// # Errors
    /// `duty_factor` out of range, or a derived value would leave its range.
    pub fn set_duty_factor(&mut self, duty_factor: f64) -> Result<Derived, GaitError> {
        check_input("duty_factor", duty_factor, &DUTY_FACTOR_RANGE)?;
        let next = (self.period_s, duty_factor, self.speed_mps);
        self.commit(EDIT_DUTY, next)
    }

    /// Sets `v`, keeping stroke and `β`: `support = stroke / v` (eq. 7), then `P` and transfer.
    ///
    /// # Errors
    /// `speed_mps` out of range, or a derived value would leave its range.
    pub fn set_speed(&mut self, speed_mps: f64) -> Result<Derived, GaitError> {
        check_input("speed_mps", speed_mps, &SPEED_RANGE_MPS)?;
        let period_s = self.stroke_m() / speed_mps / self.duty_factor;
        let next = (period_s, self.duty_factor, speed_mps);
        self.commit(EDIT_SPEED, next)
    }

    /// Sets the stroke, keeping speed and `β`: `support = stroke / v`, then `P` and transfer.
    ///
    /// # Errors
    /// `stroke_m` out of range, or a derived value would leave its range.
    pub fn set_stroke(&mut self, stroke_m: f64) -> Result<Derived, GaitError> {
        check_input("stroke_m", stroke_m, &STROKE_RANGE_M)?;
        let period_s = stroke_m / self.speed_mps / self.duty_factor;
        let next = (period_s, self.duty_factor, self.speed_mps);
        self.commit(EDIT_STROKE, next)
    }

    /// Sets the support duration, keeping `P` and speed: `β = S / P`, transfer `P − S`,
    /// stroke `v·S`.
    ///
    /// # Errors
    /// `support_s` not positive, or a derived value would leave its range.
    pub fn set_support(&mut self, support_s: f64) -> Result<Derived, GaitError> {
        check_positive("support_s", support_s)?;
        let next = (self.period_s, support_s / self.period_s, self.speed_mps);
        self.commit(EDIT_SUPPORT, next)
    }

    /// Sets the transfer duration, keeping support (and so stroke and speed): `P = S + T`
    /// (eq. 8), `β = S / P`.
    ///
    /// # Errors
    /// `transfer_s` not positive, or a derived value would leave its range.
    pub fn set_transfer(&mut self, transfer_s: f64) -> Result<Derived, GaitError> {
        check_positive("transfer_s", transfer_s)?;
        let support_s = self.support_s();
        let period_s = support_s + transfer_s;
        let next = (period_s, support_s / period_s, self.speed_mps);
        self.commit(EDIT_TRANSFER, next)
    }

    /// Sets one leg's relative phase (normalised into `[0, 1)`); nothing else changes.
    ///
    /// # Errors
    /// `phases[leg]` when the leg does not exist or the phase is not finite.
    pub fn set_phase(&mut self, leg: usize, phase: f64) -> Result<Derived, GaitError> {
        let path = format!("phases[{leg}]");
        if !phase.is_finite() {
            return Err(GaitError::new(path, format!("{phase} is not finite")));
        }
        let count = self.leg_count();
        let Some(slot) = self.phases.get_mut(leg) else {
            return Err(GaitError::new(path, format!("no such leg of {count}")));
        };
        *slot = normalise_phase(phase);
        Ok(EDIT_PHASE)
    }

    /// Each leg's share of gravity, `g_n = g / leg_count` (each leg hops its share of the weight).
    #[must_use]
    pub fn gravity_share_mps2(&self, g_mps2: f64) -> f64 {
        #[expect(clippy::cast_precision_loss, reason = "leg count ≤ 32")]
        let legs = self.leg_count() as f64;
        g_mps2 / legs
    }

    /// Constant upward leg force during support that balances the leg's weight share over one
    /// cycle: impulse `F·β·P = m·g_n·P`, so `F = m·g_n / β` (eq. 12–13 with transfer unchanged).
    #[must_use]
    pub fn leg_force_for_balance_n(&self, mass_kg: f64, g_mps2: f64) -> f64 {
        mass_kg * self.gravity_share_mps2(g_mps2) / self.duty_factor
    }

    /// Sets the support-phase leg force, keeping support (and stroke, speed): eq. 12 gives
    /// `a = F/m − g_n`, eq. 13 `transfer = (a / g_n)·support`; `P` and `β` are derived.
    ///
    /// # Errors
    /// `mass_kg`/`g_mps2` not positive, `force_n` not above the weight share `m·g_n`, or a
    /// derived value would leave its range.
    pub fn set_leg_force(
        &mut self,
        force_n: f64,
        mass_kg: f64,
        g_mps2: f64,
    ) -> Result<Derived, GaitError> {
        check_positive("mass_kg", mass_kg)?;
        check_positive("g_mps2", g_mps2)?;
        let g_n = self.gravity_share_mps2(g_mps2);
        let accel = force_n / mass_kg - g_n;
        if !(accel.is_finite() && accel > 0.0) {
            let share = mass_kg * g_n;
            let reason = format!("{force_n} must exceed the weight share m·g/legs = {share} N");
            return Err(GaitError::new("force_n", reason));
        }
        let support_s = self.support_s();
        let period_s = support_s + accel / g_n * support_s;
        let next = (period_s, support_s / period_s, self.speed_mps);
        self.commit(EDIT_FORCE, next)
    }

    /// Sets every leg's phase and `β` at once (a named gait), keeping `P` and
    /// speed; support and stroke are derived. Legs take it on one by one
    /// ([`super::leg_cycles`]).
    ///
    /// # Errors
    /// Wrong phase count, non-finite phase, duty factor out of range, or a
    /// derived stroke out of range; nothing changes.
    pub fn set_shape(&mut self, phases: &[f64], duty_factor: f64) -> Result<(), GaitError> {
        check_phases(phases, self.leg_count()..=self.leg_count())?;
        check_input("duty_factor", duty_factor, &DUTY_FACTOR_RANGE)?;
        check_candidate("duty_factor", (self.period_s, duty_factor, self.speed_mps))?;
        for (slot, &phase) in self.phases.iter_mut().zip(phases) {
            *slot = normalise_phase(phase);
        }
        self.duty_factor = duty_factor;
        Ok(())
    }

    /// Eq. 9 state of `leg` at time `t_s`; `None` for a missing leg or non-finite time.
    #[must_use]
    pub fn leg_phase(&self, leg: usize, t_s: f64) -> Option<LegPhase> {
        let phase = *self.phases.get(leg)?;
        if !t_s.is_finite() {
            return None;
        }
        let (period, support) = (self.period_s, self.support_s());
        let state_s = wrap(phase * period + t_s, period);
        let touchdown = t_s - state_s;
        let on_ground = state_s < support;
        // Lift-off is at leg state `support`: in support, the previous cycle's.
        let last_liftoff_s = touchdown + support - if on_ground { period } else { 0.0 };
        let (elapsed_s, len_s) = if on_ground {
            (state_s, support)
        } else {
            (state_s - support, period - support)
        };
        Some(LegPhase {
            support: on_ground,
            state_s,
            fraction: (elapsed_s / len_s).clamp(0.0, ONE_BELOW),
            last_touchdown_s: touchdown,
            last_liftoff_s,
            next_touchdown_s: touchdown + period,
            next_liftoff_s: last_liftoff_s + period,
        })
    }

    /// The body's vertical displacement at `t_s` (no allocation, uncentred): the
    /// superposition of every leg's ballistic contribution ([`vertical_offset_m`], with
    /// `g_n = g / leg_count` and `tau` measured from the leg's mid-stance). A driver picks the
    /// constant that sets where the body stands.
    #[must_use]
    pub fn vertical_superposition_m(&self, t_s: f64, g_mps2: f64) -> f64 {
        let (support, transfer) = (self.support_s(), self.transfer_s());
        let g_n = self.gravity_share_mps2(g_mps2);
        (0..self.leg_count())
            .filter_map(|leg| self.leg_phase(leg, t_s))
            .map(|p| vertical_offset_m(support, transfer, g_n, p.state_s - 0.5 * support))
            .sum()
    }

    /// `Σ_i w_i · y_i(t)`: the legs' ballistic contributions (as in
    /// [`vertical_superposition_m`](Self::vertical_superposition_m)) weighted
    /// per leg; with the weights of the body's least-squares line through the
    /// legs' positions it is the body's pitch slope (no allocation).
    #[must_use]
    pub fn vertical_weighted_m(&self, t_s: f64, g_mps2: f64, weights: &[f64]) -> f64 {
        let (support, transfer) = (self.support_s(), self.transfer_s());
        let g_n = self.gravity_share_mps2(g_mps2);
        (0..self.leg_count())
            .zip(weights)
            .filter_map(|(leg, w)| self.leg_phase(leg, t_s).map(|p| (p, w)))
            .map(|(p, w)| w * vertical_offset_m(support, transfer, g_n, p.state_s - 0.5 * support))
            .sum()
    }
}

impl TryFrom<GaitSpec> for GaitParams {
    type Error = GaitError;
    fn try_from(spec: GaitSpec) -> Result<Self, GaitError> {
        Self::new(spec.period_s, spec.duty_factor, spec.phases, spec.speed_mps)
    }
}

impl From<GaitParams> for GaitSpec {
    fn from(p: GaitParams) -> Self {
        Self {
            period_s: p.period_s,
            duty_factor: p.duty_factor,
            speed_mps: p.speed_mps,
            phases: p.phases,
        }
    }
}

/// One leg's ballistic `(height, velocity)` at `tau_s` since mid-stance, or `None` for bad input.
fn ballistic(support_s: f64, transfer_s: f64, g_n: f64, tau_s: f64) -> Option<(f64, f64)> {
    let ok =
        support_s.is_finite() && support_s > 0.0 && transfer_s.is_finite() && transfer_s >= 0.0;
    if !(ok && g_n.is_finite() && tau_s.is_finite()) {
        return None;
    }
    let (period, half) = (support_s + transfer_s, 0.5 * support_s);
    let accel = g_n * transfer_s / support_s;
    let x = wrap(tau_s + half, period) - half;
    if x <= half {
        return Some((0.5 * accel * x * x, accel * x));
    }
    let f = x - half;
    let y = accel * support_s * support_s / 8.0 + 0.5 * accel * support_s * f - 0.5 * g_n * f * f;
    Some((y, 0.5 * accel * support_s - g_n * f))
}

/// One leg's vertical contribution at `tau_s` after its mid-stance (periodic in `S + T`): stance
/// acceleration `a = g_n·T/S` (eq. 13; restoring in the first half of stance, pushing in the
/// second), free fall `−g_n` in transfer; minimum 0 at mid-stance, position and velocity
/// continuous. `g_n` is the leg's gravity share in m/s² ([`GaitParams::gravity_share_mps2`]).
/// Returns 0 for non-finite input, `support_s ≤ 0` or `transfer_s < 0`.
#[must_use]
pub fn vertical_offset_m(support_s: f64, transfer_s: f64, g_n: f64, tau_s: f64) -> f64 {
    ballistic(support_s, transfer_s, g_n, tau_s).map_or(0.0, |(y, _)| y)
}

/// Time derivative of [`vertical_offset_m`]; 0 for the same bad inputs.
#[must_use]
pub fn vertical_velocity_mps(support_s: f64, transfer_s: f64, g_n: f64, tau_s: f64) -> f64 {
    ballistic(support_s, transfer_s, g_n, tau_s).map_or(0.0, |(_, v)| v)
}

/// Exact mean of [`vertical_offset_m`] over one period:
/// `a·(S³/24 + S²T/8 + S·T²/12) / (S + T)`; 0 for bad inputs.
#[must_use]
pub fn vertical_mean_m(support_s: f64, transfer_s: f64, g_n: f64) -> f64 {
    if ballistic(support_s, transfer_s, g_n, 0.0).is_none() {
        return 0.0;
    }
    let (s, t) = (support_s, transfer_s);
    let accel = g_n * t / s;
    accel * (s * s * s / 24.0 + s * s * t / 8.0 + s * t * t / 12.0) / (s + t)
}

#[cfg(test)]
#[expect(clippy::float_cmp, reason = "exact values are asserted on purpose")]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12
    }

    fn assert_relations(g: &GaitParams) {
        assert!(close(g.support_s(), g.stroke_m() / g.speed_mps()), "eq. 7");
        assert!(close(g.period_s(), g.support_s() + g.transfer_s()), "eq. 8");
        assert!(close(g.duty_factor(), g.support_s() / g.period_s()), "duty");
    }

    fn trot() -> GaitParams {
        GaitParams::new(0.8, 0.5, vec![0.0, 0.5, 0.5, 0.0], 1.5).expect("valid")
    }

    #[test]
    fn edits_keep_eq_7_and_8_and_name_derived_values() {
        let mut g = trot();
        assert!(close(g.stroke_m(), 0.6));
        assert!(g.set_period(1.0).expect("ok").contains("stroke_m") && close(g.stroke_m(), 0.75));
        assert_relations(&g);
        g.set_duty_factor(0.6).expect("ok");
        assert!(close(g.support_s(), 0.6) && close(g.stroke_m(), 0.9));
        assert_relations(&g);
        let d = g.set_speed(3.0).expect("ok"); // stroke 0.9 and β 0.6 kept
        assert_eq!(d.derived, ["support_s", "period_s", "transfer_s"]);
        assert!(close(g.stroke_m(), 0.9) && close(g.support_s(), 0.3) && close(g.period_s(), 0.5));
        assert_relations(&g);
        g.set_stroke(1.2).expect("ok");
        assert!(close(g.support_s(), 0.4) && g.speed_mps() == 3.0);
        assert_relations(&g);
        assert!(g.set_support(0.5).expect("ok").contains("duty_factor")); // P = 2/3 kept
        assert!(close(g.duty_factor(), 0.75) && close(g.stroke_m(), 1.5));
        assert_relations(&g);
        g.set_transfer(0.5).expect("ok");
        assert!(close(g.period_s(), 1.0) && close(g.duty_factor(), 0.5));
        assert_relations(&g);
        assert!(g.set_phase(2, -0.75).expect("ok").derived.is_empty() && g.phases()[2] == 0.25);
        assert_relations(&g);
    }

    #[test]
    fn rejected_edits_name_the_field_and_leave_state_unchanged() {
        let mut g = trot();
        let before = g.clone();
        let e = g.set_speed(0.05).expect_err("support 12 s → P 24 s");
        assert_eq!(
            e.to_string(),
            "speed_mps: would make period_s 24, outside 0.1..=10"
        );
        let e = g.set_duty_factor(0.96).expect_err("range");
        assert_eq!(e.to_string(), "duty_factor: 0.96 is outside 0.05..=0.95");
        assert_eq!(g.set_period(f64::NAN).expect_err("NaN").path, "period_s");
        assert!(
            g.set_transfer(0.001)
                .expect_err("β > 0.95")
                .reason
                .contains("duty_factor")
        );
        assert_eq!(g.set_phase(4, 0.1).expect_err("no leg").path, "phases[4]");
        assert_eq!(
            g.set_leg_force(10.0, 10.0, 9.81).expect_err("weak").path,
            "force_n"
        );
        assert_eq!(g, before);
        let bad_phase = GaitParams::new(1.0, 0.5, vec![0.0, f64::INFINITY], 1.0);
        assert_eq!(bad_phase.expect_err("inf").path, "phases[1]");
        assert_eq!(
            GaitParams::new(1.0, 0.5, vec![], 1.0)
                .expect_err("no legs")
                .path,
            "phases"
        );
        let long_stroke = GaitParams::new(1.0, 0.5, vec![0.0], 20.0);
        assert_eq!(long_stroke.expect_err("10 m").path, "stroke_m");
    }

    #[test]
    fn leg_state_follows_eq_9() {
        let g = GaitParams::new(1.0, 0.6, vec![0.25], 1.0).expect("valid");
        let a = g.leg_phase(0, 0.0).expect("leg 0");
        assert!(a.support && close(a.state_s, 0.25) && close(a.fraction, 0.25 / 0.6));
        assert!(close(a.last_touchdown_s, -0.25) && close(a.next_liftoff_s, 0.35));
        assert!(close(a.last_liftoff_s, -0.65) && close(a.next_touchdown_s, 0.75));
        let b = g.leg_phase(0, 0.5).expect("leg 0");
        assert!(!b.support && close(b.state_s, 0.75) && close(b.fraction, 0.375));
        assert!(close(b.last_liftoff_s, 0.35) && close(b.next_touchdown_s, 0.75));
        assert!(close(b.next_liftoff_s, 1.35));
        let c = g.leg_phase(0, -7.25).expect("leg 0"); // a touchdown
        assert!(c.support && c.state_s.abs() < 1e-12 && close(c.last_liftoff_s, -7.65));
        assert!(g.leg_phase(1, 0.0).is_none() && g.leg_phase(0, f64::NAN).is_none());
    }

    #[test]
    fn vertical_motion_is_continuous_and_centred() {
        let (st, tr, g_n) = (0.3, 0.2, 9.81 / 4.0);
        let (period, steps, h) = (st + tr, 20_000, 1e-6);
        let y = |tau| vertical_offset_m(st, tr, g_n, tau);
        let v = |tau| vertical_velocity_mps(st, tr, g_n, tau);
        assert!(y(0.0) == 0.0 && v(0.0) == 0.0);
        let mut mean = 0.0;
        for k in 0..steps {
            let tau = -0.5 * st + period * (f64::from(k) + 0.5) / f64::from(steps);
            mean += y(tau) / f64::from(steps);
            assert!(y(tau) > 0.0 && (y(tau) - y(tau + 3.0 * period)).abs() < 1e-12);
            assert!(((y(tau + h) - y(tau - h)) / (2.0 * h) - v(tau)).abs() < 1e-6);
        }
        assert!((mean - vertical_mean_m(st, tr, g_n)).abs() < 1e-8, "{mean}");
        for edge in [-0.5 * st, 0.5 * st] {
            let (after, before) = (edge + 1e-9, edge - 1e-9);
            assert!((y(after) - y(before)).abs() < 1e-8 && (v(after) - v(before)).abs() < 1e-7);
        }
        assert_eq!(vertical_offset_m(0.0, tr, g_n, 0.1), 0.0);
        // A trot's two diagonal pairs: the body offset is periodic in P/2.
        let g = trot();
        let half = 0.5 * g.period_s();
        for k in 0..100 {
            let t = f64::from(k) * 7e-3;
            let (a, b) = (
                g.vertical_superposition_m(t, 9.81),
                g.vertical_superposition_m(t + half, 9.81),
            );
            assert!((a - b).abs() < 1e-12);
        }
    }

    #[test]
    fn leg_force_follows_eq_12_13() {
        let mut g = trot(); // P 0.8, β 0.5
        let (m, gr) = (20.0, 9.81);
        let f = g.leg_force_for_balance_n(m, gr);
        assert!(close(f, m * gr / 4.0 / 0.5));
        g.set_leg_force(f, m, gr).expect("ok");
        assert!(close(g.period_s(), 0.8) && close(g.duty_factor(), 0.5));
        let d = g.set_leg_force(3.0 * m * gr / 4.0, m, gr).expect("ok"); // a = 2 g_n → T = 2 S
        assert!(d.contains("transfer_s") && close(g.transfer_s(), 0.8));
        assert!(close(g.duty_factor(), 1.0 / 3.0));
        assert_relations(&g);
    }

    #[test]
    fn serde_round_trip_validates() {
        let json = serde_json::to_string(&trot()).expect("serialise");
        assert_eq!(
            serde_json::from_str::<GaitParams>(&json).expect("valid"),
            trot()
        );
        let bad = r#"{"period_s":1.0,"duty_factor":2.0,"speed_mps":1.0,"phases":[0.0]}"#;
        let e = serde_json::from_str::<GaitParams>(bad).expect_err("duty 2");
        assert!(e.to_string().contains("duty_factor"));
    }
}
