//! Side-by-side comparison of IK methods (She 2006 §4.4: transpose, pinv,
//! DLS, SDLS; PODA eq. 6's null-space centering; CCD as a non-Jacobian
//! contrast): 2 or 4 views, each its own thesis driver with its own solver
//! configuration, on the same creature, mode and parameters, advanced in lock
//! step (same `dt`, same frame), so every view sees the same targets. Per view:
//! tracking error (She 2006 §5.3's `d`), wall time per IK iteration, joint
//! velocity jitter and limit hits; per effector, how far its target is out of
//! its limb's reach, the errors over reachable and unreachable frames and the
//! limb's oscillation (docs/ik-metrics.md). The "singularity" scenario pulls every limb
//! target to about its full reach ([`gaitlab_engine::StretchOptions`]). Each view is a
//! [`Stage`](crate::stage::Stage) over its own driver, as the lab's single view is.
//!
//! # The `compare` command and state (DESIGN.md "Browser")
//! `{"compare": {"views": [NAME, …], "scenario": "script" | "singularity",
//! "overlay": BOOL, "options": [{"lambda", "gamma_max", "max_step", "rank_tolerance",
//! "null_space_gain"}, …]}}` starts (or reconfigures) a comparison; `views`
//! holds 2 or 4 of [`CompareMethod::ALL`]'s names, `scenario` and `options`
//! (one object per view, each key optional) may be left out. `{"compare":
//! false}` leaves it. `state().compare` is that same object plus a
//! `metrics` array, the plots' shared `plot_error_max_mm`, the scenario's
//! "what to notice" lines, `notice` (a line that compares methods ends with
//! this run's verdict, "here: holds — …"), and those comparisons, `claims`
//! (`{line, figure, method, rank, among, verdict}`; all ignored by the
//! command), so passing it back verbatim restores the configuration; it is
//! `null` when no comparison runs.

mod bars;
mod cards;
mod claim;
mod colours;
mod command;
mod comparison;
mod config;
mod controls;
mod method;
mod metrics;
mod notice;
mod snapshot;
mod table;
mod view;

pub use cards::cards;
pub use claim::{Checked, Claim, Figure, LEVEL_FRACTION, MIN_FRAMES, Rank, Verdict};
pub use colours::{METHOD_COLOURS, colour_srgb, colour32, colours_for, method_colour};
pub use command::{
    CompareCommand, CompareMethodName, CompareOptions, CompareValue, ScenarioName,
    config_from_command,
};
pub use comparison::Comparison;
pub use config::{CompareConfig, CompareScenario, DEFAULT_VIEWS};
pub use controls::{CompareRequest, controls};
pub use method::{CompareMethod, DEFAULT_NULL_SPACE_GAIN, Parameter};
pub use metrics::{JITTER_WINDOW_FRAMES, ViewMetrics};
pub use notice::{NoticeLine, notice};
pub use snapshot::CompareSnapshot;
pub use view::{CompareView, EffectorFigures};
