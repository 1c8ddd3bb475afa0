//! gaitlab-bench: the performance budget (issue 7, item 4). One suite of timed
//! cases — µs per IK iteration (She 2006 §4.4) and per animation frame for the
//! thesis presets, µs per PODA frame (Girard & Maciejewski 1985), integration
//! steps per second of each Raibert & Hodgins 1991 creature — run by
//! `gaitlab bench` natively and by `window.gaitlab.bench('{"suite": true}')`
//! in the browser, so the two reports have the same cases and fields; and the
//! check of a run against a committed baseline ([`compare()`]).
//!
//! Nothing here reads a clock: callers pass `clock_ms` (`Instant` natively,
//! `performance.now()` in the browser).

pub mod compare;
pub mod frame;
pub mod iteration;
pub mod step;
pub mod suite;
#[cfg(test)]
mod test_presets;

pub use compare::{CaseComparison, Comparison, Verdict, cases_of, compare};
pub use iteration::{RecordedFrame, Timing, record_walk, time_iterations};
pub use suite::{BenchError, DEFAULT_PRESETS, SuiteOptions, run_suite};
