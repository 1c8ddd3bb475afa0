//! The drawable primitives, in world metres with sRGB colours: [`Capsule`]
//! (a bone), [`Sphere`] (a joint, effector or target), [`Segment`] (a line of
//! constant screen width) and [`GroundMark`] (a blob shadow or contact mark).
//! Each is `#[repr(C)]` and [`bytemuck::Pod`]: the GPU instance buffers are
//! byte copies of their lists, laid out as `scene.wgsl` reads them.

use bytemuck::{Pod, Zeroable};
use glam::Vec3;

/// A bone: a capsule from `a` to `b` (`a == b` makes it a sphere).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Capsule {
    /// Start point (the parent joint), world metres.
    pub a: [f32; 3],
    /// Radius, metres.
    pub radius: f32,
    /// End point (the child joint or effector), world metres.
    pub b: [f32; 3],
    padding: f32,
    /// sRGB colour.
    pub color: [f32; 4],
}

impl Capsule {
    /// A capsule from `a` to `b` with `radius` and sRGB `color`.
    #[must_use]
    pub fn new(a: Vec3, b: Vec3, radius: f32, color: [f32; 4]) -> Self {
        Self {
            a: a.to_array(),
            radius,
            b: b.to_array(),
            padding: 0.0,
            color,
        }
    }
}

impl From<&Sphere> for Capsule {
    /// The sphere as a capsule of zero length (the renderer draws both with one pipeline).
    fn from(sphere: &Sphere) -> Self {
        Self {
            a: sphere.centre,
            radius: sphere.radius,
            b: sphere.centre,
            padding: 0.0,
            color: sphere.color,
        }
    }
}

/// A sphere: a joint, an effector or a target.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Sphere {
    /// Centre, world metres.
    pub centre: [f32; 3],
    /// Radius, metres.
    pub radius: f32,
    /// sRGB colour.
    pub color: [f32; 4],
}

impl Sphere {
    /// A sphere at `centre` with `radius` and sRGB `color`.
    #[must_use]
    pub fn new(centre: Vec3, radius: f32, color: [f32; 4]) -> Self {
        Self {
            centre: centre.to_array(),
            radius,
            color,
        }
    }
}

/// A line segment of constant screen width.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Segment {
    /// Start, world metres.
    pub a: [f32; 3],
    /// Width on screen, points (not pixels).
    pub width: f32,
    /// End, world metres.
    pub b: [f32; 3],
    padding: f32,
    /// sRGB colour; alpha blends.
    pub color: [f32; 4],
}

impl Segment {
    /// A segment from `a` to `b`, `width` points wide.
    #[must_use]
    pub fn new(a: Vec3, b: Vec3, width: f32, color: [f32; 4]) -> Self {
        Self {
            a: a.to_array(),
            width,
            b: b.to_array(),
            padding: 0.0,
            color,
        }
    }
}

/// A soft dark mark on the ground: the blob shadow of a capsule or sphere
/// seen from straight above, or a foot's contact mark.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GroundMark {
    /// Ground position (x, z) of one end, metres.
    pub a: [f32; 2],
    /// Ground position (x, z) of the other end, metres.
    pub b: [f32; 2],
    /// Radius of the caster, metres.
    pub radius: f32,
    /// Height of the caster's lowest end above the ground, metres (the shadow
    /// softens and fades with it).
    pub height: f32,
    /// Darkness at the centre, 0 (none) to 1 (black).
    pub darkness: f32,
    padding: f32,
}

impl GroundMark {
    /// A mark from ground point `a` to `b` (x, z).
    #[must_use]
    pub fn new(a: [f32; 2], b: [f32; 2], radius: f32, height: f32, darkness: f32) -> Self {
        Self {
            a,
            b,
            radius,
            height,
            darkness,
            padding: 0.0,
        }
    }
}
