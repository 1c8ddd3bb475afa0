//! Pose CSV writer: one row per frame with the time, the root transform and
//! every joint value, optionally followed by effector world positions and their
//! targets, for plotting and analysis.
//!
//! The columns are described on [`PoseCsvWriter`].

use std::fmt::Write;

use glam::DVec3;

use super::WriteError;
use super::rotation::rotation_vector;
use super::text::{write_csv_field, write_round_trip, write_suffixed_field};
use crate::{Pose, Skeleton};

/// Which optional column groups a pose CSV has. Plain data; the default has neither.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PoseCsvColumns {
    /// Add `<effector>_x,_y,_z`: each effector's world position, metres.
    pub effector_positions: bool,
    /// Add `<effector>_target_x,_y,_z`: each effector's target, metres.
    pub effector_targets: bool,
}

/// Streaming pose CSV writer for one skeleton.
///
/// # Columns
/// `t,root_x,root_y,root_z,root_rx,root_ry,root_rz,<joint names…>` then, when
/// enabled, `<effector>_x,<effector>_y,<effector>_z` for every effector and then
/// `<effector>_target_x,<effector>_target_y,<effector>_target_z` for every effector.
/// Time in seconds; root position and effector columns in metres; the root
/// orientation as a rotation vector (axis × angle, radians, angle in [0, π]);
/// joint values in radians (revolute) or metres (prismatic). Names are quoted
/// (RFC 4180) only when they hold commas, quotes or line breaks.
///
/// Numbers use the shortest text that parses back to the same `f64` (exponent
/// form only for magnitudes below 1e-5 or from 1e16 up). Non-finite values are
/// written as `NaN` / `inf` / `-inf` rather than refused, so a run that blew up
/// can still be inspected.
#[derive(Clone, Debug)]
#[must_use]
pub struct PoseCsvWriter<'s> {
    skeleton: &'s Skeleton,
    columns: PoseCsvColumns,
}

impl<'s> PoseCsvWriter<'s> {
    /// A writer for `skeleton` with the optional `columns`.
    pub fn new(skeleton: &'s Skeleton, columns: PoseCsvColumns) -> Self {
        Self { skeleton, columns }
    }

    /// Number of columns in every row.
    #[must_use]
    pub fn column_count(&self) -> usize {
        let k = self.skeleton.effector_count();
        let groups = usize::from(self.columns.effector_positions)
            + usize::from(self.columns.effector_targets);
        7 + self.skeleton.joint_count() + 3 * k * groups
    }

    /// Writes the header row.
    ///
    /// # Errors
    /// [`WriteError::Sink`] if the output fails.
    pub fn write_header(&self, out: &mut impl Write) -> Result<(), WriteError> {
        out.write_str("t,root_x,root_y,root_z,root_rx,root_ry,root_rz")?;
        for joint in self.skeleton.joints() {
            out.write_char(',')?;
            write_csv_field(out, &joint.name)?;
        }
        let groups = [
            (self.columns.effector_positions, ["_x", "_y", "_z"]),
            (
                self.columns.effector_targets,
                ["_target_x", "_target_y", "_target_z"],
            ),
        ];
        for (enabled, suffixes) in groups {
            if !enabled {
                continue;
            }
            for effector in self.skeleton.effectors() {
                for suffix in suffixes {
                    out.write_char(',')?;
                    write_suffixed_field(out, &effector.name, suffix)?;
                }
            }
        }
        out.write_char('\n')?;
        Ok(())
    }

    /// Writes one row: time `t` (seconds), `pose`, and when their columns are
    /// enabled the effector world positions and targets (one per effector, in
    /// effector order; pass empty slices for disabled groups, they are ignored).
    ///
    /// # Errors
    /// [`WriteError::ValueCount`] if the pose or an enabled slice has the wrong
    /// length (nothing is written then); [`WriteError::Sink`] if the output fails.
    pub fn write_row(
        &self,
        out: &mut impl Write,
        t: f64,
        pose: &Pose,
        effector_positions: &[DVec3],
        effector_targets: &[DVec3],
    ) -> Result<(), WriteError> {
        let n = self.skeleton.joint_count();
        let k = self.skeleton.effector_count();
        if pose.joints.len() != n {
            return Err(WriteError::ValueCount {
                what: "joint values",
                expected: n,
                found: pose.joints.len(),
            });
        }
        if self.columns.effector_positions && effector_positions.len() != k {
            return Err(WriteError::ValueCount {
                what: "effector positions",
                expected: k,
                found: effector_positions.len(),
            });
        }
        if self.columns.effector_targets && effector_targets.len() != k {
            return Err(WriteError::ValueCount {
                what: "effector targets",
                expected: k,
                found: effector_targets.len(),
            });
        }
        write_round_trip(out, t)?;
        write_vector(out, pose.root.position)?;
        write_vector(out, rotation_vector(pose.root.rotation))?;
        for &value in &pose.joints {
            out.write_char(',')?;
            write_round_trip(out, value)?;
        }
        if self.columns.effector_positions {
            for &p in effector_positions {
                write_vector(out, p)?;
            }
        }
        if self.columns.effector_targets {
            for &p in effector_targets {
                write_vector(out, p)?;
            }
        }
        out.write_char('\n')?;
        Ok(())
    }
}

/// Writes `,x,y,z`.
fn write_vector(out: &mut impl Write, v: DVec3) -> std::fmt::Result {
    for value in [v.x, v.y, v.z] {
        out.write_char(',')?;
        write_round_trip(out, value)?;
    }
    Ok(())
}
