//! A motion take (She 2006 §6.2 "Recording panel", which records every
//! animation frame) and the one way frames are written out: each frame's pose,
//! effector positions and targets as BVH or as the pose CSV of the core's
//! exporters, the whole take or only its last N seconds (the page's "Save the
//! last N s" and `gaitlab run --last N` count frames by one rule,
//! [`frames_in`]). The page records into a [`Take`] and writes it on demand;
//! the CLI streams each frame through the same [`FrameWriter`] as it runs. A
//! take is capped at [`MAX_TAKE_S`] of animation so memory stays bounded;
//! buffers are reserved up front, so recording does not allocate every frame.

use std::fmt;

use gaitlab_core::export::{BvhWriter, PoseCsvColumns, PoseCsvWriter, WriteError};
use gaitlab_core::{Pose, RootTransform, Skeleton};
use glam::DVec3;

/// Longest take, seconds of animation.
pub const MAX_TAKE_S: f64 = 600.0;
/// Animation reserved for when a take starts, seconds.
const RESERVE_S: f64 = 60.0;

/// One recorded take.
#[derive(Clone, Debug)]
pub struct Take {
    fps: f64,
    joints: usize,
    effectors: usize,
    /// Whether the driver has effector targets (the CSV gets target columns).
    has_targets: bool,
    max_frames: usize,
    times: Vec<f64>,
    roots: Vec<RootTransform>,
    values: Vec<f64>,
    positions: Vec<DVec3>,
    targets: Vec<DVec3>,
}

fn frames_for(seconds: f64, fps: f64) -> usize {
    // fps is a validated preset rate (1..=1000), so this is a small whole number.
    (seconds * fps).ceil().max(1.0) as usize
}

/// Frames in the last `seconds` of animation at `fps`: rounded to the nearest
/// frame and at least one. The one rule for the page's take and `gaitlab run
/// --last`; callers check `seconds` against their own limit first.
#[must_use]
pub fn frames_in(seconds: f64, fps: f64) -> usize {
    // Callers bound seconds (≤ 3600) and fps (≤ 1000): a small whole number.
    (seconds * fps).round().max(1.0) as usize
}

/// Frames in the last `seconds` of a take at `fps` (see [`frames_in`]).
///
/// # Errors
/// `last_s: reason` when `seconds` is not finite, positive and at most [`MAX_TAKE_S`].
pub fn last_frames(seconds: f64, fps: f64) -> Result<usize, String> {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= MAX_TAKE_S) {
        return Err(format!(
            "last_s: must be more than 0 and at most {MAX_TAKE_S} s, not {seconds}"
        ));
    }
    Ok(frames_in(seconds, fps))
}

/// Writes frames as BVH or pose CSV (with effector positions, and targets
/// when the driver has them) to any text sink: the one writer behind a
/// take's files and the CLI's streamed `--bvh` / `--csv`.
pub enum FrameWriter<'a> {
    /// BVH: degrees, `Zrotation Xrotation Yrotation`.
    Bvh(BvhWriter<'a>),
    /// The core's pose CSV.
    Csv(PoseCsvWriter<'a>),
}

impl<'a> FrameWriter<'a> {
    /// A BVH writer for `skeleton` at `fps` frames per second.
    ///
    /// # Errors
    /// The skeleton cannot be written as BVH or `fps` is not positive.
    pub fn bvh(skeleton: &'a Skeleton, fps: f64) -> Result<Self, WriteError> {
        BvhWriter::new(skeleton, fps).map(Self::Bvh)
    }

    /// A CSV writer for `skeleton`; `has_targets` adds the target columns.
    #[must_use]
    pub fn csv(skeleton: &'a Skeleton, has_targets: bool) -> Self {
        Self::Csv(PoseCsvWriter::new(
            skeleton,
            PoseCsvColumns {
                effector_positions: true,
                effector_targets: has_targets,
            },
        ))
    }

    /// Writes the header for `frames` frames.
    ///
    /// # Errors
    /// The sink's error.
    pub fn begin(&mut self, out: &mut impl fmt::Write, frames: usize) -> Result<(), WriteError> {
        match self {
            Self::Bvh(writer) => writer.write_header(out, frames),
            Self::Csv(writer) => writer.write_header(out),
        }
    }

    /// Writes one frame at `time_s`.
    ///
    /// # Errors
    /// A non-finite pose, or the sink's error.
    pub fn frame(
        &mut self,
        out: &mut impl fmt::Write,
        time_s: f64,
        pose: &Pose,
        positions: &[DVec3],
        targets: &[DVec3],
    ) -> Result<(), WriteError> {
        match self {
            Self::Bvh(writer) => writer.write_frame(out, pose),
            Self::Csv(writer) => writer.write_row(out, time_s, pose, positions, targets),
        }
    }

    /// Checks the frame count the header promised.
    ///
    /// # Errors
    /// Fewer or more frames were written than the header said.
    pub fn finish(self) -> Result<(), WriteError> {
        match self {
            Self::Bvh(writer) => writer.finish(),
            Self::Csv(_) => Ok(()),
        }
    }
}

impl Take {
    /// An empty take for `skeleton` (the driver's, as drawn) animated at `fps`
    /// frames per second; `has_targets` says whether the CSV gets target columns.
    #[must_use]
    pub fn new(skeleton: &Skeleton, fps: f64, has_targets: bool) -> Self {
        let fps = if fps.is_finite() && fps > 0.0 {
            fps
        } else {
            60.0
        };
        let joints = skeleton.joint_count();
        let effectors = skeleton.effector_count();
        let reserve = frames_for(RESERVE_S, fps);
        Self {
            fps,
            joints,
            effectors,
            has_targets,
            max_frames: frames_for(MAX_TAKE_S, fps),
            times: Vec::with_capacity(reserve),
            roots: Vec::with_capacity(reserve),
            values: Vec::with_capacity(reserve * joints),
            positions: Vec::with_capacity(reserve * effectors),
            targets: Vec::with_capacity(reserve * effectors),
        }
    }

    /// Frames recorded.
    #[must_use]
    pub fn frames(&self) -> usize {
        self.times.len()
    }

    /// Animation recorded, seconds.
    #[must_use]
    pub fn seconds(&self) -> f64 {
        self.frames() as f64 / self.fps
    }

    /// Whether the take reached [`MAX_TAKE_S`].
    #[must_use]
    pub fn is_full(&self) -> bool {
        self.frames() >= self.max_frames
    }

    /// Appends one frame; returns false (and records nothing) once full or if
    /// the sizes do not match the skeleton.
    pub fn push(&mut self, time: f64, pose: &Pose, positions: &[DVec3], targets: &[DVec3]) -> bool {
        if self.is_full() || pose.joints.len() != self.joints || positions.len() != self.effectors {
            return false;
        }
        self.times.push(time);
        self.roots.push(pose.root);
        self.values.extend_from_slice(&pose.joints);
        self.positions.extend_from_slice(positions);
        if targets.len() == self.effectors {
            self.targets.extend_from_slice(targets);
        } else {
            self.targets.extend_from_slice(positions);
        }
        true
    }

    /// The frames of the last `last_s` seconds (all of them for `None`).
    ///
    /// # Errors
    /// An empty take or a bad `last_s`.
    pub fn frame_range(&self, last_s: Option<f64>) -> Result<std::ops::Range<usize>, String> {
        if self.frames() == 0 {
            return Err("recording: nothing recorded yet".to_owned());
        }
        let count = match last_s {
            None => self.frames(),
            Some(seconds) => last_frames(seconds, self.fps)?.min(self.frames()),
        };
        Ok(self.frames() - count..self.frames())
    }

    fn pose_into(&self, frame: usize, pose: &mut Pose) {
        pose.root = self.roots[frame];
        pose.joints.clear();
        pose.joints
            .extend_from_slice(&self.values[frame * self.joints..(frame + 1) * self.joints]);
    }

    /// The take, or its last `last_s` seconds, as a BVH file (degrees,
    /// `Zrotation Xrotation Yrotation`).
    ///
    /// # Errors
    /// The writer's reason (an empty take, a non-finite pose, a bad `last_s`).
    pub fn to_bvh(&self, skeleton: &Skeleton, last_s: Option<f64>) -> Result<String, String> {
        let frames = self.frame_range(last_s)?;
        let fail = |e: WriteError| format!("recording: BVH: {e}");
        let writer = FrameWriter::bvh(skeleton, self.fps).map_err(fail)?;
        self.write(writer, frames).map_err(fail)
    }

    /// The take, or its last `last_s` seconds, as a pose CSV with effector
    /// positions (and targets, when the driver has them).
    ///
    /// # Errors
    /// The writer's reason, an empty take or a bad `last_s`.
    pub fn to_csv(&self, skeleton: &Skeleton, last_s: Option<f64>) -> Result<String, String> {
        let frames = self.frame_range(last_s)?;
        self.write(FrameWriter::csv(skeleton, self.has_targets), frames)
            .map_err(|e| format!("recording: CSV: {e}"))
    }

    fn write(
        &self,
        mut writer: FrameWriter<'_>,
        frames: std::ops::Range<usize>,
    ) -> Result<String, WriteError> {
        let mut out = String::new();
        writer.begin(&mut out, frames.len())?;
        let mut pose = Pose {
            root: RootTransform::default(),
            joints: Vec::with_capacity(self.joints),
        };
        let k = self.effectors;
        for frame in frames {
            self.pose_into(frame, &mut pose);
            let span = frame * k..(frame + 1) * k;
            writer.frame(
                &mut out,
                self.times[frame],
                &pose,
                &self.positions[span.clone()],
                &self.targets[span],
            )?;
        }
        writer.finish()?;
        Ok(out)
    }
}
