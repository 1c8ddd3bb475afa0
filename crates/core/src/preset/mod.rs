//! Presets: the JSON description of a creature and its default scenario
//! (format `gaitlab-preset/2`; `/1` files read as they ran), parsed with serde, validated against DESIGN.md's
//! input limits before anything is built, and built into a [`Creature`].
//!
//! ```text
//! &str ──Preset::from_json──▶ Preset (parsed + validated) ──Preset::build──▶ Creature
//!        (size limit, serde with JSON paths,                 (Skeleton, root position,
//!         every rule of Preset::validate)                      Scenario)
//! ```
//!
//! Every failure is a [`PresetError`] whose `path` is a JSON path into the file
//! (`skeleton.joints[3].axis`), shown to people as `path: reason`.

mod build;
mod bundled;
mod deprecated;
mod edit;
mod error;
#[cfg(feature = "schema")]
mod json_schema;
mod lab_additions;
mod limits;
mod listing;
mod paper_alone;
pub mod physics;
mod physics_params;
pub mod poda;
mod poda_params;
mod scenario;
mod schema;
pub mod thesis;
mod thesis_params;
mod validate;
mod versions;

pub use build::Creature;
pub use bundled::{
    BundledInfo, DEFAULT_PRESET, bundled, bundled_catalog, bundled_json, bundled_names,
    load_bundled,
};
pub use deprecated::Deprecation;
pub use edit::{MAX_EDIT_PATH_CHARS, set_preset_value};
pub use error::{PresetError, ROOT_PATH, json_path};
#[cfg(feature = "schema")]
pub use json_schema::{SCHEMA_ID, SCHEMA_TITLE, preset_schema, preset_schema_text};
pub use lab_additions::{LabAddition, ik_lab_additions, poda_lab_additions, thesis_lab_additions};
pub use limits::{MAX_EFFECTORS, MAX_JOINTS, MAX_LIMBS, MAX_NAME_CHARS, MAX_PRESET_BYTES};
pub use paper_alone::paper_alone;
pub use physics::{
    GroundSpec, MassSpec, ObstacleSpec, PhysicsBase, PhysicsBodySpec, PhysicsLegSpec, PhysicsModel,
    PhysicsParams,
};
pub use physics_params::PHYSICS_PARAMS;
pub use poda::{PathKindSpec, PathSpec, PodaLegSpec, PodaParams, check_transfer_keys};
pub use poda_params::{
    DUTY_FACTOR_RANGE, MAX_LEG_ITERATIONS, PERIOD_RANGE_S, PODA_PARAMS, SPEED_RANGE_MPS,
    STROKE_RANGE_M,
};
pub use scenario::{DEFAULT_FPS, Engine, MAX_FPS, Scenario};
pub use schema::{
    DhJointSpec, EffectorSpec, FORMAT, Format, JointSpec, JointType, LimbSpec, Preset, RootSpec,
    SkeletonSpec,
};
pub use thesis_params::{
    MAX_ITERATIONS_PER_FRAME, MAX_SLOWDOWN, MAX_SPEED_MPS, MAX_START_RAMP_S, MIN_SLOWDOWN,
    THESIS_PARAMS,
};
pub use validate::{
    MAX_FREQUENCY_HZ, MAX_WOUNDED_ADD, MAX_WOUNDED_MULTIPLY, Purpose, THESIS_ROLE_COUNT,
    check_ik_options, check_thesis_values,
};
