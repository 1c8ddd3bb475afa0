//! One frame's primitives ([`SceneFrame`]) and the [`Scene`] that holds them
//! behind an `Arc` shared with the renderer: read access for the viewport and
//! tests, write access for [`Scene::fill`] and the overlays.

use std::sync::Arc;

use glam::DVec3;

use super::bounds::Bounds;
use super::primitives::{Capsule, GroundMark, Segment, Sphere};
use super::terrain_mesh::TerrainMesh;

/// One frame's primitives. Read it through [`Scene`]; the renderer holds an
/// `Arc` of it while drawing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneFrame {
    /// Bones: one per joint (from its parent, or from the root) and one per
    /// effector (from its joint), skipping zero-length ones.
    pub capsules: Vec<Capsule>,
    /// Joints, effectors and (when shown) targets.
    pub spheres: Vec<Sphere>,
    /// Error segments, rotation axes and world axes, as enabled.
    pub segments: Vec<Segment>,
    /// Blob shadows of the bones and contact marks of the feet (when shadows are on).
    pub ground_marks: Vec<GroundMark>,
    /// Box around the root, the joints and the effectors (not the targets)
    /// and the physics trunk; `None` before the first fill or when no
    /// position is finite.
    pub bounds: Option<Bounds>,
    /// Where the IK targets lie in [`Self::spheres`] and their error
    /// segments in [`Self::segments`] (the overlay keeps one set of targets).
    pub targets: TargetRanges,
    /// The ground when it is not flat (`None`: the floor). Kept across
    /// fills; set by [`Scene::set_terrain`].
    pub terrain: Option<Arc<TerrainMesh>>,
}

/// Index ranges of the targets' spheres and error segments in a frame's lists.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TargetRanges {
    /// Target spheres.
    pub spheres: std::ops::Range<usize>,
    /// Effector-to-target error segments.
    pub segments: std::ops::Range<usize>,
}

impl SceneFrame {
    /// Empties every list and forgets the bounds (the allocations and the
    /// terrain are kept).
    pub(super) fn clear(&mut self) {
        self.capsules.clear();
        self.spheres.clear();
        self.segments.clear();
        self.ground_marks.clear();
        self.bounds = None;
        self.targets = TargetRanges::default();
    }

    /// Grows [`Self::bounds`] to hold `p` (non-finite points are skipped).
    pub(crate) fn include(&mut self, p: DVec3) {
        if !p.is_finite() {
            return;
        }
        match &mut self.bounds {
            Some(bounds) => bounds.include(p),
            None => self.bounds = Some(Bounds::point(p)),
        }
    }
}

/// The figure as drawable primitives, rebuilt each frame by [`Scene::fill`].
#[derive(Clone, Debug, Default)]
pub struct Scene {
    frame: Arc<SceneFrame>,
}

impl From<SceneFrame> for Scene {
    /// A scene showing hand-made primitives.
    fn from(frame: SceneFrame) -> Self {
        Self {
            frame: Arc::new(frame),
        }
    }
}

impl Scene {
    /// An empty scene.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// The primitives, for adding overlays after [`Scene::fill`] (copied
    /// first if the renderer still holds the previous frame).
    pub(crate) fn frame_mut(&mut self) -> &mut SceneFrame {
        Arc::make_mut(&mut self.frame)
    }

    /// Draws `terrain` under the figure from now on (a mesh is built only
    /// when the terrain differs from the one drawn).
    pub fn set_terrain(&mut self, terrain: &gaitlab_core::terrain::Terrain) {
        let same = match &self.frame.terrain {
            Some(mesh) => mesh.terrain == *terrain,
            None => terrain.is_flat(),
        };
        if !same {
            self.frame_mut().terrain = TerrainMesh::of(terrain).map(Arc::new);
        }
    }

    /// The ground's height under (x, z), metres (0 on the floor).
    #[must_use]
    pub fn ground_height_m(&self, x: f64, z: f64) -> f64 {
        self.frame
            .terrain
            .as_ref()
            .map_or(0.0, |mesh| mesh.height_m(x, z))
    }

    /// The primitives of the last fill, shared with the renderer.
    #[must_use]
    pub fn frame(&self) -> &Arc<SceneFrame> {
        &self.frame
    }

    /// Bones.
    #[must_use]
    pub fn capsules(&self) -> &[Capsule] {
        &self.frame.capsules
    }

    /// Joints, effectors and targets.
    #[must_use]
    pub fn spheres(&self) -> &[Sphere] {
        &self.frame.spheres
    }

    /// Error segments and axes.
    #[must_use]
    pub fn segments(&self) -> &[Segment] {
        &self.frame.segments
    }

    /// Shadows and contact marks on the ground.
    #[must_use]
    pub fn ground_marks(&self) -> &[GroundMark] {
        &self.frame.ground_marks
    }

    /// Box around the figure (root, joints, effectors).
    #[must_use]
    pub fn bounds(&self) -> Option<Bounds> {
        self.frame.bounds
    }

    /// Centre of the figure's box: what the camera follows.
    #[must_use]
    pub fn centre(&self) -> Option<DVec3> {
        self.frame.bounds.map(|bounds| bounds.centre())
    }
}
