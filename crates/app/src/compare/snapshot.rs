//! The comparison's part of the history scrubber (issue 21 item 1; issue 44
//! item 6: the comparison keeps its own state, the scrubber stores what it
//! is handed): each view's driver, error history and figures at a keyframe,
//! taken and put back by the comparison itself.

use gaitlab_engine::AnyDriver;

use super::comparison::Comparison;
use super::metrics::ViewMetrics;
use crate::history::History;

/// Every view's simulation state at a keyframe.
#[derive(Clone, Debug)]
pub struct CompareSnapshot {
    views: Vec<(AnyDriver, History, ViewMetrics)>,
}

impl Comparison {
    /// Every view's driver, history and figures now.
    #[must_use]
    pub fn snapshot(&self) -> CompareSnapshot {
        CompareSnapshot {
            views: self
                .views
                .iter()
                .map(|v| {
                    (
                        v.stage.driver.clone(),
                        v.stage.history.clone(),
                        v.metrics.clone(),
                    )
                })
                .collect(),
        }
    }

    /// Puts `snapshot` back, every view at `frame` frames (a snapshot of
    /// another configuration puts back the views the two share, in order).
    pub fn restore(&mut self, snapshot: &CompareSnapshot, frame: u64) {
        for (view, (driver, history, metrics)) in self.views.iter_mut().zip(&snapshot.views) {
            view.stage.driver.clone_from(driver);
            view.stage.history.clone_from(history);
            view.metrics.clone_from(metrics);
            view.stage.frame = frame;
        }
    }
}
