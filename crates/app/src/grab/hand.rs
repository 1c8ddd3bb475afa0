//! The hand's state in the 3-D view: the panes' pickable points, the drag
//! in progress, the hover, the events for the lab, and the pin and settle
//! settings.

use glam::DVec3;

use super::pick::Pickable;

/// What the hand did this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GrabEvent {
    /// Holds effector `effector`'s target at `at`, world metres.
    Hold {
        /// The effector.
        effector: usize,
        /// Where, world metres.
        at: DVec3,
    },
    /// Lets go of effector `effector`'s target.
    Release {
        /// The effector.
        effector: usize,
    },
    /// Pins or unpins effector `effector`'s target.
    Pin {
        /// The effector.
        effector: usize,
        /// Pinned.
        on: bool,
    },
}

/// A drag in progress: the effector, the pane it started in, and the point
/// the drag plane passes through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct HandHold {
    pub(super) effector: usize,
    pub(super) pane: usize,
    pub(super) through: DVec3,
}

/// The hand's state in the 3-D view.
#[derive(Clone, Debug, Default)]
pub struct Grab {
    /// Each pane's pickable points (the lab refills them every frame).
    pub(super) panes: Vec<Vec<Pickable>>,
    pub(super) held: Option<HandHold>,
    /// The picked point's offset from the drag plane's point under the press.
    pub(super) offset: DVec3,
    /// The point under the pointer, highlighted: the pane and the point.
    pub(super) hover: Option<(usize, Pickable)>,
    pub(super) events: Vec<GrabEvent>,
    /// Pin a target when the hand lets go of it (the panel's *Pin*).
    pub pin_on_release: bool,
    /// UI frames left in which a paused figure keeps reaching for a
    /// target the hand moved.
    pub(super) settle_frames: u32,
}

/// UI frames a paused figure keeps reaching after the hand moves a target.
pub const SETTLE_FRAMES: u32 = 60;

impl Grab {
    /// Whether the hand holds a target now (the camera stays still).
    #[must_use]
    pub fn is_held(&self) -> bool {
        self.held.is_some()
    }

    /// The effector whose target the hand holds.
    #[must_use]
    pub fn held_effector(&self) -> Option<usize> {
        self.held.map(|h| h.effector)
    }

    /// The effector under the pointer.
    #[must_use]
    pub fn hovered(&self) -> Option<usize> {
        self.hover.map(|(_, p)| p.effector)
    }

    /// Clears the panes' points, keeping their buffers, for `count` panes.
    pub fn clear_panes(&mut self, count: usize) {
        self.panes.resize_with(count, Vec::new);
        for pane in &mut self.panes {
            pane.clear();
        }
    }

    /// What the hand did since the last call, oldest first, in the event
    /// buffer itself (give it back with [`Grab::give_back_events`]).
    pub fn take_events(&mut self) -> Vec<GrabEvent> {
        std::mem::take(&mut self.events)
    }

    /// Returns the (emptied) event buffer, keeping its capacity.
    pub fn give_back_events(&mut self, mut events: Vec<GrabEvent>) {
        events.clear();
        if self.events.is_empty() {
            self.events = events;
        }
    }

    /// Notes that a target moved, so a paused figure reaches for it a while.
    pub fn note_moved(&mut self) {
        self.settle_frames = SETTLE_FRAMES;
    }

    /// Whether a paused figure should reach for moved targets this frame
    /// (counts the frame).
    pub fn take_settle_frame(&mut self) -> bool {
        if self.held.is_some() {
            return true;
        }
        let settle = self.settle_frames > 0;
        self.settle_frames = self.settle_frames.saturating_sub(1);
        settle
    }

    /// Forgets a drag in progress (a new preset, a reset).
    pub fn cancel(&mut self) {
        if let Some(held) = self.held.take() {
            self.events.push(GrabEvent::Release {
                effector: held.effector,
            });
        }
        self.hover = None;
    }
}
