//! The BVH (Biovision Hierarchy) motion file as data: a joint hierarchy with
//! offsets and channels, and a table of channel values per frame.
//!
//! The format itself is described on [`Bvh`].

use glam::DVec3;

/// Most joints (ROOT and JOINT blocks, not End Sites) the reader accepts.
pub const MAX_BVH_JOINTS: usize = 4096;
/// Most channels one joint may declare.
pub const MAX_BVH_CHANNELS_PER_JOINT: usize = 6;

/// One animated degree of freedom of a BVH joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BvhChannel {
    /// Translation along the parent frame's x axis.
    Xposition,
    /// Translation along the parent frame's y axis.
    Yposition,
    /// Translation along the parent frame's z axis.
    Zposition,
    /// Rotation about the local x axis, degrees.
    Xrotation,
    /// Rotation about the local y axis, degrees.
    Yrotation,
    /// Rotation about the local z axis, degrees.
    Zrotation,
}

impl BvhChannel {
    /// Every channel, in the order of the enum.
    pub const ALL: [Self; 6] = [
        Self::Xposition,
        Self::Yposition,
        Self::Zposition,
        Self::Xrotation,
        Self::Yrotation,
        Self::Zrotation,
    ];

    /// The channel's name as written in a file, e.g. `Zrotation`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Xposition => "Xposition",
            Self::Yposition => "Yposition",
            Self::Zposition => "Zposition",
            Self::Xrotation => "Xrotation",
            Self::Yrotation => "Yrotation",
            Self::Zrotation => "Zrotation",
        }
    }

    /// The channel called `name` (ASCII case-insensitive), if any.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|c| c.name().eq_ignore_ascii_case(name))
    }

    /// Whether this is a position (translation) channel.
    #[must_use]
    pub fn is_position(self) -> bool {
        matches!(self, Self::Xposition | Self::Yposition | Self::Zposition)
    }
}

/// One ROOT or JOINT block of a BVH hierarchy.
#[derive(Clone, Debug, PartialEq)]
pub struct BvhJoint {
    /// The name after `ROOT` / `JOINT` (words joined by single spaces).
    pub name: String,
    /// Index of the enclosing joint; `None` for a ROOT. Always smaller than this joint's index.
    pub parent: Option<usize>,
    /// `OFFSET`: translation from the parent joint in the parent's frame, file units.
    pub offset: DVec3,
    /// `CHANNELS`, in file order.
    pub channels: Vec<BvhChannel>,
    /// Index of this joint's first channel within a frame's values.
    pub first_channel: usize,
    /// `End Site` offset in this joint's frame, if the block has one.
    pub end_site: Option<DVec3>,
}

/// A parsed BVH file. Build one with [`parse_bvh`](super::parse_bvh), which
/// guarantees the invariants documented on each field.
///
/// # BVH format notes
/// A file has two sections:
/// ```text
/// HIERARCHY
/// ROOT hips                       ← one or more ROOT blocks
/// {
///     OFFSET 0 0 0                ← translation from the parent joint, in the parent's frame
///     CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
///     JOINT knee { OFFSET … CHANNELS 3 Zrotation Xrotation Yrotation … }
///     End Site { OFFSET … }       ← a leaf's tip, no channels
/// }
/// MOTION
/// Frames: 2
/// Frame Time: 0.033333
/// 0 1 0 0 0 0 5 …                 ← one line per frame: every channel, in hierarchy order
/// ```
/// A joint's local transform is `Trans(t) · R₁ · R₂ · R₃`, where the rotations
/// follow the order the rotation channels are listed, each about the local axis it
/// names, in **degrees**. Joints without position channels use `t = OFFSET`; for
/// joints with position channels this crate reads each listed position channel as
/// that component of `t`, replacing the OFFSET component (the common reading of
/// Biovision's root channels; gaitlab writes `OFFSET 0 0 0` for its root, so readers
/// that add the channels to the offset agree). Lengths carry whatever unit the
/// file was written in (gaitlab writes metres by default).
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    /// Joints in file order (parents before children).
    pub joints: Vec<BvhJoint>,
    /// `Frame Time:`, seconds per frame.
    pub frame_time: f64,
    /// `Frames:`, the number of frames.
    pub frame_count: usize,
    /// Values per frame: the sum of every joint's channel count.
    pub channel_count: usize,
    /// Channel values, frame-major: frame `f` is `motion[f·channel_count .. (f+1)·channel_count]`.
    pub motion: Vec<f64>,
}

impl Bvh {
    /// The channel values of frame `frame`, or `None` past the last frame.
    #[must_use]
    pub fn frame(&self, frame: usize) -> Option<&[f64]> {
        if frame >= self.frame_count {
            return None;
        }
        let start = frame.checked_mul(self.channel_count)?;
        self.motion
            .get(start..start.checked_add(self.channel_count)?)
    }

    /// Index of the first joint called `name`.
    #[must_use]
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| j.name == name)
    }

    /// Frames per second, `1 / frame_time`.
    #[must_use]
    pub fn fps(&self) -> f64 {
        1.0 / self.frame_time
    }
}
