//! Targets held by hand — the lab's grab and pull (issue 44; no paper
//! drives a target by hand): a held target replaces the script's for its
//! effector, kept in the root's frame so a walking figure carries it along;
//! on release the script's target takes over again through a smoothstep
//! blend long enough that the hand's offset fades by at most
//! [`RELEASE_SPEED_MPS`] on average, so the target never jumps; a pinned
//! target stays held after release. Allocation-free per frame.

use gaitlab_core::RootTransform;
use glam::DVec3;

/// The average speed at which a released target's offset from the script
/// fades, m/s: at 60 frames a second the smoothstep's steepest frame moves
/// the target 1.5 × 0.15 / 60 ≈ 3.8 mm beyond the script's own motion.
pub const RELEASE_SPEED_MPS: f64 = 0.15;

/// The shortest release blend, seconds.
pub const MIN_RELEASE_S: f64 = 0.5;

/// What the hand does to one effector's target.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
enum Hold {
    /// The script's target.
    #[default]
    Free,
    /// Held (or pinned) at a point in the root's frame, metres.
    Held { body: DVec3 },
    /// Let go at `since` seconds from the point `body` (root frame); the
    /// offset from the script, measured at the first frame after release,
    /// fades over `duration` seconds.
    Releasing {
        body: DVec3,
        since: f64,
        offset: Option<DVec3>,
        duration: f64,
    },
}

/// Each effector's hold, and whether it is pinned.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HeldTargets {
    holds: Vec<Hold>,
    pinned: Vec<bool>,
}

impl HeldTargets {
    /// No target held, for `effectors` effectors.
    #[must_use]
    pub fn new(effectors: usize) -> Self {
        Self {
            holds: vec![Hold::Free; effectors],
            pinned: vec![false; effectors],
        }
    }

    /// Holds effector `e`'s target at the world point `at` (the root at
    /// `root`). Out-of-range effectors and non-finite points are ignored;
    /// returns whether the hold took.
    pub fn hold(&mut self, e: usize, at: DVec3, root: &RootTransform) -> bool {
        let Some(slot) = self.holds.get_mut(e) else {
            return false;
        };
        if !at.is_finite() {
            return false;
        }
        *slot = Hold::Held {
            body: root.rotation.transpose() * (at - root.position),
        };
        true
    }

    /// Lets go of effector `e`'s target at `time` seconds: a pinned target
    /// stays where it is, any other blends back into the script.
    pub fn release(&mut self, e: usize, time: f64) {
        if self.pinned.get(e).copied().unwrap_or(true) {
            return;
        }
        if let Some(slot) = self.holds.get_mut(e)
            && let Hold::Held { body } = *slot
        {
            *slot = Hold::Releasing {
                body,
                since: time,
                offset: None,
                duration: MIN_RELEASE_S,
            };
        }
    }

    /// Pins or unpins effector `e`'s target. Unpinning a target that is held
    /// but not by the hand lets go of it at `time`.
    pub fn pin(&mut self, e: usize, on: bool, time: f64) {
        if let Some(pinned) = self.pinned.get_mut(e) {
            *pinned = on;
            if !on {
                self.release(e, time);
            }
        }
    }

    /// Whether effector `e`'s target is pinned.
    #[must_use]
    pub fn is_pinned(&self, e: usize) -> bool {
        self.pinned.get(e).copied().unwrap_or(false)
    }

    /// Where effector `e`'s target is held, root frame, metres (`None` when
    /// free or blending back).
    #[must_use]
    pub fn held_at(&self, e: usize) -> Option<DVec3> {
        match self.holds.get(e)? {
            Hold::Held { body } => Some(*body),
            _ => None,
        }
    }

    /// Whether any target is held or blending back.
    #[must_use]
    pub fn any(&self) -> bool {
        self.holds.iter().any(|h| *h != Hold::Free)
    }

    /// Forgets every hold and pin.
    pub fn clear(&mut self) {
        self.holds.fill(Hold::Free);
        self.pinned.fill(false);
    }

    /// At a reset: blends end, holds and pins stay.
    pub fn reset(&mut self) {
        for slot in &mut self.holds {
            if matches!(slot, Hold::Releasing { .. }) {
                *slot = Hold::Free;
            }
        }
    }

    /// Replaces the script's targets `targets` (world, one per effector) at
    /// `time` with the held ones, the root at `root`.
    pub fn apply(&mut self, time: f64, root: &RootTransform, targets: &mut [DVec3]) {
        for (slot, target) in self.holds.iter_mut().zip(targets.iter_mut()) {
            let world = |body: DVec3| root.position + root.rotation * body;
            match slot {
                Hold::Free => {}
                Hold::Held { body } => *target = world(*body),
                Hold::Releasing {
                    body,
                    since,
                    offset,
                    duration,
                } => {
                    let fade = *offset.get_or_insert_with(|| {
                        let offset = root.rotation.transpose() * (world(*body) - *target);
                        *duration = (offset.length() / RELEASE_SPEED_MPS).max(MIN_RELEASE_S);
                        *since = time;
                        offset
                    });
                    let x = ((time - *since) / *duration).clamp(0.0, 1.0);
                    let weight = 1.0 - x * x * (3.0 - 2.0 * x);
                    if weight <= 0.0 {
                        *slot = Hold::Free;
                    } else {
                        *target += root.rotation * fade * weight;
                    }
                }
            }
        }
    }
}
