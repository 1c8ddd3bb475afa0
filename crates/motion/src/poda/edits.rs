//! Live edits as events (issue 41 item 5): a setter that changes the gait
//! or the body path queues an edit here, and the stage that takes it on
//! consumes it at the next frame — no stage compares stored copies every
//! frame. The legs take a gait change on one by one from their next
//! mid-stances (Girard & Maciejewski 1985, "Vertical Control": changes are
//! taken on "by adjusting the related dynamic parameters for each leg's
//! contribution independently at the beginning of its upward pushing
//! phase"; [`super::leg_cycles`], [`super::transition`]), the body plans its
//! track anew (eq. 14–15), and a new path has the gait read its speed.
//!
//! The queue coalesces: several gait edits between two frames are one event,
//! which keeps the gait's values from before the first of them, so the
//! stages see what changed from the last frame to this one.

use super::gait::GaitParams;

/// What the gait edits since the last frame changed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GaitChange {
    /// Period, duty factor or a relative phase changed: eq. 9 would
    /// re-phase every leg at once, so the legs take it on one by one
    /// ([`super::leg_cycles`]) and the transition bounds are for a new gait.
    pub rephased: bool,
    /// Speed, period or duty factor changed: the body's track is planned
    /// anew beyond the footholds already planned.
    pub replanned: bool,
}

/// The live edits queued since the last frame.
#[derive(Clone, Debug, Default)]
pub struct Edits {
    /// Whether some gait edit is queued.
    gait_pending: bool,
    /// Speed, period and duty factor before the first queued gait edit.
    before_rates: [f64; 3],
    /// Relative phases before the first queued gait edit (capacity: the legs).
    before_phases: Vec<f64>,
    /// The body path was replaced, or the run restarted: the gait reads the
    /// path's speed at the next frame, whatever the legs' mid-stances.
    path_speed_due: bool,
}

impl Edits {
    /// An empty queue for `legs` legs (the only allocation).
    #[must_use]
    pub fn new(legs: usize) -> Self {
        Self {
            before_phases: Vec::with_capacity(legs),
            ..Self::default()
        }
    }

    /// Queues a gait edit; `gait` is the gait before the edit (call before
    /// changing it). An edit that changes nothing is dropped when taken.
    pub fn gait_edited(&mut self, gait: &GaitParams) {
        if self.gait_pending {
            return;
        }
        self.gait_pending = true;
        self.before_rates = [gait.speed_mps(), gait.period_s(), gait.duty_factor()];
        self.before_phases.clear();
        self.before_phases.extend_from_slice(gait.phases());
    }

    /// Takes the queued gait edits: what they changed from the values before
    /// the first of them to `gait` (nothing when none is queued).
    pub fn take_gait(&mut self, gait: &GaitParams) -> GaitChange {
        if !std::mem::take(&mut self.gait_pending) {
            return GaitChange::default();
        }
        let [speed, period, duty] = self.before_rates;
        let timing = period != gait.period_s() || duty != gait.duty_factor();
        GaitChange {
            rephased: timing || self.before_phases.as_slice() != gait.phases(),
            replanned: timing || speed != gait.speed_mps(),
        }
    }

    /// Queues a new body path: the gait reads its speed at the next frame.
    pub fn path_replaced(&mut self) {
        self.path_speed_due = true;
    }

    /// Takes the queued new path (whether one is queued).
    pub fn take_path_replaced(&mut self) -> bool {
        std::mem::take(&mut self.path_speed_due)
    }

    /// Drops every queued edit (a restart takes them all on).
    pub fn clear(&mut self) {
        self.gait_pending = false;
        self.path_speed_due = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gait() -> GaitParams {
        GaitParams::new(0.8, 0.6, vec![0.0, 0.5, 0.25, 0.75], 0.4).expect("gait")
    }

    #[test]
    fn nothing_queued_changes_nothing() {
        let mut edits = Edits::new(4);
        assert_eq!(edits.take_gait(&gait()), GaitChange::default());
        assert!(!edits.take_path_replaced());
    }

    #[test]
    fn an_edit_reports_what_it_changed_once() {
        let mut g = gait();
        let mut edits = Edits::new(4);
        edits.gait_edited(&g);
        // A stroke edit keeps the speed and derives the period.
        let _ = g.set_stroke(0.4).expect("stroke");
        let change = edits.take_gait(&g);
        assert_eq!(
            change,
            GaitChange {
                rephased: true,
                replanned: true
            }
        );
        assert_eq!(edits.take_gait(&g), GaitChange::default());
        edits.gait_edited(&g);
        let _ = g.set_phase(1, 0.4).expect("phase");
        assert_eq!(
            edits.take_gait(&g),
            GaitChange {
                rephased: true,
                replanned: false
            }
        );
    }

    #[test]
    fn edits_coalesce_from_the_values_before_the_first() {
        let mut g = gait();
        let mut edits = Edits::new(4);
        edits.gait_edited(&g);
        let _ = g.set_period(1.0).expect("period");
        edits.gait_edited(&g);
        let _ = g.set_period(0.8).expect("period back");
        // Speed and duty factor kept, the period back where it was: nothing changed.
        assert_eq!(edits.take_gait(&g), GaitChange::default());
    }

    #[test]
    fn a_restart_drops_the_queue() {
        let mut g = gait();
        let mut edits = Edits::new(4);
        edits.gait_edited(&g);
        let _ = g.set_period(1.0).expect("period");
        edits.path_replaced();
        edits.clear();
        assert_eq!(edits.take_gait(&g), GaitChange::default());
        assert!(!edits.take_path_replaced());
    }
}
