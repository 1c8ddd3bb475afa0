//! BVH writer: a gaitlab [`Skeleton`] becomes a BVH hierarchy and each [`Pose`]
//! one MOTION line, streamed frame by frame (format notes on [`Bvh`](super::Bvh)).
//!
//! How a skeleton maps onto BVH is described on [`BvhWriter`].

use std::fmt::Write;

use glam::{DMat3, DVec3};

use super::WriteError;
use super::rotation::euler_zxy;
use super::text::{write_fixed, zero_below};
use crate::fk::axis_angle;
use crate::{Joint, JointKind, Pose, Skeleton};

/// Name of the BVH ROOT node that carries the pose's root transform.
pub const BVH_ROOT_NAME: &str = "root";

/// Options of the BVH writer. Plain data with a [`Default`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhOptions {
    /// File length units per metre: 1 writes metres (the default), 100 centimetres.
    /// Must be finite and positive.
    pub scale: f64,
    /// Digits after the decimal point for every number. Default 9 (nanometres
    /// and nano-degrees), so a written file reproduces gaitlab's joint positions
    /// to well under a micrometre. At most 17.
    pub decimals: usize,
}

impl Default for BvhOptions {
    fn default() -> Self {
        Self {
            scale: 1.0,
            decimals: 9,
        }
    }
}

/// Streaming BVH writer for one skeleton: [`write_header`](Self::write_header)
/// once, then [`write_frame`](Self::write_frame) per pose, then
/// [`finish`](Self::finish) to check the frame count.
///
/// # Mapping
/// - A ROOT named [`BVH_ROOT_NAME`] (`root`) at `OFFSET 0 0 0` with channels
///   `Xposition Yposition Zposition Zrotation Xrotation Yrotation`: the pose's
///   root position and the ZXY Euler angles of its root rotation.
/// - One JOINT per gaitlab joint, named by the joint name (whitespace and braces
///   replaced by `_`, since BVH names are single words), nested as in the
///   skeleton; joints without a parent hang under the root. `OFFSET` is the
///   joint's `offset` in **metres** (times [`BvhOptions::scale`]). Names are
///   not made unique: a joint called `root`, or two names differing only in
///   whitespace, give duplicate BVH names (legal BVH; match joints by position).
/// - Revolute joints get `CHANNELS 3 Zrotation Xrotation Yrotation`, the ZXY
///   Euler angles in degrees of the joint's full local rotation
///   `frame · axis_angle(axis, value)` ([`crate::fk`]'s convention). Because the
///   fixed `frame` is folded into the channels, a rest pose can show non-zero angles.
/// - Prismatic joints get `CHANNELS 6 Xposition Yposition Zposition Zrotation
///   Xrotation Yrotation`: the position channels hold the joint's full local
///   translation `offset + frame · axis · value` (they replace the OFFSET, which
///   holds the unslid `offset` for viewers that draw the rest pose), and the
///   rotation channels hold `frame`.
/// - Every leaf gets an `End Site`: the offset of the first effector on that
///   joint, or else a tip a quarter of the incoming bone's length along the
///   bone's direction at the rest value (zero when the bone has no length).
///
/// Frames are written with [`BvhOptions::decimals`] digits after the point (never
/// exponent form). The writer checks each pose completely before writing it, and
/// allocates nothing per frame.
#[derive(Clone, Debug)]
#[must_use]
pub struct BvhWriter<'s> {
    skeleton: &'s Skeleton,
    options: BvhOptions,
    frame_time: f64,
    zero_below: f64,
    /// Joint indices in hierarchy (depth-first) order: the order of the MOTION channels.
    order: Vec<usize>,
    declared_frames: Option<usize>,
    written_frames: usize,
}

impl<'s> BvhWriter<'s> {
    /// A writer for `skeleton` at `fps` frames per second, default options.
    ///
    /// # Errors
    /// [`WriteError::InvalidOption`] if `fps` is not finite and positive.
    pub fn new(skeleton: &'s Skeleton, fps: f64) -> Result<Self, WriteError> {
        Self::with_options(skeleton, fps, BvhOptions::default())
    }

    /// A writer for `skeleton` at `fps` frames per second with `options`.
    ///
    /// # Errors
    /// [`WriteError::InvalidOption`] if `fps` or `options.scale` is not finite and
    /// positive, or `options.decimals` exceeds 17.
    pub fn with_options(
        skeleton: &'s Skeleton,
        fps: f64,
        options: BvhOptions,
    ) -> Result<Self, WriteError> {
        let frame_time = 1.0 / fps;
        if !(fps.is_finite() && fps > 0.0 && frame_time.is_finite()) {
            return Err(WriteError::InvalidOption {
                name: "fps",
                reason: format!("must be a finite positive number, not {fps}"),
            });
        }
        if !(options.scale.is_finite() && options.scale > 0.0) {
            return Err(WriteError::InvalidOption {
                name: "scale",
                reason: format!("must be a finite positive number, not {}", options.scale),
            });
        }
        if options.decimals > 17 {
            return Err(WriteError::InvalidOption {
                name: "decimals",
                reason: format!("at most 17, not {}", options.decimals),
            });
        }
        let mut order = Vec::with_capacity(skeleton.joint_count());
        let mut stack: Vec<usize> = skeleton
            .joints()
            .iter()
            .enumerate()
            .rev()
            .filter(|(_, joint)| joint.parent.is_none())
            .map(|(j, _)| j)
            .collect();
        while let Some(j) = stack.pop() {
            order.push(j);
            stack.extend(skeleton.children(j).iter().rev());
        }
        Ok(Self {
            skeleton,
            options,
            frame_time,
            zero_below: zero_below(options.decimals),
            order,
            declared_frames: None,
            written_frames: 0,
        })
    }

    /// Seconds per frame, as written after `Frame Time:`.
    #[must_use]
    pub fn frame_time(&self) -> f64 {
        self.frame_time
    }

    /// Frames written so far.
    #[must_use]
    pub fn frames_written(&self) -> usize {
        self.written_frames
    }

    /// Writes the HIERARCHY section and the MOTION preamble declaring `frames` frames.
    ///
    /// # Errors
    /// [`WriteError::Order`] if the header was already written; [`WriteError::Sink`]
    /// if the output fails.
    pub fn write_header(&mut self, out: &mut impl Write, frames: usize) -> Result<(), WriteError> {
        if self.declared_frames.is_some() {
            return Err(WriteError::Order("the BVH header was already written"));
        }
        out.write_str("HIERARCHY\nROOT ")?;
        out.write_str(BVH_ROOT_NAME)?;
        out.write_str("\n{\n\tOFFSET ")?;
        self.write_vector(out, DVec3::ZERO)?;
        out.write_str(
            "\n\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n",
        )?;
        let joints = self.skeleton.joints();
        // Depth-first with explicit close markers, so deep chains need no recursion.
        let mut stack: Vec<(usize, bool)> = joints
            .iter()
            .enumerate()
            .rev()
            .filter(|(_, joint)| joint.parent.is_none())
            .map(|(j, _)| (j, false))
            .collect();
        let mut depth = 1_usize;
        while let Some((j, close)) = stack.pop() {
            if close {
                depth -= 1;
                indent(out, depth)?;
                out.write_str("}\n")?;
                continue;
            }
            let joint = &joints[j];
            indent(out, depth)?;
            out.write_str("JOINT ")?;
            write_name(out, &joint.name)?;
            out.write_char('\n')?;
            indent(out, depth)?;
            out.write_str("{\n")?;
            depth += 1;
            indent(out, depth)?;
            out.write_str("OFFSET ")?;
            self.write_vector(out, joint.offset * self.options.scale)?;
            out.write_char('\n')?;
            indent(out, depth)?;
            out.write_str(match joint.kind {
                JointKind::Revolute => "CHANNELS 3 Zrotation Xrotation Yrotation\n",
                JointKind::Prismatic => {
                    "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                }
            })?;
            let children = self.skeleton.children(j);
            if children.is_empty() {
                indent(out, depth)?;
                out.write_str("End Site\n")?;
                indent(out, depth)?;
                out.write_str("{\n")?;
                indent(out, depth + 1)?;
                out.write_str("OFFSET ")?;
                self.write_vector(out, self.end_site(j) * self.options.scale)?;
                out.write_char('\n')?;
                indent(out, depth)?;
                out.write_str("}\n")?;
            }
            stack.push((j, true));
            stack.extend(children.iter().rev().map(|&c| (c, false)));
        }
        out.write_str("}\nMOTION\n")?;
        writeln!(out, "Frames: {frames}")?;
        writeln!(out, "Frame Time: {}", self.frame_time)?;
        self.declared_frames = Some(frames);
        Ok(())
    }

    /// Writes one MOTION line for `pose`.
    ///
    /// # Errors
    /// [`WriteError::Order`] before the header or past the declared frame count,
    /// [`WriteError::ValueCount`] if the pose has the wrong number of joint values,
    /// [`WriteError::NonFinite`] if any value is NaN or infinite (nothing is written
    /// then), [`WriteError::Sink`] if the output fails.
    pub fn write_frame(&mut self, out: &mut impl Write, pose: &Pose) -> Result<(), WriteError> {
        let Some(declared) = self.declared_frames else {
            return Err(WriteError::Order("write the BVH header before any frame"));
        };
        if self.written_frames >= declared {
            return Err(WriteError::Order(
                "more BVH frames than the header declared",
            ));
        }
        let joints = self.skeleton.joints();
        if pose.joints.len() != joints.len() {
            return Err(WriteError::ValueCount {
                what: "joint values",
                expected: joints.len(),
                found: pose.joints.len(),
            });
        }
        let finite = pose.root.position.is_finite()
            && pose.root.rotation.is_finite()
            && pose.joints.iter().all(|v| v.is_finite());
        if !finite {
            return Err(WriteError::NonFinite {
                what: "pose",
                row: self.written_frames,
            });
        }
        let scale = self.options.scale;
        self.write_vector(out, pose.root.position * scale)?;
        out.write_char(' ')?;
        self.write_rotation(out, pose.root.rotation)?;
        for &j in &self.order {
            let joint = &joints[j];
            let value = pose.joints[j];
            out.write_char(' ')?;
            match joint.kind {
                JointKind::Revolute => {
                    self.write_rotation(out, joint.frame * axis_angle(joint.axis, value))?;
                }
                JointKind::Prismatic => {
                    let translation = joint.offset + joint.frame * joint.axis * value;
                    self.write_vector(out, translation * scale)?;
                    out.write_char(' ')?;
                    self.write_rotation(out, joint.frame)?;
                }
            }
        }
        out.write_char('\n')?;
        self.written_frames += 1;
        Ok(())
    }

    /// Checks that exactly the declared number of frames was written.
    ///
    /// # Errors
    /// [`WriteError::Order`] if no header was written, [`WriteError::FrameCount`]
    /// if the count differs.
    pub fn finish(&self) -> Result<(), WriteError> {
        let Some(declared) = self.declared_frames else {
            return Err(WriteError::Order("the BVH header was never written"));
        };
        if declared == self.written_frames {
            Ok(())
        } else {
            Err(WriteError::FrameCount {
                declared,
                written: self.written_frames,
            })
        }
    }

    /// End Site offset of leaf joint `j`, metres in the joint's moving frame.
    fn end_site(&self, j: usize) -> DVec3 {
        if let Some(effector) = self.skeleton.effectors().iter().find(|e| e.joint == j) {
            return effector.offset;
        }
        let joint: &Joint = &self.skeleton.joints()[j];
        // The incoming bone, expressed in the joint's moving frame at its rest value.
        let rest_rotation: DMat3 = match joint.kind {
            JointKind::Revolute => joint.frame * axis_angle(joint.axis, joint.rest),
            JointKind::Prismatic => joint.frame,
        };
        rest_rotation.transpose() * joint.offset * 0.25
    }

    fn write_vector(&self, out: &mut impl Write, v: DVec3) -> Result<(), WriteError> {
        let (decimals, zero) = (self.options.decimals, self.zero_below);
        write_fixed(out, v.x, decimals, zero)?;
        out.write_char(' ')?;
        write_fixed(out, v.y, decimals, zero)?;
        out.write_char(' ')?;
        write_fixed(out, v.z, decimals, zero)?;
        Ok(())
    }

    /// Writes `Zrotation Xrotation Yrotation` in degrees.
    fn write_rotation(&self, out: &mut impl Write, rotation: DMat3) -> Result<(), WriteError> {
        let angles = euler_zxy(rotation);
        let (decimals, zero) = (self.options.decimals, self.zero_below);
        write_fixed(out, angles.z.to_degrees(), decimals, zero)?;
        out.write_char(' ')?;
        write_fixed(out, angles.x.to_degrees(), decimals, zero)?;
        out.write_char(' ')?;
        write_fixed(out, angles.y.to_degrees(), decimals, zero)?;
        Ok(())
    }
}

fn indent(out: &mut impl Write, depth: usize) -> std::fmt::Result {
    for _ in 0..depth {
        out.write_char('\t')?;
    }
    Ok(())
}

/// Writes a joint name as one BVH word: whitespace, braces and control characters become `_`.
fn write_name(out: &mut impl Write, name: &str) -> std::fmt::Result {
    for c in name.chars() {
        let safe = if c.is_whitespace() || c.is_control() || c == '{' || c == '}' {
            '_'
        } else {
            c
        };
        out.write_char(safe)?;
    }
    Ok(())
}

/// Writes a whole BVH file for `poses` at `fps` with default options.
///
/// # Errors
/// As [`BvhWriter::new`] and [`BvhWriter::write_frame`].
pub fn write_bvh(
    out: &mut impl Write,
    skeleton: &Skeleton,
    poses: &[Pose],
    fps: f64,
) -> Result<(), WriteError> {
    let mut writer = BvhWriter::new(skeleton, fps)?;
    writer.write_header(out, poses.len())?;
    for pose in poses {
        writer.write_frame(out, pose)?;
    }
    writer.finish()
}

/// A whole BVH file for `poses` at `fps` as a `String` (default options).
///
/// # Errors
/// As [`write_bvh`].
pub fn bvh_string(skeleton: &Skeleton, poses: &[Pose], fps: f64) -> Result<String, WriteError> {
    let mut out = String::new();
    write_bvh(&mut out, skeleton, poses, fps)?;
    Ok(out)
}
