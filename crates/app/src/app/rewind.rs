//! The history scrubber (issue 21 item 1): the last [`REWIND_S`] seconds can
//! be stepped back through, frame by frame, and run forward again. Every
//! frame's pose is stored (root and joints of the figure, or of every
//! comparison view, as `f64` bits); every [`KEY_EVERY_FRAMES`] frames the
//! whole simulation state is kept as a keyframe (the driver or the views'
//! drivers with their plots and figures). Going back to frame `f` restores
//! the last keyframe at or before `f` and simulates forward to `f`, so what
//! the view then shows is the simulation itself; each frame simulated again
//! is checked against the stored pose, bit for bit
//! ([`RewindState::pose_matches_stored`]). A frame that differs (a setting
//! was changed while back in time) drops the stored future from there.
//!
//! Memory: poses take `REWIND_S / dt × (12 + joints)` values per figure
//! (600 × 75 × 8 B ≈ 0.35 MB for the 63-joint quadruped); keyframes clone
//! the drivers twice a second (an allocation every 30 frames, not every frame).

use std::collections::VecDeque;

use gaitlab_core::Pose;
use gaitlab_core::driver::Driver;
use gaitlab_engine::AnyDriver;
use serde::Serialize;

use super::App;
use crate::compare::CompareSnapshot;
use crate::history::History;
use crate::lab::Overlays;

/// Seconds of history the scrubber keeps.
pub const REWIND_S: f64 = 10.0;

/// Frames between keyframes (half a second at 60 frames per second).
pub const KEY_EVERY_FRAMES: u64 = 30;

/// The simulation state a keyframe holds.
enum Snapshot {
    /// The single view: its driver, plots and footprints.
    Single {
        driver: Box<AnyDriver>,
        history: History,
        joint_history: History,
        overlays: Overlays,
    },
    /// Each comparison view's driver, plot and figures.
    Compare(CompareSnapshot),
}

/// A keyframe: the state after `frame` frames.
struct Key {
    frame: u64,
    snapshot: Snapshot,
}

/// Stored poses and keyframes.
#[derive(Default)]
pub(crate) struct Rewind {
    keys: VecDeque<Key>,
    /// Ring of poses, `capacity` frames of `width` values; frame `f` at slot `f % capacity`.
    poses: Vec<f64>,
    width: usize,
    capacity: u64,
    /// The newest stored frame (`None`: nothing stored).
    newest: Option<u64>,
    /// The pose of the current frame, as stored (scratch, reused).
    scratch: Vec<f64>,
    /// Whether the last frame simulated again equalled the stored pose.
    matched: Option<bool>,
}

/// `state().rewind`: where the scrubber stands.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct RewindState {
    /// The frame shown.
    pub frame: u64,
    /// The oldest frame one can step back to.
    pub oldest_frame: u64,
    /// The newest frame simulated (stepping forward to it replays stored poses).
    pub newest_frame: u64,
    /// Whether the pose shown, the last time a frame was simulated again
    /// after stepping back, equalled the stored one bit for bit (`null`
    /// until a frame is simulated again).
    pub pose_matches_stored: Option<bool>,
    /// FNV-1a hash of the shown pose's bits, hex (for tests comparing frames).
    pub pose_digest: String,
}

/// Appends `pose` as root position, rotation columns and joints.
fn write_pose(out: &mut Vec<f64>, pose: &Pose) {
    out.extend(pose.root.position.to_array());
    out.extend(pose.root.rotation.to_cols_array());
    out.extend_from_slice(&pose.joints);
}

fn bits_equal(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

impl Rewind {
    /// The oldest frame one can go back to: the oldest stored pose with a
    /// keyframe at or before it.
    fn oldest(&self) -> Option<u64> {
        let newest = self.newest?;
        let by_poses = (newest + 1).saturating_sub(self.capacity);
        let key = self.keys.front()?.frame;
        Some(by_poses.max(key))
    }

    fn slot(&self, frame: u64) -> std::ops::Range<usize> {
        let at = (frame % self.capacity.max(1)) as usize * self.width;
        at..at + self.width
    }
}

impl App {
    /// The pose of what is shown (the figure, or every comparison view's) into the scratch.
    fn rewind_capture(&mut self) {
        let mut scratch = std::mem::take(&mut self.rewind.scratch);
        scratch.clear();
        self.capture_into(&mut scratch);
        self.rewind.scratch = scratch;
    }

    /// Appends the pose of what is shown (the figure, or every comparison
    /// view's) to `out`: what the history stores for a frame.
    fn capture_into(&self, out: &mut Vec<f64>) {
        match &self.compare {
            Some(compare) => {
                for view in compare.views() {
                    write_pose(out, view.driver().pose());
                }
            }
            None => write_pose(out, self.stage.driver.pose()),
        }
    }

    fn rewind_snapshot(&self) -> Snapshot {
        match &self.compare {
            Some(compare) => Snapshot::Compare(compare.snapshot()),
            None => Snapshot::Single {
                driver: Box::new(self.stage.driver.clone()),
                history: self.stage.history.clone(),
                joint_history: self.plots.joint_history.clone(),
                overlays: self.overlays.clone(),
            },
        }
    }

    /// Forgets the history and starts it at the current frame (a reset, a
    /// new comparison, another figure).
    pub(crate) fn rewind_restart(&mut self) {
        self.rewind_capture();
        let rewind = &mut self.rewind;
        rewind.width = rewind.scratch.len();
        rewind.capacity = (REWIND_S / self.lab.session.creature.scenario.frame_seconds())
            .round()
            .max(1.0) as u64;
        rewind.poses.clear();
        rewind
            .poses
            .resize(rewind.capacity as usize * rewind.width, 0.0);
        rewind.keys.clear();
        rewind.newest = None;
        rewind.matched = None;
        self.rewind_note();
    }

    /// Stores the current frame's pose (checking it against the stored one
    /// when this frame was simulated before) and, every
    /// [`KEY_EVERY_FRAMES`], a keyframe.
    pub(crate) fn rewind_note(&mut self) {
        let frame = self.stage.frame;
        self.rewind_capture();
        if self.rewind.scratch.len() != self.rewind.width || self.rewind.capacity == 0 {
            // Another figure or comparison: start again from here.
            return self.rewind_restart();
        }
        let stored = self
            .rewind
            .oldest()
            .zip(self.rewind.newest)
            .is_some_and(|(oldest, newest)| (oldest..=newest).contains(&frame));
        let slot = self.rewind.slot(frame);
        let rewind = &mut self.rewind;
        if stored {
            let same = bits_equal(&rewind.poses[slot.clone()], &rewind.scratch);
            rewind.matched = Some(same);
            if !same {
                // A new future: drop the stored one.
                rewind.newest = Some(frame);
                while rewind.keys.back().is_some_and(|k| k.frame > frame) {
                    rewind.keys.pop_back();
                }
                rewind.poses[slot].copy_from_slice(&rewind.scratch);
            }
        } else {
            rewind.poses[slot].copy_from_slice(&rewind.scratch);
            rewind.newest = Some(frame);
        }
        let keyed = self.rewind.keys.iter().any(|k| k.frame == frame);
        if frame.is_multiple_of(KEY_EVERY_FRAMES) && !keyed {
            let snapshot = self.rewind_snapshot();
            self.rewind.keys.push_back(Key { frame, snapshot });
        }
        // Keep one keyframe at or before the oldest stored pose.
        let rewind = &mut self.rewind;
        if let Some(newest) = rewind.newest {
            let by_poses = (newest + 1).saturating_sub(rewind.capacity);
            while rewind.keys.len() > 1 && rewind.keys[1].frame <= by_poses {
                rewind.keys.pop_front();
            }
        }
    }

    /// Goes to frame `target` of the stored history (clamped to it): restores
    /// the last keyframe at or before it and simulates forward to it, or
    /// simulates forward from the current frame when that is nearer. Pauses.
    ///
    /// # Errors
    /// While a motion take or a video records (their frames would repeat).
    pub fn rewind_to(&mut self, target: u64) -> Result<(), String> {
        if self.recording() || self.video_recording() {
            return Err("history: stop recording before stepping back".to_owned());
        }
        let (Some(oldest), Some(newest)) = (self.rewind.oldest(), self.rewind.newest) else {
            return Ok(());
        };
        let target = target.clamp(oldest, newest);
        self.set_paused(true);
        let frame = self.stage.frame;
        let key = self.rewind.keys.iter().rposition(|k| k.frame <= target);
        let restore = key.filter(|&k| target < frame || self.rewind.keys[k].frame > frame);
        if let Some(k) = restore {
            self.rewind_restore(k);
        }
        let dt = self.frame_seconds();
        while self.stage.frame < target {
            self.step_frame(dt);
        }
        self.refresh_scene();
        Ok(())
    }

    /// Steps back `frames` frames (at most to the oldest stored one). Pauses.
    ///
    /// # Errors
    /// As [`App::rewind_to`].
    pub fn step_back(&mut self, frames: u64) -> Result<(), String> {
        self.rewind_to(self.stage.frame.saturating_sub(frames))
    }

    /// Puts keyframe `k` back.
    fn rewind_restore(&mut self, k: usize) {
        let key = &self.rewind.keys[k];
        match (&key.snapshot, self.compare.as_mut()) {
            (Snapshot::Compare(views), Some(compare)) => {
                compare.restore(views, key.frame);
                self.lab.stage.frame = key.frame;
            }
            (
                Snapshot::Single {
                    driver,
                    history,
                    joint_history,
                    overlays,
                },
                None,
            ) => {
                let lab = &mut self.lab;
                lab.stage.driver.clone_from(driver);
                lab.stage.history.clone_from(history);
                lab.plots.joint_history.clone_from(joint_history);
                lab.overlays.clone_from(overlays);
                lab.stage.frame = key.frame;
            }
            // A keyframe of the other mode cannot be here (starting or
            // leaving a comparison restarts the history); nothing to restore.
            _ => {}
        }
        self.rewind.matched = None;
    }

    /// The oldest and newest frame one can go to, once any is stored.
    #[must_use]
    pub fn rewind_range(&self) -> Option<(u64, u64)> {
        self.rewind.oldest().zip(self.rewind.newest)
    }

    /// Where the scrubber stands.
    #[must_use]
    pub fn rewind_state(&self) -> RewindState {
        let mut scratch = Vec::with_capacity(self.rewind.width);
        self.capture_into(&mut scratch);
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        for byte in scratch.iter().flat_map(|x| x.to_bits().to_le_bytes()) {
            hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
        RewindState {
            frame: self.stage.frame,
            oldest_frame: self.rewind.oldest().unwrap_or(0),
            newest_frame: self.rewind.newest.unwrap_or(0),
            pose_matches_stored: self.rewind.matched,
            pose_digest: format!("{hash:016x}"),
        }
    }
}
