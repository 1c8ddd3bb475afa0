//! The hand applied to the figures on screen (issue 44 item 1; item 6: the
//! drag's own code, in its folder): the points each pane offers the hand,
//! and the hand's events given to every figure's driver, so side by side
//! every view chases the same target. The lab lends the drivers; nothing
//! here knows the lab.

use gaitlab_core::driver::Driver;
use gaitlab_engine::AnyDriver;

use super::hand::{Grab, GrabEvent};
use super::pick::Pickable;

/// Refills the hand's pickable points: one pane per driver in `panes`
/// (one pane for all of them when `overlay`), each holding every target and
/// every effector of a figure whose targets can be held. Allocates nothing
/// once the panes have grown.
pub fn offer_points<'a>(
    grab: &mut Grab,
    panes: impl ExactSizeIterator<Item = &'a AnyDriver>,
    overlay: bool,
) {
    grab.clear_panes(if overlay { 1 } else { panes.len() });
    for (k, driver) in panes.enumerate() {
        if driver.held_targets().is_none() {
            continue;
        }
        let Some(pane) = grab.panes.get_mut(if overlay { 0 } else { k }) else {
            continue;
        };
        if let Some(targets) = driver.targets() {
            pane.extend(
                targets
                    .position
                    .iter()
                    .enumerate()
                    .map(|(effector, &at)| Pickable { effector, at }),
            );
        }
        pane.extend(
            driver
                .effector_positions()
                .iter()
                .enumerate()
                .map(|(effector, &at)| Pickable { effector, at }),
        );
    }
}

/// What [`apply`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Applied {
    /// A target was held, let go of or pinned.
    pub moved: bool,
    /// A paused figure reached for its targets one frame's iterations.
    pub settled: bool,
}

/// Gives the hand's events of this frame to every driver `each_driver`
/// visits, and while `paused` lets each figure reach for a moved target
/// for a while ([`super::SETTLE_FRAMES`]). Allocates nothing: the event
/// buffer is lent out and given back.
pub fn apply(
    grab: &mut Grab,
    paused: bool,
    mut each_driver: impl FnMut(&mut dyn FnMut(&mut AnyDriver)),
) -> Applied {
    let mut events = grab.take_events();
    let moved = !events.is_empty();
    for event in events.drain(..) {
        each_driver(&mut |driver| match event {
            GrabEvent::Hold { effector, at } => {
                driver.hold_target(effector, Some(at));
            }
            GrabEvent::Release { effector } => {
                driver.hold_target(effector, None);
            }
            GrabEvent::Pin { effector, on } => {
                driver.pin_target(effector, on);
            }
        });
    }
    grab.give_back_events(events);
    let settled = paused && grab.take_settle_frame();
    if settled {
        each_driver(&mut |driver| {
            driver.settle();
        });
    }
    Applied { moved, settled }
}
