//! [`Bounds`]: an axis-aligned box in world metres, grown point by point
//! around the figure; the camera frames it and follows its centre.

use glam::DVec3;

/// An axis-aligned box, world metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest x, y, z.
    pub min: DVec3,
    /// Largest x, y, z.
    pub max: DVec3,
}

impl Bounds {
    /// The box around one point.
    #[must_use]
    pub fn point(p: DVec3) -> Self {
        Self { min: p, max: p }
    }

    /// Grows the box to hold `p`.
    pub fn include(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }

    /// Centre of the box.
    #[must_use]
    pub fn centre(&self) -> DVec3 {
        0.5 * (self.min + self.max)
    }

    /// Half the diagonal: the radius of the sphere around the box.
    #[must_use]
    pub fn radius(&self) -> f64 {
        0.5 * (self.max - self.min).length()
    }
}
