//! The body's planned motion on the ground plane, computed ahead of time so
//! that footholds can be planned (Girard & Maciejewski 1985, "Directional
//! Control of the Body", Figure 13's order of calculation):
//! 1. **translation** (eq. 14–15): a desired point moves along the body path
//!    at the desired speed (the path's speed where the point is, when the
//!    path carries speeds, [`BodyPath::desired_speed_mps`]; else the gait's);
//!    the desired velocity is the path's tangent times
//!    that speed plus a pull toward the desired point; each frame the body's
//!    velocity moves toward it by at most `Σ‖F_max‖ / mass` over the legs in
//!    support at that moment (eq. 14), in the direction of the velocity error
//!    (eq. 15);
//! 2. **direction of travel**: the heading of the planned velocity;
//! 3. **yaw** ("Rotational Control"): each leg, from one mid-stance to the
//!    next, pushes with `σ̈ = Δσ / (push·(push + fall))` during its push, coasts
//!    through its fall and restores with `−σ̈`, where `Δσ` is its share (1/n)
//!    of the turn from the body's yaw at the mid-stance to the direction of
//!    travel at the next (the paper's `σ_{midStance+P} − σ_{midStance}`, read
//!    with the actual yaw at mid-stance, so a yaw error left over is corrected
//!    too; `yaw_toward_actual` off, as before 2026-12-02: the change of the
//!    direction of travel between the mid-stances); the legs' contributions
//!    add up.
//!
//! With `turn_within_reach` (the lab's reading of the paper's "coherent with
//! its leg support duration pattern" for the legs' reach) the direction of
//! travel also turns at most `v / r` (gait speed over the farthest foot's
//! distance from the centre), the body never outruns the gait and slows for
//! a sharp turn, and the desired point waits at most one stroke ahead: the
//! body cuts corners its legs cannot take (`BodyDynamics::min_turn_radius_m`,
//! `max_lead_strokes`).
//!
//! Translation is planned one gait period further ahead than yaw, because a
//! leg's yaw target lies one period after its mid-stance.

use gaitlab_core::portable::Portable;
use std::collections::VecDeque;

use glam::DVec2;

use super::gait::GaitParams;
use super::ground_pose::GroundPose;
use super::path::BodyPath;

/// The least fraction of the gait's speed the body keeps while turning
/// toward a direction far off its own (with `min_turn_radius_m`): slow enough
/// to turn inside its turning circle, never stopped.
const MIN_TURN_SPEED_FRACTION: f64 = 0.25;

/// Options of the horizontal and yaw dynamics.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyDynamics {
    /// Body mass, kg (eq. 14).
    pub mass_kg: f64,
    /// Largest horizontal force of one supporting leg, N (eq. 14).
    pub max_leg_force_n: f64,
    /// Pull of the desired velocity toward the desired point on the path, 1/s.
    pub path_gain_per_s: f64,
    /// Tightest radius the body turns on, metres (0: no limit): its direction
    /// of travel turns at most `speed / radius` rad/s, so the body cuts a
    /// tighter corner of the path instead of dragging its planted feet.
    pub min_turn_radius_m: f64,
    /// Farthest the desired point runs ahead of the body, in strokes of the
    /// gait (0: no limit); with a limit the body also never runs faster than
    /// the gait.
    pub max_lead_strokes: f64,
    /// Turn each leg's yaw cycle from the body's actual yaw at its mid-stance
    /// (`yaw_toward_actual`), not from the direction of travel there.
    pub yaw_toward_actual: bool,
}

impl Default for BodyDynamics {
    fn default() -> Self {
        Self {
            mass_kg: 30.0,
            max_leg_force_n: 30.0 * 9.81,
            path_gain_per_s: 2.0,
            min_turn_radius_m: 0.0,
            max_lead_strokes: 0.0,
            yaw_toward_actual: true,
        }
    }
}

/// One planned instant.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyState {
    /// Time, seconds.
    pub t_s: f64,
    /// Position `(x, z)`, metres.
    pub position: DVec2,
    /// Velocity `(x, z)`, m/s.
    pub velocity: DVec2,
    /// Yaw, radians (0 faces +z).
    pub yaw_rad: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// Arc length of the desired point on the path, metres.
    pub desired_m: f64,
}

/// A leg's current yaw cycle: from its mid-stance `start_s`, push with
/// `accel` for `push_s`, coast for `fall_s`, restore with `−accel`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct YawCycle {
    start_s: f64,
    push_s: f64,
    fall_s: f64,
    accel: f64,
}

impl YawCycle {
    /// Yaw rate this cycle has built up by `t`, rad/s.
    fn velocity(&self, t: f64) -> f64 {
        let tau = (t - self.start_s).max(0.0);
        let push = tau.min(self.push_s);
        let restore = (tau - self.push_s - self.fall_s).clamp(0.0, self.push_s);
        self.accel * (push - restore)
    }
}

/// The planned body motion: states every `step_s` from the current time on.
#[derive(Clone, Debug)]
pub struct BodyTrack {
    step_s: f64,
    states: VecDeque<BodyState>,
    /// States whose yaw is planned (a prefix of `states`).
    yaw_planned: usize,
    cycles: Vec<YawCycle>,
    dynamics: BodyDynamics,
}

/// The desired body speed at arc length `distance_m` of `path`, m/s: the
/// path's own where it carries speeds ([`BodyPath::desired_speed_mps`]),
/// else the gait's.
#[must_use]
pub fn desired_speed_mps(path: &BodyPath, gait: &GaitParams, distance_m: f64) -> f64 {
    path.desired_speed_mps(distance_m)
        .unwrap_or_else(|| gait.speed_mps())
}

/// Wraps an angle into (−π, π].
fn wrap(angle: f64) -> f64 {
    let a = angle.rem_euclid(std::f64::consts::TAU);
    if a > std::f64::consts::PI {
        a - std::f64::consts::TAU
    } else {
        a
    }
}

impl BodyTrack {
    /// An empty track planning every `step_s` seconds.
    #[must_use]
    pub fn new(step_s: f64, dynamics: BodyDynamics) -> Self {
        Self {
            step_s: if step_s.is_finite() && step_s > 0.0 {
                step_s
            } else {
                1.0 / 60.0
            },
            states: VecDeque::new(),
            yaw_planned: 0,
            cycles: Vec::new(),
            dynamics,
        }
    }

    /// The dynamics options.
    #[must_use]
    pub fn dynamics(&self) -> &BodyDynamics {
        &self.dynamics
    }

    /// Starts at time 0 at the path's start, moving along it at the desired
    /// speed there ([`desired_speed_mps`]) and facing that way, then plans
    /// ahead.
    pub fn reset(&mut self, path: &BodyPath, gait: &GaitParams) {
        let start = path.sample(0.0);
        self.states.clear();
        self.states.push_back(BodyState {
            t_s: 0.0,
            position: start.position,
            velocity: start.tangent * desired_speed_mps(path, gait, 0.0),
            yaw_rad: start.heading_rad,
            yaw_rate: 0.0,
            desired_m: 0.0,
        });
        self.yaw_planned = 1;
        self.cycles.clear();
        self.cycles.resize(gait.leg_count(), YawCycle::default());
        // The legs' cycles are already under way at time 0: start with the
        // yaw rate they have built up (0 on a straight path).
        let period = gait.period_s();
        while self
            .states
            .back()
            .is_some_and(|s| s.t_s < 2.0 * period + 6.0 * self.step_s)
        {
            self.extend_translation(path, gait);
        }
        self.update_cycles(gait, 0.0);
        let rate: f64 = self.cycles.iter().map(|c| c.velocity(0.0)).sum();
        if let Some(first) = self.states.front_mut() {
            first.yaw_rate = rate;
        }
        self.plan(path, gait);
    }

    /// Drops states before `t_s` (keeping the one just before it) and plans
    /// ahead again.
    pub fn advance_to(&mut self, t_s: f64, path: &BodyPath, gait: &GaitParams) {
        while self.states.len() > 2 && self.states.get(1).is_some_and(|s| s.t_s <= t_s) {
            self.states.pop_front();
            self.yaw_planned = self.yaw_planned.saturating_sub(1).max(1);
        }
        self.plan(path, gait);
    }

    /// Forgets the plan later than `keep_s` after `t_s` (a gait edit: the new
    /// speed or period applies from there) and plans again.
    pub fn replan(&mut self, t_s: f64, keep_s: f64, path: &BodyPath, gait: &GaitParams) {
        let last = t_s + keep_s.max(0.0);
        while self.states.len() > 2 && self.states.back().is_some_and(|s| s.t_s > last) {
            self.states.pop_back();
        }
        self.yaw_planned = self.yaw_planned.min(self.states.len()).max(1);
        self.plan(path, gait);
    }

    /// After the body path changed: the desired point restarts at arc length
    /// `distance_m` of the new path, and everything after `t_s` is planned
    /// again along it.
    pub fn follow_new_path(
        &mut self,
        t_s: f64,
        distance_m: f64,
        path: &BodyPath,
        gait: &GaitParams,
    ) {
        while self.states.len() > 2 && self.states.back().is_some_and(|s| s.t_s > t_s) {
            self.states.pop_back();
        }
        for state in &mut self.states {
            state.desired_m = distance_m;
        }
        self.yaw_planned = self.yaw_planned.min(self.states.len()).max(1);
        self.plan(path, gait);
    }

    /// Extends translation to two periods plus a margin ahead of the first
    /// state, and yaw to one period plus a margin.
    fn plan(&mut self, path: &BodyPath, gait: &GaitParams) {
        let Some(first) = self.states.front().copied() else {
            return;
        };
        let period = gait.period_s();
        let yaw_horizon = first.t_s + period + 4.0 * self.step_s;
        let translation_horizon = yaw_horizon + period + 2.0 * self.step_s;
        while self
            .states
            .back()
            .is_some_and(|s| s.t_s < translation_horizon)
        {
            self.extend_translation(path, gait);
        }
        while self.yaw_planned < self.states.len()
            && self.states[self.yaw_planned - 1].t_s < yaw_horizon
        {
            self.extend_yaw(gait);
        }
    }

    /// Eq. 14–15: one more translation step.
    fn extend_translation(&mut self, path: &BodyPath, gait: &GaitParams) {
        let Some(last) = self.states.back().copied() else {
            return;
        };
        let h = self.step_s;
        let t = last.t_s + h;
        // Velocity feedback (eq. 15) toward the path's velocity at the desired
        // point, pulled toward where that point is now.
        let now = path.sample(last.desired_m);
        let gap = (now.position - last.position).length();
        let lead = self.dynamics.max_lead_strokes * gait.stroke_m();
        let wait = if lead > 0.0 {
            (1.0 - gap / lead).clamp(0.0, 1.0)
        } else {
            1.0
        };
        // The desired speed where the desired point is: the gait's, or the
        // path's own speeds (the gait follows them, `PodaDriver`).
        let speed = desired_speed_mps(path, gait, last.desired_m);
        let mut desired_m = last.desired_m + speed * h * wait;
        if lead > 0.0 {
            // The desired point never stays behind the body's own place on
            // the path: a body that cut a corner goes on from where it is.
            let ahead = path.closest_distance(last.position) - desired_m;
            let ahead = if path.is_closed() {
                let length = path.length_m();
                (ahead + 0.5 * length).rem_euclid(length) - 0.5 * length
            } else {
                ahead
            };
            if ahead > 0.0 {
                desired_m += ahead;
            }
        }
        let mut wanted =
            now.tangent * speed + (now.position - last.position) * self.dynamics.path_gain_per_s;
        if lead > 0.0 && wanted.length() > speed {
            wanted *= speed / wanted.length();
        }
        if self.dynamics.min_turn_radius_m > 0.0 {
            // Slow down for a turn ahead (the cosine of the heading error):
            // at a bounded turn rate, a target inside the turning circle is
            // reached only by slowing, never by orbiting it.
            let (speed, want) = (last.velocity.length(), wanted.length());
            if speed > 1e-9 && want > 1e-9 {
                let cos = last.velocity.dot(wanted) / (speed * want);
                wanted *= cos.max(MIN_TURN_SPEED_FRACTION);
            }
        }
        let supporting = (0..gait.leg_count())
            .filter(|&i| gait.leg_phase(i, last.t_s).is_some_and(|p| p.support))
            .count();
        let max_accel =
            supporting as f64 * self.dynamics.max_leg_force_n / self.dynamics.mass_kg.max(1e-9);
        let error = wanted - last.velocity;
        let needed = error.length() / h;
        let accel = if needed > max_accel && needed > 0.0 {
            error * (max_accel / needed) / h
        } else {
            error / h
        };
        let velocity = self.turn_limited(last.velocity, last.velocity + accel * h, speed);
        self.states.push_back(BodyState {
            t_s: t,
            position: last.position + velocity * h,
            velocity,
            yaw_rad: last.yaw_rad,
            yaw_rate: last.yaw_rate,
            desired_m,
        });
    }

    /// `next` with its direction turned at most `speed / min_turn_radius_m ·
    /// step` away from `last`'s (its length kept): in half a support of `S`
    /// seconds a planted foot `r` from the centre sweeps sideways `r·ω·S/2`,
    /// at most the half stroke `v·S/2` when `ω ≤ v / r`.
    fn turn_limited(&self, last: DVec2, next: DVec2, gait_speed_mps: f64) -> DVec2 {
        let radius = self.dynamics.min_turn_radius_m;
        let speed = next.length();
        if radius <= 0.0 || speed < 1e-9 || last.length_squared() < 1e-18 {
            return next;
        }
        let max_turn = gait_speed_mps / radius * self.step_s;
        let turn = wrap(next.x.patan2(next.y) - last.x.patan2(last.y));
        if turn.abs() <= max_turn {
            return next;
        }
        let heading = last.x.patan2(last.y) + max_turn.copysign(turn);
        let (sin, cos) = heading.psin_cos();
        DVec2::new(sin, cos) * speed
    }

    /// Starts a new yaw cycle for every leg whose latest mid-stance (leg
    /// state = support / 2) at or before `t_s` is not its current cycle's.
    fn update_cycles(&mut self, gait: &GaitParams, t_s: f64) {
        let (support, transfer, period) = (gait.support_s(), gait.transfer_s(), gait.period_s());
        let share = 1.0 / gait.leg_count().max(1) as f64;
        for i in 0..gait.leg_count().min(self.cycles.len()) {
            let Some(phase) = gait.leg_phase(i, t_s) else {
                continue;
            };
            let mid = t_s - (phase.state_s - 0.5 * support).rem_euclid(period);
            let cycle = self.cycles[i];
            // A later mid-stance starts the next cycle (rounding at the
            // boundary may put `mid` a whole period back: keep the cycle then).
            if cycle.push_s == 0.0 || mid > cycle.start_s + 0.5 * period {
                // From the body's yaw at the mid-stance to the direction of
                // travel one period later ("Rotational Control": σ at
                // mid-stance + P minus σ at mid-stance), so that a yaw
                // error left over is corrected, not only the heading's change.
                let from = if self.dynamics.yaw_toward_actual {
                    self.interpolate(mid).yaw_rad
                } else {
                    self.travel_heading(mid)
                };
                let change = wrap(self.travel_heading(mid + period) - from);
                let push = 0.5 * support;
                self.cycles[i] = YawCycle {
                    start_s: mid,
                    push_s: push,
                    fall_s: transfer,
                    accel: share * change / (push * (push + transfer)).max(1e-12),
                };
            }
        }
    }

    /// Direction of travel at `t_s`, from the planned velocities.
    fn travel_heading(&self, t_s: f64) -> f64 {
        let velocity = self.interpolate(t_s).velocity;
        if velocity.length_squared() > 1e-12 {
            velocity.x.patan2(velocity.y)
        } else {
            self.interpolate(t_s).yaw_rad
        }
    }

    /// "Rotational Control": one more yaw step.
    fn extend_yaw(&mut self, gait: &GaitParams) {
        let k = self.yaw_planned;
        let (Some(previous), Some(current)) = (self.states.get(k - 1).copied(), self.states.get(k))
        else {
            return;
        };
        let t_now = current.t_s;
        self.update_cycles(gait, previous.t_s);
        // The legs' yaw rates add up; integrate at the step's midpoint.
        let h = t_now - previous.t_s;
        let middle = previous.t_s + 0.5 * h;
        let mean_rate: f64 = self.cycles.iter().map(|c| c.velocity(middle)).sum();
        let yaw_rate: f64 = self.cycles.iter().map(|c| c.velocity(t_now)).sum();
        let yaw_rad = previous.yaw_rad + mean_rate * h;
        if let Some(state) = self.states.get_mut(k) {
            state.yaw_rate = yaw_rate;
            state.yaw_rad = yaw_rad;
        }
        self.yaw_planned += 1;
    }

    /// The planned state at `t_s`, interpolated; before the first state it
    /// extrapolates back along the first velocity, after the last it holds.
    #[must_use]
    pub fn interpolate(&self, t_s: f64) -> BodyState {
        let Some(first) = self.states.front().copied() else {
            return BodyState::default();
        };
        if t_s <= first.t_s {
            return BodyState {
                t_s,
                position: first.position + first.velocity * (t_s - first.t_s),
                ..first
            };
        }
        let index = ((t_s - first.t_s) / self.step_s).floor();
        let i = index as usize;
        match (self.states.get(i), self.states.get(i + 1)) {
            (Some(a), Some(b)) => {
                let f = ((t_s - a.t_s) / (b.t_s - a.t_s)).clamp(0.0, 1.0);
                BodyState {
                    t_s,
                    position: a.position.lerp(b.position, f),
                    velocity: a.velocity.lerp(b.velocity, f),
                    yaw_rad: a.yaw_rad + wrap(b.yaw_rad - a.yaw_rad) * f,
                    yaw_rate: a.yaw_rate + (b.yaw_rate - a.yaw_rate) * f,
                    desired_m: a.desired_m + (b.desired_m - a.desired_m) * f,
                }
            }
            _ => self.states.back().copied().unwrap_or(first),
        }
    }

    /// The planned ground pose at `t_s`.
    #[must_use]
    pub fn ground_pose(&self, t_s: f64) -> GroundPose {
        let state = self.interpolate(t_s);
        GroundPose {
            position: state.position,
            yaw_rad: state.yaw_rad,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poda::gaits::named_gait;

    const H: f64 = 1.0 / 60.0;

    fn trot(speed_mps: f64) -> GaitParams {
        let (phases, duty) = named_gait("trot", 4).expect("trot");
        GaitParams::new(0.6, duty, phases, speed_mps).expect("gait")
    }

    fn run(
        track: &mut BodyTrack,
        path: &BodyPath,
        gait: &GaitParams,
        seconds: f64,
    ) -> Vec<BodyState> {
        let frames = (seconds / H).round() as usize;
        (1..=frames)
            .map(|k| {
                let t = k as f64 * H;
                track.advance_to(t, path, gait);
                track.interpolate(t)
            })
            .collect()
    }

    #[test]
    fn a_straight_path_at_the_desired_speed_needs_no_force() {
        let path = BodyPath::straight(DVec2::ZERO, 0.0, 100.0).expect("path");
        let gait = trot(0.8);
        let mut track = BodyTrack::new(H, BodyDynamics::default());
        track.reset(&path, &gait);
        for state in run(&mut track, &path, &gait, 5.0) {
            assert!(
                (state.position.y - 0.8 * state.t_s).abs() < 1e-9,
                "{state:?}"
            );
            assert!(state.position.x.abs() < 1e-12 && state.yaw_rad.abs() < 1e-12);
        }
    }

    #[test]
    fn acceleration_is_limited_by_the_supporting_legs_forces() {
        let path = BodyPath::straight(DVec2::ZERO, 0.0, 100.0).expect("path");
        let mut gait = trot(0.5);
        // Weak legs: 20 N each on 40 kg, two legs in support → at most 1 m/s².
        let dynamics = BodyDynamics {
            mass_kg: 40.0,
            max_leg_force_n: 20.0,
            path_gain_per_s: 0.0,
            min_turn_radius_m: 0.0,
            max_lead_strokes: 0.0,
            yaw_toward_actual: true,
        };
        let mut track = BodyTrack::new(H, dynamics);
        track.reset(&path, &gait);
        let mut states = run(&mut track, &path, &gait, 1.0);
        // Faster, planned from now on.
        gait.set_speed(1.5).expect("faster");
        track.replan(1.0, 0.0, &path, &gait);
        let frames = (3.0 / H).round() as usize;
        states.extend((1..=frames).map(|k| {
            let t = 1.0 + k as f64 * H;
            track.advance_to(t, &path, &gait);
            track.interpolate(t)
        }));
        let mut previous = states[0];
        let mut reached = None;
        for state in &states[1..] {
            let accel = (state.velocity - previous.velocity).length() / H;
            assert!(accel <= 1.0 + 1e-9, "{accel} m/s² at {}", state.t_s);
            if reached.is_none() && (state.velocity.length() - 1.5).abs() < 1e-6 {
                reached = Some(state.t_s);
            }
            previous = *state;
        }
        // 1 m/s of speed at 1 m/s² (a trot always has two legs down), from t = 1 s.
        let reached = reached.expect("reaches the new speed");
        assert!((reached - 2.0).abs() < 0.05, "reached at {reached} s");
    }

    #[test]
    fn a_speed_step_along_the_path_is_a_ramp_within_the_legs_force() {
        // 0.5 m/s to 1.5 m/s within 0.1 m of a straight path (control points
        // 0.1 m apart), on the weak legs above (at most 1 m/s² with a trot's
        // two legs down): followed exactly, it would ask for up to 15 m/s².
        let points: Vec<DVec2> = (0..64)
            .map(|k| DVec2::new(0.0, 0.1 * f64::from(k)))
            .collect();
        let speeds: Vec<f64> = (0..64).map(|k| if k <= 10 { 0.5 } else { 1.5 }).collect();
        let path = BodyPath::new(&points, crate::poda::path::PathKind::CatmullRom, false)
            .and_then(|p| p.with_speeds(&speeds))
            .expect("path");
        let gait = trot(0.5);
        let dynamics = BodyDynamics {
            mass_kg: 40.0,
            max_leg_force_n: 20.0,
            path_gain_per_s: 0.0,
            ..BodyDynamics::default()
        };
        let mut track = BodyTrack::new(H, dynamics);
        track.reset(&path, &gait);
        let states = run(&mut track, &path, &gait, 6.0);
        let (mut previous, mut reached) = (states[0], None);
        for state in &states[1..] {
            let accel = (state.velocity - previous.velocity).length() / H;
            assert!(accel <= 1.0 + 1e-9, "{accel} m/s² at {}", state.t_s);
            if reached.is_none() && (state.velocity.length() - 1.5).abs() < 1e-6 {
                reached = Some(state.t_s);
            }
            previous = *state;
        }
        // The desired point reaches the step at 1 m / 0.5 m/s = 2 s and
        // passes it within 0.1 s; the body takes the 1 m/s on in 1 s.
        let reached = reached.expect("reaches the path's speed");
        assert!((3.0..3.1).contains(&reached), "reached at {reached} s");
        assert!((states[0].velocity.length() - 0.5).abs() < 1e-12);
    }

    /// 6 s of a trot at 0.8 m/s straight ahead (+z), the body set facing 0.3 rad off.
    fn yawed_trot(dynamics: BodyDynamics) -> Vec<BodyState> {
        let path = BodyPath::straight(DVec2::ZERO, 0.0, 100.0).expect("path");
        let gait = trot(0.8);
        let mut track = BodyTrack::new(H, dynamics);
        track.reset(&path, &gait);
        for state in &mut track.states {
            state.yaw_rad = 0.3;
        }
        track.yaw_planned = 1;
        track.cycles.fill(YawCycle::default());
        run(&mut track, &path, &gait, 6.0)
    }

    #[test]
    fn a_yaw_left_off_the_direction_of_travel_is_turned_back() {
        // Each leg turns the body from its yaw at mid-stance toward the
        // direction of travel.
        let states = yawed_trot(BodyDynamics::default());
        let lowest = states
            .iter()
            .map(|s| s.yaw_rad)
            .fold(f64::INFINITY, f64::min);
        let last = states.last().expect("states").yaw_rad;
        assert!(last.abs() < 0.01, "still {last} rad off after 6 s");
        assert!(lowest > -0.1, "overshot to {lowest} rad");
        // Two periods in, most of the error is gone.
        let early = states[(1.2 / H) as usize].yaw_rad;
        assert!(early.abs() < 0.15, "{early} rad at 1.2 s");
        // As before 2026-12-02 (`yaw_toward_actual` off): the legs add only the
        // change of the direction of travel, and the error stays.
        let states = yawed_trot(BodyDynamics {
            yaw_toward_actual: false,
            ..BodyDynamics::default()
        });
        let last = states.last().expect("states").yaw_rad;
        assert!((last - 0.3).abs() < 1e-9, "{last} rad");
    }

    #[test]
    fn on_a_circle_the_body_faces_its_direction_of_travel() {
        let radius = 3.0;
        let path = BodyPath::circle(DVec2::new(-radius, 0.0), radius, 0.0, true).expect("circle");
        let gait = trot(0.8);
        let mut track = BodyTrack::new(H, BodyDynamics::default());
        track.reset(&path, &gait);
        let states = run(&mut track, &path, &gait, 12.0);
        let mut worst: f64 = 0.0;
        for state in states.iter().filter(|s| s.t_s > 3.0) {
            let travel = state.velocity.x.patan2(state.velocity.y);
            worst = worst.max(wrap(state.yaw_rad - travel).abs());
            let distance = (state.position - DVec2::new(-radius, 0.0)).length();
            assert!(
                (distance - radius).abs() < 0.05,
                "off the path: {distance} m"
            );
        }
        assert!(
            worst.to_degrees() < 5.0,
            "yaw off the direction of travel by {}°",
            worst.to_degrees()
        );
        // The average yaw rate is the turn rate v / r.
        let (a, b) = (states[240], states[states.len() - 1]);
        let rate = (b.yaw_rad - a.yaw_rad) / (b.t_s - a.t_s);
        assert!(
            (rate.abs() - 0.8 / radius).abs() < 0.01,
            "yaw rate {rate} rad/s"
        );
    }
}
