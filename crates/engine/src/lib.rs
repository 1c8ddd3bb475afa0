//! gaitlab-engine: the engine layer, the one place where gaitlab's engines plug
//! in — She 2006's thesis motions and recorded-target tracking, Girard &
//! Maciejewski 1985's PODA gaits, Raibert & Hodgins 1991's simulation. Front
//! ends (the page, the CLI, the benchmark suite) build every driver with
//! [`driver_for()`], hold it as an [`AnyDriver`], report its figures as
//! [`RunMetrics`], write its frames with a [`take::FrameWriter`] (a page's
//! recording is a [`Take`]) and a simulation's every step with a [`StepTrace`].
//!
//! Pure like the crates below it: no I/O and no clocks (callers measure time).

pub mod any_driver;
pub mod apply;
pub mod catalog;
pub mod driver_for;
pub mod lambda_sweep;
pub mod live;
pub mod metrics;
pub mod overlay;
pub mod parameters;
pub mod readout;
pub mod status;
pub mod switch;
pub mod take;
pub mod trace;

pub use any_driver::AnyDriver;
pub use apply::{Applied, EngineCommand};
pub use driver_for::{Overrides, Tracking, check, driver_for};
pub use gaitlab_motion::held::HeldTargets;
pub use gaitlab_motion::stretch::StretchOptions;
pub use gaitlab_motion::{IterationRecord, IterationStep};
pub use lambda_sweep::{LambdaPoint, lambda_sweep, lambda_sweep_of};
pub use live::{Change, TimedChange, edit_value, poda_gait, switch_gait};
pub use metrics::{RunMetrics, Timing};
pub use parameters::{Parameter, parameters};
pub use readout::{
    DriverKind, PhysicsReadout, PodaPathReadout, PodaReadout, RouteReadout, ThesisReadout,
};
pub use switch::bundled_for_engine;
pub use take::{FrameWriter, MAX_TAKE_S, Take};
pub use trace::StepTrace;
