//! Overlays on the 3-D scene: PODA's footprints (where supporting feet stood,
//! Girard & Maciejewski 1985 §3) and the body path ahead of the figure, and
//! the physics engine's trunk capsule and terrain obstacles.

use std::collections::VecDeque;

use gaitlab_engine::{AnyDriver, DriverKind};
use glam::DVec3;

use crate::render::Scene;
use crate::view::ViewOptions;

/// Footprints kept for the ground overlay.
const MAX_FOOTPRINTS: usize = 48;
/// Length of body path drawn ahead of the figure, metres.
const PATH_AHEAD_M: f64 = 4.0;
/// Points sampled along the path ahead.
const PATH_SAMPLES: u32 = 40;

/// What the overlays remember between frames.
#[derive(Clone)]
pub struct Overlays {
    /// Recent PODA footprints (where supporting feet stood), oldest first.
    footprints: VecDeque<DVec3>,
    /// Each PODA leg's last recorded footprint.
    last_planted: Vec<DVec3>,
}

impl Default for Overlays {
    fn default() -> Self {
        Self {
            footprints: VecDeque::with_capacity(MAX_FOOTPRINTS),
            last_planted: Vec::new(),
        }
    }
}

impl Overlays {
    /// Forgets every footprint (after a reset or a new creature).
    pub fn clear(&mut self) {
        self.footprints.clear();
        self.last_planted.clear();
    }

    /// Records a footprint for every PODA foot that landed since the last frame.
    pub fn note_footprints(&mut self, driver: &AnyDriver) {
        for (leg, (target, support)) in driver.foot_targets().enumerate() {
            if leg >= self.last_planted.len() {
                self.last_planted.resize(leg + 1, DVec3::NAN);
            }
            if support && self.last_planted[leg].distance_squared(target) > 1e-12 {
                self.last_planted[leg] = target;
                if self.footprints.len() == MAX_FOOTPRINTS {
                    self.footprints.pop_front();
                }
                self.footprints.push_back(target);
            }
        }
    }

    /// Adds the driver's overlays to `scene` (filled from its pose first): the
    /// physics trunk and obstacles, or PODA's footprints, footholds and path
    /// ahead when targets are drawn.
    pub fn add_to(&self, scene: &mut Scene, driver: &AnyDriver, view: &ViewOptions) {
        if driver.kind() == DriverKind::Physics {
            scene.add_physics_overlay(driver.trunk_capsule(), driver.obstacle_boxes());
            if let Some((tail, head)) = driver.push_arrow() {
                scene.add_push_arrow(tail, head);
            }
        }
        if driver.kind() == DriverKind::Poda && view.targets {
            scene.add_gait_overlay(
                self.footprints.iter().copied(),
                driver.footholds(),
                driver.moved_footholds(),
                driver.path_ahead(PATH_AHEAD_M, PATH_SAMPLES),
            );
            if let Some((polygon, root, inside)) = driver.support() {
                scene.add_support_overlay(polygon, root, inside);
            }
        }
    }
}
