//! What the 3-D view draws over a running figure, read through the engine
//! layer without copies (a frame's hot path): PODA's foot targets with their
//! support state, footholds (eq. 11), the body path ahead and the support
//! polygon (Girard & Maciejewski 1985); the physics creature's trunk and the
//! boxes it jumps, and the per-frame probe the plots record (Raibert &
//! Hodgins 1991). Every method answers empty or `None` for an engine that has
//! no such thing.

use gaitlab_core::driver::Driver as _;
use glam::{DVec2, DVec3};
use serde::Serialize;

use crate::AnyDriver;

/// A physics creature's state for one frame's plots: trunk height, pitch
/// and roll, the first leg's length, the ground force and the Figure-4
/// state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ProbeReadout {
    /// Simulated time, seconds.
    pub time_s: f64,
    /// Trunk height above the ground, metres.
    pub height_m: f64,
    /// Trunk pitch, degrees (positive nose down).
    pub pitch_deg: f64,
    /// Trunk roll, degrees.
    pub roll_deg: f64,
    /// First leg's hip-to-foot length, metres.
    pub leg_length_m: f64,
    /// Total vertical ground force over body weight.
    pub ground_force_bw: f64,
    /// The state machine's state as its Figure-4 index (0 flight … 4 unloading).
    pub phase_index: usize,
}

/// How long a push stays drawn after it, seconds of the run.
pub const PUSH_SHOWN_S: f64 = 1.0;

/// The drawn push's length per m/s of velocity change, metres.
pub const PUSH_ARROW_M_PER_MPS: f64 = 2.0;

impl AnyDriver {
    /// PODA's foot targets this frame, each with whether its leg supports.
    pub fn foot_targets(&self) -> impl Iterator<Item = (DVec3, bool)> + '_ {
        self.poda().into_iter().flat_map(|d| d.foot_targets())
    }

    /// PODA's planned footholds (eq. 11), one per leg in transfer.
    pub fn footholds(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.poda().into_iter().flat_map(|d| d.footholds())
    }

    /// PODA's moved footholds: (eq. 11's spot, the foothold chosen
    /// instead) for each foot in transfer whose spot was unacceptable.
    pub fn moved_footholds(&self) -> impl Iterator<Item = (DVec3, DVec3)> + '_ {
        self.poda().into_iter().flat_map(|d| d.moved_footholds())
    }

    /// `samples + 1` ground points of PODA's body path, from where the body
    /// is to `ahead_m` metres ahead of it.
    pub fn path_ahead(&self, ahead_m: f64, samples: u32) -> impl Iterator<Item = DVec2> + '_ {
        self.poda().into_iter().flat_map(move |d| {
            let (path, start) = (d.path(), d.path_distance_m());
            (0..=samples).map(move |k| {
                path.sample(start + ahead_m * f64::from(k) / f64::from(samples.max(1)))
                    .position
            })
        })
    }

    /// PODA's support polygon on the ground, the root's ground point and
    /// whether the body's centre is inside it; `None` for other engines.
    #[must_use]
    pub fn support(&self) -> Option<(&[DVec2], DVec2, bool)> {
        self.poda().map(|d| {
            let root = d.pose().root.position;
            (
                d.support_polygon(),
                DVec2::new(root.x, root.z),
                d.stability().margin_m.is_some_and(|m| m >= 0.0),
            )
        })
    }

    /// The physics creature's trunk as a capsule `(a, b, radius)` in the
    /// world; `None` for other engines or a planar creature.
    #[must_use]
    pub fn trunk_capsule(&self) -> Option<(DVec3, DVec3, f64)> {
        self.physics().and_then(|d| d.trunk_capsule())
    }

    /// The last push as an arrow `(tail, head)` in the world, metres, for
    /// [`PUSH_SHOWN_S`] after it: ending over the trunk's middle, clear of
    /// its body, [`PUSH_ARROW_M_PER_MPS`] long per m/s of the push,
    /// pointing the way it pushed; `None` otherwise.
    #[must_use]
    pub fn push_arrow(&self) -> Option<(DVec3, DVec3)> {
        let driver = self.physics()?;
        let push = driver.pushes().last()?;
        let since = driver.run_time_s() - push.at_s;
        if !(0.0..PUSH_SHOWN_S).contains(&since) {
            return None;
        }
        let (a, b, radius) = driver.trunk_capsule()?;
        let head = (a + b) / 2.0 + DVec3::Y * (2.0 * radius);
        let dv = DVec3::new(push.dv_mps[0], 0.0, push.dv_mps[1]);
        Some((head - dv * PUSH_ARROW_M_PER_MPS, head))
    }

    /// Where a drag grabs the physics creature to push it: the middle of
    /// its trunk in the world (metres), and whether it can be pushed
    /// sideways (a planar creature, the kangaroo, moves forward and up
    /// only); `None` for an engine without a trunk.
    #[must_use]
    pub fn push_grab(&self) -> Option<(DVec3, bool)> {
        let driver = self.physics()?;
        let (a, b, _) = driver.trunk_capsule()?;
        Some(((a + b) / 2.0, driver.sim().creature.model.free_base()))
    }

    /// The boxes on the physics creature's ground, each `(lowest corner,
    /// highest corner)` in the world, metres.
    pub fn obstacle_boxes(&self) -> impl Iterator<Item = (DVec3, DVec3)> + '_ {
        self.physics()
            .into_iter()
            .flat_map(|d| d.sim().terrain.obstacles.iter())
            .map(|o| {
                (
                    DVec3::new(o.min_xz[0], 0.0, o.min_xz[1]),
                    DVec3::new(o.max_xz[0], o.height_m, o.max_xz[1]),
                )
            })
    }

    /// The physics creature's probe for this frame's plots.
    #[must_use]
    pub fn physics_probe(&self) -> Option<ProbeReadout> {
        self.physics().map(|d| {
            let p = d.probe();
            ProbeReadout {
                time_s: d.time(),
                height_m: p.height_m,
                pitch_deg: p.pitch_deg,
                roll_deg: p.roll_deg,
                leg_length_m: p.leg_length_m,
                ground_force_bw: p.ground_force_bw,
                phase_index: p.phase_index,
            }
        })
    }

    /// Why the physics creature was last put back at the start, cleared by
    /// reading; `None` when it was not, or for other engines.
    pub fn take_message(&mut self) -> Option<String> {
        self.physics_mut().and_then(|d| d.take_message())
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::driver::Driver as _;
    use gaitlab_core::preset::load_bundled;

    use crate::{AnyDriver, Overrides, driver_for};

    fn driver(name: &str) -> AnyDriver {
        let Some(Ok(creature)) = load_bundled(name) else {
            panic!("{name}")
        };
        match driver_for(&creature, &Overrides::default()) {
            Ok(driver) => driver,
            Err(error) => panic!("{error}"),
        }
    }

    #[test]
    fn a_push_is_drawn_over_the_trunk_for_a_second() {
        use crate::EngineCommand;
        let mut physics = driver("raibert-quadruped");
        physics.step(1.0 / 60.0);
        assert!(physics.push_arrow().is_none(), "no push yet");
        physics
            .apply(EngineCommand::Push([0.0, 0.3]))
            .expect("pushed");
        let (tail, head) = physics.push_arrow().expect("drawn");
        let (a, b, radius) = physics.trunk_capsule().expect("trunk");
        let over = (a + b) / 2.0 + glam::DVec3::Y * (2.0 * radius);
        assert!((head - over).length() < 1e-12, "{head} over {over}");
        let along = head - tail;
        assert!(
            (along - glam::DVec3::new(0.0, 0.0, 0.3 * super::PUSH_ARROW_M_PER_MPS)).length()
                < 1e-12
        );
        for _ in 0..70 {
            physics.step(1.0 / 60.0);
        }
        assert!(
            physics.push_arrow().is_none(),
            "gone after {} s",
            super::PUSH_SHOWN_S
        );
    }

    #[test]
    fn each_engine_answers_for_its_own_overlays_only() {
        let mut poda = driver("poda-quadruped");
        poda.step(1.0 / 60.0);
        assert_eq!(poda.foot_targets().count(), 4);
        assert_eq!(poda.path_ahead(1.0, 10).count(), 11);
        assert!(poda.support().is_some());
        assert!(poda.physics_probe().is_none() && poda.trunk_capsule().is_none());
        let mut physics = driver("raibert-quadruped");
        physics.step(1.0 / 60.0);
        let probe = physics.physics_probe().expect("probe");
        assert!(probe.height_m > 0.2 && probe.time_s > 0.0, "{probe:?}");
        assert!(physics.trunk_capsule().is_some());
        assert_eq!(physics.foot_targets().count(), 0);
        assert!(physics.support().is_none());
        assert!(physics.take_message().is_none());
    }
}
