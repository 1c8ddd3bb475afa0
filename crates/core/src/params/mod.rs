//! The engine contract's parameter table (DESIGN.md, "Every engine is a
//! driver behind one typed contract"): every settable value of an engine with
//! its unit, valid range, whether it changes live, the paper's reference and
//! its origin — the paper's value, a value the paper leaves open (the lab's
//! pick), or the lab's addition. Ranges are checked here, once
//! ([`ParamSpec::check_real`], [`ParamSpec::check_integer`]).
//!
//! Each engine's table lives beside its values: [`crate::ik::IK_PARAMS`]
//! (She 2006 §4.4), [`crate::preset::THESIS_PARAMS`] (She 2006 §5),
//! [`crate::preset::PODA_PARAMS`] (Girard & Maciejewski 1985),
//! [`crate::preset::PHYSICS_PARAMS`] (Raibert & Hodgins 1991) and
//! [`SCENARIO_PARAMS`] (every engine); the physics controllers' own
//! parameters are the physics crate's. The engine layer joins them, with the
//! values in force, into one table per run (`gaitlab params PRESET`).

mod scenario;
mod spec;

pub use scenario::SCENARIO_PARAMS;
pub use spec::{Domain, Origin, ParamSpec, row};
