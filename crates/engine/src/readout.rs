//! The readouts: read-only, plain-data views of a running driver — the
//! `readout()` of DESIGN.md's engine contract (everything a panel, `state()`
//! or `--json` shows) for Raibert & Hodgins 1991's simulation (the gait, eqs.
//! 2–3's desired speed and hop height, Figure 4's state, Table 2), Girard &
//! Maciejewski 1985's PODA gaits (eqs. 6–9, the body path) and She 2006's
//! thesis motions (§5.2, §6.2). Front ends read a driver through these and
//! change it through commands, never through the concrete driver.

use gaitlab_core::driver::Driver as _;
use gaitlab_core::preset::PathSpec;
use gaitlab_core::preset::thesis::{ThesisMode, ThesisParams};
use glam::DVec2;
use serde::Serialize;

use crate::any_driver::AnyDriver;
use crate::catalog;
use crate::metrics::Table2Entry;

/// Which kind of driver runs: what a front end asks to choose its panels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DriverKind {
    /// She 2006's thesis motions (engine `ik`).
    Thesis,
    /// Girard & Maciejewski 1985's PODA gaits (engine `poda`).
    Poda,
    /// Raibert & Hodgins 1991's simulation (engine `physics`).
    Physics,
    /// Recorded effector targets followed by IK (`gaitlab track`).
    Track,
}

/// A physics creature's running state (Raibert & Hodgins 1991): what the
/// physics panel shows.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PhysicsReadout {
    /// The gait asked for last (a take-over may still be waiting for it).
    pub gait: String,
    /// The gaits of this model, the default first ([`catalog::physics_gaits`]).
    pub gaits: &'static [&'static str],
    /// The desired speeds the gait is tested at, m/s at scale 1
    /// ([`catalog::tested_speeds_mps`]); `None` for an untested gait.
    pub tested_speeds_mps: Option<(f64, f64)>,
    /// The scales L the gait is tested to hold at
    /// ([`catalog::tested_scales`]); `None` for an untested gait.
    pub tested_scales: Option<(f64, f64)>,
    /// The desired speed ẋ_d of eq. 3, m/s.
    pub speed_mps: f64,
    /// The hop height eq. 2's thrust regulates, metres: the controller's, or
    /// the preset's; `None` when neither sets one.
    pub hop_height_m: Option<f64>,
    /// The dynamic scale L the creature runs at (Table 1; 1 is the paper's size).
    pub scale: f64,
    /// The state machine's state (Figure 4).
    pub phase: &'static str,
    /// Simulated time, seconds.
    pub time_s: f64,
    /// How often the creature was put back at the start since the run began.
    pub resets: u32,
    /// The running controller's tunable gains.
    pub gains: Vec<GainReadout>,
    /// The lab's additions the gait's controller uses, by their preset
    /// names (empty: the paper's laws only).
    pub lab_additions: Vec<&'static str>,
    /// Whether the run started on the gait's cycle (`scenario.physics.start`,
    /// the lab's) rather than at the gait's own start.
    pub started_on_cycle: bool,
    /// The gaits a switch enters at their own start where the creature is
    /// (`scenario.physics.switch_to_start`, the lab's).
    pub switch_to_start: Vec<String>,
    /// The run's figures since the last reset (after 3 s settling).
    pub figures: PhysicsFigures,
    /// Table 2's rows for the gait beside the run's figures
    /// ([`catalog::table2`]); empty for a gait the paper does not tabulate.
    pub table2: Vec<Table2Entry>,
    /// Where the creature is and the path it steers along.
    pub route: RouteReadout,
    /// The desired heading, radians about +y (0 = +z): what a push
    /// "forward" pushes along.
    pub heading_rad: f64,
    /// The run's last push and its recovery, if it was pushed.
    pub last_push: Option<crate::metrics::PushEntry>,
    /// Seconds of the run, across put-backs (a push's `at_s` clock).
    pub run_time_s: f64,
}

/// Seconds after a push at which its recovery is judged
/// (`gaitlab_physics::engine::push::RECOVERY_S`).
pub const PUSH_RECOVERY_S: f64 = gaitlab_physics::engine::push::RECOVERY_S;

/// One tunable gain of a physics controller.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct GainReadout {
    /// Parameter name (`posture_kp`, `leg_stiffness`, …), the preset's key.
    pub name: &'static str,
    /// The gain in words for people ("Leg spring stiffness k (eq. 1)").
    pub label: &'static str,
    /// Unit, for labels.
    pub unit: &'static str,
    /// Current value.
    pub value: f64,
    /// The controller's default value.
    pub default: f64,
}

/// A physics run's headline figures (Table 2's measures).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PhysicsFigures {
    /// The desired speed the figures were recorded at, m/s.
    pub speed_desired_mps: f64,
    /// Mean forward speed of the centre of mass along the heading, m/s.
    pub speed_mean_mps: f64,
    /// Largest ratio of a stance foot's horizontal to vertical ground force
    /// while it carries at least 10 % of the body's weight (unitless).
    pub friction_needed_max: f64,
    /// The same without each support's first and last 10 ms.
    pub friction_needed_mid: f64,
    /// The same within those first and last 10 ms.
    pub friction_needed_edges: f64,
}

/// A physics creature's place and its waypoints (Raibert & Hodgins 1991,
/// Figure 2: "the path along which to travel").
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RouteReadout {
    /// Whether the creature can turn and so follow waypoints (a free base;
    /// the planar kangaroo cannot).
    pub steerable: bool,
    /// The centre of mass on the ground `(x, z)`, metres at scale 1 (as the
    /// waypoints are).
    pub body_m: DVec2,
    /// The waypoints `(x, z)`, metres at scale 1, in order.
    pub waypoints: Vec<[f64; 2]>,
    /// Index of the waypoint steered to now (the earlier ones are reached).
    pub next_waypoint: usize,
}

/// A PODA creature's gait and legs (Girard & Maciejewski 1985): what the
/// gait panel shows.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PodaReadout {
    /// The named gait running.
    pub gait: String,
    /// The named gaits for this many legs ([`catalog::poda_gaits`]).
    pub gaits: Vec<&'static str>,
    /// Period P of one gait cycle, seconds.
    pub period_s: f64,
    /// Duty factor β: the fraction of the period each leg supports.
    pub duty_factor: f64,
    /// Body speed along the path, m/s.
    pub speed_mps: f64,
    /// Stroke: distance a supporting foot travels relative to the body, metres.
    pub stroke_m: f64,
    /// Support duration (eq. 7: stroke / speed), seconds.
    pub support_s: f64,
    /// Transfer duration, seconds.
    pub transfer_s: f64,
    /// Each leg's relative phase (eq. 9), in leg order, fractions of the period.
    pub phases: Vec<f64>,
    /// Upward force of a supporting leg (eqs. 12–13), newtons.
    pub leg_force_n: f64,
    /// Each supporting leg's share of the body's weight, newtons: the least
    /// leg force that holds the body up.
    pub weight_share_n: f64,
    /// Whether some leg has not yet taken on the gait's present values.
    pub shifting: bool,
    /// Static stability now.
    pub stability: StabilityReadout,
    /// Highest point of a transferring foot above its support line, metres.
    pub step_height_m: f64,
    /// The transfer trajectory's key positions: (step fraction, height fraction).
    pub transfer_keys: Vec<[f64; 2]>,
    /// Each leg's name and joints, in leg order.
    pub legs: Vec<PodaLegReadout>,
    /// Each leg's support over the present gait cycle (eq. 9).
    pub footfall: Footfall,
}

/// Static stability now (feet down, the margin of the body's centre over
/// their support polygon) and over the last gait period.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct StabilityReadout {
    /// Feet on the ground now.
    pub feet_down: usize,
    /// The margin now, metres (negative: the centre is outside the support
    /// polygon, or fewer than three feet are down); `None` in flight.
    pub margin_m: Option<f64>,
    /// Share of the last gait period's time the body stood statically
    /// unstable with at least one foot down (0–1).
    pub unstable_share: f64,
}

/// One PODA leg: its name and the center and gain of each joint.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PodaLegReadout {
    /// Leg name.
    pub name: String,
    /// The leg's joints, hip first.
    pub joints: Vec<JointCenterReadout>,
}

/// One joint's center and gain (PODA eq. 6: the null-space term pulls the
/// joint toward its center with its gain, without moving the foot).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JointCenterReadout {
    /// Joint name.
    pub joint: String,
    /// Center: radians for a revolute joint, metres for a prismatic one.
    pub center: f64,
    /// Gain (unitless, 0–1).
    pub gain: f64,
    /// Whether the joint is revolute.
    pub revolute: bool,
}

/// Samples per gait cycle of a [`Footfall`]: each leg's support is looked
/// up at the middle of each of this many equal slices of the period.
pub const FOOTFALL_SAMPLES: u32 = 120;

/// Each leg's support over the gait cycle under way (Girard & Maciejewski
/// 1985, eq. 9): the footfall diagram's bars and cursor.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Footfall {
    /// Period of the cycle, seconds.
    pub period_s: f64,
    /// Now, as a fraction of the cycle under way (0–1).
    pub now: f64,
    /// Per leg, in leg order: the spans `[from, to]` of the cycle (fractions,
    /// 0–1, in steps of 1 / [`FOOTFALL_SAMPLES`]) during which the foot is on
    /// the ground.
    pub support: Vec<Vec<[f64; 2]>>,
}

/// A PODA creature's body path (Girard & Maciejewski 1985, "Horizontal
/// Control"): what the path panel shows.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PodaPathReadout {
    /// The path as a preset writes it (kind, control points, speeds).
    pub spec: PathSpec,
    /// Points `(x, z)` at [`PATH_SAMPLES`] + 1 equal arc lengths along the
    /// path, start to end, metres.
    pub samples: Vec<DVec2>,
    /// The body's planned ground position now `(x, z)`, metres.
    pub body: DVec2,
    /// The path's point closest to `body`, metres.
    pub closest: DVec2,
    /// This frame's distance of the body's ground position from its path, metres.
    pub error_m: f64,
    /// Largest distance of the body from its path since the last reset, metres.
    pub error_max_m: f64,
    /// Whether the body turns no tighter than its legs reach
    /// (`scenario.poda.turn_within_reach`, the lab's).
    pub turn_within_reach: bool,
}

/// Equal slices of a [`PodaPathReadout`]'s samples along the path.
pub const PATH_SAMPLES: u32 = 120;

/// A thesis figure's motion (She 2006 §5.2): what the Motion and Speed
/// panels show.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ThesisReadout {
    /// The motion parameters in use (shapes, speeds, wounded weights).
    pub params: ThesisParams,
    /// The motion running.
    pub mode: ThesisMode,
    /// Forward speed of the root the target script gives now, m/s (0 when
    /// not moving forward; the stride-matched speed when no speed is set).
    pub script_speed_mps: f64,
}

impl AnyDriver {
    /// Which kind of driver this is.
    #[must_use]
    pub fn kind(&self) -> DriverKind {
        match self {
            AnyDriver::Thesis(_) => DriverKind::Thesis,
            AnyDriver::Poda(_) => DriverKind::Poda,
            AnyDriver::Physics(_) => DriverKind::Physics,
            AnyDriver::Track(_) => DriverKind::Track,
        }
    }

    /// The physics creature's readout; `None` for other engines.
    #[must_use]
    pub fn physics_readout(&self) -> Option<PhysicsReadout> {
        let AnyDriver::Physics(driver) = self else {
            return None;
        };
        let species = driver.sim().creature.species;
        let gait = driver.gait().to_owned();
        let summary = driver.summary();
        let legs: Vec<&str> = driver.leg_names().collect();
        Some(PhysicsReadout {
            gaits: catalog::physics_gaits(species),
            tested_speeds_mps: catalog::tested_speeds_mps(species, &gait),
            tested_scales: catalog::tested_scales(species, &gait),
            speed_mps: driver.params().speed_mps,
            hop_height_m: driver.hop_height_m().or(driver.params().hop_height_m),
            scale: driver.params().scale,
            phase: driver.phase_name(),
            time_s: driver.time(),
            resets: driver.resets(),
            gains: driver
                .gains()
                .into_iter()
                .map(|g| GainReadout {
                    name: g.name,
                    label: g.label,
                    unit: g.unit,
                    value: g.value,
                    default: g.default,
                })
                .collect(),
            lab_additions: driver.lab_additions().collect(),
            started_on_cycle: driver.started_on_cycle(),
            switch_to_start: driver.switch_to_start().to_vec(),
            figures: PhysicsFigures {
                speed_desired_mps: summary.speed_desired_mps,
                speed_mean_mps: summary.speed_mean_mps,
                friction_needed_max: summary.friction_needed_max,
                friction_needed_mid: summary.friction_needed_mid,
                friction_needed_edges: summary.friction_needed_edges,
            },
            table2: catalog::table2(&summary, &gait, &legs),
            route: self.physics_route()?,
            heading_rad: driver.heading(),
            last_push: crate::metrics::push_entries(driver).pop(),
            run_time_s: driver.run_time_s(),
            gait,
        })
    }

    /// The physics creature's place and waypoints alone (cheap: no
    /// figures); `None` for other engines.
    #[must_use]
    pub fn physics_route(&self) -> Option<RouteReadout> {
        let AnyDriver::Physics(driver) = self else {
            return None;
        };
        let sim = driver.sim();
        let com = driver.centre_of_mass();
        Some(RouteReadout {
            steerable: sim.creature.model.free_base(),
            body_m: DVec2::new(com.x, com.z) / driver.params().scale,
            waypoints: driver.waypoints().to_vec(),
            next_waypoint: driver.waypoint(),
        })
    }

    /// The PODA creature's gait readout (no path: [`AnyDriver::poda_path`]);
    /// `None` for other engines.
    #[must_use]
    pub fn poda_readout(&self) -> Option<PodaReadout> {
        let AnyDriver::Poda(driver) = self else {
            return None;
        };
        let gait = driver.gait();
        let skeleton = driver.skeleton();
        let stability = driver.stability();
        let legs = driver
            .leg_joints()
            .map(|(name, joints)| PodaLegReadout {
                name: name.to_owned(),
                joints: joints
                    .iter()
                    .filter_map(|&j| skeleton.joints().get(j))
                    .map(|joint| JointCenterReadout {
                        joint: joint.name.clone(),
                        center: joint.center,
                        gain: joint.gain,
                        revolute: joint.kind == gaitlab_core::JointKind::Revolute,
                    })
                    .collect(),
            })
            .collect();
        let period = gait.period_s();
        let time = driver.time();
        let cycle_start = time - time.rem_euclid(period);
        let support = (0..gait.leg_count())
            .map(|leg| {
                let supporting = |c: u32| {
                    let t =
                        cycle_start + (f64::from(c) + 0.5) / f64::from(FOOTFALL_SAMPLES) * period;
                    gait.leg_phase(leg, t).is_some_and(|p| p.support)
                };
                support_runs(supporting)
            })
            .collect();
        Some(PodaReadout {
            gait: driver.gait_name().to_owned(),
            gaits: catalog::poda_gaits(gait.leg_count()),
            period_s: period,
            duty_factor: gait.duty_factor(),
            speed_mps: gait.speed_mps(),
            stroke_m: gait.stroke_m(),
            support_s: gait.support_s(),
            transfer_s: gait.transfer_s(),
            phases: gait.phases().to_vec(),
            leg_force_n: driver.leg_force_n(),
            weight_share_n: driver.weight_share_n(),
            shifting: driver.is_shifting(),
            stability: StabilityReadout {
                feet_down: stability.feet_down,
                margin_m: stability.margin_m,
                unstable_share: stability.unstable_share,
            },
            step_height_m: driver.params().step_height_m,
            transfer_keys: driver.params().transfer_keys.clone(),
            legs,
            footfall: Footfall {
                period_s: period,
                now: (time - cycle_start) / period,
                support,
            },
        })
    }

    /// The PODA creature's body path; `None` for other engines.
    #[must_use]
    pub fn poda_path(&self) -> Option<PodaPathReadout> {
        let AnyDriver::Poda(driver) = self else {
            return None;
        };
        let path = driver.path();
        let body = driver.ground_pose(driver.time()).position;
        let samples = (0..=PATH_SAMPLES)
            .map(|k| {
                path.sample(path.length_m() * f64::from(k) / f64::from(PATH_SAMPLES))
                    .position
            })
            .collect();
        Some(PodaPathReadout {
            spec: path.to_spec(),
            samples,
            body,
            closest: path.sample(path.closest_distance(body)).position,
            error_m: driver.path_error_m(),
            error_max_m: driver.path_error_max_m(),
            turn_within_reach: driver.params().turn_within_reach,
        })
    }

    /// The thesis figure's readout; `None` for other engines (a recording
    /// followed by IK has no thesis motion).
    #[must_use]
    pub fn thesis_readout(&self) -> Option<ThesisReadout> {
        let AnyDriver::Thesis(driver) = self else {
            return None;
        };
        Some(ThesisReadout {
            params: driver.params().clone(),
            mode: driver.mode(),
            script_speed_mps: driver.script().speed_mps(),
        })
    }
}

/// The runs of samples `0..FOOTFALL_SAMPLES` where `supporting` holds, as
/// `[from, to]` fractions of the cycle.
fn support_runs(supporting: impl Fn(u32) -> bool) -> Vec<[f64; 2]> {
    let fraction = |c: u32| f64::from(c) / f64::from(FOOTFALL_SAMPLES);
    let mut runs = Vec::new();
    let mut run_start: Option<u32> = None;
    for c in 0..=FOOTFALL_SAMPLES {
        let on = c < FOOTFALL_SAMPLES && supporting(c);
        match (on, run_start) {
            (true, None) => run_start = Some(c),
            (false, Some(start)) => {
                runs.push([fraction(start), fraction(c)]);
                run_start = None;
            }
            _ => {}
        }
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn support_runs_merge_neighbouring_samples() {
        let runs = support_runs(|c| (10..40).contains(&c) || c >= 100);
        assert_eq!(runs.len(), 2);
        assert!((runs[0][0] - 10.0 / 120.0).abs() < 1e-12);
        assert!((runs[0][1] - 40.0 / 120.0).abs() < 1e-12);
        assert!((runs[1][1] - 1.0).abs() < 1e-12);
        assert!(support_runs(|_| false).is_empty());
    }

    fn load(name: &str) -> AnyDriver {
        match gaitlab_core::preset::load_bundled(name) {
            Some(Ok(creature)) => {
                match crate::driver_for(&creature, &crate::Overrides::default()) {
                    Ok(driver) => driver,
                    Err(error) => panic!("{name}: {error}"),
                }
            }
            other => panic!("{name}: {other:?}"),
        }
    }

    #[test]
    fn each_engine_reads_out_its_own_view_only() {
        let human = load("human");
        assert_eq!(human.kind(), DriverKind::Thesis);
        assert!(human.thesis_readout().is_some());
        assert!(human.poda_readout().is_none() && human.physics_readout().is_none());

        let poda = load("poda-quadruped");
        assert_eq!(poda.kind(), DriverKind::Poda);
        let gait = poda.poda_readout().expect("a PODA readout");
        assert!(gait.gaits.contains(&gait.gait.as_str()));
        assert_eq!(gait.phases.len(), gait.legs.len());
        assert_eq!(gait.footfall.support.len(), gait.legs.len());
        assert!((gait.support_s - gait.stroke_m / gait.speed_mps).abs() < 1e-9);
        let path = poda.poda_path().expect("a PODA path");
        assert_eq!(path.samples.len(), PATH_SAMPLES as usize + 1);
        assert!(poda.thesis_readout().is_none() && poda.physics_route().is_none());

        let biped = load("raibert-biped");
        assert_eq!(biped.kind(), DriverKind::Physics);
        let physics = biped.physics_readout().expect("a physics readout");
        assert_eq!(physics.gaits.first().copied(), Some(physics.gait.as_str()));
        assert!(physics.route.steerable);
        assert!(!physics.gains.is_empty());
        assert!(serde_json::to_string(&physics).is_ok());
        assert!(biped.poda_readout().is_none() && biped.poda_path().is_none());
    }
}
