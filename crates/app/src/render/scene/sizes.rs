//! Dimensions of the drawn world, metres: the ground plane's height, the sizes
//! of bones, joint spheres and world axes, and how far blob shadows and
//! contact marks reach (with their darkness).

/// Height of the ground plane, world metres.
pub const GROUND_Y: f32 = 0.0;

/// Length of each world axis, metres.
pub const WORLD_AXIS_LENGTH: f32 = 0.5;
/// Joint spheres are this much wider than the bone ending at the joint.
pub const JOINT_SPHERE_SCALE: f32 = 1.3;
/// Bones with a `size` of zero are drawn this thin, metres.
pub const MIN_BONE_RADIUS: f32 = 0.006;
/// Effectors nearer the ground than this (plus their radius) leave a contact mark, metres.
pub const CONTACT_HEIGHT: f32 = 0.02;

/// Darkness of a blob shadow at its centre (before fading with height).
pub const SHADOW_DARKNESS: f32 = 0.55;
/// Casters this high above the ground (or higher) cast no shadow, metres;
/// below it shadows fade linearly with height.
pub const SHADOW_FADE_HEIGHT: f32 = 2.0;
/// Darkness of a foot's contact mark.
pub const CONTACT_DARKNESS: f32 = 0.75;

/// Points closer than this are one point (zero-length bones are skipped), metres.
pub(super) const COINCIDENT: f64 = 1e-6;
